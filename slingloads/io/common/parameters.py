"""The Study sheet's parameters as the readers use them: SI values with defaults, their cells,
and the checks every reader makes (range, choice), each failure located at its cell."""

from __future__ import annotations

import numpy as np

from slingloads.io.common.schema import FLAG, INTEGER, STUDY_SHEET, TEXT
from slingloads.io.common.units import si_factor


class StudyParameters:
    """Study-sheet parameters with defaults, in SI, and their cells.

    Parameters
    ----------
    reader : WorkbookReader
    specs : dict
        Every known :class:`~slingloads.io.common.schema.Parameter` by lower-case name.

    Calling it with a parameter name gives the value in SI (the default, converted, when the
    row is absent): ``params("fin area")``.
    """

    def __init__(self, reader, specs):
        self.reader = reader
        self.specs = specs
        self.given = reader.parameters(specs)

    def __call__(self, name):
        key = name.lower()
        if key in self.given:
            return self.given[key][0]
        spec = self.specs[key]
        if spec.kind in (TEXT, FLAG, INTEGER):
            value = spec.default
            if spec.kind == FLAG:
                return str(value).lower() in ("yes", "true", "1")
            return value
        return spec.default * si_factor(spec.unit, spec.kind)

    def cell(self, name):
        """The cell of the parameter's value, or None if the row is absent."""
        got = self.given.get(name.lower())
        return got[1] if got else None

    def where(self, name):
        """The cell of the parameter's value, or ``"(default)"``."""
        return self.cell(name) or "(default)"

    def raw(self, name):
        """The value as the user typed it, with the unit of its 'unit' cell when there is
        one (``"12 ft"``), for error messages; the default (in its unit) when the row is
        absent."""
        cell = self.cell(name)
        if cell is None:
            spec = self.specs[name.lower()]
            return f"{spec.default} {spec.unit}".strip() if spec.unit else spec.default
        sheet = self.reader.book[STUDY_SHEET]
        value = sheet[cell].value
        unit = sheet[f"C{cell[1:]}"].value if cell.startswith("B") else None
        if unit is None or not str(unit).strip() or str(unit).strip() == "-":
            return value
        return f"{value} {str(unit).strip()}"

    def error(self, name, rule, value):
        """An InputError at the parameter's cell."""
        return self.reader.error(rule, value, STUDY_SHEET, self.where(name))

    def check(self, name, ok, rule):
        """Raise an InputError with the value as typed if ``ok`` is false."""
        if not ok:
            raise self.error(name, rule, self.raw(name))

    def choice(self, name, valid):
        """The parameter's text as one of ``valid`` (case-insensitive), spelt as listed."""
        text = str(self(name) or "").strip()
        for v in valid:
            if v.lower() == text.lower():
                return v
        raise self.error(name, f"{name!r} is not valid; valid values are {list(valid)}", text)

    def positive(self, name, allow_zero=False):
        """The parameter's SI value, which must be finite and > 0 (or >= 0)."""
        value = self(name)
        ok = np.isfinite(value) and (value > 0 or (allow_zero and value == 0))
        self.check(name, ok, f"{name!r} must be {'>= 0' if allow_zero else '> 0'}")
        return float(value)

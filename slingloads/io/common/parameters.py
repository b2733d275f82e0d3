"""The Study sheet's parameters as the readers use them: SI values with defaults, their cells,
and the checks every reader makes (range, choice), each failure located at its cell with the
value as the user wrote it and its unit."""

from __future__ import annotations

import contextlib

import numpy as np

from slingloads.errors import InputError
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
        """The value as the user typed it (for error messages), or the default."""
        got = self.given.get(name.lower())
        if got is None:
            return self.specs[name.lower()].default
        return got.raw

    def unit(self, name):
        """The unit as the user wrote it (or the default's unit); None for no unit."""
        got = self.given.get(name.lower())
        unit = got.unit if got is not None else self.specs[name.lower()].unit
        return unit or None

    def error(self, name, rule, value=None):
        """An InputError at the parameter's cell. Without ``value``: the value as typed, with
        its unit."""
        if value is None:
            return self.reader.error(rule, self.raw(name), STUDY_SHEET, self.where(name),
                                     self.unit(name))
        return self.reader.error(rule, value, STUDY_SHEET, self.where(name))

    def check(self, name, ok, rule):
        """Raise an InputError with the value as typed if ``ok`` is false."""
        if not ok:
            raise self.error(name, rule)

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

    def at(self, name):
        """Locate an :class:`InputError` a model raises inside (one naming no cell yet) at
        the cell of parameter ``name``, with its value as typed and its unit in place of the
        model's SI value (see :mod:`slingloads.io.common.locate`)."""
        return self.located({}, name)

    def quantity(self, name, si_value, kind=None, digits=4):
        """An SI value in the unit of parameter ``name`` as the user wrote it (its default
        unit when the row is absent), for a message: ``"54.3 ft"``."""
        from slingloads.io.common.locate import quantity

        return quantity(si_value, self.unit(name), kind or self.specs[name.lower()].kind,
                        digits)

    @contextlib.contextmanager
    def located(self, fields, default=None):
        """Locate an :class:`InputError` a model raises on parameter values.

        Parameters
        ----------
        fields : dict
            Model argument (the error's ``field``) -> parameter name.
        default : str, optional
            Parameter whose cell takes an error naming no known field (else the sheet).
        """
        try:
            yield
        except InputError as err:
            if err.cell is not None:
                raise
            name = fields.get(err.field, default)
            if name is None:
                raise err.located(file=self.reader.file, sheet=STUDY_SHEET) from None
            raise err.located(file=self.reader.file, sheet=STUDY_SHEET, cell=self.where(name),
                              value=self.raw(name), unit=self.unit(name)) from None

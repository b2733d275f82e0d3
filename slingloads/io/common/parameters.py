"""The Study sheet: its parameters read, and used by the readers as SI values with defaults
and cells.

What this module guarantees: every row of the Study sheet names a known parameter once
(a renamed one is refused with its new name, an unknown one with the closest valid names),
with its value checked as its kind requires (:mod:`slingloads.io.common.values`) in the
unit written in its unit cell; :class:`StudyParameters` gives each value in SI, or its default,
with the cell it came from, and every check a reader makes on it (range, choice) fails at that
cell with the value as the user wrote it and its unit."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from slingloads.errors import ErrorCollector
from slingloads.io.common.locate import Place, StudyCells, located, quantity
from slingloads.io.common.schema import FLAG, INTEGER, STUDY_SHEET, TEXT
from slingloads.io.common.table import cell_name
from slingloads.io.common.units import si_factor
from slingloads.io.common.values import (
    FORMULA_HINT,
    as_text,
    check_quantity,
    echo,
    parse_flag,
    parse_number,
    parse_text,
)
from slingloads.limits import MAX_STUDY_ROWS, MAX_TEXT_CHARS


class ParameterValue(NamedTuple):
    """A Study-sheet parameter as read: SI value, cell, value as written, unit as written."""

    value: object
    cell: str
    raw: object
    unit: str


class StudyParameters:
    """Study-sheet parameters with defaults, in SI, and their cells.

    Parameters
    ----------
    reader : WorkbookReader
    specs : dict
        Every known :class:`~slingloads.io.common.schema.Parameter` by lower-case name.

    errors : ErrorCollector, optional
        Gathers the errors of the rows (then the rows that read are kept, the others count
        as absent); without it the first reading error is raised, with every bad row.

    Calling it with a parameter name gives the value in SI (the default, converted, when the
    row is absent): ``params("fin area")``.
    """

    def __init__(self, reader, specs, errors=None):
        self.reader = reader
        self.specs = specs
        self.given = read_parameters(reader, specs, errors=errors)
        #: Where an error about a parameter is located: ``located(params, default="fin area")``
        #: (:func:`slingloads.io.common.locate.located`).
        self.places = StudyCells(reader.file, {k: v.cell for k, v in self.given.items()},
                                 {k: (v.raw, v.unit) for k, v in self.given.items()}, specs)

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
        """The parameter's text as one of ``valid`` (case-insensitive), spelt as listed;
        ``valid`` may be a reader's ``CHOICES`` (valid values by row name)."""
        if isinstance(valid, dict):
            valid = valid[name]
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

    def quantity(self, name, si_value, kind=None, digits=4):
        """An SI value in the unit of parameter ``name`` as the user wrote it (its default
        unit when the row is absent), for a message: ``"54.3 ft"``."""
        return quantity(si_value, self.unit(name), kind or self.specs[name.lower()].kind,
                        digits)


def read_parameters(reader, known, sheet=STUDY_SHEET, errors=None):
    """Read the ``Study`` sheet of ``reader`` (a
    :class:`~slingloads.io.common.workbook.WorkbookReader`): ``{name: ParameterValue}`` for
    every row present.

    ``known`` gives every valid :class:`~slingloads.io.common.schema.Parameter` by
    lower-case name (:func:`slingloads.io.analyses.all_parameters`). The errors of the rows
    go to ``errors`` (an :class:`~slingloads.errors.ErrorCollector`) if given, the rows that
    read returned; else they are raised together.
    """
    rows = reader.rows(sheet, MAX_STUDY_ROWS)
    header = rows[0][1] if rows and rows[0][0] == 1 else {}
    for col, title in enumerate(("parameter", "value", "unit"), start=1):
        got = header.get(col)
        text = as_text(got).strip().lower() if got is not None else ""
        if text != title:
            raise reader.error(f"the {sheet} sheet needs the header 'parameter | value | "
                               f"unit' in row 1; column {col} should be {title!r}",
                               echo(got), sheet, cell_name(1, col))
    out = {}
    own = errors is None
    errors = ErrorCollector() if own else errors  # every bad row at once
    for r, row in rows[1:]:
        errors.call(_read_row, reader, known, sheet, header, out, r, row)
    if own:
        errors.raise_if_any()
    return out


def _read_row(reader, known, sheet, header, out, r, row):
    """Add row ``r`` of the Study sheet to ``out``, or raise its error."""
    stray = next((c for c in sorted(row) if c not in header), None)
    if stray is not None:
        raise reader.error("value in a column without a header (give the column a "
                           "header, e.g. 'notes', or clear the cell)", echo(row[stray]),
                           sheet, cell_name(r, stray))
    name, raw, unit = row.get(1), row.get(2), row.get(3)
    if name is None:
        if raw is not None or unit is not None:
            raise reader.error("value without a parameter name", echo(
                raw if raw is not None else unit), sheet, cell_name(r, 1))
        return
    key = as_text(name).strip().lower()
    if key not in known:
        renamed = next((p for p in known.values()
                        if key in (f.lower() for f in p.former)), None)
        if renamed is not None:
            raise reader.error(f"parameter renamed: use {renamed.name!r} ({renamed.help})",
                               echo(name), sheet, cell_name(r, 1))
        raise reader.error(_unknown_parameter(key, known), echo(name), sheet,
                           cell_name(r, 1))
    if key in out:
        raise reader.error("parameter appears twice", echo(name), sheet,
                           cell_name(r, 1))
    spec = known[key]
    where = cell_name(r, 2)
    unit_text = "" if unit is None else as_text(unit)
    if raw is None:
        if spec.kind == TEXT:
            out[key] = ParameterValue("", where, raw, unit_text)
            return
        raise reader.error(f"empty value for parameter {spec.name!r} (delete the row "
                           f"to use the default {spec.default!r} {spec.unit})"
                           f"{FORMULA_HINT}", None, sheet, where)
    value = _parameter_value(reader, spec, raw, unit_text, sheet, r)
    out[key] = ParameterValue(value, where, raw, unit_text.strip())


def _parameter_value(reader, spec, raw, unit_text, sheet, r):
    where = cell_name(r, 2)
    # a text parameter with a unit is a list of numbers in that unit (read by its analysis)
    unit_free = spec.kind in (FLAG, INTEGER) or (spec.kind == TEXT and not spec.unit)
    if unit_free and unit_text.strip() not in ("", "-"):
        raise reader.error(f"parameter {spec.name!r} takes no unit (leave the unit cell "
                           "empty)", echo(unit_text), sheet, cell_name(r, 3))
    if spec.kind == TEXT:
        return parse_text(raw, spec.name, MAX_TEXT_CHARS, reader.error, sheet, where)
    if spec.kind == FLAG:
        return parse_flag(raw, spec.name, reader.error, sheet, where, None)
    number = parse_number(raw, spec.name, reader.error, sheet, where)
    if spec.kind != "dimensionless" and spec.kind != INTEGER and not unit_text.strip():
        raise reader.error(f"parameter {spec.name!r} needs a unit, e.g. {spec.unit!r}",
                           None, sheet, cell_name(r, 3))
    factor = 1.0
    if spec.kind != INTEGER:
        with located(Place(reader.file, sheet, cell_name(r, 3))):
            factor = si_factor(unit_text, spec.kind)
    return check_quantity(number, raw, spec.kind, factor, unit_text.strip(), spec.bounds,
                          spec.unit, spec.name, reader.error, sheet, where)


def _unknown_parameter(key, known):
    """The rule broken by an unknown Study parameter: the closest valid names, or where the
    whole list is (there are too many to quote)."""
    import difflib

    close = difflib.get_close_matches(key, list(known), n=3, cutoff=0.6)
    hint = f"did you mean {' or '.join(repr(known[c].name) for c in close)}? " if close else ""
    return (f"unknown parameter; {hint}the valid parameters are on the Study sheet of "
            f"'slingloads template' and in docs/ ({len(known)} in all)")


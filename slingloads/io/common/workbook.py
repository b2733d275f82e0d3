"""Reading input workbooks: tables with units in their headers, parameters, precise errors.

Every problem raises :class:`~slingloads.errors.InputError` naming the file, the sheet, the
cell, the value and the rule it broke. Workbooks are opened with openpyxl, which parses their
XML through ``defusedxml`` (a dependency of slingloads) and so refuses entity-expansion
("billion laughs") and external-entity attacks; the ZIP container's uncompressed size is
checked before anything is parsed.
"""

from __future__ import annotations

import contextlib
import math
import re
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from openpyxl import load_workbook
from openpyxl.utils import get_column_letter

from slingloads.errors import InputError
from slingloads.io.common.schema import (
    FLAG,
    INTEGER,
    NOTE_COLUMNS,
    STUDY_SHEET,
    TEXT,
)
from slingloads.io.common.units import si_factor

#: Largest uncompressed workbook content accepted. [bytes]
MAX_UNCOMPRESSED = 256 * 1024**2
_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*(\[(?P<unit>[^\[\]]*)\])?\s*$")
_FORMULA_HINT = (" (or a formula whose value was never computed: open and save the workbook "
                 "in Excel or LibreOffice first)")
_TRUE = {"yes", "y", "true", "1", "on", "x"}
_FALSE = {"no", "n", "false", "0", "off", ""}


@contextlib.contextmanager
def located(file=None, sheet=None, cell=None):
    """Fill in the location of any :class:`InputError` raised inside the block."""
    try:
        yield
    except InputError as err:
        raise err.located(file=file, sheet=sheet, cell=cell) from None


def cell_name(row, col):
    """Excel coordinate of 1-based ``row``, ``col`` (``cell_name(2, 3) == "C2"``)."""
    return f"{get_column_letter(col)}{row}"


@dataclass
class Table:
    """A table read from a sheet: SI values per column, and where each value came from."""

    sheet: str
    values: dict
    cells: dict
    units: dict
    factors: dict = None

    def __len__(self):
        return len(next(iter(self.values.values()))) if self.values else 0

    def __getitem__(self, name):
        return self.values[name]

    def has(self, name):
        return name in self.values

    def cell(self, name, index):
        """Coordinate of the value of column ``name`` in record ``index``."""
        return self.cells[name][index]

    def written(self, name, index):
        """The value of column ``name`` in record ``index`` in the unit of its header, as the
        user wrote it (for error messages): ``"12 ft"``, or the bare number without a unit."""
        value = float(self.values[name][index]) / ((self.factors or {}).get(name) or 1.0)
        unit = self.units.get(name, "")
        return f"{value:.10g} {unit}".strip() if unit and unit != "-" else value


class WorkbookReader:
    """An opened input workbook.

    Parameters
    ----------
    path : str or Path
        The ``.xlsx`` file.
    """

    def __init__(self, path):
        self.path = Path(path)
        self.file = str(path)
        if not self.path.is_file():
            raise InputError("input workbook not found", str(path), file=self.file)
        if self.path.suffix.lower() not in (".xlsx", ".xlsm"):
            raise InputError("input must be an Excel .xlsx workbook (save older .xls files "
                             "as .xlsx)", self.path.suffix, file=self.file)
        self._check_container()
        try:
            self.book = load_workbook(self.path, read_only=False, data_only=True)
        except Exception as err:  # openpyxl raises many kinds on corrupt or hostile files
            root = err
            while root.__cause__ is not None or root.__context__ is not None:
                root = root.__cause__ or root.__context__
            raise InputError(f"not a readable .xlsx workbook ({type(root).__name__}: "
                             f"{str(root).splitlines()[0] if str(root) else ''})",
                             file=self.file) from None

    def _check_container(self):
        try:
            with zipfile.ZipFile(self.path) as archive:
                total = sum(info.file_size for info in archive.infolist())
        except (zipfile.BadZipFile, OSError) as err:
            raise InputError(f"not a workbook: the file is not an .xlsx (zip) container "
                             f"({err})", file=self.file) from None
        if total > MAX_UNCOMPRESSED:
            raise InputError(f"workbook refused: its content expands to {total} bytes, more "
                             f"than the {MAX_UNCOMPRESSED} accepted (possible zip bomb)",
                             file=self.file)

    def has_sheet(self, name):
        return name in self.book.sheetnames

    def error(self, rule, value=None, sheet=None, cell=None):
        """An InputError located in this file."""
        return InputError(rule, value, file=self.file, sheet=sheet, cell=cell)

    def _rows(self, name):
        if name not in self.book.sheetnames:
            raise self.error(f"missing sheet {name!r}; the workbook has "
                             f"{self.book.sheetnames}", sheet=name)
        return list(self.book[name].iter_rows(values_only=True))

    def table(self, spec):
        """Read the table sheet described by ``spec`` (a :class:`TableSheet`)."""
        rows = self._rows(spec.name)
        if not rows or all(v is None for v in rows[0]):
            raise self.error("sheet has no header row (row 1)", sheet=spec.name, cell="A1")
        header = rows[0]
        exact = {c.name: c for c in spec.columns}
        folded = {}
        for c in spec.columns:
            folded.setdefault(c.name.lower(), []).append(c)
        found = {}
        for col, text in enumerate(header, start=1):
            if text is None or str(text).strip() == "":
                continue
            match = _HEADER.match(str(text))
            name = (match.group("name") if match else str(text)).strip()
            unit = match.group("unit") if match and match.group("unit") is not None else None
            if name.lower() in NOTE_COLUMNS:
                continue
            # exact names first (CL and Cl differ), else a unique case-insensitive match
            candidates = folded.get(name.lower(), [])
            column = exact.get(name) or (candidates[0] if len(candidates) == 1 else None)
            if column is None:
                raise self.error(f"unknown column; valid columns are "
                                 f"{[c.header for c in spec.columns]}", str(text),
                                 spec.name, cell_name(1, col))
            key = column.name
            if key in found:
                raise self.error("column appears twice", str(text), spec.name,
                                 cell_name(1, col))
            factor = 1.0
            if column.kind not in (TEXT, FLAG, INTEGER):
                if unit is None and column.kind != "dimensionless":
                    raise self.error(f"header needs a unit in brackets, e.g. "
                                     f"'{column.name} [{column.unit}]'", str(text), spec.name,
                                     cell_name(1, col))
                with located(self.file, spec.name, cell_name(1, col)):
                    factor = si_factor(unit or "", column.kind)
            found[key] = (col, column, factor, unit or "")
        for column in spec.columns:
            if column.required and column.name not in found:
                raise self.error(f"missing column {column.header!r}", sheet=spec.name,
                                 cell=cell_name(1, len(header) + 1))
        values = {c.name: [] for c in spec.columns if c.name in found}
        cells = {name: [] for name in values}
        for r, row in enumerate(rows[1:], start=2):
            if all(v is None or (isinstance(v, str) and not v.strip()) for v in row):
                continue
            for col, column, factor, _ in found.values():
                raw = row[col - 1] if col - 1 < len(row) else None
                where = cell_name(r, col)
                values[column.name].append(self._value(raw, column, factor, spec.name, where))
                cells[column.name].append(where)
        if not values or not next(iter(values.values())):
            raise self.error("sheet has no data rows below its header", sheet=spec.name,
                             cell="A2")
        arrays = {}
        for name, vals in values.items():
            kind = next(c.kind for c in spec.columns if c.name == name)
            arrays[name] = vals if kind in (TEXT, FLAG) else np.asarray(vals, dtype=float)
        units = {found[k][1].name: found[k][3] for k in found}
        factors = {found[k][1].name: found[k][2] for k in found}
        return Table(spec.name, arrays, cells, units, factors)

    def _value(self, raw, column, factor, sheet, where):
        if column.kind == TEXT:
            if raw is None or (isinstance(raw, str) and not raw.strip()):
                if column.required:
                    raise self.error(f"empty cell in required column {column.header!r}"
                                     f"{_FORMULA_HINT}", None, sheet, where)
                return column.default
            if isinstance(raw, float) and raw.is_integer():
                raw = int(raw)
            return str(raw).strip()
        if column.kind == FLAG:
            return parse_flag(raw, column.header, self.error, sheet, where, column.default)
        if raw is None or (isinstance(raw, str) and not raw.strip()):
            if column.required:
                raise self.error(f"empty cell in required column {column.header!r}"
                                 f"{_FORMULA_HINT}", None, sheet, where)
            return column.default
        number = parse_number(raw, column.header, self.error, sheet, where)
        if column.kind == INTEGER:
            if not float(number).is_integer():
                raise self.error(f"{column.header!r} must be a whole number", raw, sheet, where)
            return int(number)
        return number * factor

    def parameters(self, known, sheet=STUDY_SHEET):
        """Read the ``Study`` sheet: ``{name: (SI value, cell)}`` for every row present.

        ``known`` gives every valid :class:`~slingloads.io.common.schema.Parameter` by
        lower-case name (:func:`slingloads.io.analyses.all_parameters`).
        """
        rows = self._rows(sheet)
        header = [str(v).strip().lower() if v is not None else "" for v in rows[0]] if rows \
            else []
        for col, title in enumerate(("parameter", "value", "unit"), start=1):
            if len(header) < col or header[col - 1] != title:
                raise self.error(f"the {sheet} sheet needs the header 'parameter | value | "
                                 f"unit' in row 1; column {col} should be {title!r}",
                                 header[col - 1] if len(header) >= col else None, sheet,
                                 cell_name(1, col))
        out = {}
        for r, row in enumerate(rows[1:], start=2):
            row = tuple(row) + (None,) * 3
            name, raw, unit = row[0], row[1], row[2]
            if name is None or str(name).strip() == "":
                if raw is not None:
                    raise self.error("value without a parameter name", raw, sheet,
                                     cell_name(r, 1))
                continue
            key = str(name).strip().lower()
            if key not in known:
                renamed = next((p for p in known.values()
                                if key in (f.lower() for f in p.former)), None)
                if renamed is not None:
                    raise self.error(f"parameter renamed: use {renamed.name!r} ({renamed.help})",
                                     str(name), sheet, cell_name(r, 1))
                raise self.error(f"unknown parameter; valid parameters are "
                                 f"{sorted(known)}", str(name), sheet, cell_name(r, 1))
            if key in out:
                raise self.error("parameter appears twice", str(name), sheet, cell_name(r, 1))
            spec = known[key]
            where = cell_name(r, 2)
            unit_text = "" if unit is None else str(unit)
            if raw is None or (isinstance(raw, str) and not raw.strip()):
                if spec.kind == TEXT:
                    out[key] = ("", where)
                    continue
                raise self.error(f"empty value for parameter {spec.name!r} (delete the row "
                                 f"to use the default {spec.default!r} {spec.unit})", None,
                                 sheet, where)
            out[key] = (self._parameter_value(spec, raw, unit_text, sheet, r), where)
        return out

    def _parameter_value(self, spec, raw, unit_text, sheet, r):
        where = cell_name(r, 2)
        if spec.kind == TEXT:
            return str(raw).strip()
        if spec.kind == FLAG:
            return parse_flag(raw, spec.name, self.error, sheet, where, None)
        number = parse_number(raw, spec.name, self.error, sheet, where)
        if spec.kind == INTEGER:
            if not float(number).is_integer():
                raise self.error(f"{spec.name!r} must be a whole number", raw, sheet, where)
            return int(number)
        if spec.kind != "dimensionless" and not unit_text.strip():
            raise self.error(f"parameter {spec.name!r} needs a unit, e.g. {spec.unit!r}",
                             None, sheet, cell_name(r, 3))
        with located(self.file, sheet, cell_name(r, 3)):
            return number * si_factor(unit_text, spec.kind)


def check_unique(reader, table, column):
    """Raise an InputError at the second occurrence of a value repeated in ``column``."""
    seen = {}
    for i, value in enumerate(table[column]):
        if value in seen:
            raise reader.error(f"duplicate {column} (first at {table.cell(column, seen[value])})",
                               value, table.sheet, table.cell(column, i))
        seen[value] = i


def parse_number(raw, what, error, sheet, where):
    """A finite number from a cell value, or an error naming the cell."""
    if isinstance(raw, bool):
        raise error(f"{what!r} must be a number, not a true/false value", raw, sheet, where)
    if isinstance(raw, (int, float)):
        value = float(raw)
    elif isinstance(raw, str):
        try:
            value = float(raw.strip())
        except ValueError:
            raise error(f"{what!r} must be a number", raw, sheet, where) from None
    else:
        raise error(f"{what!r} must be a number", str(raw), sheet, where)
    if not math.isfinite(value):
        raise error(f"{what!r} must be a finite number", raw, sheet, where)
    return value


def parse_flag(raw, what, error, sheet, where, default):
    """A yes/no cell as bool."""
    if raw is None:
        if default is None:
            raise error(f"empty cell: {what!r} needs yes or no", None, sheet, where)
        raw = default
    if isinstance(raw, bool):
        return raw
    text = str(raw).strip().lower()
    if text in _TRUE:
        return True
    if text in _FALSE and text != "":
        return False
    raise error(f"{what!r} must be yes or no", raw, sheet, where)

"""Reading input workbooks: tables with units in their headers, parameters, precise errors.

Every problem raises :class:`~slingloads.errors.InputError` naming the file, the sheet, the
cell, the value as the user wrote it (with the unit of its header or unit cell) and the rule
it broke. A workbook is read in bounded memory and time whatever it holds:

* the file and its ZIP container are checked before anything is parsed: size on disk, number
  of parts, uncompressed size of each part and of the whole
  (:data:`slingloads.limits.MAX_UNCOMPRESSED_BYTES`: zip bombs);
* XML is parsed through ``defusedxml``, which refuses entity-expansion ("billion laughs") and
  external-entity attacks;
* sheets are streamed row by row (openpyxl's read-only mode, with only the rows kept), only the
  sheets slingloads knows are read, and each is read once; a sheet storing more than
  :data:`~slingloads.limits.MAX_SHEET_CELLS` cells (formatted empty cells count) is refused
  rather than parsed for minutes, and a table with more data rows than its schema allows is
  refused at the first row past the limit;
* no data is silently ignored: a value in a column without a header, or below a table's limit,
  is an error, not skipped;
* every number is checked against the bounds of its column or parameter
  (:class:`~slingloads.io.common.schema.Bounds`) and the magnitude limit of its kind
  (:data:`~slingloads.limits.MAX_MAGNITUDE`), every text against its length limit.

Tables are read fast without loosening any of this: a cell holding a plain number or an
inline string is read without openpyxl's per-cell parser (:func:`_simple_cell`, taken only
where that parser would do the same), and a column of numbers is checked and converted at once
(:meth:`WorkbookReader._columns_at_once`); any other cell goes through openpyxl's parser, and a
table with any bad cell is read again cell by cell (:meth:`WorkbookReader._records`), so that
the error names the first bad cell exactly as before (tests/test_workbook_fast_path.py).

Files a workbook refers to (CSV time histories) are opened through
:meth:`WorkbookReader.referenced_file`, which checks them the same way and records them as
inputs, so that no output ever replaces one.
"""

from __future__ import annotations

import csv
import io
import math
import os
import re
import stat
import zipfile
from pathlib import Path
from typing import NamedTuple

import numpy as np
from openpyxl.utils import get_column_letter

from slingloads.errors import InputError
from slingloads.io.common.schema import FLAG, INTEGER, NOTE_COLUMNS, STUDY_SHEET, TEXT
from slingloads.io.common.table import Table, cell_name, located
from slingloads.io.common.units import si_factor
from slingloads.io.common.values import (
    _FORMULA_HINT,
    _as_column,
    _as_text,
    _echo,
    _plain_quantities,
    check_quantity,
    number_from_text,
    parse_flag,
    parse_number,
    parse_text,
)
from slingloads.io.common.xlsx_source import (
    EXCEL_COLUMNS,
    EXCEL_ROWS,
    _check_prolog,
    _is_empty,
    _MemorySource,
    _part_kind,
    _why,
    _XlsxSource,
)
from slingloads.limits import (
    MAX_CSV_BYTES,
    MAX_CSV_ROWS,
    MAX_MAGNITUDE,
    MAX_PART_BYTES,
    MAX_PATH_CHARS,
    MAX_SHEET_CELLS,
    MAX_STUDY_ROWS,
    MAX_TEXT_CHARS,
    MAX_UNCOMPRESSED_BYTES,
    MAX_WORKBOOK_BYTES,
    MAX_ZIP_MEMBERS,
)

_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*(\[(?P<unit>[^\[\]]*)\])?\s*$")


class ParameterValue(NamedTuple):
    """A Study-sheet parameter as read: SI value, cell, value as written, unit as written."""

    value: object
    cell: str
    raw: object
    unit: str


class WorkbookReader:
    """An opened input workbook.

    Parameters
    ----------
    path : str or Path
        The ``.xlsx`` file.

    Use :meth:`from_rows` to read sheets given in memory (tests). Close it (or use it as a
    context manager) to release the file.
    """

    def __init__(self, path, *, _source=None):
        self.path = Path(path)
        self.file = str(path)
        self._referenced = []
        #: Implausible but possible inputs, shown on the reports' Summary.
        self.warnings = []
        self._tables = {}
        self._cells_read = {}
        if _source is None:
            self._check_file()
            self._check_container()
            _source = _XlsxSource(self.path, lambda rule, value: self.error(rule, value))
        self._source = _source

    @classmethod
    def from_rows(cls, sheets, file="workbook.xlsx"):
        """A reader of sheets given as ``{name: [row 1 values, row 2 values, ...]}``.

        ``file`` names the workbook in messages; files the sheets refer to are looked for
        relative to its folder.
        """
        return cls(file, _source=_MemorySource(sheets))

    def close(self):
        self._source.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    @property
    def book(self):
        """The openpyxl read-only workbook (None for sheets given in memory)."""
        return getattr(self._source, "book", None)

    @property
    def input_files(self):
        """The workbook and every file it referred to that was read, in order, once each."""
        files = [self.path] + self._referenced
        return list(dict.fromkeys(files))

    # ---- checks of the file ---------------------------------------------------------------
    def _check_file(self):
        try:
            info = os.stat(self.path)
        except (FileNotFoundError, NotADirectoryError):
            raise InputError("input workbook not found", self.file, file=self.file) from None
        except (OSError, ValueError) as err:
            raise InputError(f"cannot open the input workbook ({_why(err)})", self.file,
                             file=self.file) from None
        if stat.S_ISDIR(info.st_mode):
            raise InputError("the input is a folder, not an .xlsx workbook", self.file,
                             file=self.file)
        if not stat.S_ISREG(info.st_mode):
            raise InputError("the input is not a regular file (a device, pipe or socket)",
                             self.file, file=self.file)
        if self.path.suffix.lower() not in (".xlsx", ".xlsm"):
            raise InputError("input must be an Excel .xlsx workbook (save older .xls files "
                             "as .xlsx)", self.path.suffix, file=self.file)
        if info.st_size > MAX_WORKBOOK_BYTES:
            raise InputError(f"workbook refused: {info.st_size:,} bytes, more than the "
                             f"{MAX_WORKBOOK_BYTES:,} accepted", file=self.file)
        try:
            with open(self.path, "rb"):
                pass
        except OSError as err:
            raise InputError(f"cannot read the input workbook ({_why(err)})", self.file,
                             file=self.file) from None

    def _check_container(self):
        try:
            with zipfile.ZipFile(self.path) as archive:
                infos = archive.infolist()
                self._check_sizes(infos)
                for info in infos:  # every worksheet, read or not: no DTD, no entities
                    if _part_kind(info.filename) == "worksheet":
                        with archive.open(info) as source:
                            _check_prolog(source, lambda rule, value: self.error(rule, value))
        except InputError:
            raise
        except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, ValueError, EOFError,
                NotImplementedError) as err:
            raise InputError(f"not a workbook: the file is not an .xlsx (zip) container "
                             f"({str(err)[:200]})", file=self.file) from None

    def _check_sizes(self, infos):
        if len(infos) > MAX_ZIP_MEMBERS:
            raise InputError(f"workbook refused: {len(infos):,} parts in its container, more "
                             f"than the {MAX_ZIP_MEMBERS:,} accepted", file=self.file)
        total = 0
        for info in infos:
            total += info.file_size
            limit = MAX_PART_BYTES.get(_part_kind(info.filename))
            if limit is not None and info.file_size > limit:
                raise InputError(f"workbook refused: its part {info.filename[:100]!r} expands "
                                 f"to {info.file_size:,} bytes, more than the {limit:,} "
                                 "accepted (possible zip bomb)", file=self.file)
        if total > MAX_UNCOMPRESSED_BYTES:
            raise InputError(f"workbook refused: its content expands to {total:,} bytes, more "
                             f"than the {MAX_UNCOMPRESSED_BYTES:,} accepted (possible zip "
                             "bomb)", file=self.file)

    # ---- sheets ---------------------------------------------------------------------------
    @property
    def sheetnames(self):
        return self._source.sheetnames

    def has_sheet(self, name):
        return self._sheet(name) is not None

    def _sheet(self, name):
        """The workbook's name of sheet ``name``: the one sheet whose name matches it with
        case and surrounding spaces ignored; None if there is none.

        Raises
        ------
        InputError
            If two sheets match (``Study`` and `` STUDY ``): which one is meant is not for
            the reader to guess.
        """
        names = self._source.sheetnames
        matches = [n for n in names if n.strip().casefold() == name.casefold()]
        if len(matches) > 1:
            raise self.error(f"{len(matches)} sheets match {name!r} (case and surrounding "
                             f"spaces ignored): {', '.join(repr(n) for n in matches)}; delete "
                             "or rename all but one", sheet=matches[1])
        return matches[0] if matches else None

    def error(self, rule, value=None, sheet=None, cell=None, unit=None):
        """An InputError located in this file."""
        return InputError(rule, value, file=self.file, sheet=sheet, cell=cell, unit=unit)

    def rows(self, name, max_rows, first_data_row=2):
        """The non-empty rows of sheet ``name``: ``[(row number, {column: value})]``.

        Parameters
        ----------
        name : str
        max_rows : int
            Most non-empty rows from ``first_data_row`` on; one more is an error at its row.
        first_data_row : int
            First row counted against ``max_rows`` (rows above are headers).

        Raises
        ------
        InputError
            If the sheet is missing, stores more than
            :data:`~slingloads.limits.MAX_SHEET_CELLS` cells, has more rows than allowed, or
            is corrupt.
        """
        actual = self._sheet(name)
        if actual is None:
            raise self.error(f"missing sheet {name!r}; the workbook has "
                             f"{_shorten(self._source.sheetnames)}", sheet=name)
        out = []
        cells = 0
        last = 0
        data_rows = 0
        try:
            for r, values, stored in self._source.rows(actual):
                cells += stored
                if cells > MAX_SHEET_CELLS:
                    raise self.error(f"the sheet stores more than {MAX_SHEET_CELLS:,} cells "
                                     "(formatted empty cells count): delete its unused rows "
                                     "and columns", sheet=name, cell=cell_name(r, 1))
                if not 1 <= r <= EXCEL_ROWS or r <= last:
                    raise self.error("corrupt sheet: rows out of order or beyond Excel's "
                                     "limit", r, name)
                last = r
                if not values:
                    continue
                if not (1 <= min(values) and max(values) <= EXCEL_COLUMNS):
                    # the first in the order of the cells (a column keeps its first place)
                    beyond = next(c for c in values if not 1 <= c <= EXCEL_COLUMNS)
                    raise self.error("corrupt sheet: a column beyond Excel's limit", beyond,
                                     name)
                if r >= first_data_row:
                    data_rows += 1
                    if data_rows > max_rows:
                        raise self.error(f"too many rows: at most {max_rows:,} data rows are "
                                         "allowed on this sheet (limits of slingloads)",
                                         sheet=name, cell=cell_name(r, min(values)))
                out.append((r, values))
        except InputError as err:
            raise err.located(file=self.file, sheet=name) from None
        except (OSError, zipfile.BadZipFile, EOFError, ValueError, KeyError,
                SyntaxError) as err:
            # defusedxml refusals are ValueErrors, XML syntax errors SyntaxErrors; a corrupt
            # stream raises the others
            raise self.error(f"corrupt or refused sheet ({type(err).__name__}: "
                             f"{str(err)[:200]})", sheet=name) from None
        return out

    def table(self, spec):
        """Read the table sheet described by ``spec`` (a :class:`TableSheet`), once."""
        if spec.name not in self._tables:
            self._tables[spec.name] = self._read_table(spec)
        return self._tables[spec.name]

    def _read_table(self, spec):
        rows = self.rows(spec.name, spec.max_rows)
        if not rows or rows[0][0] != 1:
            raise self.error("sheet has no header row (row 1)", sheet=spec.name, cell="A1")
        header = rows[0][1]
        found = self._columns(spec, header)
        last = max(header)
        records = rows[1:]
        for column in spec.columns:
            if column.required and column.name not in found:
                raise self._missing_column(spec, column, header, records, last)
        columns = self._columns_at_once(spec, header, found, records)
        if columns is None:  # some cell breaks a rule: the careful path names the first one
            columns = self._records(spec, header, found, records)
        values, raw, cells = columns
        if not values or not len(next(iter(values.values()))):
            raise self.error("sheet has no data rows below its header", sheet=spec.name,
                             cell="A2")
        units = {name: found[name][3] for name in found}
        return Table(spec.name, values, cells, units, raw, self.file)

    def _records(self, spec, header, found, records):
        """``(values, raw, cells)`` of the table read record by record, cell by cell.

        The careful path: the cells are checked in the order of the sheet (row by row, then
        the columns in header order), so that the first bad cell raises its located error.

        Parameters
        ----------
        spec : TableSheet
        header : dict
            Column number -> header (None for a note column).
        found : dict
            The table's columns (:meth:`_columns`).
        records : list
            ``(row number, {column number: value})`` of the data rows.

        Returns
        -------
        values, raw, cells : dict
            By column name: SI values (ndarray for numbers, list for text and flags), the cell
            values as written, the cell coordinates.
        """
        values = {c.name: [] for c in spec.columns if c.name in found}
        raw = {name: [] for name in values}
        cells = {name: [] for name in values}
        for r, row in records:
            for col in row:
                if col not in header:
                    raise self.error("value in a column without a header (give the column a "
                                     "header, or clear the cell)", _echo(row[col]),
                                     spec.name, cell_name(r, col))
            for col, column, factor, unit in found.values():
                value = row.get(col)
                where = cell_name(r, col)
                values[column.name].append(
                    self._value(value, column, factor, unit, spec.name, where))
                raw[column.name].append(value)
                cells[column.name].append(where)
        arrays = {name: _as_column(vals, found[name][1].kind) for name, vals in values.items()}
        return arrays, raw, cells

    def _missing_column(self, spec, column, header, records, last):
        """The error of a required column that no header names: at the first column holding
        values under an empty header cell (a merged or cleared header), which is likely the
        one, else at the cell after the last header."""
        unit = f" [{column.unit}]" if column.unit else ""
        kind = f" (any {column.kind} unit)" if column.unit else ""
        stray = sorted({c for _, row in records for c in row if c not in header})
        if stray:
            where = cell_name(1, stray[0])
            return self.error(f"missing column '{column.name}{unit}'{kind}, and column "
                              f"{where.rstrip('0123456789')} holds values under an empty "
                              f"header cell (a merged or cleared header?): give it its "
                              "header", None, spec.name, where)
        return self.error(f"missing column '{column.name}{unit}'{kind}", sheet=spec.name,
                          cell=cell_name(1, last + 1))

    def _columns_at_once(self, spec, header, found, records):
        """``(values, raw, cells)`` of the table read column by column, or None if any cell
        breaks a rule (then :meth:`_records` reads it again to name the first bad cell).

        The fast path, giving exactly what :meth:`_records` gives for a table without a bad
        cell: a column of plain numbers (Python ``int`` and ``float``, nearly every numeric
        column) is checked and converted at once (:func:`_plain_quantities`); any other
        column goes through :meth:`_value` cell by cell. It raises nothing: errors are left
        to the careful path, which finds them in the order of the sheet.
        """
        if not set().union(*(row for _, row in records)) <= set(header):
            return None  # a value in a column without a header
        numbers = [str(r) for r, _ in records]
        values, raw, cells = {}, {}, {}
        for col, column, factor, unit in found.values():
            name = column.name
            raw[name] = [row.get(col) for _, row in records]
            letter = get_column_letter(col)
            cells[name] = [letter + r for r in numbers]  # cell_name(r, col) of each
            try:
                array = _plain_quantities(raw[name], column, factor)
                if array is None:
                    array = _as_column([self._value(v, column, factor, unit, spec.name, where)
                                        for v, where in zip(raw[name], cells[name],
                                                            strict=True)], column.kind)
            except Exception:  # noqa: BLE001 - any error is raised again by the careful path
                return None
            values[name] = array
        return values, raw, cells

    def _columns(self, spec, header):
        """``{column name: (column number, Column, SI factor, unit as written)}``."""
        exact = {c.name: c for c in spec.columns}
        folded = {}
        for c in spec.columns:
            folded.setdefault(c.name.lower(), []).append(c)
        found = {}
        for col in sorted(header):
            text = header[col]
            where = cell_name(1, col)
            if not isinstance(text, str):
                text = _as_text(text)
            match = _HEADER.match(text)
            name = (match.group("name") if match else text).strip()
            unit = match.group("unit") if match and match.group("unit") is not None else None
            if name.lower() in NOTE_COLUMNS:
                header[col] = None  # a note column: its cells are free text
                continue
            # exact names first (CL and Cl differ), else a unique case-insensitive match
            candidates = folded.get(name.lower(), [])
            column = exact.get(name) or (candidates[0] if len(candidates) == 1 else None)
            if column is None:
                raise self.error(f"unknown column; valid columns are "
                                 f"{[c.header for c in spec.columns]}", _echo(text),
                                 spec.name, where)
            if column.name in found:
                raise self.error("column appears twice", _echo(text), spec.name, where)
            factor = 1.0
            if column.kind not in (TEXT, FLAG, INTEGER):
                if unit is None and column.kind != "dimensionless":
                    raise self.error(f"header needs a unit in brackets, e.g. "
                                     f"'{column.name} [{column.unit}]'", _echo(text),
                                     spec.name, where)
                with located(self.file, spec.name, where):
                    factor = si_factor(unit or "", column.kind)
            elif unit is not None and unit.strip() not in ("", "-"):
                raise self.error(f"column {column.name!r} takes no unit", _echo(text),
                                 spec.name, where)
            found[column.name] = (col, column, factor, (unit or "").strip())
        return found

    def _value(self, raw, column, factor, unit, sheet, where):
        header = f"{column.name} [{unit}]" if unit else column.header  # as written
        if column.kind == TEXT:
            if _is_empty(raw):
                if column.required:
                    raise self.error(f"empty cell in required column {header!r}"
                                     f"{_FORMULA_HINT}", None, sheet, where)
                return column.default
            return parse_text(raw, header, column.char_limit, self.error, sheet, where)
        if column.kind == FLAG:
            return parse_flag(raw, header, self.error, sheet, where, column.default)
        if _is_empty(raw):
            if column.required:
                raise self.error(f"empty cell in required column {header!r}"
                                 f"{_FORMULA_HINT}", None, sheet, where)
            return column.default
        number = parse_number(raw, header, self.error, sheet, where)
        return check_quantity(number, raw, column.kind, factor, unit, column.bounds,
                              column.unit, column.name, self.error, sheet, where)

    # ---- the Study sheet ------------------------------------------------------------------
    def parameters(self, known, sheet=STUDY_SHEET):
        """Read the ``Study`` sheet: ``{name: ParameterValue}`` for every row present.

        ``known`` gives every valid :class:`~slingloads.io.common.schema.Parameter` by
        lower-case name (:func:`slingloads.io.analyses.all_parameters`).
        """
        rows = self.rows(sheet, MAX_STUDY_ROWS)
        header = rows[0][1] if rows and rows[0][0] == 1 else {}
        for col, title in enumerate(("parameter", "value", "unit"), start=1):
            got = header.get(col)
            text = _as_text(got).strip().lower() if got is not None else ""
            if text != title:
                raise self.error(f"the {sheet} sheet needs the header 'parameter | value | "
                                 f"unit' in row 1; column {col} should be {title!r}",
                                 _echo(got), sheet, cell_name(1, col))
        out = {}
        for r, row in rows[1:]:
            stray = next((c for c in sorted(row) if c not in header), None)
            if stray is not None:
                raise self.error("value in a column without a header (give the column a "
                                 "header, e.g. 'notes', or clear the cell)", _echo(row[stray]),
                                 sheet, cell_name(r, stray))
            name, raw, unit = row.get(1), row.get(2), row.get(3)
            if name is None:
                if raw is not None or unit is not None:
                    raise self.error("value without a parameter name", _echo(
                        raw if raw is not None else unit), sheet, cell_name(r, 1))
                continue
            key = _as_text(name).strip().lower()
            if key not in known:
                renamed = next((p for p in known.values()
                                if key in (f.lower() for f in p.former)), None)
                if renamed is not None:
                    raise self.error(f"parameter renamed: use {renamed.name!r} ({renamed.help})",
                                     _echo(name), sheet, cell_name(r, 1))
                raise self.error(_unknown_parameter(key, known), _echo(name), sheet,
                                 cell_name(r, 1))
            if key in out:
                raise self.error("parameter appears twice", _echo(name), sheet,
                                 cell_name(r, 1))
            spec = known[key]
            where = cell_name(r, 2)
            unit_text = "" if unit is None else _as_text(unit)
            if raw is None:
                if spec.kind == TEXT:
                    out[key] = ParameterValue("", where, raw, unit_text)
                    continue
                raise self.error(f"empty value for parameter {spec.name!r} (delete the row "
                                 f"to use the default {spec.default!r} {spec.unit})"
                                 f"{_FORMULA_HINT}", None, sheet, where)
            value = self._parameter_value(spec, raw, unit_text, sheet, r)
            out[key] = ParameterValue(value, where, raw, unit_text.strip())
        return out

    def _parameter_value(self, spec, raw, unit_text, sheet, r):
        where = cell_name(r, 2)
        # a text parameter with a unit is a list of numbers in that unit (read by its analysis)
        unit_free = spec.kind in (FLAG, INTEGER) or (spec.kind == TEXT and not spec.unit)
        if unit_free and unit_text.strip() not in ("", "-"):
            raise self.error(f"parameter {spec.name!r} takes no unit (leave the unit cell "
                             "empty)", _echo(unit_text), sheet, cell_name(r, 3))
        if spec.kind == TEXT:
            return parse_text(raw, spec.name, MAX_TEXT_CHARS, self.error, sheet, where)
        if spec.kind == FLAG:
            return parse_flag(raw, spec.name, self.error, sheet, where, None)
        number = parse_number(raw, spec.name, self.error, sheet, where)
        if spec.kind != "dimensionless" and spec.kind != INTEGER and not unit_text.strip():
            raise self.error(f"parameter {spec.name!r} needs a unit, e.g. {spec.unit!r}",
                             None, sheet, cell_name(r, 3))
        factor = 1.0
        if spec.kind != INTEGER:
            with located(self.file, sheet, cell_name(r, 3)):
                factor = si_factor(unit_text, spec.kind)
        return check_quantity(number, raw, spec.kind, factor, unit_text.strip(), spec.bounds,
                              spec.unit, spec.name, self.error, sheet, where)

    # ---- files the workbook refers to -----------------------------------------------------
    def referenced_file(self, text, sheet, cell, *, suffixes=(".csv",),
                        max_bytes=MAX_CSV_BYTES):
        """The path of a file named in a cell, checked, and recorded as an input.

        A relative path is taken from the workbook's folder. The file must be a regular file
        (not a folder, device or pipe) with one of ``suffixes`` and at most ``max_bytes``.

        Raises
        ------
        InputError
            At ``sheet``/``cell``, echoing the path as written.
        """
        where = (sheet, cell)
        if len(text) > MAX_PATH_CHARS:
            raise self.error(f"a file path must have at most {MAX_PATH_CHARS} characters",
                             _echo(text), *where)
        if "\x00" in text:
            raise self.error("a file path must not contain a NUL character", _echo(text),
                             *where)
        path = Path(text)
        if not path.is_absolute():
            path = self.path.resolve().parent / path
        if path.suffix.lower() not in suffixes:
            raise self.error(f"the file must be one of {list(suffixes)}", text, *where)
        try:
            info = os.stat(path)
        except (FileNotFoundError, NotADirectoryError):
            raise self.error("file not found (a relative path is taken from the workbook's "
                             "folder)", text, *where) from None
        except (OSError, ValueError) as err:
            raise self.error(f"cannot open the file ({_why(err)})", text, *where) from None
        if not stat.S_ISREG(info.st_mode):
            raise self.error("not a regular file (a folder, device or pipe)", text, *where)
        if info.st_size > max_bytes:
            raise self.error(f"file refused: {info.st_size:,} bytes, more than the "
                             f"{max_bytes:,} accepted", text, *where)
        self._referenced.append(path)
        return path

    def csv_columns(self, text, sheet, cell, columns, max_rows=MAX_CSV_ROWS):
        """Numeric columns of a CSV file named in a cell, in SI.

        Parameters
        ----------
        text : str
            The path as written in the cell (see :meth:`referenced_file`).
        sheet, cell : str
            Where the path was written; every error is located there and names the file's
            column and data row.
        columns : dict
            Wanted column name (case-insensitive, without the unit) -> quantity kind. Every
            header must carry its unit in brackets, ``t [s]``.
        max_rows : int
            Most data rows.

        Returns
        -------
        dict
            Column name -> SI values (ndarray).
        """
        path = self.referenced_file(text, sheet, cell)
        where = (sheet, cell)
        name = path.name
        try:
            with open(path, encoding="utf-8-sig", newline="") as handle:
                content = handle.read()
        except (OSError, UnicodeDecodeError) as err:
            raise self.error(f"cannot read the CSV file {name!r} ({_why(err)})", text,
                             *where) from None
        try:
            reader = csv.reader(io.StringIO(content))
            header = next(reader, None)
        except csv.Error as err:
            raise self.error(f"CSV {name}: not a CSV file ({err})", text, *where) from None
        if not header:
            raise self.error(f"CSV {name}: the file is empty (it needs a header row)", text,
                             *where)
        index = {}
        for j, head in enumerate(header):
            label, _, unit = head.partition("[")
            key = label.strip().lower()
            if key in {c.lower() for c in columns}:
                if key in index:
                    raise self.error(f"CSV {name}: column {label.strip()!r} appears twice",
                                     text, *where)
                index[key] = (j, head, unit.rstrip("] ").strip())
        wanted = {c.lower(): (c, kind) for c, kind in columns.items()}
        missing = [c for c in wanted if c not in index]
        if missing:
            raise self.error(f"CSV {name}: needs the columns "
                             f"{[f'{wanted[c][0]} [unit]' for c in wanted]}",
                             _echo(", ".join(header)), *where)
        factors = {}
        for key, (_label, kind) in wanted.items():
            _, head, unit = index[key]
            if not unit:
                raise self.error(f"CSV {name}: column {head!r} needs a unit in brackets",
                                 text, *where)
            with located(self.file, *where):
                factors[key] = si_factor(unit, kind)
        data = {key: [] for key in wanted}
        try:
            for k, row in enumerate(reader, start=1):
                if not any(v.strip() for v in row):
                    continue
                if k > max_rows:
                    raise self.error(f"CSV {name}: at most {max_rows:,} data rows are "
                                     "allowed", text, *where)
                for key, (_label, kind) in wanted.items():
                    j, head, unit = index[key]
                    cell_text = row[j] if j < len(row) else ""
                    value = number_from_text(cell_text)
                    if value is None:
                        value = math.nan
                    if not math.isfinite(value):
                        raise self.error(f"CSV {name}: column {head!r}, data row {k} is not a "
                                         "finite number", _echo(cell_text), *where)
                    if abs(value * factors[key]) > MAX_MAGNITUDE[kind]:
                        raise self.error(f"CSV {name}: column {head!r}, data row {k} is beyond "
                                         f"the largest accepted {kind} "
                                         f"{MAX_MAGNITUDE[kind] / factors[key]:.6g} {unit}",
                                         _echo(cell_text), *where)
                    data[key].append(value * factors[key])
        except csv.Error as err:
            raise self.error(f"CSV {name}: malformed ({err})", text, *where) from None
        return {wanted[key][0]: np.asarray(v, dtype=float) for key, v in data.items()}


def _shorten(names, n=30):
    names = list(names)
    return names if len(names) <= n else names[:n] + [f"... {len(names) - n} more"]


def _unknown_parameter(key, known):
    """The rule broken by an unknown Study parameter: the closest valid names, or where the
    whole list is (there are too many to quote)."""
    import difflib

    close = difflib.get_close_matches(key, list(known), n=3, cutoff=0.6)
    hint = f"did you mean {' or '.join(repr(known[c].name) for c in close)}? " if close else ""
    return (f"unknown parameter; {hint}the valid parameters are on the Study sheet of "
            f"'slingloads template' and in docs/ ({len(known)} in all)")


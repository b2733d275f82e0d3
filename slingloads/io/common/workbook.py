"""The typed sheet reader: an input workbook's sheets read as tables with units in their
headers, every value checked, every problem located.

What this module guarantees: every problem raises :class:`~slingloads.errors.InputError`
naming the file, the sheet, the cell, the value as the user wrote it (with the unit of its
header) and the rule it broke; and a workbook is read in bounded memory and time whatever it
holds:

* the file is opened through :mod:`slingloads.io.common.xlsx_source`, which checks it and its
  ZIP container before anything is parsed (zip and XML bombs) and streams each sheet row by
  row; only the sheets slingloads knows are read, each once, and a sheet whose name two sheets
  match (case and surrounding spaces ignored) is refused;
* a sheet storing more than :data:`~slingloads.limits.MAX_SHEET_CELLS` cells (formatted
  empty cells count) is refused rather than parsed for minutes, and a table with more data
  rows than its schema allows is refused at the first row past the limit;
* no data is silently ignored: a value in a column without a header, or below a table's
  limit, is an error, not skipped; a header names a known column once, with a unit of the
  column's kind;
* every value is checked as :mod:`slingloads.io.common.values` states (numbers against the
  bounds of their column and the magnitude limit of their kind, texts against their length
  limit) and kept with its cell and the value as written
  (:class:`~slingloads.io.common.table.Table`).

Tables are read fast without loosening any of this: a column of plain numbers is checked and
converted at once (:meth:`WorkbookReader._columns_at_once`), and a table with any bad cell is
read again cell by cell (:meth:`WorkbookReader._records`), so that the error names the first
bad cell exactly as the careful path does (tests/test_workbook_fast_path.py).

The Study sheet is read by :func:`slingloads.io.common.parameters.read_parameters`, files a
workbook refers to (CSV time histories) by :mod:`slingloads.io.common.referenced`.
"""

from __future__ import annotations

import re
import zipfile
from pathlib import Path

from openpyxl.utils import get_column_letter

from slingloads.errors import ErrorCollector, InputError
from slingloads.ids import check_unique
from slingloads.io.common.locate import Place, located, place_error
from slingloads.io.common.schema import FLAG, INTEGER, NOTE_COLUMNS, TEXT
from slingloads.io.common.table import Table, cell_name
from slingloads.io.common.units import si_factor
from slingloads.io.common.values import (
    FORMULA_HINT,
    as_column,
    as_text,
    check_quantity,
    echo,
    parse_flag,
    parse_number,
    parse_text,
    plain_quantities,
)
from slingloads.io.common.xlsx_source import (
    EXCEL_COLUMNS,
    EXCEL_ROWS,
    MemorySource,
    XlsxSource,
    check_container,
    check_file,
    is_empty,
)
from slingloads.limits import (
    MAX_SHEET_CELLS,
)

_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*(\[(?P<unit>[^\[\]]*)\])?\s*$")


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
        self._filled = {}
        self._cells_read = {}
        if _source is None:
            check_file(self.path, self.file)
            check_container(self.path, self.file)
            _source = XlsxSource(self.path, lambda rule, value: self.error(rule, value))
        self._source = _source

    @classmethod
    def from_rows(cls, sheets, file="workbook.xlsx"):
        """A reader of sheets given as ``{name: [row 1 values, row 2 values, ...]}``.

        ``file`` names the workbook in messages; files the sheets refer to are looked for
        relative to its folder.
        """
        return cls(file, _source=MemorySource(sheets))

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

    def record_input(self, path):
        """Record ``path``, a file the workbook refers to, as an input of the study (so that
        no output ever replaces it)."""
        self._referenced.append(path)

    @property
    def input_files(self):
        """The workbook and every file it referred to that was read, in order, once each."""
        files = [self.path] + self._referenced
        return list(dict.fromkeys(files))

    # ---- sheets ---------------------------------------------------------------------------
    @property
    def sheetnames(self):
        return self._source.sheetnames

    def has_sheet(self, name):
        """True when the workbook has sheet ``name`` with something below its header row: a
        sheet left as the template wrote it (headers only) counts as deleted, so that an
        optional sheet need not be removed before a run."""
        actual = self._sheet(name)
        if actual is None:
            return False
        if actual not in self._filled:
            try:
                self._filled[actual] = any(r > 1 and values
                                           for r, values, _ in self._source.rows(actual))
            except Exception:  # noqa: BLE001 - a corrupt sheet: reading it says how
                self._filled[actual] = True
        return self._filled[actual]

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
            raise place_error(err, Place(self.file, name)) from None
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
        errors = ErrorCollector()  # every bad header, then every bad cell, at once
        found, named = self._columns(spec, header, errors)
        if errors and not named:  # no header at all (deleted, or the data moved up): one error
            first = header[min(header)]
            raise self.error(f"row 1 names none of the sheet's columns (was the header row "
                             f"deleted, or the table moved?); its columns are "
                             f"{[c.header for c in spec.columns]}", echo(first), spec.name,
                             cell_name(1, min(header)))
        last = max(header)
        records = rows[1:]
        for column in spec.columns:
            if column.required and column.name not in named:
                errors.add(self._missing_column(spec, column, header, records, last))
        errors.raise_if_any()
        columns = self._columns_at_once(spec, header, found, records)
        if columns is None:  # some cell breaks a rule: the careful path names the first one
            columns = self._records(spec, header, found, records)
        values, raw, cells = columns
        if not values or not len(next(iter(values.values()))):
            raise self.error("sheet has no data rows below its header", sheet=spec.name,
                             cell="A2")
        units = {name: found[name][3] for name in found}
        table = Table(spec.name, values, cells, units, raw, self.file)
        for column in spec.ids:  # the one uniqueness rule of ids, for every sheet
            if column in values:
                check_unique(table, column)
        return table

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
        errors = ErrorCollector()  # every bad cell of the table, in the order of the sheet
        for r, row in records:
            for col in row:
                if col not in header:
                    errors.add(self.error("value in a column without a header (give the "
                                          "column a header, or clear the cell)",
                                          echo(row[col]), spec.name, cell_name(r, col)))
            for col, column, factor, unit in found.values():
                value = row.get(col)
                where = cell_name(r, col)
                values[column.name].append(errors.call(
                    self._value, value, column, factor, unit, spec.name, where))
                raw[column.name].append(value)
                cells[column.name].append(where)
        errors.raise_if_any()
        arrays = {name: as_column(vals, found[name][1].kind) for name, vals in values.items()}
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
        column) is checked and converted at once (:func:`plain_quantities`); any other
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
                array = plain_quantities(raw[name], column, factor)
                if array is None:
                    array = as_column([self._value(v, column, factor, unit, spec.name, where)
                                        for v, where in zip(raw[name], cells[name],
                                                            strict=True)], column.kind)
            except Exception:  # noqa: BLE001 - any error is raised again by the careful path
                return None
            values[name] = array
        return values, raw, cells

    def _columns(self, spec, header, errors):
        """``{column name: (column number, Column, SI factor, unit as written)}`` of the
        columns read, and the names of every column a header names (read or in error); the
        error of each bad header is added to ``errors`` (an :class:`ErrorCollector`)."""
        exact = {c.name: c for c in spec.columns}
        folded = {}
        for c in spec.columns:
            folded.setdefault(c.name.lower(), []).append(c)
        found, named = {}, set()
        for col in sorted(header):
            errors.call(self._column, spec, header, col, exact, folded, found, named)
        return found, named

    def _column(self, spec, header, col, exact, folded, found, named):
        """Add header ``col`` to ``found`` (and its name to ``named``), or raise its error."""
        text = header[col]
        where = cell_name(1, col)
        if not isinstance(text, str):
            text = as_text(text)
        match = _HEADER.match(text)
        name = (match.group("name") if match else text).strip()
        unit = match.group("unit") if match and match.group("unit") is not None else None
        if name.lower() in NOTE_COLUMNS:
            header[col] = None  # a note column: its cells are free text
            return
        # exact names first (CL and Cl differ), else a unique case-insensitive match
        candidates = folded.get(name.lower(), [])
        column = exact.get(name) or (candidates[0] if len(candidates) == 1 else None)
        if column is None:
            raise self.error(f"unknown column; valid columns are "
                             f"{[c.header for c in spec.columns]}", echo(text),
                             spec.name, where)
        named.add(column.name)
        if column.name in found:
            raise self.error("column appears twice", echo(text), spec.name, where)
        factor = 1.0
        if column.kind not in (TEXT, FLAG, INTEGER):
            if unit is None and column.kind != "dimensionless":
                raise self.error(f"header needs a unit in brackets, e.g. "
                                 f"'{column.name} [{column.unit}]'", echo(text),
                                 spec.name, where)
            with located(Place(self.file, spec.name, where)):
                factor = si_factor(unit or "", column.kind)
        elif unit is not None and unit.strip() not in ("", "-"):
            raise self.error(f"column {column.name!r} takes no unit", echo(text),
                             spec.name, where)
        found[column.name] = (col, column, factor, (unit or "").strip())

    def _value(self, raw, column, factor, unit, sheet, where):
        header = f"{column.name} [{unit}]" if unit else column.header  # as written
        if column.kind == TEXT:
            if is_empty(raw):
                if column.required:
                    raise self.error(f"empty cell in required column {header!r}"
                                     f"{FORMULA_HINT}", None, sheet, where)
                return column.default
            return parse_text(raw, header, column.char_limit, self.error, sheet, where)
        if column.kind == FLAG:
            return parse_flag(raw, header, self.error, sheet, where, column.default)
        if is_empty(raw):
            if column.required:
                raise self.error(f"empty cell in required column {header!r}"
                                 f"{FORMULA_HINT}", None, sheet, where)
            return column.default
        number = parse_number(raw, header, self.error, sheet, where)
        return check_quantity(number, raw, column.kind, factor, unit, column.bounds,
                              column.unit, column.name, self.error, sheet, where)



def _shorten(names, n=30):
    names = list(names)
    return names if len(names) <= n else names[:n] + [f"... {len(names) - n} more"]

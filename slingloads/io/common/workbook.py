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

import contextlib
import csv
import io
import math
import os
import pyexpat
import re
import stat
import unicodedata
import warnings
import zipfile
from dataclasses import dataclass, field
from datetime import date, datetime, time, timedelta
from pathlib import Path
from typing import NamedTuple
from xml.etree.ElementTree import iterparse

import numpy as np
from openpyxl.utils import column_index_from_string, get_column_letter
from openpyxl.worksheet._reader import _cast_number

from slingloads.errors import InputError
from slingloads.io.common.schema import (
    FLAG,
    INTEGER,
    NOTE_COLUMNS,
    STUDY_SHEET,
    TEXT,
)
from slingloads.io.common.units import si_factor
from slingloads.limits import (
    MAX_CSV_BYTES,
    MAX_CSV_ROWS,
    MAX_ID_CHARS,
    MAX_MAGNITUDE,
    MAX_PART_BYTES,
    MAX_PATH_CHARS,
    MAX_SHEET_CELLS,
    MAX_SHEET_ELEMENTS,
    MAX_STUDY_ROWS,
    MAX_TEXT_CHARS,
    MAX_UNCOMPRESSED_BYTES,
    MAX_WORKBOOK_BYTES,
    MAX_ZIP_MEMBERS,
)

#: Excel's sheet size [rows, columns].
EXCEL_ROWS, EXCEL_COLUMNS = 1_048_576, 16_384
_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*(\[(?P<unit>[^\[\]]*)\])?\s*$")
_FORMULA_HINT = (" (or a formula whose value was never computed: open and save the workbook "
                 "in Excel or LibreOffice first)")
#: Control characters a workbook cell cannot hold (tab, line feed and carriage return can).
ILLEGAL_CHARACTERS_RE = re.compile(r"[\000-\010]|[\013-\014]|[\016-\037]")
_TRUE = {"yes", "y", "true", "1", "on", "x"}
_FALSE = {"no", "n", "false", "0", "off", ""}


_MAIN = "{http://schemas.openxmlformats.org/spreadsheetml/2006/main}"
_ROW_TAG, _CELL_TAG, _VALUE_TAG = f"{_MAIN}row", f"{_MAIN}c", f"{_MAIN}v"
_INLINE_TAG, _TEXT_TAG = f"{_MAIN}is", f"{_MAIN}t"
#: Elements that may be part of a cell (kept until their row is read).
_CELL_PARTS = frozenset(f"{_MAIN}{t}" for t in (
    "c", "v", "f", "is", "t", "r", "rPr", "rFont", "b", "i", "strike", "condense", "extend",
    "outline", "shadow", "u", "vertAlign", "sz", "color", "family", "charset", "scheme",
    "rPh", "phoneticPr"))


class _RootReached(Exception):
    """The prolog of an XML part was read to its first element."""


def _why_unreadable(err):
    """What openpyxl's error on an unreadable workbook says, in a user's words: a missing part
    of the package by its name, else the error's first line (without the Python class)."""
    if isinstance(err, KeyError) and err.args:
        return f"a part of an .xlsx file is missing: {str(err.args[0])[:200]}"
    text = str(err).splitlines()[0][:200] if str(err) else ""
    return text or "its content is not that of an .xlsx workbook"


def _check_prolog(source, error):
    """Refuse an XML part with a document type declaration (entity definitions: "billion
    laughs", external entities) before the fast C parser reads it. A DOCTYPE can only come
    before the first element, so expat reads the prolog alone and stops there."""
    parser = pyexpat.ParserCreate()

    def refuse(*_):
        raise error("not a readable .xlsx workbook: a sheet's XML declares a document type "
                    "(DTD) or entities, refused as a possible XML bomb; save the workbook "
                    "again in Excel or LibreOffice", None)

    def root(*_):
        raise _RootReached

    parser.StartDoctypeDeclHandler = refuse
    parser.EntityDeclHandler = refuse
    parser.StartElementHandler = root
    try:
        while True:
            chunk = source.read(1 << 12)  # small reads: the prolog is short, the rest unread
            parser.Parse(chunk, not chunk)
            if not chunk:
                return
    except _RootReached:
        return
    except pyexpat.ExpatError as err:
        raise error(f"corrupt sheet: not well-formed XML ({err})", None) from None


class CellError(str):
    """The value of a cell holding a spreadsheet error (``#DIV/0!``, ``#N/A``, ``#REF!``)."""


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


def _is_empty(value):
    return value is None or (isinstance(value, str) and not value.strip())


@dataclass
class Table:
    """A table read from a sheet: SI values per column, where each came from, as written.

    Attributes
    ----------
    sheet : str
    values : dict
        Column name -> SI values (ndarray for numbers, list for text and flags).
    cells : dict
        Column name -> cell coordinate of each value.
    units : dict
        Column name -> unit written in the header.
    raw : dict
        Column name -> the cell values as written.
    file : str
    """

    sheet: str
    values: dict
    cells: dict
    units: dict
    raw: dict = field(default_factory=dict)
    file: str | None = None

    def __len__(self):
        return len(next(iter(self.values.values()))) if self.values else 0

    def __getitem__(self, name):
        return self.values[name]

    def has(self, name):
        return name in self.values

    def cell(self, name, index):
        """Coordinate of the value of column ``name`` in record ``index``."""
        return self.cells[name][index]

    def shown(self, name, index):
        """``(value as written, unit of the header)`` of column ``name`` in record ``index``."""
        raw = self.raw.get(name)
        value = raw[index] if raw is not None else self.values[name][index]
        if isinstance(self.values[name], np.ndarray):
            value = _number_echo(value)
        return value, self.units.get(name) or None

    def error(self, name, index, rule):
        """An InputError at the cell of column ``name``, record ``index``, echoing the value as
        written with its unit."""
        value, unit = self.shown(name, index)
        return InputError(rule, value, file=self.file, sheet=self.sheet,
                          cell=self.cell(name, index), unit=unit)

    def require_filled(self, names, why):
        """Refuse the first empty cell (or formula never computed) of the number columns
        ``names`` that are optional in the sheet's schema but needed here (``why``)."""
        for name in names:
            values = self.values.get(name)
            if values is None or not isinstance(values, np.ndarray):
                continue
            empty = np.flatnonzero(np.isnan(values))
            if empty.size:
                raise self.error(name, int(empty[0]), f"empty cell in column "
                                 f"{self.header(name)!r}: {why}{_FORMULA_HINT}")

    def header(self, name):
        """Column ``name``'s header as written (with its unit, when it has one)."""
        unit = self.units.get(name)
        return f"{name} [{unit}]" if unit else name

    @contextlib.contextmanager
    def located(self, fields=None, cell=None):
        """Locate an :class:`InputError` a model raises on this table's values.

        An error that names its ``field`` (a model argument) and ``index`` (a record) is put at
        the cell of the column ``fields[field]`` (default: the column of that name) in that
        record, with the value as written; any other error at ``cell`` (default: the sheet).
        """
        fields = fields or {}
        try:
            yield
        except InputError as err:
            column = fields.get(err.field, err.field)
            if (err.cell is None and column in self.cells and err.index is not None
                    and 0 <= err.index < len(self.cells[column])):
                value, unit = self.shown(column, err.index)
                raise err.located(file=self.file, sheet=self.sheet,
                                  cell=self.cell(column, err.index), value=value,
                                  unit=unit) from None
            raise err.located(file=self.file, sheet=self.sheet, cell=cell) from None


class ParameterValue(NamedTuple):
    """A Study-sheet parameter as read: SI value, cell, value as written, unit as written."""

    value: object
    cell: str
    raw: object
    unit: str


class _MemorySource:
    """Sheets given as lists of rows (row 1 first), for tests and for building in memory."""

    def __init__(self, sheets):
        self.sheets = {str(k): list(v) for k, v in sheets.items()}
        self.sheetnames = list(self.sheets)

    def rows(self, name):
        """``(row number, {column: value}, cells stored)`` of each row, as
        :meth:`_XlsxSource.rows`."""
        for r, row in enumerate(self.sheets[name], start=1):
            values = list(row)
            yield r, {c: v for c, v in enumerate(values, start=1) if not _is_empty(v)}, len(values)

    def close(self):
        pass


@contextlib.contextmanager
def _no_dimension_scan():
    """Open read-only sheets without openpyxl's search for their ``<dimension>``: a sheet
    without one would be parsed whole (slowly) just to size it, and the rows are streamed
    here anyway."""
    from openpyxl.worksheet._read_only import ReadOnlyWorksheet

    original = ReadOnlyWorksheet._get_size
    ReadOnlyWorksheet._get_size = lambda self: None
    try:
        yield
    finally:
        ReadOnlyWorksheet._get_size = original


class _XlsxSource:
    """An .xlsx file streamed sheet by sheet with openpyxl's read-only machinery."""

    def __init__(self, path, error):
        from openpyxl import load_workbook

        self.error = error
        try:
            with warnings.catch_warnings(), _no_dimension_scan():
                warnings.simplefilter("ignore")  # unsupported extensions, data validation...
                self.book = load_workbook(path, read_only=True, data_only=True)
        except Exception as err:  # noqa: BLE001 - openpyxl raises many kinds on corrupt files
            root = err
            while root.__cause__ is not None or root.__context__ is not None:
                root = root.__cause__ or root.__context__
            raise error(f"not a readable .xlsx workbook ({_why_unreadable(root)}); save it "
                        "again from Excel or LibreOffice as an Excel workbook (.xlsx)",
                        None) from None
        self.sheetnames = list(self.book.sheetnames)
        #: ``s`` attribute of a cell (None if absent) -> how openpyxl reads a number of that
        #: style (see :func:`_style_kind`)
        self._styles = {}

    def rows(self, name):
        """``(row number, {column: value}, cells stored)`` for each row element of the sheet:
        the values of its non-empty cells by column (for a column given twice, its last
        non-empty value at the place of its first), and the number of cells it stores
        (empty cells are counted, not listed).

        Only end events are handled: a row is read when it ends and then cleared, and every
        element that cannot be part of a cell is cleared when it ends, so memory stays flat;
        the number of elements is capped (:data:`~slingloads.limits.MAX_SHEET_ELEMENTS`).
        """
        from openpyxl.worksheet._reader import WorkSheetParser

        ws = self.book[name]
        parser = WorkSheetParser(None, ws._shared_strings, data_only=True,
                                 epoch=self.book.epoch, date_formats=self.book._date_formats,
                                 timedelta_formats=self.book._timedelta_formats)
        count = in_row = 0
        # the limits as locals: this loop runs once per XML element of the sheet
        most, parts, widest = MAX_SHEET_ELEMENTS, _CELL_PARTS, 8 * EXCEL_COLUMNS
        with ws._get_source() as source:
            _check_prolog(source, self.error)
        with ws._get_source() as source:
            for _, element in iterparse(source):
                count += 1
                if count > most:
                    raise self.error(f"the sheet holds more than {MAX_SHEET_ELEMENTS:,} XML "
                                     "elements (cells, merged ranges, formats...): delete its "
                                     "unused rows and columns", None)
                tag = element.tag
                if tag in parts:  # (the most frequent: <c> and <v>; a row is not a part)
                    in_row += 1  # kept until its row ends: bounded by Excel's row width
                    if in_row > widest:
                        raise self.error("corrupt sheet: a row holds more cells than Excel "
                                         "allows", None)
                elif tag == _ROW_TAG:
                    in_row = 0
                    yield self._row(parser, element)
                    element.clear()
                else:
                    element.clear()

    def _row(self, parser, element):
        """``(row number, {column: value}, cells stored)`` of a ``<row>`` element (see
        :meth:`rows`).

        Plain numbers and inline strings (nearly every cell of a table) are read by
        :func:`_simple_cell`; every other cell by openpyxl's ``parse_cell`` (:meth:`_cell`).
        """
        r = element.get("r")
        try:
            parser.row_counter = int(r) if r is not None else parser.row_counter + 1
        except ValueError:
            raise self.error("corrupt sheet: invalid row number", r) from None
        # every coordinate of this row ends with this number (none can if it is not >= 1)
        suffix = str(parser.row_counter) if parser.row_counter >= 1 else None
        cut = -len(suffix) if suffix is not None else 0
        styles, date_formats = self._styles, parser.date_formats
        column = 0  # of the previous cell (openpyxl's parser.col_counter)
        values = {}
        for c in element:
            if c.tag != _CELL_TAG:
                continue
            if not len(c) and c.text is None:  # an empty (formatted) cell: nothing to read
                continue
            cell = _simple_cell(c, column, suffix, cut, styles, date_formats)
            if cell is None:
                parser.col_counter = column
                cell = self._cell(parser, c)
            column, value = cell
            if value is None or (isinstance(value, str) and not value.strip()):  # _is_empty
                continue
            values[column] = value
        return parser.row_counter, values, len(element)

    def _cell(self, parser, c):
        """``(column, value)`` of any cell, read by openpyxl's ``parse_cell`` (shared and
        inline strings, booleans, errors, dates by number format, formulas' cached values)."""
        try:
            cell = parser.parse_cell(c)
        except Exception:  # noqa: BLE001 - any malformed cell of a hostile file
            raise self.error("corrupt sheet: unreadable cell", c.get("r")) from None
        value = cell["value"]
        if cell["data_type"] == "e" and value is not None:
            value = CellError(value)
        if cell["row"] != parser.row_counter:
            raise self.error("corrupt sheet: a cell lies outside its row", c.get("r"))
        return cell["column"], value

    def close(self):
        self.book.close()


#: Column letters (upper case, as Excel writes them) -> column number, filled as met.
_COLUMN_NUMBERS = {}
_COLUMN_LETTERS = re.compile(r"[A-Z]{1,3}")


def _column_number(letters):
    """Column number of ``letters`` (``"C"`` -> 3), or None unless they are 1 to 3 upper-case
    letters (openpyxl's ``parse_cell`` then reads the coordinate itself)."""
    column = _COLUMN_NUMBERS.get(letters)
    if column is None and _COLUMN_LETTERS.fullmatch(letters):
        column = _COLUMN_NUMBERS[letters] = column_index_from_string(letters)
    return column


#: How openpyxl's ``parse_cell`` reads a number of a style (see :func:`_style_kind`).
_PLAIN, _DATE, _UNREADABLE = "plain", "date", "unreadable"


def _style_kind(style, date_formats):
    """How openpyxl's ``parse_cell`` reads a number of style attribute ``style`` (its text,
    None if absent): as a plain number (:data:`_PLAIN`), as a date or duration
    (:data:`_DATE`), or not at all (:data:`_UNREADABLE`: ``parse_cell`` raises on any cell of
    that style, which is then refused as unreadable)."""
    style_id = style if style is not None else 0  # as parse_cell: element.get('s', 0)
    if style_id:
        try:
            style_id = int(style_id)
        except ValueError:
            return _UNREADABLE
    return _DATE if style_id in date_formats else _PLAIN


def _simple_cell(c, previous, suffix, cut, styles, date_formats):
    """``(column, value)`` of a cell holding a plain number or an inline string, or None for
    any other cell (then read by openpyxl's ``parse_cell``).

    A shortcut of ``parse_cell`` for the cells of nearly every table, ``<c r="C7" t="n"><v>
    0.25</v></c>`` and ``<c r="A1" t="inlineStr"><is><t>CD</t></is></c>``. It is exact
    because it is taken only where ``parse_cell`` does the same few steps:

    * the coordinate is 1 to 3 upper-case letters followed by the row's own number
      ``suffix`` (so the cell lies in its row), or absent (the column after ``previous``);
    * a number (type ``n`` or none) has one child, its ``<v>`` value with text (no formula),
      and a style that is not a date or duration format; its text is converted by
      openpyxl's own ``_cast_number`` (a text it refuses is left to ``parse_cell``);
    * an inline string has one child ``<is>`` without attributes holding one ``<t>``
      without children, and a style ``parse_cell`` can read; its value is the text of
      ``<t>`` (``""`` if none), as openpyxl's ``Text.content`` gives it.

    Parameters
    ----------
    c : Element
        The ``<c>`` element.
    previous : int
        Column of the previous cell of the row (0 for the first): openpyxl's
        ``parser.col_counter``.
    suffix : str or None
        The row number as text; None if the row number is not >= 1.
    cut : int
        ``-len(suffix)``.
    styles : dict
        Cache of :func:`_style_kind` by style attribute.
    date_formats : set
        The workbook's date and duration formats (style ids).
    """
    if suffix is None or len(c) != 1:
        return None
    kind = c.get("t", "n")
    child = c[0]
    if kind == "n":
        text = child.text
        if child.tag != _VALUE_TAG or not text:
            return None
    elif kind == "inlineStr":
        if child.tag != _INLINE_TAG or child.attrib or len(child) != 1:
            return None
        text = child[0]
        if text.tag != _TEXT_TAG or len(text):
            return None
    else:
        return None
    style = c.get("s")
    how = styles.get(style)
    if how is None:
        how = styles[style] = _style_kind(style, date_formats)
    if how != _PLAIN and (kind == "n" or how == _UNREADABLE):
        return None
    coordinate = c.get("r")
    if coordinate is None:
        column = previous + 1
    elif coordinate.endswith(suffix):
        letters = coordinate[:cut]
        column = _COLUMN_NUMBERS.get(letters) or _column_number(letters)
        if column is None:
            return None
    else:
        return None
    if kind == "n":
        try:
            return column, _cast_number(text)
        except ValueError:
            return None
    return column, text.text or ""


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


def _as_column(values, kind):
    """The values of a column as a Table holds them: a list for text and flags, else an
    ndarray of floats."""
    return values if kind in (TEXT, FLAG) else np.asarray(values, dtype=float)


def _plain_quantities(raw, column, factor):
    """SI values of a column of plain numbers, or None unless every cell passes every check.

    The column-at-once form of :func:`parse_number` and :func:`check_quantity`, giving the
    same float for each cell: it applies only to a numeric column (not text, flag or integer)
    whose cells are all Python ``int`` or ``float`` (not ``bool``: no empty cell, no text,
    date or spreadsheet error), converted by ``float`` as :func:`parse_number` does, then
    multiplied by ``factor`` in IEEE double precision as the scalar path does. The magnitude
    limit and the bounds are checked on the whole column; the bounds through
    :meth:`Bounds.contains` itself on each distinct value (``np.unique`` merges 0.0 and -0.0,
    which every comparison treats alike). None means "read cell by cell": a value that is
    not a plain number, or any cell that breaks a rule (the careful path then names it).

    Parameters
    ----------
    raw : list
        The cell values as read.
    column : Column
    factor : float
        SI factor of the header's unit.

    Returns
    -------
    ndarray or None
    """
    kind = column.kind
    # exact types: bool (a subclass of int), numpy scalars and the like go cell by cell
    if kind in (TEXT, FLAG, INTEGER) or not raw or not set(map(type, raw)) <= {int, float}:
        return None
    try:
        numbers = np.fromiter(map(float, raw), dtype=float, count=len(raw))
    except OverflowError:  # an int beyond floats: parse_number's "finite number" error
        return None
    with np.errstate(all="ignore"):  # an overflow to inf is an error below, never a warning
        values = numbers * factor
        if not np.isfinite(numbers).all():
            return None
        limit = MAX_MAGNITUDE.get(kind)
        if limit is not None and not (np.abs(values) <= limit).all():
            return None
        bounds = column.bounds
        if bounds is not None:
            b_unit = bounds.unit if bounds.unit is not None else column.unit
            b_factor = si_factor(b_unit or "", kind)
            if not all(bounds.contains(v) for v in np.unique(values / b_factor).tolist()):
                return None
    return values


def _part_kind(name):
    """Kind of a workbook part for MAX_PART_BYTES: worksheets are streamed; shared strings,
    styles and the other XML parts are parsed whole; other parts (images) are not parsed."""
    base = name.rsplit("/", 1)[-1]
    if name.startswith("xl/worksheets/") and base.endswith(".xml"):
        return "worksheet"
    if base == "sharedStrings.xml":
        return "sharedStrings"
    if base == "styles.xml":
        return "styles"
    if base.endswith((".xml", ".rels", ".vml")):
        return "other"
    return "binary"


def _why(err):
    """Short reason of an OSError (or other) for a message."""
    if isinstance(err, OSError) and err.strerror:
        return err.strerror
    return f"{type(err).__name__}: {str(err)[:200]}"


def _shorten(names, n=30):
    names = list(names)
    return names if len(names) <= n else names[:n] + [f"... {len(names) - n} more"]


def _as_text(value):
    """Text of a cell value (whole numbers without '.0')."""
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def _echo(value, n=200):
    """A value for a message: long texts cut to ``n`` characters."""
    if isinstance(value, str) and len(value) > n:
        return value[:n] + "..."
    return value


def check_unique(reader, table, column):
    """Raise an InputError at the second occurrence of a value repeated in ``column``; texts
    are compared with case ignored (``NOSE`` and ``nose`` would be told apart by the program
    but not by a reader of the report)."""
    seen = {}
    for i, value in enumerate(table[column]):
        key = value.casefold() if isinstance(value, str) else value
        if key in seen:
            first = seen[key]
            same = "" if table[column][first] == value else (
                f" {table[column][first]!r}: ids are compared with case ignored")
            raise table.error(column, i, f"duplicate {column} (first at "
                                         f"{table.cell(column, first)}{same})")
        seen[key] = i


def parse_text(raw, what, max_chars, error, sheet, where):
    """The text of a cell: stripped, at most ``max_chars`` characters, no control characters
    other than tab and line breaks, not a spreadsheet error."""
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    text = _as_text(raw).strip()
    if len(text) > max_chars:
        raise error(f"{what!r} must have at most {max_chars} characters", _echo(text), sheet,
                    where)
    if ILLEGAL_CHARACTERS_RE.search(text):
        raise error(f"{what!r} contains control characters", _echo(text), sheet, where)
    hidden = hidden_character(text, name_like=max_chars <= MAX_ID_CHARS)
    if hidden is not None:
        k, char = hidden
        rule = ("an id or name holds visible characters and spaces only"
                if max_chars <= MAX_ID_CHARS else "text holds no direction controls")
        name = unicodedata.name(char, None) or _CONTROL_NAMES.get(char, "a control")
        raise error(f"{what!r} contains the invisible character U+{ord(char):04X} ({name}) "
                    f"at position {k + 1}: {rule}", _echo(text), sheet, where)
    return text


_CONTROL_NAMES = {"\t": "TAB", "\n": "LINE FEED", "\r": "CARRIAGE RETURN"}
#: Characters that reorder the display of text (Unicode bidirectional controls): a text that
#: holds them can show as another ("Trojan source"); never accepted in any text.
BIDI_CONTROLS = frozenset("\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e"
                          "\u2066\u2067\u2068\u2069")


def hidden_character(text, name_like):
    """``(position, character)`` of the first character of ``text`` a reader of the report
    could not see, or None: a direction control anywhere; in an id or name
    (``name_like``) also any control or format character (zero-width space, soft hyphen...)
    and any white space but the plain space (tab, line break, no-break space), so that two
    ids that look alike are alike."""
    if text.isascii() and (text.isprintable() or not name_like):
        return None  # (nearly every cell: ASCII has no direction control)
    for k, char in enumerate(text):
        if char in BIDI_CONTROLS:
            return k, char
        if name_like and char != " " and (char.isspace()
                                          or unicodedata.category(char)[0] in "CZ"):
            return k, char
    return None


#: A number written as text: plain decimal notation with the ASCII digits 0-9, an optional
#: sign, decimal point and exponent (``12.5``, ``-3``, ``.5``, ``1e-3``). Python's float()
#: also takes ``1_0`` (ten), other scripts' digits (``٢``, ``３``) and ``infinity``: a
#: workbook's text is never read that way.
PLAIN_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def number_from_text(text):
    """The number a text cell (or CSV field, or list item) holds, surrounding spaces ignored:
    a float when the text is a plain decimal number (:data:`PLAIN_NUMBER`), ``inf`` or
    ``nan`` when it says so (``inf``, ``-Infinity``, ``nan``: refused as not finite by the
    caller), else None (not a number)."""
    text = text.strip()
    if PLAIN_NUMBER.fullmatch(text):
        return float(text)
    if text.lower().lstrip("+-") in ("inf", "infinity", "nan"):
        return float(text)
    return None


def parse_number(raw, what, error, sheet, where):
    """A finite number from a cell value, or an error naming the cell."""
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    if isinstance(raw, bool):
        raise error(f"{what!r} must be a number, not a true/false value", raw, sheet, where)
    if isinstance(raw, (datetime, date, time, timedelta)):
        raise error(f"{what!r} must be a number, not a date or time (format the cell as a "
                    "number)", str(raw), sheet, where)
    if isinstance(raw, (int, float)):
        try:
            value = float(raw)
        except OverflowError:
            value = math.inf
    elif isinstance(raw, str):
        value = number_from_text(raw)
        if value is None:
            raise error(f"{what!r} must be a number (digits 0-9, e.g. 12.5 or 1.2e3)",
                        _echo(raw), sheet, where)
    else:
        raise error(f"{what!r} must be a number", _echo(str(raw)), sheet, where)
    if not math.isfinite(value):
        raise error(f"{what!r} must be a finite number", _echo(raw), sheet, where)
    return value


def check_quantity(number, raw, kind, factor, unit, bounds, spec_unit, what, error, sheet,
                   where):
    """SI value of ``number`` (as written in ``unit``, SI factor ``factor``), checked against
    the magnitude limit of ``kind`` and ``bounds``; whole numbers for the integer kind.

    Raises
    ------
    InputError
        At ``where``, with the value as written and its unit, and the rule in that unit.
    """
    value = number * factor
    shown = unit or None
    echo = _number_echo(raw)
    if kind == INTEGER and not float(number).is_integer():
        raise error(f"{what} must be a whole number", echo, sheet, where)
    limit = MAX_MAGNITUDE.get(kind)
    if limit is not None and not abs(value) <= limit:
        raise error(f"{what} must not exceed {limit / factor:.6g}{' ' + unit if unit else ''} "
                    f"in magnitude (limit of every {kind} in slingloads)", echo, sheet, where,
                    shown)
    if bounds is not None:
        b_unit = bounds.unit if bounds.unit is not None else spec_unit
        b_factor = 1.0 if kind == INTEGER else si_factor(b_unit or "", kind)
        if not bounds.contains(value / b_factor):
            rule = bounds.rule(value / b_factor, scale=factor / b_factor, unit=unit)
            raise error(f"{what} {rule}", echo, sheet, where, shown)
    return int(number) if kind == INTEGER else value


def _number_echo(raw):
    """A numeric cell's value for a message: numbers as floats (``0.0``, ``-12.5``), text as
    written."""
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        try:
            return float(raw)
        except OverflowError:
            return raw
    return _echo(raw)


def parse_flag(raw, what, error, sheet, where, default):
    """A yes/no cell as bool."""
    if raw is None:
        if default is None:
            raise error(f"empty cell: {what!r} needs yes or no", None, sheet, where)
        raw = default
    if isinstance(raw, bool):
        return raw
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    text = _as_text(raw).strip().lower()
    if text in _TRUE:
        return True
    if text in _FALSE and text != "":
        return False
    raise error(f"{what!r} must be yes or no", _echo(raw), sheet, where)


def _unknown_parameter(key, known):
    """The rule broken by an unknown Study parameter: the closest valid names, or where the
    whole list is (there are too many to quote)."""
    import difflib

    close = difflib.get_close_matches(key, list(known), n=3, cutoff=0.6)
    hint = f"did you mean {' or '.join(repr(known[c].name) for c in close)}? " if close else ""
    return (f"unknown parameter; {hint}the valid parameters are on the Study sheet of "
            f"'slingloads template' and in docs/ ({len(known)} in all)")


"""The XLSX source: an input workbook's file and ZIP container checked, its sheets streamed
row by row, its cells parsed.

What this module guarantees, whatever the file holds:

* the file and its ZIP container are checked before anything is parsed: a regular file with
  an ``.xlsx`` suffix, its size on disk, the number of parts, the uncompressed size of each
  part and of the whole (:data:`slingloads.limits.MAX_UNCOMPRESSED_BYTES`: zip bombs);
* no XML part is parsed that declares a document type or entities ("billion laughs",
  external entities: :func:`check_prolog`); the rest goes through ``defusedxml``;
* a sheet is streamed row by row in bounded memory: an element is cleared when it ends, the
  number of XML elements of a sheet is capped
  (:data:`~slingloads.limits.MAX_SHEET_ELEMENTS`), and a row cannot hold more cells than
  Excel allows;
* a cell holding a plain number or an inline string is read without openpyxl's per-cell
  parser (:func:`_simple_cell`), only where that parser would give the same value
  (tests/test_workbook_fast_path.py); every other cell goes through openpyxl's parser, and a
  spreadsheet error (``#DIV/0!``) is a :class:`CellError`, never a number;
* every refusal is an :class:`~slingloads.errors.InputError` naming the file (and, from
  :class:`~slingloads.io.common.workbook.WorkbookReader`, the sheet).

A source yields, for each row, ``(row number, {column: value}, cells stored)``: empty cells
are left out. :class:`MemorySource` yields the same from rows given in memory (tests).
"""

from __future__ import annotations

import contextlib
import os
import pyexpat
import re
import stat
import warnings
import zipfile
from xml.etree.ElementTree import iterparse

from openpyxl.utils import column_index_from_string
from openpyxl.worksheet._reader import _cast_number

from slingloads.errors import InputError
from slingloads.limits import (
    MAX_PART_BYTES,
    MAX_SHEET_ELEMENTS,
    MAX_UNCOMPRESSED_BYTES,
    MAX_WORKBOOK_BYTES,
    MAX_ZIP_MEMBERS,
)
from slingloads.safeopen import open_regular

#: Excel's sheet size [rows, columns].
EXCEL_ROWS, EXCEL_COLUMNS = 1_048_576, 16_384
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


def check_prolog(source, error):
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


def is_empty(value):
    return value is None or (isinstance(value, str) and not value.strip())


class MemorySource:
    """Sheets given as lists of rows (row 1 first), for tests and for building in memory."""

    def __init__(self, sheets):
        self.sheets = {str(k): list(v) for k, v in sheets.items()}
        self.sheetnames = list(self.sheets)

    def rows(self, name):
        """``(row number, {column: value}, cells stored)`` of each row, as
        :meth:`XlsxSource.rows`."""
        for r, row in enumerate(self.sheets[name], start=1):
            values = list(row)
            yield r, {c: v for c, v in enumerate(values, start=1) if not is_empty(v)}, len(values)

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


class XlsxSource:
    """An .xlsx file streamed sheet by sheet with openpyxl's read-only machinery."""

    def __init__(self, path, error):
        from openpyxl import load_workbook

        self.error = error
        self._stream = None
        try:
            with warnings.catch_warnings(), _no_dimension_scan():
                warnings.simplefilter("ignore")  # unsupported extensions, data validation...
                self._stream = open_regular(path, follow_links=True)  # never a pipe
                self.book = load_workbook(self._stream, read_only=True, data_only=True)
        except Exception as err:  # noqa: BLE001 - openpyxl raises many kinds on corrupt files
            if self._stream is not None:
                self._stream.close()
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
            check_prolog(source, self.error)
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
            if value is None or (isinstance(value, str) and not value.strip()):  # is_empty
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
        self._stream.close()


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


def part_kind(name):
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


def reason_of(err):
    """Short reason of an OSError (or other) for a message."""
    if isinstance(err, OSError) and err.strerror:
        return err.strerror
    return f"{type(err).__name__}: {str(err)[:200]}"


def check_file(path, file):
    """Refuse a workbook ``path`` (named ``file`` in messages) that is not a readable regular
    file with an ``.xlsx`` (or ``.xlsm``) suffix of at most
    :data:`~slingloads.limits.MAX_WORKBOOK_BYTES`."""
    try:
        info = os.stat(path)
    except (FileNotFoundError, NotADirectoryError):
        raise InputError("input workbook not found", file, file=file) from None
    except (OSError, ValueError) as err:
        raise InputError(f"cannot open the input workbook ({reason_of(err)})", file,
                         file=file) from None
    if stat.S_ISDIR(info.st_mode):
        raise InputError("the input is a folder, not an .xlsx workbook", file,
                         file=file)
    if not stat.S_ISREG(info.st_mode):
        raise InputError("the input is not a regular file (a device, pipe or socket)",
                         file, file=file)
    if path.suffix.lower() not in (".xlsx", ".xlsm"):
        raise InputError("input must be an Excel .xlsx workbook (save older .xls files "
                         "as .xlsx)", path.suffix, file=file)
    if info.st_size > MAX_WORKBOOK_BYTES:
        raise InputError(f"workbook refused: {info.st_size:,} bytes, more than the "
                         f"{MAX_WORKBOOK_BYTES:,} accepted", file=file)
    try:
        with open_regular(path, follow_links=True):  # never blocks on a pipe swapped in
            pass
    except OSError as err:
        raise InputError(f"cannot read the input workbook ({reason_of(err)})", file,
                         file=file) from None


def check_container(path, file):
    """Refuse a workbook whose ZIP container has too many parts, a part or a whole that
    expands beyond its limit (zip bombs), or a worksheet declaring a document type or
    entities (XML bombs); nothing is decompressed but the worksheets' prologs."""
    try:
        with open_regular(path, follow_links=True) as stream, \
                zipfile.ZipFile(stream) as archive:
            infos = archive.infolist()
            _check_sizes(infos, file)
            for info in infos:  # every worksheet, read or not: no DTD, no entities
                if part_kind(info.filename) == "worksheet":
                    with archive.open(info) as source:
                        check_prolog(source,
                                      lambda rule, value: InputError(rule, value, file=file))
    except InputError:
        raise
    except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, ValueError, EOFError,
            NotImplementedError) as err:
        raise InputError(f"not a workbook: the file is not an .xlsx (zip) container "
                         f"({str(err)[:200]}){_what_it_is(path)}", file=file) from None


#: First bytes of an OLE2 compound document: an old .xls, or an .xlsx that Excel encrypted
#: (a workbook with a password to open is stored in one).
_OLE2_SIGNATURE = bytes.fromhex("d0cf11e0a1b11ae1")


def _what_it_is(path):
    """What a file that is no zip container looks like it is, for the message ("" when it
    cannot tell)."""
    try:
        with open_regular(path, follow_links=True) as stream:
            head = stream.read(len(_OLE2_SIGNATURE))
    except OSError:
        return ""
    if head == _OLE2_SIGNATURE:
        return ("; it is an OLE2 compound document: a workbook protected by a password to "
                "open (encrypted), or an .xls saved under the name .xlsx; remove the "
                "password or save it as an Excel .xlsx workbook")
    if not head:
        return "; the file is empty"
    return ""


def _check_sizes(infos, file):
    if len(infos) > MAX_ZIP_MEMBERS:
        raise InputError(f"workbook refused: {len(infos):,} parts in its container, more "
                         f"than the {MAX_ZIP_MEMBERS:,} accepted", file=file)
    total = 0
    for info in infos:
        total += info.file_size
        limit = MAX_PART_BYTES.get(part_kind(info.filename))
        if limit is not None and info.file_size > limit:
            raise InputError(f"workbook refused: its part {info.filename[:100]!r} expands "
                             f"to {info.file_size:,} bytes, more than the {limit:,} "
                             "accepted (possible zip bomb)", file=file)
    if total > MAX_UNCOMPRESSED_BYTES:
        raise InputError(f"workbook refused: its content expands to {total:,} bytes, more "
                         f"than the {MAX_UNCOMPRESSED_BYTES:,} accepted (possible zip "
                         "bomb)", file=file)

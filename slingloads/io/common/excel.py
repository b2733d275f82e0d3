"""The one workbook writer of the reports: pandas DataFrames to a print-ready Excel workbook.

The writer only formats: it receives DataFrames already in report units with unit-labelled
headers, and images already drawn. Every sheet it writes, whatever its content, gets:

* **print setup**: A4, portrait or landscape from the width of its columns, fitted to the
  page width (never a column cut from its row labels), margins, the header rows repeated on
  every printed page, a page header with the report title, the sheet's title and the input
  file, and a footer with the run date, the slingloads version and ``page x of y``;
* **frozen panes** below the header row (and right of the id column when the first column
  holds ids);
* **numbers at an engineering precision**: an Excel number format per unit
  (:mod:`slingloads.io.common.formats`), read from the column header (``Vy [lbf]``) or, in a
  table that mixes kinds in one value column, from the row's ``unit`` column; booleans as
  ``yes``/``no``;
* **readable columns**: widths from the contents, long text wrapped (no column wider than
  :data:`MAX_TEXT_WIDTH` characters), header cells bold and wrapped, notes wrapped to the
  table width;
* **safety**: every string stored as text, never as a formula (a case description such as
  ``=HYPERLINK("x")`` is a string cell, ``data_type "s"``; a text that looks like
  XlsxWriter's own rich-string markup, ``<r>...</r>``, is written as a rich string of two
  runs, so that it too is escaped); NaN an empty cell and +/-inf the text
  :data:`INFINITE_TEXT`, never a bare ``inf`` (Excel has neither; the reports write what
  their infinite values mean instead, :func:`slingloads.io.common.report.explain_infinite`:
  this is the last resort); a table longer than Excel's row limit split over ``NAME_1``,
  ``NAME_2``... with the header repeated, never truncated;
* images scaled to the printable width, two to a page when they fit, never cut by a page
  break; a red fill on ratio cells above a threshold (conditional formatting).

With a :class:`~slingloads.io.common.cover.ReportInfo`, the workbook opens on a *Cover* sheet
(title, what the analysis covers, input file with its SHA-256 and modification time, version
and source revision, run date, project / document / author / checker, list of sheets,
conventions). A new report sheet therefore needs nothing but its DataFrame (or titled
:class:`Section` blocks): print setup, formats and panes come from here.

The workbook is written with XlsxWriter, each cell format made once: in memory up to
:data:`IN_MEMORY_CELLS` table cells, else streamed row by row through temporary files
(``constant_memory``: memory does not grow with a table). Nothing is written at ``path``
until every sheet is done: a workbook refused half-way (text Excel cannot store) leaves no
file, and no temporary file.

References
----------
.. [1] Microsoft, "Excel specifications and limits": 1,048,576 rows by 16,384 columns;
   32,767 characters per cell; sheet names of at most 31 characters without ``: \\ / ? * [ ]``;
   255 characters in a page header or footer.
.. [2] ECMA-376 Part 1, 18.3.1.63 ``pageSetup`` (paperSize 9 = A4; ``fitToWidth`` and
   ``fitToHeight`` default to 1) and 18.3.1.46 ``headerFooter`` codes (``&P`` page, ``&N``
   pages, ``&&`` an ampersand, ``&8`` an 8-point font).
.. [3] W3C, "Extensible Markup Language (XML) 1.0", 2.2 Characters: the control characters
   below U+0020 other than tab, line feed and carriage return are not allowed.
"""

from __future__ import annotations

import io
import math
import numbers
import re
import tempfile
import textwrap
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
import xlsxwriter
from xlsxwriter.exceptions import FileCreateError
from xlsxwriter.utility import xl_col_to_name, xl_rowcol_to_cell

from slingloads.errors import InputError
from slingloads.io.common.figures import collect_pngs, figure_png
from slingloads.io.common.formats import header_unit, unit_format, value_format

#: Rows in one Excel worksheet (header included) [1]_.
EXCEL_MAX_ROWS = 1_048_576
#: Columns in one Excel worksheet [1]_.
EXCEL_MAX_COLUMNS = 16_384
#: Characters in one Excel cell [1]_.
EXCEL_MAX_CELL_CHARS = 32_767
#: Characters in a sheet name [1]_.
EXCEL_MAX_SHEET_NAME = 31
#: Characters (UTF-16 code units) in a page header or footer, codes included [1]_.
EXCEL_MAX_HEADER_CHARS = 255
#: Widest text column [characters]; longer text wraps.
MAX_TEXT_WIDTH = 40
#: Widest numeric column [characters].
MAX_NUMBER_WIDTH = 16
#: A4 paper, ECMA-376 ``paperSize`` code [2]_.
PAPER_A4 = 9
#: Page margins: left, right, top, bottom, header, footer. [in]
MARGINS = (0.5, 0.5, 0.75, 0.75, 0.3, 0.3)
#: Printable width and height of an A4 page inside :data:`MARGINS`, at 96 px per inch. [px]
PRINTABLE = {"portrait": (round((8.27 - 1.0) * 96), round((11.69 - 1.5) * 96)),
             "landscape": (round((11.69 - 1.0) * 96), round((8.27 - 1.5) * 96))}
#: Pixel height of a default row (15 pt at 96 dpi).
ROW_PIXELS = 20
#: Most table cells of a workbook built in memory (XlsxWriter keeps about 250 bytes a cell:
#: some 60 MB at most); a larger one is streamed through temporary files, which is slower.
IN_MEMORY_CELLS = 250_000

_BAD_SHEET_CHARS = re.compile(r"[:\\/?*\[\]]")
#: Characters an XML 1.0 document cannot hold [3]_ (openpyxl's ``ILLEGAL_CHARACTERS_RE``).
_ILLEGAL_CHARACTERS = re.compile(r"[\000-\010]|[\013-\014]|[\016-\037]")
#: A literal ``&`` (doubled) before what XlsxWriter's ``set_header`` reads as an image code.
_IMAGE_CODE = re.compile(r"&&(?=G|\[Picture\])")
_FONT = "Calibri"


def _props(**kwargs):
    """XlsxWriter format properties as a hashable tuple of ``(name, value)`` pairs."""
    return tuple(sorted(kwargs.items()))


# Parts of a cell style: tuples of XlsxWriter format properties, combined by _style().
_TITLE_FONT = _props(font_name=_FONT, bold=True, font_size=12)
_COVER_TITLE_FONT = _props(font_name=_FONT, bold=True, font_size=16)
_HEADER_FONT = _props(font_name=_FONT, bold=True)
_HEADER_FILL = _props(pattern=1, fg_color="#DDEBF7", bg_color="#DDEBF7")  # solid
_HEADER_BORDER = _props(bottom=1)  # thin
_HEADER_ALIGN = _props(text_wrap=True, valign="bottom")
_HEADER_RIGHT = _props(text_wrap=True, valign="bottom", align="right")
_HEADER_CENTER = _props(text_wrap=True, valign="bottom", align="center")
_WRAP = _props(text_wrap=True, valign="top", align="left", indent=1)
_WRAP_GENERAL = _props(text_wrap=True, valign="top")
_TOP = _props(valign="top")
_LEFT = _props(valign="top", align="left", indent=1)
_RIGHT = _props(valign="top", align="right")
_CENTER = _props(valign="top", align="center")
#: Longest text of a column of ids that is centred (case, station, yes/no).
_ID_WIDTH = 10
#: The conditional format of a highlighted cell: red fill, dark red text.
_RED = {"bg_color": "#FFC7CE", "font_color": "#9C0006"}
#: Average width of a character of text in Calibri 11 (digits are 7 px). [px]
_CHAR_PIXELS = 6.3
#: Pixels of a column per character of its stored width (a Calibri 11 digit).
_DIGIT_PIXELS = 7


def _px(width):
    """Pixels of a column ``width`` characters wide (Calibri 11: 7 px per digit + 5)."""
    return 7 * width + 5


@dataclass
class Section:
    """A titled block of a sheet: a table, a note, or both.

    Parameters
    ----------
    title : str
        Written in bold above the block; empty for none.
    table : pandas.DataFrame, optional
        Written with a bold header row.
    note : str
        Written under the title (before the table), wrapped to the width of the sheet.
    """

    title: str = ""
    table: pd.DataFrame | None = None
    note: str = ""


@dataclass
class Highlight:
    """Red fill on the cells of some columns above a threshold (conditional formatting).

    Parameters
    ----------
    columns : sequence of str
        Header names of the columns to watch.
    threshold : float
        Cells with a number greater than this, or with a text (a ratio without a finite
        value, written as what it means: ``"unbounded (previous 0)"``), are filled red.
    """

    columns: Sequence[str] = field(default_factory=tuple)
    threshold: float = 1.0


def check_sheet_name(name):
    """Return ``name`` if Excel accepts it as a sheet name, else raise :class:`InputError`."""
    if not isinstance(name, str) or not name.strip():
        raise InputError("a sheet name must be a non-empty string", name)
    if len(name) > EXCEL_MAX_SHEET_NAME:
        raise InputError(f"a sheet name must have at most {EXCEL_MAX_SHEET_NAME} characters",
                         name)
    if _BAD_SHEET_CHARS.search(name) or name.startswith("'") or name.endswith("'"):
        raise InputError("a sheet name must not contain : \\ / ? * [ ] nor start or end "
                         "with an apostrophe", name)
    if name.lower() == "history":
        raise InputError("'History' is a sheet name reserved by Excel", name)
    return name


def split_sheet_names(name, n_rows, max_rows=EXCEL_MAX_ROWS):
    """Sheet names and row ranges for a table of ``n_rows`` data rows.

    Parameters
    ----------
    name : str
        Base sheet name.
    n_rows : int
        Data rows (the header is added on every sheet).
    max_rows : int
        Rows per sheet including the header (Excel: 1,048,576), >= 2.

    Returns
    -------
    list of (str, int, int)
        ``(sheet name, first row, stop row)`` slices of the table: one ``(name, 0, n_rows)``
        when it fits, else ``NAME_1``, ``NAME_2``... each with ``max_rows - 1`` data rows.
    """
    if int(max_rows) < 2:
        raise InputError("a sheet needs room for the header and at least one row",
                         max_rows)
    per_sheet = int(max_rows) - 1
    if n_rows <= per_sheet:
        return [(check_sheet_name(name), 0, n_rows)]
    parts = math.ceil(n_rows / per_sheet)
    return [(check_sheet_name(f"{name}_{k + 1}"), k * per_sheet,
             min((k + 1) * per_sheet, n_rows)) for k in range(parts)]


#: Text of an infinite number the report has not explained, by sign (+inf: True).
INFINITE_TEXT = {True: "infinite", False: "-infinite"}


def _plain(value):
    """A Python value the writer stores faithfully (numpy scalars unwrapped, NaN -> None,
    booleans -> ``yes``/``no``)."""
    kind = type(value)
    if kind is float:  # the common cases first (a table's cells)
        if value != value:
            return None
        return value if -math.inf < value < math.inf else INFINITE_TEXT[value > 0]
    if kind is str or kind is int:
        return value
    if isinstance(value, np.generic):
        value = value.item()
    if value is None or value is pd.NA or value is pd.NaT:
        return None
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, numbers.Real):
        value = float(value) if not isinstance(value, numbers.Integral) else int(value)
        if isinstance(value, float):
            if math.isnan(value):
                return None
            if math.isinf(value):
                return INFINITE_TEXT[value > 0]
        return value
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple, np.ndarray)):
        return ", ".join(str(_plain(v)) for v in value)
    return str(value)


def wrapped_lines(text, width, bold=False):
    """Lines that ``text`` takes in a wrapped cell ``width`` characters wide (a cautious
    estimate: a row too tall wastes a little paper, a row too short hides text)."""
    chars = max(4, int((_px(width) - 8) / (_CHAR_PIXELS * (1.2 if bold else 1.0))))
    return sum(max(1, len(textwrap.wrap(part, chars))) for part in str(text).split("\n"))


class _Workbook(xlsxwriter.Workbook):
    """An XlsxWriter workbook that makes each cell format once.

    Parameters
    ----------
    path : path-like
        ``.xlsx`` file written by :meth:`save`.
    stream : bool
        Write each row to a temporary file as soon as the next one starts (XlsxWriter's
        ``constant_memory``: memory does not grow with the tables, strings are inline)
        instead of keeping the workbook in memory until it is saved (``in_memory``: no
        temporary file, strings shared).
    tmpdir : str, optional
        Folder of XlsxWriter's temporary files (default: the system's).
    """

    def __init__(self, path, *, stream=False, tmpdir=None):
        mode = "constant_memory" if stream else "in_memory"
        super().__init__(str(path), {mode: True, "use_zip64": True, "tmpdir": tmpdir})
        self._cell_formats = {}
        self._red = None

    def cell_format(self, style):
        """The XlsxWriter ``Format`` of a (font, number format, alignment, fill, border)
        style (:func:`_style`), made on first use; None for a style of nothing."""
        try:
            return self._cell_formats[style]
        except KeyError:
            pass
        font, number_format, alignment, fill, border = style
        props = {}
        for part in (font, alignment, fill, border):
            props.update(part or ())
        if number_format is not None:
            props["num_format"] = number_format
        made = self.add_format(props) if props else None
        self._cell_formats[style] = made
        return made

    def red(self):
        """The format of a highlighted cell (a conditional format's red fill)."""
        if self._red is None:
            self._red = self.add_format(_RED)
        return self._red

    def save(self):
        """Write the file; an OSError (full disk, no permission) is raised as itself, not
        as XlsxWriter's ``FileCreateError``."""
        try:
            self.close()
        except FileCreateError as err:
            cause = err.args[0] if err.args else None
            if isinstance(cause, OSError):
                raise cause from None
            raise


def _text_style(style):
    """``style`` without its number format (text and empty cells take none)."""
    return None if style is None else (style[0], None, *style[2:])


def _wraps(style):
    """Whether cells of ``style`` wrap their text."""
    return style is not None and style[2] is not None and ("text_wrap", True) in style[2]


def _bold(style):
    """Whether cells of ``style`` are in a bold font."""
    return style is not None and style[0] is not None and ("bold", True) in style[0]


class _SheetWriter:
    """Writes rows into one sheet, one after the other, keeping track of the row number, of
    the height of the rows written and of the page breaks asked for.

    Cell formats come from :meth:`_Workbook.cell_format`, one per style. A row with wrapped
    text gets the height of its tallest wrapped cell (LibreOffice does not compute it when
    it opens the file).

    Parameters
    ----------
    wb : _Workbook
    ws : xlsxwriter.worksheet.Worksheet
        A sheet of ``wb``.
    widths : dict of int to float, optional
        Column widths [characters], for the lines of wrapped text.
    """

    def __init__(self, wb, ws, widths=None):
        self.wb = wb
        self.ws = ws
        self.widths = widths or {}
        self.row = 0
        self.pixels = 0
        self.breaks = []

    def _where(self, column):
        return {"sheet": self.ws.name, "cell": xl_rowcol_to_cell(self.row, column)}

    def _text(self, column, value, cell_format):
        """Write the string ``value`` as text (never a formula)."""
        if _ILLEGAL_CHARACTERS.search(value):
            raise InputError("text contains a control character that Excel cannot store",
                             value, **self._where(column))
        if len(value) > EXCEL_MAX_CELL_CHARS:
            done = -2
        elif value.startswith("<r>") and value.endswith("</r>"):
            # XlsxWriter writes such a string unescaped, as rich-text XML: two runs instead
            done = self.ws.write_rich_string(self.row, column, "<",
                                             cell_format or self.wb.cell_format(_PLAIN),
                                             value[1:], *[cell_format] if cell_format else [])
        else:
            done = self.ws.write_string(self.row, column, value, cell_format)
        if done == -2:  # longer than 32,767 UTF-16 units: XlsxWriter would truncate it
            raise InputError(f"text longer than Excel's {EXCEL_MAX_CELL_CHARS} characters "
                             "per cell", value[:40] + "...", **self._where(column))

    def write(self, values, formats, lines=1):
        """Write one row of plain values (:func:`_plain`), one format (or None) each, of
        ``lines`` lines of text."""
        if self.row >= EXCEL_MAX_ROWS:
            raise InputError(f"a sheet has more than Excel's {EXCEL_MAX_ROWS} rows",
                             self.row + 1, sheet=self.ws.name)
        if lines > 1:
            self.ws.set_row(self.row, 15 * lines)
        ws, row = self.ws, self.row
        for j, (value, cell_format) in enumerate(zip(values, formats, strict=True)):
            if value is None:
                if cell_format is not None:  # a styled empty cell
                    ws.write_blank(row, j, None, cell_format)
            elif type(value) is str:
                if value:
                    self._text(j, value, cell_format)
                elif cell_format is not None:  # an empty text is an empty cell
                    ws.write_blank(row, j, None, cell_format)
            else:
                ws.write_number(row, j, value, cell_format)
        self.row += 1
        self.pixels += ROW_PIXELS * lines

    def lines(self, values, wrapping, bold=()):
        """Lines the row takes: the most of its wrapped text cells (``wrapping``: the
        indices of the cells whose style wraps; ``bold``: those in a bold font)."""
        most = 1
        for j in wrapping:
            value = values[j]
            if isinstance(value, str) and len(value) > 4:
                most = max(most, wrapped_lines(value, self.widths.get(j, 10), j in bold))
        return most

    def append(self, values, styles=None):
        """Append one row; ``styles`` is one (font, format, alignment, fill, border) tuple
        for every cell, or a list of them, or None."""
        values = [_plain(v) for v in values]
        if styles is None or isinstance(styles, tuple):
            styles = [styles] * len(values)
        formats = [self.wb.cell_format(s if isinstance(v, (int, float)) else _text_style(s))
                   if s is not None else None for v, s in zip(values, styles, strict=True)]
        wrapping = [j for j, s in enumerate(styles) if _wraps(s)]
        bold = {j for j in wrapping if _bold(styles[j])}
        self.write(values, formats, self.lines(values, wrapping, bold))

    def blank(self, n=1):
        """Leave ``n`` empty rows."""
        self.row += n
        self.pixels += ROW_PIXELS * n

    def page_break(self):
        """A page break above the next row."""
        self.breaks.append(self.row)

    def close(self):
        """Set the page breaks asked for (XlsxWriter takes them all at once)."""
        if self.breaks:
            self.ws.set_h_pagebreaks(self.breaks)


def _style(font=None, number_format=None, alignment=None, fill=None, border=None):
    return (font, number_format, alignment, fill, border)


_PLAIN = _style(_props(font_name=_FONT))
_TITLE_STYLE = _style(_TITLE_FONT)
_HEADER_STYLE = _style(_HEADER_FONT, None, _HEADER_ALIGN, _HEADER_FILL, _HEADER_BORDER)


# ----------------------------------------------------------------------------- column plan
@dataclass
class _Columns:
    """Widths [characters] and wrapped columns of one sheet."""

    widths: dict
    wrapped: set

    @property
    def pixels(self):
        return sum(_px(w) for w in self.widths.values())


def _number_formats(columns, number_format):
    """The format of each column: the report's override, else from the header's unit."""
    out = []
    for c in columns:
        fmt = None
        if isinstance(number_format, Mapping):
            fmt = number_format.get(c)
        elif callable(number_format):
            fmt = number_format(str(c))
        out.append(fmt if fmt is not None else unit_format(header_unit(c)))
    return out


def _is_text(series):
    """A column of strings (pandas ``str`` or ``object`` dtype)."""
    return series.dtype == object or pd.api.types.is_string_dtype(series.dtype)


def _explained_numbers(series, header):
    """A column of numbers in which some values are written as what they mean (the texts of
    :func:`~slingloads.io.common.report.explain_infinite`): its header carries a unit and
    every value is a number, a text or empty. It is laid out as a column of numbers (right
    aligned, as wide as its numbers and its texts)."""
    if series.dtype != object or header_unit(header) is None:
        return False
    kinds = {type(v) for v in series if v is not None and not (isinstance(v, float) and v != v)}
    return str in kinds and all(k is str or (issubclass(k, numbers.Real) and k is not bool)
                                for k in kinds)


def _row_unit_columns(frame, formats):
    """Columns whose format comes from the row's ``unit`` column: numeric columns with no
    unit in their header, in a table that has a ``unit`` column."""
    if "unit" not in frame.columns:
        return []
    out = []
    for j, column in enumerate(frame.columns):
        if column == "unit" or formats[j] is not None or header_unit(column) is not None:
            continue
        series = frame.iloc[:, j]
        if pd.api.types.is_bool_dtype(series.dtype):
            continue
        if pd.api.types.is_numeric_dtype(series.dtype) or (
                series.dtype == object
                and series.map(lambda v: isinstance(v, (float, np.floating))).any()):
            out.append(j)
    return out


def _text_width(series):
    """Characters of the longest line of text in ``series`` as written."""
    widest = 0
    for value in series:
        shown = _plain(value)
        if shown is not None:
            widest = max(widest, max(len(line) for line in str(shown).split("\n")))
    return widest


def _number_width(series, number_format):
    values = pd.to_numeric(series, errors="coerce").to_numpy(float)
    values = values[np.isfinite(values)]
    if not values.size:
        return 3
    big = float(np.max(np.abs(values)))
    if number_format is None:
        return min(len(f"{-big:.6g}"), MAX_NUMBER_WIDTH)
    if "E" in number_format:
        return 9
    decimals = len(number_format.split(".")[1]) if "." in number_format else 0
    sep = "," if "#,##" in number_format else ""
    return len(f"{-big:{sep}.{decimals}f}")


def _column_plan(tables, notes=(), formats_of=None):
    """Widths of the columns of every table of a sheet, and which columns wrap."""
    widths, wrapped = {}, set()
    for frame in tables:
        formats = formats_of(frame) if formats_of else [None] * frame.shape[1]
        for j, col in enumerate(frame.columns):
            series = frame.iloc[:, j]
            explained = _explained_numbers(series, col)
            if pd.api.types.is_bool_dtype(series.dtype):
                data = 3
            elif pd.api.types.is_numeric_dtype(series.dtype):
                data = _number_width(series, formats[j])
            elif explained:
                data = max(_number_width(series, formats[j]),
                           _text_width(v for v in series if isinstance(v, str)))
            else:
                data = _text_width(series)
            words = max((len(w) for w in str(col).split()), default=0)
            text = not (pd.api.types.is_numeric_dtype(series.dtype) or explained
                        or pd.api.types.is_bool_dtype(series.dtype))
            width = max(data + text, int(1.1 * words) + 1, min(len(str(col)), 10), 4) + 2
            if width > MAX_TEXT_WIDTH:
                wrapped.add(j)
                width = MAX_TEXT_WIDTH
            widths[j] = max(widths.get(j, 0), min(width, MAX_TEXT_WIDTH))
    if not widths and notes:
        widths[0] = MAX_TEXT_WIDTH * 2
    return _Columns(widths, wrapped)


def _set_widths(ws, columns):
    """Set the column widths of the plan [characters], stored as they are.

    A width stored as ``w`` characters shows 7 ``w`` px wide (Excel's rule for Calibri 11);
    XlsxWriter stores ``pixels / 7``, whereas its ``set_column(w)`` would add the 5 px of
    cell padding (``w + 5/7`` stored).
    """
    for j, width in columns.widths.items():
        ws.set_column_pixels(j, j, _DIGIT_PIXELS * width)


def _note_lines(text, columns):
    """A note split into lines that fit the sheet's width (about 1 character per 7 px)."""
    chars = max(60, min(int(columns.pixels / 7.5), 160))
    lines = []
    for paragraph in str(text).splitlines():
        lines.extend(textwrap.wrap(paragraph, chars) or [""])
    return lines


# ----------------------------------------------------------------------------- print setup
def _escape(text, limit=80):
    """Header/footer text: at most ``limit`` characters, made safe
    (:func:`header_footer_text`)."""
    text = str(text)
    if len(text) > limit:
        text = text[:limit - 3] + "..."
    return header_footer_text(text)


def orientation_for(pixels, height=0.0):
    """The orientation of a sheet ``pixels`` wide and ``height`` high [px].

    Portrait when the sheet fits the portrait width (8 % shrink allowed); portrait also for a
    long sheet (more than a landscape page) that a fit-to-width shrink of at most 32 % puts on
    a portrait page, since that prints it on fewer pages; else landscape.
    """
    width, _ = PRINTABLE["portrait"]
    land_width, land_height = PRINTABLE["landscape"]
    if pixels <= 1.08 * width:
        return "portrait"
    if pixels <= width / 0.68 and height * min(1.0, land_width / pixels) > 1.2 * land_height:
        return "portrait"
    return "landscape"


def print_setup(ws, *, pixels, height=0.0, title_rows=None, sheet_title="", info=None):
    """Page setup of one sheet: A4, orientation from its width, fitted to the page width,
    header rows repeated, page header and footer.

    Parameters
    ----------
    ws : xlsxwriter.worksheet.Worksheet
    pixels : float
        Width of the sheet's used columns. [px]
    height : float
        Estimated height of its rows (long sheets print portrait when they can). [px]
    title_rows : int, optional
        Rows 1..title_rows are printed at the top of every page.
    sheet_title : str
        Centre of the page header.
    info : ReportInfo, optional
        Report title and input file (page header), run date, version and document number
        (footer).

    Returns
    -------
    str
        The orientation chosen.
    """
    orientation = orientation_for(pixels, height)
    ws.set_paper(PAPER_A4)
    _orient(ws, orientation)
    ws.fit_to_pages(1, 0)  # 1 page wide, as many high as needed
    left, right, top, bottom, header, footer = MARGINS
    ws.set_margins(left=left, right=right, top=top, bottom=bottom)
    if title_rows:
        ws.repeat_rows(0, int(title_rows) - 1)
    title = info.title if info is not None else "slingloads report"
    narrow = orientation == "portrait"
    right = " | ".join(t for t in ((info.document, info.input_name) if info is not None
                                   else ()) if t)
    ws.set_header(_header_footer([(title, 45 if narrow else 60),
                                  (sheet_title or ws.name, 45 if narrow else 70),
                                  (right, 45)]), {"margin": header})
    ws.set_footer(_header_footer([(f"run {info.run_date}" if info is not None else "", 40),
                                  None, (info.software if info is not None else "slingloads",
                                         45)]), {"margin": footer})
    return orientation


def _orient(ws, orientation):
    """Print ``ws`` in ``orientation`` (``"portrait"`` or ``"landscape"``)."""
    if orientation == "portrait":
        ws.set_portrait()
    else:
        ws.set_landscape()


def _header_footer(parts):
    """A page header or footer: left, centre and right parts in 8 pt, ``&L&8 left&C&8
    centre&R&8 right`` [2]_.

    Parameters
    ----------
    parts : sequence of 3 (str, int) or None
        ``(text, most characters)`` of each part, the text made safe by :func:`_escape`;
        None for the page number, ``page &P of &N``.

    Returns
    -------
    str
        At most :data:`EXCEL_MAX_HEADER_CHARS` UTF-16 units: the longest part is shortened
        while it is longer (only a text full of ``&``, each written ``&&``, comes near).
    """
    limits = [None if p is None else p[1] for p in parts]
    while True:
        texts = ["page &P of &N" if p is None else _escape(p[0], limit)
                 for p, limit in zip(parts, limits, strict=True)]
        text = "".join(f"&{key}&8 {part}" for key, part in zip("LCR", texts, strict=True))
        # XlsxWriter reads &G and &[Picture] as image codes, even after a literal &&: an
        # 8 pt size code between (the part's size already) keeps them text
        text = _IMAGE_CODE.sub("&&&8", text)
        shorter = [k for k, limit in enumerate(limits) if limit is not None and limit > 10]
        if _utf16_units(text) <= EXCEL_MAX_HEADER_CHARS or not shorter:
            return text
        k = max(shorter, key=lambda k: _utf16_units(texts[k]))
        limits[k] = max(10, min(limits[k], len(str(parts[k][0]))) - 5)


def _utf16_units(text):
    """Length of ``text`` as Excel counts it: UTF-16 code units."""
    return len(text.encode("utf-16-le")) // 2


def _freeze(frame, header_row):
    """Freeze panes below ``header_row``, right of the first column when it holds text ids."""
    first = frame.iloc[:, 0] if frame.shape[1] > 1 else None
    ids = (first is not None and len(first) > 0 and _is_text(first)
           and first.map(lambda v: isinstance(v, str)).all())
    return f"{'B' if ids else 'A'}{header_row + 1}"


# ----------------------------------------------------------------------------- tables
def _highlight(writer, frame, first_row, last_row, highlight):
    """Add a red-fill conditional format on the highlighted columns of rows first..last
    (1-based)."""
    if highlight is None or last_row < first_row:
        return
    for name in highlight.columns:
        if name not in frame.columns:
            continue
        j = list(frame.columns).index(name)
        top = f"{xl_col_to_name(j)}{first_row}"
        writer.ws.conditional_format(first_row - 1, j, last_row - 1, j, {
            "type": "formula", "format": writer.wb.red(),
            "criteria": f'=OR(AND(ISNUMBER({top}),{top}>{highlight.threshold!r}),'
                        f'ISTEXT({top}))'})


def _check_highlight(frames, highlight, sheet):
    if highlight is None:
        return
    columns = {c for f in frames for c in f.columns}
    for name in highlight.columns:
        if name not in columns:
            raise InputError(f"column to highlight is not in the table; columns are "
                             f"{sorted(map(str, columns))}", name, sheet=sheet)


def _alignments(frame, columns):
    """Cell and header alignment of each column: numbers right, short ids centred, long
    text wrapped, everything at the top of its row."""
    cells, heads = [], []
    for j in range(frame.shape[1]):
        series = frame.iloc[:, j]
        values = list(series) if _is_text(series) else None
        texts = values is not None and all(isinstance(v, str) or v is None for v in values)
        if j in columns.wrapped:
            cells.append(_WRAP if texts else _WRAP_GENERAL)  # numbers stay right-aligned
            heads.append(_HEADER_ALIGN)
        elif pd.api.types.is_bool_dtype(series.dtype) or (
                texts and values
                and max(len(v) if isinstance(v, str) else 0 for v in values) <= _ID_WIDTH):
            cells.append(_CENTER)
            heads.append(_HEADER_CENTER)
        elif (pd.api.types.is_numeric_dtype(series.dtype)
              or _explained_numbers(series, frame.columns[j])):
            cells.append(_RIGHT)  # numbers, and the text of an infinite one
            heads.append(_HEADER_RIGHT)
        elif texts:
            cells.append(_LEFT)  # text: a little room from the number on its left
            heads.append(_HEADER_ALIGN)
        else:
            cells.append(_TOP)  # mixed numbers and text: Excel's own alignment
            heads.append(_HEADER_ALIGN)
    return cells, heads


def _write_table(writer, frame, formats, columns, highlight, paginate=None):
    """Header and rows of ``frame`` at the writer's current row.

    ``paginate``, when given, is called with the printed height [px] of each data row before
    it is written, and returns True when it has put a page break above it: the header row
    is then written again at the top of the new page (a table of a sheet of several
    sections continues under its own column headers, which the sheet's repeated title rows
    cannot give)."""
    names = [str(c) for c in frame.columns]
    if len(names) > EXCEL_MAX_COLUMNS:
        raise InputError(f"a table has more than Excel's {EXCEL_MAX_COLUMNS} columns",
                         len(names), sheet=writer.ws.name)
    cells, heads = _alignments(frame, columns)
    header_styles = [_style(_HEADER_FONT, None, h, _HEADER_FILL, _HEADER_BORDER)
                     for h in heads]
    writer.append(names, header_styles)
    first = writer.row + 1
    segments = []  # (first, last) rows of the data between repeated headers (1-based)
    per_row = _row_unit_columns(frame, formats)
    unit_at = names.index("unit") if per_row else None
    ratio = [header_unit(c) == "-" for c in names]
    wrapping = [j for j, a in enumerate(cells) if ("text_wrap", True) in a]
    cell_format = writer.wb.cell_format
    texts = [cell_format(_style(None, None, a)) for a in cells]  # text: no number format
    looks = [{} for _ in cells]  # per column: number format -> cell format
    for row in frame.itertuples(index=False, name=None):
        values = [_plain(v) for v in row]
        fmts, small = formats, ratio
        if per_row:
            unit = row[unit_at]
            fmts, small = list(formats), list(ratio)
            for j in per_row:
                fmts[j] = unit_format(unit)
                small[j] = unit == "-"
        out = list(texts)
        for j, shown in enumerate(values):
            if isinstance(shown, (int, float)):
                fmt = fmts[j]
                if fmt is not None:
                    fmt = value_format(shown, fmt, small[j])
                made = looks[j].get(fmt)
                if made is None:
                    made = looks[j][fmt] = cell_format(_style(None, fmt, cells[j]))
                out[j] = made
        lines = writer.lines(values, wrapping)
        if paginate is not None and paginate(ROW_PIXELS * lines):
            segments.append((first, writer.row))
            writer.append(names, header_styles)
            first = writer.row + 1
        writer.write(values, out, lines)
    segments.append((first, writer.row))
    for start, stop in segments:
        _highlight(writer, frame, start, stop, highlight)


def frame_title(frame, default=""):
    """The title a DataFrame sheet carries (``frame.attrs["title"]``), or ``default``."""
    return str(frame.attrs.get("title", default)) if hasattr(frame, "attrs") else default


def write_table_sheets(wb, name, frame, *, number_format=None, highlight=None,
                       max_rows=EXCEL_MAX_ROWS, info=None):
    """Write a DataFrame to one sheet, or to ``NAME_1``, ``NAME_2``... when too long.

    The header is row 1; it is frozen and repeated on every printed page. The page header
    shows ``frame.attrs["title"]`` when the frame has one.

    Parameters
    ----------
    wb : _Workbook
        The workbook being written.
    name : str
        Sheet name (base name when split).
    frame : pandas.DataFrame
        Table in report units, headers carrying units (``"Vy [lbf]"``).
    number_format : mapping or callable, optional
        Excel number format per column header overriding the format of its unit
        (``{"residual [N]": "0.00E+00"}``), or a function of the header returning a format or
        None.
    highlight : Highlight, optional
        Columns whose cells above a threshold are filled red.
    max_rows : int
        Rows per sheet including the header; Excel's limit by default (a test uses less).
    info : ReportInfo, optional
        Page header and footer.

    Returns
    -------
    list of str
        The sheet names written, in order.
    """
    _check_highlight([frame], highlight, name)
    formats = _number_formats(frame.columns, number_format)
    columns = _column_plan([frame], formats_of=lambda f: formats)
    title = frame_title(frame, name)
    names = []
    for sheet_name, start, stop in split_sheet_names(name, len(frame), max_rows):
        ws = wb.add_worksheet(sheet_name)
        ws.freeze_panes(_freeze(frame, 1))
        _set_widths(ws, columns)
        print_setup(ws, pixels=columns.pixels, height=ROW_PIXELS * (stop - start + 1),
                    title_rows=1, sheet_title=title, info=info)
        _write_table(_SheetWriter(wb, ws, columns.widths), frame.iloc[start:stop], formats,
                     columns, highlight)
        names.append(sheet_name)
    return names


def _table_pixels(frame, columns):
    """Estimated printed height of a table with its header row. [px]"""
    header = max(wrapped_lines(c, columns.widths.get(j, 10), bold=True)
                 for j, c in enumerate(map(str, frame.columns))) if frame.shape[1] else 1
    lines = len(frame)
    for j in columns.wrapped:
        if j < frame.shape[1]:
            extra = frame.iloc[:, j].map(
                lambda v, w=columns.widths[j]: wrapped_lines(v, w) - 1 if isinstance(v, str)
                else 0)
            lines += int(extra.sum())
    return ROW_PIXELS * (header + lines)


def _page_pixels(orientation, pixels):
    """Printable height of a page in sheet pixels, after the fit-to-width shrink. [px]"""
    width, height = PRINTABLE[orientation]
    return height / min(1.0, width / max(pixels, 1.0))


def write_sections_sheet(wb, name, sections, *, number_format=None, highlight=None,
                         info=None):
    """Write titled blocks (notes and tables) one under another on one sheet.

    A sheet whose only table is its last block is a table sheet: the rows down to the
    table's header are frozen and repeated on every printed page. Otherwise the first row
    (the sheet's title) is frozen and repeated, and a block that would straddle a page
    break but fits on one page starts on a new page.

    Parameters
    ----------
    wb : _Workbook
        The workbook being written.
    name : str
        Sheet name.
    sections : sequence of Section
    number_format, highlight
        As in :func:`write_table_sheets`, applied to every table of the sheet.
    info : ReportInfo, optional
        Page header and footer.

    Returns
    -------
    list of str
        ``[name]``.
    """
    ws = wb.add_worksheet(check_sheet_name(name))
    tables = [s.table for s in sections if s.table is not None]
    _check_highlight(tables, highlight, name)
    columns = _column_plan(tables, [s.note for s in sections],
                           formats_of=lambda f: _number_formats(f.columns, number_format))
    _set_widths(ws, columns)
    blocks = [(s.title, _note_lines(s.note, columns) if s.note else [], s.table)
              for s in sections]
    one_table = len(tables) == 1 and sections[-1].table is not None
    if one_table:
        header_row = sum(bool(t) + len(n) + (k > 0) for k, (t, n, _) in enumerate(blocks)) + 1
        ws.freeze_panes(_freeze(tables[0], header_row))
        title_rows = header_row
    else:  # the first row is the sheet's title when the first block has no table
        heading = bool(blocks) and bool(blocks[0][0]) and blocks[0][2] is None
        if heading:
            ws.freeze_panes("A2")
        title_rows = 1 if heading else None
    sheet_title = next((s.title for s in sections if s.title), name)
    needs = [ROW_PIXELS * (bool(title) + len(lines) + (k > 0))
             + (_table_pixels(table, columns) if table is not None else 0)
             for k, (title, lines, table) in enumerate(blocks)]
    orientation = print_setup(ws, pixels=columns.pixels, height=sum(needs),
                              title_rows=title_rows, sheet_title=sheet_title, info=info)
    page = _page_pixels(orientation, columns.pixels) * 0.95
    repeated = ROW_PIXELS * (title_rows or 0)
    writer = _SheetWriter(wb, ws, columns.widths)
    top = 0  # pixels written when the current page began

    def capacity(start):
        return page - (repeated if start else 0)

    def paginate(need):
        """Break the page above a data row that would not fit on the current one (a sheet
        of several sections: its tables continue under their headers)."""
        nonlocal top
        while writer.pixels - top > capacity(top):
            top += capacity(top)
        if writer.pixels - top + need <= capacity(top) or writer.pixels == top:
            return False
        writer.page_break()
        top = writer.pixels
        return True

    for k, ((title, lines, table), need) in enumerate(zip(blocks, needs, strict=True)):
        while writer.pixels - top > capacity(top):
            top += capacity(top)
        fits = writer.pixels - top + need <= capacity(top)
        if not one_table and k and not fits and need <= capacity(1):
            writer.page_break()
            top = writer.pixels
        if k:
            writer.blank()
        if title:
            writer.append([title], _TITLE_STYLE)
        for line in lines:
            writer.append([line])
        if table is not None:
            formats = _number_formats(table.columns, number_format)
            _write_table(writer, table, formats, columns, highlight,
                         paginate=None if one_table else paginate)
    writer.close()
    return [name]


# ----------------------------------------------------------------------------- images
def header_footer_text(text):
    """Text from an input made safe for a printed header or footer: there ``&`` starts a
    control code (``&P`` page number, ``&"font"``, ``&[Path]``...), so it is doubled, and
    control characters are dropped.

    >>> header_footer_text("R&D study &P")
    'R&&D study &&P'
    """
    text = "".join(c for c in str(text) if c >= " " or c == "\n")
    return text.replace("&", "&&")


def _image_box(width, height, page_rows, page_width):
    """Displayed size of an image [px] and the rows it takes: the printable width, at most
    half a page high (two plots to a page), or a whole page for a tall figure."""
    half = (page_rows // 2 - 3) * ROW_PIXELS
    full = (page_rows - 3) * ROW_PIXELS
    scale = page_width / width
    limit = half if height * scale <= 1.3 * half else full
    scale = min(scale, limit / height)
    w, h = int(width * scale), int(height * scale)
    return w, h, math.ceil(h / ROW_PIXELS) + 2


def _png_geometry(png):
    """Size and resolution of a PNG image, from its ``IHDR`` and ``pHYs`` chunks.

    Parameters
    ----------
    png : bytes

    Returns
    -------
    (int, int, float, float)
        Width and height [px], horizontal and vertical resolution [dots per inch] as
        XlsxWriter reads them (96 when the file states none, or none in metres).

    Raises
    ------
    InputError
        If ``png`` is not a PNG image.
    """
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        raise InputError("a report image must be a PNG image", bytes(png[:8]))
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    dpi = (96.0, 96.0)
    at = 8
    while at + 8 <= len(png):
        size, kind = int.from_bytes(png[at:at + 4], "big"), png[at + 4:at + 8]
        if kind == b"pHYs" and size >= 9:
            x, y = int.from_bytes(png[at + 8:at + 12], "big"), \
                int.from_bytes(png[at + 12:at + 16], "big")
            if png[at + 16] == 1 and x > 0 and y > 0:  # pixels per metre
                dpi = (x * 0.0254, y * 0.0254)
            break
        if kind in (b"IDAT", b"IEND"):  # pHYs comes before the image data
            break
        at += 12 + size
    return width, height, *dpi


def _insert_png(ws, row, png, width, height, name):
    """Embed ``png`` with its top left corner at the top left of cell (row, A), displayed
    ``width`` x ``height`` px (as at 96 dpi), moving with its cell (not sized with it)."""
    w, h, x_dpi, y_dpi = _png_geometry(png)
    # XlsxWriter displays w * x_scale * 96 / x_dpi pixels
    ws.insert_image(row, 0, name, {
        "image_data": io.BytesIO(png), "object_position": 2,
        "x_scale": width * x_dpi / (96.0 * w), "y_scale": height * y_dpi / (96.0 * h)})


def write_images_sheet(wb, name, images, *, info=None, orientation="portrait", title=""):
    """Embed PNG images one under another, each under its title, scaled to the printable
    width, with a page break wherever the next one would not fit on the page.

    Parameters
    ----------
    wb : _Workbook
        The workbook being written.
    name : str
        Sheet name.
    images : mapping of str to (matplotlib.figure.Figure or bytes)
        Title -> figure or PNG bytes.
    info : ReportInfo, optional
        Page header and footer.
    orientation : str
        ``"portrait"`` or ``"landscape"``.
    title : str
        Printed in the page header (default: ``Plots (n)``).

    Returns
    -------
    list of str
        ``[name]``.
    """
    ws = wb.add_worksheet(check_sheet_name(name))
    page_width, page_height = PRINTABLE[orientation]
    page_rows = page_height // ROW_PIXELS
    width = (page_width - 10 - 5) // 7
    _set_widths(ws, _Columns({0: width}, set()))
    pixels = _px(width)
    print_setup(ws, pixels=pixels if orientation == "portrait" else 2 * pixels,
                sheet_title=title or f"Plots ({len(images)})", info=info)
    _orient(ws, orientation)
    writer = _SheetWriter(wb, ws)
    used = 0
    pngs = collect_pngs(images.values())  # drawn here when the helper is behind
    for k, (title, figure) in enumerate(zip(images, pngs, strict=True)):
        png = figure_png(figure)
        size = _png_geometry(png)[:2]
        w, h, rows = _image_box(*size, page_rows, pixels - 10)
        # a title wider than the page is cut when printed: wrapped (12 pt bold ~ 1.45 x)
        lines = textwrap.wrap(str(title), max(20, int((pixels - 10) / (_CHAR_PIXELS * 1.45))))
        lines = lines or [""]
        rows += len(lines) - 1
        if used and used + rows > page_rows:
            writer.page_break()
            used = 0
        for line in lines[:-1]:
            writer.append([line], _TITLE_STYLE)
        writer.append([lines[-1]], _TITLE_STYLE)
        _insert_png(ws, writer.row, png, w, h, f"plot{k + 1}.png")
        writer.blank(rows - 1)
        used += rows
    writer.close()
    return [name]


# ----------------------------------------------------------------------------- workbook
SheetContent = pd.DataFrame | Sequence[Section] | str


def _sheet_plan(sheets, images, images_sheet, max_rows):
    """(sheet name, title) of every sheet to write, in order, before anything is written."""
    plan = []
    for name, content in sheets.items():
        check_sheet_name(name)
        if isinstance(content, pd.DataFrame):
            title = frame_title(content, name)
            plan += [(n, title) for n, _, _ in split_sheet_names(name, len(content), max_rows)]
        elif isinstance(content, str):
            plan.append((name, content.splitlines()[0] if content else name))
        else:
            plan.append((name, next((s.title for s in content if s.title), name)))
    if images:
        plan.append((images_sheet, "; ".join(images)))
    seen = set()
    for n, _ in plan:
        if n.lower() in seen:
            raise InputError("sheet names must be unique (Excel ignores case)", n)
        seen.add(n.lower())
    return plan


def _table_cells(sheets):
    """Cells of the tables of ``sheets`` (of :func:`write_workbook`)."""
    frames = [c for c in sheets.values() if isinstance(c, pd.DataFrame)]
    frames += [s.table for c in sheets.values() if not isinstance(c, (pd.DataFrame, str))
               for s in c if s.table is not None]
    return sum(f.size for f in frames)


def write_workbook(path, sheets, images=None, *, number_format=None,
                   highlight: Mapping[str, Highlight] | None = None,
                   max_rows=EXCEL_MAX_ROWS, images_sheet="Plots",
                   creator="slingloads", info=None, images_title="") -> list[str]:
    """Write a report workbook from DataFrames, titled sections, notes and images.

    This is the one workbook writer of the reports (loads, lateral pendulum, parachute
    sizing): each report builds its DataFrames in report units and passes them here.

    Parameters
    ----------
    path : path-like
        ``.xlsx`` file to write (normally a temporary path from
        :func:`slingloads.io.common.atomic.atomic_outputs`).
    sheets : mapping of str to (DataFrame, sequence of Section, or str)
        Sheet name -> content, in workbook order. A DataFrame is one table (split over
        ``NAME_1``, ``NAME_2``... when longer than ``max_rows``; ``frame.attrs["title"]`` is
        its printed title); a sequence of :class:`Section` is written block after block; a
        str is a note.
    images : mapping of str to (Figure or bytes), optional
        Title -> figure or PNG bytes, embedded on the sheet ``images_sheet``.
    number_format : mapping or callable, optional
        Excel number format per column header, overriding the format of its unit (see
        :func:`write_table_sheets`).
    highlight : mapping of str to Highlight, optional
        Sheet name -> columns to fill red above a threshold.
    max_rows : int
        Rows per sheet including the header. Default: Excel's limit, 1,048,576.
    images_sheet : str
        Name of the sheet holding the images.
    creator : str
        Workbook author property.
    info : ReportInfo, optional
        The report's identity: with it the workbook opens on a *Cover* sheet
        (:mod:`slingloads.io.common.cover`) and every page header and footer names the
        report, the input file, the run date and the version.
    images_title : str
        Page-header title of the images sheet (default ``Plots (n)``).

    Returns
    -------
    list of str
        Sheet names written, in order.

    Raises
    ------
    InputError
        On an invalid or duplicate sheet name, text Excel cannot store (control characters,
        more than 32,767 characters), or more than 16,384 columns.
    """
    highlight = highlight or {}
    plan = _sheet_plan(sheets, images, images_sheet, max_rows)
    if not plan:
        raise InputError("a workbook needs at least one sheet")
    if info is not None:
        from slingloads.io.common.cover import COVER_SHEET, cover_sections

        if any(n.lower() == COVER_SHEET.lower() for n, _ in plan):
            raise InputError("sheet names must be unique (Excel ignores case)", COVER_SHEET)
    # XlsxWriter's temporary files (the rows of each sheet, the parts of the file) go to a
    # folder of their own, removed with whatever a workbook refused half-way leaves there
    with tempfile.TemporaryDirectory(prefix="slingloads-xlsx-",
                                     ignore_cleanup_errors=True) as tmp:
        wb = _Workbook(path, stream=_table_cells(sheets) > IN_MEMORY_CELLS, tmpdir=tmp)
        wb.set_properties({"author": creator, **({"title": info.title} if info else {})})
        mark_report(wb)
        written = []
        if info is not None:
            written += write_cover_sheet(wb, COVER_SHEET, cover_sections(info, plan), info)
        for name, content in sheets.items():
            mark = highlight.get(name)
            if isinstance(content, pd.DataFrame):
                written += write_table_sheets(wb, name, content, number_format=number_format,
                                              highlight=mark, max_rows=max_rows, info=info)
            elif isinstance(content, str):
                written += write_sections_sheet(wb, name, [Section(note=content)], info=info)
            else:
                written += write_sections_sheet(wb, name, list(content),
                                                number_format=number_format, highlight=mark,
                                                info=info)
        if images:
            written += write_images_sheet(wb, images_sheet, images, info=info,
                                          title=images_title)
        wb.save()
    return written


def mark_report(wb):
    """Give a workbook slingloads' mark: the custom document property
    :data:`~slingloads.io.common.ownership.XLSX_PROPERTY` = ``slingloads <version>``, by
    which a later run knows it may replace the file (no cell changes)."""
    from slingloads import __version__
    from slingloads.io.common.ownership import XLSX_PROPERTY

    wb.set_custom_property(XLSX_PROPERTY, f"slingloads {__version__}")


def write_cover_sheet(wb, name, sections, info):
    """The cover: a large title, then the cover's sections (two-column tables and notes),
    on one portrait page."""
    ws = wb.add_worksheet(check_sheet_name(name))
    columns = _Columns({0: 24, 1: 72}, {1})
    _set_widths(ws, columns)
    print_setup(ws, pixels=columns.pixels, sheet_title="Cover", info=info)
    ws.fit_to_pages(1, 1)  # a long list of sheets and files shrinks, never spills
    writer = _SheetWriter(wb, ws, columns.widths)
    writer.append([info.title], _style(_COVER_TITLE_FONT))
    wrap = _style(None, None, _WRAP)
    for title, note, table in sections:
        writer.blank()
        if title:
            writer.append([title], _TITLE_STYLE)
        for line in _note_lines(note, columns) if note else []:
            writer.append([line])
        if table is not None:
            writer.append(list(table.columns), _HEADER_STYLE)
            for row in table.itertuples(index=False, name=None):
                writer.append(list(row), [None] + [wrap] * (len(row) - 1))
    return [name]


def format_by_header(rules: Sequence[tuple[str, str]],
                     default: str | None = None) -> Callable[[str], str | None]:
    """Number format chosen by the first regular expression that matches a column header.

    Parameters
    ----------
    rules : sequence of (str, str)
        ``(pattern, excel number format)`` pairs, tried in order with :func:`re.search`.
    default : str, optional
        Format when no pattern matches (None: the format of the header's unit).

    Returns
    -------
    callable
        header -> number format or None.

    Examples
    --------
    >>> fmt = format_by_header([(r"residual", "0.00E+00")])
    >>> fmt("closure force residual [N]"), fmt("case")
    ('0.00E+00', None)
    """
    compiled = [(re.compile(p), f) for p, f in rules]

    def pick(header):
        for pattern, fmt in compiled:
            if pattern.search(header):
                return fmt
        return default

    return pick

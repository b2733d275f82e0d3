"""The cells of a report workbook: Excel's limits, cell styles, and values written as what
they are.

What this module guarantees: every value is stored faithfully (:func:`cell_value`): a string as
text, never as a formula (a text that looks like XlsxWriter's rich-string markup is written
as two runs, so that it too is escaped), NaN as an empty cell, +/-inf as the text
:data:`INFINITE_TEXT`, booleans as ``yes``/``no``; a text Excel cannot store (a control
character, more than :data:`EXCEL_MAX_CELL_CHARS` characters) or a row past
:data:`EXCEL_MAX_ROWS` is refused with its sheet and cell, never truncated; a sheet name is one
Excel accepts (:func:`check_sheet_name`); each cell format is made once per workbook
(:class:`ReportWorkbook`), and a row of wrapped text is as tall as its tallest cell.

References
----------
.. [1] Microsoft, "Excel specifications and limits": 1,048,576 rows by 16,384 columns;
   32,767 characters per cell; sheet names of at most 31 characters without ``: \\ / ? * [ ]``.
.. [3] W3C, "Extensible Markup Language (XML) 1.0", 2.2 Characters: the control characters
   below U+0020 other than tab, line feed and carriage return are not allowed.
"""

from __future__ import annotations

import math
import numbers
import re

import numpy as np
import pandas as pd
import xlsxwriter
from xlsxwriter.exceptions import FileCreateError
from xlsxwriter.utility import xl_rowcol_to_cell

from slingloads.errors import InputError
from slingloads.io.common.units import report_text

#: Rows in one Excel worksheet (header included) [1]_.
EXCEL_MAX_ROWS = 1_048_576
#: Columns in one Excel worksheet [1]_.
EXCEL_MAX_COLUMNS = 16_384
#: Characters in one Excel cell [1]_.
EXCEL_MAX_CELL_CHARS = 32_767
#: Characters in a sheet name [1]_.
EXCEL_MAX_SHEET_NAME = 31
#: Widest text column [characters]; longer text wraps.
MAX_TEXT_WIDTH = 40
#: Widest numeric column [characters].
MAX_NUMBER_WIDTH = 16
#: Pixel height of a default row (15 pt at 96 dpi).
ROW_PIXELS = 20
_BAD_SHEET_CHARS = re.compile(r"[:\\/?*\[\]]")
#: Characters an XML 1.0 document cannot hold [3]_ (openpyxl's ``ILLEGAL_CHARACTERS_RE``).
_ILLEGAL_CHARACTERS = re.compile(r"[\000-\010]|[\013-\014]|[\016-\037]")
_FONT = "Calibri"


def _props(**kwargs):
    """XlsxWriter format properties as a hashable tuple of ``(name, value)`` pairs."""
    return tuple(sorted(kwargs.items()))


# Parts of a cell style: tuples of XlsxWriter format properties, combined by cell_style().
_TITLE_FONT = _props(font_name=_FONT, bold=True, font_size=12)
COVER_TITLE_FONT = _props(font_name=_FONT, bold=True, font_size=16)
HEADER_FONT = _props(font_name=_FONT, bold=True)
HEADER_FILL = _props(pattern=1, fg_color="#DDEBF7", bg_color="#DDEBF7")  # solid
HEADER_BORDER = _props(bottom=1)  # thin
HEADER_ALIGN = _props(text_wrap=True, valign="bottom")
HEADER_RIGHT = _props(text_wrap=True, valign="bottom", align="right")
HEADER_CENTER = _props(text_wrap=True, valign="bottom", align="center")
WRAP = _props(text_wrap=True, valign="top", align="left", indent=1)
WRAP_GENERAL = _props(text_wrap=True, valign="top")
TOP = _props(valign="top")
LEFT = _props(valign="top", align="left", indent=1)
RIGHT = _props(valign="top", align="right")
CENTER = _props(valign="top", align="center")
#: Longest text of a column of ids that is centred (case, station, yes/no).
ID_WIDTH = 10
#: The conditional format of a highlighted cell: red fill, dark red text.
_RED = {"bg_color": "#FFC7CE", "font_color": "#9C0006"}
#: Average width of a character of text in Calibri 11 (digits are 7 px). [px]
CHAR_PIXELS = 6.3
#: Pixels of a column per character of its stored width (a Calibri 11 digit).
DIGIT_PIXELS = 7
#: Advance widths of the printable ASCII characters (space to ``~``) in Calibri 11, as
#: Carlito (metric-compatible with Calibri, the font LibreOffice prints the reports in) gives
#: them: font units of a 2048-unit em (the fonts' ``hmtx`` tables), regular and bold. A
#: character outside this range counts as the widest of its table (a row too tall, never
#: text hidden). [1/2048 em]
_ADVANCE = {
    False: (
    463, 667, 821, 1020, 1038, 1464, 1397, 452, 621, 621, 1020, 1020, 511, 627, 517, 791,
    1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 548, 548, 1020, 1020, 1020,
    949, 1831, 1185, 1114, 1092, 1260, 1000, 941, 1292, 1276, 516, 653, 1064, 861, 1751,
    1322, 1356, 1058, 1378, 1112, 941, 998, 1314, 1162, 1822, 1063, 998, 959, 628, 791, 628,
    1020, 1020, 596, 981, 1076, 866, 1076, 1019, 625, 964, 1076, 470, 490, 931, 470, 1636,
    1076, 1080, 1076, 1076, 714, 801, 686, 1076, 925, 1464, 887, 927, 809, 644, 943, 644,
    1020
    ),
    True: (
    463, 667, 898, 1020, 1038, 1493, 1443, 478, 638, 638, 1020, 1020, 528, 627, 547, 880,
    1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 1038, 565, 565, 1020, 1020, 1020,
    949, 1840, 1241, 1148, 1084, 1291, 999, 940, 1305, 1292, 546, 678, 1120, 866, 1790,
    1349, 1385, 1090, 1405, 1153, 968, 1014, 1337, 1211, 1856, 1128, 1064, 979, 665, 880,
    665, 1020, 1020, 615, 1011, 1099, 857, 1099, 1031, 648, 971, 1099, 503, 523, 983, 503,
    1666, 1099, 1101, 1099, 1099, 728, 817, 710, 1099, 969, 1526, 941, 970, 814, 704, 973,
    704, 1020
    ),
}
#: Pixels per font unit of Calibri 11 at 96 dpi (11 pt = 14.67 px to the em). [px]
_FONT_UNIT_PIXELS = 11 * 96 / 72 / 2048
#: Pixels of a cell's width that its wrapped text does not use (its padding, with a margin:
#: LibreOffice wraps a 285 px column at 283-286 px of Carlito text). [px]
_CELL_PADDING = 8


def column_pixels(width):
    """Pixels of a column ``width`` characters wide (Calibri 11: 7 px per digit + 5)."""
    return 7 * width + 5


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


def cell_value(value):
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
        return ", ".join(str(cell_value(v)) for v in value)
    return str(value)


def text_pixels(text, bold=False):
    """Width of one line of ``text`` in Calibri 11 at 96 dpi, from the font's advance
    widths (:data:`_ADVANCE`). [px]"""
    table = _ADVANCE[bool(bold)]
    widest = max(table)
    units = sum(table[o - 32] if 32 <= o < 127 else widest for o in map(ord, str(text)))
    return units * _FONT_UNIT_PIXELS


def wrapped_lines(text, width, bold=False):
    """Lines that ``text`` takes in a wrapped cell ``width`` characters wide, as Excel and
    LibreOffice wrap it: words laid greedily on lines as wide as the cell less its padding,
    measured with the font's advance widths (:func:`text_pixels`); a word wider than a line
    broken across lines. A cautious estimate (a row too tall wastes a little paper, a row too
    short hides text): it breaks only at spaces, where the spreadsheets also break after a
    hyphen, so that none of its lines holds more than theirs."""
    room = max(column_pixels(width) - _CELL_PADDING, 4 * DIGIT_PIXELS)
    space = text_pixels(" ", bold)
    count = 0
    for part in str(text).split("\n"):
        lines, used = 1, 0.0
        for word in part.split():
            wide = text_pixels(word, bold)
            if used and used + space + wide <= room:
                used += space + wide
                continue
            if used:
                lines += 1
            extra = max(0, math.ceil(wide / room) - 1)  # a long word broken by character
            lines += extra
            used = wide - extra * room
        count += lines
    return count


class ReportWorkbook(xlsxwriter.Workbook):
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
        #: The report's unit system: the SI quantities quoted in its sentences are written
        #: in it (:func:`~slingloads.io.common.units.report_text`).
        self.units = "SI"
        self._red = None

    def cell_format(self, style):
        """The XlsxWriter ``Format`` of a (font, number format, alignment, fill, border)
        style (:func:`cell_style`), made on first use; None for a style of nothing."""
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


class SheetWriter:
    """Writes rows into one sheet, one after the other, keeping track of the row number, of
    the height of the rows written and of the page breaks asked for.

    Cell formats come from :meth:`ReportWorkbook.cell_format`, one per style. A row with wrapped
    text gets the height of its tallest wrapped cell (LibreOffice does not compute it when
    it opens the file).

    Parameters
    ----------
    wb : ReportWorkbook
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
        """Write the string ``value`` as text (never a formula), its quoted SI quantities in
        the report's units."""
        value = report_text(value, self.wb.units)
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
        """Write one row of plain values (:func:`cell_value`), one format (or None) each, of
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
        values = [cell_value(v) for v in values]
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


def cell_style(font=None, number_format=None, alignment=None, fill=None, border=None):
    """A cell's style as the writer keys its formats: (font, number format, alignment,
    fill, border), each a property dict or None."""
    return (font, number_format, alignment, fill, border)


_PLAIN = cell_style(_props(font_name=_FONT))
TITLE_STYLE = cell_style(_TITLE_FONT)
HEADER_STYLE = cell_style(HEADER_FONT, None, HEADER_ALIGN, HEADER_FILL, HEADER_BORDER)

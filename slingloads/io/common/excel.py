"""Small openpyxl helpers that format pandas DataFrames into a report workbook.

The writer only formats: it receives DataFrames already in report units with unit-labelled
headers, and images already drawn. What it guarantees:

* every string is stored as text, never as a formula: a case description such as
  ``=HYPERLINK("x")`` or ``+cmd|' /C calc'!A0`` is an inline string cell (``data_type "s"``),
  so a hostile or accidental leading ``=``, ``+``, ``-`` or ``@`` is never evaluated;
* a bold header row, frozen header (and first column when it holds ids), column widths from
  the contents, number formats per column;
* NaN is an empty cell and +/-inf the text ``inf``/``-inf`` (Excel has neither; openpyxl
  would otherwise write ``nan``, which Excel reports as a corrupt file);
* a table longer than Excel's row limit is split over several sheets ``NAME_1``, ``NAME_2``...
  with the header repeated, never truncated;
* PNG images embedded, and a red fill on ratio cells above a threshold (conditional
  formatting, so the rule stays visible in Excel).

The workbook is written in openpyxl's write-only (streaming) mode, so memory does not grow
with the number of rows.

References
----------
.. [1] Microsoft, "Excel specifications and limits": 1,048,576 rows by 16,384 columns;
   32,767 characters per cell; sheet names of at most 31 characters without ``: \\ / ? * [ ]``.
"""

from __future__ import annotations

import io
import math
import numbers
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from openpyxl import Workbook
from openpyxl.cell import WriteOnlyCell
from openpyxl.drawing.image import Image
from openpyxl.formatting.formatting import ConditionalFormattingList
from openpyxl.formatting.rule import FormulaRule
from openpyxl.styles import Font, PatternFill
from openpyxl.utils import get_column_letter
from openpyxl.utils.exceptions import IllegalCharacterError

from slingloads.errors import InputError

#: Rows in one Excel worksheet (header included) [1]_.
EXCEL_MAX_ROWS = 1_048_576
#: Columns in one Excel worksheet [1]_.
EXCEL_MAX_COLUMNS = 16_384
#: Characters in one Excel cell [1]_.
EXCEL_MAX_CELL_CHARS = 32_767
#: Characters in a sheet name [1]_.
EXCEL_MAX_SHEET_NAME = 31

_BAD_SHEET_CHARS = re.compile(r"[:\\/?*\[\]]")
_HEADER_FONT = Font(bold=True)
_TITLE_FONT = Font(bold=True, size=12)
_RED_FILL = PatternFill("solid", start_color="FFC7CE", end_color="FFC7CE")
_RED_FONT = Font(color="9C0006")
#: Pixel height of a default Excel row (15 pt at 96 dpi).
_ROW_PIXELS = 20


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
        Written as one text cell per line under the title (before the table).
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
        Cells with a number greater than this (or the text ``inf``) are filled red.
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


def _plain(value):
    """A Python value openpyxl writes faithfully (numpy scalars unwrapped, NaN -> None)."""
    if isinstance(value, np.generic):
        value = value.item()
    if value is None or value is pd.NA or value is pd.NaT:
        return None
    if isinstance(value, bool):
        return value
    if isinstance(value, numbers.Real):
        value = float(value) if not isinstance(value, numbers.Integral) else int(value)
        if isinstance(value, float):
            if math.isnan(value):
                return None
            if math.isinf(value):
                return "inf" if value > 0 else "-inf"
        return value
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple, np.ndarray)):
        return ", ".join(str(_plain(v)) for v in value)
    return str(value)


class _SheetWriter:
    """Streams rows into one write-only sheet, keeping track of the row number."""

    def __init__(self, ws):
        self.ws = ws
        self.row = 0
        self._cells = {}

    def _cell(self, value, *, font=None, number_format=None, column=0):
        value = _plain(value)
        cell = WriteOnlyCell(self.ws)
        try:
            cell.value = value
        except IllegalCharacterError:
            raise InputError("text contains a control character that Excel cannot store",
                             value, sheet=self.ws.title,
                             cell=f"{get_column_letter(column + 1)}{self.row + 1}") from None
        if isinstance(value, str):
            if len(value) > EXCEL_MAX_CELL_CHARS:
                raise InputError(f"text longer than Excel's {EXCEL_MAX_CELL_CHARS} characters "
                                 "per cell", value[:40] + "...", sheet=self.ws.title,
                                 cell=f"{get_column_letter(column + 1)}{self.row + 1}")
            cell.data_type = "s"  # text, never a formula
        if font is not None:
            cell.font = font
        if number_format and not isinstance(value, str) and value is not None:
            cell.number_format = number_format
        return cell

    def append(self, values, *, font=None, formats=None):
        formats = formats or [None] * len(values)
        self.ws.append([self._cell(v, font=font, number_format=f, column=j)
                        for j, (v, f) in enumerate(zip(values, formats, strict=True))])
        self.row += 1

    def blank(self, n=1):
        for _ in range(n):
            self.ws.append([])
            self.row += 1


def _number_formats(columns, number_format):
    if number_format is None:
        return [None] * len(columns)
    if isinstance(number_format, Mapping):
        return [number_format.get(c) for c in columns]
    return [number_format(str(c)) for c in columns]


def _column_widths(frames, notes=(), sample=200, lo=8, hi=60):
    """Column widths [characters] from headers and a sample of values."""
    widths = {}
    for frame in frames:
        for j, col in enumerate(frame.columns):
            texts = [str(col)]
            values = frame.iloc[:sample, j]
            for v in values:
                v = _plain(v)
                texts.append(f"{v:.6g}" if isinstance(v, float) else str(v))
            widths[j] = max(widths.get(j, 0), max(len(t) for t in texts))
    for line in notes:
        widths[0] = max(widths.get(0, 0), min(len(line), 20))
    return {j: min(max(w + 2, lo), hi) for j, w in widths.items()}


def _set_widths(ws, widths):
    for j, width in widths.items():
        ws.column_dimensions[get_column_letter(j + 1)].width = width


def _highlight(ws, frame, first_row, last_row, highlight):
    """Add a red-fill conditional format on the highlighted columns of rows first..last."""
    if highlight is None or last_row < first_row:
        return
    if getattr(ws, "conditional_formatting", None) is None:
        ws.conditional_formatting = ConditionalFormattingList()
    for name in highlight.columns:
        if name not in frame.columns:
            raise InputError(f"column to highlight is not in the table; columns are "
                             f"{list(frame.columns)}", name, sheet=ws.title)
        letter = get_column_letter(list(frame.columns).index(name) + 1)
        top = f"{letter}{first_row}"
        rule = FormulaRule(
            formula=[f'OR(AND(ISNUMBER({top}),{top}>{highlight.threshold!r}),{top}="inf")'],
            fill=_RED_FILL, font=_RED_FONT)
        ws.conditional_formatting.add(f"{letter}{first_row}:{letter}{last_row}", rule)


def _write_table(writer, frame, formats, highlight):
    """Header and rows of ``frame`` at the writer's current row."""
    columns = [str(c) for c in frame.columns]
    if len(columns) > EXCEL_MAX_COLUMNS:
        raise InputError(f"a table has more than Excel's {EXCEL_MAX_COLUMNS} columns",
                         len(columns), sheet=writer.ws.title)
    writer.append(columns, font=_HEADER_FONT)
    first = writer.row + 1
    for row in frame.itertuples(index=False, name=None):
        writer.append(row, formats=formats)
    _highlight(writer.ws, frame, first, writer.row, highlight)


def _freeze_cell(frame):
    """Freeze the header row, and the first column too when it holds text ids."""
    if frame.shape[1] > 1 and frame.iloc[:, 0].map(lambda v: isinstance(v, str)).all():
        return "B2"
    return "A2"


def write_table_sheets(wb, name, frame, *, number_format=None, highlight=None,
                       max_rows=EXCEL_MAX_ROWS):
    """Write a DataFrame to one sheet, or to ``NAME_1``, ``NAME_2``... when too long.

    Parameters
    ----------
    wb : openpyxl.Workbook
        A write-only workbook.
    name : str
        Sheet name (base name when split).
    frame : pandas.DataFrame
        Table in report units, headers carrying units (``"Vy [lbf]"``).
    number_format : mapping or callable, optional
        Excel number format per column header (``{"x [m]": "0.000"}``), or a function of the
        header returning a format or None (General).
    highlight : Highlight, optional
        Columns whose cells above a threshold are filled red.
    max_rows : int
        Rows per sheet including the header; Excel's limit by default (a test uses less).

    Returns
    -------
    list of str
        The sheet names written, in order.
    """
    formats = _number_formats(frame.columns, number_format)
    widths = _column_widths([frame])
    names = []
    for sheet_name, start, stop in split_sheet_names(name, len(frame), max_rows):
        ws = wb.create_sheet(sheet_name)
        ws.freeze_panes = _freeze_cell(frame)
        _set_widths(ws, widths)
        _write_table(_SheetWriter(ws), frame.iloc[start:stop], formats, highlight)
        names.append(sheet_name)
    return names


def write_sections_sheet(wb, name, sections, *, number_format=None, highlight=None):
    """Write titled blocks (notes and small tables) one under another on one sheet.

    Parameters
    ----------
    wb : openpyxl.Workbook
        A write-only workbook.
    name : str
        Sheet name.
    sections : sequence of Section
    number_format, highlight
        As in :func:`write_table_sheets`, applied to every table of the sheet.

    Returns
    -------
    list of str
        ``[name]``.
    """
    ws = wb.create_sheet(check_sheet_name(name))
    tables = [s.table for s in sections if s.table is not None]
    notes = [line for s in sections for line in s.note.splitlines()]
    _set_widths(ws, _column_widths(tables, notes))
    writer = _SheetWriter(ws)
    for k, section in enumerate(sections):
        if k:
            writer.blank()
        if section.title:
            writer.append([section.title], font=_TITLE_FONT)
        for line in section.note.splitlines():
            writer.append([line])
        if section.table is not None:
            formats = _number_formats(section.table.columns, number_format)
            _write_table(writer, section.table, formats, highlight)
    return [name]


def figure_png(figure, dpi=120):
    """PNG bytes of a matplotlib Figure (no timestamp or version metadata, so reproducible).

    Parameters
    ----------
    figure : matplotlib.figure.Figure or bytes
        A figure, or PNG bytes returned unchanged.
    dpi : float
        Resolution. [dots per inch]

    Returns
    -------
    bytes
    """
    if isinstance(figure, (bytes, bytearray)):
        return bytes(figure)
    _plain_text(figure)
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=dpi, metadata={"Software": None})
    return buffer.getvalue()


def header_footer_text(text):
    """Text from an input made safe for a printed header or footer: there ``&`` starts a
    control code (``&P`` page number, ``&"font"``, ``&[Path]``...), so it is doubled, and
    control characters are dropped.

    >>> header_footer_text("R&D study &P")
    'R&&D study &&P'
    """
    text = "".join(c for c in str(text) if c >= " " or c == "\n")
    return text.replace("&", "&&")


def _plain_text(figure):
    """Draw every text of ``figure`` literally: ids from the inputs (a station ``FS$1$``, a
    case ``$\\frac$``) are never parsed as mathtext, which could fail or mislead."""
    from matplotlib.text import Text

    for text in figure.findobj(Text):
        text.set_parse_math(False)


def write_images_sheet(wb, name, images, *, display_width=900):
    """Embed PNG images one under another, each under its title.

    Parameters
    ----------
    wb : openpyxl.Workbook
        A write-only workbook.
    name : str
        Sheet name.
    images : mapping of str to (matplotlib.figure.Figure or bytes)
        Title -> figure or PNG bytes.
    display_width : int
        Width at which each image is shown in Excel (the file keeps its full resolution).
        [pixels]

    Returns
    -------
    list of str
        ``[name]``.
    """
    ws = wb.create_sheet(check_sheet_name(name))
    ws.column_dimensions["A"].width = 60
    writer = _SheetWriter(ws)
    for title, figure in images.items():
        writer.append([title], font=_TITLE_FONT)
        image = Image(io.BytesIO(figure_png(figure)))
        scale = min(1.0, display_width / image.width)
        image.width, image.height = int(image.width * scale), int(image.height * scale)
        ws.add_image(image, f"A{writer.row + 1}")
        writer.blank(math.ceil(image.height / _ROW_PIXELS) + 2)
    return [name]


SheetContent = pd.DataFrame | Sequence[Section] | str


def write_workbook(path, sheets, images=None, *, number_format=None,
                   highlight: Mapping[str, Highlight] | None = None,
                   max_rows=EXCEL_MAX_ROWS, images_sheet="Plots",
                   creator="slingloads") -> list[str]:
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
        ``NAME_1``, ``NAME_2``... when longer than ``max_rows``); a sequence of
        :class:`Section` is written block after block; a str is a note.
    images : mapping of str to (Figure or bytes), optional
        Title -> figure or PNG bytes, embedded on the sheet ``images_sheet``.
    number_format : mapping or callable, optional
        Excel number format per column header (see :func:`write_table_sheets`).
    highlight : mapping of str to Highlight, optional
        Sheet name -> columns to fill red above a threshold.
    max_rows : int
        Rows per sheet including the header. Default: Excel's limit, 1,048,576.
    images_sheet : str
        Name of the sheet holding the images.
    creator : str
        Workbook author property.

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
    wb = Workbook(write_only=True)
    wb.properties.creator = creator
    written = []

    def add(names):
        for n in names:
            if n.lower() in (w.lower() for w in written):
                raise InputError("sheet names must be unique (Excel ignores case)", n)
        written.extend(names)

    for name, content in sheets.items():
        check_sheet_name(name)
        mark = highlight.get(name)
        if isinstance(content, pd.DataFrame):
            add(write_table_sheets(wb, name, content, number_format=number_format,
                                   highlight=mark, max_rows=max_rows))
        elif isinstance(content, str):
            add(write_sections_sheet(wb, name, [Section(note=content)]))
        else:
            add(write_sections_sheet(wb, name, list(content), number_format=number_format,
                                     highlight=mark))
    if images:
        add(write_images_sheet(wb, images_sheet, images))
    if not written:
        raise InputError("a workbook needs at least one sheet")
    wb.save(path)
    return written


def format_by_header(rules: Sequence[tuple[str, str]],
                     default: str | None = None) -> Callable[[str], str | None]:
    """Number format chosen by the first regular expression that matches a column header.

    Parameters
    ----------
    rules : sequence of (str, str)
        ``(pattern, excel number format)`` pairs, tried in order with :func:`re.search`.
    default : str, optional
        Format when no pattern matches (None: Excel's General).

    Returns
    -------
    callable
        header -> number format or None.

    Examples
    --------
    >>> fmt = format_by_header([(r"\\[(N|lbf)\\]$", "#,##0.0")])
    >>> fmt("Vy [lbf]"), fmt("case")
    ('#,##0.0', None)
    """
    compiled = [(re.compile(p), f) for p, f in rules]

    def pick(header):
        for pattern, fmt in compiled:
            if pattern.search(header):
                return fmt
        return default

    return pick

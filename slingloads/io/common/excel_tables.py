"""Table sheets of a report workbook: DataFrames written print-ready, alone or in sections.

What this module guarantees: a table's numbers are written at an engineering precision (an
Excel number format per unit, read from the column header or from the row's ``unit`` column,
:mod:`slingloads.io.common.formats`); columns are as wide as their contents (text wrapped
beyond :data:`~slingloads.io.common.excel_cells.MAX_TEXT_WIDTH` characters), header cells
bold and wrapped, notes wrapped to the table width; panes frozen below the header (and right
of an id column); a table longer than a sheet is split over ``NAME_1``, ``NAME_2``... with its
header repeated, never truncated; ratio cells above a threshold are filled red
(:class:`Highlight`, conditional formatting), never the repeated headers. Sheets of several
sections are laid out by :mod:`slingloads.io.common.excel_sections`.
"""

from __future__ import annotations

import math
import numbers
import re
import textwrap
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from xlsxwriter.utility import xl_col_to_name

from slingloads.errors import InputError
from slingloads.io.common.excel_cells import (
    CENTER,
    DIGIT_PIXELS,
    EXCEL_MAX_COLUMNS,
    EXCEL_MAX_ROWS,
    HEADER_ALIGN,
    HEADER_BORDER,
    HEADER_CENTER,
    HEADER_FILL,
    HEADER_FONT,
    HEADER_RIGHT,
    ID_WIDTH,
    LEFT,
    MAX_NUMBER_WIDTH,
    MAX_TEXT_WIDTH,
    RIGHT,
    ROW_PIXELS,
    TOP,
    WRAP,
    WRAP_GENERAL,
    SheetWriter,
    cell_style,
    cell_value,
    column_pixels,
    split_sheet_names,
    wrapped_lines,
)
from slingloads.io.common.excel_print import (
    MIN_PRINT_SCALE,
    PRINTABLE,
    column_pages,
    height_fit,
    orientation_for,
    page_pixels,
    print_setup,
)
from slingloads.io.common.formats import header_format, header_unit, unit_format, value_format
from slingloads.io.common.units import report_text


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
    sheet : str
        The name of a sheet of its own for this section's table (a table sheet,
        :func:`sheet_blocks`); empty: on the sheet of its list, unless it is longer than a
        page among other tables.
    keys : sequence of str
        The columns that say which row is which (run, mode, metric and unit): a table too
        wide for the page is printed in blocks of columns, each with these first
        (:func:`~slingloads.io.common.excel_sections.column_blocks`); empty: its first column
        and its ``unit`` column. A table with keys is cut even alone on its sheet (not one
        naming a sheet of its own).
    """

    title: str = ""
    table: pd.DataFrame | None = None
    note: str = ""
    sheet: str = ""
    keys: Sequence[str] = ()


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


# ----------------------------------------------------------------------------- column plan
@dataclass
class TableColumns:
    """Widths [characters] and wrapped columns of one sheet."""

    widths: dict
    wrapped: set

    @property
    def pixels(self):
        return sum(column_pixels(w) for w in self.widths.values())

    def print_blocks(self, orientation):
        """``(scale, column breaks)`` of the sheet printed in ``orientation``: fitted to the
        page width, or in blocks of columns repeating the first (the row's id) when that
        fit is below the least print scale
        (:func:`~slingloads.io.common.excel_print.column_pages`)."""
        # a column stored w characters wide shows 7 w px in Excel (set_widths), which the
        # fit to the page width is judged by (the printing application scales it), and
        # 7 w + 5 px in LibreOffice (88.8 px for w = 12, measured on its PDF export): blocks
        # of columns are cut at the wider, so that no block spills a column onto a page
        stored = [self.widths.get(j, 8.43) for j in range(max(self.widths, default=-1) + 1)]
        fit, breaks = column_pages([DIGIT_PIXELS * w for w in stored], orientation)
        if not breaks:
            return fit, breaks
        return column_pages([column_pixels(w) for w in stored], orientation)


def number_formats(columns, number_format):
    """The format of each column: the report's override, else from the header's unit."""
    out = []
    for c in columns:
        fmt = None
        if isinstance(number_format, Mapping):
            fmt = number_format.get(c)
        elif callable(number_format):
            fmt = number_format(str(c))
        out.append(fmt if fmt is not None else header_format(c))
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
        shown = cell_value(value)
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


def column_plan(tables, notes=(), formats_of=None, text_width=MAX_TEXT_WIDTH):
    """Widths of the columns of every table of a sheet, and which columns wrap: a column
    wider than :data:`~slingloads.io.common.excel_cells.MAX_TEXT_WIDTH` characters wraps at
    that width, a column of text at ``text_width`` when that is narrower (a sheet of several
    tables whose text columns wrap narrower so that its wide tables print whole,
    :func:`~slingloads.io.common.excel_sections._text_width_for`)."""
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
            limit = min(text_width, MAX_TEXT_WIDTH) if text else MAX_TEXT_WIDTH
            limit = max(limit, int(1.1 * words) + 3)  # never narrower than a header word
            if width > limit:
                wrapped.add(j)
                width = limit
            widths[j] = max(widths.get(j, 0), min(width, limit))
    if not widths and notes:
        widths[0] = MAX_TEXT_WIDTH * 2
    return TableColumns(widths, wrapped)


#: Width a wrapped text column may grow to on a table sheet (:func:`_wider_text`).
#: [characters]
WIDE_TEXT_WIDTH = 60
#: Least fit-to-width print scale a wider text column may bring a table sheet to. [-]
_WIDE_TEXT_SCALE = MIN_PRINT_SCALE


def _wider_text(frame, columns):
    """The column plan of a table sheet with its wrapped text columns widened to
    :data:`WIDE_TEXT_WIDTH` when that prints it on at least 20 % fewer pages (rows of fewer
    lines outweighing the smaller fit-to-width scale), and the print scale stays at least
    :data:`_WIDE_TEXT_SCALE`; the plan unchanged otherwise."""
    if not columns.wrapped:
        return columns
    wide = TableColumns({j: (WIDE_TEXT_WIDTH if j in columns.wrapped else w)
                     for j, w in columns.widths.items()}, set(columns.wrapped))

    def pages(plan):
        height = table_pixels(frame, plan)
        return height / page_pixels(orientation_for(plan.pixels, height), plan.pixels)

    width = PRINTABLE["landscape"][0]
    if width / wide.pixels < _WIDE_TEXT_SCALE or pages(wide) > 0.8 * pages(columns):
        return columns
    return wide


def _in_blocks(frame, columns):
    """The column plan of a table sheet that prints in blocks of columns
    (:meth:`TableColumns.print_blocks`) with its wrapped text columns as wide as their longest
    text, up to a block's width: a row of the other blocks is then one line high, not as
    many lines as its text wraps to; the plan unchanged when the table fits the width."""
    orientation = orientation_for(columns.pixels)
    if not columns.wrapped or not columns.print_blocks(orientation)[1]:
        return columns
    room = (0.9 * PRINTABLE[orientation][0] / MIN_PRINT_SCALE
            - column_pixels(columns.widths.get(0, 0)))
    widths = dict(columns.widths)
    for j in columns.wrapped:
        longest = frame.iloc[:, j].astype(str).str.len().max()
        widths[j] = max(widths[j], min(int(longest) + 1, int((room - 5) / 7)))
    return TableColumns(widths, {j for j in columns.wrapped
                             if frame.iloc[:, j].astype(str).str.len().max() > widths[j]})


def set_widths(ws, columns):
    """Set the column widths of the plan [characters], stored as they are.

    A width stored as ``w`` characters shows 7 ``w`` px wide (Excel's rule for Calibri 11);
    XlsxWriter stores ``pixels / 7``, whereas its ``set_column(w)`` would add the 5 px of
    cell padding (``w + 5/7`` stored).
    """
    for j, width in columns.widths.items():
        ws.set_column_pixels(j, j, DIGIT_PIXELS * width)


def note_lines(text, columns):
    """A note split into lines that fit the sheet's width (about 1 character per 7 px)."""
    chars = max(60, min(int(columns.pixels / 7.5), 160))
    lines = []
    for paragraph in str(text).splitlines():
        lines.extend(textwrap.wrap(paragraph, chars) or [""])
    return lines


def freeze(frame, header_row):
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


def check_highlight(frames, highlight, sheet):
    """Refuse a highlight whose columns are not among the columns of ``frames`` (an
    :class:`InputError` naming the column, the valid ones and the ``sheet``)."""
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
            cells.append(WRAP if texts else WRAP_GENERAL)  # numbers stay right-aligned
            heads.append(HEADER_ALIGN)
        elif pd.api.types.is_bool_dtype(series.dtype) or (
                texts and values
                and max(len(v) if isinstance(v, str) else 0 for v in values) <= ID_WIDTH):
            cells.append(CENTER)
            heads.append(HEADER_CENTER)
        elif (pd.api.types.is_numeric_dtype(series.dtype)
              or _explained_numbers(series, frame.columns[j])):
            cells.append(RIGHT)  # numbers, and the text of an infinite one
            heads.append(HEADER_RIGHT)
        elif texts:
            cells.append(LEFT)  # text: a little room from the number on its left
            heads.append(HEADER_ALIGN)
        else:
            cells.append(TOP)  # mixed numbers and text: Excel's own alignment
            heads.append(HEADER_ALIGN)
    return cells, heads


def write_table(writer, frame, formats, columns, highlight):
    """Header and rows of ``frame`` at the writer's current row (the header once: a page
    repeats it through the print setup, never through a row written into the data)."""
    names = [str(c) for c in frame.columns]
    if len(names) > EXCEL_MAX_COLUMNS:
        raise InputError(f"a table has more than Excel's {EXCEL_MAX_COLUMNS} columns",
                         len(names), sheet=writer.ws.name)
    cells, heads = _alignments(frame, columns)
    header_styles = [cell_style(HEADER_FONT, None, h, HEADER_FILL, HEADER_BORDER)
                     for h in heads]
    writer.append(names, header_styles)
    first = writer.row + 1
    per_row = _row_unit_columns(frame, formats)
    unit_at = names.index("unit") if per_row else None
    ratio = [header_unit(c) == "-" for c in names]
    wrapping = [j for j, a in enumerate(cells) if ("text_wrap", True) in a]
    cell_format = writer.wb.cell_format
    texts = [cell_format(cell_style(None, None, a)) for a in cells]  # text: no number format
    looks = [{} for _ in cells]  # per column: number format -> cell format
    for row in frame.itertuples(index=False, name=None):
        values = [cell_value(v) for v in row]
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
                    made = looks[j][fmt] = cell_format(cell_style(None, fmt, cells[j]))
                out[j] = made
        writer.write(values, out, writer.lines(values, wrapping))
    _highlight(writer, frame, first, writer.row, highlight)


def frame_title(frame, default=""):
    """The title a DataFrame sheet carries (``frame.attrs["title"]``), or ``default``."""
    return str(frame.attrs.get("title", default)) if hasattr(frame, "attrs") else default


def write_table_sheets(wb, name, frame, *, number_format=None, highlight=None,
                       max_rows=EXCEL_MAX_ROWS, info=None, note=""):
    """Write a DataFrame to one sheet, or to ``NAME_1``, ``NAME_2``... when too long.

    The header is row 1; it is frozen and repeated on every printed page. The page header
    shows ``frame.attrs["title"]`` when the frame has one.

    Parameters
    ----------
    wb : ReportWorkbook
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
    note : str
        Printed in a text box under the table (last sheet), outside the cells: the sheet
        holds the header in row 1 and the data below it, nothing else, so that a program
        (``pandas.read_excel``, Excel's filter) reads it as data.

    Returns
    -------
    list of str
        The sheet names written, in order.
    """
    check_highlight([frame], highlight, name)
    formats = number_formats(frame.columns, number_format)
    columns = _in_blocks(frame, _wider_text(frame, column_plan([frame],
                                                                formats_of=lambda f: formats)))
    title = frame_title(frame, name)
    names = []
    parts = split_sheet_names(name, len(frame), max_rows)
    lines = note_lines(report_text(note, wb.units), columns) if note else []
    for k, (sheet_name, start, stop) in enumerate(parts):
        ws = wb.add_worksheet(sheet_name)
        ws.freeze_panes(freeze(frame, 1))
        set_widths(ws, columns)
        boxed = lines if k == len(parts) - 1 else []
        # rows with their wrapped lines, and the note under them
        height = (table_pixels(frame.iloc[start:stop], columns)
                  + ROW_PIXELS * (len(boxed) + bool(boxed)))
        orientation = orientation_for(columns.pixels, height)
        scale, column_breaks = columns.print_blocks(orientation)
        print_setup(ws, pixels=columns.pixels, height=height, title_rows=1,
                    sheet_title=title if len(parts) == 1
                    else f"{title}, part {k + 1} of {len(parts)}", info=info,
                    orientation=orientation,
                    pages=0 if column_breaks else height_fit(orientation, columns.pixels,
                                                             height),
                    scale=100 * scale if column_breaks else None,
                    column_breaks=column_breaks, key_columns=1)
        write_table(SheetWriter(wb, ws, columns.widths), frame.iloc[start:stop], formats,
                     columns, highlight)
        if boxed:
            _note_box(ws, stop - start + 2, boxed, columns, frame.shape[1])
        names.append(sheet_name)
    return names


#: Width of a column whose width is not set (Excel's default, 8.43 characters). [px]
_DEFAULT_COLUMN_PIXELS = 64


def _note_box(ws, row, lines, columns, n_columns):
    """The note of a table sheet in a text box from ``row`` (0-based) down, inside the
    printed area; the cells stay the table's alone."""
    # wide enough for its longest line (10 pt: about 6 px a character)
    width = max(columns.pixels, 300, 6 * max((len(line) for line in lines), default=0))
    ws.insert_textbox(row, 0, "\n".join(lines), {
        "width": width, "height": ROW_PIXELS * (len(lines) + 1),
        "font": {"size": 10}, "line": {"none": True}, "fill": {"none": True},
        "object_position": 3})
    # the printed area as wide as the box: a box wider than a narrow table runs on over the
    # empty columns after it (default width, 64 px), never cut at the table's edge
    extra = max(0, math.ceil((width - columns.pixels) / _DEFAULT_COLUMN_PIXELS))
    ws.print_area(0, 0, row + len(lines) + 1, max(n_columns - 1, 0) + extra)


def table_pixels(frame, columns):
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

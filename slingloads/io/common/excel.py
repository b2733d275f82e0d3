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
  :data:`~slingloads.io.common.excel_cells.MAX_TEXT_WIDTH` characters), header cells bold
  and wrapped, notes wrapped to the table width;
* **safety**: every string stored as text, never as a formula (a case description such as
  ``=HYPERLINK("x")`` is a string cell, ``data_type "s"``; a text that looks like
  XlsxWriter's own rich-string markup, ``<r>...</r>``, is written as a rich string of two
  runs, so that it too is escaped); NaN an empty cell and +/-inf the text
  :data:`~slingloads.io.common.excel_cells.INFINITE_TEXT`, never a bare ``inf`` (Excel has
  neither; the reports write what their infinite values mean instead,
  :func:`slingloads.io.common.report.explain_infinite`: this is the last resort); a table
  longer than Excel's row limit split over ``NAME_1``, ``NAME_2``... with the header
  repeated, never truncated;
* images scaled to the printable width, two to a page when they fit, never cut by a page
  break; a red fill on ratio cells above a threshold (conditional formatting).

With a :class:`~slingloads.io.common.cover.ReportInfo`, the workbook opens on a *Cover* sheet
(title, what the analysis covers, input file with its SHA-256 and modification time, version
and source revision, run date, project / document / author / checker, list of sheets,
conventions). A new report sheet therefore needs nothing but its DataFrame (or titled
:class:`Section` blocks): print setup, formats and panes come from here.

The writer is in parts, each stating what it guarantees: the cells (limits, styles, values
stored as what they are: :mod:`~slingloads.io.common.excel_cells`), the print setup
(:mod:`~slingloads.io.common.excel_print`), the table sheets
(:mod:`~slingloads.io.common.excel_tables`), the sheets of sections
(:mod:`~slingloads.io.common.excel_sections`) and the plots sheet
(:mod:`~slingloads.io.common.excel_images`); this module puts a workbook together.

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

import tempfile
from collections.abc import Mapping, Sequence

import pandas as pd

from slingloads.errors import InputError
from slingloads.io.common.excel_cells import (
    COVER_TITLE_FONT,
    EXCEL_MAX_ROWS,
    HEADER_STYLE,
    TITLE_STYLE,
    WRAP,
    ReportWorkbook,
    SheetWriter,
    cell_style,
    check_sheet_name,
    split_sheet_names,
)
from slingloads.io.common.excel_images import write_images_sheet
from slingloads.io.common.excel_print import print_setup
from slingloads.io.common.excel_sections import sheet_blocks, write_sections_sheet
from slingloads.io.common.excel_tables import (
    Highlight,
    Section,
    TableColumns,
    check_highlight,
    format_by_header,
    frame_title,
    note_lines,
    set_widths,
    write_table_sheets,
)

#: The writer's public names: a report needs this module only (the parts of the writer are in
#: excel_cells, excel_print, excel_tables, excel_sections and excel_images).
__all__ = ["EXCEL_MAX_ROWS", "IN_MEMORY_CELLS", "Highlight", "Section", "format_by_header",
           "mark_report", "write_cover_sheet", "write_workbook"]

#: Most table cells of a workbook built in memory (XlsxWriter keeps about 250 bytes a cell:
#: some 60 MB at most); a larger one is streamed through temporary files, which is slower.
IN_MEMORY_CELLS = 250_000


SheetContent = pd.DataFrame | Sequence[Section] | str


def _sheet_plan(sheets, images, images_sheet, max_rows, number_format=None):
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
            for n, part in sheet_blocks(name, content, number_format,
                                        taken=[x for x, _ in plan]):
                if isinstance(part, pd.DataFrame):
                    plan += [(m, frame_title(part, n))
                             for m, _, _ in split_sheet_names(n, len(part), max_rows)]
                else:
                    plan.append((n, next((s.title for s in part if s.title), n)))
    if images:
        plan.append((images_sheet, "; ".join(images)))
    seen = set()
    for n, _ in plan:
        if n.lower() in seen:
            raise InputError("sheet names must be unique (Excel ignores case)", n)
        seen.add(n.lower())
    return plan


def _highlight_for(highlight, content):
    """The highlight of a sheet restricted to the columns of one of its parts."""
    if highlight is None:
        return None
    frames = ([content] if isinstance(content, pd.DataFrame)
              else [s.table for s in content if s.table is not None])
    present = {c for f in frames for c in f.columns}
    kept = [c for c in highlight.columns if c in present]
    return Highlight(kept, highlight.threshold) if kept else None


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
    plan = _sheet_plan(sheets, images, images_sheet, max_rows, number_format)
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
        wb = ReportWorkbook(path, stream=_table_cells(sheets) > IN_MEMORY_CELLS, tmpdir=tmp)
        wb.units = "US" if info is not None and info.units.startswith("US") else "SI"
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
                check_highlight([s.table for s in content if s.table is not None],
                                 highlight.get(name), name)
                for n, part in sheet_blocks(name, content, number_format, taken=written):
                    mark = _highlight_for(highlight.get(name), part)
                    if isinstance(part, pd.DataFrame):
                        written += write_table_sheets(
                            wb, n, part, number_format=number_format, highlight=mark,
                            max_rows=max_rows, info=info, note=part.attrs.get("note", ""))
                    else:
                        written += write_sections_sheet(wb, n, part,
                                                        number_format=number_format,
                                                        highlight=mark, info=info)
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
    columns = TableColumns({0: 24, 1: 72}, {1})
    set_widths(ws, columns)
    print_setup(ws, pixels=columns.pixels, sheet_title="Cover", info=info)
    ws.fit_to_pages(1, 1)  # a long list of sheets and files shrinks, never spills
    writer = SheetWriter(wb, ws, columns.widths)
    writer.append([info.title], cell_style(COVER_TITLE_FONT))
    wrap = cell_style(None, None, WRAP)
    for title, note, table in sections:
        writer.blank()
        if title:
            writer.append([title], TITLE_STYLE)
        for line in note_lines(note, columns) if note else []:
            writer.append([line])
        if table is not None:
            writer.append(list(table.columns), HEADER_STYLE)
            for row in table.itertuples(index=False, name=None):
                writer.append(list(row), [None] + [wrap] * (len(row) - 1))
    return [name]



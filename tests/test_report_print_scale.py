"""Every sheet of every report of the example (SI) and of the second example (the US twin, in
US units and in SI) prints at 70 % of full size or more (Calibri 11 at 70 %: 7.7 pt), and
a table too wide for that prints in blocks of columns, each within the page width with the
first column (the row's id) repeated, its data cells unchanged (read by the table-sheet
tests of tests/test_report_tables.py).

The reference is the print setup as the file stores it (ECMA-376 ``pageSetup`` scale or
fit to page, ``colBreaks``, the ``Print_Titles`` columns, the page margins) and Excel's
column width rule (a stored width ``w``, its 5 px padding included, shows ``7 w`` px in
Calibri 11, whose digit is 7 px wide: ECMA-376 part 1, 18.3.1.13), read with
openpyxl, and A4 paper (8.27 x 11.69 in at 96 px per inch); not the writer's own plan. A
sheet printed in blocks of columns has each block within the page under LibreOffice's rule
too, which shows a stored width ``w`` as ``7 w + 5`` px (88.8 px for ``w = 12``, measured on
its PDF export of A4 pages): the wider of the two (a block that fits Excel's rule alone
spills a column onto a page of its own there)."""

from __future__ import annotations

import openpyxl
from hostile import column_widths

#: The least print scale of a sheet. [-]
FLOOR = 0.70
A4 = (8.27, 11.69)  # [in]
#: What LibreOffice adds to a column's ``7 w`` px (a stored width of 12 prints 88.8 px). [px]
LIBREOFFICE_PADDING = 5.0


def _printed(ws, padding=0.0):
    """(scale, widest printed block [px at 100 %], printable width [px]) of a sheet, a
    stored width ``w`` shown ``7 w + padding`` px wide."""
    widths = [7 * w + padding for w in column_widths(ws)]
    landscape = ws.page_setup.orientation == "landscape"
    paper_w, paper_h = A4[::-1] if landscape else A4
    m = ws.page_margins
    width = (paper_w - m.left - m.right) * 96
    height = (paper_h - m.top - m.bottom) * 96
    fit = ws.sheet_properties.pageSetUpPr is not None and ws.sheet_properties.pageSetUpPr.fitToPage
    breaks = sorted(b.id for b in ws.col_breaks.brk) if ws.col_breaks.brk else []
    if fit:
        assert not breaks, ws.title  # a fit to one page wide would drop the column breaks
        scale = min(1.0, width / sum(widths))
        tall = ws.page_setup.fitToHeight
        if tall:  # fitted to that many pages high too: the rows' height counts
            rows = sum((ws.row_dimensions[r].ht or 15.0) * 96 / 72
                       for r in range(1, ws.max_row + 1))
            scale = min(scale, int(tall) * height / rows)
        return scale, sum(widths), width
    scale = (ws.page_setup.scale or 100) / 100
    edges = [0, *breaks, len(widths)]
    repeated = widths[0] if breaks else 0.0
    if breaks:  # each block after the first repeats column A (Print_Titles columns)
        assert ws.print_title_cols in ("A:A", "$A:$A"), (ws.title, ws.print_title_cols)
    widest = max(sum(widths[a:b]) + (repeated if k else 0.0)
                 for k, (a, b) in enumerate(zip(edges, edges[1:], strict=False)))
    return scale, widest, width


def _sheets(folder):
    books = sorted(folder.glob("*.xlsx"))
    assert len(books) >= 4, books
    for book in books:
        wb = openpyxl.load_workbook(book)
        for ws in wb.worksheets:
            yield book.name, ws


def _faults(folder):
    faults, blocks = [], 0
    for book, ws in _sheets(folder):
        scale, widest, width = _printed(ws)
        blocks += bool(ws.col_breaks.brk)
        if scale < FLOOR - 0.005 or widest * scale > 1.01 * width:
            faults.append((book, ws.title, round(scale, 3), round(widest * scale), round(width)))
        if ws.col_breaks.brk:  # LibreOffice's widths (a fitted sheet is fitted by it)
            scale, widest, width = _printed(ws, padding=LIBREOFFICE_PADDING)
            if widest * scale > 1.01 * width:
                faults.append((book, ws.title, "LibreOffice", round(scale, 3),
                               round(widest * scale), round(width)))
    return faults, blocks


def test_the_examples_sheets_print_at_a_readable_scale(example_run_report):
    """The example's reports: every sheet at >= 70 %, every block within the page; the
    sheets too wide for that (the parachute sizing's every-run sweep, the lateral Runs, the
    loads' LoadCases) print in blocks of columns."""
    faults, blocks = _faults(example_run_report)
    assert not faults
    assert blocks >= 2


def test_the_us_twins_sheets_print_at_a_readable_scale(us_twin_reports):
    """The second example's reports (US units and SI, the campaign's Metrics among them):
    every sheet at >= 70 %, every block within the page."""
    _, folder = us_twin_reports
    faults, blocks = _faults(folder)
    assert not faults
    assert blocks >= 1

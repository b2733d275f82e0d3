"""Sheets of titled sections (notes and tables one under another) in a report workbook.

What this module guarantees: a list of sections is printed on sheets that read on paper
(:func:`sheet_blocks`): a table taller than a page goes to a sheet of its own named after its
title, a table too wide for the page beside the others is cut once, by one rule
(:func:`column_blocks`), in blocks of columns that each start with the table's key columns
(the row's id) and fit a landscape page at no less than
:data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE`; on a sheet of several sections
(:func:`write_sections_sheet`) a block that would straddle a page break but fits on one page
starts on a new page, at the print scale that prints the sheet on the fewest pages with the
fewest nearly empty ones, and each table keeps its own alignment and number formats
(:mod:`slingloads.io.common.excel_tables`); a sheet whose only table is its last block
repeats the rows down to the table's header on every printed page.
"""

from __future__ import annotations

import re

from slingloads.io.common.excel_cells import (
    MAX_TEXT_WIDTH,
    ROW_PIXELS,
    TITLE_STYLE,
    SheetWriter,
    check_sheet_name,
    column_pixels,
)
from slingloads.io.common.excel_print import (
    MIN_EXTRA_SCALE,
    MIN_PRINT_SCALE,
    PRINTABLE,
    SPARSE_LAST,
    height_fit,
    orientation_for,
    page_pixels,
    print_setup,
)
from slingloads.io.common.excel_tables import (
    Section,
    TableColumns,
    check_highlight,
    column_plan,
    freeze,
    note_lines,
    number_formats,
    set_widths,
    table_pixels,
    write_table,
)
from slingloads.io.common.units import report_text


def _is_long(table, number_format, text_width=MAX_TEXT_WIDTH):
    """A table taller than a printed page with its title, its text columns wrapped at
    ``text_width`` characters."""
    formats = number_formats(table.columns, number_format)
    own = column_plan([table], formats_of=lambda f: formats, text_width=text_width)
    height = table_pixels(table, own) + 2 * ROW_PIXELS
    page = page_pixels(orientation_for(own.pixels, height), own.pixels) * 0.95
    return height > page


#: Words left out of a sheet name made from a title.
_FILLER = frozenset({"a", "an", "and", "at", "by", "for", "in", "of", "on", "the", "to"})


def _sheet_name_for(base, title, taken):
    """A sheet name for a table of sheet ``base`` taken out to a sheet of its own: the base
    and the first words of the table's title (``Runs-ResultsOfEveryCase``)."""
    part = re.search(r"\bpart (\d+) of \d+", title)
    if part:  # a block of a table split for print: "Histories part 2"
        return _unique(f"{base} part {part.group(1)}", taken)
    head = re.split(r"[:,;(=]", title)[0]
    words = [w[:1].upper() + w[1:] for w in re.findall(r"[A-Za-z0-9]+", head)
             if w.lower() not in _FILLER] or ["Table"]
    out = f"{base}-"
    for w in words:
        if len(out) + len(w) > 31:
            break
        out += w
    return _unique(out.rstrip("-"), taken)


def _unique(name, taken):
    """``name`` (at most 31 characters), or with a number when taken (case ignored)."""
    name = candidate = name[:31]
    k = 2
    while candidate.lower() in taken:
        candidate = f"{name[:28]}{k}"
        k += 1
    taken.add(candidate.lower())
    return candidate


def sheet_blocks(name, sections, number_format=None, taken=()):
    """The sheets a list of sections is printed on, as (sheet name, content).

    A section naming a ``sheet`` goes to that sheet; one whose table (without key columns)
    is taller than a page, on a sheet of several tables, goes whole to a sheet of its own
    named after the base sheet and the table's title (its header is then repeated by the
    print setup on every page, never written into the data). The tables left that are too
    wide for the page are then cut into blocks of columns (:func:`column_blocks`, the
    table's keys first in each, titled ``part k of n``), and a table or block taller than a
    page among others goes to a sheet of its own: a table after the base sheet's, a block
    (``Base part k``) in its place, the sections after it continuing on the next sheet
    (named after its first table), so that the blocks print as their ``k of n`` reads. When
    no table is left on the base sheet, the first such table keeps the base name and the
    notes.
    A sheet holding one table is a *table sheet*: a DataFrame whose ``attrs`` carry its
    ``title`` and ``note`` (:func:`write_table_sheets`); any other is a list of sections
    (:func:`write_sections_sheet`), whose tables each fit on one page.

    Returns
    -------
    list of (str, DataFrame or list of Section)
    """
    sections = list(sections)
    tables = [s for s in sections if s.table is not None]
    away = [s for s in tables if s.sheet or (not s.keys and len(tables) > 1
                                             and _is_long(s.table, number_format))]
    sections = _cut(sections, number_format, away)
    tables = [s for s in sections if s.table is not None]
    kept = [s for s in sections if all(s is not x for x in away)]
    text_width = _text_width_for(kept, number_format)  # the narrowest the sheet may wrap at
    taken = {t.lower() for t in taken} | {name.lower()}
    long = [s for s in tables if any(s is x for x in away) or s.sheet or (
        len(tables) > 1 and _is_long(s.table, number_format, text_width))]
    # a long table goes to a sheet of its own after the rest; a long block of a cut table
    # to one in its place: the sections after it continue on the next sheet, so that the
    # blocks print as their k of n reads (never one after the rest)
    moved = [s for s in long if _whole_title(s.title) is None]
    groups = [[]]
    for s in sections:
        if any(s is x for x in moved):
            continue
        if any(s is x for x in long):
            groups += [[s], []]
        else:
            groups[-1].append(s)
    groups = [g for g in groups if g]
    for k in range(len(groups) - 1, 0, -1):  # notes alone join the sheet before them
        if not any(x.table is not None for x in groups[k]):
            groups[k - 1] += groups.pop(k)
    if len(groups) > 1 and not any(x.table is not None for x in groups[0]):
        groups[0] += groups.pop(1)  # the base sheet's notes stay with its first block
    if moved and not any(x.table is not None for g in groups for x in g) \
            and not moved[0].sheet:
        groups = [[*(groups[0] if groups else []), moved.pop(0)]]
    out = []
    for k, group in enumerate(groups):
        first = next(x for x in group if x.table is not None) if k else None
        own = name if not k else first.sheet or _sheet_name_for(name, first.title, taken)
        taken.add(check_sheet_name(own).lower())
        if k and len([x for x in group if x.table is not None]) > 1 and group[0].table \
                is not None:  # a sheet continuing a cut table: titled as its heading
            group = [Section(f"{_whole_title(first.title) or first.title}, continued"),
                     *group]
        out.append((own, group))
    for s in moved:
        own = s.sheet or _sheet_name_for(name, s.title, taken)
        taken.add(check_sheet_name(own).lower())
        out.append((own, [s]))
    return [(n, secs if (frame := _as_table_sheet(secs)) is None else frame)
            for n, secs in out]


def _whole_title(title):
    """The title of the table a block titled ``..., part k of n`` (:func:`_cut`) was cut
    from, or None for a table left whole."""
    found = re.fullmatch(r"(.*), part \d+ of \d+", title or "", flags=re.DOTALL)
    return found.group(1) if found else None


def _as_table_sheet(sections):
    """The one table of ``sections`` with its title and note in ``attrs``, or None."""
    tables = [s for s in sections if s.table is not None]
    if len(tables) != 1:
        return None
    own = tables[0]
    full = own.title or next((s.title for s in sections if s.title), "")
    # the page header holds the title without its long bracketed remarks (so that a "part k
    # of n" at its end shows; a short mark such as "(LIMIT)" stays); the text box under the
    # table gives it whole
    title = re.sub(r"\s*\([^()]{13,}\)", "", full)
    text = [full] if title != full else []
    for s in sections:
        if s.title and s.title != full:
            text.append(s.title)
        if s.note:
            text.append(s.note)
    frame = own.table.copy(deep=False)
    frame.attrs = {**own.table.attrs, "title": title, "note": "\n".join(text)}
    return frame


#: Print scales tried for a sheet of several blocks, relative to the fit to the page width,
#: largest first (:func:`_page_plan`). [-]
_SCALES = tuple(x for x in (1.0, 0.95, 0.9, 0.85) if x >= MIN_EXTRA_SCALE)


def _paginate(needs, page):
    """Pages of blocks ``needs`` high on pages ``page`` high [px]: a block that would
    straddle a page break but fits on a page starts a new one; a longer block flows on,
    unless less than :data:`~slingloads.io.common.excel_print.SPARSE_LAST` of the page is
    left (its title would end the page with little or none of its table under it).

    Returns
    -------
    breaks : list of int
        The blocks that start a new page.
    fills : list of float
        The fill of each page, 0 to 1.
    """
    breaks, fills, used = [], [], 0.0
    for k, need in enumerate(needs):
        if k and used and used + need > page and (need <= page
                                                  or page - used < SPARSE_LAST * page):
            breaks.append(k)
            fills.append(used / page)
            used = 0.0
        used += need
        while used > page:
            fills.append(1.0)
            used -= page
    fills.append(used / page)
    return breaks, fills


def _page_plan(needs, page, fit=1.0):
    """The page breaks of a sheet of blocks and its print scale relative to the fit to the
    page width: of :data:`_SCALES`, the largest that prints the fewest pages with the fewest
    pages under :data:`~slingloads.io.common.excel_print.SPARSE_LAST` full (its last page
    aside).

    Parameters
    ----------
    needs : sequence of float
        Height of each block at the fit to the page width. [px]
    page : float
        Height of a page at that scale, less a margin. [px]
    fit : float
        The fit to the page width: no scale takes the print below
        :data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE`. [-]

    Returns
    -------
    breaks : list of int
        The blocks that start a new page.
    scale : float

    Examples
    --------
    A small block and one of 80 % of a page: 2 pages at full size (the first 25 % full), one
    page at 0.95.

    >>> _page_plan([250, 800], 1000)
    ([], 0.95)
    """
    best = None
    for scale in [s for s in _SCALES if s == 1.0 or fit * s >= MIN_PRINT_SCALE]:
        breaks, fills = _paginate(needs, page / scale)
        key = (len(fills), sum(f < SPARSE_LAST for f in fills[:-1]))
        if best is None or key < best[0]:
            best = (key, breaks, scale)
    return best[1], best[2]


#: Columns of a table that, without key columns of its own, is never split into column
#: blocks (item, value, unit, note).
_NARROW_COLUMNS = 4
#: Widths the text columns of a sheet of several tables may wrap at, widest first, so that
#: its wide tables print whole (:func:`_text_width_for`). [characters]
_TEXT_WIDTHS = (MAX_TEXT_WIDTH, 36, 32, 28, 24)
#: Widest the columns of a sheet may be, as LibreOffice prints them: a landscape page at
#: :data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE`, less 5 % for the widths of its
#: notes. [px]
SHEET_PIXELS = 0.95 * PRINTABLE["landscape"][0] / MIN_PRINT_SCALE


def _widths(table, number_format=None, text_width=MAX_TEXT_WIDTH):
    """The printed width of each column of ``table`` as the writer sizes it. [px]"""
    own = column_plan([table], formats_of=lambda f: number_formats(f.columns, number_format),
                       text_width=text_width)
    return [column_pixels(own.widths.get(j, 8.43)) for j in range(table.shape[1])]


def _union(rows):
    """The widths of the columns of a sheet holding tables whose columns are ``rows`` wide:
    at each position the widest. [px]"""
    return [max((w[k] for w in rows if k < len(w)), default=0.0)
            for k in range(max((len(w) for w in rows), default=0))]


def _fitting_text_width(sections, number_format=None):
    """The widest of :data:`_TEXT_WIDTHS` at which the tables of ``sections`` fit beside one
    another in :data:`SHEET_PIXELS`, or None."""
    tables = [s.table for s in sections if s.table is not None]
    for text_width in _TEXT_WIDTHS:
        if sum(_union([_widths(t, number_format, text_width) for t in tables])) \
                <= SHEET_PIXELS:
            return text_width
    return None


def _text_width_for(sections, number_format=None):
    """The width the text columns (notes, descriptions) of a sheet of several tables wrap
    at: the widest of :data:`_TEXT_WIDTHS` at which every table fits beside the others (a
    row grows taller, a table stays one block that a checker reads at once). A sheet of one
    table, or one whose tables fit at none, wraps at
    :data:`~slingloads.io.common.excel_cells.MAX_TEXT_WIDTH`. [characters]"""
    if sum(s.table is not None for s in sections) < 2:
        return MAX_TEXT_WIDTH
    return _fitting_text_width(sections, number_format) or MAX_TEXT_WIDTH


def _key_positions(table, keys):
    """Positions of the key columns of ``table``: those of ``keys`` it has, else its first
    column and its ``unit`` column (which gives the row's number format)."""
    names = [str(c) for c in table.columns]
    found = [names.index(str(k)) for k in keys if str(k) in names]
    if found:
        return list(dict.fromkeys(found))
    return [0, *([names.index("unit")] if "unit" in names[1:] else [])]


def _blocks(widths, keys, beside=(), room=SHEET_PIXELS):
    """Column positions of each block of a table whose columns are ``widths`` px wide: the
    ``keys`` then as many of the other columns, in order, as fit in ``room`` px, a column
    taking at each position of the sheet the widest of itself and ``beside`` (the other
    tables' columns there); as few blocks as that gives, made as even as they can be (the
    narrowest room that gives no more blocks, by bisection). A column wider than the room
    alone is a block with the keys."""
    rest = [j for j in range(len(widths)) if j not in keys]

    def at(position, width):
        return max(width, beside[position]) if position < len(beside) else width

    base = sum(at(p, widths[j]) for p, j in enumerate(keys))

    def cut(space):
        blocks, current, used = [], [], base
        for j in rest:
            step = at(len(keys) + len(current), widths[j])
            if current and used + step > space:
                blocks.append(current)
                current, used = [], base
                step = at(len(keys), widths[j])
            current.append(j)
            used += step
        if current or not blocks:
            blocks.append(current)
        return blocks

    count = len(cut(room))
    low, high = base, room
    for _ in range(40):
        mid = 0.5 * (low + high)
        if len(cut(mid)) <= count:
            high = mid
        else:
            low = mid
    return [[*keys, *block] for block in cut(high)]


def column_blocks(frame, keys=(), *, number_format=None):
    """A table too wide for the page as the blocks of columns it prints in, each with the
    key columns first: the one rule by which every report's wide table is cut
    (:func:`sheet_blocks` applies it to the tables of a sheet together).

    The blocks, one under another on a sheet, fit a landscape A4 page at no less than
    :data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE` (:data:`SHEET_PIXELS`), the
    columns measured as the workbook writer sizes them and LibreOffice prints them.

    Parameters
    ----------
    frame : pandas.DataFrame
    keys : sequence of str
        Columns repeated first in every block (the row's id: run, mode, metric and unit);
        those ``frame`` lacks are left out; none: its first column and its ``unit`` column.
    number_format : mapping or callable, optional
        As in :func:`~slingloads.io.common.excel_tables.write_table_sheets`.

    Returns
    -------
    list of pandas.DataFrame
        The blocks, in the order of the columns; the table whole when it fits.

    Examples
    --------
    >>> import pandas as pd
    >>> wide = pd.DataFrame({"run": ["R1"], **{f"a long quantity {k} [deg]": [1.0]
    ...                                       for k in range(20)}})
    >>> [list(b.columns[:2]) for b in column_blocks(wide, ["run"])]
    [['run', 'a long quantity 0 [deg]'], ['run', 'a long quantity 10 [deg]']]
    """
    sections = _cut([Section(table=frame, keys=list(keys) or [str(frame.columns[0])])],
                    number_format)
    return [s.table for s in sections if s.table is not None]


def _cut(sections, number_format=None, away=()):
    """The sections of a sheet with each table too wide for the page (beside the others of
    the sheet) cut into blocks of columns: a heading (its title and note), then the blocks
    titled ``part k of n``, each with the table's keys first (:func:`_key_positions`).

    Cut are the tables of the sheet (not those of ``away``, which go whole to sheets of
    their own) with key columns, or with more than :data:`_NARROW_COLUMNS` columns on a sheet
    of several tables; each is cut so that its blocks fit beside the columns of every other
    block and table on the sheet (:func:`_blocks`), with the sheet's text columns wrapped at
    the width of :data:`_TEXT_WIDTHS` that prints the sheet on the least paper (its
    estimated height, times its shrink to the page width), a block fitting the page alone
    at full text width too (a long one prints on a table sheet of its own). Left whole: a
    sheet whose tables fit once its text columns wrap narrower (:func:`_text_width_for`), and
    a sheet's one table without keys (it prints in pages of columns, its cells one table
    that a program reads)."""
    own = [k for k, s in enumerate(sections)
           if s.table is not None and all(s is not x for x in away)]
    if not own or (len(own) == 1 and not sections[own[0]].keys):
        return sections
    if len(own) > 1 and _fitting_text_width([sections[k] for k in own], number_format):
        return sections
    keys = {k: _key_positions(sections[k].table, sections[k].keys) for k in own}
    wide = [k for k in own if sections[k].keys or sections[k].table.shape[1] > _NARROW_COLUMNS]
    full = {k: _widths(sections[k].table, number_format) for k in wide}

    def plan_at(text_width):
        widths = {k: _widths(sections[k].table, number_format, text_width) for k in own}
        narrow = [widths[k] for k in own if k not in wide]
        beside = _union(narrow)
        while True:
            # each table cut beside the columns of the others; while the blocks of all do
            # not fit together, cut again beside the widest columns seen so far at each
            # position: these only grow (to the widest columns at most), so this ends
            plan = {k: _blocks(widths[k], keys[k], beside) for k in wide}
            sheet = _union([*narrow, *([widths[k][j] for j in block]
                                       for k in wide for block in plan[k])])
            grown = _union([beside, sheet])
            if sum(sheet) <= SHEET_PIXELS or grown == beside:
                break
            beside = grown
        tables = [sections[k].table.iloc[:, block] for k in wide for block in plan[k]]
        tables += [sections[k].table for k in own if k not in wide]
        height = sum(table_pixels(t, column_plan([t], formats_of=lambda f: number_formats(
            f.columns, number_format), text_width=text_width)) + 2 * ROW_PIXELS
            for t in tables)
        whole = text_width == MAX_TEXT_WIDTH or all(
            sum(full[k][j] for j in block) <= SHEET_PIXELS
            for k in wide for block in plan[k] if len(block) > len(keys[k]) + 1)
        paper = height * max(1.0, sum(sheet) / PRINTABLE["landscape"][0])
        return (not whole, paper), plan

    plan = min((plan_at(w) for w in _TEXT_WIDTHS), key=lambda c: c[0])[1]
    out = []
    for k, s in enumerate(sections):
        if k not in plan or len(plan[k]) == 1:
            out.append(s)
            continue
        out.append(Section(s.title, note=s.note))
        out += [Section(f"{s.title}, part {m + 1} of {len(plan[k])}",
                        s.table.iloc[:, block])
                for m, block in enumerate(plan[k])]
    return out


def write_sections_sheet(wb, name, sections, *, number_format=None, highlight=None,
                         info=None):
    """Write titled blocks (notes and tables) one under another on one sheet.

    A sheet whose only table is its last block has the rows down to the table's header
    frozen and repeated on every printed page (a report writes such a sheet as a table
    sheet, :func:`sheet_blocks`), and is fitted to one page fewer when its last page would be
    nearly empty (:func:`~slingloads.io.common.excel_print.height_fit`). Otherwise the first
    row (the sheet's title) is frozen, no row is repeated, and a block that would straddle a
    page break but fits on one page starts on a new page, at the print scale
    (:func:`_page_plan`) that prints the sheet on the fewest pages with the fewest sparse
    ones; each table keeps its own alignment (numbers under their header).

    Parameters
    ----------
    wb : ReportWorkbook
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
    text_width = _text_width_for(sections, number_format)
    tables = [s.table for s in sections if s.table is not None]
    check_highlight(tables, highlight, name)
    columns = column_plan(tables, [s.note for s in sections],
                           formats_of=lambda f: number_formats(f.columns, number_format),
                           text_width=text_width)
    set_widths(ws, columns)
    blocks = [(s.title, note_lines(report_text(s.note, wb.units), columns) if s.note else [],
               s.table)
              for s in sections]
    one_table = len(tables) == 1 and sections[-1].table is not None
    if one_table:
        header_row = sum(bool(t) + len(n) + (k > 0) for k, (t, n, _) in enumerate(blocks)) + 1
        ws.freeze_panes(freeze(tables[0], header_row))
        title_rows = header_row
    else:  # the first row is the sheet's title when the first block has no table; the
        # page header names it, and no row is repeated: only a table sheet repeats its header
        if bool(blocks) and bool(blocks[0][0]) and blocks[0][2] is None:
            ws.freeze_panes("A2")
        title_rows = None
    # the page header names the content, never the raw sheet name: a title, else the note's
    # first line
    sheet_title = next((s.title for s in sections if s.title),
                       next((s.note.splitlines()[0] for s in sections if s.note), name))
    needs = [ROW_PIXELS * (bool(title) + len(lines) + (k > 0))
             + (table_pixels(table, columns) if table is not None else 0)
             for k, (title, lines, table) in enumerate(blocks)]
    height = sum(needs)
    orientation = orientation_for(columns.pixels, height)
    # a table too wide for a readable fit: blocks of columns, the first column (ids) on
    # each; a sheet of several tables has its wide tables in blocks already (sheet_blocks,
    # column_blocks), one under another (a column break would cut the others' columns apart)
    fit_width, column_breaks = columns.print_blocks(orientation)
    if not one_table:
        fit_width, column_breaks = min(1.0, PRINTABLE[orientation][0]
                                       / max(columns.pixels, 1.0)), []
    page = PRINTABLE[orientation][1] / fit_width * 0.95
    if one_table and not column_breaks:  # rows flow under the repeated header: fitted to a
        breaks, scale = [], None        # page count
        pages = height_fit(orientation, columns.pixels, height)
    elif one_table:
        breaks, scale, pages = [], 1.0, 0
    else:
        breaks, scale = _page_plan(needs, page, fit_width)
        pages = 0
    print_setup(ws, pixels=columns.pixels, height=height, title_rows=title_rows,
                sheet_title=sheet_title, info=info, orientation=orientation, pages=pages,
                scale=(100 * fit_width * scale if column_breaks
                       else None if scale in (None, 1.0) else 100 * fit_width * scale),
                column_breaks=column_breaks, key_columns=1)
    writer = SheetWriter(wb, ws, columns.widths)
    for k, (title, lines, table) in enumerate(blocks):
        if k in breaks:
            writer.page_break()
        if k:
            writer.blank()
        if title:
            writer.append([title], TITLE_STYLE)
        for line in lines:
            writer.append([line])
        if table is not None:
            formats = number_formats(table.columns, number_format)
            own = column_plan([table], formats_of=lambda f, x=formats: x,
                               text_width=text_width)
            # the sheet's widths, this table's own alignment: a number sits under its header
            write_table(writer, table, formats, TableColumns(columns.widths, own.wrapped),
                         highlight)
    writer.close()
    return [name]

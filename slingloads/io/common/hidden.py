"""Warnings on the hidden sheets, rows and columns of an input workbook whose values were read.

A value on a hidden sheet, row or column is used like any other, but someone reviewing the
workbook in Excel does not see it. Each one read is named on the reports' Summary and on
stderr (``slingloads: warning: ...``), e.g. ``sheet 'FinAero': values were read from hidden
rows 80-100``.

The reader (:mod:`slingloads.io.common.workbook`) does not keep the row and column
attributes; they are found here in the sheet's XML, read again from the container: a search
of the raw bytes for ``<row ... hidden="1">`` and ``<col ... hidden="1">`` (no parse), a few
milliseconds for the example workbook's 1.1 MB of sheets. Rows hidden by a zero height, or
by an outline level collapsed without the ``hidden`` flag, are not seen; Excel itself sets
the flag whenever it hides a row or a column.
"""

from __future__ import annotations

import re

from openpyxl.utils import column_index_from_string, get_column_letter

from slingloads.io.common.schema import STUDY_SHEET

#: A ``<row>`` or ``<col>`` start tag (any namespace prefix) and its attributes.
_TAG = re.compile(rb"<(?:[A-Za-z_][\w.-]*:)?(row|col)\b([^>]*)>")
#: A true ``hidden`` attribute (xsd:boolean).
_HIDDEN = re.compile(rb"""\bhidden\s*=\s*["'](?:1|true)["']""")
_ATTRIBUTE = {name: re.compile(rb"\b" + name + rb"""\s*=\s*["'](\d+)["']""")
              for name in (b"r", b"min", b"max")}
_CELL = re.compile(r"^([A-Z]{1,3})(\d+)$")
#: Most rows or columns named in one warning.
_SHOWN = 10


def hidden_warnings(reader, cells):
    """One warning per sheet read that is hidden, or whose hidden rows or columns hold a
    value that was read.

    Parameters
    ----------
    reader : WorkbookReader
        The open workbook (sheets given in memory have nothing hidden).
    cells : dict
        Sheet name as the schema spells it -> the coordinates of the cells read there.

    Returns
    -------
    list of str
    """
    book = reader.book
    if book is None:
        return []
    out = []
    for name, coordinates in cells.items():
        actual = _sheet_name(book.sheetnames, name)
        if actual is None or not coordinates:
            continue
        ws = book[actual]
        if ws.sheet_state != "visible":
            how = ("hidden" if ws.sheet_state == "hidden"
                   else "very hidden (Excel's menus cannot show it)")
            out.append(f"sheet {actual!r} is {how} in the workbook, yet its values were read: "
                       "a reviewer of the workbook does not see them")
            continue
        rows, columns = _hidden(ws)
        if not rows and not columns:
            continue
        used_rows, used_columns = set(), set()
        for coordinate in coordinates:
            match = _CELL.match(coordinate)
            if match is not None:
                used_columns.add(column_index_from_string(match.group(1)))
                used_rows.add(int(match.group(2)))
        parts = []
        hit = sorted(rows & used_rows)
        if hit:
            parts.append(f"{'rows' if len(hit) > 1 else 'row'} {_ranges(hit)}")
        hit = sorted(columns & used_columns)
        if hit:
            parts.append(f"{'columns' if len(hit) > 1 else 'column'} "
                         f"{_ranges(hit, get_column_letter)}")
        if parts:
            out.append(f"sheet {actual!r}: values were read from hidden {' and '.join(parts)}"
                       ": a reviewer of the workbook does not see them")
    return out


def read_cells(reader, params):
    """The cells read from each sheet: the Study values given and every table read.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters

    Returns
    -------
    dict
        Sheet name -> set of coordinates.
    """
    cells = {STUDY_SHEET: {params.cell(name) for name in params.given} - {None}}
    for table in getattr(reader, "_tables", {}).values():
        cells.setdefault(table.sheet, set()).update(
            c for column in table.cells.values() for c in column)
    return cells


def _sheet_name(names, name):
    """The workbook's name of sheet ``name``: exact, else the one that matches it with case
    and surrounding spaces ignored (as the reader finds it)."""
    if name in names:
        return name
    matches = [n for n in names if n.strip().casefold() == name.casefold()]
    return matches[0] if len(matches) == 1 else None


def _hidden(ws):
    """``(rows, columns)``: the numbers of the hidden rows and columns of a read-only sheet."""
    with ws._get_source() as source:  # the sheet's part in the container
        data = source.read()
    rows, columns = set(), set()
    if b"hidden" not in data:
        return rows, columns
    for match in _TAG.finditer(data):
        attributes = match.group(2)
        if not _HIDDEN.search(attributes):
            continue
        if match.group(1) == b"row":
            number = _ATTRIBUTE[b"r"].search(attributes)
            if number is not None:
                rows.add(int(number.group(1)))
        else:
            low, high = (_ATTRIBUTE[k].search(attributes) for k in (b"min", b"max"))
            if low is not None:
                first = int(low.group(1))
                last = int(high.group(1)) if high is not None else first
                columns.update(range(first, min(last, 16_384) + 1))
    return rows, columns


def _ranges(numbers, name=str):
    """``[3, 4, 5, 9]`` -> ``"3-5, 9"`` (at most :data:`_SHOWN` ranges, then ``...``)."""
    spans = []
    for n in numbers:
        if spans and n == spans[-1][1] + 1:
            spans[-1][1] = n
        else:
            spans.append([n, n])
    text = [name(a) if a == b else f"{name(a)}-{name(b)}" for a, b in spans[:_SHOWN]]
    return ", ".join(text) + (" ..." if len(spans) > _SHOWN else "")

"""A sheet of several tables prints each table as one block: its text columns (notes) wrap
narrower, rows taller, so that a wide table beside them keeps all its columns together; a
table cut into column parts (only when no narrower wrap lets it fit) keeps its ``unit``
column in every part, so that each number keeps the format of its row's unit; a table with
key columns (a report's run, mode, metric and unit) is cut once, each block starting with its
keys, as in the example's campaign and multibody reports.

The reference is the written file read back with openpyxl and pandas (the stored column
widths at 7 px per character unit, the Excel number format of each cell), against the A4
landscape page at the least print scale
(:data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE`)."""

from __future__ import annotations

import re

import openpyxl
import pandas as pd
from hostile import column_widths, report_table

from slingloads.io.common.excel import Section, write_workbook
from slingloads.io.common.excel_print import MIN_PRINT_SCALE, PRINTABLE


def _item_table(note_words):
    """An item / value / unit / note table with long notes (the Summary's)."""
    return pd.DataFrame({"item": ["a quantity of the study with a long name"] * 3,
                         "value": [1.5, 2.25, 3.0], "unit": ["m", "N", "deg"],
                         "note": [" ".join(["word"] * note_words)] * 3})


def _wide_table(columns):
    """A table of ``columns`` numeric columns keyed by a case id (the towed cases')."""
    return pd.DataFrame({"case": ["LC0001", "LC0002"],
                         **{f"quantity {k} [deg]": [1.0 + k, -2.0 - k]
                            for k in range(columns)}})


def _titles(ws):
    return [str(c.value) for c in ws["A"] if isinstance(c.value, str)]


def test_wide_table_beside_long_notes_prints_whole(tmp_path):
    """A 13-column table under a table of 40-character notes: the notes wrap narrower, the
    wide table is one block (no 'part k of n'), read back whole, and the sheet's columns fit
    the landscape page at the least print scale."""
    path = tmp_path / "two.xlsx"
    write_workbook(path, {"Summary": [Section("Items", _item_table(60)),
                                      Section("Towed cases", _wide_table(12))]})
    ws = openpyxl.load_workbook(path)["Summary"]
    assert not [t for t in _titles(ws) if ", part " in t]
    _, table = report_table(path, "Summary", "Towed cases")
    assert list(table.columns) == list(_wide_table(12).columns)
    assert [float(v) for v in table["quantity 11 [deg]"]] == [12.0, -13.0]
    width = sum(7 * w for w in column_widths(ws))
    assert width * MIN_PRINT_SCALE <= PRINTABLE["landscape"][0]
    note_row = next(c.row for c in ws["A"] if c.value == "a quantity of the study with a "
                    "long name")
    assert ws.row_dimensions[note_row].height > 15  # the note wraps over several lines


def test_parts_of_a_table_keep_its_unit_column(tmp_path):
    """A table too wide for any wrap is cut into parts; every part keeps the row's id and
    its ``unit`` column, and a number in a later part has its row's unit format (a force to
    the newton ``#,##0``, a ratio ``0.000``), not Excel's General."""
    table = pd.DataFrame({"quantity": ["force", "ratio"], "unit": ["N", "-"],
                          **{f"value {k}": [1234.5678 + k, 0.123456] for k in range(30)}})
    path = tmp_path / "parts.xlsx"
    write_workbook(path, {"Dynamics": [Section("Hand-off", table),
                                       Section("Other", _item_table(10))]})
    ws = openpyxl.load_workbook(path)["Dynamics"]
    parts = [t for t in _titles(ws) if t.startswith("Hand-off, part ")]
    assert len(parts) >= 2
    last = next(c.row for c in ws["A"] if c.value == parts[-1]) + 1  # its header row
    header = [c.value for c in ws[last]]
    assert header[:2] == ["quantity", "unit"]
    force, ratio = ws[last + 1], ws[last + 2]
    assert force[2].number_format == "#,##0" and ratio[2].number_format == "0.000"
    _, joined = report_table(path, "Dynamics", "Hand-off")
    assert list(joined.columns) == list(table.columns)


def _mixed_table(rows=3):
    """A table keyed by a run and a time, with text columns of several widths among numbers
    (the multibody histories' and the campaign's metrics')."""
    columns = {"run": [f"R{k:03d}" for k in range(rows)],
               "time [s]": [0.5 * k for k in range(rows)]}
    for k in range(24):
        if k % 5 == 0:
            columns[f"verdict {k}"] = ["a verdict of several words " * (1 + k % 2)] * rows
        else:
            columns[f"a quantity with a long name {k} [deg]"] = [1.0 + k] * rows
    return pd.DataFrame(columns)


def _part_titles(ws):
    return [(c.row, str(c.value)) for c in ws["A"]
            if isinstance(c.value, str) and _PART.search(c.value)]


def test_wide_tables_with_keys_are_cut_once_keys_first(tmp_path):
    """Two wide tables with key columns on one sheet, beside a narrow one: each is cut once
    (one ``part k of n`` in each title), every block starts with its keys, the parts join
    back to the table (the cells as written), and the sheet's columns, at 7 px a character
    unit plus 5 px of padding (as LibreOffice prints them), fit the landscape page at the
    least print scale."""
    wide = _mixed_table()
    other = _mixed_table().iloc[:, ::-1].copy()
    other = other[["run", "time [s]", *(c for c in other.columns if c not in ("run", "time [s]"))]]
    path = tmp_path / "keys.xlsx"
    write_workbook(path, {"Runs": [Section("Items", _item_table(10)),
                                   Section("Every run", wide, keys=["run", "time [s]"]),
                                   Section("Every run again", other, keys=["run", "time [s]"])]})
    ws = openpyxl.load_workbook(path)["Runs"]
    titles = _part_titles(ws)
    assert titles and all(len(_PART.findall(t)) == 1 for _, t in titles)
    for row, _ in titles:
        assert [c.value for c in ws[row + 1]][:2] == ["run", "time [s]"]
    for title, table in (("Every run", wide), ("Every run again", other)):
        _, joined = report_table(path, "Runs", title)
        assert list(joined.columns) == list(table.columns)
        assert list(joined["a quantity with a long name 23 [deg]"]) == [24.0] * 3
    width = sum(7 * w + 5 for w in column_widths(ws))
    assert width * MIN_PRINT_SCALE <= PRINTABLE["landscape"][0]


#: A block's title: ``part k of n``.
_PART = re.compile(r"\bpart \d+ of \d+")
#: The key columns of each wide table of the example's campaign and multibody reports (the
#: row's id: run, mode, metric and unit, run and time), by report and the start of its title.
_EXAMPLE_KEYS = {"campaign": {"Metrics of every run": ["run"],
                              "Every grid point": ["area factor [-]", "airspeed EAS [kt]"],
                              "Every ramp": ["helicopter", "ramp target [kt]"]},
                 "multibody": {"Modes of the linear model": ["mode"],
                               "Metrics of every run": ["metric", "unit"],
                               "Every run every": ["run", "time [s]"]}}


def _example_keys(report, title):
    return next(keys for start, keys in _EXAMPLE_KEYS[report].items()
                if title.startswith(start))


def test_example_reports_print_each_block_once_keys_first(example_campaign_run_report):
    """In the example's campaign and multibody reports (every analysis, the campaign on), a
    block of a wide table has one ``part k of n`` in its title, on a sheet of several tables
    (its title cell) or on a table sheet of its own (its page header), and starts with the
    table's key columns; a sheet of blocks fits the landscape page at the least print scale
    (stored widths, 7 px a unit plus 5 px), and a table sheet of a block reads back with
    pandas as data: the header in row 1, no header in the rows."""
    blocks = 0
    for report in ("campaign", "multibody"):
        path = next(example_campaign_run_report.glob(f"*-{report}.xlsx"))
        book = openpyxl.load_workbook(path)
        for ws in book.worksheets[1:]:  # after the cover (which lists the sheets)
            header = ws.oddHeader.center.text or ""
            starts = [(row + 1, title) for row, title in _part_titles(ws)]
            if _PART.search(header) and not starts:  # a table sheet of one block
                starts = [(1, header)]
                frame = pd.read_excel(path, sheet_name=ws.title)
                keys = _example_keys(report, header)
                assert list(frame.columns[:len(keys)]) == keys, (ws.title, header)
                assert not frame.isin(keys).any().any(), ws.title
            for row, title in starts:
                assert len(_PART.findall(title)) == 1, (report, ws.title, title)
                keys = _example_keys(report, title)
                assert [c.value for c in ws[row]][:len(keys)] == keys, (ws.title, title)
                blocks += 1
            if starts:
                width = sum(7 * w + 5 for w in column_widths(ws))
                assert width * MIN_PRINT_SCALE <= PRINTABLE["landscape"][0], (ws.title, width)
    assert blocks >= 6  # the campaign's metrics and ramps, the multibody modes and histories


#: A block's title: the table's title (its long bracketed remarks aside, as a page header
#: gives it), the block's k and n.
_PART_OF = re.compile(r"^(?P<table>.*), part (?P<k>\d+) of (?P<n>\d+)$", re.DOTALL)


def _printed_parts(path):
    """``{table title: [k, ...]}``: the blocks of each table cut in parts, in the order the
    workbook prints them: its sheets in order (the cover, which lists them, aside), on each
    its page header (a table sheet of one block) then its title cells by row."""
    book = openpyxl.load_workbook(path)
    order = {}
    for ws in book.worksheets[1:]:
        seen = []
        for text in [ws.oddHeader.center.text or "", *(t for _, t in _part_titles(ws))]:
            found = _PART_OF.match(text)
            if found and found.groups() not in seen:  # a header repeats its first title
                seen.append(found.groups())
        for table, k, n in seen:
            table = re.sub(r"\s*\([^()]{13,}\)", "", table)  # as a page header shortens it
            order.setdefault((table, int(n)), []).append(int(k))
    return order


def test_parts_of_each_table_print_in_order(example_campaign_run_report, us_twin_reports):
    """In every report of both examples (the example with its campaign, the US twin), the
    blocks of a table cut in parts print as their titles number them: part 1, 2, ... n, each
    once, in the workbook's sheet order and row order; a block too long for a sheet of
    several tables takes every block of its table to sheets of their own, in order, never
    itself alone after the rest ('Metrics part 4' after parts 5-9). Reference: the titles
    and page headers read back with openpyxl."""
    _, twin = us_twin_reports
    tables, wrong = 0, []
    for folder in (example_campaign_run_report, twin):
        for path in sorted(folder.glob("*.xlsx")):
            for (table, n), ks in _printed_parts(path).items():
                tables += 1
                if ks != list(range(1, n + 1)):
                    wrong.append((path.name, table, ks))
    assert tables >= 10
    assert not wrong, wrong

"""A sheet of several tables prints each table as one block: its text columns (notes) wrap
narrower, rows taller, so that a wide table beside them keeps all its columns together; a
table cut into column parts (only when no narrower wrap lets it fit) keeps its ``unit``
column in every part, so that each number keeps the format of its row's unit.

The reference is the written file read back with openpyxl and pandas (the stored column
widths at 7 px per character unit, the Excel number format of each cell), against the A4
landscape page at the least print scale
(:data:`~slingloads.io.common.excel_print.MIN_PRINT_SCALE`)."""

from __future__ import annotations

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

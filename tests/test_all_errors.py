"""A workbook with several mistakes is refused once, with every mistake named at its cell.

The reference is the rule stated in docs/inputs-and-outputs.md, section 4 ("Every mistake at
once"): independent steps (the Study sheet row by row, each table cell by cell, the airframe,
each analysis) are all checked and their errors reported together, in reading order, up to
:data:`slingloads.errors.MAX_REPORTED_ERRORS`; a step others need stops the reading and the
message says what was not checked. Each test breaks known cells of a valid copy of the example
and checks that exactly those cells are named.
"""

from __future__ import annotations

import openpyxl
import pytest
from hostile import light_example

from slingloads.cli import main
from slingloads.errors import MAX_REPORTED_ERRORS, InputError, InputErrors
from slingloads.io.study import read_study


def _copy(tmp_path, edits, name="many.xlsx"):
    book = openpyxl.load_workbook(light_example())
    for sheet, cell, value in edits:
        book[sheet][cell] = value
    path = tmp_path / name
    book.save(path)
    return path


def test_errors_in_three_analyses_are_named_together(tmp_path, capsys):
    """Bad cells on the loads', the lateral study's and the multibody model's sheets: one
    refusal naming the three cells in reading order; exit 2; nothing written."""
    path = _copy(tmp_path, [("AeroEnvelope", "B3", "fast"), ("LateralMotions", "C2", "x"),
                            ("MultibodyManoeuvres", "B3", "nope")])
    with pytest.raises(InputErrors) as info:
        read_study(path)
    cells = [(e.sheet, e.cell) for e in info.value.errors]
    assert cells == [("AeroEnvelope", "B3"), ("LateralMotions", "C2"),
                     ("MultibodyManoeuvres", "B3")]
    assert (info.value.sheet, info.value.cell) == ("AeroEnvelope", "B3")  # the first one
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "3 errors in the input" in err
    for text in ("'fast'", "value 'x'", "'nope'", "nothing was written"):
        assert text in err
    assert not out.exists()


def test_every_bad_cell_of_the_airframe_sheets(tmp_path):
    """Two bad cells of MassItems and one of Stations, besides a bad Study row: the four are
    named; the analyses' sheets are not checked, and the message says so."""
    book = openpyxl.load_workbook(light_example())
    book["MassItems"]["C2"] = "heavy"
    book["MassItems"]["D3"] = None
    book["Stations"]["B3"] = "x"
    book["Study"].append(["parachute aera", 1, "m^2"])
    path = tmp_path / "airframe.xlsx"
    book.save(path)
    with pytest.raises(InputErrors) as info:
        read_study(path)
    got = [(e.sheet, e.cell) for e in info.value.errors]
    row = book["Study"].max_row
    assert got == [("Study", f"A{row}"), ("MassItems", "C2"), ("MassItems", "D3"),
                   ("Stations", "B3")]
    assert not info.value.complete
    assert "checked once the Study sheet reads" in str(info.value)


def test_texts_in_number_cells_of_five_sheets_are_named_together(tmp_path, capsys):
    """A careless user's texts in number cells of an airframe sheet, an optional airframe
    sheet and three analyses' sheets at once: the five cells are named in one refusal (they
    used to be one per attempt: the airframe's error stopped the reading before the other
    sheets' cells were read); exit 2; nothing written."""
    edits = [("MassItems", "C3", "heavy"), ("FinAero", "B10", "n/a"),
             ("LateralMotions", "C3", "fast"), ("ChuteWake", "B3", "x"),
             ("MultibodyManoeuvres", "F3", "soon")]
    path = _copy(tmp_path, edits, "five.xlsx")
    with pytest.raises(InputErrors) as info:
        read_study(path)
    assert [(e.sheet, e.cell) for e in info.value.errors] == [(s, c) for s, c, _ in edits]
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "5 errors in the input" in err and "nothing was written" in err
    assert not out.exists()


def test_one_error_is_reported_as_before(tmp_path):
    """A single bad cell gives a plain located InputError, not a list of one."""
    path = _copy(tmp_path, [("LateralMotions", "C2", "x")])
    with pytest.raises(InputError) as info:
        read_study(path)
    assert not isinstance(info.value, InputErrors)
    assert (info.value.sheet, info.value.cell) == ("LateralMotions", "C2")


def test_reading_stops_at_the_limit(tmp_path):
    """More bad cells than the limit: exactly MAX_REPORTED_ERRORS are named, the first ones in
    the order of the sheet, and the message says reading stopped (bounded work and text)."""
    book = openpyxl.load_workbook(light_example())
    ws = book["MassItems"]
    bad = [f"{col}{r}" for r in range(2, ws.max_row + 1) for col in "CDEF"]  # mass, x, y, z
    assert len(bad) > MAX_REPORTED_ERRORS + 5, "the example has enough mass items"
    for cell in bad:
        ws[cell] = "x"
    path = tmp_path / "limit.xlsx"
    book.save(path)
    with pytest.raises(InputErrors) as info:
        read_study(path)
    assert [e.cell for e in info.value.errors] == bad[:MAX_REPORTED_ERRORS]
    assert "reading stopped" in str(info.value)


def test_a_deleted_header_row_is_one_error(tmp_path):
    """A table whose header row was deleted (its first data row moved up into row 1) names
    no column: one error at A1 saying so, with the sheet's columns, not one 'unknown column'
    per number of the row."""
    book = openpyxl.load_workbook(light_example())
    book["Stations"].delete_rows(1)
    path = tmp_path / "noheader.xlsx"
    book.save(path)
    with pytest.raises(InputError) as info:
        read_study(path)
    err = info.value
    assert not isinstance(err, InputErrors)
    assert (err.sheet, err.cell) == ("Stations", "A1")
    assert "names none of the sheet's columns" in str(err) and "'x [m]'" in str(err)


def test_the_message_of_many_errors_is_bounded(tmp_path):
    """Every cell of MassItems made bad: the message names the file once (not on every line)
    and stays within MAX_MESSAGE_CHARS plus its last lines, saying how many more there are."""
    from slingloads.errors import MAX_MESSAGE_CHARS

    book = openpyxl.load_workbook(light_example())
    ws = book["MassItems"]
    for r in range(2, ws.max_row + 1):
        for col in "CDEFGHIJ":
            ws[f"{col}{r}"] = "a rather long text where a number belongs"
    path = tmp_path / "long.xlsx"
    book.save(path)
    with pytest.raises(InputErrors) as info:
        read_study(path)
    text = str(info.value)
    assert text.count(str(path)) == 1
    assert len(text) < MAX_MESSAGE_CHARS + 400
    assert "more (fix these first)" in text or len(info.value.errors) * 80 < MAX_MESSAGE_CHARS


def test_rows_of_an_analysis_not_run_are_checked_with_the_others(tmp_path, capsys):
    """'run campaign' = no and 'run lateral' = no: a campaign list with a text in it, a
    lateral choice that is no choice and a bad campaign scheduler address are named with a
    bad Study number of an analysis that runs, a bad airframe choice (read after the Study
    sheet) and a bad cell of a sheet, in one refusal
    (the rule of docs/inputs-and-outputs.md section 4: every mistake at once; a row of an
    analysis not run is an input of the study all the same). The list used to be read only
    when the campaign ran: alone it passed, beside another error it was not named."""
    from hostile import study_row

    book = openpyxl.load_workbook(light_example())
    edits = {"run lateral": "no", "campaign no-parachute gust ramps": "20, fast",
             "lateral cable model": "elastc", "multibody output interval": -1.0,
             "campaign scheduler": "tcp://host:99999", "fin axes": "sideways"}
    for name, value in edits.items():
        book["Study"][f"B{study_row(book, name)}"] = value
    book["MassItems"]["C2"] = "heavy"
    path = tmp_path / "rows.xlsx"
    book.save(path)
    with pytest.raises(InputErrors) as info:
        read_study(path)
    cells = [(e.sheet, e.cell) for e in info.value.errors]
    row = {name: f"B{study_row(book, name)}" for name in edits}
    assert cells == [("Study", row["multibody output interval"]), ("Study", row["fin axes"]),
                     ("Study", row["lateral cable model"]),
                     ("Study", row["campaign no-parachute gust ramps"]),
                     ("Study", row["campaign scheduler"]), ("MassItems", "C2")], cells
    text = str(info.value)
    for fragment in ("value 'fast'", "'elastc'", "port must be in [1, 65535]", "'heavy'",
                     "'sideways'"):
        assert fragment in text, text
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    assert "6 errors in the input" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_bad_row_of_an_analysis_not_run_is_refused_alone(tmp_path):
    """The campaign's gust-ramp list with a text in it, 'run campaign' = no, no other
    mistake: refused at its cell (it used to pass unread)."""
    from hostile import study_row

    book = openpyxl.load_workbook(light_example())
    cell = f"B{study_row(book, 'campaign no-parachute gust ramps')}"
    book["Study"][cell] = "20, fast"
    path = tmp_path / "one.xlsx"
    book.save(path)
    with pytest.raises(InputError) as info:
        read_study(path)
    assert (info.value.sheet, info.value.cell) == ("Study", cell)
    assert "value 'fast'" in str(info.value)

"""Bad input: each kind of error names the file, sheet, cell, the value and the rule it broke;
the command exits with code 2 and writes nothing (an earlier report is left intact).

The reference for every test is the rule written in the input workbook's own documentation
(README sheet of ``slingloads template``, ``docs/loads-method.md``): each test breaks one rule
in an otherwise valid copy of the example workbook and checks that exactly that rule is named
at exactly that place.
"""

from __future__ import annotations

import shutil
import zipfile

import openpyxl
import pytest
from hostile import EXAMPLE, light_example

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.study import read_study


@pytest.fixture(scope="module")
def example_book():
    return openpyxl.load_workbook(light_example())


def edited(tmp_path, example_book, edit, name="bad.xlsx"):
    """Save a copy of the example (:func:`hostile.light_example`: its fuselage table thinned)
    with ``edit(workbook)`` applied; return its path."""
    book = openpyxl.load_workbook(light_example())
    edit(book)
    path = tmp_path / name
    book.save(path)
    return path


def study_row(book, name):
    ws = book["Study"]
    for row in ws.iter_rows(min_row=2):
        if row[0].value == name:
            return row[0].row
    raise KeyError(name)


def expect_error(path, *fragments):
    with pytest.raises(InputError) as info:
        read_study(path)
    message = str(info.value)
    assert str(path) in message
    for fragment in fragments:
        assert fragment in message, message
    return info.value


def test_missing_sheet(tmp_path, example_book):
    """Rule: the Stations sheet is required."""
    path = edited(tmp_path, example_book, lambda b: b.remove(b["Stations"]))
    expect_error(path, "sheet 'Stations'", "missing sheet 'Stations'")


def test_missing_column(tmp_path, example_book):
    """Rule: MassItems needs a mass column (header in row 1)."""
    def edit(b):
        b["MassItems"]["C1"] = "weight note"
    path = edited(tmp_path, example_book, edit)
    expect_error(path, "sheet 'MassItems'", "unknown column", "weight note")

    def drop(b):
        b["MassItems"].delete_cols(3)
    path = edited(tmp_path, example_book, drop, "drop.xlsx")
    expect_error(path, "sheet 'MassItems'", "missing column 'mass [kg]'")


def test_unknown_unit(tmp_path, example_book):
    """Rule: a header's unit must be a unit pint knows."""
    def edit(b):
        b["MassItems"]["C1"] = "mass [lbz]"
    expect_error(edited(tmp_path, example_book, edit), "sheet 'MassItems'", "cell C1",
                 "unknown unit", "'lbz'")


def test_unit_of_wrong_kind(tmp_path, example_book):
    """Rule: a length column takes a length unit."""
    def edit(b):
        b["MassItems"]["D1"] = "x [kg]"
    expect_error(edited(tmp_path, example_book, edit), "cell D1", "unit is not a length")


def test_non_numeric_cell(tmp_path, example_book):
    """Rule: masses are numbers."""
    def edit(b):
        b["MassItems"]["C5"] = "heavy"
    expect_error(edited(tmp_path, example_book, edit), "sheet 'MassItems'", "cell C5",
                 "must be a number", "'heavy'")


def test_empty_cell(tmp_path, example_book):
    """Rule: a required cell may not be empty."""
    def edit(b):
        b["MassItems"]["D7"] = None
    expect_error(edited(tmp_path, example_book, edit), "cell D7", "empty cell")


def test_errors_name_the_column_as_written(tmp_path, example_book):
    """Rule: an error names the column with the unit the user wrote in its header (the
    example's masses are in lb, stations in in), not the SI unit it is converted to."""
    def edit(b):
        b["MassItems"]["C5"] = "heavy"
        b["MassItems"]["D7"] = None
    expect_error(edited(tmp_path, example_book, edit), "cell C5", "'mass [lb]' must be a "
                 "number")

    def edit_station(b):
        b["Stations"]["B3"] = None
    error = expect_error(edited(tmp_path, example_book, edit_station), "cell B3",
                         "empty cell in required column 'x [in]'")
    assert "[m]" not in str(error)


@pytest.mark.parametrize("sheet, cell", [("FuselageAero", "C3"), ("FuselageAero", "E40")])
def test_empty_or_uncomputed_coefficient_names_its_cell(tmp_path, example_book, sheet, cell):
    """Rule: the fuselage table needs every coefficient of its frame at every grid point.
    An empty cell, or a formula saved without its value (openpyxl saves none), is named at
    its cell with the column as written, with the hint to recompute formulas."""
    def edit(b):
        b[sheet][cell] = "=1+1" if cell == "C3" else None
    column = example_book[sheet][f"{cell[0]}1"].value
    expect_error(edited(tmp_path, example_book, edit), f"sheet '{sheet}'", f"cell {cell}",
                 "empty cell in", f"column '{column}'", "formula whose value was never computed")


def test_empty_parachute_coefficient_names_its_cell(tmp_path):
    """Rule: the ParachuteCD table needs its coefficient (CD in wind axes) at every alpha:
    an empty one is named at its cell."""
    from hostile import save_xlsx, small_workbook

    sheets = small_workbook()
    sheets["ParachuteCD"] = [("alpha [deg]", "CD"), (-10.0, 0.9), (0.0, None), (10.0, 0.9)]
    path = save_xlsx(sheets, tmp_path / "chute.xlsx")
    expect_error(path, "sheet 'ParachuteCD'", "cell B3", "empty cell in column 'CD'")


@pytest.mark.parametrize("mass", [0, -12.5])
def test_zero_or_negative_mass(tmp_path, example_book, mass):
    """Rule: every mass is > 0."""
    def edit(b):
        b["MassItems"]["C3"] = mass
    expect_error(edited(tmp_path, example_book, edit), "cell C3", "mass must be > 0",
                 repr(float(mass)))


def test_duplicate_ids(tmp_path, example_book):
    """Rule: mass item ids are unique."""
    def edit(b):
        b["MassItems"]["A4"] = b["MassItems"]["A2"].value
    expect_error(edited(tmp_path, example_book, edit), "cell A4", "duplicate id", "A2")


def test_unsorted_stations(tmp_path, example_book):
    """Rule: cut stations are sorted by increasing x."""
    def edit(b):
        ws = b["Stations"]
        ws["B4"], ws["B5"] = ws["B5"].value, ws["B4"].value
    expect_error(edited(tmp_path, example_book, edit), "sheet 'Stations'", "cell B5",
                 "sorted by increasing x")


def test_duplicated_stations(tmp_path, example_book):
    """Rule: cut stations do not repeat."""
    def edit(b):
        ws = b["Stations"]
        ws["B5"] = ws["B4"].value
    expect_error(edited(tmp_path, example_book, edit), "cell B5", "must not repeat")


def test_hardpoint_outside_airframe(tmp_path, example_book):
    """Rule: a hardpoint lies within the mass items' x range."""
    def edit(b):
        ws = b["Hardpoints"]
        ws["C2"] = 2000  # the hub, 2000 in aft of the nose: beyond the tail
    expect_error(edited(tmp_path, example_book, edit), "sheet 'Hardpoints'", "cell C2",
                 "outside the airframe")


def test_envelope_outside_aero_table(tmp_path, example_book):
    """Rule: no extrapolation of the aerodynamic tables (fuselage alpha range -40..40 deg)."""
    def edit(b):
        b["AeroEnvelope"]["B3"] = 45
    expect_error(edited(tmp_path, example_book, edit), "sheet 'AeroEnvelope'", "cell B3",
                 "outside the fuselage table's range", "no extrapolation")


def test_parachute_wake_ratio_above_one(tmp_path, example_book):
    """Rule: the wake dynamic-pressure ratio lies in (0, 1]."""
    def edit(b):
        b["Study"].cell(study_row(b, "parachute wake ratio"), 2).value = 1.5
    expect_error(edited(tmp_path, example_book, edit), "sheet 'Study'", "wake",
                 "(0, 1]", "1.5")


def test_parachute_without_attachment(tmp_path, example_book):
    """Rule: a parachute area needs a 'chute' hardpoint."""
    def edit(b):
        ws = b["Hardpoints"]
        for row in ws.iter_rows(min_row=2):
            if row[1].value == "chute":
                ws.delete_rows(row[0].row)
                break
    expect_error(edited(tmp_path, example_book, edit), "parachute area",
                 "no row of kind 'chute'")


def test_unknown_parameter(tmp_path, example_book):
    """Rule: Study-sheet parameters are the documented ones."""
    def edit(b):
        b["Study"].cell(study_row(b, "fin area"), 1).value = "fin areaa"
    expect_error(edited(tmp_path, example_book, edit), "sheet 'Study'", "unknown parameter",
                 "'fin areaa'")


def test_file_that_is_not_a_workbook(tmp_path):
    """Rule: the input is an .xlsx (zip) container."""
    path = tmp_path / "notes.xlsx"
    path.write_text("this is plain text, not a workbook\n")
    expect_error(path, "not a workbook")


@pytest.mark.parametrize("content, words", [
    # the OLE2 signature (MS-CFB 2.2: D0 CF 11 E0 A1 B1 1A E1) begins an encrypted .xlsx
    (bytes.fromhex("d0cf11e0a1b11ae1") + bytes(504), "protected by a password"),
    (b"", "the file is empty"),
])
def test_a_file_that_looks_like_a_workbook_says_what_it_is(tmp_path, content, words):
    """Rule: the input is an .xlsx (zip) container; a file that is not says what it looks
    like when it can tell: an encrypted workbook (Excel stores one with a password to open
    in an OLE2 compound document) or an empty file."""
    path = tmp_path / "locked.xlsx"
    path.write_bytes(content)
    expect_error(path, "not a workbook", words)


def test_corrupt_workbook(tmp_path):
    """Rule: the workbook must be readable: a truncated file is refused."""
    path = tmp_path / "truncated.xlsx"
    path.write_bytes(EXAMPLE.read_bytes()[:5000])
    expect_error(path, "not a workbook")


def test_xml_bomb_is_refused(tmp_path):
    """Hostile workbook: a 'billion laughs' entity expansion in a sheet's XML is refused by
    defusedxml (through openpyxl) instead of exhausting memory (defusedxml documentation)."""
    bomb = ('<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
            + "".join(f'<!ENTITY lol{i} "{("&lol%s;" % (i - 1 if i > 1 else "")) * 10}">'
                      for i in range(1, 10))
            + ']><worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">'
            '<sheetData><row r="1"><c r="A1" t="inlineStr"><is><t>&lol9;</t></is></c></row>'
            '</sheetData></worksheet>')
    path = tmp_path / "bomb.xlsx"
    with zipfile.ZipFile(EXAMPLE) as src, zipfile.ZipFile(path, "w") as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "xl/worksheets/sheet2.xml":
                data = bomb.encode()
            dst.writestr(item, data)
    error = expect_error(path, "not a readable .xlsx workbook")
    assert "Entities" in str(error) or "DTD" in str(error)


def test_cli_bad_input_exit_code_and_nothing_written(tmp_path, example_book, capsys):
    """Rule: bad input -> exit code 2, no output at all, an earlier report left intact."""
    good = tmp_path / "study.xlsx"
    shutil.copy(EXAMPLE, good)
    out = tmp_path / "reports"
    out.mkdir()
    earlier = out / "study-loads.xlsx"
    earlier.write_bytes(b"earlier report")

    def edit(b):
        b["MassItems"]["C3"] = -1
    bad = edited(tmp_path, example_book, edit, "study.xlsx")
    assert bad == good
    code = main(["run", str(bad), "--out", str(out), "--quiet"])
    assert code == 2
    err = capsys.readouterr().err
    assert "cell C3" in err and "nothing was written" in err
    assert sorted(p.name for p in out.iterdir()) == ["study-loads.xlsx"]
    assert earlier.read_bytes() == b"earlier report"


def test_cli_refuses_to_overwrite_the_input(tmp_path, capsys):
    """Rule: an input is never overwritten, even through a link named like an output."""
    source = tmp_path / "study.xlsx"
    shutil.copy(EXAMPLE, source)
    before = source.read_bytes()
    out = tmp_path / "out"
    out.mkdir()
    (out / "study-loads.xlsx").symlink_to(source)
    code = main(["loads", str(source), "--out", str(out), "--quiet"])
    assert code == 2
    assert "never overwritten" in capsys.readouterr().err
    assert source.read_bytes() == before


@pytest.mark.parametrize("text", ["1_0", "\u0662", "\uff13\uff19\uff16", "0x1A", "1e", "--2"])
def test_numbers_are_written_with_ascii_digits(tmp_path, example_book, text):
    """Rule (docs/inputs-and-outputs.md): a number written as text is plain decimal
    notation with the digits 0-9. Python's float() reads '1_0' as 10 and other scripts'
    digits ('\u0662' is 2, full-width '\uff13\uff19\uff16' is 396): refused at the cell."""
    def edit(b):
        b["MassItems"]["C3"] = text
    expect_error(edited(tmp_path, example_book, edit), "cell C3", "must be a number",
                 repr(text))


def test_plain_numbers_written_as_text_are_read(tmp_path, example_book, example_study):
    """Rule: text holding a plain decimal number, spaces around it ignored, is that number
    (' 396.83\\n' is the example's 396.83 lb)."""
    def edit(b):
        b["MassItems"]["C3"] = " 396.83\n"
    study = read_study(edited(tmp_path, example_book, edit))
    got, expected = study.airframe.mass_items, example_study.airframe.mass_items
    assert got.mass[1] == expected.mass[1] == pytest.approx(396.83 * 0.45359237, rel=1e-15)
    assert list(got.mass) == list(expected.mass)


def test_two_sheets_matching_one_name_are_refused(tmp_path, example_book):
    """Rule: sheet names are matched with case and surrounding spaces ignored, so a second
    sheet ' STUDY ' beside 'Study' is ambiguous: refused, naming both, not silently
    ignored."""
    def edit(b):
        ws = b.create_sheet(" STUDY ")
        ws.append(["parameter", "value", "unit"])
        ws.append(["hook load factor Nz", 19, None])
    expect_error(edited(tmp_path, example_book, edit), "2 sheets match 'Study'", "' STUDY '")


@pytest.mark.parametrize("text, char", [("CK\tPT", "U+0009 (TAB)"),
                                        ("CR\nEW", "U+000A (LINE FEED)"),
                                        ("CK\u202ePT", "U+202E (RIGHT-TO-LEFT OVERRIDE)"),
                                        ("CK\u200bPT", "U+200B (ZERO WIDTH SPACE)"),
                                        ("CK\u00a0PT", "U+00A0 (NO-BREAK SPACE)")])
def test_ids_hold_visible_characters_only(tmp_path, example_book, text, char):
    """Rule: an id holds visible characters and plain spaces only, so that two ids that
    look alike on a printed report are alike (a tab, line break, zero-width or no-break
    space, or a direction override would make them differ unseen)."""
    def edit(b):
        b["MassItems"]["A3"] = text
    expect_error(edited(tmp_path, example_book, edit), "cell A3", char)


def test_descriptions_refuse_direction_controls_but_keep_line_breaks(tmp_path, example_book):
    """Rule: free text may hold line breaks and any script, never a Unicode direction
    control (which can make a text display as another: 'Trojan source')."""
    def edit(b):
        b["MassItems"]["B3"] = "cockpit \u202estructure"
    expect_error(edited(tmp_path, example_book, edit), "cell B3", "U+202E")

    def fine(b):
        b["MassItems"]["B3"] = "cockpit\nstructure, \u00e9\u6f22"
    read_study(edited(tmp_path, example_book, fine, "fine.xlsx"))


def test_ids_differing_only_in_case_are_duplicates(tmp_path, example_book):
    """Rule: ids are unique with case ignored ('NOSE' and 'nose' cannot be told apart by a
    reader of the report): the second is refused, naming the first."""
    def edit(b):
        b["MassItems"]["A3"] = b["MassItems"]["A2"].value.lower()
    expect_error(edited(tmp_path, example_book, edit), "cell A3", "duplicate id",
                 "first at A2")


def test_the_no_aero_id_is_reserved(tmp_path, example_book):
    """Rule: in LoadCases, aero NONE means no aerodynamic load, so no AeroEnvelope point
    may be called NONE (in any case)."""
    def edit(b):
        b["AeroEnvelope"]["A3"] = "None"
    expect_error(edited(tmp_path, example_book, edit), "sheet 'AeroEnvelope'", "cell A3",
                 "'NONE' is reserved")


def test_a_study_value_under_no_header_is_refused(tmp_path, example_book):
    """Rule: no data is silently ignored: a value in a Study column without a header, as in
    every table sheet, is refused at its cell."""
    def edit(b):
        b["Study"].cell(5, 5).value = 42
    expect_error(edited(tmp_path, example_book, edit), "sheet 'Study'", "cell E5",
                 "column without a header")


def test_an_empty_zip_is_explained_without_python_names(tmp_path):
    """Rule: a file that is a zip but not a workbook is refused in a user's words (the
    missing part of the package named, no Python exception class)."""
    path = tmp_path / "empty.xlsx"
    zipfile.ZipFile(path, "w").close()
    error = expect_error(path, "not a readable .xlsx workbook", "[Content_Types].xml",
                         "save it again")
    assert "KeyError" not in str(error)


def test_a_numeric_factor_in_a_unit_is_refused_with_the_reason(tmp_path, example_book):
    """Rule (docs/inputs-and-outputs.md): a unit is unit names and powers only; a numeric
    factor (0.0254*m for inches) is refused at the header, saying so."""
    def edit(b):
        b["Stations"]["B1"] = "x [0.0254*m]"
    expect_error(edited(tmp_path, example_book, edit), "cell B1", "never a numeric factor",
                 "0.0254*m")



def test_a_merged_header_is_named_where_the_header_is_missing(tmp_path, example_book):
    """Rule: every required column has a header. Merging C1:D1 empties D1 while D2 down
    still hold the x values: the error is at D1 (not past the table), saying that column D
    holds values under an empty header."""
    def edit(b):
        b["MassItems"].merge_cells("C1:D1")
    expect_error(edited(tmp_path, example_book, edit), "sheet 'MassItems'", "cell D1",
                 "missing column 'x [m]'", "column D holds values under an empty header")

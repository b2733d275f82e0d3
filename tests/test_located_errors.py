"""Every validation error is located, and implausible geometry is refused or flagged.

The reference is the rule of docs/inputs-and-outputs.md: an error names the file, the sheet,
the cell, the value as the user wrote it with the user's unit, and the rule; an error a model
raises on a value from a cell is put at that cell. Each test breaks one rule of the small
workbook (tests/hostile.py) and checks exactly that location; the geometry tests check the
limits stated in the template (coordinates within 100 m of the datum, mass items within an
80 m box, cut stations near the load points, ids distinct in file names).
"""

from __future__ import annotations

import pytest
from hostile import located_error, read_book, save_xlsx, set_parameter, small_workbook, study_cell

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.common.cover import input_digest
from slingloads.io.common.xlsx_source import CellError

FILE = "located.xlsx"


def read(book):
    return read_book(book, FILE)


def error(book, sheet, cell, *fragments):
    """Read ``book``: an InputError at ``sheet``/``cell`` whose message holds every
    fragment (:func:`hostile.located_error`)."""
    return located_error(book, FILE, sheet, cell, *fragments)


def with_parameter(name, value, unit=None):
    book = small_workbook()
    set_parameter(book, name, value, unit)
    return book, study_cell(book, name)


def test_unknown_hook_direction_of_a_listed_case():
    """LoadCases 'hook' must be a direction the Study's hook options generate."""
    book = small_workbook()
    book["LoadCases"][1][1] = "AZ100"
    error(book, "LoadCases", "B2", "unknown hook direction", "'AZ100'", "AZ090")


def test_table_not_increasing():
    """FinAero beta must be strictly increasing: the cell that breaks the order is named."""
    book = small_workbook()
    book["FinAero"][3][0] = -25.0  # after -20
    error(book, "FinAero", "A4", "strictly increasing", "-25.0", "[deg]")


@pytest.mark.parametrize("value, unit, fragment", [
    (95, "deg", "[deg]"), (2.0, "rad", "< 1.5708 rad"), (-5, "deg", ">= 0 deg")])
def test_hook_angle_out_of_range(value, unit, fragment):
    """'hook angle from mast' lies in [0, 90) deg; the value and the bound are shown in the
    user's unit."""
    book, cell = with_parameter("hook angle from vertical", value, unit)
    error(book, "Study", cell, "hook angle from vertical", repr(value), fragment)


def test_negative_nz():
    """'hook load factor Nz' must be >= 1 (the hook carries the weight in steady flight)."""
    book, cell = with_parameter("hook load factor Nz", -2.5)
    error(book, "Study", cell, "Nz", "-2.5", ">= 1")


def test_negative_own_inertia():
    """An own moment of inertia is >= 0: the cell of the negative value."""
    book = small_workbook()
    book["MassItems"][2][6] = -5.0
    error(book, "MassItems", "G3", "Izz", ">= 0", "-5.0", "[kg m^2]")


def test_non_physical_inertia_tensor():
    """A tensor with too large a product of inertia has a negative principal moment: the
    model's error is put at the item's row."""
    book = small_workbook()
    book["MassItems"][0].append("Ixy [kg m^2]")
    for row in book["MassItems"][1:]:
        row.append(0.0)
    book["MassItems"][2][-1] = 5000.0
    error(book, "MassItems", "H3", "principal moment")


def test_zero_mast_axis_is_blamed_on_the_study_sheet():
    """A zero mast axis is a Study-sheet error (not a Hardpoints one)."""
    book = small_workbook()
    for name in ("mast axis x", "mast axis y", "mast axis z"):
        set_parameter(book, name, 0)
    error(book, "Study", study_cell(book, "mast axis z"), "zero vector")


def test_mast_axis_along_x():
    """A mast along the fuselage x axis has no hook cone: refused at 'mast axis x'."""
    book = small_workbook()
    set_parameter(book, "mast axis x", 1)
    set_parameter(book, "mast axis z", 0)
    error(book, "Study", study_cell(book, "mast axis x"), "parallel")


@pytest.mark.parametrize("sheet, r, c, cell", [
    ("MassItems", 2, 2, "C3"), ("MassItems", 2, 6, "G3"), ("FuselageAero", 3, 2, "C4"),
    ("Hardpoints", 1, 4, "E2"), ("LateralRopes", 1, 0, "A2")])
def test_overflowing_values_are_refused_at_their_cell(sheet, r, c, cell):
    """1e300 (or any value beyond the magnitude limit of its kind) is refused at its cell,
    never reported later as a closure residual or a NaN inertia."""
    book = small_workbook()
    book[sheet][r][c] = 1e300
    error(book, sheet, cell, "1e+300", "must not exceed")


@pytest.mark.parametrize("unit", ["kg/0", "kt/0", "kg**0", "1e999 kg", "degC",
                                  "percent**1000", "(" * 40 + "kg" + ")" * 40])
def test_malformed_units_in_a_header(unit):
    """Every malformed unit is an InputError at the header cell (no ZeroDivisionError,
    KeyError, RecursionError)."""
    book = small_workbook()
    book["MassItems"][0][2] = f"mass [{unit}]"
    error(book, "MassItems", "C1", "unit")


@pytest.mark.parametrize("unit", ["kt/0", "kg**0", "degC", "m/s/0"])
def test_malformed_units_of_a_parameter(unit, tmp_path, capsys):
    """The same in the Study 'unit' column, through the command line: exit 2, located at
    the unit cell, nothing written."""
    book, cell = with_parameter("airspeed EAS", 100, unit)
    path = save_xlsx(book, tmp_path / "units.xlsx")
    assert main(["loads", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"sheet 'Study', cell C{cell[1:]}" in err and "Traceback" not in err, err
    assert not (tmp_path / "out").exists()


def test_listed_case_id_clashing_with_a_generated_one():
    """A listed case may not take the id of a generated case (LC0001...)."""
    book = small_workbook()
    book["LoadCases"][1][0] = "LC0003"
    error(book, "LoadCases", "A2", "generated case")


def test_fuselage_table_not_a_full_grid():
    """FuselageAero rows form a full alpha x beta grid: the alpha short of rows is named."""
    book = small_workbook()
    del book["FuselageAero"][3]
    error(book, "FuselageAero", "A2", "full grid")


def test_repeated_grid_point():
    """A repeated (alpha, beta) row of FuselageAero is named at its beta cell."""
    book = small_workbook()
    book["FuselageAero"][3][1] = book["FuselageAero"][2][1]
    error(book, "FuselageAero", "B4", "repeats row 3")


def test_value_in_a_column_without_header():
    """A value right of the table, under no header, is an error (never silently ignored)."""
    book = small_workbook()
    book["Stations"][2].append("stray")
    error(book, "Stations", "C3", "without a header", "'stray'")


@pytest.mark.parametrize("value, fragment", [
    (CellError("#DIV/0!"), "spreadsheet error"), (True, "true/false"),
    (__import__("datetime").datetime(2024, 1, 2), "date or time")])
def test_cells_that_are_not_numbers(value, fragment):
    """Spreadsheet errors, booleans and dates in a number column, each at its cell."""
    book = small_workbook()
    book["Stations"][2][1] = value
    error(book, "Stations", "B3", fragment)


def test_cg_above_the_hub_is_located():
    """A CG above the rotor hub (the airframe cannot hang from it, the lateral pendulum needs
    it below): an error derived from several values is still located, at the hub's z (the
    lateral body) or at the Study row that resolves it (the hanging attitude)."""
    book = small_workbook()
    book["Hardpoints"][1][4] = 0.1
    with pytest.raises(InputError) as info:
        read(book)
    err = info.value
    assert err.file == FILE and err.cell, str(err)
    assert (err.sheet, err.cell) in (("Hardpoints", "E2"), ("Study", "(default)")), str(err)
    assert "hub" in str(err)


def test_mass_items_on_one_line():
    """Mass items on one line without own inertias cannot balance a moment about it."""
    book = small_workbook()
    for row in book["MassItems"][1:]:
        row[3], row[4], row[5], row[6] = row[3], 0.0, 0.0, None
    book["MassItems"][0] = book["MassItems"][0][:6]
    for row in book["MassItems"][1:]:
        del row[6:]
    error(book, "MassItems", "G1", "no inertia about the axis")


# ---- geometry ---------------------------------------------------------------------------
def test_mass_item_kilometres_away():
    """A mass item 25 km from the datum is refused at its cell (|x| <= 100 m)."""
    book = small_workbook()
    book["MassItems"][0][3] = "x [km]"
    for row in book["MassItems"][1:]:
        row[3] = row[3] / 1000
    book["MassItems"][4][3] = 25.0
    error(book, "MassItems", "D5", "in [-0.1, 0.1] km", "25.0", "[km]")


def test_mass_items_spread_wider_than_an_airframe():
    """Items 90 m apart (each within 100 m of the datum): the outlier is named."""
    book = small_workbook()
    book["MassItems"][4][3] = 95.0
    error(book, "MassItems", "D5", "span", "80 m")


def test_hardpoint_outside_the_airframe():
    """A hardpoint beyond the mass items' x range is refused at its x cell."""
    book = small_workbook()
    book["Hardpoints"][4][2] = 30.0
    error(book, "Hardpoints", "C5", "outside the airframe")


def test_cut_station_far_outside_is_refused_and_near_outside_flagged():
    """A cut station an airframe length beyond the load points is an error; one just beyond
    them (zero internal loads) is a warning shown on the reports."""
    book = small_workbook()
    book["Stations"][4][1] = 40.0
    error(book, "Stations", "B5", "far outside")
    book = small_workbook()
    book["Stations"][4][1] = 8.5
    study = read(book)
    assert any("S4 (B5)" in w and "zero" in w for w in study.source.warnings)
    assert any(k.startswith("warning") for k in input_digest(study))


def test_station_ids_that_collide_in_file_names():
    """'S 2' and 'S_2' would give the same hull plot file: refused at the second id."""
    book = small_workbook()
    book["Stations"][2][0], book["Stations"][3][0] = "S 2", "s_2"
    set_parameter(book, "hull stations", "S 2")
    error(book, "Stations", "A4", "same report file name part")


def test_mass_item_far_to_the_side_is_flagged(tmp_path, capsys):
    """An item farther from the loads axis than the airframe is long (possible, e.g. a
    sling-load fixture) is accepted with a warning on stderr and on every report's
    Summary."""
    book = small_workbook()
    book["MassItems"][5][4] = -12.0
    for name in ("run lateral", "run chute sizing"):
        set_parameter(book, name, "no")
    path = save_xlsx(book, tmp_path / "side.xlsx")
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    assert "warning: mass item(s) left (E6)" in capsys.readouterr().err
    from openpyxl import load_workbook

    summary = load_workbook(tmp_path / "out" / "side-loads.xlsx", read_only=True)["Summary"]
    assert any("mass item(s) left" in str(v) for row in summary.iter_rows(values_only=True)
               for v in row)


def test_work_found_too_large_while_computing_is_located(tmp_path, capsys):
    """The automatic RK4 step is only known while computing: a stiff elastic cable on a very
    light body (1 kg) would take a million steps; the analysis refuses it and the message
    points at the Study row that sets the step ('lateral RK4 step')."""
    book = small_workbook()
    for name, value, unit in (("lateral cable model", "elastic", None),
                              ("lateral cable EA", 1e9, "N"), ("lateral simulation time", 0, "s"),
                              ("lateral RK4 step", 0, "s"), ("run loads", "no", None),
                              ("run chute sizing", "no", None)):
        set_parameter(book, name, value, unit)
    book["LateralBodies"] = [["id", "mass [kg]", "roll inertia [kg m^2]", "CG below hub [m]"],
                             ["light", 1.0, 1.0, 0.5]]
    path = save_xlsx(book, tmp_path / "stiff.xlsx")
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"sheet 'Study', cell {study_cell(book, 'lateral RK4 step')}" in err, err
    assert "RK4 steps per run" in err


def test_an_input_read_later_is_reported_before_the_first_analysis_fails(tmp_path, capsys):
    """The first analysis of a run is computed as soon as its inputs are read (its figures
    start early), but its error comes at its turn: an error in an input read after it is
    reported first, as when everything is read before anything is computed. The stiff
    lateral case above with 'chute sizing number of areas' 0 reports that cell; once the
    cell is valid, the lateral step row."""
    book = small_workbook()
    for name, value, unit in (("lateral cable model", "elastic", None),
                              ("lateral cable EA", 1e9, "N"), ("lateral simulation time", 0, "s"),
                              ("lateral RK4 step", 0, "s"), ("run loads", "no", None),
                              ("chute sizing number of areas", 0, None)):
        set_parameter(book, name, value, unit)
    book["LateralBodies"] = [["id", "mass [kg]", "roll inertia [kg m^2]", "CG below hub [m]"],
                             ["light", 1.0, 1.0, 0.5]]
    out = tmp_path / "out"
    path = save_xlsx(book, tmp_path / "both.xlsx")
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"cell {study_cell(book, 'chute sizing number of areas')}" in err, err
    set_parameter(book, "chute sizing number of areas", 2)
    path = save_xlsx(book, tmp_path / "lateral.xlsx")
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"cell {study_cell(book, 'lateral RK4 step')}" in err and "RK4 steps" in err, err
    assert not out.exists()

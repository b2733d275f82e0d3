"""An error a model raises on a workbook value echoes the value as the user wrote it, at the
right cell, in the user's unit.

The reference is the rule of docs/inputs-and-outputs.md: an error names the file, the sheet,
the cell, the value as the user wrote it with the user's unit, and the rule it broke. The
models work in SI, so an error they raise carries an SI value (76.2 for a hardpoint written
3000 in, 14.999999999999998 for a sideslip written 15 deg); where the io layer puts such an
error at a cell (:mod:`slingloads.io.common.locate`), the message must show that cell's value
as written, never the model's number, a numpy repr or the float noise of a unit round trip;
a quantity derived from several cells (the mass items' range, the parachute's reach, the CG)
is stated in the unit of the cell to change, and its cells are named. Each test breaks one
rule of the small workbook (tests/hostile.py), most with the airframe in inches and the
cables in feet, as a US user writes them; the last tests guard the mechanism itself.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import numpy as np
import pytest
from hostile import set_parameter, small_dynamics_workbook, small_workbook, study_cell

from slingloads.constants import INCH
from slingloads.errors import InputError
from slingloads.io.common.workbook import WorkbookReader
from slingloads.io.study import read_study
from slingloads.runs.study import run_analysis

FILE = "values.xlsx"
#: Float noise of a unit round trip (15 deg -> 14.999999999999998) or an SI conversion
#: (18 ft -> 5.486400000000001): twelve or more digits after the point.
NOISE = re.compile(r"\d\.\d{12,}")
#: Columns of the small workbook's airframe sheets that hold lengths.
LENGTHS = {"MassItems": ("x", "y", "z"), "Stations": ("x",), "Hardpoints": ("x", "y", "z")}


def in_inches(book):
    """``book`` with the lengths of its airframe sheets written in inches (two decimals, as
    a user types them)."""
    for sheet, names in LENGTHS.items():
        header = book[sheet][0]
        for j, text in enumerate(header):
            name = str(text).split(" [")[0]
            if name in names and str(text).endswith("[m]"):
                header[j] = f"{name} [in]"
                for row in book[sheet][1:]:
                    if row[j] is not None:
                        row[j] = round(row[j] / INCH, 2)
    return book


def us_book():
    """The small workbook, airframe in inches."""
    return in_inches(small_workbook())


def us_dynamics_book():
    """The small multibody and campaign workbook, airframe in inches."""
    return in_inches(small_dynamics_workbook())


def read(book):
    return read_study(FILE, reader=WorkbookReader.from_rows(book, file=FILE))


def compute(book, analysis):
    """Read ``book`` and compute ``analysis`` (an InputError propagates)."""
    run_analysis(read(book), analysis)


def check_message(err):
    """What every located message obeys: no numpy repr, no float noise."""
    text = str(err)
    assert "np." not in text and "array(" not in text, text
    assert not NOISE.search(text), text


def error(book, sheet, cell, *fragments, analysis=None, absent=()):
    """Read (and compute ``analysis``) ``book``, expect an InputError at ``sheet``/``cell``
    whose message holds every fragment and none of ``absent``."""
    with pytest.raises(InputError) as info:
        if analysis is None:
            read(book)
        else:
            compute(book, analysis)
    err = info.value
    assert (err.file, err.sheet, err.cell) == (FILE, sheet, cell), str(err)
    for fragment in fragments:
        assert fragment in str(err), str(err)
    for fragment in absent:
        assert fragment not in str(err), str(err)
    check_message(err)
    return err




# ---- the error names the right cell ----------------------------------------------------
def test_negative_parachute_cd_is_named_at_its_cell():
    """Every CD of the ParachuteCD sheet lies in (0, 2]: a negative CD is refused at its own
    cell, with its value, not blamed on the Study's 'parachute wake ratio' (whose value is
    valid)."""
    book = us_book()
    book["ParachuteCD"] = [["alpha [deg]", "CD"], [-30, -1], [0, -1.0], [30, -1]]
    error(book, "ParachuteCD", "B2", "parachute CD must lie in (0, 2]", "value -1.0",
          absent=("wake",))


def test_a_one_row_fin_table_is_named_at_its_cell_in_degrees():
    """A table needs at least two breakpoints: a one-row FinAero is refused at its angle
    cell, with the angle as written in degrees (not -3.14159 rad)."""
    book = us_book()
    book["FinAero"] = book["FinAero"][:2]
    error(book, "FinAero", "A2", "at least two breakpoints", "value -30.0 [deg]",
          absent=("0.52",))


def test_a_tiny_rope_that_makes_the_work_explode_is_blamed_on_the_rope(monkeypatch):
    """A rope of 1e-6 ft swings with a period of a fraction of a millisecond: the time-history
    re-run exceeds its work limit. The error is put at the rope length's cell, with its value
    in feet, and says what made the work explode; it is not the 'lateral history rtol' cell
    with the limit as its value."""
    import slingloads.limits

    monkeypatch.setattr(slingloads.limits, "MAX_ODE_EVALUATIONS", 20_000)
    book = us_book()
    book["LateralRopes"][1][0] = 1e-6
    error(book, "LateralRopes", "A2", "too much work", "period", "value 1e-06 [ft]",
          f"'lateral history rtol' (Study {study_cell(book, 'lateral history rtol')} = 1e-05)",
          analysis="lateral")


def test_no_yaw_trim_is_located_at_the_hub():
    """With the hub off the plane of symmetry the yawing moment about it never changes sign:
    no trim. The error names the hub's cells, its value as written in inches and the moment
    with its unit (before: no sheet, no cell, 'value 410.87522214979725')."""
    book = us_book()
    for r, dy in ((1, 0.0), (2, -0.3), (3, 0.3)):  # hub and mast feet moved 40 in to the side
        book["Hardpoints"][r][3] = round((1.016 + dy) / INCH, 2)
    error(book, "Hardpoints", "D2", "no yaw trim", " N m at beta = 0 deg", "Hardpoints C2:E2",
          "y 40.0 in", "value 40.0 [in]", analysis="chute sizing")


def test_an_envelope_beta_outside_the_fuselage_table_is_named_at_beta():
    """An AeroEnvelope point outside the fuselage table names the angle that is outside:
    the beta cell for a beta beyond the table (inside the fin's), not the alpha cell."""
    book = us_book()
    book["FinAero"] = [["beta [deg]", "CY"], [-40.0, 1.2], [0.0, 0.0], [40.0, -1.2]]
    book["AeroEnvelope"][2][2] = 25.0  # fuselage beta table: -20 to 20 deg
    error(book, "AeroEnvelope", "C3", "beta = 25 deg is outside the fuselage table",
          "value 25.0 [deg]")


# ---- the value is the cell's, in the user's unit -----------------------------------------
def test_hardpoint_outside_the_airframe_in_inches():
    """A hardpoint beyond the mass items' x range: its x as written (3000 in) and the range
    in inches, naming the MassItems cells of its ends (before: 'range [0.8001, 10.75] m:
    value 76.2')."""
    book = us_book()
    book["Hardpoints"][4][2] = 3000
    error(book, "Hardpoints", "C5", "outside the airframe", "x range [39.37, 315] in",
          "MassItems D2 to D5", "value 3000.0 [in]", absent=(" m ", "76.2"))


def test_single_mass_item():
    """One mass item gives the airframe no length: the hub's x is shown as written with the
    item's x in inches (before: 'range [0.8001, 0.8001] m: value 4.2999659999999995')."""
    book = us_book()
    book["MassItems"] = book["MassItems"][:2]  # (its own Ixx, Iyy and Izz: a full tensor)
    error(book, "Hardpoints", "C2", "the mass items all lie at x = 39.37 in",
          "MassItems D2", "value 122.05 [in]")


def test_aerodynamic_point_far_outside():
    """An AeroPoints x far beyond the airframe: its value with its unit and the range in
    that unit."""
    book = us_book()
    book["AeroPoints"] = [["x [ft]", "weight"], [300, 1], [10, 1]]
    error(book, "AeroPoints", "A2", "aerodynamic point 1 lies outside the airframe",
          "x range [3.281, 26.25] ft", "value 300.0 [ft]")


def test_hardpoint_far_to_the_side():
    """A hardpoint farther from the loads reference axis than the airframe is long: its y as
    written, the distance and the length in inches."""
    book = us_book()
    book["Hardpoints"][4][3] = 400.0
    error(book, "Hardpoints", "D5", "from the loads reference axis", "275.6 in",
          "value 400.0 [in]")


def test_hub_below_the_cg_is_named_at_the_hub_z():
    """The hanging attitude needs the hub above the CG: the error is at the hub's z cell,
    its value in inches, the CG's z in inches (before: an SI vector at the 'attitude' row)."""
    book = us_book()
    book["Hardpoints"][1][4] = -100
    for name in ("run lateral", "run chute sizing"):
        set_parameter(book, name, "no")
    error(book, "Hardpoints", "E2", "above the CG", "CG z = 30.34 in",
          "the default 'attitude' = hanging", "value -100.0 [in]", absent=("[m]",))


def test_multibody_cable_too_short_in_feet():
    """A multibody cable the parachute could reach: the cable as written with its unit, the
    reach in feet (before: 'value 40' without [ft]). 40 ft lies within the line's reach,
    from the fin's 21 ft aft of the hub to 48.77 ft (line plus hub-to-attachment distance)."""
    book = us_dynamics_book()
    set_parameter(book, "multibody cable length", 40, "ft")
    error(book, "Study", study_cell(book, "multibody cable length"),
          "the parachute could reach the carrier", "to 48.77 ft", "carrier cable (40 ft)",
          "value 40 [ft]")


def test_campaign_run_cable_too_short_in_feet():
    """A CampaignRuns cable the parachute could reach: at its cell, 40 ft as written (before:
    'value 12.192')."""
    book = us_dynamics_book()
    set_parameter(book, "campaign matrix", "listed rows")
    book["CampaignRuns"][2][4] = 40.0
    error(book, "CampaignRuns", "E3", "the parachute could reach the carrier",
          "carrier cable (40 ft)", "value 40.0 [ft]", absent=("12.19",))


def test_campaign_list_cable_too_short_in_feet():
    """The same for a value of the 'campaign cable lengths' list: the list as written, the
    offending length in feet."""
    book = us_dynamics_book()
    set_parameter(book, "campaign cable lengths", "60, 40", "ft")
    error(book, "Study", study_cell(book, "campaign cable lengths"), "carrier cable (40 ft)",
          "value '60, 40' [ft]")


@pytest.mark.parametrize("row, column, value, cell, fragment", [
    (2, 2, 15.0, "C3", "beta = 15 deg is outside the fin table"),
    (2, 1, 15.0, "B3", "alpha = 15 deg is outside the fuselage table")])
def test_envelope_point_outside_a_table(row, column, value, cell, fragment):
    """An AeroEnvelope angle outside a table: the angle as written with [deg] (before:
    'value 14.999999999999998', 'value 10.0' without a unit)."""
    book = us_book()
    book["FinAero"] = [["beta [deg]", "CY"], [-10.0, 0.3], [0.0, 0.0], [10.0, -0.3]]
    book["AeroEnvelope"][row][column] = value
    error(book, "AeroEnvelope", cell, fragment, f"value {value} [deg]")


def test_wake_table_that_never_reaches_the_target_in_feet():
    """A ChuteWake table short of the target q ratio: at its largest ratio's cell, with the
    distance in the table's feet and the Study cell of the target (before: the header cell
    B1 and '3.048 m')."""
    book = us_book()
    set_parameter(book, "chute sizing wake source", "table")
    book["ChuteWake"] = [["distance [ft]", "q ratio"], [5, 0.80], [10, 0.891]]
    error(book, "ChuteWake", "B3", "never reaches the target dynamic-pressure ratio 0.95",
          "at 10 ft (A3)", "'chute sizing target q ratio'", "value 0.891",
          absent=("3.048",))


def test_unused_lateral_column_shows_the_value_as_written():
    """A LateralMotions column a motion does not use: the value as written with its unit
    (before: 'value np.float64(5.0)')."""
    book = us_book()
    book["LateralMotions"][0].append("delta V [ft/s]")
    book["LateralMotions"][1].append(5)
    book["LateralMotions"][2].append(None)
    error(book, "LateralMotions", "G2", "does not use the column 'delta V'",
          "value 5.0 [ft/s]")


def test_counts_are_not_shown_as_the_value_of_a_header_cell():
    """A rule about a count (two hubs, one ChuteWake row) states the count in the rule; the
    'value' of a message is a cell's value, never a count put at a header cell."""
    book = us_book()
    book["Hardpoints"].append(["hub2", "hub", 122.0, 0.0, 80.0, None])
    error(book, "Hardpoints", "B8", "exactly 1 row(s) of kind 'hub' (it has 2)",
          "value 'hub'")
    book = us_book()
    set_parameter(book, "chute sizing wake source", "table")
    book["ChuteWake"] = [["distance [ft]", "q ratio"], [5, 0.99]]
    err = error(book, "ChuteWake", "A3", "at least two rows (it has 1)")
    assert err.value is None


# ---- generic: many derived errors, each in the user's unit at the right cell -------------
def _edit(sheet, row, column, value):
    def edit(book):
        book[sheet][row][column] = value
    return edit


def _parameter(name, value, unit=None):
    def edit(book):
        set_parameter(book, name, value, unit)
    return edit


def _mass_items_far_apart(book):
    book["MassItems"][4][3] = 3600.0  # 91 m from the nose, within 100 m of the datum


def _tiny_mass(book):
    book["MassItems"][0][2] = "mass [lb]"
    for row in book["MassItems"][1:]:
        row[2] = 1e-3


def _cg_above_hub_mast_vertical(book):
    set_parameter(book, "attitude", "mast vertical")
    book["Hardpoints"][1][4] = 10.0  # the hub 10 in above the datum, the CG about 30 in


def _chute_forward_of_hub(book):
    book["Hardpoints"][4][2] = 100.0  # the hub is at x = 122.05 in


GENERIC = [
    # (label, edit, sheet, cell, fragments)
    ("hardpoint x", _edit("Hardpoints", 4, 2, 3000), "Hardpoints", "C5", ("[in]", " in ")),
    ("hardpoint y", _edit("Hardpoints", 5, 3, -500.0), "Hardpoints", "D6",
     ("[in]", " in ")),
    ("hub z", _edit("Hardpoints", 1, 4, -100), "Hardpoints", "E2", ("[in]", " in,")),
    ("station", _edit("Stations", 4, 1, 1500.0), "Stations", "B5", ("[in]", "] in")),
    ("mass span", _mass_items_far_apart, "MassItems", "D5", ("[in]", " in along x")),
    ("total mass", _tiny_mass, "MassItems", "C2", ("[lb]", " lb in all")),
    ("fin one row", lambda b: b.__setitem__("FinAero", b["FinAero"][:2]), "FinAero", "A2",
     ("[deg]",)),
    ("envelope beta", _edit("AeroEnvelope", 2, 2, 45.0), "AeroEnvelope", "C3", ("[deg]",)),
    ("parachute CD", lambda b: b.__setitem__(
        "ParachuteCD", [["alpha [deg]", "CD"], [-8, 1.0], [0, 2.5], [8, 1.0]]),
     "ParachuteCD", "B3", ("value 2.5",)),
    ("lateral CG above hub", _cg_above_hub_mast_vertical, "Hardpoints", "E2",
     ("value 10.0 [in]", " in above the hub along the mast")),
    ("chute forward of hub", _chute_forward_of_hub, "Hardpoints", "C5",
     ("value 100.0 [in]", "hub is at x = 122.05 in (C2)")),
    ("multibody cable", _parameter("multibody cable length", 12, "m"), "Study", None,
     ("[m]", "to 14.87 m")),
]


@pytest.mark.parametrize("label, edit, sheet, cell, fragments", GENERIC,
                         ids=[g[0] for g in GENERIC])
def test_derived_errors_are_in_the_users_unit_at_the_right_cell(label, edit, sheet, cell,
                                                                fragments):
    """Over many errors a model or a cross-cell check raises, each message is at the cell to
    change, echoes its value as written with the header's unit, states what it is compared
    with in that unit, and shows no numpy repr and no float noise."""
    book = us_dynamics_book() if label.startswith("multibody") else us_book()
    edit(book)
    if cell is None:
        cell = study_cell(book, "multibody cable length")
    error(book, sheet, cell, *fragments)


# ---- the mechanism -----------------------------------------------------------------------
def test_errors_show_numpy_values_as_plain_numbers():
    """An InputError never shows a numpy repr: numpy scalars and arrays (also inside tuples)
    are echoed as Python numbers and lists."""
    err = InputError("rule", np.float64(5.0))
    assert str(err) == "rule: value 5.0" and type(err.value) is float
    assert str(InputError("rule", np.array([1.5, 2.0]))) == "rule: value [1.5, 2.0]"
    assert str(InputError("rule", (np.int64(3), "a"))) == "rule: value (3, 'a')"


def test_a_model_error_located_at_a_parameter_echoes_it_as_written():
    """An error computed later (a work limit named by its field) put at a Study cell echoes
    that parameter's value as written with its unit, not the model's value."""
    book = us_book()
    set_parameter(book, "lateral RK4 step", 0.5, "ms")
    study = read(book)
    from slingloads.limits import check_count

    with pytest.raises(InputError) as info, study.located("lateral"):
        check_count(10**9, 10, "RK4 steps per run", field="step")
    err = info.value
    assert err.cell == study_cell(book, "lateral RK4 step"), str(err)
    assert str(err).endswith("value 0.5 [ms]"), str(err)


IO = Path(__file__).resolve().parents[1] / "slingloads" / "io"


def _cell_locations(path):
    """Places given a cell but no value as written (``Place(file, sheet, cell)``: a third
    positional argument or ``cell=``, and no fourth nor ``written=``), as ``(line, source)``.
    """
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                and node.func.id == "Place"
                and (len(node.args) >= 3 or any(k.arg == "cell" for k in node.keywords))
                and len(node.args) < 4 and not any(k.arg == "written" for k in node.keywords)):
            yield node.lineno, ast.get_source_segment(path.read_text(encoding="utf-8"), node)


#: The readers of the cells' own text (a header's or a unit cell's unit), whose errors echo
#: that text themselves.
CELL_TEXT_READERS = ("workbook.py", "parameters.py", "referenced.py")


@pytest.mark.parametrize("path", sorted(p for p in IO.rglob("*.py")
                                        if p.name not in CELL_TEXT_READERS),
                         ids=lambda p: str(p.relative_to(IO)))
def test_no_reader_puts_a_model_value_at_a_cell(path):
    """A ``Place`` with a cell but no value as written keeps the error's own value: for a
    model's (SI) error, the message would show at the cell a number that is not the cell's.
    The io layer locates a model's error at a cell only through
    :func:`slingloads.io.common.locate.located` given a table, the Study parameters or a
    ``Place`` with the cell's value as written; only the readers of a cell's own text give a
    cell without it."""
    found = list(_cell_locations(path))
    assert not found, f"{path.name}: {found}"

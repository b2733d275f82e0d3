"""Absurd or contradictory inputs are refused at their cell; missing results are not silent.

Each rule has its reference in the test's docstring (the regulation, the physical law or the
documented rule of docs/inputs-and-outputs.md). The inputs start from the small workbook of
tests/hostile.py (read in memory, a few milliseconds); the tests of the command line write
it as an .xlsx file.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hostile import (
    located_error,
    read_book,
    save_xlsx,
    set_parameter,
    small_dynamics_workbook,
    small_workbook,
    study_cell,
)
from openpyxl import load_workbook

from slingloads.cli import EXIT_INCOMPLETE, main
from slingloads.errors import InputError
from slingloads.io.common.excel import Highlight, write_workbook
from slingloads.io.common.excel_cells import INFINITE_TEXT
from slingloads.io.common.report import explain_infinite
from slingloads.io.lateral import report as lateral_report
from slingloads.io.multibody.report import modes_table
from slingloads.io.study import read_study
from slingloads.models.airframe import MassItems
from slingloads.models.wake import TabulatedWake
from slingloads.runs import lateral as lateral_run

FILE = "physical.xlsx"


def read(book):
    return read_book(book, FILE)


def error(book, sheet, cell, *fragments):
    """Read ``book``: an InputError at ``sheet``/``cell`` whose message holds every
    fragment (:func:`hostile.located_error`)."""
    return located_error(book, FILE, sheet, cell, *fragments)


def column(book, sheet, header):
    """The 0-based column of ``header`` on ``sheet``."""
    return list(book[sheet][0]).index(header)


# ---- airspeeds --------------------------------------------------------------------------

@pytest.mark.parametrize(("name", "value", "unit"), [
    ("airspeed EAS", 1900.0, "kt"),
    ("airspeed EAS", 120.0, "m/s"),
    ("chute sizing airspeed IAS", 250.0, "kt"),
    ("lateral airspeed EAS", 300.0, "kt"),
])
def test_airspeeds_above_200_kt_are_refused(name, value, unit):
    """Every analysis caps its airspeed at 200 kt (docs/inputs-and-outputs.md section 4:
    above the never-exceed speed of the heavy-lift helicopters that carry slung loads; 1900
    kt is Mach 2.9 at sea level), as the multibody model and the campaign already did; the
    bound is shown in the user's unit."""
    book = small_workbook()
    set_parameter(book, name, value, unit)
    shown = "200 kt" if unit == "kt" else "102.889 m/s"
    error(book, "Study", study_cell(book, name), name, f"must be <= {shown}", repr(value))


def test_airspeed_of_200_kt_is_accepted():
    """200 kt itself lies inside the cap."""
    book = small_workbook()
    set_parameter(book, "airspeed EAS", 200.0, "kt")
    assert read(book).inputs.loads.flight.eas == pytest.approx(200.0 * 0.514444, rel=1e-5)


# ---- hook load factor -------------------------------------------------------------------

@pytest.mark.parametrize("nz", [1e-320, 0.5, 0.999])
def test_hook_load_factor_below_one_is_refused(nz):
    """CS 29.865(a): the hook's limit load is Nz x the external load's weight; in steady
    flight the hook already carries the whole weight, so no limit hook load factor is below
    1 (the Study sheet refuses it at its cell)."""
    book = small_workbook()
    set_parameter(book, "hook load factor Nz", nz)
    error(book, "Study", study_cell(book, "hook load factor Nz"), "Nz", "must be >= 1")


@pytest.mark.parametrize(("nz", "warned"), [(1.0, True), (2.0, True), (2.5, False),
                                            (3.5, False)])
def test_hook_load_factor_below_2_5_is_flagged(nz, warned):
    """CS 29.865(a): 2.5, or a lower factor approved under CS 29.337 to 29.341 (whose
    smallest positive limit manoeuvring factor is +2.0): a factor in [1, 2.5) is read, with a
    warning naming its cell."""
    book = small_workbook()
    set_parameter(book, "hook load factor Nz", nz)
    study = read(book)
    assert study.inputs.loads.hook.nz == nz
    found = [w for w in study.source.warnings if "hook load factor Nz" in w]
    assert bool(found) is warned, study.source.warnings
    if warned:
        assert f"Study {study_cell(book, 'hook load factor Nz')}" in found[0]
        assert "CS 29.865(a)" in found[0] and "CS 29.337 to 29.341" in found[0]
        assert len(found) == 1  # read by the loads and the lateral study, flagged once


# ---- mass items: the inertia tensor of a body -------------------------------------------

def test_own_inertia_breaking_the_triangle_inequality_is_refused_at_its_cell():
    """Rigid-body mechanics: about the principal axes through a body's CG, I1 + I2 - I3 =
    2 integral(x3^2 dm) >= 0, so no moment exceeds the sum of the other two. Ixx = 1000 with
    Iyy 5 and Izz 10 (as the hostile sweep's 1000 against 67 and 73) is refused at that Ixx
    cell."""
    book = small_workbook()
    book["MassItems"][3][column(book, "MassItems", "Ixx [kg m^2]")] = 1000.0
    err = error(book, "MassItems", "H4", "not physical", "sum of the other two", "1000")
    assert "[kg m^2]" in str(err)


def test_own_inertia_of_a_yaw_moment_alone_is_refused_at_izz():
    """The same law: an item with only a yaw moment (Izz 20, Ixx = Iyy = 0) is no body (mass
    away from the z axis gives inertia about x or y); the Izz cell is named."""
    book = small_workbook()
    for name in ("Ixx [kg m^2]", "Iyy [kg m^2]"):
        book["MassItems"][1][column(book, "MassItems", name)] = 0.0
    error(book, "MassItems", "G2", "not physical", "Izz = Ixx + Iyy")


@pytest.mark.parametrize("moments", [(10.0, 10.0, 20.0), (0.0, 5.0, 5.0), (3.0, 4.0, 5.0),
                                     (10.0, 10.0, 20.19)])
def test_physical_own_inertias_are_accepted(moments):
    """Bodies meet the inequality, a thin plate (Izz = Ixx + Iyy) and a thin rod (one moment
    0, the others equal) with equality; 1 % of the largest moment is allowed for rounding."""
    items = MassItems(("a",), [10.0], [[0.0, 0.0, 0.0]], [np.diag(moments)])
    assert np.allclose(np.diagonal(items.inertia[0]), moments)


def test_own_inertia_breaking_the_inequality_through_products_is_refused():
    """The inequality holds for the principal moments: a tensor whose diagonal meets it but
    whose principal moments do not (diag(4, 4, 1) with Ixy = -3: principal 7, 1, 1) is
    refused, and the error names the item's inertia (no single diagonal term is wrong)."""
    tensor = np.array([[4.0, -3.0, 0.0], [-3.0, 4.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(InputError, match="not physical") as info:
        MassItems(("a", "b"), [10.0, 10.0], [[0.0, 0, 0], [1.0, 0, 0]],
                  [np.eye(3), tensor])
    assert (info.value.field, info.value.index) == ("inertia", 1)


# ---- aerodynamic coefficients -----------------------------------------------------------

@pytest.mark.parametrize(("sheet", "value"), [("FinAero", 9.9), ("FinAero", -3.5),
                                              ("HTailAero", 5.0)])
def test_surface_coefficients_are_bounded(sheet, value):
    """A lifting surface's force coefficient on its own area: a flat plate square to the flow
    reaches about 1.2 (2.0 in two dimensions), an unflapped aerofoil stalls below 2; the
    FinAero CY and the HTailAero CN are bounded to [-3, 3] alike (docs/inputs-and-outputs.md
    section 4)."""
    if sheet == "FinAero":
        book = small_workbook()
        book["FinAero"][2][1] = value
        error(book, "FinAero", "B3", "CY", "in [-3, 3]", repr(value))
    else:
        book = small_dynamics_workbook()
        set_parameter(book, "multibody tail", "full tail")
        book["HTailAero"][2][1] = value
        error(book, "HTailAero", "B3", "CN", "in [-3, 3]", repr(value))


def test_fuselage_force_area_is_bounded():
    """CD = 1e5 on 3 m^2 is a drag area of 3e5 m^2: no airframe 7 m long makes that much.
    The bound does not depend on the reference area chosen: a flat plate as long as the
    airframe and as wide, square to the flow, at the 2-D plate's force coefficient 2."""
    book = small_workbook()
    book["FuselageAero"][7][column(book, "FuselageAero", "CD")] = 1e5
    err = error(book, "FuselageAero", "C8", "force area", "flat plate", "100000")
    assert "3e+05 m^2" in str(err)


def test_fuselage_moment_is_bounded():
    """A moment coefficient x area x length is bounded by that plate's force times the
    farthest airframe point from the moment reference."""
    book = small_workbook()
    book["FuselageAero"][4][column(book, "FuselageAero", "Cn")] = 500.0
    error(book, "FuselageAero", "H5", "|Cn|", "m^3", "farthest airframe point")


def test_fuselage_coefficients_on_one_square_foot_are_accepted():
    """D/q tables (coefficients on 1 ft^2 and 1 ft) are physical: the same forces and moments
    as the table on 3 m^2 and 10 m, coefficients 32 and 1060 times larger, are read alike."""
    book = small_workbook()
    set_parameter(book, "fuselage reference area", 1.0, "ft^2")
    set_parameter(book, "fuselage reference length", 1.0, "ft")
    area, length = 3.0 / 0.3048**2, 10.0 / 0.3048
    for row in book["FuselageAero"][1:]:
        row[2:5] = [v * area for v in row[2:5]]
        row[5:8] = [v * area * length for v in row[5:8]]
    reference = read(small_workbook()).inputs.loads.fuselage.loads([0.1], [0.2], 1000.0)
    loads = read(book).inputs.loads.fuselage.loads([0.1], [0.2], 1000.0)
    for got, want in zip(loads, reference, strict=True):
        np.testing.assert_allclose(got, want, rtol=1e-9)


def test_negative_drag_in_wind_axes_is_refused():
    """In wind axes CD is the drag along the airflow: a body without propulsion takes energy
    from the flow, so CD >= 0."""
    book = small_workbook()
    book["FuselageAero"][3][column(book, "FuselageAero", "CD")] = -0.1
    error(book, "FuselageAero", "C4", "CD must be >= 0 in wind axes")


# ---- wake and parachute -----------------------------------------------------------------

def test_wake_q_ratio_falling_downstream_is_refused():
    """A wake recovers downstream: its centreline velocity defect decays (as x^(-2/3) far
    behind a 3-D body, Pope, Turbulent Flows, 5.4), so the ChuteWake q ratio does not
    decrease with distance; the first falling ratio is refused at its cell."""
    book = small_workbook()
    set_parameter(book, "chute sizing wake source", "table")
    book["ChuteWake"] = [["distance [m]", "q ratio"], [1.0, 0.98], [5.0, 0.97], [10.0, 0.99]]
    error(book, "ChuteWake", "B3", "must not decrease downstream", "0.98 at B2", "0.97")
    with pytest.raises(InputError, match="must not decrease downstream"):
        TabulatedWake([1.0, 5.0, 10.0], [0.98, 0.97, 0.99])


def test_wake_q_ratio_that_holds_is_accepted():
    """A ratio that stays the same (the wake recovered) is allowed."""
    book = small_workbook()
    set_parameter(book, "chute sizing wake source", "table")
    set_parameter(book, "chute sizing target q ratio", 0.9)
    book["ChuteWake"] = [["distance [m]", "q ratio"], [1.0, 0.5], [5.0, 0.95], [10.0, 0.95]]
    assert read(book).inputs.chute_sizing.wake.line_length(0.9) == pytest.approx(
        1.0 + 4.0 * 0.4 / 0.45)


@pytest.mark.parametrize(("rows", "ok"), [
    ([(-8.0, 1.0), (8.0, 1.0)], True),          # the default table, written out
    ([(-30.0, 0.9), (10.0, 1.0), (30.0, 0.9)], True),
    ([(0.0, 1.0), (10.0, 0.9)], True),
    ([(2.0, 1.0), (10.0, 0.9)], False),
])
def test_parachute_table_covers_alpha_zero(rows, ok):
    """The template's rule: the ParachuteCD alpha column covers 0 (from a negative to a
    positive alpha, or with a row at 0), where the canopy trails in steady flight; the paper's
    table (CD within +-8 deg) has no row at 0 and is valid."""
    book = small_workbook()
    book["ParachuteCD"] = [["alpha [deg]", "CD"], *map(list, rows)]
    if ok:
        assert read(book).inputs.loads.parachute is not None
    else:
        error(book, "ParachuteCD", "A2", "must cover alpha = 0 deg")


# ---- lateral bodies ---------------------------------------------------------------------

def _with_body(mass, inertia, cg=1.1):
    book = small_workbook()
    book["LateralBodies"] = [["id", "mass [kg]", "roll inertia [kg m^2]", "CG below hub [m]"],
                             ["ODD", mass, inertia, cg]]
    return book


def test_lateral_body_mass_below_1_kg_is_refused():
    """As the MassItems' total: below 1 kg no aircraft (the hostile sweep's 1e-9 kg)."""
    error(_with_body(1e-9, 1700.0), "LateralBodies", "B2", "mass must be >= 1 kg")


@pytest.mark.parametrize("inertia", [1e-9, 20.0])
def test_lateral_body_radius_of_gyration_below_0_1_m_is_refused(inertia):
    """A roll radius of gyration sqrt(I/m) under 0.1 m is a solid cylinder less than 0.28 m
    across (k = R / sqrt(2)); helicopters have about 1 m (BO-105C 0.93 m, NASA CR-3144;
    UH-60A 1.01 m, NASA TM 85890). 3000 kg with 20 kg m^2 gives 0.08 m: refused."""
    error(_with_body(3000.0, inertia, 0.0), "LateralBodies", "C2", "radius of gyration",
          "0.1 m")


def test_lateral_body_of_a_light_twin_is_accepted():
    """2.9 t with 1,700 kg m^2 (k = 0.77 m) is read."""
    body = read(_with_body(2900.0, 1700.0)).inputs.lateral.bodies[0]
    assert body.radius_of_gyration == pytest.approx(np.sqrt(1700.0 / 2900.0))


# ---- hidden sheets, rows and columns ----------------------------------------------------

def _saved(tmp_path, edit):
    """The small workbook as an .xlsx file, edited with openpyxl (``edit(workbook)``)."""
    path = save_xlsx(small_workbook(), tmp_path / "hidden.xlsx")
    wb = load_workbook(path)
    edit(wb)
    wb.save(path)
    return path


def test_values_on_hidden_rows_and_columns_are_flagged(tmp_path):
    """docs/inputs-and-outputs.md section 5: a value read from a hidden row or column is used
    like any other but a reviewer of the workbook does not see it: a warning names the sheet
    and the rows or columns (consecutive rows as a range)."""
    def edit(wb):
        for r in (4, 5, 6, 8):
            wb["FinAero"].row_dimensions[r].hidden = True
        wb["MassItems"].column_dimensions["G"].hidden = True
        wb["Study"].row_dimensions[30].hidden = True  # below the last parameter: no value

    warnings = read_study(_saved(tmp_path, edit)).source.warnings
    assert "sheet 'FinAero': values were read from hidden rows 4-6, 8: a reviewer of the " \
           "workbook does not see them" in warnings, warnings
    assert any(w.startswith("sheet 'MassItems': values were read from hidden column G")
               for w in warnings), warnings
    assert not any("'Study'" in w for w in warnings), warnings


def test_hidden_sheet_is_flagged(tmp_path):
    """A hidden (or very hidden) sheet that is read is named."""
    def edit(wb):
        wb["Stations"].sheet_state = "hidden"
        wb["Hardpoints"].sheet_state = "veryHidden"

    warnings = read_study(_saved(tmp_path, edit)).source.warnings
    assert any(w.startswith("sheet 'Stations' is hidden in the workbook") for w in warnings)
    assert any(w.startswith("sheet 'Hardpoints' is very hidden") for w in warnings)


def test_nothing_hidden_gives_no_warning(tmp_path):
    """The small workbook as saved: no warning (a hidden row without a value read is not
    flagged either)."""
    def edit(wb):
        wb["Stations"].row_dimensions[40].hidden = True

    assert read_study(_saved(tmp_path, edit)).source.warnings == []


# ---- a requested analysis without its results ------------------------------------------

def test_multibody_without_trim_exits_3_and_says_so(tmp_path, capsys):
    """docs/inputs-and-outputs.md section 1: a run whose reports are written but whose
    multibody model found no trim (here the horizontal-tail table covers 20 to 40 deg only:
    the equilibrium lies outside it) exits with code 3, and stderr names each missing result;
    the report is published (it says why)."""
    book = small_dynamics_workbook()
    set_parameter(book, "run campaign", "no")
    set_parameter(book, "multibody tail", "full tail")
    book["HTailAero"] = [["alpha [deg]", "CN"], [20.0, 1.0], [40.0, 1.1]]
    path = save_xlsx(book, tmp_path / "notrim.xlsx")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == EXIT_INCOMPLETE == 3
    err = capsys.readouterr().err
    assert "slingloads: incomplete: multibody: no trim at 80 kt EAS (the only equilibrium " \
           "found lies outside the horizontal-tail table)" in err, err
    assert "2 of 2 runs not flown for want of a trim: 'free', 'gust'" in err, err
    assert "exit code 3" in err
    assert (out / "notrim-multibody.xlsx").exists()
    assert not (out / "notrim-multibody-eigenvalues.png").exists()


# ---- no inf or nan text in a report -----------------------------------------------------

def test_explain_infinite_writes_what_an_infinity_means():
    """Excel has no infinity: a report writes +inf and -inf of the columns named as the
    texts given; finite numbers, NaN and other columns are kept."""
    frame = pd.DataFrame({"a [-]": [1.0, np.inf, -np.inf, np.nan], "b [-]": [np.inf] * 4})
    out = explain_infinite(frame, ["a [-]", "missing"], "unbounded", "increase from 0")
    assert out["a [-]"].iloc[:3].tolist() == [1.0, "unbounded", "increase from 0"]
    assert np.isnan(out["a [-]"].iloc[3])
    assert np.isinf(out["b [-]"]).all()
    assert explain_infinite(frame, ["a [-]"], "x")["a [-]"].iloc[2] == "-x"


def test_writer_never_writes_the_text_inf(tmp_path):
    """An infinite number a report did not explain is the word 'infinite', never the bare
    'inf' of a program; an explained one keeps its text, in a column still laid out as
    numbers (right-aligned, as wide as its numbers and texts, not as the repr of a float)."""
    frame = pd.DataFrame({"peak [g]": [0.1 + 0.2, np.inf, -np.inf]})
    explained = explain_infinite(frame, ["peak [g]"], "unbounded")
    write_workbook(tmp_path / "t.xlsx", {"Raw": frame, "Explained": explained})
    wb = load_workbook(tmp_path / "t.xlsx")
    assert [c.value for c in wb["Raw"]["A"]][1:] == [pytest.approx(0.3), INFINITE_TEXT[True],
                                                      INFINITE_TEXT[False]]
    assert [c.value for c in wb["Explained"]["A"]][1:] == [pytest.approx(0.3), "unbounded",
                                                           "-unbounded"]
    ws = wb["Explained"]
    assert {ws[f"A{r}"].alignment.horizontal for r in (1, 2, 3, 4)} == {"right"}
    assert ws.column_dimensions["A"].width < 16


def test_explained_ratio_is_filled_red(tmp_path):
    """A ratio written as a text (over a previous envelope of 0) is filled red like a ratio
    above the threshold: the conditional format tests ISTEXT besides the number."""
    frame = explain_infinite(pd.DataFrame({"ratio [-]": [0.5, 2.0, np.inf]}), ["ratio [-]"],
                             "unbounded (previous 0)")
    write_workbook(tmp_path / "r.xlsx", {"R": frame},
                   highlight={"R": Highlight(["ratio [-]"], 1.0)})
    rules = [r for cf in load_workbook(tmp_path / "r.xlsx")["R"].conditional_formatting
             for r in cf.rules]
    assert any("ISTEXT(A2)" in f and "A2>1.0" in f for r in rules for f in r.formula)


def test_velocity_step_peak_acceleration_is_written_unbounded():
    """A velocity step's hook acceleration is an impulse (the speed jumps at t = 0): the
    lateral Runs table writes its peak S'' as 'unbounded' (the sheet's note says why),
    every other motion's as a number."""
    book = small_workbook()
    set_parameter(book, "run loads", "no")
    set_parameter(book, "run chute sizing", "no")
    book["LateralMotions"][0].append("delta V [m/s]")
    for row in book["LateralMotions"][1:]:
        row.append(None)
    book["LateralMotions"].append(["jump", "velocity step", None, None, None, None, 1.0])
    study = read(book)
    result = lateral_run.run(study)
    runs = lateral_report.runs_table(result)
    for name in ("peak S'' [m/s^2]", "peak S'' [g]"):
        jump = runs[runs["motion id"] == "jump"][name]
        others = runs[runs["motion id"] != "jump"][name]
        assert (jump == lateral_report.UNBOUNDED_STEP).all()
        assert np.isfinite(others.to_numpy(float)).all()
    note = lateral_report._sheets(result, "SI")["Runs"][0].note
    assert "unbounded" in note and "impulse" in note


def test_modes_without_period_or_doubling_time_say_why():
    """An aperiodic mode has no period, a neutral one (real part 0) no time to half or
    double: the Modes sheet says 'none (aperiodic)' and 'none (neutral)'."""
    class Linear:
        def modes_frame(self):
            return pd.DataFrame({"mode": ["a", "b"], "period [s]": [np.inf, 2.0],
                                 "time to half or double [s]": [3.0, np.inf]})

    table = modes_table(Linear())
    assert table["period [s]"].tolist() == ["none (aperiodic)", 2.0]
    assert table["time to half or double [s]"].tolist() == [3.0, "none (neutral)"]

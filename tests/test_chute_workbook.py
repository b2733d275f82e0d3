"""Parachute sizing driven from the input workbook: round trip, report read-back, bad input.

References: the neutral area read through the workbook equals the one computed with the
Python API from the same data (the generic HC1 tables of ``slingloads/data`` placed at the
workbook's hardpoints, and a yaw inertia summed by hand about the hub axis, parallel-axis
theorem); the report's numbers read back equal those of the API run; each bad-input test
breaks one rule written in ``slingloads.io.chute.schema`` and checks exit code 2, the sheet
and cell in the message, and that nothing is written.
"""

from __future__ import annotations

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE, light_example, refused_copy, study_row
from once import made_once

from slingloads.analyses.chute_sizing import neutral_area
from slingloads.cli import main
from slingloads.constants import FOOT, KNOT
from slingloads.io.chute.report import PLOTS
from slingloads.io.study import read_study
from slingloads.models.aerodynamics import Fin, FuselageAero
from slingloads.models.flight import FlightCondition
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_reference
from slingloads.models.yaw_dynamics import YawModel
from slingloads.runs.chute_sizing import run as compute

STEM = EXAMPLE.stem


@pytest.fixture(scope="module")
def study():
    return read_study(EXAMPLE, only=["chute sizing"])


@pytest.fixture(scope="module")
def result(study):
    return compute(study)


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    """The folder of ``slingloads chute`` on the example, made once for the session's
    workers (:func:`once.made_once`): to be read, not changed."""
    def make(out):
        assert main(["chute", str(EXAMPLE), "--out", str(out), "--quiet"]) == 0

    return made_once(tmp_path_factory, "example-chute-command", make)


def test_neutral_area_workbook_equals_api(study, result):
    """Same data, two paths: the workbook reader and the API (HC1 tables, hand inertia)."""
    frame, points = study.airframe, study.source.points
    ref = sample_reference("HC1")
    hc1 = sample_fuselage("HC1")
    fuselage = FuselageAero(hc1.table, ref.fuselage_area, ref.fuselage_length,
                            points["aero_reference"])
    fin = Fin(sample_fin("HC1").table, ref.fin_area, points["fin_cp"], ref.fin_efficiency)
    items, hub = frame.mass_items, frame.hardpoints.hub
    # hanging, the CG lies under the hub: the yaw axis is the line through both, k; item by
    # item, own inertia about k plus m times the squared distance from the axis
    cg = items.mass @ items.position / items.mass.sum()
    k = (hub - cg) / np.linalg.norm(hub - cg)
    d = items.position - cg
    inertia = float(np.sum(np.einsum("i,nij,j->n", k, items.inertia, k)
                           + items.mass * (np.sum(d * d, axis=1) - (d @ k) ** 2)))
    # `slingloads chute` has no towed trim (no multibody, no loads): the suspension axis is
    # the hub-CG line k, the body hanging at rest (no weight moment about the vertical)
    model = YawModel(fuselage, fin, frame.hardpoints, inertia, FlightCondition(80 * KNOT),
                     Parachute(1.0), axis=k)
    half = np.radians(15.0)                        # the example's linearisation range
    api = neutral_area(model, (-half, half))
    assert result.inputs.fit_range == pytest.approx((-half, half), rel=1e-12)
    assert result.inputs.model.yaw_inertia == pytest.approx(inertia, rel=1e-12)
    assert result.static.area == pytest.approx(api.area, rel=1e-9)
    assert result.static.area > 0
    # the example's Study parachute area is 1.4 x the neutral area on the fitted slopes of the
    # paper's balance of Mz (airframe z at alpha 0), rounded to 0.1 m^2
    paper = YawModel(fuselage, fin, frame.hardpoints, inertia, FlightCondition(80 * KNOT),
                     Parachute(1.0))
    fit = neutral_area(paper, (-half, half), basis="fit")
    assert result.inputs.study_area == pytest.approx(round(1.4 * fit.area, 1), abs=1e-12)
    # its line length is the wake line rounded up to 0.1 m, and the 60 ft cable passes
    assert 0 <= result.inputs.study_line - result.line.line_length < 0.1 + 1e-12
    assert result.line.cable.cable_length == pytest.approx(60 * FOOT)
    assert result.line.cable.ok


def test_report_reads_back(run_dir, result):
    """`slingloads chute` writes the workbook, CSV and PNGs; the numbers read back."""
    for tag in PLOTS:
        assert (run_dir / f"{STEM}-chute-{tag}.png").stat().st_size > 1000
    summary = pd.read_excel(run_dir / f"{STEM}-chute.xlsx", sheet_name="Summary", header=None)
    row = summary[summary[0] == "neutral static area"].iloc[0]
    assert float(row[1]) == pytest.approx(result.static.area, rel=1e-12)
    assert row[2] == "m^2"
    rec = summary[summary[0] == "recommended area"].iloc[0]
    assert float(rec[1]) == pytest.approx(result.sweep.smallest_stable_area, rel=1e-12)
    axis = summary[summary[0] == "yaw axis"].iloc[0]
    assert axis[1] == "'suspension'" and "hub-CG line" in axis[3]
    line = summary[summary[0] == "parachute line length (from the wake)"].iloc[0]
    assert float(line[1]) == pytest.approx(result.line.line_length, rel=1e-12)
    assert summary[summary[0] == "carrier cable check"].iloc[0][1] == "ok"
    # every run: a table sheet of its own (header in row 1, never repeated in the data)
    runs = pd.read_excel(run_dir / f"{STEM}-chute.xlsx", sheet_name="Sweep-EveryRun")
    api = result.sweep.to_frame()
    assert len(runs) == len(api) == 55                # 11 areas x 5 gust shapes
    np.testing.assert_allclose(runs["peak beta [deg]"].astype(float), api["peak beta [deg]"],
                               rtol=1e-12)
    assert list(runs["verdict"]) == list(api["verdict"])
    csv = pd.read_csv(run_dir / f"{STEM}-chute-histories.csv")
    assert list(csv.columns) == ["run", "area_m2", "gust", "time_s", "beta_deg", "psi_deg"]
    j = result.history_runs()[0]
    rows = csv[csv["run"] == j + 1]
    assert rows["area_m2"].iloc[0] == pytest.approx(result.sweep.runs.areas[j], rel=1e-15)
    np.testing.assert_allclose(rows["beta_deg"], np.degrees(result.sweep.runs.histories.beta[j]),
                               rtol=1e-12, atol=1e-12)


def test_us_report(tmp_path, result):
    """--units US: areas in ft^2 (1 ft = 0.3048 m exactly), lengths in in."""
    assert main(["chute", str(EXAMPLE), "--out", str(tmp_path), "--units", "US",
                 "--quiet"]) == 0
    summary = pd.read_excel(tmp_path / f"{STEM}-chute.xlsx", sheet_name="Summary", header=None)
    row = summary[summary[0] == "neutral static area"].iloc[0]
    assert row[2] == "ft^2"
    assert float(row[1]) == pytest.approx(result.static.area / FOOT**2, rel=1e-12)
    line = summary[summary[0] == "parachute line length (from the wake)"].iloc[0]
    assert float(line[1]) == pytest.approx(result.line.line_length / 0.0254, rel=1e-12)


# ---------------------------------------------------------------------------- bad input
def _bad(tmp_path, capsys, edits, sheet, cell, *fragments):
    return refused_copy(tmp_path, capsys, "chute", edits, sheet, cell, *fragments)


@pytest.mark.parametrize("speed", [0, -80])
def test_bad_airspeed(tmp_path, capsys, speed):
    """Rule: 'chute sizing airspeed IAS' > 0; the message echoes the value with the unit the
    user wrote beside it (the example gives the airspeed in kt)."""
    name = "chute sizing airspeed IAS"
    _bad(tmp_path, capsys, {("Study", name): speed}, "Study", name, "must be > 0",
         f"value {float(speed)} [kt]")


def test_zero_fin_area(tmp_path, capsys):
    """Rule: 'fin area' > 0 (the sizing reads FinAero on its own, without the loads)."""
    _bad(tmp_path, capsys, {("Study", "fin area"): 0}, "Study", "fin area", "'fin area'")


def test_negative_area_factor(tmp_path, capsys):
    """Rule: 'chute sizing area factor min' > 0."""
    name = "chute sizing area factor min"
    _bad(tmp_path, capsys, {("Study", name): -1}, "Study", name, "must be > 0")


def test_zero_yaw_inertia_parameter(tmp_path, capsys):
    """Rule: with the source 'parameter', 'chute sizing yaw inertia' > 0."""
    name = "chute sizing yaw inertia"
    _bad(tmp_path, capsys, {("Study", "chute sizing yaw inertia source"): "parameter",
                            ("Study", name): 0}, "Study", name, "must be > 0")


def test_negative_yaw_inertia(tmp_path, capsys):
    """Rule: a yaw inertia is never negative."""
    name = "chute sizing yaw inertia"
    _bad(tmp_path, capsys, {("Study", name): -5000}, "Study", name, "> 0", "-5000")


def test_non_monotonic_wake_table(tmp_path, capsys):
    """Rule: ChuteWake distances strictly increasing (A4 repeats A3)."""
    book = openpyxl.load_workbook(light_example())
    repeat = book["ChuteWake"]["A3"].value
    _bad(tmp_path, capsys, {("ChuteWake", "A4"): repeat}, "ChuteWake", "A4",
         "strictly increasing")


def test_unknown_gust_shape(tmp_path, capsys):
    """Rule: gust shapes among step, finite, 1-cosine, continuous, harmonic, turbulence."""
    name = "chute sizing gust shapes"
    _bad(tmp_path, capsys, {("Study", name): "step, gusty"}, "Study", name,
         "unknown gust shape", "'gusty'", "1-cosine", "harmonic", "turbulence")


@pytest.mark.parametrize("name, value, fragments", [
    ("chute sizing gust rise time", -2, ("must be >= 0", "-2")),
    ("chute sizing harmonic period", 0, ("must be > 0",)),
    ("chute sizing turbulence altitude", 2000, ("10 to 1000 ft", "above ground")),
    ("chute sizing turbulence severity", "extreme", ("valid values", "'moderate'")),
    ("chute sizing turbulence duration", 100, ("before the end of the simulation",)),
    ("chute sizing sideslip limit", 0, ("must be > 0",)),
])
def test_bad_gust_and_limit_rows(tmp_path, capsys, name, value, fragments):
    """Rules of the gust rows: a rise time is >= 0, a period > 0; the Dryden turbulence's
    height lies in the MIL-F-8785C low-altitude range (10 to 1000 ft), its severity is light,
    moderate or severe, and it ends before the run does (onset 30 s + 100 s > 120 s); the
    sideslip limit is > 0. Each error names the row's cell."""
    _bad(tmp_path, capsys, {("Study", name): value}, "Study", name, *fragments)


def test_gust_shapes_in_the_report(run_dir, result):
    """The Sweep sheet lists every gust shape read; each gust angle is atan(peak / V_TAS)
    (80 kt at sea level: V = 41.156 m/s; the 30 ft/s gust: atan(9.144/41.156) = 12.53 deg),
    and the turbulence's intensity is MIL-F-8785C's at 300 ft, moderate (2.18 m/s)."""
    frame = result.sweep.gust_frame()
    assert list(frame["shape"]) == ["step", "finite", "1-cosine", "continuous", "turbulence"]
    assert frame["gust angle [deg]"][0] == pytest.approx(12.53, abs=0.01)
    tas = result.inputs.model.condition.tas
    np.testing.assert_allclose(np.tan(np.radians(frame["gust angle [deg]"])),
                               frame["peak gust [m/s]"] / tas, rtol=1e-12)
    turbulence = result.inputs.gusts[-1]
    assert turbulence.intensity == pytest.approx(2.1755, rel=1e-4)
    sheet = pd.read_excel(run_dir / f"{STEM}-chute.xlsx", sheet_name="Sweep", header=None)
    assert "Gust shapes" in set(sheet[0].astype(str))
    assert "turbulence" in set(sheet[0].astype(str))


def test_gust_after_the_end(tmp_path, capsys):
    """Rule: the gust starts before the end of the simulation."""
    name = "chute sizing gust onset"
    _bad(tmp_path, capsys, {("Study", name): 500}, "Study", name, "before the end")


def test_gust_outside_the_tables(tmp_path, capsys):
    """Rule: no extrapolation: the gust's sideslip atan(v_gust / V) must lie inside the
    aerodynamic tables. The fin table is cut to +-30 deg (FinAero rows beyond removed, the
    loads envelope's +-15 deg still inside) and the gust raised to 100 ft/s: at 80 kt
    (41.16 m/s TAS at sea level) atan(30.48 / 41.16) = 36.5 deg > 30 deg."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book["FinAero"]
    keep = [r for r in ws.iter_rows(min_row=2, values_only=True)
            if r[0] is not None and abs(r[0]) <= 30]
    ws.delete_rows(2, ws.max_row)
    for r in keep:
        ws.append(r)
    name = "chute sizing gust amplitude"
    row = study_row(book, name)
    ws_study = book["Study"]
    ws_study[f"B{row}"] = 100
    ws_study[f"C{row}"] = "ft/s"
    path = tmp_path / "narrow.xlsx"
    book.save(path)
    out = tmp_path / "out"
    assert main(["chute", str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"cell B{row}" in err and "outside the aerodynamic tables' range" in err, err
    assert "36.5" in err
    assert not out.exists()


def test_very_stiff_adaptive_runs_are_refused_at_the_tolerance(tmp_path, capsys):
    """Rule: an adaptive run tries at most 200,000 steps (limits of slingloads). A yaw
    inertia of 0.01 kg m^2 (source 'parameter') instead of the example's 10,833 kg m^2 makes the
    yaw mode's fast root c / I about 2e5 1/s, so the explicit Dormand-Prince pair would need
    steps below 3.3 / |lambda| (about 1e-5 s), millions of them a run: the runs stop at the
    limit and the error points at the tolerance row, the setting the user may change (with
    the advice to check the inertia), instead of computing for minutes."""
    name = "chute sizing yaw inertia"
    _bad(tmp_path, capsys, {("Study", "chute sizing yaw inertia source"): "parameter",
                            ("Study", name): 0.01}, "Study", "chute sizing reference rtol",
         "too much work", "adaptive steps", "200,000 a run", "yaw inertia")


def test_us_plots_convert_lengths_and_moments(result):
    """--units US plots in the units of the US tables: wake distances in inches (1 in =
    0.0254 m) and yawing moments in lbf in (1 lbf in = 4.4482216152605 x 0.0254 N m),
    converted from the SI results (they were in ft and 1000 lbf ft beside tables in in and
    lbf in)."""
    from slingloads.io.chute.plots import plot_static_moments, plot_wake

    wake = plot_wake(result.line, "US").axes[0]
    assert "[in]" in wake.get_xlabel()
    np.testing.assert_allclose(wake.lines[0].get_xdata(),
                               np.asarray(result.line.distance) / 0.0254, rtol=1e-12)
    moments = plot_static_moments(result.static, "US").axes[0]
    assert "[lbf in]" in moments.get_ylabel()
    first = next(iter(result.static.moments.values()))
    np.testing.assert_allclose(moments.lines[0].get_ydata(),
                               first / (4.4482216152605 * 0.0254), rtol=1e-12)


def test_rk4_grid_rule_located_at_the_output_interval(tmp_path, capsys):
    """Rule: with the fixed-step 'rk4' integrator the stored samples fall on its steps, so the
    output interval must be a whole multiple of the time step: 0.1 s / 0.03 s = 3.33 is not."""
    _bad(tmp_path, capsys, {("Study", "chute sizing integrator"): "rk4",
                            ("Study", "chute sizing time step"): 0.03},
         "Study", "chute sizing output interval", "whole multiple", "0.03 s")


def test_simulation_time_must_hold_whole_output_intervals(tmp_path, capsys):
    """Rule: the stored samples land on the simulation time: 120.05 s is not a whole number
    of 0.1 s intervals (1,200.5), whatever the integrator."""
    _bad(tmp_path, capsys, {("Study", "chute sizing simulation time"): 120.05},
         "Study", "chute sizing simulation time", "output interval", "0.1 s")


def test_adaptive_integrator_ignores_the_time_step(tmp_path, result):
    """'dopri5' chooses its own steps (docs: the time step binds 'rk4' only): a time step of
    0.03 s, which divides neither 120 s nor the 0.1 s output interval, is accepted, and the
    result equals the example's (the integration never reads it): same neutral area and
    the same peak sideslip of every run to round-off."""
    book = openpyxl.load_workbook(EXAMPLE)
    book["Study"][f"B{study_row(book, 'chute sizing time step')}"] = 0.03
    path = tmp_path / "odd-step.xlsx"
    book.save(path)
    odd = compute(read_study(path, only=["chute sizing"]))
    assert odd.static.area == result.static.area
    np.testing.assert_allclose(odd.sweep.to_frame()["peak beta [deg]"],
                               result.sweep.to_frame()["peak beta [deg]"], rtol=1e-12)

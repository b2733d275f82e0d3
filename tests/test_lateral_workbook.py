"""Lateral-step pendulum driven from the input workbook: round trip, loads link, bad input.

References: the recommended angle read through the workbook equals the one of the Python API
on the same data (the body summed by hand from the MassItems: parallel-axis theorem for Ixx
about the CG, e = hub z - CG z for the vertical mast; the motions built from the
LateralMotions rows); the report's numbers read back equal those of the API run. The loads
link is checked against closed forms: the hook load's lateral component is Nz W sin(angle)
and the airframe is symmetric in y, so the Y-shear envelope scales as sin(angle) (reduction
1 - sin(rec)/sin(30 deg)); at a zero cone angle every hook direction is the mast axis, so the
envelope equals the vertical hook case alone, run independently. Each bad-input test breaks
one rule of ``slingloads.io.lateral.schema`` and checks exit code 2, the sheet and cell in
the message, and that nothing is written.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE, light_example, refused_copy
from once import made_once

from slingloads.analyses.hook_angle import hook_angle_comparison
from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.lateral import CarrierLimits, ParameterRanges, lateral_study
from slingloads.cli import main
from slingloads.constants import FOOT, G0, POUND_FORCE
from slingloads.io.common.ownership import MANIFEST_NAME
from slingloads.io.lateral.report import PLOTS, verdict
from slingloads.io.study import read_study
from slingloads.models.carrier_motion import (
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
    TimeHistory,
    VelocityStep,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import SlungBody
from slingloads.runs.lateral import run as compute

STEM = EXAMPLE.stem


def _nominal_book():
    """The example with no uncertainty spread (nominal inputs only): its recommended angle
    stays below 90 deg, so the hook cases are re-run at it."""
    book = openpyxl.load_workbook(EXAMPLE)
    rows = {row[0].value: row[0].row for row in book["Study"].iter_rows(min_row=2)}
    for name in ("lateral roll inertia spread", "lateral CG below hub spread",
                 "lateral rope length spread"):
        book["Study"][f"B{rows[name]}"] = 0.0
    return book, rows


@pytest.fixture(scope="module")
def study():
    return read_study(EXAMPLE, only=["lateral"])


@pytest.fixture(scope="module")
def nominal(tmp_path_factory):
    """The lateral study of the example without the uncertainty spread, and its report."""
    book, _ = _nominal_book()
    path = tmp_path_factory.mktemp("nominal") / "nominal.xlsx"
    book.save(path)
    out = path.parent / "out"
    assert main(["lateral", str(path), "--out", str(out), "--quiet"]) == 0
    return compute(read_study(path, only=["lateral"])), out / "nominal-lateral.xlsx"


@pytest.fixture(scope="module")
def result(study):
    return compute(study)


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    """The folder of ``slingloads lateral`` on the example, made once for the session's
    workers (:func:`once.made_once`): to be read, not changed."""
    def make(out):
        assert main(["lateral", str(EXAMPLE), "--out", str(out), "--quiet"]) == 0

    return made_once(tmp_path_factory, "example-lateral-command", make)


def _sheet(path, name, title):
    """The table under the section ``title`` of a report sheet."""
    raw = pd.read_excel(path, sheet_name=name, header=None)
    start = int(np.nonzero(raw[0].astype(str).str.startswith(title).to_numpy())[0][0])
    head = start + 1
    while str(raw.iloc[head, 1]) == "nan":  # skip the section's note lines
        head += 1
    block = raw.iloc[head + 1:].copy()
    block.columns = raw.iloc[head]
    end = block.iloc[:, 0].isna().to_numpy()
    return block.iloc[: int(np.argmax(end)) if end.any() else len(block)]


def test_recommended_angle_workbook_equals_api(study, result):
    """Same data, two paths: the workbook reader and the API (body summed by hand)."""
    frame = study.airframe
    items = frame.mass_items
    m = float(np.sum(items.mass))
    cg = items.mass @ items.position / m
    d = items.position - cg
    # hanging, the CG lies under the hub (vertical k); the airframe rolls about the horizontal
    # fore-and-aft axis a: own inertia about a plus m times the squared distance from it
    k = (frame.hardpoints.hub - cg) / np.linalg.norm(frame.hardpoints.hub - cg)
    a = np.array([1.0, 0.0, 0.0]) - k[0] * k
    a /= np.linalg.norm(a)
    ixx = float(np.sum(np.einsum("i,nij,j->n", a, items.inertia, a)
                       + items.mass * (np.sum(d * d, axis=1) - (d @ a) ** 2)))
    body = SlungBody(m, ixx, float(np.linalg.norm(frame.hardpoints.hub - cg)))
    rows = pd.read_excel(EXAMPLE, sheet_name="LateralMotions")
    hist = pd.read_excel(EXAMPLE, sheet_name="LateralHistory")
    motions = []
    for _, r in rows.iterrows():
        if r["type"] == "quintic step":
            motions.append(QuinticStep.from_peak_acceleration(r["acceleration [g0]"] * G0,
                                                             r["duration [s]"]))
        elif r["type"] == "cycloidal step":
            motions.append(CycloidalStep.from_peak_acceleration(r["acceleration [g0]"] * G0,
                                                               r["duration [s]"]))
        elif r["type"] == "constant acceleration":
            motions.append(ConstantAcceleration(r["acceleration [g0]"] * G0, r["duration [s]"],
                                                r["then"]))
        elif r["type"] == "velocity step":
            motions.append(VelocityStep(r["delta V [m/s]"]))
        else:
            h = hist[hist["history id"] == r["history"]]
            motions.append(TimeHistory(h["t [s]"].to_numpy(), h["S [m]"].to_numpy()))
    ropes = [ft * FOOT for ft in (18.0, 60.0, 100.0)]
    api = lateral_study([body], ropes, motions, margin=1.5, hook_load_factor=2.5,
                        ranges=ParameterRanges.spread(0.2, 0.2, 0.2, points=3),
                        solver=SolverSettings(t_end=60.0, step=0.05), limits=CarrierLimits())
    got = result.inputs.bodies[0]
    assert (got.mass, got.roll_inertia, got.cg_below_hub) == pytest.approx(
        (body.mass, body.roll_inertia, body.cg_below_hub), rel=1e-12)
    assert result.recommended_angle == pytest.approx(api.recommended_angle, rel=1e-12,
                                                     nan_ok=True)
    assert result.study.max_load_angle == pytest.approx(api.max_load_angle, rel=1e-12)
    assert result.study.critical_index == api.critical_index
    # the example: its own inertias give a level Ixx about 1,680 kg m^2 (the order of a
    # BO-105's scaled to 2.9 t); its carrier motions are all flyable (bank <= 20 deg, roll
    # rate <= 10 deg/s) and every case stays inside the model's domain; the worst is the
    # cycloidal sidestep at the bank limit; nominal inputs keep the load angle near 6 deg, the
    # +-20 % ranges bring it past 20 deg, and the 1.5 margin past 30 deg: no reduction of the
    # CS-29.865 angle is supported; the cable tension stays below Nz = 2.5
    assert 1500 < items.inertia_about_cg[0, 0] < 2000
    # hanging 9 deg nose down (hub aft of the CG), it rolls about a tilted axis: the Izz and
    # Ixz of a long fuselage raise the roll inertia by about 40 %
    assert 2200 < body.roll_inertia < 2500
    assert result.motion_id(api.critical_index) == "CYC-0.36g-12s"
    assert result.study.flyable.all() and result.study.outside_domain == 0
    assert np.degrees(result.study.nominal_max_load_angle) < 10.0
    assert 20.0 < np.degrees(result.study.max_load_angle) < 30.0
    assert result.study.exceeds_regulatory_angle and "EXCEEDS" in verdict(result)
    assert not result.study.regulatory_angle_not_conservative
    assert result.study.max_tension_ratio < 2.5
    assert result.inputs.damping.off and "hover" in result.inputs.damping.note


def test_report_reads_back(run_dir, result):
    """`slingloads lateral` writes the workbook and PNGs; the numbers read back: the design
    angle, every run, the sensitivity table and the tension against Nz."""
    path = run_dir / f"{STEM}-lateral.xlsx"
    for tag in PLOTS:  # the example's recommended angle is below 90 deg: the shear plot too
        assert (run_dir / f"{STEM}-lateral-{tag}.png").stat().st_size > 1000
    sheets = pd.ExcelFile(path).sheet_names
    assert {"Cover", "Summary", "Runs", "Sensitivity", "Modes", "Histories", "LoadsAtAngle",
            "Plots"} <= set(sheets)
    angle = _sheet(path, "Summary", "Design angle")
    rec = angle[angle["item"] == "recommended design angle"].iloc[0]
    assert float(rec["value"]) == pytest.approx(np.degrees(result.recommended_angle),
                                                rel=1e-12, nan_ok=True)
    big = angle[angle["item"] ==
                "largest load angle |theta1 - theta2| over the stated ranges"].iloc[0]
    assert float(big["value"]) == pytest.approx(np.degrees(result.study.max_load_angle),
                                                rel=1e-12)
    # a table of more than a page has a sheet of its own, else it is a section of Runs
    runs = (pd.read_excel(path, sheet_name="Runs-ResultsEveryCase")
            if "Runs-ResultsEveryCase" in sheets else _sheet(path, "Runs", "Results of every case"))
    cases = result.study.case_frame()
    assert len(runs) == 21                                  # 7 motions x 3 ropes x 1 body
    nominal = result.study.metrics.max_load_angle[result.study.nominal]
    np.testing.assert_allclose(runs["max |theta1 - theta2| [deg]"].astype(float),
                               np.degrees(nominal), rtol=1e-12)
    np.testing.assert_allclose(
        runs["max |theta1 - theta2| over the ranges [deg]"].astype(float),
        cases["max |theta1 - theta2| over the ranges [deg]"], rtol=1e-12)
    assert runs["max |theta1 - theta2| over the ranges [deg]"].astype(float).max() == \
        pytest.approx(np.degrees(result.study.max_load_angle), rel=1e-12)
    sens = _sheet(path, "Sensitivity", "Largest load angle and tension")
    np.testing.assert_allclose(
        sens["max load angle, others over their ranges [deg]"].astype(float),
        result.study.sensitivity_frame()["max load angle, others over their ranges [deg]"],
        rtol=1e-12)
    tension = _sheet(path, "Summary", "Cable tension")
    over = tension[tension["item"] == "cases with T/(m g) above Nz"].iloc[0]
    # the flyable motions keep the cable tension below Nz = 2.5 in every case
    assert int(over["value"]) == int(result.study.exceeds_hook_load_factor.sum()) == 0
    assert str(over["note"]).startswith("Nz covers")


def test_nominal_report_reads_back_the_hook_cases(nominal):
    """Without the spread the recommended angle is below 90 deg: the hook cases at it read
    back from the LoadsAtAngle sheet."""
    result, path = nominal
    loads = _sheet(path, "LoadsAtAngle", "Envelope max |LIMIT load| of the hook cases per "
                                          "station: shear forces")
    c = result.comparison
    from slingloads.analyses.hook_loads import angle_words

    at = angle_words(np.degrees(c.angle))
    np.testing.assert_allclose(loads["max |Vy| at 30 deg [N]"].astype(float),
                               c.reference[:, 1], rtol=1e-12)
    np.testing.assert_allclose(loads[f"max |Vy| lateral at {at} deg [N]"].astype(float),
                               c.at_angle[:, 1], rtol=1e-12)


def test_us_report(tmp_path, nominal):
    """--units US: forces in lbf (1 lbf = 0.45359237 kg x 9.80665 m/s^2 exactly); every
    rope length in inches alone (1 in = 0.0254 m exactly): the critical case's rope on the
    Summary without a remark in ft, no rope length in ft on the Runs and Modes sheets (nor
    in SI: one unit per quantity in each report, m in SI)."""
    result, path = nominal
    source = path.parent.parent / "nominal.xlsx"
    assert main(["lateral", str(source), "--out", str(tmp_path), "--units", "US",
                 "--quiet"]) == 0
    report = tmp_path / "nominal-lateral.xlsx"
    loads = _sheet(report, "LoadsAtAngle", "Envelope")
    np.testing.assert_allclose(loads["max |Vy| at 30 deg [lbf]"].astype(float),
                               result.comparison.reference[:, 1] / POUND_FORCE, rtol=1e-12)
    angle = _sheet(report, "Summary", "Design angle").set_index("item")
    rope = angle.loc["  rope length"]
    assert rope["unit"] == "in" and " ft" not in str(rope["note"])
    assert float(rope["value"]) == pytest.approx(
        float(result.study.critical_case["rope length [m]"]) / 0.0254, rel=1e-12)
    runs = _sheet(report, "Runs", "Definition of every case")
    modes = pd.read_excel(report, sheet_name="Modes", header=None)
    headers = [str(h) for h in [*runs.columns, *modes.iloc[:4].to_numpy().ravel()]]
    assert "rope length [in]" in headers
    assert not [h for h in headers if "rope length" in h and "[ft]" in h]
    si = _sheet(path, "Summary", "Design angle").set_index("item")
    assert si.loc["  rope length", "unit"] == "m" and " ft" not in str(
        si.loc["  rope length", "note"])


def test_us_plots_in_the_report_units(result):
    """--units US figures of the lateral study: the carrier displacement in inches (1 in =
    0.0254 m) and the rope length and motion in the title in inches and ft/s^2, no metre
    left; the rope legend of the max-angle plot in inches."""
    from slingloads.io.lateral.plots import plot_max_angle_vs_acceleration, plot_time_histories

    fig = plot_time_histories(result.critical_run, units="US")
    carrier = fig.axes[2]
    assert carrier.get_ylabel() == "carrier S [in]"
    np.testing.assert_allclose(carrier.lines[0].get_ydata(),
                               result.critical_run.carrier[0] / 0.0254, rtol=1e-12)
    title = fig._suptitle.get_text()
    assert " in" in title and " m " not in title and "m/s" not in title
    legend = plot_max_angle_vs_acceleration(result.study, units="US").legends[0]
    ropes = [t.get_text() for t in legend.get_texts() if t.get_text().startswith("rope")]
    assert ropes and all(r.endswith(" in") for r in ropes)


@pytest.mark.parametrize("angle_deg", [10.0, 17.3, 25.0])
def test_y_shear_scales_with_the_largest_lateral_component(result, angle_deg):
    """Only the pure lateral directions (AZ090, AZ270) take a smaller angle; the diagonals
    keep 30 deg. Y shear of a y-symmetric airframe is proportional to the hook's lateral
    component Nz W sin(theta) |sin(psi)|, so its envelope at an angle rec is
    max(sin rec, sin 30 sin 45) / sin 30 of the one at 30 deg: reduction
    1 - max(sin rec, 0.353553) / 0.5 (at most 29.3 % whatever the angle)."""
    c = hook_angle_comparison(result.inputs.loads, np.radians(angle_deg))
    assert c.reduced == ("AZ090", "AZ270")
    vy_ref, vy_at = c.reference[:, 1], c.at_angle[:, 1]
    assert np.all(vy_at <= vy_ref * (1 + 1e-12))
    expected = 1.0 - max(np.sin(c.angle), 0.5 * np.sqrt(0.5)) / 0.5
    loaded = vy_ref > 1e-6 * vy_ref.max()
    np.testing.assert_allclose(c.reduction[loaded, 1], 100.0 * expected, rtol=1e-9)
    summary = c.summary_frame()
    assert summary["component"].iloc[0] == "Vy"
    assert summary["reduction [%]"].iloc[0] == pytest.approx(100.0 * expected, rel=1e-9)


def test_zero_lateral_angle_keeps_the_other_directions(study, result):
    """At a zero lateral angle the two lateral directions fall onto the vertical case, and
    the envelope is that of the vertical and the six other directions at 30 deg (run on
    their own, without AZ090 and AZ270)."""
    loads = result.inputs.loads
    zero = hook_angle_comparison(loads, 0.0)
    assert zero.reduced == ("AZ090", "AZ270")
    kept = ["VERTICAL", "AZ000", "AZ045", "AZ135", "AZ180", "AZ225", "AZ315"]
    alone = replace(loads, hook=HookLoadOptions(nz=loads.hook.nz, towed=False),
                    envelope=None, fuselage=None, fin=None, parachute=None, listed=(),
                    previous_envelope=None).run()
    rows = alone.cases["hook"].isin(kept).to_numpy()
    scale = np.abs(alone.loads).max()
    np.testing.assert_allclose(zero.at_angle, np.abs(alone.loads[rows]).max(axis=0),
                               rtol=1e-12, atol=1e-12 * scale)
    assert "kept at 30 deg" in zero.reduced_note().lower()


# ---------------------------------------------------------------------------- bad input
def _bad(tmp_path, capsys, edit, sheet, cell, *fragments):
    return refused_copy(tmp_path, capsys, "lateral", edit, sheet, cell, *fragments)


def _bodies(mass=2900.0, inertia=900.0, cg=1.07):
    def edit(book):
        ws = book.create_sheet("LateralBodies")
        ws.append(["id", "mass [kg]", "roll inertia [kg m^2]", "CG below hub [m]"])
        ws.append(["HEAVY", 2900.0, 900.0, 1.07])
        ws.append(["LIGHT", mass, inertia, cg])
    return edit


@pytest.mark.parametrize("length", [0.0, -18.0])
def test_bad_rope_length(tmp_path, capsys, length):
    """Rule: every rope length of LateralRopes is > 0."""
    def edit(book):
        book["LateralRopes"]["A3"] = length
    _bad(tmp_path, capsys, edit, "LateralRopes", "A3", "rope length must be > 0")


@pytest.mark.parametrize("mass", [0.0, -100.0, 0.5])
def test_bad_body_mass(tmp_path, capsys, mass):
    """Rule: every body mass of LateralBodies is >= 1 kg (the smallest total of the
    MassItems: below it no aircraft)."""
    _bad(tmp_path, capsys, _bodies(mass=mass), "LateralBodies", "B3", "mass must be >= 1 kg")


@pytest.mark.parametrize("inertia", [0.0, -5.0])
def test_bad_body_inertia(tmp_path, capsys, inertia):
    """Rule: every roll inertia of LateralBodies is > 0."""
    _bad(tmp_path, capsys, _bodies(inertia=inertia), "LateralBodies", "C3",
         "roll inertia must be > 0")


def test_history_not_increasing(tmp_path, capsys):
    """Rule: the times of a LateralHistory are strictly increasing."""
    def edit(book):
        ws = book["LateralHistory"]
        ws["B5"] = ws["B3"].value  # the 4th sample goes back in time
    _bad(tmp_path, capsys, edit, "LateralHistory", "B5", "strictly increasing")


def test_unknown_motion_type(tmp_path, capsys):
    """Rule: a motion type is one of the documented kinds."""
    def edit(book):
        book["LateralMotions"]["B2"] = "zigzag"
    _bad(tmp_path, capsys, edit, "LateralMotions", "B2", "unknown motion type", "zigzag")


def test_run_command_includes_lateral(tmp_path):
    """`slingloads run` on the example writes the lateral report beside the others."""
    book, study_rows = _nominal_book()
    for name in ("run loads", "run chute sizing", "run multibody"):
        book["Study"][f"B{study_rows[name]}"] = "no"
    path = tmp_path / "only-lateral.xlsx"
    book.save(path)
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 0
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [MANIFEST_NAME, "only-lateral-lateral.xlsx", "only-lateral-lateral-histories.csv"]
        + [f"only-lateral-lateral-{t}.png" for t in PLOTS])


def test_recommended_angle_above_30_deg_is_flagged(tmp_path):
    """Margin 5 puts the example's nominal recommendation (5 x 6.3 deg) above 30 deg: the
    report says so and the hook cases at that angle give a larger Y shear (sin(rec) >
    sin(30 deg))."""
    from slingloads.io.lateral.report import verdict

    book, rows = _nominal_book()
    book["Study"][f"B{rows['lateral design-angle margin']}"] = 5.0
    path = tmp_path / "margin5.xlsx"
    book.save(path)
    res = compute(read_study(path, only=["lateral"]))
    assert np.degrees(res.recommended_angle) > 30.0
    assert res.study.exceeds_regulatory_angle
    assert "EXCEEDS" in verdict(res)
    assert res.comparison.summary_frame()["reduction [%]"].iloc[0] < 0


def test_time_history_from_a_csv_file_equals_the_sheet(tmp_path):
    """The same carrier displacement samples given as a CSV file beside the workbook (S in
    feet, converted with 1 ft = 0.3048 m exactly) and on the LateralHistory sheet (in m) give
    the same peak load angle, swing and tension: two input routes, one motion."""
    book, _ = _nominal_book()
    rows = [r for r in book["LateralHistory"].iter_rows(min_row=2, values_only=True)
            if r[0] == "REPOSITION"]
    pd.DataFrame({"t [s]": [r[1] for r in rows],
                  "S [ft]": [r[2] / 0.3048 for r in rows]}).to_csv(tmp_path / "hist.csv",
                                                                    index=False)
    ws = book["LateralMotions"]
    header = [c.value for c in ws[1]]
    history_col = header.index("history") + 1
    for row in ws.iter_rows(min_row=2):
        if row[0].value == "REPOSITION":
            row[history_col - 1].value = "hist.csv"
    path = tmp_path / "csv-history.xlsx"
    book.save(path)
    columns = ["max |theta1 - theta2| [deg]", "max |theta1| [deg]", "max T/(m g) [-]"]

    def reposition(source):
        frame = compute(read_study(source, only=["lateral"])).study.to_frame()
        return frame[frame["motion"] == "time_history"][columns].to_numpy()

    sheet = tmp_path / "sheet-history.xlsx"
    nominal_book, _ = _nominal_book()
    nominal_book.save(sheet)
    np.testing.assert_allclose(reposition(path), reposition(sheet), rtol=1e-9)


def test_elastic_cable_from_the_workbook_tends_to_the_rigid_rope(tmp_path):
    """'lateral cable model' = elastic with a stiff cable (EA = 2e8 N: static stretch
    W l / EA under 1 mm on the 18 ft rope) gives the rigid rope's peak load angle and
    tension (limit case: the elastic model converges to the inextensible one)."""
    book, rows = _nominal_book()
    ws = book["LateralMotions"]
    ws.delete_rows(4, ws.max_row)                   # keep two quintic steps
    book["LateralRopes"].delete_rows(3, 10)         # keep the 18 ft rope
    book["Study"][f"B{rows['lateral RK4 step']}"] = 0  # automatic step for both models
    book["Study"][f"B{rows['lateral simulation time']}"] = 8.0  # the peaks come within 5 s

    def peaks(model, ea):
        book["Study"][f"B{rows['lateral cable model']}"] = model
        book["Study"][f"B{rows['lateral cable EA']}"] = ea
        path = tmp_path / f"{model}.xlsx"
        book.save(path)
        frame = compute(read_study(path, only=["lateral"])).study.to_frame()
        return frame[["max |theta1 - theta2| [deg]", "max T/(m g) [-]"]].to_numpy()

    rigid, elastic = peaks("rigid", 0), peaks("elastic", 2e8)
    assert rigid.shape == (2, 2)
    np.testing.assert_allclose(elastic, rigid, rtol=5e-3)


def test_step_laws_by_type_name_and_the_former_name(tmp_path):
    """Motion types name their laws: 'cycloidal step' reads a CycloidalStep whose peak
    acceleration is the row's (0.1 g0 = 0.980665 m/s^2, so A = a T^2 / (2 pi)); the former
    name 'smooth step' still reads the quintic step."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book["LateralMotions"]
    ws["B2"] = "cycloidal step"
    ws["B3"] = "Smooth Step"
    path = tmp_path / "laws.xlsx"
    book.save(path)
    motions = read_study(path, only=["lateral"]).inputs.lateral.motions
    duration = float(ws["D2"].value)
    assert isinstance(motions[0], CycloidalStep)
    assert motions[0].amplitude == pytest.approx(0.1 * G0 * duration**2 / (2 * np.pi),
                                                 rel=1e-12)
    assert isinstance(motions[1], QuinticStep)


@pytest.mark.parametrize("name, value, fragments", [
    ("lateral damping source", "guess", ("valid values", "'aerodynamic tables'")),
    ("lateral damping", 500.0, ("used only with 'lateral damping source' = parameters",)),
    ("lateral roll inertia spread", 1.0, ("in [0, 1)",)),
    ("lateral rope length spread", -0.1, ("must be >= 0",)),
    ("lateral spread points", 0, ("must be >= 1",)),
    ("lateral airspeed EAS", -10, ("must be >= 0",)),
])
def test_bad_damping_and_range_rows(tmp_path, capsys, name, value, fragments):
    """Rules of the damping and uncertainty rows: the source is 'parameters' or 'aerodynamic
    tables' (the example's), the damping rows stay 0 with the tables, a spread lies in
    [0, 1), the number of points is a whole number >= 1, the airspeed is >= 0."""
    def edit(book):
        rows = {row[0].value: row[0].row for row in book["Study"].iter_rows(min_row=2)}
        book["Study"][f"B{rows[name]}"] = value

    book = openpyxl.load_workbook(light_example())
    row = {r[0].value: r[0].row for r in book["Study"].iter_rows(min_row=2)}[name]
    _bad(tmp_path, capsys, edit, "Study", f"B{row}", *fragments)


def test_fin_damping_from_the_workbook_by_hand(tmp_path):
    """'lateral airspeed EAS' = 60 kt with the aerodynamic tables: the fin's damping is
    1/2 rho V S_fin eta |dCY/dbeta| with the fin slope fitted here independently (np.polyfit
    of the FinAero rows within +-10 deg): 0.5 x 1.225 x 30.867 x 0.9 x 0.5 x |slope|, at the
    fin's centre of pressure below the hub (negative: above); the fuselage adds its own."""
    book = openpyxl.load_workbook(EXAMPLE)
    rows = {row[0].value: row[0].row for row in book["Study"].iter_rows(min_row=2)}
    book["Study"][f"B{rows['lateral airspeed EAS']}"] = 60
    path = tmp_path / "forward.xlsx"
    book.save(path)
    study = read_study(path, only=["lateral"])
    damping = study.inputs.lateral.damping
    fin = pd.read_excel(EXAMPLE, sheet_name="FinAero")
    beta = fin.iloc[:, 0].to_numpy()
    inside = np.abs(beta) <= 10.0 + 1e-9
    slope = np.polyfit(np.radians(beta[inside]), fin["CY"].to_numpy()[inside], 1)[0]
    parts = {name: (c, d) for name, c, d in damping.parts}
    assert parts["fin"][0] == pytest.approx(0.5 * 1.225 * 60 * 0.514444 * 0.9 * 0.5 * -slope,
                                            rel=1e-4)
    hub, cp = study.airframe.hardpoints.hub, study.source.points["fin_cp"]
    assert parts["fin"][1] == pytest.approx(hub[2] - cp[2], rel=1e-9)
    assert damping.lateral > parts["fin"][0] > 0 and damping.roll > 0

"""The multibody model driven from the input workbook: round trip, report read-back, bad input.

References: the system read through the workbook equals the one built with the Python API from
the same data (the example's mass items, hardpoints and GENERIC HC1 tables; 60 ft = 18.288 m
and 80 kt = 41.1556 m/s exactly by the definitions of the foot and the knot); the manoeuvres
read from the MultibodyManoeuvres sheet equal those of the API builders; the report's numbers
read back equal those of the API run. Each bad-input test breaks one rule written in
``slingloads.io.multibody.schema`` and checks exit code 2, the sheet and cell, the value as
written and the rule in the message, and that nothing is written.
"""

from __future__ import annotations

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE, refused_copy, study_row
from once import made_once

from slingloads.analyses.multibody import (
    forward_acceleration,
    free_response,
    gust_response,
    linearise,
    paper_manoeuvres,
    simulate,
    trim,
    wind_ramp,
)
from slingloads.cli import main
from slingloads.constants import FOOT, KNOT
from slingloads.io.study import load_workbook_system, read_study
from slingloads.models.multibody import (
    Cable,
    FreeCarrier,
    HingedParachute,
    LiftingSurface,
    RigidBody,
    SlingSystem,
)
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_htail,
    sample_reference,
)
from slingloads.runs.multibody import run as compute

STEM = EXAMPLE.stem
MANOEUVRES = "MultibodyManoeuvres"


@pytest.fixture(scope="module")
def study():
    return read_study(EXAMPLE, only=["multibody"])


@pytest.fixture(scope="module")
def result(study):
    return compute(study)


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    """The folder of ``slingloads simulate`` on the example, made once for the session's
    workers (:func:`once.made_once`): to be read, not changed."""
    def make(out):
        assert main(["simulate", str(EXAMPLE), "--out", str(out), "--quiet"]) == 0

    return made_once(tmp_path_factory, "example-simulate-command", make)


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    """The example with a coarse FuselageAero (every 20 deg of alpha and beta) and the other
    analyses switched off: quick to load for the bad-input tests."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book["FuselageAero"]
    keep = [r for r in ws.iter_rows(min_row=2, values_only=True)
            if r[0] is not None and r[0] % 20 == 0 and r[1] % 20 == 0]
    ws.delete_rows(2, ws.max_row)
    for r in keep:
        ws.append(r)
    for name in ("run loads", "run lateral", "run chute sizing"):
        book["Study"][f"B{study_row(book, name)}"] = "no"
    path = tmp_path_factory.mktemp("small") / "small.xlsx"
    book.save(path)
    return path


def api_system(study):
    """The example's system built with the Python API from the same data."""
    frame, points = study.airframe, study.source.points
    ref = sample_reference("HC1")
    hc1 = sample_fuselage("HC1")
    from slingloads.models.aerodynamics import Fin, FuselageAero

    fuselage = FuselageAero(hc1.table, ref.fuselage_area, ref.fuselage_length,
                            points["aero_reference"])
    fin = Fin(sample_fin("HC1").table, ref.fin_area, points["fin_cp"], ref.fin_efficiency)
    chute = Parachute(study.source.parameters["parachute area"], extended_cd_table(),
                      line_length=study.source.parameters["parachute line length"])
    return SlingSystem(RigidBody.from_mass_items(frame.mass_items), frame.hardpoints,
                       Cable(60 * FOOT, 5e6, 0.05), fuselage, (LiftingSurface.from_fin(fin),),
                       HingedParachute(chute, 3.0), airspeed=80 * KNOT)


def _summary(path):
    """The rows of the Summary sheets (the Summary and the tables it puts on sheets of their
    own, ``Summary-...``), read without a header."""
    return pd.concat([pd.read_excel(path, sheet_name=n, header=None)
                      for n in pd.ExcelFile(path).sheet_names if n.startswith("Summary")],
                     ignore_index=True)


def test_workbook_system_equals_api(study):
    """Same data, two paths: the parameter vector and the tables of the compiled equations
    are equal (60 ft = 18.288 m, 80 kt = 41.1556 m/s)."""
    system = study.inputs.multibody.system
    api = api_system(study)
    assert system.cable.length == pytest.approx(18.288, rel=1e-15)
    assert system.airspeed == pytest.approx(80 * 1852 / 3600, rel=1e-15)
    np.testing.assert_allclose(system.parameters(), api.parameters(), rtol=1e-12, atol=0)
    for mine, theirs in zip(system.tables(), api.tables(), strict=True):
        np.testing.assert_allclose(mine, theirs, rtol=1e-12, atol=1e-12)


def test_manoeuvres_from_the_sheet_equal_the_builders(study):
    """The example's four rows equal the API builders with the same numbers (30 ft/s =
    9.144 m/s; 60 kt and 40 kt; 2 deg of yaw seed on the runs from hover)."""
    runs = {m.name: m for m in study.inputs.multibody.manoeuvres}
    assert list(runs) == ["free response 10 deg yaw", "lateral gust +30 ft/s 10 s",
                          "accelerate to 60 KIAS", "head-wind ramp to 40 kt"]
    free = free_response({"yaw": np.radians(10.0)})
    assert runs["free response 10 deg yaw"].disturbance == pytest.approx(free.disturbance)
    gust = gust_response("finite", 30 * FOOT, onset=5.0, duration=10.0).wind
    read = runs["lateral gust +30 ft/s 10 s"].wind
    assert type(read.gust) is type(gust.gust) and read.direction == gust.direction
    assert read.gust.amplitude == pytest.approx(9.144, rel=1e-12)
    assert (read.gust.onset, read.gust.duration) == (gust.gust.onset, gust.gust.duration)
    accel = forward_acceleration(60 * KNOT, acceleration=1.0, onset=5.0)
    assert runs["accelerate to 60 KIAS"].trajectory == accel.trajectory
    assert runs["accelerate to 60 KIAS"].disturbance == pytest.approx(accel.disturbance)
    ramp = wind_ramp(40 * KNOT, rate=0.5, onset=5.0)
    assert runs["head-wind ramp to 40 kt"].wind == ramp.wind
    assert runs["head-wind ramp to 40 kt"].from_hover


def _table(workbook, sheet, header, part=0):
    """The first table (or its ``part``-th part, when printed in parts) of a report sheet
    whose header row holds ``header``, down to its first empty row."""
    raw = pd.read_excel(workbook, sheet_name=sheet, header=None)
    at = int(np.flatnonzero((raw == header).any(axis=1))[part])
    body = raw.iloc[at + 1:]
    end = np.flatnonzero(body.isna().all(axis=1).to_numpy())
    body = body.iloc[:end[0]] if end.size else body
    columns = raw.iloc[at]
    keep = columns.notna().to_numpy()
    return pd.DataFrame(body.loc[:, keep].to_numpy(), columns=list(columns[keep]))


def test_report_reads_back(run_dir, study, result):
    """`slingloads simulate` writes the workbook, CSV and PNGs; trim, modes, metrics and
    histories read back equal an API run of the same system and manoeuvres (the runs within
    the integration's accuracy, 0.002 deg: the two systems' parameters differ by round-off,
    enough to move the adaptive steps within the tolerance, rtol 1e-4)."""
    for tag in ("histories", "eigenvalues", "views"):
        assert (run_dir / f"{STEM}-multibody-{tag}.png").stat().st_size > 5000
    api = api_system(study)
    point = trim(api)
    workbook = run_dir / f"{STEM}-multibody.xlsx"
    summary = _summary(workbook)
    pitch = summary[summary[0] == "pitch"].iloc[0]
    assert pitch[2] == "deg"
    assert float(pitch[1]) == pytest.approx(np.degrees(point.attitude[1]), rel=1e-9)
    modes = _table(workbook, "Modes", "natural frequency [rad/s]")
    expected = linearise(point).modes_frame()
    np.testing.assert_allclose(modes["natural frequency [rad/s]"].astype(float),
                               expected["natural frequency [rad/s]"], rtol=1e-6)
    sim = simulate(api, study.inputs.multibody.manoeuvres)
    parts = int(pd.read_excel(workbook, sheet_name="Metrics", header=None).eq(
        "metric").any(axis=1).sum())
    metrics = pd.concat([_table(workbook, "Metrics", "metric", k).set_index("metric")
                         .drop(columns="unit") for k in range(parts)], axis=1)
    runs = list(sim.metrics_frame()["run"])
    assert list(metrics.loc["verdict", runs]) == list(sim.metrics_frame()["verdict"])
    np.testing.assert_allclose(metrics.loc["yaw change", runs].astype(float),
                               sim.metrics_frame()["yaw change [deg]"], atol=2e-3)
    csv = pd.read_csv(run_dir / f"{STEM}-multibody-histories.csv")
    np.testing.assert_allclose(csv["beta_deg"], sim.histories_frame()["beta [deg]"],
                               atol=2e-3)
    assert result.simulation.dt is None  # adaptive


def test_us_report_converts_lengths(small, tmp_path):
    """--units US: the cable length in in (60 ft = 720 in exactly), tension in lbf."""
    book = openpyxl.load_workbook(small)
    book["Study"][f"B{study_row(book, 'multibody simulation time')}"] = 20
    path = tmp_path / "us.xlsx"
    book.save(path)
    assert main(["simulate", str(path), "--out", str(tmp_path), "--units", "US",
                 "--quiet"]) == 0
    summary = _summary(tmp_path / "us-multibody.xlsx")
    row = summary[summary[0] == "cable length"].iloc[0]
    assert row[2] == "in" and float(row[1]) == pytest.approx(720.0, rel=1e-12)
    tension = summary[summary[0] == "cable tension"].iloc[0]
    assert tension[2] == "lbf"


def test_without_the_sheet_the_paper_list_is_flown(small, tmp_path):
    """No MultibodyManoeuvres sheet: the paper's manoeuvres (17 runs) in their order."""
    book = openpyxl.load_workbook(small)
    del book[MANOEUVRES]
    path = tmp_path / "paper.xlsx"
    book.save(path)
    inputs = load_workbook_system(path)
    assert [m.name for m in inputs.manoeuvres] == [m.name for m in paper_manoeuvres()]
    assert inputs.manoeuvre_source == "the paper's list"


def test_full_tail_without_parachute_and_free_carrier(small, tmp_path):
    """'without parachute', 'full tail' and a free carrier: no parachute, the intact fin
    (efficiency 1) and the horizontal tail of the HTailAero sheet (the HC1 table) at the
    htail_cp hardpoint; the carrier's mass, drag area and gain as written."""
    book = openpyxl.load_workbook(small)
    study = book["Study"]
    for name, value in (("multibody configuration", "without parachute"),
                        ("multibody tail", "full tail"), ("multibody carrier", "free"),
                        ("multibody carrier mass", 12000), ("multibody carrier drag area", 3),
                        ("multibody carrier speed gain", 0.4),
                        ("multibody horizontal tail area", 1.2)):
        study[f"B{study_row(book, name)}"] = value
    tail = sample_htail("HC1")
    ws = book.create_sheet("HTailAero")
    ws.append(["alpha [deg]", "CN"])
    for a, c in zip(np.degrees(tail.table.angle), tail.table.coefficients["CN"], strict=True):
        ws.append([float(a), float(c)])
    book["Hardpoints"].append(["HTAIL_CP", "htail_cp", 380.0, 0.0, 60.0, 1.0])
    path = tmp_path / "full.xlsx"
    book.save(path)
    system = load_workbook_system(path).system
    assert system.parachute is None
    assert system.fin.efficiency == 1.0
    assert system.tail.area == 1.2
    np.testing.assert_allclose(system.tail.table.coefficients["CN"],
                               tail.table.coefficients["CN"], atol=1e-12)
    np.testing.assert_allclose(system.tail.centre_of_pressure, [380 * 0.0254, 0, 60 * 0.0254])
    assert system.carrier == FreeCarrier(12000.0, 3.0, 0.4)


def test_short_cable_is_a_warning_in_the_report(small, tmp_path):
    """Rule: the cable at least 20 % longer than the parachute line, else a WARNING in the
    report (not an error when the canopy cannot reach the carrier). Line 40 m: 1.2 x 40 =
    48 m required; the hub-to-attachment distance (6.45 m) gives a reach of 46.45 m, so a
    47 m cable passes the reach rule and fails the 20 % rule."""
    book = openpyxl.load_workbook(small)
    study = book["Study"]
    study[f"B{study_row(book, 'parachute line length')}"] = 40
    study[f"C{study_row(book, 'parachute line length')}"] = "m"
    study[f"B{study_row(book, 'multibody cable length')}"] = 47
    study[f"C{study_row(book, 'multibody cable length')}"] = "m"
    study[f"B{study_row(book, 'multibody simulation time')}"] = 2
    ws = book[MANOEUVRES]
    ws.delete_rows(3, ws.max_row)
    path = tmp_path / "short.xlsx"
    book.save(path)
    assert main(["simulate", str(path), "--out", str(tmp_path), "--quiet"]) == 0
    summary = _summary(tmp_path / "short-multibody.xlsx")
    texts = summary[1].astype(str)
    warning = texts[texts.str.contains("too short")]
    # at a length cell's precision (0.000 m), trailing zeros dropped
    assert len(warning) == 1 and "i.e. >= 48 m;" in warning.iloc[0]
    assert summary[summary[0] == "cable against the line"].iloc[0][1] == "WARNING"


# ---------------------------------------------------------------------------- bad input
def _bad(small, tmp_path, capsys, edits, sheet, cell, *fragments):
    return refused_copy(tmp_path, capsys, "simulate", edits, sheet, cell, *fragments,
                        base=small)


@pytest.mark.parametrize("length", [0, -60])
def test_bad_cable_length(small, tmp_path, capsys, length):
    """Rule: 'multibody cable length' > 0."""
    name = "multibody cable length"
    _bad(small, tmp_path, capsys, {("Study", name): length}, "Study", name, "must be > 0",
         f"value {length!r}")


@pytest.mark.parametrize("ea", [0, -5000000])
def test_bad_cable_ea(small, tmp_path, capsys, ea):
    """Rule: 'multibody cable EA' in [1e4, 1e9] N (below, the load would stretch the cable
    several times its length)."""
    name = "multibody cable EA"
    _bad(small, tmp_path, capsys, {("Study", name): ea}, "Study", name, "must be >= 10000 N",
         f"value {ea!r}")


@pytest.mark.parametrize("mass", [0, -3])
def test_bad_canopy_mass(small, tmp_path, capsys, mass):
    """Rule: 'multibody canopy mass' in [0.1, 1000] kg (hinged canopy)."""
    name = "multibody canopy mass"
    _bad(small, tmp_path, capsys, {("Study", name): mass}, "Study", name, "must be >= 0.1 kg",
         f"value {mass!r}")


@pytest.mark.parametrize("mass", [0, -10000])
def test_bad_carrier_mass(small, tmp_path, capsys, mass):
    """Rule: 'multibody carrier mass' > 0."""
    name = "multibody carrier mass"
    _bad(small, tmp_path, capsys, {("Study", name): mass, ("Study", "multibody carrier"):
                                   "free"}, "Study", name, "must be > 0", f"value {mass!r}")


def test_negative_parachute_area(small, tmp_path, capsys):
    """Rule: 'multibody parachute area' >= 0 (0: the Study's 'parachute area')."""
    name = "multibody parachute area"
    _bad(small, tmp_path, capsys, {("Study", name): -1.1}, "Study", name, "must be >= 0",
         "value -1.1")


def test_zero_parachute_line(small, tmp_path, capsys):
    """Rule: 'parachute line length' > 0 (the line of the multibody canopy)."""
    name = "parachute line length"
    _bad(small, tmp_path, capsys, {("Study", name): 0}, "Study", name, "line length",
         "> 0")


def test_parachute_that_could_reach_the_carrier(small, tmp_path, capsys):
    """Rule: the line (10.1 m) plus the hub-to-attachment distance (6.45 m) must be shorter
    than the cable; a 40 ft (12.19 m) cable is refused, the value echoed as written."""
    name = "multibody cable length"
    _bad(small, tmp_path, capsys, {("Study", name): 40}, "Study", name,
         "could reach the carrier", "value 40", "lengthen the cable")


def test_unknown_manoeuvre(small, tmp_path, capsys):
    """Rule: kind among free response, gust, forward acceleration, wind ramp."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "B3"): "barrel roll"}, MANOEUVRES, "B3",
         "unknown kind", "'barrel roll'", "forward acceleration")


def test_unknown_gust_shape(small, tmp_path, capsys):
    """Rule: gust shape among step, finite, 1-cosine, continuous."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "C3"): "square"}, MANOEUVRES, "C3",
         "unknown shape", "'square'", "1-cosine")


@pytest.mark.parametrize("name, value, valid", [
    ("multibody configuration", "two parachutes", "without parachute"),
    ("multibody tail", "T-tail", "full tail"),
    ("multibody carrier", "towed", "frozen"),
])
def test_unknown_configuration(small, tmp_path, capsys, name, value, valid):
    """Rule: configuration, tail and carrier among their listed values."""
    _bad(small, tmp_path, capsys, {("Study", name): value}, "Study", name, "is not valid",
         repr(value), valid)


def test_acceleration_without_target(small, tmp_path, capsys):
    """Rule: a forward acceleration needs its target speed (H4 emptied)."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "H4"): None}, MANOEUVRES, "H4", "'target'")


def test_negative_ramp_rate(small, tmp_path, capsys):
    """Rule: a wind ramp's rate > 0."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "I5"): -0.5}, MANOEUVRES, "I5",
         "rate must be > 0 m/s^2", "-0.5")


@pytest.mark.parametrize("name", ["free response 10 deg yaw", "FREE RESPONSE 10 DEG YAW"])
def test_duplicate_run_name(small, tmp_path, capsys, name):
    """Rule: run names unique, case ignored (docs/inputs-and-outputs.md: ids are unique with
    case ignored): A3 repeats A2, as written or in capitals."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "A3"): name},
         MANOEUVRES, "A3", "duplicate name", "first at A2")


def test_gust_after_the_end(small, tmp_path, capsys):
    """Rule: an input starts before the end of the run."""
    _bad(small, tmp_path, capsys, {(MANOEUVRES, "F3"): 90}, MANOEUVRES, "F3",
         "before the end of the run", "value 90")


def test_full_tail_needs_its_table(small, tmp_path, capsys):
    """Rule: 'multibody tail' = full tail needs the HTailAero sheet."""
    name = "multibody tail"
    _bad(small, tmp_path, capsys, {("Study", name): "full tail"}, "Study", name,
         "HTailAero")


def test_tolerance_must_be_positive(small, tmp_path, capsys):
    """Rule: the adaptive step's relative tolerance in [1e-13, 0.1] (below, under the
    round-off)."""
    name = "multibody relative tolerance"
    _bad(small, tmp_path, capsys, {("Study", name): 0}, "Study", name, "must be >= 1e-13")


def test_canopy_table_must_pull_along_the_wind(small, tmp_path, capsys):
    """Rule: the hinged canopy's table from the sheet must be in wind axes (a CD pulling along
    the canopy's relative wind); a canopy-axes (CT) table is refused with the way out."""
    _bad(small, tmp_path, capsys, {("Study", "parachute table axes"): "canopy",
                                   ("Study", "multibody canopy CD"): "sheet"}, "Study",
         "parachute table axes", "wind axes", "'canopy'", "extended")


def test_us_views_in_the_tables_length_unit():
    """The views of a US report in inches, the unit of its cable length and positions (1 in
    = 0.0254 m exactly): a point 1 m aft and 2 m up is drawn at 39.37 in and 78.74 in."""
    from slingloads.io.multibody.plots import plot_view_points

    points = {"fuselage": np.array([[1.0, 0.0, 2.0], [2.0, 0.0, 2.0]])}
    fig = plot_view_points([("trim", points)], "US")
    side = fig.axes[0]
    assert side.get_xlabel() == "X aft [in]" and side.get_ylabel() == "Z up [in]"
    np.testing.assert_allclose(side.lines[0].get_xdata(), [1 / 0.0254, 2 / 0.0254])
    np.testing.assert_allclose(side.lines[0].get_ydata(), [2 / 0.0254, 2 / 0.0254])

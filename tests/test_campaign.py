"""The campaign engine (slingloads.analyses.campaign): execution, resume, selection, stability
map, transport without parachute, the envelope handed to the loads, and bad input.

References used below:
- the multibody model itself, run directly (``simulate_runs``, ``trim``, ``linearise``), for
  what the campaign must reproduce exactly whatever executes it;
- eigenvalues of the linearised state matrix computed here with ``numpy.linalg.eigvals`` for
  the stability map;
- hand-built metrics tables whose answer is worked out in each docstring for the selection and
  the speed limits;
- the stored time histories of the runs for the envelope handed to the loads.

Runs are short (30 s) and matrices tiny: the whole file costs well under a minute.
"""

import numpy as np
import pandas as pd
import pytest
from hostile import EXAMPLE
from numpy.testing import assert_allclose, assert_array_equal

from slingloads.analyses.campaign import (
    Campaign,
    CampaignMatrix,
    CampaignSetup,
    DaskCluster,
    Factors,
    InProcess,
    KeyMaker,
    MapSettings,
    MassCase,
    MemoryStore,
    RunSettings,
    SelectionCriteria,
    dynamics_envelope,
    run_campaign,
    select_parachute,
    speed_limits,
)
from slingloads.analyses.campaign.matrix import MANOEUVRES
from slingloads.analyses.multibody import linearise, simulate_runs, trim
from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError
from slingloads.models.multibody import Cable, HingedParachute, SlingSystem
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_body,
    sample_fuselage,
    sample_hardpoints,
    sample_surfaces,
)

SETTINGS = RunSettings(t_end=30.0, dt=0.01, output_interval=0.1)


def base_system():
    """GENERIC HC1 in the transport configuration with a hinged drogue (area replaced)."""
    return SlingSystem(sample_body("HC1"), sample_hardpoints("HC1"), Cable(60 * FOOT, 5e6),
                       sample_fuselage("HC1"), sample_surfaces("HC1"),
                       HingedParachute(Parachute(1.0, extended_cd_table())))


def tiny(areas=(1.2, 1.6), manoeuvres=("free response", "gust +30 ft/s"), **kw):
    factors = Factors(area_factors=areas, airspeeds=(60 * KNOT,), density_altitudes=(0.0,),
                      cable_lengths=(60 * FOOT,), manoeuvres=manoeuvres)
    kw.setdefault("stability", None)
    return Campaign(CampaignSetup(base_system()), factors, settings=SETTINGS, **kw)


@pytest.fixture(scope="module")
def local():
    """The tiny campaign run in this process."""
    return run_campaign(tiny(), executor=InProcess())


# ------------------------------------------------------------------------- execution
def test_campaign_runs_are_the_multibody_runs(local):
    """Each campaign run is the multibody model's run of its system and manoeuvre: the stored
    histories equal those of simulate_runs called directly (same integration, same trim), bit for
    bit."""
    campaign = tiny()
    row = campaign.matrix.frame.iloc[3]  # area 1.6, gust
    system = campaign.setup.system_for(row)
    manoeuvre = MANOEUVRES[row["manoeuvre"]].build(row["airspeed EAS [m/s]"], 0.0)
    direct = simulate_runs([(system, manoeuvre)], **SETTINGS.as_dict()).runs[0]
    history = local.history(row["run"])
    assert_array_equal(history["beta [deg]"].to_numpy(), np.degrees(direct.histories()["beta"]))
    assert_allclose(system.parachute.parachute.area, 1.6 * campaign.neutral.area, rtol=1e-15)


def test_dask_cluster_gives_the_local_results(local):
    """A LocalCluster of two worker processes (one thread each) runs the same campaign: the
    metrics table and every history are identical to the in-process run (each run is
    integrated on its own whatever batch or process it falls in)."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        result = run_campaign(tiny(), executor=DaskCluster(cluster.scheduler_address),
                              batch_size=1)
    assert result.execution.computed == 4 and result.execution.batches == 4
    assert "Dask" in result.execution.executor
    pd.testing.assert_frame_equal(result.metrics, local.metrics)
    for run in local.metrics["run"]:
        pd.testing.assert_frame_equal(result.history(run), local.history(run))


def test_resume_after_an_interruption_runs_only_the_missing_runs():
    """Interrupted after its first batch (of one run), the campaign stored that run only; run
    again with the same store it computes the 3 others and finds 1, and its results equal an
    uninterrupted run's."""
    store = MemoryStore()
    calls = []

    def interrupt(done, total):
        calls.append(done)
        if done >= 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_campaign(tiny(), executor=InProcess(), store=store, batch_size=1,
                     progress=interrupt)
    assert len(store) == 1
    again = run_campaign(tiny(), executor=InProcess(), store=store, batch_size=1)
    assert (again.execution.cached, again.execution.computed) == (1, 3)
    full = run_campaign(tiny(), executor=InProcess())
    pd.testing.assert_frame_equal(again.metrics, full.metrics)


def test_an_edited_input_reruns_only_what_changed(local):
    """Editing the matrix (area factors 1.2, 1.6 -> 1.2, 1.4) keeps the keys of the 1.2 runs
    and changes the others: 2 found, 2 computed. Changing the cable's damping (an input of
    every run) changes every key."""
    store = MemoryStore()
    run_campaign(tiny(), executor=InProcess(), store=store)
    edited = run_campaign(tiny(areas=(1.2, 1.4)), executor=InProcess(), store=store)
    assert (edited.execution.cached, edited.execution.computed) == (2, 2)
    keys = KeyMaker(SETTINGS.as_dict())
    campaign = tiny()
    _, jobs = campaign.run_jobs(keys)
    damped = Campaign(CampaignSetup(base_system().with_(cable=Cable(60 * FOOT, 5e6, 0.1))),
                      campaign.factors, settings=SETTINGS, stability=None)
    _, changed = damped.run_jobs(keys)
    assert not {j[0] for j in jobs} & {j[0] for j in changed}
    _, same = tiny().run_jobs(keys)
    assert [j[0] for j in same] == [j[0] for j in jobs]


# ------------------------------------------------------------------------- selection
def _table(rows):
    """Hand-built metrics: (area factor, airspeed kt, manoeuvre, linear verdict, response
    verdict, yaw-mode damping ratio, time to half amplitude [s], trimmed swing [deg])."""
    frame = pd.DataFrame(rows, columns=["area factor [-]", "airspeed kt", "manoeuvre",
                                        "linear verdict", "response verdict",
                                        "yaw mode damping ratio [-]",
                                        "yaw mode time to half amplitude [s]",
                                        "swing angle trim [deg]"])
    frame["airspeed EAS [m/s]"] = frame.pop("airspeed kt") * KNOT
    frame["area [m^2]"] = frame["area factor [-]"] * 0.5
    frame["trim converged"] = frame["linear verdict"] != "no trim"
    frame["mass case"], frame["density altitude [m]"] = "max", 0.0
    frame["cable length [m]"], frame["carrier"] = 18.288, "frozen"
    frame["yaw change [deg]"] = 5.0
    frame["run"] = [f"R{i}" for i in range(len(frame))]
    return frame


def test_selection_against_a_hand_built_table():
    """Areas 1.0-1.6 at 40 and 80 kt, two manoeuvres each. At 40 kt every area from 1.2 is
    stable; at 80 kt 1.2 has no trim and the gust at 1.4 diverges, so 1.6 is the smallest area
    stable in every condition, governed by 80 kt (the gust fails at 1.4). The damping criterion
    (zeta >= 0.1, half time <= 20 s) holds everywhere at 1.6 only (1.4 is not stable): the
    recommended area is 1.6, governed by 80 kt where its damping is least (0.12). With the
    criterion relaxed to zeta >= 0.05 and the gust at 1.4 convergent, 1.4 becomes both."""
    rows = []
    for f, z80 in ((1.0, np.nan), (1.2, np.nan), (1.4, 0.08), (1.6, 0.12)):
        for m in ("free", "gust"):
            rows.append((f, 40, m, "stable" if f > 1.0 else "unstable", "convergent",
                         0.5 if f > 1.0 else -1.0, 9.0, 1.0 + f))
            linear = {1.0: "no trim", 1.2: "no trim"}.get(f, "stable")
            response = "divergent" if (f == 1.4 and m == "gust") else "convergent"
            rows.append((f, 80, m, linear, response if linear == "stable" else "no trim",
                         z80, 12.0, 3.0 + f))
    sel = select_parachute(_table(rows), SelectionCriteria(0.1, 20.0), neutral_area=0.5)
    assert sel.smallest_stable == 1.6 and sel.recommended == 1.6
    assert_allclose(sel.recommended_area, 0.8)
    gov = sel.governing_stable
    assert gov["airspeed EAS [m/s]"] == pytest.approx(80 * KNOT)
    assert gov["needs area factor [-]"] == 1.6
    assert gov["fails below with"] == "gust (response divergent)"
    assert sel.governing_recommended["least yaw-mode damping ratio [-]"] == 0.12
    by = sel.by_area.set_index("area factor [-]")
    assert by.loc[1.2, "no trim"] == 2 and by.loc[1.4, "stable runs"] == 3
    relaxed = _table([r if not (r[0] == 1.4 and r[4] == "divergent")
                      else r[:4] + ("convergent",) + r[5:] for r in rows])
    sel = select_parachute(relaxed, SelectionCriteria(0.05, 20.0), neutral_area=0.5)
    assert sel.smallest_stable == 1.4 and sel.recommended == 1.4


def test_recommended_area_is_the_least_drag_one_meeting_the_criterion():
    """Three areas all stable; 1.2 fails the half-time limit (30 s > 20 s), 1.4 and 1.8 meet
    it: the recommended area is the one of smaller largest trimmed swing angle, 1.4 (2.4 deg
    against 2.8 deg), although 1.2 is the smallest stable."""
    rows = [(f, v, "free", "stable", "convergent", 0.3, half, 1.0 + f)
            for f, half in ((1.2, 30.0), (1.4, 10.0), (1.8, 8.0)) for v in (40, 80)]
    sel = select_parachute(_table(rows), SelectionCriteria(), neutral_area=1.0)
    assert (sel.smallest_stable, sel.recommended) == (1.2, 1.4)
    assert sel.governing_recommended["largest trimmed swing angle [deg]"] == pytest.approx(2.4)


# -------------------------------------------------------------------- stability map
def test_stability_map_against_eigenvalues_computed_directly():
    """At each grid point the map's largest real part equals that of
    numpy.linalg.eigvals of the state matrix of the system built here by hand (area =
    factor x neutral area, the point's airspeed), and so do the root locus's least-damped
    roots; the refined minimum stable area is stable and 0.5 % below it is not (eigenvalues
    computed directly)."""
    campaign = tiny(stability=MapSettings((1.0, 1.3), (50 * KNOT, 70 * KNOT), (0.0,)))
    result = run_campaign(campaign, executor=InProcess())
    points = result.stability.points
    neutral = campaign.neutral.area

    def eigenvalues(factor, speed):
        chute = HingedParachute(Parachute(factor * neutral, extended_cd_table()))
        point = trim(base_system().with_(parachute=chute, airspeed=speed))
        return np.linalg.eigvals(linearise(point).a) if point.converged else np.array([np.nan])

    def largest(factor, speed):
        return eigenvalues(factor, speed).real.max()

    loci = result.stability.loci
    for _, p in points.iterrows():
        lam = eigenvalues(p["area factor [-]"], p["airspeed EAS [m/s]"])
        assert_allclose(p["largest real part [1/s]"], lam.real.max(), rtol=1e-9, atol=1e-12)
        upper = lam[lam.imag >= -1e-9]
        upper = upper[np.argsort(-upper.real)][:5]
        mine = loci[(loci["area factor [-]"] == p["area factor [-]"])
                    & (loci["airspeed EAS [m/s]"] == p["airspeed EAS [m/s]"])]
        assert_allclose(mine["real [1/s]"], upper.real, rtol=1e-6, atol=1e-9)
        assert_allclose(np.abs(mine["imag [rad/s]"]), np.abs(upper.imag), rtol=1e-6,
                        atol=1e-9)
    for _, m in result.stability.minimum.iterrows():
        f = m["minimum stable area factor [-]"]
        assert largest(f, m["airspeed EAS [m/s]"]) < 0
        assert largest(f - 0.005, m["airspeed EAS [m/s]"]) > -1e-6


# ----------------------------------------------------------------- without parachute
def test_speed_limits_logic():
    """HC1 converges at 20 and 30 kt and diverges at 40: limit 30 kt. HC2 converges at 20,
    departs statically at 30 and converges again at 40 (the first failure ends the range):
    limit 20 kt. HC3 is a limit cycle at 20 kt already: no limit (NaN). HC4 converges at every
    ramp tried: its limit is only known to be at least the highest, ">= 40 kt". A ramp is
    convergent only when its response converges and its final equilibrium is stable (else
    inconclusive)."""
    from slingloads.analyses.campaign.no_parachute import ramp_verdict

    assert ramp_verdict("convergent", "stable") == "convergent"
    assert ramp_verdict("convergent", "unstable") == "inconclusive"
    assert ramp_verdict("static departure", "unstable") == "static departure"
    assert ramp_verdict("divergent", "stable") == "divergent"
    rows = [("HC1", 20, "convergent"), ("HC1", 30, "convergent"), ("HC1", 40, "divergent"),
            ("HC2", 40, "convergent"), ("HC2", 20, "convergent"),
            ("HC2", 30, "static departure"), ("HC3", 20, "limit cycle"),
            ("HC3", 30, "convergent"), ("HC4", 20, "convergent"), ("HC4", 40, "convergent")]
    runs = pd.DataFrame(rows, columns=["helicopter", "kt", "verdict"])
    runs["ramp target [m/s]"] = runs.pop("kt") * KNOT
    limits = speed_limits(runs).set_index("helicopter")
    assert_allclose(limits["largest convergent ramp [kt]"].to_numpy(), [30, 20, np.nan, 40])
    assert limits.loc["HC2", "first non-convergent ramp [kt]"] == pytest.approx(30)
    assert limits.loc["HC2", "its verdict"] == "static departure"
    assert limits.loc["HC3", "its verdict"] == "limit cycle"
    # the bracket the ramps tried give, never a bare number that reads as the limit itself
    assert list(limits["speed limit"]) == [
        ">= 30 kt and < 40 kt (the ramp to 40 kt: divergent)",
        ">= 20 kt and < 30 kt (the ramp to 30 kt: static departure)",
        "< 20 kt (the lowest ramp tried, to 20 kt: limit cycle)",
        ">= 40 kt (every ramp tried converges)"]


# --------------------------------------------------------------- loads hand-off
def test_loads_envelope_against_the_histories(local):
    """The extremes handed to the loads are those of the chosen area's stored histories:
    alpha, beta and line angles min/max, line tension and tension factor max, and the hub-load
    angles from the hanging vertical (the sample's hub is straight above its CG, so that
    vertical is z): atan2(|Fy|, Fz) sideways, arccos(Fz / |F|) in total; with a margin of 1.5
    each bound is 1.5 times as large and the alpha-beta range includes zero."""
    env = dynamics_envelope(local.metrics, 1.6, margin=1.5)
    runs = local.metrics.loc[local.metrics["area factor [-]"] == 1.6, "run"]
    h = pd.concat([local.history(r) for r in runs])
    for quantity, column in (("alpha", "alpha [deg]"), ("beta", "beta [deg]"),
                             ("line theta", "line theta [deg]"),
                             ("line psi", "line psi [deg]")):
        assert env.reached[quantity] == pytest.approx((h[column].min(), h[column].max()))
        lo, hi = env.bounds(quantity)
        assert lo == pytest.approx(min(0.0, 1.5 * h[column].min()))
        assert hi == pytest.approx(max(0.0, 1.5 * h[column].max()))
    assert env.reached["line tension"][1] == pytest.approx(h["line tension [N]"].max())
    assert env.tension_factor == pytest.approx(1.5 * h["tension / weight [-]"].max())
    lateral = np.degrees(np.arctan2(h["hub Fy [N]"].abs(), h["hub Fz [N]"])).max()
    assert env.reached["hub load lateral"][1] == pytest.approx(lateral)
    total = np.degrees(np.arccos(h["hub Fz [N]"] / np.sqrt(
        h["hub Fx [N]"] ** 2 + h["hub Fy [N]"] ** 2 + h["hub Fz [N]"] ** 2))).max()
    assert env.hook_angle == pytest.approx(np.radians(1.5 * total))
    assert env.runs == 2 and set(env.source["beta"]) <= set(runs)
    # the table handed to the report says the rule beside each row, and its numbers follow it
    # (an alpha range whose runs never reach 0 still ends at 0.0 with the margin: the note
    # says why)
    for _, row in env.to_frame().iterrows():
        assert row["note"].startswith("x 1.5")
        widened = "include 0" in row["note"]
        assert widened == (row["quantity"] in ("alpha", "beta", "line theta", "line psi"))
        hi = 1.5 * row["reached max"]
        assert row["with margin max"] == pytest.approx(max(0.0, hi) if widened else hi)


# -------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, rule", [
    ({"area_factors": ()}, "at least one parachute area factor"),
    ({"area_factors": (1.0, 0.0)}, "must be > 0"),
    ({"area_factors": (1.0, -1.2)}, "must be > 0"),
    ({"airspeeds": (0.0,)}, "airspeed must be > 0"),
    ({"manoeuvres": ("free response", "loop")}, "unknown manoeuvre"),
    ({"carriers": ("tethered",)}, "unknown carrier"),
])
def test_bad_factors_are_refused(kwargs, rule):
    """An empty factor list, a factor <= 0 and an unknown manoeuvre or carrier raise an
    InputError that states the rule (and, for names, the valid ones)."""
    with pytest.raises(InputError, match=rule):
        Factors(**kwargs)
    with pytest.raises(InputError, match="mass of the mass case 'max' must be > 0"):
        MassCase("max", -5.0)


def test_bad_listed_rows_are_refused():
    """Listed rows: an empty list, an unknown mass case (condition) or manoeuvre, and a factor
    <= 0 are refused naming the row; the valid names are listed."""
    row = {"area factor [-]": 1.2, "airspeed EAS [m/s]": 30.0, "mass case": "max",
           "density altitude [m]": 0.0, "cable length [m]": 20.0, "carrier": "frozen",
           "manoeuvre": "free response"}
    masses = (MassCase("max", 2900.0),)
    with pytest.raises(InputError, match="empty"):
        CampaignMatrix.from_rows([], 0.5, masses)
    with pytest.raises(InputError, match=r"row 1: unknown mass case.*\['max'\]"):
        CampaignMatrix.from_rows([{**row, "mass case": "heavy"}], 0.5, masses)
    with pytest.raises(InputError, match="row 2: unknown manoeuvre"):
        CampaignMatrix.from_rows([row, {**row, "manoeuvre": "spin"}], 0.5, masses)
    with pytest.raises(InputError, match="row 1: area factor must be > 0"):
        CampaignMatrix.from_rows([{**row, "area factor [-]": 0.0}], 0.5, masses)
    with pytest.raises(InputError, match="listed twice"):
        CampaignMatrix.from_rows([row, row], 0.5, masses)


def test_a_cable_the_parachute_could_reach_is_refused():
    """A 40 ft (12.2 m) cable lies within the reach of the sample's 10.1 m line streaming aft
    or hanging from its attachment 6.4 m aft of the hub (6.4 to 16.5 m from the hub): the
    campaign refuses it before running anything."""
    factors = Factors(cable_lengths=(40 * FOOT, 60 * FOOT))
    with pytest.raises(InputError, match="could reach the carrier"):
        Campaign(CampaignSetup(base_system()), factors)


def test_unreachable_scheduler_fails_within_its_time_out():
    """A scheduler address nobody listens on: an InputError naming the address and the
    time-out given, and nothing run into the store (not a hang: the guard is generous, the
    time taken depends on the machine)."""
    import time

    from hostile import DEADLINE

    start = time.monotonic()
    with pytest.raises(InputError, match=r"could not reach the Dask scheduler within 1 s"):
        DaskCluster("tcp://127.0.0.1:9", timeout=1.0)
    assert time.monotonic() - start < DEADLINE


# ------------------------------------------------------------ loads from the dynamics
@pytest.fixture(scope="module")
def example_loads():
    """The example workbook's hand-entered loads study (GENERIC light twin, HC1 tables)."""
    from slingloads.io.study import read_study

    return read_study(EXAMPLE, only=["loads"]).inputs.loads


def test_loads_take_the_dynamics_cases(local, example_loads):
    """The hand-off keeps the hand-entered points and adds the dynamics' corners and centre
    (the margin bounds, the sideslip mirrored about zero); it keeps the CS-29.865 30 deg cone
    and Nz 2.5, which the dynamics (x 1.25) do not reach; it keeps the Study's parachute
    (the chosen one only when asked). A LINE case loads the parachute fitting along
    e = (cos t cos p, sin p, sin t cos p) (psi mirrored) with the line load scaled to the
    loads' dynamic pressure and area: margin x max over the runs of T_line / (q_EAS A) x
    q_loads x A_loads, worked here from the metrics by hand."""
    from slingloads.analyses.campaign import loads_from_dynamics

    env = dynamics_envelope(local.metrics, 1.6, margin=1.25)
    handoff = loads_from_dynamics(example_loads, env, "CS-29.865")
    study = handoff.study
    hand = example_loads.envelope
    assert study.envelope.ids[:len(hand.ids)] == hand.ids
    dyn = dict(zip(study.envelope.ids, zip(study.envelope.alpha, study.envelope.beta,
                                           strict=True), strict=True))
    a0, a1 = np.radians(env.bounds("alpha"))
    b = np.radians(max(np.abs(env.bounds("beta"))))
    assert dyn["DYN-A+B-"] == pytest.approx((a1, -b)) and dyn["DYN-CENTRE"] == (0.0, 0.0)
    assert study.hook.angle == pytest.approx(np.radians(30.0)) and study.hook.nz == 2.5
    assert study.parachute.area == pytest.approx(example_loads.parachute.area)
    chosen = loads_from_dynamics(example_loads, env, "CS-29.865", parachute="chosen")
    assert chosen.study.parachute.area == pytest.approx(env.area)
    runs = local.metrics[np.isclose(local.metrics["area factor [-]"], 1.6)]
    per = (runs["line tension max [N]"]
           / (0.5 * 1.225 * runs["airspeed EAS [m/s]"] ** 2 * runs["area [m^2]"])).max()
    line_load = 1.25 * per * example_loads.flight.dynamic_pressure * example_loads.parachute.area
    cases = study.case_matrix()
    line = cases[cases["chute line"] == "LINE-T+P-"].index[0]
    _, forces, _ = study.applied_loads(cases.loc[[line]])
    t1 = np.radians(env.bounds("line theta")[1])
    p0 = -np.radians(max(np.abs(env.bounds("line psi"))))
    expected = line_load * np.array([np.cos(t1) * np.cos(p0), np.sin(p0),
                                     np.sin(t1) * np.cos(p0)])
    assert_allclose(forces[0, -1], expected, rtol=1e-9)
    # the cone and the vertical at each dynamics point; the towed cases fly the trim (aero
    # TRIM), not a dynamics point
    hooks = len(study.hook_table())
    assert (cases["source"] == "dynamics").sum() == hooks * 5 * (2 + 5)
    assert not cases.loc[cases["hook"] == "TOW", "source"].eq("dynamics").any()


def test_loads_hook_cone_from_the_dynamics_and_table_limits(example_loads):
    """With hook source 'dynamics' the cone takes the reached angles x margin (fore-and-aft
    the larger |longitudinal| extreme, sideways the lateral one, elliptical); a margin bound
    beyond the fuselage table's alpha range (-35 x 1.25 = -43.75 < -40 deg) is set at the
    table's edge and flagged; Nz is raised when the tension factor x margin exceeds it."""
    from slingloads.analyses.campaign import DynamicsEnvelope, loads_from_dynamics

    reached = {"alpha": (-35.0, -5.0), "beta": (-20.0, 18.0), "line theta": (-10.0, 4.0),
               "line psi": (-12.0, 12.0), "hub load from mast": (None, 22.0),
               "hub load from vertical": (None, 21.0), "hub load lateral": (None, 8.0),
               "hub load longitudinal": (-14.0, 6.0), "line tension": (None, 900.0),
               "tension / weight": (None, 2.2)}
    env = DynamicsEnvelope(1.4, 1.0, 1.25, reached, {k: (None, "R1") for k in reached}, 4, 0)
    handoff = loads_from_dynamics(example_loads, env, "dynamics")
    hook = handoff.study.hook
    assert hook.angle == pytest.approx(np.radians(1.25 * 14.0))
    assert hook.lateral_angle == pytest.approx(np.radians(1.25 * 8.0))
    assert hook.cone == "elliptical" and hook.nz == pytest.approx(1.25 * 2.2)
    alpha = dict(zip(handoff.study.envelope.ids, handoff.study.envelope.alpha, strict=True))
    assert alpha["DYN-A-B+"] == pytest.approx(np.radians(-40.0))
    notes = handoff.comparison.set_index("quantity")["note"]
    assert "limited to the fuselage alpha table's range" in notes["alpha range"]
    # the dynamics' smaller cone is below the Study's 30 deg: flagged beside it
    lowered = handoff.comparison.set_index("quantity")["lowered"]
    assert lowered["hook cone, fore-and-aft angle from the vertical"]
    assert notes["hook cone, fore-and-aft angle from the vertical"].startswith("LOWER")
    assert not lowered["hook load factor Nz"]
    kept = loads_from_dynamics(example_loads, env, "CS-29.865").study.hook
    assert kept.angle == pytest.approx(np.radians(30.0))
    with pytest.raises(InputError, match="not a valid hook-cone source"):
        loads_from_dynamics(example_loads, env, "guess")


# ------------------------------------------------------------------------- sensitivity
def test_sensitivity_tables_and_carrier_pairs_against_a_hand_built_table():
    """Paper figures 9 to 13 as tables, on hand-built metrics: areas 1.0 and 1.4 at 40 and
    80 kt, carriers frozen and free, one manoeuvre; yaw change = 10 x area factor + airspeed
    [kt] / 10 + (1 if free). The area table groups every run (4 per area: worst yaw change at
    1.4 is 14 + 8 + 1 = 23 deg; at 1.0, 19 deg; stable runs 0 at 1.0 whose linear verdict is
    unstable); the airspeed and carrier tables take the runs at the selected area 1.4 only (2
    per group: worst at 80 kt 23 deg, at 40 kt 19 deg; frozen 22, free 23 deg). The carrier
    pairs are the 4 (area, airspeed) pairs with free - frozen = 1 deg each."""
    from slingloads.analyses.campaign.sensitivity import carrier_comparison, sensitivity_tables

    rows = [(f, v, "free response", "stable" if f > 1.0 else "unstable", "convergent", 0.2,
             5.0, 2.0) for f in (1.0, 1.4) for v in (40, 80) for _ in ("frozen", "free")]
    frame = _table(rows)
    frame["carrier"] = ["frozen", "free"] * 4
    frame["yaw change [deg]"] = (10 * frame["area factor [-]"]
                                 + frame["airspeed EAS [m/s]"] / KNOT / 10
                                 + (frame["carrier"] == "free"))
    for column in ("beta peak [deg]", "yaw rms [deg]", "settling time [s]",
                   "tension / weight max [-]", "hub load from hanging vertical max [deg]",
                   "yaw damping ratio from response [-]"):
        frame[column] = 1.0
    tables = sensitivity_tables(frame, 1.4)
    assert set(tables) == {"parachute area", "airspeed", "carrier"}
    area = tables["parachute area"].set_index("area factor [-]")
    assert_array_equal(area["runs"], [4, 4])
    assert_array_equal(area["stable runs"], [0, 4])
    assert_allclose(area["largest yaw change [deg]"], [19.0, 23.0])
    speed = tables["airspeed"].set_index("airspeed EAS [m/s]")
    assert_array_equal(speed["runs"], [2, 2])
    # the table says which runs it is taken over: those at the selected area factor
    assert_allclose(speed["at area factor [-]"], 1.4)
    assert "at area factor [-]" not in tables["parachute area"]
    assert_allclose(speed["largest yaw change [deg]"], [19.0, 23.0])
    carrier = tables["carrier"].set_index("carrier")
    assert_allclose(carrier.loc[["frozen", "free"], "largest yaw change [deg]"], [22.0, 23.0])
    pairs = carrier_comparison(frame)
    assert len(pairs) == 4
    assert_allclose(pairs["yaw change free - frozen"], 1.0)


# ------------------------------------------------------- neutral area at the towed trim
def test_campaign_neutral_area_is_the_sizings_at_the_towed_trim():
    """On the example, the campaign's neutral area (its base system, 80 KEAS) equals the
    parachute sizing's (its own yaw model, at the towed trim's angle of attack of the
    multibody system at its 80 KEAS) to round-off: both read the fuselage tables at the one
    towed trim (-22.2 deg, docs/parachute-sizing.md), the campaign's trim equal to the
    sizing's, and both about the one suspension axis (the trim's cable line, weight included:
    0.289 m^2, the hand calculation of tests/test_yaw_axis.py). The same model read at alpha 0
    gives a different area (0.451 m^2), and about airframe z (the paper's balance of Mz)
    another (0.612 m^2), so the comparison can fail."""
    from dataclasses import replace

    from slingloads.analyses.campaign import neutral_area_of, yaw_model_of
    from slingloads.analyses.chute_sizing import neutral_area
    from slingloads.io.study import read_study
    from slingloads.runs.chute_sizing import run

    study = read_study(EXAMPLE, ["campaign", "chute sizing", "multibody"])
    campaign = study.inputs.campaign.campaign
    sizing = run(study)
    assert sizing.towed.converged and campaign.neutral_trim.converged
    assert campaign.neutral_trim.alpha == pytest.approx(sizing.towed.alpha, abs=1e-12)
    assert np.degrees(sizing.towed.alpha) == pytest.approx(-22.15, abs=0.01)
    assert campaign.neutral.area == pytest.approx(sizing.static.area, rel=1e-12)
    assert campaign.neutral.area == pytest.approx(0.2886, abs=5e-4)
    assert campaign.neutral_condition.startswith("at the towed trim, alpha -22.2 deg (80 KEAS")
    system, speed = campaign.setup.system, campaign.neutral_trim.airspeed
    model = yaw_model_of(system, speed)
    level = replace(model, condition=replace(model.condition, alpha=0.0))
    at_zero = neutral_area(level, campaign.neutral_fit_range).area
    assert at_zero == pytest.approx(0.4505, abs=5e-4)
    paper = neutral_area(yaw_model_of(system, speed, axis="airframe z"),
                         campaign.neutral_fit_range).area
    assert paper == pytest.approx(0.612, abs=5e-4)
    assert neutral_area_of(system, speed, campaign.neutral_fit_range).area == pytest.approx(
        sizing.static.area, rel=1e-12)


def test_without_a_towed_trim_the_campaign_stays_at_alpha_0_and_says_so(monkeypatch):
    """When no towed trim is found (a stand-in trim that did not converge), the campaign's
    neutral area is that of the same yaw model at alpha 0 (built here directly), and its
    condition text, printed beside the neutral area in the Summary and the decision, says
    alpha 0 and why."""
    from types import SimpleNamespace

    from slingloads.analyses.campaign import campaign as module
    from slingloads.analyses.campaign import yaw_model_of
    from slingloads.analyses.chute_sizing import FIT_RANGE, neutral_area
    from slingloads.analyses.towed_attitude import TowedAttitude
    from slingloads.models.yaw_dynamics import FlightCondition

    failed = TowedAttitude(60 * KNOT, SimpleNamespace(converged=False,
                                                      message="the fuselage table is left"),
                           True)
    monkeypatch.setattr(module, "towed_trim_of", lambda system, speed: failed)
    campaign = tiny()
    model = yaw_model_of(base_system(), 60 * KNOT, 0.0, towed=failed)
    assert model.condition == FlightCondition(60 * KNOT, 0.0, 0.0)
    assert campaign.neutral.area == pytest.approx(neutral_area(model, FIT_RANGE).area,
                                                  rel=1e-12)
    assert campaign.neutral_condition == ("at alpha 0: no towed trim at 60 KEAS, density "
                                          "altitude 0 m (the fuselage table is left)")
    monkeypatch.undo()
    trimmed = tiny()  # the real trim converges at 60 KEAS, 1.7 deg nose down
    assert trimmed.neutral_condition.startswith("at the towed trim")
    assert trimmed.neutral.area != pytest.approx(campaign.neutral.area, rel=1e-3)

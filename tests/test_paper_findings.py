"""The reference paper's findings that this library reproduces on the GENERIC sample aircraft
(``docs/paper-comparison.md``, written by ``benchmarks/paper_comparison.py``), kept from
regressing on a tiny matrix of linear analyses and a few short runs.

Each test names the paper's finding it checks against (section and figure of
``sling-load-parachute-paper.txt``) and, where the finding is not reproduced, the explanation
the comparison gives (which must stay true for the comparison to stay right).
"""

import numpy as np
import pytest

from slingloads.analyses.chute_sizing import neutral_area, run_yaw
from slingloads.analyses.multibody import Manoeuvre, linearise, simulate_runs, trim
from slingloads.constants import FOOT, G0, KNOT
from slingloads.models.aerodynamics import Fin
from slingloads.models.carrier_motion import QuinticStep
from slingloads.models.flight import FlightCondition
from slingloads.models.gusts import make_gust
from slingloads.models.integration import SolverSettings
from slingloads.models.multibody import (
    Cable,
    FreeCarrier,
    HingedParachute,
    LateralHookMotion,
    SlingSystem,
)
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_body,
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
    sample_surfaces,
)
from slingloads.models.yaw_dynamics import YawModel

FIT = (np.radians(-10.0), np.radians(10.0))


def yaw_model(name="HC1", alpha=0.0):
    fin = sample_fin(name)
    return YawModel(sample_fuselage(name),
                    Fin(fin.table, fin.area, fin.centre_of_pressure, fin.efficiency),
                    sample_hardpoints(name), sample_reference(name).yaw_inertia,
                    FlightCondition(80 * KNOT, 0.0, alpha=alpha), Parachute(1.0))


def towed(area, airspeed=80 * KNOT, cable=60 * FOOT, line=10.1, **kw):
    return SlingSystem(sample_body("HC1"), sample_hardpoints("HC1"), Cable(cable, 5e6),
                       sample_fuselage("HC1"), sample_surfaces("HC1"),
                       HingedParachute(Parachute(area, extended_cd_table(), line_length=line)),
                       airspeed=airspeed, **kw)


def stable(system):
    point = trim(system)
    return point.converged and linearise(point).verdict() == "stable"


def boundary(make, low=0.9, high=1.6, tol=0.01):
    assert stable(make(high)) and not stable(make(low))
    while high - low > tol:
        mid = 0.5 * (low + high)
        low, high = (low, mid) if stable(make(mid)) else (mid, high)
    return high


@pytest.fixture(scope="module")
def areas():
    """The neutral area on both slope bases: the +-10 deg least-squares fit (the paper's
    figures 4-5) and the local slope at zero sideslip (the tables' +-2 deg breakpoints)."""
    res = neutral_area(yaw_model(), FIT)
    return res.area_fit, res.area_local


def test_fuselage_unstable_fin_stabilising_and_the_neutral_area(areas):
    """Paper s.4.1, figures 4-5: the fuselage alone is directionally unstable, the cut-down
    fin stabilising, and the moment balance gives a positive parachute area; the local
    slope's area lies above the +-10 deg fit's (the sample's Cn is steepest at beta = 0)."""
    res = neutral_area(yaw_model(), FIT)
    assert res.derivatives["fuselage"] < 0 < res.derivatives["fin"]
    fitted, local = areas
    assert fitted == pytest.approx(0.490, abs=0.002)
    assert 1.10 < local / fitted < 1.15


def test_one_dof_neutral_area_holds_the_gust_at_the_local_slope(areas):
    """Paper s.4.2, figure 7: at 80 KIAS the 1-DOF model at the neutral area rides out the
    30 ft/s gust. Reproduced with the neutral area at the local slope plus 5 %: the yaw comes
    back on heading; at the +-10 deg fit's area the local stiffness is negative and the yaw
    settles several degrees off (a static departure: linear theory, negative stiffness)."""
    fitted, local = areas
    gust = make_gust("finite", 30 * FOOT, 30.0, 10.0)
    runs = run_yaw(yaw_model(), [fitted, 1.05 * local], [gust, gust],
                   settings=SolverSettings(t_end=120.0, step=0.05, output_interval=0.1),
                   fit_range=(np.radians(-15.0), np.radians(15.0)))
    final = np.degrees(runs.histories.psi[:, -1])
    assert abs(final[0]) > 3.0
    assert abs(final[1]) < 1.0


def test_multibody_boundary_is_the_static_neutral_point_whatever_the_carrier_and_cable(areas):
    """Paper s.4.5, figures 10 and 13 (cable, carrier: negligible) and the comparison's
    reason why the paper's +40 % is not reproduced: the smallest stable area of the towed
    system at 80 KEAS lies within 5 % of the 1-DOF local-slope neutral area at the trimmed
    angle of attack, and the cable (18 or 100 ft) and a free carrier move it by less than
    the bisection's 0.01. Paper s.4.1 (definition), how much of the +40 % the neutral
    area's definition accounts for: the boundary lies within 3 % of the local-slope
    area at alpha 0, i.e. 10-15 % above the +-10 deg least-squares area, the part of the
    margin the definition accounts for."""
    fitted, local = areas
    base = boundary(lambda f: towed(f * fitted))
    alpha = trim(towed(base * fitted)).quantity("alpha")
    static = neutral_area(yaw_model(alpha=alpha), FIT).area_local / fitted
    assert base == pytest.approx(static, rel=0.05)
    assert base == pytest.approx(local / fitted, rel=0.03)
    assert 1.10 < base < 1.15
    assert base < 1.3
    for kw in ({"cable": 18 * FOOT}, {"cable": 100 * FOOT},
               {"carrier": FreeCarrier(15000.0, 4.0)}):
        assert boundary(lambda f, kw=kw: towed(f * fitted, **kw)) == pytest.approx(
            base, abs=0.011)


def test_larger_parachute_is_draggier(areas):
    """Paper s.4.5 and conclusion 5: a larger parachute area gives a larger trimmed swing
    angle (the drag proxy) at 100 KEAS."""
    fitted, _ = areas
    swing = [trim(towed(f * fitted, airspeed=100 * KNOT)).swing_angle for f in (1.0, 1.4, 1.8)]
    assert np.all(np.diff(swing) > 0)


def test_lateral_hook_step_keeps_the_mast_load_below_30_deg():
    """Paper s.6, figure 23 and conclusion 7: after a sudden lateral motion of the carrier
    in hover the hub load stays well inside CS 29.865's 30 deg cone (0.5 g peak in 2 s,
    60 ft cable, no parachute)."""
    from slingloads.analyses.campaign import sample_full_tail_system

    step = QuinticStep.from_peak_acceleration(0.5 * G0, 2.0)
    sim = simulate_runs([(sample_full_tail_system("HC1"),
                          Manoeuvre("lateral step", trajectory=LateralHookMotion(step)))],
                        t_end=20.0)
    h = sim.runs[0].to_frame()
    peak = np.nanmax(np.abs(h["hub load from mast [deg]"]))
    assert 1.0 < peak < 15.0


def test_without_parachute_airspeed_matters_only_through_yaw_and_pendulum_coalescence():
    """Paper s.5.3, figures 16-18 (a speed limit without parachute), and the comparison's
    reason: both sides of the static yaw balance scale with q, so a speed limit can only come
    from a dynamic coupling. HC1's full tail with twice its fin area (a stiffer yaw) is stable
    at 30 kt and 80 kt and unstable at 50 kt, in an oscillation at the cable pendulum's
    frequency sqrt(g / (l + e)) (FACTS s.5, k -> 0) within 10 %."""
    from dataclasses import replace

    from slingloads.analyses.campaign import sample_full_tail_system

    base = sample_full_tail_system("HC1")
    fin, tail = base.surfaces
    stiff = base.with_(surfaces=(replace(fin, area=2.0 * fin.area), tail))
    lam = {}
    for v in (30.0, 50.0, 80.0):
        point = trim(stiff.with_(airspeed=v * KNOT))
        ev = linearise(point).eigenvalues
        lam[v] = ev[np.argmax(ev.real)]
    assert lam[30.0].real < 0 and lam[80.0].real < 0 < lam[50.0].real
    hang = float(np.linalg.norm(sample_hardpoints("HC1").hub))   # hub above the CG
    pendulum = np.sqrt(G0 / (60 * FOOT + hang))
    assert abs(lam[50.0].imag) == pytest.approx(pendulum, rel=0.10)


def test_chosen_area_is_stable_whatever_the_airspeed_altitude_and_mass():
    """Paper s.4.5, figures 11-12 and conclusion 4 (airspeed, altitude, weight negligible
    once the area is adequate), as the comparison finds them: at its chosen area, 1.2 x the
    campaign's neutral area (about airframe z at the 80 KEAS towed trim, 0.543 m^2: 0.652
    m^2), the towed system's eigenvalues are stable at 40 and 100 KEAS, at sea level and
    10,000 ft, at the maximum and minimum mass (2,900 and 2,300 kg), on the 18 ft cable; and
    1.0 x the +-10 deg fit area (0.490 m^2) is not, at 40 KEAS (the boundary, 1.145 x)."""
    from slingloads.analyses.campaign import CampaignSetup
    from slingloads.analyses.campaign.setup import neutral_area_of

    neutral = neutral_area_of(towed(1.0), 80 * KNOT, axis="airframe z")
    assert neutral.area == pytest.approx(0.543, abs=0.003)
    setup = CampaignSetup(towed(1.0))
    for v in (40.0, 100.0):
        for h in (0.0, 10000 * FOOT):
            for mass in (2900.0, 2300.0):
                row = {"area [m^2]": 1.2 * 0.543, "carrier": "frozen", "mass [kg]": mass,
                       "cable length [m]": 18 * FOOT, "airspeed EAS [m/s]": v * KNOT,
                       "density altitude [m]": h, "run": "check"}
                assert stable(setup.system_for(row)), (v, h, mass)
    assert not stable(towed(0.490, airspeed=40 * KNOT))


def test_wake_criterion_is_the_papers_and_the_far_wake_line_outruns_its_cables():
    """Paper s.3.2-3.3, figure 3, and the comparison's reason why only the criterion is
    reproduced: the canopy's drag factor is the paper's CD 0.95 over +-8 deg (free-stream CD
    1.0 x the wake ratio 0.95, the loss counted once), the 5 % loss costs exactly 1 / 0.95 in
    neutral area (the parachute's yawing moment is proportional to wake ratio x CD x area),
    and the far-wake law with K = 1 puts the 0.95 point on HC1's drag area where its closed
    form says, K^1.5 sqrt(CD S) / (1 - sqrt(0.95))^1.5, far beyond the longest line the
    paper's cables allow (100 ft / 1.2 = 25.4 m, its 20 % rule of s.4.3). The line's length
    does not decide the stability boundary (5 m and 20 m lines: the same smallest stable area
    at 80 KEAS, to the bisection's 0.01)."""
    from slingloads.analyses.chute_sizing import neutral_area as sizing
    from slingloads.models.wake import BluffBodyWake

    chute = Parachute(1.0, extended_cd_table())
    for deg in (-8.0, -4.0, 0.0, 4.0, 8.0):
        assert chute.effective_coefficient(np.radians(deg)) == pytest.approx(0.95, abs=1e-12)

    def area(ratio):
        fin = sample_fin("HC1")
        model = YawModel(sample_fuselage("HC1"),
                         Fin(fin.table, fin.area, fin.centre_of_pressure, fin.efficiency),
                         sample_hardpoints("HC1"), sample_reference("HC1").yaw_inertia,
                         FlightCondition(80 * KNOT), Parachute(1.0, wake_ratio=ratio))
        return sizing(model, FIT, basis="fit").area

    assert area(0.95) / area(1.0) == pytest.approx(1 / 0.95, rel=1e-9)
    fus = sample_fuselage("HC1")
    cds = float(fus.drag_coefficient(0.0, 0.0)) * fus.area
    line = BluffBodyWake(cds, 1.0).line_length(0.95)
    assert line == pytest.approx(np.sqrt(cds) / (1 - np.sqrt(0.95)) ** 1.5, rel=1e-9)
    assert line > 5 * (100 * FOOT / 1.2)
    fitted = neutral_area(yaw_model(), FIT).area_fit
    short = boundary(lambda f: towed(f * fitted, line=5.0))
    long_ = boundary(lambda f: towed(f * fitted, line=20.0, cable=100 * FOOT))
    assert short == pytest.approx(long_, abs=0.011)


@pytest.fixture(scope="module")
def example_loads():
    """The example light twin's loads study (its workbook: GENERIC airframe, parachute 1.4 x
    its fitted neutral area, 100 KEAS, Nz 2.5, the 30 deg cone, every case with and without
    the parachute), run as it stands and with the lateral hook directions at 7 deg."""
    from pathlib import Path

    import slingloads as sl

    book = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"
    study = sl.read_study(book, only=["loads"]).inputs.loads
    return study, study.run(), study.with_hook(lateral_angle_deg=7.0).run()


def test_parachute_drag_is_the_aft_x_shear_and_the_lateral_cone_governs_y_shear(example_loads):
    """Paper s.6, figures 19-20: the parachute's loads act primarily along X shear (here: aft
    of the mast its cases add a larger share of the |Vx| envelope than of |Vy| and |Vz|, and
    at least half of |Vx| at the station next to the parachute), and the Y shear comes from
    the mast attachment under CS 29.865's cone (|Vy| governed at every station by a lateral
    hook direction). Checked against the rigid body: in a cone case the drag D is reacted by
    the whole airframe's acceleration D / m, so the parachute's own Vx in a cut (the vertical-
    hook pair, with minus without) is D m_fwd / m, within 3 % (the angular relief neglected);
    and with the lateral directions at 7 deg the diagonals govern, whose lateral component is
    sin 45 deg = 0.71 of the lateral direction's, so |Vy| falls to 0.70-0.85 of the 30 deg
    envelope."""
    study, res, reduced = example_loads
    ct = res.case_table()
    hook = ct["hook"].to_numpy(str)
    chute = ct["chute"].to_numpy(bool)
    loads = res.loads
    aft = res.stations > study.airframe.hardpoints.mast_feet[:, 0].max()

    def envelope(k, keep=slice(None), values=loads):
        return np.abs(values[keep, :, k]).max(axis=0)

    share = [1.0 - envelope(k, ~chute)[aft] / envelope(k)[aft] for k in range(3)]
    assert share[0][-1] >= 0.5
    assert np.all(share[0] >= np.maximum(share[1], share[2]) - 1e-12)
    assert set(hook[np.abs(loads[:, :, 1]).argmax(axis=0)]) <= {"AZ090", "AZ270"}
    on, off = (int(np.flatnonzero((hook == "VERTICAL") & (ct["aero"] == "CENTRE")
                                  & (chute == c))[0]) for c in (True, False))
    items = study.airframe.mass_items
    drag = float(study.parachute.drag(study.flight.dynamic_pressure, 0.0))
    m_fwd = np.array([items.mass[items.position[:, 0] < x].sum() for x in res.stations])
    rigid = drag * m_fwd / items.mass.sum()
    np.testing.assert_allclose((loads[on, :, 0] - loads[off, :, 0])[aft], rigid[aft], rtol=0.03)
    ratio = envelope(1, values=reduced.loads) / envelope(1)
    assert np.all((ratio > 0.70) & (ratio < 0.85))
    governing = set(reduced.case_table()["hook"].to_numpy(str)[
        np.abs(reduced.loads[:, :, 1]).argmax(axis=0)])
    assert governing <= {"AZ045", "AZ135", "AZ225", "AZ315"}

"""Multibody model of the towed system: verification against independent references.

References used below:
- the lateral-plane pendulum of the lateral study (``slingloads.models.pendulum``): its
  small-oscillation quartic l k^2 w^4 - g (k^2 + e^2 + e l) w^2 + g^2 e = 0 and its elastic
  cable equations (Meirovitch, Methods of Analytical Dynamics);
- the 1-DOF yaw model of the parachute sizing (``slingloads.models.yaw_dynamics``);
- statics: cable stretch W L / EA, trail angle atan(D / W) of a drag-only body;
- conservation of energy without aerodynamics or damping;
- the damped oscillator: period 2 pi / Im(lambda), damping ratio -Re(lambda) / |lambda| against
  the log decrement of the simulated free response.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from slingloads.analyses.lateral import simulate as lateral_simulate
from slingloads.analyses.multibody import (
    Manoeuvre,
    free_response,
    gust_response,
    linearise,
    simulate,
    trim,
)
from slingloads.analyses.multibody.simulate import _damping_from_peaks
from slingloads.constants import G0, KNOT
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import FUSELAGE_COEFFICIENTS, Fin, FuselageAero
from slingloads.models.airframe import Hardpoints
from slingloads.models.carrier_motion import QuinticStep
from slingloads.models.flight import FlightCondition
from slingloads.models.gusts import FiniteGust
from slingloads.models.integration import SolverSettings
from slingloads.models.multibody import (
    Cable,
    FreeCarrier,
    HingedParachute,
    LateralHookMotion,
    LiftingSurface,
    QuasiStaticParachute,
    RigidBody,
    SlingSystem,
    Wind,
)
from slingloads.models.multibody.rigid_body import (
    euler_angles,
    quaternion_from_euler,
    rotation_matrix,
)
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.pendulum import LateralPendulum, SlungBody, elastic_cable_derivatives
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_reference
from slingloads.models.yaw_dynamics import YawModel, integrate_reference

MASS, IXX, IYY, IZZ, E = 2900.0, 2500.0, 7000.0, 9000.0, 1.0
EA, LENGTH = 5e6, 18.3


def hardpoints(chute=(6.4, 0.0, 1.6)):
    return Hardpoints(hub=[0.0, 0.0, E], mast_feet=[[0.0, 0.0, 0.5]], chute=list(chute))


def bare_system(**kw):
    """Rigid body hung at its hub, no aerodynamics."""
    body = RigidBody(MASS, np.zeros(3), np.diag([IXX, IYY, IZZ]))
    return SlingSystem(body, hardpoints(), Cable(LENGTH, EA, kw.pop("zeta", 0.0)), **kw)


def hc1_system(parachute="hinged", airspeed=80 * KNOT, **kw):
    ref = sample_reference("HC1")
    chute = Parachute(1.1, extended_cd_table())
    kinds = {"hinged": HingedParachute(chute), "quasi-static": QuasiStaticParachute(chute),
             None: None}
    body = RigidBody(ref.mass, np.zeros(3), np.diag([IXX, IYY, ref.yaw_inertia]))
    return SlingSystem(body, hardpoints(ref.chute), Cable(LENGTH, EA), sample_fuselage("HC1"),
                       (LiftingSurface.from_fin(sample_fin("HC1")),), kinds[parachute],
                       airspeed=airspeed, **kw)


# ------------------------------------------------------------------------ kinematics
def test_euler_conventions():
    """docs/conventions.md: yaw nose right turns the aft-pointing x axis towards -Y, pitch nose
    up turns it towards -Z, roll right side down turns body y towards -Z; round trip exact."""
    r = rotation_matrix(quaternion_from_euler(0.3, 0.0, 0.0))
    assert r[1, 0] < 0
    r = rotation_matrix(quaternion_from_euler(0.0, 0.2, 0.0))
    assert r[2, 0] < 0
    r = rotation_matrix(quaternion_from_euler(0.0, 0.0, 0.1))
    assert r[2, 1] < 0
    angles = (0.7, -0.4, 0.25)
    assert_allclose(euler_angles(quaternion_from_euler(*angles)), angles, atol=1e-14)


# ------------------------------------------------------------------------ statics
def test_static_stretch_in_hover():
    """Hanging at rest the cable carries the hung weight (HC plus canopy) and stretches by
    W L / EA; with 2900 + 3 kg, L = 18.3 m, EA = 5e6 N: 0.10624 m."""
    system = bare_system(parachute=HingedParachute(Parachute(1.0, extended_cd_table())))
    tr = trim(system)
    weight = (MASS + 3.0) * G0
    assert tr.converged
    assert_allclose(tr.quantity("cable_span") - LENGTH, weight * LENGTH / EA, rtol=1e-9)
    assert_allclose(tr.quantity("tension"), weight, rtol=1e-10)


def test_trim_swing_angle_of_a_drag_only_body():
    """A body with drag only (CD = 1 on 2 m^2, no side force, lift or moment) trails at
    atan(D / W). At 80 KEAS and 5000 ft density altitude q = 1/2 rho0 V_EAS^2 = 1037.5 Pa, so
    D = 2074.9 N and the swing from the vertical is atan(2074.9 / (2900 g0)) = 4.173 deg.
    Without any moment every heading is an equilibrium (limit case): the trim is flagged
    neutral in yaw, held at the start, and its message says so."""
    alpha, beta = np.radians([-40.0, 40.0]), np.radians([-180.0, 180.0])
    coeffs = {c: np.zeros((2, 2)) for c in FUSELAGE_COEFFICIENTS}
    coeffs["CD"] = np.ones((2, 2))
    fuselage = FuselageAero(Table2D(alpha, beta, coeffs), 2.0, 10.0, np.zeros(3))
    system = bare_system(fuselage=fuselage, airspeed=80 * KNOT, density_altitude=1524.0)
    tr = trim(system)
    drag = 0.5 * 1.225 * (80 * KNOT) ** 2 * 2.0
    assert tr.converged
    assert_allclose(np.tan(tr.swing_angle), drag / (MASS * G0), rtol=1e-8)
    assert_allclose(np.degrees(tr.swing_angle), 4.173, atol=1e-3)
    assert tr.neutral == "yaw" and "nothing fixes the yaw" in tr.message
    assert_allclose(tr.attitude[0], 0.0, atol=1e-9)


# ------------------------------------------------------------------------ small oscillations
@pytest.mark.parametrize("inertia, plane", [(IXX, "lateral swing"),
                                            (IYY, "longitudinal swing")])
def test_small_oscillations_match_the_pendulum_quartic(inertia, plane):
    """Without aerodynamics the swing modes in each vertical plane solve the lateral study's
    quartic l k^2 w^4 - g (k^2 + e^2 + e l) w^2 + g^2 e = 0 (FACTS s.5, models/pendulum.py)
    with k^2 = Ixx/m (lateral) or Iyy/m (longitudinal), l the stretched length; the bounce
    mode has w^2 = (EA/L)/m; the yaw mode is neutral (w = 0)."""
    model = linearise(trim(bare_system()))
    modes = model.modes_frame()
    pendulum = LateralPendulum(SlungBody(MASS, inertia, E), LENGTH, cable_ea=EA)
    expected = pendulum.linear_modes().omega
    plane_modes = modes[modes["mode"].str.startswith(plane)
                        | modes["mode"].str.startswith("roll" if inertia == IXX else "pitch")]
    assert_allclose(np.sort(plane_modes["natural frequency [rad/s]"]), expected[:2],
                    rtol=1e-6)
    bounce = modes[modes["mode"] == "cable stretch"]["natural frequency [rad/s]"]
    assert_allclose(bounce, np.sqrt(EA / LENGTH / MASS), rtol=1e-6)
    assert np.min(np.abs(model.eigenvalues)) < 1e-6


def test_lateral_plane_response_matches_the_pendulum():
    """A lateral quintic step of the hook in hover (no aerodynamics) keeps the motion in the
    lateral plane; hub position and airframe roll equal the lateral pendulum's elastic-cable
    equations integrated by solve_ivp (theta2 = -roll: the pendulum's angle is right-handed
    about +x, the report's roll is right side down), and the lateral study's own run of the
    same body gives the same roll and lateral swing angle, in the same convention."""
    motion = QuinticStep(3.0, 4.0)
    system = bare_system()
    sim = simulate(system, Manoeuvre("step", trajectory=LateralHookMotion(motion)),
                   t_end=12.0, dt=0.005, output_interval=0.05)
    run = sim.runs[0]
    d = run.info[:, 2:5]
    roll = euler_angles(run.states[:, 9:13])[2]
    pend = LateralPendulum(SlungBody(MASS, IXX, E), LENGTH, cable_ea=EA)
    args = pend.arrays()

    def rhs(t, x):
        _, vel, acc = motion.kinematics(t)
        return elastic_cable_derivatives(x, vel, acc, **args)[0]

    x0 = pend.initial_state()
    ref = solve_ivp(rhs, (0, 12.0), x0, t_eval=run.time, rtol=1e-10, atol=1e-12, max_step=0.01)
    assert np.max(np.abs(ref.y[0])) > 0.5  # the hub really swings
    assert_allclose(d[:, 1], ref.y[0], atol=2e-5 * 3.0)
    assert_allclose(d[:, 2], ref.y[1], atol=1e-5)
    assert_allclose(-roll, ref.y[2], atol=2e-5)
    assert_allclose(d[:, 0], 0.0, atol=1e-9)
    # one attitude convention: the lateral study's run of the same body reports the same roll
    # (right side down positive) and the same lateral swing, sign and value
    lateral = lateral_simulate(pend, motion, solver=SolverSettings(
        t_end=12.0, output_interval=0.05, method="DOP853", rtol=1e-10, atol=1e-12))
    assert_allclose(lateral.t, run.time, atol=1e-9)
    assert np.sign(lateral.roll[20]) == np.sign(roll[20]) != 0
    assert_allclose(lateral.roll, roll, atol=2e-5)
    assert_allclose(np.degrees(lateral.theta1), sim.runs[0].to_frame()["swing lateral [deg]"],
                    atol=np.degrees(2e-5))


def test_yaw_alone_matches_the_one_dof_model():
    """Held in translation, roll and pitch (level, straight flight at 80 KEAS), the HC yaws as
    the 1-DOF yaw model of the parachute sizing: same fuselage table (reference point on the
    hub axis), fin at its local sideslip and quasi-static drogue, 10 s lateral gust of
    30 ft/s. The yaw histories agree to 0.01 deg (Dormand-Prince 5(4) at a fixed 0.005 s step
    against the 1-DOF model's solve_ivp at rtol 1e-10)."""
    ref = sample_reference("HC1")
    fus = sample_fuselage("HC1")
    fuselage = FuselageAero(fus.table, fus.area, fus.length, np.array([0.0, 0.0, -0.3]))
    fin = sample_fin("HC1")
    chute = Parachute(0.8)
    hp = hardpoints(ref.chute)
    body = RigidBody(ref.mass, np.zeros(3), np.diag([IXX, IYY, ref.yaw_inertia]))
    system = SlingSystem(body, hp, Cable(LENGTH, EA), fuselage, (LiftingSurface.from_fin(fin),),
                         QuasiStaticParachute(chute), airspeed=80 * KNOT,
                         restrict=("translation", "tilt"))
    gust = FiniteGust(9.144, 2.0, 10.0)
    tr = trim(system)
    level = {"pitch": -tr.attitude[1], "roll": -tr.attitude[2]}
    sim = simulate(system, Manoeuvre("gust", wind=Wind(gust=gust), disturbance=level),
                   t_end=30.0, dt=0.005, output_interval=0.05)
    yaw = sim.runs[0].histories()["yaw"]
    model = YawModel(fuselage, fin, hp, ref.yaw_inertia, FlightCondition(80 * KNOT), chute)
    one = integrate_reference(model, 0.8, gust, settings=SolverSettings(
        t_end=30.0, step=0.005, output_interval=0.05, rtol=1e-10, atol=1e-12))
    assert np.max(np.abs(one.psi[0])) > np.radians(3)
    assert_allclose(np.degrees(yaw), np.degrees(one.psi[0]), atol=0.01)


# ------------------------------------------------------------------------ conservation
def energy(system, states):
    """Kinetic + potential + cable strain energy, computed here from the states (hover)."""
    m, inertia = system.body.mass, system.body.inertia
    chute = system.parachute
    mp, lp = chute.mass, chute.line_length
    attach = system.hardpoints.chute - system.body.cg
    hub = system.hardpoints.hub - system.body.cg
    out = []
    for x in states:
        r = rotation_matrix(x[9:13])
        v, w = x[6:9] - x[0:3], x[13:16]
        th, ps, thd, psd = x[16:20]
        e = np.array([np.cos(th) * np.cos(ps), np.sin(ps), np.sin(th) * np.cos(ps)])
        e_t = np.array([-np.sin(th) * np.cos(ps), 0.0, np.cos(th) * np.cos(ps)])
        e_p = np.array([-np.cos(th) * np.sin(ps), np.cos(ps), -np.sin(th) * np.sin(ps)])
        s = attach + lp * e
        vp = v + r @ (np.cross(w, s) + lp * (e_t * thd + e_p * psd))
        kinetic = 0.5 * m * v @ v + 0.5 * w @ inertia @ w + 0.5 * mp * vp @ vp
        potential = m * G0 * x[5] + mp * G0 * (x[5] + (r @ s)[2])
        span = np.linalg.norm(x[3:6] + r @ hub)
        strain = 0.5 * system.cable.stiffness * max(span - system.cable.length, 0.0) ** 2
        out.append(kinetic + potential + strain)
    return np.array(out)


def test_energy_is_conserved_without_aerodynamics_or_damping():
    """Hover, aerodynamics off (cut-off speed above any speed reached), undamped cable,
    20 kg canopy on its hinged line: the total energy of the swinging, rolling, yawing system
    stays constant: Dormand-Prince 5(4) at a fixed 2 ms step, drift below 1e-8 of the energy
    scale 1/2 m (1 m/s)^2 + the start's (measured 1.4e-10; the adaptive default at rtol 1e-4
    drifts by about 0.6 % in these 10 s)."""
    chute = HingedParachute(Parachute(1.0, extended_cd_table()), mass=20.0)
    system = bare_system(parachute=chute, aero_cutoff=1e3)
    start = {"lateral": 1.0, "longitudinal": -0.5, "roll": 0.1, "yaw_rate": 0.2,
             "theta": 0.4, "psi": 0.3, "vertical": -0.05}
    sim = simulate(system, Manoeuvre("free", disturbance=start), t_end=10.0, dt=0.002,
                   output_interval=0.02)
    total = energy(system, sim.runs[0].states)
    exchanged = np.ptp(energy(system, sim.runs[0].states[:1])) + 0.5 * MASS * 1.0
    assert np.ptp(sim.runs[0].states[:, 4]) > 1.0  # it really swings
    assert np.ptp(total) < 1e-8 * exchanged


# ------------------------------------------------------------------------ limits
def test_free_carrier_of_huge_mass_equals_frozen():
    """A free carrier whose mass is 1e12 kg is not moved by the cable and holds its speed: the
    gust response equals the frozen carrier's (paper figure 13's comparison, in the limit)."""
    gust = gust_response("finite", onset=2.0, duration=5.0)
    frozen = simulate(hc1_system(), gust, t_end=20.0).runs[0].histories()
    heavy = simulate(hc1_system(carrier=FreeCarrier(1e12, 3.0)), gust,
                     t_end=20.0).runs[0].histories()
    for key in ("yaw", "swing lateral", "tension"):
        assert_allclose(heavy[key], frozen[key], rtol=1e-7, atol=1e-9)
    light = simulate(hc1_system(carrier=FreeCarrier(5000.0, 3.0)), gust,
                     t_end=20.0).runs[0].histories()
    assert np.max(np.abs(light["carrier speed"] - frozen["carrier speed"])) > 1e-3


def test_small_canopy_mass_tends_to_the_quasi_static_drogue():
    """As the canopy mass goes to zero the hinged parachute's trim tends to the quasi-static
    (Apollo legacy) drogue's: the drag then acts along the relative wind of the attachment;
    the differences in swing and pitch shrink in proportion to the canopy mass."""
    qs = trim(hc1_system("quasi-static"))
    diffs = []
    for mass in (3.0, 0.3, 0.03):
        system = hc1_system()
        system = system.with_(parachute=HingedParachute(system.parachute.parachute, mass))
        tr = trim(system)
        diffs.append(abs(tr.attitude[1] - qs.attitude[1]))
    assert diffs[2] < 1e-3 * 3
    assert_allclose(diffs[1] / diffs[0], 0.1, rtol=0.05)
    assert_allclose(diffs[2] / diffs[1], 0.1, rtol=0.05)


def test_eigenvalue_matches_the_simulated_free_response():
    """The yaw mode of the linear model (period 2 pi / Im, damping ratio -Re / |lambda|)
    against the period and log decrement of the simulated free response started on that mode
    (0.5 deg of yaw) with the quasi-static drogue at 80 KEAS: within 1 % and 0.005."""
    system = hc1_system("quasi-static")
    model = linearise(trim(system))
    modes = model.modes_frame()
    yaw = modes[modes["mode"].str.startswith("yaw")].iloc[0]
    start = model.mode_state(yaw["real [1/s]"] + 1j * yaw["imag [rad/s]"], np.radians(0.5))
    sim = simulate(system, Manoeuvre("mode", start_state=start), t_end=60.0,
                   dt=0.005, output_interval=0.02)
    h = sim.runs[0].histories()
    period, zeta = _damping_from_peaks(h["time"], h["yaw rate"])
    assert_allclose(period, yaw["period [s]"], rtol=0.01)
    assert_allclose(zeta, yaw["damping ratio [-]"], atol=0.005)


# ------------------------------------------------------------------------ verdicts
def test_a_run_that_leaves_a_table_stops_with_its_verdict_and_the_batch_goes_on():
    """Fuselage table limited to beta +-12 deg: a 30 ft/s gust at 60 kt takes the sideslip
    past it; the run stops (verdict outside domain, table and time named, NaN after), while the
    free response in the same batch runs to the end. No extrapolation."""
    full = sample_fuselage("HC1")
    keep = np.abs(full.table.beta) <= np.radians(12.01)
    table = Table2D(full.table.alpha, full.table.beta[keep],
                    {k: v[:, keep] for k, v in full.table.coefficients.items()})
    fus = FuselageAero(table, full.area, full.length, full.moment_reference)
    system = hc1_system("quasi-static", airspeed=60 * KNOT).with_(fuselage=fus)
    sim = simulate(system, [gust_response("step", onset=1.0),
                            free_response({"yaw": np.radians(2.0)})], t_end=20.0)
    gust, free = sim.runs
    assert gust.stopped and "fuselage table's beta range" in gust.stop_reason()
    assert 1.0 <= gust.stop_time < 20.0
    assert np.isnan(gust.states[-1, 0])
    assert gust.metrics()["verdict"] == "outside domain"
    assert not free.stopped and np.all(np.isfinite(free.states))


def test_trim_without_solution_is_reported_not_a_number():
    """A fuselage table covering only alpha +-1 deg cannot hold the nose-down trim at 80 kt:
    the trim says so (converged False, the table named) and linearise refuses it."""
    full = sample_fuselage("HC1")
    alpha = np.radians([-1.0, 1.0])
    coeffs = {k: np.vstack([full.table.beta_slice(k, a) for a in alpha])
              for k in FUSELAGE_COEFFICIENTS}
    fus = FuselageAero(Table2D(alpha, full.table.beta, coeffs), full.area, full.length,
                       full.moment_reference)
    tr = trim(hc1_system(None).with_(fuselage=fus))
    assert not tr.converged
    assert "alpha" in tr.message
    with pytest.raises(InputError, match="no trim"):
        linearise(tr)


def test_line_reach_against_sampled_directions_and_the_paper_18_ft_cable():
    """The reach of a line streaming aft or hanging (directions e_x >= 0) against a brute-force
    sampling of its points over that half ball; the paper's 18 ft cable (5.49 m, hook nearer
    the hub than the fin attachment 6.4 m aft) is accepted, with the 20 % rule a warning."""
    from slingloads.models.multibody.parachute_line import line_reach

    rng = np.random.default_rng(3)
    e = rng.normal(size=(200_000, 3))
    e /= np.linalg.norm(e, axis=1)[:, None]
    e[:, 0] = np.abs(e[:, 0])
    s = rng.uniform(0.0, 1.0, size=(e.shape[0], 1)) ** (1 / 3)
    for chute, line in (((6.4, 0.0, 0.6), 10.1), ((6.4, 0.0, 0.6), 0.3),
                        ((-1.0, 0.5, 0.2), 0.6), ((2.0, 1.0, -3.0), 1.5)):
        d = np.linalg.norm(np.asarray(chute) + line * s * e, axis=1)
        near, far = line_reach((0.0, 0.0, 0.0), chute, line)
        assert near == pytest.approx(d.min(), abs=0.02 * line)
        assert far == pytest.approx(d.max(), abs=0.02 * line)
        assert d.min() >= near - 1e-9 and d.max() <= far + 1e-9
    short = hc1_system().with_(cable=Cable(18 * 0.3048, EA))
    assert short.warnings() and "too short" in short.warnings()[0]


def test_parachute_that_could_reach_the_carrier_is_refused_and_short_cable_warned():
    """Paper s.4.3: the carrier cable at least 20 % longer than the parachute line (a warning);
    a line that reaches the hook is an error naming both lengths."""
    system = hc1_system().with_(cable=Cable(45.0, EA))  # fin fitting 6.43 m from the hub
    chute = Parachute(1.0, line_length=38.0)             # 45 < 1.2 x 38 = 45.6: warned
    warned = system.with_(parachute=HingedParachute(chute))
    assert warned.warnings() and "too short" in warned.warnings()[0]
    assert system.warnings() == []
    with pytest.raises(InputError, match="could reach the carrier"):  # 39 + 6.43 >= 45
        system.with_(parachute=HingedParachute(Parachute(1.0, line_length=39.0)))
    with pytest.raises(InputError, match="cable length must be > 0"):
        Cable(0.0, EA)
    with pytest.raises(InputError, match="parachute mass must be > 0"):
        HingedParachute(chute, mass=0.0)


def test_fin_from_the_one_dof_model():
    """LiftingSurface.from_fin keeps the fin's table, area, centre of pressure, efficiency."""
    fin = Fin(Table1D(np.radians([-180.0, 180.0]), {"CY": [1.0, -1.0]}), 0.9,
              np.array([5.0, 0.0, 1.0]), 0.5)
    s = LiftingSurface.from_fin(fin)
    assert (s.area, s.efficiency, s.normal) == (0.9, 0.5, "y")


# ------------------------------------------------------------------------ the integrator
def _reference_run(system, manoeuvre, t_end, times):
    """The run by solve_ivp (DOP853, rtol 1e-11) on the same compiled equations, the exact
    drive at every time, split at the input's jumps."""
    from slingloads.analyses.multibody.trim import evaluate_state

    point = trim(system)
    wind, v0 = manoeuvre.wind, point.state[0:3]

    def rhs(t, x):
        drive = np.concatenate([wind.velocity([t])[0], np.zeros(3), v0])
        return evaluate_state(system, x, drive)[0]

    edges = [0.0, *[b for b in manoeuvre.breakpoints if 0 < b < t_end], t_end]
    times = np.round(times, 9)
    state, out = point.state, []
    for k, (a, b) in enumerate(zip(edges[:-1], edges[1:], strict=True)):
        wanted = times[((times >= a) if k == 0 else (times > a)) & (times <= b)]
        grid = wanted if wanted.size and wanted[-1] == b else np.append(wanted, b)
        sol = solve_ivp(rhs, (a, b), state, method="DOP853", rtol=1e-11, atol=1e-12,
                        t_eval=grid)
        out.append(sol.y[:, :wanted.size])
        state = sol.y[:, -1]
    return np.concatenate(out, axis=1).T


def test_adaptive_integration_matches_a_tight_reference():
    """The default (adaptive Dormand-Prince 5(4), rtol 1e-4) run of a 10 s, 30 ft/s lateral
    gust at 80 KEAS equals a DOP853 solution at rtol 1e-11 of the same equations with the
    exact gust (the drive tables, the dense output at the samples and the split at the gust's
    jumps included): largest yaw, lateral swing and hinge-angle errors below 0.05 % of their
    excursions."""
    system = hc1_system()
    gust = gust_response("finite", onset=2.0, duration=5.0)
    sim = simulate(system, gust, t_end=15.0)
    run = sim.runs[0]
    ref = _reference_run(system, gust, 15.0, run.time)
    yaw, yaw_ref = euler_angles(run.states[:, 9:13])[0], euler_angles(ref[:, 9:13])[0]
    assert np.ptp(yaw_ref) > np.radians(5.0)  # a real excursion
    assert np.max(np.abs(yaw - yaw_ref)) < 5e-4 * np.ptp(yaw_ref)
    for k in (4, 17):  # lateral CG position, line angle psi
        assert np.max(np.abs(run.states[:, k] - ref[:, k])) < 5e-4 * np.ptp(ref[:, k])


def test_fixed_step_converges_at_fifth_order():
    """With a fixed step the Dormand-Prince method is of order 5: halving the step divides
    the error against the tight reference by about 2^5 = 32 (accepted 20 to 50). Checked on
    the smooth equations of the body without aerodynamics (piecewise-linear tables make the
    right-hand side only continuous, which caps any method's order), swinging and bouncing
    from an initial offset."""
    system = bare_system()
    start = Manoeuvre("free", disturbance={"lateral": 1.0, "vertical": 0.02,
                                           "yaw_rate": 0.05})
    errors = []
    for dt in (0.04, 0.02):
        run = simulate(system, start, t_end=4.0, dt=dt, output_interval=0.04).runs[0]
        if not errors:
            x0 = run.states[0]
            ref = solve_ivp(lambda t, x: _rates(system, x), (0.0, 4.0), x0, method="DOP853",
                            rtol=1e-12, atol=1e-13, t_eval=np.round(run.time, 9)).y.T
        errors.append(np.max(np.abs(run.states[:, 3:6] - ref[:, 3:6])))
    assert 20 < errors[0] / errors[1] < 50, errors


def _rates(system, x):
    from slingloads.analyses.multibody.trim import evaluate_state

    return evaluate_state(system, x, np.zeros(9))[0]


def test_drive_table_interpolation():
    """The drive tables: a drive linear in time is reproduced exactly (Catmull-Rom with
    quadratic ends reproduces polynomials of degree 1), a 1-cosine gust of 10 s within
    1e-5 of its amplitude (cubic interpolation error ~ h^3 |v'''| with h = 0.01 s), and the
    value at a jump is the one after it at the start of a segment and before it at its
    end, and a channel constant over a segment is its value exactly."""
    from slingloads.models.multibody.integrator import _drive_at, stack_drives, tabulate_drive

    gust = FiniteGust(9.0, 2.0, 3.0)

    def drive(t):
        t = np.asarray(t, float)
        cosine = 0.5 * 9.0 * (1 - np.cos(2 * np.pi * t / 10.0))
        return np.column_stack([gust.velocity(t), 1.5 * t - 2.0, cosine] + [0 * t] * 6)

    d = stack_drives([tabulate_drive(drive, gust.breakpoints, 10.0, 0.1)])
    out = np.empty(9)
    args = (d["a"], d["h"], d["n"], d["offset"], d["values"], d["vary"], d["bend"], out)
    assert d["vary"][0].tolist() == [[False, True, True] + [False] * 6] * 3
    for s, t in ((0, 0.7), (1, 3.33333), (2, 7.891)):
        _drive_at(t, 0, s, *args)
        assert out[1] == pytest.approx(1.5 * t - 2.0, abs=1e-12)
        assert out[2] == pytest.approx(drive([t])[0, 2], abs=1e-5 * 9.0)
        assert out[0] == (9.0 if s == 1 else 0.0) and not out[3:].any()
    _drive_at(2.0, 0, 1, *args)
    assert out[0] == 9.0  # the gust's start: after the jump
    _drive_at(5.0, 0, 1, *args)
    assert out[0] == 9.0  # the end of its segment: before it stops


def test_trims_of_a_batch_equal_single_trims():
    """The batch trims (damped Newton on all at once) equal Powell's hybrid method on each
    system alone: hinged, quasi-static and no parachute, in towed flight and in hover (where
    the yaw is held), with a steady wind."""
    from slingloads.analyses.multibody.trim import trim_many

    systems = [hc1_system("hinged"), hc1_system("quasi-static", 60 * KNOT),
               hc1_system(None, 20 * KNOT), hc1_system("hinged", 100 * KNOT)]
    requests = [(s, None, (0.0, 0.0, 0.0)) for s in systems]
    requests += [(systems[0], 0.0, (0.0, 0.0, 0.0)), (systems[1], None, (0.0, 2.0, 0.0))]
    together = trim_many(requests)
    for (system, speed, wind), point in zip(requests, together, strict=True):
        alone = trim(system, speed, wind=wind)
        assert point.converged and alone.converged
        assert_allclose(point.state, alone.state, atol=1e-8)


# ------------------------------------------------------------------------ trimmed pitch
def hand_pitch_balance(system, airspeed):
    """Pitch angles [rad] at which the towed body's planar moments about its CG balance,
    worked by hand (statics of docs/multibody.md section 8), independent of the equations of
    motion: flow horizontal, so alpha = pitch; fuselage table at beta = 0 (CD, CL along and
    across the flow, Cm about its reference point, nose up +); quasi-static drogue drag
    q eta CD(0) A horizontal at the attachment; the cable pull at the hub closes the force
    polygon, T = -(W + D + L + D_p). Moment about +y (nose up) of a force F at r (earth,
    from the CG): r_z F_x - r_x F_z. Roots located on a 0.1 deg grid and refined by brentq."""
    from scipy.optimize import brentq

    fus, hp, cg = system.fuselage, system.hardpoints, system.body.cg
    column = int(np.argmin(np.abs(fus.table.beta)))
    q = 0.5 * 1.225 * airspeed**2
    chute = system.parachute.parachute

    def coefficient(name, alpha):
        return np.interp(alpha, fus.table.alpha, fus.table.coefficients[name][:, column])

    def moment(pitch):
        c, s = np.cos(pitch), np.sin(pitch)
        turn = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])

        def arm(point, force):
            r = turn @ (np.asarray(point) - cg)
            return r[2] * force[0] - r[0] * force[2]

        aero = q * fus.area * np.array([coefficient("CD", pitch), 0.0,
                                        coefficient("CL", pitch)])
        drogue = np.array([q * chute.drag_area(0.0), 0.0, 0.0])
        cable = -(aero + drogue + np.array([0.0, 0.0, -system.body.mass * G0]))
        return (q * fus.area * fus.length * coefficient("Cm", pitch) + arm(fus.moment_reference,
                aero) + arm(hp.chute, drogue) + arm(hp.hub, cable))

    grid = np.radians(np.arange(-39.9, 10.0, 0.1))
    values = np.array([moment(p) for p in grid])
    return [brentq(moment, a, b, xtol=1e-12) for a, b, fa, fb in
            zip(grid[:-1], grid[1:], values[:-1], values[1:], strict=True) if fa * fb < 0]


@pytest.mark.parametrize("knots", [60.0, 100.0, 120.0])
def test_trimmed_pitch_matches_a_hand_moment_balance(knots):
    """The GENERIC HC1 fuselage alone is unstable in pitch (Cm rising with alpha), so the
    towed helicopter hangs nose down ever more with speed, held by the cable's pull at the hub
    above its CG (here 0.17 m behind it, as in the example: -9 deg in hover). The trimmed
    pitch equals the planar moment balance worked by hand (``hand_pitch_balance``: one root)
    to 1e-6 rad, at 60 and 100 KEAS and at 120 KEAS, where the first starting point of the trim
    fails and the pitch scan finds the equilibrium the hand balance has (about -38 deg, inside
    the table's -40 deg)."""
    ref = sample_reference("HC1")
    body = RigidBody(ref.mass, np.array([-0.17, 0.0, 0.0]), np.diag([IXX, IYY, ref.yaw_inertia]))
    system = SlingSystem(body, hardpoints(ref.chute), Cable(LENGTH, EA), sample_fuselage("HC1"),
                         (LiftingSurface.from_fin(sample_fin("HC1")),),
                         QuasiStaticParachute(Parachute(0.9)))
    speed = knots * KNOT
    roots = hand_pitch_balance(system, speed)
    tr = trim(system, speed)
    assert len(roots) == 1 and tr.converged, tr.message
    assert_allclose(tr.attitude[1], roots[0], atol=1e-6)
    assert np.degrees(roots[0]) < -10.0  # nose down, the unstable fuselage's signature


def test_a_slack_cable_is_reported_and_the_body_falls_freely():
    """Hover, no aerodynamics, undamped cable: raised 0.3 m above its hanging position (the
    static stretch is W L / EA = 0.1041 m) the cable is slack, the helicopter falls freely,
    z(t) = z0 - g t^2 / 2, until the cable is taut again after sqrt(2 (0.3 - 0.1041) / g) =
    0.1999 s; the run reports the slack (from t = 0, for 0.2 s at 0.01 s sampling) and the
    tension is zero meanwhile; then the cable holds it for half a bounce period,
    pi / sqrt(EA / (L m)) = 0.324 s, so it is still taut at 0.5 s."""
    system = bare_system()
    sim = simulate(system, Manoeuvre("drop", disturbance={"vertical": 0.3}), t_end=0.5,
                   dt=0.001, output_interval=0.01)
    run = sim.runs[0]
    h = run.histories()
    stretch = MASS * G0 * LENGTH / EA
    taut_again = np.sqrt(2.0 * (0.3 - stretch) / G0)
    assert_allclose(taut_again, 0.1999, atol=1e-4)
    falling = h["time"] < taut_again - 1e-3
    z = run.states[:, 5]
    assert_allclose(z[falling], z[0] - 0.5 * G0 * h["time"][falling] ** 2, atol=1e-9)
    assert np.all(h["tension"][falling] == 0.0) and h["tension"][-1] > 0.0
    row = sim.metrics_frame().iloc[0]
    assert row["cable slack"] and row["cable slack first at [s]"] == 0.0
    assert_allclose(row["cable slack time [s]"], 0.20, atol=0.011)

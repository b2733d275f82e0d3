"""Lateral pendulum model: verification against closed forms, limits and conservation laws.

The oracles are the analytic results for the planar pendulum with a moving support (rope
length L, rigid body of mass m, radius of gyration k, CG a distance e below the hub):

* small-oscillation frequencies, the roots of L k^2 w^4 - g (k^2 + e^2 + e L) w^2 + g^2 e = 0,
  with the limits w^2 = g/(L + e) as k -> 0 and the compound pendulum w^2 = g e/(k^2 + e^2)
  as L -> 0 (derived from M = m[[L^2, L e], [L e, e^2 + k^2]], K = diag(m g L, m g e));
* point mass under a step in support acceleration a: peak swing 2 atan(a/g);
* point mass under a step in support velocity dV: cos(theta_max) = 1 - dV^2/(2 g L), tension
  m (g + dV^2/L) at the bottom of the swing;
* energy conserved with a fixed support and no damping;
* static tension equal to the weight.
"""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from rk4_references import sweep_numpy

from slingloads.analyses.lateral import simulate, sweep
from slingloads.constants import FOOT, G0
from slingloads.errors import InputError
from slingloads.models.carrier_motion import ConstantAcceleration, QuinticStep, VelocityStep
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import (
    LateralPendulum,
    SlungBody,
    elastic_cable_derivatives,
    hub_load_airframe_axes,
    rigid_rope_derivatives,
)

UH60 = SlungBody(7439.0, 7632.0, 1.722, "UH-60A")  # NASA TM 85890 mass, Ixx, hub above CG
TIGHT = SolverSettings(output_interval=0.005, method="DOP853", rtol=1e-10, atol=1e-12)
FIXED = VelocityStep(0.0)  # the hook does not move


def quartic_omegas(length, k, e, g=G0):
    """Roots of L k^2 w^4 - g (k^2 + e^2 + e L) w^2 + g^2 e = 0, ascending [rad/s]."""
    w2 = np.roots([length * k**2, -g * (k**2 + e**2 + e * length), g**2 * e])
    return np.sort(np.sqrt(w2.real))


@pytest.mark.parametrize("rope_ft", [18.0, 60.0, 100.0])
@pytest.mark.parametrize("body", [UH60, SlungBody(2096.0, 1803.0, 0.95, "BO-105C")])
def test_frequencies_match_closed_form_quartic(body, rope_ft):
    """Rigid-rope frequencies equal the roots of the closed-form quartic (FACTS 5)."""
    pendulum = LateralPendulum(body, rope_ft * FOOT)
    expected = quartic_omegas(rope_ft * FOOT, body.radius_of_gyration, body.cg_below_hub)
    assert_allclose(pendulum.linear_modes().omega, expected, rtol=1e-10)


def test_frequency_limit_point_mass():
    """k -> 0: the low root tends to the simple pendulum of length L + e, w^2 = g/(L + e)."""
    L, e, k = 10.0, 1.5, 1e-4
    pendulum = LateralPendulum(SlungBody(1000.0, 1000.0 * k**2, e), L)
    assert pendulum.linear_modes().omega[0] ** 2 == pytest.approx(G0 / (L + e), rel=1e-6)


def test_frequency_limit_compound_pendulum():
    """L -> 0: the low root tends to the compound pendulum w^2 = g e/(k^2 + e^2)."""
    L, e, k = 1e-7, 1.5, 1.2
    pendulum = LateralPendulum(SlungBody(1000.0, 1000.0 * k**2, e), L)
    assert pendulum.linear_modes().omega[0] ** 2 == pytest.approx(G0 * e / (k**2 + e**2),
                                                                 rel=1e-6)


def test_elastic_cable_modes():
    """Elastic cable: the bounce mode is the spring-mass w^2 = (EA/L)/m, and the swing modes
    are the quartic's with the rope stretched by m g/(EA/L)."""
    ea, L = 2e7, 18.0 * FOOT
    pendulum = LateralPendulum(UH60, L, cable_ea=ea)
    modes = pendulum.linear_modes()
    stretched = L * (1.0 + UH60.mass * G0 / ea)
    expected = quartic_omegas(stretched, UH60.radius_of_gyration, UH60.cg_below_hub)
    assert_allclose(modes.omega[:2], expected, rtol=1e-10)
    assert modes.omega[2] == pytest.approx(np.sqrt(ea / L / UH60.mass), rel=1e-12)
    assert modes.kinds == ("swing", "swing", "bounce")


@pytest.mark.parametrize("mode", [0, 1])
def test_nonlinear_small_swing_period_matches_quartic(mode):
    """Started in a mode shape at 1e-4 rad, the nonlinear equations oscillate at that mode's
    closed-form frequency (quartic root): checks the equations of motion, not only M and K."""
    L = 60.0 * FOOT
    pendulum = LateralPendulum(UH60, L)
    modes = pendulum.linear_modes()
    shape = modes.shapes[mode, :2] * 1e-4
    omega = quartic_omegas(L, UH60.radius_of_gyration, UH60.cg_below_hub)[mode]
    period = 2 * np.pi / omega
    run = simulate(pendulum, FIXED, solver=replace(TIGHT, t_end=5 * period),
                   x0=[shape[0], shape[1], 0.0, 0.0])
    theta = run.theta1
    # upward zero crossings of theta1 (a cosine started at its maximum), interpolated
    i = np.flatnonzero((theta[:-1] < 0) & (theta[1:] >= 0))
    t0 = run.t[i] - theta[i] * (run.t[i + 1] - run.t[i]) / (theta[i + 1] - theta[i])
    assert np.mean(np.diff(t0)) == pytest.approx(period, rel=1e-6)


@pytest.mark.parametrize("accel_g", [0.2, 0.5])
def test_point_mass_acceleration_step_peak_swing(accel_g):
    """Point mass (e = 0) under a step in support acceleration a from rest: the peak swing is
    2 atan(a/g), twice the steady angle (FACTS 5). The swing is away from the motion."""
    L, a = 10.0, accel_g * G0
    pendulum = LateralPendulum(SlungBody(1000.0, 10.0, 0.0), L)
    period = 2 * np.pi * np.sqrt(L / G0)
    run = simulate(pendulum, ConstantAcceleration(a, 10 * period),
                   solver=replace(TIGHT, t_end=1.5 * period))
    expected = 2 * np.arctan(a / G0)
    assert run.metrics.max_rope_angle == pytest.approx(expected, rel=1e-6)
    assert run.theta1.min() == pytest.approx(-expected, rel=1e-6)
    # with the CG at the hub the airframe does not rotate: the load angle is the rope angle
    assert run.metrics.max_load_angle == pytest.approx(expected, rel=1e-6)


def test_point_mass_velocity_step():
    """Point mass under a step dV in support velocity: cos(theta_max) = 1 - dV^2/(2 g L), and
    the tension at the bottom of the swing m (g + dV^2/L) (FACTS 5), rigid rope. (An elastic
    cable would see that tension applied suddenly and overshoot it: not this oracle.)"""
    L, dv = 10.0, 4.0
    pendulum = LateralPendulum(SlungBody(1000.0, 10.0, 0.0), L)
    period = 2 * np.pi * np.sqrt(L / G0)
    run = simulate(pendulum, VelocityStep(dv), solver=replace(TIGHT, t_end=period))
    assert np.cos(run.metrics.max_rope_angle) == pytest.approx(1 - dv**2 / (2 * G0 * L),
                                                               rel=1e-7)
    assert run.metrics.max_tension_ratio == pytest.approx(1 + dv**2 / (G0 * L), rel=1e-9)
    assert run.metrics.t_max_tension_ratio == 0.0


def _energy(run):
    """Kinetic + potential (+ strain) energy from the states, written from the geometry."""
    p = run.pendulum
    m, inertia, e, g = p.body.mass, p.body.roll_inertia, p.body.cg_below_hub, p.gravity
    if p.rigid:
        th1, th2, w1, w2 = run.states
        L = p.rope_length
        vy = L * np.cos(th1) * w1 + e * np.cos(th2) * w2
        vz = L * np.sin(th1) * w1 + e * np.sin(th2) * w2
        z = -L * np.cos(th1) - e * np.cos(th2)
        strain = 0.0
    else:
        ry, rz, th2, vry, vrz, w2 = run.states
        vy = vry + e * np.cos(th2) * w2
        vz = vrz + e * np.sin(th2) * w2
        z = rz - e * np.cos(th2)
        stretch = np.maximum(np.hypot(ry, rz) - p.rope_length, 0.0)
        strain = 0.5 * p.cable_stiffness * stretch**2
    return 0.5 * m * (vy**2 + vz**2) + 0.5 * inertia * w2**2 + m * g * z + strain


def test_energy_conserved_rigid_rope():
    """Fixed support, no damping: total energy is conserved (to 1e-8 of m g L) through a
    large-amplitude swing with both modes excited."""
    pendulum = LateralPendulum(UH60, 18.0 * FOOT)
    run = simulate(pendulum, FIXED, solver=replace(TIGHT, t_end=10.0), x0=[0.6, -0.4, 0.0, 0.5])
    energy = _energy(run)
    scale = pendulum.weight * pendulum.rope_length
    assert np.ptp(energy) < 1e-8 * scale


def test_energy_conserved_elastic_cable_through_slack():
    """Fixed support, no damping, elastic cable started from a large swing that slackens the
    cable: kinetic + potential + strain energy is conserved (the tension-only law is
    conservative)."""
    pendulum = LateralPendulum(UH60, 18.0 * FOOT, cable_ea=2e7)
    x0 = [0.0, -pendulum.hanging_length, 0.0, 7.0, 4.0, 1.5]
    run = simulate(pendulum, FIXED, x0=x0,
                   solver=SolverSettings(t_end=6.0, output_interval=0.002, method="DOP853",
                                         rtol=1e-11, atol=1e-12))
    assert run.metrics.slack  # the case does go slack
    energy = _energy(run)
    assert np.ptp(energy) < 1e-6 * pendulum.weight * pendulum.rope_length


def test_damping_only_dissipates():
    """With aerodynamic damping and a fixed support, energy never increases (dissipation)."""
    pendulum = LateralPendulum(UH60, 18.0 * FOOT, lateral_damping=2000.0, roll_damping=5000.0)
    run = simulate(pendulum, FIXED, solver=replace(TIGHT, t_end=15.0), x0=[0.4, -0.2, 0.0, 0.3])
    energy = _energy(run)
    assert np.all(np.diff(energy) <= 1e-9 * pendulum.weight)
    assert energy[-1] < energy[0]


@pytest.mark.parametrize("cable_ea", [None, 5e8])
def test_damping_power_is_the_dampers_work(cable_ea):
    """Work-energy theorem with the damping applied at a point h = 1.5 m above the CG and a
    fixed hook: dE/dt = -c y_P'^2 - c_r theta2'^2 along the run (y_P' the damped point's
    lateral speed, from the geometry: y_P = y_hub + (e - h) sin theta2), for the rigid rope
    (Lagrange) and the elastic cable (Newton-Euler): the generalised damping forces of each
    derivation do exactly the dampers' work."""
    c, c_r, h = 3000.0, 4000.0, 1.5
    pendulum = LateralPendulum(UH60, 18.0 * FOOT, cable_ea=cable_ea, lateral_damping=c,
                               roll_damping=c_r, damping_height=h)
    r = pendulum.hanging_length                         # swung out 0.3 rad, cable at rest
    x0 = ([0.3, -0.2, 0.0, 0.4] if cable_ea is None else
          [r * np.sin(0.3), -r * np.cos(0.3), -0.2, 0.0, 0.0, 0.4])
    run = simulate(pendulum, FIXED, x0=x0,
                   solver=SolverSettings(t_end=4.0, output_interval=0.001, method="DOP853",
                                         rtol=1e-11, atol=1e-12))
    energy = _energy(run)
    th2, w2 = run.theta2, (run.states[3] if cable_ea is None else run.states[5])
    e = UH60.cg_below_hub
    if cable_ea is None:
        hub_vy = run.pendulum.rope_length * np.cos(run.states[0]) * run.states[2]
    else:
        hub_vy = run.states[3]
    vp = hub_vy + (e - h) * np.cos(th2) * w2
    power = -c * vp**2 - c_r * w2**2
    rate = np.gradient(energy, run.t)
    scale = np.abs(power).max()
    assert_allclose(rate[2:-2], power[2:-2], atol=2e-4 * scale)


def test_lateral_damping_of_a_point_mass_decays_at_the_closed_form_rate():
    """Point mass (CG at the hub, e = 0) on a rope with lateral damping c: m l^2 theta'' +
    c l^2 theta' + m g l theta = 0, so the swing decays as exp(-c t/(2 m)) with the damped
    period 2 pi / sqrt(g/l - (c/2m)^2): successive peaks of a small swing (0.01 rad) have
    the ratio exp(-c T_d/(2 m))."""
    body = SlungBody(1000.0, 1.0, 0.0, "point")
    L, c = 10.0, 400.0
    pendulum = LateralPendulum(body, L, lateral_damping=c)
    sigma = c / (2 * body.mass)
    period = 2 * np.pi / np.sqrt(G0 / L - sigma**2)
    run = simulate(pendulum, FIXED, x0=[0.01, 0.0, 0.0, 0.0],
                   solver=replace(TIGHT, t_end=2.2 * period, output_interval=0.001))
    th = run.theta1
    i1 = int(np.argmax(th[run.t > 0.5 * period])) + int(np.sum(run.t <= 0.5 * period))
    i2 = int(np.argmax(th[run.t > 1.5 * period])) + int(np.sum(run.t <= 1.5 * period))
    assert run.t[i2] - run.t[i1] == pytest.approx(period, abs=2e-3)
    assert th[i2] / th[i1] == pytest.approx(np.exp(-sigma * period), rel=1e-4)


def test_elastic_cable_converges_to_rigid_rope():
    """As EA grows, the elastic cable's peak load angle and peak tension tend to the rigid
    rope's (the rigid-rope limit): EA = 1e6, 1e7, 1e8 N give load-angle differences of about
    8 %, 0.3 %, 0.04 %; the peak tension, which carries the bounce mode's dynamic overshoot,
    converges more slowly."""
    L = 18.0 * FOOT
    motion = QuinticStep.from_peak_acceleration(0.3 * G0, 2.0)
    eas = [1e6, 1e7, 1e8]
    pendulums = [LateralPendulum(UH60, L, cable_ea=ea) for ea in eas]
    pendulums.append(LateralPendulum(UH60, L))
    metrics, _ = sweep(pendulums, [motion] * len(pendulums), solver=SolverSettings(t_end=8.0))
    angle = metrics.max_load_angle
    error = np.abs(angle[:-1] - angle[-1]) / angle[-1]
    assert np.all(np.diff(error) < 0)
    assert error[-1] < 1e-3
    tension_error = np.abs(metrics.max_tension_ratio[:-1] - metrics.max_tension_ratio[-1])
    assert np.all(np.diff(tension_error) < 0)
    assert tension_error[-1] < 5e-3


@pytest.mark.parametrize("cable_ea", [None, 2e7])
def test_static_tension_equals_weight(cable_ea):
    """Hanging at rest under a fixed hook: tension equals the weight, the hub load is axial
    (static equilibrium), and the elastic cable is stretched by m g/(EA/L)."""
    L = 60.0 * FOOT
    pendulum = LateralPendulum(UH60, L, cable_ea=cable_ea)
    run = simulate(pendulum, FIXED, solver=SolverSettings(t_end=5.0))
    assert_allclose(run.tension, UH60.mass * G0, rtol=1e-7)
    fy, fz = run.hub_load
    assert_allclose(fy, 0.0, atol=1e-9 * UH60.mass * G0)
    assert_allclose(fz, UH60.mass * G0, rtol=1e-7)
    if cable_ea is not None:
        assert pendulum.hanging_length - L == pytest.approx(UH60.mass * G0 * L / cable_ea)


def test_hub_load_in_airframe_axes():
    """Hand calculation: 1000 N along a rope 30 deg from the vertical, hub right of the hook,
    pulls the hub up and to the left: with the airframe level, Fy = -500 N, Fz = 866 N; with
    the airframe tilted the same 30 deg, the load is along the mast."""
    fy, fz = hub_load_airframe_axes(1000.0, np.radians(30.0), 0.0)
    assert (fy, fz) == (pytest.approx(-500.0), pytest.approx(1000 * np.sqrt(3) / 2))
    fy, fz = hub_load_airframe_axes(1000.0, np.radians(30.0), np.radians(30.0))
    assert (fy, fz) == (pytest.approx(0.0, abs=1e-12), pytest.approx(1000.0))


@pytest.mark.parametrize("build, match", [
    (lambda: SlungBody(0.0, 1.0, 1.0), r"mass of 'HC' must be > 0 \[kg\]: value 0.0"),
    (lambda: SlungBody(-5.0, 1.0, 1.0), r"mass of 'HC' must be > 0 \[kg\]: value -5.0"),
    (lambda: SlungBody(1.0, 0.0, 1.0), r"roll inertia of 'HC' must be > 0.*value 0.0"),
    (lambda: SlungBody(1.0, -3.0, 1.0), r"roll inertia of 'HC' must be > 0.*value -3.0"),
    (lambda: SlungBody(1.0, 1.0, -0.5), r"CG distance below the hub.*>= 0.*value -0.5"),
    (lambda: SlungBody(float("nan"), 1.0, 1.0), r"mass of 'HC' must be > 0.*value nan"),
    (lambda: LateralPendulum(UH60, 0.0), r"rope length must be > 0 \[m\]: value 0.0"),
    (lambda: LateralPendulum(UH60, -10.0), r"rope length must be > 0 \[m\]: value -10.0"),
    (lambda: LateralPendulum(UH60, 10.0, cable_ea=0.0), r"EA must be > 0.*value 0.0"),
    (lambda: LateralPendulum(UH60, 10.0, lateral_damping=-1.0), r"damping.*value -1.0"),
    (lambda: SolverSettings(method="Euler"), r"valid options.*value 'Euler'"),
    (lambda: SolverSettings(rtol=0.0), r"rtol must be > 0: value 0.0"),
])
def test_bad_model_input(build, match):
    """Bad model input raises InputError naming the rule and echoing the value."""
    with pytest.raises(InputError, match=match):
        build()


def test_load_angle_is_an_angle_between_directions():
    """Regression: an airframe tumbling on a slack cable (theta2 counting whole turns) once gave
    load angles of thousands of degrees; the angle between the cable force and the mast is at
    most 180 deg, and a full extra turn of the airframe does not change it."""
    from slingloads.models.pendulum import load_angle

    assert load_angle(0.1, 0.1 - 2 * np.pi) == pytest.approx(0.0, abs=1e-12)
    assert load_angle(0.0, np.radians(190.0)) == pytest.approx(np.radians(170.0))
    pendulum = LateralPendulum(UH60, 18.0 * FOOT, cable_ea=2e7)
    x0 = [0.0, -pendulum.hanging_length, 0.0, 0.0, 0.0, 12.0]  # airframe spun fast
    run = simulate(pendulum, FIXED, solver=SolverSettings(t_end=4.0), x0=x0)
    assert np.ptp(run.theta2) > 2 * np.pi
    assert np.all(np.abs(run.load_angle) <= np.pi)
    assert run.metrics.max_load_angle <= np.pi


def test_compiled_sweep_equals_the_numpy_sweep():
    """The compiled batch against its reference, the vectorised numpy RK4 batch of
    ``rk4_references.sweep_numpy`` (the scheme written out in numpy): the same scheme on
    the same grid, so every metric agrees to round-off on
    rigid and elastic runs, with damping, a velocity step, constant-acceleration jumps (the
    tension counted on both sides) and a cable going slack."""
    damped = replace(LateralPendulum(UH60, 30 * FOOT), lateral_damping=800.0,
                     roll_damping=2000.0, damping_height=0.7)
    pendulums = [LateralPendulum(UH60, 60 * FOOT), LateralPendulum(UH60, 18 * FOOT, 2e7),
                 damped, replace(damped, cable_ea=5e6), LateralPendulum(UH60, 18 * FOOT, 2e7)]
    motions = [QuinticStep.from_peak_acceleration(0.3 * G0, 2.0),
               ConstantAcceleration(0.4 * G0, 1.5, "stop"), VelocityStep(2.0),
               ConstantAcceleration(-0.2 * G0, 3.0, "hold"),
               ConstantAcceleration(1.5 * G0, 1.0, "stop")]
    solver = SolverSettings(t_end=12.0)
    fast, h_fast = sweep(pendulums, motions, solver=solver)
    ref, h_ref = sweep_numpy(pendulums, motions, solver=solver)
    assert h_fast == h_ref
    assert ref.slack.any()  # the hard stop slackens the short elastic cable
    for name in ("max_load_angle", "t_max_load_angle", "max_rope_angle", "t_max_rope_angle",
                 "max_tension_ratio", "t_max_tension_ratio", "min_tension_ratio",
                 "max_side_force_ratio", "t_max_side_force_ratio"):
        assert_allclose(getattr(fast, name), getattr(ref, name), rtol=1e-12, atol=1e-12,
                        err_msg=name)


def _floats(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_subnormal=False)


@settings(max_examples=300, deadline=None)
@given(rigid=st.booleans(),
       state=st.lists(_floats(-20.0, 20.0), min_size=6, max_size=6),
       hook=st.lists(_floats(-50.0, 50.0), min_size=2, max_size=2),
       body=st.tuples(_floats(1.0, 1e5), _floats(0.01, 1e3), _floats(0.0, 5.0)),
       cable=st.tuples(_floats(0.5, 100.0), _floats(1e4, 1e9)),
       damping=st.tuples(_floats(0.0, 1e5), _floats(0.0, 1e5), _floats(-3.0, 3.0)))
def test_compiled_equations_are_the_numpy_equations(rigid, state, hook, body, cable, damping):
    """The compiled scalar equations (pendulum_batch.rigid_rope, elastic_cable: the sweep's,
    and the solve_ivp runs' right-hand side) against the numpy equations of this module (the
    ones the closed-form tests above verify), at random states, hook motions, bodies, cables
    and damping: the same derivative and tension to the last bit, as the compiled module says
    (operation for operation, no fast-math, the same C library sin, cos and sqrt)."""
    from slingloads.models import pendulum_batch

    mass, k2, e = body
    length, ea = cable
    pendulum = LateralPendulum(SlungBody(mass, mass * k2, e), length,
                               cable_ea=None if rigid else ea, lateral_damping=damping[0],
                               roll_damping=damping[1], damping_height=damping[2])
    x = np.array(state[:4] if rigid else state)
    if not rigid:
        x[1] -= length  # about the hanging length: taut or slack
        # the hub at the hook is 0/0 (test_lateral_study); within 1e-150 m of it the squared
        # distance underflows to 0 as well (hypothesis found 1e-170 m): a micrometre apart
        assume(np.hypot(x[0], x[1]) > 1e-6)
    params = pendulum.arrays()
    row = np.array([params[name] for name in pendulum_batch.PARAMETERS])
    compiled = pendulum_batch.rigid_rope if rigid else pendulum_batch.elastic_cable
    reference = rigid_rope_derivatives if rigid else elastic_cable_derivatives
    dx = np.empty(x.size)
    tension = compiled(x, hook[0], hook[1], row, dx)
    dx_ref, tension_ref = reference(x[:, None], np.asarray(hook[0]), np.asarray(hook[1]),
                                    **params)
    np.testing.assert_array_equal(dx, dx_ref[:, 0])
    assert tension == tension_ref[0]


@pytest.mark.parametrize("cable_ea", [None, 5e6])
def test_roll_follows_the_attitude_convention_small_angle_closed_form(cable_ea):
    """The airframe's ``roll`` of a lateral run is the product's attitude angle (right side
    down positive, docs/conventions.md section 8), checked against the small-angle
    Lagrangian written here from scratch, M q'' + K q = -m (L, e) S'' with
    M = m[[L^2, L e], [L e, e^2 + k^2]], K = diag(m g L, m g e) in the right-hand angles
    q = (theta1, theta2) (L the statically stretched length m g L0 / EA + L0 for the elastic
    cable), and roll = -theta2. A small hook step to the right first leaves the
    hub behind (theta1 < 0) and pulls it right of the CG: the airframe rolls right side down
    (roll > 0) while the rope leans left, and the columns of ``to_frame`` say so."""
    from scipy.integrate import solve_ivp

    body, length = UH60, 15.0
    motion = QuinticStep(0.02, 3.0)  # 2 cm: the small-angle equations hold to ~1e-3
    run = simulate(LateralPendulum(body, length, cable_ea), motion,
                   solver=replace(TIGHT, t_end=4.0))
    m, e, k2 = body.mass, body.cg_below_hub, body.roll_inertia / body.mass
    if cable_ea:
        length += m * G0 * length / cable_ea
    mass = m * np.array([[length**2, length * e], [length * e, e**2 + k2]])
    stiff = np.diag([m * G0 * length, m * G0 * e])
    force = -m * np.array([length, e])

    def rhs(t, x):
        acc = motion.kinematics(t)[2]
        return np.concatenate([x[2:], np.linalg.solve(mass, force * acc - stiff @ x[:2])])

    ref = solve_ivp(rhs, (0.0, 4.0), np.zeros(4), t_eval=run.t, rtol=1e-11, atol=1e-14)
    roll_ref = -ref.y[1]
    scale = np.max(np.abs(roll_ref))
    assert scale > 1e-5
    assert_allclose(run.roll, roll_ref, atol=2e-3 * scale)
    early = run.t <= 1.0
    assert np.all(run.roll[early][1:] > 0) and np.all(run.theta1[early][1:] < 0)
    frame = run.to_frame()
    assert_allclose(frame["roll [deg]"], np.degrees(roll_ref), atol=np.degrees(2e-3 * scale))
    assert "theta2 [deg]" not in frame

"""Carrier lateral motions S(t): closed forms, calculus consistency and bad input."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import cumulative_trapezoid

from slingloads.errors import InputError
from slingloads.models.carrier_motion import (
    ConstantAcceleration,
    CycloidalStep,
    MotionBatch,
    QuinticStep,
    TimeHistory,
    VelocityStep,
    make_motion,
)


def _integrate_twice(t, acc):
    vel = cumulative_trapezoid(acc, t, initial=0.0)
    return cumulative_trapezoid(vel, t, initial=0.0), vel


def test_quintic_step_closed_form():
    """Quintic minimum-jerk step: S(T) = A, S'(T) = S''(T) = 0, S(T/2) = A/2, and peak
    acceleration (10/sqrt 3) A/T^2 at tau = (3 - sqrt 3)/6 (from d3S/dt3 = 0 by hand)."""
    step = QuinticStep(amplitude=12.0, duration=3.0)
    s, v, a = step.kinematics(np.array([3.0, 1.5, 10.0]))
    assert_allclose(s, [12.0, 6.0, 12.0], rtol=1e-14)
    assert_allclose(v[[0, 2]], 0.0, atol=1e-14)
    assert_allclose(a[[0, 2]], 0.0, atol=1e-14)
    tau = (3.0 - np.sqrt(3.0)) / 6.0
    assert step.acceleration(tau * 3.0) == pytest.approx(10.0 / np.sqrt(3.0) * 12.0 / 9.0,
                                                           rel=1e-12)
    assert step.peak_acceleration == pytest.approx(10.0 / np.sqrt(3.0) * 12.0 / 9.0, rel=1e-12)
    made = QuinticStep.from_peak_acceleration(4.9, 2.0)
    assert made.peak_acceleration == pytest.approx(4.9, rel=1e-12)


def test_cycloidal_step_closed_form():
    """Cycloidal step S = A (tau - sin(2 pi tau)/(2 pi)) by hand, A = 12 m, T = 3 s:
    S(T) = A, S(T/2) = A/2, S(T/4) = A (1/4 - 1/(2 pi)) = 1.09014 m; S' = A/T (1 - cos 2 pi
    tau), 8 m/s at T/2 (= 2 A/T); S'' = 2 pi A/T^2 sin 2 pi tau, peak 2 pi x 12/9 =
    8.37758 m/s^2 at T/4, zero at both ends and at T/2."""
    step = CycloidalStep(amplitude=12.0, duration=3.0)
    s, v, a = step.kinematics(np.array([0.75, 1.5, 3.0, 10.0]))
    assert_allclose(s, [12.0 * (0.25 - 1.0 / (2.0 * np.pi)), 6.0, 12.0, 12.0], rtol=1e-14)
    assert_allclose(v, [4.0, 8.0, 0.0, 0.0], atol=1e-13)
    assert_allclose(a, [8.37758040957278, 0.0, 0.0, 0.0], atol=1e-12)
    assert step.peak_acceleration == pytest.approx(2.0 * np.pi * 12.0 / 9.0, rel=1e-14)
    assert CycloidalStep.from_peak_acceleration(4.9, 2.0).amplitude == pytest.approx(
        4.9 * 4.0 / (2.0 * np.pi), rel=1e-14)
    assert step.breakpoints == (0.0, 3.0)


def test_steps_are_named_for_their_laws():
    """Each step is named for its law; the quintic step's former name is still read."""
    assert make_motion("smooth_step", amplitude=1.0, duration=2.0) == QuinticStep(1.0, 2.0)
    assert make_motion("cycloidal_step", amplitude=1.0, duration=2.0) == CycloidalStep(1.0,
                                                                                       2.0)
    assert "cycloidal step" in CycloidalStep(1.0, 2.0).describe()
    assert "quintic step" in QuinticStep(1.0, 2.0).describe()


@pytest.mark.parametrize("motion", [
    QuinticStep(5.0, 2.0),
    CycloidalStep(-4.0, 1.5),
    ConstantAcceleration(2.0, 1.5, "hold"),
    ConstantAcceleration(-3.0, 1.0, "stop"),
])
def test_velocity_and_displacement_are_integrals_of_acceleration(motion):
    """Calculus check: integrating S'' twice by the trapezoid rule (an independent quadrature)
    recovers S' and S, from rest at S = 0 (the trapezoid rule errs by h |jump| / 2 across a
    jump of the acceleration, 1.5e-4 m/s here)."""
    t = np.linspace(0.0, 5.0, 50001)
    s, v, a = motion.kinematics(t)
    s_num, v_num = _integrate_twice(t, a)
    assert_allclose(v_num, v, atol=5e-4)
    assert_allclose(s_num, s, atol=5e-4 * 5.0)


def test_constant_acceleration_closed_form():
    """Uniform acceleration: after T, S = a T^2 / 2 and S' = a T; holding speed, S grows by
    a T per second; stopping at -a for T, the hook ends at rest at a T^2."""
    hold = ConstantAcceleration(2.0, 3.0, "hold")
    assert_allclose(hold.kinematics(3.0), [9.0, 6.0, 0.0])
    assert hold.displacement(5.0) == pytest.approx(9.0 + 12.0)
    stop = ConstantAcceleration(2.0, 3.0, "stop")
    assert_allclose(stop.kinematics(7.0), [18.0, 0.0, 0.0], atol=1e-12)
    assert stop.acceleration(4.0) == -2.0
    assert stop.end_time == 6.0


def test_velocity_step():
    """Velocity step dV: S = dV t after t = 0, no acceleration after the jump."""
    step = VelocityStep(3.0)
    assert_allclose(step.kinematics(2.0), [6.0, 3.0, 0.0])
    assert step.velocity_jump == 3.0


def test_time_history_reproduces_a_sampled_quintic_step():
    """A finely sampled quintic step fed back as a time history: the spline passes through the
    samples and its acceleration matches the analytic quintic's to 1 % of the peak."""
    step = QuinticStep(10.0, 4.0)
    t = np.linspace(0.0, 6.0, 601)
    history = TimeHistory(t + 2.0, step.displacement(t) + 1.0)  # shifted to start at 0, 0
    assert_allclose(history.displacement(t), step.displacement(t), atol=1e-12)
    mid = np.linspace(0.1, 3.9, 77)
    assert_allclose(history.acceleration(mid), step.acceleration(mid),
                    atol=0.01 * step.peak_acceleration)
    assert abs(history.velocity_jump) < 1e-3
    # beyond the last sample: the final speed is kept, no acceleration
    assert history.acceleration(10.0) == 0.0


def test_motion_batch_matches_closed_forms():
    """A batch of mixed motions evaluated at one time equals each motion's closed form:
    S'' = a for constant acceleration, dV t for the velocity step, A/2 at mid quintic step."""
    history = TimeHistory([0.0, 1.0, 2.0], [0.0, 0.0, 0.0])
    motions = [ConstantAcceleration(1.0, 2.0), ConstantAcceleration(-2.0, 2.0, "stop"),
               VelocityStep(4.0), QuinticStep(6.0, 1.0), history, history]
    s, v, a = MotionBatch(motions).kinematics(0.5)
    assert_allclose(a[:2], [1.0, -2.0])
    assert_allclose(s[2:4], [2.0, 3.0])
    assert_allclose(s[4:], 0.0)
    assert_allclose(MotionBatch(motions).velocity_jump, [0, 0, 4.0, 0, 0, 0])


def test_make_motion_by_name():
    """The workbook route: a type name and SI parameters give the same motion object."""
    motion = make_motion("constant_acceleration", rate=4.9, duration=2.0, then="stop")
    assert motion == ConstantAcceleration(4.9, 2.0, "stop")


@pytest.mark.parametrize("build, match", [
    (lambda: make_motion("zigzag", duration=1.0), r"unknown carrier motion type.*'zigzag'"),
    (lambda: make_motion("smooth_step", amplitude=1.0, duration=1.0, speed=3.0),
     r"unknown parameter: value 'speed'"),
    (lambda: QuinticStep(1.0, 0.0), r"duration must be > 0 \[s\]: value 0.0"),
    (lambda: ConstantAcceleration(1.0, -2.0), r"duration must be > 0 \[s\]: value -2.0"),
    (lambda: ConstantAcceleration(1.0, 2.0, "coast"), r"valid options.*'coast'"),
    (lambda: VelocityStep(float("nan")), r"velocity step must be a finite number"),
    (lambda: TimeHistory([0.0, 1.0, 1.0, 2.0], [0, 1, 2, 3]),
     r"strictly increasing; sample 3 \(t = 1 s\).*value 1.0"),
    (lambda: TimeHistory([0.0, 2.0, 1.0], [0, 1, 2]),
     r"strictly increasing; sample 3 \(t = 1 s\).*value 1.0"),
    (lambda: TimeHistory([0.0, 1.0], [0.0]), r"one displacement per time"),
    (lambda: TimeHistory([0.0], [0.0]), r"at least two samples"),
])
def test_bad_motion_input(build, match):
    """Bad motion input raises InputError naming the rule and echoing the value."""
    with pytest.raises(InputError, match=match):
        build()


_SAMPLED = np.linspace(0.0, 4.0, 41)
_RAMP = np.linspace(0.3, 5.0, 60)
_IRREGULAR = np.sort(np.random.default_rng(7).uniform(0.0, 10.0, 300))


@pytest.mark.parametrize("motion", [
    QuinticStep(3.0, 4.0), QuinticStep(-1.3, 0.7), CycloidalStep(-2.0, 1.5),
    CycloidalStep(1.1, 3.3), ConstantAcceleration(2.0, 3.0, "hold"),
    ConstantAcceleration(-4.9, 1.3, "stop"), VelocityStep(2.0), VelocityStep(-0.3),
    TimeHistory(_SAMPLED, QuinticStep(3.0, 4.0).displacement(_SAMPLED), name="sampled step"),
    TimeHistory(_RAMP, 0.7 * (_RAMP - 0.3) + 0.2 * np.sin(3.0 * _RAMP), name="ramp"),
    TimeHistory(_IRREGULAR, np.random.default_rng(8).normal(size=300), name="irregular"),
], ids=lambda m: m.describe())
def test_kinematics_at_is_kinematics_in_floats(motion):
    """The scalar fast path kinematics_at gives the same doubles as kinematics at that one
    time (numpy's path the solve_ivp runs took before it), at random times before, inside and
    after the motion, exactly at and one ulp either side of its breakpoints, at a time
    history's samples, and at -0.0; and floats, not numpy scalars. Against kinematics on a
    whole array of times (numpy computes powers of arrays by other means) it agrees to the
    last place or so."""
    end = max(motion.breakpoints)
    rng = np.random.default_rng(0)
    special = [np.nextafter(b, side) for b in motion.breakpoints
               for side in (-np.inf, b, np.inf)]
    times = np.concatenate([rng.uniform(-1.0, 2.0 * end + 1.0, 3000), special,
                            [-0.0, 0.0, 2.0 * end, 50.0], getattr(motion, "time", [])])
    fast = np.array([motion.kinematics_at(t) for t in times]).T
    one_by_one = np.array([[float(x) for x in motion.kinematics(t)] for t in times]).T
    np.testing.assert_array_equal(fast, one_by_one)
    assert all(type(x) is float for x in motion.kinematics_at(np.float64(0.3 * end)))
    assert_allclose(fast, np.stack(motion.kinematics(times)), rtol=1e-15)

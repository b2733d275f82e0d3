"""The lateral-step pendulum: single runs, per-run metrics and the design-angle study.

CS-29.865 asks for the hook load applied at the largest angle from the mast that can be
achieved in service, and not less than 30 deg unless it is shown that a smaller angle cannot
be exceeded. This module makes that showing: it moves the carrier's hook sideways
(:mod:`slingloads.models.carrier_motion`), integrates the lateral pendulum
(:mod:`slingloads.models.pendulum`), and takes the largest load angle
:math:`|\\theta_1 - \\theta_2|` over a sweep of motions, rope lengths and mass properties.
The recommended design angle is that maximum times a stated margin.

Two integrators:

* :func:`simulate`: one run with :func:`scipy.integrate.solve_ivp` (settings in
  :class:`~slingloads.models.integration.SolverSettings`: ``method``, ``rtol``, ``atol``,
  ``max_step``, ``t_end``, ``output_interval``), integrated piecewise between the motion's
  breakpoints; gives time histories.
* :func:`sweep`: many runs at once, the fixed-step classical Runge-Kutta (RK4) step of
  :mod:`slingloads.models.runge_kutta` in compiled code, the runs spread over the cores;
  gives the per-run metrics. Its step is chosen from the fastest natural mode unless given
  (``SolverSettings.step``).

References
----------
.. [1] EASA CS-29, CS 29.865 "External loads"; 14 CFR 29.865(a).
.. [2] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993 (RK4, section II.1; dense output, section II.6).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, fields, replace

import numpy as np
import pandas as pd

from slingloads.analyses.lateral_damping import LateralDamping
from slingloads.constants import FOOT, G0
from slingloads.errors import InputError
from slingloads.limits import (
    MAX_HISTORY_OUTPUT,
    MAX_LATERAL_MOTION_STEPS,
    MAX_LATERAL_RUN_STEPS,
    MAX_LATERAL_STEPS,
    check_count,
    evaluation_budget,
)
from slingloads.models.airframe import hanging_roll_axis
from slingloads.models.carrier_motion import (
    MOTION_ALIASES,
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
    TimeHistory,
    VelocityStep,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import (
    LateralPendulum,
    SlungBody,
    airframe_angle,
    hub_load_airframe_axes,
    load_angle,
    rope_angle,
)

#: CS-29.865 minimum angle of the hook load from the mast. [rad]
REGULATORY_ANGLE = np.radians(30.0)
#: Domain of the lateral pendulum: the cable stays taut (T > 0 throughout), the rope angle
#: from the vertical stays below this (past it the hub is above the hook's horizontal: the
#: body goes over the top, a motion no carrier flies and a cable that only pulls cannot
#: hold), and the hub load's angle from the mast stays below it (past 90 deg the cable pulls
#: the hub from below its own horizontal plane: no hook load case). [rad]
DOMAIN_ANGLE = np.radians(90.0)

#: Default largest bank angle of the carrier: 20 deg, the limit of damaged-helicopter
#: recovery under CH-47 / UH-60 (US Army TM 1-1670-260-12&P, "about 30-40 KIAS, 20 deg bank").
#: [rad]
BANK_LIMIT = np.radians(20.0)
#: Default largest roll rate of the carrier: 10 deg/s, an engineering assumption (no
#: published limit for sling-load recovery was found): a gentle roll for a carrier with an
#: external load; set it to the operation's own limit. [rad/s]
ROLL_RATE_LIMIT = np.radians(10.0)


@dataclass(frozen=True)
class CarrierLimits:
    """What a pilot can fly laterally: a coordinated carrier banked phi accelerates sideways
    at a_y = g tan(phi), so the bank and roll-rate limits bound the hook's lateral
    acceleration, |S''| <= g tan(phi_max), and its rate, |S'''| <= g sec^2(phi_max) p_max.

    Parameters
    ----------
    bank : float
        Largest bank angle, 0 < bank < 90 deg. [rad]
    roll_rate : float
        Largest roll rate, > 0. [rad/s]
    gravity : float
        [m/s^2]
    carrier_mass : float
        Mass of the carrier, for the frozen-carrier check (NaN: not checked). [kg]
    """

    bank: float = BANK_LIMIT
    roll_rate: float = ROLL_RATE_LIMIT
    gravity: float = G0
    carrier_mass: float = float("nan")

    def __post_init__(self):
        bank, rate = float(self.bank), float(self.roll_rate)
        if not (np.isfinite(bank) and 0 < bank < np.pi / 2):
            raise InputError("carrier bank-angle limit must lie in (0, 90) deg",
                             np.degrees(bank))
        if not (np.isfinite(rate) and rate > 0):
            raise InputError("carrier roll-rate limit must be > 0 [deg/s]", np.degrees(rate))
        object.__setattr__(self, "bank", bank)
        object.__setattr__(self, "roll_rate", rate)

    @property
    def acceleration(self):
        """Largest lateral acceleration g tan(phi_max). [m/s^2]"""
        return self.gravity * np.tan(self.bank)

    @property
    def jerk(self):
        """Largest rate of lateral acceleration g sec^2(phi_max) p_max. [m/s^3]"""
        return self.gravity * self.roll_rate / np.cos(self.bank) ** 2

    def describe(self):
        """The limits in words.

        Returns
        -------
        str
            Bank [deg], peak acceleration [m/s^2 and g], roll rate [deg/s] and peak jerk [m/s^3].
        """
        return (f"bank <= {np.degrees(self.bank):.3g} deg (peak S'' <= "
                f"{self.acceleration:.3g} m/s^2 = {self.acceleration / self.gravity:.3g} g), "
                f"roll rate <= {np.degrees(self.roll_rate):.3g} deg/s (peak jerk <= "
                f"{self.jerk:.3g} m/s^3)")


def peak_jerk(motion):
    """Largest |S'''| of a carrier motion [m/s^3]: inf for a motion whose acceleration jumps
    (constant acceleration, velocity step); 60 A/T^3 for a quintic step and (2 pi)^2 A/T^3 for
    a cycloidal one (the derivatives of their laws at the start); the largest slope of a
    time history's piecewise-linear spline acceleration.

    Parameters
    ----------
    motion : carrier motion
        A motion of :mod:`slingloads.models.carrier_motion`.

    Returns
    -------
    float
        [m/s^3]
    """
    if isinstance(motion, (ConstantAcceleration, VelocityStep)):
        return np.inf
    if isinstance(motion, QuinticStep):
        return 60.0 * abs(motion.amplitude) / motion.duration**3
    if isinstance(motion, CycloidalStep):
        return (2 * np.pi) ** 2 * abs(motion.amplitude) / motion.duration**3
    if isinstance(motion, TimeHistory):
        t = np.asarray(motion.time, float)
        a = np.asarray(motion.acceleration(t), float)
        return float(np.max(np.abs(np.diff(a) / np.diff(t)))) if t.size > 1 else 0.0
    return np.nan


def flyable(motion, limits=None):
    """'' if the carrier can fly ``motion`` within ``limits`` (:class:`CarrierLimits`), else
    why, with the numbers.

    Parameters
    ----------
    motion : carrier motion
        A motion of :mod:`slingloads.models.carrier_motion`.
    limits : CarrierLimits, optional
        The carrier's limits (default :class:`CarrierLimits`).

    Returns
    -------
    str
        '' if flyable, else the limits passed with the numbers.
    """
    limits = CarrierLimits() if limits is None else limits
    acc = float(getattr(motion, "peak_acceleration", np.nan))
    jerk = peak_jerk(motion)
    why = []
    if not acc <= limits.acceleration * (1 + 1e-9):
        why.append(f"peak acceleration {acc:.3g} m/s^2 ({acc / limits.gravity:.3g} g) above "
                   f"g tan({np.degrees(limits.bank):.3g} deg) = {limits.acceleration:.3g} "
                   "m/s^2")
    if not jerk <= limits.jerk * (1 + 1e-9):
        why.append(f"peak jerk {jerk:.3g} m/s^3 above {limits.jerk:.3g} m/s^3 (roll rate "
                   f"{np.degrees(limits.roll_rate):.3g} deg/s)")
    return "; ".join(why)


#: Largest lateral cable force over the carrier's weight for which the carrier is taken to
#: follow its prescribed path (the frozen carrier of the paper's figure 13): beyond, the
#: load would push the carrier off it by more than a tenth of g. [-]
CARRIER_FORCE_LIMIT = 0.1

#: The paper's rope lengths, 18, 60 and 100 ft. [m]
PAPER_ROPE_LENGTHS = tuple(ft * FOOT for ft in (18.0, 60.0, 100.0))
#: A default sweep of carrier peak accelerations, 0.1 to 0.5 g. [m/s^2]
DEFAULT_ACCELERATIONS = tuple(n * G0 for n in (0.1, 0.2, 0.3, 0.4, 0.5))
#: A default sweep of motion durations. [s]
DEFAULT_DURATIONS = (0.5, 1.0, 2.0, 4.0)

#: Default interval of the time histories of single runs. [s]
OUTPUT_INTERVAL = 0.01


def _refine(y0, y1, y2):
    """Vertex of the parabola through equally spaced samples (y0, y1, y2) around a peak y1.

    Returns (value, offset in steps from the middle sample, within [-1/2, 1/2]).
    """
    curvature = y0 - 2.0 * y1 + y2
    safe = np.where(curvature < 0, curvature, -1.0)
    offset = np.where(curvature < 0, np.clip(0.5 * (y0 - y2) / safe, -0.5, 0.5), 0.0)
    return y1 - 0.25 * (y0 - y2) * offset, offset


def _peak(t, y, valid=None, smooth=None):
    """Largest value of a sampled signal ``y`` (last axis) with its time, parabola-refined.

    Parameters
    ----------
    t : ndarray, shape (n,)
        Equally spaced times. [s]
    y : ndarray, shape (..., n)
    valid : ndarray of bool, shape (..., n), optional
        Samples that count (default all).
    smooth : ndarray of bool, shape (..., n), optional
        Samples where the signal is smooth (default ``valid``); a peak is refined only where
        its three samples are smooth and count (a parabola through a kink, such as the cable
        going slack, would overshoot).

    Returns
    -------
    value, time : ndarray, shape (...)
        NaN where no sample counts.
    """
    y = np.asarray(y, dtype=float)
    valid = np.ones(y.shape, bool) if valid is None else np.broadcast_to(valid, y.shape)
    ok = valid if smooth is None else valid & np.broadcast_to(smooth, y.shape)
    h = t[1] - t[0]
    masked = np.where(valid, y, -np.inf)
    i = np.argmax(masked, axis=-1)
    value = np.take_along_axis(masked, i[..., None], axis=-1)[..., 0]
    time = t[i]
    y0, y1, y2 = y[..., :-2], y[..., 1:-1], y[..., 2:]
    local = (y1 >= y0) & (y1 >= y2) & ok[..., :-2] & ok[..., 1:-1] & ok[..., 2:]
    refined, offset = _refine(y0, y1, y2)
    refined = np.where(local, refined, -np.inf)
    j = np.argmax(refined, axis=-1)
    best = np.take_along_axis(refined, j[..., None], axis=-1)[..., 0]
    off = np.take_along_axis(offset, j[..., None], axis=-1)[..., 0]
    better = best > value
    none = ~np.any(valid, axis=-1)
    return (np.where(none, np.nan, np.where(better, best, value)),
            np.where(none, np.nan, np.where(better, t[1:-1][j] + off * h, time)))


@dataclass(frozen=True, eq=False)
class RunMetrics:
    """Peak values of one run, or of many runs as arrays of shape (runs,).

    Parameters
    ----------
    max_load_angle : max |theta1 - theta2| while the cable carries load (T > 0): the
        largest angle of the hub load from the mast. [rad]
    t_max_load_angle : when it occurs [s]
    max_rope_angle : max |theta1| while the cable carries load. [rad]
    t_max_rope_angle : [s]
    max_tension_ratio : max T/(m g) [-]
    t_max_tension_ratio : [s]
    min_tension_ratio : min T/(m g) [-]; <= 0 means the cable went slack. The elastic
        cable then carries no load until it snatches taut again; the rigid-rope model is not
        valid after the first time its tension goes negative (such runs are flagged
        ``slack``; use the elastic cable for them).
    max_side_force_ratio : max over the run of the cable's lateral force on the hook over
        the load's weight, max(T, 0) |sin theta1| / (m g). [-]
    t_max_side_force_ratio : [s]
    """

    max_load_angle: np.ndarray
    t_max_load_angle: np.ndarray
    max_rope_angle: np.ndarray
    t_max_rope_angle: np.ndarray
    max_tension_ratio: np.ndarray
    t_max_tension_ratio: np.ndarray
    min_tension_ratio: np.ndarray
    max_side_force_ratio: np.ndarray
    t_max_side_force_ratio: np.ndarray

    @property
    def slack(self):
        """True where the cable went slack (tension reached zero or below)."""
        return np.asarray(self.min_tension_ratio) <= 0

    def to_dict(self):
        """Metrics with unit-labelled keys, angles in degrees.

        Returns
        -------
        dict
            The metrics by unit-labelled key (deg, s, -).
        """
        return {
            "max |theta1 - theta2| [deg]": np.degrees(self.max_load_angle),
            "t at max |theta1 - theta2| [s]": self.t_max_load_angle,
            "max |theta1| [deg]": np.degrees(self.max_rope_angle),
            "t at max |theta1| [s]": self.t_max_rope_angle,
            "max T/(m g) [-]": self.max_tension_ratio,
            "t at max T/(m g) [s]": self.t_max_tension_ratio,
            "min T/(m g) [-]": self.min_tension_ratio,
            "slack [-]": self.slack,
            "max T sin|theta1| / (m g) [-]": self.max_side_force_ratio,
            "t at max T sin|theta1| / (m g) [s]": self.t_max_side_force_ratio,
        }

    @classmethod
    def from_histories(cls, t, angle, rope_angle_, tension_ratio, rigid=False,
                       breakpoints=()):
        """Metrics of sampled time histories (last axis = time).

        ``angle`` is theta1 - theta2 (wrapped here to [-pi, pi)). For the rigid rope
        (``rigid=True``) the angles count only until the tension first goes negative, after
        which that model is not valid. No peak is refined by a parabola across one of the
        ``breakpoints`` [s] (where S'' and so the tension jump).

        Parameters
        ----------
        t : ndarray, shape (n,)
            Sample times. [s]
        angle : ndarray, shape (..., n)
            theta1 - theta2. [rad]
        rope_angle_ : ndarray, shape (..., n)
            Rope angle theta1. [rad]
        tension_ratio : ndarray, shape (..., n)
            Cable tension over the load's weight, T / (m g). [-]
        rigid : bool
            The rigid rope (angles count only while it pulls).
        breakpoints : sequence of float
            Times at which S'' jumps. [s]

        Returns
        -------
        RunMetrics
        """
        taut = np.asarray(tension_ratio) > 0
        if rigid:
            taut = np.logical_and.accumulate(taut, axis=-1)
        smooth = taut.copy()
        for b in breakpoints:
            smooth[..., 1:-1] &= ~((t[:-2] < b) & (b <= t[2:]))
        a, ta = _peak(t, np.abs(load_angle(angle, 0.0)), taut, smooth)
        a = np.minimum(a, np.pi)  # a parabola through the wrap at pi must not pass it
        r, tr = _peak(t, np.abs(rope_angle_), taut, smooth)
        n, tn = _peak(t, tension_ratio, smooth=smooth)
        low, _ = _peak(t, -np.asarray(tension_ratio), smooth=smooth)
        side, ts = _peak(t, np.maximum(tension_ratio, 0.0) * np.abs(np.sin(rope_angle_)),
                         smooth=smooth)
        values = [a, ta, r, tr, n, tn, -low, side, ts]
        if np.ndim(a) == 0:  # one run: plain floats
            values = [float(v) for v in values]
        return cls(*values)


def default_end_time(pendulums, motions, periods=3.0):
    """A run length that covers the motion and ``periods`` of the slowest swing mode. [s]

    Undamped, the two swing modes beat and the largest load angle may come several periods
    after the motion; lengthen the run (or add damping) to check that the maximum has settled.

    Parameters
    ----------
    pendulums : sequence of LateralPendulum
        The cases' pendulums.
    motions : sequence of carrier motions
        Their carrier motions (:mod:`slingloads.models.carrier_motion`).
    periods : float
        Periods of the slowest swing mode after the motion. [-]

    Returns
    -------
    float
        [s]
    """
    slowest = max(_swing_period(p) for p in pendulums)
    return max(m.end_time for m in motions) + periods * slowest


def _swing_period(pendulum):
    modes = pendulum.linear_modes()
    swing = [w for w, k in zip(modes.omega, modes.kinds, strict=True) if k == "swing" and w > 0]
    return 2.0 * np.pi / min(swing)


def _fastest_mode(pendulum):
    return float(pendulum.linear_modes().omega.max())


@dataclass(frozen=True, eq=False)
class LateralRun:
    """Time histories of one run.

    Attributes
    ----------
    pendulum : LateralPendulum
    motion : carrier motion
    t : ndarray, shape (n,) [s]
    states : ndarray, shape (states, n), see ``pendulum.state_names``
    carrier : ndarray, shape (3, n): S [m], S' [m/s], S'' [m/s^2]
    tension : ndarray, shape (n,) [N]
    solver : SolverSettings
    """

    pendulum: LateralPendulum
    motion: object
    t: np.ndarray
    states: np.ndarray
    carrier: np.ndarray
    tension: np.ndarray
    solver: SolverSettings

    @property
    def theta1(self):
        """Rope angle from the vertical, the pendulum's generalised coordinate: > 0 with the
        hub to the right of the hook (the multibody model's lateral swing angle). [rad]"""
        return rope_angle(self.states, self.pendulum.rigid)

    @property
    def theta2(self):
        """Airframe (mast) angle from the vertical, the pendulum's generalised coordinate:
        a right-hand rotation about +x (aft), ``-roll``. [rad]"""
        return airframe_angle(self.states, self.pendulum.rigid)

    @property
    def roll(self):
        """Roll of the airframe in the product's attitude convention (aerospace Euler angle,
        right side down positive; ``docs/conventions.md`` section 8): ``-theta2``. [rad]"""
        return 0.0 - self.theta2  # (a zero roll prints as 0, not -0)

    @property
    def load_angle(self):
        """theta1 - theta2, wrapped to [-pi, pi): angle of the cable force from the mast. [rad]"""
        return load_angle(self.theta1, self.theta2)

    @property
    def tension_ratio(self):
        """T/(m g). [-]"""
        return self.tension / self.pendulum.weight

    @property
    def hub_load(self):
        """Cable force on the airframe at the hub, airframe axes: (Fy, Fz). [N]"""
        return hub_load_airframe_axes(self.tension, self.theta1, self.theta2)

    @property
    def metrics(self):
        """Peak values and when they occur: :class:`RunMetrics`."""
        return RunMetrics.from_histories(self.t, self.load_angle, self.theta1,
                                         self.tension_ratio, self.pendulum.rigid,
                                         self.motion.breakpoints)

    def to_frame(self):
        """Time histories with unit-labelled columns (angles in degrees).

        Returns
        -------
        pandas.DataFrame
            One row per sample: time [s], carrier S [m], S' [m/s], S'' [m/s^2], the rope
            angle theta1 (hub right of the hook positive) [deg], the airframe's ``roll``
            (right side down positive, ``-theta2``) [deg], the load angle theta1 - theta2
            [deg], tension [N] and its factor T/(m g) [-], hub load [N], slack.
        """
        fy, fz = self.hub_load
        frame = pd.DataFrame({
            "t [s]": self.t,
            "S [m]": self.carrier[0], "S' [m/s]": self.carrier[1],
            "S'' [m/s^2]": self.carrier[2],
            "theta1 [deg]": np.degrees(self.theta1),
            "roll [deg]": np.degrees(self.roll),
            "theta1 - theta2 [deg]": np.degrees(self.load_angle),
            "T [N]": self.tension, "T/(m g) [-]": self.tension_ratio,
            "hub Fy [N]": fy, "hub Fz [N]": fz,
            "slack [-]": self.tension <= 0,
        })
        if not self.pendulum.rigid:
            frame["cable length [m]"] = np.hypot(self.states[0], self.states[1])
        return frame


def simulate(pendulum, motion, *, solver=None, x0=None):
    """One run of the lateral pendulum with :func:`scipy.integrate.solve_ivp`.

    Starts hanging at rest under the hook; a jump of the hook's speed at t = 0 (velocity step)
    enters as the initial state. The run is integrated piecewise between the motion's
    breakpoints, where its acceleration or jerk jumps.

    Parameters
    ----------
    pendulum : LateralPendulum
    motion : carrier motion (see :mod:`slingloads.models.carrier_motion`)
    solver : SolverSettings, optional
        ``method``, ``rtol``, ``atol``, ``max_step``; ``t_end`` (default
        :func:`default_end_time`) and ``output_interval`` (default 0.01 s). [s]
    x0 : array_like, optional
        Initial state in the order of ``pendulum.state_names`` (default: hanging at rest,
        plus the motion's velocity jump). [rad, m, rad/s, m/s]

    Returns
    -------
    LateralRun

    Raises
    ------
    InputError
        For a bad initial state, or if the integrator fails.
    """
    from scipy.integrate import solve_ivp  # scipy loads where it is used

    solver = _settings(solver).with_defaults(output_interval=OUTPUT_INTERVAL)
    if solver.t_end is None:
        solver = solver.with_defaults(t_end=default_end_time([pendulum], [motion]))
    t_end = solver.t_end
    max_step = solver.max_step
    if isinstance(motion, TimeHistory):
        max_step = min(max_step, motion.min_interval)

    rhs = evaluation_budget(_right_hand_side(pendulum, motion), "the time-history run",
                            field="rtol")
    n_out = max(int(np.ceil(t_end / solver.output_interval - 1e-9)), 2)
    check_count(n_out, MAX_HISTORY_OUTPUT, "stored samples of a time-history run",
                field="output_interval")
    t_out = np.linspace(0.0, t_end, n_out + 1)
    cuts = np.unique(np.clip([0.0, *motion.breakpoints, t_end], 0.0, t_end))
    if x0 is None:
        x = pendulum.initial_state(motion.velocity_jump)
    else:
        x = np.asarray(x0, dtype=float).reshape(-1)
        if x.size != len(pendulum.state_names) or not np.all(np.isfinite(x)):
            raise InputError(f"initial state needs {len(pendulum.state_names)} finite values "
                             f"{pendulum.state_names}", x.tolist())
    states = np.empty((x.size, t_out.size))
    which = np.clip(np.searchsorted(cuts, t_out, side="right") - 1, 0, cuts.size - 2)
    for k in range(cuts.size - 1):
        sol = solve_ivp(rhs, (cuts[k], cuts[k + 1]), x, method=solver.method,
                        rtol=solver.rtol, atol=solver.atol, max_step=max_step,
                        dense_output=True, vectorized=True)
        if not sol.success:
            raise InputError(f"integration failed between t = {cuts[k]:.6g} s and "
                             f"{cuts[k + 1]:.6g} s: {sol.message}; tighten the solver "
                             "settings", solver.method)
        mask = which == k
        states[:, mask] = sol.sol(t_out[mask])
        x = sol.y[:, -1]
    carrier = np.stack(motion.kinematics(t_out))
    _, tension = pendulum.derivatives(states, carrier[1], carrier[2])
    return LateralRun(pendulum, motion, t_out, states, carrier, tension, solver)


def _right_hand_side(pendulum, motion):
    """The state derivative f(t, x) of one run, for solve_ivp with ``vectorized=True``.

    A single state (shape (states, 1): every call of the explicit methods) goes through the
    compiled scalar equations of :mod:`slingloads.models.pendulum_batch` at the hook's
    velocity and acceleration from the motion's ``kinematics_at``; several states at once (the
    finite-difference Jacobians of the implicit methods) through the numpy equations, and so
    does a call the compiled code refuses (an elastic cable's hub exactly at the hook: 0/0,
    which numpy makes nan and solve_ivp then reports), so that errors are those of before.

    Why: the numpy equations on 0-d arrays and the motion's array kinematics cost about
    190 us a call, nearly all of a run's time (4,500 calls for the example's critical case);
    this path takes a few us. Why it is exact: the compiled equations are the numpy ones,
    compiled from the same source (:func:`~slingloads.models.pendulum.rigid_rope_equations`)
    without fast-math, calling the same C library sin, cos and sqrt,
    and ``kinematics_at`` is ``kinematics`` in floats likewise, so each derivative is the same
    double and solve_ivp takes the same steps (tested in ``tests/test_lateral_study.py``).

    Returns
    -------
    callable
        ``f(t, x)`` of t [s] and x of shape (states, k): a new array of shape (states,) for
        k = 1, (states, k) otherwise. [state units / s]
    """
    from slingloads.models import pendulum_batch

    params = pendulum.arrays()
    row = np.array([params[name] for name in pendulum_batch.PARAMETERS])
    equations = pendulum_batch.rigid_rope if pendulum.rigid else pendulum_batch.elastic_cable
    n = len(pendulum.state_names)
    kinematics_at = motion.kinematics_at

    def derivatives(t, x):
        if x.shape[1] != 1:
            _, v, a = motion.kinematics(t)
            return pendulum.derivatives(x, v, a)[0]
        _, v, a = kinematics_at(t)
        dx = np.empty(n)  # a new array: solve_ivp keeps the ones it is given
        try:
            equations(x[:, 0], v, a, row, dx)
        except ZeroDivisionError:
            return pendulum.derivatives(x, v, a)[0]
        return dx

    return derivatives


def _settings(solver):
    if solver is None:
        return SolverSettings()
    if not isinstance(solver, SolverSettings):
        raise InputError("solver settings must be a SolverSettings", type(solver).__name__)
    return solver


def _stack_parameters(pendulums):
    rows = [p.arrays() for p in pendulums]
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


#: Largest drive table of one compiled batch (motions x nodes x 6 values). [bytes]
_DRIVE_BYTES = 64e6


def sweep(pendulums, motions, *, solver=None):
    """Per-run metrics of many runs, integrated together by vectorised RK4.

    Run i is ``pendulums[i]`` under ``motions[i]``. All runs share one time grid: uniform,
    with the breakpoints of every motion (where S'' jumps) inserted, so that no step
    straddles a jump (RK4 across a jump would be only first-order accurate). The runs are
    integrated one at a time in compiled code, in parallel over the cores
    (:mod:`slingloads.models.pendulum_batch`, the RK4 step of
    :mod:`slingloads.models.runge_kutta`), with the hook's motion tabulated once per distinct
    motion; rigid-rope and elastic-cable runs form two groups. Peaks between grid points are
    refined by a parabola through the three samples around them.

    Parameters
    ----------
    pendulums : sequence of LateralPendulum, length runs
    motions : sequence of carrier motions, length runs
    solver : SolverSettings, optional
        ``t_end``: common run length (default :func:`default_end_time` over all runs) [s];
        ``step``: RK4 step, default min(0.01 s, 0.25/omega_max) with omega_max the fastest
        natural mode of any run (the elastic cable's bounce mode when present), which keeps
        the peak load angle and tension within about 1e-4 of a tight solve_ivp solution. [s]
        The grid has a whole number of steps, so the step used may be slightly shorter.

    Returns
    -------
    metrics : RunMetrics
        Arrays of shape (runs,).
    step : float
        The step used. [s]
    """
    pendulums, motions = list(pendulums), list(motions)
    if len(pendulums) != len(motions) or not pendulums:
        raise InputError("a sweep needs one motion per pendulum, and at least one run",
                         (len(pendulums), len(motions)))
    solver = sweep_settings(pendulums, motions, solver)
    t_end, step = solver.t_end, solver.step
    n_steps = t_end / step
    check_count(n_steps, MAX_LATERAL_STEPS, "RK4 steps per run", field="step")
    check_count(n_steps * len(pendulums), MAX_LATERAL_RUN_STEPS, "run-steps (runs x steps)",
                field="step")
    check_count(n_steps * len({id(m) for m in motions}), MAX_LATERAL_MOTION_STEPS,
                "motion-steps (distinct motions x steps)", field="step")
    n_steps = max(int(np.ceil(n_steps - 1e-9)), 2)
    h = t_end / n_steps
    nodes, jumps = _time_nodes(t_end, n_steps, motions)
    rigid = np.array([p.rigid for p in pendulums])
    out = {f.name: np.empty(len(pendulums)) for f in fields(RunMetrics)}
    for flag in (True, False):
        idx = np.flatnonzero(rigid == flag)
        if idx.size == 0:
            continue
        group = [pendulums[i] for i in idx]
        metrics = _compiled_group(group, [motions[i] for i in idx], nodes, jumps, flag)
        for name in out:
            out[name][idx] = getattr(metrics, name)
    return RunMetrics(**out), h


def sweep_settings(pendulums, motions, solver=None):
    """``solver`` with the sweep's automatic run length and RK4 step filled in where unset
    (see :func:`sweep`).

    Parameters
    ----------
    pendulums : sequence of LateralPendulum
        The cases' pendulums.
    motions : sequence of carrier motions
        Their carrier motions (:mod:`slingloads.models.carrier_motion`).
    solver : SolverSettings, optional

    Returns
    -------
    SolverSettings
    """
    solver = _settings(solver)
    if solver.t_end is None:
        solver = solver.with_defaults(t_end=default_end_time(pendulums, motions))
    if solver.step is None:
        solver = solver.with_defaults(
            step=min(0.01, 0.25 / max(_fastest_mode(p) for p in pendulums)))
    return solver


def _time_nodes(t_end, n_steps, motions):
    """The uniform grid with every motion breakpoint inserted (nodes closer than 1 % of a step
    to a breakpoint are moved onto it), so that no RK4 step straddles a jump of S''.

    Returns the nodes and a flag per node: True where S'' may jump (the step ending there
    samples S'' just before it, the step starting there just after).
    """
    h = t_end / n_steps
    grid = np.linspace(0.0, t_end, n_steps + 1)
    unique = {id(m): m for m in motions}.values()
    breaks = np.unique([b for m in unique for b in m.breakpoints if 0.0 < b < t_end])
    if breaks.size:
        near = np.abs(grid[:, None] - breaks[None, :]).min(axis=1) < 0.01 * h
        near[[0, -1]] = False
        grid = np.union1d(grid[~near], breaks)
    return grid, np.isin(grid, breaks)


def _drive_table(motions, nodes, jumps):
    """Hook (velocity, acceleration) of each motion at the start (just after a jump), middle
    and end (just before a jump) of every step from each node: shape (motions, nodes, 3, 2)."""
    start = nodes
    step = np.diff(nodes)
    middle = np.append(nodes[:-1] + 0.5 * step, nodes[-1])
    end = np.append(np.where(jumps[1:], np.nextafter(nodes[1:], -np.inf), nodes[1:]),
                    nodes[-1])
    table = np.empty((len(motions), nodes.size, 3, 2))
    for k, motion in enumerate(motions):
        for stage, times in enumerate((start, middle, end)):
            _, v, a = motion.kinematics(times)
            table[k, :, stage, 0] = v
            table[k, :, stage, 1] = a
    return table


def _compiled_group(pendulums, motions, nodes, jumps, rigid):
    """Per-run metrics of runs sharing one cable model, by
    :func:`slingloads.models.pendulum_batch.rk4_peaks`, in batches of distinct motions whose
    drive table stays within ``_DRIVE_BYTES``."""
    from slingloads.models import pendulum_batch

    params = _stack_parameters(pendulums)
    P = np.column_stack([params[name] for name in pendulum_batch.PARAMETERS])
    unique = {}
    profile = np.array([unique.setdefault(id(m), len(unique)) for m in motions])
    distinct = list({id(m): m for m in motions}.values())
    x0 = np.stack([p.initial_state(m.velocity_jump) for p, m in zip(pendulums, motions,
                                                                    strict=True)])
    best = np.empty((len(pendulums), pendulum_batch.N_SIGNALS))
    t_best = np.empty_like(best)
    per_batch = max(1, int(_DRIVE_BYTES // (nodes.size * 6 * 8)))
    for first in range(0, len(distinct), per_batch):
        idx = np.flatnonzero((profile >= first) & (profile < first + per_batch))
        drive = _drive_table(distinct[first:first + per_batch], nodes, jumps)
        b, tb = best[idx], t_best[idx]
        pendulum_batch.rk4_peaks(rigid, x0[idx], P[idx], drive, profile[idx] - first,
                                 nodes, jumps, b, tb)
        best[idx], t_best[idx] = b, tb
    best = np.where(np.isfinite(best), best, np.nan).T
    t_best = t_best.T
    best[0] = np.minimum(best[0], np.pi)  # a parabola through the wrap at pi must not pass it
    return RunMetrics(best[0], t_best[0], best[1], t_best[1], best[2], t_best[2], -best[3],
                      best[4], t_best[4])


def acceleration_sweep(accelerations, durations,
                       kinds=("quintic_step", "constant_acceleration"), then="stop"):
    """Carrier motions for every (kind, peak acceleration, duration) combination.

    Parameters
    ----------
    accelerations : sequence of float
        Peak lateral accelerations of the hook (sign gives the direction). [m/s^2]
    durations : sequence of float
        Step durations (quintic and cycloidal steps) or acceleration-phase durations. [s]
    kinds : sequence of {"quintic_step", "cycloidal_step", "constant_acceleration"}
        (``"smooth_step"``, the former name of the quintic step, is accepted).
    then : {"hold", "stop"}
        What follows a constant-acceleration phase.

    Returns
    -------
    list of motions
    """
    makers = {
        "quintic_step": QuinticStep.from_peak_acceleration,
        "cycloidal_step": CycloidalStep.from_peak_acceleration,
        "constant_acceleration": lambda a, d: ConstantAcceleration(a, d, then),
    }
    kinds = [MOTION_ALIASES.get(k, k) for k in kinds]
    for kind in kinds:
        if kind not in makers:
            raise InputError(f"acceleration sweeps take the motion types {sorted(makers)}",
                             kind)
    return [makers[k](a, d) for k in kinds for a in accelerations for d in durations]


def _max(values):
    return float(np.nanmax(values)) if np.size(values) and np.any(np.isfinite(values)) \
        else np.nan


def _motion_row(motion):
    duration = getattr(motion, "duration", getattr(motion, "end_time", np.nan))
    peak = motion.peak_acceleration
    return {
        "motion": motion.kind, "motion description": motion.describe(),
        "peak S'' [m/s^2]": peak, "peak S'' [g]": peak / G0,
        "motion duration [s]": float(duration), "velocity jump [m/s]": motion.velocity_jump,
    }


def airframe_body(airframe, name="airframe (MassItems)"):
    """The lateral-pendulum body of an airframe, hanging: mass, roll inertia, CG below hub.

    At rest the airframe hangs with its CG under the hub
    (:func:`~slingloads.models.airframe.hanging_vertical`), so the CG distance below the hub
    is :math:`e = |\\mathbf{r}_{hub} - \\mathbf{r}_{CG}|` and the roll inertia is taken about
    the horizontal fore-and-aft axis :math:`\\hat a` of that attitude
    (:func:`~slingloads.models.airframe.hanging_roll_axis`),
    :math:`I = \\hat a^T I_{CG} \\hat a`. With the hub on the body z axis through the CG these
    are the distance along the mast and :math:`I_{xx}`.

    Parameters
    ----------
    airframe : Airframe
    name : str

    Returns
    -------
    SlungBody

    Raises
    ------
    InputError
        If the CG does not lie below the hub or the roll inertia is not positive.
    """
    items = airframe.mass_items
    d = np.asarray(airframe.hardpoints.hub, float) - items.cg
    mast = np.asarray(airframe.hardpoints.mast_axis, float)
    along_mast = float(d @ mast / np.linalg.norm(mast))
    if not along_mast > 0:
        raise InputError("the CG of the mass items lies above the rotor hub along the mast; "
                         "the lateral pendulum needs it below [m]", along_mast,
                         field="cg_below_hub")
    e = float(np.linalg.norm(d))
    axis = hanging_roll_axis(airframe)
    inertia = float(axis @ items.inertia_about_cg @ axis)
    if not inertia > 0:
        raise InputError("the mass items' roll inertia about the CG must be > 0 [kg m^2]",
                         inertia, field="roll_inertia")
    return SlungBody(items.total_mass, inertia, e, name)


@dataclass(frozen=True)
class ParameterRanges:
    """Stated uncertainty of the mass properties and the rope, as factors on nominal values.

    The study runs every combination of ``points`` factors evenly spaced over each range
    (plus the nominal 1 if it is not among them): the recommended angle is taken over that
    envelope, so that it survives the uncertainty of the inputs.

    Parameters
    ----------
    roll_inertia, cg_below_hub, rope_length : (float, float)
        (lowest, highest) factor on the roll inertia, the CG distance below the hub and the
        rope length, each 0 < low <= 1 <= high (default +-20 %). [-]
    points : int
        Factors per range, >= 1 (1: the nominal value alone). [-]
    """

    roll_inertia: tuple = (0.8, 1.2)
    cg_below_hub: tuple = (0.8, 1.2)
    rope_length: tuple = (0.8, 1.2)
    points: int = 5

    NAMES = ("roll inertia", "CG below hub", "rope length")

    def __post_init__(self):
        for name in ("roll_inertia", "cg_below_hub", "rope_length"):
            value = getattr(self, name)
            try:
                lo, hi = (float(v) for v in value)
            except (TypeError, ValueError):
                raise InputError(f"the {name.replace('_', ' ')} range must be two factors "
                                 f"(low, high)", value) from None
            if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo <= 1 <= hi):
                raise InputError(f"the {name.replace('_', ' ')} range must satisfy 0 < low "
                                 f"<= 1 <= high [-]", (lo, hi))
            object.__setattr__(self, name, (lo, hi))
        if int(self.points) != self.points or self.points < 1:
            raise InputError("points per range must be a whole number >= 1", self.points)
        object.__setattr__(self, "points", int(self.points))

    @classmethod
    def nominal(cls):
        """No variation: the nominal values alone.

        Returns
        -------
        ParameterRanges
        """
        return cls((1.0, 1.0), (1.0, 1.0), (1.0, 1.0), 1)

    @classmethod
    def spread(cls, roll_inertia=0.2, cg_below_hub=0.2, rope_length=0.2, points=5):
        """Symmetric ranges 1 -+ the given fractions (each in [0, 1)).

        Parameters
        ----------
        roll_inertia, cg_below_hub, rope_length : float
            Fractions of the nominal values, each in [0, 1). [-]
        points : int
            Factors per range.

        Returns
        -------
        ParameterRanges
        """
        ranges = []
        for name, f in (("roll inertia", roll_inertia), ("CG below hub", cg_below_hub),
                        ("rope length", rope_length)):
            f = float(f)
            if not (np.isfinite(f) and 0 <= f < 1):
                raise InputError(f"the {name} spread must lie in [0, 1) [-]", f)
            ranges.append((1.0 - f, 1.0 + f))
        return cls(*ranges, points)

    def factors(self):
        """The factors of each range: three 1-D arrays, each with 1 among them. [-]

        Returns
        -------
        tuple of three ndarray
            Roll-inertia, CG and rope-length factors. [-]
        """
        out = []
        for lo, hi in (self.roll_inertia, self.cg_below_hub, self.rope_length):
            grid = np.linspace(lo, hi, self.points) if self.points > 1 else np.array([1.0])
            out.append(np.unique(np.append(np.round(grid, 12), 1.0)))
        return tuple(out)

    def to_frame(self):
        """The ranges, one row per parameter.

        Returns
        -------
        pandas.DataFrame
            Parameter, lowest and highest factor [-] and points.
        """
        return pd.DataFrame({
            "parameter": list(self.NAMES),
            "lowest factor [-]": [r[0] for r in (self.roll_inertia, self.cg_below_hub,
                                                 self.rope_length)],
            "highest factor [-]": [r[1] for r in (self.roll_inertia, self.cg_below_hub,
                                                  self.rope_length)],
            "values [-]": [len(f) for f in self.factors()],
        })


def lateral_study(bodies, rope_lengths, motions, *, margin, cable_ea=None, damping=None,
                  ranges=None, hook_load_factor=None, solver=None, gravity=G0,
                  regulatory_angle=REGULATORY_ANGLE, limits=None):
    """The design-angle study: every body x rope length x carrier motion, over the stated
    ranges of roll inertia, CG distance below the hub and rope length.

    Parameters
    ----------
    bodies : sequence of SlungBody
        Mass properties to cover (e.g. maximum, medium and minimum weight).
    rope_lengths : sequence of float
        Unstretched cable lengths, each > 0 (the paper uses 18, 60 and 100 ft). [m]
    motions : sequence of carrier motions
        See :func:`acceleration_sweep` for a grid of accelerations and durations.
    margin : float
        Factor >= 1 on the largest load angle found: recommended angle = margin x max. [-]
    cable_ea : float or None
        Cable EA (None: rigid rope). [N]
    damping : LateralDamping, optional
        Linear damping of the swing and roll (default none: the paper's hover step; see
        :func:`slingloads.analyses.lateral_damping.aerodynamic_damping`).
    ranges : ParameterRanges, optional
        Uncertainty of roll inertia, CG below hub and rope length (default +-20 %, five
        values each; :meth:`ParameterRanges.nominal` for none).
    hook_load_factor : float, optional
        Nz of the hook cases, compared with the largest cable tension factor T/(m g). [-]
    solver : SolverSettings, optional
        ``t_end`` and ``step`` of the sweep (see :func:`sweep`; default: the longest motion
        plus three periods of the slowest swing mode, and a step from the fastest mode); the
        solve_ivp settings and ``output_interval`` of :meth:`LateralStudy.run_case`.
    gravity : float
        [m/s^2]
    regulatory_angle : float
        The angle set beside the recommendation (CS-29.865: 30 deg). [rad]
    limits : CarrierLimits, optional
        What the carrier can fly (``CarrierLimits()``: 20 deg bank, 10 deg/s roll rate); a
        motion beyond them is flagged and bounds no design angle (CS-29.865: the angle
        achievable in service). Default None: not checked (the workbook's study checks
        them).

    Returns
    -------
    LateralStudy

    Raises
    ------
    InputError
        For empty inputs, a margin below 1, or any invalid body, length, motion or range.
    """
    bodies, rope_lengths, motions = list(bodies), list(rope_lengths), list(motions)
    for what, items in (("body", bodies), ("rope length", rope_lengths), ("motion", motions)):
        if not items:
            raise InputError(f"the lateral study needs at least one {what}")
    for body in bodies:
        if not isinstance(body, SlungBody):
            raise InputError("study bodies must be SlungBody objects", type(body).__name__)
    margin = float(margin)
    if not np.isfinite(margin) or margin < 1:
        raise InputError("design-angle margin must be >= 1", margin)
    damping = LateralDamping() if damping is None else damping
    if not isinstance(damping, LateralDamping):
        raise InputError("damping must be a LateralDamping", type(damping).__name__)
    ranges = ParameterRanges() if ranges is None else ranges
    if not isinstance(ranges, ParameterRanges):
        raise InputError("ranges must be a ParameterRanges", type(ranges).__name__)
    if hook_load_factor is not None:
        hook_load_factor = float(hook_load_factor)
        if not np.isfinite(hook_load_factor) or hook_load_factor <= 0:
            raise InputError("hook load factor Nz must be > 0", hook_load_factor)
    f_inertia, f_cg, f_rope = ranges.factors()
    pendulums = {}
    for (ib, b), fi, fe in itertools.product(enumerate(bodies), f_inertia, f_cg):
        body = SlungBody(b.mass, b.roll_inertia * fi, b.cg_below_hub * fe, b.name)
        for (il, length), fl in itertools.product(enumerate(rope_lengths), f_rope):
            pendulums[ib, fi, fe, il, fl] = LateralPendulum(
                body, length * fl, cable_ea, damping.lateral, damping.roll, gravity,
                damping.height_above_cg(body.cg_below_hub))
    keys = list(pendulums)
    case_pendulums = [pendulums[k] for k in keys for _ in motions]
    case_motions = [m for _ in keys for m in motions]
    factors = np.array([[k[1], k[2], k[4]] for k in keys for _ in motions])
    nominal_lengths = np.array([rope_lengths[k[3]] for k in keys for _ in motions])
    solver = _settings(solver)
    if solver.t_end is None:
        solver = solver.with_defaults(t_end=default_end_time(pendulums.values(), motions))
    metrics, h = sweep(case_pendulums, case_motions, solver=solver)
    return LateralStudy(tuple(case_pendulums), tuple(case_motions), metrics, margin,
                        solver.t_end, h, float(regulatory_angle), solver, factors,
                        nominal_lengths, ranges, damping, hook_load_factor,
                        limits)


@dataclass(frozen=True, eq=False)
class LateralStudy:
    """Result of :func:`lateral_study`.

    Attributes
    ----------
    pendulums, motions : tuple, one per case
    metrics : RunMetrics, arrays of shape (cases,)
    margin : float [-]
    t_end : float, common run length [s]
    step : float, RK4 step used [s]
    regulatory_angle : float [rad]
    solver : SolverSettings, the settings of :meth:`run_case` (its ``t_end`` is the sweep's)
    factors : ndarray, shape (cases, 3), factors on roll inertia, CG below hub, rope [-]
    nominal_rope : ndarray, shape (cases,), the rope length before its factor [m]
    ranges : ParameterRanges
    damping : LateralDamping
    hook_load_factor : float or None, Nz of the hook cases [-]
    limits : CarrierLimits or None, what the carrier can fly (None: not checked)
    """

    pendulums: tuple
    motions: tuple
    metrics: RunMetrics
    margin: float
    t_end: float
    step: float
    regulatory_angle: float = REGULATORY_ANGLE
    solver: SolverSettings = SolverSettings()
    factors: np.ndarray | None = None
    nominal_rope: np.ndarray | None = None
    ranges: ParameterRanges | None = None
    damping: LateralDamping | None = None
    hook_load_factor: float | None = None
    limits: CarrierLimits | None = None

    def __post_init__(self):
        n = len(self.pendulums)
        if self.factors is None:
            object.__setattr__(self, "factors", np.ones((n, 3)))
        if self.nominal_rope is None:
            object.__setattr__(self, "nominal_rope",
                               np.array([p.rope_length for p in self.pendulums]))
        if self.ranges is None:
            object.__setattr__(self, "ranges", ParameterRanges.nominal())
        if self.damping is None:
            object.__setattr__(self, "damping", LateralDamping())

    @property
    def nominal(self):
        """True for the cases at the nominal roll inertia, CG and rope length."""
        return np.all(self.factors == 1.0, axis=1)

    @property
    def in_domain(self):
        """True for the cases that stay inside the model's domain (:data:`DOMAIN_ANGLE`):
        taut cable throughout, rope angle and load angle below 90 deg. The others yield no
        design angle."""
        m = self.metrics
        with np.errstate(invalid="ignore"):
            return (~np.asarray(m.slack, bool)
                    & (np.asarray(m.max_rope_angle) < DOMAIN_ANGLE)
                    & (np.asarray(m.max_load_angle) < DOMAIN_ANGLE))

    def domain_notes(self):
        """Why each case is outside the domain, with the time ('' inside). [str]

        Returns
        -------
        list of str
            One note per case.
        """
        m, d = self.metrics, np.degrees
        notes = []
        for k in range(len(self.pendulums)):
            why = []
            if bool(np.asarray(m.slack)[k]):
                why.append(f"cable slack (min T/(m g) {float(m.min_tension_ratio[k]):.3g})")
            if not np.asarray(m.max_rope_angle)[k] < DOMAIN_ANGLE:
                why.append(f"rope angle {float(d(m.max_rope_angle[k])):.4g} deg at t = "
                           f"{float(m.t_max_rope_angle[k]):.4g} s passes "
                           f"{float(d(DOMAIN_ANGLE)):.3g} deg (over the top)")
            if not np.asarray(m.max_load_angle)[k] < DOMAIN_ANGLE:
                why.append(f"load angle {float(d(m.max_load_angle[k])):.4g} deg at t = "
                           f"{float(m.t_max_load_angle[k]):.4g} s passes "
                           f"{float(d(DOMAIN_ANGLE)):.3g} deg")
            notes.append("; ".join(why))
        return notes

    @property
    def outside_domain(self):
        """Number of cases outside the domain."""
        return int(np.count_nonzero(~self.in_domain))

    def flyable_notes(self):
        """Why each case's carrier motion is beyond :attr:`limits` ('' if flyable or not
        checked). [str]

        Returns
        -------
        list of str
            One note per case (:func:`flyable`).
        """
        if self.limits is None:
            return [""] * len(self.motions)
        seen = {}
        return [seen.setdefault(id(m), flyable(m, self.limits)) for m in self.motions]

    @property
    def flyable(self):
        """True for the cases whose carrier motion the carrier can fly (all without
        limits)."""
        return np.array([not note for note in self.flyable_notes()], dtype=bool)

    @property
    def carrier_force_ratio(self):
        """Each case's largest lateral cable force on the carrier over the carrier's weight,
        max over the run of T(t) |sin theta1(t)| / (m_carrier g) (NaN without a carrier
        mass). [-]"""
        mass = np.nan if self.limits is None else self.limits.carrier_mass
        loads = np.array([p.body.mass for p in self.pendulums])
        return np.asarray(self.metrics.max_side_force_ratio) * loads / mass

    @property
    def counted(self):
        """The cases the design angle is taken over: inside the domain, motion flyable."""
        return self.in_domain & self.flyable

    def _inside(self, values):
        return np.where(self.counted, values, np.nan)

    @property
    def critical_index(self):
        """Index of the case with the largest load angle among those inside the domain (of
        all cases when none is)."""
        inside = self._inside(self.metrics.max_load_angle)
        if np.any(np.isfinite(inside)):
            return int(np.nanargmax(inside))
        return int(np.nanargmax(self.metrics.max_load_angle))

    @property
    def max_load_angle(self):
        """Largest |theta1 - theta2| over the cases inside the domain, the envelope over the
        ranges (NaN when no case is inside). [rad]"""
        value = float(self._inside(self.metrics.max_load_angle)[self.critical_index])
        return value

    @property
    def nominal_max_load_angle(self):
        """Largest |theta1 - theta2| over the nominal cases inside the domain (NaN if
        none). [rad]"""
        values = self._inside(self.metrics.max_load_angle)[self.nominal]
        return float(np.nanmax(values)) if np.any(np.isfinite(values)) else np.nan

    @property
    def critical_case(self):
        """The row of :meth:`to_frame` of the case with the largest load angle (a Series)."""
        return self.to_frame().iloc[self.critical_index]

    @property
    def max_load_angle_taut(self):
        """Largest |theta1 - theta2| over the cases whose cable never went slack (NaN if
        none). [rad]"""
        values = np.where(self.metrics.slack, np.nan, self.metrics.max_load_angle)
        return float(np.nanmax(values)) if np.any(np.isfinite(values)) else np.nan

    @property
    def recommended_angle(self):
        """Recommended design angle of the hook load from the mast = margin x the largest
        load angle over the envelope of the ranges, the cases inside the domain only; NaN
        when no case is inside or when it would reach 90 deg (no hook cone). [rad]"""
        value = self.margin * self.max_load_angle
        return value if value < DOMAIN_ANGLE else np.nan

    @property
    def exceeds_regulatory_angle(self):
        """True if the recommended angle is above the regulatory angle (no reduction)."""
        return self.recommended_angle > self.regulatory_angle

    @property
    def regulatory_angle_not_conservative(self):
        """True if a load angle found exceeds the regulatory angle itself: for this motion
        set the 30 deg rule is not conservative."""
        return self.max_load_angle > self.regulatory_angle

    @property
    def max_tension_ratio(self):
        """Largest T/(m g) over all cases. [-]"""
        return float(np.nanmax(self.metrics.max_tension_ratio))

    @property
    def exceeds_hook_load_factor(self):
        """Cases whose largest T/(m g) exceeds the hook load factor Nz (all False without
        Nz)."""
        if self.hook_load_factor is None:
            return np.zeros(len(self.pendulums), dtype=bool)
        return self.metrics.max_tension_ratio > self.hook_load_factor

    def caveats(self):
        """What limits the conclusion, in words ('' when nothing): cases outside the domain,
        carrier motions beyond the carrier's limits, cases loading the carrier sideways
        beyond :data:`CARRIER_FORCE_LIMIT` of its weight.

        Returns
        -------
        str
        """
        reg = np.degrees(self.regulatory_angle)
        n = len(self.pendulums)
        text = ""
        out = self.outside_domain
        if out:
            text += (f" {out} of {n} cases leave the model's domain (sheet Runs, 'domain'): "
                     f"their motions bound no angle, so no reduction below {reg:.3g} deg is "
                     "supported while they are in the motion set.")
        unflyable = int(np.count_nonzero(~self.flyable))
        if unflyable:
            text += (f" {unflyable} of {n} cases have carrier motions beyond what the carrier "
                     f"can fly ({self.limits.describe()}; sheet Runs, 'flyable'): they bound "
                     "no angle.")
        heavy = int(np.count_nonzero(self.carrier_force_ratio > CARRIER_FORCE_LIMIT))
        if heavy:
            text += (f" {heavy} cases load the carrier sideways above "
                     f"{CARRIER_FORCE_LIMIT:g} x its weight (largest T |sin theta1| over the "
                     "run): the prescribed (frozen-carrier) path is not assured for them.")
        return text

    def verdict(self):
        """The study's conclusion on the 30 deg rule, in words.

        Returns
        -------
        str
            The largest load angle and the recommended design angle against the regulatory one
            [deg], with the caveats.
        """
        found, rec = np.degrees(self.max_load_angle), np.degrees(self.recommended_angle)
        reg = np.degrees(self.regulatory_angle)
        caveats = self.caveats()
        if self.outside_domain == len(self.pendulums):
            return (f"Every case leaves the lateral pendulum's domain (slack cable, or rope or "
                    f"load angle past {np.degrees(DOMAIN_ANGLE):.3g} deg): no design angle; "
                    f"for this motion set the {reg:.3g} deg rule can be neither reduced nor "
                    "confirmed. Use flyable carrier motions.")
        if not np.any(self.counted):
            return ("No case has a flyable carrier motion inside the model's domain: no design "
                    f"angle.{caveats}")
        if not np.isfinite(rec):
            return (f"The largest load angle inside the domain is {found:.3g} deg; with the "
                    f"margin {self.margin:g} it reaches 90 deg: no hook cone can be built, no "
                    f"design angle. Restrict the operation (motions, masses, rope lengths) or "
                    f"show more damping.{caveats}")
        return self._verdict_inside(found, rec, reg) + caveats

    def _verdict_inside(self, found, rec, reg):
        if self.regulatory_angle_not_conservative:
            need = (f"the hook cases need at least {rec:.3g} deg ({self.margin:g} x "
                    f"{found:.3g} deg)." if rec < 90.0 else
                    f"with the margin ({rec:.3g} deg) no hook cone can be built: restrict the "
                    f"operation (motions, masses, rope lengths) or show more damping.")
            return (f"For this motion set the {reg:.3g} deg rule is NOT conservative: the "
                    f"largest load angle over the stated ranges is {found:.3g} deg, above "
                    f"{reg:.3g} deg; {need}")
        if self.exceeds_regulatory_angle:
            return (f"The recommended angle {rec:.3g} deg ({self.margin:g} x the largest load "
                    f"angle {found:.3g} deg) exceeds {reg:.3g} deg: no reduction is supported.")
        return (f"The recommended angle {rec:.3g} deg ({self.margin:g} x the largest load angle "
                f"{found:.3g} deg over the stated ranges) is below {reg:.3g} deg for this "
                f"motion set.")

    def to_frame(self):
        """One row per case: inputs and metrics, unit-labelled columns.

        Returns
        -------
        pandas.DataFrame
            One row per case, units in the column labels (kg, kg m^2, m, s, deg, -).
        """
        rows = []
        for p, m in zip(self.pendulums, self.motions, strict=True):
            rows.append({
                "body": p.body.name, "mass [kg]": p.body.mass,
                "roll inertia [kg m^2]": p.body.roll_inertia,
                "CG below hub [m]": p.body.cg_below_hub,
                "rope length [m]": p.rope_length,
                "cable EA [N]": np.inf if p.rigid else p.cable_ea,
                **_motion_row(m),
            })
        frame = pd.DataFrame(rows)
        frame.insert(0, "case", np.arange(1, len(rows) + 1))
        for j, name in enumerate(("roll inertia factor [-]", "CG below hub factor [-]",
                                  "rope length factor [-]")):
            frame.insert(6 + j, name, self.factors[:, j])
        frame.insert(9, "nominal rope length [m]", self.nominal_rope)
        frame.insert(10, "nominal [-]", self.nominal)
        for key, values in self.metrics.to_dict().items():
            frame[key] = values
        if self.hook_load_factor is not None:
            frame["T/(m g) > Nz [-]"] = self.exceeds_hook_load_factor
        frame["inside domain [-]"] = self.in_domain
        frame["domain"] = self.domain_notes()
        frame["flyable [-]"] = self.flyable
        frame["flyable note"] = self.flyable_notes()
        frame["max lateral cable force / carrier weight [-]"] = self.carrier_force_ratio
        return frame

    def nominal_case(self, index):
        """The case number (1-based, as :meth:`case_frame` lists it) of the nominal case of
        which run ``index`` (0-based, of :attr:`pendulums`) is a variant over the stated
        ranges: the same body, nominal rope length and carrier motion.

        Parameters
        ----------
        index : int
            A run of the sweep, 0-based.

        Returns
        -------
        int
            Its nominal case, 1-based (the ``case`` of :meth:`case_frame`).

        Examples
        --------
        A nominal run is its own case: ``study.nominal_case(j) == j + 1`` where
        ``study.nominal[j]``.
        """
        per_pendulum = len(self.pendulums) // len({id(p) for p in self.pendulums})

        def key(j):
            return (self.pendulums[j].body.name, float(self.nominal_rope[j]),
                    j % per_pendulum)

        target = key(int(index))
        return next(int(j) + 1 for j in np.flatnonzero(self.nominal) if key(j) == target)

    def case_frame(self):
        """One row per nominal case (body x rope length x motion): its inputs and metrics
        with the nominal roll inertia, CG and rope, and beside them the largest load angle
        over the stated ranges among the cases inside the model's domain (NaN: none), the
        factors that gave it, the largest tension factor and the number of cases of the
        ranges outside the domain.

        Returns
        -------
        pandas.DataFrame
            One row per nominal case, units in the column labels.
        """
        frame = self.to_frame()
        per_pendulum = len(self.pendulums) // len({id(p) for p in self.pendulums})
        frame["motion number"] = np.arange(len(frame)) % per_pendulum
        key = ["body", "nominal rope length [m]", "motion number"]
        inside = frame["inside domain [-]"].astype(bool) & frame["flyable [-]"].astype(bool)
        angle = frame["max |theta1 - theta2| [deg]"].where(inside).fillna(-np.inf)
        worst = frame.loc[angle.groupby([frame[k] for k in key], sort=False).idxmax()]
        worst = worst.set_index(key)
        worst.loc[~worst["inside domain [-]"].astype(bool), "max |theta1 - theta2| [deg]"] = (
            np.nan)
        factors = ["roll inertia factor [-]", "CG below hub factor [-]",
                   "rope length factor [-]"]
        out = frame[frame["nominal [-]"]].set_index(key)
        out["max |theta1 - theta2| over the ranges [deg]"] = \
            worst["max |theta1 - theta2| [deg]"]
        for name in factors:
            out[name.replace(" [-]", " at that maximum [-]")] = worst[name]
        out["max T/(m g) over the ranges [-]"] = frame.groupby(key)["max T/(m g) [-]"].max()
        out["cases outside the domain over the ranges [-]"] = (~inside).groupby(
            [frame[k] for k in key]).sum()
        out = out.reset_index().drop(columns=[*factors, "nominal [-]", "motion number"])
        return out[["case", *[c for c in out.columns if c != "case"]]]

    def summary_frame(self):
        """The largest load angle, its case, the margin and the recommended angle.

        Returns
        -------
        pandas.DataFrame
            Item, value and unit (deg, m, -).
        """
        case = self.critical_case
        items = [
            ("cases run", len(self.pendulums), "-"),
            ("largest load angle |theta1 - theta2|, nominal inputs",
             np.degrees(self.nominal_max_load_angle), "deg"),
            ("largest load angle |theta1 - theta2| over the stated ranges",
             np.degrees(self.max_load_angle), "deg"),
            ("case producing it", int(case["case"]), "-"),
            ("  body", case["body"], "-"),
            ("  roll inertia", case["roll inertia [kg m^2]"], "kg m^2"),
            ("  CG below hub", case["CG below hub [m]"], "m"),
            ("  rope length", case["rope length [m]"], "m"),
            ("  carrier motion", case["motion description"], "-"),
            ("  time of the maximum", case["t at max |theta1 - theta2| [s]"], "s"),
            ("  cable slack in that case", bool(case["slack [-]"]), "-"),
            ("cases whose cable went slack", int(np.sum(self.metrics.slack)), "-"),
            ("cases outside the model's domain (no design value)", self.outside_domain, "-"),
            ("cases with a carrier motion beyond the carrier's limits",
             int(np.count_nonzero(~self.flyable)), "-"),
            ("largest load angle, cases that stayed taut",
             np.degrees(self.max_load_angle_taut), "deg"),
            ("margin", self.margin, "-"),
            ("recommended design angle", np.degrees(self.recommended_angle), "deg"),
            ("CS-29.865 angle", np.degrees(self.regulatory_angle), "deg"),
            ("recommended angle exceeds CS-29.865 angle", self.exceeds_regulatory_angle, "-"),
            ("CS-29.865 angle not conservative for this motion set",
             self.regulatory_angle_not_conservative, "-"),
            ("largest cable tension factor T/(m g)", self.max_tension_ratio, "-"),
        ]
        if self.hook_load_factor is not None:
            items += [("hook load factor Nz", self.hook_load_factor, "-"),
                      ("cases with T/(m g) above Nz",
                       int(np.sum(self.exceeds_hook_load_factor)), "-")]
        items += [("damping", self.damping.source if not self.damping.off else "none", "-"),
                  ("run length", self.t_end, "s"),
                  ("RK4 step", self.step, "s")]
        return pd.DataFrame(items, columns=["quantity", "value", "unit"])

    def sensitivity_frame(self):
        """Largest load angle and tension factor against each parameter's factor.

        For each of roll inertia, CG below hub and rope length, and each of its factors:
        the maxima over bodies, ropes and motions with the two other parameters nominal
        ("one at a time") and over their whole ranges ("envelope").

        Returns
        -------
        pandas.DataFrame
            Parameter, factor [-], largest load angle [deg] and tension factor [-], one at a time
            and over the envelope.
        """
        angle = np.degrees(self.metrics.max_load_angle)
        ratio = self.metrics.max_tension_ratio
        rows = []
        for j, name in enumerate(ParameterRanges.NAMES):
            others = np.delete(self.factors, j, axis=1)
            alone = np.all(others == 1.0, axis=1)
            for f in np.unique(self.factors[:, j]):
                at = self.factors[:, j] == f
                rows.append({
                    "parameter": name, "factor [-]": f,
                    "max load angle, others nominal [deg]": _max(angle[at & alone]),
                    "max load angle, others over their ranges [deg]": _max(angle[at]),
                    "max T/(m g), others nominal [-]": _max(ratio[at & alone]),
                    "max T/(m g), others over their ranges [-]": _max(ratio[at]),
                })
        return pd.DataFrame(rows)

    def tension_frame(self):
        """Largest cable tension factor per carrier motion (over bodies, ropes and ranges)
        against the hook load factor Nz, with the exceedance flagged.

        Returns
        -------
        pandas.DataFrame
            One row per carrier motion: largest and smallest T/(m g) [-], largest load angle [deg],
            against the hook load factor [-].
        """
        frame = self.to_frame()
        grouped = frame.groupby("motion description", sort=False)
        out = grouped.agg(**{
            "max T/(m g) [-]": ("max T/(m g) [-]", "max"),
            "min T/(m g) [-]": ("min T/(m g) [-]", "min"),
            "max |theta1 - theta2| [deg]": ("max |theta1 - theta2| [deg]", "max"),
        }).reset_index()
        if self.hook_load_factor is not None:
            out["Nz [-]"] = self.hook_load_factor
            out["T/(m g) above Nz [-]"] = out["max T/(m g) [-]"] > self.hook_load_factor
        return out

    def envelope_frame(self):
        """Largest load angle per nominal rope length and peak carrier acceleration, over
        the stated ranges. Velocity steps (no finite acceleration) are left out.

        Returns
        -------
        pandas.DataFrame
            Nominal rope length [m], peak S'' [g] and largest load angle [deg].
        """
        frame = self.to_frame()
        frame = frame[np.isfinite(frame["peak S'' [m/s^2]"])]
        return (frame.groupby(["nominal rope length [m]", "peak S'' [g]"], as_index=False)
                ["max |theta1 - theta2| [deg]"].max())

    def frames(self):
        """Sheet name -> DataFrame, for the Excel report.

        Returns
        -------
        dict of str to pandas.DataFrame
        """
        return {"lateral summary": self.summary_frame(), "lateral runs": self.to_frame(),
                "lateral cases": self.case_frame(), "lateral envelope": self.envelope_frame(),
                "lateral sensitivity": self.sensitivity_frame(),
                "lateral tension": self.tension_frame(),
                "lateral ranges": self.ranges.to_frame(),
                "lateral damping": self.damping.to_frame()}

    def run_case(self, index=None, solver=None):
        """Re-run one case (default the critical one) with solve_ivp for its time histories.

        Parameters
        ----------
        index : int, optional
            0-based case index (the ``case`` column minus 1).
        solver : SolverSettings, optional
            solve_ivp settings (default the study's); the run length is the study's.

        Returns
        -------
        LateralRun
        """
        index = self.critical_index if index is None else int(index)
        if not 0 <= index < len(self.pendulums):
            raise InputError(f"case index must lie in [0, {len(self.pendulums) - 1}]", index)
        solver = self.solver if solver is None else _settings(solver)
        return simulate(self.pendulums[index], self.motions[index],
                        solver=replace(solver, t_end=self.t_end))

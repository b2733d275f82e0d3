"""One run of the lateral pendulum with :func:`scipy.integrate.solve_ivp`: time histories.

:func:`simulate` integrates the pendulum of :mod:`slingloads.models.pendulum` under one carrier
motion of :mod:`slingloads.models.carrier_motion`, piecewise between the motion's breakpoints
(where its acceleration or jerk jumps), and returns a :class:`LateralRun` of states, hook
kinematics and cable tension on an even output grid, whose peaks are :class:`RunMetrics`. The
run's length defaults to :func:`default_end_time`: the motion plus three periods of the slowest
swing mode.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.lateral.metrics import RunMetrics
from slingloads.errors import InputError
from slingloads.limits import MAX_HISTORY_OUTPUT, check_count, evaluation_budget
from slingloads.models.carrier_motion import TimeHistory
from slingloads.models.integration import SolverSettings, solver_settings
from slingloads.models.pendulum import (
    LateralPendulum,
    airframe_angle,
    hub_load_airframe_axes,
    load_angle,
    rope_angle,
)

#: Default interval of the time histories of single runs. [s]
OUTPUT_INTERVAL = 0.01


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


@dataclass(frozen=True, eq=False)
class LateralRun:
    """Time histories of one run.

    Attributes
    ----------
    pendulum : LateralPendulum
    motion : carrier motion
    t : ndarray, shape (n,) [s]
    states : ndarray, shape (states, n), see ``pendulum.state_names``
        The states at the output times. [rad, rad/s] or [m, rad, m/s, rad/s]
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

    solver = solver_settings(solver).with_defaults(output_interval=OUTPUT_INTERVAL)
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

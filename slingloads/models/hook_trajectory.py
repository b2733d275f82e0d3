"""Hook trajectories in three dimensions: what the carrier's hook does, as data.

A :class:`HookTrajectory` is the hook's motion relative to its steady flight, in the earth
axes of the multibody model (X aft along the flight path, the carrier flying towards -X; Y
right; Z up): a sum of one-dimensional motions, each along its own fixed direction,

.. math:: a(t) = \\sum_i \\ddot S_i(t)\\, e_i, \\qquad v(t) = v_0 + \\sum_i \\dot S_i(t)\\, e_i

with ``S_i`` any motion of :mod:`slingloads.models.carrier_motion` (quintic or cycloidal
step, constant acceleration, time history) or a :class:`PiecewiseAcceleration`: an
acceleration given at breakpoints, linear between them (continuous, jerk-limited profiles)
or held from one to the next (steps), integrated exactly to velocity and displacement. The
hook is at rest (on its steady flight) before the first breakpoint, and keeps the velocity
reached after the last.

Constructors cover the usual ways to state a motion: :meth:`HookTrajectory.from_acceleration`,
:meth:`~HookTrajectory.from_velocity` and :meth:`~HookTrajectory.from_displacement` (samples in
three columns, e.g. from a CSV file read by
:func:`slingloads.io.multibody.trajectory.read_trajectory_csv`), :meth:`~HookTrajectory.along`
(a one-dimensional motion along a direction), and the manoeuvres of the paper:
:meth:`~HookTrajectory.forward_acceleration` (from hover, -X, jerk-limited: what
:class:`~slingloads.models.multibody.carrier.ForwardAcceleration` flies) and
:meth:`~HookTrajectory.lateral` (+Y: what
:class:`~slingloads.models.multibody.carrier.LateralHookMotion` flies).

The protocol the multibody model asks of a trajectory (checked by
:class:`~slingloads.analyses.multibody.Manoeuvre`): ``command(t, v0)`` returning the commanded
acceleration and velocity, each of shape (n, 3) [m/s^2, m/s]; ``breakpoints``, the times [s]
at which the acceleration jumps or kinks (the integrator steps on them); ``from_hover``; and
``describe()``.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

import numpy as np

from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.carrier_motion import Motion

#: Ways of joining the acceleration between breakpoints.
INTERPOLATIONS = ("linear", "previous")
#: Named directions of :meth:`HookTrajectory.along`.
AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0),
        "-X": (-1.0, 0.0, 0.0), "-Y": (0.0, -1.0, 0.0), "-Z": (0.0, 0.0, -1.0)}


def _times(time, what):
    t = np.asarray(time, dtype=float).reshape(-1)
    if t.size < 2 or not np.all(np.isfinite(t)):
        raise InputError(f"a {what} needs at least two finite times [s]", t.tolist())
    steps = np.diff(t)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0)) + 1
        raise InputError(f"{what} times must be strictly increasing; time {i + 1} does not "
                         "come after the one before [s]", float(t[i]))
    if t[0] < 0:
        raise InputError(f"{what} times must be >= 0 (t = 0 is the run's start) [s]",
                         float(t[0]))
    return t


@dataclass(frozen=True)
class PiecewiseAcceleration(Motion):
    """Acceleration given at breakpoints along one direction, integrated exactly.

    Parameters
    ----------
    time : array_like, shape (n,)
        Breakpoints, strictly increasing, >= 0, n >= 2. [s]
    acceleration : array_like, shape (n,)
        Acceleration at each breakpoint. [m/s^2]
    interpolation : {"linear", "previous"}
        ``"linear"``: linear between breakpoints (continuous; zero before the first and after
        the last unless given there); ``"previous"``: each value held until the next
        breakpoint (the last must be 0: nothing is commanded after the last breakpoint).
    name : str

    Examples
    --------
    >>> m = PiecewiseAcceleration([0.0, 1.0, 3.0, 4.0], [0.0, 2.0, 2.0, 0.0])
    >>> # displacement [m], velocity [m/s], acceleration [m/s^2] at 4 s
    >>> [round(float(v), 9) for v in m.kinematics(4.0)]
    [12.0, 6.0, 0.0]
    """

    time: np.ndarray
    acceleration: np.ndarray
    interpolation: str = "linear"
    name: str = "piecewise acceleration"

    kind = "piecewise_acceleration"
    velocity_jump = 0.0

    def __post_init__(self):
        t = _times(self.time, "piecewise acceleration")
        a = np.asarray(self.acceleration, dtype=float).reshape(-1)
        if a.shape != t.shape or not np.all(np.isfinite(a)):
            raise InputError(f"a piecewise acceleration needs one finite acceleration per "
                             f"time ({t.size} times) [m/s^2]", a.tolist())
        if self.interpolation not in INTERPOLATIONS:
            raise InputError(f"interpolation must be one of {list(INTERPOLATIONS)}",
                             self.interpolation)
        if self.interpolation == "previous" and a[-1] != 0:
            raise InputError("with interpolation 'previous' the last acceleration must be 0 "
                             "(nothing is commanded after the last breakpoint) [m/s^2]",
                             float(a[-1]))
        dt = np.diff(t)
        if self.interpolation == "linear":
            slope = np.diff(a) / dt
            dv = (a[:-1] + a[1:]) / 2 * dt
            ds_extra = (2 * a[:-1] + a[1:]) / 6 * dt**2  # beyond v_k dt
        else:
            slope = np.zeros(dt.size)
            dv = a[:-1] * dt
            ds_extra = a[:-1] / 2 * dt**2
        v = np.concatenate([[0.0], np.cumsum(dv)])
        s = np.concatenate([[0.0], np.cumsum(v[:-1] * dt + ds_extra)])
        t.flags.writeable = a.flags.writeable = False
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "acceleration", a)
        object.__setattr__(self, "_pieces", (t.tolist(), a.tolist(), slope.tolist(),
                                             v.tolist(), s.tolist()))

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return tuple(float(v) for v in self.time)

    @property
    def end_time(self):
        """Time of its last breakpoint, after which it no longer changes. [s]"""
        return float(self.time[-1])

    @property
    def peak_acceleration(self):
        """Largest |acceleration| of the table. [m/s^2]"""
        return float(np.max(np.abs(self.acceleration)))

    def describe(self):
        """A one-line description for the run tables.

        Returns
        -------
        str
        """
        return (f"{self.name} ({self.time.size} breakpoints over "
                f"{self.time[0]:.4g}-{self.time[-1]:.4g} s)")

    def kinematics(self, t):
        """Displacement, velocity and acceleration at times ``t`` (exact integrals).

        Parameters
        ----------
        t : float or array_like
            [s]

        Returns
        -------
        s, v, a : ndarray
            S [m], S' [m/s] and S'' [m/s^2], each of the shape of ``t``.
        """
        t = np.asarray(t, dtype=float)
        knots, a, slope, v, s = (np.asarray(p) for p in self._pieces)
        i = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, knots.size - 2)
        tau = np.clip(t, knots[0], knots[-1]) - knots[i]
        acc = a[i] + slope[i] * tau
        vel = v[i] + a[i] * tau + slope[i] * tau**2 / 2
        dis = s[i] + v[i] * tau + a[i] * tau**2 / 2 + slope[i] * tau**3 / 6
        acc = np.where(t == knots[-1], a[-1], acc)  # the value given at the last one
        before, after = t < knots[0], t > knots[-1]
        dis = np.where(after, s[-1] + v[-1] * (t - knots[-1]), dis)
        vel = np.where(after, v[-1], vel)
        return (np.where(before, 0.0, dis), np.where(before, 0.0, vel),
                np.where(before | after, 0.0, acc))

    def kinematics_at(self, t):
        """:meth:`kinematics` at one time, in floats.

        Parameters
        ----------
        t : float
            [s]

        Returns
        -------
        s, v, a : float
            S [m], S' [m/s], S'' [m/s^2].
        """
        knots, a, slope, v, s = self._pieces
        t = float(t)
        if t < knots[0]:
            return 0.0, 0.0, 0.0
        if t > knots[-1]:
            return s[-1] + v[-1] * (t - knots[-1]), v[-1], 0.0
        i = min(bisect.bisect_right(knots, t), len(knots) - 1) - 1
        tau = t - knots[i]
        acc = a[-1] if t == knots[-1] else a[i] + slope[i] * tau
        return (s[i] + v[i] * tau + a[i] * tau**2 / 2 + slope[i] * tau**3 / 6,
                v[i] + a[i] * tau + slope[i] * tau**2 / 2, acc)


def _direction(direction):
    if isinstance(direction, str):
        if direction not in AXES:
            raise InputError(f"unknown direction; valid names are {list(AXES)} or a vector",
                             direction)
        direction = AXES[direction]
    e = np.asarray(direction, dtype=float).reshape(-1)
    norm = np.linalg.norm(e) if e.size == 3 else 0.0
    if not (np.isfinite(norm) and norm > 0):
        raise InputError("a direction needs three finite values, not all zero",
                         np.atleast_1d(e).tolist())
    e = e / norm
    e.flags.writeable = False
    return e


@dataclass(frozen=True)
class HookTrajectory:
    """The hook's motion relative to its steady flight, earth axes (module notes).

    Parameters
    ----------
    components : sequence of (motion, direction)
        One-dimensional motions (``kinematics(t)`` -> S, S', S''; no velocity jump) and the
        direction each acts along (a 3-vector, normalised, or ``"X"``, ``"-X"``, ``"Y"``...).
    from_hover : bool
        The run starts trimmed in hover (zero airspeed) rather than at the system airspeed.
    name : str
        Shown in the run tables.
    """

    components: tuple
    from_hover: bool = False
    name: str = "hook trajectory"

    def __post_init__(self):
        parts = []
        for item in self.components:
            try:
                motion, direction = item
            except (TypeError, ValueError):
                raise InputError("a hook trajectory's components are (motion, direction) "
                                 "pairs", repr(item)) from None
            if not callable(getattr(motion, "kinematics", None)):
                raise InputError("a hook trajectory component needs a motion with "
                                 "kinematics(t)", type(motion).__name__)
            if getattr(motion, "velocity_jump", 0.0):
                raise InputError("a velocity step cannot drive the hook (its speed would "
                                 "jump); use a step, an acceleration or a time history "
                                 "[m/s]", motion.velocity_jump)
            parts.append((motion, _direction(direction)))
        if not parts:
            raise InputError("a hook trajectory needs at least one component")
        object.__setattr__(self, "components", tuple(parts))
        object.__setattr__(self, "from_hover", bool(self.from_hover))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def along(cls, motion, direction="Y", *, from_hover=False, name=None):
        """One motion of :mod:`slingloads.models.carrier_motion` (or a
        :class:`PiecewiseAcceleration`) along ``direction``.

        Parameters
        ----------
        motion : object
            A one-dimensional motion with ``kinematics(t)`` and ``describe()``.
        direction : str or array_like, shape (3,)
            ``"X"``, ``"-X"``, ``"Y"``... or a vector (normalised), earth axes. [-]
        from_hover : bool
            The run starts trimmed in hover.
        name : str, optional
            Default: the motion's description and the direction.

        Returns
        -------
        HookTrajectory
        """
        return cls(((motion, direction),), from_hover,
                   name or f"{motion.describe()} along {direction}")

    @classmethod
    def from_acceleration(cls, time, acceleration, interpolation="linear", *,
                          from_hover=False, name="acceleration history"):
        """Acceleration samples at breakpoints, joined as :class:`PiecewiseAcceleration` joins
        them.

        Parameters
        ----------
        time : array_like, shape (n,)
            Breakpoints, strictly increasing, >= 0. [s]
        acceleration : array_like, shape (n, 3)
            X, Y, Z acceleration at each breakpoint, earth axes. [m/s^2]
        interpolation : {"linear", "previous"}
        from_hover : bool
            The run starts trimmed in hover.
        name : str

        Returns
        -------
        HookTrajectory
        """
        t = _times(time, "hook trajectory")
        a = _samples(acceleration, t, "acceleration", "m/s^2")
        parts = tuple((PiecewiseAcceleration(t, a[:, k], interpolation, name), axis)
                      for k, axis in enumerate("XYZ") if np.any(a[:, k] != 0))
        return cls(parts or ((PiecewiseAcceleration(t, a[:, 0], interpolation, name), "X"),),
                   from_hover, name)

    @classmethod
    def from_velocity(cls, time, velocity, *, from_hover=False, name="velocity history"):
        """Velocity samples relative to the steady flight, linear between the breakpoints:
        the acceleration is held over each interval. The first sample must be 0 (the hook's
        speed cannot jump) and the hook keeps the last.

        Parameters
        ----------
        time : array_like, shape (n,)
            Breakpoints, strictly increasing, >= 0. [s]
        velocity : array_like, shape (n, 3)
            X, Y, Z velocity at each breakpoint, earth axes. [m/s]
        from_hover : bool
            The run starts trimmed in hover.
        name : str

        Returns
        -------
        HookTrajectory
        """
        t = _times(time, "hook trajectory")
        v = _samples(velocity, t, "velocity", "m/s")
        if np.any(v[0] != 0):
            raise InputError("a velocity history must start from 0 (the hook's speed cannot "
                             "jump) [m/s]", v[0].tolist())
        a = np.vstack([np.diff(v, axis=0) / np.diff(t)[:, None], np.zeros((1, 3))])
        return cls.from_acceleration(t, a, "previous", from_hover=from_hover, name=name)

    @classmethod
    def from_displacement(cls, time, displacement, *, from_hover=False,
                          name="displacement history"):
        """Displacement samples (n, 3) [m] at times ``time`` [s] relative to the first, each
        axis a cubic spline that leaves the first sample at rest (zero slope: the hook's
        speed cannot jump) and ends without acceleration (the hook then keeps its speed):
        ``scipy.interpolate.CubicSpline(bc_type=((1, 0), (2, 0)))``.

        Parameters
        ----------
        time : array_like, shape (n,)
            Sample times, strictly increasing, >= 0. [s]
        displacement : array_like, shape (n, 3)
            X, Y, Z displacement at each time, earth axes. [m]
        from_hover : bool
            The run starts trimmed in hover.
        name : str

        Returns
        -------
        HookTrajectory
        """
        t = _times(time, "hook trajectory")
        s = _samples(displacement, t, "displacement", "m")
        parts = tuple((_SplineMotion(t, s[:, k] - s[0, k], name), axis)
                      for k, axis in enumerate("XYZ") if np.any(s[:, k] != s[0, k]))
        if not parts:
            raise InputError("a displacement history that never moves the hook")
        return cls(parts, from_hover, name)

    @classmethod
    def forward_acceleration(cls, target, acceleration=1.0, onset=5.0, jerk_time=2.0):
        """From hover to ``target`` [m/s] along the flight path (-X): the acceleration rises
        linearly to ``acceleration`` [m/s^2] in ``jerk_time`` [s] from ``onset`` [s], holds
        and falls in ``jerk_time`` (a triangle of lower peak when the target is too small
        for a plateau).

        Parameters
        ----------
        target : float
            Final speed along the flight path. [m/s]
        acceleration : float
            Plateau acceleration. [m/s^2]
        onset : float
            Start of the manoeuvre. [s]
        jerk_time : float
            Rise and fall time of the acceleration. [s]

        Returns
        -------
        HookTrajectory
        """
        hold = target / acceleration - jerk_time
        peak, hold = (target / jerk_time, 0.0) if hold < 0 else (acceleration, hold)
        t = onset + np.array([0.0, jerk_time, jerk_time + hold, 2 * jerk_time + hold])
        if hold == 0:
            t, a = t[[0, 1, 3]], [0.0, peak, 0.0]
        else:
            a = [0.0, peak, peak, 0.0]
        return cls(((PiecewiseAcceleration(t, a), "-X"),), True,
                   f"forward acceleration to {target / KNOT:.4g} kt at {acceleration:.3g} m/s^2")

    @classmethod
    def lateral(cls, motion):
        """A lateral hook motion of :mod:`slingloads.models.carrier_motion` along +Y.

        Parameters
        ----------
        motion : object
            A one-dimensional motion with ``kinematics(t)`` and ``describe()``.

        Returns
        -------
        HookTrajectory
        """
        return cls(((motion, "Y"),), False, f"lateral hook motion: {motion.describe()}")

    # ------------------------------------------------------------------ the protocol
    @property
    def breakpoints(self):
        """Times at which the acceleration jumps or kinks. [s]"""
        times = set()
        for motion, _ in self.components:
            times.update(float(v) for v in getattr(motion, "breakpoints", ()))
        return tuple(sorted(times))

    def kinematics(self, t):
        """Displacement, velocity and acceleration relative to the steady flight.

        Parameters
        ----------
        t : array_like, shape (n,)
            [s]

        Returns
        -------
        s, v, a : ndarray, shape (n, 3)
            Displacement [m], velocity [m/s] and acceleration [m/s^2], earth axes.
        """
        t = np.asarray(t, dtype=float).reshape(-1)
        out = np.zeros((3, t.size, 3))
        for motion, e in self.components:
            s, v, a = (np.broadcast_to(np.asarray(x, float), t.shape)
                       for x in motion.kinematics(t))
            out += np.stack([s, v, a])[:, :, None] * e
        return out[0], out[1], out[2]

    def command(self, t, v0):
        """Commanded acceleration and velocity of the hook.

        Parameters
        ----------
        t : array_like, shape (n,)
            [s]
        v0 : array_like, shape (3,)
            The steady velocity, earth axes. [m/s]

        Returns
        -------
        a, v : ndarray, shape (n, 3)
            Acceleration [m/s^2] and velocity [m/s], earth axes.
        """
        _, v, a = self.kinematics(t)
        return a, v + np.asarray(v0, float)

    def describe(self):
        """The trajectory's name, for the run tables.

        Returns
        -------
        str
        """
        return self.name

    def lateral_motion(self):
        """The hook's motion along +Y as a one-dimensional carrier motion (S, S', S'') for
        the lateral-pendulum study (:mod:`slingloads.analyses.lateral`); the other axes are
        not part of that model.

        Returns
        -------
        object
            A one-dimensional motion with ``kinematics(t)`` -> S [m], S' [m/s], S'' [m/s^2].
        """
        return _Projected(self, _direction("Y"))


@dataclass(frozen=True, eq=False)
class _Projected(Motion):
    """A hook trajectory's motion along one direction: a one-dimensional carrier motion."""

    trajectory: HookTrajectory
    direction: np.ndarray

    velocity_jump = 0.0

    @property
    def breakpoints(self):
        return self.trajectory.breakpoints

    @property
    def end_time(self):
        return max(self.breakpoints, default=0.0)

    def kinematics(self, t):
        t = np.asarray(t, dtype=float)
        s, v, a = self.trajectory.kinematics(t.reshape(-1))
        e = self.direction
        return tuple((x @ e).reshape(t.shape) for x in (s, v, a))

    def describe(self):
        return f"{self.trajectory.describe()} (its Y motion)"


class _SplineMotion(Motion):
    """Displacement samples joined by a cubic spline starting at rest (one axis); the speed
    reached is kept after the last sample."""

    velocity_jump = 0.0

    def __init__(self, time, displacement, name):
        from scipy.interpolate import CubicSpline

        self.time, self.name = time, name
        self._s = CubicSpline(time, displacement, bc_type=((1, 0.0), (2, 0.0)))
        self._v, self._a = self._s.derivative(1), self._s.derivative(2)
        self._end = (float(time[-1]), float(self._s(time[-1])), float(self._v(time[-1])))

    @property
    def breakpoints(self):
        return (float(self.time[0]), float(self.time[-1]))

    @property
    def end_time(self):
        return self._end[0]

    def describe(self):
        return f"{self.name} ({self.time.size} samples)"

    def kinematics(self, t):
        t = np.asarray(t, dtype=float)
        t0, (t1, s1, v1) = self.time[0], self._end
        inside = np.clip(t, t0, t1)
        before, after = t < t0, t > t1
        s = np.where(after, s1 + v1 * (t - t1), self._s(inside))
        return (np.where(before, 0.0, s), np.where(before, 0.0, self._v(inside)),
                np.where(before | after, 0.0, self._a(inside)))


def _samples(values, t, what, unit):
    v = np.asarray(values, dtype=float)
    if v.shape != (t.size, 3) or not np.all(np.isfinite(v)):
        raise InputError(f"a hook trajectory needs one finite (X, Y, Z) {what} per time "
                         f"({t.size} times) [{unit}]", list(v.shape))
    return v

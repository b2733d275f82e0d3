"""Lateral motions S(t) of the carrier's hook, with their velocity and acceleration.

The carrier (the rotorcraft that carries the sling load) hovers and then moves its hook
sideways along the lateral axis y (positive right). Every motion starts at t = 0 from rest at
S = 0 unless it says otherwise, and every function of time broadcasts over numpy arrays, so a
run or a whole sweep can evaluate it in one call.

Five kinds are offered, each named for its law:

* :class:`QuinticStep`: a displacement step of given amplitude reached in a given time along
  the quintic (minimum-jerk) law :math:`S = A (10\\tau^3 - 15\\tau^4 + 6\\tau^5)`,
  :math:`\\tau = t/T`; its peak acceleration is :math:`(10/\\sqrt{3})\\,A/T^2`.
* :class:`CycloidalStep`: the same step along the cycloidal law
  :math:`S = A (\\tau - \\sin(2\\pi\\tau)/(2\\pi))`, one sine period of acceleration; its
  peak acceleration is :math:`2\\pi A/T^2`.
* :class:`ConstantAcceleration`: acceleration ``a`` held for ``T``, then either holding the
  speed reached (``then="hold"``) or decelerating at ``-a`` for another ``T`` to stop
  (``then="stop"``).
* :class:`VelocityStep`: the hook's speed jumps from 0 to ``dV`` at t = 0.
* :class:`TimeHistory`: displacement samples (from a workbook or CSV file, read by the io
  layer), interpolated by a natural cubic spline so that velocity and acceleration exist
  (:mod:`slingloads.models.cubic_spline`, scipy's ``CubicSpline`` computed with numpy).

Every motion also has :meth:`~Motion.kinematics_at`, the same numbers at one time in plain
Python floats. It exists for speed: the right-hand side of an adaptive solve
(:func:`slingloads.analyses.lateral.simulate`) asks for the kinematics at one time thousands
of times, and numpy on 0-d arrays costs 20 to 110 us a call where floats and :mod:`math`
take 0.3 to 5 us. It is exact, not an approximation: each kind evaluates its law with the
same operations in the same order (the cycloid's law is written once for both, with
``xp=np`` or ``xp=math``; ``min(max(x, lo), hi)`` is np.clip's value, -0.0 and nan
included; the spline's pieces are summed as scipy sums them), and math's sin and cos give
the same doubles as numpy's, so it returns what :meth:`~Motion.kinematics` returns for one
time to the last bit (tested in ``tests/test_carrier_motion.py``; for a whole array of times
numpy computes some powers otherwise, within an ulp).

:class:`MotionBatch` evaluates many motions (one per run of a sweep) at one time in a few
vectorised calls, one per kind of motion, not one per run.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

import numpy as np

from slingloads.checks import finite as _finite
from slingloads.checks import positive as _positive
from slingloads.errors import InputError
from slingloads.models.cubic_spline import natural_cubic_spline

#: Peak acceleration of the unit quintic step over unit time: 10/sqrt(3). [-]
QUINTIC_PEAK = 10.0 / np.sqrt(3.0)
#: Peak acceleration of the cycloidal step over A/T^2: 2 pi. [-]
CYCLOIDAL_PEAK = 2.0 * np.pi


class Motion:
    """What every carrier motion offers: the hook's lateral displacement S(t), velocity S'(t)
    and acceleration S''(t). A motion defines ``_params()`` and a static
    ``_kinematics(t, **params)`` (vectorised, used by :class:`MotionBatch`), or overrides
    :meth:`kinematics`, and overrides :meth:`kinematics_at` with its law in floats."""

    def kinematics(self, t):
        """Displacement, velocity and acceleration of the hook at times ``t``.

        Parameters
        ----------
        t : float or array_like
            Times from the start of the motion. [s]

        Returns
        -------
        S, S', S'' : ndarray, shaped as ``t``
            [m], [m/s], [m/s^2]
        """
        return self._kinematics(np.asarray(t, dtype=float), **self._params())

    def kinematics_at(self, t):
        """S, S' and S'' at one time ``t``, as floats.

        The same numbers as :meth:`kinematics`; each kind of motion overrides this with its
        law in plain floats (see the module's notes), this generic form converts the array
        path's results.

        Parameters
        ----------
        t : float
            Time from the start of the motion. [s]

        Returns
        -------
        S, S', S'' : float
            [m], [m/s], [m/s^2]
        """
        s, v, a = self.kinematics(float(t))
        return float(s), float(v), float(a)

    def displacement(self, t):
        """S(t).

        Parameters
        ----------
        t : float or array_like
            [s]

        Returns
        -------
        ndarray
            [m]
        """
        return self.kinematics(t)[0]

    def velocity(self, t):
        """S'(t).

        Parameters
        ----------
        t : float or array_like
            [s]

        Returns
        -------
        ndarray
            [m/s]
        """
        return self.kinematics(t)[1]

    def acceleration(self, t):
        """S''(t).

        Parameters
        ----------
        t : float or array_like
            [s]

        Returns
        -------
        ndarray
            [m/s^2]
        """
        return self.kinematics(t)[2]


@dataclass(frozen=True)
class _DisplacementStep(Motion):
    """A displacement step of amplitude A completed in duration T along a fixed law
    S = A f(t/T), at rest at both ends; a subclass gives the law (:meth:`_law`), its peak
    acceleration over A/T^2 (``PEAK``) and its name."""

    amplitude: float
    duration: float

    PEAK = np.nan
    law = ""

    def __post_init__(self):
        object.__setattr__(self, "amplitude", _finite(
            self.amplitude, f"{self.law} step amplitude must be a finite number [m]"))
        object.__setattr__(self, "duration", _positive(
            self.duration, f"{self.law} step duration must be > 0 [s]"))

    @classmethod
    def from_peak_acceleration(cls, acceleration, duration):
        """The step of ``duration`` [s] whose peak acceleration is ``acceleration`` [m/s^2]."""
        duration = _positive(duration, f"{cls.law} step duration must be > 0 [s]")
        return cls(float(acceleration) * duration**2 / cls.PEAK, duration)

    @property
    def peak_acceleration(self):
        """Largest |S''|. [m/s^2]"""
        return self.PEAK * abs(self.amplitude) / self.duration**2

    @property
    def end_time(self):
        """Time after which the hook no longer accelerates. [s]"""
        return self.duration

    @property
    def breakpoints(self):
        """Times where the motion is not smooth (its jerk or snap jumps). [s]"""
        return (0.0, self.duration)

    velocity_jump = 0.0

    def describe(self):
        """One-line description for tables."""
        # the amplitude to 6 digits: a report quotes it at a length cell's precision
        return (f"{self.law} step {self.amplitude:.6g} m over {self.duration:.4g} s "
                f"(peak {self.peak_acceleration:.4g} m/s^2)")

    def _params(self):
        return {"amplitude": self.amplitude, "duration": self.duration}

    @classmethod
    def _kinematics(cls, t, amplitude, duration):
        tau = np.clip(t / duration, 0.0, 1.0)
        inside = (t > 0) & (t < duration)
        f, df, ddf = cls._law(tau)
        return (amplitude * f, np.where(inside, amplitude / duration * df, 0.0),
                np.where(inside, amplitude / duration**2 * ddf, 0.0))

    def kinematics_at(self, t):
        """S [m], S' [m/s], S'' [m/s^2] at one time ``t`` [s]: :meth:`_kinematics` in floats,
        the same law (:meth:`_law` with :mod:`math`) and the same operations."""
        t, amplitude, duration = float(t), self.amplitude, self.duration
        tau = min(max(t / duration, 0.0), 1.0)  # np.clip's value (-0.0 and nan kept)
        f, df, ddf = self._law(tau, math)
        if 0 < t < duration:
            return amplitude * f, amplitude / duration * df, amplitude / duration**2 * ddf
        return amplitude * f, 0.0, 0.0


@dataclass(frozen=True)
class QuinticStep(_DisplacementStep):
    """Lateral displacement step of the hook along the quintic (minimum-jerk) law.

    .. math::

        S(t) = A\\,(10\\tau^3 - 15\\tau^4 + 6\\tau^5), \\quad \\tau = \\min(\\max(t/T, 0), 1)

    the polynomial of least integrated squared jerk with velocity and acceleration zero at
    both ends [1]_. The acceleration is continuous and peaks at :math:`(10/\\sqrt{3})\\,A/T^2`
    at :math:`\\tau = (3 - \\sqrt{3})/6`; the jerk jumps at both ends.

    Parameters
    ----------
    amplitude : float
        Final displacement A, positive to the right. [m]
    duration : float
        Time T taken by the step, > 0. [s]

    References
    ----------
    .. [1] T. Flash, N. Hogan, "The coordination of arm movements: an experimentally
       confirmed mathematical model", Journal of Neuroscience 5(7), 1985.
    """

    kind = "quintic_step"
    law = "quintic"
    PEAK = QUINTIC_PEAK

    @staticmethod
    def _law(tau, xp=np):
        """f, f', f'' of tau (array or float; ``xp`` unused: the law is a polynomial)."""
        return (tau**3 * (10.0 - 15.0 * tau + 6.0 * tau**2),
                30.0 * tau**2 * (1.0 - tau) ** 2,
                60.0 * tau * (1.0 - tau) * (1.0 - 2.0 * tau))


@dataclass(frozen=True)
class CycloidalStep(_DisplacementStep):
    """Lateral displacement step of the hook along the cycloidal law.

    .. math::

        S(t) = A\\left(\\tau - \\frac{\\sin 2\\pi\\tau}{2\\pi}\\right), \\quad
        \\tau = \\min(\\max(t/T, 0), 1)

    the rest-to-rest law common in the cam and trajectory-planning literature [1]_: one
    sine period of acceleration, :math:`\\ddot S = (2\\pi A/T^2) \\sin 2\\pi\\tau`, zero at
    both ends, peaking at :math:`2\\pi A/T^2` at :math:`\\tau = 1/4` (9 % above the quintic
    law's peak for the same step); the jerk jumps at both ends.

    Parameters
    ----------
    amplitude : float
        Final displacement A, positive to the right. [m]
    duration : float
        Time T taken by the step, > 0. [s]

    References
    ----------
    .. [1] R. L. Norton, "Cam Design and Manufacturing Handbook", 2nd ed., Industrial Press,
       2009, ch. 3 (cycloidal displacement).
    """

    kind = "cycloidal_step"
    law = "cycloidal"
    PEAK = CYCLOIDAL_PEAK

    @staticmethod
    def _law(tau, xp=np):
        """f, f', f'' of tau: arrays with ``xp=np``, floats with ``xp=math``."""
        phase = 2.0 * xp.pi * tau
        return (tau - xp.sin(phase) / (2.0 * xp.pi), 1.0 - xp.cos(phase),
                2.0 * xp.pi * xp.sin(phase))


@dataclass(frozen=True)
class ConstantAcceleration(Motion):
    """Hook accelerated at a constant rate, then holding its speed or stopping.

    ``then="hold"``: :math:`S'' = a` for :math:`0 \\le t < T`, then 0 (speed :math:`aT` kept).
    ``then="stop"``: :math:`S'' = a` for :math:`0 \\le t < T`, :math:`-a` for
    :math:`T \\le t < 2T`, then 0 (the hook ends at rest, :math:`aT^2` from its start).

    Parameters
    ----------
    rate : float
        The acceleration a, positive to the right. [m/s^2]
    duration : float
        T, time of the acceleration phase, > 0. [s]
    then : {"hold", "stop"}
        What follows the acceleration phase.
    """

    rate: float
    duration: float
    then: str = "hold"

    kind = "constant_acceleration"
    THEN = ("hold", "stop")

    def __post_init__(self):
        object.__setattr__(self, "rate", _finite(
            self.rate, "constant acceleration must be a finite number [m/s^2]"))
        object.__setattr__(self, "duration", _positive(
            self.duration, "constant-acceleration duration must be > 0 [s]"))
        if self.then not in self.THEN:
            raise InputError(
                f"constant-acceleration 'then' is not a valid option; valid options are "
                f"{list(self.THEN)}", self.then)

    @property
    def peak_acceleration(self):
        """Largest |S''|. [m/s^2]"""
        return abs(self.rate)

    @property
    def end_time(self):
        """Time after which the hook no longer accelerates. [s]"""
        return self.duration * (2.0 if self.then == "stop" else 1.0)

    @property
    def breakpoints(self):
        """Times where the acceleration jumps. [s]"""
        return (0.0, self.duration) + ((2.0 * self.duration,) if self.then == "stop" else ())

    velocity_jump = 0.0

    def describe(self):
        """One-line description for tables.

        Returns
        -------
        str
        """
        return (f"constant acceleration {self.rate:.4g} m/s^2 for "
                f"{self.duration:.4g} s, then {self.then}")

    def _params(self):
        return {"rate": self.rate, "duration": self.duration,
                "stop": float(self.then == "stop")}

    @staticmethod
    def _kinematics(t, rate, duration, stop):
        a, T = rate, duration
        t1 = np.clip(t, 0.0, T)                       # time spent accelerating
        t2 = np.clip(t - T, 0.0, T) * stop            # time spent decelerating (stop only)
        t3 = np.maximum(t - T, 0.0) * (1.0 - stop)    # time spent holding speed (hold only)
        s = 0.5 * a * t1**2 + a * T * t2 - 0.5 * a * t2**2 + a * T * t3
        v = a * t1 - a * t2
        acc = (np.where((t >= 0) & (t < T), a, 0.0)
               - np.where((t >= T) & (t < 2.0 * T), a * stop, 0.0))
        return s, v, acc

    def kinematics_at(self, t):
        """S, S', S'' at one time, as floats: :meth:`_kinematics` operation for operation
        (``min(max(x, lo), hi)`` is np.clip's value).

        Parameters
        ----------
        t : float
            Time. [s]

        Returns
        -------
        s : float
            Hook displacement. [m]
        v : float
            Hook velocity. [m/s]
        a : float
            Hook acceleration. [m/s^2]
        """
        t, a, T = float(t), self.rate, self.duration
        stop = float(self.then == "stop")
        t1 = min(max(t, 0.0), T)
        t2 = min(max(t - T, 0.0), T) * stop
        t3 = max(t - T, 0.0) * (1.0 - stop)
        s = 0.5 * a * t1**2 + a * T * t2 - 0.5 * a * t2**2 + a * T * t3
        v = a * t1 - a * t2
        acc = (a if 0 <= t < T else 0.0) - (a * stop if T <= t < 2.0 * T else 0.0)
        return s, v, acc


@dataclass(frozen=True)
class VelocityStep(Motion):
    """Hook speed jumping from 0 to ``delta_v`` at t = 0: S(t) = dV t for t > 0.

    The acceleration is an impulse at t = 0; the models take it as a jump in the initial
    state (:attr:`velocity_jump`), and :meth:`acceleration` is zero for t > 0.

    Parameters
    ----------
    delta_v : float
        Speed reached, positive to the right. [m/s]
    """

    delta_v: float

    kind = "velocity_step"

    def __post_init__(self):
        object.__setattr__(self, "delta_v", _finite(
            self.delta_v, "velocity step must be a finite number [m/s]"))

    @property
    def velocity_jump(self):
        """Jump of the hook's speed at t = 0. [m/s]"""
        return self.delta_v

    peak_acceleration = np.inf
    end_time = 0.0
    breakpoints = (0.0,)

    def describe(self):
        """One-line description for tables.

        Returns
        -------
        str
        """
        return f"velocity step {self.delta_v:.4g} m/s"

    def _params(self):
        return {"delta_v": self.delta_v}

    @staticmethod
    def _kinematics(t, delta_v):
        after = t > 0
        s = np.where(after, delta_v * t, 0.0)
        v = np.where(after, delta_v + 0.0 * t, 0.0)
        return s, v, np.zeros_like(s)

    def kinematics_at(self, t):
        """S, S', S'' at one time, as floats: :meth:`_kinematics` in floats.

        Parameters
        ----------
        t : float
            Time. [s]

        Returns
        -------
        s : float
            Hook displacement. [m]
        v : float
            Hook velocity. [m/s]
        a : float
            Hook acceleration. [m/s^2]
        """
        t, delta_v = float(t), self.delta_v
        if t > 0:
            return delta_v * t, delta_v + 0.0 * t, 0.0
        return 0.0, 0.0, 0.0

    def velocity(self, t):
        """S'(t) (dV for t > 0).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            [m/s]
        """
        return self.kinematics(t)[1]

    def acceleration(self, t):
        """S''(t) for t > 0 (zero; the impulse at t = 0 is :attr:`velocity_jump`).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            [m/s^2]
        """
        return self.kinematics(t)[2]


@dataclass(frozen=True, eq=False)
class TimeHistory(Motion):
    """Hook displacement given as samples, interpolated by a natural cubic spline.

    Times are taken relative to the first sample, which becomes t = 0 of a run. The hook is
    at rest before it; if the spline's slope at the first sample is not zero the hook's
    speed jumps there (:attr:`velocity_jump`). After the last sample the hook keeps the
    spline's final speed (the natural spline has zero acceleration at both ends, so the
    acceleration stays continuous).

    Parameters
    ----------
    time : array_like, shape (n,)
        Sample times, strictly increasing, n >= 2. [s]
    displacement : array_like, shape (n,)
        Lateral hook displacement, positive to the right. [m]
    name : str
        Where the history came from, used in tables ("CSV file carrier.csv").

    Raises
    ------
    InputError
        If the times are not strictly increasing, or samples are missing or not finite.
    """

    time: np.ndarray
    displacement_samples: np.ndarray
    name: str = "time history"

    kind = "time_history"

    def __post_init__(self):
        t = np.asarray(self.time, dtype=float)
        s = np.asarray(self.displacement_samples, dtype=float)
        if t.ndim != 1 or t.size < 2:
            raise InputError("a carrier time history needs at least two samples",
                             np.atleast_1d(t).tolist())
        if s.shape != t.shape:
            raise InputError(f"a carrier time history needs one displacement per time "
                             f"({t.size} times, {s.size} displacements)", s.size)
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(s))):
            raise InputError("carrier time-history samples must be finite numbers")
        steps = np.diff(t)
        if np.any(steps <= 0):
            i = int(np.argmax(steps <= 0))
            raise InputError(
                f"carrier time-history times must be strictly increasing; sample {i + 2} "
                f"(t = {t[i + 1]:.6g} s) does not come after sample {i + 1} "
                f"(t = {t[i]:.6g} s)", t[i + 1].item())
        t = t - t[0]
        spline = natural_cubic_spline(t, s - s[0])  # scipy's CubicSpline, natural, in numpy
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "displacement_samples", s - s[0])
        object.__setattr__(self, "_spline", spline)
        object.__setattr__(self, "_d1", spline.derivative(1))
        object.__setattr__(self, "_d2", spline.derivative(2))
        # for kinematics_at: the knots, and per interval the coefficients of S, S', S''
        object.__setattr__(self, "_knots", t.tolist())
        pieces = np.vstack([spline.c, self._d1.c, self._d2.c]).T.copy()  # (intervals, 9)
        object.__setattr__(self, "_pieces", pieces)
        object.__setattr__(self, "_v_end", float(self._d1(t[-1])))

    @property
    def velocity_jump(self):
        """Speed of the hook just after t = 0 (it is at rest before). [m/s]"""
        return float(self._d1(0.0))

    @property
    def peak_acceleration(self):
        """Largest |S''| (at a sample, the spline's acceleration being piecewise linear). [m/s^2]"""
        return float(np.max(np.abs(self._d2(self.time))))

    @property
    def end_time(self):
        """Time of the last sample. [s]"""
        return float(self.time[-1])

    @property
    def breakpoints(self):
        """First and last sample times. [s]"""
        return (0.0, float(self.time[-1]))

    @property
    def min_interval(self):
        """Smallest time between samples: a solver step limit. [s]"""
        return float(np.min(np.diff(self.time)))

    def describe(self):
        """One-line description for tables.

        Returns
        -------
        str
        """
        return f"{self.name} ({self.time.size} samples over {self.end_time:.4g} s)"

    def kinematics(self, t):
        """Displacement, velocity and acceleration at times ``t``.

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        s : ndarray
            Hook displacement. [m]
        v : ndarray
            Hook velocity. [m/s]
        a : ndarray
            Hook acceleration. [m/s^2]
        """
        t = np.asarray(t, dtype=float)
        t_end = self.time[-1]
        inside = np.clip(t, 0.0, t_end)
        v_end = float(self._d1(t_end))
        s = np.where(t < 0, 0.0, self._spline(inside) + v_end * np.maximum(t - t_end, 0.0))
        v = np.where(t < 0, 0.0, self._d1(inside))
        a = np.where((t < 0) | (t > t_end), 0.0, self._d2(inside))
        return s, v, a

    def kinematics_at(self, t):
        """S [m], S' [m/s], S'' [m/s^2] at one time ``t`` [s]: :meth:`kinematics` in floats.

        The spline's pieces are evaluated as scipy's ``PPoly`` does (and
        :class:`~slingloads.models.cubic_spline.PiecewiseCubic`): the interval with
        ``x[i] <= t < x[i + 1]`` (the last one closed), then the sum of ``c[k] s**(m - k)``,
        ``s = t - x[i]``, from the constant term up, the powers by repeated products.

        Parameters
        ----------
        t : float
            Time. [s]

        Returns
        -------
        s, v, a : float
            Displacement [m], velocity [m/s], acceleration [m/s^2].
        """
        t = float(t)
        if t < 0:
            return 0.0, 0.0, 0.0
        knots = self._knots
        t_end = knots[-1]
        x = min(t, t_end)
        i = min(bisect.bisect_right(knots, x), len(knots) - 1) - 1
        c = self._pieces[i].tolist()
        ds = x - knots[i]
        s = _ppoly_piece(c[0:4], ds) + self._v_end * max(t - t_end, 0.0)
        a = 0.0 if t > t_end else _ppoly_piece(c[7:9], ds)
        return s, _ppoly_piece(c[4:7], ds), a


def _ppoly_piece(c, s):
    """One piece of a scipy ``PPoly`` at ``s`` from its start, summed as scipy sums it."""
    value, power = 0.0, 1.0
    for coefficient in reversed(c):
        value = value + coefficient * power
        power = power * s
    return value


#: The motion kinds by name.
MOTION_TYPES = {cls.kind: cls for cls in (QuinticStep, CycloidalStep, ConstantAcceleration,
                                          VelocityStep, TimeHistory)}
#: Former names still accepted: the quintic step was called the "smooth step".
MOTION_ALIASES = {"smooth_step": "quintic_step"}

_PARAMETERS = {
    "quintic_step": ("amplitude", "duration"),
    "cycloidal_step": ("amplitude", "duration"),
    "constant_acceleration": ("rate", "duration", "then"),
    "velocity_step": ("delta_v",),
    "time_history": ("time", "displacement_samples", "name"),
}


def make_motion(kind, **parameters):
    """Build a carrier motion from its type name and parameters (as read from a workbook).

    Parameters
    ----------
    kind : str
        One of ``"quintic_step"``, ``"cycloidal_step"``, ``"constant_acceleration"``,
        ``"velocity_step"``, ``"time_history"`` (``"smooth_step"``, the former name of the
        quintic step, is accepted).
    **parameters
        The parameters of that motion class, in SI.

    Returns
    -------
    carrier motion
        An instance of the motion class named.

    Raises
    ------
    InputError
        For an unknown type, or a parameter the type does not take.

    Examples
    --------
    >>> make_motion("constant_acceleration", rate=4.9, duration=2.0, then="stop")
    ConstantAcceleration(rate=4.9, duration=2.0, then='stop')
    """
    kind = MOTION_ALIASES.get(kind, kind)
    if kind not in MOTION_TYPES:
        raise InputError(f"unknown carrier motion type; valid types are {sorted(MOTION_TYPES)}",
                         kind)
    allowed = _PARAMETERS[kind]
    unknown = sorted(set(parameters) - set(allowed))
    if unknown:
        raise InputError(f"carrier motion {kind!r} takes the parameters {list(allowed)}; "
                         f"unknown parameter", unknown[0])
    return MOTION_TYPES[kind](**parameters)


class MotionBatch:
    """Many carrier motions, one per run, evaluated together.

    Motions of one analytic kind are evaluated in one vectorised call over their parameter
    arrays; time histories in one call per distinct history object. The cost of one
    evaluation therefore grows with the number of kinds and distinct histories, not with the
    number of runs.

    Parameters
    ----------
    motions : sequence of motion objects
    """

    def __init__(self, motions):
        motions = list(motions)
        if not motions:
            raise InputError("a motion batch needs at least one motion")
        self.motions = motions
        self.size = len(motions)
        self._groups = []
        by_kind = {}
        histories = {}
        for i, motion in enumerate(motions):
            if type(motion) in MOTION_TYPES.values() and not isinstance(motion, TimeHistory):
                by_kind.setdefault(type(motion), []).append(i)
            elif callable(getattr(motion, "kinematics", None)):  # histories, piecewise...
                histories.setdefault(id(motion), (motion, []))[1].append(i)
            else:
                raise InputError("unknown carrier motion object; valid types are "
                                 f"{sorted(MOTION_TYPES)}", type(motion).__name__)
        for cls, idx in by_kind.items():
            params = [motions[i]._params() for i in idx]
            arrays = {k: np.array([p[k] for p in params]) for k in params[0]}
            self._groups.append((np.array(idx), cls._kinematics, arrays))
        for motion, idx in histories.values():
            self._groups.append((np.array(idx), lambda t, _m=motion: _m.kinematics(t), {}))
        self.velocity_jump = np.array([m.velocity_jump for m in motions], dtype=float)

    def kinematics(self, t):
        """S, S', S'' of every run at one time.

        Parameters
        ----------
        t : float
            Time. [s]

        Returns
        -------
        ndarray, shape (3, runs)
            Displacement [m], velocity [m/s] and acceleration [m/s^2] of each run.
        """
        out = np.empty((3, self.size))
        for idx, function, arrays in self._groups:
            s, v, a = function(np.float64(t), **arrays)
            out[0, idx], out[1, idx], out[2, idx] = s, v, a
        return out

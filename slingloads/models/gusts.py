"""Lateral gusts for the yaw analyses: step, finite-duration, 1-cosine, continuous, tabulated.

Each gust gives the lateral gust velocity ``v(t)`` [m/s] of the air, positive when the air
moves from the right to the left of the flight path (so that a positive gust makes a positive
sideslip, "wind from the right"). CS 29.341 asks for 30 ft/s (9.144 m/s) horizontal gusts at
each critical airspeed and prescribes no shape [1]_, so several shapes are offered. All are
right-continuous (``v`` at a jump time is the value after the jump) and expose the times of
their jumps and kinks (:attr:`breakpoints`) so an integrator can step on them.

References
----------
.. [1] EASA, CS-29 "Certification Specifications for Large Rotorcraft", CS 29.341 Gust loads.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import finite, positive
from slingloads.constants import FOOT
from slingloads.errors import InputError

#: CS 29.341 gust velocity, 30 ft/s. [m/s]
GUST_VELOCITY = 30.0 * FOOT
#: Default gust onset: the paper applies its gust at t = 30 s after a trimmed start. [s]
GUST_ONSET = 30.0
#: Default duration of finite-duration and 1-cosine gusts, and period of the continuous one. [s]
GUST_DURATION = 10.0


def _finite(value, name, unit):
    return finite(value, f"gust {name} must be a finite number [{unit}]")


def _positive(value, name, unit):
    _finite(value, name, unit)
    return positive(value, f"gust {name} must be > 0 [{unit}]")


@dataclass(frozen=True)
class StepGust:
    """Sharp-edged gust that starts at ``onset`` and stays.

    Parameters
    ----------
    amplitude : float
        Lateral gust velocity; negative for a gust from the left. [m/s]
    onset : float
        Start time, >= 0. [s]
    """

    amplitude: float = GUST_VELOCITY
    onset: float = GUST_ONSET

    kind = "step"

    def __post_init__(self):
        object.__setattr__(self, "amplitude", _finite(self.amplitude, "amplitude", "m/s"))
        onset = _finite(self.onset, "onset", "s")
        if onset < 0:
            raise InputError("gust onset must be >= 0 [s]", onset)
        object.__setattr__(self, "onset", onset)

    @property
    def breakpoints(self):
        """Times at which the gust jumps or kinks. [s]"""
        return (self.onset,)

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return self.onset

    @property
    def peak(self):
        """Largest |v(t)|. [m/s]"""
        return abs(self.amplitude)

    @property
    def label(self):
        return f"step {self.amplitude:.3g} m/s"

    def velocity(self, t):
        """Lateral gust velocity [m/s] at times ``t`` [s] (array_like)."""
        t = np.asarray(t, dtype=float)
        return np.where(t >= self.onset, self.amplitude, 0.0)


@dataclass(frozen=True)
class FiniteGust(StepGust):
    """Rectangular ("impulsive") gust of ``duration`` seconds, e.g. the paper's 10 s gust.

    Parameters
    ----------
    amplitude : float
        [m/s]
    onset : float
        [s]
    duration : float
        > 0. [s]
    """

    duration: float = GUST_DURATION

    kind = "finite"

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "duration", _positive(self.duration, "duration", "s"))

    @property
    def breakpoints(self):
        return (self.onset, self.onset + self.duration)

    @property
    def end(self):
        return self.onset + self.duration

    @property
    def label(self):
        return f"finite {self.amplitude:.3g} m/s, {self.duration:.3g} s"

    def velocity(self, t):
        t = np.asarray(t, dtype=float)
        inside = (t >= self.onset) & (t < self.onset + self.duration)
        return np.where(inside, self.amplitude, 0.0)


@dataclass(frozen=True)
class OneMinusCosineGust(FiniteGust):
    """Discrete 1-cosine gust: v = A/2 (1 - cos(2 pi (t - onset) / duration)) over its duration."""

    kind = "1-cosine"

    @property
    def label(self):
        return f"1-cosine {self.amplitude:.3g} m/s, {self.duration:.3g} s"

    def velocity(self, t):
        t = np.asarray(t, dtype=float)
        tau = (t - self.onset) / self.duration
        inside = (tau >= 0) & (tau < 1)
        return np.where(inside, 0.5 * self.amplitude * (1.0 - np.cos(2 * np.pi * tau)), 0.0)


@dataclass(frozen=True)
class ContinuousGust(FiniteGust):
    """Continuous harmonic gust v = A sin(2 pi (t - onset) / period) from ``onset`` on.

    The ``duration`` field is the period. The worst case tunes it to the yaw natural period
    (see :func:`slingloads.analyses.chute_sizing.linear_yaw`).
    """

    kind = "continuous"

    @property
    def breakpoints(self):
        return (self.onset,)

    @property
    def end(self):
        return None

    @property
    def label(self):
        return f"continuous {self.amplitude:.3g} m/s, period {self.duration:.3g} s"

    def velocity(self, t):
        t = np.asarray(t, dtype=float)
        phase = 2 * np.pi * (t - self.onset) / self.duration
        return np.where(t >= self.onset, self.amplitude * np.sin(phase), 0.0)


@dataclass(frozen=True)
class TabulatedGust:
    """Gust time history supplied by the user (measured or synthetic turbulence).

    Linear interpolation; zero before the first time; an error after the last one.

    Parameters
    ----------
    time : array_like, shape (n,)
        Strictly increasing, >= 0. [s]
    velocity_table : array_like, shape (n,)
        Lateral gust velocity. [m/s]
    """

    time: np.ndarray
    velocity_table: np.ndarray

    kind = "tabulated"

    def __post_init__(self):
        t = np.asarray(self.time, dtype=float)
        v = np.asarray(self.velocity_table, dtype=float)
        if t.ndim != 1 or t.size < 2 or v.shape != t.shape:
            raise InputError("a tabulated gust needs at least two (time, velocity) pairs")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
            raise InputError("tabulated gust times and velocities must be finite numbers")
        steps = np.diff(t)
        if np.any(steps <= 0):
            i = int(np.argmax(steps <= 0)) + 1
            raise InputError("tabulated gust times must be strictly increasing [s]", t[i].item())
        if t[0] < 0:
            raise InputError("tabulated gust times must be >= 0 [s]", t[0].item())
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "velocity_table", v)

    @property
    def breakpoints(self):
        return (float(self.time[0]),)

    @property
    def end(self):
        return float(self.time[-1])

    @property
    def peak(self):
        return float(np.abs(self.velocity_table).max())

    @property
    def label(self):
        return f"tabulated, peak {self.peak:.3g} m/s"

    def velocity(self, t):
        t = np.asarray(t, dtype=float)
        if np.any(t > self.time[-1] * (1 + 1e-12) + 1e-12):
            bad = float(np.max(t))
            raise InputError(f"time is after the end of the tabulated gust "
                             f"({self.time[-1]:.6g} s); no extrapolation is done", bad)
        return np.where(t < self.time[0], 0.0, np.interp(t, self.time, self.velocity_table))


GUST_KINDS = {"step": StepGust, "finite": FiniteGust, "1-cosine": OneMinusCosineGust,
              "continuous": ContinuousGust}


def make_gust(kind, amplitude=GUST_VELOCITY, onset=GUST_ONSET, duration=GUST_DURATION):
    """Build a gust by name.

    Parameters
    ----------
    kind : str
        One of ``"step"``, ``"finite"``, ``"1-cosine"``, ``"continuous"``.
    amplitude : float
        [m/s]
    onset : float
        [s]
    duration : float
        Duration (finite, 1-cosine) or period (continuous); ignored for a step. [s]

    Examples
    --------
    >>> g = make_gust("finite", duration=10.0)
    >>> [float(v) for v in g.velocity([29.9, 30.0, 39.9, 40.0])]
    [0.0, 9.144, 9.144, 0.0]
    """
    if kind not in GUST_KINDS:
        raise InputError(f"{kind=!r} is not a valid gust shape. Valid shapes are: "
                         f"{', '.join(GUST_KINDS)}", kind)
    if kind == "step":
        return StepGust(amplitude, onset)
    return GUST_KINDS[kind](amplitude, onset, duration)


def standard_gusts(amplitude=GUST_VELOCITY, onset=GUST_ONSET, duration=GUST_DURATION):
    """The four shapes at the same amplitude: step, finite, 1-cosine, continuous."""
    return tuple(make_gust(k, amplitude, onset, duration) for k in GUST_KINDS)

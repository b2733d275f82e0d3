"""Lateral gusts for the yaw analyses: discrete shapes, a sustained crosswind, a harmonic gust,
Dryden continuous turbulence, and a tabulated history.

Each gust gives the lateral gust velocity ``v(t)`` [m/s] of the air, positive when the air
moves from the right to the left of the flight path (so that a positive gust makes a positive
sideslip, "wind from the right"). CS 29.341 asks for 30 ft/s (9.144 m/s) horizontal gusts at
each critical airspeed and prescribes no shape [1]_, so several are offered:

* ``step``: sharp-edged, from the onset on (:class:`StepGust`);
* ``finite``: rectangular, the paper's "impulsive" 10 s gust (:class:`FiniteGust`);
* ``1-cosine``: the discrete 1-cosine gust (:class:`OneMinusCosineGust`);
* ``continuous``: a sustained crosswind, the paper's "continuous 30 ft/s gust starting at 20 s"
  (its figure 10): it builds up over a rise time along a half cosine and is then held
  (:class:`SustainedGust`);
* ``harmonic``: a sine of given period from the onset on (:class:`HarmonicGust`), the worst
  case when its period is tuned to the yaw period;
* ``turbulence``: continuous turbulence with the Dryden lateral spectrum of MIL-F-8785C [2]_,
  one seeded, reproducible realisation (:class:`DrydenTurbulence`);
* a user time history (:class:`TabulatedGust`).

All are right-continuous (``v`` at a jump time is the value after the jump) and expose the
times of their jumps and kinks (:attr:`breakpoints`) so that an integrator can step on them;
every one is a deterministic function of time, so that every stage of an integrator sees the
same gust.

References
----------
.. [1] EASA, CS-29 "Certification Specifications for Large Rotorcraft", CS 29.341 Gust loads.
.. [2] US Department of Defense, MIL-F-8785C "Flying Qualities of Piloted Airplanes", 1980,
   section 3.7 (Dryden form, low-altitude scale lengths and intensities); MIL-HDBK-1797,
   "Flying Qualities of Piloted Aircraft", 1997, appendix A (the same spectra).
.. [3] M. Shinozuka, C.-M. Jan, "Digital simulation of random processes and its
   applications", Journal of Sound and Vibration 25(1), 1972 (sum of sinusoids with random
   phases).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from slingloads.checks import finite, positive
from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError

#: CS 29.341 gust velocity, 30 ft/s. [m/s]
GUST_VELOCITY = 30.0 * FOOT
#: Default gust onset: the paper applies its gust at t = 30 s after a trimmed start. [s]
GUST_ONSET = 30.0
#: Default duration of the finite and 1-cosine gusts, and period of the harmonic one. [s]
GUST_DURATION = 10.0
#: Default rise time of the sustained crosswind: that of the 10 s 1-cosine gust. [s]
GUST_RISE = 0.5 * GUST_DURATION
#: MIL-F-8785C wind speed at 20 ft for light, moderate and severe turbulence. [m/s]
W20 = {"light": 15.0 * KNOT, "moderate": 30.0 * KNOT, "severe": 45.0 * KNOT}
#: Altitudes above ground of the MIL-F-8785C low-altitude turbulence model. [m]
LOW_ALTITUDE_RANGE = (10.0 * FOOT, 1000.0 * FOOT)


def _finite(value, name, unit):
    return finite(value, f"gust {name} must be a finite number [{unit}]")


def _positive(value, name, unit):
    _finite(value, name, unit)
    return positive(value, f"gust {name} must be > 0 [{unit}]")


def _onset(value):
    onset = _finite(value, "onset", "s")
    if onset < 0:
        raise InputError("gust onset must be >= 0 [s]", onset)
    return onset


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
        object.__setattr__(self, "onset", _onset(self.onset))

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
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return f"step {self.amplitude:.4g} m/s"

    def velocity(self, t):
        """Lateral gust velocity at times ``t``.

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
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
        """Times at which it jumps or kinks. [s]"""
        return (self.onset, self.onset + self.duration)

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return self.onset + self.duration

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return f"finite {self.amplitude:.4g} m/s, {self.duration:.3g} s"

    def velocity(self, t):
        """Lateral gust velocity at times ``t`` (the amplitude from the onset for ``duration``).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
        t = np.asarray(t, dtype=float)
        inside = (t >= self.onset) & (t < self.onset + self.duration)
        return np.where(inside, self.amplitude, 0.0)


@dataclass(frozen=True)
class OneMinusCosineGust(FiniteGust):
    """Discrete 1-cosine gust: v = A/2 (1 - cos(2 pi (t - onset) / duration)) over its duration.

    Parameters
    ----------
    amplitude : float
        Peak lateral gust velocity A; negative for a gust from the left. [m/s]
    onset : float
        Start time, >= 0. [s]
    duration : float
        Length of the pulse, > 0. [s]
    """

    kind = "1-cosine"

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return f"1-cosine {self.amplitude:.4g} m/s, {self.duration:.3g} s"

    def velocity(self, t):
        """Lateral gust velocity at times ``t`` (a 1-cosine pulse from the onset).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
        t = np.asarray(t, dtype=float)
        tau = (t - self.onset) / self.duration
        inside = (tau >= 0) & (tau < 1)
        return np.where(inside, 0.5 * self.amplitude * (1.0 - np.cos(2 * np.pi * tau)), 0.0)


@dataclass(frozen=True)
class SustainedGust(StepGust):
    """Sustained crosswind: builds up over ``rise_time`` and is then held.

    .. math::

        v = \\tfrac{A}{2}\\left(1 - \\cos\\frac{\\pi (t - t_0)}{t_r}\\right)
        \\ \\text{for}\\ t_0 \\le t < t_0 + t_r, \\qquad v = A \\ \\text{after}

    The paper's "continuous 30 ft/s gust starting at 20 s" (its figure 10) is such a held
    crosswind, not an oscillation. The rise is the first half of a 1-cosine gust of duration
    2 t_r (velocity and its rate continuous); ``rise_time = 0`` is the sharp-edged step.

    Parameters
    ----------
    amplitude : float
        Crosswind reached. [m/s]
    onset : float
        Start of the rise, >= 0. [s]
    rise_time : float
        Time to reach the amplitude, >= 0 (default 5 s, the rise of the 10 s 1-cosine
        gust). [s]
    """

    rise_time: float = GUST_RISE

    kind = "continuous"

    def __post_init__(self):
        super().__post_init__()
        rise = _finite(self.rise_time, "rise time", "s")
        if rise < 0:
            raise InputError("gust rise time must be >= 0 [s]", rise)
        object.__setattr__(self, "rise_time", rise)

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return (self.onset, self.onset + self.rise_time) if self.rise_time > 0 else (
            self.onset,)

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return self.onset + self.rise_time

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return (f"continuous {self.amplitude:.4g} m/s held, rise {self.rise_time:.3g} s")

    def velocity(self, t):
        """Lateral gust velocity at times ``t`` (a half-cosine rise, then held).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
        t = np.asarray(t, dtype=float)
        if self.rise_time == 0:
            return np.where(t >= self.onset, self.amplitude, 0.0)
        tau = np.clip((t - self.onset) / self.rise_time, 0.0, 1.0)
        ramp = 0.5 * self.amplitude * (1.0 - np.cos(np.pi * tau))
        return np.where(t >= self.onset, ramp, 0.0)


@dataclass(frozen=True)
class HarmonicGust(StepGust):
    """Harmonic gust v = A sin(2 pi (t - onset) / period) from ``onset`` on.

    Never ends. The worst case tunes the period to the yaw natural period (see
    :func:`slingloads.analyses.chute_sizing.linear_yaw`): it is a resonance test, not a
    CS 29.341 gust.

    Parameters
    ----------
    amplitude : float
        [m/s]
    onset : float
        [s]
    period : float
        > 0 (default 10 s). [s]
    """

    period: float = GUST_DURATION

    kind = "harmonic"

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "period", _positive(self.period, "period", "s"))

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return None

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return f"harmonic {self.amplitude:.4g} m/s, period {self.period:.3g} s"

    def velocity(self, t):
        """Lateral gust velocity at times ``t`` (a sine from the onset).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
        t = np.asarray(t, dtype=float)
        phase = 2 * np.pi * (t - self.onset) / self.period
        return np.where(t >= self.onset, self.amplitude * np.sin(phase), 0.0)


def dryden_lateral_spectrum(omega, intensity, scale_length, tas):
    """One-sided Dryden power spectral density of the lateral gust velocity against time
    frequency (MIL-F-8785C, frozen field: omega = V Omega).

    .. math::

        \\Phi_v(\\omega) = \\sigma_v^2 \\frac{L_v}{\\pi V}
            \\frac{1 + 3 (L_v \\omega / V)^2}{\\left(1 + (L_v \\omega / V)^2\\right)^2},
        \\qquad \\int_0^\\infty \\Phi_v\\,d\\omega = \\sigma_v^2

    MIL-HDBK-1797 writes the same spectrum with a scale length half as long
    (:math:`2 L_v` in place of :math:`L_v`).

    Parameters
    ----------
    omega : array_like
        Circular frequency, >= 0. [rad/s]
    intensity : float
        sigma_v. [m/s]
    scale_length : float
        L_v (MIL-F-8785C). [m]
    tas : float
        True airspeed V. [m/s]

    Returns
    -------
    ndarray
        [m^2/s^2 per rad/s]
    """
    x = scale_length * np.asarray(omega, dtype=float) / tas
    return intensity**2 * scale_length / (np.pi * tas) * (1 + 3 * x**2) / (1 + x**2) ** 2


def dryden_variance_fraction(x):
    """Share of the Dryden lateral variance below a reduced frequency.

    :math:`F(x) = (2\\arctan x - x/(1 + x^2))/\\pi` (the spectrum integrated in closed form;
    F(0) = 0, F(inf) = 1).

    Parameters
    ----------
    x : array_like
        Reduced frequency L_v omega / V, >= 0. [-]

    Returns
    -------
    ndarray
        F(x). [-]
    """
    x = np.asarray(x, dtype=float)
    return (2.0 * np.arctan(x) - x / (1.0 + x * x)) / np.pi


def low_altitude_turbulence(altitude, severity="moderate"):
    """MIL-F-8785C low-altitude lateral turbulence intensity and scale length.

    .. math::

        L_v = \\frac{h}{(0.177 + 0.000823\\,h)^{1.2}}, \\qquad
        \\sigma_v = \\frac{0.1\\,W_{20}}{(0.177 + 0.000823\\,h)^{0.4}}
        \\qquad (h \\text{ in ft, } 10 \\le h \\le 1000)

    with W20 the wind speed at 20 ft: 15, 30 and 45 kt for light, moderate and severe
    turbulence.

    Parameters
    ----------
    altitude : float
        Height above ground h, 10 ft to 1000 ft (3.048 m to 304.8 m). [m]
    severity : {"light", "moderate", "severe"}

    Returns
    -------
    intensity : float
        sigma_v. [m/s]
    scale_length : float
        L_v. [m]

    Raises
    ------
    InputError
        Outside the model's altitude range (give the intensity and scale length of the
        medium/high-altitude model yourself there), or for an unknown severity.
    """
    if severity not in W20:
        raise InputError(f"{severity=!r} is not a valid turbulence severity. Valid options "
                         f"are: {', '.join(W20)}", severity)
    h = _finite(altitude, "turbulence altitude", "m")
    lo, hi = LOW_ALTITUDE_RANGE
    if not lo <= h <= hi:
        raise InputError(f"the MIL-F-8785C low-altitude turbulence model holds from "
                         f"{lo:.4g} m to {hi:.4g} m (10 to 1000 ft) above ground; give the "
                         f"intensity and scale length of the medium/high-altitude model "
                         f"instead [m]", h)
    h_ft = h / FOOT
    base = 0.177 + 0.000823 * h_ft
    return 0.1 * W20[severity] / base**0.4, h_ft / base**1.2 * FOOT


@dataclass(frozen=True, eq=False)
class DrydenTurbulence:
    """Continuous lateral turbulence with the Dryden spectrum: one seeded realisation.

    The gust velocity is a sum of sinusoids with random phases [3]_,

    .. math:: v(t) = \\sum_k a_k \\cos(\\omega_k (t - t_0) + \\varphi_k)

    over ``components`` frequency bins spaced evenly in log(L_v omega / V) across ``band``:
    each frequency is drawn within its bin, each phase in [0, 2 pi), and each amplitude
    carries the closed-form variance of its bin, :math:`a_k^2 / 2 = \\sigma_v^2 [F(x_{k+1}) -
    F(x_k)]` (:func:`dryden_variance_fraction`), so that the realisation's spectrum follows
    :func:`dryden_lateral_spectrum` and its variance is sigma_v^2 times the band's share
    (:attr:`variance_fraction`, 0.990 for the default band; the rest lies above 100 V/L_v,
    far above the yaw and swing frequencies). The same ``seed`` gives the same history, at
    any time, for any integrator. The turbulence acts from ``onset`` for ``duration``
    seconds (it jumps in and out there) and is zero outside.

    Parameters
    ----------
    intensity : float
        sigma_v, > 0 (see :func:`low_altitude_turbulence`). [m/s]
    scale_length : float
        L_v of MIL-F-8785C, > 0. [m]
    tas : float
        True airspeed that carries the aircraft through the frozen field, > 0. [m/s]
    onset : float
        >= 0. [s]
    duration : float
        > 0. [s]
    seed : int
        Seed of the realisation (numpy ``default_rng``). [-]
    components : int
        Number of sinusoids, >= 16. [count]
    band : (float, float)
        Reduced-frequency range (x = L_v omega / V) covered, 0 < low < high. [-]
    """

    intensity: float
    scale_length: float
    tas: float
    onset: float = GUST_ONSET
    duration: float = 60.0
    seed: int = 0
    components: int = 400
    band: tuple = (1e-3, 1e2)

    kind = "turbulence"

    def __post_init__(self):
        for name, unit in (("intensity", "m/s"), ("scale_length", "m"), ("tas", "m/s"),
                           ("duration", "s")):
            object.__setattr__(self, name, _positive(getattr(self, name),
                                                     name.replace("_", " "), unit))
        object.__setattr__(self, "onset", _onset(self.onset))
        if int(self.components) != self.components or self.components < 16:
            raise InputError("turbulence components must be a whole number >= 16",
                             self.components)
        if int(self.seed) != self.seed:
            raise InputError("turbulence seed must be a whole number", self.seed)
        lo, hi = (float(v) for v in self.band)
        if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo < hi):
            raise InputError("turbulence band must be two reduced frequencies 0 < low < high",
                             self.band)
        n = int(self.components)
        edges = np.geomspace(lo, hi, n + 1)
        rng = np.random.default_rng(int(self.seed))
        x = np.exp(rng.uniform(np.log(edges[:-1]), np.log(edges[1:])))
        share = np.diff(dryden_variance_fraction(edges))
        object.__setattr__(self, "band", (lo, hi))
        object.__setattr__(self, "omega", x * self.tas / self.scale_length)
        object.__setattr__(self, "amplitudes", self.intensity * np.sqrt(2.0 * share))
        object.__setattr__(self, "phases", rng.uniform(0.0, 2.0 * np.pi, n))

    @classmethod
    def low_altitude(cls, altitude, tas, severity="moderate", **options):
        """The realisation with the MIL-F-8785C low-altitude intensity and scale length
        (:func:`low_altitude_turbulence`).

        Parameters
        ----------
        altitude : float
            Height above ground, 10 to 1000 ft. [m]
        tas : float
            True airspeed. [m/s]
        severity : str
            As :func:`low_altitude_turbulence`.
        **options
            The other fields of the class (onset, duration, seed, band, ...).

        Returns
        -------
        DrydenTurbulence
        """
        intensity, length = low_altitude_turbulence(altitude, severity)
        return cls(intensity, length, tas, **options)

    @property
    def variance_fraction(self):
        """Share of the Dryden variance sigma_v^2 the realisation carries (its band). [-]"""
        lo, hi = self.band
        return float(dryden_variance_fraction(hi) - dryden_variance_fraction(lo))

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return (self.onset, self.end)

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return self.onset + self.duration

    @cached_property
    def peak(self):
        """Largest |v(t)| of this realisation (sampled at 1/16 of its shortest period, or
        0.05 s if shorter). [m/s]"""
        step = min(0.05, np.pi / (8.0 * self.omega.max()))
        grid = self.onset + np.arange(int(np.ceil(self.duration / step)) + 1) * step
        return float(np.abs(self._sum(grid[grid < self.end])).max())

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return (f"turbulence sigma {self.intensity:.3g} m/s, L {self.scale_length:.6g} m, "
                f"{self.duration:.3g} s, seed {self.seed}")

    def spectrum(self, omega):
        """The target one-sided spectrum (:func:`dryden_lateral_spectrum`).

        Parameters
        ----------
        omega : array_like
            Time frequency. [rad/s]

        Returns
        -------
        ndarray
            Power spectral density. [m^2/s^2/(rad/s)]
        """
        return dryden_lateral_spectrum(omega, self.intensity, self.scale_length, self.tas)

    def _sum(self, t, chunk=4096):
        t = np.asarray(t, dtype=float).reshape(-1)
        out = np.empty(t.size)
        for i in range(0, t.size, chunk):
            phase = np.outer(t[i:i + chunk] - self.onset, self.omega) + self.phases
            out[i:i + chunk] = np.cos(phase) @ self.amplitudes
        return out

    def velocity(self, t):
        """Lateral gust velocity at times ``t`` (the sum of the realisation's cosines
        between its onset and end, zero outside).

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            Gust velocity, positive from the right (air moving right to left). [m/s]
        """
        t = np.asarray(t, dtype=float)
        inside = (t >= self.onset) & (t < self.end)
        out = np.zeros(t.shape)
        if np.any(inside):
            out[inside] = self._sum(t[inside])
        return out


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
        """Times at which it jumps or kinks. [s]"""
        return (float(self.time[0]),)

    @property
    def end(self):
        """Time after which the gust no longer changes (``None`` if it never stops). [s]"""
        return float(self.time[-1])

    @property
    def peak(self):
        """Largest |v(t)| of the table. [m/s]"""
        return float(np.abs(self.velocity_table).max())

    @property
    def label(self):
        """A short description for tables and legends (amplitude in m/s, times in s)."""
        return f"tabulated, peak {self.peak:.4g} m/s"

    def velocity(self, t):
        """Lateral gust velocity at times ``t``: the table, linear between its points, zero
        before its first time.

        Parameters
        ----------
        t : array_like
            Times, not after the table's last time. [s]

        Returns
        -------
        ndarray
            Gust velocity. [m/s]

        Raises
        ------
        InputError
            For a time after the end of the table (no extrapolation).
        """
        t = np.asarray(t, dtype=float)
        if np.any(t > self.time[-1] * (1 + 1e-12) + 1e-12):
            bad = float(np.max(t))
            raise InputError(f"time is after the end of the tabulated gust "
                             f"({self.time[-1]:.6g} s); no extrapolation is done", bad)
        return np.where(t < self.time[0], 0.0, np.interp(t, self.time, self.velocity_table))


#: The deterministic shapes :func:`make_gust` builds, by name.
GUST_KINDS = {"step": StepGust, "finite": FiniteGust, "1-cosine": OneMinusCosineGust,
              "continuous": SustainedGust, "harmonic": HarmonicGust}
#: Every shape name a study may list (turbulence is built with its own parameters).
GUST_SHAPES = (*GUST_KINDS, DrydenTurbulence.kind)


def make_gust(kind, amplitude=GUST_VELOCITY, onset=GUST_ONSET, duration=GUST_DURATION, *,
              rise_time=GUST_RISE, period=GUST_DURATION):
    """Build a deterministic gust by name.

    Parameters
    ----------
    kind : str
        One of ``"step"``, ``"finite"``, ``"1-cosine"``, ``"continuous"`` (sustained
        crosswind), ``"harmonic"``. Turbulence is built with :class:`DrydenTurbulence`.
    amplitude : float
        [m/s]
    onset : float
        [s]
    duration : float
        Duration of the finite and 1-cosine gusts; ignored by the others. [s]
    rise_time : float
        Rise of the sustained crosswind. [s]
    period : float
        Period of the harmonic gust. [s]

    Returns
    -------
    StepGust
        The gust (a subclass of StepGust for every shape).

    Raises
    ------
    InputError
        For an unknown shape.

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
    if kind == "continuous":
        return SustainedGust(amplitude, onset, rise_time)
    if kind == "harmonic":
        return HarmonicGust(amplitude, onset, period)
    return GUST_KINDS[kind](amplitude, onset, duration)


#: The shapes of :func:`standard_gusts`: the CS 29.341 gust as step, finite, 1-cosine and
#: sustained crosswind.
STANDARD_SHAPES = ("step", "finite", "1-cosine", "continuous")


def standard_gusts(amplitude=GUST_VELOCITY, onset=GUST_ONSET, duration=GUST_DURATION):
    """The four CS 29.341 shapes at the same amplitude: step, finite, 1-cosine, and the
    sustained crosswind (continuous, rising over half of ``duration``).

    Parameters
    ----------
    amplitude : float
        Gust velocity. [m/s]
    onset : float
        Start of every gust. [s]
    duration : float
        Duration of the finite and 1-cosine gusts; twice the crosswind's rise. [s]

    Returns
    -------
    tuple of gust
        StepGust, FiniteGust, OneMinusCosineGust, SustainedGust.
    """
    return tuple(make_gust(k, amplitude, onset, duration, rise_time=0.5 * duration)
                 for k in STANDARD_SHAPES)

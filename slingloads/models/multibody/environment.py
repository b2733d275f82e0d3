"""Air around the system: density altitude, steady wind, gusts in any direction, wind ramps.

Earth axes X aft along the flight path, Y right, Z up (``docs/multibody.md``). The wind is the
velocity of the air mass in those axes:

.. math:: W(t) = W_0 + g(t)\\, n + r(t)\\, \\hat X

* ``W_0``: steady wind.
* a gust of :mod:`slingloads.models.gusts` (any shape there: step, finite, 1-cosine,
  continuous, tabulated, and any later shape with ``velocity(t)``) along a direction ``n``:
  ``"lateral"`` (air moving towards -Y: a positive gust blows from the right, as in the 1-DOF
  analysis), ``"longitudinal"`` (towards +X: a head-on gust), ``"vertical"`` (towards +Z: an
  updraught) or any vector.
* a frontal wind ramp (paper figure 15): a head wind rising from 0 at ``rate`` to ``target``
  (air moving towards +X), e.g. on a hovering carrier.

Air density from the density altitude (ISA, :func:`slingloads.models.atmosphere.isa_density`);
airspeeds are equivalent airspeeds, converted to true airspeed with that density.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import finite, non_negative, positive
from slingloads.constants import KNOT
from slingloads.errors import InputError

#: Named gust directions (unit vectors in earth axes, for a positive gust velocity).
GUST_DIRECTIONS = {"lateral": (0.0, -1.0, 0.0), "longitudinal": (1.0, 0.0, 0.0),
                   "vertical": (0.0, 0.0, 1.0)}


def gust_direction(direction):
    """Unit vector of a named or given gust direction.

    Parameters
    ----------
    direction : str or array_like, shape (3,)
        One of :data:`GUST_DIRECTIONS`, or a vector in earth axes (non-zero). [-]

    Returns
    -------
    ndarray, shape (3,)
        Earth axes. [-]

    Raises
    ------
    InputError
        For an unknown name or a zero vector.
    """
    if isinstance(direction, str):
        if direction not in GUST_DIRECTIONS:
            raise InputError(f"{direction=!r} is not a valid gust direction; valid directions "
                             f"are {list(GUST_DIRECTIONS)} or a vector", direction)
        return np.array(GUST_DIRECTIONS[direction])
    n = np.asarray(direction, float).reshape(3)
    norm = np.linalg.norm(n)
    if not np.isfinite(norm) or norm == 0:
        raise InputError("a gust direction must be a non-zero vector", n.tolist())
    return n / norm


@dataclass(frozen=True)
class WindRamp:
    """Head wind rising linearly from 0 to ``target`` at ``rate`` from ``onset``.

    Parameters
    ----------
    target : float
        Final wind speed, > 0. [m/s]
    rate : float
        Rate of increase, > 0. [m/s^2]
    onset : float
        >= 0. [s]
    """

    target: float
    rate: float = 0.5
    onset: float = 5.0

    def __post_init__(self):
        object.__setattr__(self, "target", positive(
            self.target, "wind-ramp target speed must be > 0 [m/s]"))
        object.__setattr__(self, "rate", positive(
            self.rate, "wind-ramp rate must be > 0 [m/s^2]"))
        object.__setattr__(self, "onset", non_negative(
            self.onset, "wind-ramp onset must be >= 0 [s]"))

    @property
    def end_time(self):
        """Time the target is reached. [s]"""
        return self.onset + self.target / self.rate

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return (self.onset, self.end_time)

    def speed(self, t):
        """Head-wind speed of the ramp.

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray
            [m/s]
        """
        t = np.asarray(t, float)
        return np.clip((t - self.onset) * self.rate, 0.0, self.target)


@dataclass(frozen=True)
class Wind:
    """Steady wind, plus a gust along a direction, plus a frontal ramp.

    Parameters
    ----------
    steady : array_like, shape (3,)
        Steady wind, earth axes. [m/s]
    gust : gust of :mod:`slingloads.models.gusts` or None
    direction : str or array_like
        Direction of the gust (see :data:`GUST_DIRECTIONS`). [-]
    ramp : WindRamp or None
    """

    steady: tuple = (0.0, 0.0, 0.0)
    gust: object = None
    direction: object = "lateral"
    ramp: WindRamp | None = None

    def __post_init__(self):
        steady = np.asarray(self.steady, float).reshape(3)
        for value in steady:
            finite(value, "steady wind components must be finite numbers [m/s]")
        object.__setattr__(self, "steady", tuple(steady))
        if self.gust is not None and not hasattr(self.gust, "velocity"):
            raise InputError("a gust needs velocity(t)", type(self.gust).__name__)
        object.__setattr__(self, "_direction", gust_direction(self.direction))
        if self.ramp is not None and not isinstance(self.ramp, WindRamp):
            raise InputError("a wind ramp must be a WindRamp", type(self.ramp).__name__)

    @property
    def breakpoints(self):
        """Times at which the wind jumps or kinks. [s]"""
        points = tuple(getattr(self.gust, "breakpoints", ())) if self.gust is not None else ()
        return points + (self.ramp.breakpoints if self.ramp is not None else ())

    def velocity(self, t):
        """Wind velocity at times ``t``.

        Parameters
        ----------
        t : array_like
            Times. [s]

        Returns
        -------
        ndarray, shape (n, 3)
            Earth axes. [m/s]
        """
        t = np.asarray(t, float).reshape(-1)
        w = np.tile(np.asarray(self.steady), (t.size, 1))
        if self.gust is not None:
            w += np.asarray(self.gust.velocity(t), float)[:, None] * self._direction
        if self.ramp is not None:
            w[:, 0] += self.ramp.speed(t)
        return w

    def describe(self):
        """The wind in words ("still air" when there is none).

        Returns
        -------
        str
        """
        parts = []
        if any(self.steady):
            parts.append(f"steady wind {np.round(self.steady, 3).tolist()} m/s")
        if self.gust is not None:
            label = getattr(self.gust, "label", type(self.gust).__name__)
            where = self.direction if isinstance(self.direction, str) else "given direction"
            parts.append(f"{where} gust {label}")
        if self.ramp is not None:
            parts.append(f"head-wind ramp to {self.ramp.target / KNOT:.4g} kt at "
                         f"{self.ramp.rate:.3g} m/s^2")
        return ", ".join(parts) or "still air"

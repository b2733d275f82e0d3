"""What the carrier can fly laterally, and what it can carry sideways.

CS-29.865 asks for the hook load at the largest angle achievable *in service*: a carrier motion
that no pilot can fly bounds no design angle. A coordinated carrier banked phi accelerates
sideways at g tan(phi), so its bank and roll-rate limits bound the hook's lateral acceleration
and its rate (:class:`CarrierLimits`); :func:`peak_jerk` gives a motion's largest rate of
acceleration and :func:`flyable` says why a motion is beyond the limits, with the numbers. The
frozen carrier of the paper (its path prescribed) holds while the cable's lateral pull stays
below :data:`CARRIER_FORCE_LIMIT` of the carrier's weight.

References
----------
.. [1] EASA CS-29, CS 29.865 "External loads"; 14 CFR 29.865(a).
.. [2] US Army TM 1-1670-260-12&P, "Multiservice helicopter sling load" (20 deg bank).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.carrier_motion import (
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
    TimeHistory,
    VelocityStep,
)

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

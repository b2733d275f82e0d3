"""Attitude of the carried helicopter: where the earth vertical lies in airframe axes.

A helicopter hung by its rotor hub pitches and rolls until its centre of gravity lies under
the hub: at rest the only loads are its weight at the CG and the cable's pull at the hub, and
they balance only when both lie on one vertical line. That **hanging attitude** is the
default of the loads: gravity, the vertical hook case and the CS-29.865 cone are taken about
the earth vertical it gives, not about the mast.

Angles (aerospace Euler angles, yaw irrelevant): **pitch** theta positive nose up, **roll**
phi positive right side down. The earth's upward vertical in airframe axes (x aft, y right,
z up; ``docs/conventions.md``, section 4) is

.. math::

    \\hat k = (-\\sin\\theta,\\; -\\sin\\phi\\cos\\theta,\\; \\cos\\phi\\cos\\theta)

(the flight-mechanics body-axes gravity direction (-sin theta, sin phi cos theta,
cos phi cos theta), x and z reversed). Hanging: :math:`\\hat k = (r_{hub} - r_{cg}) /
|r_{hub} - r_{cg}|`, so a hub aft of the CG gives a nose-down pitch, a hub to the right of the
CG a left-side-down roll.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.constants import G0
from slingloads.errors import InputError

#: Attitude sources accepted by the loads analysis besides an explicit :class:`Attitude`.
ATTITUDE_SOURCES = ("hanging", "mast vertical")


@dataclass(frozen=True)
class Attitude:
    """Pitch and roll of the airframe relative to the earth.

    Parameters
    ----------
    pitch : float
        Nose-up pitch, within (-90, 90) deg. [rad]
    roll : float
        Right-side-down roll, within (-90, 90) deg. [rad]
    source : str
        How the attitude was obtained (``"hanging"``, ``"mast vertical"``, ``"given"``).
    """

    pitch: float = 0.0
    roll: float = 0.0
    source: str = "given"

    def __post_init__(self):
        for name in ("pitch", "roll"):
            value = float(getattr(self, name))
            if not np.isfinite(value) or abs(value) >= np.pi / 2:
                raise InputError(f"attitude {name} must lie within (-90, 90) deg",
                                 float(np.degrees(value)) if np.isfinite(value) else value)
            object.__setattr__(self, name, value)

    @property
    def vertical(self):
        """Earth's upward vertical in airframe axes, unit vector, shape (3,). [-]"""
        t, p = self.pitch, self.roll
        return np.array([-np.sin(t), -np.sin(p) * np.cos(t), np.cos(p) * np.cos(t)])

    @property
    def gravity(self):
        """Gravitational acceleration in airframe axes, ``-g0 k``, shape (3,). [m/s^2]"""
        return -G0 * self.vertical

    @classmethod
    def from_vertical(cls, vertical, source="given"):
        """The attitude whose earth vertical is ``vertical`` (airframe axes, any length > 0)."""
        k = np.asarray(vertical, float).reshape(3)
        norm = np.linalg.norm(k)
        if not np.isfinite(norm) or norm == 0:
            raise InputError("the earth vertical must be a non-zero vector", k.tolist())
        k = k / norm
        if k[2] <= 0:
            raise InputError("the earth vertical must point to the airframe's upper side "
                             "(z component > 0): an upright attitude", k.tolist())
        return cls(float(np.arcsin(np.clip(-k[0], -1.0, 1.0))), float(np.arctan2(-k[1], k[2])),
                   source)

    @classmethod
    def hanging(cls, mass_items, hub):
        """The attitude in which the CG of ``mass_items`` lies under ``hub`` [m].

        Raises
        ------
        InputError
            If the hub coincides with the CG or lies below it.
        """
        offset = np.asarray(hub, float).reshape(3) - mass_items.cg
        if np.linalg.norm(offset) < 1e-9:
            raise InputError("the rotor hub coincides with the CG: no hanging attitude; give "
                             "the attitude (pitch and roll) instead [m]", offset.tolist())
        if offset[2] <= 0:
            raise InputError("the rotor hub must lie above the CG (z) for the airframe to hang "
                             "upright from it; give the attitude instead [m]",
                             offset.tolist())
        return cls.from_vertical(offset, "hanging")

    @classmethod
    def mast_vertical(cls, mast_axis):
        """The attitude in which the mast axis is the earth vertical."""
        return cls.from_vertical(mast_axis, "mast vertical")

    def describe(self):
        """Readable text at the reports' precision of an angle (0.1 deg): "pitch -9.2 deg
        (nose down), roll +0.0 deg (level); hanging: CG under the hub"."""
        pitch, roll = (float(np.round(np.degrees(a), 1)) + 0.0 for a in (self.pitch, self.roll))
        nose = "nose up" if pitch > 0 else "nose down" if pitch < 0 else "level"
        side = ("right side down" if roll > 0 else "left side down" if roll < 0 else "level")
        how = {"hanging": "hanging: CG under the hub",
               "mast vertical": "mast along the earth vertical"}.get(self.source, self.source)
        return f"pitch {pitch:+.1f} deg ({nose}), roll {roll:+.1f} deg ({side}); {how}"

    def to_frame(self):
        """The attitude and its earth vertical as a one-row DataFrame (angles in degrees)."""
        k = self.vertical
        return pd.DataFrame([{"attitude source": self.source,
                              "pitch [deg]": float(np.degrees(self.pitch)),
                              "roll [deg]": float(np.degrees(self.roll)),
                              "vertical x [-]": k[0], "vertical y [-]": k[1],
                              "vertical z [-]": k[2]}])


def resolve_attitude(attitude, airframe):
    """An :class:`Attitude` from ``"hanging"``, ``"mast vertical"`` or an Attitude.

    Parameters
    ----------
    attitude : str or Attitude
    airframe : Airframe
        Mass items and hardpoints (hub, mast axis).
    """
    if isinstance(attitude, Attitude):
        return attitude
    if attitude == "hanging":
        return Attitude.hanging(airframe.mass_items, airframe.hardpoints.hub)
    if attitude == "mast vertical":
        return Attitude.mast_vertical(airframe.hardpoints.mast_axis)
    raise InputError(f"attitude must be an Attitude or one of {list(ATTITUDE_SOURCES)}",
                     attitude)

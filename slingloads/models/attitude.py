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
        """The attitude whose earth vertical is a given vector.

        Parameters
        ----------
        vertical : array_like, shape (3,)
            Earth's upward vertical in airframe axes, any length > 0, z component > 0. [-]
        source : str
            How the attitude was found (kept in :attr:`source`).

        Returns
        -------
        Attitude

        Raises
        ------
        InputError
            For a zero vector or one that points to the airframe's lower side.
        """
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
        """The attitude in which the CG of ``mass_items`` lies under the hub.

        Parameters
        ----------
        mass_items : MassItems
            Mass model; its CG is used. [m]
        hub : array_like, shape (3,)
            Rotor hub (cable attachment), airframe axes. [m]

        Returns
        -------
        Attitude

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
        """The attitude in which the mast axis is the earth vertical.

        Parameters
        ----------
        mast_axis : array_like, shape (3,)
            Mast axis in airframe axes, pointing up. [-]

        Returns
        -------
        Attitude
        """
        return cls.from_vertical(mast_axis, "mast vertical")

    def describe(self):
        """Readable text at the reports' precision of an angle (0.1 deg), e.g. "pitch -9.2 deg
        (nose down), roll +0.0 deg (level); hanging: CG under the hub".

        Returns
        -------
        str
        """
        pitch, roll = (float(np.round(np.degrees(a), 1)) + 0.0 for a in (self.pitch, self.roll))
        nose = "nose up" if pitch > 0 else "nose down" if pitch < 0 else "level"
        side = ("right side down" if roll > 0 else "left side down" if roll < 0 else "level")
        how = {"hanging": "hanging: CG under the hub",
               "mast vertical": "mast along the earth vertical"}.get(self.source, self.source)
        return f"pitch {pitch:+.1f} deg ({nose}), roll {roll:+.1f} deg ({side}); {how}"

    def to_frame(self):
        """The attitude and its earth vertical as a one-row DataFrame.

        Returns
        -------
        pandas.DataFrame
            Columns ``attitude source``, ``pitch [deg]``, ``roll [deg]`` and the vertical's
            components ``vertical x [-]``, ``vertical y [-]``, ``vertical z [-]``.
        """
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
        ``"hanging"`` (CG under the hub), ``"mast vertical"``, or an attitude, returned as is.
    airframe : Airframe
        Mass items and hardpoints (hub, mast axis). [m]

    Returns
    -------
    Attitude

    Raises
    ------
    InputError
        For any other value.
    """
    if isinstance(attitude, Attitude):
        return attitude
    if attitude == "hanging":
        return Attitude.hanging(airframe.mass_items, airframe.hardpoints.hub)
    if attitude == "mast vertical":
        return Attitude.mast_vertical(airframe.hardpoints.mast_axis)
    raise InputError(f"attitude must be an Attitude or one of {list(ATTITUDE_SOURCES)}",
                     attitude)


def to_right_handed(yaw, pitch, roll):
    """Right-handed rotation angles about +x, +y, +z (x aft, y right, z up) of the aerospace
    Euler angles used by slingloads (``docs/conventions.md``, section 8).

    The attitude R = Rz(-yaw) Ry(pitch) Rx(-roll) (body to earth, yaw nose right, pitch nose
    up, roll right side down) is Rz(rz) Ry(ry) Rx(rx) with right-handed angles
    ``(rx, ry, rz) = (-roll, pitch, -yaw)``: in these axes nose right and right side down
    are negative rotations about +z and +x, nose up a positive one about +y. The lateral
    pendulum's airframe angle theta2 is such an ``rx``.

    Parameters
    ----------
    yaw, pitch, roll : float or array_like
        [rad]

    Returns
    -------
    rx, ry, rz : float or ndarray
        [rad]
    """
    return -np.asarray(roll, float), np.asarray(pitch, float), -np.asarray(yaw, float)


def from_right_handed(rx, ry, rz):
    """Aerospace (yaw, pitch, roll) of right-handed angles about +x, +y, +z: the inverse of
    :func:`to_right_handed`.

    Parameters
    ----------
    rx, ry, rz : float or array_like
        [rad]

    Returns
    -------
    yaw, pitch, roll : float or ndarray
        [rad]
    """
    return -np.asarray(rz, float), np.asarray(ry, float), -np.asarray(rx, float)

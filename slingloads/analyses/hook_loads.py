"""CS-29.865 hook-load directions at the rotor hub of the carried helicopter.

CS 29.865(a) applies the limit load (2.5 x the external load unless a lower factor is
approved) vertically and in any direction making the maximum angle with the vertical that can
be achieved in service, not less than 30 deg unless a smaller angle is shown not to be exceeded.
Here that cone is discretised, as in the paper, into the mast-axis direction and ``n_azimuth``
directions evenly spread in azimuth about the mast axis, each inclined by ``angle`` from it.

Azimuth 0 is the projection of +x (aft) on the plane normal to the mast, 90 deg is +y (right)
for a vertical mast. The force on the airframe at the hub is ``nz * weight`` along the direction.

References
----------
.. [1] EASA CS-29 Amdt 11, CS 29.865 External loads; 14 CFR 29.865(a).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError


@dataclass(frozen=True)
class HookLoadOptions:
    """The CS-29.865 hook-load cone and its load factor.

    Parameters
    ----------
    nz : float
        Load factor on the carried aircraft's weight, > 0 (CS 29.865: 2.5). [-]
    angle : float
        Inclination of the off-axis directions from the mast axis, 0 <= angle < 90 deg. [rad]
    n_azimuth : int
        Number of off-axis directions, evenly spread in azimuth (0 for the mast axis alone).
    include_axial : bool
        Include the direction along the mast axis.
    """

    nz: float = 2.5
    angle: float = np.radians(30.0)
    n_azimuth: int = 8
    include_axial: bool = True

    def __post_init__(self):
        nz = float(self.nz)
        if not np.isfinite(nz) or nz <= 0:
            raise InputError("hook load factor Nz must be > 0", nz)
        angle = float(self.angle)
        if not np.isfinite(angle) or not (0 <= angle < np.pi / 2):
            raise InputError("hook-load angle from the mast axis must lie in [0, 90) deg",
                             float(np.degrees(angle)))
        n = self.n_azimuth
        if isinstance(n, bool) or int(n) != n or n < 0:
            raise InputError("number of hook-load azimuths must be a whole number >= 0", n)
        if int(n) == 0 and not self.include_axial:
            raise InputError("hook-load options give no direction at all "
                             "(no azimuths and no mast-axis case)")
        object.__setattr__(self, "nz", nz)
        object.__setattr__(self, "angle", angle)
        object.__setattr__(self, "n_azimuth", int(n))


def mast_basis(mast_axis):
    """Orthonormal (e1, e2, m): e1 the projection of +x normal to the mast, e2 = m x e1."""
    m = np.asarray(mast_axis, float)
    m = m / np.linalg.norm(m)
    x = np.array([1.0, 0.0, 0.0])
    e1 = x - (x @ m) * m
    if np.linalg.norm(e1) < 1e-9:
        raise InputError("the mast axis must not be parallel to the fuselage x axis",
                         m.tolist())
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(m, e1), m


def hook_directions(options, mast_axis=(0.0, 0.0, 1.0)):
    """Unit directions of the CS-29.865 hook load, as a table.

    Parameters
    ----------
    options : HookLoadOptions
    mast_axis : array_like, shape (3,)
        Mast direction from the deck to the hub. [-]

    Returns
    -------
    pandas.DataFrame
        One row per direction: ``hook`` id (``AXIAL``, ``AZ000``, ``AZ045``...),
        ``azimuth [deg]``, ``inclination [deg]``, and unit vector ``ux, uy, uz``.
    """
    e1, e2, m = mast_basis(mast_axis)
    rows = []
    if options.include_axial:
        rows.append(("AXIAL", 0.0, 0.0, m))
    azimuths = 2 * np.pi * np.arange(options.n_azimuth) / max(options.n_azimuth, 1)
    for psi in azimuths:
        u = (np.cos(options.angle) * m
             + np.sin(options.angle) * (np.cos(psi) * e1 + np.sin(psi) * e2))
        rows.append((f"AZ{round(np.degrees(psi)) % 360:03d}", np.degrees(psi),
                     np.degrees(options.angle), u))
    frame = pd.DataFrame({
        "hook": [r[0] for r in rows],
        "azimuth [deg]": [r[1] for r in rows],
        "inclination [deg]": [r[2] for r in rows],
    })
    vectors = np.array([r[3] for r in rows])
    frame["ux"], frame["uy"], frame["uz"] = vectors.T
    if frame["hook"].duplicated().any():
        raise InputError("hook-load azimuths round to the same whole degree; use fewer "
                         "azimuths", options.n_azimuth)
    return frame


def describe_direction(azimuth_deg, inclination_deg):
    """Readable text for a hook direction ("30 deg from mast, towards aft-right")."""
    if inclination_deg == 0:
        return "along the mast axis"
    names = ["aft", "aft-right", "right", "forward-right", "forward", "forward-left", "left",
             "aft-left"]
    sector = names[int(np.round(azimuth_deg / 45.0)) % 8]
    return (f"{inclination_deg:g} deg from the mast axis at azimuth {azimuth_deg:g} deg "
            f"(towards {sector})")

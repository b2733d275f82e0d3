"""CS-29.865 hook-load directions at the rotor hub of the carried helicopter.

CS 29.865(a) applies the limit load (2.5 x the external load unless a lower factor is
approved) vertically and in any direction making the maximum angle with the vertical that can
be achieved in service, not less than 30 deg unless a smaller angle is shown not to be exceeded.
Here that cone is discretised, as in the paper, into the vertical direction and ``n_azimuth``
directions evenly spread in azimuth about it, each inclined from the vertical by the cone's
inclination at its azimuth.

**Vertical** is the earth's upward vertical expressed in airframe axes, given by the airframe's
attitude (:mod:`slingloads.models.attitude`; by default the hanging attitude, CG under the
hub). **Azimuth** is measured about that vertical from the horizontal projection of +x (aft,
azimuth 0) towards the horizontal projection of +y (right, azimuth 90 deg). The force on the
airframe at the hub is ``nz * weight`` along the direction.

**The cone's inclination may differ by azimuth**, so that a smaller angle is used only where
it is shown: ``angle`` (default 30 deg) applies to every direction, except that ``lateral_angle``
replaces it

* at the pure lateral azimuths 90 and 270 deg only (``cone="lateral directions"``, the
  default: the lateral-step study justifies lateral directions, nothing else), or
* along an elliptical cone whose inclination runs from ``angle`` fore and aft to
  ``lateral_angle`` sideways (``cone="elliptical"``, for when longitudinal evidence exists):
  :math:`\\tan\\theta(\\psi) = \\tan a \\tan b / \\sqrt{(\\tan b \\cos\\psi)^2 +
  (\\tan a \\sin\\psi)^2}`, a the fore-and-aft and b the lateral inclination.

Besides the cone, the **towed-flight equilibrium** case (hook id ``TOW``) pulls along the
trimmed cable: vertical component ``nz * weight``, horizontal component balancing the
aerodynamic and parachute forces (:meth:`slingloads.analyses.loads.LoadsStudy.applied_loads`).

References
----------
.. [1] EASA CS-29 Amdt 11, CS 29.865 External loads; 14 CFR 29.865(a).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError

#: Hook id of the vertical case (along the earth vertical of the attitude).
VERTICAL = "VERTICAL"
#: Hook id of the towed-flight equilibrium case (along the trimmed cable).
TOWED = "TOW"
#: Hook id of a case without hook load.
NO_HOOK = "NONE"
#: Former hook ids still read, and what they mean now.
LEGACY_HOOK_IDS = {"AXIAL": VERTICAL}
#: Shapes of the cone between the fore-and-aft and the lateral inclination.
CONE_SHAPES = ("lateral directions", "elliptical")
#: Azimuth tolerance of the pure lateral directions (90 and 270 deg). [rad]
_LATERAL_TOLERANCE = 1e-9


def _angle(value, what):
    """``value`` [rad] as a float in [0, pi/2), else an error that says the unit."""
    angle = float(value)
    if not np.isfinite(angle) or not (0 <= angle < np.pi / 2):
        degrees = f" = {np.degrees(angle):.6g} deg" if np.isfinite(angle) else ""
        raise InputError(f"{what} must lie in [0, 90) deg, that is [0, pi/2) rad (a "
                         "HookLoadOptions angle is in radians, numpy.radians(20) for 20 deg; "
                         f"LoadsStudy.with_hook takes degrees); given {angle:.6g} rad"
                         f"{degrees}", angle, unit="rad")
    return angle


@dataclass(frozen=True)
class HookLoadOptions:
    """The CS-29.865 hook-load cone, its load factor and the towed-flight cases.

    Parameters
    ----------
    nz : float
        Load factor on the carried aircraft's weight, > 0 (CS 29.865: 2.5). [-]
    angle : float
        Inclination from the vertical of every off-vertical direction that ``lateral_angle``
        does not replace (fore and aft; CS 29.865: 30 deg), 0 <= angle < 90 deg. [rad]
    n_azimuth : int
        Number of off-vertical directions, evenly spread in azimuth (0 for the vertical alone).
        [count]
    include_vertical : bool
        Include the direction along the earth vertical (id ``VERTICAL``).
    lateral_angle : float, optional
        Inclination of the lateral directions, 0 <= angle < 90 deg; None = ``angle``. [rad]
    cone : str
        Where ``lateral_angle`` applies: ``"lateral directions"`` (azimuths 90 and 270 deg
        only) or ``"elliptical"`` (module notes).
    towed : bool
        Generate the towed-flight equilibrium cases (id ``TOW``), one per aerodynamic point
        with and without parachute.
    """

    nz: float = 2.5
    angle: float = np.radians(30.0)
    n_azimuth: int = 8
    include_vertical: bool = True
    lateral_angle: float | None = None
    cone: str = "lateral directions"
    towed: bool = True

    def __post_init__(self):
        nz = float(self.nz)
        if not np.isfinite(nz) or nz <= 0:
            raise InputError("hook load factor Nz must be > 0", nz)
        angle = _angle(self.angle, "hook-load angle from the vertical")
        lateral = (None if self.lateral_angle is None
                   else _angle(self.lateral_angle, "lateral hook-load angle from the vertical"))
        if self.cone not in CONE_SHAPES:
            raise InputError(f"hook cone shape must be one of {list(CONE_SHAPES)}", self.cone)
        n = self.n_azimuth
        if isinstance(n, bool) or int(n) != n or n < 0:
            raise InputError("number of hook-load azimuths must be a whole number >= 0", n)
        if int(n) == 0 and not self.include_vertical:
            raise InputError("hook-load options give no direction at all "
                             "(no azimuths and no vertical case)")
        object.__setattr__(self, "nz", nz)
        object.__setattr__(self, "angle", angle)
        object.__setattr__(self, "lateral_angle", lateral)
        object.__setattr__(self, "n_azimuth", int(n))
        object.__setattr__(self, "towed", bool(self.towed))
        object.__setattr__(self, "include_vertical", bool(self.include_vertical))

    @property
    def lateral(self):
        """Inclination of the lateral directions (``angle`` unless replaced). [rad]"""
        return self.angle if self.lateral_angle is None else self.lateral_angle

    def inclination(self, azimuth):
        """Inclination of the cone from the vertical at an azimuth.

        Parameters
        ----------
        azimuth : array_like
            Azimuth from aft (0) towards right (90 deg). [rad]

        Returns
        -------
        ndarray
            [rad]
        """
        psi = np.asarray(azimuth, float)
        a, b = self.angle, self.lateral
        if a == b:
            return np.full(psi.shape, a)
        if self.cone == "lateral directions":
            return np.where(np.abs(np.cos(psi)) < _LATERAL_TOLERANCE, b, a)
        ta, tb = np.tan(a), np.tan(b)
        den = np.hypot(tb * np.cos(psi), ta * np.sin(psi))
        num = ta * tb
        return np.arctan(np.divide(num, den, out=np.zeros_like(den), where=den > 0))

    def azimuths(self):
        """Azimuths of the off-vertical directions, evenly spread from 0.

        Returns
        -------
        ndarray, shape (n_azimuth,)
            [rad]
        """
        return 2 * np.pi * np.arange(self.n_azimuth) / max(self.n_azimuth, 1)


def horizontal_basis(vertical=(0.0, 0.0, 1.0)):
    """Orthonormal (a0, a90, k): k the upward vertical, a0 the horizontal projection of +x
    (azimuth 0, aft), a90 = k x a0 (azimuth 90 deg, right), all in airframe axes.

    Parameters
    ----------
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (default +z: the mast vertical). [-]

    Returns
    -------
    a0, a90, k : ndarray, shape (3,)
        [-]

    Raises
    ------
    InputError
        If the vertical is parallel to the fuselage x axis.
    """
    k = np.asarray(vertical, float).reshape(3)
    k = k / np.linalg.norm(k)
    x = np.array([1.0, 0.0, 0.0])
    a0 = x - (x @ k) * k
    if np.linalg.norm(a0) < 1e-9:
        raise InputError("the vertical must not be parallel to the fuselage x axis",
                         k.tolist())
    a0 /= np.linalg.norm(a0)
    return a0, np.cross(k, a0), k


def hook_directions(options, vertical=(0.0, 0.0, 1.0)):
    """Unit directions of the CS-29.865 hook load, as a table.

    Parameters
    ----------
    options : HookLoadOptions
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (the attitude's). [-]

    Returns
    -------
    pandas.DataFrame
        One row per direction: ``hook`` id (``VERTICAL``, ``AZ000``, ``AZ045``...),
        ``azimuth [deg]``, ``inclination [deg]`` from the vertical, ``reduced`` (True where
        ``lateral_angle`` changed the inclination from ``angle``) and the unit vector
        ``ux, uy, uz`` (airframe axes).
    """
    a0, a90, k = horizontal_basis(vertical)
    psi = options.azimuths()
    theta = options.inclination(psi)
    u = (np.cos(theta)[:, None] * k
         + np.sin(theta)[:, None] * (np.cos(psi)[:, None] * a0 + np.sin(psi)[:, None] * a90))
    ids = [f"AZ{round(np.degrees(p)) % 360:03d}" for p in psi]
    if options.include_vertical:
        ids, psi, theta = [VERTICAL, *ids], np.r_[0.0, psi], np.r_[0.0, theta]
        u = np.vstack([k, u])
    frame = pd.DataFrame({"hook": ids, "azimuth [deg]": np.degrees(psi),
                          "inclination [deg]": np.degrees(theta)})
    frame["reduced"] = ~np.isclose(theta, options.angle, rtol=0, atol=1e-12)
    if options.include_vertical:
        frame.loc[0, "reduced"] = False
    frame["ux"], frame["uy"], frame["uz"] = u.T
    if frame["hook"].duplicated().any():
        raise InputError("hook-load azimuths round to the same whole degree; use fewer "
                         "azimuths", options.n_azimuth)
    return frame


def cable_geometry(force, vertical=(0.0, 0.0, 1.0)):
    """Angle from the vertical and azimuth of hook forces.

    Parameters
    ----------
    force : array_like, shape (n, 3)
        Force on the airframe at the hub, airframe axes. [N]
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes. [-]

    Returns
    -------
    angle : ndarray, shape (n,)
        Angle of the force from the upward vertical. [rad]
    azimuth : ndarray, shape (n,)
        Azimuth of its horizontal part, in [0, 2 pi), 0 where it has none. [rad]
    """
    a0, a90, k = horizontal_basis(vertical)
    f = np.asarray(force, float)
    up, aft, right = f @ k, f @ a0, f @ a90
    horizontal = np.hypot(aft, right)
    azimuth = np.where(horizontal > 1e-12 * np.maximum(np.abs(up), 1.0),
                       np.mod(np.arctan2(right, aft), 2 * np.pi), 0.0)
    return np.arctan2(horizontal, up), azimuth


def angle_words(value_deg):
    """An angle for a sentence, at the precision of an angle's cell (0.1 deg), so that a
    sentence and the cells beside it quote one number for one angle: the hook design angle
    33.2361 deg reads "33.2" in a load case's description, a note and a column label as in
    the cells; a whole angle without its decimal ("30").

    Parameters
    ----------
    value_deg : float
        [deg]

    Returns
    -------
    str

    Examples
    --------
    >>> angle_words(33.2361), angle_words(30.0), angle_words(-22.1537), angle_words(12.04)
    ('33.2', '30', '-22.2', '12')
    """
    text = f"{float(value_deg):.1f}"
    text = text[:-2] if text.endswith(".0") else text
    return "0" if text == "-0" else text


def describe_direction(azimuth_deg, inclination_deg):
    """Readable text for a hook direction ("30 deg from the vertical at azimuth 45 deg...").

    Parameters
    ----------
    azimuth_deg : float
        Azimuth from aft towards right. [deg]
    inclination_deg : float
        Angle from the vertical. [deg]

    Returns
    -------
    str
    """
    if inclination_deg == 0:
        return "along the vertical"
    names = ["aft", "aft-right", "right", "forward-right", "forward", "forward-left", "left",
             "aft-left"]
    sector = names[int(np.round(azimuth_deg / 45.0)) % 8]
    return (f"{angle_words(inclination_deg)} deg from the vertical at azimuth "
            f"{angle_words(azimuth_deg)} deg "
            f"(towards {sector})")

"""Aerodynamic loads of the carried helicopter from the flow each part actually sees.

The air velocity relative to a point r (from the CG, body axes) of the rotating airframe is

.. math:: u = R^T (W - v) - \\omega \\times r

with W the wind and v the CG velocity (earth axes), omega the body rates. So every surface
away from the CG sees the rotation, and its damping comes from the physics (no hand-set rate
derivative).

* **Fuselage**: the six-coefficient table (:class:`~slingloads.models.aerodynamics.FuselageAero`,
  interpolated in its declared frames and converted to airframe axes at the flow's angles,
  as the loads analysis does) at the angle of attack and sideslip of the flow at its moment
  reference point, with the
  airflow direction of ``docs/conventions.md``, ``d = u/|u| = (cos a cos b, -sin b,
  sin a cos b)``; inverted with ``cos a >= 0`` so that sideslip covers the whole circle:
  ``b = atan2(-d_y, sign(d_x) sqrt(d_x^2 + d_z^2))``, ``a = atan(d_z / d_x)``.
* **Lifting surfaces** (:class:`LiftingSurface`: the fin, and the horizontal tail of the
  full-tail configuration): a normal force along the surface's normal axis (body y for the
  fin, body z for the tail) from its table against the local angle in the plane of the chord
  and the normal, ``beta_f = atan2(-u_y, u_x)`` for the fin (the yaw model's local sideslip),
  ``alpha_t = atan2(u_z, u_x)`` for the tail, at the dynamic pressure of the flow in that plane
  (the spanwise component does not load the surface: cross-flow principle).

Below the airspeed ``v_cut`` the flow angles are undefined and the loads negligible; the loads
are then taken as zero and the tables are not consulted (``docs/multibody.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slingloads.checks import positive
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D
from slingloads.models.aerodynamics import Fin
from slingloads.models.multibody._jit import jit
from slingloads.models.multibody.lookup import bilinear, cell, interp1

#: Normal axes a lifting surface may have, and the sign that makes its angle positive.
NORMAL_AXES = {"y": (1, -1.0), "z": (2, 1.0)}


@dataclass(frozen=True)
class LiftingSurface:
    """A fin or horizontal tail: normal force from its local flow.

    Parameters
    ----------
    table : Table1D
        Normal-force coefficient against the local angle (``CY`` against sideslip for a fin,
        negative for positive sideslip; ``CN`` against angle of attack for a horizontal tail,
        positive for positive alpha), on ``area``. It must cover the angles the run reaches:
        -180 to 180 deg for a helicopter that may turn broadside.
    area : float
        Reference area of the table. [m^2]
    centre_of_pressure : array_like, shape (3,)
        Airframe axes. [m]
    normal : {"y", "z"}
        Body axis of the normal force: "y" for a fin, "z" for a horizontal tail.
    efficiency : float
        Share of the table's force the surface keeps, 0 < eta <= 1 (0.5 for the cut-down fin
        of the paper's transport configuration, 1 for an intact surface). [-]
    name : str
    """

    table: Table1D
    area: float
    centre_of_pressure: np.ndarray
    normal: str = "y"
    efficiency: float = 1.0
    name: str = "fin"

    def __post_init__(self):
        if self.normal not in NORMAL_AXES:
            raise InputError(f"{self.normal=!r} is not a valid surface normal; valid normals "
                             f"are {list(NORMAL_AXES)}", self.normal)
        if self.coefficient not in self.table.coefficients:
            raise InputError(f"the {self.name} table needs a {self.coefficient} column",
                             sorted(self.table.coefficients))
        object.__setattr__(self, "area", positive(
            self.area, f"{self.name} area must be > 0 [m^2]"))
        eta = float(self.efficiency)
        if not (0 < eta <= 1):
            raise InputError(f"{self.name} efficiency must lie in (0, 1]", eta)
        object.__setattr__(self, "efficiency", eta)
        object.__setattr__(self, "centre_of_pressure",
                           np.asarray(self.centre_of_pressure, float).reshape(3))

    @property
    def coefficient(self):
        """Name of the table's coefficient: CY for a fin, CN for a horizontal tail."""
        return "CY" if self.normal == "y" else "CN"

    @classmethod
    def from_fin(cls, fin, efficiency=None):
        """The fin of the 1-DOF analyses (:class:`~slingloads.models.aerodynamics.Fin`).

        Parameters
        ----------
        fin : Fin
            With its CY table in body axes.
        efficiency : float, optional
            Efficiency replacing the fin's, in (0, 1]. [-]

        Returns
        -------
        LiftingSurface

        Raises
        ------
        InputError
            For something other than a Fin, or a table not in body axes.
        """
        if not isinstance(fin, Fin):
            raise InputError("from_fin needs a Fin", type(fin).__name__)
        if fin.axes != "body":
            raise InputError("the multibody model (and its campaign) flies the fin as a "
                             "lifting surface whose CY is its normal force, along +y: it needs "
                             "the fin's CY in body axes ('fin axes' = body); a table in wind "
                             "axes serves the loads and the parachute sizing only", fin.axes)
        eta = fin.efficiency if efficiency is None else efficiency
        return cls(fin.table, fin.area, fin.centre_of_pressure, "y", eta, "fin")


@jit
def flow_at(u0, u1, u2, p, q, r, x, y, z):
    """Air velocity relative to a point of the body: u_cg - omega x r (body axes).

    Parameters
    ----------
    u0, u1, u2 : float
        Air velocity relative to the CG. [m/s]
    p, q, r : float
        Body rates. [rad/s]
    x, y, z : float
        The point, from the CG. [m]

    Returns
    -------
    tuple of float
        [m/s]
    """
    return u0 - (q * z - r * y), u1 - (r * x - p * z), u2 - (p * y - q * x)


@jit
def frame_axis(frame, i, ca, sa, cb, sb):
    """Axis ``i`` of a flight-mechanics frame in airframe axes (docs/conventions.md
    section 3).

    Parameters
    ----------
    frame : int
        ``FRAME_CODES``: 0 body, 1 stability, 2 wind. [-]
    i : int
        0 x, 1 y, 2 z. [-]
    ca, sa, cb, sb : float
        cos and sin of alpha and beta. [-]

    Returns
    -------
    tuple of float
        Unit vector, airframe axes. [-]
    """
    if frame == 0:
        if i == 0:
            return -1.0, 0.0, 0.0
        if i == 1:
            return 0.0, 1.0, 0.0
        return 0.0, 0.0, -1.0
    if i == 2:
        return sa, 0.0, -ca
    if i == 1:
        if frame == 1:
            return 0.0, 1.0, 0.0
        return ca * sb, cb, sa * sb
    if frame == 1:
        return -ca, 0.0, -sa
    return -ca * cb, sb, -sa * cb


@jit
def to_airframe(frame, force, c0, c1, c2, ca, sa, cb, sb):
    """Coefficients along a frame's axes as airframe-axes ones; ``force`` makes drag and
    lift of the wind and stability frames point along -x and -z of the frame.

    Parameters
    ----------
    frame : int
        ``FRAME_CODES``: 0 body, 1 stability, 2 wind. [-]
    force : bool
        Force coefficients (else moment coefficients).
    c0, c1, c2 : float
        Coefficients along the frame's axes. [-]
    ca, sa, cb, sb : float
        cos and sin of alpha and beta. [-]

    Returns
    -------
    tuple of float
        Airframe-axes coefficients. [-]
    """
    s = -1.0 if (force and frame != 0) else 1.0
    x0, y0, z0 = frame_axis(frame, 0, ca, sa, cb, sb)
    x1, y1, z1 = frame_axis(frame, 1, ca, sa, cb, sb)
    x2, y2, z2 = frame_axis(frame, 2, ca, sa, cb, sb)
    a, b = s * c0, s * c2
    return (a * x0 + c1 * x1 + b * x2, a * y0 + c1 * y1 + b * y2, a * z0 + c1 * z1 + b * z2)


@jit
def fuselage_loads(u0, u1, u2, half_rho, area, length, alpha_grid, beta_grid, coeffs, v_cut,
                   force_frame, moment_frame):
    """Fuselage force and moment about its reference point, body axes.

    Parameters
    ----------
    u0, u1, u2 : float
        Air velocity relative to the reference point, body axes. [m/s]
    half_rho : float
        rho / 2. [kg/m^3]
    area, length : float
        Reference area [m^2] and length [m].
    alpha_grid, beta_grid, coeffs :
        The table (its three force and three moment coefficients, ``FuselageAero.columns``,
        stacked on the first axis), in its declared frames.
    v_cut : float
        Airspeed below which the loads are zero. [m/s]
    force_frame, moment_frame : int
        Frames of the force and moment coefficients (``FRAME_CODES``); the interpolated
        coefficients are converted at the flow's alpha and beta. [-]

    Returns
    -------
    fx, fy, fz, mx, my, mz : float
        [N], [N m]
    alpha, beta : float
        [rad]
    alpha_inside, beta_inside : bool
        False when alpha (beta) lies outside the table.
    """
    speed2 = u0 * u0 + u1 * u1 + u2 * u2
    if speed2 < v_cut * v_cut:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, True, True
    speed = math.sqrt(speed2)
    d0, d1, d2 = u0 / speed, u1 / speed, u2 / speed
    side = math.sqrt(d0 * d0 + d2 * d2)
    beta = math.atan2(-d1, side if d0 >= 0.0 else -side)
    alpha = math.atan(d2 / d0) if d0 != 0.0 else (0.5 * math.pi if d2 > 0 else -0.5 * math.pi)
    i, wa, in_a = cell(alpha_grid, alpha)
    j, wb, in_b = cell(beta_grid, beta)
    c0 = bilinear(coeffs, 0, i, j, wa, wb)
    c1 = bilinear(coeffs, 1, i, j, wa, wb)
    c2 = bilinear(coeffs, 2, i, j, wa, wb)
    m0 = bilinear(coeffs, 3, i, j, wa, wb)
    m1 = bilinear(coeffs, 4, i, j, wa, wb)
    m2 = bilinear(coeffs, 5, i, j, wa, wb)
    ca, sa, cb, sb = math.cos(alpha), math.sin(alpha), math.cos(beta), math.sin(beta)
    cfx, cfy, cfz = to_airframe(force_frame, True, c0, c1, c2, ca, sa, cb, sb)
    cmx, cmy, cmz = to_airframe(moment_frame, False, m0, m1, m2, ca, sa, cb, sb)
    qs = half_rho * speed2 * area
    qsl = qs * length
    return qs * cfx, qs * cfy, qs * cfz, qsl * cmx, qsl * cmy, qsl * cmz, alpha, beta, in_a, in_b


@jit
def surface_force(u0, u1, u2, axis, sign, half_rho, area_eff, grid, values, v_cut):
    """Normal force of a lifting surface from its local flow (body axes).

    Parameters
    ----------
    u0, u1, u2 : float
        Air velocity relative to the centre of pressure, body axes. [m/s]
    axis : int
        1 (normal along y, a fin) or 2 (along z, a horizontal tail). [-]
    sign : float
        -1 for a fin (beta = atan2(-u_y, u_x)), +1 for a tail (alpha = atan2(u_z, u_x)). [-]
    half_rho : float
        [kg/m^3]
    area_eff : float
        Area times efficiency. [m^2]
    grid, values :
        Coefficient table against the local angle.
    v_cut : float
        [m/s]

    Returns
    -------
    force : float
        Along the normal axis. [N]
    angle : float
        Local angle. [rad]
    inside : bool
    """
    un = u1 if axis == 1 else u2
    speed2 = u0 * u0 + un * un
    if speed2 < v_cut * v_cut:
        return 0.0, 0.0, True
    angle = math.atan2(sign * un, u0)
    c, ok = interp1(grid, values, angle)
    return half_rho * speed2 * area_eff * c, angle, ok

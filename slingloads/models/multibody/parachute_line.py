"""The drogue parachute on its line from the fin: hinged point mass, or quasi-static.

**Hinged** (:class:`HingedParachute`, paper section 4.3): a point mass ``m_p`` at the end of a
rigid, massless line of length ``L_p`` from the attachment A on the fin, free on two hinges in
body axes. The line direction in body axes is

.. math:: e(\\theta, \\psi) = (\\cos\\theta\\cos\\psi,\\; \\sin\\psi,\\; \\sin\\theta\\cos\\psi)

theta, the angle of the line's projection on the x-z plane above the x axis (positive up, the
hinge about body y), psi, the angle of the line out of that plane (positive to the right, the
second hinge); at theta = psi = 0 the line trails straight aft. Roll about the line is ignored
(an axisymmetric canopy). The coordinates are singular only when the line points along body y
(cos psi = 0), never in towed flight; a run that gets within 5 deg of it stops with that
verdict. Hanging straight down (theta = -90 deg, in hover) is regular.

The canopy's drag acts at the canopy along its own relative wind u_P:

.. math:: D = \\tfrac12 \\rho\\, \\eta_{wake}\\, C_D(\\alpha_p)\\, A\\, |u_P|\\, u_P

with alpha_p the angle between the line and the canopy's relative wind. The line carries only
tension; the tension is computed at every step and a negative value (the line would go slack)
is reported.

**Quasi-static** (:class:`QuasiStaticParachute`): the Apollo legacy drogue model of the 1-DOF
analysis, the drag acting at the attachment along the attachment point's relative wind with
``C_D(0)``; no parachute states.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slingloads.checks import positive
from slingloads.errors import InputError
from slingloads.models.multibody._jit import jit
from slingloads.models.parachute import Parachute

#: Default canopy mass (canopy and line of a drogue of about 1 m^2 flat-plate area). [kg]
DEFAULT_CANOPY_MASS = 3.0
#: The hinge coordinates stop a run when |psi| comes within this of 90 deg. [rad]
HINGE_MARGIN = math.radians(5.0)


@dataclass(frozen=True)
class HingedParachute:
    """Parachute as a point mass on a rigid line with two hinges at the fin attachment.

    Parameters
    ----------
    parachute : Parachute
        Flat-plate area, CD table against the canopy angle of attack, wake ratio and line
        length (:attr:`Parachute.line_length`). A table that covers only small angles (the
        paper's +-8 deg) stops a run whose canopy leaves it, as in a start from hover:
        :func:`~slingloads.models.parachute.extended_cd_table` covers 0-180 deg.
    mass : float
        Canopy and line mass, > 0 (default small). [kg]
    """

    parachute: Parachute
    mass: float = DEFAULT_CANOPY_MASS

    kind = "hinged"

    def __post_init__(self):
        if not isinstance(self.parachute, Parachute):
            raise InputError("a hinged parachute needs a Parachute",
                             type(self.parachute).__name__)
        if self.parachute.axes != "wind":
            raise InputError("the hinged parachute pulls along its relative wind: its table "
                             "must be in wind axes (CD)", self.parachute.axes)
        object.__setattr__(self, "mass", positive(
            self.mass, "parachute mass must be > 0 [kg] (use the quasi-static model for a "
                       "massless canopy)"))

    @property
    def line_length(self):
        """[m]"""
        return self.parachute.line_length


@dataclass(frozen=True)
class QuasiStaticParachute:
    """Apollo legacy (quasi-static) drogue: drag at the attachment along its relative wind.

    Parameters
    ----------
    parachute : Parachute
        Only ``CD(0)``, the area and the wake ratio are used.
    """

    parachute: Parachute

    kind = "quasi-static"
    mass = 0.0

    def __post_init__(self):
        if not isinstance(self.parachute, Parachute):
            raise InputError("a quasi-static parachute needs a Parachute",
                             type(self.parachute).__name__)
        if self.parachute.axes != "wind":
            raise InputError("the quasi-static parachute pulls along its relative wind: its table "
                             "must be in wind axes (CD)", self.parachute.axes)

    @property
    def line_length(self):
        """[m]"""
        return self.parachute.line_length


def line_reach(hub, chute, line_length):
    """Nearest and farthest distance from the hub that the parachute line and canopy reach.

    The line is judged as it flies: in forward flight the drag streams it aft of its
    attachment, in hover it hangs below it; it never points forward of the attachment (that
    would need a forward force on the canopy). Its points c + s e (c the attachment from the
    hub, 0 <= s <= L, e in airframe axes with e_x >= 0, x aft) fill the aft half of the ball
    of radius L about the attachment. With the attachment aft of the hub (c_x > 0) the
    farthest is ``|c| + L`` and the nearest ``sqrt(c_x^2 + max(0, |c_yz| - L)^2)`` (the line
    square to the body axis); ahead of it, ``sqrt(c_x^2 + (|c_yz| + L)^2)`` and
    ``max(0, |c| - L)``. A carrier
    hook (at the cable length from the hub) outside [nearest, farthest] cannot meet the line
    or the canopy; the sphere rule used before (``|c| + L`` against the cable, as if the line
    could point anywhere, forward included) refused the short cables the paper flies.

    Parameters
    ----------
    hub, chute : array_like, shape (3,)
        Hub (cable attachment) and parachute attachment, airframe axes. [m]
    line_length : float
        [m]

    Returns
    -------
    (float, float)
        Nearest and farthest distance from the hub. [m]
    """
    c = np.asarray(chute, float).reshape(3) - np.asarray(hub, float).reshape(3)
    line = float(line_length)
    size, side = float(np.linalg.norm(c)), float(np.hypot(c[1], c[2]))
    if c[0] <= 0.0:
        near = max(0.0, size - line)
        far = float(np.hypot(c[0], side + line))
    else:
        near = float(np.hypot(c[0], max(0.0, side - line)))
        far = size + line
    return near, far


@jit
def line_direction(theta, psi):
    """Unit line direction e and its partial derivatives e_theta, e_psi (body axes).

    Parameters
    ----------
    theta, psi : float
        Hinge angles. [rad]

    Returns
    -------
    e, e_theta, e_psi : tuple of float
        [-], [1/rad], [1/rad]
    """
    ct, st, cp, sp = math.cos(theta), math.sin(theta), math.cos(psi), math.sin(psi)
    e = (ct * cp, sp, st * cp)
    e_t = (-st * cp, 0.0, ct * cp)
    e_p = (-ct * sp, cp, -st * sp)
    return e, e_t, e_p


@jit
def line_curvature(theta, psi, theta_dot, psi_dot):
    """Velocity-squared part of the line's second derivative (body axes):
    e_tt th'^2 + 2 e_tp th' ps' + e_pp ps'^2.

    Parameters
    ----------
    theta, psi : float
        Hinge angles. [rad]
    theta_dot, psi_dot : float
        Their rates. [rad/s]

    Returns
    -------
    tuple of float
        [1/s^2]
    """
    ct, st, cp, sp = math.cos(theta), math.sin(theta), math.cos(psi), math.sin(psi)
    a, b = theta_dot * theta_dot, 2.0 * theta_dot * psi_dot
    c = psi_dot * psi_dot
    return (-ct * cp * a + st * sp * b - ct * cp * c, -sp * c,
            -st * cp * a - ct * sp * b - st * cp * c)


def line_angles(direction):
    """Hinge angles of unit line directions in body axes (inverse of e).

    Parameters
    ----------
    direction : array_like, shape (..., 3)
        Unit line directions, body axes. [-]

    Returns
    -------
    theta, psi : ndarray
        [rad]
    """
    d = np.asarray(direction, float)
    psi = np.arcsin(np.clip(d[..., 1], -1.0, 1.0))
    theta = np.arctan2(d[..., 2], d[..., 0])
    return theta, psi

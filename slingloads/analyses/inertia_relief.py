"""Inertia relief: the rigid-body accelerations that balance the applied loads.

A free body under applied forces :math:`F_i` at :math:`r_i` and moments :math:`M_i` (gravity
included) accelerates, quasi-statically (angular rate zero), with

.. math::

    a = \\frac{\\sum F_i}{m}, \\qquad I_{cg} \\dot\\omega = \\sum (r_i - r_{cg}) \\times F_i + M_i

and every mass item then carries the inertia load :math:`-m_j (a + \\dot\\omega \\times
(r_j - r_{cg}))` and the moment :math:`-I_j \\dot\\omega`. Applied plus inertia loads are in
equilibrium, so the free-free internal loads close to zero at both ends.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from slingloads.constants import G0


@dataclass(frozen=True)
class RigidBodyAcceleration:
    """Accelerations per case that balance the applied loads.

    Attributes
    ----------
    linear : ndarray, shape (c, 3)
        Acceleration of the CG, airframe axes. [m/s^2]
    angular : ndarray, shape (c, 3)
        Angular acceleration. [rad/s^2]
    """

    linear: np.ndarray
    angular: np.ndarray
    gravity: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, -G0]))

    @property
    def load_factor(self):
        """Load factor at the CG, n = (a - g) / g0, airframe axes, shape (c, 3); hanging at
        rest it is the earth's upward vertical (+1 on z when z is vertical). [-]"""
        return (self.linear - self.gravity) / G0

    @property
    def vertical_load_factor(self):
        """Load factor along the earth's upward vertical, n . k, shape (c,); +1 hanging at
        rest, Nz in the vertical hook case. [-]"""
        k = -self.gravity / np.linalg.norm(self.gravity)
        return self.load_factor @ k


def rigid_body_acceleration(mass_items, positions, forces, moments, add_gravity=False,
                            vertical=(0.0, 0.0, 1.0)):
    """Accelerations that balance applied loads.

    Parameters
    ----------
    mass_items : MassItems
    positions : ndarray, shape (p, 3)
        Points of application. [m]
    forces, moments : ndarray, shape (c, p, 3)
        Applied forces [N] and moments [N m] per case (``moments`` may be None).
    add_gravity : bool
        Add the weight of every mass item (when ``forces`` does not already hold it).
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (the attitude's; default +z). [-]

    Returns
    -------
    RigidBodyAcceleration
    """
    cg = mass_items.cg
    resultant = _point_sum(forces)
    moment_cg = moment_sum(np.asarray(positions) - cg, forces)
    if moments is not None:
        moment_cg += _point_sum(moments)
    if add_gravity:
        weight, weight_moment = gravity_resultants(mass_items, vertical)
        resultant += weight
        moment_cg += weight_moment
    linear = resultant / mass_items.total_mass
    angular = moment_cg @ inverse_inertia(mass_items).T
    return RigidBodyAcceleration(linear, angular, gravity_field(vertical))


def inverse_inertia(mass_items):
    """(Pseudo-)inverse of the inertia tensor about the CG.

    The pseudo-inverse: a line of point masses has no inertia about its own axis; a moment
    about that axis then stays unbalanced and the closure check reports it.

    Parameters
    ----------
    mass_items : MassItems

    Returns
    -------
    ndarray, shape (3, 3)
        [1/(kg m^2)]
    """
    return np.linalg.pinv(mass_items.inertia_about_cg, hermitian=True)


def gravity_resultants(mass_items, vertical=(0.0, 0.0, 1.0)):
    """Resultant force and moment about the CG of the weights (the moment is zero but
    for round-off: the weights act through the CG).

    Parameters
    ----------
    mass_items : MassItems
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (default +z: the mast vertical). [-]

    Returns
    -------
    force : ndarray, shape (3,)
        [N]
    moment : ndarray, shape (3,)
        About the CG. [N m]
    """
    weight = gravity_forces(mass_items, vertical)
    return weight.sum(axis=0), np.cross(mass_items.position - mass_items.cg, weight).sum(axis=0)


def _point_sum(vectors):
    """Sum over the points of vectors of shape (c, p, 3): one matrix product (c, 3p) @
    (3p, 3), much faster than a reduction along the short middle axis."""
    c, p, _ = vectors.shape
    vectors = np.ascontiguousarray(vectors)
    return vectors.reshape(c, 3 * p) @ np.tile(np.eye(3), (p, 1))


def moment_sum(positions, forces):
    """Sum over points of r x F per case, shape (c, 3), by matrix products (no (c, p, 3) temp).

    Parameters
    ----------
    positions : ndarray, shape (p, 3)
        Lever arms. [m]
    forces : ndarray, shape (c, p, 3)
        [N]

    Returns
    -------
    ndarray, shape (c, 3)
        [N m]
    """
    rx, ry, rz = np.asarray(positions, float).T
    fx, fy, fz = forces[..., 0], forces[..., 1], forces[..., 2]
    return np.stack([fz @ ry - fy @ rz, fx @ rz - fz @ rx, fy @ rx - fx @ ry], axis=-1)


def inertia_loads(mass_items, acceleration):
    """Inertia forces and moments at every mass item.

    Parameters
    ----------
    mass_items : MassItems
    acceleration : RigidBodyAcceleration
        Linear [m/s^2] and angular [rad/s^2] accelerations of each case, shape (c, 3).

    Returns
    -------
    forces : ndarray, shape (c, n, 3)
        -m_j (a + alpha x (r_j - r_cg)). [N]
    moments : ndarray, shape (c, n, 3)
        -I_j alpha. [N m]
    """
    rho = mass_items.position - mass_items.cg
    local = acceleration.linear[:, None, :] + np.cross(acceleration.angular[:, None, :], rho)
    forces = -mass_items.mass[None, :, None] * local
    moments = -np.einsum("nij,cj->cni", mass_items.inertia, acceleration.angular)
    return forces, moments


def gravity_forces(mass_items, vertical=(0.0, 0.0, 1.0)):
    """Weight of every mass item, shape (n, 3), along the earth's downward vertical. [N]

    Parameters
    ----------
    mass_items : MassItems
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (default +z: the mast vertical). [-]

    Returns
    -------
    ndarray, shape (n, 3)
        [N]
    """
    return -G0 * mass_items.mass[:, None] * _unit(vertical)[None, :]


def gravity_field(vertical=(0.0, 0.0, 1.0)):
    """Acceleration of gravity: g0 along the earth's downward vertical, airframe axes.

    Parameters
    ----------
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes (default +z: the mast vertical). [-]

    Returns
    -------
    ndarray, shape (3,)
        [m/s^2]
    """
    return -G0 * _unit(vertical)


def _unit(vector):
    v = np.asarray(vector, float).reshape(3)
    return v / np.linalg.norm(v)

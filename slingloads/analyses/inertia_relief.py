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

from dataclasses import dataclass

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

    @property
    def load_factor(self):
        """Load factor at the CG, n = (a - g) / g0, shape (c, 3); +1 on z hanging at rest. [-]"""
        return (self.linear - np.array([0.0, 0.0, -G0])) / G0


def rigid_body_acceleration(mass_items, positions, forces, moments, add_gravity=False):
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

    Returns
    -------
    RigidBodyAcceleration
    """
    cg = mass_items.cg
    resultant = forces.sum(axis=1)
    moment_cg = moment_sum(np.asarray(positions) - cg, forces)
    if moments is not None:
        moment_cg += moments.sum(axis=1)
    if add_gravity:
        weight = gravity_forces(mass_items)
        resultant += weight.sum(axis=0)
        moment_cg += np.cross(mass_items.position - cg, weight).sum(axis=0)
    linear = resultant / mass_items.total_mass
    # pinv: a line of point masses has no inertia about its own axis; a moment about that
    # axis then stays unbalanced and the closure check reports it.
    angular = moment_cg @ np.linalg.pinv(mass_items.inertia_about_cg, hermitian=True).T
    return RigidBodyAcceleration(linear, angular)


def moment_sum(positions, forces):
    """Sum over points of r x F per case, shape (c, 3), by matrix products (no (c, p, 3) temp).

    Parameters
    ----------
    positions : ndarray, shape (p, 3)
        Lever arms. [m]
    forces : ndarray, shape (c, p, 3)
        [N]
    """
    rx, ry, rz = np.asarray(positions, float).T
    fx, fy, fz = forces[..., 0], forces[..., 1], forces[..., 2]
    return np.stack([fz @ ry - fy @ rz, fx @ rz - fz @ rx, fy @ rx - fx @ ry], axis=-1)


def inertia_loads(mass_items, acceleration):
    """Inertia forces and moments at every mass item.

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


def gravity_forces(mass_items):
    """Weight of every mass item, shape (n, 3), along -z. [N]"""
    forces = np.zeros_like(mass_items.position)
    forces[:, 2] = -G0 * mass_items.mass
    return forces

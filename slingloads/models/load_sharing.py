"""Sharing a force and moment among several points: the rigid-body (RBE3-like) weighted rule.

A load known at one point (the rotor hub, the aerodynamic moment reference point) reaches the
airframe through several points (the mast feet on the transmission deck, stations along the
loads axis). Among every set of point forces whose resultant force and moment equal the given
ones, this module takes the one that minimises :math:`\\sum_i |F_i|^2 / w_i`, the weighted
least-squares share used by NASTRAN's RBE3 element:

.. math::

    F_i = w_i \\left( \\frac{F}{W} + \\mu \\times d_i \\right), \\qquad
    J \\mu = M_g, \\qquad J = \\sum_i w_i (|d_i|^2 I - d_i d_i^T)

with :math:`W = \\sum w_i`, :math:`d_i` the position of point *i* from the weighted centroid
*g*, and :math:`M_g` the moment of the load about *g*. The resultant force and moment are
preserved exactly. Where the points cannot carry a moment component by forces (collinear
points cannot carry torsion about their line), that component is shared as point moments in
proportion to the weights, so the resultant is still exact.
"""

from __future__ import annotations

import numpy as np

from slingloads.errors import InputError


def rigid_share(points, weights, force, moment, reference):
    """Share loads given at ``reference`` among ``points`` by the RBE3-like weighted rule.

    Parameters
    ----------
    points : array_like, shape (k, 3)
        Receiving points, airframe axes. [m]
    weights : array_like, shape (k,)
        Positive weights (relative stiffness or share). [-]
    force : array_like, shape (..., 3)
        Force applied at ``reference``, one row per load case. [N]
    moment : array_like, shape (..., 3)
        Moment applied about ``reference``. [N m]
    reference : array_like, shape (3,)
        Point where the load is applied. [m]

    Returns
    -------
    point_forces : ndarray, shape (..., k, 3)
        Force at each receiving point. [N]
    point_moments : ndarray, shape (..., k, 3)
        Moment at each receiving point (zero unless the points are collinear or single). [N m]
    """
    points = np.asarray(points, dtype=float)
    weights = np.asarray(weights, dtype=float)
    if points.ndim != 2 or points.shape[1] != 3 or points.shape[0] < 1:
        raise InputError("load-sharing points must be an array of shape (k, 3)", points.shape)
    if weights.shape != points.shape[:1] or np.any(~np.isfinite(weights) | (weights <= 0)):
        raise InputError("load-sharing weights must be > 0, one per point", weights.tolist())
    force = np.asarray(force, dtype=float)
    moment = np.asarray(moment, dtype=float)
    total = weights.sum()
    centroid = weights @ points / total
    d = points - centroid
    moment_g = moment + np.cross(np.asarray(reference, dtype=float) - centroid, force)
    j = np.einsum("k,kl,ij->ij", weights, d * d, np.eye(3)) - np.einsum("k,ki,kj->ij",
                                                                        weights, d, d)
    # Pseudo-inverse of J with an absolute floor as well as a relative one: the centroid of a
    # single point (or of coincident points) carries round-off of order eps |p|, which makes
    # J tiny but not zero; inverting that would give huge, spurious opposing forces. Directions
    # with less stiffness than 1e-10 W |p|max^2 are treated as not carried by forces (their
    # moment goes into point moments below, so the resultants stay exact).
    vals, vecs = np.linalg.eigh(j)
    floor = max(1e-10 * total * float(np.abs(points).max()) ** 2, 1e-10 * vals.max(initial=0))
    keep = vals > floor
    inv = np.where(keep, 1.0 / np.where(keep, vals, 1.0), 0.0)
    j_pinv = (vecs * inv) @ vecs.T
    mu = moment_g @ j_pinv.T
    carried = mu @ j.T
    residual = moment_g - carried
    share = weights / total
    point_forces = (force[..., None, :] * share[:, None]
                    + weights[:, None] * np.cross(mu[..., None, :], d))
    point_moments = residual[..., None, :] * share[:, None]
    return point_forces, point_moments

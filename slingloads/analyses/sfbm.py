"""Shear force and bending moment (internal loads) along the cut stations.

Convention (``docs/conventions.md``): the internal load at a cut is the force and moment that
the part aft of the cut exerts on the part forward of it, moments about the point of the loads
reference axis at the cut. A point load exactly at a cut belongs to the forward part. With
point forces :math:`F_i` at :math:`r_i` and point moments :math:`M_i`:

.. math::

    V(x_c) = -\\sum_{x_i \\le x_c} F_i, \\qquad
    M(x_c) = -\\sum_{x_i \\le x_c} \\left[(r_i - p_c) \\times F_i + M_i\\right]

computed for all cases and stations at once with one cumulative sum over the points sorted by
x. The loads are linear in the applied loads, so unit-load solutions superpose.
"""

from __future__ import annotations

import numpy as np

#: Names of the six internal-load components, in array order.
COMPONENTS = ("Vx", "Vy", "Vz", "Mx", "My", "Mz")
#: Kind of each component (for units).
COMPONENT_KINDS = ("force",) * 3 + ("moment",) * 3


def internal_loads(positions, forces, moments, station_points):
    """Six internal loads at every cut station for every case.

    Parameters
    ----------
    positions : ndarray, shape (p, 3)
        Points where loads act, airframe axes. [m]
    forces : ndarray, shape (c, p, 3)
        Point forces per case. [N]
    moments : ndarray, shape (c, p, 3) or None
        Point moments per case. [N m]
    station_points : ndarray, shape (s, 3)
        Points of the loads reference axis at the cuts (x increasing). [m]

    Returns
    -------
    ndarray, shape (c, s, 6)
        Vx, Vy, Vz [N], Mx, My, Mz [N m].
    """
    positions = np.asarray(positions, float)
    order = np.argsort(positions[:, 0], kind="stable")
    pos = positions[order]
    f = forces[:, order, :]
    per_point = np.empty(f.shape[:2] + (6,))
    per_point[..., :3] = f
    per_point[..., 3:] = np.cross(pos, f)
    if moments is not None:
        per_point[..., 3:] += moments[:, order, :]
    np.cumsum(per_point, axis=1, out=per_point)
    count = np.searchsorted(pos[:, 0], station_points[:, 0], side="right")
    out = np.zeros(f.shape[:1] + (station_points.shape[0], 6))
    has = count > 0
    out[:, has, :] = per_point[:, count[has] - 1, :]
    # out now holds the forward sums S_F, S_rxF; internal = -S_F, -(S_rxF - p x S_F)
    out[..., 3:] -= np.cross(station_points, out[..., :3])
    np.negative(out, out=out)
    return out


def closure_residual(positions, forces, moments, reference):
    """Sum of all forces and of all moments about ``reference``, per case, shape (c, 6).

    This is the internal load aft of every load: zero for a free-free body in equilibrium.
    """
    total_f = forces.sum(axis=1)
    total_m = np.cross(np.asarray(positions) - reference, forces).sum(axis=1)
    if moments is not None:
        total_m = total_m + moments.sum(axis=1)
    return np.concatenate([total_f, total_m], axis=1)

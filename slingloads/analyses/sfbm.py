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

from slingloads.errors import InputError

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
        Points of the loads reference axis at the cuts: x increasing, y and z the same for
        all (the axis is parallel to x). [m]

    Returns
    -------
    ndarray, shape (c, s, 6)
        Vx, Vy, Vz [N], Mx, My, Mz [N m].
    """
    out = _forward_sums(positions, forces, moments, station_points)
    np.negative(out, out=out)
    return out


def _forward_sums(positions, forces, moments, station_points):
    """Minus the internal loads: forward sums of force and moment about each cut's point.

    Moments are first summed about the axis point (0, y0, z0); moving them to the cut's point
    (x_c, y0, z0) changes only My and Mz, by x_c times the force sums, so the per-case work
    is one cumulative sum over the load points and one gather at the stations.
    """
    positions = np.asarray(positions, float)
    station_points = np.asarray(station_points, float)
    axis = station_points[0, 1:]
    if np.any(station_points[:, 1:] != axis):
        raise InputError("cut-station points must lie on one line parallel to x (the loads "
                         "reference axis)", station_points[:, 1:].tolist())
    order = np.argsort(positions[:, 0], kind="stable")
    pos = positions[order]
    f = forces[:, order, :]
    per_point = np.zeros((f.shape[0], f.shape[1] + 1, 6))
    per_point[:, 1:, :3] = f
    _cross_into(pos - np.array([0.0, axis[0], axis[1]]), f, per_point[:, 1:, 3:])
    if moments is not None:
        per_point[:, 1:, 3:] += moments[:, order, :]
    np.cumsum(per_point, axis=1, out=per_point)
    count = np.searchsorted(pos[:, 0], station_points[:, 0], side="right")
    out = np.take(per_point, count, axis=1)
    x = station_points[:, 0]
    out[..., 4] += x * out[..., 2]
    out[..., 5] -= x * out[..., 1]
    return out


class _ForwardSums:
    """:func:`_forward_sums` for chunks of at most ``size`` cases, the point order, station
    counts and working arrays prepared once."""

    def __init__(self, positions, station_points, size):
        positions = np.asarray(positions, float)
        station_points = np.asarray(station_points, float)
        axis = station_points[0, 1:]
        self.order = np.argsort(positions[:, 0], kind="stable")
        pos = positions[self.order]
        self.arm = pos - np.array([0.0, axis[0], axis[1]])
        self.count = np.searchsorted(pos[:, 0], station_points[:, 0], side="right")
        self.x = station_points[:, 0]
        self.per_point = np.zeros((size, len(pos) + 1, 6))
        self.out = np.empty((size, len(self.count), 6))

    def __call__(self, forces, moments):
        n = len(forces)
        per_point, out = self.per_point[:n], self.out[:n]
        f = forces[:, self.order, :]
        per_point[:, 1:, :3] = f
        _cross_into(self.arm, f, per_point[:, 1:, 3:])
        if moments is not None:
            per_point[:, 1:, 3:] += moments[:, self.order, :]
        np.cumsum(per_point, axis=1, out=per_point)
        np.take(per_point, self.count, axis=1, out=out)
        out[..., 4] += self.x * out[..., 2]
        out[..., 5] -= self.x * out[..., 1]
        return out


def _cross_into(r, f, out):
    """out = r x f, r of shape (p, 3) broadcast over the cases of f (c, p, 3)."""
    rx, ry, rz = r[:, 0], r[:, 1], r[:, 2]
    fx, fy, fz = f[..., 0], f[..., 1], f[..., 2]
    np.multiply(ry, fz, out=out[..., 0])
    out[..., 0] -= rz * fy
    np.multiply(rz, fx, out=out[..., 1])
    out[..., 1] -= rx * fz
    np.multiply(rx, fy, out=out[..., 2])
    out[..., 2] -= ry * fx
    return out


def unit_inertia_responses(mass_items, station_points):
    """Internal loads of the inertia field of each unit rigid-body acceleration.

    The inertia loads are linear in the six accelerations (a_x, a_y, a_z, alpha_x, alpha_y,
    alpha_z), so the internal loads of any case's inertia relief are ``acc @ U`` with these
    unit responses: the classic superposition of unit-load solutions.

    Returns
    -------
    ndarray, shape (6, s, 6)
        Response to a unit acceleration [per m/s^2] or angular acceleration [per rad/s^2].
    """
    from slingloads.analyses.inertia_relief import RigidBodyAcceleration, inertia_loads

    eye = np.eye(6)
    forces, moments = inertia_loads(mass_items, RigidBodyAcceleration(eye[:, :3], eye[:, 3:]))
    return internal_loads(mass_items.position, forces, moments, station_points)


def closure_residual(positions, forces, moments, reference):
    """Sum of all forces and of all moments about ``reference``, per case, shape (c, 6).

    This is the internal load aft of every load: zero for a free-free body in equilibrium.
    """
    from slingloads.analyses.inertia_relief import moment_sum

    total_f = forces.sum(axis=1)
    total_m = moment_sum(np.asarray(positions) - reference, forces)
    if moments is not None:
        total_m = total_m + moments.sum(axis=1)
    return np.concatenate([total_f, total_m], axis=1)


#: Load cases per chunk of :func:`free_free_internal_loads`: the working arrays of a chunk
#: (a few times chunk x stations x 6 floats) stay in cache and the result is written once.
CHUNK_CASES = 128


def free_free_internal_loads(mass_items, positions, forces, moments, station_points,
                             vertical=(0.0, 0.0, 1.0), *, chunk=CHUNK_CASES):
    """Internal loads of the free-free airframe: applied loads, gravity and inertia relief.

    Gravity acts at every mass item; the rigid-body accelerations balance gravity and the
    applied loads (:mod:`slingloads.analyses.inertia_relief`), and their inertia loads enter
    through the unit-acceleration responses (:func:`unit_inertia_responses`), so only the few
    applied load points are summed per case. The cases are worked in chunks of ``chunk``,
    each written once into the result, so that the memory used beyond the result is a few
    chunks' worth, whatever the number of cases.

    Parameters
    ----------
    mass_items : MassItems
    positions : ndarray, shape (p, 3)
        Points of the applied loads (gravity excluded). [m]
    forces, moments : ndarray, shape (c, p, 3)
        Applied forces [N] and moments [N m].
    station_points : ndarray, shape (s, 3)
        [m]
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes, along which gravity acts downwards (the
        attitude's, :mod:`slingloads.models.attitude`). [-]
    chunk : int
        Cases per chunk, >= 1.

    Returns
    -------
    loads : ndarray, shape (c, s, 6)
        Internal loads. [N, N m]
    acceleration : RigidBodyAcceleration
    residual : ndarray, shape (c, 6)
        Internal loads at a cut aft of every load and mass item, which free-free closure
        makes zero. [N, N m]
    """
    from slingloads.analyses.inertia_relief import gravity_forces, rigid_body_acceleration

    acceleration = rigid_body_acceleration(mass_items, positions, forces, moments,
                                           add_gravity=True, vertical=vertical)
    linear, angular = acceleration.linear, acceleration.angular
    x_end = max(np.max(positions[:, 0]), mass_items.position[:, 0].max(),
                station_points[:, 0].max()) + 1.0
    cuts = np.vstack([station_points, [x_end, station_points[0, 1], station_points[0, 2]]])
    # gravity and the six unit inertia fields, superposed by one matrix product
    basis = np.concatenate([
        unit_inertia_responses(mass_items, cuts),
        internal_loads(mass_items.position, gravity_forces(mass_items, vertical)[None], None,
                       cuts),
    ]).reshape(7, -1)
    weights = np.concatenate([linear, angular, np.ones((len(linear), 1))], axis=1)
    cases, n_st = len(linear), len(station_points)
    chunk = int(chunk)
    if chunk < 1:
        raise InputError("internal loads: cases per chunk must be >= 1", chunk)
    loads = np.empty((cases, n_st, 6))
    residual = np.empty((cases, 6))
    forward = _ForwardSums(positions, cuts, min(chunk, max(cases, 1)))
    for first in range(0, cases, chunk):
        part = slice(first, min(first + chunk, cases))
        block = loads[part]
        # einsum: a product of inner size 7, single-threaded (a threaded BLAS call per chunk
        # costs more than it saves, and much more on a busy machine)
        np.einsum("ck,kn->cn", weights[part], basis[:, :-6], out=block.reshape(len(block), -1))
        sums = forward(forces[part], None if moments is None else moments[part])
        block -= sums[:, :-1]
        np.einsum("ck,kn->cn", weights[part], basis[:, -6:], out=residual[part])
        residual[part] -= sums[:, -1]
    return loads, acceleration, residual

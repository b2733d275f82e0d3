"""Shear force and bending moment (internal loads) along the cut stations.

Convention (``docs/conventions.md``): the internal load at a cut is the force and moment that
the part aft of the cut exerts on the part forward of it, moments about the point of the loads
reference axis at the cut. A point load exactly at a cut belongs to the forward part. With
point forces :math:`F_i` at :math:`r_i` and point moments :math:`M_i`:

.. math::

    V(x_c) = -\\sum_{x_i \\le x_c} F_i, \\qquad
    M(x_c) = -\\sum_{x_i \\le x_c} \\left[(r_i - p_c) \\times F_i + M_i\\right]

:func:`internal_loads` computes them for all cases and stations at once with one cumulative
sum over the points sorted by x. The loads are linear in the applied loads, so unit-load
solutions superpose: :func:`free_free_internal_loads` adds gravity and inertia relief as seven
precomputed responses, and sums only the few applied load points per case, in a compiled
kernel that writes each case's loads once (:mod:`slingloads.analyses.sfbm_kernel`), or in
numpy for a small study.
"""

from __future__ import annotations

import numpy as np

from slingloads.analyses.sfbm_layout import (
    R_CG,
    R_FORCE,
    R_INV_INERTIA,
    R_INV_MASS,
    R_MOMENT,
    RIGID,
)
from slingloads.errors import InputError

#: Names of the six internal-load components, in array order.
COMPONENTS = ("Vx", "Vy", "Vz", "Mx", "My", "Mz")
#: Kind of each component (for units).
COMPONENT_KINDS = ("force",) * 3 + ("moment",) * 3
#: DataFrame column of each component (name and SI unit, as in the CSV files).
LOAD_COLUMNS = ("Vx_N", "Vy_N", "Vz_N", "Mx_Nm", "My_Nm", "Mz_Nm")


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

    Parameters
    ----------
    mass_items : MassItems
    station_points : ndarray, shape (s, 3)
        Cut points. [m]

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

    Parameters
    ----------
    positions : ndarray, shape (p, 3)
        Load points. [m]
    forces, moments : ndarray, shape (c, p, 3)
        Forces [N] and moments [N m].
    reference : array_like, shape (3,)
        Point the moments are taken about. [m]

    Returns
    -------
    ndarray, shape (c, 6)
        Force [N] and moment [N m] sums.
    """
    from slingloads.analyses.inertia_relief import moment_sum

    total_f = forces.sum(axis=1)
    total_m = moment_sum(np.asarray(positions) - reference, forces)
    if moments is not None:
        total_m = total_m + moments.sum(axis=1)
    return np.concatenate([total_f, total_m], axis=1)


def free_free_internal_loads(mass_items, positions, forces, moments, station_points,
                             vertical=(0.0, 0.0, 1.0), *, out=None):
    """Internal loads of the free-free airframe: applied loads, gravity and inertia relief.

    Gravity acts at every mass item; the rigid-body accelerations balance gravity and the
    applied loads (:mod:`slingloads.analyses.inertia_relief`), and their inertia loads enter
    through the unit-acceleration responses (:func:`unit_inertia_responses`), so only the few
    applied load points are summed per case. The cases are worked one at a time by a compiled
    kernel (:mod:`slingloads.analyses.sfbm_kernel`) that writes each case's loads once into
    the result: the memory used beyond the result is a few rows, whatever the number of
    cases. A small study (at most :data:`NUMPY_CUTS` cases x cuts) is worked by the same
    operations in numpy (:func:`free_free_rows_numpy`, the same numbers to the last bit),
    which spares it the kernel's start-up.

    Parameters
    ----------
    mass_items : MassItems
    positions : ndarray, shape (p, 3)
        Points of the applied loads (gravity excluded). [m]
    forces, moments : ndarray, shape (c, p, 3)
        Applied forces [N] and moments [N m] (``moments`` may be None).
    station_points : ndarray, shape (s, 3)
        [m]
    vertical : array_like, shape (3,)
        Earth's upward vertical in airframe axes, along which gravity acts downwards (the
        attitude's, :mod:`slingloads.models.attitude`). [-]
    out : ndarray, shape (c, s, 6), optional
        C-contiguous float array to write the loads into (instead of a new one). [N, N m]

    Returns
    -------
    loads : ndarray, shape (c, s, 6)
        Internal loads. [N, N m]
    acceleration : RigidBodyAcceleration
    residual : ndarray, shape (c, 6)
        Internal loads at a cut aft of every load and mass item, which free-free closure
        makes zero. [N, N m]
    """
    from slingloads.analyses.inertia_relief import (
        RigidBodyAcceleration,
        gravity_field,
        gravity_forces,
        gravity_resultants,
        inverse_inertia,
    )
    positions = np.asarray(positions, float)
    forces = np.asarray(forces, float)
    station_points = np.asarray(station_points, float)
    x_end = max(np.max(positions[:, 0], initial=-np.inf), mass_items.position[:, 0].max(),
                station_points[:, 0].max()) + 1.0
    cuts = np.vstack([station_points, [x_end, station_points[0, 1], station_points[0, 2]]])
    # gravity and the six unit inertia fields, superposed per case
    basis = np.concatenate([
        unit_inertia_responses(mass_items, cuts),
        internal_loads(mass_items.position, gravity_forces(mass_items, vertical)[None], None,
                       cuts),
    ]).reshape(7, -1)
    cases, n_st = len(forces), len(station_points)
    loads = _result_array(out, (cases, n_st, 6))
    residual, linear, angular = np.empty((cases, 6)), np.empty((cases, 3)), np.empty((cases, 3))
    axis_point = np.array([0.0, cuts[0, 1], cuts[0, 2]])
    order = np.argsort(positions[:, 0], kind="stable")
    count = np.searchsorted(positions[order, 0], cuts[:, 0], side="right")
    rigid = np.empty(len(RIGID))
    rigid[RIGID.slice("cg")] = mass_items.cg - axis_point
    rigid[RIGID.slice("gravity_force")], rigid[RIGID.slice("gravity_moment")] = \
        gravity_resultants(mass_items, vertical)
    rigid[R_INV_MASS] = 1.0 / mass_items.total_mass
    rigid[RIGID.slice("inv_inertia")] = inverse_inertia(mass_items).ravel()
    has_moments = moments is not None
    moments = np.asarray(moments, float) if has_moments else np.empty((0, 0, 3))
    # the kernel does not check its indices
    for name, array in (("forces", forces), ("moments", moments if has_moments else forces)):
        if array.shape != (cases, len(positions), 3):
            raise ValueError(f"internal loads: {name} must have the shape (cases, points, 3) = "
                             f"{(cases, len(positions), 3)}, not {array.shape}")
    rows = free_free_rows_numpy if cases * len(cuts) <= NUMPY_CUTS else _compiled_rows()
    rows(basis, forces, moments, has_moments, order, positions[order] - axis_point, count,
         cuts[:, 0].copy(), rigid, loads.reshape(cases, 6 * n_st), residual, linear, angular)
    return loads, RigidBodyAcceleration(linear, angular, gravity_field(vertical)), residual


#: Largest cases x cuts worked by numpy (:func:`free_free_rows_numpy`) rather than the
#: compiled kernel: below it numpy takes a few milliseconds, while the kernel's first call in
#: a process costs about 0.7 s (numba's import and the loading of its machine code), most of
#: a small study; above it the kernel is faster and its memory bounded. [-]
NUMPY_CUTS = 100_000


def _compiled_rows():
    """The compiled kernel (numba is imported on first use)."""
    from slingloads.analyses.sfbm_kernel import free_free_rows

    return free_free_rows


def free_free_rows_numpy(basis, forces, moments, has_moments, order, arm, count, x, rigid,
                         out, residual, linear, angular):
    """:func:`slingloads.analyses.sfbm_kernel.free_free_rows` in numpy, all cases at once:
    the same arguments, the same operations in the same order (sums left to right, no fused
    or reordered products), so the same numbers to the last bit; temporaries of the
    result's size, so for small studies only (:data:`NUMPY_CUTS`).

    Parameters
    ----------
    basis, forces, moments, has_moments, order, arm, count, x, rigid, out, residual, linear, angular
        As :func:`slingloads.analyses.sfbm_kernel.free_free_rows` (units there).
    """
    f = forces[:, order, :]
    cum = np.zeros((len(f), len(order) + 1, 6))
    cum[:, 1:, :3] = f
    _cross_into(arm, f, cum[:, 1:, 3:])
    if has_moments:
        cum[:, 1:, 3:] += moments[:, order, :]
    np.add.accumulate(cum, axis=1, out=cum)  # sequential, as the kernel's running sums
    sums = cum[:, count, :]
    sums[..., 4] += x * sums[..., 2]
    sums[..., 5] -= x * sums[..., 1]
    _accelerations_numpy(cum[:, -1, :], rigid, linear, angular)
    w = np.concatenate([linear, angular], axis=1)
    total = w[:, :1] * basis[0]
    for k in range(1, 6):
        total += w[:, k:k + 1] * basis[k]
    total += basis[6]
    total -= sums.reshape(len(f), basis.shape[1])
    n_out = out.shape[1]
    out[:] = total[:, :n_out]
    residual[:] = total[:, n_out:]


def _accelerations_numpy(totals, rigid, linear, angular):
    """The kernel's inertia relief from the applied loads' totals (c, 6), for all cases."""
    fx, fy, fz = totals[:, 0], totals[:, 1], totals[:, 2]
    dx, dy, dz = rigid[R_CG], rigid[R_CG + 1], rigid[R_CG + 2]
    mx = totals[:, 3] - (dy * fz - dz * fy) + rigid[R_MOMENT]
    my = totals[:, 4] - (dz * fx - dx * fz) + rigid[R_MOMENT + 1]
    mz = totals[:, 5] - (dx * fy - dy * fx) + rigid[R_MOMENT + 2]
    for k in range(3):
        linear[:, k] = (totals[:, k] + rigid[R_FORCE + k]) * rigid[R_INV_MASS]
        row = R_INV_INERTIA + 3 * k
        angular[:, k] = rigid[row] * mx + rigid[row + 1] * my + rigid[row + 2] * mz


def _result_array(out, shape):
    """``out`` if it is a C-contiguous float array of ``shape``, a new array if None."""
    if out is None:
        return np.empty(shape)
    if out.shape != shape or out.dtype != np.float64 or not out.flags.c_contiguous:
        raise ValueError(f"internal loads: out must be a C-contiguous float64 array of shape "
                         f"{shape}, not {out.dtype} {out.shape} (C-contiguous: "
                         f"{out.flags.c_contiguous})")
    return out

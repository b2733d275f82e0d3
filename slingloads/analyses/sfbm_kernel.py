"""Compiled free-free internal loads: one pass over the cut stations of each case, writing
every element of the result once.

The same sums as :func:`slingloads.analyses.sfbm.free_free_internal_loads` computed by numpy
(superposed gravity and unit inertia responses, minus the forward sums of the applied loads),
fused per case: the applied loads' forward sums are accumulated over the load points sorted by
x (a few dozen), read at each cut, and combined with the seven basis responses as the result's
row is written. No array of the result's size other than the result itself is made, so the
memory beyond the result is a few rows, whatever the number of cases. Single-threaded.
Compiled with `numba <https://numba.pydata.org>`_ (``cache=True``: the machine code is kept
in this package's ``__pycache__`` after the first call). The kernel reads the rigid-body
vector by the offsets of :data:`slingloads.analyses.sfbm_layout.RIGID`, so the cache is
dropped when that module, :mod:`slingloads.models.packed` or this one changes (every
module of this folder is hashed) (:mod:`slingloads.models.numba_cache`).

The numpy twin :func:`slingloads.analyses.sfbm.free_free_rows_numpy` stays in production,
with a reason: for a small study (:data:`slingloads.analyses.sfbm.NUMPY_CUTS`) it spares the
kernel's start-up in a fresh process (about 0.7 s, numba's import and the loading of the
machine code: most of such a study's time). It makes the same operations in the same order,
and the tests check the two agree to the last bit
(``tests/test_closure_superposition.py``).
"""

from __future__ import annotations

from pathlib import Path

import numba
import numpy as np

from slingloads.analyses.sfbm_layout import R_CG, R_FORCE, R_INV_INERTIA, R_INV_MASS, R_MOMENT
from slingloads.models.numba_cache import drop_stale_cache

_HERE = Path(__file__).resolve()
drop_stale_cache(_HERE.parent, also=(_HERE.parents[1] / "models" / "packed.py",))

_jit = numba.njit(cache=True, fastmath=False, nogil=True)


@_jit
def _forward_rows(forces, moments, has_moments, case, order, arm, cum):
    """Cumulative forward sums of the applied loads of one case, points sorted by x.

    ``cum[i]`` holds the sums over the first ``i`` sorted points: force (3) [N] and moment
    about the axis point (0, y0, z0) (3) [N m]; ``cum[0]`` is zero.
    """
    for k in range(6):
        cum[0, k] = 0.0
    for i in range(len(order)):
        q = order[i]
        fx, fy, fz = forces[case, q, 0], forces[case, q, 1], forces[case, q, 2]
        rx, ry, rz = arm[i, 0], arm[i, 1], arm[i, 2]
        mx = ry * fz - rz * fy
        my = rz * fx - rx * fz
        mz = rx * fy - ry * fx
        if has_moments:
            mx += moments[case, q, 0]
            my += moments[case, q, 1]
            mz += moments[case, q, 2]
        cum[i + 1, 0] = cum[i, 0] + fx
        cum[i + 1, 1] = cum[i, 1] + fy
        cum[i + 1, 2] = cum[i, 2] + fz
        cum[i + 1, 3] = cum[i, 3] + mx
        cum[i + 1, 4] = cum[i, 4] + my
        cum[i + 1, 5] = cum[i, 5] + mz


@_jit
def _at_cuts(cum, count, x, sums):
    """The forward sums at every cut, moments moved from the axis point to the cut's point
    (x_c, y0, z0): My + x_c Fz, Mz - x_c Fy. ``sums`` is flat, cut after cut, 6 per cut."""
    for j in range(len(count)):
        c = count[j]
        base = 6 * j
        sums[base] = cum[c, 0]
        sums[base + 1] = cum[c, 1]
        sums[base + 2] = cum[c, 2]
        sums[base + 3] = cum[c, 3]
        sums[base + 4] = cum[c, 4] + x[j] * cum[c, 2]
        sums[base + 5] = cum[c, 5] - x[j] * cum[c, 1]


@_jit
def _accelerations(cum, p, rigid, case, linear, angular):
    """Inertia relief of one case from its applied loads' totals ``cum[p]``: the
    accelerations that balance them and gravity (``rigid``: see :func:`free_free_rows`)."""
    fx, fy, fz = cum[p, 0], cum[p, 1], cum[p, 2]
    dx, dy, dz = rigid[R_CG], rigid[R_CG + 1], rigid[R_CG + 2]
    # moment about the CG = moment about the axis point - (cg - axis point) x force
    mx = cum[p, 3] - (dy * fz - dz * fy) + rigid[R_MOMENT]
    my = cum[p, 4] - (dz * fx - dx * fz) + rigid[R_MOMENT + 1]
    mz = cum[p, 5] - (dx * fy - dy * fx) + rigid[R_MOMENT + 2]
    inv_mass = rigid[R_INV_MASS]
    linear[case, 0] = (fx + rigid[R_FORCE]) * inv_mass
    linear[case, 1] = (fy + rigid[R_FORCE + 1]) * inv_mass
    linear[case, 2] = (fz + rigid[R_FORCE + 2]) * inv_mass
    for k in range(3):
        row = R_INV_INERTIA + 3 * k
        angular[case, k] = rigid[row] * mx + rigid[row + 1] * my + rigid[row + 2] * mz


@_jit
def free_free_rows(basis, forces, moments, has_moments, order, arm, count, x, rigid,
                   out, residual, linear, angular):
    """Accelerations and internal loads of every case, written row by row.

    Parameters
    ----------
    basis : ndarray, shape (7, 6 (s + 1)), C-contiguous
        Internal loads of the six unit inertia fields (per unit linear [m/s^2] and angular
        [rad/s^2] acceleration) and of gravity at the s cuts and at the closing cut aft of
        everything, flattened cut after cut. [N, N m]
    forces, moments : ndarray, shape (c, p, 3)
        Applied forces [N] and moments [N m] (``moments`` unread unless ``has_moments``).
    order : ndarray, shape (p,)
        The load points sorted by x. [-]
    arm : ndarray, shape (p, 3)
        Sorted load points relative to the axis point (0, y0, z0). [m]
    count : ndarray, shape (s + 1,)
        Number of sorted load points forward of (or at) each cut. [count]
    x : ndarray, shape (s + 1,)
        x of each cut. [m]
    rigid : ndarray, shape (19,)
        Laid out by :data:`slingloads.analyses.sfbm_layout.RIGID`: CG relative to the axis point (3)
        [m], resultant force (3) [N] and moment about the CG (3) [N m] of gravity,
        1 / total mass [1/kg], inverse inertia tensor about the CG row by row (9)
        [1/(kg m^2)].
    out : ndarray, shape (c, 6 s), C-contiguous
        Internal loads, written. [N, N m]
    residual : ndarray, shape (c, 6)
        Internal loads at the closing cut, written. [N, N m]
    linear, angular : ndarray, shape (c, 3)
        Accelerations, written. [m/s^2, rad/s^2]
    """
    n_out = out.shape[1]
    p = len(order)
    cum = np.empty((p + 1, 6))
    sums = np.empty(basis.shape[1])
    b0, b1, b2, b3, b4, b5, b6 = (basis[0], basis[1], basis[2], basis[3], basis[4],
                                  basis[5], basis[6])
    for case in range(out.shape[0]):
        _forward_rows(forces, moments, has_moments, case, order, arm, cum)
        _accelerations(cum, p, rigid, case, linear, angular)
        _at_cuts(cum, count, x, sums)
        w0, w1, w2 = linear[case, 0], linear[case, 1], linear[case, 2]
        w3, w4, w5 = angular[case, 0], angular[case, 1], angular[case, 2]
        row = out[case]
        for n in range(n_out):
            row[n] = (w0 * b0[n] + w1 * b1[n] + w2 * b2[n] + w3 * b3[n] + w4 * b4[n]
                      + w5 * b5[n] + b6[n]) - sums[n]
        for k in range(6):
            n = n_out + k
            residual[case, k] = (w0 * b0[n] + w1 * b1[n] + w2 * b2[n] + w3 * b3[n]
                                 + w4 * b4[n] + w5 * b5[n] + b6[n]) - sums[n]

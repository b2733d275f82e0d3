"""Compiled fixed-step RK4 of many runs of the 1-DOF yaw model.

The same moments as :meth:`slingloads.models.yaw_dynamics.YawModel.moments` (fuselage table,
fin at its local sideslip, Apollo legacy drogue), written on scalars operation for operation,
and the same step logic as the numpy batch of
:func:`slingloads.models.yaw_dynamics.integrate_rk4`: each run on its own (runs in parallel
over the cores) on the shared time grid, the relative wind read from a table per distinct
gust, a run that leaves a table frozen from the start of that step. Compiled with `numba <https://numba.pydata.org>`_
(``cache=True``); the module is self-contained, so numba's own check of this file's source
keeps the cache valid.

Model row (``M``): 1/2 rho [kg/m^3], yaw inertia [kg m^2], then flags and constants: has
fuselage, has fin, fin at its local sideslip, has parachute, fin arm dx, dy [m], fin table
limits lo, hi [rad], parachute CD [-], parachute arm dx, dy [m], fuselage table limits lo,
hi [rad].
"""

from __future__ import annotations

import math

import numba
import numpy as np

_jit = numba.njit(cache=True, fastmath=False, nogil=True)
_parallel_jit = numba.njit(cache=True, fastmath=False, nogil=True, parallel=True)

(HALF_RHO, INERTIA, HAS_FUS, HAS_FIN, FIN_LOCAL, HAS_CHUTE, FIN_DX, FIN_DY, FIN_LO, FIN_HI,
 CHUTE_CD, CHUTE_DX, CHUTE_DY, FUS_LO, FUS_HI) = range(15)
#: Length of a model row.
N_MODEL = 15


@_jit
def interp(x, xp, fp, hint, slot):
    """``numpy.interp`` for one value: linear between breakpoints, end values outside.

    The interval is searched from the one found last (``hint[slot]``, updated): successive
    evaluations of a run move little along a table.
    """
    n = xp.size
    if x != x:
        return x
    if x <= xp[0]:
        return fp[0]
    if x >= xp[n - 1]:
        return fp[n - 1]
    lo = hint[slot]
    if lo < 0 or lo > n - 2:
        lo = 0
    while xp[lo] > x:
        lo -= 1
    while xp[lo + 1] <= x:
        lo += 1
    hint[slot] = lo
    slope = (fp[lo + 1] - fp[lo]) / (xp[lo + 1] - xp[lo])
    return slope * (x - xp[lo]) + fp[lo]


@_jit
def yaw_acceleration(psi, rate, gamma, v_rel, area, M, fus_x, fus_n, fin_x, fin_k, hint):
    """(psi'' [rad/s^2], outside a table) at yaw ``psi`` [rad], rate [rad/s], wind angle
    ``gamma`` [rad], relative speed ``v_rel`` [m/s] and parachute ``area`` [m^2]; ``hint``
    (2,) the table intervals found last (fuselage, fin), updated."""
    half_rho = M[HALF_RHO]
    beta = gamma - psi
    q = half_rho * (v_rel * v_rel)
    inside = True
    n_fus = 0.0
    n_fin = 0.0
    n_chute = 0.0
    if M[HAS_FUS] != 0.0:
        n_fus = q * interp(beta, fus_x, fus_n, hint, 0)
        inside = inside and (beta >= M[FUS_LO]) and (beta <= M[FUS_HI])
    ux0 = v_rel * math.cos(beta)
    uy0 = -v_rel * math.sin(beta)
    if M[HAS_FIN] != 0.0:
        dx, dy = M[FIN_DX], M[FIN_DY]
        if M[FIN_LOCAL] != 0.0:
            ux = ux0 - rate * dy
            uy = uy0 + rate * dx
            beta_f = math.atan2(-uy, ux)
            q_f = half_rho * (ux * ux + uy * uy)
        else:
            beta_f, q_f = beta, q
        n_fin = (-dx * q_f) * interp(beta_f, fin_x, fin_k, hint, 1)
        inside = inside and (beta_f >= M[FIN_LO]) and (beta_f <= M[FIN_HI])
    if M[HAS_CHUTE] != 0.0:
        dx, dy = M[CHUTE_DX], M[CHUTE_DY]
        ux = ux0 - rate * dy
        uy = uy0 + rate * dx
        scale = (half_rho * M[CHUTE_CD]) * area * math.hypot(ux, uy)
        n_chute = scale * (dy * ux - dx * uy)
    return (n_fus + n_fin + n_chute) / M[INERTIA], not inside


@_parallel_jit
def rk4_batch(psi0, rate0, areas, index, wind, step, stored, M, fus_x, fus_n, fin_x, fin_k,
              out_psi, out_rate, left, exit_step):
    """Integrate runs from ``psi0``, ``rate0`` (runs,) with parachute ``areas`` (runs,).

    ``wind`` (gusts, steps, 3, 2): the wind angle gamma [rad] and relative speed [m/s] of each
    distinct gust at the start, middle and end of every step; ``index`` (runs,) each run's
    gust. ``step`` (steps,) the step lengths [s], ``stored`` (steps + 1,) True at the output
    nodes; ``out_psi``, ``out_rate`` (runs, outputs) receive the histories, ``left`` and
    ``exit_step`` (runs,) whether and in which step a run left a table (its state is then
    frozen at the start of that step, its rate set to zero).
    """
    runs = psi0.size
    n_steps = step.size
    for j in numba.prange(runs):
        hint = np.zeros(2, dtype=np.int64)
        w = wind[index[j]]
        area = areas[j]
        psi, rate = psi0[j], rate0[j]
        out_psi[j, 0], out_rate[j, 0] = psi, rate
        gone = False
        k_out = 1
        for i in range(n_steps):
            if not gone:
                dt = step[i]
                half = 0.5 * dt
                ga, va = w[i, 0, 0], w[i, 0, 1]
                gb, vb = w[i, 1, 0], w[i, 1, 1]
                gc, vc = w[i, 2, 0], w[i, 2, 1]
                k1r, o1 = yaw_acceleration(psi, rate, ga, va, area, M, fus_x, fus_n, fin_x,
                                           fin_k, hint)
                k1p = rate
                k2r, o2 = yaw_acceleration(psi + half * k1p, rate + half * k1r, gb, vb, area,
                                           M, fus_x, fus_n, fin_x, fin_k, hint)
                k2p = rate + half * k1r
                k3r, o3 = yaw_acceleration(psi + half * k2p, rate + half * k2r, gb, vb, area,
                                           M, fus_x, fus_n, fin_x, fin_k, hint)
                k3p = rate + half * k2r
                k4r, o4 = yaw_acceleration(psi + dt * k3p, rate + dt * k3r, gc, vc, area, M,
                                           fus_x, fus_n, fin_x, fin_k, hint)
                k4p = rate + dt * k3r
                if o1 or o2 or o3 or o4:
                    gone = True
                    left[j] = True
                    exit_step[j] = i
                    rate = 0.0
                else:
                    psi = psi + (dt / 6.0) * (k1p + 2 * k2p + 2 * k3p + k4p)
                    rate = rate + (dt / 6.0) * (k1r + 2 * k2r + 2 * k3r + k4r)
            if stored[i + 1]:
                out_psi[j, k_out] = psi
                out_rate[j, k_out] = rate
                k_out += 1

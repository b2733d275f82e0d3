"""Compiled batch integrators of many runs of the 1-DOF yaw model: fixed-step RK4 and
adaptive Dormand-Prince 5(4).

The moments of :meth:`slingloads.models.yaw_dynamics.YawModel.moments` (fuselage table, fin at
its local sideslip, Apollo legacy drogue), compiled from their one source
(:func:`slingloads.models.yaw_dynamics.make_yaw_moments`), stepped by the RK4 step of
:mod:`slingloads.models.runge_kutta` (:func:`slingloads.models.yaw_dynamics.integrate_rk4`):
each run on its own (runs in parallel over the cores) on the shared time grid, the relative
wind read from a table per distinct gust, a run that leaves a table frozen from the start of
that step. Compiled with `numba <https://numba.pydata.org>`_ (``cache=True``; the cache is
dropped when a source of the package changes, :mod:`slingloads.models.runge_kutta`).

The adaptive kernel :func:`dopri_batch` is the Dormand-Prince pair 5(4) of
:func:`scipy.integrate.solve_ivp`'s ``RK45`` [1]_ (same error norm, step-size control and
fourth-order dense output [2]_; :mod:`slingloads.models.dormand_prince`): each run is
integrated segment by segment between its gust's breakpoints and the starts of its pieces (no
step straddles a jump or a kink) with its own step, and sampled on the output times from the
dense output. The gust is evaluated in the kernel, exactly, from the segment's piece (``c0 + c1
(t - start) + sum a cos(omega (t - ref) + phase)``), so that at a segment's end it takes the
value just before the breakpoint; on a steady piece (a constant) the relative wind is computed
once per segment instead of at every stage.

Model row (``M``): laid out by :data:`slingloads.models.yaw_dynamics.LAYOUT`. Tables: the
fuselage's ``fus_x`` [rad], ``fus_n`` (N per unit q about the axis) [m^3] and the slopes of its
segments ``fus_s`` [m^3/rad]; the fin's ``fin_x`` [rad], ``fin_k`` (S eta CY) [m^2] and
``fin_s`` [m^2/rad]: a lookup is a search from the interval found last, one multiplication and
one addition.

References
----------
.. [1] J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta formulae", Journal of
   Computational and Applied Mathematics 6 (1), 1980.
.. [2] L. F. Shampine, "Some Practical Runge-Kutta Formulas", Mathematics of Computation 46
   (173), 1986 (the dense output).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from slingloads.models.dormand_prince import LEFT, OVER_BUDGET, SAMPLE, integrator
from slingloads.models.runge_kutta import rk4_stepper
from slingloads.models.yaw_moments import INERTIA, TAS, make_yaw_moments, weight_moment

_jit = numba.njit(cache=True, fastmath=False, nogil=True)
_inline_jit = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")
_parallel_jit = numba.njit(cache=True, fastmath=False, nogil=True, parallel=True)

#: Chunks of runs of the adaptive kernel, each run j in chunk j mod CHUNKS.
CHUNKS = 64

#: The state of a run, in order: yaw psi [rad] and yaw rate r [rad/s]; its offsets (the
#: kernels index ``x[X_PSI]``, never ``x[0]``).
STATES = ("psi", "rate")
N_STATES = len(STATES)
X_PSI, X_RATE = STATES.index("psi"), STATES.index("rate")
#: Channels of the relative wind (the RK4 kernel's ``wind[..., channel]`` and the adaptive
#: kernel's work pair): wind angle gamma [rad] and relative speed [m/s].
WIND = ("gamma", "v_rel")
N_WIND = len(WIND)
W_GAMMA, W_V_REL = WIND.index("gamma"), WIND.index("v_rel")
#: Columns of a gust piece's coefficients ``p_coef[g, piece]`` (:func:`gust_value`): c0 [m/s],
#: c1 [m/s^2], ref [s].
PIECE = ("c0", "c1", "ref")
P_C0, P_C1, P_REF = (PIECE.index(n) for n in ("c0", "c1", "ref"))
#: Columns of a harmonic term ``harm[k]``: amplitude [m/s], omega [rad/s], phase [rad].
HARMONIC = ("amplitude", "omega", "phase")
H_AMPLITUDE, H_OMEGA, H_PHASE = (HARMONIC.index(n) for n in ("amplitude", "omega", "phase"))


@_jit
def interp(x, xp, fp, slope, lo):
    """``numpy.interp`` for one value, and the interval used: linear between breakpoints,
    end values outside.

    The interval is searched from ``lo``, the one found last: successive evaluations of a run
    move little along a table.

    Parameters
    ----------
    x : float
        Where to interpolate. [unit of ``xp``]
    xp, fp : ndarray, shape (n,)
        Breakpoints (increasing) and values. [any unit]
    slope : ndarray, shape (n - 1,)
        Slopes of the segments. [unit of ``fp`` / unit of ``xp``]
    lo : int
        Interval found last. [-]

    Returns
    -------
    value : float
        Interpolated value. [unit of ``fp``]
    lo : int
        Interval used. [-]
    """
    n = xp.size
    if x != x:
        return x, lo
    if x <= xp[0]:
        return fp[0], lo
    if x >= xp[n - 1]:
        return fp[n - 1], lo
    if lo < 0 or lo > n - 2:
        lo = 0
    while xp[lo] > x:
        lo -= 1
    while xp[lo + 1] <= x:
        lo += 1
    return slope[lo] * (x - xp[lo]) + fp[lo], lo


@_inline_jit
def _lookup(x, xp, fp, slope, lo, k):
    """The lookup of the yaw moments (:func:`~slingloads.models.yaw_dynamics.make_yaw_moments`)
    in compiled code: :func:`interp` from the interval ``lo[k]`` found last, updated."""
    value, lo[k] = interp(x, xp, fp, slope, lo[k])
    return value


# the moments, compiled from their one source in slingloads.models.yaw_dynamics
_moments = _inline_jit(make_yaw_moments(_lookup))
_weight = _inline_jit(weight_moment)


@_jit
def yaw_acceleration(psi, rate, gamma, v_rel, area, M, fus_x, fus_n, fus_s, fin_x, fin_k,
                     fin_s, lo):
    """Yaw acceleration of the model at one state
    (:meth:`slingloads.models.yaw_dynamics.YawModel.moments` compiled).

    Parameters
    ----------
    psi, rate : float
        Yaw [rad] and yaw rate [rad/s].
    gamma, v_rel : float
        Wind angle [rad] and relative speed [m/s].
    area : float
        Parachute flat-plate area. [m^2]
    M : ndarray, shape (N_MODEL,)
        Model row (:data:`slingloads.models.yaw_dynamics.LAYOUT`). [SI]
    fus_x, fus_n, fus_s, fin_x, fin_k, fin_s : ndarray
        Fuselage and fin tables and the slopes of their segments (module notes).
        [rad], [m^3], [m^3/rad], [rad], [m^2], [m^2/rad]
    lo : ndarray of int64, shape (2,)
        Fuselage and fin table intervals found last, updated. [-]

    Returns
    -------
    acceleration : float
        psi''. [rad/s^2]
    outside : bool
        A table was read outside its range.
    """
    n_fus, n_fin, n_chute, inside = _moments(gamma - psi, rate, v_rel, area, M, fus_x, fus_n,
                                             fus_s, fin_x, fin_k, fin_s, lo)
    return (n_fus + n_fin + n_chute + _weight(psi, M)) / M[INERTIA], not inside


@_inline_jit
def _rhs(x, wind, i, stage, args, dx):
    """The right-hand side of the RK4 step, state ``x`` = (psi [rad], r [rad/s]), the wind
    ``wind[i, stage]`` = (gamma [rad], relative speed [m/s]); ``args`` = (area, M, tables...,
    ``lo``: the table intervals found last, updated). Returns True outside a table."""
    area, M, fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, lo = args
    acc, outside = yaw_acceleration(x[X_PSI], x[X_RATE], wind[i, stage, W_GAMMA],
                                    wind[i, stage, W_V_REL], area, M, fus_x, fus_n, fus_s,
                                    fin_x, fin_k, fin_s, lo)
    dx[X_PSI] = x[X_RATE]
    dx[X_RATE] = acc
    return outside


_rk4_step = rk4_stepper(_rhs)


@_parallel_jit
def rk4_batch(psi0, rate0, areas, index, wind, step, stored, M, fus_x, fus_n, fus_s, fin_x,
              fin_k, fin_s, out_psi, out_rate, left, exit_step):
    """Integrate runs by the RK4 step of :mod:`slingloads.models.runge_kutta`, in place.

    Parameters
    ----------
    psi0, rate0 : ndarray, shape (runs,)
        Initial yaw [rad] and yaw rate [rad/s].
    areas : ndarray, shape (runs,)
        Parachute flat-plate areas. [m^2]
    index : ndarray of int, shape (runs,)
        Each run's distinct gust. [-]
    wind : ndarray, shape (gusts, steps, 3, N_WIND)
        Wind angle gamma [rad] and relative speed [m/s] (channels :data:`WIND`) of each
        distinct gust at the start, middle and end of every step.
    step : ndarray, shape (steps,)
        Step lengths. [s]
    stored : ndarray of bool, shape (steps + 1,)
        True at the output nodes.
    M : ndarray, shape (N_MODEL,)
        Model row (:data:`slingloads.models.yaw_dynamics.LAYOUT`). [SI]
    fus_x, fus_n, fus_s, fin_x, fin_k, fin_s : ndarray
        Fuselage and fin tables and the slopes of their segments (module notes).
        [rad], [m^3], [m^3/rad], [rad], [m^2], [m^2/rad]
    out_psi, out_rate : ndarray, shape (runs, outputs)
        Receive the histories. [rad], [rad/s]
    left, exit_step : ndarray, shape (runs,)
        Receive whether and in which step a run left a table (its state is then frozen at
        the start of that step, its rate set to zero). [-]
    """
    runs = psi0.size
    n_steps = step.size
    for j in numba.prange(runs):
        x = np.empty(N_STATES)
        new = np.empty(N_STATES)
        k1, k2, k3, k4 = np.empty(N_STATES), np.empty(N_STATES), np.empty(N_STATES), np.empty(
            N_STATES)
        tmp = np.empty(N_STATES)
        lo = np.zeros(2, dtype=np.int64)
        w = wind[index[j]]
        args = (areas[j], M, fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, lo)
        x[X_PSI], x[X_RATE] = psi0[j], rate0[j]
        out_psi[j, 0], out_rate[j, 0] = x[X_PSI], x[X_RATE]
        gone = False
        k_out = 1
        for i in range(n_steps):
            if not gone:
                o1 = _rhs(x, w, i, 0, args, k1)
                o2, o3, o4 = _rk4_step(x, step[i], w, i, args, k1, k2, k3, k4, tmp, new)
                if o1 or o2 or o3 or o4:
                    gone = True
                    left[j] = True
                    exit_step[j] = i
                    x[X_RATE] = 0.0
                else:
                    x[X_PSI], x[X_RATE] = new[X_PSI], new[X_RATE]
            if stored[i + 1]:
                out_psi[j, k_out] = x[X_PSI]
                out_rate[j, k_out] = x[X_RATE]
                k_out += 1


@_jit
def gust_value(t, start, c0, c1, ref, first, count, harm):
    """Lateral gust on one piece: ``c0 + c1 (t - start) + sum a cos(omega (t - ref) +
    phase)``.

    Parameters
    ----------
    t : float
        Time. [s]
    start : float
        Start of the piece. [s]
    c0, c1 : float
        Constant [m/s] and slope [m/s^2] of the piece.
    ref : float
        Time origin of the harmonic terms. [s]
    first, count : int
        Rows of ``harm`` of the piece's harmonic terms. [-], [count]
    harm : ndarray, shape (terms, 3)
        Amplitude [m/s], omega [rad/s], phase [rad] (columns :data:`HARMONIC`).

    Returns
    -------
    float
        Gust velocity. [m/s]
    """
    v = c0 + c1 * (t - start)
    for k in range(first, first + count):
        v += harm[k, H_AMPLITUDE] * math.cos(harm[k, H_OMEGA] * (t - ref) + harm[k, H_PHASE])
    return v


@_jit
def relative_wind(v, tas):
    """Wind angle and relative speed of a lateral gust.

    Parameters
    ----------
    v : float
        Lateral gust. [m/s]
    tas : float
        True airspeed. [m/s]

    Returns
    -------
    gamma : float
        atan2(v, V). [rad]
    v_rel : float
        sqrt(V^2 + v^2). [m/s]
    """
    return math.atan2(v, tas), math.sqrt(tas * tas + v * v)


@_inline_jit
def _dopri_rhs(phase, t, s, k, y, args, dx):
    """The right-hand side of the Dormand-Prince loop (:func:`slingloads.models.dormand_prince.
    integrator`), state ``y`` = (psi [rad], r [rad/s]) at time ``t`` [s] of segment ``s``;
    at a sample, ``y`` is kept in the run's row of the histories. The gust is evaluated from
    the segment's piece (:func:`gust_value`); on a steady piece the relative wind is computed
    at the segment's start (phase 0) and kept in ``wind`` for its stages. Returns 1 outside a
    table."""
    (j, g, area, seg_piece, p_start, p_coef, h_off, h_count, harm, M, fus_x, fus_n, fus_s,
     fin_x, fin_k, fin_s, lo, wind, out_psi, out_rate) = args
    if phase == SAMPLE:
        out_psi[j, k] = y[X_PSI]
        out_rate[j, k] = y[X_RATE]
        return 0
    piece = seg_piece[g, s]
    c0, c1, count = p_coef[g, piece, P_C0], p_coef[g, piece, P_C1], h_count[g, piece]
    if c1 == 0.0 and count == 0:  # steady: the relative wind of the segment
        if phase == 0:
            wind[W_GAMMA], wind[W_V_REL] = relative_wind(c0, M[TAS])
        gamma, v_rel = wind[W_GAMMA], wind[W_V_REL]
    else:
        gamma, v_rel = relative_wind(
            gust_value(t, p_start[g, piece], c0, c1, p_coef[g, piece, P_REF], h_off[g, piece],
                       count, harm), M[TAS])
    rate_dot, outside = yaw_acceleration(y[X_PSI], y[X_RATE], gamma, v_rel, area, M, fus_x,
                                         fus_n, fus_s, fin_x, fin_k, fin_s, lo)
    dx[X_PSI] = y[X_RATE]
    dx[X_RATE] = rate_dot
    return 1 if outside else 0


@_inline_jit
def _no_projection(x):
    """The yaw state needs nothing after a step."""


_dopri_loop = integrator(_dopri_rhs, _no_projection)


@_jit
def _dopri_run(j, psi0, rate0, areas, index, seg_end, seg_piece, n_seg, p_start, p_coef, h_off,
               h_count, harm, interval, rtol, atol, max_step, first_step, max_steps, stop, M,
               fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, out_psi, out_rate, left, exit_time,
               steps):
    """Run ``j`` of :func:`dopri_batch` (same arguments)."""
    n_out = out_psi.shape[1]
    g = index[j]
    x = np.empty(N_STATES)
    x[X_PSI], x[X_RATE] = psi0[j], rate0[j]
    args = (j, g, areas[j], seg_piece, p_start, p_coef, h_off, h_count, harm, M, fus_x, fus_n,
            fus_s, fin_x, fin_k, fin_s, np.zeros(2, dtype=np.int64), np.empty(N_WIND),
            out_psi, out_rate)
    status, _, t, accepted, sample = _dopri_loop(x, seg_end[g], n_seg[g], interval, n_out, 0.0,
                                                 rtol, atol, max_step, first_step, max_steps,
                                                 stop, args)
    if status == OVER_BUDGET:  # the call is refused
        steps[j] = -1
        return
    if status == LEFT:  # frozen from then
        left[j] = True
        exit_time[j] = t
        x[X_RATE] = 0.0
    for k in range(sample, n_out):
        out_psi[j, k] = x[X_PSI]
        out_rate[j, k] = x[X_RATE]
    steps[j] = accepted


@_parallel_jit
def dopri_batch(psi0, rate0, areas, index, seg_end, seg_piece, n_seg, p_start, p_coef, h_off,
                h_count, harm, interval, rtol, atol, max_step, first_step, max_steps, stop, M,
                fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, out_psi, out_rate, left, exit_time,
                steps):
    """Integrate runs by the adaptive Dormand-Prince 5(4) pair, in place.

    Run j follows distinct gust ``g = index[j]``: ``n_seg[g]`` segments ending at
    ``seg_end[g]`` (the gust's breakpoints and the starts of its pieces, then the end time),
    segment s on piece ``seg_piece[g, s]`` of the gust; on a steady piece (c1 = 0, no terms)
    the relative wind is computed once for the segment. The local error estimate is kept within
    ``atol + rtol max(|y|, |y_new|)`` (root mean square over psi and r) and the step within
    ``max_step``. A stage outside a table halves the step, and below
    :data:`~slingloads.models.dormand_prince.SMALLEST_STEP` the
    run stops (its state frozen from then, its rate set to zero). A run that would try more than
    ``max_steps`` steps (accepted or rejected) sets ``stop[0]``, and every run then stops at once
    with ``steps[j] = -1``: the call is to be refused, its histories are not complete.

    Parameters
    ----------
    psi0, rate0 : ndarray, shape (runs,)
        Initial yaw [rad] and yaw rate [rad/s].
    areas : ndarray, shape (runs,)
        Parachute flat-plate areas. [m^2]
    index : ndarray of int, shape (runs,)
        Each run's distinct gust. [-]
    seg_end : ndarray, shape (gusts, segments)
        Ends of the segments. [s]
    seg_piece : ndarray of int, shape (gusts, segments)
        Piece of each segment. [-]
    n_seg : ndarray of int, shape (gusts,)
        Segments of each gust. [count]
    p_start : ndarray, shape (gusts, pieces)
        Start of each piece. [s]
    p_coef : ndarray, shape (gusts, pieces, 3)
        c0 [m/s], c1 [m/s^2], ref [s] of each piece (columns :data:`PIECE`,
        :func:`gust_value`).
    h_off, h_count : ndarray of int, shape (gusts, pieces)
        First row and number of the piece's harmonic terms in ``harm``. [-], [count]
    harm : ndarray, shape (terms, 3)
        Amplitude [m/s], omega [rad/s], phase [rad] of the harmonic terms (columns
        :data:`HARMONIC`).
    interval : float
        Output interval, from t = 0 (dense output). [s]
    rtol, atol : float
        Tolerances. [-], [rad or rad/s]
    max_step, first_step : float
        Largest step and first trial step. [s]
    max_steps : int
        Steps a run may try. [count]
    stop : ndarray of int64, shape (1,)
        0 on entry; set to 1 when a run runs over ``max_steps``. [-]
    M : ndarray, shape (N_MODEL,)
        Model row (:data:`slingloads.models.yaw_dynamics.LAYOUT`). [SI]
    fus_x, fus_n, fus_s, fin_x, fin_k, fin_s : ndarray
        Fuselage and fin tables and the slopes of their segments (module notes).
        [rad], [m^3], [m^3/rad], [rad], [m^2], [m^2/rad]
    out_psi, out_rate : ndarray, shape (runs, outputs)
        Receive the histories. [rad], [rad/s]
    left, exit_time : ndarray, shape (runs,)
        Receive whether and when [s] a run left a table.
    steps : ndarray of int, shape (runs,)
        Receive the accepted steps of each run. [count]
    """
    # runs spread over the chunks (run j in chunk j mod CHUNKS): the chunks, shared out in
    # order among the threads, then carry like mixes of cheap and costly runs
    runs = psi0.size
    chunks = min(runs, CHUNKS)
    for c in numba.prange(chunks):
        for j in range(c, runs, chunks):
            _dopri_run(j, psi0, rate0, areas, index, seg_end, seg_piece, n_seg, p_start, p_coef,
                       h_off, h_count, harm, interval, rtol, atol, max_step, first_step,
                       max_steps, stop, M, fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, out_psi,
                       out_rate, left, exit_time, steps)

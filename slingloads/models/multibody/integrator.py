"""Runge-Kutta integration of many runs at once, compiled, with the runs spread over threads.

The method is the Dormand-Prince pair 5(4) (the one of :func:`scipy.integrate.solve_ivp`'s
``RK45``, with its fourth-order dense output): adaptive by default, the step of every run
controlled on its own so that the local error estimate stays within ``atol + rtol |x|`` (root
mean square over the states), or with a fixed step when one is given. Each run is integrated
segment by segment between the times at which its inputs jump or kink (a step gust's onset, the
end of a ramp), so that no step straddles a jump; within a segment the drive (wind, commanded
carrier acceleration and velocity) is interpolated (cubic, Catmull-Rom: third order, exact for
a drive linear in time) in a table sampled every :data:`DRIVE_STEP` or finer, its ends being
the drive just after the segment's start and just before its end. The histories are the dense
output at the sampling times. There the kernel evaluates the reported quantities with the
drive at that time, for the caller (``report``) or only into a buffer of one run from which,
as soon as the run is done, its histories are derived and measured
(:mod:`slingloads.models.multibody.response`): a batch then keeps its sampled states, or
nothing but the measures, never the reported quantities of every run.

A run whose flow leaves a table (or its hinge range) stops: with the adaptive step, after the
step has been halved down to :data:`~slingloads.models.dormand_prince.SMALLEST_STEP`
without staying inside; with a fixed step, or outside at a segment's start (after a jump of
its input), at once. Its state is kept up to that time, the rest of its history is NaN, and
the flag and the time are returned. The quaternion is renormalised after every step.

One compiled kernel, :func:`dopri_runs`, integrates a block of runs. It is serial and releases
the GIL (``nogil``), so :func:`integrate` spreads blocks of runs over a pool of threads: the
same machine code serves a single run and a batch of thousands, and no parallel variant has to
be compiled. The step loop is the one of every adaptive integrator of the package
(:func:`slingloads.models.dormand_prince.integrator`), with this model's right-hand side; it
calls the equations at a single place (over the stages and the samples), which keeps the
compiled code, and its one-time compilation, small. Each run is integrated on its own,
whatever the runs beside it: a run integrated again alone gives the same numbers to the last
bit.

References
----------
.. [1] J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta formulae", Journal of
   Computational and Applied Mathematics 6 (1), 1980.
.. [2] L. F. Shampine, "Some Practical Runge-Kutta Formulas", Mathematics of Computation 46
   (173), 1986 (the dense output).
"""

from __future__ import annotations

import math
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from slingloads.models.dormand_prince import LEFT, SAMPLE, integrator
from slingloads.models.multibody._jit import (
    KERNEL_ARRAY_FLAGS,
    jit,
    jit_alloc,
    jit_inline,
    kernel_array,
)
from slingloads.models.multibody.equations import (
    CARRIER_FREE,
    N_INFO,
    N_STATES,
    X_QUAT,
    evaluate,
)
from slingloads.models.multibody.response import (
    N_HISTORY,
    N_MEASURES,
    derive,
    measure,
)

#: Runs per block handed to one thread (small blocks balance the load of uneven runs).
BLOCK = 16
#: Default tolerances of the adaptive step (states in SI: m, m/s, rad, rad/s). [-], [SI]
RTOL, ATOL = 1e-4, 1e-5
#: Sampling step of the drive tables (finer where a segment is shorter). [s]
DRIVE_STEP = 0.01
#: Steps a run may try: no budget (the work of a multibody batch is bounded before it starts,
#: :mod:`slingloads.analyses.multibody.simulate`).
NO_BUDGET = 2 ** 62
#: First trial step of a run. [s]
FIRST_STEP = 0.01

@jit
def _drive_at(t, row, s, seg_a, seg_h, seg_n, seg_off, vals, vary, bend, out):
    """Drive at time ``t`` of segment ``s`` of profile ``row``: cubic (Catmull-Rom) in the
    segment's table, exact for a drive linear in time, the end slopes from a quadratic through
    the last three points. A channel constant over the segment (``vary`` false) is its value
    plus the one term of the cubic that its rounding leaves, w^2 ``bend`` (the same number,
    to the last bit, as the whole cubic gives)."""
    u = (t - seg_a[row, s]) / seg_h[row, s]
    last = seg_n[row, s]
    m = int(u)
    if m >= last:
        m = last - 1
    if m < 0:
        m = 0
    w = u - m
    base = seg_off[row, s] + m
    w2 = w * w
    w3 = w2 * w
    for c in range(9):
        p1 = vals[row, base, c]
        if not vary[row, s, c]:
            out[c] = p1 + w2 * bend[row, s, c]
            continue
        p2 = vals[row, base + 1, c]
        if m > 0:
            p0 = vals[row, base - 1, c]
        elif last > 1:  # quadratic through the first three
            p0 = 3.0 * p1 - 3.0 * p2 + vals[row, base + 2, c]
        else:
            p0 = 2.0 * p1 - p2
        if m + 1 < last:
            p3 = vals[row, base + 2, c]
        elif last > 1:  # quadratic through the last three
            p3 = 3.0 * p2 - 3.0 * p1 + p0
        else:
            p3 = 2.0 * p2 - p1
        out[c] = (p1 + 0.5 * w * (p2 - p0) + w2 * (p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3)
                  + w3 * (1.5 * (p1 - p2) + 0.5 * (p3 - p0)))


@jit_inline
def _renormalise(x):
    """The quaternion of state ``x`` (its four elements from ``X_QUAT``) scaled to unit
    length, in place."""
    q0, q1, q2, q3 = x[X_QUAT], x[X_QUAT + 1], x[X_QUAT + 2], x[X_QUAT + 3]
    qn = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    for m in range(X_QUAT, X_QUAT + 4):
        x[m] /= qn


@jit_inline
def _rhs(phase, t, s, k, y, args, dx):
    """The right-hand side of the Dormand-Prince loop (:func:`slingloads.models.dormand_prince.
    integrator`): the equations (:func:`~slingloads.models.multibody.equations.evaluate`) at
    state ``y`` and time ``t`` [s] of segment ``s``, the drive from the segment's table
    (:func:`_drive_at`; on a segment whose channels are constant to the last bit, once at its
    start, phase 0: the commanded velocity drives a free carrier only). At sample ``k`` the
    state (its quaternion renormalised, for the dense output) is kept, and with ``report``
    the reported quantities and derivatives there, with the drive at the sample. The
    equations are called at this one place. Returns the table or limit left (0: none)."""
    (pj, row, js, ji, report, seg_a, seg_h, seg_n, seg_off, vals, vary, bend, nodes, fus_a,
     fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v, out, info, rates, d,
     steady_drive, steady, reported) = args
    if phase == SAMPLE:
        if k > 0:  # the dense output
            _renormalise(y)
        for m in range(y.size):
            out[js, k, m] = y[m]
        for c in range(9):
            d[c] = nodes[row, k, c]
        want = True
        evaluating = report
    else:
        if phase == 0:
            steady[0] = True
            for c in range(9 if pj[CARRIER_FREE] > 0.0 else 6):
                if vary[row, s, c] or bend[row, s, c] != 0.0:
                    steady[0] = False
            if steady[0]:
                _drive_at(t, row, s, seg_a, seg_h, seg_n, seg_off, vals, vary, bend,
                          steady_drive)
        if steady[0]:
            for c in range(9):
                d[c] = steady_drive[c]
        else:
            _drive_at(t, row, s, seg_a, seg_h, seg_n, seg_off, vals, vary, bend, d)
        want = False
        evaluating = True
    f = 0
    if evaluating:
        f = evaluate(y, pj, d, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v,
                     dx, reported, want)
    if phase == SAMPLE and report:
        for m in range(y.size):
            rates[ji, k, m] = dx[m]
        for m in range(N_INFO):
            info[ji, k, m] = reported[m]
    return f


_loop = integrator(_rhs, _renormalise)


@jit_alloc
def dopri_runs(x0, P, seg_a, seg_b, seg_h, seg_n, seg_off, n_seg, vals, vary, bend, nodes,
               profile, interval, fixed, rtol, atol, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g,
               tail_v, cd_g, cd_v, report, out, info, rates, flags, stop_time, time, measured,
               measures):
    """Integrate runs ``x0`` (runs, N) with parameters ``P`` (runs, NP), in place.

    Profile ``row = profile[j]`` of run j: ``n_seg[row]`` segments from ``seg_a`` to
    ``seg_b`` (profiles, S), each a drive table of ``seg_n`` intervals of ``seg_h`` from row
    ``seg_off`` of ``vals`` (profiles, K, 9), ``vary`` (profiles, S, 9) true for the channels
    that vary over a segment, ``bend`` (profiles, S, 9) the rounding term of the others
    (:func:`_drive_at`); ``nodes`` (profiles, n_out, 9) the drive at the samples
    ``time`` (n_out,), every ``interval``. ``fixed`` > 0: that step; else adaptive with
    ``rtol``, ``atol``: the Dormand-Prince pair of :mod:`slingloads.models.dormand_prince`.

    ``out`` receives the states at the samples (NaN after a stop): (runs, n_out, N), or
    (1, n_out, N) to keep only those of the run in hand. With ``report``, the reported
    quantities are evaluated at the samples into ``info`` (runs or 1, n_out, N_INFO) and
    their derivatives into ``rates`` (same leading size), NaN after a stop. ``flags`` and
    ``stop_time`` (runs,) receive the flag and the time of a run that stopped. With
    ``measures`` of a row per run (runs, N_MEASURES) and ``report``, each run's measures
    (:func:`~slingloads.models.multibody.response.measure`) are computed after its
    integration, ``measured`` (runs, 9) holding its weight [N], mast axis (3), whether it
    has a parachute (0 or 1), the start and end of its input, the start of its verdict's
    time [s] and the settling band's floor [rad].

    With no segment, only the first sample is evaluated (its flag returned): the equations at
    the states ``x0``.

    Parameters
    ----------
    x0 : ndarray, shape (runs, N)
        Initial states. [SI]
    P : ndarray, shape (runs, NP)
        Parameter vectors (:data:`~slingloads.models.multibody.equations.LAYOUT`). [SI]
    seg_a, seg_b, seg_h : ndarray, shape (profiles, S)
        Start, end and table step of each segment. [s]
    seg_n, seg_off : ndarray of int, shape (profiles, S)
        Intervals and first row of each segment's table. [count], [-]
    n_seg : ndarray of int, shape (profiles,)
        Segments of each profile. [count]
    vals : ndarray, shape (profiles, K, 9)
        Drive tables (wind [m/s], commanded acceleration [m/s^2] and velocity [m/s]).
    vary, bend : ndarray, shape (profiles, S, 9)
        Channels that vary over a segment; the rounding term of the others.
        [-], [units of :data:`~slingloads.models.multibody.equations.DRIVE`]
    nodes : ndarray, shape (profiles, n_out, 9)
        The drive at the samples. [m/s, m/s^2, m/s]
    profile : ndarray of int, shape (runs,)
        Drive profile of each run. [-]
    interval : float
        Sampling interval. [s]
    fixed : float
        Fixed step, or 0 for the adaptive one. [s]
    rtol, atol : float
        Tolerances of the adaptive step. [-], [SI]
    fus_a, fus_b, fus_c : ndarray
        Fuselage table: alpha and beta breakpoints [rad], stacked coefficients [-].
    fin_g, fin_v, tail_g, tail_v, cd_g, cd_v : ndarray
        Fin, tail and parachute CD tables: breakpoints [rad], values [-]
        (:meth:`SlingSystem.tables <slingloads.models.multibody.system.SlingSystem.tables>`).
    report : bool
        Evaluate the reported quantities at the samples.
    out, info, rates : ndarray
        Receive the states, reported quantities and derivatives at the samples (see above).
        [SI, rad]
    flags, stop_time : ndarray, shape (runs,)
        Receive the flag and the time [s] of a run that stopped.
    time : ndarray, shape (n_out,)
        Sample times. [s]
    measured : ndarray, shape (runs, 9)
        What the measures need (see above). [SI]
    measures : ndarray, shape (runs, N_MEASURES) or (0, N_MEASURES)
        Receive each run's measures. [SI, rad, deg/s]
    """
    runs = x0.shape[0]
    n = x0.shape[1]
    n_out = out.shape[1]
    keep_states = out.shape[0] == runs
    keep_info = info.shape[0] == runs
    measuring = report and measures.shape[0] == runs
    x = np.empty(n)
    d = np.empty(9)
    steady_drive = np.empty(9)
    steady = np.zeros(1, dtype=np.bool_)
    reported = np.empty(N_INFO)
    hist = np.empty((n_out if measuring else 0, N_HISTORY))
    buf = np.empty((4, n_out if measuring else 0))
    stop = np.zeros(1, dtype=np.int64)
    first_step = fixed if fixed > 0.0 else min(FIRST_STEP, interval)
    for j in range(runs):
        row = profile[j]
        js = j if keep_states else 0
        ji = j if keep_info else 0
        for m in range(n):
            x[m] = x0[j, m]
        args = (P[j], row, js, ji, report, seg_a, seg_h, seg_n, seg_off, vals, vary, bend,
                nodes, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v, out,
                info, rates, d, steady_drive, steady, reported)
        status, flag, t, _, sample = _loop(x, seg_b[row], n_seg[row], interval, n_out, fixed,
                                           rtol, atol, np.inf, first_step, NO_BUDGET, stop,
                                           args)
        flags[j] = flag
        if status == LEFT:
            stop_time[j] = t
        # the samples a stopped run did not reach
        for k in range(sample, n_out):
            for m in range(n):
                out[js, k, m] = np.nan
            if report:
                for m in range(n):
                    rates[ji, k, m] = np.nan
                for m in range(N_INFO):
                    info[ji, k, m] = np.nan
        if measuring:
            derive(time, out[js], info[ji], measured[j, 0], measured[j, 1:4],
                   measured[j, 4] > 0.0, hist)
            measure(time, hist, measured[j, 5], measured[j, 6], measured[j, 7],
                    measured[j, 8], buf, measures[j])


def _constant_channels(table):
    """Which channels of a segment's drive table (rows, 9) vary, and for the constant ones the
    term w^2 ((p - 2.5 p) + 2 p - 0.5 p) to which :func:`_drive_at`'s cubic reduces there
    (zero for zero and some values, a rounding error for the others)."""
    p = table[0]
    vary = np.any(table != p, axis=0)
    bend = np.where(vary, 0.0, ((p - 2.5 * p) + 2.0 * p) - 0.5 * p)
    return vary, bend


def tabulate_drive(drive, breakpoints, t_end, interval, step=DRIVE_STEP):
    """Drive tables of one input profile for :func:`dopri_runs`.

    Parameters
    ----------
    drive : callable
        ``drive(t)`` for times ``t`` (n,) [s]: the drive (n, 9) (wind, commanded acceleration
        and velocity, earth axes), right-continuous (the value after a jump at ``t``).
    breakpoints : iterable of float
        Times at which the drive jumps or kinks. [s]
    t_end, interval : float
        Run length and sampling interval. [s]
    step : float
        Largest sampling step of the tables. [s]

    Returns
    -------
    dict
        ``a``, ``b``, ``h`` (segments' start, end, table step [s]), ``n``, ``offset``
        (intervals and first row of each segment's table), ``values`` (rows, 9), ``vary``
        and ``bend`` (segments, 9: the channels that vary over each segment, the rounding
        term of the others, :func:`_drive_at`), ``nodes`` (the drive at the samples,
        (n_out, 9)).
    """
    inner = sorted({float(b) for b in breakpoints if 0.0 < b < t_end * (1 - 1e-12)})
    edges = [0.0, *inner, float(t_end)]
    a, b, h, n, offset, values, vary, bend = [], [], [], [], [], [], [], []
    rows = 0
    for start, end in zip(edges[:-1], edges[1:], strict=True):
        count = max(1, int(np.ceil((end - start) / step - 1e-9)))
        times = start + (end - start) * np.arange(count + 1) / count
        times[-1] = end - 1e-9 * (end - start)  # just before the end: the left limit
        a.append(start), b.append(end), h.append((end - start) / count), n.append(count)
        offset.append(rows)
        table = np.asarray(drive(times), float)
        values.append(table)
        varies, bends = _constant_channels(table)
        vary.append(varies)
        bend.append(bends)
        rows += count + 1
    n_out = int(round(t_end / interval)) + 1
    return {"a": np.array(a), "b": np.array(b), "h": np.array(h), "n": np.array(n),
            "offset": np.array(offset), "values": np.concatenate(values),
            "vary": np.array(vary, dtype=bool), "bend": np.array(bend),
            "nodes": np.asarray(drive(np.arange(n_out) * interval), float)}


def stack_drives(profiles):
    """Padded arrays of several :func:`tabulate_drive` profiles, for :func:`dopri_runs`.

    Parameters
    ----------
    profiles : sequence of dict
        :func:`tabulate_drive` profiles.

    Returns
    -------
    dict
        The keys of :func:`tabulate_drive` stacked on a first axis of profiles (padded), and
        ``segments``, the number of segments of each.
    """
    count = len(profiles)
    segments = max(len(p["a"]) for p in profiles)
    rows = max(len(p["values"]) for p in profiles)
    samples = max(len(p["nodes"]) for p in profiles)
    out = {"a": np.zeros((count, segments)), "b": np.zeros((count, segments)),
           "h": np.ones((count, segments)), "n": np.ones((count, segments), dtype=np.int64),
           "offset": np.zeros((count, segments), dtype=np.int64),
           "segments": np.array([len(p["a"]) for p in profiles], dtype=np.int64),
           "values": np.zeros((count, rows, 9)), "vary": np.zeros((count, segments, 9), bool),
           "bend": np.zeros((count, segments, 9)),
           "nodes": np.zeros((count, samples, 9))}
    for k, p in enumerate(profiles):
        m = len(p["a"])
        for key in ("a", "b", "h", "n", "offset", "vary", "bend"):
            out[key][k, :m] = p[key]
        out["values"][k, :len(p["values"])] = p["values"]
        out["nodes"][k, :len(p["nodes"])] = p["nodes"]
    return out


def worker_count():
    """Threads used for a batch: the processors this process may run on.

    Returns
    -------
    int
        Threads. [count]
    """
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def in_blocks(block, runs, workers=None):
    """Call ``block(start)`` for the blocks of :data:`BLOCK` runs from ``start``, on a pool of
    ``workers`` threads (default :func:`worker_count`; the compiled kernels release the
    GIL).

    Parameters
    ----------
    block : callable
        ``block(start)``, integrating runs ``start`` to ``start + BLOCK``.
    runs : int
        Number of runs. [count]
    workers : int, optional
        Threads. [count]
    """
    starts = range(0, runs, BLOCK)
    workers = min(worker_count() if workers is None else int(workers), len(starts))
    if workers <= 1:
        for start in starts:
            block(start)
    else:
        with ThreadPoolExecutor(max_workers=workers) as pool:
            list(pool.map(block, starts))


@dataclass(frozen=True)
class Integrated:
    """What :func:`integrate` returns.

    Attributes
    ----------
    states : ndarray, shape (runs, n_out, N), or None
        States at the samples (NaN after a stop); None unless kept. [m, m/s, -, rad/s, rad]
    info : ndarray, shape (runs, n_out, N_INFO), or None
        Reported quantities at the samples, with ``report``. [SI]
    flags : ndarray of int, shape (runs,)
        Table or limit each run left (0: none). [-]
    stop_time : ndarray, shape (runs,)
        When a run stopped (NaN if it did not). [s]
    measures : ndarray, shape (runs, N_MEASURES), or None
        Each run's measures, when asked for. [SI, rad, deg/s]
    """

    states: np.ndarray | None
    info: np.ndarray | None
    flags: np.ndarray
    stop_time: np.ndarray
    measures: np.ndarray | None


def integrate(x0, P, drives, profile, interval, n_out, tables, *, step=None, rtol=RTOL,
              atol=ATOL, workers=None, report=False, measured=None, keep_states=True):
    """Integrate runs with :func:`dopri_runs`, blocks of runs on a pool of threads.

    Parameters
    ----------
    x0 : ndarray, shape (runs, N)
        Initial states. [m, m/s, -, rad/s, rad]
    P : ndarray, shape (runs, NP)
        Parameter vectors. [SI]
    drives : dict
        :func:`stack_drives` of the runs' drive profiles.
    profile : ndarray of int, shape (runs,)
        Drive profile of each run. [-]
    interval : float
        Sampling interval of the histories. [s]
    n_out : int
        Samples (the first at t = 0). [count]
    tables : tuple of ndarray
        :meth:`SlingSystem.tables <slingloads.models.multibody.system.SlingSystem.tables>`. [rad, -]
    step : float, optional
        Fixed step [s]; default adaptive.
    rtol, atol : float
        Tolerances of the adaptive step (SI units of the states). [-], [SI]
    workers : int, optional
        Threads (default :func:`worker_count`). [count]
    report : bool
        Also keep the reported quantities at the samples, evaluated during the integration
        (the same numbers as :func:`evaluate_many` gives afterwards at the sampled states and
        the drive at the samples).
    measured : ndarray, shape (runs, 9), optional
        With it, each run's measures are computed as soon as it is integrated, from its
        reported quantities evaluated at its samples (see :func:`dopri_runs` for the
        columns). [SI]
    keep_states : bool
        Keep the sampled states of every run (else only the measures are kept).

    Returns
    -------
    Integrated
    """
    runs = x0.shape[0]
    measuring = measured is not None
    states = np.empty((runs, n_out, N_STATES)) if keep_states else None  # the kernel fills it
    info = np.empty((runs, n_out, N_INFO)) if report else None
    rates = np.empty((runs, n_out, N_STATES)) if report else None
    measures = np.empty((runs, N_MEASURES)) if measuring else np.empty((0, N_MEASURES))
    measured = kernel_array(np.zeros((runs, 9)) if measured is None else measured)
    flags = np.zeros(runs, dtype=np.int64)
    stop_time = np.full(runs, np.nan)
    x0, P = kernel_array(x0), kernel_array(P)
    profile = np.require(profile, np.int64, KERNEL_ARRAY_FLAGS)
    fixed = 0.0 if step is None else float(step)
    time = np.arange(n_out) * float(interval)
    # what a block does not keep goes to work rows of one run, reused from run to run
    work = 1 if measuring else 0

    def block(start):
        own = slice(start, min(start + BLOCK, runs))
        dopri_runs(x0[own], P[own], drives["a"], drives["b"], drives["h"], drives["n"],
                   drives["offset"], drives["segments"], drives["values"], drives["vary"],
                   drives["bend"], drives["nodes"], profile[own], float(interval), fixed,
                   float(rtol), float(atol), *tables, report or measuring,
                   states[own] if keep_states else np.empty((1, n_out, N_STATES)),
                   info[own] if report else np.empty((work, n_out * work, N_INFO)),
                   rates[own] if report else np.empty((work, n_out * work, N_STATES)),
                   flags[own], stop_time[own], time, measured[own],
                   measures[own] if measuring else measures)

    in_blocks(block, runs, workers)
    return Integrated(states, info, flags, stop_time, measures if measuring else None)


@jit_alloc
def evaluate_states(states, P, drives, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v,
                     cd_g, cd_v, want, rates, info, flags):
    """The equations (:func:`~slingloads.models.multibody.equations.evaluate`) at each row of
    ``states`` (n, N) with parameters ``P`` (n, NP) and drive ``drives`` (n, 9): the
    derivatives into ``rates`` (n, N), the reported quantities into ``info`` (n, N_INFO), the
    flags into ``flags`` (n,). The equations as the integration loop calls them (``want`` a
    run-time bool, so that one compiled ``evaluate`` serves both), without the loop: a trim
    or a linearisation compiles the equations alone.

    Parameters
    ----------
    states : ndarray, shape (n, N)
        One state a row, in the layout of :mod:`slingloads.models.multibody.equations`.
        [m, rad, m/s, rad/s]
    P : ndarray, shape (n, NP)
        The packed parameters of each row (:mod:`slingloads.models.multibody.layout`). [SI]
    drives : ndarray, shape (n, 9)
        The carrier's drive of each row, as ``evaluate`` takes it. [SI]
    fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v : ndarray
        The aerodynamic tables of :mod:`slingloads.models.multibody.lookup`. [-]
    want : bool
        Whether the reported quantities are computed.
    rates : ndarray, shape (n, N)
        Out: the derivatives of the states. [state units / s]
    info : ndarray, shape (n, N_INFO)
        Out: the reported quantities. [SI]
    flags : ndarray, shape (n,)
        Out: the flags ``evaluate`` returns for each row. [-]
    """
    n = states.shape[1]
    y = np.empty(n)
    d = np.empty(9)
    dx = np.empty(n)
    reported = np.empty(N_INFO)
    for j in range(states.shape[0]):
        for m in range(n):
            y[m] = states[j, m]
        for c in range(9):
            d[c] = drives[j, c]
        flags[j] = evaluate(y, P[j], d, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v,
                            cd_g, cd_v, dx, reported, want)
        for m in range(n):
            rates[j, m] = dx[m]
        for m in range(N_INFO):
            info[j, m] = reported[m]


def evaluate_many(states, P, drives, tables):
    """The equations at many states at once (the integration kernel's equations, no step).

    Parameters
    ----------
    states : ndarray, shape (n, N)
        States. [m, m/s, -, rad/s, rad]
    P : ndarray, shape (n, NP) or (NP,)
        Parameter vectors (one for all). [SI]
    drives : ndarray, shape (n, 9) or (9,)
        Drive at each state (one for all). [m/s, m/s^2, m/s]
    tables : tuple of ndarray
        :meth:`SlingSystem.tables <slingloads.models.multibody.system.SlingSystem.tables>`. [rad, -]

    Returns
    -------
    rates : ndarray, shape (n, N)
        Derivatives of the states. [m/s, m/s^2, 1/s, rad/s^2, rad/s]
    info : ndarray, shape (n, N_INFO)
        Reported quantities (:data:`~slingloads.models.multibody.equations.INFO`). [SI]
    flags : ndarray of int, shape (n,)
        Flags of :data:`~slingloads.models.multibody.equations.FLAGS`. [-]
    """
    states = kernel_array(np.atleast_2d(states))
    n = states.shape[0]
    P = kernel_array(np.broadcast_to(P, (n, np.shape(P)[-1])))
    drives = kernel_array(np.broadcast_to(drives, (n, 9)))
    rates = np.empty((n, N_STATES))
    info = np.empty((n, N_INFO))
    flags = np.zeros(n, dtype=np.int64)
    evaluate_states(states, P, drives, *tables, True, rates, info, flags)
    return rates, info, flags

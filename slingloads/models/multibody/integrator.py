"""Fixed-step Runge-Kutta 4 over many runs at once, compiled, with the runs spread over threads.

Each run is integrated on its own; all runs of a batch share the aerodynamic tables and differ
in their parameters, initial state and drive. The drive of a run (wind, commanded carrier
acceleration and velocity) is tabulated beforehand, per distinct profile, at the start (just
after), middle and end (just before) of every step, so that a jump on a step boundary (a step
gust, a gust's end) is seen on its correct side.

A run that leaves a table (or its hinge range) stops: its state is kept up to the start of the
step in which it happened, the rest of its history is NaN, and the flag and the step are
returned. The quaternion is renormalised after every step.

One compiled kernel, :func:`rk4_runs`, integrates a block of runs and evaluates the reported
quantities at the stored samples. It is serial and releases the GIL (``nogil``), so
:func:`integrate` spreads blocks of runs over a pool of threads: the same machine code serves a
single run and a batch of thousands, and no parallel variant has to be compiled. The kernel
calls the equations at a single place (a loop over the four stages and the sample), which keeps
the compiled code, and its one-time compilation, small.
"""

from __future__ import annotations

import math
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from slingloads.models.multibody._jit import jit
from slingloads.models.multibody.equations import N_INFO, N_STATES, evaluate

#: Runs per block handed to one thread (small blocks balance the load of uneven runs).
BLOCK = 16


@jit
def rk4_runs(x0, P, drive, nodes, profile, dt, n_steps, every, fus_a, fus_b, fus_c, fin_g,
             fin_v, tail_g, tail_v, cd_g, cd_v, out, info, flags, exit_step):
    """Integrate runs ``x0`` (runs, N) with parameters ``P`` (runs, NP), in place.

    ``drive`` (profiles, n_steps, 3, 9) and ``nodes`` (profiles, n_out, 9), ``profile`` (runs,)
    the row of each run; ``out`` (runs, n_out, N) and ``info`` (runs, n_out, N_INFO) receive
    the states and reported quantities every ``every`` steps (pre-filled with NaN); ``flags``
    and ``exit_step`` (runs,) the flag and the step of a run that stopped.
    """
    runs = x0.shape[0]
    n = x0.shape[1]
    k = np.empty((4, n))
    tmp = np.empty(n)
    y = np.empty(n)
    scratch = np.empty(N_INFO)
    for j in range(runs):
        x = x0[j].copy()
        pj = P[j]
        row = profile[j]
        for m in range(n):
            out[j, 0, m] = x[m]
        flag = 0
        # i = -1 only evaluates the first sample; each step: four stages, then the sample.
        # One call of the equations for all five keeps the compiled code small.
        for i in range(-1, n_steps):
            sample = i < 0 or (i + 1) % every == 0
            s = (i + 1) // every
            for stage in range(0 if i >= 0 else 4, 5):
                want = stage == 4
                if want:
                    if not sample:
                        break
                    for m in range(n):
                        y[m] = x[m]
                    d = nodes[row, s]
                    dx = tmp
                    reported = info[j, s]
                else:
                    c = 0.0 if stage == 0 else (dt if stage == 3 else 0.5 * dt)
                    for m in range(n):
                        y[m] = x[m] + c * k[stage - 1, m] if stage else x[m]
                    d = drive[row, i, 0 if stage == 0 else (2 if stage == 3 else 1)]
                    dx = k[stage]
                    reported = scratch
                f = evaluate(y, pj, d, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v,
                             cd_g, cd_v, dx, reported, want)
                if not want:
                    flag |= f
                if stage == 3:
                    if flag != 0:
                        break
                    for m in range(n):
                        x[m] += dt / 6.0 * (k[0, m] + 2.0 * k[1, m] + 2.0 * k[2, m] + k[3, m])
                    qn = math.sqrt(x[9] * x[9] + x[10] * x[10] + x[11] * x[11]
                                   + x[12] * x[12])
                    for m in range(9, 13):
                        x[m] /= qn
                    if sample:
                        for m in range(n):
                            out[j, s, m] = x[m]
            if flag != 0:
                flags[j] = flag
                exit_step[j] = i
                break


def worker_count():
    """Threads used for a batch: the processors this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def integrate(x0, P, drive, nodes, profile, dt, n_steps, every, tables, workers=None):
    """Integrate runs with :func:`rk4_runs`, blocks of runs on a pool of threads.

    Parameters
    ----------
    x0 : ndarray, shape (runs, N)
        Initial states.
    P : ndarray, shape (runs, NP)
        Parameter vectors.
    drive : ndarray, shape (profiles, n_steps, 3, 9)
        Drive at the start, middle and end of every step.
    nodes : ndarray, shape (profiles, n_out, 9)
        Drive at the stored samples.
    profile : ndarray of int, shape (runs,)
        Drive profile of each run.
    dt : float
        Step. [s]
    n_steps, every : int
        Steps, and steps between stored samples.
    tables : tuple of ndarray
        :meth:`SlingSystem.tables <slingloads.models.multibody.system.SlingSystem.tables>`.
    workers : int, optional
        Threads (default :func:`worker_count`).

    Returns
    -------
    states : ndarray, shape (runs, n_out, N)
    info : ndarray, shape (runs, n_out, N_INFO)
    flags, exit_step : ndarray of int, shape (runs,)
    """
    runs = x0.shape[0]
    n_out = n_steps // every + 1
    states = np.full((runs, n_out, N_STATES), np.nan)
    info = np.full((runs, n_out, N_INFO), np.nan)
    flags = np.zeros(runs, dtype=np.int64)
    exit_step = np.full(runs, -1, dtype=np.int64)
    x0 = np.ascontiguousarray(x0, dtype=float)
    P = np.ascontiguousarray(P, dtype=float)
    profile = np.ascontiguousarray(profile, dtype=np.int64)

    def block(start):
        stop = min(start + BLOCK, runs)
        rk4_runs(x0[start:stop], P[start:stop], drive, nodes, profile[start:stop], float(dt),
                 int(n_steps), int(every), *tables, states[start:stop], info[start:stop],
                 flags[start:stop], exit_step[start:stop])

    starts = range(0, runs, BLOCK)
    workers = min(worker_count() if workers is None else int(workers), len(starts))
    if workers <= 1:
        for start in starts:
            block(start)
    else:
        with ThreadPoolExecutor(max_workers=workers) as pool:
            list(pool.map(block, starts))
    return states, info, flags, exit_step

"""Fixed-step Runge-Kutta 4 over many runs at once, compiled and parallel over runs.

Each run is integrated on its own (one thread per run, ``prange``); all runs of a batch share
the aerodynamic tables and differ in their parameters, initial state and drive. The drive of a
run (wind, commanded carrier acceleration and velocity) is tabulated beforehand, per distinct
profile, at the start (just after), middle and end (just before) of every step, so that a jump
on a step boundary (a step gust, a gust's end) is seen on its correct side.

A run that leaves a table (or its hinge range) stops: its state is kept up to the start of the
step in which it happened, the rest of its history is NaN, and the flag and the step are
returned. The quaternion is renormalised after every step.
"""

from __future__ import annotations

import math

import numpy as np

from slingloads.models.multibody._jit import parallel_jit, prange
from slingloads.models.multibody.equations import N_INFO, N_STATES, evaluate


@parallel_jit
def rk4_batch(x0, P, drive, profile, dt, n_steps, every, fus_a, fus_b, fus_c, fin_g, fin_v,
              tail_g, tail_v, cd_g, cd_v, out, flags, exit_step):
    """Integrate runs ``x0`` (runs, N) with parameters ``P`` (runs, NP).

    ``drive`` (profiles, n_steps, 3, 9), ``profile`` (runs,) its row per run; ``out`` (runs,
    n_steps // every + 1, N) receives the states every ``every`` steps (pre-filled with NaN);
    ``flags`` and ``exit_step`` (runs,) the flag and the step of a run that stopped.
    """
    runs = x0.shape[0]
    n = x0.shape[1]
    for j in prange(runs):
        x = x0[j].copy()
        k1 = np.empty(n)
        k2 = np.empty(n)
        k3 = np.empty(n)
        k4 = np.empty(n)
        tmp = np.empty(n)
        info = np.empty(1)
        pj = P[j]
        row = profile[j]
        out[j, 0] = x
        for i in range(n_steps):
            f = evaluate(x, pj, drive[row, i, 0], fus_a, fus_b, fus_c, fin_g, fin_v, tail_g,
                         tail_v, cd_g, cd_v, k1, info, False)
            for m in range(n):
                tmp[m] = x[m] + 0.5 * dt * k1[m]
            f |= evaluate(tmp, pj, drive[row, i, 1], fus_a, fus_b, fus_c, fin_g, fin_v, tail_g,
                          tail_v, cd_g, cd_v, k2, info, False)
            for m in range(n):
                tmp[m] = x[m] + 0.5 * dt * k2[m]
            f |= evaluate(tmp, pj, drive[row, i, 1], fus_a, fus_b, fus_c, fin_g, fin_v, tail_g,
                          tail_v, cd_g, cd_v, k3, info, False)
            for m in range(n):
                tmp[m] = x[m] + dt * k3[m]
            f |= evaluate(tmp, pj, drive[row, i, 2], fus_a, fus_b, fus_c, fin_g, fin_v, tail_g,
                          tail_v, cd_g, cd_v, k4, info, False)
            if f != 0:
                flags[j] = f
                exit_step[j] = i
                break
            for m in range(n):
                x[m] += dt / 6.0 * (k1[m] + 2.0 * k2[m] + 2.0 * k3[m] + k4[m])
            qn = math.sqrt(x[9] * x[9] + x[10] * x[10] + x[11] * x[11] + x[12] * x[12])
            for m in range(9, 13):
                x[m] /= qn
            if (i + 1) % every == 0:
                out[j, (i + 1) // every] = x


@parallel_jit
def info_batch(states, P, drive, profile, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v,
               cd_g, cd_v, info, rates):
    """Reported quantities ``info`` (runs, n, N_INFO) and state derivatives ``rates`` (runs, n,
    N) of stored states (runs, n, N) with their drive (profiles, n, 9); NaN states stay NaN."""
    runs, n_out = states.shape[0], states.shape[1]
    for j in prange(runs):
        row = profile[j]
        for i in range(n_out):
            if np.isnan(states[j, i, 0]):
                for m in range(N_INFO):
                    info[j, i, m] = np.nan
                for m in range(N_STATES):
                    rates[j, i, m] = np.nan
                continue
            evaluate(states[j, i], P[j], drive[row, i], fus_a, fus_b, fus_c, fin_g, fin_v,
                     tail_g, tail_v, cd_g, cd_v, rates[j, i], info[j, i], True)

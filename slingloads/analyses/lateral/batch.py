"""Many lateral-pendulum runs at once: the compiled fixed-step RK4 sweep and its drive tables.

:func:`sweep` integrates every run of a study on one shared time grid (uniform, with every
motion's breakpoints inserted so that no step straddles a jump of the hook's acceleration), in
compiled code (:mod:`slingloads.models.pendulum_batch`, the classical Runge-Kutta step of
:mod:`slingloads.models.runge_kutta`), the runs spread over the cores, with the hook's velocity
and acceleration tabulated once per distinct motion at the start, middle and end of each step
(the drive table). It returns the per-run peaks (:class:`RunMetrics`), not time histories
(:func:`~slingloads.analyses.lateral.simulation.simulate` gives those).

References
----------
.. [1] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993 (RK4, section II.1).
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from slingloads.analyses.lateral.metrics import RunMetrics
from slingloads.analyses.lateral.simulation import default_end_time
from slingloads.errors import InputError
from slingloads.limits import (
    MAX_LATERAL_MOTION_STEPS,
    MAX_LATERAL_RUN_STEPS,
    MAX_LATERAL_STEPS,
    check_count,
)
from slingloads.models.integration import solver_settings


def _stack_parameters(pendulums):
    rows = [p.arrays() for p in pendulums]
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


#: Largest drive table of one compiled batch (motions x nodes x 6 values). [bytes]
_DRIVE_BYTES = 64e6


def sweep(pendulums, motions, *, solver=None):
    """Per-run metrics of many runs, integrated together by vectorised RK4.

    Run i is ``pendulums[i]`` under ``motions[i]``. All runs share one time grid: uniform,
    with the breakpoints of every motion (where S'' jumps) inserted, so that no step
    straddles a jump (RK4 across a jump would be only first-order accurate). The runs are
    integrated one at a time in compiled code, in parallel over the cores
    (:mod:`slingloads.models.pendulum_batch`, the RK4 step of
    :mod:`slingloads.models.runge_kutta`), with the hook's motion tabulated once per distinct
    motion; rigid-rope and elastic-cable runs form two groups. Peaks between grid points are
    refined by a parabola through the three samples around them.

    Parameters
    ----------
    pendulums : sequence of LateralPendulum, length runs
    motions : sequence of carrier motions, length runs
    solver : SolverSettings, optional
        ``t_end``: common run length (default :func:`default_end_time` over all runs) [s];
        ``step``: RK4 step, default min(0.01 s, 0.25/omega_max) with omega_max the fastest
        natural mode of any run (the elastic cable's bounce mode when present), which keeps
        the peak load angle and tension within about 1e-4 of a tight solve_ivp solution. [s]
        The grid has a whole number of steps, so the step used may be slightly shorter.

    Returns
    -------
    metrics : RunMetrics
        Arrays of shape (runs,).
    step : float
        The step used. [s]
    """
    pendulums, motions = list(pendulums), list(motions)
    if len(pendulums) != len(motions) or not pendulums:
        raise InputError("a sweep needs one motion per pendulum, and at least one run",
                         (len(pendulums), len(motions)))
    solver = sweep_settings(pendulums, motions, solver)
    t_end, step = solver.t_end, solver.step
    n_steps = t_end / step
    check_count(n_steps, MAX_LATERAL_STEPS, "RK4 steps per run", field="step")
    check_count(n_steps * len(pendulums), MAX_LATERAL_RUN_STEPS, "run-steps (runs x steps)",
                field="step")
    check_count(n_steps * len({id(m) for m in motions}), MAX_LATERAL_MOTION_STEPS,
                "motion-steps (distinct motions x steps)", field="step")
    n_steps = max(int(np.ceil(n_steps - 1e-9)), 2)
    h = t_end / n_steps
    nodes, jumps = _time_nodes(t_end, n_steps, motions)
    rigid = np.array([p.rigid for p in pendulums])
    out = {f.name: np.empty(len(pendulums)) for f in fields(RunMetrics)}
    for flag in (True, False):
        idx = np.flatnonzero(rigid == flag)
        if idx.size == 0:
            continue
        group = [pendulums[i] for i in idx]
        metrics = _compiled_group(group, [motions[i] for i in idx], nodes, jumps, flag)
        for name in out:
            out[name][idx] = getattr(metrics, name)
    return RunMetrics(**out), h


def sweep_settings(pendulums, motions, solver=None):
    """``solver`` with the sweep's automatic run length and RK4 step filled in where unset
    (see :func:`sweep`).

    Parameters
    ----------
    pendulums : sequence of LateralPendulum
        The cases' pendulums.
    motions : sequence of carrier motions
        Their carrier motions (:mod:`slingloads.models.carrier_motion`).
    solver : SolverSettings, optional

    Returns
    -------
    SolverSettings
    """
    solver = solver_settings(solver)
    if solver.t_end is None:
        solver = solver.with_defaults(t_end=default_end_time(pendulums, motions))
    if solver.step is None:
        solver = solver.with_defaults(
            step=min(0.01, 0.25 / max(_fastest_mode(p) for p in pendulums)))
    return solver


def _fastest_mode(pendulum):
    return float(pendulum.linear_modes().omega.max())


def _time_nodes(t_end, n_steps, motions):
    """The uniform grid with every motion breakpoint inserted (nodes closer than 1 % of a step
    to a breakpoint are moved onto it), so that no RK4 step straddles a jump of S''.

    Returns the nodes and a flag per node: True where S'' may jump (the step ending there
    samples S'' just before it, the step starting there just after).
    """
    h = t_end / n_steps
    grid = np.linspace(0.0, t_end, n_steps + 1)
    unique = {id(m): m for m in motions}.values()
    breaks = np.unique([b for m in unique for b in m.breakpoints if 0.0 < b < t_end])
    if breaks.size:
        near = np.abs(grid[:, None] - breaks[None, :]).min(axis=1) < 0.01 * h
        near[[0, -1]] = False
        grid = np.union1d(grid[~near], breaks)
    return grid, np.isin(grid, breaks)


def _drive_table(motions, nodes, jumps):
    """Hook (velocity, acceleration) of each motion at the start (just after a jump), middle
    and end (just before a jump) of every step from each node: shape (motions, nodes, 3, 2),
    the channels :data:`slingloads.models.pendulum_batch.DRIVE`."""
    from slingloads.models.pendulum_batch import D_ACC, D_VEL

    start = nodes
    step = np.diff(nodes)
    middle = np.append(nodes[:-1] + 0.5 * step, nodes[-1])
    end = np.append(np.where(jumps[1:], np.nextafter(nodes[1:], -np.inf), nodes[1:]),
                    nodes[-1])
    table = np.empty((len(motions), nodes.size, 3, 2))
    for k, motion in enumerate(motions):
        for stage, times in enumerate((start, middle, end)):
            _, v, a = motion.kinematics(times)
            table[k, :, stage, D_VEL] = v
            table[k, :, stage, D_ACC] = a
    return table


def _compiled_group(pendulums, motions, nodes, jumps, rigid):
    """Per-run metrics of runs sharing one cable model, by
    :func:`slingloads.models.pendulum_batch.rk4_peaks`, in batches of distinct motions whose
    drive table stays within ``_DRIVE_BYTES``."""
    from slingloads.models import pendulum_batch

    params = _stack_parameters(pendulums)
    P = np.column_stack([params[name] for name in pendulum_batch.PARAMETERS])
    unique = {}
    profile = np.array([unique.setdefault(id(m), len(unique)) for m in motions])
    distinct = list({id(m): m for m in motions}.values())
    x0 = np.stack([p.initial_state(m.velocity_jump) for p, m in zip(pendulums, motions,
                                                                    strict=True)])
    best = np.empty((len(pendulums), pendulum_batch.N_SIGNALS))
    t_best = np.empty_like(best)
    per_batch = max(1, int(_DRIVE_BYTES // (nodes.size * 6 * 8)))
    for first in range(0, len(distinct), per_batch):
        idx = np.flatnonzero((profile >= first) & (profile < first + per_batch))
        drive = _drive_table(distinct[first:first + per_batch], nodes, jumps)
        b, tb = best[idx], t_best[idx]
        pendulum_batch.rk4_peaks(rigid, x0[idx], P[idx], drive, profile[idx] - first,
                                 nodes, jumps, b, tb)
        best[idx], t_best[idx] = b, tb
    best = np.where(np.isfinite(best), best, np.nan).T
    t_best = t_best.T
    load, rope = pendulum_batch.S_LOAD_ANGLE, pendulum_batch.S_ROPE_ANGLE
    tension, side = pendulum_batch.S_TENSION, pendulum_batch.S_SIDE_FORCE
    best[load] = np.minimum(best[load], np.pi)  # a parabola through the wrap at pi: not past it
    return RunMetrics(best[load], t_best[load], best[rope], t_best[rope], best[tension],
                      t_best[tension], -best[pendulum_batch.S_MINUS_TENSION], best[side],
                      t_best[side])

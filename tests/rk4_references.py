"""The numpy references of the compiled RK4 batches.

Each function steps every run of a batch together with numpy operations over arrays of shape
(runs,) or (states, runs): the classical RK4 scheme written out in full, on the same grid as
the compiled batch, operation for operation, so the two agree to round-off. The closed-form
and limit-case tests verify the scheme; these references show that the compiled kernels
(:mod:`slingloads.models.runge_kutta`, :mod:`slingloads.models.yaw_batch`,
:mod:`slingloads.models.pendulum_batch`) carry it out.
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from slingloads.analyses.lateral import RunMetrics, refine_peak, sweep_settings
from slingloads.analyses.lateral.batch import _stack_parameters, _time_nodes
from slingloads.models.carrier_motion import MotionBatch
from slingloads.models.pendulum import (
    elastic_cable_derivatives,
    load_angle,
    rigid_rope_derivatives,
)
from slingloads.models.yaw_dynamics import (
    Histories,
    _check_runs,
    _distinct,
    yaw_solver_settings,
)
from slingloads.models.yaw_dynamics import _time_nodes as _yaw_time_nodes


def yaw_rk4_numpy(model, areas, gusts, psi0=0.0, rate0=0.0, settings=None):
    """:func:`slingloads.models.yaw_dynamics.integrate_rk4` in numpy: the same arguments and
    :class:`~slingloads.models.yaw_dynamics.Histories`, every run stepped together."""
    settings = yaw_solver_settings(settings)
    areas, gusts, psi, rate = _check_runs(model, areas, gusts, psi0, rate0)
    runs = areas.size
    unique, index = _distinct(gusts)
    times = settings.output_times()
    nodes, stored = _yaw_time_nodes(settings, unique)
    start, step = nodes[:-1], np.diff(nodes)
    tables = []
    for when in (start, start + 0.5 * step, nodes[1:] - 1e-9 * step):
        v = np.stack([g.velocity(when) for g in unique])
        gamma, v_rel = model.relative_wind(v)
        tables.append((gamma.T.copy(), v_rel.T.copy()))
    out_psi, out_rate = np.empty((runs, times.size)), np.empty((runs, times.size))
    left = np.zeros(runs, dtype=bool)
    (g0, w0), (gm, wm), (g1, w1) = tables
    out_psi[:, 0], out_rate[:, 0] = psi, rate
    exit_time = np.full(psi.size, np.nan)
    deriv = model.derivatives
    k_out = 1
    for i in range(start.size):
        dt = step[i]
        half = 0.5 * dt
        ga, va = g0[i, index], w0[i, index]
        gb, vb = gm[i, index], wm[i, index]
        gc, vc = g1[i, index], w1[i, index]
        k1p, k1r, o1 = deriv(psi, rate, ga, va, areas)
        k2p, k2r, o2 = deriv(psi + half * k1p, rate + half * k1r, gb, vb, areas)
        k3p, k3r, o3 = deriv(psi + half * k2p, rate + half * k2r, gb, vb, areas)
        k4p, k4r, o4 = deriv(psi + dt * k3p, rate + dt * k3r, gc, vc, areas)
        new_psi = psi + (dt / 6.0) * (k1p + 2 * k2p + 2 * k3p + k4p)
        new_rate = rate + (dt / 6.0) * (k1r + 2 * k2r + 2 * k3r + k4r)
        bad = o1 | o2 | o3 | o4
        if bad.any() or left.any():  # a run that left stays frozen
            fresh = bad & ~left
            exit_time[fresh] = start[i]
            left |= bad
            new_psi = np.where(left, psi, new_psi)
            new_rate = np.where(left, 0.0, new_rate)
        psi, rate = new_psi, new_rate
        if stored[i + 1]:
            out_psi[:, k_out] = psi
            out_rate[:, k_out] = rate
            k_out += 1
    gust_out = np.stack([g.velocity(times) for g in unique])
    gamma_out = model.relative_wind(gust_out)[0]
    beta = gamma_out[index] - out_psi
    return Histories(times, out_psi, out_rate, beta, gust_out[index], left, exit_time)


def sweep_numpy(pendulums, motions, *, solver=None):
    """:func:`slingloads.analyses.lateral.sweep` in numpy: the same arguments and results
    (metrics, step [s]), the runs of each cable model stepped together."""
    pendulums, motions = list(pendulums), list(motions)
    solver = sweep_settings(pendulums, motions, solver)
    t_end, step = solver.t_end, solver.step
    n_steps = max(int(np.ceil(t_end / step - 1e-9)), 2)
    h = t_end / n_steps
    nodes, jumps = _time_nodes(t_end, n_steps, motions)
    rigid = np.array([p.rigid for p in pendulums])
    out = {f.name: np.empty(len(pendulums)) for f in fields(RunMetrics)}
    for flag in (True, False):
        idx = np.flatnonzero(rigid == flag)
        if idx.size == 0:
            continue
        metrics = _rk4_group([pendulums[i] for i in idx], [motions[i] for i in idx], nodes,
                             jumps, flag)
        for name in out:
            out[name][idx] = getattr(metrics, name)
    return RunMetrics(**out), h


def _rk4_group(pendulums, motions, nodes, jumps, rigid):
    """Vectorised RK4 over runs sharing one cable model; running parabola-refined peaks."""
    params = _stack_parameters(pendulums)
    weight = params["mass"] * params["g"]
    batch = MotionBatch(motions)
    derivatives = rigid_rope_derivatives if rigid else elastic_cable_derivatives
    x = np.stack([p.initial_state(v) for p, v in zip(pendulums, batch.velocity_jump,
                                                     strict=True)], axis=1)

    def f(kin, x):
        return derivatives(x, kin[1], kin[2], **params)

    alive = np.ones(len(pendulums), bool)  # rigid rope: valid until the tension first goes < 0

    def signals(x, tension):
        th1 = x[0] if rigid else np.arctan2(x[0], -x[1])
        th2 = x[1] if rigid else x[2]
        ratio = tension / weight
        taut = ratio > 0
        if rigid:
            alive[:] = alive & taut
            taut = alive.copy()
        side = np.maximum(ratio, 0.0) * np.abs(np.sin(th1))
        return np.stack([np.abs(load_angle(th1, th2)), np.abs(th1), ratio, -ratio, side]), taut

    kin = batch.kinematics(0.0)
    k1, tension = f(kin, x)
    y1, ok1 = signals(x, tension)
    counts = np.array([True, True, False, False, False])[:, None]  # angles count only when taut
    best = np.where(counts & ~ok1, -np.inf, y1)
    t_best = np.zeros_like(y1)
    y0 = ok0 = h_prev = None
    for i in range(nodes.size - 1):
        t, t_next = nodes[i], nodes[i + 1]
        h = t_next - t
        kin_half = batch.kinematics(t + 0.5 * h)
        k2, _ = f(kin_half, x + 0.5 * h * k1)
        k3, _ = f(kin_half, x + 0.5 * h * k2)
        # at a breakpoint, this step ends with S'' just before the jump
        kin = batch.kinematics(np.nextafter(t_next, -np.inf) if jumps[i + 1] else t_next)
        k4, _ = f(kin, x + h * k3)
        x = x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        if jumps[i + 1]:
            # the tension jumps with S'': count its value just before, then go on after
            _, tension_left = f(kin, x)
            y_left, ok_left = signals(x, tension_left)
            better = (y_left > best) & (~counts | ok_left)
            best = np.where(better, y_left, best)
            t_best = np.where(better, t_next, t_best)
            kin = batch.kinematics(t_next)
        k1, tension = f(kin, x)
        y2, ok2 = signals(x, tension)
        if (y0 is not None and abs(h - h_prev) <= 1e-9 * h
                and not (jumps[i] or jumps[i + 1])):
            # parabola through the equally spaced samples at t - h, t, t + h, none of them
            # across a jump of S'' (the sample at a breakpoint is taken just after it)
            peak = (y1 >= y0) & (y1 >= y2) & ok0 & ok1 & ok2  # no parabola through a kink
            value, offset = refine_peak(y0, y1, y2)
            better = peak & (value > best)
            best = np.where(better, value, best)
            t_best = np.where(better, t + offset * h, t_best)
        better = (y2 > best) & (~counts | ok2)
        best = np.where(better, y2, best)
        t_best = np.where(better, t_next, t_best)
        y0, y1, ok0, ok1, h_prev = y1, y2, ok1, ok2, h
    best = np.where(np.isfinite(best), best, np.nan)
    best[0] = np.minimum(best[0], np.pi)  # a parabola through the wrap at pi must not pass it
    return RunMetrics(best[0], t_best[0], best[1], t_best[1], best[2], t_best[2], -best[3],
                      best[4], t_best[4])

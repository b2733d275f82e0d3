"""Benchmark: a 1,000-run lateral-pendulum sweep against a lean solve_ivp loop.

The sweep: 4 bodies x 5 rope lengths x 50 hook motions (quintic steps and constant
accelerations, 0.1-0.5 g, 1-8 s), elastic cable EA = 2e7 N, all runs the same length.

* fast: :func:`slingloads.analyses.lateral.sweep` (compiled RK4 over all runs, running
  parabola-refined peaks); median of 3 calls after a warm-up call.
* baseline: what one writes by hand: a lean right-hand side on plain Python floats (``math``,
  no dicts, no numpy scalars; the hook motion as plain formulas), one
  :func:`scipy.integrate.solve_ivp` call per run and per smooth piece (the integration is
  split at the motion's breakpoints, where S'' or its rate jumps), DOP853 at the tolerance
  that just meets the accuracy asked (``--rtol``, default 1e-6: on random samples rtol 2e-6
  already misses 1e-4 and 1e-5 misses 1e-3), sampled every 0.01 s
  from its dense output, peaks refined by the same parabola. It is timed on a random sample
  of runs and scaled per run (``--full``: all runs).
* reference: the same lean loop at rtol 1e-11, atol 1e-13 on the sampled runs; the error of
  the peak load angle max |theta1 - theta2| of both methods against it is printed side by
  side (runs whose cable went slack are left out: the snatch that follows is sensitive to the
  integration and reported apart).

Prints CPU and wall time of both. The sweep runs in parallel over the cores and the loop on
one, so the speed-up (the last line) is the ratio of the medians of 3 wall times; the ratio of
CPU times (the work done) is printed above it. Run from the repository root::

    .venv/bin/python benchmarks/bench_lateral.py          # about 1.5 minutes
    .venv/bin/python benchmarks/bench_lateral.py --full   # the whole baseline loop
"""

from __future__ import annotations

import argparse
import itertools
import math
import sys

import numpy as np
from _timing import median_timed, sample, timed
from scipy.integrate import solve_ivp

from slingloads.analyses.lateral import RunMetrics, default_end_time, sweep
from slingloads.constants import FOOT, G0
from slingloads.models.carrier_motion import ConstantAcceleration, QuinticStep
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import LateralPendulum, SlungBody

BODIES = [
    SlungBody(7439.0, 7632.0, 1.722, "UH-60A"),      # NASA TM 85890
    SlungBody(5500.0, 5600.0, 1.60, "UH-60 light"),  # generic lighter configuration
    SlungBody(2096.0, 1803.0, 0.95, "BO-105C"),      # NASA CR-3144
    SlungBody(1157.0, 900.0, 0.848, "OH-6A"),        # mass and e from NASA CR-3144; Ixx assumed
]
ROPES_FT = [18.0, 30.0, 60.0, 80.0, 100.0]
ACCELERATIONS_G = [0.1, 0.2, 0.3, 0.4, 0.5]
DURATIONS = [1.0, 2.0, 4.0, 6.0, 8.0]
OUTPUT_STEP = 0.01
#: Largest relative error of the peak load angle asked for: the sweep's stated accuracy
#: (its default step keeps the peaks within about 1e-4 of a tight solution).
ACCURACY = 1e-4


def build_cases(runs, cable_ea):
    """Pendulums and motions of the sweep, ``runs`` of them (the full grid is 1,000)."""
    motions = []
    for a, d in itertools.product(ACCELERATIONS_G, DURATIONS):
        motions.append(QuinticStep.from_peak_acceleration(a * G0, d))
        motions.append(ConstantAcceleration(a * G0, d, "hold"))
    grid = list(itertools.product(BODIES, ROPES_FT, motions))
    if runs > len(grid):
        grid = (grid * (runs // len(grid) + 1))
    grid = grid[:runs]
    pendulums = [LateralPendulum(b, ft * FOOT, cable_ea) for b, ft, _ in grid]
    return pendulums, [m for _, _, m in grid]


# ----------------------------------------------------------------------------- lean loop
def lean_pieces(motion):
    """The hook's (velocity, acceleration) as plain functions of t, one per smooth piece:
    a list of (start [s], function)."""
    if isinstance(motion, QuinticStep):
        amp, dur = motion.amplitude, motion.duration

        def moving(t):
            tau = t / dur
            return (amp / dur * 30.0 * tau * tau * (1.0 - tau) ** 2,
                    amp / dur**2 * 60.0 * tau * (1.0 - tau) * (1.0 - 2.0 * tau))

        return [(0.0, moving), (dur, lambda t: (0.0, 0.0))]
    if isinstance(motion, ConstantAcceleration) and motion.then == "hold":
        rate, dur = motion.rate, motion.duration
        return [(0.0, lambda t: (rate * t, rate)), (dur, lambda t: (rate * dur, 0.0))]
    raise ValueError(f"no lean form for {motion!r}")


def lean_rhs(p, drive):
    """Plain-float right-hand side of ``p`` (LateralPendulum) under ``drive(t) -> (S', S'')``."""
    m, inertia, e, length = p.body.mass, p.body.roll_inertia, p.body.cg_below_hub, p.rope_length
    c_lat, c_roll, g, h_d = p.lateral_damping, p.roll_damping, p.gravity, p.damping_height
    sin, cos, sqrt = math.sin, math.cos, math.sqrt
    if p.rigid:
        le, m11, m22 = length * e, length * length, e * e + inertia / m

        def rigid(t, x):
            th1, th2, w1, w2 = x.tolist()
            s_vel, s_acc = drive(t)
            s1, c1, s2, c2 = sin(th1), cos(th1), sin(th2), cos(th2)
            sd, cd = sin(th1 - th2), cos(th1 - th2)
            drag = c_lat * (s_vel + length * c1 * w1 + (e - h_d) * c2 * w2) / m
            f1 = -le * sd * w2 * w2 - g * length * s1 - length * c1 * (s_acc + drag)
            f2 = (le * sd * w1 * w1 - g * e * s2 - e * c2 * s_acc - (e - h_d) * c2 * drag
                  - c_roll * w2 / m)
            m12 = le * cd
            det = m11 * m22 - m12 * m12
            return [w1, w2, (m22 * f1 - m12 * f2) / det, (m11 * f2 - m12 * f1) / det]

        return rigid
    stiffness = p.cable_stiffness

    def elastic(t, x):
        ry, rz, th2, vy, vz, w2 = x.tolist()
        s_vel, s_acc = drive(t)
        s2, c2 = sin(th2), cos(th2)
        dist = sqrt(ry * ry + rz * rz)
        tension = stiffness * (dist - length) if dist > length else 0.0
        fy, fz = -tension * ry / dist, -tension * rz / dist
        drag = c_lat * (s_vel + vy + (e - h_d) * c2 * w2)
        a2 = (-e * (fy * c2 + fz * s2) - c_roll * w2 + h_d * c2 * drag) / inertia
        return [vy, vz, w2, (fy - drag) / m - s_acc - e * a2 * c2 + e * w2 * w2 * s2,
                fz / m - g - e * a2 * s2 - e * w2 * w2 * c2, a2]

    return elastic


def lean_loop(pendulums, motions, t_end, rtol, atol):
    """Peak load angle [rad] and slack flag of each run, one solve_ivp call per smooth piece."""
    n_out = int(round(t_end / OUTPUT_STEP))
    t_out = np.linspace(0.0, t_end, n_out + 1)
    peaks, slack = [], []
    for p, motion in zip(pendulums, motions, strict=True):
        pieces = lean_pieces(motion)
        starts = [s for s, _ in pieces] + [t_end]
        x = p.initial_state(motion.velocity_jump)
        states = np.empty((x.size, t_out.size))
        for k, (t0, drive) in enumerate(pieces):
            t1 = min(starts[k + 1], t_end)
            if t1 <= t0:
                continue
            sol = solve_ivp(lean_rhs(p, drive), (t0, t1), x, method="DOP853", rtol=rtol,
                            atol=atol, dense_output=True)
            inside = (t_out >= t0) & ((t_out < t1) | (t1 == t_end))
            states[:, inside] = sol.sol(t_out[inside])
            x = sol.y[:, -1]
        _, v, a = motion.kinematics(t_out)
        _, tension = p.derivatives(states, v, a)
        th1 = states[0] if p.rigid else np.arctan2(states[0], -states[1])
        th2 = states[1] if p.rigid else states[2]
        metrics = RunMetrics.from_histories(t_out, th1 - th2, th1, tension / p.weight,
                                            p.rigid, motion.breakpoints)
        peaks.append(metrics.max_load_angle)
        slack.append(metrics.slack)
    return np.array(peaks), np.array(slack)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1000)
    parser.add_argument("--sample", type=int, default=40,
                        help="runs of the baseline and reference loops (default 40)")
    parser.add_argument("--full", action="store_true", help="baseline loop over all runs")
    parser.add_argument("--rigid", action="store_true", help="rigid rope instead of elastic")
    parser.add_argument("--cable-ea", type=float, default=2.0e7,
                        help="cable EA [N] (default 2e7 N, about a 3/4 in steel rope)")
    parser.add_argument("--rtol", type=float, default=1e-6, help="baseline DOP853 rtol")
    parser.add_argument("--atol", type=float, default=1e-8, help="baseline DOP853 atol")
    parser.add_argument("--repeat", type=int, default=3,
                        help="timed calls of each method, the median kept (default 3)")
    args = parser.parse_args(argv)

    cable_ea = None if args.rigid else args.cable_ea
    pendulums, motions = build_cases(args.runs, cable_ea)
    n = len(pendulums)
    t_end = default_end_time(set(pendulums), set(motions))
    solver = SolverSettings(t_end=t_end)
    print(f"lateral-pendulum sweep: {n} runs, "
          f"{'rigid rope' if cable_ea is None else f'elastic cable EA = {cable_ea:.3g} N'}, "
          f"{t_end:.1f} s each")

    _, cold = timed(sweep, pendulums[:2], motions[:2], solver=solver)
    print(f"  first call (compilation, or loading the compiled cache): {cold}")
    (metrics, h), fast = median_timed(lambda: sweep(pendulums, motions, solver=solver),
                                      args.repeat)
    print(f"  compiled RK4 sweep (step {h:.4g} s, parallel over runs), median of "
          f"{args.repeat}: {fast}")

    chosen = np.arange(n) if args.full else sample(n, args.sample)
    sub_p, sub_m = [pendulums[i] for i in chosen], [motions[i] for i in chosen]
    (base, _), t_base = median_timed(
        lambda: lean_loop(sub_p, sub_m, t_end, args.rtol, args.atol), args.repeat)
    loop = t_base.scaled(n / chosen.size)
    label = (f", median of {args.repeat}" if chosen.size == n else
             f" (median of {args.repeat} on {chosen.size} runs, scaled to {n})")
    print(f"  lean solve_ivp loop (DOP853, rtol {args.rtol:g}, atol {args.atol:g}, split at "
          f"breakpoints): {loop}{label}")

    (truth, slack), _ = timed(lean_loop, sub_p, sub_m, t_end, 1e-11, 1e-13)
    taut = ~slack & ~metrics.slack[chosen]
    err_fast = np.abs(metrics.max_load_angle[chosen] - truth) / truth
    err_base = np.abs(base - truth) / truth
    print(f"  peak load angle against DOP853 at rtol 1e-11 on {int(taut.sum())} sampled runs "
          f"that stayed taut ({int((~taut).sum())} went slack): largest relative error "
          f"compiled sweep {err_fast[taut].max():.2e}, lean loop {err_base[taut].max():.2e} "
          f"(asked: {ACCURACY:g})")
    if (~taut).any():
        print(f"  runs that went slack (snatch loads are sensitive to the integration): "
              f"largest relative difference compiled sweep {err_fast[~taut].max():.2e}, "
              f"lean loop {err_base[~taut].max():.2e}")
    print(f"  largest load angle of the sweep: {np.degrees(np.nanmax(metrics.max_load_angle)):.2f}"
          f" deg; runs whose cable went slack: {int(metrics.slack.sum())}")
    ok = bool(err_fast[taut].max() <= ACCURACY)
    print(f"  CPU-time ratio (work done, all threads): {loop.cpu / fast.cpu:.1f}x")
    ratio = loop.wall / fast.wall
    print(f"speed-up, medians of {args.repeat} wall times, lean solve_ivp loop / compiled "
          f"sweep: {ratio:.1f}x (target >= 50x; accuracy {'met' if ok else 'NOT met'})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

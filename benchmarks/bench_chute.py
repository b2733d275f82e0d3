"""Benchmark of the parachute sizing sweep against a lean solve_ivp loop.

The sweep is 100 parachute areas (1x to 2x the neutral static area) x 4 gust shapes (step,
10 s finite, 10 s 1-cosine, continuous; 30 ft/s at t = 30 s), 120 s each, on the GENERIC
sample aircraft HC2 at 80 KIAS, ISA sea level.

* fast: :func:`slingloads.analyses.chute_sizing.sizing_sweep`, all 400 runs by the compiled
  adaptive Dormand-Prince 5(4) (the pair of solve_ivp's RK45, split at the gust breakpoints,
  dense output) at the baseline's rtol and atol, trims, linearisations and metrics
  included; median of 3 calls after a warm-up call. ``--integrator rk4``: the compiled
  fixed-step RK4 (dt = 0.05 s, gust breakpoints on the grid) instead.
* baseline: what one writes by hand: a lean right-hand side on plain Python floats (``math``,
  ``bisect`` on lists for the tables, no dicts, no numpy scalars, the gust as a plain formula
  per piece), one :func:`scipy.integrate.solve_ivp` call per run and per smooth piece of its
  gust (the integration is split at the gust's breakpoints instead of capping the step),
  sampled every 0.1 s from its dense output; no metrics. ``--method`` and ``--rtol`` at the
  cheapest decade that meets the accuracy asked, 1e-3 deg (default RK45, rtol 1e-7, atol
  1e-9: rtol 1e-6 misses it, DOP853 costs more). Timed on a random sample of runs (median of
  3) and scaled per run (``--full``: all runs).
* reference: the same lean loop with DOP853 at rtol 1e-11, atol 1e-13 on the sampled runs;
  the largest |psi| error of both methods against it is printed side by side.

The sweep runs in parallel over the cores, the loop on one: the speed-up (the last line) is
taken on CPU time, the work done by all threads of the process (the parallel overhead, threads
waiting for work included); the sweep is also timed on one thread (the CPU-time ratio of
single-threaded work), and the ratio of median wall times is printed. The load average is
printed first: on a shared machine every figure moves with it. Run from the repository root::

    .venv/bin/python benchmarks/bench_chute.py           # about 1 minute
    .venv/bin/python benchmarks/bench_chute.py --full    # the whole baseline loop
"""

from __future__ import annotations

import argparse
import bisect
import math
import os
import sys

import numba
import numpy as np
from _timing import median_timed, sample, timed
from scipy.integrate import solve_ivp

from slingloads.analyses.chute_sizing import neutral_area, sizing_sweep
from slingloads.models.gusts import (
    FiniteGust,
    OneMinusCosineGust,
    StepGust,
    SustainedGust,
    standard_gusts,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)
from slingloads.models.yaw_dynamics import YawModel

#: Largest error of the yaw histories asked for. [deg]
ACCURACY_DEG = 1e-3


# ----------------------------------------------------------------------------- lean loop
def lean_pieces(gust, t_end):
    """The gust velocity as plain functions of t, one per smooth piece: [(start, end, v(t))]."""
    amp, t0 = gust.amplitude, gust.onset

    def zero(t):
        return 0.0

    if isinstance(gust, SustainedGust):
        tr = gust.rise_time

        def rise(t):
            return 0.5 * amp * (1.0 - math.cos(math.pi * (t - t0) / tr))

        pieces = [(0.0, t0, zero), (t0, t0 + tr, rise), (t0 + tr, t_end, lambda t: amp)]
    elif isinstance(gust, OneMinusCosineGust):
        d = gust.duration

        def bump(t):
            return 0.5 * amp * (1.0 - math.cos(2.0 * math.pi * (t - t0) / d))

        pieces = [(0.0, t0, zero), (t0, t0 + d, bump), (t0 + d, t_end, zero)]
    elif isinstance(gust, FiniteGust):
        d = gust.duration
        pieces = [(0.0, t0, zero), (t0, t0 + d, lambda t: amp), (t0 + d, t_end, zero)]
    elif isinstance(gust, StepGust):
        pieces = [(0.0, t0, zero), (t0, t_end, lambda t: amp)]
    else:
        raise ValueError(f"no lean form for {gust!r}")
    return [(a, min(b, t_end), f) for a, b, f in pieces if a < min(b, t_end)]


def lean_rhs(model, area, gust):
    """Plain-float right-hand side of the yaw model with the fuselage, the fin at its local
    sideslip and the parachute of ``area`` [m^2] under ``gust(t)`` [m/s]."""
    fus_x, fus_n = (list(map(float, a)) for a in model._fus[:2])
    fin_x, fin_k = (list(map(float, a)) for a in model._fin[:2])
    fdx, fdy = float(model._fin[2]), float(model._fin[3])
    cd, cdx, cdy = (float(v) for v in model._chute)
    half_rho, tas, inertia = float(model._half_rho), float(model._tas), model.yaw_inertia
    chute = half_rho * cd * area
    sin, cos, atan2, sqrt = math.sin, math.cos, math.atan2, math.sqrt
    right = bisect.bisect_right

    def interp(x, xp, fp):
        i = min(max(right(xp, x) - 1, 0), len(xp) - 2)
        return fp[i] + (fp[i + 1] - fp[i]) * (x - xp[i]) / (xp[i + 1] - xp[i])

    def rhs(t, y):
        psi, r = y.tolist()
        v = gust(t)
        v_rel = sqrt(tas * tas + v * v)
        beta = atan2(v, tas) - psi
        ux0, uy0 = v_rel * cos(beta), -v_rel * sin(beta)
        n_fus = half_rho * v_rel * v_rel * interp(beta, fus_x, fus_n)
        ux, uy = ux0 - r * fdy, uy0 + r * fdx
        n_fin = -fdx * half_rho * (ux * ux + uy * uy) * interp(atan2(-uy, ux), fin_x, fin_k)
        ux, uy = ux0 - r * cdy, uy0 + r * cdx
        n_chute = chute * sqrt(ux * ux + uy * uy) * (cdy * ux - cdx * uy)
        return [r, (n_fus + n_fin + n_chute) / inertia]

    return rhs


def lean_loop(model, areas, gusts, psi0, times, method, rtol, atol):
    """Yaw histories (runs, times) [rad], one solve_ivp call per run and smooth gust piece."""
    t_end = float(times[-1])
    out = np.empty((len(areas), times.size))
    for j, (area, gust) in enumerate(zip(areas, gusts, strict=True)):
        y = [float(psi0[j]), 0.0]
        for a, b, v in lean_pieces(gust, t_end):
            sol = solve_ivp(lean_rhs(model, float(area), v), (a, b), y, method=method,
                            rtol=rtol, atol=atol, dense_output=True)
            inside = (times >= a) & ((times < b) | (b == t_end))
            out[j, inside] = sol.sol(times[inside])[0]
            y = sol.y[:, -1]
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--aircraft", default="HC2")
    parser.add_argument("--sample", type=int, default=40,
                        help="runs of the baseline and reference loops (default 40)")
    parser.add_argument("--full", action="store_true", help="baseline loop over all runs")
    parser.add_argument("--repeat", type=int, default=3,
                        help="timed calls of each method, the median kept (default 3)")
    parser.add_argument("--integrator", default="dopri5", choices=("dopri5", "rk4"),
                        help="compiled integrator of the sweep (default dopri5)")
    parser.add_argument("--method", default="RK45", help="baseline solve_ivp method")
    parser.add_argument("--rtol", type=float, default=1e-7, help="baseline rtol")
    parser.add_argument("--atol", type=float, default=1e-9, help="baseline atol")
    args = parser.parse_args(argv)

    ref = sample_reference(args.aircraft)
    model = YawModel(sample_fuselage(args.aircraft), sample_fin(args.aircraft),
                     sample_hardpoints(args.aircraft), ref.yaw_inertia,
                     parachute=Parachute(1.0))
    static = neutral_area(model)
    gusts = standard_gusts()
    factors = np.linspace(1.0, 2.0, 100)
    settings = SolverSettings(t_end=120.0, step=0.05, output_interval=0.1, rtol=args.rtol,
                              atol=args.atol)

    def sweep(f):
        return sizing_sweep(model, f, gusts, settings, static=static,
                            integrator=args.integrator)

    load = os.getloadavg()
    print(f"load average {load[0]:.2f}, {load[1]:.2f}, {load[2]:.2f} (1, 5, 15 min) on "
          f"{os.cpu_count()} cores")
    _, cold = timed(sweep, factors[:2])
    result, fast = median_timed(lambda: sweep(factors), args.repeat)
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    _, single = median_timed(lambda: sweep(factors), args.repeat)
    numba.set_num_threads(threads)
    runs = result.runs
    n = runs.areas.size
    print(f"aircraft {args.aircraft}: neutral static area {static.area:.4f} m^2, "
          f"{n} runs ({factors.size} areas x {len(gusts)} gusts), 120 s each")
    print(f"  first call (compilation, or loading the compiled cache): {cold}")
    scheme = (f"adaptive Dormand-Prince 5(4), rtol {args.rtol:g}, atol {args.atol:g}"
              if args.integrator == "dopri5" else f"RK4, dt {settings.step} s")
    print(f"  compiled sizing sweep ({scheme}, trims and metrics included), "
          f"median of {args.repeat}: {fast} ({threads} threads); {single} (1 thread)")

    chosen = np.arange(n) if args.full else sample(n, args.sample)
    areas = runs.areas[chosen]
    chosen_gusts = [runs.gusts[j] for j in chosen]
    h = runs.histories
    psi0 = h.psi[chosen, 0]
    base, t_base = median_timed(
        lambda: lean_loop(model, areas, chosen_gusts, psi0, h.time, args.method, args.rtol,
                          args.atol), args.repeat)
    loop = t_base.scaled(n / chosen.size)
    label = (f", median of {args.repeat}" if chosen.size == n else
             f" (median of {args.repeat} on {chosen.size} runs, scaled to {n})")
    print(f"  lean solve_ivp loop ({args.method}, rtol {args.rtol:g}, atol {args.atol:g}, split "
          f"at gust breakpoints): {loop}{label}")

    truth, _ = timed(lean_loop, model, areas, chosen_gusts, psi0, h.time, "DOP853", 1e-11,
                     1e-13)
    inside = ~h.left_table[chosen]
    err_fast = np.degrees(np.abs(h.psi[chosen] - truth)[inside]).max()
    err_base = np.degrees(np.abs(base - truth)[inside]).max()
    peak = np.degrees(np.abs(truth[inside])).max()
    print(f"  yaw histories against DOP853 at rtol 1e-11 on {int(inside.sum())} sampled runs "
          f"(largest |psi| {peak:.1f} deg): largest |d psi| compiled sweep {err_fast:.2e} deg, "
          f"lean loop {err_base:.2e} deg (asked: {ACCURACY_DEG:g} deg)")
    verdicts = runs.to_frame()["verdict"].value_counts().to_dict()
    print(f"  verdicts: {verdicts}")
    ok = bool(err_fast <= ACCURACY_DEG)
    print(f"  wall-time ratio, medians of {args.repeat}: {loop.wall / fast.wall:.1f}x; CPU-time "
          f"ratio with the sweep on 1 thread: {loop.cpu / single.cpu:.1f}x")
    load = os.getloadavg()
    print(f"  load average at the end {load[0]:.2f}, {load[1]:.2f}, {load[2]:.2f}")
    print(f"speed-up on CPU time, lean solve_ivp loop / compiled sizing sweep ({threads} "
          f"threads): {loop.cpu / fast.cpu:.1f}x (target >= 50x; accuracy "
          f"{'met' if ok else 'NOT met'})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

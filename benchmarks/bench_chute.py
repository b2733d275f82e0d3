"""Benchmark of the parachute sizing sweep: vectorised RK4 against a plain solve_ivp loop.

The sweep is 100 parachute areas (1x to 2x the neutral static area) x 4 gust shapes (step,
10 s finite, 10 s 1-cosine, 10 s-period continuous; 30 ft/s at t = 30 s), 120 s each, on the
GENERIC sample aircraft HC2 at 80 KIAS, ISA sea level.

* fast: :func:`slingloads.analyses.chute_sizing.sizing_sweep`, all 400 runs integrated at once
  by fixed-step RK4 on arrays of shape (runs,), dt = 0.05 s (metrics included in the time).
* reference: the same model, one :func:`scipy.integrate.solve_ivp` (RK45) call per run in a
  plain Python loop, at a tolerance (rtol 1e-7, atol 1e-9) whose error against a tight
  solution (rtol 1e-11) is about the RK4 one (both about 1e-4 to 1e-3 deg).

Run from the repository root::

    .venv/bin/python benchmarks/bench_chute.py              # full reference loop (minutes)
    .venv/bin/python benchmarks/bench_chute.py --reference-runs 40   # subset, extrapolated
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from slingloads.analyses.chute_sizing import neutral_area, sizing_sweep
from slingloads.models.gusts import standard_gusts
from slingloads.models.integration import SolverSettings
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)
from slingloads.models.yaw_dynamics import YawModel, integrate_reference


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--aircraft", default="HC2")
    parser.add_argument("--reference-runs", type=int, default=None,
                        help="time the solve_ivp loop on this many runs (evenly spread) and "
                             "extrapolate; default: all 400")
    args = parser.parse_args()

    ref = sample_reference(args.aircraft)
    model = YawModel(sample_fuselage(args.aircraft), sample_fin(args.aircraft),
                     sample_hardpoints(args.aircraft), ref.yaw_inertia,
                     parachute=Parachute(1.0))
    static = neutral_area(model)
    gusts = standard_gusts()
    factors = np.linspace(1.0, 2.0, 100)
    fast_settings = SolverSettings(t_end=120.0, step=0.05, output_interval=0.1)
    ref_settings = SolverSettings(t_end=120.0, step=0.05, output_interval=0.1,
                                  rtol=1e-7, atol=1e-9)

    sizing_sweep(model, factors[:2], gusts, fast_settings, static=static)  # warm-up
    t0 = time.perf_counter()
    sweep = sizing_sweep(model, factors, gusts, fast_settings, static=static)
    fast_time = time.perf_counter() - t0
    runs = sweep.runs
    n = runs.areas.size

    chosen = (np.arange(n) if args.reference_runs is None
              else np.unique(np.linspace(0, n - 1, args.reference_runs).round().astype(int)))
    t0 = time.perf_counter()
    slow = integrate_reference(model, runs.areas[chosen], [runs.gusts[j] for j in chosen],
                               settings=ref_settings)
    slow_time = (time.perf_counter() - t0) * n / chosen.size

    h = runs.histories
    dpsi = np.degrees(np.abs(h.psi[chosen] - slow.psi)).max()
    dbeta = np.degrees(np.abs(h.beta[chosen] - slow.beta)).max()
    peak = np.degrees(np.abs(h.psi[chosen])).max()

    print(f"aircraft {args.aircraft}: neutral static area {static.area:.4f} m^2, "
          f"{n} runs ({factors.size} areas x {len(gusts)} gusts), 120 s each")
    print(f"vectorised RK4 sweep (dt {fast_settings.step} s, with metrics): {fast_time:8.3f} s")
    label = "" if chosen.size == n else f" (timed on {chosen.size} runs, extrapolated)"
    print(f"solve_ivp loop, one call per run (RK45, rtol {ref_settings.rtol:g}): "
          f"{slow_time:8.3f} s{label}")
    print(f"speed-up: {slow_time / fast_time:8.1f} x  (target >= 10 x)")
    print(f"agreement over {chosen.size} runs: max |d psi| {dpsi:.2e} deg, max |d beta| "
          f"{dbeta:.2e} deg (largest |psi| {peak:.1f} deg)")
    verdicts = runs.to_frame()["verdict"].value_counts().to_dict()
    print(f"verdicts: {verdicts}")


if __name__ == "__main__":
    main()

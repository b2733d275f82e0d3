"""Time the loads pipeline for 10,000 cases x 200 cut stations (six components).

Measures what ``LoadsStudy.run`` does per case set once the applied loads are known: gravity,
inertia relief and internal loads (shear force and bending moment) for 10,000 load cases with
30 applied load points (mast feet, aerodynamic points, fin, parachute) on an airframe of 120
mass items and 200 cut stations; and, in the same run, one ``numpy.cumsum`` over an array of
the result's shape (10,000 x 200 x 6), the floor of any cumulative-sum SFBM. Prints both
and their ratio (target: at most 5).

Run: ``python benchmarks/bench_sfbm.py``
"""

from __future__ import annotations

import time

import numpy as np

from slingloads.analyses.sfbm import free_free_internal_loads
from slingloads.models.airframe import MassItems

CASES, STATIONS, ITEMS, APPLIED = 10_000, 200, 120, 30


def best_of(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    rng = np.random.default_rng(0)
    x = np.sort(rng.uniform(0, 11, ITEMS))
    items = MassItems([f"m{i}" for i in range(ITEMS)], rng.uniform(5, 50, ITEMS),
                      np.column_stack([x, rng.normal(0, 0.4, ITEMS), rng.normal(1, 0.4, ITEMS)]))
    positions = np.column_stack([rng.uniform(0.5, 10.5, APPLIED), rng.normal(0, 0.3, APPLIED),
                                 rng.normal(1, 0.5, APPLIED)])
    forces = rng.normal(0, 1e3, (CASES, APPLIED, 3))
    moments = rng.normal(0, 1e2, (CASES, APPLIED, 3))
    stations = np.column_stack([np.linspace(0.05, 11.5, STATIONS), np.zeros(STATIONS),
                                np.ones(STATIONS)])

    def pipeline():
        return free_free_internal_loads(items, positions, forces, moments, stations)

    result, _, residual = pipeline()
    reference = np.random.default_rng(1).normal(size=result.shape)
    t_sfbm = best_of(pipeline)
    t_cumsum = best_of(lambda: np.cumsum(reference, axis=1))
    print(f"SFBM pipeline, {CASES} cases x {STATIONS} stations x 6 components: "
          f"{t_sfbm * 1e3:.1f} ms")
    print(f"numpy.cumsum over an array of shape {result.shape}: {t_cumsum * 1e3:.1f} ms")
    print(f"ratio: {t_sfbm / t_cumsum:.2f} (target <= 5)")
    print(f"largest free-free closure residual: {np.abs(residual).max():.2e} "
          f"(largest internal load {np.abs(result).max():.2e})")


if __name__ == "__main__":
    main()

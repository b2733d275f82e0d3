"""Time and memory of the loads pipeline for many cases x 200 cut stations (six components).

Measures what ``LoadsStudy.run`` does per case set once the applied loads are known: gravity,
inertia relief and internal loads (shear force and bending moment), for ``--cases`` load cases
(default 100,000) with 30 applied load points on an airframe of 120 mass items and
``--stations`` cut stations (default 200), by the compiled kernel that writes each case's
loads once; and, in the same run, on an array of the result's shape:

* one write pass (``ndarray.fill``), the floor of any computation that writes its result;
* one ``numpy.cumsum`` along the stations, the floor of any cumulative-sum SFBM (into a fresh
  array up to 200,000 cases; in place beyond, to stay within the machine's memory).

All three are single-threaded. Each figure is the median of ``--repeat`` calls, as wall time
and as CPU time (user + system: the page faults of a fresh array count); the ratio to cumsum is
printed on both, the CPU-time ratio (the steadier on a shared machine) last. The first call,
which compiles the kernel or loads it from the cache, is timed apart. The peak memory of the
pipeline is measured by ``tracemalloc`` (numpy's buffers included) in a separate, untimed call,
and as the process's peak resident set; both are printed against the size of the result.

Run from the repository root::

    .venv/bin/python benchmarks/bench_sfbm.py                              # about 20 s
    .venv/bin/python benchmarks/bench_sfbm.py --cases 1000000 --repeat 1   # ~11 GB, 2-4 min
"""

from __future__ import annotations

import argparse
import resource
import tracemalloc

import numpy as np
from _timing import median_timed, timed

from slingloads.analyses.sfbm import free_free_internal_loads
from slingloads.models.airframe import MassItems

ITEMS, APPLIED = 120, 30
#: Largest number of cases whose cumsum is timed into a fresh array.
FRESH_CUMSUM = 200_000


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=100_000)
    parser.add_argument("--stations", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args(argv)
    cases, stations = args.cases, args.stations

    rng = np.random.default_rng(0)
    x = np.sort(rng.uniform(0, 11, ITEMS))
    items = MassItems([f"m{i}" for i in range(ITEMS)], rng.uniform(5, 50, ITEMS),
                      np.column_stack([x, rng.normal(0, 0.4, ITEMS), rng.normal(1, 0.4, ITEMS)]))
    positions = np.column_stack([rng.uniform(0.5, 10.5, APPLIED), rng.normal(0, 0.3, APPLIED),
                                 rng.normal(1, 0.5, APPLIED)])
    forces = rng.normal(0, 1e3, (cases, APPLIED, 3))
    moments = rng.normal(0, 1e2, (cases, APPLIED, 3))
    points = np.column_stack([np.linspace(0.05, 11.5, stations), np.zeros(stations),
                              np.ones(stations)])
    shape = (cases, stations, 6)
    size = np.prod(shape) * 8
    print(f"loads pipeline: {cases:,} cases x {stations} stations x 6 components "
          f"(result {size / 2**30:.2f} GiB; applied loads {2 * forces.nbytes / 2**30:.2f} GiB)")

    def pipeline():
        return free_free_internal_loads(items, positions, forces, moments, points)

    _, t_first = timed(free_free_internal_loads, items, positions, forces[:1], moments[:1],
                       points)
    print(f"  first call, one case (compiles the kernel or loads it from the cache): {t_first}")
    tracemalloc.start()
    result, _, residual = pipeline()
    _, traced = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(f"  largest free-free closure residual: {np.abs(residual).max():.2e} "
          f"(largest internal load {np.abs(result).max():.2e})")
    del result, residual
    print(f"  peak memory of the pipeline (tracemalloc): {traced / 2**30:.2f} GiB = "
          f"{traced / size:.2f}x the result (target <= 1.3x)")
    print(f"  peak resident set of the process so far (inputs, interpreter and libraries "
          f"included): {rss / 2**30:.2f} GiB = {rss / size:.2f}x the result")

    def fresh_pipeline():
        pipeline()  # the result is freed at once: one result-sized array alive at a time

    _, t_sfbm = median_timed(fresh_pipeline, args.repeat)
    print(f"  SFBM pipeline, median of {args.repeat}: {t_sfbm}")

    def write_pass():
        out = np.empty(shape)
        out.fill(1.0)
        return out

    target, t_write = median_timed(write_pass, args.repeat)
    print(f"  one write pass over a fresh array of the result's shape (np.empty + fill), "
          f"median of {args.repeat}: {t_write}")
    if cases <= FRESH_CUMSUM:
        _, t_cumsum = median_timed(lambda: np.cumsum(target, axis=1), args.repeat)
        how = "into a fresh array"
    else:
        _, t_cumsum = median_timed(lambda: np.cumsum(target, axis=1, out=target), args.repeat)
        how = "in place"
    print(f"  numpy.cumsum along the stations {how}, median of {args.repeat}: {t_cumsum}")
    _, t_again = timed(target.fill, 2.0)
    print(f"  one write pass over that array again (fill, pages already mapped): {t_again}")
    print(f"  pipeline / one fresh write pass: {t_sfbm.wall / t_write.wall:.2f}x wall, "
          f"{t_sfbm.cpu / t_write.cpu:.2f}x CPU")
    print(f"  pipeline / numpy.cumsum, medians of {args.repeat} wall times: "
          f"{t_sfbm.wall / t_cumsum.wall:.2f}x (target <= 2)")
    print(f"ratio of the pipeline to numpy.cumsum (medians of {args.repeat} CPU times, both "
          f"single-threaded): {t_sfbm.cpu / t_cumsum.cpu:.2f}x (target <= 2)")


if __name__ == "__main__":
    main()

"""Time the README's main job: ``slingloads run`` on the example workbook (target: < 10 s).

Runs the command line in a fresh Python process, as a user does, writing into a temporary
directory: one cold run that compiles the numba kernels into an empty cache, as the first run
on a machine does, then three warm runs. Prints each run's wall time and CPU time (of the
child process, all its threads); the figure is the median warm wall time.

Run: ``python benchmarks/bench_example.py``
"""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"


def run(env=None):
    """(wall, CPU) time of one ``slingloads run`` on the example. [s]"""
    with tempfile.TemporaryDirectory() as out:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "slingloads.cli", "run", str(EXAMPLE), "--out",
                        out, "--quiet"], check=True, stdout=subprocess.DEVNULL, env=env)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def main():
    with tempfile.TemporaryDirectory() as cache:
        cold = run({**os.environ, "NUMBA_CACHE_DIR": cache})
    warm = [run() for _ in range(3)]
    print(f"cold (compiling the numba kernels): {cold[0]:.2f} s wall / {cold[1]:.2f} s CPU")
    print("warm: " + ", ".join(f"{w:.2f} s wall / {c:.2f} s CPU" for w, c in warm))
    print(f"slingloads run on the example (loads, lateral study, parachute sizing, multibody): "
          f"warm median {statistics.median(w for w, _ in warm):.2f} s wall, "
          f"{statistics.median(c for _, c in warm):.2f} s CPU of {len(warm)} runs "
          f"(target < 10 s)")


if __name__ == "__main__":
    main()

"""Time the README's main job: ``slingloads run`` on the example workbook (target: < 10 s).

Runs the command line in a fresh Python process, as a user does, writing into a temporary
directory, and prints the wall-clock time of the best of three runs (warm), after one cold run
that compiles the multibody kernels into an empty cache, as the first run on a machine does.

Run: ``python benchmarks/bench_example.py``
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"


def run(env=None):
    """Wall-clock time of one ``slingloads run`` on the example. [s]"""
    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "slingloads.cli", "run", str(EXAMPLE), "--out",
                        out, "--quiet"], check=True, stdout=subprocess.DEVNULL, env=env)
        return time.perf_counter() - t0


def main():
    with tempfile.TemporaryDirectory() as cache:
        cold = run({**os.environ, "NUMBA_CACHE_DIR": cache})
    times = [run() for _ in range(3)]
    print(f"slingloads run on the example (loads, lateral study, parachute sizing, multibody): "
          f"cold (compiling the multibody kernels) {cold:.2f} s; warm best {min(times):.2f} s "
          f"of {len(times)} runs (target < 10 s)")


if __name__ == "__main__":
    main()

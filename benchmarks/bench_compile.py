"""Processor time of compiling the numerical kernels of each analysis from an empty numba
cache (what a fresh installation spends once, in ``slingloads compile`` or in its first run).

Each analysis's warm-up (:data:`slingloads.runs.warmup.STEPS`, the calls ``slingloads
compile`` makes) runs in turn in one fresh process whose ``NUMBA_CACHE_DIR`` is a new
temporary folder, so the installation's own cache is neither used nor touched; the processor
time and the wall time of each are printed, with the load average before and after (other
jobs sharing the machine lengthen the wall time, hardly the processor time). The figure is
the last line: the processor time of all of them.

Run from the repository root::

    .venv/bin/python benchmarks/bench_compile.py
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_CHILD = """
import time
from slingloads.runs import warmup
for name, step in warmup.STEPS.items():
    c0, w0 = time.process_time(), time.perf_counter()
    step()
    print(f"{name}\\t{time.process_time() - c0:.2f}\\t{time.perf_counter() - w0:.2f}",
          flush=True)
"""


def _load():
    try:
        return ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not Unix
        return "unknown"


def main():
    print(f"load average before: {_load()}")
    with tempfile.TemporaryDirectory(prefix="slingloads-bench-compile-") as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache, "PYTHONPATH": str(ROOT)}
        done = subprocess.run([sys.executable, "-c", _CHILD], cwd=ROOT, env=env,
                              capture_output=True, text=True, check=True)
    total = 0.0
    for line in done.stdout.splitlines():
        name, cpu, wall = line.split("\t")
        total += float(cpu)
        print(f"{name:14s} {float(cpu):6.1f} s CPU {float(wall):6.1f} s wall")
    print(f"load average after: {_load()}")
    print(f"compiling every kernel from an empty cache: {total:.1f} s of processor time")


if __name__ == "__main__":
    main()

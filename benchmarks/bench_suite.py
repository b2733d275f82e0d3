"""Time the README's test command, ``python -m pytest -q`` (target: <= 3 minutes on a quiet
2-core machine).

Runs the suite from the repository root in a fresh Python process, as the README and CI do
(the options of pyproject.toml apply: parallel workers), and prints pytest's closing line, the
slowest tests (``--durations``), the load average before and after (other jobs sharing the
machine lengthen the figure: compare runs on a quiet machine), and last the figure: the
suite's wall-clock time. Each worker's numba cache is kept between runs (pytest's cache
folder): the first run on a machine also compiles the kernels, about 10 s of each worker.

Run: ``python benchmarks/bench_suite.py`` (one run of the whole suite: minutes);
``python benchmarks/bench_suite.py --durations 40`` for more of the slowest tests; extra
arguments after ``--`` go to pytest (``-- -n 0``: one process, no workers).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET = 180.0  # [s]


def _load():
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not Unix
        return "n/a"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--durations", type=int, default=15,
                        help="slowest tests to list (pytest --durations)")
    parser.add_argument("pytest_args", nargs="*", help="further pytest arguments (after --)")
    args = parser.parse_args(argv)
    command = [sys.executable, "-m", "pytest", "-q", f"--durations={args.durations}",
               *args.pytest_args]
    print(f"load average before (1, 5, 15 min): {_load()}; {os.cpu_count()} processors")
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - start
    lines = done.stdout.splitlines()
    slowest = [i for i, line in enumerate(lines) if "slowest" in line and "durations" in line]
    if slowest:
        print("\n".join(lines[slowest[0]:slowest[0] + args.durations + 1]))
    print("\n".join(line for line in lines if line.startswith(("FAILED", "ERROR"))))
    print(lines[-1] if lines else done.stderr[-2000:])
    print(f"load average after (1, 5, 15 min): {_load()}")
    verdict = "within" if wall <= TARGET else "over"
    print(f"README test command (python -m pytest -q): {wall:.1f} s wall, exit code "
          f"{done.returncode}, {verdict} the {TARGET:.0f} s target")
    return done.returncode


if __name__ == "__main__":
    sys.exit(main())

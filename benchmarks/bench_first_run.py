"""Time to the first report of ``slingloads run`` on the example, cold and warm (target: a
cold first run on a 2-core machine writes its first report within 10 s).

A **cold** run starts from an empty numba cache (``NUMBA_CACHE_DIR`` set to a new temporary
folder, so the installation's own cache is neither used nor touched), as the first run of a
fresh installation does without ``slingloads compile``: it compiles every kernel it needs. A
**warm** run reuses the cache the cold run left. Each run is the command line in a fresh
process, as a user runs it, writing into an empty temporary ``--out`` folder that is polled
every 10 ms: the time each report file appears there, from the start of the process (the
reports are published together, in one atomic exchange of the folder, so the first and the
last appear at once), the process's end, and its processor time with its helper processes
(user + system), the steadier figure when other jobs share the machine (its load average is
printed before and after).

Run from the repository root::

    .venv/bin/python benchmarks/bench_first_run.py              # 1 cold, 2 warm runs
    .venv/bin/python benchmarks/bench_first_run.py --root ../other-checkout --cold 2

(``--root``: the checkout whose ``slingloads`` is run, e.g. an older one to compare.)
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def load_average():
    """The machine's load average over 1, 5 and 15 minutes, as text."""
    try:
        return ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not available
        return "unknown"


def one_run(root, workbook, cache):
    """(first report [s], last report [s], end [s], CPU [s]) of one run with numba cache
    folder ``cache``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(NUMBA_CACHE_DIR=str(cache), PYTHONPATH=str(root))
    with tempfile.TemporaryDirectory() as parent:
        out = Path(parent) / "reports"
        before = os.times()
        t0 = time.perf_counter()
        process = subprocess.Popen([sys.executable, "-m", "slingloads.cli", "run",
                                    str(workbook), "--out", str(out), "--quiet"], cwd=root,
                                   env=env, stdout=subprocess.DEVNULL)
        seen = {}
        while True:
            done = process.poll() is not None
            if out.is_dir():
                now = time.perf_counter() - t0
                for path in out.iterdir():
                    if path.name.endswith((".xlsx", ".csv", ".png")):
                        seen.setdefault(path.name, now)
            if done:
                break
            time.sleep(0.01)
        end = time.perf_counter() - t0
        after = os.times()
        if process.returncode not in (0, 3):
            raise SystemExit(f"slingloads run failed with exit code {process.returncode}")
    cpu = (after.children_user - before.children_user
           + after.children_system - before.children_system)
    if not seen:
        raise SystemExit("the run wrote no report")
    return min(seen.values()), max(seen.values()), end, cpu


def _line(name, runs):
    first, last, end, cpu = (statistics.median(r[i] for r in runs) for i in range(4))
    print(f"{name} (median of {len(runs)}): first report {first:.2f} s, last report "
          f"{last:.2f} s, end {end:.2f} s, CPU {cpu:.2f} s")
    return first


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=str(ROOT), help="checkout to run (default: this)")
    parser.add_argument("--workbook", default=None,
                        help="input workbook (default: the checkout's example)")
    parser.add_argument("--cold", type=int, default=1, help="cold runs (default 1)")
    parser.add_argument("--warm", type=int, default=2, help="warm runs (default 2)")
    args = parser.parse_args(argv)
    root = Path(args.root).resolve()
    workbook = Path(args.workbook or root / "loadcases" / "example-light-twin.xlsx").resolve()
    print(f"load average before: {load_average()} ({os.cpu_count()} processors)")
    cold, warm = [], []
    for i in range(max(args.cold, 1)):
        with tempfile.TemporaryDirectory() as cache:
            cold.append(one_run(root, workbook, cache))
            if i == 0:
                warm = [one_run(root, workbook, cache) for _ in range(args.warm)]
    print(f"load average after: {load_average()}")
    if warm:
        _line("warm run", warm)
    first = _line("cold run (empty numba cache)", cold)
    print(f"cold first run of slingloads run on the example, to its first report: "
          f"{first:.2f} s (target <= 10 s)")


if __name__ == "__main__":
    main()

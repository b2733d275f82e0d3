"""Time the README's main job: ``slingloads run`` on the example workbook (target: <= 5 s).

Runs the command line in a fresh Python process, as a user does, writing into a temporary
directory; and, beside it, the analyses alone in a fresh process (import, read the workbook,
compute loads, lateral study, parachute sizing and multibody; no report written). The
difference is the cost of writing the reports (the run draws its figures in a helper process
on the machine's second core while it computes and writes the tables, so the difference can
be less than the reports' own processor time). Each figure is the median of the repeats, as
wall-clock time and as processor time of the child process and its helper (user + system):
the processor time is the steadier figure when other jobs share the machine, whose load
average is printed before and after.
A cold run first compiles the numba kernels into an empty cache, as the first run on a
machine does; it is printed apart and not counted in the median. The runs keep Python's
bytecode cache as Python does by default (``PYTHONDONTWRITEBYTECODE`` is removed from their
environment: where it is set, every run compiles the package's hundred modules again, about
half a second of processor time).

Run: ``python benchmarks/bench_example.py`` (3 repeats, about 2 minutes with the cold run);
``python benchmarks/bench_example.py --repeats 10`` for steadier figures;
``python benchmarks/bench_example.py --campaign``: the same on a copy of the workbook with
'run campaign' = yes, each run with an empty run cache of its own (``SLINGLOADS_CACHE``), so
that every campaign run is computed.
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

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"

ANALYSES_ONLY = (
    "import sys\n"
    "from slingloads.io.study import read_study\n"
    "read_study(sys.argv[1]).run()\n"
)


#: The environment of the runs: this one, with Python's default bytecode cache.
ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _timed(command, env=None):
    """(wall [s], CPU of the child [s]) of one run of ``command``, with an empty campaign
    run cache of its own."""
    before = os.times()
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as runs:
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL,
                       env={**(env or ENVIRONMENT), "SLINGLOADS_CACHE": runs})
    wall = time.perf_counter() - t0
    after = os.times()
    cpu = (after.children_user - before.children_user
           + after.children_system - before.children_system)
    return wall, cpu


def _median(runs):
    """Median wall and median CPU time of timed runs. [s]"""
    return (statistics.median(w for w, _ in runs), statistics.median(c for _, c in runs))


def load_average():
    """The machine's load average over 1, 5 and 15 minutes, as text."""
    try:
        return ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not available
        return "unknown"


def _with_campaign(workbook, folder):
    """A copy of ``workbook`` in ``folder`` with the Study row 'run campaign' = yes."""
    import openpyxl

    book = openpyxl.load_workbook(workbook)
    for row in book["Study"].iter_rows(min_row=2):
        if str(row[0].value).strip().lower() == "run campaign":
            row[1].value = "yes"
    path = folder / Path(workbook).name
    book.save(path)
    return str(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="runs of each (default 3)")
    parser.add_argument("--workbook", default=str(EXAMPLE),
                        help="input workbook (default: the example)")
    parser.add_argument("--campaign", action="store_true",
                        help="on a copy of the workbook with 'run campaign' = yes")
    args = parser.parse_args(argv)
    if args.campaign:
        copy = tempfile.TemporaryDirectory()
        args.workbook = _with_campaign(args.workbook, Path(copy.name))
    print(f"load average before: {load_average()} (2 cores)")
    with tempfile.TemporaryDirectory() as cache, tempfile.TemporaryDirectory() as out:
        cold = _timed([sys.executable, "-m", "slingloads.cli", "run", args.workbook, "--out",
                       out, "--quiet"], {**ENVIRONMENT, "NUMBA_CACHE_DIR": cache})
    print(f"cold run (compiling the numba kernels into an empty cache): wall {cold[0]:.2f} s, "
          f"CPU {cold[1]:.2f} s")
    alone, whole = [], []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(args.repeats):  # alternated: a change of load hits both alike
            alone.append(_timed([sys.executable, "-c", ANALYSES_ONLY, args.workbook]))
            whole.append(_timed([sys.executable, "-m", "slingloads.cli", "run", args.workbook,
                                 "--out", out, "--quiet"]))
    analyses, run = _median(alone), _median(whole)
    print(f"load average after: {load_average()}")
    print(f"analyses alone (import, read, compute; no report): wall {analyses[0]:.2f} s, "
          f"CPU {analyses[1]:.2f} s")
    print(f"reports (run - analyses): wall {run[0] - analyses[0]:.2f} s, "
          f"CPU {run[1] - analyses[1]:.2f} s")
    what = "loads, lateral study, parachute sizing, multibody" + (
        ", campaign" if args.campaign else "")
    print(f"slingloads run on {Path(args.workbook).name} ({what}), median of "
          f"{args.repeats}: wall {run[0]:.2f} s, CPU {run[1]:.2f} s (target <= 5 s)")


if __name__ == "__main__":
    main()

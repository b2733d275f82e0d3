"""Benchmark of memory: the peak memory of a whole command (its process and every process it
starts) on the largest inputs the documented limits allow, each workbook under 1 MB.

Each case writes a workbook (the small test workbook of ``tests/hostile.py`` with its Study
rows pushed to the limits), runs ``slingloads COMMAND`` on it in a child process (``nice``,
with a time-out) and samples every 0.1 s the processes of its tree: the sum of their resident
set sizes (RSS, each process's shared library pages counted in each) and of their
proportional set sizes (PSS, shared pages split between the processes sharing them: what the
machine gives the command). The budget (docs/inputs-and-outputs.md, section 9) is 1 GiB for a
command; a case refused before it starts passes when its message names the cell and gives the
estimate. Run from the repository root::

    .venv/bin/python benchmarks/bench_memory.py            # the quick cases, 1 to 2 minutes
    .venv/bin/python benchmarks/bench_memory.py --full     # also the lateral sweep and the
                                                           # long multibody and campaign
                                                           # runs (about an hour)
    .venv/bin/python benchmarks/bench_memory.py --case multibody-long-run

The last line printed is the largest peak (PSS) over the cases run, in MiB.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import psutil

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from hostile import (  # noqa: E402
    save_xlsx,
    set_parameter,
    small_dynamics_workbook,
    small_workbook,
)

#: A command's memory budget (docs/inputs-and-outputs.md, section 9). [bytes]
BUDGET = 2**30
#: Time-out of one case. [s]
TIMEOUT = 1800


def _dynamics(multibody, campaign):
    book = small_dynamics_workbook()
    set_parameter(book, "run multibody", "yes" if multibody else "no")
    set_parameter(book, "run campaign", "yes" if campaign else "no")
    return book


def multibody_many_long_runs(runs=200, interval=4.0):
    """``runs`` runs (200: MAX_MULTIBODY_RUNS) of 3,600 s (the longest) sampled every
    ``interval`` (4 s: 180,200 stored samples, within MAX_MULTIBODY_SAMPLES), adaptive step,
    each its own gust (distinct drive tables of 52 MB each)."""
    book = _dynamics(True, False)
    rows = book["MultibodyManoeuvres"][:1]
    for k in range(runs):
        rows.append([f"gust {k}", "gust", "1-cosine", "lateral", 30.0, 1.0 + 0.01 * k, 2.0,
                     None, None, None, None])
    book["MultibodyManoeuvres"] = rows
    set_parameter(book, "multibody simulation time", 3600.0, "s")
    set_parameter(book, "multibody output interval", interval, "s")
    set_parameter(book, "multibody time step", 0.0, "s")
    return "simulate", book


def multibody_fine_step():
    """Two runs of 3,600 s at about the finest fixed step MAX_MULTIBODY_RUN_STEPS allows
    (0.0025 s: 2,880,000 run-steps), sampled every 0.04 s (180,002 samples, within
    MAX_MULTIBODY_SAMPLES)."""
    book = _dynamics(True, False)
    set_parameter(book, "multibody simulation time", 3600.0, "s")
    set_parameter(book, "multibody output interval", 0.04, "s")
    set_parameter(book, "multibody time step", 0.0025, "s")
    return "simulate", book


def campaign_long_runs(workers=None):
    """The largest matrix of runs of 3,600 s that MAX_CAMPAIGN_SAMPLES lets be stored:
    864 runs sampled every 1.25 s (2.49 million samples), adaptive step."""
    book = _dynamics(False, True)
    set_parameter(book, "campaign area factors", "1.0, 1.2, 1.4, 1.6, 1.8, 2.0")
    set_parameter(book, "campaign airspeeds EAS", "40, 60, 80, 100", "kt")
    set_parameter(book, "campaign density altitudes", "0, 5000, 10000", "ft")
    set_parameter(book, "campaign cable lengths", "60", "ft")
    set_parameter(book, "campaign carriers", "frozen, free")
    set_parameter(book, "campaign manoeuvres", "free response, gust +30 ft/s, gust -30 ft/s")
    set_parameter(book, "campaign run length", 3600.0, "s")
    set_parameter(book, "campaign time step", 0.0, "s")
    set_parameter(book, "campaign output interval", 1.25, "s")
    if workers is not None:
        set_parameter(book, "campaign workers", workers)
    return "campaign", book


def campaign_many_workers():
    """A small campaign asking for 64 local workers (MAX_WORKERS)."""
    book = _dynamics(False, True)
    set_parameter(book, "campaign workers", 64)
    return "campaign", book


def campaign_one_long_run():
    """One campaign run (plus the runs without parachute) as long as a run's memory lets:
    a run of 3,600 s sampled every 0.0075 s (480,001 samples of 680 bytes and 52 MB of drive
    tables: about 378 MB, within the 512 MiB of a computation)."""
    book = _dynamics(False, True)
    set_parameter(book, "campaign area factors", "1.0")
    set_parameter(book, "campaign density altitudes", "0", "ft")
    book["CampaignMasses"] = book["CampaignMasses"][:2]
    set_parameter(book, "campaign run length", 3600.0, "s")
    set_parameter(book, "campaign time step", 0.0, "s")
    set_parameter(book, "campaign output interval", 0.0075, "s")
    return "campaign", book


def lateral_long_histories():
    """The lateral sweep near its limits: 20 motions (19 smooth steps and a measured history
    of 40,000 samples) x 1 rope x the 125 points of the parameter ranges = 2,500 pendulums
    of 100 s at 0.02 s (12.5 million run-steps of MAX_LATERAL_RUN_STEPS' 20 million), the
    critical run's histories at 200,000 samples (MAX_HISTORY_OUTPUT)."""
    book = small_workbook()
    set_parameter(book, "run loads", "no")
    set_parameter(book, "run chute sizing", "no")
    motions = book["LateralMotions"][:1]
    for k in range(19):
        motions.append([f"step {k}", "smooth step", 1.0 + 0.1 * k, 1.5, None, None])
    motions.append(["measured", "time history", None, None, "H1", None])
    book["LateralMotions"] = motions
    history = [("history id", "t [s]", "S [m]")]
    for k in range(40_000):
        t = 0.0025 * k
        history.append(("H1", t, 0.05 * t * t))
    book["LateralHistory"] = history
    book["LateralRopes"] = [book["LateralRopes"][0]] + [
        (20.0 + 10.0 * k, f"rope {k}") for k in range(1)]
    set_parameter(book, "lateral simulation time", 100.0, "s")
    set_parameter(book, "lateral RK4 step", 0.02, "s")
    set_parameter(book, "lateral history output step", 0.0005, "s")
    return "lateral", book


def loads_many_cases():
    """Loads near their limits: 10,000 mass items (MAX_MASS_ITEMS) x 400 listed load cases
    and those generated at 4 hook azimuths (about 4.2 million case-points, MAX_CASE_POINTS
    5 million), 100 stations (about 42,000 SFBM rows, MAX_SFBM_ROWS 50,000)."""
    book = small_workbook()
    set_parameter(book, "run lateral", "no")
    set_parameter(book, "run chute sizing", "no")
    set_parameter(book, "hook azimuths", 4)
    items = book["MassItems"][:1]
    for k in range(10_000):
        x = 1.0 + 7.0 * (k % 1000) / 1000
        items.append([f"m{k}", None, 0.17, round(x, 4), 0.0, 0.6, 0.01, 0.005, 0.005])
    book["MassItems"] = items
    book["Stations"] = [("id", "x [m]")] + [(f"S{k}", round(1.2 + 0.06 * k, 3))
                                            for k in range(100)]
    cases = [("id", "hook", "aero", "chute", "description")]
    for k in range(400):
        cases.append((f"L{k}", "VERTICAL", "C", "no", None))
    book["LoadCases"] = cases
    set_parameter(book, "hull stations", "S2")
    return "loads", book


QUICK = {
    "campaign-many-workers": campaign_many_workers,
    "campaign-one-long-run": campaign_one_long_run,
    "loads-many-cases": loads_many_cases,
}
FULL = {
    "lateral-long-histories": lateral_long_histories,
    "multibody-fine-step": multibody_fine_step,
    "multibody-200-long-runs": multibody_many_long_runs,
    "multibody-100-long-runs": lambda: multibody_many_long_runs(100, 2.0),
    "campaign-long-runs": campaign_long_runs,
    "campaign-long-runs-16-workers": lambda: campaign_long_runs(16),
}


def _tree(root):
    try:
        return [root, *root.children(recursive=True)]
    except psutil.Error:
        return [root]


def measure(command, path, out, timeout=TIMEOUT):
    """Run ``slingloads command path --out out``: (exit code, peak summed RSS, peak summed
    PSS [bytes], largest number of slingloads processes (the ``timeout`` process that starts
    them apart; its 2 MB are in the sums), seconds, stderr, the PSS of each process at the
    peak [bytes])."""
    argv = ["nice", "-n", "10", "timeout", str(timeout), sys.executable, "-m",
            "slingloads.cli", command, str(path), "--out", str(out), "--quiet"]
    env = {**os.environ, "SLINGLOADS_CACHE": str(Path(out).parent / "cache")}
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, env=env)
    root = psutil.Process(proc.pid)
    rss = pss = count = 0
    split = []
    while proc.poll() is None:
        total_rss = total_pss = 0
        tree = _tree(root)
        each = []
        for p in tree:
            try:
                info = p.memory_full_info()
            except psutil.Error:
                continue
            total_rss += info.rss
            total_pss += info.pss
            each.append(info.pss)
        if total_pss > pss:
            split = each
        rss, pss, count = max(rss, total_rss), max(pss, total_pss), max(count, len(tree) - 1)
        time.sleep(0.1)
    err = proc.stderr.read()
    return proc.returncode, rss, pss, count, time.monotonic() - start, err, split


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--full", action="store_true", help="also the long cases")
    parser.add_argument("--case", action="append", help="only this case (repeatable)")
    args = parser.parse_args()
    cases = {**QUICK, **FULL} if args.full else dict(QUICK)
    if args.case:
        cases = {name: {**QUICK, **FULL}[name] for name in args.case}
    worst = 0
    with tempfile.TemporaryDirectory(prefix="slingloads-memory-") as folder:
        for name, build in cases.items():
            command, book = build()
            path = save_xlsx(book, Path(folder) / f"{name}.xlsx")
            size = path.stat().st_size
            assert size < 2**20, (name, size)
            code, rss, pss, count, seconds, err, split = measure(command, path,
                                                                 Path(folder) / name / "out")
            lines = [line for line in err.strip().splitlines() if "Warning" not in line
                     and not line.startswith(" ")]
            last = " | ".join(lines[-3:])
            print(f"{name}: {size / 1024:.0f} kB workbook, exit {code}, {seconds:.0f} s, "
                  f"{count} processes, peak RSS sum {rss / 2**20:,.0f} MiB, "
                  f"PSS sum {pss / 2**20:,.0f} MiB (at the peak, by process: "
                  f"{', '.join(f'{b / 2**20:,.0f}' for b in split[1:])})"
                  f"{' OVER BUDGET' if pss > BUDGET else ''}\n    {last[:600]}", flush=True)
            worst = max(worst, pss)
    print(f"largest peak (PSS, all processes of a command): {worst / 2**20:,.0f} MiB")


if __name__ == "__main__":
    main()

"""Time writing the load cases as a Nastran input file.

On the example (its generated cases) and on 10,000 cases of the same airframe (listed cases
cycling through its hook directions, aerodynamic points and parachute states): the loads
run, then ``LoadsResult.to_nastran`` (layout and vectorised card formatting, file written),
with the file's size and card count. For comparison, if pyNastran is installed, the same
number of FORCE and MOMENT cards created as pyNastran objects (``BDF.add_force``,
``add_moment``) and written by ``BDF.write_bdf`` (large field), on the example's cards
(``--full``: on the 10,000 cases' as well).

Run: ``python benchmarks/bench_nastran.py [--full]``
"""

from __future__ import annotations

import argparse
import io
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from slingloads.analyses.fe_loads import PointLoadCases
from slingloads.analyses.loads import ListedCase
from slingloads.io.study import read_study

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"


def timed(fn):
    """(result, wall time [s]), the CPU time printed beside it."""
    wall, cpu = time.perf_counter(), time.process_time()
    out = fn()
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    print(f"    ({wall:.2f} s wall, {cpu:.2f} s CPU)")
    return out, wall


def many_cases(study, count):
    """``count`` listed cases cycling through the study's hooks, aero points and chute; a
    towed case (hook TOW) flies its trim (aerodynamic point TRIM), with the parachute (the
    example has no trim without it)."""
    hooks = list(study.hook_table()["hook"]) + ["TOW"]
    aero = list(study.envelope.ids)

    def case(i):
        hook = hooks[i % len(hooks)]
        if hook == "TOW":
            return ListedCase(f"C{i:05d}", hook, "TRIM", True)
        return ListedCase(f"C{i:05d}", hook, aero[(i // 3) % len(aero)], bool(i % 2))

    return replace(study, generate=False, listed=tuple(case(i) for i in range(count)))


def write(result, folder, name):
    path = Path(folder) / name
    deck, seconds = timed(lambda: result.to_nastran(path))
    lines = path.read_text(encoding="ascii").splitlines()
    bulk = lines[next(k for k, line in enumerate(lines) if line.startswith("BEGIN BULK")) + 1:]
    # a card's name opens its first line (continuations start with a blank or '*')
    cards = sum(1 for line in bulk if line[:1].isalpha() and not line.startswith("ENDDATA"))
    print(f"  to_nastran: {seconds:.2f} s, {path.stat().st_size / 1e6:.1f} MB, {cards:,} "
          f"cards, {deck.loads.n_cases:,} subcases")
    return seconds


def pynastran_cards(result):
    """Time creating and writing the FORCE and MOMENT cards as pyNastran objects."""
    try:
        from pyNastran.bdf.bdf import BDF
    except ImportError:
        print("  pyNastran not installed: no comparison")
        return None
    loads = PointLoadCases.from_result(result)
    model = BDF(debug=None)

    def build():
        for i in range(loads.n_cases):
            for p in range(len(loads.point_ids)):
                f, m = loads.forces[i, p], loads.moments[i, p]
                if f.any():
                    model.add_force(100_011 + 10 * i, 900_001 + p, 1.0, f)
                if m.any():
                    model.add_moment(100_011 + 10 * i, 900_001 + p, 1.0, m)

    _, t_build = timed(build)
    _, t_write = timed(lambda: model.write_bdf(io.StringIO(), size=16, close=False))
    count = sum(len(v) for v in model.loads.values())
    print(f"  pyNastran objects for the {count:,} FORCE/MOMENT cards: create {t_build:.2f} s, "
          f"write {t_write:.2f} s")
    return t_build + t_write


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true",
                        help="also time pyNastran objects on the 10,000 cases")
    args = parser.parse_args()
    study = read_study(EXAMPLE, only=["loads"]).inputs.loads
    with tempfile.TemporaryDirectory() as folder:
        example, t_run = timed(study.run)
        print(f"example: {len(example.cases)} cases, loads run {t_run:.2f} s")
        write(example, folder, "example.bdf")
        pynastran_cards(example)
        big, t_run = timed(many_cases(study, 10_000).run)
        print(f"10,000 cases: loads run {t_run:.2f} s")
        t_big = write(big, folder, "big.bdf")
        if args.full:
            pynastran_cards(big)
    print(f"to_nastran for 10,000 cases: {t_big:.2f} s")


if __name__ == "__main__":
    np.seterr(all="raise")
    main()

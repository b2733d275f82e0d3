"""Benchmark of the multibody model: one run, a batch of 1,000 runs, and a solve_ivp loop.

System: GENERIC sample aircraft HC1 (blades off, cut-down fin), hinged drogue on its line,
elastic cable, frozen carrier. Every run lasts 60 s of flight, sampled every 0.1 s.

* **one run**: a 10 s lateral gust of 30 ft/s at 80 KEAS, through :func:`simulate` (trim,
  integration, metrics, histories as a DataFrame), cold (first call in the process:
  compilation or loading of the compiled kernels) and warm (median of 5).
* **batch**: 1,000 different runs through one :func:`simulate_runs` call and the table of
  their metrics (``metrics_frame``: peaks and when, RMS, damping, settling, verdict of every
  run), histories not kept (``keep_histories=False``; a run's are integrated again when
  asked for): 10 parachute areas (0.6-1.5 m^2) x 5 airspeeds (60-100 KEAS) x 4 lateral
  gusts (step, 10 s finite, 1-cosine, continuous; 30 ft/s at 5 s) x 5 cable lengths
  (60-140 ft). Timed on every processor (the target's figure), then on one thread, five
  times in turn with the loop (the ratio's figure, the median); where the one-thread time
  goes is printed.
* **baseline**: the loop a competent engineer writes by hand: one
  :func:`scipy.integrate.solve_ivp` call per run on a lean right-hand side in plain Python
  (``benchmarks/lean_multibody.py``: math-module scalars, not the product's compiled kernel),
  the integration split at the gust's jumps, and the method and tolerances that just meet the
  accuracy asked (:data:`BASELINE`, found with ``--calibrate``: the cheapest that met it on
  every sampled run and finished them all; looser ones let a trial step leave a table). It
  computes the states at the samples and the two peaks, no other metric; it is handed the
  trimmed initial states for free (its trims are not timed). It is timed on a sample of runs
  (median of 5, ``--repeat``) and scaled to 1,000 (``--full``: every run).
* **accuracy**: peak yaw change and peak lateral swing of the sampled runs, from the batch and
  from the baseline, against a tight reference (DOP853, rtol 1e-10, on the same lean
  right-hand side; split at the jumps); both must lie within 0.5 %.

Both sides are single-threaded for the ratio, which is taken on CPU time (the machine may be
shared; its load is printed). Run from the repository root (about a minute)::

    .venv/bin/python benchmarks/bench_multibody.py            # sample of 24 baseline runs
    .venv/bin/python benchmarks/bench_multibody.py --full --repeat 1   # the whole loop
    .venv/bin/python benchmarks/bench_multibody.py --calibrate   # re-choose the baseline

The figure the targets ask for is printed last: the ratio of the solve_ivp loop to the batch.
"""

from __future__ import annotations

import argparse
import itertools
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

T0 = time.perf_counter()
from slingloads.analyses.multibody import gust_response, simulate, simulate_runs  # noqa: E402
from slingloads.analyses.multibody.trim import trim  # noqa: E402
from slingloads.constants import FOOT, KNOT  # noqa: E402
from slingloads.models.multibody import (  # noqa: E402
    Cable,
    HingedParachute,
    RigidBody,
    SlingSystem,
)
from slingloads.models.multibody.rigid_body import euler_angles, rotation_matrix  # noqa: E402
from slingloads.models.parachute import Parachute, extended_cd_table  # noqa: E402
from slingloads.models.sample_aircraft import (  # noqa: E402
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
    sample_surfaces,
)

IMPORT_TIME = time.perf_counter() - T0
sys.path.insert(0, str(Path(__file__).resolve().parent))
from _timing import Timing, median_timed, sample, timed  # noqa: E402
from lean_multibody import LeftTable, lean_rhs  # noqa: E402

T_END, OUT = 60.0, 0.1
#: Step of the product: its default (None: adaptive, rtol 1e-4, atol 1e-5).
DT = None
#: Accuracy asked of peak yaw and peak lateral swing against the tight reference. [-]
ACCURACY = 0.005
#: The baseline's solve_ivp method and tolerances: the cheapest that met ACCURACY on the
#: sampled runs and finished all of them (``--calibrate``: RK23, RK45, DOP853 and LSODA at
#: atol 1e-4, 1e-5, 1e-6 and rtol from 0.1 down), atol in SI units of the states.
BASELINE = {"method": "RK45", "rtol": 3e-3, "atol": 1e-4}
#: Tolerances of the product tried by ``--calibrate`` (its defaults, timed here, are stricter
#: than ACCURACY asks: peaks within about 0.02 %; its step is held by the stability of the
#: cable's bounce mode more than by its tolerances, so looser ones save little).
PRODUCT_TRIALS = [(rtol, atol) for atol in (1e-5, 1e-4) for rtol in (1e-4, 3e-4, 1e-3, 3e-3)]
REFERENCE = {"method": "DOP853", "rtol": 1e-10, "atol": 1e-12}
#: Times the batch (on one thread) and the loop are timed, in turn.
REPEAT = 5


def system(area=1.1, speed=80 * KNOT, cable=60 * FOOT):
    ref = sample_reference("HC1")
    body = RigidBody(ref.mass, np.zeros(3), np.diag([2500.0, 7000.0, ref.yaw_inertia]))
    chute = HingedParachute(Parachute(area, extended_cd_table()))
    return SlingSystem(body, sample_hardpoints("HC1"), Cable(cable, 5e6),
                       sample_fuselage("HC1"), sample_surfaces("HC1"), chute, airspeed=speed)


def batch_pairs():
    base = system()
    gusts = [gust_response(kind, onset=5.0) for kind in ("step", "finite", "1-cosine",
                                                         "continuous")]
    pairs = []
    for area, speed, cable in itertools.product(
            np.linspace(0.6, 1.5, 10), np.linspace(60, 100, 5) * KNOT,
            np.linspace(60, 140, 5) * FOOT):
        s = base.with_(parachute=HingedParachute(Parachute(area, extended_cd_table())),
                       airspeed=speed, cable=Cable(cable, 5e6))
        pairs += [(s, g) for g in gusts]
    return pairs


def peaks(yaw, swing_lateral):
    """(peak |yaw change|, peak |lateral swing|) [rad] of sampled histories."""
    return np.nanmax(np.abs(yaw - yaw[0])), np.nanmax(np.abs(swing_lateral))


def segments(manoeuvre):
    """Integration intervals between the input's jumps and kinks. [s]"""
    inner = sorted(b for b in manoeuvre.breakpoints if 0.0 < b < T_END)
    edges = [0.0, *inner, T_END]
    return list(itertools.pairwise(edges))


def solve_loop(sys_, manoeuvre, x0, settings):
    """One run with solve_ivp on the lean right-hand side, split at the input's jumps.

    Returns (peak yaw, peak lateral swing) [rad], or None if the run left a table."""
    rhs = lean_rhs(sys_, manoeuvre)

    def f(t, y):
        return rhs(t, y.tolist())

    times = np.round(np.arange(int(round(T_END / OUT)) + 1) * OUT, 9)
    state, pieces = np.asarray(x0, float), []
    try:
        for k, (a, b) in enumerate(segments(manoeuvre)):
            keep = ((times >= a) if k == 0 else (times > a)) & (times <= b)
            wanted = times[keep]
            grid = wanted if wanted.size and wanted[-1] == b else np.append(wanted, b)
            sol = solve_ivp(f, (a, b), state, t_eval=grid, **settings)
            if sol.status != 0:
                return None
            pieces.append(sol.y[:, :wanted.size])
            state = sol.y[:, -1]
    except LeftTable:
        return None
    y = np.concatenate(pieces, axis=1)
    yaw = np.unwrap(euler_angles(y[9:13].T)[0])
    hub = sys_.hardpoints.hub - sys_.body.cg
    d = y[3:6].T + np.einsum("nij,j->ni", rotation_matrix(y[9:13].T), hub)
    return peaks(yaw, np.arctan2(d[:, 1], -d[:, 2]))


def initial_states(pairs, chosen):
    """Trimmed initial states of the chosen runs (given to the loop, untimed)."""
    out = {}
    for k in chosen:
        sys_, manoeuvre = pairs[k]
        if manoeuvre.disturbance or manoeuvre.from_hover:
            raise ValueError("the baseline handles gust runs from trim only")
        tr = trim(sys_, wind=manoeuvre.wind.steady)
        out[k] = tr.state if tr.converged else None
    return out


class _Stopwatch:
    """CPU time spent in some functions of the simulation module (the batch's profile)."""

    def __init__(self, names):
        self.module = sys.modules["slingloads.analyses.multibody.simulate"]
        self.names, self.spent, self._saved = names, dict.fromkeys(names, 0.0), {}

    def __enter__(self):
        for name in self.names:
            original = getattr(self.module, name)
            self._saved[name] = original

            def wrapper(*args, _f=original, _n=name, **kwargs):
                start = time.process_time()
                try:
                    return _f(*args, **kwargs)
                finally:
                    self.spent[_n] += time.process_time() - start

            setattr(self.module, name, wrapper)
        return self

    def __exit__(self, *exc):
        for name, original in self._saved.items():
            setattr(self.module, name, original)


def batch(pairs, workers=None):
    """The batch: every run integrated, the table of their metrics (histories not kept)."""
    sim = simulate_runs(pairs, t_end=T_END, dt=DT, output_interval=OUT, workers=workers,
                        keep_histories=False)
    return sim, sim.metrics_frame()


def relative_error(value, reference):
    return abs(value / reference - 1.0)


def calibrate(pairs, chosen, x0, references):
    """Print, per method, the loosest rtol meeting ACCURACY and its CPU time per run; then
    the cheapest of them (the baseline to put in :data:`BASELINE`)."""
    best = None
    for method, atol in itertools.product(("RK23", "RK45", "DOP853", "LSODA"),
                                          (1e-4, 1e-5, 1e-6)):
        for rtol in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 1e-6):
            settings = {"method": method, "rtol": rtol, "atol": atol}
            start, worst = time.process_time(), 0.0
            for k in chosen:
                got = solve_loop(*pairs[k], x0[k], settings)
                if references[k] is None:
                    continue
                if got is None:  # a trial step left a table: the run did not finish
                    worst = np.inf
                    break
                worst = max(worst, *(relative_error(g, r) for g, r in
                                     zip(got, references[k], strict=True)))
            per_run = (time.process_time() - start) / len(chosen)
            print(f"  {method:6s} rtol {rtol:.0e} atol {atol:.0e}: worst peak error "
                  f"{100 * worst:.3f} %, {per_run:.3f} s CPU per run")
            if worst <= ACCURACY:
                if best is None or per_run < best[0]:
                    best = (per_run, settings)
                break
    print(f"  cheapest that meets {100 * ACCURACY:.1f} %: {best[1] if best else None}")
    best = None
    for rtol, atol in PRODUCT_TRIALS:
        sim, t = timed(simulate_runs, [pairs[k] for k in chosen], t_end=T_END, dt=DT,
                       output_interval=OUT, rtol=rtol, atol=atol)
        cpu = t.cpu
        worst = batch_error(sim.runs, references, chosen)
        print(f"  product rtol {rtol:.0e} atol {atol:.0e}: worst peak error "
              f"{100 * worst:.3f} %, {cpu / len(chosen) * 1e3:.2f} ms CPU per run")
        if worst <= ACCURACY and (best is None or cpu < best[0]):
            best = (cpu, {"rtol": rtol, "atol": atol})
    print(f"  product's cheapest that meets {100 * ACCURACY:.1f} %: "
          f"{best[1] if best else None} (the CPU time of so few runs is noisy)")


def batch_error(runs, references, chosen):
    """Worst relative error of peak yaw and peak lateral swing of ``runs`` (in the order of
    ``chosen``) against the references; runs that stopped or lack a reference are skipped."""
    worst = 0.0
    for run, k in zip(runs, chosen, strict=True):
        if references[k] is None or run.stopped:
            continue
        h = run.histories()
        mine = peaks(h["yaw"], h["swing lateral"])
        worst = max(worst, *(relative_error(a, b) for a, b in zip(mine, references[k],
                                                                  strict=True)))
    return worst


def load():
    """The machine's load average over 1, 5 and 15 minutes, and its processors."""
    try:
        one, five, fifteen = os.getloadavg()
    except OSError:  # not on this platform
        return "load average unknown"
    return (f"load average {one:.1f}, {five:.1f}, {fifteen:.1f} (1, 5, 15 min) on "
            f"{os.cpu_count()} processors")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="run the whole baseline loop")
    parser.add_argument("--sample", type=int, default=24, help="baseline runs timed")
    parser.add_argument("--calibrate", action="store_true",
                        help="try solve_ivp methods and tolerances for the baseline")
    parser.add_argument("--repeat", type=int, default=REPEAT,
                        help="times the batch (one thread) and the loop are timed, in turn")
    args = parser.parse_args()
    repeat = max(1, args.repeat)
    cache = Path(__file__).resolve().parents[1] / "slingloads" / "models" / "multibody"
    cached = any((cache / "__pycache__").glob("*.nbi"))
    print(load())
    print(f"import: {IMPORT_TIME:.2f} s; compiled kernels on disk before this run: {cached}")

    gust = gust_response("finite", onset=5.0)

    def one_run():
        sim = simulate(system(), gust, t_end=T_END, dt=DT, output_interval=OUT)
        return sim.metrics_frame(), sim.runs[0].to_frame()

    _, cold = timed(one_run)
    _, warm = median_timed(one_run, repeat=5)
    print(f"one 60 s run (trim, integration, metrics, histories as a DataFrame): cold "
          f"{cold.wall:.2f} s (CPU {cold.cpu:.2f} s; compiles or loads the kernels), warm "
          f"{warm.wall:.3f} s (CPU {warm.cpu:.3f} s, median of 5; target <= 0.3 s)")

    pairs = batch_pairs()
    (sim, _), every = timed(batch, pairs)
    stopped = sum(r.stopped for r in sim.runs)
    print(f"batch of {len(pairs)} different 60 s runs and their metrics "
          f"({sim.describe_integration()}), on every processor: {every.wall:.2f} s wall, "
          f"{every.cpu:.2f} s CPU ({len(pairs) / every.wall:.0f} runs/s; {stopped} left a "
          f"table and stopped; target <= 60 s on 2 cores)")

    chosen = np.arange(len(pairs)) if args.full else sample(len(pairs), args.sample, seed=1)
    x0 = initial_states(pairs, chosen)
    checked = chosen[:min(len(chosen), args.sample)]
    start = time.perf_counter()
    references = {k: solve_loop(*pairs[k], x0[k], REFERENCE) if x0[k] is not None else None
                  for k in checked}
    print(f"tight reference ({REFERENCE['method']}, rtol {REFERENCE['rtol']:g}) on "
          f"{len(checked)} runs: {time.perf_counter() - start:.1f} s")
    if args.calibrate:
        calibrate(pairs, checked, x0, references)

    # the batch on one thread and the loop, in turn (a change of the machine's load falls
    # on both), repeat times each
    names = ("trim_many", "_check_adaptive_work", "tabulate_drive", "integrate")
    singles, laps = [], []
    for _ in range(repeat):
        fresh = batch_pairs()  # new systems: nothing cached from the previous call
        with _Stopwatch(names) as watch:
            _, one = timed(batch, fresh, workers=1)
        singles.append((one, dict(watch.spent)))
        loop_results, lap = timed(
            lambda: {k: solve_loop(*pairs[k], x0[k], BASELINE) for k in chosen})
        laps.append(lap)
    single = Timing(statistics.median(t.wall for t, _ in singles),
                    statistics.median(t.cpu for t, _ in singles))
    spent = min(singles, key=lambda item: abs(item[0].cpu - single.cpu))[1]
    print(f"the same batch on one thread, {repeat} times: {single.cpu:.2f} s CPU (median; "
          f"{', '.join(f'{t.cpu:.2f}' for t, _ in singles)}), {single.wall:.2f} s wall")
    other = single.cpu - sum(spent.values())
    print(f"  of which (CPU): {len({id(s) for s, _ in pairs})} trims "
          f"{spent['trim_many']:.3f} s, step-work check {spent['_check_adaptive_work']:.3f} s, "
          f"drive tables {spent['tabulate_drive']:.3f} s, integration with each run's measures "
          f"(the reported quantities at its 601 samples, histories derived and measured) "
          f"{spent['integrate']:.3f} s, set-up and the metrics table {other:.3f} s")

    batch_worst = loop_worst = 0.0
    compared = 0
    unfinished = sum(loop_results[k] is None and references[k] is not None for k in checked)
    for k in checked:
        ref, got = references[k], loop_results[k]
        if ref is None or got is None or sim.runs[k].stopped:
            continue
        compared += 1
        h = sim.runs[k].histories()  # integrated again: the batch kept only the metrics
        mine = peaks(h["yaw"], h["swing lateral"])
        batch_worst = max(batch_worst, *(relative_error(a, b) for a, b in zip(mine, ref,
                                                                              strict=True)))
        loop_worst = max(loop_worst, *(relative_error(a, b) for a, b in zip(got, ref,
                                                                            strict=True)))
    n = len(chosen)
    loop = Timing(statistics.median(t.wall for t in laps), statistics.median(t.cpu for t in laps))
    scaled = loop.scaled(len(pairs) / n)
    print(f"solve_ivp loop ({BASELINE['method']}, rtol {BASELINE['rtol']:g}, atol "
          f"{BASELINE['atol']:g}, lean plain-Python right-hand side) on {n} runs, {repeat} "
          f"times: {loop.cpu:.2f} s CPU (median; "
          f"{', '.join(f'{t.cpu:.2f}' for t in laps)}; {1e3 * loop.cpu / n:.1f} ms a run), "
          f"{loop.wall:.2f} s wall; scaled to {len(pairs)} runs: {scaled.cpu:.0f} s CPU, "
          f"{scaled.wall:.0f} s wall")
    print(f"peak yaw change and peak lateral swing against the tight reference ({compared} "
          f"runs that stayed inside their tables): batch {100 * batch_worst:.3f} %, solve_ivp "
          f"loop {100 * loop_worst:.3f} % (each must be <= {100 * ACCURACY:.1f} %); runs the "
          f"loop could not finish (a trial step left a table): {unfinished}")
    print(load())
    turns = sorted(lap.cpu * len(pairs) / n / one.cpu
                   for lap, (one, _) in zip(laps, singles, strict=True))
    untrimmed = single.cpu - spent["trim_many"] - spent["_check_adaptive_work"]
    print(f"ratio of the solve_ivp loop to the batch (metrics of every run included), both "
          f"within {100 * ACCURACY:.1f} % of the reference, single-threaded: "
          f"{scaled.cpu / single.cpu:.0f}x on CPU time (medians of {repeat} timed in turn; "
          f"{turns[0]:.0f}-{turns[-1]:.0f}x turn by turn; {scaled.wall / single.wall:.0f}x on "
          f"wall time; {scaled.cpu / untrimmed:.0f}x without the batch's trims and step-work "
          f"check, which the loop is given; target >= 30)")


if __name__ == "__main__":
    main()

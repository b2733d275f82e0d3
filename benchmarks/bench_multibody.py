"""Benchmark of the multibody model: one run, a batch of 1,000 runs, and a solve_ivp loop.

System: GENERIC sample aircraft HC1 (blades off, cut-down fin), hinged drogue on its line,
elastic cable, frozen carrier. Every run lasts 60 s of flight (RK4, dt = 0.01 s, histories
every 0.1 s) and includes its trim, linear model (step check), integration, histories.

* one run: a 10 s lateral gust of 30 ft/s at 80 KEAS.
* batch: 1,000 different runs integrated together (compiled RK4, parallel over runs):
  10 parachute areas (0.6-1.5 m^2) x 5 airspeeds (60-100 KEAS) x 4 lateral gusts (step,
  10 s finite, 1-cosine, continuous; 30 ft/s at 5 s) x 5 cable lengths (60-140 ft).
* baseline: the same runs, one :func:`scipy.integrate.solve_ivp` (RK45, rtol 1e-6,
  atol 1e-8, max_step 0.1 s) call per run in a plain Python loop, with a lean right-hand side
  (the same compiled equations for one run, the gust evaluated at t). By default it is timed
  on a sample of runs and scaled to 1,000; ``--full`` runs all 1,000. The peak yaw and peak
  lateral swing of the sampled runs are compared with the batch's (must agree within 0.5 %).

The first call pays the JIT compilation, unless the on-disk cache of a previous run is there;
both cold and warm times are printed. Run from the repository root::

    .venv/bin/python benchmarks/bench_multibody.py            # about 2 minutes
    .venv/bin/python benchmarks/bench_multibody.py --full     # the whole baseline loop
"""

from __future__ import annotations

import argparse
import itertools
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

T0 = time.perf_counter()
from slingloads.analyses.multibody import gust_response, simulate, simulate_runs  # noqa: E402
from slingloads.analyses.multibody.simulate import _disturbed  # noqa: E402
from slingloads.analyses.multibody.trim import trim  # noqa: E402
from slingloads.constants import FOOT, KNOT  # noqa: E402
from slingloads.models.multibody import (  # noqa: E402
    Cable,
    HingedParachute,
    RigidBody,
    SlingSystem,
)
from slingloads.models.multibody.equations import N_INFO, N_STATES, evaluate  # noqa: E402
from slingloads.models.multibody.rigid_body import euler_angles, rotation_matrix  # noqa: E402
from slingloads.models.parachute import Parachute, extended_cd_table  # noqa: E402
from slingloads.models.sample_aircraft import (  # noqa: E402
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
    sample_surfaces,
)

IMPORT_TIME = time.perf_counter() - T0
T_END, DT, OUT = 60.0, 0.01, 0.1


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
    return np.nanmax(np.abs(yaw - yaw[0])), np.nanmax(np.abs(swing_lateral))


def solve_one(sys_, manoeuvre):
    """One run by solve_ivp with a lean right-hand side; returns (peak yaw, peak swing)."""
    tr = trim(sys_, wind=manoeuvre.wind.steady)
    x0 = _disturbed(tr, manoeuvre.disturbance)
    params, tables = sys_.parameters(), sys_.tables()
    drive = tr.drive.copy()
    steady = drive[0:3].copy()
    gust, direction = manoeuvre.wind.gust, manoeuvre.wind._direction
    dx, info = np.zeros(N_STATES), np.zeros(N_INFO)

    def rhs(t, x):
        drive[0:3] = steady + float(gust.velocity(t)) * direction
        evaluate(x, params, drive, *tables, dx, info, False)
        return dx.copy()

    times = np.arange(int(round(T_END / OUT)) + 1) * OUT
    sol = solve_ivp(rhs, (0.0, T_END), x0, t_eval=times, rtol=1e-6, atol=1e-8, max_step=OUT)
    yaw = np.unwrap(euler_angles(sol.y[9:13].T)[0])
    hub = sys_.hardpoints.hub - sys_.body.cg
    d = sol.y[3:6].T + np.einsum("nij,j->ni", rotation_matrix(sol.y[9:13].T), hub)
    return peaks(yaw, np.arctan2(d[:, 1], -d[:, 2]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="run the whole baseline loop")
    parser.add_argument("--sample", type=int, default=20, help="baseline runs timed")
    args = parser.parse_args()
    cache = Path(__file__).resolve().parents[1] / "slingloads" / "models" / "multibody"
    cached = any((cache / "__pycache__").glob("*.nbi"))
    print(f"import: {IMPORT_TIME:.2f} s; compiled cache present before this run: {cached}")

    gust = gust_response("finite", onset=5.0)
    start = time.perf_counter()
    simulate(system(), gust, t_end=T_END, dt=DT, output_interval=OUT)
    cold = time.perf_counter() - start
    start = time.perf_counter()
    simulate(system(), gust, t_end=T_END, dt=DT, output_interval=OUT)
    warm = time.perf_counter() - start
    print(f"one 60 s run: cold (JIT compile or cache load) {cold:.2f} s, warm {warm:.3f} s "
          f"(target <= 0.3 s)")

    pairs = batch_pairs()
    start = time.perf_counter()
    sim = simulate_runs(pairs, t_end=T_END, dt=DT, output_interval=OUT)
    batch = time.perf_counter() - start
    stopped = sum(r.stopped for r in sim.runs)
    print(f"batch of {len(pairs)} different 60 s runs: {batch:.1f} s "
          f"({len(pairs) / batch:.0f} runs/s; {stopped} stopped on a table limit; "
          f"target <= 60 s)")

    rng = np.random.default_rng(1)
    n = len(pairs) if args.full else min(args.sample, len(pairs))
    chosen = np.sort(rng.choice(len(pairs), n, replace=False))
    start = time.perf_counter()
    reference = [solve_one(*pairs[k]) for k in chosen]
    loop = time.perf_counter() - start
    worst, compared = 0.0, 0
    for k, (yaw_ref, swing_ref) in zip(chosen, reference, strict=True):
        if sim.runs[k].stopped:  # left a table: the batch stops it, solve_ivp does not
            continue
        compared += 1
        h = sim.runs[k].histories()
        yaw, swing = peaks(h["yaw"], h["swing lateral"])
        worst = max(worst, abs(yaw / yaw_ref - 1), abs(swing / swing_ref - 1))
    scaled = loop * len(pairs) / n
    print(f"solve_ivp loop: {loop:.1f} s for {n} runs ({loop / n:.3f} s per run), "
          f"{scaled:.0f} s scaled to {len(pairs)} runs")
    print(f"peak yaw and lateral swing, batch against solve_ivp ({compared} runs that stayed "
          f"inside their tables): largest difference {100 * worst:.3f} % (must be <= 0.5 %)")
    print(f"speed-up of the batch over the solve_ivp loop: {scaled / batch:.0f}x "
          f"(target >= 30)")


if __name__ == "__main__":
    main()

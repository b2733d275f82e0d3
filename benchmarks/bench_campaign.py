"""Benchmark of the campaign: the paper's matrix (section 4.4), about 4,000 runs of 60 s.

System: GENERIC sample aircraft HC1 (blades off, cut-down fin), hinged drogue on a 10 m line,
elastic cable (EA 5 MN). Matrix (3,888 runs): parachute area 1.0 to 2.0 x the neutral area in
steps of 0.2 (6) x 40, 60, 80, 100 KEAS (4) x mass 2900, 2600, 2300 kg (3) x ISA SL, 5,000 and
10,000 ft (3) x cables of 60, 80 and 100 ft (3; the paper's 18 ft cannot clear this sample's
10 m line and 6.4 m fin arm, so the system refuses it) x carrier frozen and free (2) x free
response and +-30 ft/s lateral gusts (3). Every run lasts 60 s (RK4, dt = 0.01 s, histories
every 0.1 s) and includes its trim, linear model, integration, histories and metrics; the
campaign adds the selection, sensitivity tables, stability map, the 1.0 x neutral-area checks
and the transport without parachute (HC1 and HC2, 5 wind ramps). Histories are not kept
(metrics only), as a user would not hold 4,000 runs of histories in memory.

By default a random sample of the matrix (``--sample``, 1,500 runs, as listed rows) is run and
the wall time scaled to the whole matrix; ``--full`` runs all of it. Target: the full matrix in
<= 5 min on a 2-core machine. Run from the repository root::

    .venv/bin/python benchmarks/bench_campaign.py                # about 2 minutes
    .venv/bin/python benchmarks/bench_campaign.py --full         # the whole matrix
    .venv/bin/python benchmarks/bench_campaign.py --workers 1    # in this process only
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from slingloads.analyses.campaign import (
    Campaign,
    CampaignSetup,
    Factors,
    MassCase,
    MemoryStore,
    NoParachuteStudy,
    make_executor,
    run_campaign,
    sample_full_tail_system,
)
from slingloads.constants import FOOT, KNOT
from slingloads.models.multibody import Cable, HingedParachute, SlingSystem
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_body,
    sample_fuselage,
    sample_hardpoints,
    sample_surfaces,
)

FACTORS = Factors(
    area_factors=(1.0, 1.2, 1.4, 1.6, 1.8, 2.0),
    airspeeds=tuple(v * KNOT for v in (40.0, 60.0, 80.0, 100.0)),
    masses=(MassCase("maximum", 2900.0), MassCase("medium", 2600.0),
            MassCase("minimum", 2300.0)),
    density_altitudes=(0.0, 5000 * FOOT, 10000 * FOOT),
    cable_lengths=tuple(v * FOOT for v in (60.0, 80.0, 100.0)),
    carriers=("frozen", "free"),
    manoeuvres=("free response", "gust +30 ft/s", "gust -30 ft/s"),
)


def setup():
    system = SlingSystem(sample_body("HC1"), sample_hardpoints("HC1"), Cable(60 * FOOT, 5e6),
                         sample_fuselage("HC1"), sample_surfaces("HC1"),
                         HingedParachute(Parachute(1.0, extended_cd_table())))
    return CampaignSetup(system)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="run the whole matrix")
    parser.add_argument("--sample", type=int, default=1500, help="runs of the default sample")
    parser.add_argument("--workers", type=int, default=None,
                        help="local worker processes (default: automatic)")
    args = parser.parse_args()
    no_chute = NoParachuteStudy({h: sample_full_tail_system(h) for h in ("HC1", "HC2")})
    full = Campaign(setup(), FACTORS, no_parachute=no_chute)
    total = full.size
    campaign = full
    if not args.full:
        rng = np.random.default_rng(1)
        frame = full.matrix.frame
        rows = frame.iloc[np.sort(rng.choice(total, min(args.sample, total), replace=False))]
        campaign = Campaign(setup(), FACTORS, rows.drop(columns=["run", "area [m^2]",
                                                                  "mass [kg]"]),
                            no_parachute=no_chute)
    print(f"paper's matrix: {total} runs of 60 s; running {campaign.size} "
          f"({'all' if args.full else 'a random sample'}) plus "
          f"{len(no_chute.jobs())} wind ramps without parachute")
    executor = make_executor(workers=args.workers, runs=campaign.size)
    marks = {}

    def progress(done, total_runs):
        marks.setdefault("first", time.perf_counter())
        marks["last"] = time.perf_counter()

    start = time.perf_counter()
    result = run_campaign(campaign, executor=executor, store=MemoryStore(keep_histories=False),
                          progress=progress)
    wall = time.perf_counter() - start
    runs_time = marks["last"] - start
    fixed = wall - runs_time
    m = result.metrics
    sel = result.selection
    print(f"executor: {result.execution.executor}; {result.execution.batches} batches")
    print(f"runs stable: {int(m['stable'].sum())}, stopped on a table limit: "
          f"{int((m['stopped'].fillna('') != '').sum())}, no trim: "
          f"{int((~m['trim converged'].astype(bool)).sum())}")
    print(f"smallest stable area factor {sel.smallest_stable:.3g}, recommended "
          f"{sel.recommended:.3g} (neutral area {result.neutral.area:.4g} m^2)")
    runs = campaign.size + len(no_chute.jobs())
    rate = runs / runs_time
    print(f"runs (start of workers included): {runs_time:.1f} s for {runs} runs, "
          f"{rate:.1f} runs/s; campaign-level work (selection, stability map, 1.0 x neutral "
          f"checks): {fixed:.1f} s")
    projected = wall if args.full else fixed + (total + len(no_chute.jobs())) / rate
    print(f"wall time {wall:.1f} s; full matrix ({total} runs): {projected:.0f} s "
          f"{'measured' if args.full else 'projected'} (target <= 300 s)")


if __name__ == "__main__":
    main()

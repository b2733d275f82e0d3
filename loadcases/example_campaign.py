"""Campaign part of the example workbook (merged by ``loadcases/build_example.py``).

Defines ``TABLES`` (none: the example's one mass case is the mass items' total), ``PARAMETERS``
(the Study rows of the campaign) and ``NOTES`` (README lines). The example's campaign is a
REDUCED one, and OPT-IN: ``run campaign`` is "no", so that ``slingloads run`` on the example
stays a few seconds (the campaign's runs, stability map and seven plots add several seconds
even with every run cached); ``slingloads campaign`` runs it whatever the switch says, and
``run campaign = yes`` chains it before the loads. Three parachute areas
(1.0, 2.2 and 3.0 x the neutral area about the suspension axis; 2.2 x is the parachute
sizing's proposal, which the campaign would add when the sizing runs), 60 and 80 KEAS, sea
level, the 60 ft cable, the frozen carrier, the free response and the +30 ft/s gust (12 runs
of 60 s); the transport without
parachute of the GENERIC samples HC1 and HC2 under ramps to 20, 30 and 40 kt (the paper's
figures 16 to 18). The paper's matrix (about 4,000 runs) is ``benchmarks/bench_campaign.py``.
"""

from __future__ import annotations

TABLES = {}

PARAMETERS = {
    "run campaign": ("no", ""),
    "campaign area factors": ("1.0, 2.2, 3.0", ""),
    "campaign airspeeds EAS": ("60, 80", "kt"),
    "campaign density altitudes": ("0", "ft"),
    "campaign cable lengths": ("60", "ft"),
    "campaign carriers": ("frozen", ""),
    "campaign manoeuvres": ("free response, gust +30 ft/s", ""),
    "campaign run length": (60, "s"),
    "campaign stability map areas": (5, ""),
    "campaign stability map airspeeds": (3, ""),
    "campaign no-parachute helicopters": ("HC1, HC2", ""),
    "campaign no-parachute ramps": ("20, 30, 40", "kt"),
    "campaign no-parachute gust ramps": ("20, 30", "kt"),
    "campaign no-parachute gust": (10, "ft/s"),
    "campaign loads margin": (1.25, ""),
}

NOTES = [
    "Campaign (Study rows 'campaign ...'): a REDUCED matrix of the paper's section 4.4 (3 "
    "parachute areas, 1.0, 2.2 (the parachute sizing's proposal) and 3.0 x neutral, x 2 "
    "airspeeds x 2 manoeuvres, 60 s runs) on the example's own airframe "
    "and tables, with the HC1 and HC2 GENERIC samples flown without parachute under wind "
    "ramps to 20, 30 and 40 kt, the 20 and 30 kt ramps flown again with a 10 ft/s lateral "
    "gust 10 s after the ramp ends (the paper's limit; a stable case shows its damping). "
    "OPT-IN: 'run campaign' is no, so that 'slingloads run' stays "
    "quick; run it with 'slingloads campaign', or set 'run campaign' to yes to chain it "
    "before the loads. Finished runs are cached outside the output folder "
    "(docs/campaign.md), so a second run reuses them.",
]

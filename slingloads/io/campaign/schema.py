"""Study-sheet parameters and sheets of the campaign (types in ``io.common.schema``).

The campaign also reads the airframe (mass items, hardpoints, ``FuselageAero``, ``FinAero``,
``ParachuteCD``, 'fuselage reference area', 'fin area', 'fin efficiency', 'parachute wake
ratio', 'parachute line length'), from which it builds the towed system. Method:
``docs/campaign.md``.

List parameters (``campaign area factors``, ``campaign airspeeds``...) hold comma-separated
values; a number list takes its unit from the row's unit column (any unit of the kind).
"""

from __future__ import annotations

from slingloads.io.common.schema import (
    CABLE_EA,
    CABLE_LENGTH,
    CANOPY_MASS,
    CARRIER_MASS,
    DRAG_AREA,
    FLAG,
    INTEGER,
    ISA_ALTITUDE,
    OUTPUT_INTERVAL,
    RUN_LENGTH,
    TEXT,
    Bounds,
    Column,
    Parameter,
    Section,
    TableSheet,
)
from slingloads.limits import (
    MAX_CAMPAIGN_RUNS,
    MAX_LIST_ITEMS,
    MAX_SCHEDULER_TIMEOUT,
    MAX_WORKERS,
)

_S = "campaign"

#: List parameters and the quantity kind of their numbers (TEXT: names).
LISTS = {
    "campaign area factors": "dimensionless",
    "campaign airspeeds EAS": "speed",
    "campaign density altitudes": "length",
    "campaign cable lengths": "length",
    "campaign carriers": TEXT,
    "campaign manoeuvres": TEXT,
    "campaign no-parachute ramps": "speed",
    "campaign no-parachute helicopters": TEXT,
    "campaign no-parachute gust ramps": "speed",
}
#: Allowed range of each number of a list parameter (in the bounds' unit), checked at its
#: cell with the value as written; a list holds at most MAX_LIST_ITEMS values.
LIST_BOUNDS = {
    "campaign area factors": Bounds(0.01, 100),
    "campaign airspeeds EAS": Bounds(0, 200, lo_open=True, unit="kt"),
    "campaign density altitudes": ISA_ALTITUDE,
    "campaign cable lengths": CABLE_LENGTH,
    "campaign no-parachute ramps": Bounds(0, 200, lo_open=True, unit="kt"),
    "campaign no-parachute gust ramps": Bounds(0, 200, lo_open=True, unit="kt"),
}
#: Valid values of 'campaign matrix'.
MATRIX_KINDS = ("full factorial", "listed rows")
#: Valid values of 'campaign loads hook angle'.
HOOK_ANGLE_SOURCES = ("CS-29.865", "dynamics")
#: GENERIC sample helicopters the study without parachute may fly.
SAMPLE_HELICOPTERS = ("HC1", "HC2")

PARAMETERS = (
    Parameter("campaign matrix", TEXT, "", "full factorial",
              "'full factorial' of the list rows below (and the CampaignMasses sheet), or "
              "'listed rows' (the CampaignRuns sheet).", _S),
    Parameter("campaign area factors", TEXT, "", "1.0, 1.2, 1.4, 1.6, 1.8, 2.0",
              "Parachute areas over the neutral static area, comma-separated, each > 0 "
              "(paper: 1.0 to 2.0).", _S),
    Parameter("campaign airspeeds EAS", TEXT, "kt", "40, 60, 80, 100",
              "Equivalent airspeeds, comma-separated, each > 0, in the unit of the unit column "
              "(paper: up to 100 KEAS).", _S),
    Parameter("campaign density altitudes", TEXT, "ft", "0, 5000, 10000",
              "ISA density altitudes, comma-separated (paper: SL, 5000, 10000 ft).", _S),
    Parameter("campaign cable lengths", TEXT, "ft", "60, 100",
              "Carrier-to-hub cable lengths, comma-separated, each > 0 (paper: 18, 60, 100 ft; "
              "each must clear the parachute line and fin arm).", _S),
    Parameter("campaign carriers", TEXT, "", "frozen",
              "Carrier models, comma-separated: 'frozen' (the hook follows its path), 'free' "
              "(point-mass carrier loaded by the cable, paper figure 13).", _S),
    Parameter("campaign manoeuvres", TEXT, "", "free response, gust +30 ft/s, gust -30 ft/s",
              "Manoeuvres, comma-separated: 'free response', 'gust +30 ft/s', 'gust -30 ft/s', "
              "'acceleration' (from hover to the run's airspeed).", _S),
    Parameter("campaign run length", "time", "s", 60.0,
              "Simulated time of every run, a whole multiple of the time step (paper: 60 s).",
              _S, RUN_LENGTH),
    Parameter("campaign time step", "time", "s", 0.0,
              "0 = the multibody model's adaptive step (Dormand-Prince 5(4)); > 0: that fixed "
              "step, checked against the fastest linear mode.", _S, Bounds(0, 1, unit="s")),
    Parameter("campaign output interval", "time", "s", 0.1,
              "Sampling interval of the stored histories (a whole multiple of a fixed step).",
              _S, OUTPUT_INTERVAL),
    Parameter("campaign cable EA", "force", "N", 5.0e6,
              "Axial stiffness EA of the carrier cable, > 0 (default: a GENERIC synthetic "
              "long line).", _S, CABLE_EA),
    Parameter("campaign cable damping ratio", "dimensionless", "", 0.05,
              "Structural damping of the cable as the bounce mode's damping ratio, >= 0.",
              _S, Bounds(0, 10)),
    Parameter("campaign canopy mass", "mass", "kg", 3.0,
              "Mass of the canopy and line of the hinged parachute, > 0.",
              _S, CANOPY_MASS),
    Parameter("campaign carrier mass", "mass", "kg", 15000.0,
              "Mass of the free carrier, > 0 (GENERIC heavy-lift class).", _S, CARRIER_MASS),
    Parameter("campaign carrier drag area", "area", "m^2", 4.0,
              "Flat-plate drag area of the free carrier, >= 0 (CH-47 class: 43 ft^2).",
              _S, DRAG_AREA),
    Parameter("campaign minimum yaw damping", "dimensionless", "", 0.05,
              "Damping criterion of the recommended area: least damping ratio of the yaw modes "
              "in every run, in [0, 1).", _S, Bounds(0, 1, hi_open=True)),
    Parameter("campaign maximum yaw half time", "time", "s", 20.0,
              "Damping criterion of the recommended area: longest time to half amplitude of "
              "the yaw modes in every run, > 0.", _S, Bounds(0, 3600, lo_open=True, unit="s")),
    Parameter("campaign chosen area factor", "dimensionless", "", 0.0,
              "Area factor handed to the loads, one of the matrix's; 0 = the recommended "
              "(else the smallest stable).", _S, Bounds(0, 100)),
    Parameter("campaign loads margin", "dimensionless", "", 1.25,
              "Factor >= 1 on the extremes the dynamics reach before they become loads cases "
              "(angles, line tension, tension factor).", _S, Bounds(1, 10)),
    Parameter("campaign loads from dynamics", FLAG, "", "yes",
              "With 'run loads': add the loads cases of the dynamics (alpha-beta envelope, "
              "parachute line directions and drag) and compare with the hand-entered ones.",
              _S),
    Parameter("campaign loads hook angle", TEXT, "", "CS-29.865",
              "Hook cone of the loads: 'CS-29.865' keeps the Study's angle (30 deg unless "
              "justified), raised if the dynamics exceed it; 'dynamics' uses the hub-load "
              "angles the dynamics reach x margin, the justified smaller angle.", _S),
    Parameter("campaign stability map areas", INTEGER, "", 11,
              "Area factors of the stability map, evenly spread from half the matrix's "
              "smallest to its largest (the minimum stable area may lie below the matrix), "
              ">= 2.", _S, Bounds(2, 200)),
    Parameter("campaign stability map airspeeds", INTEGER, "", 7,
              "Airspeeds of the stability map, evenly spread over the matrix's, >= 1.",
              _S, Bounds(1, 200)),
    Parameter("campaign no-parachute helicopters", TEXT, "", "HC1, HC2",
              "Helicopters flown without parachute in their full-tail configuration: GENERIC "
              "samples 'HC1', 'HC2' (comma-separated), or 'none'.", _S),
    Parameter("campaign no-parachute ramps", TEXT, "kt", "20, 30, 40, 60, 80",
              "Frontal wind-ramp targets, comma-separated, each > 0 (paper: 20 to 80 kt).",
              _S),
    Parameter("campaign no-parachute gust ramps", TEXT, "kt", "20, 30",
              "Ramp targets flown again with a lateral gust 10 s after the ramp ends, so that "
              "a stable case shows its damping: comma-separated, each > 0, or 'none' "
              "(default 20, 30 kt, the paper's limit).", _S),
    Parameter("campaign no-parachute gust", "speed", "ft/s", 10.0,
              "Lateral gust of the ramps with a gust, 10 s long, > 0 (10 ft/s: at 20 kt a "
              "30 ft/s gust alone turns the relative wind by 41 deg).", _S,
              Bounds(0, 100, lo_open=True, unit="ft/s")),
    Parameter("campaign scheduler", TEXT, "", "",
              "Address of a dask.distributed scheduler to run the batches on (e.g. "
              "tcp://10.0.0.5:8786); empty = local worker processes. The command line's "
              "--scheduler overrides it.", _S),
    Parameter("campaign workers", INTEGER, "", 0,
              "Local worker processes; 0 = automatic (one per core, or this process for a "
              "small campaign); at most 2 start (the cores, the memory and a command's "
              "1 GB budget cap them). The command line's --workers overrides it.",
              _S, Bounds(0, MAX_WORKERS)),
    Parameter("campaign scheduler time-out", "time", "s", 10.0,
              "Time the scheduler has to answer before the campaign stops, > 0.",
              _S, Bounds(0, MAX_SCHEDULER_TIMEOUT, lo_open=True, unit="s")),
)

SHEETS = (
    TableSheet("CampaignMasses", (
        Column("mass case", TEXT, help="Name of the mass case, e.g. maximum, medium, minimum."),
        Column("mass", "mass", "kg", help="Mass of the carried helicopter, > 0 (inertia "
                                          "scaled with it, CG kept). Typical: 2,000 to "
                                          "3,000 kg for a light twin.",
               bounds=Bounds(0, 1e5, lo_open=True, unit="kg")),
    ), help="Optional: mass cases of the campaign (default: one, 'nominal', the mass items' "
       "total).", max_rows=MAX_LIST_ITEMS, ids=("mass case",)),
    TableSheet("CampaignRuns", (
        Column("area factor", "dimensionless", help="Parachute area over the neutral area.",
               bounds=LIST_BOUNDS["campaign area factors"]),
        Column("airspeed EAS", "speed", "kt",
               help="Equivalent airspeed of the run, > 0. Typical: 40 to 100 kt.",
               bounds=LIST_BOUNDS["campaign airspeeds EAS"]),
        Column("mass case", TEXT, required=False, default="",
               help="A CampaignMasses name (may be empty with a single mass case)."),
        Column("density altitude", "length", "ft",
               help="ISA density altitude of the run. Typical: 0, 5,000 or 10,000 ft.",
               bounds=ISA_ALTITUDE),
        Column("cable length", "length", "ft",
               help="Unstretched carrier-to-hub cable length, > 0. Typical: 18, 60 or 100 ft.",
               bounds=CABLE_LENGTH),
        Column("carrier", TEXT, help="frozen | free"),
        Column("manoeuvre", TEXT, help="free response | gust +30 ft/s | gust -30 ft/s | "
                                       "acceleration"),
    ), help="Optional, with 'campaign matrix' = listed rows: the runs, one per row.",
       max_rows=MAX_CAMPAIGN_RUNS),
)

SECTION = Section("campaign", parameters=PARAMETERS, sheets=SHEETS)

#: The Study parameter behind each setting the analysis may refuse while computing (none).
COMPUTE_FIELDS = {}

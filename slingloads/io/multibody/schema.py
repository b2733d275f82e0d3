"""Study-sheet parameters and sheets of the multibody model (types in ``io.common.schema``).

The model also reads the airframe's sheets and parameters (:mod:`slingloads.io.airframe.schema`):
``MassItems`` (mass, CG and inertia tensor of the carried helicopter), ``Hardpoints`` (``hub``,
``chute``, ``fin_cp``, ``aero_reference`` and, for the full tail, ``htail_cp``), the mast axis,
``FuselageAero``, ``FinAero`` with 'fin area' and 'fin efficiency', ``ParachuteCD``, and the
Study rows 'parachute area', 'parachute wake ratio' and 'parachute line length'. Method, axes
and signs: ``docs/multibody.md``.
"""

from __future__ import annotations

from slingloads.io.airframe.schema import SURFACE_COEFFICIENT
from slingloads.io.common.schema import (
    ABSOLUTE_TOLERANCE,
    AIRSPEED,
    CABLE_EA,
    CABLE_LENGTH,
    CANOPY_MASS,
    CARRIER_MASS,
    DRAG_AREA,
    ISA_ALTITUDE,
    OUTPUT_INTERVAL,
    RELATIVE_TOLERANCE,
    RUN_LENGTH,
    TEXT,
    Bounds,
    Column,
    Parameter,
    Section,
    TableSheet,
)
from slingloads.limits import MAX_AERO_ROWS, MAX_MULTIBODY_RUNS

#: Valid values of 'multibody configuration'.
CONFIGURATIONS = ("with parachute", "without parachute")
#: Valid values of 'multibody tail'.
TAILS = ("cut-down fin", "full tail")
#: Valid values of 'multibody parachute model'.
PARACHUTE_MODELS = ("hinged", "quasi-static")
#: Valid values of 'multibody canopy CD'.
CANOPY_TABLES = ("extended", "sheet")
#: Valid values of 'multibody carrier'.
CARRIERS = ("frozen", "free")
#: Manoeuvre kinds of the MultibodyManoeuvres sheet.
MANOEUVRE_KINDS = ("free response", "gust", "forward acceleration", "wind ramp",
                   "hook trajectory")
#: Gust directions of the MultibodyManoeuvres sheet.
DIRECTIONS = ("lateral", "longitudinal", "vertical")
#: Initial-disturbance columns of the MultibodyManoeuvres sheet, by disturbance name.
DISTURBANCE_COLUMNS = {"yaw": "yaw", "pitch": "pitch", "roll": "roll",
                       "yaw rate": "yaw_rate", "lateral offset": "lateral",
                       "longitudinal offset": "longitudinal", "vertical offset": "vertical"}

_S = "multibody"
#: Bounds of an initial attitude disturbance.
ANGLE = Bounds(-180, 180, unit="deg")
#: Bounds of an initial displacement of the CG. [m]
OFFSET = Bounds(-100, 100, unit="m")

PARAMETERS = (
    Parameter("multibody airspeed EAS", "speed", "kt", 80.0,
              "Equivalent airspeed of the towed flight, >= 0: the trim, the linear modes, "
              "the free responses and the gusts (forward accelerations and wind ramps start "
              "from hover), at most 200 kt (above the never-exceed speed of the heavy-lift "
              "helicopters that carry slung loads).", _S, AIRSPEED),
    Parameter("multibody density altitude", "length", "ft", 0.0,
              "ISA density altitude (paper: sea level, 5000 and 10000 ft).", _S, ISA_ALTITUDE),
    Parameter("multibody configuration", TEXT, "", "with parachute",
              f"{' or '.join(repr(c) for c in CONFIGURATIONS)}: the drogue on its line from "
              "the Hardpoints row of kind 'chute' (paper section 4), or none (section 5).", _S),
    Parameter("multibody tail", TEXT, "", "cut-down fin",
              "'cut-down fin': FinAero x 'fin efficiency' (the transport configuration, "
              "paper 3.1); 'full tail': the intact fin (efficiency 1) and the horizontal tail "
              "of the HTailAero sheet at the Hardpoints row of kind 'htail_cp' (paper 5.1).",
              _S),
    Parameter("multibody horizontal tail area", "area", "m^2", 0.0,
              "Reference area of the HTailAero table, > 0 with 'multibody tail' = full tail.",
              _S, Bounds(0, 100, unit="m^2")),
    Parameter("multibody parachute model", TEXT, "", "hinged",
              "'hinged': the canopy as a point mass on its line, free on two hinge angles "
              "(paper 4.3); 'quasi-static': the Apollo legacy drogue, its drag at the "
              "attachment along the attachment's relative wind.", _S),
    Parameter("multibody parachute area", "area", "m^2", 0.0,
              "Flat-plate area of the canopy, > 0; 0 = the Study's 'parachute area'.",
              _S, Bounds(0, 1000, unit="m^2")),
    Parameter("multibody canopy mass", "mass", "kg", 3.0,
              "Mass of the canopy and its line (hinged model), > 0.",
              _S, CANOPY_MASS),
    Parameter("multibody canopy CD", TEXT, "", "extended",
              "'extended': GENERIC canopy CD over 0-180 deg (the paper's 0.95 within 8 deg, "
              "falling to 0.4 broadside: an assumption), so that a canopy hanging below its "
              "attachment in hover stays inside its table; 'sheet': the ParachuteCD sheet (or "
              "the paper's +-8 deg table without it): a run whose canopy meets the flow at a "
              "larger angle stops there.", _S),
    Parameter("multibody cable length", "length", "ft", 60.0,
              "Unstretched carrier cable, hook to hub, > 0 (paper: 18, 60, 100 ft). It must lie "
              "outside the distances from the hub that the parachute line and canopy reach, "
              "streaming aft of the attachment or hanging below it (else the canopy could "
              "reach the carrier: an error), and should be at least (1 + margin) x the line "
              "(else a warning in the report).", _S, CABLE_LENGTH),
    Parameter("multibody cable EA", "force", "N", 5.0e6,
              "Axial stiffness EA of the cable, > 0.", _S, CABLE_EA),
    Parameter("multibody cable damping ratio", "dimensionless", "", 0.05,
              "Structural damping of the cable as the damping ratio of the load's bounce on "
              "it, >= 0.", _S, Bounds(0, 10)),
    Parameter("multibody cable margin", "dimensionless", "", 0.20,
              "Required excess of the carrier cable over the parachute line (paper: 20 %), "
              ">= 0.", _S, Bounds(0, 10)),
    Parameter("multibody carrier", TEXT, "", "frozen",
              "'frozen': the hook follows the commanded trajectory, unaffected by the cable; "
              "'free': a point mass with drag under a speed-hold thrust law "
              "(docs/multibody.md).", _S),
    Parameter("multibody carrier mass", "mass", "kg", 10000.0,
              "Mass of the free carrier, > 0 (GENERIC default).", _S, CARRIER_MASS),
    Parameter("multibody carrier drag area", "area", "m^2", 2.0,
              "Flat-plate drag area of the free carrier, >= 0 (GENERIC default).", _S, DRAG_AREA),
    Parameter("multibody carrier speed gain", "frequency", "1/s", 0.5,
              "Gain of the free carrier's speed hold (1 / its time constant), > 0.",
              _S, Bounds(0, 100, lo_open=True, unit="1/s")),
    Parameter("multibody simulation time", "time", "s", 60.0,
              "Length of every run, > 0.", _S, RUN_LENGTH),
    Parameter("multibody time step", "time", "s", 0.0,
              "0 = adaptive step (Dormand-Prince 5(4), each run's local error within the "
              "tolerances below); > 0: that fixed step, checked against the fastest linear "
              "mode (|lambda| dt <= 1).", _S, Bounds(0, 1, unit="s")),
    Parameter("multibody relative tolerance", "dimensionless", "", 1e-4,
              "Relative tolerance of the adaptive step, > 0 (1e-4: peaks within about 0.02 % "
              "of a tight reference).", _S, RELATIVE_TOLERANCE),
    Parameter("multibody absolute tolerance", "dimensionless", "", 1e-5,
              "Absolute tolerance of the adaptive step in SI units of the states (m, m/s, "
              "rad, rad/s), > 0.", _S, ABSOLUTE_TOLERANCE),
    Parameter("multibody output interval", "time", "s", 0.1,
              "Sampling interval of the histories, > 0.", _S, OUTPUT_INTERVAL),
)

SHEETS = (
    TableSheet("MultibodyManoeuvres", (
        Column("name", TEXT, help="Unique name of the run."),
        Column("kind", TEXT, help=" | ".join(MANOEUVRE_KINDS) + "."),
        Column("shape", TEXT, required=False, default="",
               help="Gust only: step | finite | 1-cosine | continuous (default finite)."),
        Column("direction", TEXT, required=False, default="",
               help="Gust only: lateral (air from the right for a positive amplitude) | "
                    "longitudinal (head-on) | vertical (up) (default lateral)."),
        Column("amplitude", "speed", "ft/s", False, None,
               "Gust only: gust velocity, finite and not 0, sign = direction (default 30 "
               "ft/s, CS 29.341). Typical: +30 or -30 ft/s.",
               bounds=Bounds(-100, 100, unit="m/s", nonzero=True)),
        Column("onset", "time", "s", False, None,
               "Gust, forward acceleration, wind ramp: start time, >= 0 and before the end of "
               "the run (default 5 s). Typical: 5 s.", bounds=Bounds(0, 3600, unit="s")),
        Column("duration", "time", "s", False, None,
               "Gust only: duration of the finite and 1-cosine gusts, period of the continuous "
               "one, > 0 (default 10 s). Typical: 10 s.",
               bounds=Bounds(0, 3600, lo_open=True, unit="s")),
        Column("target", "speed", "kt", False, None,
               "Forward acceleration: final indicated airspeed (paper: 40, 60, 80, 100 KIAS); "
               "wind ramp: final head-wind speed (paper: 20 to 80 kt). > 0, required. "
               "Typical: 80 kt.",
               bounds=Bounds(0, 200, lo_open=True, unit="kt")),
        Column("rate", "acceleration", "m/s^2", False, None,
               "Forward acceleration: peak acceleration (default 1 m/s^2); wind ramp: rate of "
               "increase of the wind (default 0.5 m/s^2). > 0. Typical: 0.5 to 1 m/s^2.",
               bounds=Bounds(0, 50, lo_open=True, unit="m/s^2")),
        Column("yaw", "angle", "deg", False, None,
               "Initial disturbance from the start: yaw, nose right +. Typical: 10 deg for a "
               "free response.", bounds=ANGLE),
        Column("pitch", "angle", "deg", False, None,
               "Initial pitch, nose up +. Typical: 0 to 5 deg.", bounds=ANGLE),
        Column("roll", "angle", "deg", False, None,
               "Initial roll, right side down +. Typical: 0 to 5 deg.",
               bounds=ANGLE),
        Column("yaw rate", "frequency", "deg/s", False, None,
               "Initial yaw rate, nose right +. Typical: 0 to 5 deg/s.",
               bounds=Bounds(-360, 360, unit="deg/s")),
        Column("lateral offset", "length", "ft", False, None,
               "Initial CG displacement to the right (earth axes). Typical: 0 to 3 ft.",
               bounds=OFFSET),
        Column("longitudinal offset", "length", "ft", False, None,
               "Initial CG displacement aft (earth axes). Typical: 0 to 3 ft.",
               bounds=OFFSET),
        Column("vertical offset", "length", "ft", False, None,
               "Initial CG displacement up (earth axes). Typical: 0 to 1 ft.",
               bounds=OFFSET),
        Column("file", TEXT, required=False, default="",
               help="Hook trajectory only: a CSV file (path from the workbook's folder) with "
                    "time_s and ax_mps2, ay_mps2, az_mps2 (acceleration) or vx_mps, vy_mps, "
                    "vz_mps (velocity) or x_m, y_m, z_m (displacement) of the hook relative to "
                    "its steady flight, earth axes (X aft, Y right, Z up), one row per "
                    "breakpoint (slingloads.io.multibody.trajectory)."),
        Column("description", TEXT, required=False, default="", help="Free text."),
    ), help="Optional: the runs of the multibody model, each from its trim plus its stated "
       "initial disturbance (empty disturbance columns: 10 deg of yaw for a free response, a "
       "2 deg yaw seed for the runs from hover, none for a gust). Without the sheet the "
       "paper's list is flown: free response, +-30 ft/s lateral gusts of four shapes, "
       "accelerations to 40/60/80/100 KIAS, wind ramps to 20/30/40/60/80 kt.",
       max_rows=MAX_MULTIBODY_RUNS, ids=("name",)),
    TableSheet("HTailAero", (
        Column("alpha", "angle", "deg",
               help="Local angle of attack of the horizontal tail, strictly increasing; it "
                    "should cover -180..180 deg (never extrapolated: a run that leaves it "
                    "stops). Typical: -180 to 180 deg in 5 to 10 deg steps.",
               bounds=Bounds(-180, 180, unit="deg")),
        Column("CN", "dimensionless", bounds=SURFACE_COEFFICIENT,
               help="Normal-force coefficient on 'multibody horizontal tail area' (the tail's "
                    "planform area), positive up for a positive alpha. Within [-3, 3], as the "
                    "fin's CY: a flat plate square to the flow reaches about 1.2 (2.0 in two "
                    "dimensions). Typical (HC1): 1.17 at 90 deg."),
    ), help="Optional (with 'multibody tail' = full tail): the horizontal tail's normal-force "
       "coefficient against its local angle of attack.", max_rows=MAX_AERO_ROWS),
)

SECTION = Section("multibody", parameters=PARAMETERS, sheets=SHEETS)

#: The Study parameter behind each setting the analysis may refuse while computing.
COMPUTE_FIELDS = {"t_end": "multibody simulation time", "dt": "multibody time step"}

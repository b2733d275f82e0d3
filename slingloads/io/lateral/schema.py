"""Study-sheet parameters and sheets of the lateral-step pendulum (types in ``io.common.schema``).

The study sweeps every carrier motion of ``LateralMotions`` x every rope length of
``LateralRopes`` x every body of ``LateralBodies`` (default: one body built from the
``MassItems`` and the ``Hardpoints`` hub). It also reads the loads' Study parameters
'hook load factor Nz', 'hook azimuths', 'hook along mast axis' and the airframe's mast axis to
re-run the CS-29.865 hook cases at the recommended angle. Method, signs and limits:
``docs/lateral-pendulum.md``.
"""

from __future__ import annotations

from slingloads.analyses.lateral_damping import DAMPING_SOURCES
from slingloads.io.common.schema import (
    AIRSPEED,
    CARRIER_MASS,
    INTEGER,
    RELATIVE_TOLERANCE,
    TEXT,
    Bounds,
    Column,
    Parameter,
    Section,
    TableSheet,
    above,
    at_least,
)
from slingloads.limits import (
    MAX_HISTORY_SAMPLES,
    MAX_LATERAL_RUNS,
    MAX_LATERAL_STEPS,
    MAX_TABLE_ROWS,
)
from slingloads.models.integration import SOLVE_IVP_METHODS

#: Valid values of 'lateral cable model'.
CABLE_MODELS = ("rigid", "elastic")
#: Valid motion types of the LateralMotions sheet (spaces or underscores).
MOTION_TYPES = ("quintic step", "cycloidal step", "constant acceleration", "velocity step",
                "time history")
#: Former motion type names still accepted, and what they now are.
MOTION_ALIASES = {"smooth step": "quintic step"}
#: Valid values of the LateralMotions 'then' column.
THEN = ("hold", "stop")
#: solve_ivp methods of the time histories of the critical case.
SOLVER_METHODS = SOLVE_IVP_METHODS

_S = "lateral"
#: Smallest mass of a LateralBodies row (the smallest total of the MassItems). [kg]
MIN_BODY_MASS = 1.0
#: Smallest roll radius of gyration sqrt(I/m) of a LateralBodies row: a solid cylinder
#: 0.28 m across (k = R / sqrt(2)); helicopters have about 0.9 to 1 m (BO-105C 0.93 m, NASA
#: CR-3144; UH-60A 1.01 m, NASA TM 85890). [m]
MIN_ROLL_GYRATION = 0.1

PARAMETERS = (
    Parameter("lateral design-angle margin", "dimensionless", "", 1.5,
              "Factor on the largest load angle found: recommended design angle = margin x "
              "max |theta1 - theta2|, >= 1.", _S, Bounds(1, 10)),
    Parameter("lateral carrier bank limit", "angle", "deg", 20.0,
              "Largest bank angle of the carrier: a coordinated carrier banked phi accelerates "
              "sideways at g tan(phi), so no flyable motion exceeds g tan(limit). Default 20 "
              "deg (US Army TM 1-1670-260-12&P, damaged-helicopter recovery). A motion beyond "
              "it is flagged and bounds no design angle.", _S,
              Bounds(0, 60, lo_open=True, unit="deg")),
    Parameter("lateral carrier roll rate limit", "frequency", "deg/s", 10.0,
              "Largest roll rate of the carrier: the hook's lateral acceleration changes at "
              "most g sec^2(bank limit) x this. Default 10 deg/s, an engineering assumption "
              "(no published limit found): set the operation's own.", _S,
              Bounds(0, 1.0, lo_open=True, unit="1/s")),
    Parameter("lateral carrier mass", "mass", "kg", 15000.0,
              "Mass of the carrier, > 0 (GENERIC heavy-lift class): the frozen-carrier "
              "assumption (the hook follows its prescribed path) is flagged where the cable's "
              "lateral force exceeds 10 % of its weight.", _S, CARRIER_MASS),
    Parameter("lateral cable model", TEXT, "", "rigid",
              "'rigid' (inextensible rope, fast; not valid once the tension goes negative) or "
              "'elastic' (tension-only spring EA/l: slack and snatch).", _S),
    Parameter("lateral cable EA", "force", "N", 0.0,
              "Axial stiffness EA of the cable, > 0 with the 'elastic' model; leave 0 with "
              "'rigid'.", _S, at_least(0)),
    Parameter("lateral damping source", TEXT, "", "parameters",
              f"Where the damping of the swing and roll comes from, one of "
              f"{list(DAMPING_SOURCES)}: 'parameters' = the two rows below (0 = off, the "
              "paper's hover assumption); 'aerodynamic tables' = derived from the FuselageAero "
              "and FinAero side-force slopes at 'lateral airspeed EAS' (zero in hover: no "
              "free stream; docs/lateral-pendulum.md).", _S),
    Parameter("lateral damping", "linear damping", "N*s/m", 0.0,
              "With the source 'parameters': linear damping of the CG's lateral speed, >= 0 "
              "(0 = off, the paper's assumption); leave 0 with 'aerodynamic tables'.", _S,
              at_least(0)),
    Parameter("lateral roll damping", "rotational damping", "N*m*s/rad", 0.0,
              "With the source 'parameters': linear damping of the airframe's roll rate, >= 0 "
              "(0 = off); leave 0 with 'aerodynamic tables'.", _S,
              at_least(0)),
    Parameter("lateral airspeed EAS", "speed", "kt", 0.0,
              "Airspeed at which the aerodynamic damping is derived, >= 0 (0 = hover, the "
              "paper's lateral step: no linear aerodynamic damping), at most 200 kt (the "
              "cap of every analysis).", _S, AIRSPEED),
    Parameter("lateral density altitude", "length", "ft", 0.0,
              "ISA density altitude of the aerodynamic damping.", _S,
              Bounds(-610, 11000, unit="m")),
    Parameter("lateral roll inertia spread", "dimensionless", "", 0.2,
              "Uncertainty of the roll inertia: the study runs factors 1 -+ this, in [0, 1) "
              "(default 20 %); the recommended angle covers the whole range.", _S,
              Bounds(0, 1, hi_open=True)),
    Parameter("lateral CG below hub spread", "dimensionless", "", 0.2,
              "Uncertainty of the CG distance below the hub, as the roll inertia's.", _S,
              Bounds(0, 1, hi_open=True)),
    Parameter("lateral rope length spread", "dimensionless", "", 0.2,
              "Uncertainty of every rope length, as the roll inertia's.", _S,
              Bounds(0, 1, hi_open=True)),
    Parameter("lateral spread points", INTEGER, "", 5,
              "Values per range, evenly spaced (nominal included), >= 1; the study runs "
              "every combination (points^3 x bodies x ropes x motions runs).", _S,
              Bounds(1, 21)),
    Parameter("lateral simulation time", "time", "s", 0.0,
              "Length of every run, > 0; 0 = automatic: the longest motion plus three periods "
              "of the slowest swing mode. Lengthen it (or add damping) to check that the "
              "maximum has settled: undamped, the two swing modes beat. At most "
              f"{MAX_LATERAL_STEPS:,} RK4 steps per run.", _S, Bounds(0, 3600)),
    Parameter("lateral RK4 step", "time", "s", 0.0,
              "Fixed step of the vectorised RK4 sweep, > 0; 0 = automatic: min(0.01 s, "
              "0.25/omega_max) (about 1e-4 on the peak angle). The report compares the "
              "critical case with an adaptive solve_ivp re-run.", _S, at_least(0)),
    Parameter("lateral history method", TEXT, "", "RK45",
              f"solve_ivp method of the critical case's time histories: {list(SOLVER_METHODS)}."
              , _S),
    Parameter("lateral history rtol", "dimensionless", "", 1e-8,
              "Relative tolerance of the time-history re-run, > 0.", _S, RELATIVE_TOLERANCE),
    Parameter("lateral history output step", "time", "s", 0.01,
              "Sampling interval of the time histories, > 0.", _S, above(0)),
)

SHEETS = (
    TableSheet("LateralMotions", (
        Column("id", TEXT, help="Unique name of the carrier motion, e.g. STEP-0.1g-1s."),
        Column("type", TEXT, help="Kind of motion of the hook (the carrier's cable end): "
                                  "quintic step (minimum-jerk law S = A (10 tau^3 - 15 "
                                  "tau^4 + 6 tau^5), peak acceleration 5.77 A/T^2; 'smooth "
                                  "step' is its former name) | cycloidal step (S = A (tau - "
                                  "sin(2 pi tau)/(2 pi)), peak 2 pi A/T^2) | constant "
                                  "acceleration | velocity step | time history."),
        Column("acceleration", "acceleration", "m/s^2", False, None,
               "Quintic or cycloidal step: peak lateral acceleration of the hook; constant "
               "acceleration: the rate. Finite, not 0; positive to the right (+y). Typical: "
               "0.1 to 0.5 g0. Any acceleration unit: m/s^2, ft/s^2, or g0 (standard gravity; "
               "'g' would be the gram)."),
        Column("duration", "time", "s", False, None,
               "Quintic or cycloidal step: time T to complete the step; constant "
               "acceleration: time of the acceleration phase. > 0. Typical: 0.5 to 5 s.",
               Bounds(0, 3600, lo_open=True)),
        Column("amplitude", "length", "m", False, None,
               "Quintic or cycloidal step only, instead of the acceleration: the step's lateral "
               "displacement A of the hook, positive to the right. Typical: 1 to 20 m."),
        Column("then", TEXT, required=False, default="",
               help="Constant acceleration only: 'hold' (keep the speed reached) or 'stop' "
                    "(decelerate at the same rate for the same time)."),
        Column("delta V", "speed", "m/s", False, None,
               "Velocity step only: the hook's lateral speed jump at t = 0, positive to the "
               "right, finite, not 0. Typical: 0.5 to 2 m/s."),
        Column("history", TEXT, required=False, default="", max_chars=1000,
               help="Time history only: a 'history id' of the LateralHistory sheet, or a CSV "
                    "file (path relative to the workbook) with columns 't [s]' and 'S [m]' "
                    "(units in brackets, any of the right kind)."),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Carrier (hook) lateral motions to sweep, each starting from hover at rest "
       "(docs/lateral-pendulum.md section 5). Must cover the manoeuvres of the operation being "
       f"certified. At most {MAX_LATERAL_RUNS:,} runs (motions x ropes x bodies).",
       max_rows=MAX_LATERAL_RUNS, ids=("id",)),
    TableSheet("LateralHistory", (
        Column("history id", TEXT, help="Name referred to by LateralMotions 'history', e.g. "
                                        "REPOSITION."),
        Column("t", "time", "s", help="Sample time from the start of the run (t = 0 at rest), "
                                      "strictly increasing within a history. Typical: every "
                                      "0.1 to 1 s over 10 to 30 s.",
               bounds=Bounds(-3600, 3600)),
        Column("S", "length", "m", help="Lateral displacement of the hook from its start, "
                                        "positive to the right (+y). Typical: 0 to 20 m."),
    ), help="Optional: measured or planned hook displacement histories, one block of rows per "
       f"history id (natural cubic spline between samples), at most "
       f"{MAX_TABLE_ROWS:,} samples in all (longer histories: a CSV file, up to "
       f"{MAX_HISTORY_SAMPLES:,} samples).", max_rows=MAX_TABLE_ROWS),
    TableSheet("LateralRopes", (
        Column("rope length", "length", "ft",
               help="Unstretched cable length from the carrier's hook to the carried "
                    "helicopter's hub, > 0. Typical: 18, 60, 100 ft (paper).",
               bounds=Bounds(0, 1000, lo_open=True, unit="m")),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Rope (cable) lengths to sweep.", max_rows=MAX_LATERAL_RUNS),
    TableSheet("LateralBodies", (
        Column("id", TEXT, help="Unique name of the mass case, e.g. HEAVY."),
        Column("mass", "mass", "kg", help="Mass of the carried helicopter, >= 1 kg (as the "
                                          "MassItems' total: below it no aircraft). Typical: "
                                          "2,000 to 3,000 kg for a light twin.",
               bounds=at_least(MIN_BODY_MASS, unit="kg")),
        Column("roll inertia", "inertia", "kg m^2",
               help="Roll moment of inertia about the x axis through the CG, > 0, with a "
                    f"radius of gyration sqrt(inertia / mass) of at least "
                    f"{MIN_ROLL_GYRATION:g} m (a solid cylinder 0.28 m across; helicopters: "
                    "about 0.9 to 1 m). Typical: 1,000 to 2,000 kg m^2 for a 2.9 t light "
                    "twin without blades.",
               bounds=above(0)),
        Column("CG below hub", "length", "m",
               help="Distance from the rotor hub down the mast axis to the CG, >= 0 "
                    "(positive: CG below the hub). Typical: about 1.1 m.",
               bounds=Bounds(0, 100, unit="m")),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Optional: mass-property cases (e.g. heaviest, lightest). Default: one body from "
       "MassItems, hanging with its CG under the hub: total mass, roll inertia about the "
       "CG around the horizontal fore-and-aft axis, CG distance below the hub.",
       max_rows=MAX_LATERAL_RUNS, ids=("id",)),
)

SECTION = Section("lateral", parameters=PARAMETERS, sheets=SHEETS)

#: The Study parameter behind each setting the analysis may refuse while computing (to locate
#: its error): the automatic run length and step are only known then.
COMPUTE_FIELDS = {"step": "lateral RK4 step", "t_end": "lateral simulation time",
                  "rtol": "lateral history rtol",
                  "output_interval": "lateral history output step"}

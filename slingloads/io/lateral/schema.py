"""Study-sheet parameters and sheets of the lateral-step pendulum (types in ``io.common.schema``).

The study sweeps every carrier motion of ``LateralMotions`` x every rope length of
``LateralRopes`` x every body of ``LateralBodies`` (default: one body built from the
``MassItems`` and the ``Hardpoints`` hub). It also reads the loads' Study parameters
'hook load factor Nz', 'hook azimuths', 'hook along mast axis' and the airframe's mast axis to
re-run the CS-29.865 hook cases at the recommended angle. Method, signs and limits:
``docs/lateral-pendulum.md``.
"""

from __future__ import annotations

from slingloads.io.common.schema import TEXT, Column, Parameter, Section, TableSheet

#: Valid values of 'lateral cable model'.
CABLE_MODELS = ("rigid", "elastic")
#: Valid motion types of the LateralMotions sheet (spaces or underscores).
MOTION_TYPES = ("smooth step", "constant acceleration", "velocity step", "time history")
#: Valid values of the LateralMotions 'then' column.
THEN = ("hold", "stop")
#: solve_ivp methods of the time histories of the critical case.
SOLVER_METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

_S = "lateral"

PARAMETERS = (
    Parameter("lateral design-angle margin", "dimensionless", "", 1.5,
              "Factor on the largest load angle found: recommended design angle = margin x "
              "max |theta1 - theta2|, >= 1.", _S),
    Parameter("lateral cable model", TEXT, "", "rigid",
              "'rigid' (inextensible rope, fast; not valid once the tension goes negative) or "
              "'elastic' (tension-only spring EA/l: slack and snatch).", _S),
    Parameter("lateral cable EA", "force", "N", 0.0,
              "Axial stiffness EA of the cable, > 0 with the 'elastic' model; leave 0 with "
              "'rigid'.", _S),
    Parameter("lateral damping", "linear damping", "N*s/m", 0.0,
              "Linear aerodynamic damping of the CG's lateral speed, >= 0 (0 = off, the "
              "paper's assumption).", _S),
    Parameter("lateral roll damping", "rotational damping", "N*m*s/rad", 0.0,
              "Linear aerodynamic damping of the airframe's roll rate, >= 0 (0 = off).", _S),
    Parameter("lateral simulation time", "time", "s", 0.0,
              "Length of every run, > 0; 0 = automatic: the longest motion plus three periods "
              "of the slowest swing mode. Lengthen it (or add damping) to check that the "
              "maximum has settled: undamped, the two swing modes beat.", _S),
    Parameter("lateral RK4 step", "time", "s", 0.0,
              "Fixed step of the vectorised RK4 sweep, > 0; 0 = automatic: min(0.01 s, "
              "0.25/omega_max) (about 1e-4 on the peak angle). The report compares the "
              "critical case with an adaptive solve_ivp re-run.", _S),
    Parameter("lateral history method", TEXT, "", "RK45",
              f"solve_ivp method of the critical case's time histories: {list(SOLVER_METHODS)}."
              , _S),
    Parameter("lateral history rtol", "dimensionless", "", 1e-8,
              "Relative tolerance of the time-history re-run, > 0.", _S),
    Parameter("lateral history output step", "time", "s", 0.01,
              "Sampling interval of the time histories, > 0.", _S),
)

SHEETS = (
    TableSheet("LateralMotions", (
        Column("id", TEXT, help="Unique name of the carrier motion, e.g. STEP-0.1g-1s."),
        Column("type", TEXT, help="Kind of motion of the hook (the carrier's cable end): "
                                  "smooth step | constant acceleration | velocity step | "
                                  "time history."),
        Column("acceleration", "acceleration", "m/s^2", False, None,
               "Smooth step: peak lateral acceleration of the hook; constant acceleration: "
               "the rate. Finite, not 0; positive to the right (+y). Typical: 0.1 to 0.5 g0. "
               "Any acceleration unit: m/s^2, ft/s^2, or g0 (standard gravity; 'g' would be "
               "the gram)."),
        Column("duration", "time", "s", False, None,
               "Smooth step: time to complete the step; constant acceleration: time of the "
               "acceleration phase. > 0. Typical: 0.5 to 5 s."),
        Column("amplitude", "length", "m", False, None,
               "Smooth step only, instead of the acceleration: the step's lateral "
               "displacement of the hook, positive to the right. Typical: 1 to 20 m."),
        Column("then", TEXT, required=False, default="",
               help="Constant acceleration only: 'hold' (keep the speed reached) or 'stop' "
                    "(decelerate at the same rate for the same time)."),
        Column("delta V", "speed", "m/s", False, None,
               "Velocity step only: the hook's lateral speed jump at t = 0, positive to the "
               "right, finite, not 0. Typical: 0.5 to 2 m/s."),
        Column("history", TEXT, required=False, default="",
               help="Time history only: a 'history id' of the LateralHistory sheet, or a CSV "
                    "file (path relative to the workbook) with columns 't [s]' and 'S [m]' "
                    "(units in brackets, any of the right kind)."),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Carrier (hook) lateral motions to sweep, each starting from hover at rest "
       "(docs/lateral-pendulum.md section 5). Must cover the manoeuvres of the operation being "
       "certified."),
    TableSheet("LateralHistory", (
        Column("history id", TEXT, help="Name referred to by LateralMotions 'history', e.g. "
                                        "REPOSITION."),
        Column("t", "time", "s", help="Sample time from the start of the run (t = 0 at rest), "
                                      "strictly increasing within a history. Typical: every "
                                      "0.1 to 1 s over 10 to 30 s."),
        Column("S", "length", "m", help="Lateral displacement of the hook from its start, "
                                        "positive to the right (+y). Typical: 0 to 20 m."),
    ), help="Optional: measured or planned hook displacement histories, one block of rows per "
       "history id (natural cubic spline between samples)."),
    TableSheet("LateralRopes", (
        Column("rope length", "length", "ft",
               help="Unstretched cable length from the carrier's hook to the carried "
                    "helicopter's hub, > 0. Typical: 18, 60, 100 ft (paper)."),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Rope (cable) lengths to sweep."),
    TableSheet("LateralBodies", (
        Column("id", TEXT, help="Unique name of the mass case, e.g. HEAVY."),
        Column("mass", "mass", "kg", help="Mass of the carried helicopter, > 0. Typical: "
                                          "2,000 to 3,000 kg for a light twin."),
        Column("roll inertia", "inertia", "kg m^2",
               help="Roll moment of inertia about the x axis through the CG, > 0. Typical: "
                    "about 900 kg m^2 for a 2.9 t light twin without blades."),
        Column("CG below hub", "length", "m",
               help="Distance from the rotor hub down the mast axis to the CG, >= 0 "
                    "(positive: CG below the hub). Typical: about 1.1 m."),
        Column("description", TEXT, required=False, default="",
               help="Free text printed on the report."),
    ), help="Optional: mass-property cases (e.g. heaviest, lightest). Default: one body from "
       "MassItems: total mass, Ixx about the CG, CG below the hub along the mast."),
)

SECTION = Section("lateral", parameters=PARAMETERS, sheets=SHEETS)

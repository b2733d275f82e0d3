"""Study-sheet parameters and sheets of the parachute sizing (types in ``io.common.schema``).

The sizing also reads the airframe's sheets and parameters
(:mod:`slingloads.io.airframe.schema`): ``FuselageAero``, ``FinAero``, ``ParachuteCD``, the
``Hardpoints`` of kind ``hub``, ``chute``, ``fin_cp`` and ``aero_reference``, the
``MassItems`` (yaw inertia) and the Study parameters 'fuselage reference area', 'fuselage
reference length', 'fin area', 'fin efficiency', 'parachute wake ratio' and 'parachute line
length'. Method and signs: ``docs/parachute-sizing.md``.
"""

from __future__ import annotations

from slingloads.io.common.schema import (
    AIRSPEED,
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
    MAX_AERO_ROWS,
    MAX_CHUTE_AREAS,
    MAX_CHUTE_REFERENCE_RUNS,
    MAX_CHUTE_RUNS,
    MAX_CHUTE_STEPS,
)
from slingloads.models.gusts import GUST_SHAPES, W20

#: Valid values of 'chute sizing wake source'.
WAKE_SOURCES = ("model", "table")
#: Valid values of 'chute sizing yaw inertia source'.
INERTIA_SOURCES = ("mass items", "parameter")
#: Valid values of 'chute sizing integrator'.
INTEGRATORS = ("dopri5", "rk4", "solve_ivp")
#: Valid values of 'chute sizing turbulence severity' (MIL-F-8785C W20 = 15, 30, 45 kt).
SEVERITIES = tuple(W20)

_S = "chute sizing"

PARAMETERS = (
    Parameter("chute sizing airspeed IAS", "speed", "kt", 80.0,
              "Indicated airspeed of the sizing, taken equal to EAS, > 0 and at most 200 kt "
              "(the cap of every analysis; paper: 80 KIAS).", _S,
              Bounds(0, AIRSPEED.hi, lo_open=True, unit=AIRSPEED.unit)),
    Parameter("chute sizing density altitude", "length", "ft", 0.0,
              "ISA density altitude of the sizing (paper: sea level).", _S,
              Bounds(-610, 11000, unit="m")),
    Parameter("chute sizing alpha trim", "angle", "deg", 0.0,
              "Trimmed angle of attack of the carried helicopter (FuselageAero is read at it; "
              "it must be a breakpoint of the table or lie between two).", _S,
              Bounds(-90, 90, unit="deg")),
    Parameter("chute sizing linearisation range", "angle", "deg", 10.0,
              "Half-width of the sideslip range of the least-squares fit of Cn (+-value; "
              "paper figures 4-5), > 0.", _S,
              Bounds(0, 90, lo_open=True, hi_open=True, unit="deg")),
    Parameter("chute sizing yaw inertia source", TEXT, "", "mass items",
              "'mass items': yaw inertia about the yaw axis ('chute sizing yaw axis') "
              "computed from MassItems (parallel-axis term where the axis misses the CG); "
              "'parameter': 'chute sizing yaw inertia'.",
              _S),
    Parameter("chute sizing yaw axis", TEXT, "", "suspension",
              "Axis of the 1-DOF yaw model, through the hub, about which its yawing moments, "
              "yaw inertia and weight are all taken: 'suspension' (the line from the hook "
              "through the hub: the towed trim's cable line, or the hub-CG line without a "
              "trim) or 'airframe z' (the paper's balance of Mz, weight left out).", _S),
    Parameter("chute sizing yaw inertia", "inertia", "kg m^2", 0.0,
              "Yaw inertia about the suspension axis, used (and then > 0) only with the "
              "source 'parameter'; leave 0 with 'mass items'.", _S),
    Parameter("chute sizing wake source", TEXT, "", "model",
              "'model': empirical bluff-body far-wake model (docs/parachute-sizing.md); "
              "'table': the ChuteWake sheet (CFD or test).", _S),
    Parameter("chute sizing wake coefficient", "dimensionless", "", 1.0,
              "Empirical constant K of the far-wake model, > 0 (NOT calibrated on helicopter "
              "fuselages: the line for a given ratio scales as K^1.5).", _S, above(0)),
    Parameter("chute sizing wake drag area", "area", "m^2", 0.0,
              "Drag area CD S of the wake model; 0 = FuselageAero CD at (alpha trim, beta 0) "
              "x 'fuselage reference area'.", _S, at_least(0)),
    Parameter("chute sizing target q ratio", "dimensionless", "", 0.95,
              "Dynamic-pressure ratio the canopy must see; sets the line length (paper: "
              "0.95), in (0, 1].", _S, Bounds(0, 1, lo_open=True)),
    Parameter("chute sizing carrier cable length", "length", "ft", 0.0,
              "Carrier-to-hub cable (paper: 18 to 100 ft); checked >= (1 + margin) x the "
              "parachute line. 0 = not given: the check is skipped.", _S, at_least(0)),
    Parameter("chute sizing cable margin", "dimensionless", "", 0.20,
              "Required excess of the carrier cable over the parachute line (paper: 20 %).",
              _S, Bounds(0, 10)),
    Parameter("chute sizing gust shapes", TEXT, "", "step, finite, 1-cosine, continuous",
              f"Comma-separated lateral gust shapes, of {list(GUST_SHAPES)}: step (sharp-edged, "
              "held), finite (rectangular, the paper's 'impulsive' gust), 1-cosine, continuous "
              "(a sustained crosswind: rises over 'chute sizing gust rise time', then held; the "
              "paper's continuous gust), harmonic (a sine of period 'chute sizing harmonic "
              "period', never ending: a resonance test), turbulence (Dryden, MIL-F-8785C; "
              "rows 'chute sizing turbulence ...').", _S),
    Parameter("chute sizing gust amplitude", "speed", "ft/s", 30.0,
              "Lateral gust velocity, > 0 (CS 29.341 / paper: 30 ft/s).", _S, above(0)),
    Parameter("chute sizing gust onset", "time", "s", 30.0,
              "Time at which the gust starts, >= 0 and before the end of the simulation.", _S,
              at_least(0)),
    Parameter("chute sizing gust duration", "time", "s", 10.0,
              "Duration of the finite and 1-cosine gusts, > 0.", _S, above(0)),
    Parameter("chute sizing gust rise time", "time", "s", 5.0,
              "Time the continuous (sustained) crosswind takes to build up along a half "
              "cosine, >= 0 (0: a sharp-edged step; 5 s: the rise of the 10 s 1-cosine gust).",
              _S, Bounds(0, 3600)),
    Parameter("chute sizing harmonic period", "time", "s", 10.0,
              "Period of the harmonic gust, > 0 (the worst case is near the yaw period).", _S,
              Bounds(0, 3600, lo_open=True)),
    Parameter("chute sizing turbulence altitude", "length", "ft", 300.0,
              "Height above ground of the Dryden turbulence, 10 to 1000 ft (MIL-F-8785C "
              "low-altitude scale length L_v = h/(0.177 + 0.000823 h)^1.2 and intensity).", _S),
    Parameter("chute sizing turbulence severity", TEXT, "", "moderate",
              f"MIL-F-8785C turbulence level, one of {list(W20)} (wind at 20 ft: 15, 30, 45 "
              "kt; sigma_v = 0.1 W20/(0.177 + 0.000823 h)^0.4).", _S),
    Parameter("chute sizing turbulence duration", "time", "s", 60.0,
              "Time the turbulence acts from the gust onset, > 0; it must end before the end "
              "of the simulation so that the free response is seen.", _S,
              Bounds(0, 3600, lo_open=True)),
    Parameter("chute sizing turbulence seed", INTEGER, "", 1,
              "Seed of the turbulence realisation (the same seed gives the same history).", _S,
              Bounds(0, 2**32 - 1)),
    Parameter("chute sizing sideslip limit", "angle", "deg", 20.0,
              "A run whose |sideslip| passes it is never called stable, > 0 (past about 20 "
              "deg helicopter fuselage Cn curves turn over and a cut-down fin nears stall; "
              "set it to the loads' sideslip envelope to keep the two consistent). A run that "
              "leaves the linearisation range is not called stable either.", _S,
              Bounds(0, 90, lo_open=True)),
    Parameter("chute sizing simulation time", "time", "s", 120.0,
              "Simulated time of each 1-DOF run, a whole multiple of the output interval "
              "(and, with 'rk4', of the time step); at most "
              f"{MAX_CHUTE_STEPS:,} steps a run ('rk4': simulation time / time step; "
              "'dopri5': the steps it tries).", _S, Bounds(0, 3600, lo_open=True)),
    Parameter("chute sizing time step", "time", "s", 0.05,
              "Fixed step of the 'rk4' integrator (gust onsets and ends between its grid "
              "points are inserted into it); 'dopri5' and 'solve_ivp' choose their own steps. "
              "With 'rk4' the simulation time and the output interval are whole multiples "
              "of it.", _S,
              above(0)),
    Parameter("chute sizing output interval", "time", "s", 0.1,
              "Sampling interval of the stored histories (with 'rk4', a whole multiple of "
              "the time step).",
              _S, above(0)),
    Parameter("chute sizing integrator", TEXT, "", "dopri5",
              "'dopri5': adaptive Dormand-Prince 5(4) (the pair of solve_ivp's RK45), compiled, "
              "all runs at once, each with its own step within 'chute sizing reference rtol' "
              "(absolute tolerance 1e-10 rad and rad/s), split at the gust breakpoints; "
              "'rk4': compiled fixed-step Runge-Kutta 4 at 'chute sizing time step' (no error "
              "control: halve the step to check it); 'solve_ivp': scipy's solve_ivp one run at "
              "a time with the reference method and rtol (a cross-check; slow, at most "
              f"{MAX_CHUTE_REFERENCE_RUNS} runs).", _S),
    Parameter("chute sizing reference method", TEXT, "", "RK45",
              "solve_ivp method of the 'solve_ivp' integrator (RK45, DOP853, Radau, ...).", _S),
    Parameter("chute sizing reference rtol", "dimensionless", "", 1e-8,
              "Relative tolerance of the adaptive integrators, 'dopri5' and 'solve_ivp', > 0: "
              "each step's local error estimate stays within rtol |state| + 1e-10 (solve_ivp's "
              "norm).", _S, RELATIVE_TOLERANCE),
    Parameter("chute sizing area factor min", "dimensionless", "", 1.0,
              "Smallest swept area over the neutral static area, > 0 (paper: 1).", _S,
              Bounds(0, 100, lo_open=True)),
    Parameter("chute sizing area factor max", "dimensionless", "", 2.0,
              "Largest swept area over the neutral static area, >= min (paper: 2).", _S,
              Bounds(0, 100, lo_open=True)),
    Parameter("chute sizing number of areas", INTEGER, "", 11,
              f"Number of swept areas, evenly spaced, >= 1 (at most {MAX_CHUTE_RUNS:,} runs "
              "areas x gust shapes).", _S, Bounds(1, MAX_CHUTE_AREAS)),
    Parameter("chute sizing recommended factor", "dimensionless", "", 1.4,
              "Recommended area over the neutral static area, > 0. 1.4 is the paper's optimum "
              "for its own aircraft (FPA + 40 %, found by its multibody campaign: the 1-DOF "
              "model had confirmed the neutral area, the shortfall came from inter-axis "
              "coupling); a placeholder until a multibody campaign computes this aircraft's.",
              _S,
              Bounds(0, 100, lo_open=True)),
)

SHEETS = (
    TableSheet("ChuteWake", (
        Column("distance", "length", "m",
               help="Distance behind the parachute attachment along the wake, >= 0, strictly "
                    "increasing. Typical: 0 to 40 m.",
               bounds=Bounds(0, 10_000, unit="m")),
        Column("q ratio", "dimensionless",
               help="Dynamic pressure in the fuselage wake at that distance over the free "
                    "stream's, in (0, 1.2], not decreasing down the sheet (the wake recovers "
                    "with distance: its velocity defect decays). Typical: 0.5 just behind the "
                    "fuselage, 0.95 at 10 m.",
               bounds=Bounds(0, 1.2, lo_open=True)),
    ), help="Optional (with 'chute sizing wake source' = table): dynamic-pressure ratio in the "
       "fuselage wake against distance, from CFD or test (paper section 3.2). Never "
       "extrapolated.", max_rows=MAX_AERO_ROWS),
)

SECTION = Section("chute sizing", parameters=PARAMETERS, sheets=SHEETS)

#: The Study parameter behind each setting the analysis may refuse while computing.
COMPUTE_FIELDS = {"rtol": "chute sizing reference rtol",
                  "fit_range": "chute sizing linearisation range"}

"""Study-sheet parameters and sheets of the structural loads analysis.

The loads also read the airframe's sheets and parameters (:mod:`slingloads.io.airframe.schema`).
Method: ``docs/loads-method.md``. Types: :mod:`slingloads.io.common.schema`.
"""

from __future__ import annotations

from slingloads.io.airframe.schema import COORDINATE, TABLE_ANGLE
from slingloads.io.common.schema import (
    AIRSPEED,
    FLAG,
    INTEGER,
    TEXT,
    Bounds,
    Column,
    Parameter,
    Section,
    TableSheet,
    at_least,
)
from slingloads.limits import MAX_HOOK_AZIMUTHS, MAX_LOAD_CASES, MAX_SFBM_ROWS, MAX_STATIONS

#: The Nastran input file of the load cases (docs/nastran.md), in the units of --units.
NASTRAN_PARAMETERS = (
    Parameter("nastran bulk data", FLAG, "", "no",
              "Also write <input>-loads.bdf, the load cases as a Nastran input file (GRID, "
              "CONM2, FORCE, MOMENT, GRAV, RFORCE, a SUBCASE per case; docs/nastran.md); the "
              "option --nastran does the same. Units of --units: SI (m, N, kg, s) or US (in, "
              "lbf, s, mass in lbf s^2/in).", "nastran"),
    Parameter("nastran model axes", TEXT, "", "x, y, z",
              "The finite-element model's X, Y, Z as signed project axes (x aft, y right, z "
              "up), e.g. '-x, y, -z' for X forward, Y right, Z down; must be a rotation.",
              "nastran"),
    *(Parameter(f"nastran offset {axis}", "length", "m", 0.0,
                f"Position of the project's origin (the airframe datum) in the model's axes: "
                f"{axis.upper()}.", "nastran") for axis in "xyz"),
    Parameter("nastran inertia relief", TEXT, "", "accelerations",
              "'accelerations' (each subcase carries the inertia loads of the rigid-body "
              "accelerations as GRAV and RFORCE: self-balanced, constrain the model "
              "statically determinate) or 'inrel' (PARAM,INREL,-2: Nastran computes them "
              "from the CONM2 masses).", "nastran"),
    Parameter("nastran hook load at", TEXT, "", "mast feet",
              "'mast feet' (shared among the feet as the loads analysis does) or 'hub' (one "
              "force at the rotor hub grid).", "nastran"),
    Parameter("nastran first grid id", INTEGER, "", 900001,
              "Id of the first GRID (mass items, then hub, mast feet, aerodynamic points, fin, "
              "parachute).", "nastran"),
    Parameter("nastran first element id", INTEGER, "", 900001,
              "Id of the first CONM2 (one per mass item).", "nastran"),
    Parameter("nastran load id base", INTEGER, "", 100000,
              "Load-set ids: base + 1 is gravity; subcase s uses base + 10 s (LOAD) to "
              "base + 10 s + 4.", "nastran"),
    Parameter("nastran first subcase", INTEGER, "", 1,
              "Number of the first SUBCASE (one per load case, in case order).", "nastran"),
)

PARAMETERS = (
    Parameter("airspeed EAS", "speed", "kt", 100.0,
              "Equivalent airspeed of the loads cases (paper: 100 KEAS), at most 200 kt "
              "(above the never-exceed speed of the heavy-lift helicopters that carry slung "
              "loads; the cap of every analysis).", "flight", AIRSPEED),
    Parameter("density altitude", "length", "ft", 0.0,
              "ISA density altitude (paper: 0, 5000, 10000 ft).", "flight",
              Bounds(-610, 11000, unit="m")),
    Parameter("hook load factor Nz", "dimensionless", "", 2.5,
              "CS-29.865(a): limit hook load = Nz x carried aircraft weight; 2.5, or a lower "
              "factor approved under CS 29.337 to 29.341 (a value below 2.5 is flagged as a "
              "warning). At least 1: the hook carries the whole weight in steady flight, so "
              "no limit hook load is below 1 g.", "hook", Bounds(1, 20)),
    Parameter("attitude", TEXT, "", "hanging",
              "Attitude that fixes the earth vertical for gravity, the vertical hook case and "
              "the cone: 'hanging' (pitch and roll until the CG lies under the hub, from the "
              "MassItems and the hub), 'mast vertical' (the mast axis is the vertical) or "
              "'given' ('attitude pitch' and 'attitude roll').", "attitude"),
    Parameter("attitude pitch", "angle", "deg", 0.0,
              "Pitch, nose up positive, within (-90, 90) deg; only with attitude 'given'.",
              "attitude"),
    Parameter("attitude roll", "angle", "deg", 0.0,
              "Roll, right side down positive, within (-90, 90) deg; only with attitude "
              "'given'.", "attitude"),
    Parameter("hook angle from vertical", "angle", "deg", 30.0,
              "Inclination of the off-vertical hook loads from the earth vertical (CS-29.865: "
              "30 deg unless a smaller angle is shown); the lateral directions may take "
              "'hook lateral angle'.", "hook", Bounds(0, 90, hi_open=True, unit="deg"),
              former=("hook angle from mast",)),
    Parameter("hook lateral angle", "angle", "deg", 0.0,
              "Inclination of the lateral hook loads where a different angle is shown (e.g. "
              "the lateral study's recommended angle); 0 = the same as 'hook angle from "
              "vertical'. Applied as 'hook cone shape' says.", "hook"),
    Parameter("hook cone shape", TEXT, "", "lateral directions",
              "Where 'hook lateral angle' applies: 'lateral directions' (azimuths 90 and 270 "
              "deg only: what the lateral study covers) or 'elliptical' (from the fore-and-aft "
              "to the lateral angle, when longitudinal evidence exists).", "hook"),
    Parameter("hook angle justification", TEXT, "", "",
              "Where a hook angle below 30 deg is shown not to be exceeded in service (a "
              "report reference); quoted beside the flag on the loads Summary.", "hook"),
    Parameter("hook azimuths", INTEGER, "", 8,
              "Number of off-vertical hook directions evenly spread in azimuth about the "
              "vertical (0 = aft, 90 deg = right).", "hook", Bounds(0, MAX_HOOK_AZIMUTHS)),
    Parameter("hook vertical case", FLAG, "", "yes",
              "Include the hook load along the earth vertical (case VERTICAL).", "hook",
              former=("hook along mast axis",)),
    Parameter("towed equilibrium cases", FLAG, "", "yes",
              "Add, with and without parachute, the towed-flight case (hook TOW, aero TRIM) at "
              "the trimmed attitude (weight, aerodynamic and parachute moments balance about "
              "the hub): cable vertical component Nz x weight, horizontal component balancing "
              "aerodynamics and parachute; its angle is checked against the cone and a trim "
              "outside the AeroEnvelope range is flagged.",
              "hook"),
    Parameter("generate case matrix", FLAG, "", "yes",
              "Generate hook direction x aero point x parachute on/off, then the towed "
              "cases (cases on the LoadCases sheet are added).", "cases"),
    Parameter("ultimate factor", "dimensionless", "", 1.5,
              "Factor of safety, CS 29.303 (ultimate = factor x limit).", "cases",
              Bounds(1, 10)),
    Parameter("parachute area", "area", "m^2", 0.0,
              "Flat-plate area of the drogue parachute; 0 = no parachute.", "parachute",
              at_least(0)),
    Parameter("parachute opening factor", "dimensionless", "", 1.0,
              "Opening-load factor on the parachute drag (>= 1).", "parachute",
              Bounds(1, 10)),
    Parameter("parachute line direction", TEXT, "", "relative wind",
              "'relative wind' or 'fuselage axis'.", "parachute"),
    Parameter("previous envelope source", TEXT, "", "",
              "Where the PreviousEnvelope sheet comes from (report, loads model, issue), "
              "quoted beside the exceedance check.", "report"),
    Parameter("SFBM workbook", FLAG, "", "no",
              "Also write <input>-sfbm.xlsx: the SFBM of every case at every station in the "
              "report's units (the -sfbm.csv file always has them, in SI).", "report"),
    Parameter("hull stations", TEXT, "", "",
              "Comma-separated station ids for the 2-D envelopes (empty: three stations "
              "around the mast).", "report"),
    Parameter("hull pairs", TEXT, "", "Vy-Mz, Vz-My",
              "Comma-separated component pairs for the 2-D envelopes.", "report"),
    *NASTRAN_PARAMETERS,
)

#: Components of the PreviousEnvelope sheet: name, kind, unit, what it is.
_PREVIOUS = (
    ("Vx", "force", "N", "axial force Vx (> 0 tension)"),
    ("Vy", "force", "N", "shear force Vy (along +y)"),
    ("Vz", "force", "N", "shear force Vz (along +z)"),
    ("Mx", "moment", "N m", "torsion Mx (right-handed about +x)"),
    ("My", "moment", "N m", "bending moment My (about +y; > 0 puts the +z fibres in tension)"),
    ("Mz", "moment", "N m", "bending moment Mz (about +z; > 0 puts the -y fibres in tension)"),
)


def _previous_columns():
    """The min and max columns of every component of the previous design envelope."""
    typical = "Typical: of the order of the report's Envelope sheet."
    for name, kind, unit, what in _PREVIOUS:
        yield Column(f"{name} min", kind, unit,
                     help=f"Previous design envelope: smallest (most negative) LIMIT {what} at "
                          f"this station, same sign convention as the report. {typical}")
        yield Column(f"{name} max", kind, unit,
                     help=f"Previous design envelope: largest LIMIT {what} at this station, >= "
                          f"min. {typical}")


SHEETS = (
    TableSheet("AeroEnvelope", (
        Column("id", TEXT, help="Name of the point, used in the case ids and the LoadCases "
                                "sheet, e.g. A+B+ (alpha up, beta right) or CENTRE."),
        Column("alpha", "angle", "deg",
               help="Angle of attack of the point, positive nose up. Typical: -10 to +10 deg "
                    "(the multibody campaign's envelope).", bounds=TABLE_ANGLE),
        Column("beta", "angle", "deg",
               help="Sideslip of the point, positive with the wind from the right. Typical: "
                    "-15 to +15 deg.", bounds=TABLE_ANGLE),
    ), help="Points of the angle-of-attack / sideslip envelope (corners and centre).",
       max_rows=MAX_STATIONS, ids=("id",)),
    TableSheet("LoadCases", (
        Column("id", TEXT, help="Unique case id, printed on the reports, e.g. LC-SPECIAL-1."),
        Column("hook", TEXT,
               help="Hook-load direction: VERTICAL (along the earth vertical), AZ000, AZ045, "
                    "... (inclined from the vertical by 'hook angle from vertical' towards "
                    "azimuth 000 = aft, 090 = right), TOW (towed-flight equilibrium) or NONE (no "
                    "hook load); AXIAL is read as VERTICAL."),
        Column("aero", TEXT, help="An AeroEnvelope id, NONE (no aerodynamic load), or TRIM "
                                  "(the trimmed attitude's: only, and always, with hook TOW)."),
        Column("chute", FLAG, help="Parachute drag on: yes or no."),
        Column("description", TEXT, required=False, default="",
               help="Free text printed beside the case on the LoadCases sheet of the report."),
    ), help="Optional: cases listed by hand (added to the generated matrix). In all, at most "
       f"{MAX_LOAD_CASES:,} cases, and at most {MAX_SFBM_ROWS:,} cases x cut stations.",
       max_rows=MAX_LOAD_CASES, ids=("id",)),
    TableSheet("PreviousEnvelope", (
        Column("x", "length", "m",
               help="Station of the previous envelope, x positive aft, strictly increasing. "
                    "The report interpolates linearly between these stations (and marks the "
                    "cut stations it interpolated); outside them it does not compare. Typical: "
                    "the cut stations of the Stations sheet.", bounds=COORDINATE),
        *_previous_columns(),
    ), help="Optional: the previous design envelope (limit loads) for the exceedance check.",
       max_rows=MAX_STATIONS),
)

SECTION = Section("loads", parameters=PARAMETERS, sheets=SHEETS)

#: The Study parameter behind each setting the analysis may refuse while computing (none).
COMPUTE_FIELDS = {}

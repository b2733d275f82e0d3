"""What an input workbook contains: its sheets, columns and parameters, in one place.

The reader (:mod:`slingloads.io.common.workbook`), the study builder (:mod:`slingloads.io.study`)
and the blank template (:mod:`slingloads.io.template`) all follow these definitions, so the
template's explanations are always those the reader enforces.

Column headers carry their unit in square brackets, ``x [in]``, ``mass [lb]``; any unit of the
right kind is accepted (SI or US customary). Parameters on the ``Study`` sheet carry theirs in
the ``unit`` column.
"""

from __future__ import annotations

from dataclasses import dataclass

#: Kinds that are not physical quantities.
TEXT, FLAG, INTEGER = "text", "flag", "integer"


@dataclass(frozen=True)
class Column:
    """One column of a table sheet.

    Parameters
    ----------
    name : str
        Header text without the unit (matched case-insensitively).
    kind : str
        A quantity kind of :data:`slingloads.io.common.units.SI_UNITS`, or ``text``,
        ``flag``, ``integer``.
    unit : str
        Unit written in the template header (the user may change it to any unit of the kind).
    required : bool
        The column must be present and each row must fill it.
    default : object
        Value used when an optional cell is empty (SI).
    help : str
    """

    name: str
    kind: str
    unit: str = ""
    required: bool = True
    default: object = None
    help: str = ""

    @property
    def header(self):
        return f"{self.name} [{self.unit}]" if self.unit else self.name


@dataclass(frozen=True)
class TableSheet:
    """A sheet holding a table: header in row 1, one record per row below."""

    name: str
    columns: tuple
    required: bool = False
    help: str = ""


@dataclass(frozen=True)
class Parameter:
    """One row of the ``Study`` sheet: ``parameter | value | unit | description``.

    ``default`` is in the unit ``unit`` (converted on reading); ``None`` means required.
    """

    name: str
    kind: str
    unit: str = ""
    default: object = None
    help: str = ""
    section: str = "general"


@dataclass(frozen=True)
class Section:
    """Parameters and sheets that belong to one analysis."""

    name: str
    parameters: tuple = ()
    sheets: tuple = ()


STUDY_SHEET = "Study"
NOTE_COLUMNS = ("note", "notes", "comment", "comments", "source")

GENERAL = Section("general", parameters=(
    Parameter("study name", TEXT, "", "study", "Name printed on the reports."),
    Parameter("run loads", FLAG, "", "yes", "Run the structural loads analysis (SFBM)."),
    Parameter("run lateral", FLAG, "", "no",
              "Run the lateral-step pendulum study (sheets Lateral*)."),
    Parameter("run chute sizing", FLAG, "", "no",
              "Run the parachute sizing (sheets Chute*)."),
))

LOADS = Section("loads", parameters=(
    Parameter("airspeed EAS", "speed", "kt", 100.0,
              "Equivalent airspeed of the loads cases (paper: 100 KEAS).", "flight"),
    Parameter("density altitude", "length", "ft", 0.0,
              "ISA density altitude (paper: 0, 5000, 10000 ft).", "flight"),
    Parameter("hook load factor Nz", "dimensionless", "", 2.5,
              "CS-29.865(a): limit hook load = Nz x carried aircraft weight.", "hook"),
    Parameter("hook angle from mast", "angle", "deg", 30.0,
              "Inclination of the off-axis hook loads (CS-29.865: 30 deg unless a smaller "
              "angle is justified).", "hook"),
    Parameter("hook azimuths", INTEGER, "", 8,
              "Number of off-axis hook directions evenly spread in azimuth.", "hook"),
    Parameter("hook along mast axis", FLAG, "", "yes",
              "Include the hook load along the mast axis.", "hook"),
    Parameter("mast axis x", "dimensionless", "", 0.0, "Mast direction, x component.", "hook"),
    Parameter("mast axis y", "dimensionless", "", 0.0, "Mast direction, y component.", "hook"),
    Parameter("mast axis z", "dimensionless", "", 1.0, "Mast direction, z component.", "hook"),
    Parameter("generate case matrix", FLAG, "", "yes",
              "Generate hook direction x aero point x parachute on/off (cases on the "
              "LoadCases sheet are added).", "cases"),
    Parameter("ultimate factor", "dimensionless", "", 1.5,
              "Factor of safety, CS 29.303 (ultimate = factor x limit).", "cases"),
    Parameter("reference axis y", "length", "m", 0.0,
              "Butt line of the loads reference axis (parallel to x).", "airframe"),
    Parameter("reference axis z", "length", "m", 0.0,
              "Water line of the loads reference axis.", "airframe"),
    Parameter("fuselage reference area", "area", "m^2", 0.0,
              "Reference area of the FuselageAero coefficients (needed with that sheet).",
              "aero"),
    Parameter("fuselage reference length", "length", "m", 0.0,
              "Reference length of the FuselageAero moment coefficients.", "aero"),
    Parameter("fin area", "area", "m^2", 0.0, "Reference area of the FinAero table.", "aero"),
    Parameter("fin efficiency", "dimensionless", "", 0.5,
              "Share of the intact fin's side force kept by the cut-down fin (paper: ~0.5).",
              "aero"),
    Parameter("parachute area", "area", "m^2", 0.0,
              "Flat-plate area of the drogue parachute; 0 = no parachute.", "parachute"),
    Parameter("parachute wake ratio", "dimensionless", "", 0.95,
              "Dynamic pressure at the canopy / free stream (paper: 0.95).", "parachute"),
    Parameter("parachute line length", "length", "m", 10.0,
              "Line length from the fin attachment to the canopy.", "parachute"),
    Parameter("parachute opening factor", "dimensionless", "", 1.0,
              "Opening-load factor on the parachute drag (>= 1).", "parachute"),
    Parameter("parachute line direction", TEXT, "", "relative wind",
              "'relative wind' or 'fuselage axis'.", "parachute"),
    Parameter("hull stations", TEXT, "", "",
              "Comma-separated station ids for the 2-D envelopes (empty: three stations "
              "around the mast).", "report"),
    Parameter("hull pairs", TEXT, "", "Vy-Mz, Vz-My",
              "Comma-separated component pairs for the 2-D envelopes.", "report"),
), sheets=(
    TableSheet("MassItems", (
        Column("id", TEXT, help="Unique name of the mass item."),
        Column("description", TEXT, required=False, default="", help="Free text."),
        Column("mass", "mass", "kg", help="Mass, > 0."),
        Column("x", "length", "m", help="Fuselage station of the item's CG (x aft)."),
        Column("y", "length", "m", help="Butt line (y right)."),
        Column("z", "length", "m", help="Water line (z up)."),
        Column("Ixx", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG."),
        Column("Iyy", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG."),
        Column("Izz", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG."),
        Column("Ixy", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
        Column("Ixz", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
        Column("Iyz", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
    ), required=True, help="Lumped masses of the carried helicopter in its transport "
       "configuration."),
    TableSheet("Stations", (
        Column("id", TEXT, help="Station name, e.g. FS2300."),
        Column("x", "length", "m", help="Cut station x, strictly increasing."),
    ), required=True, help="Cut stations where internal loads are reported."),
    TableSheet("Hardpoints", (
        Column("id", TEXT, help="Unique name."),
        Column("kind", TEXT, help="hub | mast_foot | chute | fin_cp | aero_reference"),
        Column("x", "length", "m"),
        Column("y", "length", "m"),
        Column("z", "length", "m"),
        Column("weight", "dimensionless", "", False, 1.0,
               "Share weight of a mast foot in the rigid-body (RBE3-like) distribution."),
    ), required=True, help="Where external loads enter: rotor hub (hook), mast feet on the "
       "transmission deck, parachute attachment on the fin, fin centre of pressure, moment "
       "reference point of the fuselage aerodynamic coefficients."),
    TableSheet("AeroPoints", (
        Column("x", "length", "m", help="Point of the loads reference axis."),
        Column("weight", "dimensionless", "", help="Share of the fuselage aero load, > 0."),
    ), help="Optional: how the fuselage aerodynamic load is spread along the reference axis "
       "(default: mid-points between stations, equal weights)."),
    TableSheet("FuselageAero", (
        Column("alpha", "angle", "deg"), Column("beta", "angle", "deg"),
        Column("CD", "dimensionless"), Column("CY", "dimensionless"),
        Column("CL", "dimensionless"), Column("Cl", "dimensionless"),
        Column("Cm", "dimensionless"), Column("Cn", "dimensionless"),
    ), help="Fuselage coefficients on a full alpha x beta grid (conventions: docs/"
       "conventions.md). Never extrapolated."),
    TableSheet("FinAero", (
        Column("beta", "angle", "deg"), Column("CY", "dimensionless"),
    ), help="Intact fin side-force coefficient against sideslip, on 'fin area'."),
    TableSheet("ParachuteCD", (
        Column("alpha", "angle", "deg"), Column("CD", "dimensionless"),
    ), help="Optional parachute drag coefficient against canopy angle of attack "
       "(default: 0.95 within +-8 deg)."),
    TableSheet("AeroEnvelope", (
        Column("id", TEXT), Column("alpha", "angle", "deg"), Column("beta", "angle", "deg"),
    ), help="Points of the angle-of-attack / sideslip envelope (corners and centre)."),
    TableSheet("LoadCases", (
        Column("id", TEXT, help="Unique case id."),
        Column("hook", TEXT, help="AXIAL, AZ000, AZ045, ... or NONE."),
        Column("aero", TEXT, help="An AeroEnvelope id or NONE."),
        Column("chute", FLAG, help="Parachute drag on (yes/no)."),
        Column("description", TEXT, required=False, default=""),
    ), help="Optional: cases listed by hand (added to the generated matrix)."),
    TableSheet("PreviousEnvelope", (
        Column("x", "length", "m"),
        Column("Vx min", "force", "N"), Column("Vx max", "force", "N"),
        Column("Vy min", "force", "N"), Column("Vy max", "force", "N"),
        Column("Vz min", "force", "N"), Column("Vz max", "force", "N"),
        Column("Mx min", "moment", "N m"), Column("Mx max", "moment", "N m"),
        Column("My min", "moment", "N m"), Column("My max", "moment", "N m"),
        Column("Mz min", "moment", "N m"), Column("Mz max", "moment", "N m"),
    ), help="Optional: the previous design envelope (limit loads) for the exceedance check."),
))

#: Every section known to the reader, the template and the study builder.
SECTIONS = [GENERAL, LOADS]


def _other_sections():
    """Sections of the other analyses, defined in their own modules."""
    from slingloads.io.chute import schema as schema_chute
    from slingloads.io.lateral import schema as schema_lateral

    return [schema_lateral.SECTION, schema_chute.SECTION]


SECTIONS += _other_sections()


def all_parameters():
    """Every Study-sheet parameter by lower-case name."""
    return {p.name.lower(): p for s in SECTIONS for p in s.parameters}


def all_sheets():
    """Every table sheet by name."""
    return {t.name: t for s in SECTIONS for t in s.sheets}

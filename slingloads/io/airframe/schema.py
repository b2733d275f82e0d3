"""Study-sheet parameters and sheets of the airframe, which every analysis reads.

The carried helicopter's mass items, cut stations and hardpoints, the loads reference axis and
the mast axis, and the aerodynamic tables of the fuselage, the fin and the parachute with
their reference values. Conventions: ``docs/conventions.md``. Types:
:mod:`slingloads.io.common.schema`.
"""

from __future__ import annotations

from slingloads.io.common.schema import (
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
    MAX_AIRFRAME_SIZE,
    MAX_COORDINATE,
    MAX_MASS_ITEMS,
    MAX_STATIONS,
)

#: Bounds of every airframe coordinate: within MAX_COORDINATE of the datum.
COORDINATE = Bounds(-MAX_COORDINATE, MAX_COORDINATE, unit="m")
#: Bounds of a table's angle of attack or sideslip.
TABLE_ANGLE = Bounds(-180.0, 180.0, unit="deg")

#: Kinds of the Hardpoints rows.
HARDPOINT_KINDS = ("hub", "mast_foot", "chute", "fin_cp", "aero_reference", "htail_cp")

PARAMETERS = (
    Parameter("reference axis y", "length", "m", 0.0,
              "Butt line of the loads reference axis (parallel to x).", "airframe", COORDINATE),
    Parameter("reference axis z", "length", "m", 0.0,
              "Water line of the loads reference axis.", "airframe", COORDINATE),
    Parameter("mast axis x", "dimensionless", "", 0.0, "Mast direction, x component.", "hook"),
    Parameter("mast axis y", "dimensionless", "", 0.0, "Mast direction, y component.", "hook"),
    Parameter("mast axis z", "dimensionless", "", 1.0, "Mast direction, z component.", "hook"),
    Parameter("fuselage reference area", "area", "m^2", 0.0,
              "Reference area of the FuselageAero coefficients (needed with that sheet).",
              "aero", at_least(0)),
    Parameter("fuselage reference length", "length", "m", 0.0,
              "Reference length of the FuselageAero moment coefficients.", "aero",
              at_least(0)),
    Parameter("fin area", "area", "m^2", 0.0, "Reference area of the FinAero table.", "aero",
              at_least(0)),
    Parameter("fin efficiency", "dimensionless", "", 0.5,
              "Share of the intact fin's side force kept by the cut-down fin (paper: ~0.5).",
              "aero", Bounds(0, 1, lo_open=True)),
    Parameter("fuselage force axes", TEXT, "", "wind",
              "Frame of the FuselageAero force coefficients (docs/conventions.md section 3): "
              "'wind' (CD along the airflow, CY along the wind frame's y axis, CL normal to "
              "the airflow in the x-z plane, up), 'stability' (CD along the airflow's "
              "projection on the plane of symmetry, CY along body y, CL up) or 'body' "
              "(columns CX forward, CY right, CZ down). Converted to airframe axes. The "
              "generic sample tables are in wind axes.", "aero"),
    Parameter("fuselage moment axes", TEXT, "", "body",
              "Frame of the FuselageAero moment coefficients Cl, Cm, Cn: 'body' (Cl right "
              "side down, Cm nose up, Cn nose right), 'stability' or 'wind'.", "aero"),
    Parameter("fin axes", TEXT, "", "body",
              "Frame of the FinAero CY (at zero angle of attack): 'body' (along +y, normal "
              "to the fin) or 'wind' (normal to the airflow).", "aero"),
    Parameter("parachute table axes", TEXT, "", "wind",
              "Frame of the ParachuteCD table: 'wind' (column CD, along the canopy's "
              "relative wind) or 'canopy' (column CT, along the canopy axis, i.e. the line).",
              "parachute"),
    Parameter("parachute wake ratio", "dimensionless", "", 0.95,
              "Dynamic pressure at the canopy / free stream. It carries the 5 % wake loss, "
              "counted once: the default ParachuteCD is the canopy's free-stream CD 1.0, so "
              "0.95 x 1.0 = the paper's 0.95. Set 1 if your ParachuteCD already contains the "
              "wake loss.", "parachute", Bounds(0, 1, lo_open=True)),
    Parameter("parachute line length", "length", "m", 10.0,
              "Line length from the fin attachment to the canopy.", "parachute",
              Bounds(0, 1000, lo_open=True, unit="m")),
)

SHEETS = (
    TableSheet("MassItems", (
        Column("id", TEXT, help="Unique name of the mass item."),
        Column("description", TEXT, required=False, default="", help="Free text."),
        Column("mass", "mass", "kg", help="Mass, > 0.", bounds=above(0)),
        Column("x", "length", "m", help="Fuselage station of the item's CG (x aft).",
               bounds=COORDINATE),
        Column("y", "length", "m", help="Butt line (y right).", bounds=COORDINATE),
        Column("z", "length", "m", help="Water line (z up).", bounds=COORDINATE),
        Column("Ixx", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG.",
               at_least(0)),
        Column("Iyy", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG.",
               at_least(0)),
        Column("Izz", "inertia", "kg m^2", False, 0.0, "Own inertia about the item's CG.",
               at_least(0)),
        Column("Ixy", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
        Column("Ixz", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
        Column("Iyz", "inertia", "kg m^2", False, 0.0, "Product of inertia (tensor sign)."),
    ), required=True, help="Lumped masses of the carried helicopter in its transport "
       f"configuration. Items must fit in a box of {MAX_AIRFRAME_SIZE:g} m; an item farther "
       "from the loads reference axis than the airframe is long is flagged on the reports' "
       "Summary.",
       max_rows=MAX_MASS_ITEMS),
    TableSheet("Stations", (
        Column("id", TEXT, help="Station name, e.g. FS2300; ids must stay distinct once made "
                                "safe for file names (letters, digits, . _ - kept; "
                                "case ignored)."),
        Column("x", "length", "m", help="Cut station x, strictly increasing, within the x "
                                        "range of the mass items.", bounds=COORDINATE),
    ), required=True, help="Cut stations where internal loads are reported.",
       max_rows=MAX_STATIONS),
    TableSheet("Hardpoints", (
        Column("id", TEXT, help="Unique name."),
        Column("kind", TEXT, help="hub | mast_foot | chute | fin_cp | aero_reference | "
                                  "htail_cp"),
        Column("x", "length", "m", bounds=COORDINATE),
        Column("y", "length", "m", bounds=COORDINATE),
        Column("z", "length", "m", bounds=COORDINATE),
        Column("weight", "dimensionless", "", False, 1.0,
               "Share weight of a mast foot in the rigid-body (RBE3-like) distribution.",
               above(0)),
    ), required=True, help="Where external loads enter: rotor hub (hook), mast feet on the "
       "transmission deck, parachute attachment on the fin, fin centre of pressure, moment "
       "reference point of the fuselage aerodynamic coefficients, horizontal-tail centre of "
       "pressure (the multibody model's full-tail configuration). Every point but the "
       "aero_reference must lie within the airframe (x within the mass items' range, no "
       "farther from the loads reference axis than the airframe is long).",
       max_rows=MAX_STATIONS),
    TableSheet("AeroPoints", (
        Column("x", "length", "m", help="Point of the loads reference axis.",
               bounds=COORDINATE),
        Column("weight", "dimensionless", "", help="Share of the fuselage aero load, > 0.",
               bounds=above(0)),
    ), help="Optional: how the fuselage aerodynamic load is spread along the reference axis "
       "(default: mid-points between stations, equal weights).", max_rows=MAX_STATIONS),
    TableSheet("FuselageAero", (
        Column("alpha", "angle", "deg", bounds=TABLE_ANGLE),
        Column("beta", "angle", "deg", bounds=TABLE_ANGLE),
        Column("CD", "dimensionless", required=False,
               help="Drag (wind or stability axes)."),
        Column("CY", "dimensionless", help="Side force along the frame's y axis."),
        Column("CL", "dimensionless", required=False,
               help="Lift (wind or stability axes)."),
        Column("CX", "dimensionless", required=False, help="Body axes: along x forward."),
        Column("CZ", "dimensionless", required=False, help="Body axes: along z down."),
        Column("Cl", "dimensionless"), Column("Cm", "dimensionless"),
        Column("Cn", "dimensionless"),
    ), help="Fuselage coefficients on a full alpha x beta grid, in the frames declared by "
       "'fuselage force axes' (CD, CY, CL for wind or stability; CX, CY, CZ for body) and "
       "'fuselage moment axes' (docs/conventions.md section 3). Never extrapolated.",
       max_rows=MAX_AERO_ROWS),
    TableSheet("FinAero", (
        Column("beta", "angle", "deg", help="Strictly increasing.", bounds=TABLE_ANGLE),
        Column("CY", "dimensionless"),
    ), help="Intact fin side-force coefficient against sideslip, on 'fin area', in the frame "
       "of 'fin axes'.", max_rows=MAX_AERO_ROWS),
    TableSheet("ParachuteCD", (
        Column("alpha", "angle", "deg", help="Strictly increasing, including 0.",
               bounds=TABLE_ANGLE),
        Column("CD", "dimensionless", required=False,
               help="Free-stream drag along the canopy's relative wind ('wind' axes)."),
        Column("CT", "dimensionless", required=False,
               help="Free-stream force along the canopy axis ('canopy' axes)."),
    ), help="Optional parachute force coefficient against canopy angle of attack, free "
       "stream (the wake loss is in 'parachute wake ratio'; default: CD 1.0 within +-8 deg, "
       "times the wake ratio 0.95 = the paper's 0.95).", max_rows=MAX_AERO_ROWS),
)

SECTION = Section("airframe", parameters=PARAMETERS, sheets=SHEETS)

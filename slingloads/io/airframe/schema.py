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

#: Bounds of the force coefficient of a lifting surface on its own planform area (FinAero CY,
#: HTailAero CN): a flat plate square to the flow reaches about 1.2 (2.0 in two dimensions)
#: and an unflapped aerofoil stalls below 2, so |C| <= 3 leaves half as much again; a larger
#: value is a typing or reference-area mistake.
SURFACE_COEFFICIENT = Bounds(-3.0, 3.0)
#: Force coefficient of a flat plate square to the flow in two dimensions (the largest of a
#: bluff body's); the FuselageAero force areas are bounded by a square plate as long as the
#: airframe at this coefficient.
PLATE_FORCE_COEFFICIENT = 2.0

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

_POSITION = ("Positions are in airframe axes from the airframe datum (docs/conventions.md): "
             "x aft, y right, z up.")

SHEETS = (
    TableSheet("MassItems", (
        Column("id", TEXT, help="Unique name of the mass item, e.g. MGB."),
        Column("description", TEXT, required=False, default="",
               help="Free text, e.g. 'main gearbox'; printed on the reports, not used in the "
                    "computation."),
        Column("mass", "mass", "kg",
               help="Mass of the item, > 0. Typical: 25 to 250 kg per item on a 2.9 t light "
                    "twin; the items sum to the aircraft mass in its transport configuration.",
               bounds=above(0)),
        Column("x", "length", "m",
               help="Fuselage station of the item's CG: x positive aft from the airframe "
                    "datum. Typical: 0.8 m (nose) to 10.8 m (fin) on an 11 m fuselage.",
               bounds=COORDINATE),
        Column("y", "length", "m",
               help="Butt line of the item's CG: y positive to the right (pilot's right) of "
                    "the datum. Typical: 0 on the centre line, +-0.35 m for side-by-side "
                    "engines.", bounds=COORDINATE),
        Column("z", "length", "m",
               help="Water line of the item's CG: z positive up from the datum. Typical: 0 "
                    "(skid tubes) to 2.2 m (rotor hub).", bounds=COORDINATE),
        Column("Ixx", "inertia", "kg m^2", False, 0.0,
               "Own moment of inertia of the item about the x axis through its OWN CG (the "
               "offset from the aircraft CG is added by slingloads), >= 0; 0 for a point mass. "
               "An item's own moments are a body's: none larger than the sum of the other two "
               "(Iyy + Izz - Ixx = 2 integral(x^2 dm) >= 0; 1 % allowed for rounding), so "
               "give all three. Typical: 0 to 50 kg m^2 (a gearbox).", at_least(0)),
        Column("Iyy", "inertia", "kg m^2", False, 0.0,
               "Own moment of inertia about the y axis through the item's own CG, >= 0; 0 for a "
               "point mass; at most Ixx + Izz. Typical: 0 to 50 kg m^2.", at_least(0)),
        Column("Izz", "inertia", "kg m^2", False, 0.0,
               "Own moment of inertia about the z axis through the item's own CG, >= 0; 0 for a "
               "point mass; at most Ixx + Iyy (an item flat in the x-y plane has Izz = Ixx + "
               "Iyy). Typical: 0 to 50 kg m^2.", at_least(0)),
        Column("Ixy", "inertia", "kg m^2", False, 0.0,
               "Product of inertia about the item's own CG, tensor sign: the tensor's xy term "
               "= -integral(x y dm). Typical: 0 (item symmetric about its own axes)."),
        Column("Ixz", "inertia", "kg m^2", False, 0.0,
               "Product of inertia about the item's own CG, tensor sign: -integral(x z dm). "
               "Typical: 0."),
        Column("Iyz", "inertia", "kg m^2", False, 0.0,
               "Product of inertia about the item's own CG, tensor sign: -integral(y z dm). "
               "Typical: 0."),
    ), required=True, help="Lumped masses of the carried helicopter in its transport "
       "configuration. " + _POSITION + f" Items must fit in a box of {MAX_AIRFRAME_SIZE:g} m; "
       "an item farther from the loads reference axis than the airframe is long is flagged on "
       "the reports' Summary.",
       max_rows=MAX_MASS_ITEMS, ids=("id",)),
    TableSheet("Stations", (
        Column("id", TEXT, help="Station name printed on the reports, e.g. FS0161 (fuselage "
                                "station 161 in); ids must stay distinct once made safe for "
                                "file names (letters, digits, . _ - kept; case ignored)."),
        Column("x", "length", "m",
               help="Cut station: x positive aft from the airframe datum, strictly increasing "
                    "down the sheet. The internal loads are those of the part aft of the cut "
                    "on the part forward of it; a load exactly at a cut belongs to the forward "
                    "part. Within the x range of the mass items. Typical: 20 to 30 cuts from "
                    "nose to tail, 0.4 m apart.", bounds=COORDINATE),
    ), required=True, help="Cut stations where internal loads are reported.",
       max_rows=MAX_STATIONS, ids=("id",)),
    TableSheet("Hardpoints", (
        Column("id", TEXT, help="Unique name, e.g. HUB, MAST_FL (mast foot front left)."),
        Column("kind", TEXT,
               help="What the point is: hub (rotor hub, where the hook load acts) | mast_foot "
                    "(mast attachment on the transmission deck, one row per foot) | chute "
                    "(parachute attachment on the fin) | fin_cp (fin centre of pressure) | "
                    "aero_reference (moment reference point of the FuselageAero "
                    "coefficients) | htail_cp (horizontal-tail centre of pressure, for the "
                    "multibody model's full-tail configuration)."),
        Column("x", "length", "m",
               help="Fuselage station of the point, x positive aft. Typical: hub 4.3 m, fin "
                    "10.5 m on an 11 m fuselage.", bounds=COORDINATE),
        Column("y", "length", "m",
               help="Butt line of the point, y positive right. Typical: 0, +-0.35 m for mast "
                    "feet.", bounds=COORDINATE),
        Column("z", "length", "m",
               help="Water line of the point, z positive up. Typical: hub 2.2 m, mast feet "
                    "1.55 m.", bounds=COORDINATE),
        Column("weight", "dimensionless", "", False, 1.0,
               "Mast feet only: share weight of the foot in the rigid-body (RBE3-like) "
               "distribution of the hub load, > 0 (docs/conventions.md section 4). Typical: 1 "
               "on every foot (equal shares).", above(0)),
    ), required=True, help="Where external loads enter: rotor hub (hook), mast feet on the "
       "transmission deck, parachute attachment on the fin, fin centre of pressure, moment "
       "reference point of the fuselage aerodynamic coefficients, horizontal-tail centre of "
       "pressure (the multibody model's full-tail configuration). Every point but the "
       "aero_reference must lie within the airframe (x within the mass items' range, no "
       "farther from the loads reference axis than the airframe is long). " + _POSITION,
       max_rows=MAX_STATIONS, ids=("id",)),
    TableSheet("AeroPoints", (
        Column("x", "length", "m",
               help="Point of the loads reference axis (y0, z0 of the Study sheet) that takes "
                    "a share of the fuselage aerodynamic load, x positive aft. Typical: the "
                    "mid-points between cut stations.", bounds=COORDINATE),
        Column("weight", "dimensionless", "",
               help="Share of the fuselage aerodynamic load taken at this point, > 0 "
                    "(normalised over the sheet). Typical: 1 on every point.",
               bounds=above(0)),
    ), help="Optional: how the fuselage aerodynamic load is spread along the reference axis "
       "(default: mid-points between stations, equal weights).", max_rows=MAX_STATIONS),
    TableSheet("FuselageAero", (
        Column("alpha", "angle", "deg",
               help="Angle of attack, positive nose up (relative wind from below). A full "
                    "alpha x beta grid. Typical: -40 to +40 deg (generic HC1 tables).",
               bounds=TABLE_ANGLE),
        Column("beta", "angle", "deg",
               help="Sideslip, positive with the wind from the right. Typical: -180 to +180 "
                    "deg.", bounds=TABLE_ANGLE),
        Column("CD", "dimensionless", required=False,
               help="DRAG coefficient on 'fuselage reference area' ('fuselage force axes' wind "
                    "or stability): along the airflow (downstream), >= 0 in wind axes (a body "
                    "without propulsion takes energy from the flow). Typical (generic HC1 "
                    "tables of slingloads/data, wind axes): 0.30 at alpha = beta = 0, 2.0 "
                    "side-on (beta 90 deg)."),
        Column("CY", "dimensionless",
               help="Side-force coefficient on 'fuselage reference area', along the y axis of "
                    "the declared force frame (positive towards the right side): wind from the "
                    "right (beta > 0) pushes left, CY < 0. Typical (HC1, wind axes): -0.35 at "
                    "beta 10 deg."),
        Column("CL", "dimensionless", required=False,
               help="LIFT coefficient (upper-case L) on 'fuselage reference area' (wind or "
                    "stability axes): normal to the airflow in the plane of symmetry, positive "
                    "upwards. Typical (HC1): 0.05 at alpha 0, 0.20 at alpha 10 deg. Not the "
                    "rolling moment: that is Cl, lower-case l."),
        Column("CX", "dimensionless", required=False,
               help="Body axes only ('fuselage force axes' = body): force coefficient along "
                    "x_B, FORWARD (an axial force CA rearwards is CX = -CA). Typical: -0.30 at "
                    "alpha = beta = 0 (the drag)."),
        Column("CZ", "dimensionless", required=False,
               help="Body axes only: force coefficient along z_B, DOWN (a normal force CN "
                    "upwards is CZ = -CN). Typical: -0.05 at alpha 0 (a small lift)."),
        Column("Cl", "dimensionless",
               help="ROLLING-moment coefficient (lower-case l) on 'fuselage reference area' x "
                    "'fuselage reference length', about the x axis of 'fuselage moment axes' "
                    "through the aero_reference hardpoint; in body axes positive right side "
                    "down. Typical (HC1, body axes): -0.009 at beta 10 deg."),
        Column("Cm", "dimensionless",
               help="Pitching-moment coefficient (area x length) about the y axis of the "
                    "moment frame through the aero_reference hardpoint, positive nose up. "
                    "Typical (HC1): -0.02 at alpha 0, +0.08 at alpha 10 deg."),
        Column("Cn", "dimensionless",
               help="Yawing-moment coefficient (area x length) about the z axis of the moment "
                    "frame through the aero_reference hardpoint; in body axes positive nose "
                    "right, and dCn/dbeta > 0 is directionally stable. Typical (HC1): -0.064 at "
                    "beta 10 deg (a fuselage alone is unstable)."),
    ), help="Fuselage coefficients on a full alpha x beta grid, in the frames declared by "
       "'fuselage force axes' (CD, CY, CL for wind or stability; CX, CY, CZ for body) and "
       "'fuselage moment axes' (docs/conventions.md section 3). Never extrapolated. Any "
       "reference area and length may be used (D/q tables on 1 ft^2 too), so the bound is on "
       "the force area: |coefficient| x 'fuselage reference area' at most 2 L^2, the force on "
       "a flat plate L x L square to the flow (force coefficient 2), L the airframe's length "
       "(the x span of the mass items and hardpoints); a moment coefficient x area x "
       "reference length at most 2 L^2 times the farthest airframe point from the "
       "aero_reference hardpoint.",
       max_rows=MAX_AERO_ROWS),
    TableSheet("FinAero", (
        Column("beta", "angle", "deg",
               help="Sideslip, positive with the wind from the right, strictly increasing. "
                    "Typical: -180 to +180 deg.", bounds=TABLE_ANGLE),
        Column("CY", "dimensionless",
               help="Side-force coefficient of the INTACT fin on 'fin area', acting at the "
                    "fin_cp hardpoint (the cut-down fin keeps 'fin efficiency' of it): along +y "
                    "normal to the fin ('fin axes' body) or along y_W normal to the airflow "
                    "(wind). A stabilising fin has CY < 0 for beta > 0. Typical (HC1, body "
                    "axes): -0.53 at beta 10 deg, -0.86 at 20 deg, then stall. Within "
                    "[-3, 3] on the fin's own area: a flat plate square to the flow reaches "
                    "about 1.2 (2.0 in two dimensions).", bounds=SURFACE_COEFFICIENT),
    ), help="Intact fin side-force coefficient against sideslip, on 'fin area' (the fin's "
       "planform area), in the frame of 'fin axes'.", max_rows=MAX_AERO_ROWS),
    TableSheet("ParachuteCD", (
        Column("alpha", "angle", "deg",
               help="Angle of attack of the canopy (between its axis and the relative wind), "
                    "strictly increasing, covering 0 (the canopy trails at 0 in steady "
                    "flight): from a negative to a positive alpha, or with a row at 0; the "
                    "coefficient at 0 is then read or interpolated linearly. Typical: -30 to "
                    "+30 deg (the default table: -8 and +8 deg).",
               bounds=TABLE_ANGLE),
        Column("CD", "dimensionless", required=False,
               help="Free-stream drag coefficient on the flat-plate area ('parachute area'), "
                    "along the canopy's relative wind ('parachute table axes' = wind). "
                    "Typical: 1.0 within +-8 deg (the paper's 0.95 includes the 5 % wake loss, "
                    "carried by 'parachute wake ratio')."),
        Column("CT", "dimensionless", required=False,
               help="Free-stream force coefficient along the canopy axis ('parachute table "
                    "axes' = canopy), on the flat-plate area. Typical: 1.0 near 0 deg."),
    ), help="Optional parachute force coefficient against canopy angle of attack, free "
       "stream (the wake loss is in 'parachute wake ratio'; default: CD 1.0 within +-8 deg, "
       "times the wake ratio 0.95 = the paper's 0.95).", max_rows=MAX_AERO_ROWS),
)

SECTION = Section("airframe", parameters=PARAMETERS, sheets=SHEETS)

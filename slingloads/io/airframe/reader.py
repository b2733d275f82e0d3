"""Read the airframe sheets every analysis uses (see :mod:`slingloads.io.airframe.schema`).

:func:`read_airframe` builds the :class:`~slingloads.models.airframe.Airframe` (mass items,
cut stations, hardpoints, aerodynamic load points) of every workbook; the aerodynamic tables
are read by the analyses that need them (:func:`read_fuselage_aero`, :func:`read_fin_aero`,
:func:`read_parachute_cd`, :func:`read_parachute`). Every value is SI after reading; every bad
value raises :class:`~slingloads.errors.InputError` naming the file, sheet, cell, value and
rule.
"""

from __future__ import annotations

import numpy as np

from slingloads.errors import InputError
from slingloads.io.airframe.schema import HARDPOINT_KINDS, PLATE_FORCE_COEFFICIENT, SHEETS
from slingloads.io.common.atomic import safe_file_part
from slingloads.io.common.locate import Place, column_quantity, located, quantity, quantity_range
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.common.table import cell_name
from slingloads.limits import MAX_AIRFRAME_SIZE
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import (
    FIN_AXES,
    FORCE_AXES,
    MOMENT_AXES,
    Fin,
    FuselageAero,
    fuselage_columns,
)
from slingloads.models.airframe import Airframe, Hardpoints, MassItems
from slingloads.models.parachute import PARACHUTE_AXES, PARACHUTE_CD_MAX, Parachute

#: Valid values of each choice row of the airframe's Study rows (case ignored), checked
#: with the other Study rows (:func:`slingloads.io.study.read_study`).
CHOICES = {
    "fuselage force axes": tuple(FORCE_AXES),
    "fuselage moment axes": MOMENT_AXES,
    "fin axes": FIN_AXES,
    "parachute table axes": tuple(PARACHUTE_AXES),
}

_SPEC = {s.name: s for s in SHEETS}

#: Study parameters of the parachute read with its CD table, by Parachute argument.
PARACHUTE_PARAMETERS = {"parachute wake ratio": "wake_ratio",
                        "parachute line length": "line_length"}


def read_airframe(reader, params):
    """The airframe of the workbook, and its hardpoints by kind.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
        Study-sheet parameters (reference and mast axes, study name).

    Returns
    -------
    airframe : Airframe
    points : dict
        Hardpoint position by kind (``hub``, ``mast_foot``, ``chute``, ``fin_cp``,
        ``aero_reference``, ``htail_cp``: the first row of that kind, or None) [m],
        ``chute_row``: the 0-based row of the chute hardpoint, or None, and ``rows``: the
        0-based rows of each kind (to locate errors on derived quantities).

    Raises
    ------
    InputError
        At the cell of the bad value. Implausible but possible geometry (a mass item far to
        the side, a cut station outside the load points) is added to ``reader.warnings``.
    """
    items, items_t = _mass_items(reader)
    stations = reader.table(_SPEC["Stations"])
    _check_file_names(stations, "id", "station")
    x = stations["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            rule = ("cut stations must not repeat" if x[i] == x[i - 1]
                    else "cut stations must be sorted by increasing x")
            raise stations.error("x", i, rule)
    axis = (params("reference axis y"), params("reference axis z"))
    mast = _mast_axis(params)
    _mass_item_warnings(reader, items_t, items, axis)
    hp_t, points = _hardpoint_rows(reader, params, items_t, items, axis)
    aero_points, aero_weights = _aero_points(reader, params, items_t, items, axis)
    with located(hp_t, {"mast_weights": "weight"}):
        hardpoints = Hardpoints(
            hub=points["hub"][0][1],
            mast_feet=np.array([p[1] for p in points["mast_foot"]]),
            mast_weights=np.array([p[2] for p in points["mast_foot"]]),
            mast_axis=mast,
            chute=points["chute"][0][1] if points["chute"] else None,
            mast_feet_ids=tuple(p[0] for p in points["mast_foot"]),
        )
    with located(stations, {"stations": "x"}):
        airframe = Airframe(items, x, hardpoints, axis, tuple(stations["id"]), aero_points,
                            aero_weights, name=str(params("study name")))
    _check_stations_span(reader, stations, items_t, hp_t, airframe)
    refs = {k: (v[0][1] if v else None) for k, v in points.items()}
    refs["chute_row"] = points["chute"][0][3] if points["chute"] else None
    refs["rows"] = {k: [p[3] for p in v] for k, v in points.items()}
    return airframe, refs


def _mast_axis(params):
    """The mast direction from the Study sheet: not zero, not along the fuselage x axis."""
    names = ("mast axis x", "mast axis y", "mast axis z")
    mast = np.array([params(n) for n in names])
    norm = float(np.linalg.norm(mast))
    given = [n for n in names if params.cell(n)] or ["mast axis z"]
    if norm == 0:
        raise params.error(given[-1], "the mast axis ('mast axis x', 'mast axis y', 'mast "
                           "axis z') must not be the zero vector")
    if np.linalg.norm(mast[1:]) <= 1e-9 * norm:
        raise params.error("mast axis x", "the mast axis must not be parallel to the "
                           "fuselage x axis (give its y or z component)")
    return mast


def _check_file_names(table, column, what):
    """Ids that name report files must stay distinct once made file-name safe."""
    seen = {}
    for i, text in enumerate(table[column]):
        key = safe_file_part(text).casefold()
        if key in seen:
            j = seen[key]
            raise table.error(column, i, f"{what} ids {table[column][j]!r} "
                              f"({table.cell(column, j)}) and this one give the same report "
                              f"file name part {safe_file_part(text)!r} (only letters, "
                              "digits, '.', '_' and '-' are kept, and case is ignored): "
                              "rename one")
        seen[key] = i


def _check_stations_span(reader, stations, items_t, hp_t, airframe):
    """A cut station far outside the load points is refused; one just outside (where the
    internal loads are zero) is flagged."""
    xs = [airframe.mass_items.position[:, 0], airframe.hardpoints.mast_feet[:, 0],
          [airframe.hardpoints.hub[0]], airframe.aero_points]
    if airframe.hardpoints.chute is not None:
        xs.append([airframe.hardpoints.chute[0]])
    span = np.concatenate([np.ravel(v) for v in xs])
    lo, hi = float(span.min()), float(span.max())
    reach = max(hi - lo, 1.0)
    outside = []
    for i, x in enumerate(stations["x"]):
        if x < lo - reach or x > hi + reach:
            raise stations.error("x", i, (
                f"cut station lies far outside the airframe: the load points (mass items, "
                f"hardpoints, aerodynamic points) span x = "
                f"{quantity_range(lo, hi, stations.units.get('x'), 'length')} and a cut more "
                f"than the airframe length "
                f"({column_quantity(stations, 'x', reach, 'length')}) beyond them is refused "
                "(check the unit of the header)"))
        if not lo <= x <= hi:
            outside.append(f"{stations['id'][i]} ({stations.cell('x', i)})")
    if outside:
        reader.warnings.append(
            f"cut station(s) {', '.join(outside[:10])}{' ...' if len(outside) > 10 else ''} "
            f"lie outside the span of the load points x = [{lo:.4g}, {hi:.4g}] m: their "
            "internal loads are zero")


def _mass_items(reader):
    items_t = reader.table(_SPEC["MassItems"])
    masses = items_t["mass"]
    inertia = np.zeros((len(masses), 3, 3))
    present = []
    for (a, b), name in {(0, 0): "Ixx", (1, 1): "Iyy", (2, 2): "Izz", (0, 1): "Ixy",
                         (0, 2): "Ixz", (1, 2): "Iyz"}.items():
        if items_t.has(name):
            inertia[:, a, b] = inertia[:, b, a] = items_t[name]
            present.append(name)
    position = np.column_stack([items_t["x"], items_t["y"], items_t["z"]])
    _check_extent(items_t, position)
    fields = {"mass": "mass", "position": "x", "inertia": present[0] if present else "mass"}
    with located(items_t, fields):
        items = MassItems(tuple(items_t["id"]), masses, position, inertia,
                          tuple(items_t["description"]) if items_t.has("description") else ())
    if items.total_mass < MIN_TOTAL_MASS:
        raise items_t.error("mass", int(np.argmax(masses)), (
            f"the mass items weigh {column_quantity(items_t, 'mass', items.total_mass, 'mass', 3)}"
            f" in all, less than the {MIN_TOTAL_MASS:g} kg "
            f"({column_quantity(items_t, 'mass', MIN_TOTAL_MASS, 'mass', 3)}) of any aircraft "
            "(check the header's unit)"))
    _check_rigid_inertia(items_t, items)
    return items, items_t


#: Smallest total mass of the mass items. [kg]
MIN_TOTAL_MASS = 1.0


def _check_rigid_inertia(items_t, items):
    """The mass items must have inertia about every axis through their CG, else inertia
    relief cannot balance a moment about that axis (the loads would not close)."""
    tensor = items.inertia_about_cg
    values, vectors = np.linalg.eigh(tensor)
    if values[0] <= 1e-9 * max(values[-1], 1e-300):
        axis = vectors[:, 0] * np.sign(vectors[np.argmax(np.abs(vectors[:, 0])), 0])
        names = [c for c in ("Ixx", "Iyy", "Izz") if items_t.has(c)]
        cell = items_t.cell(names[0], 0) if names else cell_name(1, len(items_t.cells) + 1)
        raise InputError(f"the mass items have no inertia about the axis "
                         f"({axis[0]:.3g}, {axis[1]:.3g}, {axis[2]:.3g}) through their CG (all "
                         "on one line, without own inertias): inertia relief cannot balance a "
                         "moment about it; give the items their own inertias (Ixx, Iyy, Izz "
                         "columns) or their true positions", file=items_t.file,
                         sheet=items_t.sheet, cell=cell)


def _check_extent(items_t, position):
    """The mass items fit in a box of MAX_AIRFRAME_SIZE; the item farthest from the median
    along the offending axis is blamed."""
    for k, column in enumerate("xyz"):
        values = position[:, k]
        if values.max() - values.min() > MAX_AIRFRAME_SIZE:
            median = float(np.median(values))
            i = int(np.argmax(np.abs(values - median)))
            size = values.max() - values.min()
            raise items_t.error(column, i, (
                f"mass items span {column_quantity(items_t, column, size, 'length')} along "
                f"{column}, more than the {MAX_AIRFRAME_SIZE:g} m "
                f"({column_quantity(items_t, column, MAX_AIRFRAME_SIZE, 'length')}) an "
                "airframe may measure: this item lies far outside the others (check its value "
                "and the header's unit)"))


def _hardpoint_rows(reader, params, items_t, items, axis):
    """The Hardpoints table and its rows by kind: ``{kind: [(id, position, weight, row)]}``."""
    hp_t = reader.table(_SPEC["Hardpoints"])
    points = {k: [] for k in HARDPOINT_KINDS}
    for i, kind in enumerate(hp_t["kind"]):
        k = kind.strip().lower()
        if k not in HARDPOINT_KINDS:
            raise hp_t.error("kind", i, f"unknown hardpoint kind; valid kinds are "
                             f"{list(HARDPOINT_KINDS)}")
        p = np.array([hp_t["x"][i], hp_t["y"][i], hp_t["z"][i]])
        if k != "aero_reference":
            _check_inside(params, items_t, items, axis, hp_t, i,
                          f"hardpoint {hp_t['id'][i]!r}", p)
        w = hp_t["weight"][i] if hp_t.has("weight") else 1.0
        points[k].append((hp_t["id"][i], p, w, i))
    for kind, lo, hi in (("hub", 1, 1), ("mast_foot", 1, None), ("chute", 0, 1),
                         ("fin_cp", 0, 1), ("aero_reference", 0, 1), ("htail_cp", 0, 1)):
        n = len(points[kind])
        if n < lo or (hi is not None and n > hi):
            want = f"exactly {lo}" if lo == hi else (f"at least {lo}" if hi is None
                                                    else f"at most {hi}")
            rule = f"the Hardpoints sheet needs {want} row(s) of kind {kind!r} (it has {n})"
            if hi is not None and n > hi:  # at the first row too many
                raise hp_t.error("kind", points[kind][hi][3], rule)
            raise reader.error(rule, None, hp_t.sheet, "B1")
    return hp_t, points


def _check_inside(params, items_t, items, axis, table, i, label, point):
    """A point of row ``i`` of ``table`` (Hardpoints, AeroPoints) lies inside the airframe
    (the rule of :func:`~slingloads.models.airframe.check_inside`), else an error at the cell
    to change, with the value as written and the mass items' range in that cell's unit.

    Inside means: x within the mass items' x range (where the beam exists), and a distance
    from the loads reference axis no larger than that range (at least 1 m).
    """
    x = items.position[:, 0]
    lo, hi = int(np.argmin(x)), int(np.argmax(x))
    if not x[lo] <= point[0] <= x[hi]:
        where = quantity_range(x[lo], x[hi], table.units.get("x"), "length")
        if x[lo] == x[hi]:
            rule = (f"{label} lies outside the airframe: the mass items all lie at x = "
                    f"{column_quantity(table, 'x', x[lo], 'length')} ({items_t.sheet} "
                    f"{items_t.cell('x', lo)}{' ...' if len(x) > 1 else ''}), so the airframe "
                    "has no length along x for the loads; give the mass items along the "
                    "airframe (or check this x and the headers' units)")
        else:
            rule = (f"{label} lies outside the airframe: x must lie within the mass items' x "
                    f"range {where} ({items_t.sheet} {items_t.cell('x', lo)} to "
                    f"{items_t.cell('x', hi)}); check the value and the headers' units")
        raise table.error("x", i, rule)
    if not (table.has("y") and table.has("z")):
        return
    reach = max(float(x[hi] - x[lo]), 1.0)
    dy, dz = point[1] - axis[0], point[2] - axis[1]
    if np.hypot(dy, dz) > reach:
        column = "y" if abs(dy) >= abs(dz) else "z"
        axis_text = ", ".join(f"{n!r} {params.quantity(n, v)}" for n, v in
                              (("reference axis y", axis[0]), ("reference axis z", axis[1])))
        raise table.error(column, i, (
            f"{label} lies outside the airframe: it lies "
            f"{column_quantity(table, column, np.hypot(dy, dz), 'length')} from the loads "
            f"reference axis ({axis_text}), more than the airframe length "
            f"{column_quantity(table, column, reach, 'length')} (the mass items' x extent, at "
            f"least 1 m); check the value and the headers' units"))


def _aero_points(reader, params, items_t, items, axis):
    """The optional AeroPoints sheet: stations and weights, or (None, None)."""
    if not reader.has_sheet("AeroPoints"):
        return None, None
    ap = reader.table(_SPEC["AeroPoints"])
    aero_points, aero_weights = ap["x"], ap["weight"]
    for i, xa in enumerate(aero_points):
        _check_inside(params, items_t, items, axis, ap, i, f"aerodynamic point {i + 1}",
                      np.array([xa, axis[0], axis[1]]))
    return aero_points, aero_weights


def _mass_item_warnings(reader, items_t, items, axis):
    """Flag mass items farther from the loads reference axis than the airframe is long."""
    x = items.position[:, 0]
    reach = max(float(x.max() - x.min()), 1.0)
    distance = np.hypot(items.position[:, 1] - axis[0], items.position[:, 2] - axis[1])
    far = np.flatnonzero(distance > reach)
    if far.size:
        names = ", ".join(f"{items_t['id'][i]} ({items_t.cell('y', i)})" for i in far[:10])
        reader.warnings.append(
            f"mass item(s) {names}{' ...' if far.size > 10 else ''} lie farther from the loads "
            f"reference axis than the airframe is long ({reach:.4g} m): check their y and z")


def read_fuselage_aero(reader, params, refs):
    """The FuselageAero sheet with its reference area, length and point, or None if absent.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
        Study-sheet parameters ('fuselage reference area', 'fuselage reference length').
    refs : dict
        Hardpoints by kind (``refs["aero_reference"]``: moment reference point [m]).

    Returns
    -------
    FuselageAero or None
    """
    if not reader.has_sheet("FuselageAero"):
        return None
    t = reader.table(_SPEC["FuselageAero"])
    if refs["aero_reference"] is None:
        raise reader.error("the FuselageAero sheet needs a Hardpoints row of kind "
                           "'aero_reference' (moment reference point)", sheet="Hardpoints",
                           cell="B1")
    area = params.positive("fuselage reference area")
    length = params.positive("fuselage reference length")
    force_axes = params.choice("fuselage force axes", CHOICES)
    moment_axes = params.choice("fuselage moment axes", CHOICES)
    columns = fuselage_columns(force_axes)
    _columns_match(reader, t, columns, ("CD", "CL", "CX", "CZ"),
                   f"'fuselage force axes' is {force_axes!r}")
    t.require_filled(columns, "the table needs every coefficient of its frame at every "
                     "(alpha, beta) point")
    _check_full_grid(t)
    _check_force_areas(reader, t, columns, force_axes, area, length, refs)
    with located(t):
        table = Table2D.from_long(t["alpha"], t["beta"], {c: t[c] for c in columns})
        return FuselageAero(table, area, length, refs["aero_reference"], force_axes,
                            moment_axes)


def _check_force_areas(reader, t, columns, force_axes, area, length, refs):
    """Bounds of the FuselageAero coefficients, at the cell of the first that breaks one.

    The coefficients may be on any reference area and length (D/q tables on 1 ft^2 too), so
    the bounds are on what does not depend on that choice: no force area |C| x S above that
    of a flat plate L x L square to the flow (force coefficient
    :data:`~slingloads.io.airframe.schema.PLATE_FORCE_COEFFICIENT`), L the airframe's length
    (the x span of the mass items and hardpoints, at least 1 m), and no moment |C| x S x l
    above that force times the distance from the aero_reference hardpoint to the farthest
    airframe point. In wind axes the drag CD is >= 0: a body without propulsion takes energy
    from the flow (the drag force is along the airflow)."""
    if force_axes == "wind" and "CD" in columns:
        negative = np.flatnonzero(t["CD"] < 0)
        if negative.size:
            raise t.error("CD", int(negative[0]), "the drag coefficient CD must be >= 0 in "
                          "wind axes (a body without propulsion takes energy from the flow: "
                          "its drag is along the airflow)")
    items = reader.table(_SPEC["MassItems"])
    points = [np.column_stack([items["x"], items["y"], items["z"]])]
    points += [np.atleast_2d(p) for k, p in refs.items()
               if k in HARDPOINT_KINDS and p is not None]
    points = np.concatenate(points)
    size = max(float(np.ptp(points[:, 0])), 1.0)
    force_area = PLATE_FORCE_COEFFICIENT * size**2
    arm = max(float(np.linalg.norm(points - refs["aero_reference"], axis=1).max()), size)
    for column in columns:
        values = np.abs(t[column])
        i = int(np.argmax(values))
        moment = column in ("Cl", "Cm", "Cn")
        got = values[i] * area * (length if moment else 1.0)
        limit = force_area * (arm if moment else 1.0)
        if got > limit:
            plate = (f"a flat plate as long as the airframe ({size:.4g} m) and as wide, "
                     f"square to the flow (force coefficient {PLATE_FORCE_COEFFICIENT:g}): "
                     f"{force_area:.4g} m^2")
            what = (f"|{column}| x 'fuselage reference area' x 'fuselage reference length' "
                    f"= {got:.4g} m^3 exceeds {limit:.4g} m^3, the force area of {plate} at "
                    f"{arm:.4g} m (the farthest airframe point from the aero_reference "
                    "hardpoint)") if moment else (
                    f"the force area |{column}| x 'fuselage reference area' = {got:.4g} m^2 "
                    f"exceeds that of {plate}")
            raise t.error(column, i, f"{what}: no airframe makes that much; check the "
                          "coefficient and the reference area and length")


def _columns_match(reader, table, needed, optional, why):
    """Each column of ``needed`` present, none of ``optional`` outside it (the frame's) with
    a value in it: a column the template lists for another frame and left empty is
    ignored."""
    for name in needed:
        if not table.has(name):
            raise reader.error(f"missing column {name!r}: {why}, whose columns are "
                               f"{list(needed)}", sheet=table.sheet, cell="A1")
    for name in optional:
        if table.has(name) and name not in needed and not _left_empty(table, name):
            raise reader.error(f"column {name!r} does not belong to the declared frame: {why}, "
                               f"whose columns are {list(needed)}", name, table.sheet,
                               table.cell(name, 0).rstrip("0123456789") + "1")


def _left_empty(table, name):
    """True when every cell of number column ``name`` is empty (no value, no formula)."""
    values = table.values.get(name)
    if not isinstance(values, np.ndarray) or not np.all(np.isnan(values)):
        return False
    raw = table.raw.get(name)
    return raw is None or all(v is None or (isinstance(v, str) and not v.strip())
                              for v in raw)


def _check_full_grid(t):
    """The FuselageAero rows form a full alpha x beta grid without repeats."""
    repeat = _first_repeat(t["alpha"], t["beta"])
    if repeat is not None:
        i, first = repeat
        raise t.error("beta", i, f"the (alpha, beta) point of this row repeats row "
                      f"{t.cell('alpha', first)[1:]}")
    alphas = np.unique(t["alpha"])
    betas = np.unique(t["beta"])
    for name, values in (("alpha", alphas), ("beta", betas)):
        if values.size < 2:
            raise t.error(name, 0, f"the table needs at least two {name} values (it is "
                          "never extrapolated)")
    if len(t) != alphas.size * betas.size:
        for i, a in enumerate(t["alpha"]):
            count = int(np.count_nonzero(t["alpha"] == a))
            if count != betas.size:
                raise t.error("alpha", i, f"the table must be a full grid: this alpha has "
                              f"{count} rows but there are {betas.size} beta values "
                              f"({alphas.size} x {betas.size} = {alphas.size * betas.size} "
                              "rows needed)")


def _first_repeat(alpha, beta):
    """``(i, j)``: the first row ``i`` whose ``(alpha, beta)`` equals that of an earlier row
    ``j``, or None if no point repeats.

    The pairs are sorted (a stable sort: equal pairs keep the order of their rows), so that
    each repeat follows the first row of its point; the first repeat is the smallest row
    that is not the first of its point, and its point has only one earlier row. Adding 0.0
    makes -0.0 and 0.0 one point, as ``==`` does; the values are finite (read as such).
    """
    alpha, beta = np.asarray(alpha) + 0.0, np.asarray(beta) + 0.0
    order = np.lexsort((beta, alpha))
    a, b = alpha[order], beta[order]
    same = (a[1:] == a[:-1]) & (b[1:] == b[:-1])  # sorted row k + 1 repeats row k
    if not same.any():
        return None
    new_point = np.r_[True, ~same]
    starts = np.flatnonzero(new_point)  # sorted index of the first row of each point
    point = np.cumsum(new_point) - 1  # point of each sorted row
    repeats = np.flatnonzero(~new_point)  # sorted indices of the rows that repeat
    k = repeats[np.argmin(order[repeats])]  # the repeat of the smallest row
    return int(order[k]), int(order[starts[point[k]]])


def read_fin_aero(reader, params, refs):
    """The FinAero sheet with 'fin area', 'fin efficiency' and the fin_cp hardpoint, or None.

    Returns
    -------
    Fin or None
    """
    if not reader.has_sheet("FinAero"):
        return None
    t = reader.table(_SPEC["FinAero"])
    if refs["fin_cp"] is None:
        raise reader.error("the FinAero sheet needs a Hardpoints row of kind 'fin_cp'",
                           sheet="Hardpoints", cell="B1")
    area = params.positive("fin area")
    eff = params("fin efficiency")
    axes = params.choice("fin axes", CHOICES)
    with located(t):
        table = Table1D(t["beta"], {"CY": t["CY"]}, angle_name="beta", what="fin")
    with located(params, {"efficiency": "fin efficiency", "area": "fin area"},
                 default="fin efficiency"):
        return Fin(table, area, refs["fin_cp"], eff, axes)


def read_parachute_cd(reader, axes="wind"):
    """The optional ParachuteCD sheet as a table, or None (the default canopy CD 1.0 within
    +-8 deg is then used).

    Parameters
    ----------
    reader : WorkbookReader
    axes : str
        'parachute table axes': ``"wind"`` (column CD) or ``"canopy"`` (column CT).

    Returns
    -------
    Table1D or None
    """
    if not reader.has_sheet("ParachuteCD"):
        return None
    t = reader.table(_SPEC["ParachuteCD"])
    column = PARACHUTE_AXES[axes]
    _columns_match(reader, t, (column,), tuple(PARACHUTE_AXES.values()),
                   f"'parachute table axes' is {axes!r}")
    t.require_filled((column,), f"the table needs {column} at every alpha")
    for i, value in enumerate(t[column]):  # the rule of Parachute, at the cell
        if not 0 < value <= PARACHUTE_CD_MAX:
            raise t.error(column, i, f"parachute {column} must lie in (0, "
                          f"{PARACHUTE_CD_MAX:g}] (a flat plate normal to the flow has 1.17)")
    with located(t):
        table = Table1D(t["alpha"], {column: t[column]}, angle_name="alpha",
                        what="parachute")
    if not t["alpha"].min() <= 0 <= t["alpha"].max():
        raise t.error("alpha", int(np.argmin(np.abs(t["alpha"]))),
                      "the parachute table must cover alpha = 0 deg (from a negative to a "
                      "positive alpha, or with a row at 0): the canopy trails at 0 in steady "
                      "flight")
    return table


def read_parachute(reader, params, area, parameters=PARACHUTE_PARAMETERS):
    """A parachute of ``area`` with the ParachuteCD table and its Study parameters.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
    area : float
        Flat-plate area. [m^2]
    parameters : dict
        Study parameter name -> :class:`~slingloads.models.parachute.Parachute` argument
        (default: wake ratio and line length). Each is checked on its own so that an error
        names its cell.

    Returns
    -------
    Parachute
    """
    axes = params.choice("parachute table axes", CHOICES)
    cd = read_parachute_cd(reader, axes)  # checked at its cells
    for name, arg in parameters.items():  # each with the default table: only its own error
        with located(params, default=name):
            Parachute(area, None, axes=axes, **{arg: params(name)})
    with located(Place(reader.file, "ParachuteCD" if cd is not None else STUDY_SHEET)):
        return Parachute(area, cd, axes=axes,
                         **{arg: params(name) for name, arg in parameters.items()})


def parachute_reach_rule(reader, params, refs, hardpoints, line, cable, unit):
    """The rule a carrier cable of ``cable`` [m] breaks when the parachute could reach the
    carrier (the cable's length within the distances from the hub that the line and canopy
    reach, streaming aft of their attachment or hanging below it:
    :func:`~slingloads.models.multibody.parachute_line.line_reach`), in the cable's ``unit``
    (as the user wrote it) and naming the cells the reach comes from; None when the cable is
    clear of them.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
    refs : dict
        Hardpoints by kind, with their rows (:func:`read_airframe`).
    hardpoints : Hardpoints
    line : float
        The parachute's line length. [m]
    cable : float
        [m]
    unit : str
        Unit of the cable length as written.
    """
    from slingloads.models.multibody.parachute_line import line_reach  # compiled: on use

    near, far = line_reach(hardpoints.hub, hardpoints.chute, line)
    if not near <= cable <= far:
        return None
    hp_t = reader.table(_SPEC["Hardpoints"])
    rows = [refs["rows"]["hub"][0], refs["chute_row"]]
    cells = " and ".join(f"{hp_t.cell('x', r)}:{hp_t.cell('z', r)}" for r in rows)
    return (f"the parachute could reach the carrier: its line ('parachute line length' "
            f"{params.quantity('parachute line length', line)}) from its attachment "
            f"(Hardpoints {cells}), streaming aft or hanging, reaches from "
            f"{quantity(near, unit, 'length')} to {quantity(far, unit, 'length')} from the "
            f"hub, and the carrier cable ({quantity(cable, unit, 'length')}) lies in that "
            f"range; lengthen the cable beyond {quantity(far, unit, 'length')} (or shorten "
            f"the line)")

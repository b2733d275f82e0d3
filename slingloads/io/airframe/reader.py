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

from slingloads.io.airframe.schema import HARDPOINT_KINDS, SHEETS
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.common.units import si_factor
from slingloads.io.common.workbook import check_unique, located
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import (
    FIN_AXES,
    FORCE_AXES,
    MOMENT_AXES,
    Fin,
    FuselageAero,
    fuselage_columns,
)
from slingloads.models.airframe import Airframe, Hardpoints, MassItems, check_inside
from slingloads.models.parachute import PARACHUTE_AXES, Parachute

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
        ``aero_reference``, ``htail_cp``: the first row of that kind, or None) [m], and
        ``chute_row``: the
        0-based row of the chute hardpoint, or None.
    """
    items = _mass_items(reader)
    stations = reader.table(_SPEC["Stations"])
    check_unique(reader, stations, "id")
    x = stations["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            rule = ("cut stations must not repeat" if x[i] == x[i - 1]
                    else "cut stations must be sorted by increasing x")
            raise reader.error(rule, float(x[i] / si_factor(stations.units["x"], "length")),
                               stations.sheet, stations.cell("x", i))
    axis = (params("reference axis y"), params("reference axis z"))
    hp_t, points = _hardpoint_rows(reader, items, axis)
    mast = np.array([params("mast axis x"), params("mast axis y"), params("mast axis z")])
    aero_points, aero_weights = _aero_points(reader, items, axis)
    with located(reader.file, hp_t.sheet):
        hardpoints = Hardpoints(
            hub=points["hub"][0][1],
            mast_feet=np.array([p[1] for p in points["mast_foot"]]),
            mast_weights=np.array([p[2] for p in points["mast_foot"]]),
            mast_axis=mast,
            chute=points["chute"][0][1] if points["chute"] else None,
            mast_feet_ids=tuple(p[0] for p in points["mast_foot"]),
        )
    with located(reader.file, stations.sheet):
        airframe = Airframe(items, x, hardpoints, axis, tuple(stations["id"]), aero_points,
                            aero_weights, name=str(params("study name")))
    refs = {k: (v[0][1] if v else None) for k, v in points.items()}
    refs["chute_row"] = points["chute"][0][3] if points["chute"] else None
    return airframe, refs


def _mass_items(reader):
    items_t = reader.table(_SPEC["MassItems"])
    check_unique(reader, items_t, "id")
    masses = items_t["mass"]
    for i, m in enumerate(masses):
        if m <= 0:
            raise reader.error("mass must be > 0",
                               float(m / si_factor(items_t.units["mass"], "mass")),
                               items_t.sheet, items_t.cell("mass", i))
    inertia = np.zeros((len(masses), 3, 3))
    for (a, b), name in {(0, 0): "Ixx", (1, 1): "Iyy", (2, 2): "Izz", (0, 1): "Ixy",
                         (0, 2): "Ixz", (1, 2): "Iyz"}.items():
        if items_t.has(name):
            inertia[:, a, b] = inertia[:, b, a] = items_t[name]
    position = np.column_stack([items_t["x"], items_t["y"], items_t["z"]])
    with located(reader.file, items_t.sheet):
        return MassItems(tuple(items_t["id"]), masses, position, inertia,
                         tuple(items_t["description"]) if items_t.has("description") else ())


def _hardpoint_rows(reader, items, axis):
    """The Hardpoints table and its rows by kind: ``{kind: [(id, position, weight, row)]}``."""
    hp_t = reader.table(_SPEC["Hardpoints"])
    check_unique(reader, hp_t, "id")
    points = {k: [] for k in HARDPOINT_KINDS}
    for i, kind in enumerate(hp_t["kind"]):
        k = kind.strip().lower()
        if k not in HARDPOINT_KINDS:
            raise reader.error(f"unknown hardpoint kind; valid kinds are "
                               f"{list(HARDPOINT_KINDS)}", kind, hp_t.sheet,
                               hp_t.cell("kind", i))
        p = np.array([hp_t["x"][i], hp_t["y"][i], hp_t["z"][i]])
        if k != "aero_reference":
            with located(reader.file, hp_t.sheet, hp_t.cell("x", i)):
                check_inside(items, axis, f"{hp_t['id'][i]!r}", p)
        w = hp_t["weight"][i] if hp_t.has("weight") else 1.0
        if not w > 0:
            raise reader.error("hardpoint weight must be > 0", float(w), hp_t.sheet,
                               hp_t.cell("weight", i))
        points[k].append((hp_t["id"][i], p, w, i))
    for kind, lo, hi in (("hub", 1, 1), ("mast_foot", 1, None), ("chute", 0, 1),
                         ("fin_cp", 0, 1), ("aero_reference", 0, 1), ("htail_cp", 0, 1)):
        n = len(points[kind])
        if n < lo or (hi is not None and n > hi):
            want = f"exactly {lo}" if lo == hi else (f"at least {lo}" if hi is None
                                                    else f"at most {hi}")
            raise reader.error(f"the Hardpoints sheet needs {want} row(s) of kind {kind!r}",
                               n, hp_t.sheet, "B1")
    return hp_t, points


def _aero_points(reader, items, axis):
    """The optional AeroPoints sheet: stations and weights, or (None, None)."""
    if not reader.has_sheet("AeroPoints"):
        return None, None
    ap = reader.table(_SPEC["AeroPoints"])
    aero_points, aero_weights = ap["x"], ap["weight"]
    for i, (xa, wa) in enumerate(zip(aero_points, aero_weights, strict=True)):
        if not wa > 0:
            raise reader.error("aerodynamic share weight must be > 0", float(wa), ap.sheet,
                               ap.cell("weight", i))
        with located(reader.file, ap.sheet, ap.cell("x", i)):
            check_inside(items, axis, f"aerodynamic point {i + 1}",
                         np.array([xa, axis[0], axis[1]]))
    return aero_points, aero_weights


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
                           "'aero_reference' (moment reference point)", sheet="Hardpoints")
    area = params.positive("fuselage reference area")
    length = params.positive("fuselage reference length")
    force_axes = params.choice("fuselage force axes", tuple(FORCE_AXES))
    moment_axes = params.choice("fuselage moment axes", MOMENT_AXES)
    columns = fuselage_columns(force_axes)
    _columns_match(reader, t, columns, ("CD", "CL", "CX", "CZ"),
                   f"'fuselage force axes' is {force_axes!r}")
    with located(reader.file, t.sheet):
        table = Table2D.from_long(t["alpha"], t["beta"], {c: t[c] for c in columns})
        return FuselageAero(table, area, length, refs["aero_reference"], force_axes,
                            moment_axes)


def _columns_match(reader, table, needed, optional, why):
    """Each column of ``needed`` present, none of ``optional`` outside it (the frame's)."""
    for name in needed:
        if not table.has(name):
            raise reader.error(f"missing column {name!r}: {why}, whose columns are "
                               f"{list(needed)}", sheet=table.sheet, cell="A1")
    for name in optional:
        if table.has(name) and name not in needed:
            raise reader.error(f"column {name!r} does not belong to the declared frame: {why}, "
                               f"whose columns are {list(needed)}", name, table.sheet,
                               table.cell(name, 0).rstrip("0123456789") + "1")


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
                           sheet="Hardpoints")
    area = params.positive("fin area")
    eff = params("fin efficiency")
    axes = params.choice("fin axes", FIN_AXES)
    with located(reader.file, t.sheet):
        table = Table1D(t["beta"], {"CY": t["CY"]}, angle_name="beta", what="fin")
    with located(reader.file, STUDY_SHEET, params.cell("fin efficiency")):
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
    with located(reader.file, t.sheet):
        return Table1D(t["alpha"], {column: t[column]}, angle_name="alpha", what="parachute")


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
    axes = params.choice("parachute table axes", tuple(PARACHUTE_AXES))
    cd = read_parachute_cd(reader, axes)
    for name, arg in parameters.items():
        with located(reader.file, STUDY_SHEET, params.where(name)):
            Parachute(area, cd, axes=axes, **{arg: params(name)})
    with located(reader.file, "ParachuteCD" if cd is not None else STUDY_SHEET):
        return Parachute(area, cd, axes=axes,
                         **{arg: params(name) for name, arg in parameters.items()})

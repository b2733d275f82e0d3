"""The loads report's tables: each a DataFrame in the report's units, built from a result.

What this module guarantees: every value is converted from SI at this boundary
(:mod:`slingloads.io.common.report`), its unit in its column header or, where the unit
depends on the row's load component, in a ``unit`` column beside it
(:func:`convert_by_component`); every table says LIMIT or ULTIMATE where it holds loads;
an unknown component or station is refused with :class:`~slingloads.errors.InputError`.
Which sheet shows which table is :mod:`slingloads.io.loads.sheets`.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd

from slingloads.analyses.envelopes import bound_values, component_index
from slingloads.analyses.hook_loads import TOWED, angle_words
from slingloads.analyses.loads import CLOSURE_TOLERANCE
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS, LOAD_COLUMNS
from slingloads.io.common.formats import header_unit
from slingloads.io.common.report import (
    check_units,
    convert_columns,
    explain_infinite,
    in_report_units,
    labelled,
    report_unit,
    report_value,
)
from slingloads.io.common.units import unit_label

#: Component pairs of the 2-D envelopes (hull tables and plots) unless the study names others.
DEFAULT_HULL_PAIRS = (("Vy", "Mz"), ("Vz", "My"))

#: Columns of the SFBM CSV file (SI, limit loads).
SFBM_CSV_COLUMNS = ("case", "station", "x_m", "Vx_N", "Vy_N", "Vz_N", "Mx_Nm", "My_Nm",
                    "Mz_Nm")

#: A previous-envelope station within this distance of a cut station is the same station
#: (the workbook's positions are rounded). [m]
SAME_STATION = 1e-3



def convert_by_component(frame, columns, units, component="component"):
    """Convert columns whose unit depends on the row's load component (force or moment).

    Adds a ``unit`` column after the first converted column.

    Parameters
    ----------
    frame : pandas.DataFrame
        Table with a ``component`` column (``"Vx"``... ``"Mz"``) and SI load columns.
    columns : sequence of str
        Load columns to convert (e.g. ``["value"]``). [N] or [N m] by row
    units : str
        ``"SI"`` or ``"US"``.
    component : str
        Name of the component column.

    Returns
    -------
    pandas.DataFrame
    """
    check_units(units)
    out = frame.copy()
    kinds = out[component].map(lambda c: COMPONENT_KINDS[component_index(c)])
    factor = np.ones(len(out))
    labels = np.empty(len(out), dtype=object)
    for kind in set(kinds):
        mask = (kinds == kind).to_numpy()
        factor[mask] = float(in_report_units(1.0, kind, units))
        labels[mask] = unit_label(report_unit(kind, units))
    for column in columns:
        out[column] = out[column].to_numpy(float) * factor
    out.insert(list(out.columns).index(columns[0]) + 1, "unit", labels)
    return out



def _loads_spec(names=COMPONENTS):
    return {LOAD_COLUMNS[component_index(n)]: (n, COMPONENT_KINDS[component_index(n)])
            for n in names}



def report_unit_label(kind, units):
    """The label of the report's unit of quantity ``kind`` in the ``units`` system
    (``"SI"`` or ``"US"``), as the column headers print it."""
    return unit_label(report_unit(kind, units))



def _limit(ultimate):
    return "ULTIMATE" if ultimate else "LIMIT"



def sfbm_table(result, units="SI", ultimate=False):
    """Long SFBM table in report units: ``case, station, x [..], Vx [..] ... Mz [..]``."""
    frame = result.to_frame(ultimate=ultimate)
    spec = {"x_m": ("x", "length")}
    for name, column in zip(COMPONENTS, SFBM_CSV_COLUMNS[3:], strict=True):
        spec[column] = (name, COMPONENT_KINDS[component_index(name)])
    out = convert_columns(frame, spec, units)
    out.attrs["title"] = (f"SFBM of every case at every cut station, {_limit(ultimate)} loads, "
                          f"{result.study.name}")
    return out



def envelope_report_table(result, units="SI", ultimate=False):
    """Envelope with the critical case and correlated loads, in report units, with a
    ``unit`` column for the row's ``value``."""
    frame = _one_value(result.envelope(ultimate=ultimate))
    frame = convert_by_component(frame, ["value"], units)
    spec = {"x_m": ("x", "length"), **_loads_spec()}
    return convert_columns(frame, spec, units)



def _one_value(frame):
    """An API table's ``value_N`` / ``value_Nm`` pair as one ``value`` column in their place
    (the report gives each row's unit beside it)."""
    out = frame.drop(columns=["value_Nm"]).rename(columns={"value_N": "value"})
    out["value"] = bound_values(frame)
    return out



def envelope_wide_table(result, components, units="SI", ultimate=False):
    """One row per station: max and min of each component with the case that gives it.

    Parameters
    ----------
    result : LoadsResult
    components : sequence of str
        Components, e.g. ``("Vx", "Vy", "Vz")``.
    units : str
    ultimate : bool
        Ultimate (factor x limit) instead of limit loads.

    Returns
    -------
    pandas.DataFrame
        ``station, x [..], Vx max [..], Vx max case, Vx min [..], Vx min case, ...``.
    """
    loads = result.ultimate if ultimate else result.loads
    ids = np.asarray(result.case_ids, dtype=object)
    stations = np.arange(len(result.stations))
    frame = {"station": list(result.station_ids),
             labelled("x", "length", units): in_report_units(result.stations, "length",
                                                             units)}
    for name in components:
        j = component_index(name)
        kind = COMPONENT_KINDS[j]
        for bound, pick in (("max", np.argmax), ("min", np.argmin)):
            index = pick(loads[:, :, j], axis=0)
            frame[labelled(f"{name} {bound}", kind, units)] = in_report_units(
                loads[index, stations, j], kind, units)
            frame[f"{name} {bound} case"] = ids[index]
    return pd.DataFrame(frame)



#: Where a load case comes from (the LoadCases column ``source``).
CASE_SOURCES = ("CS-29.865 direction", "towed equilibrium", "dynamics", "hand-listed")

#: The columns of the second LoadCases table (what each case applies); the first defines it.
_CASE_FACTORS = re.compile(r"^(n vertical|nx|ny|nz|alpha_dot_|closure )")



def case_sources(result, frame):
    """Where each case of ``frame`` (:meth:`case_table`) comes from, one of
    :data:`CASE_SOURCES`: listed on the LoadCases sheet by hand; at an aerodynamic point or
    on a parachute line of the dynamics; generated in a towed-flight equilibrium; or
    generated along a CS-29.865 hook direction."""
    listed = {c.id for c in result.study.listed}
    return ["hand-listed" if case in listed else "dynamics" if source == "dynamics"
            else "towed equilibrium" if hook == TOWED else "CS-29.865 direction"
            for case, source, hook in zip(frame["case"], frame["source"], frame["hook"],
                                          strict=True)]



def case_report_table(result, units="SI"):
    """Load-case table in report units (closure residuals converted): each case with where
    it comes from (column ``source``, :func:`case_sources`) and its description."""
    frame = result.case_table()
    frame["source"] = case_sources(result, frame)
    first = ["case", "source"]
    frame = frame[first + [c for c in frame.columns if c not in first + ["description"]]
                  + ["description"]]
    return convert_columns(frame, {
        "closure force residual [N]": ("closure force residual", "force"),
        "closure moment residual [N m]": ("closure moment residual", "moment"),
    }, units)



def case_report_tables(result, units="SI"):
    """The load-case table as two printed tables: (definition, load factors), both keyed by
    ``case``; the first gives each case's source and ends with its description, the second
    only the case and its factors (narrow enough for a portrait page, twice the rows of a
    landscape one)."""
    frame = case_report_table(result, units)
    factors = [c for c in frame.columns if _CASE_FACTORS.match(str(c))]
    return (frame[[c for c in frame.columns if c not in factors]],
            frame[["case", *factors]])



def previous_station_status(result):
    """How the previous envelope is known at each cut station, one entry per station.

    Returns
    -------
    list of str
        ``"given"`` where every component of the previous envelope has a station within
        :data:`SAME_STATION` of the cut; ``"INTERPOLATED"`` where at least one component is
        interpolated between its neighbouring stations; ``"not covered"`` outside its x
        range; empty strings when there is no previous envelope.
    """
    prev = result.study.previous_envelope
    x = np.asarray(result.stations, float)
    if prev is None:
        return [""] * len(x)
    status = np.full(len(x), "given", dtype=object)
    for name in COMPONENTS:
        xp = np.sort(prev.loc[prev["component"] == name, "x [m]"].to_numpy(float))
        if not len(xp):
            status[:] = "not covered"
            continue
        near = np.min(np.abs(x[:, None] - xp[None, :]), axis=1) <= SAME_STATION
        inside = (x >= xp[0] - SAME_STATION) & (x <= xp[-1] + SAME_STATION)
        status[inside & ~near & (status == "given")] = "INTERPOLATED"
        status[~inside] = "not covered"
    return status.tolist()



def comparison_report_table(result, units="SI"):
    """Exceedance over the previous design envelope, one row per station and component, in
    report units, with how the previous value is known there; or None."""
    comparison = result.comparison()
    if comparison is None:
        return None
    frame = convert_by_component(
        comparison, ["new max", "new min", "previous max", "previous min"], units)
    status = dict(zip(result.station_ids, previous_station_status(result), strict=True))
    frame["previous values"] = frame["station"].map(status)
    frame["status"] = frame["status"].map(_SHORT_STATUS).fillna(frame["status"])
    frame = frame.rename(columns={"exceedance ratio": "exceedance ratio [-]"})
    frame = frame.drop(columns=["exceeds"])
    frame = explain_infinite(frame, ["exceedance ratio [-]"], UNBOUNDED_RATIO)
    return convert_columns(frame, {"x [m]": ("x", "length")}, units)



#: An exceedance ratio over a previous envelope of 0 (a new load where there was none), as
#: the Exceedance sheets write it (filled red like a ratio above 1).
UNBOUNDED_RATIO = "unbounded (previous 0)"

_SHORT_STATUS = {"EXCEEDS previous envelope": "EXCEEDS", "within": "within",
                 "not covered by previous envelope": "not covered"}



def exceedance_wide_table(result, units="SI"):
    """One row per station: the exceedance ratio of each component beside the station id,
    and how the previous envelope is known there; or None."""
    comparison = result.comparison()
    if comparison is None:
        return None
    ratios = comparison.pivot(index="station", columns="component",
                              values="exceedance ratio").reindex(list(result.station_ids))
    frame = pd.DataFrame({"station": list(result.station_ids),
                          labelled("x", "length", units): in_report_units(
                              result.stations, "length", units)})
    for name in COMPONENTS:
        frame[f"{name} ratio [-]"] = ratios[name].to_numpy(float)
    frame["worst [-]"] = ratios[list(COMPONENTS)].max(axis=1).to_numpy(float)
    frame["previous values"] = previous_station_status(result)
    return explain_infinite(frame, [*(f"{name} ratio [-]" for name in COMPONENTS),
                                    "worst [-]"], UNBOUNDED_RATIO)



def hull_report_table(result, pair, stations, units="SI"):
    """Hull vertices of ``pair`` at each station, one block of rows per station."""
    frames = []
    for station in stations:
        hull = result.hull(station, pair)
        index = result.station_index(station)
        hull.insert(0, "vertex", np.arange(1, len(hull) + 1))
        hull.insert(0, "x_m", result.stations[index])
        hull.insert(0, "station", result.station_ids[index])
        frames.append(hull)
    frame = pd.concat(frames, ignore_index=True)
    return convert_columns(frame, {"x_m": ("x", "length"), **_loads_spec(pair)}, units)




def study_table(result, units="SI"):
    """Settings of the study (mass, CG, flight condition, hook, cases) in report units."""
    study = result.study
    items = study.airframe.mass_items

    def conv(value, kind):
        return float(in_report_units(value, kind, units))

    cg = items.cg
    c, s = len(result.case_ids), len(result.stations)
    rows = [
        ("study", study.name, ""),
        ("CSV files", "SI (m, N, N m), LIMIT loads", ""),
        ("aircraft mass", conv(items.total_mass, "mass"), report_unit_label("mass", units)),
        ("CG x", conv(cg[0], "length"), report_unit_label("length", units)),
        ("CG y", conv(cg[1], "length"), report_unit_label("length", units)),
        ("CG z", conv(cg[2], "length"), report_unit_label("length", units)),
        ("equivalent airspeed KEAS", conv(study.flight.eas, "airspeed"),
         report_unit_label("airspeed", units)),
        ("density altitude", report_value(study.flight.density_altitude, "altitude", units),
         report_unit_label("altitude", units)),
        ("air density", conv(study.flight.density, "density"), report_unit_label("density", units)),
        ("attitude (earth vertical in airframe axes)", result.attitude.describe(), ""),
        ("attitude pitch", float(np.degrees(result.attitude.pitch)), "deg"),
        ("attitude roll", float(np.degrees(result.attitude.roll)), "deg"),
        ("hook load factor Nz (limit)", float(study.hook.nz), "-"),
        ("hook cone angle from the vertical", float(np.degrees(study.hook.angle)), "deg"),
        ("hook cone angle of the lateral directions", float(np.degrees(study.hook.lateral)),
         "deg"),
        ("hook cone shape", study.hook.cone, ""),
        ("hook azimuths", int(study.hook.n_azimuth), "-"),
        ("vertical hook case included", bool(study.hook.include_vertical), ""),
        ("towed-flight equilibrium cases", bool(study.hook.towed), ""),
        ("aerodynamic envelope points",
         len(study.envelope.ids) if study.envelope is not None else 0, "-"),
        ("parachute", study.parachute is not None, ""),
        ("parachute line direction", study.chute_line if study.parachute is not None else "-",
         ""),
        ("ultimate factor (CS 29.303)", float(study.ultimate_factor), "-"),
        ("load cases", c, "-"),
        ("cut stations", s, "-"),
        ("SFBM rows (cases x stations)", c * s, "-"),
        ("previous design envelope",
         "given" if study.previous_envelope is not None else "none", ""),
    ]
    return pd.DataFrame(rows, columns=["item", "value", "unit"])



def attitude_table(result):
    """The attitude and its earth vertical in airframe axes (angles in degrees)."""
    return result.attitude.to_frame()



def hook_direction_table(result):
    """The hook directions: azimuth and inclination from the vertical, whether the
    inclination was changed from the cone angle ('reduced'), unit vector in airframe axes."""
    frame = result.study.hook_table().copy()
    frame["reduced"] = np.where(frame["reduced"], "yes", "no")
    return frame.rename(columns={"ux": "ux [-]", "uy": "uy [-]", "uz": "uz [-]"})



def hook_direction_note(result):
    """One sentence on the cone's inclinations and the directions a lateral angle changed."""
    hook = result.study.hook
    table = result.study.hook_table()
    reduced = list(table.loc[table["reduced"], "hook"])
    base = ("Cone about the earth vertical of the attitude: "
            f"{angle_words(np.degrees(hook.angle))} deg from the vertical")
    if not reduced:
        return base + " in every direction."
    where = ("at the pure lateral azimuths only" if hook.cone == "lateral directions"
             else "along an elliptical cone to the lateral angle")
    return (f"{base}, except {', '.join(reduced)} at the lateral angle "
            f"{angle_words(np.degrees(hook.lateral))} deg ({where}; the lateral-step study "
            "justifies lateral directions only).")



def towed_outside(result):
    """The towed-flight cases whose trimmed cable lies outside the hook cone (ids)."""
    towed = result.towed_table()
    if towed.empty:
        return []
    return list(towed.loc[towed["inside hook cone"] != "yes", "case"])



def outside_text(outside):
    """The finding on towed cables outside the hook cone ``outside`` (case ids)."""
    return (f"OUTSIDE THE HOOK CONE: {', '.join(outside)}: the cone does not cover the cable "
            "angle reached in towed flight; widen it or restrict the flight envelope.")



def towed_summary_table(result):
    """The towed-flight cases as the Summary prints them: one row per quantity of
    :meth:`~slingloads.analyses.loads.LoadsResult.towed_table` (its name, its unit, empty
    for a text), one column per towed case, so that the few towed cases print as one narrow
    block beside the Summary's other tables; or None without a towed case."""
    towed = result.towed_table()
    if towed.empty:
        return None
    names, units = [], []
    for column in towed.columns[1:]:
        unit = header_unit(column)
        names.append(str(column) if unit is None else str(column).rsplit(" [", 1)[0])
        units.append("" if unit is None else unit)
    out = pd.DataFrame({"quantity": names, "unit": units})
    for k, case in enumerate(towed["case"]):
        out[str(case)] = list(towed.iloc[k, 1:])
    return out


def _sentences(lines):
    """``lines`` joined as sentences (a full stop after each that has none)."""
    return " ".join(t if t.rstrip().endswith(".") else f"{t.rstrip()}." for t in lines)


def towed_note(result):
    """The towed-case verdict: how many trimmed cables lie outside the hook cone."""
    findings = _sentences(result.towed_findings())
    if result.towed_table().empty:
        return ("No towed-flight equilibrium case (no fuselage table, or off). "
                + findings).strip()
    outside = towed_outside(result)
    study = result.study
    source = study.towed_source or "a system assembled from the loads' airframe, fuselage, "\
        "fin and parachute"
    rule = (f"Each towed case flies at its trimmed attitude (pitch and roll at which weight, "
            f"aerodynamic and parachute moments balance about the hub; trim of {source} at "
            f"the loads' airspeed; its vertical replaces the study's attitude in that case). "
            "Cable angle from the vertical at Nz and at 1 g (the steady trail angle), judged "
            "at the larger against the cone's inclination at the cable's azimuth."
            + (f" {findings}" if findings else ""))
    if not outside:
        return f"{rule} Every trimmed cable lies inside the hook cone."
    return f"{rule} {outside_text(outside)}"



def closure_passes(result):
    """Whether every case closes: its largest |residual| (force or moment) within
    :data:`~slingloads.analyses.loads.CLOSURE_TOLERANCE` x the load scale."""
    return float(np.abs(result.residual).max()) <= CLOSURE_TOLERANCE * result.residual_scale



def closure_table(result, units="SI"):
    """Free-free closure check: the largest residual force and moment over every case
    against the tolerance, and the verdict, in report units (checked in SI; the LoadFactors
    sheet gives the residuals in the same units)."""
    residual = np.abs(result.residual)
    tol = CLOSURE_TOLERANCE * result.residual_scale
    worst = int(np.argmax(residual.max(axis=1)))
    frame = pd.DataFrame([
        (f"tolerance: {CLOSURE_TOLERANCE:g} x load scale {result.residual_scale:,.0f} N m "
         "(largest force x max(1 m, airframe length))", tol, tol),
        ("largest |residual| over every case, at a cut aft of every load",
         float(residual[:, :3].max()), float(residual[:, 3:].max())),
        (f"case with the largest residual: {result.case_ids[worst]}",
         float(residual[worst, :3].max()), float(residual[worst, 3:].max())),
        ("result: " + ("PASS" if closure_passes(result) else "FAIL"), np.nan, np.nan),
    ], columns=["check", "force residual [N]", "moment residual [N m]"])
    return convert_columns(frame, {"force residual [N]": ("force residual", "force"),
                                   "moment residual [N m]": ("moment residual", "moment")},
                           units)



def governing_report_table(result, units="SI"):
    """Case and station of the largest |limit load| of each component, in report units,
    with the hook direction, aerodynamic point and parachute of the case."""
    frame = result.governing_cases().drop(columns=["description"])
    cases = result.cases.set_index("case")
    for column in ("hook", "aero", "chute"):
        frame[column] = cases.loc[frame["case"], column].to_numpy()
    frame = convert_by_component(_one_value(frame), ["value"], units)
    return convert_columns(frame, {"x_m": ("x", "length")}, units)



def inputs_tables(result, units="SI"):
    """The mass items, cut stations and hardpoints the loads were computed from, in report
    units: ``{"mass items": ..., "stations": ..., "hardpoints": ...}``."""
    study = result.study
    airframe = study.airframe
    items = airframe.mass_items

    def length(v):
        return in_report_units(v, "length", units)

    mass = pd.DataFrame({
        "id": list(items.ids),
        "description": list(items.description) or [""] * len(items.ids),
        labelled("mass", "mass", units): in_report_units(items.mass, "mass", units),
        labelled("x", "length", units): length(items.position[:, 0]),
        labelled("y", "length", units): length(items.position[:, 1]),
        labelled("z", "length", units): length(items.position[:, 2]),
    })
    inertia = np.asarray(items.inertia)
    if np.any(inertia != 0):
        for name, (a, b) in {"Ixx": (0, 0), "Iyy": (1, 1), "Izz": (2, 2), "Ixy": (0, 1),
                             "Ixz": (0, 2), "Iyz": (1, 2)}.items():
            mass[labelled(name, "inertia", units)] = in_report_units(inertia[:, a, b],
                                                                     "inertia", units)
    stations = pd.DataFrame({"station": list(airframe.station_ids),
                             labelled("x", "length", units): length(airframe.stations)})
    hp = airframe.hardpoints
    rows = [("HUB", "rotor hub: hook load", hp.hub, np.nan)]
    rows += [(i, "mast foot: hook load enters here", p, w)
             for i, p, w in zip(hp.mast_feet_ids, hp.mast_feet, hp.mast_weights, strict=True)]
    if hp.chute is not None:
        rows.append(("CHUTE", "parachute attachment: drag", hp.chute, np.nan))
    if study.fin is not None:
        rows.append(("FIN_CP", "fin centre of pressure: side force",
                     study.fin.centre_of_pressure, np.nan))
    if study.fuselage is not None:
        rows.append(("AERO_REF", "moment reference of the fuselage coefficients",
                     study.fuselage.moment_reference, np.nan))
    y0, z0 = airframe.reference_axis
    points = np.array([r[2] for r in rows], float)
    hardpoints = pd.DataFrame({
        "id": [r[0] for r in rows], "role": [r[1] for r in rows],
        labelled("x", "length", units): length(points[:, 0]),
        labelled("y", "length", units): length(points[:, 1]),
        labelled("z", "length", units): length(points[:, 2]),
        "weight [-]": [r[3] for r in rows]})
    axis = pd.DataFrame([
        ("loads reference axis y0", float(length(y0)), report_unit_label("length", units)),
        ("loads reference axis z0", float(length(z0)), report_unit_label("length", units)),
        ("mast axis (unit vector) x", float(hp.mast_axis[0]), "-"),
        ("mast axis (unit vector) y", float(hp.mast_axis[1]), "-"),
        ("mast axis (unit vector) z", float(hp.mast_axis[2]), "-"),
    ], columns=["item", "value", "unit"])
    return {"mass items": mass, "stations": stations, "hardpoints": hardpoints, "axes": axis}



def hull_table_stations(result, hull_stations=None):
    """The stations of the hull tables: ``hull_stations`` (ids or indices), else every cut
    station."""
    return list(hull_stations) if hull_stations is not None else list(result.station_ids)

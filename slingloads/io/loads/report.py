"""The loads report: a print-ready Excel workbook, CSV tables and PNG plots of a loads analysis.

The report is a :class:`~slingloads.io.common.report_writer.ReportKind` (:func:`loads_report`,
:func:`report_kind` for a workbook's study) written by the one report writer,
:func:`~slingloads.io.common.report_writer.write_report` (:func:`write` for a study,
:func:`write_loads_outputs` from Python), all at once or not at all
(:mod:`slingloads.io.common.atomic`), its files named ``<stem>-<name>`` (:data:`OUTPUTS`):

* ``<stem>-loads.xlsx``, the report: *Cover* (identification, input file and its SHA-256,
  version, sheets, conventions), *Summary* (findings and flags: hook angle against
  CS 29.865, towed cables outside the hook cone, exceedances and where the previous envelope
  comes from, closure; study settings; the attitude and its vertical; the hook directions
  with the reduced ones; the towed cases' cable angles; closure check), *Inputs* (mass items,
  cut stations, hardpoints), *LoadCases* (with each case's cable angle and inside-cone
  flag), *Envelope* (LIMIT max / min of each component at each station with its critical
  case), *Correlated* (LIMIT envelope with the correlated loads of the
  critical case), *Exceedance* and, with a previous envelope, *ExceedanceDetail* (ratio to
  the previous design envelope, red above 1, interpolated previous values marked), *Ultimate*
  (ULTIMATE = factor x LIMIT envelope), *Hulls* (vertex tables) and *Plots*; all in the chosen unit
  system with the unit beside every value, each sheet and title saying LIMIT or ULTIMATE;
* ``<stem>-sfbm.xlsx`` when asked for (Study 'SFBM workbook' = yes): the SFBM of every case
  at every station in report units (a data workbook, not for print, split as ``SFBM_1``,
  ``SFBM_2``... past Excel's row limit; the CSV file has the same numbers in SI);
* ``<stem>-sfbm.csv`` (columns ``case,station,x_m,Vx_N,Vy_N,Vz_N,Mx_Nm,My_Nm,Mz_Nm``) and
  ``<stem>-envelope.csv`` (``station,x_m,component,bound,case,value_N,value_Nm,Vx_N...``):
  LIMIT loads, always SI, headers ``name_unit``;
* ``<stem>-stations.png`` (side and top views: cut stations, mass items, hub, mast feet,
  fin, parachute attachment), one SFBM plot per component ``<stem>-X_shear.png``...
  ``<stem>-Z_moment.png`` (the paper's figures 19 and 20 are X and Y shear) and
  ``<stem>-hull_<A>_<B>_<station>.png``.
* on request, ``<stem>-loads.bdf``: the load cases as a Nastran input file
  (:mod:`slingloads.io.loads.nastran`), with a *Nastran* sheet in the workbook.

:func:`convert_by_component` converts the columns whose unit depends on the row's load
component; the conversions shared by every report are in :mod:`slingloads.io.common.report`.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace
from functools import partial

import numpy as np
import pandas as pd

from slingloads.analyses.envelopes import bound_values, component_index
from slingloads.analyses.hook_loads import TOWED
from slingloads.analyses.loads import CLOSURE_TOLERANCE
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS, LOAD_COLUMNS
from slingloads.errors import InputError
from slingloads.io.common.atomic import safe_file_part
from slingloads.io.common.cover import info_from_digest, input_digest
from slingloads.io.common.csvout import csv_bytes
from slingloads.io.common.decision import decision_section
from slingloads.io.common.excel import (
    EXCEL_MAX_ROWS,
    Highlight,
    Section,
    format_by_header,
    write_workbook,
)
from slingloads.io.common.figures import plot_function
from slingloads.io.common.formats import header_unit
from slingloads.io.common.locate import located
from slingloads.io.common.report import (
    check_units,
    convert_columns,
    explain_infinite,
    in_report_units,
    labelled,
    report_unit,
    report_value,
    warning_sections,
)
from slingloads.io.common.report_writer import ReportKind, write_report
from slingloads.io.common.units import unit_label
from slingloads.io.loads.nastran import prepare_nastran
from slingloads.io.loads.tags import COMPONENT_TAGS, COMPONENT_TITLES

#: Components drawn each on its own PNG, all six (the paper's figures 19 and 20: Vx, Vy).
PNG_COMPONENTS = COMPONENTS

#: Names of the files of a loads report (``*``: a part made from a station id), for the
#: publisher: a new report replaces every earlier file of these names (``-sfbm_all.png``:
#: the six-panel plot of earlier versions, replaced by one PNG per component).
OUTPUTS = ("{stem}-loads.xlsx", "{stem}-sfbm.xlsx", "{stem}-sfbm.csv", "{stem}-envelope.csv",
           "{stem}-stations.png", *(f"{{stem}}-{COMPONENT_TAGS[n]}.png" for n in COMPONENTS),
           "{stem}-sfbm_all.png", "{stem}-hull_*.png", "{stem}-loads.bdf")

#: Component pairs of the 2-D envelopes (hull tables and plots) unless the study names others.
DEFAULT_HULL_PAIRS = (("Vy", "Mz"), ("Vz", "My"))

#: Columns of the SFBM CSV file (SI, limit loads).
SFBM_CSV_COLUMNS = ("case", "station", "x_m", "Vx_N", "Vy_N", "Vz_N", "Mx_Nm", "My_Nm",
                    "Mz_Nm")
#: Columns of the envelope CSV file (SI, limit loads): the bound's value in ``value_N`` for
#: a shear, in ``value_Nm`` for a moment (the other is empty).
ENVELOPE_CSV_COLUMNS = ("station", "x_m", "component", "bound", "case", "value_N",
                        "value_Nm", *SFBM_CSV_COLUMNS[3:])

#: Regulatory hook angle of CS 29.865(a): the off-axis hook loads are inclined 30 deg from
#: the mast unless a smaller angle is shown not to be exceeded in service. [deg]
CS29865_ANGLE_DEG = 30.0
#: A previous-envelope station within this distance of a cut station is the same station
#: (the workbook's positions are rounded). [m]
SAME_STATION = 1e-3

TITLE = "Structural loads report: LIMIT loads, ULTIMATE where stated"
ANALYSIS = (
    "Structural loads of the carried helicopter hung by its rotor hub under the carrier "
    "rotorcraft: the CS 29.865 hook loads (Nz x weight along the mast and on a cone of "
    "inclined directions), fuselage and fin aerodynamic loads over the angle-of-attack / "
    "sideslip envelope, parachute drag, gravity and inertia relief (quasi-static, free-free), "
    "combined into shear forces and bending moments (SFBM) at the cut stations. Every table "
    "and plot holds LIMIT loads unless its title says ULTIMATE (ultimate = factor of safety x "
    "limit). Method: docs/loads-method.md.")
CONVENTIONS = (
    "Internal loads at a cut: the force and moment that the part AFT of the cut exerts on "
    "the part FORWARD of it, moments about the point (x_cut, y0, z0) of the loads reference "
    "axis; Vx > 0 is tension; +My puts the +z fibres in tension, +Mz the -y fibres.",
    "A point load exactly at a cut station belongs to the forward part. Hook directions: "
    "VERTICAL along the earth vertical of the attitude (hanging: hub above the CG), AZxxx "
    "inclined from that vertical towards azimuth xxx deg (0 aft, 90 right), TOW along the "
    "trimmed towing cable.",
    "LIMIT loads: hook load Nz x weight (CS 29.865) with the aerodynamic, parachute, gravity "
    "and inertia loads. ULTIMATE = ultimate factor (CS 29.303: 1.5) x LIMIT, only where a "
    "title says ULTIMATE.",
)

#: Report columns whose format is not that of their unit.
NUMBER_FORMATS = format_by_header([(r"residual", "0.00E+00")])

_PNG_DPI = 100


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


def _unit(kind, units):
    return unit_label(report_unit(kind, units))


def _limit(ultimate):
    return "ULTIMATE" if ultimate else "LIMIT"


# ------------------------------------------------------------------------------- tables
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
        index = _station_index(result, station)
        hull.insert(0, "vertex", np.arange(1, len(hull) + 1))
        hull.insert(0, "x_m", result.stations[index])
        hull.insert(0, "station", result.station_ids[index])
        frames.append(hull)
    frame = pd.concat(frames, ignore_index=True)
    return convert_columns(frame, {"x_m": ("x", "length"), **_loads_spec(pair)}, units)


def _station_index(result, station):
    if isinstance(station, (int, np.integer)):
        if not 0 <= int(station) < len(result.stations):
            raise InputError("station index out of range", int(station))
        return int(station)
    ids = list(result.station_ids)
    if str(station) not in ids:
        raise InputError(f"unknown station; valid ids are {ids}", station)
    return ids.index(str(station))


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
        ("aircraft mass", conv(items.total_mass, "mass"), _unit("mass", units)),
        ("CG x", conv(cg[0], "length"), _unit("length", units)),
        ("CG y", conv(cg[1], "length"), _unit("length", units)),
        ("CG z", conv(cg[2], "length"), _unit("length", units)),
        ("equivalent airspeed KEAS", conv(study.flight.eas, "airspeed"),
         _unit("airspeed", units)),
        ("density altitude", report_value(study.flight.density_altitude, "altitude", units),
         _unit("altitude", units)),
        ("air density", conv(study.flight.density, "density"), _unit("density", units)),
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
    base = (f"Cone about the earth vertical of the attitude: {np.degrees(hook.angle):.4g} deg "
            f"from the vertical")
    if not reduced:
        return base + " in every direction."
    where = ("at the pure lateral azimuths only" if hook.cone == "lateral directions"
             else "along an elliptical cone to the lateral angle")
    return (f"{base}, except {', '.join(reduced)} at the lateral angle "
            f"{np.degrees(hook.lateral):.4g} deg ({where}; the lateral-step study justifies "
            f"lateral directions only).")


def towed_outside(result):
    """The towed-flight cases whose trimmed cable lies outside the hook cone (ids)."""
    towed = result.towed_table()
    if towed.empty:
        return []
    return list(towed.loc[towed["inside hook cone"] != "yes", "case"])


def _outside_text(outside):
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
    return f"{rule} {_outside_text(outside)}"


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
        ("loads reference axis y0", float(length(y0)), _unit("length", units)),
        ("loads reference axis z0", float(length(z0)), _unit("length", units)),
        ("mast axis (unit vector) x", float(hp.mast_axis[0]), "-"),
        ("mast axis (unit vector) y", float(hp.mast_axis[1]), "-"),
        ("mast axis (unit vector) z", float(hp.mast_axis[2]), "-"),
    ], columns=["item", "value", "unit"])
    return {"mass items": mass, "stations": stations, "hardpoints": hardpoints, "axes": axis}


# ------------------------------------------------------------------------------- findings
def hook_angle_finding(result, lateral=None, justification=""):
    """The hook-cone inclinations against CS 29.865(a), with the evidence they rest on.

    Parameters
    ----------
    result : LoadsResult
    lateral : object, optional
        The lateral study of the same run (a result with ``study.recommended_angle`` [rad],
        ``study.max_load_angle`` [rad], ``study.margin`` and ``study.pendulums``), or None.
    justification : str
        The Study sheet's 'hook angle justification' (a reference to the evidence).

    Returns
    -------
    (str, str)
        ``(verdict, evidence)``: the verdict starts with ``FLAG`` when an inclination used is
        below 30 deg, or the lateral directions are inclined less than the lateral study
        recommends.
    """
    hook = result.study.hook
    ref = CS29865_ANGLE_DEG
    fore_aft = float(np.degrees(hook.angle))
    side = float(np.degrees(hook.lateral))
    if lateral is not None:
        st = lateral.study
        rec, peak = float(np.degrees(st.recommended_angle)), float(np.degrees(st.max_load_angle))
        said = (f"recommended design angle {rec:.1f} deg for the lateral directions"
                if np.isfinite(rec) else "no design angle (see its verdict)")
        evidence = (f"Lateral-step pendulum study of this run: largest load angle from the "
                    f"mast {peak:.1f} deg over {len(st.pendulums)} cases (carrier motions x "
                    f"rope lengths x bodies x stated ranges), margin {st.margin:g}, "
                    f"{said}; see the lateral report.")
    else:
        rec = peak = None
        evidence = ("No lateral-step pendulum study in this run: nothing here shows that a "
                    "smaller angle cannot be exceeded in service (run it with 'run lateral' = "
                    "yes).")
    if justification:
        evidence += f" Study sheet 'hook angle justification': {justification}"
    below = [(name, angle) for name, angle in (("fore-and-aft and diagonal", fore_aft),
                                                ("lateral", side)) if angle < ref - 1e-9]
    if below:
        which = "; ".join(f"{name} directions {angle:.1f} deg" for name, angle in below)
        verdict = (f"FLAG: hook loads inclined less than the {ref:.0f} deg of CS 29.865(a) from "
                   f"the vertical ({which}). A smaller angle is allowed only if it is shown "
                   f"that it cannot be exceeded in service.")
        if fore_aft < ref - 1e-9:
            verdict += (" The lateral-step study covers the lateral directions only: the "
                        "fore-and-aft angle needs its own evidence.")
        if rec is not None and rec > side + 1e-9:
            verdict += (f" The lateral study recommends {rec:.1f} deg: the lateral angle used is "
                        f"NOT covered by it.")
        elif rec is not None and side < ref - 1e-9:
            verdict += (f" The lateral study's recommended {rec:.1f} deg is within the lateral "
                        f"angle used, provided its motions cover the operation being "
                        f"certified.")
    elif rec is not None and rec >= 90.0:
        verdict = (f"FLAG: the lateral study finds load angles up to {peak:.1f} deg from the "
                   f"mast (recommended {rec:.1f} deg with its margin), beyond the {side:.1f} deg "
                   f"used for the lateral hook loads: the {ref:.0f} deg of CS 29.865(a) is not "
                   f"conservative for the motions swept, and no hook cone can be built at "
                   f"{rec:.1f} deg. Restrict the carrier motions or rope lengths, or "
                   f"substantiate the lateral hook loads otherwise.")
    elif rec is not None and rec > side + 1e-9:
        verdict = (f"FLAG: the lateral study recommends {rec:.1f} deg, more than the {side:.1f} "
                   f"deg used for the lateral hook loads: rerun the loads at {rec:.1f} deg.")
    else:
        verdict = (f"Hook loads inclined {fore_aft:.1f} deg from the vertical"
                   + (f" ({side:.1f} deg laterally)" if abs(side - fore_aft) > 1e-9 else "")
                   + f", the {ref:.0f} deg of CS 29.865(a) or more.")
    return verdict, evidence


def exceedance_findings(result, source=""):
    """Lines on the exceedance check: how many stations exceed, and where the previous
    envelope comes from."""
    comparison = result.comparison()
    if comparison is None:
        return ["No previous design envelope given: no exceedance check."]
    over = comparison[comparison["exceeds"]]
    worst = comparison["exceedance ratio"].replace(np.inf, np.nan)
    status = previous_station_status(result)
    interpolated = sum(s == "INTERPOLATED" for s in status)
    lines = [f"{len(over)} of {len(comparison)} station x component entries exceed the "
             f"previous design envelope (largest finite ratio "
             f"{np.nanmax(worst.to_numpy(float)) if worst.notna().any() else 0:.3f}); "
             f"components: {', '.join(sorted(set(over['component']))) or 'none'}. Sheets "
             "Exceedance and ExceedanceDetail."]
    if interpolated:
        lines.append(f"{interpolated} cut station(s) are not stations of the previous envelope:"
                     " its values there are INTERPOLATED linearly (marked on the sheets).")
    lines.append("Previous envelope: " + (source or "source not stated (Study sheet "
                                          "'previous envelope source')."))
    return lines


# ------------------------------------------------------------------------------- writing
def _safe(text):
    """A file-name-safe version of a station id (the Stations reader refuses ids that give
    the same one)."""
    return safe_file_part(text)


def _default_hull_station(result, pair):
    """The station where the first component of the pair has its largest magnitude."""
    j = component_index(pair[0])
    return result.station_ids[int(np.argmax(np.abs(result.loads[:, :, j]).max(axis=0)))]


def write_loads_outputs(result, out_dir, stem, units="SI", inputs_digest=None,
                        hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None, *,
                        input_paths: Sequence = (), max_rows=EXCEL_MAX_ROWS, plots=True,
                        info=None, findings=None, sfbm_workbook=False, figures=None,
                        nastran=None, checks=None, dynamics=None, study_findings=None):
    """Write the loads report (workbook, CSV tables, PNG plots) atomically: the Python call
    of :func:`~slingloads.io.common.report_writer.write_report` of :func:`loads_report`.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    out_dir : path-like
        Output directory (created if needed).
    stem : str
        File-name stem: ``<stem>-loads.xlsx``, ``<stem>-sfbm.csv``...
    units : str
        Unit system of the workbooks and plots, ``"SI"`` (m, N, N m) or ``"US"`` (in, lbf,
        lbf in). The CSV files are always SI.
    inputs_digest : dict or pandas.DataFrame, optional
        What the analysis was run from (input file name, SHA-256, ...), for the cover when
        no ``info`` is given.
    hull_pairs : sequence of (str, str)
        Component pairs of the 2-D envelopes.
    hull_stations : sequence of (str or int), optional
        Stations of the hull tables and plots. Default: the tables at every station, and
        one plot per pair at the station where its first component is largest.
    input_paths : sequence of path-like
        Input files: an output onto one of them is refused.
    max_rows : int
        Rows per sheet including the header (Excel's limit by default).
    plots : bool
        Draw the PNG plots and the Plots sheet (False for fast batch runs).
    info : ReportInfo, optional
        Identification of the report (cover, page headers and footers). Default: from
        ``inputs_digest``.
    findings : dict, optional
        ``{"lateral": lateral result or None, "hook angle handoff": HookAngleHandoff or None,
        "parachute decision": ParachuteDecision or None, "hook angle justification": str,
        "previous envelope source": str}`` for the Summary's findings.
    sfbm_workbook : bool
        Also write ``<stem>-sfbm.xlsx``, every case at every station in report units (the
        CSV file always has them in SI).
    figures : FigureRenderer, optional
        Already drawing this report's figures
        (:func:`~slingloads.io.common.report_writer.start_figures` of :func:`loads_report`
        with the same hull pairs and stations); default: drawn now.
    nastran : dict or True, optional
        Also write ``<stem>-loads.bdf``, the load cases as a Nastran input file in the units
        ``units``, with these options of :func:`~slingloads.io.loads.nastran.prepare_nastran`
        (True: the defaults), and a *Nastran* sheet linking each subcase to its case id.
    checks : pandas.DataFrame, optional
        Checks against the other analyses of the run (:mod:`slingloads.io.consistency`),
        shown on the Summary sheet with a warning when one fails.
    dynamics : pandas.DataFrame, optional
        The campaign's hand-off comparison (:class:`~slingloads.analyses.campaign.Handoff`
        ``.comparison``): written on a *Dynamics* sheet with the largest loads of the
        hand-entered cases against those of the cases from the dynamics.
    study_findings : Findings, optional
        The run's findings (:mod:`slingloads.runs.findings`), written on the Findings sheet.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    InputError
        On an unknown unit system, component or station, or an output onto an input file;
        nothing is written then.
    """
    check_units(units)
    deck = None
    if nastran is not None and nastran is not False:
        deck = prepare_nastran(result, units=units, inputs_digest=inputs_digest,
                               **({} if nastran is True else dict(nastran)))
    kind = loads_report(hull_pairs, hull_stations, plots=plots, findings=findings,
                        checks=checks, dynamics=dynamics, deck=deck,
                        sfbm_workbook=sfbm_workbook, max_rows=max_rows)
    if info is None:
        info = info_from_digest(inputs_digest, title=TITLE, analysis=ANALYSIS,
                                study=result.study.name, units=units, conventions=CONVENTIONS)
    return write_report(kind, result, out_dir, stem, units, figures=figures if plots else None,
                        findings=study_findings, info=info, inputs=input_paths)


def figure_jobs(result, units, hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None):
    """The loads report's figures: ``({tag: (plot function, args, kwargs)}, {tag: title})``,
    after checking the hull pairs and stations.

    Default hull plots: one per pair at the station where its first component is largest.
    """
    plot_hull, plot_sfbm, plot_station_diagram = (  # matplotlib loads where they are drawn
        plot_function("slingloads.io.loads.plots", name)
        for name in ("plot_hull", "plot_sfbm", "plot_station_diagram"))
    check_units(units)
    for pair in hull_pairs:
        if len(pair) != 2:
            raise InputError("a hull pair needs two components", pair)
        for name in pair:
            component_index(name)
    stations = hull_table_stations(result, hull_stations)
    for station in stations:
        _station_index(result, station)
    jobs = {"stations": (plot_station_diagram, (result.study, units), {})}
    titles = {"stations": "Cut stations, mass items and hardpoints where the LIMIT loads enter "
                          "(side and top views)"}
    for name in PNG_COMPONENTS:
        jobs[COMPONENT_TAGS[name]] = (plot_sfbm, (result, name, units), {})
        titles[COMPONENT_TAGS[name]] = f"{COMPONENT_TITLES[name]} {name}, LIMIT loads"
    for pair in hull_pairs:
        where = stations if hull_stations is not None else [_default_hull_station(result, pair)]
        for station in where:
            index = _station_index(result, station)
            tag = f"hull_{pair[0]}_{pair[1]}_{_safe(result.station_ids[index])}"
            jobs[tag] = (plot_hull, (result, index, pair, units), {})
            titles[tag] = f"{pair[0]}-{pair[1]} LIMIT envelope at {result.station_ids[index]}"
    return jobs, titles


def hull_table_stations(result, hull_stations=None):
    """The stations of the hull tables: ``hull_stations`` (ids or indices), else every cut
    station."""
    return list(hull_stations) if hull_stations is not None else list(result.station_ids)


def envelope_csv_frame(result):
    """The LIMIT envelope as written to the CSV file: :meth:`LoadsResult.envelope` itself
    (SI, ``name_unit`` headers)."""
    return result.envelope()[list(ENVELOPE_CSV_COLUMNS)]


def sheets_columns(sheets, name):
    """Column names of the tables of one sheet."""
    content = sheets.get(name)
    if isinstance(content, pd.DataFrame):
        return list(content.columns)
    if isinstance(content, str) or content is None:
        return []
    return [c for s in content if s.table is not None for c in s.table.columns]


def nastran_sheet(deck):
    """The *Nastran* sheet: the file's settings, the subcase -> case id table, the grids."""
    return [Section("Nastran input file (<stem>-loads.bdf): settings", deck.settings_table()),
            Section("Subcases: number, LOAD set and the case id each stands for",
                    deck.subcase_table(),
                    note="Nastran labels hold printable ASCII; a longer or non-ASCII case id "
                         "is shortened and ends in '~' and a checksum."),
            Section("Grids (model axes, file units) and CONM2 elements", deck.grid_table())]


def _workbook_sheets(result, units, hull_pairs, stations, findings, checks=None):
    """The sheets of the loads workbook, in order."""
    study = result.study
    verdict, evidence = hook_angle_finding(result, findings.get("lateral"),
                                           findings.get("hook angle justification", ""))
    closure = closure_table(result, units)
    closure_line = (f"Free-free closure: {'PASS' if closure_passes(result) else 'FAIL'} "
                    f"(largest residual against {CLOSURE_TOLERANCE:g} x the load scale).")
    outside = towed_outside(result)
    hook_handoff = findings.get("hook angle handoff")
    notes = [verdict, *([hook_handoff.describe()] if hook_handoff is not None else []),
             "Evidence: " + evidence,
             *(["FLAG: towed cables " + _outside_text(outside)] if outside else []),
             *[f"FLAG: {line}" for line in result.towed_findings()],
             *exceedance_findings(result, findings.get("previous envelope source", "")),
             closure_line]
    summary = [
        Section("Summary of the LIMIT loads analysis: findings", note="\n".join(notes)),
        *warning_sections(findings.get("warnings", ())),
    ]
    if checks is not None and len(checks):
        failed = checks["status"] != "ok"
        lines = [f"WARNING: {n}" for n in checks["note"][failed]] or [
            "Every check against the other analyses of this run passes: "
            + " ".join(checks["note"])]
        summary.append(Section(  # the notes above the table, which stays narrow for print
            "Consistency with the other analyses of this run",
            checks.drop(columns=["note"], errors="ignore"), note="\n".join(lines)))
    if hook_handoff is not None:
        summary.append(Section("Lateral hook angle: the lateral study's hand-off to the loads",
                               hook_handoff.to_frame()))
    if study.parachute is not None:  # the loads' parachute: the study's one decision on it
        summary += decision_section(findings.get("parachute decision"), units)
    summary += [
        Section("Study settings", study_table(result, units)),
        Section("Attitude (earth vertical in airframe axes)", attitude_table(result),
                note=result.attitude.describe() + ". Gravity, the vertical hook case and the "
                     "hook cone are taken about this vertical."),
        Section("Hook-load directions (CS-29.865)", hook_direction_table(result),
                note=hook_direction_note(result)),
        Section("Towed-flight equilibrium cases: trimmed attitude and cable angles",
                towed_summary_table(result),
                note=towed_note(result)),
        Section("Closure check (free-free equilibrium)", closure),
    ]
    tables = inputs_tables(result, units)
    total = float(in_report_units(study.airframe.mass_items.total_mass, "mass", units))
    inputs = [
        Section("Inputs of the LIMIT loads analysis: mass items, cut stations, hardpoints",
                note="As read from the input workbook (Study, MassItems, Stations, Hardpoints "
                     "sheets), in the report's units."),
        Section("Mass items (transport configuration)", tables["mass items"],
                note=f"{len(tables['mass items'])} items, total {total:,.1f} "
                     f"{_unit('mass', units)}."),
        Section("Cut stations", tables["stations"]),
        Section("Hardpoints (where external loads enter)", tables["hardpoints"],
                note="Weight: share of the hub load taken by each mast foot in the "
                     "rigid-body (RBE3-like) distribution."),
        Section("Loads reference axis and mast axis", tables["axes"]),
    ]
    factor = study.ultimate_factor
    envelope = [
        Section("Envelope of LIMIT loads: max and min of each component over every case, with "
                "the critical case",
                note="Correlated loads of each critical case: sheet Correlated. ULTIMATE "
                     "loads: sheet Ultimate."),
        Section("Governing cases: largest |LIMIT load| of each component",
                governing_report_table(result, units)),
        Section("Shear forces (LIMIT): Vx axial (> 0 tension), Vy and Vz",
                envelope_wide_table(result, COMPONENTS[:3], units)),
        Section("Moments (LIMIT): Mx torsion, My and Mz bending about the loads reference "
                "axis", envelope_wide_table(result, COMPONENTS[3:], units)),
    ]
    correlated = [Section("Envelope of LIMIT loads with the correlated loads of the critical "
                          "case (one row per station, component and bound)",
                          envelope_report_table(result, units))]
    wide = exceedance_wide_table(result, units)
    if wide is not None:
        source = findings.get("previous envelope source", "")
        exceedance = [Section(
            "Exceedance of the LIMIT envelope over the previous design envelope, by station",
            wide,
            note="ratio = max(new max+ / previous max+, |new min-| / |previous min-|); above 1 "
                 "(red) the new envelope exceeds the previous one; "
                 f"'{UNBOUNDED_RATIO}' (red): a new load where the previous envelope is 0. "
                 "'previous values': given at "
                 "this station, or INTERPOLATED linearly between the previous envelope's "
                 "stations. Where the previous envelope comes from: "
                 + ("Summary, findings." if source else "not stated (Study sheet 'previous "
                    "envelope source')."))]
        detail = [Section("LIMIT loads over the previous design envelope: exceedance at every "
                          "station and component", comparison_report_table(result, units))]
    else:  # one page says so (the Summary too); the detail sheet would repeat it
        exceedance, detail = "no previous envelope given", None
    ultimate = [
        Section(f"Envelope of ULTIMATE loads = {factor:g} x LIMIT loads",
                note=f"Ultimate factor of safety {factor:g} (CS 29.303). Only this sheet holds "
                     "ULTIMATE loads; every other sheet, plot and CSV file holds LIMIT loads."),
        Section(f"Shear forces (ULTIMATE = {factor:g} x LIMIT)",
                envelope_wide_table(result, COMPONENTS[:3], units, ultimate=True)),
        Section(f"Moments (ULTIMATE = {factor:g} x LIMIT)",
                envelope_wide_table(result, COMPONENTS[3:], units, ultimate=True)),
    ]
    hulls = ([Section("2-D envelopes (convex hulls) of LIMIT loads at chosen stations",
                      note="Vertices counter-clockwise from the case of the smallest first "
                           "component; every case inside or on the hull. "
                           "Stations and pairs: Study sheet 'hull stations', 'hull pairs'.")]
             + [Section(f"{a}-{b} convex hull vertices, LIMIT loads",
                        hull_report_table(result, (a, b), stations, units))
                for a, b in hull_pairs]) if hull_pairs else "no hull pair requested"
    cases, factors = case_report_tables(result, units)
    counts = cases["source"].value_counts()
    origin = ", ".join(f"{counts[s]} {s}" for s in CASE_SOURCES if s in counts)
    cases_sheet = [Section(
        f"LIMIT load cases ({len(cases)}: {origin}): hook direction x "
        "aerodynamic point x parachute, cable angles, description", cases),
        Section(f"LIMIT load factors of the load cases ({len(cases)}), angular accelerations "
                "and closure residuals", factors, sheet="LoadFactors")]
    sheets = {
        "Summary": summary,
        "Inputs": inputs,
        "LoadCases": cases_sheet,
        "Envelope": envelope,
        "Correlated": correlated,
        "Exceedance": exceedance,
        "ExceedanceDetail": detail,
        "Ultimate": ultimate,
        "Hulls": hulls,
    }
    return {name: content for name, content in sheets.items() if content is not None}


_NUMBER = re.compile(r"(?<![\w.+-])-?\d+(?:\.\d+)?(?![\w.])")


def _angle_text(value):
    """An angle of the hand-off table [deg] at the report's 0.1 deg: a number rounded, every
    number of a range written the same (``"theta -28.01 to -12.05"`` -> ``"theta -28.0 to
    -12.1"``); a text without numbers unchanged.

    Examples
    --------
    >>> _angle_text("hand points, and -32.42 to 0 (DYN-* points)")
    'hand points, and -32.4 to 0.0 (DYN-* points)'
    """
    if isinstance(value, str):
        return _NUMBER.sub(lambda m: f"{float(m.group(0)):.1f}", value)
    return value


def dynamics_sections(result, comparison, units="SI"):
    """The *Dynamics* sheet: what the campaign's dynamics changed in the cases, and the
    largest loads of the hand-entered cases against those of the cases from the dynamics."""
    from slingloads.analyses.campaign import comparison_as_run, loads_comparison

    table = comparison_as_run(comparison, result.study.hook)
    if units == "US":
        for unit, kind in (("N", "force"), ("m^2", "area")):
            rows = table["unit"] == unit
            label = unit_label(report_unit(kind, units))
            for column in ("hand-entered", "dynamics reached", "with margin",
                           "used in the loads"):
                values = pd.to_numeric(table.loc[rows, column], errors="coerce")
                table.loc[rows, column] = in_report_units(values.to_numpy(float), kind, units)
            table.loc[rows, "unit"] = label
    columns = [c for c in ("hand-entered", "dynamics reached", "with margin",
                           "used in the loads", "note") if c in table.columns]
    degrees = table["unit"] == "deg"
    for column in columns:  # an angle to 0.1 deg, in its ranges as in its numbers
        table.loc[degrees, column] = table.loc[degrees, column].map(_angle_text)
    sections = [Section("Hand-entered against the dynamics (the campaign's hand-off)", table,
                        note=result.study.dynamics.note if result.study.dynamics else "")]
    loads = loads_comparison(result)
    if loads is not None:
        loads = convert_by_component(loads.drop(columns="kind"),
                                     ["hand-entered cases", "dynamics cases"], units)
        sections.append(Section(
            "Largest |limit load| over the airframe: hand-entered cases against the cases "
            "from the dynamics (LoadCases column 'source')", loads))
    return sections


def sfbm_csv(result):
    """The bytes of ``<stem>-sfbm.csv``: every case at every station, SI LIMIT loads."""
    return csv_bytes(result.to_frame(), columns=SFBM_CSV_COLUMNS)


def envelope_csv(result):
    """The bytes of ``<stem>-envelope.csv`` (:func:`envelope_csv_frame`)."""
    return csv_bytes(envelope_csv_frame(result))


#: The loads report's CSV files: name after the stem -> function of the result to its bytes.
CSV_FILES = {"sfbm.csv": sfbm_csv, "envelope.csv": envelope_csv}


def _sheets(result, units, warnings=(), *, hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None,
            findings=None, checks=None, dynamics=None, deck=None):
    """The sheets of the loads workbook (:func:`_workbook_sheets`), with the *Nastran* sheet
    of ``deck`` and the *Dynamics* sheet of the campaign's hand-off ``dynamics`` when
    given; ``warnings`` on the Summary unless ``findings`` names its own."""
    sheets = _workbook_sheets(result, units, hull_pairs,
                              hull_table_stations(result, hull_stations),
                              {"warnings": warnings, **(findings or {})}, checks)
    if deck is not None:
        sheets["Nastran"] = nastran_sheet(deck)
    if dynamics is not None:
        sheets["Dynamics"] = dynamics_sections(result, dynamics, units)
    return sheets


def _highlight(sheets):
    """The ratios filled red: above 1 on the Exceedance sheets."""
    return {"Exceedance": Highlight([c for c in sheets_columns(sheets, "Exceedance")
                                     if c.endswith("ratio [-]") or c == "worst [-]"]),
            "ExceedanceDetail": Highlight(["exceedance ratio [-]"], 1.0)}


def _number_format(result):
    return NUMBER_FORMATS


def _figures(result, units, hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None, plots=True):
    """The figures to draw (:func:`figure_jobs`, which checks the hull pairs and stations;
    none when ``plots`` is false)."""
    jobs = figure_jobs(result, units, hull_pairs, hull_stations)[0]
    return jobs if plots else {}


def _titles(result, hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None, plots=True):
    return figure_jobs(result, "SI", hull_pairs, hull_stations)[1] if plots else {}


def _write_sfbm(result, units, path, info, max_rows=EXCEL_MAX_ROWS):
    """``<stem>-sfbm.xlsx``: the SFBM of every case at every station in report units, a data
    workbook split past ``max_rows`` rows."""
    write_workbook(path, {"SFBM": sfbm_table(result, units)}, max_rows=max_rows,
                   info=replace(info, title=f"{TITLE}: SFBM of every case (data)", files=()))


def _write_deck(deck, result, units, path, info):
    """``<stem>-loads.bdf``: the Nastran input file ``deck``, prepared in ``units``."""
    deck.write(path)


#: The loads report with its default options (:func:`loads_report`): files named
#: ``<stem>-<name>`` (:data:`OUTPUTS`).
REPORT = ReportKind(tag="loads", prefix="", title=TITLE, description=ANALYSIS,
                    conventions=CONVENTIONS, dpi=_PNG_DPI, sheets=_sheets, figures=_figures,
                    titles=_titles, data=CSV_FILES, number_format=_number_format,
                    highlight=_highlight, images_title="Plots of the LIMIT loads ({count})")


def loads_report(hull_pairs=DEFAULT_HULL_PAIRS, hull_stations=None, *, plots=True,
                 findings=None, checks=None, dynamics=None, deck=None, sfbm_workbook=False,
                 max_rows=EXCEL_MAX_ROWS):
    """The loads report (:data:`REPORT`, written by
    :func:`~slingloads.io.common.report_writer.write_report`) with its options: those of
    :func:`write_loads_outputs`, and ``deck``, the Nastran input file already prepared
    (:func:`~slingloads.io.loads.nastran.prepare_nastran`), written as ``<stem>-loads.bdf``
    with a *Nastran* sheet.

    Returns
    -------
    ReportKind
    """
    hulls = {"hull_pairs": hull_pairs, "hull_stations": hull_stations}
    return replace(
        REPORT,
        sheets=partial(_sheets, **hulls, findings=findings, checks=checks, dynamics=dynamics,
                       deck=deck),
        figures=partial(_figures, **hulls, plots=plots),
        titles=partial(_titles, **hulls, plots=plots),
        files={"sfbm.xlsx": partial(_write_sfbm, max_rows=max_rows)} if sfbm_workbook else {},
        appendices={} if deck is None else {"loads.bdf": partial(_write_deck, deck)})


def report_kind(study, checks=None, deck=None):
    """The loads report of a workbook's study: its Study-sheet options, and the findings of
    the other analyses of the run (the lateral study of the same run, when there is one, is
    the evidence on the hook angle; the campaign's hand-off, when the loads took the
    dynamics' cases); ``checks`` and ``deck`` as in :func:`loads_report`."""
    options, results = study.report, study.results
    findings = {"lateral": results.lateral,
                "hook angle handoff": results.loads_hook_angle,
                "parachute decision": results.parachute_decision,
                "hook angle justification": options.hook_angle_justification,
                "previous envelope source": options.previous_envelope_source}
    handoff = results.loads_handoff
    return loads_report(options.hull_pairs, options.hull_stations, findings=findings,
                        checks=checks, dynamics=None if handoff is None else handoff.comparison,
                        deck=deck, sfbm_workbook=options.sfbm_workbook)


def write(result, out_dir, stem, units, study, figures=None, checks=None, findings=None):
    """Write the loads report of a study into the run's outputs ``out_dir``
    (:func:`~slingloads.io.common.report_writer.write_report` of :func:`report_kind`), with
    the study's identification, report options, warnings and findings, the ``checks``
    against the other analyses of the run (:mod:`slingloads.io.consistency`), the Nastran
    input file when the study asks for it, and the run's ``findings`` on the Findings sheet
    (default: those of ``study.results``)."""
    options = study.report
    with located(study.path):
        deck = None
        if options.nastran:
            settings = {**options.nastran_settings, "locations": options.nastran_locations}
            deck = prepare_nastran(result, units=units, inputs_digest=input_digest(study),
                                   **settings)
        return write_report(report_kind(study, checks, deck), result, out_dir, stem, units,
                            study, figures, findings)

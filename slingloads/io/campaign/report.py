"""The campaign report: an Excel workbook, PNG plots and the histories as Parquet.

The campaign is run by :func:`slingloads.runs.campaign.run` (on the executor the command line
or the workbook asks for, with the run cache of :mod:`slingloads.runs.cache`); this module
only says what its report is made of (:func:`report_kind`), which the one report writer
publishes all at once or not at all (:mod:`slingloads.io.common.atomic`):

* ``<stem>-campaign.xlsx``, print-ready (:mod:`slingloads.io.common.excel`): sheets *Cover*
  (identification, input file and its SHA-256, version, sheets, conventions), *Summary*
  (warnings on the inputs, selection with its governing conditions, the 1.0 x neutral area
  in the 1-DOF and multibody models, matrix definition, execution, speed limits without
  parachute, loads hand-off), *Matrix*, *Metrics* (one row per run, in column blocks that fit
  a page), *Selection* (by area), *NeutralArea*, *Sensitivity*, *StabilityMap*, *NoParachute*,
  *LoadsHandoff* and *Plots*;
* ``<stem>-campaign-<tag>.png``: selection, sensitivity to each factor (paper figures 9-13),
  stability map, root locus, transport without parachute (figures 16-18) and its ramps with a
  gust, loads envelope;
* ``<stem>-campaign-histories.parquet``: every stored history (SI, angles in degrees), a
  ``run`` column first (matrix run ids; ``NP-<helicopter>-<target>kt`` without parachute,
  ``NP-<helicopter>-<target>kt-gust`` its ramps with a gust).

Speeds, lengths, masses, areas and forces are in the report unit system (``--units``: SI, or
kt, ft, lb, ft^2, lbf); the Parquet file is SI.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads import __version__
from slingloads.analyses.verdicts import ratio_words
from slingloads.constants import KNOT, POUND
from slingloads.io.campaign.words import mass_text
from slingloads.io.common.excel import Section
from slingloads.io.common.figures import plot_function
from slingloads.io.common.ownership import PARQUET_KEY
from slingloads.io.common.report import (
    explain_infinite,
    in_report_units,
    quantity_text,
    report_unit,
    report_value,
    si_columns_in_units,
    warning_sections,
)
from slingloads.io.common.report_writer import ReportKind
from slingloads.io.common.units import unit_label

ANALYSIS = "campaign"
_PNG_DPI = 90
#: Names of the files of a campaign report, for the publisher (a new report replaces them).
OUTPUTS = ("{stem}-campaign.xlsx", "{stem}-campaign-histories.parquet", "{stem}-campaign-*.png")
TITLE = "Campaign report: parachute selection over the operating envelope"
DESCRIPTION = (
    "The multibody model of the towed sling load run over a matrix of parachute areas, "
    "airspeeds, mass cases, density altitudes, cable lengths, carriers and manoeuvres: the "
    "smallest parachute area stable in every condition and the recommended one (least drag "
    "meeting the damping criterion), with their governing conditions; the 1.0 x neutral area "
    "checked in the 1-DOF and multibody models; the sensitivity to each factor; the stability "
    "map over area x airspeed; the transport without parachute; and the angle envelope "
    "handed to the loads. Method: docs/campaign.md.")
CONVENTIONS = (
    "Earth axes of the multibody model: X aft along the flight path, Y right, Z up; yaw is "
    "the heading of the carried helicopter from the flight path, beta > 0 wind from the "
    "right. Areas are flat-plate parachute areas; area factor = area / neutral static area "
    "(total dN/dbeta = 0).",
    "A condition is stable when every eigenvalue's real part is below -1e-6 1/s. The loads "
    "hand-off gives the extremes of the dynamics (angles, tensions) times the loads margin, "
    "not loads; the loads report states LIMIT or ULTIMATE. Definitions: docs/campaign.md, "
    "docs/multibody.md.",
)
#: The quantity of a header's SI unit (a length whose name says altitude is an altitude;
#: every speed of the campaign's tables is an airspeed, in kt in both unit systems).


#: How the campaign's tables write the metrics that have no finite value.
_INFINITE = {"yaw mode period [s]": "none (aperiodic)",
             "yaw mode time to half amplitude [s]": "none (not damped)",
             "longest yaw-mode time to half amplitude [s]": "none (not damped)"}


def _explained(frame):
    """``frame`` with the infinite metrics of :data:`_INFINITE` written as what they mean."""
    for column, text in _INFINITE.items():
        frame = explain_infinite(frame, [column], text)
    return frame


def in_units(frame, units):
    """A copy of ``frame`` with its SI columns in the report units
    (:func:`~slingloads.io.common.report.si_columns_in_units`): every speed of the campaign's
    tables (airspeeds, ramp targets) is an airspeed, in kt in both unit systems."""
    return si_columns_in_units(frame, units, airspeed=lambda name: True)


# ------------------------------------------------------------------------------- tables
def _items(rows):
    return pd.DataFrame(rows, columns=["item", "value", "unit", "note"])


def _in(kind):
    """``value -> (value in report units, unit)`` of a quantity ``kind``, for listings."""
    return lambda v, units: (report_value(v, kind, units),
                             unit_label(report_unit(kind, units)))


_speed, _length, _altitude, _area = (_in(k) for k in ("airspeed", "length", "altitude",
                                                       "area"))


def definition_table(report, units):
    """The campaign's definition: factors, settings, criteria, execution."""
    c = report.inputs.campaign
    frame = c.matrix.frame
    r = report.result
    ex = r.execution

    def listed(v):  # a factor as its cell (0.000), trailing zeros dropped: never 1.4999...6
        return f"{v:.3f}".rstrip("0").rstrip(".") if isinstance(v, float) else str(v)

    def listing(column, convert=None):
        values = list(dict.fromkeys(frame[column]))
        if convert is None:
            return ", ".join(dict.fromkeys(listed(v) for v in values)), ""
        shown = [convert(v)[0] for v in values]
        return ", ".join(f"{v:.4g}" for v in shown), convert(values[0])[1]

    masses = ", ".join(f"{k} {(m / POUND if units == 'US' else m):,.1f}"  # as its cells
                       for k, m in c.matrix.masses.items())
    rows = [
        ("runs in the matrix", len(frame), "-", "full factorial" if c.rows is None
         else "listed rows"),
        ("area factors", *listing("area factor [-]"),
         "x neutral static area" + (
             f"; {report.sizing_factor:.4g} added: the parachute sizing's proposed area"
             if getattr(report, "sizing_factor", None) is not None else "")),
        ("airspeeds EAS", *listing("airspeed EAS [m/s]", lambda v: _speed(v, units)), ""),
        ("mass cases", masses, "lb" if units == "US" else "kg", "inertia scaled with mass"),
        ("density altitudes", *listing("density altitude [m]",
                                       lambda v: _altitude(v, units)), "ISA"),
        ("cable lengths", ", ".join(quantity_text(v, "length", units).rpartition(" ")[0]
                                    for v in dict.fromkeys(frame["cable length [m]"])),
         _length(1.0, units)[1], ""),
        ("carriers", *listing("carrier"), ""),
        ("manoeuvres", *listing("manoeuvre"), ""),
        ("run length", c.settings.t_end, "s", ""),
        (("time step", c.settings.dt, "s", "fixed step, Dormand-Prince 5(4)")
         if c.settings.dt is not None else
         ("integration", "adaptive", "", f"Dormand-Prince 5(4), rtol {c.settings.rtol:g}, "
          f"atol {c.settings.atol:g}")),
        ("output interval", c.settings.output_interval, "s", ""),
        ("damping criterion: least yaw-mode damping ratio", c.criteria.min_damping, "-", ""),
        ("damping criterion: longest yaw-mode time to half amplitude",
         c.criteria.max_half_time, "s", ""),
        ("loads margin on the dynamics' extremes", c.margin, "-", ""),
        ("executor", ex.executor, "", ""),
        *_cache_rows(ex, report.cache),
    ]
    return _items(rows)


def _cache_rows(ex, cache):
    """Runs found in the cache and computed now: the matrix's, then those without parachute
    (each group counted on its own, so the matrix's rows never exceed its runs)."""
    from slingloads.runs.cache import where_stated

    parts = ex.parts or ((ex.total, ex.cached, ex.computed),)
    rows = [("run cache folder", str(cache), "", where_stated(cache)[0]),
            ("runs found in the cache", parts[0][1], "-", "of this matrix"),
            ("runs computed now", parts[0][2], "-", f"in {ex.batches} batches")]
    if len(parts) > 1:
        rows += [("runs without parachute found in the cache", parts[1][1], "-", ""),
                 ("runs without parachute computed now", parts[1][2], "-", "")]
    return rows


def selection_table(report, units):
    """The selection: neutral area, smallest stable and recommended areas, governing
    conditions, and the 1.0 x neutral area's verdicts."""
    r = report.result
    sel = r.selection
    neutral = r.neutral.area
    a_neutral, unit = _area(neutral, units)
    gs, gr = sel.governing_stable, sel.governing_recommended

    def area(factor):
        return _area(factor * neutral, units)[0] if np.isfinite(factor) else np.nan

    rows = [
        ("neutral static area (1-DOF sizing)", a_neutral, unit,
         f"total dN/dbeta = 0 (paper 4.1), {r.campaign.neutral_condition}"),
        ("smallest area stable in every condition", area(sel.smallest_stable), unit,
         f"{sel.smallest_stable:.3g} x neutral" if np.isfinite(sel.smallest_stable)
         else "no area of the matrix is stable in every condition"),
        ("its governing condition", gs["condition"], "",
         f"fails below with: {gs['fails below with']}" if gs["fails below with"] else
         "the least damped condition at that area"),
        ("recommended area (least drag meeting the damping criterion)",
         area(sel.recommended), unit,
         f"{sel.recommended:.3g} x neutral (paper: 1.4 x)" if np.isfinite(sel.recommended)
         else "no area meets the criterion in every condition"),
    ]
    if gr is not None:
        rows += [("its governing condition (least yaw damping)", gr["condition"], "",
                  f"yaw-mode damping {ratio_words(gr['least yaw-mode damping ratio [-]'])} "
                  f"({gr['with manoeuvre']})"),
                 ("its largest trimmed swing angle", gr["largest trimmed swing angle [deg]"],
                  "deg", gr["largest swing condition"])]
    check = r.neutral_check
    one = check[check["model"] == "1-DOF yaw"]
    multi = check[(check["model"] == "multibody") & (check["test"] == "eigenvalues")]
    rows += [
        ("1.0 x neutral area, 1-DOF yaw model", ", ".join(sorted(set(one["verdict"]))), "",
         "standard 9.144 m/s lateral gusts (CS 29.341)"),
        ("1.0 x neutral area, multibody eigenvalues",
         f"stable in {(multi['verdict'] == 'stable').sum()} of {len(multi)} conditions", "",
         ", ".join(f"{v}: {n}" for v, n in multi["verdict"].value_counts().items())),
    ]
    return _items(rows)


def no_parachute_table(report, units):
    """Speed limits without parachute, in kt whatever the unit system."""
    npr = report.result.no_parachute
    if npr is None:
        return None
    return npr.limits.drop(columns=["largest convergent ramp [m/s]"])


def handoff_table(report, units="SI"):
    """The envelope handed to the loads, angles in degrees, the line tension in the report's
    force unit (one unit per quantity: lbf in a US report, as every force of it)."""
    from slingloads.analyses.campaign.loads_envelope import QUANTITIES
    from slingloads.io.common.report import report_unit
    from slingloads.io.common.units import unit_label

    env = report.result.envelope
    if env is None:
        return None
    frame = env.to_frame()
    values = ["reached min", "reached max", "with margin min", "with margin max"]
    for quantity, _, _, kind in QUANTITIES:
        if kind != "force":
            continue
        row = frame["quantity"] == quantity
        frame.loc[row, values] = in_report_units(
            frame.loc[row, values].to_numpy(float), "force", units)
        frame.loc[row, "unit"] = unit_label(report_unit("force", units))
    return frame


def _sheets(report, units, warnings=(), decision=None):
    # the campaign's modules load when its report is written, not when its files are named
    from slingloads.analyses.campaign import GUST_DELAY, GUST_DURATION
    from slingloads.io.common.decision import decision_section
    from slingloads.runs.cache import where_stated

    r = report.result
    decision = r.decision if decision is None else decision
    summary = [Section("Summary of the campaign",
                       note="Parachute selection first; every run: sheets Matrix and "
                            "Metrics."),
               *warning_sections(warnings),
               *decision_section(decision, units),
               Section("Parachute selection", selection_table(report, units)),
               Section("Campaign", definition_table(report, units),
                       note=where_stated(report.cache)[1])]
    limits = no_parachute_table(report, units)
    if limits is not None:
        summary.append(Section("Transport without parachute: largest convergent ramp",
                               limits))
    handoff = handoff_table(report, units)
    if handoff is not None:
        summary.append(Section(f"Dynamics handed to the loads: runs at "
                               f"{r.envelope.area_factor:g} x neutral area, margin "
                               f"{r.envelope.margin:g}", note="Extremes and the envelope "
                               "with its margin: sheet LoadsHandoff."))
    matrix = r.campaign.matrix.frame
    results = r.metrics[["run", *(c for c in r.metrics.columns if c not in matrix.columns)]]
    sheets = {
        "Summary": summary,
        "Matrix": [Section("The run matrix", in_units(r.campaign.matrix.frame, units),
                           keys=["run"])],
        "Metrics": [Section("Metrics of every run (its definition: sheet Matrix)",
                            _explained(in_units(results, units)), keys=["run"])],
        "Selection": [Section("By area factor",
                              _explained(in_units(r.selection.by_area, units)))],
        "NeutralArea": [Section("1.0 x neutral area: 1-DOF and multibody verdicts",
                                r.neutral_check)],
    }
    sens = [Section(f"Sensitivity to the {name}", in_units(table, units))
            for name, table in r.sensitivity.items()]
    if r.carrier is not None:
        sens.append(Section("Carrier free against frozen (paired runs)",
                            in_units(r.carrier, units)))
    sheets["Sensitivity"] = ([Section("Sensitivity of the metrics to each factor of the "
                                      "matrix", note="Each row: the runs with that value "
                                      "of the factor, over every value of the others "
                                      "(largest or least as the header says); for every "
                                      "factor but the parachute area, only the runs at the "
                                      "selected area factor (column 'at area factor'): the "
                                      "area is fixed first, then the rest varies."), *sens]
                             if sens else "no factor varies")
    if r.stability is not None:
        sheets["StabilityMap"] = [
            Section("Stability map over parachute area x airspeed x density altitude"),
            Section("Minimum stable area by airspeed and density altitude",
                    _minimum_stable(r, units), note=minimum_stable_basis(r, units)),
            Section("Every grid point", _explained(in_units(r.stability.points, units)),
                    keys=["area factor [-]", "airspeed EAS [m/s]", "airspeed EAS [kt]"])]
    if r.no_parachute is not None:
        keys = ["helicopter", "ramp target [m/s]", "ramp target [kt]"]
        sheets["NoParachute"] = [Section(
            "Every ramp", _explained(in_units(r.no_parachute.runs, units)), keys=keys)]
        if not r.no_parachute.gust_runs.empty:
            study = r.campaign.no_parachute
            sheets["NoParachute"].append(Section(
                f"Every ramp with a lateral gust ({GUST_DURATION:g} s of "
                f"{quantity_text(study.gust_speed, 'speed', units, digits=3)}, "
                f"{GUST_DELAY:g} s after the ramp's end; the verdict read after the gust)",
                _explained(in_units(r.no_parachute.gust_runs, units)), keys=keys))
    sheets["LoadsHandoff"] = (
        [Section("Extremes of the chosen parachute's runs", handoff)] if handoff is not None
        else "no area is stable in every condition and none was chosen: nothing is handed to "
             "the loads")
    return sheets


#: The basis of the stability map's minimum stable area, in the note of each of its rows.
EIGENVALUES_ONLY = "eigenvalues only"


def minimum_stable_basis(result, units):
    """The basis of the stability map's minimum stable area, for the note over its table:
    the linear model about the trim (eigenvalues only), beside the campaign's chosen area,
    which also needs the time-domain runs, so that a checker reads why the two differ."""
    basis = ("Minimum stable area from the eigenvalues only (linear model about the trim): "
             "the smallest area whose least-damped eigenvalue is stable.")
    factor = result.chosen_area_factor
    if factor is not None and np.isfinite(factor):
        chosen = quantity_text(factor * result.neutral.area, "area", units)
        return (f"{basis} The campaign's chosen {chosen} (sheet Selection) also needs every "
                "time-domain run of the matrix stable.")
    return (f"{basis} A campaign choice also needs every time-domain run of the matrix "
            "stable; none was chosen (sheet Selection).")


def _minimum_stable(result, units):
    """The stability map's minimum stable areas, each row's note naming its basis
    (:data:`EIGENVALUES_ONLY`, told in full by :func:`minimum_stable_basis`) before what
    the map says of the row."""
    frame = result.stability.minimum.copy()
    frame["note"] = [f"{EIGENVALUES_ONLY}; {note}" if note else EIGENVALUES_ONLY
                     for note in frame["note"].fillna("").astype(str)]
    return in_units(frame, units)


def sweep_plots(result):
    """(tag, run ids, factor column, title) of the sensitivity plots (paper figures 9-13)."""
    from slingloads.analyses.campaign import FACTORS, base_condition, sweep_runs

    m = result.campaign.matrix.frame
    base = base_condition(m, result.chosen_area_factor)
    manoeuvres = list(dict.fromkeys(m["manoeuvre"]))
    free = "free response" if "free response" in manoeuvres else manoeuvres[0]
    gust = next((x for x in manoeuvres if x.startswith("gust")), free)
    choice = {"area factor [-]": free, "airspeed EAS [m/s]": free, "carrier": free,
              "cable length [m]": gust, "density altitude [m]": gust, "mass case": gust}
    out = []
    for factor, name in FACTORS.items():
        runs = sweep_runs(m, factor, base, choice[factor])
        if runs:
            tag = "sensitivity-" + name.replace(" ", "-")
            out.append((tag, runs, factor, f"{name}: {choice[factor]}"))
    return out


def _locus(result, units="SI"):
    """(loci, title) of the stability map's least-damped roots at its highest airspeed and
    first density altitude, or None without them."""
    loci = getattr(result.stability, "loci", None)
    if loci is None or loci.empty:
        return None
    speed = loci["airspeed EAS [m/s]"].max()
    altitude = loci["density altitude [m]"].iloc[0]
    sel = loci[np.isclose(loci["airspeed EAS [m/s]"], speed)
               & np.isclose(loci["density altitude [m]"], altitude)]
    c = result.stability.condition
    mass = mass_text(c["mass [kg]"], units)
    title = (f"{speed / KNOT:.0f} KEAS, {quantity_text(altitude, 'altitude', units)} density "
             f"altitude, mass {c['mass case']} {mass}, cable "
             f"{quantity_text(c['cable length [m]'], 'length', units)}, carrier "
             f"{c['carrier']}:\nleast-damped roots, area {sel['area factor [-]'].min():.3g}-"
             f"{sel['area factor [-]'].max():.3g} x neutral")
    return (sel, title)


def _figures(report, units):
    """The figures to draw: ``{tag: (title, (plot function, args, kwargs))}``."""
    (plot_envelope, plot_no_parachute, plot_root_locus, plot_selection, plot_stability_map,
     plot_sweep) = (  # matplotlib loads where they are drawn
        plot_function("slingloads.io.campaign.plots", name)
        for name in ("plot_envelope", "plot_no_parachute", "plot_root_locus",
                     "plot_selection", "plot_stability_map", "plot_sweep"))
    r = report.result
    figs = {"selection": ("Parachute selection", (plot_selection, (r, units), {}))}
    for tag, runs, factor, title in sweep_plots(r):
        figs[tag] = (f"Sensitivity, {title}", (plot_sweep, (r, runs, factor, title),
                                               {"units": units}))
    if r.stability is not None:
        chosen = r.chosen_area_factor * r.neutral.area
        figs["stability-map"] = ("Stability map", (plot_stability_map,
                                                   (r.stability, r.neutral.area, units),
                                                   {"chosen_area": chosen}))
        locus = _locus(r, units)
        if locus is not None:
            figs["root-locus"] = ("Root locus against the parachute area",
                                  (plot_root_locus, locus,
                                   {"chosen": r.chosen_area_factor}))
    if r.no_parachute is not None:
        figs["no-parachute"] = ("Transport without parachute (paper figures 16-18)",
                                (plot_no_parachute, (r,), {"units": units}))
        if not r.no_parachute.gust_runs.empty:
            figs["no-parachute-gust"] = (
                "Transport without parachute: ramps with a gust after their end",
                (plot_function("slingloads.io.campaign.plots", "plot_no_parachute_gust"),
                 (r,), {"units": units}))
    if r.envelope is not None:
        figs["envelope"] = ("Angle envelope handed to the loads", (plot_envelope, (r,), {}))
    return figs


def write_histories(result, path):
    """Every stored history as one Parquet file (SI, angles in degrees), ``run`` first, with
    slingloads' mark in its key-value metadata (``PARQUET_KEY`` = the version:
    :mod:`slingloads.io.common.ownership`).

    Returns
    -------
    int
        Runs written.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq

    from slingloads.analyses.campaign import HISTORY_LABELS

    # the run ids by dictionary, the float columns split by byte (as in the run cache)
    options = {"compression": "zstd", "use_dictionary": ["run"],
               "use_byte_stream_split": list(HISTORY_LABELS)}
    mark = {PARQUET_KEY: __version__}

    runs = [(run, result.keys[run]) for run in result.metrics["run"]]
    if result.no_parachute is not None:
        runs += [(f"NP-{name}-{target / KNOT:.0f}kt", key)
                 for (name, target), key in result.no_parachute.keys.items()]
        runs += [(f"NP-{name}-{target / KNOT:.0f}kt-gust", key)
                 for (name, target), key in result.no_parachute.gust_keys.items()]
    writer, count = None, 0
    try:
        for start in range(0, len(runs), 50):
            arrays, names = [], []
            for run, key in runs[start:start + 50]:
                record = result.store.get(key)
                if record is None or record[1] is None:
                    continue
                arrays.append(record[1])
                names += [run] * record[1].shape[0]
            if not arrays:
                continue
            data = np.vstack(arrays)
            table = pa.Table.from_arrays(
                [pa.array(names)] + [pa.array(data[:, j]) for j in range(data.shape[1])],
                names=["run", *HISTORY_LABELS])
            if writer is None:
                writer = pq.ParquetWriter(path, table.schema.with_metadata(mark), **options)
            writer.write_table(table)
            count += len(arrays)
        if writer is None:  # no history kept: an empty table with the columns
            empty = pa.Table.from_arrays(
                [pa.array([], pa.string())] + [pa.array([], pa.float64())
                                               for _ in HISTORY_LABELS],
                names=["run", *HISTORY_LABELS])
            pq.write_table(empty.replace_schema_metadata(mark), path, **options)
    finally:
        if writer is not None:
            writer.close()
    return count


def _jobs(report, units):
    return {tag: job for tag, (_, job) in _figures(report, units).items()}


def _titles(report):
    return {tag: title for tag, (title, _) in _figures(report, "SI").items()}


def _write_histories(report, units, path, info):
    """``<stem>-campaign-histories.parquet`` (:func:`write_histories`: SI, whatever
    ``units``; ``info`` unused)."""
    write_histories(report.result, path)


#: The campaign report (:func:`~slingloads.io.common.report_writer.write_report`).
REPORT = ReportKind(tag="campaign", title=TITLE, description=DESCRIPTION,
                    conventions=CONVENTIONS, dpi=_PNG_DPI, sheets=_sheets, figures=_jobs,
                    titles=_titles, files={"histories.parquet": _write_histories})


def report_kind(study):
    """The campaign report of ``study``: :data:`REPORT` with the study's parachute
    decision."""
    from slingloads.io.common.decision import with_decision

    return with_decision(REPORT, study)

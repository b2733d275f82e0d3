"""The loads report: an Excel workbook, CSV tables and PNG plots of a loads analysis.

:func:`write_loads_outputs` writes, all at once or not at all
(:mod:`slingloads.io.common.atomic`):

* ``<stem>-loads.xlsx``: sheets *Summary* (input digest, study settings, units, the attitude
  and its vertical, the hook directions with the reduced ones, the towed cases' cable angles
  with the inside-cone flag, closure check, governing cases), *LoadCases* (with each case's
  cable angle and inside-cone flag), *Envelope* (critical case and correlated loads),
  *Exceedance* (ratio to the previous design envelope, red above 1), *SFBM* (every case and
  station, split as ``SFBM_1``, ``SFBM_2``... past Excel's row limit), *Ultimate* (envelope
  at ultimate = factor x limit), *Hulls* (vertex tables) and *Plots*; all in the chosen unit
  system with the unit in every header (``x [in]``, ``Vy [lbf]``, ``Mz [lbf in]``);
* ``<stem>-sfbm.csv`` (columns ``case,station,x_m,Vx_N,Vy_N,Vz_N,Mx_Nm,My_Nm,Mz_Nm``) and
  ``<stem>-envelope.csv``: limit loads, always SI;
* ``<stem>-X_shear.png`` and ``<stem>-Y_shear.png`` (the paper's figures 19 and 20),
  ``<stem>-sfbm_all.png`` (all six components, 2 x 3 grid) and
  ``<stem>-hull_<A>_<B>_<station>.png``;
* on request, ``<stem>-loads.bdf``: the load cases as a Nastran input file
  (:mod:`slingloads.io.loads.nastran`), with a *Nastran* sheet in the workbook.

:func:`convert_by_component` converts the columns whose unit depends on the row's load
component; the conversions shared by every report are in :mod:`slingloads.io.common.report`.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

import slingloads
from slingloads.analyses.envelopes import component_index
from slingloads.analyses.loads import CLOSURE_TOLERANCE
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
from slingloads.errors import InputError
from slingloads.io.common.atomic import atomic_outputs, check_not_input, safe_file_part
from slingloads.io.common.csvout import write_csv
from slingloads.io.common.excel import (
    EXCEL_MAX_ROWS,
    Highlight,
    Section,
    figure_png,
    format_by_header,
    write_workbook,
)
from slingloads.io.common.report import (
    check_units,
    convert_columns,
    digest_frame,
    in_report_units,
    report_unit,
)
from slingloads.io.common.units import unit_label
from slingloads.io.common.workbook import located
from slingloads.io.loads.nastran import prepare_nastran

#: Names of the files of a loads report (``*``: a part made from a station id), for the
#: publisher: a new report replaces every earlier file of these names.
OUTPUTS = ("{stem}-loads.xlsx", "{stem}-sfbm.csv", "{stem}-envelope.csv", "{stem}-X_shear.png",
           "{stem}-Y_shear.png", "{stem}-sfbm_all.png", "{stem}-hull_*.png", "{stem}-loads.bdf")

#: Components drawn on their own PNG (the paper's figures 19 and 20); all six are on the grid.
PNG_COMPONENTS = ("Vx", "Vy")

#: Columns of the SFBM CSV file (SI, limit loads).
SFBM_CSV_COLUMNS = ("case", "station", "x_m", "Vx_N", "Vy_N", "Vz_N", "Mx_Nm", "My_Nm",
                    "Mz_Nm")

#: Number formats of the report columns, by header pattern (first match wins).
NUMBER_FORMATS = format_by_header([
    (r"residual", "0.00E+00"),
    (r"ratio", "0.000"),
    (r"^x \[", "0.000"),
    (r"\[(N|lbf|N m|lbf in)\]$", "#,##0.0"),
    (r"^(value|new max|new min|previous max|previous min)$", "#,##0.0"),
    (r"\[deg\]$", "0.0##"),
    (r"\[(-|rad/s\^2)\]$", "0.000"),
])

_PNG_DPI = 120


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
    return {n: (n, COMPONENT_KINDS[component_index(n)]) for n in names}


def sfbm_table(result, units="SI", ultimate=False):
    """Long SFBM table in report units: ``case, station, x [..], Vx [..] ... Mz [..]``."""
    frame = result.to_frame(ultimate=ultimate)
    spec = {"x_m": ("x", "length")}
    for name, column in zip(COMPONENTS, SFBM_CSV_COLUMNS[3:], strict=True):
        spec[column] = (name, COMPONENT_KINDS[component_index(name)])
    return convert_columns(frame, spec, units)


def envelope_report_table(result, units="SI", ultimate=False):
    """Envelope (critical case, correlated loads) in report units, with a ``unit`` column."""
    frame = convert_by_component(result.envelope(ultimate=ultimate), ["value"], units)
    spec = {"x [m]": ("x", "length"), **_loads_spec()}
    return convert_columns(frame, spec, units)


def case_report_table(result, units="SI"):
    """Load-case table in report units (closure residuals converted)."""
    return convert_columns(result.case_table(), {
        "closure force residual [N]": ("closure force residual", "force"),
        "closure moment residual [N m]": ("closure moment residual", "moment"),
    }, units)


def comparison_report_table(result, units="SI"):
    """Exceedance over the previous design envelope in report units, or None."""
    comparison = result.comparison()
    if comparison is None:
        return None
    frame = convert_by_component(
        comparison, ["new max", "new min", "previous max", "previous min"], units)
    return convert_columns(frame, {"x [m]": ("x", "length")}, units)


def hull_report_table(result, pair, stations, units="SI"):
    """Hull vertices of ``pair`` at each station, one block of rows per station."""
    frames = []
    for station in stations:
        hull = result.hull(station, pair)
        index = _station_index(result, station)
        hull.insert(0, "vertex", np.arange(1, len(hull) + 1))
        hull.insert(0, "x [m]", result.stations[index])
        hull.insert(0, "station", result.station_ids[index])
        frames.append(hull)
    frame = pd.concat(frames, ignore_index=True)
    return convert_columns(frame, {"x [m]": ("x", "length"), **_loads_spec(pair)}, units)


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

    def unit(kind):
        return unit_label(report_unit(kind, units))

    def conv(value, kind):
        return float(in_report_units(value, kind, units))

    alt_unit = "ft" if units == "US" else "m"
    altitude = study.flight.density_altitude / (0.3048 if units == "US" else 1.0)
    cg = items.cg
    c, s = len(result.case_ids), len(result.stations)
    rows = [
        ("study", study.name, ""),
        ("slingloads version", slingloads.__version__, ""),
        ("report unit system", units, ", ".join(unit(k) for k in ("length", "force",
                                                                  "moment"))),
        ("CSV files", "SI (m, N, N m), limit loads", ""),
        ("aircraft mass", conv(items.total_mass, "mass"), unit("mass")),
        ("CG x", conv(cg[0], "length"), unit("length")),
        ("CG y", conv(cg[1], "length"), unit("length")),
        ("CG z", conv(cg[2], "length"), unit("length")),
        ("equivalent airspeed", conv(study.flight.eas, "speed"), unit("speed")),
        ("density altitude", altitude, alt_unit),
        ("air density", conv(study.flight.density, "density"), unit("density")),
        ("attitude (earth vertical in airframe axes)", result.attitude.describe(), ""),
        ("attitude pitch", float(np.degrees(result.attitude.pitch)), "deg"),
        ("attitude roll", float(np.degrees(result.attitude.roll)), "deg"),
        ("hook load factor Nz", study.hook.nz, "-"),
        ("hook cone angle from the vertical", float(np.degrees(study.hook.angle)), "deg"),
        ("hook cone angle of the lateral directions", float(np.degrees(study.hook.lateral)),
         "deg"),
        ("hook cone shape", study.hook.cone, ""),
        ("hook azimuths", study.hook.n_azimuth, "-"),
        ("vertical hook case included", "yes" if study.hook.include_vertical else "no", ""),
        ("towed-flight equilibrium cases", "yes" if study.hook.towed else "no", ""),
        ("aerodynamic envelope points",
         len(study.envelope.ids) if study.envelope is not None else 0, "-"),
        ("parachute", "yes" if study.parachute is not None else "no", ""),
        ("parachute line direction", study.chute_line if study.parachute is not None else "-",
         ""),
        ("ultimate factor", study.ultimate_factor, "-"),
        ("load cases", c, "-"),
        ("cut stations", s, "-"),
        ("SFBM rows (cases x stations)", c * s, "-"),
        ("previous design envelope",
         "given" if study.previous_envelope is not None else "none", ""),
    ]
    return pd.DataFrame(rows, columns=["item", "setting", "unit"])


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


def towed_note(result):
    """The towed-case verdict: how many trimmed cables lie outside the hook cone."""
    towed = result.towed_table()
    if towed.empty:
        return "No towed-flight equilibrium case (no aerodynamic point or parachute, or off)."
    outside = towed[towed["inside hook cone"] != "yes"]
    rule = ("Cable angle from the vertical at Nz and at 1 g (the steady trail angle), judged "
            "at the larger against the cone's inclination at the cable's azimuth.")
    if outside.empty:
        return f"{rule} Every trimmed cable lies inside the hook cone."
    return (f"{rule} OUTSIDE THE HOOK CONE: {', '.join(outside['case'])}: the cone does not "
            "cover the cable angle reached in towed flight; widen it or restrict the flight "
            "envelope.")


def closure_table(result):
    """Free-free closure check (SI, as applied by the analysis): residuals vs tolerance."""
    residual = np.abs(result.residual)
    tol = CLOSURE_TOLERANCE * result.residual_scale
    worst = int(np.argmax(residual.max(axis=1)))
    largest = float(residual.max())
    rows = [
        ("relative tolerance", CLOSURE_TOLERANCE, "-"),
        ("load scale (largest force x max(1 m, airframe length))", result.residual_scale,
         "N m"),
        ("tolerance on every residual component", tol, "N or N m"),
        ("max |force residual|", float(residual[:, :3].max()), "N"),
        ("max |moment residual| at a cut aft of every load", float(residual[:, 3:].max()), "N m"),
        ("case with the largest residual", result.case_ids[worst], ""),
        ("result", "PASS" if largest <= tol else "FAIL", ""),
    ]
    return pd.DataFrame(rows, columns=["item", "setting", "unit"])


def governing_report_table(result, units="SI"):
    """Case and station of the largest |limit load| of each component, in report units."""
    frame = convert_by_component(result.governing_cases(), ["value"], units)
    return convert_columns(frame, {"x [m]": ("x", "length")}, units)


def _safe(text):
    """A file-name-safe version of a station id (the Stations reader refuses ids that give
    the same one)."""
    return safe_file_part(text)


def _default_hull_station(result, pair):
    """The station where the first component of the pair has its largest magnitude."""
    j = component_index(pair[0])
    return result.station_ids[int(np.argmax(np.abs(result.loads[:, :, j]).max(axis=0)))]


def write_loads_outputs(result, out_dir, stem, units="SI", inputs_digest=None,
                        hull_pairs=(("Vy", "Mz"), ("Vz", "My")), hull_stations=None, *,
                        input_paths: Sequence = (), max_rows=EXCEL_MAX_ROWS, plots=True,
                        nastran=None, checks=None, dynamics=None):
    """Write the loads report (workbook, CSV tables, PNG plots) atomically.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    out_dir : path-like
        Output directory (created if needed).
    stem : str
        File-name stem: ``<stem>-loads.xlsx``, ``<stem>-sfbm.csv``...
    units : str
        Unit system of the workbook and plots, ``"SI"`` (m, N, N m) or ``"US"`` (in, lbf,
        lbf in). The CSV files are always SI.
    inputs_digest : dict or pandas.DataFrame, optional
        What the analysis was run from (input file name, SHA-256, ...), shown first on the
        Summary sheet.
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
    from slingloads.io.loads.plots import (  # matplotlib loads only when writing
        COMPONENT_TAGS,
        plot_hull,
        plot_sfbm,
        plot_sfbm_grid,
    )

    check_units(units)
    for pair in hull_pairs:
        if len(pair) != 2:
            raise InputError("a hull pair needs two components", pair)
        for name in pair:
            component_index(name)
    stations = list(hull_stations) if hull_stations is not None else list(result.station_ids)
    for station in stations:
        _station_index(result, station)
    plot_stations = {pair: (stations if hull_stations is not None
                            else [_default_hull_station(result, pair)]) for pair in hull_pairs}

    hull_plots = {}
    for pair, where in plot_stations.items():
        for station in where:
            index = _station_index(result, station)
            hull_plots[f"hull_{pair[0]}_{pair[1]}_{_safe(result.station_ids[index])}"] = (
                pair, index)
    tags = ([COMPONENT_TAGS[n] for n in PNG_COMPONENTS] + ["sfbm_all", *hull_plots]
            if plots else [])
    names = [f"{stem}-loads.xlsx", f"{stem}-sfbm.csv", f"{stem}-envelope.csv",
             *(f"{stem}-{tag}.png" for tag in tags)]
    deck = None
    if nastran is not None and nastran is not False:
        deck = prepare_nastran(result, units=units, inputs_digest=inputs_digest,
                               **({} if nastran is True else dict(nastran)))
        names.append(f"{stem}-loads.bdf")
    for name in names:  # fail before the slow work, not after it
        check_not_input(Path(out_dir) / name, input_paths)

    pngs = {}
    if plots:
        for name in PNG_COMPONENTS:
            pngs[COMPONENT_TAGS[name]] = figure_png(plot_sfbm(result, name, units), _PNG_DPI)
        pngs["sfbm_all"] = figure_png(plot_sfbm_grid(result, units), _PNG_DPI)
        for tag, (pair, index) in hull_plots.items():
            pngs[tag] = figure_png(plot_hull(result, index, pair, units), _PNG_DPI)
    embedded = {}
    if plots:
        embedded = {"X shear (Vx)": pngs["X_shear"], "Y shear (Vy)": pngs["Y_shear"],
                    "All six components": pngs["sfbm_all"]}
        embedded.update({tag: pngs[tag] for tag in hull_plots})
    sheets = _workbook_sheets(result, units, inputs_digest, hull_pairs, stations, checks)
    if deck is not None:
        sheets["Nastran"] = nastran_sheet(deck)
    if dynamics is not None:
        sheets["Dynamics"] = dynamics_sections(result, dynamics, units)

    with atomic_outputs(out_dir, inputs=input_paths) as out:
        write_workbook(out.path(f"{stem}-loads.xlsx"), sheets, embedded,
                       number_format=NUMBER_FORMATS,
                       highlight={"Exceedance": Highlight(["exceedance ratio"], 1.0)},
                       max_rows=max_rows)
        write_csv(result.to_frame(), out.path(f"{stem}-sfbm.csv"), columns=SFBM_CSV_COLUMNS)
        write_csv(result.envelope(), out.path(f"{stem}-envelope.csv"))
        for tag, png in pngs.items():
            out.path(f"{stem}-{tag}.png").write_bytes(png)
        if deck is not None:
            deck.write(out.path(f"{stem}-loads.bdf"))
    return out.written


def nastran_sheet(deck):
    """The *Nastran* sheet: the file's settings, the subcase -> case id table, the grids."""
    return [Section("Nastran input file (<stem>-loads.bdf): settings", deck.settings_table()),
            Section("Subcases: number, LOAD set and the case id each stands for",
                    deck.subcase_table(),
                    note="Nastran labels hold printable ASCII; a longer or non-ASCII case id "
                         "is shortened and ends in '~' and a checksum."),
            Section("Grids (model axes, file units) and CONM2 elements", deck.grid_table())]


def _workbook_sheets(result, units, inputs_digest, hull_pairs, stations, checks=None):
    """The sheets of the loads workbook, in order."""
    digest = digest_frame(inputs_digest)
    summary = [
        Section("Inputs", digest) if digest is not None
        else Section("Inputs", note="no input digest given"),
    ]
    if checks is not None and len(checks):
        failed = checks[checks["status"] != "ok"]
        summary.append(Section(
            "Consistency with the other analyses of this run", checks,
            note=("WARNING: " + " ".join(failed["note"])) if len(failed) else
                 "Every check against the other analyses of this run passes."))
    summary += [
        Section("Study", study_table(result, units)),
        Section("Attitude (earth vertical in airframe axes)", attitude_table(result),
                note=result.attitude.describe() + ". Gravity, the vertical hook case and the "
                     "hook cone are taken about this vertical."),
        Section("Hook-load directions (CS-29.865)", hook_direction_table(result),
                note=hook_direction_note(result)),
        Section("Towed-flight equilibrium cases: trimmed cable angles",
                result.towed_table() if (result.cases["hook"] == "TOW").any() else None,
                note=towed_note(result)),
        Section("Closure check (free-free equilibrium, SI as checked)", closure_table(result)),
        Section("Governing cases (largest |limit load| of each component)",
                governing_report_table(result, units)),
    ]
    comparison = comparison_report_table(result, units)
    exceedance = (
        [Section("Exceedance over the previous design envelope",
                 comparison,
                 note="ratio = max(new max+/previous max+, |new min-|/|previous min-|); "
                      "above 1 the new envelope exceeds the previous one (red)")]
        if comparison is not None else "no previous envelope given")
    factor = result.study.ultimate_factor
    ultimate = [Section(f"Ultimate loads = {factor:g} x limit loads",
                        envelope_report_table(result, units, ultimate=True),
                        note=f"Ultimate factor of safety {factor:g} (CS 29.303). The "
                             "envelope below is at ultimate; every other sheet, and the "
                             "CSV files, hold limit loads.")]
    hulls = [Section(f"{a}-{b} convex hull vertices (counter-clockwise), limit loads",
                     hull_report_table(result, (a, b), stations, units))
             for a, b in hull_pairs] or "no hull pair requested"
    return {
        "Summary": summary,
        "LoadCases": case_report_table(result, units),
        "Envelope": envelope_report_table(result, units),
        "Exceedance": exceedance,
        "SFBM": sfbm_table(result, units),
        "Ultimate": ultimate,
        "Hulls": hulls,
    }


def dynamics_sections(result, comparison, units="SI"):
    """The *Dynamics* sheet: what the campaign's dynamics changed in the cases, and the
    largest loads of the hand-entered cases against those of the cases from the dynamics."""
    from slingloads.analyses.campaign import loads_comparison

    table = comparison.copy()
    if units == "US":
        for unit, kind in (("N", "force"), ("m^2", "area")):
            rows = table["unit"] == unit
            label = unit_label(report_unit(kind, units))
            for column in ("hand-entered", "dynamics reached", "with margin",
                           "used in the loads"):
                values = pd.to_numeric(table.loc[rows, column], errors="coerce")
                table.loc[rows, column] = in_report_units(values.to_numpy(float), kind, units)
            table.loc[rows, "unit"] = label
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


def compute(study):
    """Run the loads analysis read from a workbook.

    With the campaign's result in ``study.results`` (``slingloads run`` with ``run campaign``
    and ``campaign loads from dynamics``), the cases the dynamics reached are added
    (:func:`slingloads.analyses.campaign.loads_from_dynamics`) and the hand-off is kept in
    ``study.results["loads handoff"]`` for the report.

    Parameters
    ----------
    study : WorkbookStudy
        With ``study.loads`` (:class:`~slingloads.analyses.loads.LoadsStudy`).

    Returns
    -------
    LoadsResult

    Raises
    ------
    InputError
        If the workbook does not ask for the loads analysis.
    """
    if study.loads is None:
        raise InputError("the workbook does not ask for the loads analysis (Study sheet: "
                         "'run loads' is no)", file=study.path, sheet="Study")
    results = getattr(study, "results", {})
    campaign = results.get("campaign")
    if campaign is None or not campaign.inputs.loads_from_dynamics:
        return _finite(study.loads.run(), study)
    if campaign.result.envelope is None:
        raise InputError("the loads are to take the dynamics' cases, but no parachute area of "
                         "the campaign is stable in every condition and none was chosen "
                         "('campaign chosen area factor'); choose one or set 'campaign loads "
                         "from dynamics' to no", file=study.path, sheet="Study")
    from slingloads.analyses.campaign import loads_from_dynamics

    with located(study.path, "Study"):
        handoff = loads_from_dynamics(study.loads, campaign.result.envelope,
                                      campaign.inputs.hook_angle_source)
    results["loads handoff"] = handoff
    return _finite(handoff.study.run(), study)


def _finite(result, study):
    """``result``, refused if its loads are not finite numbers."""
    if not np.all(np.isfinite(result.loads)):
        raise InputError("the loads are not finite numbers (an input far out of scale?): check "
                         "the magnitudes and units of the MassItems, FuselageAero and Study "
                         "values", file=study.path)
    return result


def write(result, out_dir, stem, units, study, checks=None):
    """Write the loads report of a workbook's study (:func:`write_loads_outputs`) into the
    run's outputs ``out_dir``, with the study's inputs digest and hull options, and the
    ``checks`` against the other analyses of the run (:mod:`slingloads.io.consistency`)."""
    nastran = None
    if study.options.get("nastran"):
        nastran = {**study.options["nastran settings"],
                   "locations": study.options["nastran locations"]}
    handoff = getattr(study, "results", {}).get("loads handoff")
    with located(study.path):
        return write_loads_outputs(result, out_dir, stem, units=units,
                                   inputs_digest=study.digest(),
                                   hull_pairs=study.options.get("hull pairs", (("Vy", "Mz"),)),
                                   hull_stations=study.options.get("hull stations"),
                                   input_paths=study.input_files, nastran=nastran,
                                   checks=checks,
                                   dynamics=None if handoff is None else handoff.comparison)

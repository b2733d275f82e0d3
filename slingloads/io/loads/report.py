"""The loads report: a print-ready Excel workbook, CSV tables and PNG plots of a loads analysis.

The report is a :class:`~slingloads.io.common.report_writer.ReportKind` (:func:`loads_report`,
:func:`report_kind` for a workbook's study) written by the one report writer,
:func:`~slingloads.io.common.report_writer.write_report` (through the registry,
:meth:`slingloads.io.analyses.Analysis.write`, for a study; :func:`write_loads_outputs` from
Python), all at once or not at all
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

The tables are built by :mod:`slingloads.io.loads.tables` (in the report's units), the
sheets and the Summary's findings by :mod:`slingloads.io.loads.sheets`; this module says what
the report is made of (:func:`loads_report`, :func:`report_kind`), its figures and its files.
The conversions shared by every report are in :mod:`slingloads.io.common.report`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from functools import partial

import numpy as np

from slingloads.analyses.envelopes import component_index
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.errors import InputError
from slingloads.io.common.atomic import safe_file_part
from slingloads.io.common.cover import info_from_digest, input_digest
from slingloads.io.common.csvout import csv_bytes
from slingloads.io.common.excel import (
    EXCEL_MAX_ROWS,
    Highlight,
    format_by_header,
    write_workbook,
)
from slingloads.io.common.figures import plot_function
from slingloads.io.common.locate import located
from slingloads.io.common.report import check_units
from slingloads.io.common.report_writer import ReportKind, write_report
from slingloads.io.loads.nastran import prepare_nastran
from slingloads.io.loads.sheets import (
    dynamics_sections,
    nastran_sheet,
    sheets_columns,
    workbook_sheets,
)
from slingloads.io.loads.tables import (
    DEFAULT_HULL_PAIRS,
    SFBM_CSV_COLUMNS,
    hull_table_stations,
    sfbm_table,
)
from slingloads.io.loads.tags import COMPONENT_TAGS, COMPONENT_TITLES

#: Components drawn each on its own PNG, all six (the paper's figures 19 and 20: Vx, Vy).
PNG_COMPONENTS = COMPONENTS

#: Names of the files of a loads report (``*``: a part made from a station id), for the
#: publisher: a new report replaces every earlier file of these names (``-sfbm_all.png``:
#: the six-panel plot of earlier versions, replaced by one PNG per component).
OUTPUTS = ("{stem}-loads.xlsx", "{stem}-sfbm.xlsx", "{stem}-sfbm.csv", "{stem}-envelope.csv",
           "{stem}-stations.png", *(f"{{stem}}-{COMPONENT_TAGS[n]}.png" for n in COMPONENTS),
           "{stem}-sfbm_all.png", "{stem}-hull_*.png", "{stem}-loads.bdf")

#: Columns of the envelope CSV file (SI, limit loads): the bound's value in ``value_N`` for
#: a shear, in ``value_Nm`` for a moment (the other is empty).
ENVELOPE_CSV_COLUMNS = ("station", "x_m", "component", "bound", "case", "value_N",
                        "value_Nm", *SFBM_CSV_COLUMNS[3:])

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
        result.station_index(station)
    jobs = {"stations": (plot_station_diagram, (result.study, units), {})}
    titles = {"stations": "Cut stations, mass items and hardpoints where the LIMIT loads enter "
                          "(side and top views)"}
    for name in PNG_COMPONENTS:
        jobs[COMPONENT_TAGS[name]] = (plot_sfbm, (result, name, units), {})
        titles[COMPONENT_TAGS[name]] = f"{COMPONENT_TITLES[name]} {name}, LIMIT loads"
    for pair in hull_pairs:
        where = stations if hull_stations is not None else [_default_hull_station(result, pair)]
        for station in where:
            index = result.station_index(station)
            tag = f"hull_{pair[0]}_{pair[1]}_{_safe(result.station_ids[index])}"
            jobs[tag] = (plot_hull, (result, index, pair, units), {})
            titles[tag] = f"{pair[0]}-{pair[1]} LIMIT envelope at {result.station_ids[index]}"
    return jobs, titles



def envelope_csv_frame(result):
    """The LIMIT envelope as written to the CSV file: :meth:`LoadsResult.envelope` itself
    (SI, ``name_unit`` headers)."""
    return result.envelope()[list(ENVELOPE_CSV_COLUMNS)]



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
    """The sheets of the loads workbook (:func:`workbook_sheets`), with the *Nastran* sheet
    of ``deck`` and the *Dynamics* sheet of the campaign's hand-off ``dynamics`` when
    given; ``warnings`` on the Summary unless ``findings`` names its own."""
    sheets = workbook_sheets(result, units, hull_pairs,
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



class _StudyDeck:
    """The Nastran input file a workbook's study asks for, prepared once per result and unit
    system (the *Nastran* sheet and ``<stem>-loads.bdf`` show the same deck); an error in
    its settings is put at the Study-sheet cell it came from."""

    def __init__(self, study):
        self.study = study
        self._made = {}

    def __call__(self, result, units):
        key = (id(result), units)
        if key not in self._made:
            options = self.study.report
            settings = {**options.nastran_settings, "locations": options.nastran_locations}
            with located(self.study.path):
                # the result kept beside its deck, so that its id is not reused
                self._made[key] = (result, prepare_nastran(
                    result, units=units, inputs_digest=input_digest(self.study), **settings))
        return self._made[key][1]



def _sheets_with_deck(sheets, deck_of, result, units, warnings=()):
    return sheets(result, units, warnings, deck=deck_of(result, units))



def _write_study_deck(deck_of, result, units, path, info):
    deck_of(result, units).write(path)



def report_kind(study, checks=None):
    """The loads report of a workbook's study: its Study-sheet options (the Nastran input
    file when it asks for one, prepared from the result in the report's units), and the
    findings of the other analyses of the run (the lateral study of the same run, when there
    is one, is the evidence on the hook angle; the campaign's hand-off, when the loads took
    the dynamics' cases); ``checks`` as in :func:`loads_report`."""
    options, results = study.report, study.results
    findings = {"lateral": results.lateral,
                "hook angle handoff": results.loads_hook_angle,
                "parachute decision": results.parachute_decision,
                "hook angle justification": options.hook_angle_justification,
                "previous envelope source": options.previous_envelope_source}
    handoff = results.loads_handoff
    kind = loads_report(options.hull_pairs, options.hull_stations, findings=findings,
                        checks=checks, dynamics=None if handoff is None else handoff.comparison,
                        sfbm_workbook=options.sfbm_workbook)
    if not options.nastran:
        return kind
    deck_of = _StudyDeck(study)
    return replace(kind, sheets=partial(_sheets_with_deck, kind.sheets, deck_of),
                   appendices={"loads.bdf": partial(_write_study_deck, deck_of)})

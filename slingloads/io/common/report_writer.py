"""The one writer of an analysis's report: its workbook, data files and figures, all at once.

Guarantees: nothing is written unless every file is (:func:`~slingloads.io.common.atomic.
atomic_outputs`); no input file of the study (the workbook and the files it names, or the
workbook alone when that list is empty) is replaced; names are checked before anything is
drawn; the figures started while the other analyses were computed are used, never drawn
twice.

An analysis's report module says what its report is made of in a :class:`ReportKind`
(sheets, figures with their titles, data files) and writes it with :func:`write_report`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from slingloads.io.common.atomic import atomic_outputs, check_outputs
from slingloads.io.common.cover import report_info
from slingloads.io.common.excel import write_workbook
from slingloads.io.common.figures import drawings, png_bytes, task_result
from slingloads.io.common.findings import with_findings
from slingloads.io.common.report import check_units


def _same_warnings(result, warnings):
    return list(warnings)


def _no_format(result):
    return None


@dataclass(frozen=True)
class ReportKind:
    """What one analysis's report is made of.

    Attributes
    ----------
    tag : str
        Its files are ``<stem>-<tag>.xlsx`` and ``<stem>-<tag>-<name>`` (``"lateral"``).
    title, description : str
        The report's title and what the analysis covers (its cover sheet).
    conventions : tuple of str
        The analysis's conventions (its cover sheet, after those of every report).
    dpi : float
        Resolution of its PNG figures. [dots per inch]
    sheets : callable
        ``sheets(result, units, warnings) -> {sheet name: content}``
        (:func:`~slingloads.io.common.excel.write_workbook`).
    figures : callable
        ``figures(result, units) -> {tag: (plot function, args, kwargs)}``: drawn as
        ``<stem>-<tag>-<figure tag>.png`` and on the workbook's Plots sheet.
    titles : callable
        ``titles(result) -> {figure tag: title}`` on the Plots sheet.
    data : dict
        ``{name: make(result) -> bytes or None}``: the data files ``<stem>-<tag>-<name>``
        (None: not written for this result), made while the figures are drawn (or taken
        from the started renderer's task of that name).
    files : dict
        ``{name: write(result, path)}``: data files written straight to their path.
    warnings : callable
        ``warnings(result, study warnings) -> list of str`` shown on the Summary (default:
        the study's).
    number_format : callable
        ``number_format(result) -> {column: Excel format} or None``.
    """

    tag: str
    title: str
    description: str
    conventions: tuple
    dpi: float
    sheets: Callable
    figures: Callable
    titles: Callable
    data: dict = field(default_factory=dict)
    files: dict = field(default_factory=dict)
    warnings: Callable = _same_warnings
    number_format: Callable = _no_format


def protected_inputs(study):
    """The files no output may replace: every file the study read, else its workbook."""
    source = study.source
    return list(source.input_files) or ([source.path] if source.path else [])


def study_findings_of(study):
    """The findings of ``study``'s results (:func:`slingloads.runs.findings.study_findings`),
    for a report written alone (``slingloads run`` builds them once and passes them on)."""
    from slingloads.runs.findings import study_findings

    return study_findings(study.results)


def write_report(kind, result, out_dir, stem, units, study, figures=None, findings=None):
    """Write the report of ``result`` atomically: ``<stem>-<tag>.xlsx``, its data files and
    its PNG figures.

    Parameters
    ----------
    kind : ReportKind
    result : object
        The analysis's result (:mod:`slingloads.runs`).
    out_dir : path-like or AtomicOutputs
    stem : str
    units : str
        ``"SI"`` or ``"US"``.
    study : Study
        For the report's identification and warnings; its input files are never replaced.
    figures : FigureRenderer, optional
        Already drawing the figures (the report module's ``start_figures``); default: drawn
        now.
    findings : Findings, optional
        The run's findings, written on the Findings sheet (default: those of
        ``study.results``).

    Returns
    -------
    list of pathlib.Path
    """
    check_units(units)
    inputs = protected_inputs(study)
    tag = kind.tag
    jobs = kind.figures(result, units) if figures is None else figures.pngs  # not made twice
    names = [f"{stem}-{tag}.xlsx", *(f"{stem}-{tag}-{name}" for name in kind.data),
             *(f"{stem}-{tag}-{name}" for name in kind.files),
             *(f"{stem}-{tag}-{t}.png" for t in jobs)]
    check_outputs(out_dir, names, inputs)
    titles = kind.titles(result)
    with drawings(jobs, figures, kind.dpi) as pngs:
        # the data files before the figures are awaited: made here while the helper draws,
        # unless it has made them
        data = {name: task_result(figures, name, make, result)
                for name, make in kind.data.items()}
        data = {name: content for name, content in data.items() if content is not None}
        info = report_info(study, title=kind.title, analysis=kind.description, units=units,
                           conventions=kind.conventions,
                           files=[*(f"{stem}-{tag}-{name}" for name in (*data, *kind.files)),
                                  *(f"{stem}-{tag}-{t}.png" for t in pngs)])
        sheets = with_findings(
            kind.sheets(result, units, kind.warnings(result, study.source.warnings)),
            study_findings_of(study) if findings is None else findings, units)
        with atomic_outputs(out_dir, inputs=inputs) as out:
            write_workbook(out.path(f"{stem}-{tag}.xlsx"), sheets,
                           {titles[t]: png for t, png in pngs.items()}, info=info,
                           number_format=kind.number_format(result))
            for name, content in data.items():
                out.path(f"{stem}-{tag}-{name}").write_bytes(content)
            for name, write in kind.files.items():
                write(result, out.path(f"{stem}-{tag}-{name}"))
            for t, png in pngs.items():
                out.path(f"{stem}-{tag}-{t}.png").write_bytes(png_bytes(png))
    return out.written

"""The one writer of an analysis's report: its workbook, data files and figures, all at once.

Guarantees: nothing is written unless every file is (:func:`~slingloads.io.common.atomic.
atomic_outputs`); no input file of the study (the workbook and the files it names, or the
workbook alone when that list is empty) is replaced; names are checked before anything is
drawn; the figures started while the other analyses were computed are used, never drawn
twice.

An analysis's report module says what its report is made of in a :class:`ReportKind`
(sheets, figures with their titles, data files, other files) and writes it with
:func:`write_report`; :func:`start_figures` starts drawing its figures while the other
analyses are computed.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from slingloads.io.common.atomic import atomic_outputs, check_outputs
from slingloads.io.common.cover import report_info
from slingloads.io.common.excel import write_workbook
from slingloads.io.common.figures import drawings, png_bytes, start_drawing, task_result
from slingloads.io.common.findings import with_findings
from slingloads.io.common.report import check_units


def _same_warnings(result, warnings):
    return list(warnings)


def _no_format(result):
    return None


def _no_highlight(sheets):
    return None


@dataclass(frozen=True)
class ReportKind:
    """What one analysis's report is made of.

    Attributes
    ----------
    tag : str
        Its workbook is ``<stem>-<tag>.xlsx`` (``"lateral"``).
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
        ``<stem>-<prefix><figure tag>.png`` and on the workbook's Plots sheet.
    titles : callable
        ``titles(result) -> {figure tag: title}`` on the Plots sheet.
    data : dict
        ``{name: make(result) -> bytes or None}``: the data files ``<stem>-<prefix><name>``
        (None: not written for this result), made while the figures are drawn (or taken
        from the started renderer's task of that name).
    files : dict
        ``{name: write(result, units, path, info)}``: files written straight to their path
        ``<stem>-<prefix><name>`` (``info``: the report's :class:`~slingloads.io.common.
        cover.ReportInfo`, for a file that is a workbook of its own), listed on the cover
        before the data files.
    appendices : dict
        The same as ``files``, listed on the cover after the figures (the loads' Nastran
        input file).
    warnings : callable
        ``warnings(result, study warnings) -> list of str`` shown on the Summary (default:
        the study's).
    number_format : callable
        ``number_format(result) -> {column: Excel format} or None``.
    highlight : callable
        ``highlight(sheets) -> {sheet name: Highlight} or None``: the cells filled red
        (:func:`~slingloads.io.common.excel.write_workbook`).
    images_title : str
        Page-header title of the Plots sheet, ``{count}`` the number of figures (default:
        ``Plots (count)``).
    prefix : str, optional
        What the names of its other files start with after ``<stem>-`` (default
        ``"<tag>-"``; the loads report's are ``<stem>-<name>``).
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
    appendices: dict = field(default_factory=dict)
    warnings: Callable = _same_warnings
    number_format: Callable = _no_format
    highlight: Callable = _no_highlight
    images_title: str = ""
    prefix: str | None = None

    def name(self, stem, part):
        """The file name of its file ``part`` (``"histories.csv"``, a figure's
        ``"<tag>.png"``) for input ``stem``."""
        prefix = f"{self.tag}-" if self.prefix is None else self.prefix
        return f"{stem}-{prefix}{part}"


def protected_inputs(study):
    """The files no output may replace: every file the study read, else its workbook."""
    source = study.source
    return list(source.input_files) or ([source.path] if source.path else [])


def study_findings_of(study):
    """The findings of ``study``'s results (:func:`slingloads.runs.findings.study_findings`),
    for a report written alone (``slingloads run`` builds them once and passes them on)."""
    from slingloads.runs.findings import study_findings

    return study_findings(study.results)


def start_figures(kind, result, units):
    """Start drawing the figures of ``kind``'s report of ``result`` (helper processes draw
    them while the other analyses are computed), its data files kept for the writing
    process to make after them; pass the renderer to :func:`write_report` as ``figures``,
    which uses these drawings and never draws them again.

    Parameters
    ----------
    kind : ReportKind
    result : object
    units : str
        ``"SI"`` or ``"US"``.

    Returns
    -------
    FigureRenderer
        A context manager to leave once the report is written.
    """
    renderer = start_drawing(kind.figures(result, units), kind.dpi)
    for name, make in kind.data.items():  # after the figures
        renderer.later(name, make, result)
    return renderer


def write_report(kind, result, out_dir, stem, units, study=None, figures=None, findings=None,
                 *, info=None, inputs=None):
    """Write the report of ``result`` atomically: ``<stem>-<tag>.xlsx``, its other files and
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
    study : Study, optional
        For the report's identification and warnings; its input files are never replaced.
        None for a report written through the Python API without a workbook study (then
        give ``info``).
    figures : FigureRenderer, optional
        Already drawing the figures (:func:`start_figures`); default: drawn now.
    findings : Findings, optional
        The run's findings, written on the Findings sheet (default: those of
        ``study.results``; none without a study).
    info : ReportInfo, optional
        The report's identification (default: that of ``study``); its list of files is
        that of this report.
    inputs : sequence of path-like, optional
        Files no output may replace (default: those of ``study``, :func:`protected_inputs`).

    Returns
    -------
    list of pathlib.Path
    """
    check_units(units)
    inputs = list(inputs or ()) if study is None else protected_inputs(study)
    jobs = kind.figures(result, units) if figures is None else figures.pngs  # not made twice
    workbook = f"{stem}-{kind.tag}.xlsx"
    names = [workbook, *(kind.name(stem, n) for n in (*kind.files, *kind.data)),
             *(kind.name(stem, f"{t}.png") for t in jobs),
             *(kind.name(stem, n) for n in kind.appendices)]
    check_outputs(out_dir, names, inputs)
    titles = kind.titles(result)
    with drawings(jobs, figures, kind.dpi) as pngs:
        # the data files before the figures are awaited: made here while the helper draws,
        # unless it has made them
        data = {name: task_result(figures, name, make, result)
                for name, make in kind.data.items()}
        data = {name: content for name, content in data.items() if content is not None}
        files = [*(kind.name(stem, n) for n in (*kind.files, *data)),
                 *(kind.name(stem, f"{t}.png") for t in pngs),
                 *(kind.name(stem, n) for n in kind.appendices)]
        if info is None:
            info = report_info(study, title=kind.title, analysis=kind.description,
                               units=units, conventions=kind.conventions, files=files)
        else:
            info = info.with_files(files)
        warnings = kind.warnings(result, () if study is None else study.source.warnings)
        if findings is None and study is not None:
            findings = study_findings_of(study)
        sheets = with_findings(kind.sheets(result, units, warnings), findings, units)
        images = {titles[t]: png for t, png in pngs.items()}
        with atomic_outputs(out_dir, inputs=inputs) as out:
            write_workbook(out.path(workbook), sheets, images, info=info,
                           number_format=kind.number_format(result),
                           highlight=kind.highlight(sheets),
                           images_title=kind.images_title.format(count=len(images)))
            for name, write in kind.files.items():
                write(result, units, out.path(kind.name(stem, name)), info)
            for name, content in data.items():
                out.path(kind.name(stem, name)).write_bytes(content)
            for t, png in pngs.items():
                out.path(kind.name(stem, f"{t}.png")).write_bytes(png_bytes(png))
            for name, write in kind.appendices.items():
                write(result, units, out.path(kind.name(stem, name)), info)
    return out.written

"""Write the reports of a study's results: every analysis's report, published together.

:func:`write_reports` is the Python call (``sl.write_reports(results, "reports")``);
:func:`prepare_outputs` and :func:`publish_reports` are its two halves, which the command line
calls before computing (so that an output folder that cannot be written, or a name that would
replace an input, stops the run before any work) and after.
"""

from __future__ import annotations

from pathlib import Path

from slingloads.io.analyses import ANALYSES
from slingloads.io.common.atomic import AtomicOutputs

_BY_NAME = {a.name: a for a in ANALYSES}


def prepare_outputs(study, out_dir, names, stem, *, replace_all=True):
    """The output set of the reports of analyses ``names`` of ``study``, checked before
    anything is computed: the output folder can be written, no input would be replaced, no
    name is too long.

    Parameters
    ----------
    study : Study
    out_dir : path-like
    names : iterable of str
        The analyses whose reports are written.
    stem : str
        The reports' names start with it (the workbook's name without extension).
    replace_all : bool
        The new reports replace the earlier files of every analysis for this stem (the
        ``run`` command: the whole report of the input), else those of ``names`` only.

    Returns
    -------
    AtomicOutputs
    """
    chosen = [a for a in ANALYSES if a.name in set(names)]
    replaced = ANALYSES if replace_all else chosen
    patterns = [p for a in replaced for p in a.output_patterns(stem)]
    outputs = AtomicOutputs(out_dir, inputs=study.source.input_files, replaces=patterns)
    outputs.check([n for a in chosen for n in a.output_names(stem)])
    return outputs


def publish_reports(results, outputs, stem, units="SI", names=None, figures=None, *,
                    before=None, after=None):
    """Write the report of each analysis ``names`` of ``results`` into ``outputs`` and
    publish them all together (or none).

    Parameters
    ----------
    results : Results
        With its ``study``.
    outputs : AtomicOutputs
        From :func:`prepare_outputs`.
    stem : str
    units : str
        ``"SI"`` or ``"US"``.
    names : iterable of str, optional
        Default: every analysis with a result.
    figures : dict, optional
        Analysis name -> its figures already started
        (:meth:`~slingloads.io.analyses.Analysis.start_figures`).
    before, after : callable, optional
        Called as ``before(name)`` and ``after(name)`` around each report.

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    study = results.study
    names = results.computed() if names is None else list(names)
    figures = figures or {}
    # imported here, when there are results to check (pandas): a refused workbook loads none
    from slingloads.io.consistency import consistency_checks
    from slingloads.runs.findings import study_findings

    checks = consistency_checks(results)
    findings = study_findings(results)  # once: the same Findings sheet in every report
    with outputs:
        for name in names:
            if before is not None:
                before(name)
            _BY_NAME[name].write(results.of(name), outputs, stem, units, study,
                                 figures=figures.get(name), checks=checks.get(name),
                                 findings=findings)
            if after is not None:
                after(name)
    return outputs.written


def write_reports(results, out_dir, units="SI", *, stem=None):
    """Write the report of every analysis of ``results`` into ``out_dir``, all published
    together (or none), replacing the earlier reports of the same input.

    Parameters
    ----------
    results : Results
        From :meth:`Study.run <slingloads.runs.study.Study.run>` or
        :func:`slingloads.io.study.run_workbook`.
    out_dir : path-like
    units : str
        ``"SI"`` or ``"US"`` (the Excel reports; CSV files are always SI).
    stem : str, optional
        Start of the file names (default: the workbook's name without extension, else the
        study's name).

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    study = results.study
    stem = stem or Path(study.path).stem or study.name
    names = results.computed()
    outputs = prepare_outputs(study, out_dir, names, stem)
    return publish_reports(results, outputs, stem, units, names)

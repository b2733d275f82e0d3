"""Read an input workbook: the airframe, then each analysis it asks for (see
:mod:`slingloads.io.analyses`)."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field

from slingloads.io.airframe.reader import read_airframe
from slingloads.io.airframe.schema import SHEETS
from slingloads.io.analyses import ANALYSES, all_parameters
from slingloads.io.common.cover import IDENTIFICATION, now_stamp
from slingloads.io.common.hidden import hidden_warnings, read_cells
from slingloads.io.common.locate import StudyCells, located
from slingloads.io.common.parameters import StudyParameters
from slingloads.io.common.workbook import WorkbookReader
from slingloads.models.airframe import Airframe

AIRFRAME_SHEETS = {s.name: s for s in SHEETS}


@dataclass
class WorkbookStudy:
    """Everything read from one input workbook.

    Attributes
    ----------
    name : str
    path : str
    sha256 : str
        Digest of the input file, printed on the reports.
    run : dict
        Which analyses the workbook asks for, by name (:data:`slingloads.io.analyses.ANALYSES`).
    airframe : Airframe
    parameters : dict
        The Study parameters given in the workbook, by lower-case name (SI).
    options : dict
        Report options (hull stations and pairs).
    inputs : dict
        Inputs of each analysis read, by analysis name (``inputs["loads"]``: the
        :class:`~slingloads.analyses.loads.LoadsStudy`).
    points : dict
        Hardpoints by kind (``fin_cp``, ``aero_reference``...: position or None). [m]
    identification : dict
        The free fields printed on the report covers (``project``, ``document number``,
        ``author``, ``checker``), by name; empty strings when not given.
    run_date : str
        When the workbook was read (the run date printed on the reports).
    results : dict
        Results of the analyses computed in this run, by analysis name (filled by the
        command line before the reports are written, so that a report can quote another's
        result: the loads report quotes the lateral study's recommended hook angle).
    input_files : list of pathlib.Path
        The workbook and every file it refers to that was read (CSV time histories): no
        output may replace one.
    warnings : list of str
        Implausible but possible inputs, each naming its cells; shown on the reports' Summary.
    cells : dict
        Cell of each Study parameter given, by lower-case name (to locate errors found while
        computing).
    written : dict
        ``(value as written, unit as written)`` of each Study parameter given, by lower-case
        name: what an error located at its cell echoes.
    tables : dict
        Tables read from the sheets, by sheet name (at least MassItems and Hardpoints), so
        that an error found while computing can be located at the cells of its inputs, with
        their values as written.
    runtime : dict
        How to execute (set by the command line): ``scheduler``, ``workers``, ``cache``,
        ``timeout``, ``progress`` of the campaign.
    results : dict
        Results of the analyses computed so far, by name (the loads read the campaign's).
    """

    name: str
    path: str
    sha256: str
    run: dict
    airframe: Airframe
    parameters: dict
    options: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    input_files: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    cells: dict = field(default_factory=dict)
    written: dict = field(default_factory=dict)
    tables: dict = field(default_factory=dict)
    identification: dict = field(default_factory=dict)
    run_date: str = field(default_factory=now_stamp)
    runtime: dict = field(default_factory=dict)
    results: dict = field(default_factory=dict)

    def digest(self):
        """What a report is computed from: input file, SHA-256, study, analyses, version, and
        the warnings on the inputs."""
        from pathlib import Path

        from slingloads import __version__

        out = {"input workbook": Path(self.path).name, "SHA-256": self.sha256,
               "study": self.name,
               "analyses": ", ".join(k for k, v in self.run.items() if v),
               "slingloads version": __version__}
        for k, text in enumerate(self.warnings, start=1):
            out[f"warning {k}"] = text
        return out

    @property
    def loads(self):
        """The loads study, or None if the loads analysis was not read."""
        return self.inputs.get("loads")

    def located(self, fields=None):
        """Locate an :class:`InputError` raised while computing: in this workbook, at the
        Study cell of the parameter ``fields[error.field]`` when there is one, echoing that
        parameter's value as written with its unit (not the model's value); see
        :func:`slingloads.io.common.locate.located`."""
        return located(StudyCells(self.path, self.cells, self.written, all_parameters(),
                                  sheet=None), fields)


def file_digest(path):
    """SHA-256 of a file, hex."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_study(path, only=None, *, reader=None, on_read=None):
    """Read an input workbook and build every analysis it asks for.

    Parameters
    ----------
    path : str or Path
    only : iterable of str, optional
        Build these analyses (``"loads"``, ``"lateral"``, ``"chute sizing"``) whatever the
        workbook's ``run ...`` parameters say.
    reader : WorkbookReader, optional
        An opened reader of the workbook (e.g. :meth:`WorkbookReader.from_rows`); by default
        the file ``path`` is opened.
    on_read : callable, optional
        Called as ``on_read(name, study)`` once the inputs and report options of analysis
        ``name`` are read, before the next analysis is read (the study is not complete yet:
        its ``input_files`` and ``warnings`` are filled in at the end).

    Returns
    -------
    WorkbookStudy

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule, for any bad input.
    """
    own = reader is None
    reader = WorkbookReader(path) if own else reader
    try:
        return _build(reader, path, only, file_digest(path) if own else "", on_read)
    finally:
        reader.close()


def _build(reader, path, only, sha256, on_read=None):
    params = StudyParameters(reader, all_parameters())
    run = {a.name: params(a.run_parameter) for a in ANALYSES}
    if only is not None:
        run = {name: name in set(only) for name in run}
    airframe, refs = read_airframe(reader, params)
    study = WorkbookStudy(name=str(params("study name")), path=str(path), sha256=sha256,
                          run=run, airframe=airframe,
                          parameters={k: v[0] for k, v in params.given.items()}, points=refs,
                          cells={k: v[1] for k, v in params.given.items()},
                          written={k: (v.raw, v.unit) for k, v in params.given.items()},
                          tables={name: reader.table(AIRFRAME_SHEETS[name])
                                  for name in ("MassItems", "Hardpoints")},
                          identification={k: str(params(k) or "").strip()
                                          for k in IDENTIFICATION})
    for analysis in ANALYSES:
        if run[analysis.name]:
            study.inputs[analysis.name] = analysis.read(reader, params, study)
        study.options.update(analysis.report_options(params, study))
        if run[analysis.name] and on_read is not None:
            on_read(analysis.name, study)
    study.input_files = reader.input_files
    study.warnings = [*reader.warnings, *hidden_warnings(reader, read_cells(reader, params))]
    return study

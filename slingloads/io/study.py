"""Read an input workbook: the airframe, then each analysis it asks for (see
:mod:`slingloads.io.analyses`)."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field

from slingloads.io.airframe.reader import read_airframe
from slingloads.io.analyses import ANALYSES, all_parameters
from slingloads.io.common.cover import IDENTIFICATION, now_stamp
from slingloads.io.common.parameters import StudyParameters
from slingloads.io.common.workbook import WorkbookReader
from slingloads.models.airframe import Airframe


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
        Hardpoints by kind that the Airframe does not keep (``fin_cp``, ``aero_reference``:
        position or None). [m]
    identification : dict
        The free fields printed on the report covers (``project``, ``document number``,
        ``author``, ``checker``), by name; empty strings when not given.
    run_date : str
        When the workbook was read (the run date printed on the reports).
    results : dict
        Results of the analyses computed in this run, by analysis name (filled by the
        command line before the reports are written, so that a report can quote another's
        result: the loads report quotes the lateral study's recommended hook angle).
    """

    name: str
    path: str
    sha256: str
    run: dict
    airframe: Airframe
    parameters: dict
    options: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)

    def digest(self):
        """What a report is computed from: input file, SHA-256, study, analyses, version."""
        from pathlib import Path

        from slingloads import __version__

        return {"input workbook": Path(self.path).name, "SHA-256": self.sha256,
                "study": self.name,
                "analyses": ", ".join(k for k, v in self.run.items() if v),
                "slingloads version": __version__}
    points: dict = field(default_factory=dict)
    identification: dict = field(default_factory=dict)
    run_date: str = field(default_factory=now_stamp)
    results: dict = field(default_factory=dict)

    @property
    def loads(self):
        """The loads study, or None if the loads analysis was not read."""
        return self.inputs.get("loads")


def file_digest(path):
    """SHA-256 of a file, hex."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_study(path, only=None):
    """Read an input workbook and build every analysis it asks for.

    Parameters
    ----------
    path : str or Path
    only : iterable of str, optional
        Build these analyses (``"loads"``, ``"lateral"``, ``"chute sizing"``) whatever the
        workbook's ``run ...`` parameters say.

    Returns
    -------
    WorkbookStudy

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule, for any bad input.
    """
    reader = WorkbookReader(path)
    params = StudyParameters(reader, all_parameters())
    run = {a.name: params(a.run_parameter) for a in ANALYSES}
    if only is not None:
        run = {name: name in set(only) for name in run}
    airframe, refs = read_airframe(reader, params)
    study = WorkbookStudy(name=str(params("study name")), path=str(path),
                          sha256=file_digest(path), run=run, airframe=airframe,
                          parameters={k: v[0] for k, v in params.given.items()}, points=refs,
                          identification={k: str(params(k) or "").strip()
                                          for k in IDENTIFICATION})
    for analysis in ANALYSES:
        if run[analysis.name]:
            study.inputs[analysis.name] = analysis.read(reader, params, study)
        study.options.update(analysis.report_options(params, study))
    return study

"""Read an input workbook into a :class:`~slingloads.runs.study.Study`: the airframe, then
each analysis it asks for (see :mod:`slingloads.io.analyses`); :func:`run_workbook` reads
and runs it."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field

from slingloads.errors import ErrorCollector
from slingloads.io.airframe.schema import SHEETS
from slingloads.io.analyses import ANALYSES, all_parameters
from slingloads.io.common.cover import IDENTIFICATION, now_stamp
from slingloads.io.common.hidden import hidden_warnings, read_cells
from slingloads.io.common.locate import StudyCells, find_place, place_error
from slingloads.io.common.parameters import StudyParameters
from slingloads.io.common.workbook import WorkbookReader
from slingloads.runs.study import Source, Study
from slingloads.safeopen import open_regular

AIRFRAME_SHEETS = {s.name: s for s in SHEETS}
_BY_NAME = {a.name: a for a in ANALYSES}


@dataclass
class WorkbookSource(Source):
    """Where a study read from a workbook comes from, and where each of its values is.

    Attributes
    ----------
    path, sha256, input_files, warnings, identification, run_date
        See :class:`~slingloads.runs.study.Source`.
    parameters : dict
        The Study parameters given in the workbook, by lower-case name (SI).
    points : dict
        Hardpoints by kind (``fin_cp``, ``aero_reference``...: position or None) [m], and
        ``rows``: the Hardpoints row of each kind.
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
    """

    parameters: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    cells: dict = field(default_factory=dict)
    written: dict = field(default_factory=dict)
    tables: dict = field(default_factory=dict)

    def locate(self, study, analysis, err, context=None):
        """Put ``err``, raised while analysis ``analysis`` of ``study`` ran, in this
        workbook: where its reader puts it (``locate`` of its reader, e.g. the lateral
        critical case's rope length), else at the Study cell of the parameter its ``field``
        comes from (its schema's ``COMPUTE_FIELDS``), echoing that parameter's value as
        written with its unit (not the model's value); always naming the file
        (:func:`slingloads.io.common.locate.find_place`).

        Parameters
        ----------
        study : Study
            The study read from this workbook.
        analysis : str
            The analysis that raised ``err`` (a name of :data:`~slingloads.runs.study.
            ANALYSES`).
        err : InputError
        context : object, optional
            What the analysis was doing (:meth:`~slingloads.runs.study.Study.located`).

        Returns
        -------
        InputError
            ``err`` with its file, sheet and cell.
        """
        entry = _BY_NAME[analysis]
        err = entry.locate(err, study, context)
        cells = StudyCells(self.path, self.cells, self.written, all_parameters(), sheet=None)
        return place_error(err, find_place(err, cells, entry.compute_fields))


def file_digest(path):
    """SHA-256 of a file, hex.

    Parameters
    ----------
    path : path-like

    Returns
    -------
    str
        64 hexadecimal digits.
    """
    h = hashlib.sha256()
    with open_regular(path, follow_links=True) as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_study(path, only=None, *, reader=None, on_read=None, on_checked=None):
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
    on_checked : callable, optional
        Called as ``on_checked(asked)`` once the Study sheet and the cells of the table
        sheets read without error, with the names of the analyses to run, before the
        airframe and the analyses are read (the command line starts its helper processes
        there: a workbook refused before starts none).

    Returns
    -------
    Study
        Its :attr:`~slingloads.runs.study.Study.source` is the :class:`WorkbookSource`.

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule, for any bad input.
    """
    own = reader is None
    reader = WorkbookReader(path) if own else reader
    try:
        return _build(reader, path, only, file_digest(path) if own else "", on_read,
                      on_checked)
    finally:
        reader.close()


def _build(reader, path, only, sha256, on_read=None, on_checked=None):
    # Independent steps are attempted one after another and their errors reported together
    # (up to MAX_REPORTED_ERRORS): the Study sheet row by row (with the checks of each
    # analysis's rows that need none of its sheets, whether it runs or not), each table sheet
    # cell by cell, the airframe, then each analysis. A step others need stops the reading
    # when it fails.
    errors = ErrorCollector()
    params = errors.call(StudyParameters, reader, all_parameters(), errors)
    rows_read = not errors
    if params is not None:  # the rows every analysis checks on the Study sheet alone, run or not
        # the airframe's models (pandas) load once the Study sheet is there
        from slingloads.io.airframe.reader import CHOICES as AIRFRAME_CHOICES

        for name, valid in AIRFRAME_CHOICES.items():
            errors.call(params.choice, name, valid)
        for analysis in ANALYSES:
            analysis.check_rows(params, errors)
    for sheet in AIRFRAME_SHEETS.values():  # every cell of the airframe's sheets, at once
        if sheet.required or reader.has_sheet(sheet.name):
            errors.call(reader.table, sheet)
    if params is None or not rows_read:
        errors.raise_if_any(note="the analyses' sheets are checked once the Study sheet reads")
    asked = [a.name for a in ANALYSES if errors.call(params, a.run_parameter)]
    if only is not None:
        asked = [a.name for a in ANALYSES if a.name in set(only)]
    if errors:  # the reading stops here: first every cell of the asked analyses' table
        # sheets present, so that a text in a number cell of several sheets is reported for
        # all of them, not one sheet per attempt (else their readers check them below)
        seen = set(AIRFRAME_SHEETS)
        for sheet in (t for name in asked for t in _BY_NAME[name].modules().schema.SHEETS):
            if sheet.name not in seen and reader.has_sheet(sheet.name):
                seen.add(sheet.name)
                errors.call(reader.table, sheet)
    errors.raise_if_any(note="the airframe and the analyses are checked beyond their cells "
                             "once these read")
    if on_checked is not None:
        on_checked(asked)
    from slingloads.io.airframe.reader import read_airframe

    read = errors.call(read_airframe, reader, params)
    if read is None:
        errors.raise_if_any(note=f"the sheets of {', '.join(asked) or 'the analyses'} are "
                                 "checked once the airframe reads")
    airframe, refs = read
    source = WorkbookSource(
        path=str(path), sha256=sha256, points=refs,
        parameters={k: v[0] for k, v in params.given.items()},
        cells={k: v[1] for k, v in params.given.items()},
        written={k: (v.raw, v.unit) for k, v in params.given.items()},
        tables={name: reader.table(AIRFRAME_SHEETS[name]) for name in ("MassItems", "Hardpoints")},
        identification={k: str(params(k) or "").strip() for k in IDENTIFICATION},
        run_date=now_stamp())
    study = Study(name=str(params("study name")), airframe=airframe, asked=tuple(asked),
                  source=source)
    for analysis in ANALYSES:
        if analysis.name in asked:
            inputs = errors.call(analysis.read, reader, params, study)
            if inputs is not None:
                study.inputs.set(analysis.name, inputs)
        if analysis.options:
            options = errors.call(analysis.modules().reader.report_options, params, study)
            if options is not None:
                study.report = options
        if analysis.name in asked and on_read is not None and not errors:
            on_read(analysis.name, study)
    errors.raise_if_any()
    source.input_files = list(reader.input_files)
    source.warnings = [*reader.warnings, *hidden_warnings(reader, read_cells(reader, params))]
    return study


def run_workbook(path, only=None):
    """Read the workbook at ``path`` and run every analysis it asks for (or ``only`` these).

    Parameters
    ----------
    path : str or Path
    only : iterable of str, optional
        Run these analyses (``"loads"``, ``"lateral"``, ``"chute sizing"``, ``"multibody"``,
        ``"campaign"``) whatever the workbook's ``run ...`` rows say.

    Returns
    -------
    Results
        Typed results (:class:`~slingloads.runs.study.Results`), with the study read as
        ``.study``.

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule, for any bad input.

    Examples
    --------
    >>> import slingloads as sl
    >>> results = sl.run("loadcases/example-light-twin.xlsx", only=["loads"])
    >>> results.loads.envelope().shape[1] > 0
    True
    """
    return read_study(path, only).run()


def load_workbook_system(path):
    """The multibody inputs of the workbook at ``path`` (whatever its 'run multibody' says).

    Parameters
    ----------
    path : path-like
        The input workbook (``.xlsx``).

    Returns
    -------
    MultibodyInputs
    """
    return read_study(path, only=["multibody"]).inputs.multibody

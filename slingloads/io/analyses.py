"""The registry of analyses: what a workbook may ask for, and where each analysis's io lives.

Each analysis has a folder ``slingloads/io/<folder>/`` with

* ``schema.py``: ``SECTION``, its Study-sheet parameters and sheets
  (:mod:`slingloads.io.common.schema` types), and ``COMPUTE_FIELDS`` (model argument ->
  Study parameter: where an error the analysis raises on that argument is put);
* ``rows.py``: ``CHOICES`` (row name -> valid values) and ``ROW_CHECKS`` (row name ->
  ``check(params)``), its Study rows checked for every workbook whether it runs or not
  (:meth:`Analysis.check_rows`), in a module that imports none of its models;
* ``reader.py``: ``read(reader, params, study) -> inputs``, building the analysis's inputs
  (SI, the types of :mod:`slingloads.runs`) from the workbook, with located errors;
  ``locate(err, study, context) -> InputError``, putting an error the analysis
  raised while running at the workbook cell its value came from
  (:meth:`slingloads.runs.study.Study.located`);
* ``report.py``: ``report_kind(study)``, what its report is made of
  (:class:`~slingloads.io.common.report_writer.ReportKind`; the loads report's also takes
  ``checks``, the checks against the other analyses of the run:
  :mod:`slingloads.io.consistency`), whose figures
  :func:`~slingloads.io.common.report_writer.start_figures` starts drawing while the next
  analyses are computed and which the one writer,
  :func:`~slingloads.io.common.report_writer.write_report`, writes (:meth:`Analysis.write`);
  ``OUTPUTS``, the names of its files;
* ``plots.py``: the figures of the report.

Running an analysis is not here: :mod:`slingloads.runs` runs the analyses of a study, in
order, with their hand-offs. The study reader (:func:`slingloads.io.study.read_study`), the
blank template (:mod:`slingloads.io.template`), the report writer
(:mod:`slingloads.io.reports`) and the command line (:mod:`slingloads.cli`) all follow this
list. Each analysis's modules are imported (by name, in the functions of its :class:`Modules`)
on first use, each on its own, so listing the analyses costs nothing (``slingloads --help``
stays fast) and reading a workbook imports the schema and the rows of every analysis but the
reader and the report of those it runs only.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType

from slingloads.io.airframe.schema import SECTION as AIRFRAME
from slingloads.io.common.schema import FLAG, TEXT, Parameter, Section


@dataclass(frozen=True)
class Modules:
    """The io modules of one analysis, each imported on first use by the function given for
    it (a study that does not run an analysis imports its schema and its rows only, which
    import no numerical model).

    Parameters
    ----------
    schema_module, rows_module, reader_module, report_module : callable
        Each imports and returns the analysis's module of that name.
    """

    schema_module: Callable[[], ModuleType]
    rows_module: Callable[[], ModuleType]
    reader_module: Callable[[], ModuleType]
    report_module: Callable[[], ModuleType]

    @property
    def schema(self):
        """Its ``schema.py``."""
        return self.schema_module()

    @property
    def rows(self):
        """Its ``rows.py``: ``CHOICES`` and ``ROW_CHECKS``, checked for every workbook."""
        return self.rows_module()

    @property
    def reader(self):
        """Its ``reader.py`` (imports the analysis's models)."""
        return self.reader_module()

    @property
    def report(self):
        """Its ``report.py``."""
        return self.report_module()


def _loads_schema():
    from slingloads.io.loads import schema

    return schema


def _loads_rows():
    from slingloads.io.loads import rows

    return rows


def _loads_reader():
    from slingloads.io.loads import reader

    return reader


def _loads_report():
    from slingloads.io.loads import report

    return report


def _lateral_schema():
    from slingloads.io.lateral import schema

    return schema


def _lateral_rows():
    from slingloads.io.lateral import rows

    return rows


def _lateral_reader():
    from slingloads.io.lateral import reader

    return reader


def _lateral_report():
    from slingloads.io.lateral import report

    return report


def _chute_schema():
    from slingloads.io.chute import schema

    return schema


def _chute_rows():
    from slingloads.io.chute import rows

    return rows


def _chute_reader():
    from slingloads.io.chute import reader

    return reader


def _chute_report():
    from slingloads.io.chute import report

    return report


def _multibody_schema():
    from slingloads.io.multibody import schema

    return schema


def _multibody_rows():
    from slingloads.io.multibody import rows

    return rows


def _multibody_reader():
    from slingloads.io.multibody import reader

    return reader


def _multibody_report():
    from slingloads.io.multibody import report

    return report


def _campaign_schema():
    from slingloads.io.campaign import schema

    return schema


def _campaign_rows():
    from slingloads.io.campaign import rows

    return rows


def _campaign_reader():
    from slingloads.io.campaign import reader

    return reader


def _campaign_report():
    from slingloads.io.campaign import report

    return report


@dataclass(frozen=True)
class Analysis:
    """One analysis a workbook may ask for.

    Parameters
    ----------
    name : str
        Name in the Study sheet (``run <name>``), in the reports and in
        :mod:`slingloads.runs`.
    subcommand : str
        Its command of ``slingloads``.
    io : Modules
        Its io modules, each imported on first use.
    summary : str
        One line for ``slingloads --help``.
    run_help : str
        Description of the ``run <name>`` Study parameter.
    run_default : str
        ``"yes"`` or ``"no"``.
    options : bool
        Its reader has ``report_options(params, study) -> ReportOptions``, called for every
        workbook whether or not the analysis runs.
    """

    name: str
    subcommand: str
    io: Modules
    summary: str
    run_help: str
    run_default: str = "no"
    options: bool = False

    def modules(self):
        """Its :class:`Modules` (each imported when one of its attributes is read)."""
        return self.io

    @property
    def run_parameter(self):
        """The Study parameter that asks for this analysis."""
        return f"run {self.name}"

    @property
    def section(self):
        """Its Study-sheet parameters and sheets."""
        return self.modules().schema.SECTION

    @property
    def compute_fields(self):
        """Model argument -> Study parameter, where an error on that argument is put."""
        return self.modules().schema.COMPUTE_FIELDS

    def read(self, reader, params, study):
        """Build its inputs from the workbook."""
        return self.modules().reader.read(reader, params, study)

    def check_rows(self, params, errors):
        """Check its Study rows whose rules need none of its sheets, whether it runs or not,
        each row's error gathered in ``errors``: every choice row of its ``rows.py``'s
        ``CHOICES`` and the rows of its ``ROW_CHECKS`` (row name -> ``check(params)``). A
        value in the workbook is an input of the study even while its analysis is switched
        off: it is refused now rather than when the analysis is switched on. Its rows module
        imports no model of the analysis, so that the check costs nothing to a study that
        does not run it."""
        rows = self.modules().rows
        for name, valid in getattr(rows, "CHOICES", {}).items():
            errors.call(params.choice, name, valid)
        for check in getattr(rows, "ROW_CHECKS", {}).values():
            errors.call(check, params)

    def locate(self, err, study, context=None):
        """``err``, raised while it ran on ``study``, put where its value came from (its
        reader's ``locate``)."""
        return self.modules().reader.locate(err, study, context)

    def start_figures(self, result, units, study):
        """Start drawing its report's figures in worker processes (so that they are drawn
        while the other analyses are computed): a context manager to leave once the report
        is written (:func:`~slingloads.io.common.report_writer.start_figures` of its report
        module's ``report_kind(study)``)."""
        from slingloads.io.common.report_writer import start_figures

        return start_figures(self.modules().report.report_kind(study), result, units)

    def output_patterns(self, stem):
        """Regular expressions of the names of its report files for input ``stem`` (its
        report module's ``OUTPUTS``), which a new report replaces."""
        from slingloads.io.common.atomic import output_pattern

        return [output_pattern(t, stem) for t in self.modules().report.OUTPUTS]

    def output_names(self, stem):
        """The fixed names among its report files (for the checks made before computing)."""
        return [t.format(stem=stem) for t in self.modules().report.OUTPUTS if "*" not in t]

    def write(self, result, out_dir, stem, units, study, figures=None, checks=None,
              findings=None):
        """Write its report into the run's outputs ``out_dir``: the one report writer,
        :func:`~slingloads.io.common.report_writer.write_report`, of its report module's
        ``report_kind(study)``, with the figures started by :meth:`start_figures`, if any;
        ``checks``, a DataFrame of checks against the other
        analyses of the run (:mod:`slingloads.io.consistency`), is passed to the reports that
        show them; ``findings``, the run's findings (:mod:`slingloads.runs.findings`), to
        every report (its Findings sheet)."""
        from slingloads.io.common.report_writer import write_report

        report = self.modules().report
        kind = report.report_kind(study) if checks is None else report.report_kind(study, checks)
        return write_report(kind, result, out_dir, stem, units, study, figures, findings)


#: Every analysis, in the order they are read, run and written.
ANALYSES = (
    Analysis("loads", "loads",
             Modules(_loads_schema, _loads_rows, _loads_reader, _loads_report),
             "structural loads only: CS-29.865 cases, inertia relief, SFBM, envelopes",
             "Run the structural loads analysis (SFBM).", "yes", options=True),
    Analysis("lateral", "lateral",
             Modules(_lateral_schema, _lateral_rows, _lateral_reader, _lateral_report),
             "lateral-step pendulum study only",
             "Run the lateral-step pendulum study (sheets Lateral*)."),
    Analysis("chute sizing", "chute",
             Modules(_chute_schema, _chute_rows, _chute_reader, _chute_report),
             "parachute sizing only",
             "Run the parachute sizing (sheets Chute*)."),
    Analysis("multibody", "simulate",
             Modules(_multibody_schema, _multibody_rows, _multibody_reader, _multibody_report),
             "multibody model only: trim, linear modes, manoeuvres",
             "Run the multibody model (Study rows 'multibody ...', sheets MultibodyManoeuvres, "
             "HTailAero)."),
    Analysis("campaign", "campaign",
             Modules(_campaign_schema, _campaign_rows, _campaign_reader, _campaign_report),
             "multibody campaign only: parachute selection over the operating envelope, "
             "sensitivity, stability maps, transport without parachute, loads hand-off",
             "Run the multibody campaign (Study rows 'campaign ...'); with 'run loads' the "
             "loads then take the dynamics' cases."),
)


#: Parameters of the whole study: its name, the report's free identification fields and which
#: analyses to run.
GENERAL = Section("general", parameters=(
    Parameter("study name", TEXT, "", "study", "Name printed on the reports."),
    Parameter("project", TEXT, "", "",
              "Project the reports belong to, printed on their cover (free text)."),
    Parameter("document number", TEXT, "", "",
              "Document number of the reports, printed on their cover and in the footer of "
              "every page (free text, e.g. 'LR-1234 issue A')."),
    Parameter("author", TEXT, "", "", "Who prepared the analysis, printed on the covers."),
    Parameter("checker", TEXT, "", "", "Who checked it, printed on the covers."),
    *(Parameter(a.run_parameter, FLAG, "", a.run_default, a.run_help) for a in ANALYSES),
))


def sections():
    """Every section: the general parameters, the airframe, then each analysis."""
    return [GENERAL, AIRFRAME, *(a.section for a in ANALYSES)]


def all_parameters():
    """Every Study-sheet parameter by lower-case name."""
    return {p.name.lower(): p for s in sections() for p in s.parameters}


def all_sheets():
    """Every table sheet by name."""
    return {t.name: t for s in sections() for t in s.sheets}

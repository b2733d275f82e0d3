"""The registry of analyses: what a workbook may ask for, and where each analysis's io lives.

Each analysis has a folder ``slingloads/io/<folder>/`` with

* ``schema.py``: ``SECTION``, its Study-sheet parameters and sheets
  (:mod:`slingloads.io.common.schema` types);
* ``reader.py``: ``read(reader, params, study) -> inputs``, building the analysis's inputs
  (SI) from the workbook, with located errors;
* ``report.py``: ``compute(study) -> result`` (orchestration: the physics is in
  :mod:`slingloads.analyses`) and ``write(result, out_dir, stem, units, study)``, publishing
  through :func:`slingloads.io.common.atomic.atomic_outputs` (the loads report also takes
  ``checks``, the checks against the other analyses of the run:
  :mod:`slingloads.io.consistency`); optionally ``start_figures(result, units, study)`` (a
  started :class:`~slingloads.io.common.figures.FigureRenderer`, then passed to ``write`` as
  ``figures=``) so that the figures are drawn while the next analyses are computed; and
  optionally ``shortfalls(result) -> list of str``, what the analysis was asked for and could
  not compute (the command line then says so and exits with code 3);
* ``plots.py``: the figures of the report.

The study builder (:func:`slingloads.io.study.read_study`), the blank template
(:mod:`slingloads.io.template`) and the command line (:mod:`slingloads.cli`) all follow this
list. Modules are imported on first use, so listing the analyses costs nothing
(``slingloads --help`` stays fast).
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import import_module

from slingloads.io.airframe.schema import SECTION as AIRFRAME
from slingloads.io.common.schema import FLAG, TEXT, Parameter, Section


@dataclass(frozen=True)
class Analysis:
    """One analysis a workbook may ask for.

    Parameters
    ----------
    name : str
        Name in the Study sheet (``run <name>``) and in the reports.
    subcommand : str
        Its command of ``slingloads``.
    folder : str
        Its io package under ``slingloads.io``.
    summary : str
        One line for ``slingloads --help``.
    run_help : str
        Description of the ``run <name>`` Study parameter.
    run_default : str
        ``"yes"`` or ``"no"``.
    options : str
        Name of a function of its reader, ``options(params, study) -> dict``, called for every
        workbook whether or not the analysis runs (report options); empty for none.
    feeds : tuple of str
        Analyses that take this one's result (``study.results``): it is computed before them.
    """

    name: str
    subcommand: str
    folder: str
    summary: str
    run_help: str
    run_default: str = "no"
    options: str = ""
    feeds: tuple = ()

    @property
    def run_parameter(self):
        """The Study parameter that asks for this analysis."""
        return f"run {self.name}"

    def module(self, part):
        """Its ``schema``, ``reader``, ``report`` or ``plots`` module (imported on first use)."""
        return import_module(f"slingloads.io.{self.folder}.{part}")

    def runner(self):
        """Its module of :mod:`slingloads.runs`."""
        return import_module(f"slingloads.runs.{self.name.replace(' ', '_')}")

    @property
    def section(self):
        """Its Study-sheet parameters and sheets."""
        return self.module("schema").SECTION

    def read(self, reader, params, study):
        """Build its inputs from the workbook."""
        return self.module("reader").read(reader, params, study)

    def report_options(self, params, study):
        """Its report options (checked for every workbook), or an empty dict."""
        if not self.options:
            return {}
        return getattr(self.module("reader"), self.options)(params, study)

    def compute(self, study):
        """Run it on a study read from a workbook. An :class:`InputError` the analysis raises
        is located in the workbook, at the Study cell its ``field`` comes from when the
        analysis's schema maps it (``COMPUTE_FIELDS``: model argument -> Study parameter)."""
        fields = getattr(self.module("schema"), "COMPUTE_FIELDS", {})
        with study.located(fields):
            return self.runner().compute(study)

    def start_figures(self, result, units, study):
        """Start drawing its report's figures in worker processes (so that they are drawn
        while the other analyses are computed): a context manager to leave once the report
        is written, or None when its report module draws them at writing time."""
        start = getattr(self.module("report"), "start_figures", None)
        return start(result, units, study) if start is not None else None

    def shortfalls(self, result):
        """What the analysis was asked for and could not compute (e.g. the multibody model
        without a trim: no linear modes, no stability verdict), one line each; empty when
        its report holds every result asked for."""
        find = getattr(self.runner(), "shortfalls", None)
        return list(find(result)) if find is not None else []

    def output_patterns(self, stem):
        """Regular expressions of the names of its report files for input ``stem`` (its
        report module's ``OUTPUTS``), which a new report replaces."""
        from slingloads.io.common.atomic import output_pattern

        return [output_pattern(t, stem) for t in getattr(self.module("report"), "OUTPUTS", ())]

    def output_names(self, stem):
        """The fixed names among its report files (for the checks made before computing)."""
        return [t.format(stem=stem) for t in getattr(self.module("report"), "OUTPUTS", ())
                if "*" not in t]

    def write(self, result, out_dir, stem, units, study, figures=None, checks=None):
        """Write its report into the run's outputs ``out_dir`` (with the figures started by
        :meth:`start_figures`, if any); ``checks``, a DataFrame of checks against the other
        analyses of the run (:mod:`slingloads.io.consistency`), is passed to the reports that
        show them."""
        extra = {} if checks is None else {"checks": checks}
        if figures is not None:
            extra["figures"] = figures
        return self.module("report").write(result, out_dir, stem, units, study, **extra)


#: Every analysis, in the order they are read, run and written.
ANALYSES = (
    Analysis("loads", "loads", "loads",
             "structural loads only: CS-29.865 cases, inertia relief, SFBM, envelopes",
             "Run the structural loads analysis (SFBM).", "yes", options="report_options"),
    Analysis("lateral", "lateral", "lateral", "lateral-step pendulum study only",
             "Run the lateral-step pendulum study (sheets Lateral*)."),
    Analysis("chute sizing", "chute", "chute", "parachute sizing only",
             "Run the parachute sizing (sheets Chute*)."),
    Analysis("multibody", "simulate", "multibody",
             "multibody model only: trim, linear modes, manoeuvres",
             "Run the multibody model (Study rows 'multibody ...', sheets MultibodyManoeuvres, "
             "HTailAero)."),
    Analysis("campaign", "campaign", "campaign",
             "multibody campaign only: parachute selection over the operating envelope, "
             "sensitivity, stability maps, transport without parachute, loads hand-off",
             "Run the multibody campaign (Study rows 'campaign ...'); with 'run loads' the "
             "loads then take the dynamics' cases.", feeds=("loads",)),
)


def compute_order(names):
    """``names`` in the order to compute them: an analysis that feeds others (its result is
    their input) before them, the rest in registry order."""
    names = list(names)
    feeders = [a.name for a in ANALYSES if a.name in names and set(a.feeds) & set(names)]
    return feeders + [n for n in names if n not in feeders]

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

"""One study: the airframe, the inputs of each analysis, how to run them, and their results.

A :class:`Study` is what a workbook (or a script) describes: the airframe, the inputs of
every analysis it asks for (:class:`Inputs`), how to execute the campaign
(:class:`RunOptions`), what the reports show (:class:`ReportOptions`) and where it came from
(:class:`Source`). :meth:`Study.run` runs the analyses it asks for in order
(:func:`compute_order`: the campaign before the loads and the sizing it feeds) and fills in its
:class:`Results`; :func:`run_analysis` runs one, with its hand-off. Nothing here reads a file
or writes a report: :func:`slingloads.io.study.read_study` builds a study from a workbook and
:func:`slingloads.io.reports.write_reports` writes the reports of its results.

Analyses, by name (the Study sheet's ``run <name>``), in the order they are read and written:
``"loads"``, ``"lateral"``, ``"chute sizing"``, ``"multibody"``, ``"campaign"``.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path
from typing import TYPE_CHECKING

from slingloads.errors import InputError

if TYPE_CHECKING:  # the analyses' modules load when they run (keeps a loads run light)
    from slingloads.analyses.campaign import Handoff
    from slingloads.analyses.hook_angle import HookAngleHandoff
    from slingloads.analyses.loads import LoadsResult, LoadsStudy
    from slingloads.analyses.parachute_decision import ParachuteDecision
    from slingloads.models.airframe import Airframe
    from slingloads.runs.campaign import CampaignInputs, CampaignReport
    from slingloads.runs.chute_sizing import ChuteSizingInputs, ChuteSizingReport
    from slingloads.runs.lateral import LateralInputs, LateralReport
    from slingloads.runs.multibody import MultibodyInputs, MultibodyReport

#: Every analysis, in the order they are read and reported.
ANALYSES = ("loads", "lateral", "chute sizing", "multibody", "campaign")
#: The field of :class:`Inputs` and :class:`Results` that holds each analysis.
FIELD = {name: name.replace(" ", "_") for name in ANALYSES}


def _field(name):
    """The field of analysis ``name``, refused with the valid names if unknown."""
    if name not in FIELD:
        raise InputError(f"unknown analysis; valid names are {list(ANALYSES)}", name)
    return FIELD[name]
#: What each analysis is called in messages.
TITLES = {"loads": "loads analysis", "lateral": "lateral study",
          "chute sizing": "parachute sizing", "multibody": "multibody model",
          "campaign": "campaign"}
#: The analyses whose result is another's input: name -> the analyses it feeds (the lateral
#: study's recommended design angle to the loads' lateral hook cases; the campaign's dynamics
#: to the loads; its selection to the parachute decision the sizing makes).
FEEDS = {"lateral": ("loads",), "campaign": ("loads", "chute sizing")}
#: How a finding of the parachute decision starts (:meth:`Results.shortfalls`).
DECISION_FINDING = "parachute decision:"


def compute_order(names):
    """``names`` in the order to compute them: an analysis that feeds others (its result is
    their input, :data:`FEEDS`) before them, the rest in the order of :data:`ANALYSES`.

    Parameters
    ----------
    names : iterable of str
        Analyses (names of :data:`ANALYSES`).

    Returns
    -------
    list of str
    """
    names = set(names)
    names = [n for n in ANALYSES if n in names]
    feeders = [n for n in names if set(FEEDS.get(n, ())) & set(names)]
    return feeders + [n for n in names if n not in feeders]


@dataclass
class Inputs:
    """The inputs of each analysis of a study; None for an analysis it does not ask for.

    Attributes
    ----------
    loads : LoadsStudy or None
        Hook, aerodynamic and parachute cases on the airframe (SI).
    lateral : LateralInputs or None
        Bodies, rope lengths [m], carrier motions, margin, damping and solver settings.
    chute_sizing : ChuteSizingInputs or None
        Yaw model, wake, gusts and swept area factors of the parachute sizing.
    multibody : MultibodyInputs or None
        The towed system, its manoeuvres and the simulation settings.
    campaign : CampaignInputs or None
        The campaign (factors swept, selection rules) and where to run it.
    """

    loads: LoadsStudy | None = None
    lateral: LateralInputs | None = None
    chute_sizing: ChuteSizingInputs | None = None
    multibody: MultibodyInputs | None = None
    campaign: CampaignInputs | None = None

    def of(self, name):
        """The inputs of analysis ``name`` (None if not given).

        Parameters
        ----------
        name : str
            A name of :data:`ANALYSES`.

        Returns
        -------
        object or None
            Its field of this object (the types above).

        Raises
        ------
        InputError
            On an unknown name (the valid ones listed).
        """
        return getattr(self, _field(name))

    def set(self, name, value):
        """Keep ``value`` as the inputs of analysis ``name``.

        Parameters
        ----------
        name : str
            A name of :data:`ANALYSES`.
        value : object or None
            Its inputs (the type of its field above).
        """
        setattr(self, _field(name), value)

    def given(self):
        """The analyses whose inputs are given, in the order of :data:`ANALYSES`.

        Returns
        -------
        tuple of str
        """
        return tuple(n for n in ANALYSES if self.of(n) is not None)


@dataclass
class RunOptions:
    """How to execute the campaign; None: the study's own choice (its Study rows), else the
    default.

    Attributes
    ----------
    scheduler : str or None
        Address of a dask.distributed scheduler (``tcp://host:port``).
    workers : int or None
        Local worker processes. [count]
    cache : pathlib.Path or None
        Folder of the run cache (default: :func:`slingloads.runs.cache.default_cache_dir`).
    timeout : float or None
        Time the scheduler has to answer. [s]
    progress : callable or None
        Called as ``progress(done, total)`` after each batch of runs.
    """

    scheduler: str | None = None
    workers: int | None = None
    cache: Path | None = None
    timeout: float | None = None
    progress: Callable[[int, int], None] | None = None


@dataclass
class ReportOptions:
    """What the loads report shows besides the results (Study rows, checked on reading).

    Attributes
    ----------
    hull_stations : list of str
        Station ids of the 2-D envelopes (None: three stations about the hub).
    hull_pairs : list of tuple of str
        Component pairs of the 2-D envelopes, e.g. ``[("Vy", "Mz")]``.
    hook_angle_justification : str
        Why the hook angle used holds (quoted on the Summary).
    previous_envelope_source : str
        Where the previous design envelope comes from.
    sfbm_workbook : bool
        Also write the SFBM of every case as a data workbook.
    nastran : bool
        Also write the load cases as Nastran bulk data.
    nastran_settings : dict
        Keywords of the Nastran writer (:mod:`slingloads.io.loads.nastran`): axes, offset,
        units, inertia relief...
    nastran_locations : dict
        Cell of each Nastran setting, by keyword (to locate an error the writer finds).
    """

    hull_stations: list | None = None
    hull_pairs: list = field(default_factory=lambda: [("Vy", "Mz")])
    hook_angle_justification: str = ""
    previous_envelope_source: str = ""
    sfbm_workbook: bool = False
    nastran: bool = False
    nastran_settings: dict = field(default_factory=dict)
    nastran_locations: dict = field(default_factory=dict)


def _now():
    return datetime.now().astimezone().isoformat(sep=" ", timespec="seconds")


@dataclass
class Source:
    """Where a study comes from, and how to locate an error its inputs cause.

    A study built in code has this plain source; a study read from a workbook has the
    workbook's (:class:`slingloads.io.study.WorkbookSource`), which puts an error an analysis
    raises at the workbook cell its value came from.

    Attributes
    ----------
    path : str
        The file read ("" when built in code).
    sha256 : str
        Digest of that file, hex ("" when built in code).
    input_files : list of pathlib.Path
        Every file read (the workbook and the CSV files it names): no output may replace one.
    warnings : list of str
        Implausible but possible inputs, each naming where it is.
    identification : dict
        Free fields printed on the report covers: ``project``, ``document number``,
        ``author``, ``checker`` (empty strings when not given).
    run_date : str
        When the study was read (local time with its UTC offset).
    """

    path: str = ""
    sha256: str = ""
    input_files: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    identification: dict = field(default_factory=dict)
    run_date: str = field(default_factory=_now)

    def locate(self, study, analysis, err, context=None):
        """The error to raise for ``err``, raised while analysis ``analysis`` of ``study``
        runs; here ``err`` itself (a workbook's source puts it at its cell).

        Parameters
        ----------
        study : Study
        analysis : str
            The analysis that raised ``err`` (a name of :data:`ANALYSES`).
        err : InputError
        context : object, optional
            What the analysis was doing (see :meth:`Study.located`).

        Returns
        -------
        InputError
        """
        return err


@dataclass
class Results:
    """The results of a study's analyses; None for an analysis not run.

    Attributes
    ----------
    loads : LoadsResult or None
        Every load case at every station (LIMIT loads, SI).
    loads_handoff : Handoff or None
        The cases the campaign's dynamics handed to the loads (when asked for).
    loads_hook_angle : HookAngleHandoff or None
        The lateral study's recommended design angle handed to the loads' lateral hook cases
        (when both run): the larger of it and the loads' own angle.
    lateral : LateralReport or None
        The lateral sweep, its critical case re-run, modes and the hook cases at its angle.
    chute_sizing : ChuteSizingReport or None
        Neutral area, line length and the swept areas' yaw runs.
    multibody : MultibodyReport or None
        Trim, linear model and manoeuvres of the towed system.
    campaign : CampaignReport or None
        The campaign's runs, selection and envelope.
    parachute_decision : ParachuteDecision or None
        The one parachute decision of the study (made by the sizing, with the campaign's
        selection when the campaign ran too): every report that mentions the parachute
        shows it.
    sizing_sweep : SizingSweep or None
        The 1-DOF sizing's yaw model, neutral area and sweep, computed ahead of the campaign
        when both run (the campaign then also runs the sizing's proposed area), and reused by
        the sizing (:func:`slingloads.runs.chute_sizing.sizing_sweep_of`).
    study : Study
        The study these are the results of.
    """

    loads: LoadsResult | None = None
    loads_handoff: Handoff | None = None
    loads_hook_angle: HookAngleHandoff | None = None
    lateral: LateralReport | None = None
    chute_sizing: ChuteSizingReport | None = None
    multibody: MultibodyReport | None = None
    campaign: CampaignReport | None = None
    parachute_decision: ParachuteDecision | None = None
    sizing_sweep: object = None
    #: The study these are the results of (set by :func:`run_study`).
    study: Study | None = field(default=None, repr=False, compare=False)

    def of(self, name):
        """The result of analysis ``name`` (None if not run).

        Parameters
        ----------
        name : str
            A name of :data:`ANALYSES`.

        Returns
        -------
        object or None
            Its field of this object (the types above).
        """
        return getattr(self, _field(name))

    def set(self, name, result):
        """Keep ``result`` as that of analysis ``name``.

        Parameters
        ----------
        name : str
            A name of :data:`ANALYSES`.
        result : object or None
            Its result (the type of its field above).
        """
        setattr(self, _field(name), result)

    def computed(self):
        """The analyses with a result, in the order of :data:`ANALYSES`.

        Returns
        -------
        tuple of str
        """
        return tuple(n for n in ANALYSES if self.of(n) is not None)

    def shortfalls(self):
        """What the analyses were asked for and could not compute, one line each: the
        multibody model without a trim (no linear modes, no stability verdict), no swept
        area stable under every gust, no campaign area stable everywhere (and so no dynamics'
        cases for the loads), no area meeting every criterion of the parachute decision.

        Returns
        -------
        list of str
            Empty when every analysis computed what it was asked for.
        """
        out = []
        for name in ("multibody", "chute sizing", "campaign"):
            result = self.of(name)
            if result is not None:
                from slingloads.runs.registry import RUNS  # loaded by the run that made it

                out += [line for line in RUNS[name]().shortfalls(result) if line not in out]
        if self.parachute_decision is not None:  # the study's one decision, said once
            out = [line for line in out if not line.startswith(DECISION_FINDING)]
            if not self.parachute_decision.found:
                out.append(f"{DECISION_FINDING} {self.parachute_decision.reason}")
        return out


@dataclass
class Study:
    """A study: the airframe, the inputs of each analysis, options, results.

    Attributes
    ----------
    name : str
        Printed on the reports.
    airframe : Airframe
        Mass items [kg, m], cut stations [m] and hardpoints [m] (SI, airframe axes).
    inputs : Inputs
        The inputs of each analysis asked for.
    asked : tuple of str
        The analyses the study asks for (its ``run <name>`` rows), in the order of
        :data:`ANALYSES`; :meth:`run` runs these.
    options : RunOptions
        How to execute the campaign.
    report : ReportOptions
        What the loads report shows besides the results.
    source : Source
        Where the study comes from (and how an error is located there).
    results : Results
        Filled in by :meth:`run` (and :func:`run_analysis`).
    """

    name: str
    airframe: Airframe
    inputs: Inputs = field(default_factory=Inputs)
    asked: tuple = ()
    options: RunOptions = field(default_factory=RunOptions)
    report: ReportOptions = field(default_factory=ReportOptions)
    source: Source = field(default_factory=Source)
    results: Results = field(default_factory=Results)

    @property
    def path(self):
        """The file the study was read from ("" when built in code)."""
        return self.source.path

    def require(self, name):
        """The inputs of analysis ``name``.

        Parameters
        ----------
        name : str
            A name of :data:`ANALYSES`.

        Returns
        -------
        object
            Its inputs (:class:`Inputs` lists the types).

        Raises
        ------
        InputError
            If the study does not ask for it (its inputs were not read).
        """
        inputs = self.inputs.of(name)
        if inputs is None:
            raise InputError(f"the workbook does not ask for the {TITLES[name]} (Study sheet: "
                             f"'run {name}' is no)", file=self.path or None, sheet="Study")
        return inputs

    @contextlib.contextmanager
    def located(self, analysis, context=None):
        """Locate an :class:`InputError` raised inside, by analysis ``analysis``, where its
        value came from (:meth:`Source.locate`).

        Parameters
        ----------
        analysis : str
            The analysis run inside the block (a name of :data:`ANALYSES`).
        context : object, optional
            What the analysis was doing, when that needs saying (the lateral study's
            critical case: its sweep).

        Returns
        -------
        context manager
            Raises the located :class:`InputError` in place of the one raised inside.
        """
        try:
            yield
        except InputError as err:
            raise self.source.locate(self, analysis, err, context) from None

    def run(self, only=None):
        """Run the analyses the study asks for (or ``only`` these), in order
        (:func:`compute_order`), each after those that feed it.

        Parameters
        ----------
        only : iterable of str, optional
            The analyses to run (names of :data:`ANALYSES`; default: those it asks for,
            :attr:`asked`).

        Returns
        -------
        Results
            Also kept as :attr:`results`.
        """
        return run_study(self, self.asked if only is None else only)


def run_one(study, name):
    """Run analysis ``name`` of ``study`` alone (its module's ``run(study) -> result``).

    Parameters
    ----------
    study : Study
    name : str
        A name of :data:`ANALYSES`.

    Returns
    -------
    object
        Its result (:class:`Results` lists the types).
    """
    if name not in ANALYSES:
        raise InputError(f"unknown analysis; valid names are {list(ANALYSES)}", name)
    from slingloads.runs.registry import RUNS  # the analyses load when one runs

    return RUNS[name]().run(study)


def run_analysis(study, name):
    """Run analysis ``name`` of ``study`` with what the analyses before it handed over (the
    campaign's dynamics to the loads, when the study asks for it; the lateral study's
    recommended design angle to the loads' lateral hook cases, when it ran), and keep its
    result in ``study.results``.

    Parameters
    ----------
    study : Study
    name : str
        A name of :data:`ANALYSES`.

    Returns
    -------
    object
        Its result (:class:`Results` lists the types).
    """
    if name == "loads":
        from slingloads.runs.loads import handoff, hook_angle_handoff

        study.results.loads_handoff = handoff(study, study.results.campaign)
        study.results.loads_hook_angle = hook_angle_handoff(study, study.results.lateral)
    result = run_one(study, name)
    study.results.set(name, result)
    return result


def run_study(study, names, *, before=None, after=None, run=run_analysis):
    """Run the analyses ``names`` of ``study`` in order (:func:`compute_order`).

    Parameters
    ----------
    study : Study
    names : iterable of str
    before, after : callable, optional
        Called as ``before(name)`` and ``after(name, result)`` around each analysis (the
        command line shows its progress and starts drawing the figures).
    run : callable, optional
        ``run(study, name) -> result`` (default :func:`run_analysis`).

    Returns
    -------
    Results
    """
    study.results.study = study
    study.results.sizing_sweep = None  # computed afresh by this run
    for name in compute_order(names):
        if before is not None:
            before(name)
        result = run(study, name)
        study.results.set(name, result)
        if after is not None:
            after(name, result)
    return study.results

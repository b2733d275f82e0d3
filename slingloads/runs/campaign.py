"""Run the multibody campaign of a study: its inputs, its result and :func:`run`."""

from __future__ import annotations

from dataclasses import dataclass

ANALYSIS = "campaign"
#: The context of an error reaching the study's own scheduler (:meth:`Study.located`).
SCHEDULER = "scheduler"


@dataclass(frozen=True, eq=False)
class CampaignInputs:
    """Everything the campaign of a workbook needs.

    Attributes
    ----------
    campaign : Campaign
    scheduler : str
        Dask scheduler address ('' for local execution).
    workers : int or None
        Local worker processes (None: automatic).
    timeout : float
        Scheduler time-out. [s]
    loads_from_dynamics : bool
    hook_angle_source : str
        'CS-29.865' or 'dynamics'.
    scheduler_cell : str
        Cell of 'campaign scheduler' on the Study sheet (errors reaching it are put there).
    """

    campaign: object
    scheduler: str
    workers: int | None
    timeout: float
    loads_from_dynamics: bool
    hook_angle_source: str
    scheduler_cell: str = "(default)"


@dataclass(frozen=True, eq=False)
class CampaignReport:
    """The campaign of one workbook and its results.

    Attributes
    ----------
    inputs : CampaignInputs
    result : CampaignResult
    cache : str
        Where the run cache is.
    """

    inputs: CampaignInputs
    result: object
    cache: str

    def to_frame(self):
        """Every run of the campaign, one row each: its factors, then its metrics (units in
        the headers; :attr:`~slingloads.analyses.campaign.CampaignResult.metrics`)."""
        return self.result.metrics


def run(study):
    """Run the campaign of a study, on the executor and with the run cache its options ask
    for.

    The execution options come from ``study.options`` (:class:`~slingloads.runs.study.
    RunOptions`: the command line's ``--scheduler``, ``--workers``, ``--cache``,
    ``--scheduler-timeout`` and progress bar), else from the campaign's inputs (its Study
    rows), else the defaults (local processes; the user's cache folder). What the run could
    not use (workers not started, cache entries or a cache location) is added to
    ``study.source.warnings``.

    Returns
    -------
    CampaignReport

    Raises
    ------
    InputError
        If the workbook does not ask for the campaign, the scheduler cannot be reached, or a
        run refuses its inputs.
    """
    from slingloads.analyses.campaign import make_executor, run_campaign
    from slingloads.runs.cache import RunCache, default_cache_dir

    inputs = study.require(ANALYSIS)
    options = study.options
    cache_dir = options.cache or default_cache_dir()
    scheduler = options.scheduler or inputs.scheduler
    workers = options.workers or inputs.workers
    timeout = options.timeout or inputs.timeout
    campaign = inputs.campaign
    total = campaign.size + (len(campaign.no_parachute.jobs()) if campaign.no_parachute else 0)
    with study.located(ANALYSIS):
        store = RunCache(cache_dir)
        # the study's own scheduler (not the command line's): errors at its Study cell
        with study.located(ANALYSIS, SCHEDULER if scheduler and not options.scheduler
                           else None):
            executor = make_executor(scheduler or None, workers, timeout, runs=total,
                                     settings=campaign.settings.as_dict())
        executor_warnings = list(executor.warnings)  # fewer workers than asked for
        result = run_campaign(campaign, executor=executor, store=store,
                              progress=options.progress)
    # workers not started, entries or a location the cache could not use
    study.source.warnings.extend([*executor_warnings, *store.warnings])
    return CampaignReport(inputs, result, str(cache_dir))

"""Run the multibody campaign of a study: its inputs, its result and :func:`compute`."""

from __future__ import annotations

import contextlib
from dataclasses import dataclass

from slingloads.errors import InputError
from slingloads.io.common.locate import at_cell

ANALYSIS = "campaign"


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

    inputs: object
    result: object
    cache: str


def compute(study):
    """Run the campaign read from a workbook (module notes).

    The execution options come from ``study.runtime`` (the command line: ``scheduler``,
    ``workers``, ``cache``, ``timeout``, ``progress``), else from the workbook. The result is
    also left in ``study.results["campaign"]`` for the loads that follow.

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

    inputs = study.inputs.get(ANALYSIS)
    if inputs is None:
        raise InputError("the workbook does not ask for the campaign (Study sheet: 'run "
                         "campaign' is no)", file=study.path, sheet="Study")
    runtime = getattr(study, "runtime", {}) or {}
    cache_dir = runtime.get("cache") or default_cache_dir()
    scheduler = runtime.get("scheduler") or inputs.scheduler
    workers = runtime.get("workers") or inputs.workers
    timeout = runtime.get("timeout") or inputs.timeout
    campaign = inputs.campaign
    total = campaign.size + (len(campaign.no_parachute.jobs()) if campaign.no_parachute else 0)
    store = RunCache(cache_dir)
    written = getattr(study, "written", {}).get("campaign scheduler", (scheduler, None))
    where = (at_cell(study.path, "Study", inputs.scheduler_cell, written[0])
             if scheduler and not runtime.get("scheduler") else contextlib.nullcontext())
    with where:
        executor = make_executor(scheduler or None, workers, timeout, runs=total)
    result = run_campaign(campaign, executor=executor, store=store,
                          progress=runtime.get("progress"))
    report = CampaignReport(inputs, result, str(cache_dir))
    if hasattr(study, "results"):
        study.results[ANALYSIS] = report
    return report

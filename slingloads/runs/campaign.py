"""Run the multibody campaign of a study: its inputs, its result and :func:`run`."""

from __future__ import annotations

import math
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
        Local worker processes (None: automatic). [count]
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
    sizing_factor : float or None
        The area factor added to the matrix from the 1-DOF sizing's proposed area (None: none
        added). [-]
    """

    inputs: CampaignInputs
    result: object
    cache: str
    sizing_factor: float | None = None

    def to_frame(self):
        """Every run of the campaign, one row each: its factors, then its metrics (units in
        the headers; :attr:`~slingloads.analyses.campaign.CampaignResult.metrics`).

        Returns
        -------
        pandas.DataFrame
            One row per run, units in the column labels.
        """
        return self.result.metrics


def run(study):
    """Run the campaign of a study, on the executor and with the run cache its options ask
    for.

    The execution options come from ``study.options`` (:class:`~slingloads.runs.study.
    RunOptions`: the command line's ``--scheduler``, ``--workers``, ``--cache``,
    ``--scheduler-timeout`` and progress bar), else from the campaign's inputs (its Study
    rows), else the defaults (local processes; the user's cache folder). What the run could
    not use (workers not started, cache entries or a cache location) is added to
    ``study.source.warnings``; the campaign's parachute decision is kept in
    ``study.results.parachute_decision`` (the sizing, when it runs after, replaces it with
    the decision of both models).

    Parameters
    ----------
    study : Study
        The study (:class:`~slingloads.runs.study.Study`) with campaign inputs.

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
    campaign, added = _with_sizing_area(study, inputs.campaign)
    total = campaign.size + (campaign.no_parachute.size if campaign.no_parachute else 0)
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
    if result.decision is not None:  # the sizing, run after, decides with both models
        study.results.parachute_decision = result.decision
    if added is not None:
        from dataclasses import replace

        inputs = replace(inputs, campaign=campaign)
    return CampaignReport(inputs, result, str(cache_dir), added)


def _with_sizing_area(study, campaign):
    """The campaign with the 1-DOF sizing's proposed area among its area factors, when the
    study runs the sizing too (the sizing's sweep is computed first, and kept for it), so that
    the parachute decision has a multibody verdict at that area; and the factor added (None
    when the study has no sizing, the sizing proposes no area, the factor is already in the
    matrix, or the matrix is listed row by row)."""
    from dataclasses import replace

    import numpy as np

    from slingloads.runs.chute_sizing import sizing_sweep_of

    if study.inputs.chute_sizing is None or campaign.rows is not None:
        return campaign, None
    area = sizing_sweep_of(study).proposed_area
    if not (math.isfinite(area) and area > 0):
        return campaign, None
    factor = area / campaign.neutral.area
    factors = tuple(float(f) for f in campaign.factors.area_factors)
    if np.any(np.isclose(factors, factor, rtol=1e-9)):
        return campaign, None
    grown = replace(campaign.factors, area_factors=tuple(sorted((*factors, factor))))
    return replace(campaign, factors=grown), factor


def shortfalls(report):
    """The campaign's findings that leave a result asked for without a value, one line each
    (``slingloads`` then exits 3 with the reports written): no parachute area stable in every
    condition, and then no dynamics' cases for the loads; no area meeting every criterion of
    the parachute decision.

    Parameters
    ----------
    report : CampaignReport

    Returns
    -------
    list of str
    """
    r = report.result
    out = []
    if not math.isfinite(r.selection.smallest_stable):
        out.append("campaign: no parachute area of the matrix is stable in every condition "
                   "(sheet Selection)")
    if r.envelope is None and report.inputs.loads_from_dynamics:
        out.append("campaign: no area chosen, so the loads keep their hand-entered cases only "
                   "(no cases from the dynamics)")
    if r.decision is not None and not r.decision.found:
        out.append(f"parachute decision: {r.decision.reason}")
    return out

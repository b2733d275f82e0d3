"""Run the structural loads analysis of a study (:func:`compute`), with the cases the
campaign's dynamics reached when the study asks for them."""

from __future__ import annotations

import numpy as np

from slingloads.errors import InputError
from slingloads.io.common.workbook import located


def compute(study):
    """Run the loads analysis read from a workbook.

    With the campaign's result in ``study.results`` (``slingloads run`` with ``run campaign``
    and ``campaign loads from dynamics``), the cases the dynamics reached are added
    (:func:`slingloads.analyses.campaign.loads_from_dynamics`) and the hand-off is kept in
    ``study.results["loads handoff"]`` for the report.

    Parameters
    ----------
    study : WorkbookStudy
        With ``study.loads`` (:class:`~slingloads.analyses.loads.LoadsStudy`).

    Returns
    -------
    LoadsResult

    Raises
    ------
    InputError
        If the workbook does not ask for the loads analysis.
    """
    if study.loads is None:
        raise InputError("the workbook does not ask for the loads analysis (Study sheet: "
                         "'run loads' is no)", file=study.path, sheet="Study")
    results = getattr(study, "results", {})
    campaign = results.get("campaign")
    if campaign is None or not campaign.inputs.loads_from_dynamics:
        return _finite(study.loads.run(), study)
    if campaign.result.envelope is None:
        raise InputError("the loads are to take the dynamics' cases, but no parachute area of "
                         "the campaign is stable in every condition and none was chosen "
                         "('campaign chosen area factor'); choose one or set 'campaign loads "
                         "from dynamics' to no", file=study.path, sheet="Study")
    from slingloads.analyses.campaign import loads_from_dynamics

    with located(study.path, "Study"):
        handoff = loads_from_dynamics(study.loads, campaign.result.envelope,
                                      campaign.inputs.hook_angle_source)
    results["loads handoff"] = handoff
    return _finite(handoff.study.run(), study)


def _finite(result, study):
    """``result``, refused if its loads are not finite numbers."""
    if not np.all(np.isfinite(result.loads)):
        raise InputError("the loads are not finite numbers (an input far out of scale?): check "
                         "the magnitudes and units of the MassItems, FuselageAero and Study "
                         "values", file=study.path)
    return result

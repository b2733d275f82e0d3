"""Run the structural loads analysis of a study (:func:`run`), with the cases the campaign's
dynamics reached when the study asks for them (:func:`handoff`)."""

from __future__ import annotations

import numpy as np

from slingloads.errors import InputError

ANALYSIS = "loads"
#: The context of an error of the campaign's hand-off to the loads (:meth:`Study.located`):
#: it comes from the Study rows 'campaign ...'.
HANDOFF = "handoff"


def handoff(study, campaign):
    """The campaign's hand-off to the loads: the study's load cases with those the dynamics
    reached added (:func:`slingloads.analyses.campaign.loads_from_dynamics`), when the study
    asks for them ('campaign loads from dynamics').

    Parameters
    ----------
    study : Study
        With ``study.inputs.loads``.
    campaign : CampaignReport or None
        The campaign's result (None: no campaign run).

    Returns
    -------
    Handoff or None
        None when the loads take no case from the dynamics.

    Raises
    ------
    InputError
        If the loads are to take the dynamics' cases but the campaign found no parachute
        area stable in every condition and none was chosen.
    """
    if campaign is None or not campaign.inputs.loads_from_dynamics:
        return None
    loads = study.require(ANALYSIS)
    with study.located(ANALYSIS, HANDOFF):
        if campaign.result.envelope is None:
            raise InputError("the loads are to take the dynamics' cases, but no parachute "
                             "area of the campaign is stable in every condition and none was "
                             "chosen ('campaign chosen area factor'); choose one or set "
                             "'campaign loads from dynamics' to no", sheet="Study")
        from slingloads.analyses.campaign import loads_from_dynamics

        return loads_from_dynamics(loads, campaign.result.envelope,
                                   campaign.inputs.hook_angle_source)


def run(study):
    """Run the loads analysis of a study: its load cases, or those of the campaign's hand-off
    when there is one (``study.results.loads_handoff``, set by
    :func:`slingloads.runs.study.run_analysis`).

    Parameters
    ----------
    study : Study
        With ``study.inputs.loads`` (:class:`~slingloads.analyses.loads.LoadsStudy`).

    Returns
    -------
    LoadsResult

    Raises
    ------
    InputError
        If the study does not ask for the loads analysis, or its loads are not finite.
    """
    loads = study.require(ANALYSIS)
    given = study.results.loads_handoff
    with study.located(ANALYSIS):
        return _finite((loads if given is None else given.study).run())


def _finite(result):
    """``result``, refused if its loads are not finite numbers."""
    if not np.all(np.isfinite(result.loads)):
        raise InputError("the loads are not finite numbers (an input far out of scale?): check "
                         "the magnitudes and units of the MassItems, FuselageAero and Study "
                         "values")
    return result

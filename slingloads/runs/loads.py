"""Run the structural loads analysis of a study (:func:`run`), with the cases the campaign's
dynamics reached when the study asks for them (:func:`handoff`) and the lateral hook cases at
the lateral study's recommended design angle when that is larger (:func:`hook_angle_handoff`)."""

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
        None when the loads take no case from the dynamics, or when the campaign found no
        parachute area stable in every condition and none was chosen (a finding of the
        campaign, not an input error: the loads keep their hand-entered cases and the
        campaign's shortfalls say why, exit 3).

    Raises
    ------
    InputError
        If the dynamics' cases cannot be added to the study's (located at the Study rows
        'campaign ...').
    """
    if campaign is None or not campaign.inputs.loads_from_dynamics:
        return None
    if campaign.result.envelope is None:
        return None
    loads = study.require(ANALYSIS)
    with study.located(ANALYSIS, HANDOFF):
        from slingloads.analyses.campaign import loads_from_dynamics

        return loads_from_dynamics(loads, campaign.result.envelope,
                                   campaign.inputs.hook_angle_source)


def hook_angle_handoff(study, lateral):
    """The lateral study's hand-off to the loads: the loads' lateral hook cases at
    max(the loads' own lateral angle, the lateral study's recommended design angle)
    (:func:`slingloads.analyses.hook_angle.lateral_hook_handoff`). The loads' own angle is the
    Study's, or the campaign hand-off's (``study.results.loads_handoff``) when that raised it
    (its source is named "campaign hand-off" only then).

    Parameters
    ----------
    study : Study
        With ``study.inputs.loads``.
    lateral : LateralReport or None
        The lateral study's result (None: not run).

    Returns
    -------
    HookAngleHandoff or None
        None when the lateral study did not run.
    """
    if lateral is None:
        return None
    loads = study.require(ANALYSIS)
    given = study.results.loads_handoff
    base = loads if given is None else given.study
    from slingloads.analyses.hook_angle import lateral_hook_handoff

    why = "" if np.isfinite(lateral.recommended_angle) else lateral.study.verdict()
    own = study.require(ANALYSIS).hook.lateral
    # the campaign hand-off keeps the Study's angle unless the dynamics reach further: then
    # the angle is the campaign's, else still the Study's (the Dynamics sheet says "kept")
    source = ("Study" if given is None or np.isclose(base.hook.lateral, own, rtol=1e-12)
              else "campaign hand-off")
    return lateral_hook_handoff(base, lateral.recommended_angle, why, source)


def loads_study(study):
    """The loads study that :func:`run` runs: the lateral hook-angle hand-off's when there is
    one, else the campaign hand-off's, else the study's own.

    Parameters
    ----------
    study : Study
        The study (:class:`~slingloads.runs.study.Study`).

    Returns
    -------
    LoadsStudy
        The loads study to run (:class:`~slingloads.analyses.loads.LoadsStudy`).
    """
    results = study.results
    if results.loads_hook_angle is not None:
        return results.loads_hook_angle.study
    if results.loads_handoff is not None:
        return results.loads_handoff.study
    return study.require(ANALYSIS)


def run(study):
    """Run the loads analysis of a study: its load cases, with the hand-offs of the campaign
    (``study.results.loads_handoff``) and of the lateral study
    (``study.results.loads_hook_angle``) when there are (set by
    :func:`slingloads.runs.study.run_analysis`; :func:`loads_study`).

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
    study.require(ANALYSIS)
    with study.located(ANALYSIS):
        return _finite(with_towed_system(study, loads_study(study)).run())


def with_towed_system(study, loads):
    """``loads`` with the towed system whose trim gives its towed cases' attitude: the
    multibody model's when the study has one flying the loads' parachute (the same area, or
    neither has one), so that the loads, the sizing and the multibody model fly one attitude
    per airspeed; otherwise the loads assemble one from their own parts (and say so).

    Parameters
    ----------
    study : Study
    loads : LoadsStudy

    Returns
    -------
    LoadsStudy
    """
    from dataclasses import replace

    system = towed_system_of(study)
    if system is None or loads.towed_system is not None:
        return loads
    chute = system.parachute
    same = ((chute is None and loads.parachute is None)
            or (chute is not None and loads.parachute is not None
                and np.isclose(chute.parachute.area, loads.parachute.area, rtol=1e-12)))
    if not same:
        return replace(loads, towed_source="a system assembled from the loads' parts (the "
                       "multibody model flies another parachute area)")
    return replace(loads, towed_system=system, towed_source="the multibody model's system")


def towed_system_of(study):
    """The multibody model's towed system of the study, or None without one.

    Parameters
    ----------
    study : Study
        The study (:class:`~slingloads.runs.study.Study`).

    Returns
    -------
    SlingSystem or None
        The towed system (:class:`~slingloads.models.multibody.system.SlingSystem`).
    """
    inputs = study.inputs.multibody
    return None if inputs is None else inputs.system


def _finite(result):
    """``result``, refused if its loads are not finite numbers."""
    if not np.all(np.isfinite(result.loads)):
        raise InputError("the loads are not finite numbers (an input far out of scale?): check "
                         "the magnitudes and units of the MassItems, FuselageAero and Study "
                         "values")
    return result

"""Run the parachute sizing of a study: its inputs, its result and :func:`run`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.chute_sizing import (
    MetricSettings,
    line_length,
    neutral_area,
    run_yaw,
    sizing_sweep,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.yaw_dynamics import YawModel

ANALYSIS = "chute sizing"


@dataclass(frozen=True)
class ChuteSizingInputs:
    """Everything the parachute sizing needs, in SI.

    Attributes
    ----------
    model : YawModel
        Fuselage, fin, hardpoints, yaw inertia about the suspension axis, condition, and a
        parachute template (its CD and wake ratio; the area is swept).
    fit_range : tuple of float
        Sideslip range of the linearisation. [rad]
    wake : TabulatedWake or BluffBodyWake
    target : float
        Dynamic-pressure ratio the canopy must see. [-]
    cable_length : float or None
        Carrier cable; None skips the check. [m]
    margin : float
        Required excess of the cable over the line. [-]
    gusts : tuple
        Gust shapes of the sweep.
    settings : SolverSettings
    metrics : MetricSettings
        With the sideslip limit past which no run is called stable.
    factors : ndarray
        Swept areas over the neutral area. [-]
    recommended_factor : float
        Recommended area over the neutral area. [-]
    integrator : str
        ``"dopri5"``, ``"rk4"`` or ``"solve_ivp"`` (see
        :func:`slingloads.analyses.chute_sizing.run_yaw`).
    inertia_source : str
        ``"mass items"`` or ``"parameter"``.
    study_area : float
        The Study's 'parachute area' (used by the loads; 0 if none). [m^2]
    study_line : float
        The Study's 'parachute line length'. [m]
    yaw_axis : str
        The axis of the yaw model's moments, inertia and weight
        (:data:`slingloads.models.yaw_dynamics.YAW_AXES`).
    """

    model: YawModel
    fit_range: tuple
    wake: object
    target: float
    cable_length: float | None
    margin: float
    gusts: tuple
    settings: SolverSettings
    metrics: MetricSettings
    factors: np.ndarray
    recommended_factor: float
    integrator: str
    inertia_source: str
    study_area: float
    study_line: float
    yaw_axis: str = "suspension"


@dataclass(frozen=True)
class ChuteSizingReport:
    """Results of the parachute sizing of one workbook.

    Attributes
    ----------
    inputs : ChuteSizingInputs
    static : NeutralAreaResult
    line : LineLengthResult
    sweep : SweepResult or None
        None when fuselage and fin are already statically stable (no positive neutral area).
    recommended_area : float
        The smallest swept area at which every gust run meets the criterion (NaN when none
        does; 0 when already stable). [m^2]
    study_area_runs : YawRuns or None
        Every gust at the Study's 'parachute area', the one the loads use (None if it is 0).
    decision : ParachuteDecision or None
        The parachute decision (:mod:`slingloads.analyses.parachute_decision`), with the
        campaign's selection when the campaign ran in the same study.
    axes_angle : float
        Angle between the yaw model's axis (moments, inertia and weight all about it) and
        airframe z. [rad]
    towed : TowedAttitude or None
        The towed trim at the sizing airspeed (None without a towed system).
    axis_text : str
        The yaw model's axis in words (:func:`slingloads.analyses.towed_attitude.
        yaw_model_about`).
    """

    inputs: ChuteSizingInputs
    static: object
    line: object
    sweep: object
    recommended_area: float
    study_area_runs: object = None
    decision: object = None
    axes_angle: float = float("nan")
    towed: object = None
    axis_text: str = ""

    @property
    def study_area_peak_sideslip(self):
        """Largest |sideslip| of the gusts at the Study's 'parachute area', and the gust
        that gives it (NaN, "" without that area). [rad], str"""
        if self.study_area_runs is None:
            return float("nan"), ""
        frame = self.study_area_runs.to_frame()
        i = int(np.argmax(frame["peak beta [deg]"].to_numpy()))
        return float(np.radians(frame["peak beta [deg]"].iloc[i])), str(frame["gust"].iloc[i])

    def to_frame(self):
        """Every run of the area sweep, one row each (units in the headers); empty when
        fuselage and fin are already stable (no sweep).

        Returns
        -------
        pandas.DataFrame
            One row per run (area x gust), units in the column labels (m^2, deg, s).
        """
        return self.sweep.to_frame() if self.sweep is not None else pd.DataFrame()

    def stability_by_area(self):
        """One row per swept area: all gusts stable?, worst peak sideslip and yaw.

        Returns
        -------
        pandas.DataFrame
            One row per swept area [m^2]: stable under every gust, largest peak sideslip and
            yaw [deg].
        """
        if self.sweep is None:
            return pd.DataFrame()
        return self.sweep.by_area()

    @property
    def smallest_stable_area(self):
        """Smallest swept area at which every gust run is stable (NaN if none). [m^2]"""
        return self.sweep.smallest_stable_area if self.sweep is not None else float("nan")

    def history_runs(self):
        """Indices of the runs at the smallest, recommended and largest swept areas.

        Returns
        -------
        list of int
            Indices (0-based, sorted) of the runs at the swept areas nearest the smallest,
            the recommended and the largest factor. [-]
        """
        if self.sweep is None:
            return []
        ratio = self.sweep.runs.areas / self.static.area
        f = self.inputs.factors
        chosen = []
        recommended = (self.recommended_area / self.static.area
                       if np.isfinite(self.recommended_area) else self.inputs.recommended_factor)
        for target in (f.min(), recommended, f.max()):
            nearest = ratio[np.argmin(np.abs(ratio - target))]
            chosen += list(np.nonzero(np.isclose(ratio, nearest))[0])
        return sorted(set(chosen))


def run(study):
    """Run the parachute sizing of a study.

    Parameters
    ----------
    study : Study
        With ``study.inputs.chute_sizing`` (:class:`ChuteSizingInputs`).

    Returns
    -------
    ChuteSizingReport

    Raises
    ------
    InputError
        If the study does not ask for the sizing, or the analysis refuses its inputs
        (located where they came from: :meth:`Study.located`; a yaw trim that cannot be found
        has ``field = "trim"``).
    """
    inputs = study.require(ANALYSIS)
    core = sizing_sweep_of(study)
    inputs, static, sweep, towed, axis_text = (core.inputs, core.static, core.sweep,
                                               core.towed, core.axis_text)
    model = inputs.model
    with study.located(ANALYSIS):
        line = line_length(inputs.wake, inputs.target, inputs.cable_length, inputs.margin,
                           flown_line=inputs.study_line)
        at_study = None
        if inputs.study_area > 0:
            at_study = run_yaw(inputs.model, inputs.study_area, inputs.gusts, inputs.settings,
                               inputs.fit_range, inputs.metrics, inputs.integrator)
        recommended = sweep.smallest_stable_area if sweep is not None else 0.0
        decision = (_decision(study, inputs, static, sweep, axis_text) if sweep is not None
                    else None)
    return ChuteSizingReport(inputs, static, line, sweep, float(recommended), at_study,
                             decision, model.axis_tilt, towed, axis_text)


@dataclass(frozen=True, eq=False)
class SizingSweep:
    """The 1-DOF sizing's model about its yaw axis, neutral area and area sweep: computed once
    per study (:func:`sizing_sweep_of`), ahead of the campaign when both run, so that the
    campaign also runs the area the sizing proposes.

    Attributes
    ----------
    inputs : ChuteSizingInputs
        With the yaw model about its axis at the towed trim.
    static : NeutralAreaResult
    sweep : SweepResult or None
        None when fuselage and fin are already stable.
    towed : TowedAttitude or None
    axis_text : str
    given : ChuteSizingInputs
        The inputs as the study gave them (the result is reused while they are the study's).
    """

    inputs: ChuteSizingInputs
    static: object
    sweep: object
    towed: object
    axis_text: str
    given: object = None

    @property
    def proposed_area(self):
        """The 1-DOF proposal: the smallest swept area stable under every gust (NaN when
        none is; 0 when already stable). [m^2]"""
        return float(self.sweep.smallest_stable_area) if self.sweep is not None else 0.0


def sizing_sweep_of(study):
    """The study's :class:`SizingSweep`, computed on the first call and kept in
    ``study.results.sizing_sweep``.

    Parameters
    ----------
    study : Study
        With ``study.inputs.chute_sizing``.

    Returns
    -------
    SizingSweep
    """
    from dataclasses import replace

    from slingloads.analyses.towed_attitude import towed_attitude, yaw_model_about

    inputs = study.require(ANALYSIS)
    kept = study.results.sizing_sweep
    if kept is not None and kept.given is inputs:
        return kept
    given = inputs
    towed = body = None
    system = _towed_system(study)
    if system is not None:
        # the attitude the loads' towed cases and the multibody fly
        towed = towed_attitude(system, inputs.model.condition.eas)
        body = system.body
    elif study.airframe is not None and study.airframe.mass_items is not None:
        from slingloads.models.multibody.rigid_body import RigidBody

        body = RigidBody.from_mass_items(study.airframe.mass_items)
    with study.located(ANALYSIS):
        model, axis_text = yaw_model_about(
            inputs.model, inputs.yaw_axis, towed, body,
            inputs.model.yaw_inertia if inputs.inertia_source == "parameter" else None)
        inputs = replace(inputs, model=model)
        static = neutral_area(inputs.model, inputs.fit_range)
        sweep = None
        if not static.already_stable:
            sweep = sizing_sweep(inputs.model, inputs.factors, inputs.gusts, inputs.settings,
                                 inputs.fit_range, metrics=inputs.metrics, static=static,
                                 integrator=inputs.integrator)
    core = SizingSweep(inputs, static, sweep, towed, axis_text, given)
    study.results.sizing_sweep = core
    return core


def _towed_system(study):
    """The towed system whose trim gives the sizing's angle of attack: the multibody model's,
    else one assembled from the loads' parts; None when the study has neither."""
    multibody = study.inputs.multibody
    if multibody is not None:
        return multibody.system
    loads = study.inputs.loads
    if loads is None or loads.fuselage is None:
        return None
    from slingloads.analyses.towed_attitude import towed_system

    return towed_system(loads.airframe, loads.fuselage, loads.fin, loads.parachute,
                        loads.flight.eas, loads.flight.density_altitude)[0]


def shortfalls(result):
    """The sizing's findings that leave a result asked for without a value, one line each
    (``slingloads`` then exits 3 with the reports written): no swept area stable under every
    gust, no area meeting every criterion of the parachute decision.

    Parameters
    ----------
    result : ChuteSizingReport

    Returns
    -------
    list of str
    """
    out = []
    if result.sweep is not None and not np.isfinite(result.recommended_area):
        out.append("chute sizing: no swept area is stable under every gust (sheet Sweep): no "
                   "area recommended")
    if result.decision is not None and not result.decision.found:
        out.append(f"parachute decision: {result.decision.reason}")
    return out


def _decision(study, inputs, static, sweep, axis_text=""):
    """The parachute decision: the sizing's, with the campaign's selection when the campaign
    was computed in the same study (it is computed first, :data:`slingloads.runs.study.
    FEEDS`); kept in ``study.results.parachute_decision`` for every report that mentions the
    parachute."""
    from slingloads.analyses.campaign.campaign import campaign_decision
    from slingloads.analyses.parachute_decision import decide

    def one_dof(area):
        return run_yaw(inputs.model, area, inputs.gusts, inputs.settings, inputs.fit_range,
                       inputs.metrics, inputs.integrator).to_frame()

    campaign = study.results.campaign
    axis = f"'{inputs.yaw_axis}' ({axis_text})"
    speed = inputs.model.condition.eas
    if campaign is not None:
        r = campaign.result
        decision = campaign_decision(r.campaign, r.metrics, r.selection, sweep, static,
                                     one_dof, inputs.study_area, axis, speed)
    else:
        decision = decide(static, sweep, one_dof=one_dof, study_area=inputs.study_area,
                          yaw_axis=axis, airspeed=speed)
    study.results.parachute_decision = decision
    return decision


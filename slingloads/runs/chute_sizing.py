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
        ``recommended_factor`` x neutral area (0 when already stable). [m^2]
    study_area_runs : YawRuns or None
        Every gust at the Study's 'parachute area', the one the loads use (None if it is 0).
    """

    inputs: ChuteSizingInputs
    static: object
    line: object
    sweep: object
    recommended_area: float
    study_area_runs: object = None

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
        fuselage and fin are already stable (no sweep)."""
        return self.sweep.to_frame() if self.sweep is not None else pd.DataFrame()

    def stability_by_area(self):
        """One row per swept area: all gusts stable?, worst peak sideslip and yaw."""
        if self.sweep is None:
            return pd.DataFrame()
        frame = self.sweep.to_frame()
        grouped = frame.groupby("area [m^2]", sort=True)
        return pd.DataFrame({
            "area / neutral area [-]": grouped["area / neutral area [-]"].first(),
            "all gusts stable": grouped["verdict"].agg(lambda v: bool((v == "stable").all())),
            "worst peak beta [deg]": grouped["peak beta [deg]"].max(),
            "worst peak psi [deg]": grouped["peak psi [deg]"].max(),
        }).reset_index()

    @property
    def smallest_stable_area(self):
        """Smallest swept area at which every gust run is stable (NaN if none). [m^2]"""
        table = self.stability_by_area()
        ok = table[table["all gusts stable"]] if len(table) else table
        return float(ok["area [m^2]"].min()) if len(ok) else float("nan")

    def history_runs(self):
        """Indices of the runs at the smallest, recommended and largest swept areas."""
        if self.sweep is None:
            return []
        ratio = self.sweep.runs.areas / self.static.area
        f = self.inputs.factors
        chosen = []
        for target in (f.min(), self.inputs.recommended_factor, f.max()):
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
    with study.located(ANALYSIS):
        static = neutral_area(inputs.model, inputs.fit_range)
        line = line_length(inputs.wake, inputs.target, inputs.cable_length, inputs.margin)
        sweep = None
        if not static.already_stable:
            sweep = sizing_sweep(inputs.model, inputs.factors, inputs.gusts, inputs.settings,
                                 inputs.fit_range, metrics=inputs.metrics, static=static,
                                 integrator=inputs.integrator)
        at_study = None
        if inputs.study_area > 0:
            at_study = run_yaw(inputs.model, inputs.study_area, inputs.gusts, inputs.settings,
                               inputs.fit_range, inputs.metrics, inputs.integrator)
    recommended = inputs.recommended_factor * static.area if sweep is not None else 0.0
    return ChuteSizingReport(inputs, static, line, sweep, float(recommended), at_study)


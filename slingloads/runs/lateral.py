"""Run the lateral-step pendulum study of a study: its inputs, its result and :func:`run`.

:func:`run` runs the study (every motion x rope length x body in one vectorised RK4
sweep), re-runs the critical case with :func:`scipy.integrate.solve_ivp` for its time
histories, computes the natural modes about the hanging equilibrium, and, the link to the
loads, re-runs the CS-29.865 hook cases at the recommended angle and at the 30 deg of
CS-29.865 (:func:`slingloads.analyses.hook_angle.hook_angle_comparison`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.hook_angle import HookAngleComparison, hook_angle_comparison
from slingloads.analyses.lateral import CarrierLimits, ParameterRanges, lateral_study
from slingloads.analyses.lateral_damping import LateralDamping
from slingloads.models.integration import SolverSettings

ANALYSIS = "lateral"


@dataclass(frozen=True)
class LateralInputs:
    """Everything the lateral study needs, in SI.

    Attributes
    ----------
    bodies : tuple of SlungBody
    body_source : str
        ``"LateralBodies"`` or ``"MassItems"``.
    rope_lengths : tuple of float
        [m]
    motions : tuple
        Carrier motions (:mod:`slingloads.models.carrier_motion`).
    motion_ids : tuple of str
        The LateralMotions ids, one per motion.
    margin : float
        Design-angle margin, >= 1. [-]
    cable_ea : float or None
        None: rigid rope. [N]
    damping : LateralDamping
        From the parameters or derived from the aerodynamic tables.
    ranges : ParameterRanges
        Uncertainty of roll inertia, CG below hub and rope length.
    solver : SolverSettings
        Run length ``t_end`` and RK4 ``step`` of the sweep (None: automatic), and the
        solve_ivp settings of the critical case's time-history re-run.
    loads : LoadsStudy or None
        The loads study of the workbook (for the hook cases at the recommended angle).
    limits : CarrierLimits or None
        What the carrier can fly, and its mass (the frozen-carrier check); None: the
        defaults of :class:`~slingloads.analyses.lateral.CarrierLimits`.
    """

    bodies: tuple
    body_source: str
    rope_lengths: tuple
    motions: tuple
    motion_ids: tuple
    margin: float
    cable_ea: float | None
    damping: LateralDamping
    ranges: ParameterRanges
    solver: SolverSettings
    loads: object
    limits: CarrierLimits | None = None


@dataclass(frozen=True, eq=False)
class LateralReport:
    """Results of the lateral study of one workbook.

    Attributes
    ----------
    inputs : LateralInputs
    study : LateralStudy
    critical_run : LateralRun
        The critical case re-run with solve_ivp (time histories).
    modes : pandas.DataFrame
        Natural modes of every body x rope length (SI).
    comparison : HookAngleComparison or None
        None when the recommended angle is 90 deg or more (no hook cone can be built).
    """

    inputs: LateralInputs
    study: object
    critical_run: object
    modes: pd.DataFrame
    comparison: HookAngleComparison | None

    @property
    def recommended_angle(self):
        """[rad]"""
        return self.study.recommended_angle

    def to_frame(self):
        """Every case of the sweep, one row each: its definition and its metrics (SI, units
        in the headers; :meth:`~slingloads.analyses.lateral.LateralStudy.to_frame`).

        Returns
        -------
        pandas.DataFrame
            One row per case, units in the column labels (kg, kg m^2, m, s, deg, -).
        """
        return self.study.to_frame()

    def motion_id(self, index):
        """LateralMotions id of case ``index`` (0-based).

        Parameters
        ----------
        index : int
            A case of the sweep, 0-based. [-]

        Returns
        -------
        str
            The id of its carrier motion on the LateralMotions sheet.
        """
        n = len(self.inputs.motions)
        return self.inputs.motion_ids[index % n]


def run(study):
    """Run the lateral study of a study.

    Parameters
    ----------
    study : Study
        With ``study.inputs.lateral`` (:class:`LateralInputs`).

    Returns
    -------
    LateralReport

    Raises
    ------
    InputError
        If the study does not ask for the lateral study, or the analysis refuses its
        inputs (located where they came from: :meth:`Study.located`; an error of the
        critical case's re-run with the sweep as its context).
    """
    inputs = study.require(ANALYSIS)
    with study.located(ANALYSIS):
        result = lateral_study(inputs.bodies, inputs.rope_lengths, inputs.motions,
                               margin=inputs.margin, cable_ea=inputs.cable_ea,
                               damping=inputs.damping, ranges=inputs.ranges,
                               hook_load_factor=inputs.loads.hook.nz, solver=inputs.solver,
                               limits=inputs.limits or CarrierLimits())
        with study.located(ANALYSIS, result):  # too stiff a case: at its rope length
            run = result.run_case()
        comparison = None
        if result.recommended_angle < np.pi / 2:
            comparison = hook_angle_comparison(inputs.loads, result.recommended_angle)
    return LateralReport(inputs, result, run, _modes(result), comparison)


def _modes(result):
    """Natural modes of the nominal pendulums (every body x rope length)."""
    frames, seen = [], set()
    for p, nominal in zip(result.pendulums, result.nominal, strict=True):
        key = id(p)
        if not nominal:
            continue
        if key in seen:
            continue
        seen.add(key)
        frame = p.linear_modes().to_frame()
        frame.insert(0, "body", p.body.name)
        frame.insert(1, "rope length [m]", p.rope_length)
        frames.append(frame)
    return pd.concat(frames, ignore_index=True)

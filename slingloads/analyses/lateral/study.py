"""The design-angle study: the grid of cases, and the carrier motions it sweeps.

:func:`lateral_study` builds every body x rope length x carrier motion over the stated
:class:`~slingloads.analyses.lateral.ranges.ParameterRanges`, runs them together
(:func:`~slingloads.analyses.lateral.batch.sweep`) and returns the
:class:`~slingloads.analyses.lateral.result.LateralStudy`; :func:`acceleration_sweep` makes a
grid of carrier motions by peak acceleration and duration. The paper's rope lengths and a
default grid of accelerations and durations are given.

References
----------
.. [1] EASA CS-29, CS 29.865 "External loads"; 14 CFR 29.865(a).
"""

from __future__ import annotations

import itertools

import numpy as np

from slingloads.analyses.lateral.batch import sweep
from slingloads.analyses.lateral.ranges import ParameterRanges
from slingloads.analyses.lateral.result import REGULATORY_ANGLE, LateralStudy
from slingloads.analyses.lateral.simulation import default_end_time
from slingloads.analyses.lateral_damping import LateralDamping
from slingloads.constants import FOOT, G0
from slingloads.errors import InputError
from slingloads.models.carrier_motion import (
    MOTION_ALIASES,
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
)
from slingloads.models.integration import solver_settings
from slingloads.models.pendulum import LateralPendulum, SlungBody

#: The paper's rope lengths, 18, 60 and 100 ft. [m]
PAPER_ROPE_LENGTHS = tuple(ft * FOOT for ft in (18.0, 60.0, 100.0))
#: A default sweep of carrier peak accelerations, 0.1 to 0.5 g. [m/s^2]
DEFAULT_ACCELERATIONS = tuple(n * G0 for n in (0.1, 0.2, 0.3, 0.4, 0.5))
#: A default sweep of motion durations. [s]
DEFAULT_DURATIONS = (0.5, 1.0, 2.0, 4.0)


def lateral_study(bodies, rope_lengths, motions, *, margin, cable_ea=None, damping=None,
                  ranges=None, hook_load_factor=None, solver=None, gravity=G0,
                  regulatory_angle=REGULATORY_ANGLE, limits=None):
    """The design-angle study: every body x rope length x carrier motion, over the stated
    ranges of roll inertia, CG distance below the hub and rope length.

    Parameters
    ----------
    bodies : sequence of SlungBody
        Mass properties to cover (e.g. maximum, medium and minimum weight).
    rope_lengths : sequence of float
        Unstretched cable lengths, each > 0 (the paper uses 18, 60 and 100 ft). [m]
    motions : sequence of carrier motions
        See :func:`acceleration_sweep` for a grid of accelerations and durations.
    margin : float
        Factor >= 1 on the largest load angle found: recommended angle = margin x max. [-]
    cable_ea : float or None
        Cable EA (None: rigid rope). [N]
    damping : LateralDamping, optional
        Linear damping of the swing and roll (default none: the paper's hover step; see
        :func:`slingloads.analyses.lateral_damping.aerodynamic_damping`).
    ranges : ParameterRanges, optional
        Uncertainty of roll inertia, CG below hub and rope length (default +-20 %, five
        values each; :meth:`ParameterRanges.nominal` for none).
    hook_load_factor : float, optional
        Nz of the hook cases, compared with the largest cable tension factor T/(m g). [-]
    solver : SolverSettings, optional
        ``t_end`` and ``step`` of the sweep (see :func:`sweep`; default: the longest motion
        plus three periods of the slowest swing mode, and a step from the fastest mode); the
        solve_ivp settings and ``output_interval`` of :meth:`LateralStudy.run_case`.
    gravity : float
        [m/s^2]
    regulatory_angle : float
        The angle set beside the recommendation (CS-29.865: 30 deg). [rad]
    limits : CarrierLimits, optional
        What the carrier can fly (``CarrierLimits()``: 20 deg bank, 10 deg/s roll rate); a
        motion beyond them is flagged and bounds no design angle (CS-29.865: the angle
        achievable in service). Default None: not checked (the workbook's study checks
        them).

    Returns
    -------
    LateralStudy

    Raises
    ------
    InputError
        For empty inputs, a margin below 1, or any invalid body, length, motion or range.
    """
    bodies, rope_lengths, motions = list(bodies), list(rope_lengths), list(motions)
    for what, items in (("body", bodies), ("rope length", rope_lengths), ("motion", motions)):
        if not items:
            raise InputError(f"the lateral study needs at least one {what}")
    for body in bodies:
        if not isinstance(body, SlungBody):
            raise InputError("study bodies must be SlungBody objects", type(body).__name__)
    margin = float(margin)
    if not np.isfinite(margin) or margin < 1:
        raise InputError("design-angle margin must be >= 1", margin)
    damping = LateralDamping() if damping is None else damping
    if not isinstance(damping, LateralDamping):
        raise InputError("damping must be a LateralDamping", type(damping).__name__)
    ranges = ParameterRanges() if ranges is None else ranges
    if not isinstance(ranges, ParameterRanges):
        raise InputError("ranges must be a ParameterRanges", type(ranges).__name__)
    if hook_load_factor is not None:
        hook_load_factor = float(hook_load_factor)
        if not np.isfinite(hook_load_factor) or hook_load_factor <= 0:
            raise InputError("hook load factor Nz must be > 0", hook_load_factor)
    f_inertia, f_cg, f_rope = ranges.factors()
    pendulums = {}
    for (ib, b), fi, fe in itertools.product(enumerate(bodies), f_inertia, f_cg):
        body = SlungBody(b.mass, b.roll_inertia * fi, b.cg_below_hub * fe, b.name)
        for (il, length), fl in itertools.product(enumerate(rope_lengths), f_rope):
            pendulums[ib, fi, fe, il, fl] = LateralPendulum(
                body, length * fl, cable_ea, damping.lateral, damping.roll, gravity,
                damping.height_above_cg(body.cg_below_hub))
    keys = list(pendulums)
    case_pendulums = [pendulums[k] for k in keys for _ in motions]
    case_motions = [m for _ in keys for m in motions]
    factors = np.array([[k[1], k[2], k[4]] for k in keys for _ in motions])
    nominal_lengths = np.array([rope_lengths[k[3]] for k in keys for _ in motions])
    solver = solver_settings(solver)
    if solver.t_end is None:
        solver = solver.with_defaults(t_end=default_end_time(pendulums.values(), motions))
    metrics, h = sweep(case_pendulums, case_motions, solver=solver)
    return LateralStudy(tuple(case_pendulums), tuple(case_motions), metrics, margin,
                        solver.t_end, h, float(regulatory_angle), solver, factors,
                        nominal_lengths, ranges, damping, hook_load_factor,
                        limits)


def acceleration_sweep(accelerations, durations,
                       kinds=("quintic_step", "constant_acceleration"), then="stop"):
    """Carrier motions for every (kind, peak acceleration, duration) combination.

    Parameters
    ----------
    accelerations : sequence of float
        Peak lateral accelerations of the hook (sign gives the direction). [m/s^2]
    durations : sequence of float
        Step durations (quintic and cycloidal steps) or acceleration-phase durations. [s]
    kinds : sequence of {"quintic_step", "cycloidal_step", "constant_acceleration"}
        (``"smooth_step"``, the former name of the quintic step, is accepted).
    then : {"hold", "stop"}
        What follows a constant-acceleration phase.

    Returns
    -------
    list of motions
    """
    makers = {
        "quintic_step": QuinticStep.from_peak_acceleration,
        "cycloidal_step": CycloidalStep.from_peak_acceleration,
        "constant_acceleration": lambda a, d: ConstantAcceleration(a, d, then),
    }
    kinds = [MOTION_ALIASES.get(k, k) for k in kinds]
    for kind in kinds:
        if kind not in makers:
            raise InputError(f"acceleration sweeps take the motion types {sorted(makers)}",
                             kind)
    return [makers[k](a, d) for k in kinds for a in accelerations for d in durations]

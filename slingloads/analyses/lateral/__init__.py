"""The lateral-step pendulum: single runs, per-run metrics and the design-angle study.

CS-29.865 asks for the hook load applied at the largest angle from the mast that can be
achieved in service, and not less than 30 deg unless it is shown that a smaller angle cannot
be exceeded. This module makes that showing: it moves the carrier's hook sideways
(:mod:`slingloads.models.carrier_motion`), integrates the lateral pendulum
(:mod:`slingloads.models.pendulum`), and takes the largest load angle
:math:`|\\theta_1 - \\theta_2|` over a sweep of motions, rope lengths and mass properties.
The recommended design angle is that maximum times a stated margin.

Two integrators:

* :func:`simulate`: one run with :func:`scipy.integrate.solve_ivp` (settings in
  :class:`~slingloads.models.integration.SolverSettings`: ``method``, ``rtol``, ``atol``,
  ``max_step``, ``t_end``, ``output_interval``), integrated piecewise between the motion's
  breakpoints; gives time histories.
* :func:`sweep`: many runs at once, the fixed-step classical Runge-Kutta (RK4) step of
  :mod:`slingloads.models.runge_kutta` in compiled code, the runs spread over the cores;
  gives the per-run metrics. Its step is chosen from the fastest natural mode unless given
  (``SolverSettings.step``).

References
----------
.. [1] EASA CS-29, CS 29.865 "External loads"; 14 CFR 29.865(a).
.. [2] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993 (RK4, section II.1; dense output, section II.6).

The modules, one concept each (every public name is importable from this package):

* :mod:`~slingloads.analyses.lateral.carrier_limits`: what the carrier can fly
  (:class:`CarrierLimits`, :func:`flyable`, :func:`peak_jerk`) and carry sideways;
* :mod:`~slingloads.analyses.lateral.metrics`: the peaks of a run (:class:`RunMetrics`);
* :mod:`~slingloads.analyses.lateral.simulation`: one run with solve_ivp (:func:`simulate`,
  :class:`LateralRun`, :func:`default_end_time`);
* :mod:`~slingloads.analyses.lateral.batch`: many runs in compiled RK4 (:func:`sweep`,
  :func:`sweep_settings`);
* :mod:`~slingloads.analyses.lateral.ranges`: the airframe's body and the uncertainty of its
  mass properties (:func:`airframe_body`, :class:`ParameterRanges`);
* :mod:`~slingloads.analyses.lateral.study`: the design-angle study (:func:`lateral_study`,
  :func:`acceleration_sweep`);
* :mod:`~slingloads.analyses.lateral.result`: its result and verdict (:class:`LateralStudy`).
"""

from slingloads.analyses.lateral.batch import sweep, sweep_settings
from slingloads.analyses.lateral.carrier_limits import (
    BANK_LIMIT,
    CARRIER_FORCE_LIMIT,
    ROLL_RATE_LIMIT,
    CarrierLimits,
    flyable,
    peak_jerk,
)
from slingloads.analyses.lateral.metrics import RunMetrics
from slingloads.analyses.lateral.ranges import ParameterRanges, airframe_body
from slingloads.analyses.lateral.result import DOMAIN_ANGLE, REGULATORY_ANGLE, LateralStudy
from slingloads.analyses.lateral.simulation import (
    OUTPUT_INTERVAL,
    LateralRun,
    default_end_time,
    simulate,
)
from slingloads.analyses.lateral.study import (
    DEFAULT_ACCELERATIONS,
    DEFAULT_DURATIONS,
    PAPER_ROPE_LENGTHS,
    acceleration_sweep,
    lateral_study,
)
from slingloads.models.sampled_peak import refine_peak

__all__ = [
    "BANK_LIMIT", "CARRIER_FORCE_LIMIT", "DEFAULT_ACCELERATIONS", "DEFAULT_DURATIONS",
    "DOMAIN_ANGLE", "OUTPUT_INTERVAL", "PAPER_ROPE_LENGTHS", "REGULATORY_ANGLE",
    "ROLL_RATE_LIMIT", "CarrierLimits", "LateralRun", "LateralStudy", "ParameterRanges",
    "RunMetrics", "acceleration_sweep", "airframe_body", "default_end_time", "flyable",
    "lateral_study", "peak_jerk", "refine_peak", "simulate", "sweep", "sweep_settings",
]

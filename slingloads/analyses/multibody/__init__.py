"""Multibody analyses of the towed system (paper sections 4.3-5.3): trim, linear modes,
manoeuvres and their metrics, built on :mod:`slingloads.models.multibody`.

>>> from slingloads.analyses.multibody import trim, linearise, simulate
"""

from .manoeuvres import (
    DISTURBANCES,
    Manoeuvre,
    forward_acceleration,
    free_response,
    gust_response,
    paper_manoeuvres,
    wind_ramp,
)
from .simulate import RunResult, Simulation, disturbed, simulate, simulate_runs
from .start import start_state, state_table
from .trim import LinearModel, Trim, linearise, trim

__all__ = ["DISTURBANCES", "LinearModel", "Manoeuvre", "RunResult", "Simulation", "Trim",
           "disturbed", "forward_acceleration", "free_response", "gust_response", "linearise",
           "paper_manoeuvres", "simulate", "simulate_runs", "start_state", "state_table",
           "trim", "wind_ramp"]

"""Multibody model of the towed system (paper sections 4.3-5): carrier, elastic cable, the
carried helicopter as a 6-DOF rigid body, and its hinged drogue parachute.

One module per physical concept: :mod:`.rigid_body` (mass properties, quaternion attitude),
:mod:`.cable`, :mod:`.carrier` (frozen or free, trajectories), :mod:`.local_flow` (fuselage
and lifting surfaces from the flow each part sees), :mod:`.parachute_line` (hinged point mass
or quasi-static drogue), :mod:`.environment` (density altitude, wind, gusts, wind ramps),
:mod:`.equations` (the compiled equations of motion), :mod:`.integrator` (adaptive
Dormand-Prince 5(4) over many runs at once) and :mod:`.system` (the assembly). The analyses
built on it (trim, linearisation, manoeuvres, metrics) are in
:mod:`slingloads.analyses.multibody`.
"""

from slingloads.models.hook_trajectory import HookTrajectory, PiecewiseAcceleration
from slingloads.models.multibody.cable import Cable
from slingloads.models.multibody.carrier import (
    ForwardAcceleration,
    FreeCarrier,
    FrozenCarrier,
    LateralHookMotion,
    SteadyFlight,
)
from slingloads.models.multibody.environment import Wind, WindRamp
from slingloads.models.multibody.local_flow import LiftingSurface
from slingloads.models.multibody.parachute_line import HingedParachute, QuasiStaticParachute
from slingloads.models.multibody.rigid_body import RigidBody
from slingloads.models.multibody.system import SlingSystem

__all__ = ["Cable", "ForwardAcceleration", "FreeCarrier", "FrozenCarrier", "HingedParachute",
           "HookTrajectory", "LateralHookMotion", "LiftingSurface", "PiecewiseAcceleration",
           "QuasiStaticParachute", "RigidBody", "SlingSystem", "SteadyFlight", "Wind",
           "WindRamp"]

"""The carrier rotorcraft (RC): frozen on a prescribed trajectory, or free.

Earth axes of the simulation: X aft along the flight path (the carrier flies towards -X),
Y right, Z up. The carrier is a point (its hook); only its velocity matters to the load.

* **Frozen** (:class:`FrozenCarrier`): the hook follows the commanded trajectory exactly,
  whatever the cable does (the paper's "carrier dynamics frozen", figure 13).
* **Free** (:class:`FreeCarrier`): a point mass M with its own flat-plate drag area f, loaded
  by the cable, whose rotor thrust (a vector: tilting it is how a helicopter accelerates) follows
  a simple speed-hold law:

  .. math::

      T = -M g - D(V) - F_{c,0} + M\\,[a_c(t) + K_v (V_c(t) - V)]

  ``D(V) = 1/2 rho f |u| u`` is its own drag (u the air velocity relative to it, known to the
  pilot), ``F_{c,0}`` the cable's pull at the trim the run starts from (the load the pilot has
  trimmed for), ``a_c`` and ``V_c`` the commanded acceleration and velocity and ``K_v`` the gain
  of the speed hold (1 / its time constant). The carrier then accelerates as
  ``V' = a_c + K_v (V_c - V) + (F_c - F_{c,0}) / M``: a very heavy carrier reproduces the
  frozen one, and a change in the load's pull (drag as speed builds, swing) is felt as a speed
  error of ``dF / (M K_v)``. The thrust tilt reported is ``atan2(-T_X, T_Z)`` (forward
  positive).

Trajectories (commanded velocity relative to the steady flight at the system airspeed):
:class:`SteadyFlight`, and any :class:`~slingloads.models.hook_trajectory.HookTrajectory`
(any 3-D hook motion: piecewise acceleration, velocity or displacement histories, motions
along a direction), of which :class:`ForwardAcceleration` (from hover to a target speed with
a jerk-limited acceleration) and :class:`LateralHookMotion` (a lateral hook motion of
:mod:`slingloads.models.carrier_motion`, e.g. for the lateral-plane checks) are named
cases: each flies its ``trajectory``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import non_negative, positive
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.hook_trajectory import HookTrajectory

#: Default gain of the free carrier's speed hold (time constant 2 s). [1/s]
SPEED_GAIN = 0.5


@dataclass(frozen=True)
class FrozenCarrier:
    """The hook follows its commanded trajectory exactly (not loaded by the cable)."""

    kind = "frozen"


@dataclass(frozen=True)
class FreeCarrier:
    """Point-mass carrier with drag, loaded by the cable, under a speed-hold thrust law.

    Parameters
    ----------
    mass : float
        > 0. [kg]
    drag_area : float
        Flat-plate drag area f (CD S), >= 0. [m^2]
    speed_gain : float
        K_v, > 0. [1/s]
    """

    mass: float
    drag_area: float = 0.0
    speed_gain: float = SPEED_GAIN

    kind = "free"

    def __post_init__(self):
        object.__setattr__(self, "mass", positive(self.mass, "carrier mass must be > 0 [kg]"))
        object.__setattr__(self, "drag_area", non_negative(
            self.drag_area, "carrier drag area must be >= 0 [m^2]"))
        object.__setattr__(self, "speed_gain", positive(
            self.speed_gain, "carrier speed-hold gain must be > 0 [1/s]"))


class _Trajectory:
    """A commanded hook trajectory: ``command(t, v0)`` gives (acceleration, velocity), each of
    shape (n, 3) in earth axes [m/s^2, m/s], for the steady velocity ``v0`` (3,) [m/s]."""

    #: Times [s] at which the acceleration jumps (the integrator puts steps on them).
    breakpoints = ()
    #: The run starts from hover (trim at zero airspeed) rather than at the system airspeed.
    from_hover = False


@dataclass(frozen=True)
class SteadyFlight(_Trajectory):
    """Constant velocity at the system airspeed."""

    def command(self, t, v0):
        """Commanded hook acceleration and velocity at times ``t``.

        Parameters
        ----------
        t : array_like, shape (n,)
            Times. [s]
        v0 : array_like, shape (3,)
            Steady velocity of the system airspeed, earth axes. [m/s]

        Returns
        -------
        acceleration : ndarray, shape (n, 3)
            Earth axes. [m/s^2]
        velocity : ndarray, shape (n, 3)
            Earth axes. [m/s]
        """
        t = np.asarray(t, float).reshape(-1)
        return np.zeros((t.size, 3)), np.tile(np.asarray(v0, float), (t.size, 1))

    def describe(self):
        """What the carrier does, in words for the reports.

        Returns
        -------
        str
        """
        return "steady flight"


@dataclass(frozen=True)
class ForwardAcceleration(_Trajectory):
    """From hover to a target true airspeed along the flight path, jerk-limited.

    The forward acceleration rises linearly to ``acceleration`` in ``jerk_time``, holds, and
    falls linearly to zero in ``jerk_time`` so that the speed ends at ``target`` (if the target
    is too small for the plateau, the peak acceleration is lowered: a triangle).

    Parameters
    ----------
    target : float
        Final ground speed (true airspeed in still air), > 0. [m/s]
    acceleration : float
        Peak forward acceleration, > 0. [m/s^2]
    onset : float
        Start time, >= 0. [s]
    jerk_time : float
        Rise and fall time of the acceleration, > 0. [s]
    """

    target: float
    acceleration: float = 1.0
    onset: float = 5.0
    jerk_time: float = 2.0

    from_hover = True

    def __post_init__(self):
        object.__setattr__(self, "target", positive(
            self.target, "forward-acceleration target speed must be > 0 [m/s]"))
        object.__setattr__(self, "acceleration", positive(
            self.acceleration, "forward acceleration must be > 0 [m/s^2]"))
        object.__setattr__(self, "onset", non_negative(
            self.onset, "forward-acceleration onset must be >= 0 [s]"))
        object.__setattr__(self, "jerk_time", positive(
            self.jerk_time, "forward-acceleration jerk time must be > 0 [s]"))

    @property
    def trajectory(self):
        """The :class:`~slingloads.models.hook_trajectory.HookTrajectory` it flies."""
        return HookTrajectory.forward_acceleration(self.target, self.acceleration,
                                                   self.onset, self.jerk_time)

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return self.trajectory.breakpoints

    @property
    def end_time(self):
        """Time the target speed is reached. [s]"""
        return self.breakpoints[-1]

    def forward(self, t):
        """Forward acceleration and speed along the flight path at times ``t``.

        Parameters
        ----------
        t : array_like, shape (n,)
            Times. [s]

        Returns
        -------
        acceleration : ndarray, shape (n,)
            Forward acceleration. [m/s^2]
        speed : ndarray, shape (n,)
            Forward speed. [m/s]
        """
        _, v, a = self.trajectory.kinematics(np.asarray(t, float).reshape(-1))
        return -a[:, 0], -v[:, 0]

    def command(self, t, v0):
        """Commanded hook acceleration and velocity at times ``t``.

        Parameters
        ----------
        t : array_like, shape (n,)
            Times. [s]
        v0 : array_like, shape (3,)
            Steady velocity of the system airspeed, earth axes. [m/s]

        Returns
        -------
        acceleration : ndarray, shape (n, 3)
            Earth axes. [m/s^2]
        velocity : ndarray, shape (n, 3)
            Earth axes. [m/s]
        """
        return self.trajectory.command(t, v0)

    def describe(self):
        """What the carrier does, in words for the reports.

        Returns
        -------
        str
        """
        return (f"forward acceleration to {self.target / KNOT:.4g} kt at "
                f"{self.acceleration:.3g} m/s^2")


@dataclass(frozen=True)
class LateralHookMotion(_Trajectory):
    """A lateral hook motion of :mod:`slingloads.models.carrier_motion` (S(t) along +Y) on top
    of the steady flight.

    Parameters
    ----------
    motion : QuinticStep, CycloidalStep, ConstantAcceleration or TimeHistory
        A motion with ``kinematics(t)`` and no velocity jump.
    """

    motion: object

    def __post_init__(self):
        if not hasattr(self.motion, "kinematics"):
            raise InputError("a lateral hook motion needs a carrier motion with kinematics(t)",
                             type(self.motion).__name__)
        if getattr(self.motion, "velocity_jump", 0.0):
            raise InputError("a velocity step cannot drive the multibody model (the hook's "
                             "speed would jump); use a quintic or cycloidal step or an "
                             "acceleration",
                             self.motion.velocity_jump)

    @property
    def trajectory(self):
        """The :class:`~slingloads.models.hook_trajectory.HookTrajectory` it flies."""
        return HookTrajectory.lateral(self.motion)

    @property
    def breakpoints(self):
        """Times at which it jumps or kinks. [s]"""
        return self.trajectory.breakpoints

    def command(self, t, v0):
        """Commanded hook acceleration and velocity at times ``t``.

        Parameters
        ----------
        t : array_like, shape (n,)
            Times. [s]
        v0 : array_like, shape (3,)
            Steady velocity of the system airspeed, earth axes. [m/s]

        Returns
        -------
        acceleration : ndarray, shape (n, 3)
            Earth axes. [m/s^2]
        velocity : ndarray, shape (n, 3)
            Earth axes. [m/s]
        """
        return self.trajectory.command(t, v0)

    def describe(self):
        """What the carrier does, in words for the reports.

        Returns
        -------
        str
        """
        return f"lateral hook motion: {self.motion.describe()}"

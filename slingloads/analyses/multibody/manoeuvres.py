"""Manoeuvres of the towed system (paper sections 4.4 and 5.2).

A :class:`Manoeuvre` is what the carrier does, what the air does and how the run starts:

* a carrier trajectory (:mod:`slingloads.models.multibody.carrier`: steady flight, forward
  acceleration from hover, a lateral hook motion);
* a wind (:class:`~slingloads.models.multibody.environment.Wind`: steady, gust in any
  direction, frontal ramp);
* the start: trimmed at the system airspeed, or in hover (zero airspeed) for the forward
  accelerations and wind ramps, plus an optional initial disturbance (free response).

Builders for the paper's manoeuvres: :func:`free_response`, :func:`gust_response`,
:func:`forward_acceleration`, :func:`wind_ramp`, and :func:`paper_manoeuvres` (the whole list:
free response, +-30 ft/s lateral gusts of four shapes, accelerations to 40/60/80/100 KIAS, wind
ramps to 20/30/40/60/80 kt).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.atmosphere import true_airspeed
from slingloads.models.gusts import GUST_VELOCITY, make_gust
from slingloads.models.multibody.carrier import ForwardAcceleration, SteadyFlight
from slingloads.models.multibody.environment import Wind, WindRamp

#: Initial disturbances a free response may apply, and their units.
DISTURBANCES = {"yaw": "rad", "pitch": "rad", "roll": "rad", "yaw_rate": "rad/s",
                "longitudinal": "m", "lateral": "m", "vertical": "m", "theta": "rad",
                "psi": "rad"}
#: Default disturbance of the free response: 10 deg of yaw.
DEFAULT_DISTURBANCE = {"yaw": np.radians(10.0)}
#: Default seed of the runs from hover: 2 deg of yaw, so that a symmetric system's lateral and
#: directional modes are excited at all (a perfectly symmetric start stays symmetric).
HOVER_SEED = {"yaw": np.radians(2.0)}


def check_trajectory(trajectory):
    """Check that ``trajectory`` offers what a run asks of it (the protocol of
    :mod:`slingloads.models.hook_trajectory`): ``command(t, v0)`` returning the acceleration
    and velocity as finite arrays of shape (n, 3), ``breakpoints`` (finite times >= 0 [s])
    and ``describe()``; build one with
    :class:`~slingloads.models.hook_trajectory.HookTrajectory`.

    Parameters
    ----------
    trajectory : object
        The carrier trajectory of a manoeuvre.

    Raises
    ------
    InputError
        Naming what is missing or wrong.
    """
    name = type(trajectory).__name__
    hint = " (build it with slingloads.models.hook_trajectory.HookTrajectory)"
    for attribute in ("command", "describe"):
        if not callable(getattr(trajectory, attribute, None)):
            raise InputError(f"a manoeuvre's trajectory needs a method {attribute}(){hint}",
                             name)
    try:
        times = [float(b) for b in trajectory.breakpoints]
    except (AttributeError, TypeError, ValueError):
        raise InputError(f"a manoeuvre's trajectory needs breakpoints, a sequence of times "
                         f"[s]{hint}", name) from None
    if not all(np.isfinite(times)) or any(b < 0 for b in times):
        raise InputError("a trajectory's breakpoints must be finite times >= 0 [s]", times)
    probe = np.array([0.0, *times, max(times, default=0.0) + 1.0])
    out = trajectory.command(probe, np.zeros(3))
    try:
        acc, vel = (np.asarray(v, dtype=float) for v in out)
    except (TypeError, ValueError):
        raise InputError(f"a trajectory's command(t, v0) must return (acceleration, "
                         f"velocity){hint}", name) from None
    if acc.shape != (probe.size, 3) or vel.shape != (probe.size, 3):
        raise InputError("a trajectory's command(t, v0) must return two arrays of shape "
                         "(len(t), 3) [m/s^2, m/s]", [list(acc.shape), list(vel.shape)])
    if not (np.all(np.isfinite(acc)) and np.all(np.isfinite(vel))):
        raise InputError("a trajectory's commanded acceleration and velocity must be finite",
                         name)


@dataclass(frozen=True)
class Manoeuvre:
    """One manoeuvre (module notes).

    Parameters
    ----------
    name : str
    trajectory : carrier trajectory
        Default: steady flight at the system airspeed; any 3-D hook motion is a
        :class:`~slingloads.models.hook_trajectory.HookTrajectory` (checked by
        :func:`check_trajectory`).
    wind : Wind
    disturbance : dict
        Initial offsets added to the trim's state, or to ``start_state`` when given: keys of
        :data:`DISTURBANCES` (yaw, pitch, roll [rad] added to the attitude's angles; yaw_rate
        [rad/s] added to the body rates; longitudinal, lateral, vertical [m] CG displacement
        in earth axes; theta, psi [rad] of the parachute line;
        :func:`~slingloads.analyses.multibody.simulate.disturbed`).
    from_hover : bool, optional
        Start trimmed in hover rather than at the system airspeed (default: the trajectory's
        choice, True for a forward acceleration, and True for a wind ramp).
    start_state : array_like, shape (20,), optional
        A full state of the equations to start from instead of the trim's (built by name with
        :func:`~slingloads.analyses.multibody.start.start_state`, or e.g.
        :meth:`~slingloads.analyses.multibody.LinearModel.mode_state`). The run still needs
        its trim: the carrier's steady velocity and cable pull are the trim's.
        [m, m/s, -, rad/s, rad]
    """

    name: str
    trajectory: object = field(default_factory=SteadyFlight)
    wind: Wind = field(default_factory=Wind)
    disturbance: dict = field(default_factory=dict)
    from_hover: bool | None = None
    start_state: np.ndarray | None = None

    def __post_init__(self):
        if self.start_state is not None:
            x = np.asarray(self.start_state, float).reshape(-1)
            if x.size != 20 or not np.all(np.isfinite(x)):
                raise InputError("a start state needs 20 finite values", x.size)
            object.__setattr__(self, "start_state", x)
        bad = [k for k in self.disturbance if k not in DISTURBANCES]
        if bad:
            raise InputError(f"{bad[0]!r} is not a valid disturbance; valid disturbances are "
                             f"{list(DISTURBANCES)}", bad[0])
        for key, value in self.disturbance.items():
            if not np.isfinite(float(value)):
                raise InputError(f"disturbance {key} must be a finite number "
                                 f"[{DISTURBANCES[key]}]", value)
        check_trajectory(self.trajectory)
        if not isinstance(self.wind, Wind):
            raise InputError("a manoeuvre's wind must be a Wind", type(self.wind).__name__)
        if self.from_hover is None:
            hover = bool(getattr(self.trajectory, "from_hover", False)) or (
                self.wind.ramp is not None)
            object.__setattr__(self, "from_hover", hover)

    @property
    def breakpoints(self):
        """Times at which an input jumps or kinks. [s]"""
        return tuple(sorted(set(tuple(self.trajectory.breakpoints) + self.wind.breakpoints)))

    @property
    def input_end(self):
        """Time after which nothing is commanded any more (0 for a free response; None for a
        sustained input). [s]"""
        gust = self.wind.gust
        ends = [0.0]
        if gust is not None:
            end = getattr(gust, "end", None)
            if end is None:
                return None
            ends.append(end)
        if self.wind.ramp is not None:
            ends.append(self.wind.ramp.end_time)
        ends.extend(self.trajectory.breakpoints)
        return max(ends)

    def describe(self):
        """The manoeuvre in words, for the reports.

        Returns
        -------
        str
            The trajectory, the wind and the initial disturbance (deg, deg/s, m), in words.
        """
        parts = [self.trajectory.describe(), self.wind.describe()]
        if self.disturbance:
            parts.append("initial " + ", ".join(
                f"{k} {np.degrees(v) if DISTURBANCES[k].startswith('rad') else v:.3g}"
                f"{' deg' if DISTURBANCES[k] == 'rad' else ' deg/s' if k == 'yaw_rate' else ' m'}"
                for k, v in self.disturbance.items()))
        return "; ".join(parts) + ("; from hover" if self.from_hover else "")


def free_response(disturbance=None, name="free response"):
    """Free response from an initial disturbance (default: 10 deg of yaw) at trim.

    Parameters
    ----------
    disturbance : dict, optional
        Initial offsets (keys and units of :data:`DISTURBANCES`: rad, rad/s, m; default
        :data:`DEFAULT_DISTURBANCE`, 10 deg of yaw).
    name : str
        Label of the manoeuvre.

    Returns
    -------
    Manoeuvre
    """
    return Manoeuvre(name, disturbance=dict(DEFAULT_DISTURBANCE if disturbance is None
                                            else disturbance))


def gust_response(kind="finite", amplitude=GUST_VELOCITY, onset=5.0, duration=10.0,
                  direction="lateral", name=None):
    """Response to a gust of :mod:`slingloads.models.gusts` (default: 30 ft/s lateral, 10 s).

    Parameters
    ----------
    kind : str
        "step", "finite", "1-cosine" or "continuous" (sustained).
    amplitude : float
        [m/s]
    onset, duration : float
        [s]
    direction : str or array_like
        See :data:`~slingloads.models.multibody.environment.GUST_DIRECTIONS`. [-]

    Returns
    -------
    Manoeuvre
    """
    gust = make_gust(kind, amplitude, onset, duration)
    label = name or f"{direction} gust {kind} {amplitude / 0.3048:+.0f} ft/s"
    return Manoeuvre(label, wind=Wind(gust=gust, direction=direction))


def forward_acceleration(target_ias, density_altitude=0.0, acceleration=1.0, onset=5.0,
                         jerk_time=2.0, name=None, disturbance=None):
    """Forward acceleration from hover to ``target_ias`` (equivalent airspeed) [m/s], from
    :data:`HOVER_SEED` unless another ``disturbance`` is given.

    Parameters
    ----------
    target_ias : float
        Target equivalent airspeed. [m/s]
    density_altitude : float
        Density altitude, for the true airspeed the carrier reaches. [m]
    acceleration : float
        Peak forward acceleration. [m/s^2]
    onset : float
        Start of the acceleration. [s]
    jerk_time : float
        Rise and fall time of the acceleration. [s]
    name : str, optional
        Label of the manoeuvre (default from its inputs).
    disturbance : dict, optional
        Initial offsets (keys and units of :data:`DISTURBANCES`: rad, rad/s, m).

    Returns
    -------
    Manoeuvre
    """
    tas = float(true_airspeed(target_ias, density_altitude))
    label = name or f"accelerate to {target_ias / KNOT:.0f} KIAS"
    return Manoeuvre(label, trajectory=ForwardAcceleration(tas, acceleration, onset, jerk_time),
                     disturbance=dict(HOVER_SEED if disturbance is None else disturbance))


def wind_ramp(target, rate=0.5, onset=5.0, name=None, disturbance=None, gust=None,
              direction="lateral"):
    """Hovering carrier, head wind rising from 0 to ``target`` [m/s] at ``rate`` [m/s^2], from
    :data:`HOVER_SEED` unless another ``disturbance`` is given; with ``gust``, that gust on top
    of the ramp (e.g. after the ramp's end, so that a stable case shows its damping).

    Parameters
    ----------
    target : float
        Final head wind. [m/s]
    rate : float
        Rate of rise of the wind. [m/s^2]
    onset : float
        Start of the ramp. [s]
    name : str, optional
        Label of the manoeuvre (default from its inputs).
    disturbance : dict, optional
        Initial offsets (keys and units of :data:`DISTURBANCES`: rad, rad/s, m).
    gust : gust of :mod:`slingloads.models.gusts`, optional
        A gust added to the ramp's wind (:func:`~slingloads.models.gusts.make_gust`).
    direction : str or array_like
        Direction of the gust (see
        :data:`~slingloads.models.multibody.environment.GUST_DIRECTIONS`). [-]

    Returns
    -------
    Manoeuvre
    """
    label = name or f"wind ramp to {target / KNOT:.0f} kt"
    return Manoeuvre(label, wind=Wind(ramp=WindRamp(target, rate, onset), gust=gust,
                                      direction=direction),
                     disturbance=dict(HOVER_SEED if disturbance is None else disturbance))


def paper_manoeuvres(density_altitude=0.0):
    """The paper's manoeuvre list (sections 4.4 and 5.2).

    Parameters
    ----------
    density_altitude : float
        Density altitude of the forward accelerations. [m]

    Returns
    -------
    list of Manoeuvre
        The free response, the +-30 ft/s lateral gusts of four shapes, the accelerations to
        40, 60, 80, 100 KIAS and the wind ramps to 20, 30, 40, 60, 80 kt.
    """
    out = [free_response()]
    for sign in (1.0, -1.0):
        for kind in ("step", "finite", "1-cosine", "continuous"):
            out.append(gust_response(kind, sign * GUST_VELOCITY))
    out += [forward_acceleration(v * KNOT, density_altitude) for v in (40, 60, 80, 100)]
    out += [wind_ramp(v * KNOT) for v in (20, 30, 40, 60, 80)]
    return out

"""Starting states of the multibody model, by name.

The equations integrate a 20-value state (:data:`~slingloads.models.multibody.equations.STATES`):
the carrier's velocity, the CG position relative to the hook and its velocity (earth axes: X
aft along the flight path, Y right, Z up), the attitude as a scalar-first quaternion, the body
rates (body axes: x aft, y right, z up) and, with a hinged parachute, the line angles and
their rates. :func:`start_state` builds it from what an engineer states (where the hub hangs
under the hook, how fast everything moves, the attitude as angles, the body rates) and
:func:`state_table` names its values, so that a run of :class:`~.manoeuvres.Manoeuvre` can start
anywhere (``Manoeuvre(..., start_state=start_state(system, ...))``) with no airspeed in
between: velocities are taken as given, in earth axes.

Angles follow the model's conventions (docs/conventions.md): yaw nose right, pitch nose up,
roll right side down, R = Rz(-yaw) Ry(pitch) Rx(-roll) from body to earth axes; the rope
angles are those of :attr:`~.trim.Trim.swing_angles` (the hub aft of / right of the hook
positive).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.models.multibody.equations import N_STATES, STATES
from slingloads.models.multibody.rigid_body import (
    euler_angles,
    quaternion_from_euler,
    rotation_matrix,
)


def _vector(value, size, what, unit):
    v = np.asarray(value, dtype=float).reshape(-1)
    if v.size != size or not np.all(np.isfinite(v)):
        raise InputError(f"{what} needs {size} finite values [{unit}]", v.tolist())
    return v


def start_state(system, *, hub=None, rope_angles=None, span=None, velocity=(0.0, 0.0, 0.0),
                carrier_velocity=None, attitude=(0.0, 0.0, 0.0), body_rates=(0.0, 0.0, 0.0),
                line_angles=None, line_rates=(0.0, 0.0)):
    """The full state of the equations from named quantities.

    Parameters
    ----------
    system : SlingSystem
    hub : array_like, shape (3,), optional
        Hub position relative to the hook, earth axes. [m]
    rope_angles : (float, float), optional
        Instead of ``hub``: the cable's longitudinal and lateral angles from the vertical
        (tan of each = the hub's X or Y offset over its depth below the hook). [rad]
    span : float, optional
        Hook-to-hub distance with ``rope_angles`` (default: the unstretched length plus the
        static stretch under the hung weight). [m]
    velocity : array_like, shape (3,)
        Velocity of the CG, earth axes (the flight path is -X: 20 m/s forward is
        ``(-20, 0, 0)``). [m/s]
    carrier_velocity : array_like, shape (3,), optional
        Velocity of the carrier's hook, earth axes (default: ``velocity``). [m/s]
    attitude : (float, float, float)
        Yaw, pitch and roll (module notes). [rad]
    body_rates : (float, float, float)
        Angular velocity (p, q, r) about the body x, y, z axes. [rad/s]
    line_angles : (float, float), optional
        Parachute line (theta, psi) with a hinged canopy (default: trailing, (0, 0), when the
        air moves past the body faster than the system's aerodynamic cut-off, else hanging,
        (-90 deg, 0)). [rad]
    line_rates : (float, float)
        Their rates. [rad/s]

    Returns
    -------
    numpy.ndarray, shape (20,)
        For ``Manoeuvre(start_state=...)``; :func:`state_table` names its values.
        [m, m/s, -, rad/s, rad]

    Raises
    ------
    InputError
        For missing or conflicting positions, non-finite values, or a span the rope angles
        cannot reach.
    """
    if (hub is None) == (rope_angles is None):
        raise InputError("give the hub's place under the hook as hub=(X, Y, Z) [m] or as "
                         "rope_angles=(longitudinal, lateral) [rad], one of them")
    if hub is not None:
        d = _vector(hub, 3, "hub relative to the hook", "m")
    else:
        lon, lat = _vector(rope_angles, 2, "rope angles", "rad")
        if not (abs(lon) < np.pi / 2 and abs(lat) < np.pi / 2):
            raise InputError("rope angles must lie within (-90, 90) deg [rad]", [lon, lat])
        length = (system.cable.length + system.cable.static_stretch(system.weight)
                  if span is None else float(span))
        if not np.isfinite(length) or length <= 0:
            raise InputError("span must be > 0 [m]", length)
        direction = np.array([np.tan(lon), np.tan(lat), -1.0])
        d = length * direction / np.linalg.norm(direction)
    yaw, pitch, roll = _vector(attitude, 3, "attitude (yaw, pitch, roll)", "rad")
    q = quaternion_from_euler(yaw, pitch, roll)
    x = np.zeros(N_STATES)
    v = _vector(velocity, 3, "velocity", "m/s")
    x[0:3] = v if carrier_velocity is None else _vector(carrier_velocity, 3,
                                                        "carrier velocity", "m/s")
    x[3:6] = d - rotation_matrix(q) @ (system.hardpoints.hub - system.body.cg)
    x[6:9] = v
    x[9:13] = q
    x[13:16] = _vector(body_rates, 3, "body rates (p, q, r)", "rad/s")
    if system.chute_kind == "hinged":
        if line_angles is None:
            air = np.linalg.norm(v)  # still air: the air moves past at the body's speed
            line_angles = (0.0, 0.0) if air >= system.aero_cutoff else (-0.5 * np.pi, 0.0)
        x[16:18] = _vector(line_angles, 2, "line angles (theta, psi)", "rad")
        x[18:20] = _vector(line_rates, 2, "line rates", "rad/s")
    elif line_angles is not None:
        raise InputError("line angles need a hinged parachute; the system has "
                         f"{system.chute_kind}", list(line_angles))
    return x


def state_table(state):
    """The values of a state by name, with the attitude also as angles.

    Parameters
    ----------
    state : array_like, shape (20,)
        A full state of the equations. [m, m/s, -, rad/s, rad]

    Returns
    -------
    pandas.Series
        The 20 states by :data:`~slingloads.models.multibody.equations.STATES` name, then
        ``yaw``, ``pitch``, ``roll`` [rad].
    """
    x = _vector(state, N_STATES, "a state", "SI")
    yaw, pitch, roll = (float(a) for a in euler_angles(x[9:13]))
    return pd.Series([*x, yaw, pitch, roll], index=[*STATES, "yaw", "pitch", "roll"])

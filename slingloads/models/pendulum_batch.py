"""Compiled fixed-step RK4 of many lateral-pendulum runs, with their running peaks.

The equations of :func:`slingloads.models.pendulum.rigid_rope_derivatives` and
:func:`~slingloads.models.pendulum.elastic_cable_derivatives`, compiled from their one source
(:func:`~slingloads.models.pendulum.rigid_rope_equations`,
:func:`~slingloads.models.pendulum.elastic_cable_equations`, so that the results are the
numpy ones to the last bit), stepped by the RK4 step of
:mod:`slingloads.models.runge_kutta` with the peak logic of
:func:`slingloads.analyses.lateral.sweep` (a peak between samples refined by the one parabola
of :mod:`slingloads.models.sampled_peak`): each run on its own (runs in parallel over the
cores), every run on the shared time grid, the hook's velocity and acceleration read from a
table per distinct motion. Compiled with `numba <https://numba.pydata.org>`_ (``cache=True``:
the machine code is kept in this package's ``__pycache__`` after the first call; it is dropped
when a source of the package changes, :mod:`slingloads.models.runge_kutta`).

Parameter rows (``P``, one per run) are laid out by :data:`LAYOUT`
(:mod:`slingloads.models.packed`).

Drive tables (``drive``, shape (motions, nodes, 3, 2)): for the step starting at node i, the
hook's (velocity [m/s], acceleration [m/s^2]) (channels :data:`DRIVE`) at its start (just
after a jump there), middle and end (just before a jump there), as the RK4 step expects
(:mod:`slingloads.models.runge_kutta`).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from slingloads.models.packed import Field, Layout
from slingloads.models.pendulum import (
    E_RY,
    E_RY_DOT,
    E_RZ,
    E_RZ_DOT,
    E_THETA2,
    E_THETA2_DOT,
    R_THETA1,
    R_THETA1_DOT,
    R_THETA2,
    R_THETA2_DOT,
    elastic_cable_equations,
    rigid_rope_equations,
)
from slingloads.models.runge_kutta import rk4_stepper
from slingloads.models.sampled_peak import compiled_parabola_vertex

#: A row of ``P``: the parameters of one run (:meth:`LateralPendulum.arrays
#: <slingloads.models.pendulum.LateralPendulum.arrays>`).
LAYOUT = Layout((
    Field("mass", "kg", "mass of the carried helicopter"),
    Field("inertia", "kg m^2", "roll inertia about the CG"),
    Field("e", "m", "CG below the hub"),
    Field("length", "m", "rope length"),
    Field("stiffness", "N/m", "cable spring rate EA/l (unused for the rigid rope)"),
    Field("c_lat", "N s/m", "lateral damping"),
    Field("c_roll", "N m s/rad", "roll damping"),
    Field("g", "m/s^2", "acceleration of gravity"),
    Field("h_d", "m", "height of the damped point above the CG"),
))
#: Order of the parameters in a row of ``P``.
PARAMETERS = LAYOUT.names
MASS, INERTIA, E, LENGTH = LAYOUT["mass"], LAYOUT["inertia"], LAYOUT["e"], LAYOUT["length"]
STIFFNESS, C_LAT, C_ROLL = LAYOUT["stiffness"], LAYOUT["c_lat"], LAYOUT["c_roll"]
G, H_D = LAYOUT["g"], LAYOUT["h_d"]
#: Signals whose running peak is kept: |theta1 - theta2|, |theta1|, T/(m g), -T/(m g), and
#: the cable's lateral force on the hook over the load's weight, max(T, 0) |sin theta1| / (m g);
#: the angles first (they count only while the cable is taut).
SIGNALS = ("load_angle", "rope_angle", "tension_ratio", "minus_tension_ratio",
           "side_force_ratio")
N_SIGNALS = len(SIGNALS)
#: Offsets of the signals in :data:`SIGNALS`; the signals before ``S_TENSION`` are angles.
S_LOAD_ANGLE, S_ROPE_ANGLE, S_TENSION, S_MINUS_TENSION, S_SIDE_FORCE = (
    SIGNALS.index(n) for n in ("load_angle", "rope_angle", "tension_ratio",
                               "minus_tension_ratio", "side_force_ratio"))
#: Channels of the drive table (the hook's lateral motion), in order, and their offsets.
DRIVE = ("velocity", "acceleration")
D_VEL, D_ACC = DRIVE.index("velocity"), DRIVE.index("acceleration")

_jit = numba.njit(cache=True, fastmath=False, nogil=True)
_inline_jit = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")
_parallel_jit = numba.njit(cache=True, fastmath=False, nogil=True, parallel=True)

# the equations, compiled from their one source in slingloads.models.pendulum
_rigid_rope = _inline_jit(rigid_rope_equations)
_elastic_cable = _inline_jit(elastic_cable_equations)

# the peak between samples, compiled from its one source in slingloads.models.sampled_peak
_parabola_vertex = compiled_parabola_vertex()


@_jit
def rigid_rope(x, s_vel, s_acc, p, dx):
    """Rigid rope: the state derivative into ``dx`` and the rope tension.

    Parameters
    ----------
    x : ndarray, shape (4,)
        State: theta1, theta2 [rad], their rates [rad/s].
    s_vel, s_acc : float
        Hook's lateral velocity [m/s] and acceleration [m/s^2].
    p : ndarray, shape (9,)
        Parameter row (:data:`LAYOUT`). [SI]
    dx : ndarray, shape (4,)
        Receives the state derivative. [state units / s]

    Returns
    -------
    float
        Tension. [N]
    """
    dx[R_THETA1], dx[R_THETA2], dx[R_THETA1_DOT], dx[R_THETA2_DOT], tension = _rigid_rope(
        x[R_THETA1], x[R_THETA2], x[R_THETA1_DOT], x[R_THETA2_DOT], s_vel, s_acc, p[MASS],
        p[INERTIA], p[E], p[LENGTH], p[C_LAT], p[C_ROLL], p[G], p[H_D])
    return tension


@_jit
def elastic_cable(x, s_vel, s_acc, p, dx):
    """Elastic tension-only cable: the state derivative into ``dx`` and the tension.

    Parameters
    ----------
    x : ndarray, shape (6,)
        State: hub y, z from the hook [m], theta2 [rad], their rates [m/s, rad/s].
    s_vel, s_acc : float
        Hook's lateral velocity [m/s] and acceleration [m/s^2].
    p : ndarray, shape (9,)
        Parameter row (:data:`LAYOUT`). [SI]
    dx : ndarray, shape (6,)
        Receives the state derivative. [state units / s]

    Returns
    -------
    float
        Tension. [N]
    """
    (dx[E_RY], dx[E_RZ], dx[E_THETA2], dx[E_RY_DOT], dx[E_RZ_DOT], dx[E_THETA2_DOT],
     tension) = _elastic_cable(
        x[E_RY], x[E_RZ], x[E_THETA2], x[E_RY_DOT], x[E_RZ_DOT], x[E_THETA2_DOT], s_vel, s_acc,
        p[MASS], p[INERTIA], p[E], p[LENGTH], p[STIFFNESS], p[C_LAT], p[C_ROLL], p[G], p[H_D])
    return tension


@_inline_jit
def _rhs(x, drive, i, stage, args, dx):
    """The right-hand side of the RK4 step: ``args`` = (rigid, parameter row); returns the
    tension [N]."""
    rigid, p = args
    if rigid:
        return rigid_rope(x, drive[i, stage, D_VEL], drive[i, stage, D_ACC], p, dx)
    return elastic_cable(x, drive[i, stage, D_VEL], drive[i, stage, D_ACC], p, dx)


_rk4_step = rk4_stepper(_rhs)


@_jit
def _signals(rigid, x, tension, weight, alive, y):
    """Write the peak signals into ``y``; return (taut, alive). The rigid rope counts only
    until its tension first goes negative."""
    if rigid:
        th1, th2 = x[R_THETA1], x[R_THETA2]
    else:
        th1, th2 = math.atan2(x[E_RY], -x[E_RZ]), x[E_THETA2]
    ratio = tension / weight
    taut = ratio > 0
    if rigid:
        alive = alive and taut
        taut = alive
    y[S_LOAD_ANGLE] = abs((th1 - th2 + math.pi) % (2.0 * math.pi) - math.pi)
    y[S_ROPE_ANGLE] = abs(th1)
    y[S_TENSION] = ratio
    y[S_MINUS_TENSION] = -ratio
    y[S_SIDE_FORCE] = max(ratio, 0.0) * abs(math.sin(th1))
    return taut, alive


@_jit
def _keep(best, t_best, y, ok, when):
    """Running maximum: the angles (the signals before ``S_TENSION``) count only where the
    cable is taut."""
    for s in range(N_SIGNALS):
        if y[s] > best[s] and (s >= S_TENSION or ok):
            best[s] = y[s]
            t_best[s] = when


@_parallel_jit
def rk4_peaks(rigid, x0, P, drive, profile, nodes, jumps, best, t_best):
    """Integrate every run of one cable model and keep the peaks of its signals.

    Parameters
    ----------
    rigid : bool
    x0 : ndarray, shape (runs, states)
        Initial states, as :func:`rigid_rope` or :func:`elastic_cable` takes them.
        [rad, rad/s] or [m, rad, m/s, rad/s]
    P : ndarray, shape (runs, 9)
        Parameter rows (:data:`LAYOUT`). [SI]
    drive : ndarray, shape (motions, nodes, 3, 2)
        Hook velocity [m/s] and acceleration [m/s^2] at each step (module notes).
    profile : ndarray of int, shape (runs,)
        Each run's row of ``drive``. [-]
    nodes : ndarray, shape (nodes,)
        The time grid. [s]
    jumps : ndarray of bool, shape (nodes,)
        Where S'' may jump.
    best, t_best : ndarray, shape (runs, N_SIGNALS)
        Receive the peaks (-inf where none counted) and their times [s].
    """
    runs, n = x0.shape
    n_steps = nodes.size - 1
    for j in numba.prange(runs):
        x = np.empty(n)
        tmp = np.empty(n)
        k1, k2, k3, k4 = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
        y0, y1, y2, yl = (np.empty(N_SIGNALS), np.empty(N_SIGNALS), np.empty(N_SIGNALS),
                          np.empty(N_SIGNALS))
        p = P[j]
        args = (rigid, p)
        dr = drive[profile[j]]
        weight = p[MASS] * p[G]
        for m in range(n):
            x[m] = x0[j, m]
        bj, tj = best[j], t_best[j]
        tension = _rhs(x, dr, 0, 0, args, k1)
        ok1, alive = _signals(rigid, x, tension, weight, True, y1)
        for s in range(N_SIGNALS):
            bj[s] = -np.inf if (s < S_TENSION and not ok1) else y1[s]
            tj[s] = 0.0
        ok0 = False
        h_prev = 0.0
        for i in range(n_steps):
            t, t_next = nodes[i], nodes[i + 1]
            h = t_next - t
            _rk4_step(x, h, dr, i, args, k1, k2, k3, k4, tmp, x)
            if jumps[i + 1]:
                # the tension jumps with S'': count its value just before, then go on after
                tension = _rhs(x, dr, i, 2, args, k1)
                ok_left, alive = _signals(rigid, x, tension, weight, alive, yl)
                _keep(bj, tj, yl, ok_left, t_next)
            tension = _rhs(x, dr, i + 1, 0, args, k1)
            ok2, alive = _signals(rigid, x, tension, weight, alive, y2)
            if (i > 0 and abs(h - h_prev) <= 1e-9 * h and not (jumps[i] or jumps[i + 1])
                    and ok0 and ok1 and ok2):
                # parabola through the equally spaced samples at t - h, t, t + h
                for s in range(N_SIGNALS):
                    if y1[s] >= y0[s] and y1[s] >= y2[s]:
                        value, offset = _parabola_vertex(y0[s], y1[s], y2[s])
                        if value > bj[s]:
                            bj[s] = value
                            tj[s] = t + offset * h
            _keep(bj, tj, y2, ok2, t_next)
            for s in range(N_SIGNALS):
                y0[s] = y1[s]
                y1[s] = y2[s]
            ok0, ok1, h_prev = ok1, ok2, h

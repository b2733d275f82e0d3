"""Steady towed flight (trim) and the linear model about it.

**Trim.** At a given airspeed the carrier flies at constant velocity, the HC moves with it
without rotating and the parachute line is still. The unknowns are the CG position relative to
the hook (3), the attitude (yaw, pitch, roll) and, with a hinged parachute, the line angles
(theta, psi); the equations are zero CG acceleration, zero angular acceleration and zero hinge
accelerations, solved by :func:`scipy.optimize.root` from the hanging position (cable at the
drag-over-weight angle, level attitude, line trailing), or from a neighbouring trim
(``start``: continuation over airspeed, area or mass). Below the aerodynamic cut-off (hover)
the yaw is free and held at the guess. A trim whose equations cannot be met, that needs a
slack cable or lies outside a table is reported as such (:attr:`Trim.converged` False and
:attr:`Trim.message`), never as a number.

**Branch.** The equations also hold on another branch: the helicopter upside down and tail
first (Euler angles yaw 180, roll 180 deg: the mast pointing down, the hub below the CG, the
flow from behind, the parachute line forward), an equilibrium of an inverted pendulum that no
transport flies (unstable; on the sample HC1 at 100 KEAS the batched Newton iterations of
:func:`trim_many` reached it from the hanging guess). A trim is accepted only on the physical
branch, the one continuous with the hanging body in hover: the mast's upper half above the
horizontal (body z axis with an upward earth component) and the heading within 90 deg of the
guess (the flow from ahead); another equilibrium is refused with its reason and the next
starting point tried.

**Linearisation** about a trim: central differences of the compiled equations in the
perturbation coordinates (carrier velocity when free, CG position and velocity, a small
rotation vector in body axes, body rates, hinge angles and rates), eigenvalues and modes, each
mode named after the motion that holds most of its kinetic energy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.linalg import eig
from scipy.optimize import root

from slingloads.analyses import verdicts as vd
from slingloads.errors import InputError
from slingloads.models.multibody.carrier import FreeCarrier
from slingloads.models.multibody.equations import FLAGS, INFO, N_INFO, N_STATES, evaluate
from slingloads.models.multibody.integrator import evaluate_many
from slingloads.models.multibody.parachute_line import line_angles
from slingloads.models.multibody.rigid_body import (
    conjugate,
    euler_angles,
    quaternion_from_euler,
    quaternion_product,
    rotation_matrix,
    small_rotation,
)

#: Residual (scaled accelerations) below which a trim is accepted. [-]
TRIM_TOLERANCE = 1e-9
#: Smallest singular value of a trim's Jacobian, relative to its largest, at or below which
#: the equilibrium is not isolated (a free unknown: round-off of the central differences,
#: about 1e-9, not a weak stiffness: a parachute's yaw stiffness gives about 1e-2). [-]
NEUTRAL_TOLERANCE = 1e-7
#: Real part [1/s] above which an eigenvalue counts as unstable (round-off allowance): the
#: rule of every model (:data:`~slingloads.analyses.verdicts.EIGENVALUE_TOLERANCE`).
STABILITY_TOLERANCE = vd.EIGENVALUE_TOLERANCE

_INFO = {name: i for i, name in enumerate(INFO)}


def flag_text(flag):
    """Readable list of the tables or limits in a flag of the equations.

    Parameters
    ----------
    flag : int
        Flag of the equations (a sum of bits of
        :data:`~slingloads.models.multibody.equations.FLAGS`). [-]

    Returns
    -------
    str
        The tables or limits left, comma-separated ('' for 0).
    """
    return ", ".join(text for bit, text in FLAGS.items() if int(flag) & bit)


def steady_drive(wind, carrier_velocity):
    """Drive vector of a steady flight: wind, no commanded acceleration, commanded velocity.

    Parameters
    ----------
    wind : array_like, shape (3,)
        Wind velocity, earth axes. [m/s]
    carrier_velocity : array_like, shape (3,)
        Carrier velocity, earth axes. [m/s]

    Returns
    -------
    ndarray, shape (9,)
        Wind [m/s], commanded acceleration (zero) [m/s^2], commanded velocity [m/s].
    """
    return np.concatenate([np.asarray(wind, float), np.zeros(3),
                           np.asarray(carrier_velocity, float)])


def evaluate_state(system, x, drive, parameters=None, tables=None):
    """(derivative, info, flag) of the equations at state ``x`` with ``drive``.

    Parameters
    ----------
    system : SlingSystem
    x : array_like, shape (N_STATES,)
        State (:data:`~slingloads.models.multibody.equations.STATES`). [m, m/s, -, rad/s, rad]
    drive : array_like, shape (9,)
        Wind [m/s], commanded acceleration [m/s^2] and velocity [m/s], earth axes.
    parameters : ndarray, optional
        Parameter vector (default ``system.parameters(locks=system.locks)``).
        [SI: :data:`~slingloads.models.multibody.equations.LAYOUT`]
    tables : tuple of ndarray, optional
        Tables (default ``system.tables()``). [rad, -]

    Returns
    -------
    dx : ndarray, shape (N_STATES,)
        Derivative of the state. [m/s, m/s^2, 1/s, rad/s^2, rad/s]
    info : ndarray, shape (N_INFO,)
        Reported quantities (:data:`~slingloads.models.multibody.equations.INFO`). [SI]
    flag : int
        Tables or limits left (0: none; :func:`flag_text`). [-]
    """
    p = system.parameters(locks=system.locks) if parameters is None else parameters
    t = system.tables() if tables is None else tables
    dx, info = np.zeros(N_STATES), np.zeros(N_INFO)
    flag = evaluate(np.asarray(x, float), p, np.asarray(drive, float), *t, dx, info, True)
    return dx, info, flag


@dataclass(frozen=True, eq=False)
class Trim:
    """A steady towed flight (or why there is none).

    Attributes
    ----------
    system : SlingSystem
    airspeed : float
        Equivalent airspeed. [m/s]
    state : ndarray, shape (20,)
        Full state of the equations at trim. [m, m/s, -, rad/s, rad]
    drive : ndarray, shape (9,)
        Wind, commanded acceleration and velocity at trim. [m/s, m/s^2, m/s]
    converged : bool
    message : str
    residual : float
        Largest scaled acceleration left. [-]
    info : ndarray
        Reported quantities at trim (:data:`~slingloads.models.multibody.equations.INFO`). [SI]
    neutral : str
        The unknown the equilibrium leaves free ("yaw" for an airframe without any yawing
        moment: an equilibrium at every heading), "" when it is isolated; a neutral trim
        holds the free unknown where the search started.
    """

    system: object
    airspeed: float
    state: np.ndarray
    drive: np.ndarray
    converged: bool
    message: str
    residual: float
    info: np.ndarray
    neutral: str = ""

    def _require(self):
        if not self.converged:
            raise InputError(f"no trim at {self.airspeed:.4g} m/s EAS: {self.message}")

    def quantity(self, name):
        """A reported quantity of :data:`INFO` at trim.

        Parameters
        ----------
        name : str
            A name of :data:`~slingloads.models.multibody.equations.INFO`.

        Returns
        -------
        float
            Its value at trim. [N, m or rad]
        """
        return float(self.info[_INFO[name]])

    @property
    def attitude(self):
        """(yaw, pitch, roll) of the HC. [rad]"""
        return tuple(float(a) for a in euler_angles(self.state[9:13]))

    @property
    def swing_angle(self):
        """Cable angle from the vertical (the paper's drag proxy). [rad]"""
        d = self.info[_INFO["d_X"]:_INFO["d_Z"] + 1]
        return float(np.arccos(np.clip(-d[2] / np.linalg.norm(d), -1.0, 1.0)))

    @property
    def swing_angles(self):
        """(longitudinal, lateral) cable angles from the vertical: the hub aft of / right of
        the hook positive. [rad]"""
        d = self.info[_INFO["d_X"]:_INFO["d_Z"] + 1]
        return float(np.arctan2(d[0], -d[2])), float(np.arctan2(d[1], -d[2]))

    @property
    def line_angles(self):
        """(theta, psi) of the parachute line in body axes (NaN without parachute). [rad]"""
        if self.system.parachute is None:
            return np.nan, np.nan
        e = self.info[_INFO["line_x"]:_INFO["line_z"] + 1]
        theta, psi = line_angles(e)
        return float(theta), float(psi)

    def to_frame(self):
        """The trim as a one-row DataFrame (angles in degrees).

        Returns
        -------
        pandas.DataFrame
            One row: airspeed [m/s], convergence, swing, attitude and flow angles [deg], cable
            tension [N] and its ratio to the weight [-], line angles [deg].
        """
        yaw, pitch, roll = np.degrees(self.attitude)
        lon, lat = np.degrees(self.swing_angles)
        theta, psi = np.degrees(self.line_angles)
        w = self.system.weight
        row = {
            "airspeed EAS [m/s]": self.airspeed, "converged": self.converged,
            "message": self.message, "swing from vertical [deg]":
                np.degrees(self.swing_angle) if self.converged else np.nan,
            "swing longitudinal [deg]": lon, "swing lateral [deg]": lat,
            "yaw [deg]": yaw, "pitch [deg]": pitch, "roll [deg]": roll,
            "alpha [deg]": np.degrees(self.quantity("alpha")),
            "beta [deg]": np.degrees(self.quantity("beta")),
            "cable tension [N]": self.quantity("tension"),
            "tension / weight [-]": self.quantity("tension") / w,
            "line theta [deg]": theta, "line psi [deg]": psi,
            "line tension [N]": self.quantity("line_tension"),
            "parachute drag [N]": self.quantity("chute_drag"),
            "residual [-]": self.residual,
        }
        return pd.DataFrame([row])


def _initial_state(system, tas, wind):
    """Full state with the carrier at (-tas, 0, 0) + wind and the HC hanging below it."""
    x = np.zeros(N_STATES)
    vc = np.array([-tas, 0.0, 0.0]) + np.asarray(wind, float)
    x[0:3] = vc
    x[6:9] = vc
    x[9] = 1.0
    if system.parachute is not None and system.parachute.kind == "hinged":
        x[16] = -0.5 * np.pi if tas < system.aero_cutoff else 0.0
    return x


#: Pitch angles tried for the second starting point of a trim that failed from the first. [deg]
PITCH_SCAN = np.arange(-40.0, 20.5, 2.0)


def _drag_estimate(system, tas):
    """Rough drag [N] of fuselage and parachute, to start the trim at a sensible swing."""
    return 0.5 * system.density * tas**2 * system.drag_area


def _quaternion(yaw, pitch, roll):
    """:func:`~slingloads.models.multibody.rigid_body.quaternion_from_euler` for one
    attitude, on floats (the trim calls it often)."""
    cz, sz = math.cos(-0.5 * yaw), math.sin(-0.5 * yaw)
    cy, sy = math.cos(0.5 * pitch), math.sin(0.5 * pitch)
    cx, sx = math.cos(-0.5 * roll), math.sin(-0.5 * roll)
    return (cz * cy * cx + sz * sy * sx, cz * cy * sx - sz * sy * cx,
            cz * sy * cx + sz * cy * sx, sz * cy * cx - cz * sy * sx)


def hanging_attitude(hub, up, yaw=0.0):
    """Pitch and roll [rad] at which the body hangs on its cable: the vector from the CG to
    the hub along ``up``, the direction from the hub towards the hook (earth axes), at the
    given yaw [rad] (module conventions, R = Rz(-yaw) Ry(pitch) Rx(-roll)).

    A body hung at one point and pulled only at its CG (weight and a drag there) is in
    equilibrium with the CG on the cable's line; this is the trim's starting attitude.

    Parameters
    ----------
    hub : array_like, shape (3,)
        Hub relative to the CG, body axes. [m]
    up : array_like, shape (3,)
        Direction from the hub to the hook, earth axes (any length). [-]
    yaw : float
        [rad]

    Returns
    -------
    pitch, roll : float
        [rad]
    """
    u = np.asarray(hub, float) / np.linalg.norm(hub)
    c, s = math.cos(yaw), math.sin(yaw)
    t = np.asarray(up, float) / np.linalg.norm(up)
    t = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ t  # Rz(-yaw)^T t
    # Rx(a) u = (ux, uy cos a - uz sin a, uy sin a + uz cos a): its y part must be t_y
    r = math.hypot(u[1], u[2])
    beta = math.atan2(u[2], u[1])
    a = math.acos(np.clip(t[1] / r, -1.0, 1.0)) - beta if r > 0 else 0.0
    a = (a + math.pi) % (2 * math.pi) - math.pi
    v = (u[0], u[1] * math.cos(a) - u[2] * math.sin(a), u[1] * math.sin(a) + u[2] * math.cos(a))
    # Ry(pitch) turns the x-z part of v, measured from z towards x, by +pitch
    pitch = math.atan2(t[0], t[2]) - math.atan2(v[0], v[2])
    pitch = (pitch + math.pi) % (2 * math.pi) - math.pi
    return pitch, -a


class _TrimProblem:
    """The equilibrium equations of one trim: unknowns, starting guess, scaled residuals.

    Unknowns: the CG position relative to the hook (3), the yaw (not in hover), pitch and
    roll, and the line angles with a hinged canopy; equations: zero CG acceleration, zero
    angular acceleration (no yaw equation in hover) and zero hinge accelerations, scaled (CG
    and hinges in g, angular in (m g 1 m) / I).
    """

    def __init__(self, system, airspeed, wind, yaw_guess, start=None):
        eas = system.airspeed if airspeed is None else float(airspeed)
        if not np.isfinite(eas) or eas < 0:
            raise InputError("trim airspeed must be >= 0 [m/s]", eas)
        self.eas = eas
        self.system = system if eas == system.airspeed else system.with_(airspeed=eas)
        sys_at = self.system
        tas = sys_at.true_airspeed
        # the unrestricted system; neither depends on the airspeed
        self.params, self.tables = system.parameters(), system.tables()
        self.x0 = _initial_state(sys_at, tas, wind)
        self.drive = steady_drive(wind, self.x0[0:3])
        self.hinged = sys_at.parachute is not None and sys_at.parachute.kind == "hinged"
        self.hover = tas < sys_at.aero_cutoff
        self.yaw_guess = float(yaw_guess)
        w = sys_at.weight
        hub = sys_at.hardpoints.hub - sys_at.body.cg
        swing = np.arctan2(_drag_estimate(sys_at, tas), w)
        span = sys_at.cable.length + sys_at.cable.static_stretch(w / np.cos(swing))
        cable = span * np.array([np.sin(swing), 0.0, -np.cos(swing)])  # hook to hub
        pitch, roll = hanging_attitude(hub, -cable, self.yaw_guess)
        self.hub = hub
        self.cable = (sys_at.cable.length, w / sys_at.cable.stiffness)  # L0, stretch at 1 g
        # the hub's place under the hook and the tension (the cable's stretch follows from
        # it, however stiff the cable) and the hanging attitude: CG on the cable's line
        guess = [cable[0], cable[1], 1.0 / np.cos(swing)]
        guess += [] if self.hover else [yaw_guess]
        guess += [pitch, roll]
        if self.hinged:
            guess += [self.x0[16], 0.0]
        self.hanging = np.array(guess)
        self.guess = self.hanging if start is None else self.unknowns_of(start)
        g = sys_at.gravity
        self.scale = np.ones(N_STATES)
        self.scale[6:9] = self.scale[18:20] = g
        self.scale[13:16] = sys_at.body.mass * g / np.diag(sys_at.body.inertia)
        self.rows = ([6, 7, 8, 13, 14] + ([] if self.hover else [15])
                     + ([18, 19] if self.hinged else []))

    def unknowns_of(self, start):
        """The unknowns of a converged trim ``start`` (of a neighbouring system: another
        airspeed, area or mass with the same layout), as this problem's starting guess: the
        hub's place under the hook, the tension over this system's weight, the attitude and
        the line angles."""
        if not isinstance(start, Trim) or not start.converged:
            raise InputError("a trim's start must be a converged Trim",
                             getattr(start, "message", type(start).__name__))
        start_hinged = (start.system.parachute is not None
                        and start.system.parachute.kind == "hinged")
        start_hover = start.system.true_airspeed < start.system.aero_cutoff
        if (start_hinged, start_hover) != (self.hinged, self.hover):
            raise InputError("a trim's start must have the same unknowns (parachute model, "
                             "hover or not) as the trim", start.system.name)
        d = start.info[_INFO["d_X"]:_INFO["d_Y"] + 1]
        yaw, pitch, roll = start.attitude
        u = [d[0], d[1], start.quantity("tension") / self.system.weight]
        u += [] if self.hover else [yaw]
        u += [pitch, roll]
        if self.hinged:
            u += list(start.state[16:18])
        return np.array(u, float)

    def branch_rule(self, x):
        """'' on the physical branch (module notes), else why not."""
        r = rotation_matrix(x[9:13])
        if r[2, 2] <= 0.0:
            return ("the equilibrium found is on another branch: the helicopter upside down "
                    f"(mast {np.degrees(np.arccos(np.clip(r[2, 2], -1, 1))):.0f} deg from "
                    "the vertical, the hub below the CG)")
        yaw = float(euler_angles(x[9:13])[0])
        if math.cos(yaw - self.yaw_guess) <= 0.0:
            return ("the equilibrium found is on another branch: heading "
                    f"{np.degrees(yaw):.0f} deg, more than 90 deg from the start "
                    f"{np.degrees(self.yaw_guess):.0f} deg (tail first)")
        return ""

    def pitch_scan_guess(self):
        """A second starting point: the hanging guess with the pitch (every PITCH_SCAN
        angle) whose scaled residuals are least, the CG placed so that the hub stays where
        the guess put it (span and swing kept) and a hinged line trailing at the same angle
        to the flight path as in the hanging guess."""
        k = 3 if self.hover else 4
        pitches = np.radians(PITCH_SCAN)
        u = np.tile(self.hanging, (pitches.size, 1))
        for i, pitch in enumerate(pitches):  # (the hub stays where the guess put it)
            u[i, k] = pitch
            if self.hinged:
                u[i, k + 2] = self.hanging[k + 2] + pitch - self.hanging[k]
        states = self.states(u)
        rates, _, _ = evaluate_many(states, self.params, self.drive, self.tables)
        norms = np.linalg.norm(self.scaled(rates), axis=1)
        norms[~np.isfinite(norms)] = np.inf
        return u[int(np.argmin(norms))]

    @property
    def shape(self):
        """What decides the layout of the unknowns (trims of one shape solve together)."""
        return (self.hover, self.hinged, self.system.table_key())

    def states(self, u):
        """Full states (m, 20) of unknowns ``u`` (m, n)."""
        u = np.atleast_2d(u)
        x = np.tile(self.x0, (u.shape[0], 1))
        k = 3 if self.hover else 4
        x[:, 9:13] = quaternion_from_euler(self.yaw_guess if self.hover else u[:, 3],
                                           u[:, k], u[:, k + 1])
        x[:, 3:6] = _cg_from_hub(u, x[:, 9:13], self.hub[None, :], *self.cable)
        if self.hinged:
            x[:, 16:18] = u[:, k + 2:k + 4]
        return x

    def state(self, u):
        """The full state of one set of unknowns (floats: called in the solver's loop)."""
        x = self.x0.copy()
        k = 3 if self.hover else 4
        x[9:13] = _quaternion(self.yaw_guess if self.hover else u[3], u[k], u[k + 1])
        x[3:6] = _cg_from_hub(u[None, :], x[None, 9:13], self.hub[None, :], *self.cable)[0]
        if self.hinged:
            x[16:18] = u[k + 2:k + 4]
        return x

    def names(self):
        """Names of the unknowns, in their order."""
        angles = ["pitch", "roll"] if self.hover else ["yaw", "pitch", "roll"]
        line = ["parachute line pitch", "parachute line yaw"] if self.hinged else []
        return ["hub position x", "hub position y", "cable tension", *angles, *line]

    def jacobian(self, u):
        """Jacobian (n, n) of the scaled residuals at unknowns ``u``, by central
        differences (steps 1e-7 of each unknown, at least 1e-7 absolute)."""
        n = u.size
        steps = np.diag(1e-7 * np.maximum(1.0, np.abs(u)))
        rates, _, _ = evaluate_many(self.states(np.vstack([u + steps, u - steps])),
                                    self.params, self.drive, self.tables)
        scaled = self.scaled(rates)
        return ((scaled[:n] - scaled[n:]) / (2.0 * np.diag(steps)[:, None])).T

    def undetermined(self, u):
        """The unknowns the equations leave free at ``u`` (their names, the angles first,
        joined by "and"), or "" when the equilibrium is isolated: the Jacobian's smallest
        singular value within round-off (:data:`NEUTRAL_TOLERANCE` of its largest) of zero,
        the free unknowns the components of its singular vector of at least a tenth of its
        largest. An airframe without any yawing moment (no fin, no parachute, a body of
        revolution) has an equilibrium at every heading (with a side force in body axes, at
        a lateral hub position of its own): no isolated trim."""
        jac = self.jacobian(u)
        if not np.all(np.isfinite(jac)):
            return ""
        _, sv, vt = np.linalg.svd(jac)
        if sv[0] == 0.0 or sv[-1] > NEUTRAL_TOLERANCE * sv[0]:
            return ""
        weight = np.abs(vt[-1])
        names = [n for n, w in zip(self.names(), weight, strict=True) if w >= 0.1 * weight.max()]
        return " and ".join(sorted(names, key=lambda n: n.startswith(("hub", "cable"))))

    def scaled(self, rates):
        """Scaled residuals of state derivatives (m, 20) -> (m, n)."""
        return np.atleast_2d(rates)[:, self.rows] / self.scale[self.rows]

    def result(self, u, solver_message=""):
        """The :class:`Trim` at unknowns ``u``, judged (converged, outside a table, slack)."""
        x = self.state(u)
        dx, info, flag = evaluate_state(self.system, x, self.drive, self.params, self.tables)
        res = float(np.max(np.abs(self.scaled(dx))))
        converged, message = True, "trimmed"
        if not np.all(np.isfinite(u)) or res > TRIM_TOLERANCE:
            converged = False
            message = (f"the equilibrium equations cannot be met (largest scaled residual "
                       f"{res:.3g}; solver: {solver_message})")
        elif self.branch_rule(x):
            converged = False
            message = self.branch_rule(x)
        elif flag:
            converged = False
            message = f"the only equilibrium found lies outside the {flag_text(flag)}"
        elif info[_INFO["tension"]] <= 0:
            converged = False
            message = "the equilibrium found needs a slack cable"
        free = self.undetermined(u) if converged else ""
        if free:
            message = (f"trimmed, neutral: nothing fixes the {free} (no restoring force or "
                       "moment), held where the search started")
        return Trim(self.system, self.eas, x, self.drive, converged, message, res, info,
                    free)


def _cg_from_hub(u, quaternion, hub, length, stretch):
    """CG relative to the hook (m, 3) [m] of trim unknowns ``u`` (m, n): the hub at (u0, u1)
    [m] from the hook, horizontally, on a cable stretched by the tension ratio u2 [-] times
    ``stretch`` (the stretch at 1 g, W L0 / EA [m]) beyond ``length`` [m], below the hook;
    the CG at -R hub from it (``hub`` (m, 3) from the CG, body axes [m]). NaN where the
    cable cannot reach that far out."""
    span = length + u[:, 2] * stretch
    with np.errstate(invalid="ignore"):
        down = np.sqrt(span**2 - u[:, 0] ** 2 - u[:, 1] ** 2)
    d = np.column_stack([u[:, 0], u[:, 1], -down])
    return d - np.einsum("mij,mj->mi", rotation_matrix(quaternion), hub)


def _solve_one(problem):
    """Powell's hybrid method (MINPACK hybrj) on one trim, Jacobian by central differences."""
    dx, info = np.zeros(N_STATES), np.zeros(N_INFO)

    def residual(u):
        evaluate(problem.state(u), problem.params, problem.drive, *problem.tables, dx, info,
                 False)
        return problem.scaled(dx)[0]

    jacobian = problem.jacobian
    solution = root(residual, problem.guess, jac=jacobian, method="hybr",
                    options={"xtol": 1e-13})
    found = problem.result(solution.x, solution.message)
    if found.converged:
        return found
    # an unstable fuselage pitches far nose down at speed (and an unusual hang may defeat
    # the first guess in hover too): start again from the pitch that best balances the
    # equations along the hang (module notes)
    again = root(residual, problem.pitch_scan_guess(), jac=jacobian, method="hybr",
                 options={"xtol": 1e-13})
    second = problem.result(again.x, again.message)
    return second if second.converged else found


def trim(system, airspeed=None, *, wind=(0.0, 0.0, 0.0), yaw_guess=0.0, start=None):
    """Steady towed flight of ``system`` (module notes).

    Parameters
    ----------
    system : SlingSystem
    airspeed : float, optional
        Equivalent airspeed (default the system's). [m/s]
    wind : array_like, shape (3,)
        Steady wind, earth axes; the carrier flies at the airspeed relative to it. [m/s]
    yaw_guess : float
        Starting yaw of the search (and the yaw held in hover). [rad]
    start : Trim, optional
        A converged trim of a neighbouring system (another airspeed, area or mass, the same
        parachute model) to start from instead of the hanging guess: continuation. Should
        it fail, the pitch scan of the hanging guess is tried next, as without it.

    Returns
    -------
    Trim
    """
    return _solve_one(_TrimProblem(system, airspeed, wind, yaw_guess, start))


#: Newton iterations of :func:`trim_many` before a trim falls back to :func:`trim`.
NEWTON_ITERATIONS = 30


def trim_many(requests):
    """Many trims at once: damped Newton iterations on all of them together (one evaluation
    of the compiled equations per iteration for every trim's residuals, and one for every
    Jacobian), each trim that has not converged after :data:`NEWTON_ITERATIONS` solved again
    on its own by :func:`trim` (Powell's hybrid method). The same equations, unknowns, guess
    and acceptance as :func:`trim`.

    Parameters
    ----------
    requests : sequence of (SlingSystem, airspeed, wind)
        Equivalent airspeed [m/s] (None: the system's) and steady wind (3,) [m/s].

    Returns
    -------
    list of Trim
    """
    problems = [_TrimProblem(system, speed, wind, 0.0) for system, speed, wind in requests]
    results = [None] * len(problems)
    groups = {}
    for k, problem in enumerate(problems):
        groups.setdefault(problem.shape, []).append(k)
    for members in groups.values():
        solved = _newton([problems[k] for k in members])
        for k, u in zip(members, solved, strict=True):
            found = problems[k].result(u, "Newton") if u is not None else None
            # Newton's steps may cross to another branch or out of a table: then the hybrid
            # method from the hanging guess and the pitch scan, as trim()
            results[k] = (found if found is not None and found.converged
                          else _solve_one(problems[k]))
    return results


def _newton(problems):
    """Unknowns solving every problem of one shape (None where Newton did not converge)."""
    first = problems[0]
    m, n = len(problems), first.guess.size
    u = np.array([p.guess for p in problems])
    params = np.array([p.params for p in problems])
    drives = np.array([p.drive for p in problems])
    scales = np.array([p.scale[p.rows] for p in problems])

    starts = np.array([p.x0 for p in problems])
    hubs = np.array([p.hub for p in problems])
    cables = np.array([p.cable for p in problems])
    k = 3 if first.hover else 4

    def states(values, owners):
        out = starts[owners].copy()
        out[:, 9:13] = quaternion_from_euler(0.0 if first.hover else values[:, 3],
                                             values[:, k], values[:, k + 1])
        out[:, 3:6] = _cg_from_hub(values, out[:, 9:13], hubs[owners], cables[owners, 0],
                                   cables[owners, 1])
        if first.hinged:
            out[:, 16:18] = values[:, k + 2:k + 4]
        return out

    def residuals(values, owners):
        rates, _, _ = evaluate_many(states(values, owners), params[owners], drives[owners],
                                    first.tables)
        return rates[:, first.rows] / scales[owners]

    everyone = np.arange(m)
    r = residuals(u, everyone)
    done = np.zeros(m, dtype=bool)
    for _ in range(NEWTON_ITERATIONS):
        done |= np.all(np.isfinite(r), axis=1) & (np.max(np.abs(r), axis=1) <= 0.1 *
                                                   TRIM_TOLERANCE)
        active = np.nonzero(~done)[0]
        if active.size == 0:
            break
        h = 1e-7 * np.maximum(1.0, np.abs(u[active]))
        plus = u[active][:, None, :] + h[:, :, None] * np.eye(n)
        minus = u[active][:, None, :] - h[:, :, None] * np.eye(n)
        owners = np.repeat(active, n)
        rp = residuals(plus.reshape(-1, n), owners).reshape(active.size, n, n)
        rm = residuals(minus.reshape(-1, n), owners).reshape(active.size, n, n)
        jac = np.transpose((rp - rm) / (2.0 * h[:, :, None]), (0, 2, 1))
        ok = np.all(np.isfinite(jac), axis=(1, 2)) & np.all(np.isfinite(r[active]), axis=1)
        step = np.zeros((active.size, n))
        try:
            step[ok] = np.linalg.solve(jac[ok], -r[active][ok][..., None])[..., 0]
        except np.linalg.LinAlgError:
            ok[:] = False
        base = np.linalg.norm(r[active], axis=1)
        alpha = np.ones(active.size)
        moved = np.zeros(active.size, dtype=bool)
        for _ in range(8):  # halve the step until the residual falls
            trying = ok & ~moved
            if not trying.any():
                break
            who = active[trying]
            trial = u[who] + alpha[trying, None] * step[trying]
            rt = residuals(trial, who)
            better = np.all(np.isfinite(rt), axis=1) & (np.linalg.norm(rt, axis=1)
                                                        < base[trying])
            idx = np.nonzero(trying)[0][better]
            u[active[idx]] = trial[better]
            r[active[idx]] = rt[better]
            moved[idx] = True
            alpha[trying & ~moved] *= 0.5
        stuck = active[~moved]
        done[stuck] = True  # no descent: leave it to the hybrid method
        r[stuck] = np.nan
    converged = np.all(np.isfinite(r), axis=1) & (np.max(np.abs(r), axis=1) <= 0.1 *
                                                  TRIM_TOLERANCE)
    return [u[k] if converged[k] else None for k in range(m)]


# =============================================================================== linear
#: Motions the modes are named after, and the kinetic energy each is measured by.
MOTIONS = ("longitudinal swing", "lateral swing", "cable stretch", "roll", "pitch", "yaw",
           "parachute", "carrier")
#: Order of the angular groups in a two-group mode name (indices of
#: :meth:`LinearModel.angles`: 0 longitudinal, 1 lateral, 2 yaw): yaw first, as the
#: parachute is sized on the yaw modes.
NAME_ORDER = (2, 1, 0)


@dataclass(frozen=True, eq=False)
class LinearModel:
    """Linearised equations dz/dt = A z about a trim, and their modes.

    Attributes
    ----------
    trim : Trim
    a : ndarray, shape (n, n)
        State matrix. [SI per second]
    names : tuple of str
        Perturbation coordinates, in order.
    eigenvalues : ndarray, shape (n,)
        [1/s]
    vectors : ndarray, shape (n, n)
        Right eigenvectors (columns). [units of the coordinates]
    """

    trim: Trim
    a: np.ndarray
    names: tuple
    eigenvalues: np.ndarray
    vectors: np.ndarray

    @property
    def stable(self):
        """True when every eigenvalue has a real part below -:data:`STABILITY_TOLERANCE`:
        every mode decays (a real part within the tolerance of 0 is neutral, not stable; the
        same rule as :meth:`verdict`)."""
        return bool(np.all(self.eigenvalues.real < -STABILITY_TOLERANCE))

    def verdict(self):
        """"stable", "neutral" (some real parts within round-off of 0) or "unstable", with
        the rule.

        Returns
        -------
        str
            "unstable" if a real part exceeds :data:`STABILITY_TOLERANCE` [1/s], "neutral" if one
            is within it of zero, else "stable".
        """
        re = self.eigenvalues.real
        if np.any(re > STABILITY_TOLERANCE):
            return vd.UNSTABLE
        if np.any(np.abs(re) <= STABILITY_TOLERANCE):
            return vd.NEUTRAL
        return vd.STABLE

    def a_frame(self):
        """The state matrix A as a DataFrame (rows: derivative of, columns: coordinate).

        Returns
        -------
        pandas.DataFrame
            A (n, n) [1/s], indexed and labelled by :attr:`names`.
        """
        return pd.DataFrame(self.a, index=list(self.names), columns=list(self.names))

    def shares(self):
        """Share of each motion of :data:`MOTIONS` in each mode's kinetic energy, (n, 8).

        Returns
        -------
        ndarray, shape (n, len(MOTIONS))
            Share of each motion in each mode's kinetic energy, rows summing to 1. [-]
        """
        system = self.trim.system
        idx = {name: i for i, name in enumerate(self.names)}
        m = system.body.mass
        ixx, iyy, izz = np.diag(system.body.inertia)
        line = system.parachute.line_length if system.parachute is not None else 0.0
        mp = system.canopy_mass
        mc = system.carrier.mass if isinstance(system.carrier, FreeCarrier) else 0.0
        out = np.zeros((self.eigenvalues.size, len(MOTIONS)))
        for k, lam in enumerate(self.eigenvalues):
            vec = self.vectors[:, k]
            moving = abs(lam) > 1e-9

            def part(vel, pos, vec=vec, moving=moving):
                name = vel if moving else pos
                return abs(vec[idx[name]]) ** 2 if name in idx else 0.0

            rows = [m * part("v_X", "p_X"), m * part("v_Y", "p_Y"), m * part("v_Z", "p_Z"),
                    ixx * part("p", "phi_x"), iyy * part("q", "phi_y"),
                    izz * part("r", "phi_z"),
                    mp * line**2 * (part("theta_dot", "theta") + part("psi_dot", "psi")),
                    mc * (part("Vc_X", "Vc_X") + part("Vc_Y", "Vc_Y")
                          + part("Vc_Z", "Vc_Z"))]
            total = sum(rows)
            out[k] = np.array(rows) / total if total > 0 else 0.0
        return out

    def angles(self):
        """Angular amplitude of each motion group in each mode, largest 1, shape (n, 4):
        longitudinal (cable swing or pitch), lateral (cable swing or roll), yaw, parachute line.
        Swing angles are CG displacements over the cable span.

        Returns
        -------
        ndarray, shape (n, 4)
            Amplitudes, the largest of each row 1. [-]
        """
        idx = {name: i for i, name in enumerate(self.names)}
        span = self.trim.quantity("cable_span")
        out = np.zeros((self.eigenvalues.size, 4))
        for k in range(self.eigenvalues.size):
            v = np.abs(self.vectors[:, k])
            swing_x, swing_y = v[idx["p_X"]] / span, v[idx["p_Y"]] / span
            chute = max(v[idx["theta"]], v[idx["psi"]]) if "theta" in idx else 0.0
            row = np.array([max(swing_x, v[idx["phi_y"]]), max(swing_y, v[idx["phi_x"]]),
                            v[idx["phi_z"]], chute])
            out[k] = row / row.max() if row.max() > 0 else row
        return out

    def _name(self, k, shares, angles):
        """Name of mode k: cable stretch, carrier or parachute by kinetic energy (> 50 %),
        otherwise the group of largest angular amplitude among longitudinal, lateral and yaw
        (swing when the cable angle is at least 30 % of the airframe angle, else pitch or roll),
        with the second group if >= 25 % of it, the two always in the order of
        :data:`NAME_ORDER` (yaw, lateral, longitudinal), so that a mode has one name whichever
        of its groups leads. (The line's hinge angles are measured in body axes and follow
        every airframe rotation, so they do not name a mode.)"""
        if shares[k][MOTIONS.index("cable stretch")] > 0.5:
            return "cable stretch"
        if shares[k][MOTIONS.index("carrier")] > 0.5:
            return "carrier"
        if shares[k][MOTIONS.index("parachute")] > 0.5:
            return "parachute"
        idx = {name: i for i, name in enumerate(self.names)}
        v = np.abs(self.vectors[:, k])
        span = self.trim.quantity("cable_span")

        def label(group):
            if group == 0:
                return ("longitudinal swing" if v[idx["p_X"]] / span >= 0.3 * v[idx["phi_y"]]
                        else "pitch")
            if group == 1:
                return ("lateral swing" if v[idx["p_Y"]] / span >= 0.3 * v[idx["phi_x"]]
                        else "roll")
            return ("yaw", "parachute")[group - 2]

        order = np.argsort(angles[k][:3])[::-1]
        groups = [order[0]] + ([order[1]] if angles[k][order[1]] >= 0.25 else [])
        # one name per motion pair, whichever leads: the groups in the fixed order of
        # NAME_ORDER ("yaw / lateral swing", never "lateral swing / yaw")
        return " / ".join(label(g) for g in sorted(groups, key=NAME_ORDER.index))

    def modes_frame(self):
        """One row per mode (complex pairs once): eigenvalue, frequency, damping, name (unique:
        ``parachute 1``, ``parachute 2`` from the lowest frequency when two modes share one),
        the share of each motion in its kinetic energy and the angular amplitudes of the
        groups.

        Returns
        -------
        pandas.DataFrame
            Sorted by natural frequency: real part [1/s], imaginary part and natural frequency
            [rad/s], damping ratio [-], kind, stability, group amplitudes and energy shares [-].
        """
        lam = self.eigenvalues
        keep = lam.imag >= -1e-12
        shares = self.shares()
        angles = self.angles()
        rows = []
        for k in np.nonzero(keep)[0]:
            value = lam[k]
            wn = abs(value)
            oscillatory = value.imag > 1e-9
            row = {"mode": self._name(k, shares, angles), "real [1/s]": value.real,
                   "imag [rad/s]": value.imag, "natural frequency [rad/s]": wn,
                   "damping ratio [-]": -value.real / wn if wn > 0 else np.nan,
                   "period [s]": 2 * np.pi / value.imag if oscillatory else np.inf,
                   "time to half or double [s]": (np.log(2) / abs(value.real)
                                                  if abs(value.real) > 0 else np.inf),
                   "kind": "oscillatory" if oscillatory else "aperiodic",
                   "stable": bool(value.real < -STABILITY_TOLERANCE)}
            for j, group in enumerate(("longitudinal", "lateral", "yaw", "parachute")):
                row[f"{group} amplitude [-]"] = angles[k][j]
            for j, motion in enumerate(MOTIONS):
                row[f"{motion} energy share [-]"] = shares[k][j]
            rows.append(row)
        frame = pd.DataFrame(rows).sort_values("natural frequency [rad/s]", kind="stable")
        frame = frame.reset_index(drop=True)
        # names are unique: modes of one name are numbered from the lowest frequency
        counts = frame["mode"].value_counts()
        seen = {}
        names = []
        for name in frame["mode"]:
            if counts[name] > 1:
                seen[name] = seen.get(name, 0) + 1
                name = f"{name} {seen[name]}"
            names.append(name)
        frame["mode"] = names
        return frame

    def to_frame(self):
        """The modes (see :meth:`modes_frame`).

        Returns
        -------
        pandas.DataFrame
            :meth:`modes_frame`.
        """
        return self.modes_frame()

    def mode_state(self, eigenvalue, amplitude=0.01):
        """Full state of the trim perturbed along the real part of the mode nearest to
        ``eigenvalue`` [1/s], scaled so that its largest angle or swing angle is ``amplitude``
        [rad] (a free response that excites that mode alone, to linear order).

        Parameters
        ----------
        eigenvalue : complex
            Eigenvalue near the mode. [1/s]
        amplitude : float
            Largest angle or swing angle of the perturbation. [rad]

        Returns
        -------
        ndarray, shape (N_STATES,)
            Full state. [m, m/s, -, rad/s, rad]
        """
        k = int(np.argmin(np.abs(self.eigenvalues - eigenvalue)))
        vec = self.vectors[:, k]
        vec = vec * np.exp(-1j * np.angle(vec[np.argmax(np.abs(vec))]))
        z = vec.real
        idx = {name: i for i, name in enumerate(self.names)}
        span = self.trim.quantity("cable_span")
        biggest = max(abs(z[idx["phi_x"]]), abs(z[idx["phi_y"]]), abs(z[idx["phi_z"]]),
                      abs(z[idx["p_X"]]) / span, abs(z[idx["p_Y"]]) / span)
        return perturbed_state(self.trim, self.names, z * amplitude / biggest)


def _coordinates(system):
    names = []
    if isinstance(system.carrier, FreeCarrier):
        names += ["Vc_X", "Vc_Y", "Vc_Z"]
    names += ["p_X", "p_Y", "p_Z", "v_X", "v_Y", "v_Z", "phi_x", "phi_y", "phi_z", "p", "q",
              "r"]
    if system.parachute is not None and system.parachute.kind == "hinged":
        names += ["theta", "psi", "theta_dot", "psi_dot"]
    return tuple(names)


_FULL = {"Vc_X": 0, "Vc_Y": 1, "Vc_Z": 2, "p_X": 3, "p_Y": 4, "p_Z": 5, "v_X": 6, "v_Y": 7,
         "v_Z": 8, "p": 13, "q": 14, "r": 15, "theta": 16, "psi": 17, "theta_dot": 18,
         "psi_dot": 19}


def perturbed_states(trim_point, names, z):
    """Full states of the trim plus the perturbations ``z`` (m, n) in the coordinates
    ``names``, shape (m, 20).

    Parameters
    ----------
    trim_point : Trim
    names : sequence of str
        Coordinates of the linear model (:attr:`LinearModel.names`: positions [m], small
        rotations ``phi_x``, ``phi_y``, ``phi_z`` and line angles [rad], and their rates).
    z : array_like, shape (m, n)
        Perturbations in those coordinates. [m, m/s, rad, rad/s]

    Returns
    -------
    ndarray, shape (m, N_STATES)
        Full states (the quaternion rotated by the small rotation). [m, m/s, -, rad/s, rad]
    """
    return _perturbed(trim_point.state[None, :], names, z)[0]


def _perturbed(states, names, z):
    """Full states (t, m, 20) of trim states ``states`` (t, 20) plus the perturbations ``z``
    (m, n) in the coordinates ``names``."""
    z = np.atleast_2d(np.asarray(z, float))
    x = np.repeat(states[:, None, :], z.shape[0], axis=1)
    for k, name in enumerate(names):
        if name in _FULL:
            x[:, :, _FULL[name]] += z[:, k]
    phi = z[:, [names.index(n) for n in ("phi_x", "phi_y", "phi_z")]]
    x[:, :, 9:13] = small_rotation(states[:, None, 9:13], phi)
    return x


def perturbed_state(trim_point, names, z):
    """Full state of the trim plus the perturbation ``z`` in the coordinates ``names``.

    Parameters
    ----------
    trim_point : Trim
    names : sequence of str
        Coordinates of the linear model (:attr:`LinearModel.names`: positions [m], small
        rotations ``phi_x``, ``phi_y``, ``phi_z`` and line angles [rad], and their rates).
    z : array_like, shape (n,)
        Perturbation in those coordinates. [m, m/s, rad, rad/s]

    Returns
    -------
    ndarray, shape (N_STATES,)
        Full state. [m, m/s, -, rad/s, rad]
    """
    return perturbed_states(trim_point, names, z)[0]


def coordinate_rates(trim_point, names, dx):
    """Derivatives (m, 20) of the full state expressed in the coordinates ``names`` (the
    small rotation's rate from the quaternion's: 2 conj(q_trim) (x) q').

    Parameters
    ----------
    trim_point : Trim
    names : sequence of str
        Coordinates of the linear model (:attr:`LinearModel.names`: positions [m], small
        rotations ``phi_x``, ``phi_y``, ``phi_z`` and line angles [rad], and their rates).
    dx : array_like, shape (m, N_STATES)
        Derivatives of full states. [m/s, m/s^2, 1/s, rad/s^2, rad/s]

    Returns
    -------
    ndarray, shape (m, n)
        The derivatives in the coordinates ``names``. [m/s, m/s^2, rad/s, rad/s^2]
    """
    return _coordinate_rates(trim_point.state[None, 9:13], names,
                             np.atleast_2d(dx)[None])[0]


def _coordinate_rates(attitudes, names, dx):
    """:func:`coordinate_rates` of trims of attitudes (t, 4), derivatives (t, m, 20)."""
    dphi = 2.0 * quaternion_product(conjugate(attitudes[:, None, :]), dx[:, :, 9:13])[..., 1:]
    out = np.empty(dx.shape[:2] + (len(names),))
    for k, name in enumerate(names):
        out[:, :, k] = (dx[:, :, _FULL[name]] if name in _FULL
                        else dphi[:, :, "xyz".index(name[-1])])
    return out


def linearise(trim_point, *, step=1e-6):
    """Linear model about a trim (module notes).

    Parameters
    ----------
    trim_point : Trim
        A converged trim.
    step : float
        Central-difference step in each coordinate. [m, m/s, rad, rad/s]

    Returns
    -------
    LinearModel
    """
    trim_point._require()
    system = trim_point.system
    names = _coordinates(system)
    n = len(names)
    z = np.vstack([step * np.eye(n), -step * np.eye(n)])
    dx, _, _ = evaluate_many(perturbed_states(trim_point, names, z),
                             system.parameters(locks=system.locks), trim_point.drive,
                             system.tables())
    rates = coordinate_rates(trim_point, names, dx)
    a = ((rates[:n] - rates[n:]) / (2 * step)).T
    values, vectors = eig(a)
    return LinearModel(trim_point, a, names, values, vectors)


def fastest_rates(trim_points, *, step=1e-6):
    """Largest |eigenvalue| [1/s] of the linear model (:func:`linearise`) of each trim (NaN
    for one that did not converge): the state matrices of trims that share their coordinates
    and tables from one evaluation of the equations, eigenvalues only.

    Parameters
    ----------
    trim_points : sequence of Trim
    step : float
        Central-difference step in each coordinate (as :func:`linearise`).
        [m, m/s, rad, rad/s]

    Returns
    -------
    ndarray, shape (len(trim_points),)
        [1/s]
    """
    out = np.full(len(trim_points), np.nan)
    groups = {}
    for k, point in enumerate(trim_points):
        if point.converged:
            key = (_coordinates(point.system), point.system.table_key())
            groups.setdefault(key, []).append(k)
    for (names, _), members in groups.items():
        n = len(names)
        z = np.vstack([step * np.eye(n), -step * np.eye(n)])
        points = [trim_points[k] for k in members]
        trims = np.array([p.state for p in points])
        states = _perturbed(trims, names, z).reshape(-1, N_STATES)
        params = np.repeat([p.system.parameters(locks=p.system.locks) for p in points],
                           2 * n, axis=0)
        drives = np.repeat([p.drive for p in points], 2 * n, axis=0)
        dx, _, _ = evaluate_many(states, params, drives, points[0].system.tables())
        rates = _coordinate_rates(trims[:, 9:13], names, dx.reshape(len(points), 2 * n, -1))
        a = np.transpose((rates[:, :n] - rates[:, n:]) / (2 * step), (0, 2, 1))
        out[members] = np.max(np.abs(np.linalg.eigvals(a)), axis=1)
    return out


def attitude_matrix(state):
    """R (body to earth) of a full state vector.

    Parameters
    ----------
    state : array_like, shape (N_STATES,)
        Full state (quaternion in elements 9 to 12). [m, m/s, -, rad/s, rad]

    Returns
    -------
    ndarray, shape (3, 3)
        Rotation matrix, body to earth. [-]
    """
    return rotation_matrix(np.asarray(state, float)[9:13])

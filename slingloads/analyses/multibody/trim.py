"""Steady towed flight (trim) and the linear model about it.

**Trim.** At a given airspeed the carrier flies at constant velocity, the HC moves with it
without rotating and the parachute line is still. The unknowns are the CG position relative to
the hook (3), the attitude (yaw, pitch, roll) and, with a hinged parachute, the line angles
(theta, psi); the equations are zero CG acceleration, zero angular acceleration and zero hinge
accelerations, solved by :func:`scipy.optimize.root` from the hanging position (cable at the
drag-over-weight angle, level attitude, line trailing). Below the aerodynamic cut-off (hover)
the yaw is free and held at the guess. A trim whose equations cannot be met, that needs a
slack cable or lies outside a table is reported as such (:attr:`Trim.converged` False and
:attr:`Trim.message`), never as a number.

**Linearisation** about a trim: central differences of the compiled equations in the
perturbation coordinates (carrier velocity when free, CG position and velocity, a small
rotation vector in body axes, body rates, hinge angles and rates), eigenvalues and modes, each
mode named after the motion that holds most of its kinetic energy.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.linalg import eig
from scipy.optimize import root

from slingloads.errors import InputError
from slingloads.models.multibody.carrier import FreeCarrier
from slingloads.models.multibody.equations import FLAGS, INFO, N_INFO, N_STATES, evaluate
from slingloads.models.multibody.parachute_line import line_angles
from slingloads.models.multibody.rigid_body import (
    euler_angles,
    quaternion_from_euler,
    rotation_matrix,
    small_rotation,
)

#: Residual (scaled accelerations) below which a trim is accepted. [-]
TRIM_TOLERANCE = 1e-9
#: Real part [1/s] above which an eigenvalue counts as unstable (round-off allowance).
STABILITY_TOLERANCE = 1e-6

_INFO = {name: i for i, name in enumerate(INFO)}


def flag_text(flag):
    """Readable list of the tables or limits in a flag of the equations."""
    return ", ".join(text for bit, text in FLAGS.items() if int(flag) & bit)


def steady_drive(wind, carrier_velocity):
    """Drive vector of a steady flight: wind, no commanded acceleration, commanded velocity."""
    return np.concatenate([np.asarray(wind, float), np.zeros(3),
                           np.asarray(carrier_velocity, float)])


def evaluate_state(system, x, drive, parameters=None, tables=None):
    """(derivative, info, flag) of the equations at state ``x`` with ``drive``."""
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
        Full state of the equations at trim.
    drive : ndarray, shape (9,)
        Wind, commanded acceleration and velocity at trim.
    converged : bool
    message : str
    residual : float
        Largest scaled acceleration left. [-]
    info : ndarray
        Reported quantities at trim (:data:`~slingloads.models.multibody.equations.INFO`).
    """

    system: object
    airspeed: float
    state: np.ndarray
    drive: np.ndarray
    converged: bool
    message: str
    residual: float
    info: np.ndarray

    def _require(self):
        if not self.converged:
            raise InputError(f"no trim at {self.airspeed:.4g} m/s EAS: {self.message}")

    def quantity(self, name):
        """A reported quantity of :data:`INFO` at trim."""
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
        """The trim as a one-row DataFrame (angles in degrees)."""
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


def _drag_estimate(system, tas):
    """Rough drag [N] of fuselage and parachute, to start the trim at a sensible swing."""
    q = 0.5 * system.density * tas**2
    area = 0.0
    if system.fuselage is not None:
        area += system.fuselage.area * float(system.fuselage.drag_coefficient(0.0, 0.0))
    if system.parachute is not None:
        area += float(system.parachute.parachute.drag_area(0.0))
    return q * area


def trim(system, airspeed=None, *, wind=(0.0, 0.0, 0.0), yaw_guess=0.0):
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

    Returns
    -------
    Trim
    """
    eas = system.airspeed if airspeed is None else float(airspeed)
    if not np.isfinite(eas) or eas < 0:
        raise InputError("trim airspeed must be >= 0 [m/s]", eas)
    sys_at = system.with_(airspeed=eas)
    tas = sys_at.true_airspeed
    params, tables = sys_at.parameters(), sys_at.tables()  # trim the unrestricted system
    x0 = _initial_state(sys_at, tas, wind)
    drive = steady_drive(wind, x0[0:3])
    hinged = sys_at.parachute is not None and sys_at.parachute.kind == "hinged"
    hover = tas < sys_at.aero_cutoff
    w = sys_at.weight
    hub = sys_at.hardpoints.hub - sys_at.body.cg
    swing = np.arctan2(_drag_estimate(sys_at, tas), w)
    span = sys_at.cable.length + sys_at.cable.static_stretch(w / np.cos(swing))
    guess = [span * np.sin(swing) - hub[0], -hub[1], -span * np.cos(swing) - hub[2]]
    guess += [] if hover else [yaw_guess]
    guess += [swing, 0.0]
    if hinged:
        guess += [x0[16], 0.0]
    guess = np.array(guess)
    inertia = np.diag(sys_at.body.inertia)
    g = sys_at.gravity

    def unpack(u):
        x = x0.copy()
        x[3:6] = u[0:3]
        k = 3
        yaw = yaw_guess if hover else u[k]
        k += 0 if hover else 1
        x[9:13] = quaternion_from_euler(yaw, u[k], u[k + 1])
        k += 2
        if hinged:
            x[16:18] = u[k:k + 2]
        return x

    def residual(u):
        x = unpack(u)
        dx, _, _ = evaluate_state(sys_at, x, drive, params, tables)
        r = list(dx[6:9] / g)
        scale = sys_at.body.mass * g * 1.0 / inertia
        rot = dx[13:16] / scale
        r += list(rot[[0, 1]]) + ([] if hover else [rot[2]])
        if hinged:
            r += list(dx[18:20] / g)
        return np.array(r)

    solution = root(residual, guess, method="hybr", options={"xtol": 1e-13})
    x = unpack(solution.x)
    dx, info, flag = evaluate_state(sys_at, x, drive, params, tables)
    res = float(np.max(np.abs(residual(solution.x))))
    converged, message = True, "trimmed"
    if not np.all(np.isfinite(solution.x)) or res > TRIM_TOLERANCE:
        converged = False
        message = (f"the equilibrium equations cannot be met (largest scaled residual "
                   f"{res:.3g}; solver: {solution.message})")
    elif flag:
        converged = False
        message = f"the only equilibrium found lies outside the {flag_text(flag)}"
    elif info[_INFO["tension"]] <= 0:
        converged = False
        message = "the equilibrium found needs a slack cable"
    return Trim(sys_at, eas, x, drive, converged, message, res, info)


# =============================================================================== linear
#: Motions the modes are named after, and the kinetic energy each is measured by.
MOTIONS = ("longitudinal swing", "lateral swing", "cable stretch", "roll", "pitch", "yaw",
           "parachute", "carrier")


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
        Right eigenvectors (columns).
    """

    trim: Trim
    a: np.ndarray
    names: tuple
    eigenvalues: np.ndarray
    vectors: np.ndarray

    @property
    def stable(self):
        """True when every eigenvalue has a real part below -:data:`STABILITY_TOLERANCE`
        (strictly) or within it (neutral): no mode grows."""
        return bool(np.all(self.eigenvalues.real <= STABILITY_TOLERANCE))

    def verdict(self):
        """"stable", "neutral" (some real parts within round-off of 0) or "unstable", with
        the rule."""
        re = self.eigenvalues.real
        if np.any(re > STABILITY_TOLERANCE):
            return "unstable"
        if np.any(np.abs(re) <= STABILITY_TOLERANCE):
            return "neutral"
        return "stable"

    def a_frame(self):
        """The state matrix A as a DataFrame (rows: derivative of, columns: coordinate)."""
        return pd.DataFrame(self.a, index=list(self.names), columns=list(self.names))

    def shares(self):
        """Share of each motion of :data:`MOTIONS` in each mode's kinetic energy, (n, 8)."""
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
        Swing angles are CG displacements over the cable span."""
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
        with the second group if >= 25 % of it. (The line's hinge angles are measured in body
        axes and follow every airframe rotation, so they do not name a mode.)"""
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
        name = label(order[0])
        if angles[k][order[1]] >= 0.25:
            name = f"{name} / {label(order[1])}"
        return name

    def modes_frame(self):
        """One row per mode (complex pairs once): eigenvalue, frequency, damping, name, the
        share of each motion in its kinetic energy and the angular amplitudes of the groups."""
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
                   "stable": bool(value.real <= STABILITY_TOLERANCE)}
            for j, group in enumerate(("longitudinal", "lateral", "yaw", "parachute")):
                row[f"{group} amplitude [-]"] = angles[k][j]
            for j, motion in enumerate(MOTIONS):
                row[f"{motion} energy share [-]"] = shares[k][j]
            rows.append(row)
        frame = pd.DataFrame(rows)
        return frame.sort_values("natural frequency [rad/s]", kind="stable").reset_index(
            drop=True)

    def to_frame(self):
        """The modes (see :meth:`modes_frame`)."""
        return self.modes_frame()

    def mode_state(self, eigenvalue, amplitude=0.01):
        """Full state of the trim perturbed along the real part of the mode nearest to
        ``eigenvalue`` [1/s], scaled so that its largest angle or swing angle is ``amplitude``
        [rad] (a free response that excites that mode alone, to linear order)."""
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


def _quat_conj_mul(a, b):
    """conj(a) (x) b."""
    a0, a1, a2, a3 = a[0], -a[1], -a[2], -a[3]
    b0, b1, b2, b3 = b
    return np.array([a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
                     a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                     a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
                     a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0])


def perturbed_state(trim_point, names, z):
    """Full state of the trim plus the perturbation ``z`` in the coordinates ``names``."""
    x = trim_point.state.copy()
    for k, name in enumerate(names):
        if name in _FULL:
            x[_FULL[name]] += z[k]
    phi = [z[names.index(n)] for n in ("phi_x", "phi_y", "phi_z")]
    x[9:13] = small_rotation(trim_point.state[9:13], phi)
    return x


def linearise(trim_point, *, step=1e-6):
    """Linear model about a trim (module notes).

    Parameters
    ----------
    trim_point : Trim
        A converged trim.
    step : float
        Central-difference step, in SI units of each coordinate.

    Returns
    -------
    LinearModel
    """
    trim_point._require()
    system = trim_point.system
    names = _coordinates(system)
    params, tables = system.parameters(locks=system.locks), system.tables()
    q_trim = trim_point.state[9:13]

    def rate(z):
        x = perturbed_state(trim_point, names, z)
        dx, _, _ = evaluate_state(system, x, trim_point.drive, params, tables)
        out = np.zeros(len(names))
        dphi = 2.0 * _quat_conj_mul(q_trim, dx[9:13])[1:]
        for k, name in enumerate(names):
            if name in _FULL:
                out[k] = dx[_FULL[name]]
            else:
                out[k] = dphi["xyz".index(name[-1])]
        return out

    n = len(names)
    a = np.zeros((n, n))
    for k in range(n):
        dz = np.zeros(n)
        dz[k] = step
        a[:, k] = (rate(dz) - rate(-dz)) / (2 * step)
    values, vectors = eig(a)
    return LinearModel(trim_point, a, names, values, vectors)


def attitude_matrix(state):
    """R (body to earth) of a full state vector."""
    return rotation_matrix(np.asarray(state, float)[9:13])

"""Lateral-plane pendulum: the carried helicopter hung from the carrier's moving hook.

Planar model in the lateral plane (airframe y-z plane: y right, z up; viewed from behind,
looking forward). The hook moves along y with a prescribed S(t). A massless cable of
unstretched length l runs from the hook to the rotor hub of the carried helicopter (HC),
a rigid body of mass m, roll inertia :math:`I = m k^2` about its CG, its CG a distance e below
the hub along the mast. Gravity acts along -z. The derivation is in
``docs/lateral-pendulum.md``.

Angles, both positive by the right-hand rule about +x (counter-clockwise in the view above):

* ``theta1``: rope angle from the vertical; the hub sits at
  :math:`\\text{hook} + l(\\sin\\theta_1, -\\cos\\theta_1)`, so theta1 > 0 has the hub to the
  right of the hook.
* ``theta2``: airframe (mast) angle from the vertical; the CG sits at
  :math:`\\text{hub} + e(\\sin\\theta_2, -\\cos\\theta_2)`. The airframe's **roll** in the
  product's attitude convention (aerospace Euler angle, right side down positive,
  ``docs/conventions.md`` section 8) is ``-theta2``; results and reports give that roll,
  theta1 and theta2 being the generalised coordinates of the equations.
* ``theta1 - theta2``: the load angle, the angle of the cable force at the hub from the mast
  axis, the angle that CS-29.865 sets to at least 30 deg.

Two cable models:

* rigid rope (``cable_ea=None``): states ``(theta1, theta2, theta1', theta2')``; the tension
  follows from the motion and is reported even where it is negative (the rope would go slack,
  which this model cannot represent; results flag it).
* elastic cable, tension only: states ``(ry, rz, theta2, ry', rz', theta2')`` with
  ``r`` the hub position relative to the hook; tension :math:`T = (EA/l)\\max(|r| - l, 0)`,
  so the cable goes slack when it is shorter than its unstretched length.

References
----------
.. [1] L. Meirovitch, "Methods of Analytical Dynamics", McGraw-Hill, 1970 (Lagrange's
   equations with prescribed support motion).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.checks import finite as _finite
from slingloads.checks import non_negative as _non_negative
from slingloads.checks import positive as _positive
from slingloads.constants import G0
from slingloads.errors import InputError

#: Names of the states of each cable model, in order.
RIGID_STATES = ("theta1", "theta2", "theta1_dot", "theta2_dot")
ELASTIC_STATES = ("ry", "rz", "theta2", "ry_dot", "rz_dot", "theta2_dot")
#: Offsets of the rigid rope's states in :data:`RIGID_STATES` (code indexes ``x[R_THETA1]``,
#: never ``x[0]``).
R_THETA1, R_THETA2, R_THETA1_DOT, R_THETA2_DOT = (
    RIGID_STATES.index(n) for n in ("theta1", "theta2", "theta1_dot", "theta2_dot"))
#: Offsets of the elastic cable's states in :data:`ELASTIC_STATES`.
E_RY, E_RZ, E_THETA2, E_RY_DOT, E_RZ_DOT, E_THETA2_DOT = (
    ELASTIC_STATES.index(n) for n in ("ry", "rz", "theta2", "ry_dot", "rz_dot", "theta2_dot"))


@dataclass(frozen=True)
class SlungBody:
    """Mass properties of the carried helicopter in the lateral plane.

    Parameters
    ----------
    mass : float
        m, > 0. [kg]
    roll_inertia : float
        Moment of inertia about the x axis through the CG, > 0. [kg m^2]
    cg_below_hub : float
        e, distance from the rotor hub down the mast to the CG, >= 0 (0 puts the CG at the
        hub: the point-mass limit, where the airframe's rotation decouples). [m]
    name : str
        Label used in tables.
    """

    mass: float
    roll_inertia: float
    cg_below_hub: float
    name: str = "HC"

    def __post_init__(self):
        for name, check, rule in (
                ("mass", _positive, f"mass of {self.name!r} must be > 0 [kg]"),
                ("roll_inertia", _positive, f"roll inertia of {self.name!r} must be > 0 "
                                            "[kg m^2]"),
                ("cg_below_hub", _non_negative, f"CG distance below the hub of {self.name!r} "
                                                "must be >= 0 [m]")):
            try:
                object.__setattr__(self, name, check(getattr(self, name), rule))
            except InputError as err:  # the field names the argument, for the io layer
                raise InputError(err.rule, err.value, field=name) from None

    @property
    def radius_of_gyration(self):
        """k = sqrt(I/m). [m]"""
        return float(np.sqrt(self.roll_inertia / self.mass))


@dataclass(frozen=True)
class LateralPendulum:
    """The carried helicopter on its cable under the carrier's hook.

    Parameters
    ----------
    body : SlungBody
    rope_length : float
        Unstretched cable length l, hook to hub, > 0. [m]
    cable_ea : float or None
        Axial stiffness EA of the cable, > 0 [N]; ``None`` for the rigid (inextensible) rope.
        The cable's spring rate is EA/l.
    lateral_damping : float
        c, linear aerodynamic damping of the lateral velocity of the point of the mast
        ``damping_height`` above the CG, >= 0 (off by default; the parachute is taken to have
        no influence; see :func:`slingloads.analyses.lateral_damping.aerodynamic_damping`). [N s/m]
    roll_damping : float
        c_r, linear aerodynamic damping of the airframe's roll rate, >= 0. [N m s/rad]
    damping_height : float
        h, height along the mast above the CG of the point whose lateral velocity the
        lateral damping opposes (0: the CG). Side-force dampers c_i at heights h_i are
        reproduced exactly at linear order by c = sum c_i, h = sum c_i h_i / c and
        c_r = sum c_i h_i^2 - c h^2. [m]
    gravity : float
        [m/s^2]
    """

    body: SlungBody
    rope_length: float
    cable_ea: float | None = None
    lateral_damping: float = 0.0
    roll_damping: float = 0.0
    gravity: float = G0
    damping_height: float = 0.0

    def __post_init__(self):
        if not isinstance(self.body, SlungBody):
            raise InputError("the pendulum's body must be a SlungBody",
                             type(self.body).__name__)
        object.__setattr__(self, "rope_length", _positive(
            self.rope_length, "rope length must be > 0 [m]"))
        if self.cable_ea is not None:
            object.__setattr__(self, "cable_ea", _positive(
                self.cable_ea, "cable axial stiffness EA must be > 0 [N] (None: rigid rope)"))
        object.__setattr__(self, "lateral_damping", _non_negative(
            self.lateral_damping, "lateral damping must be >= 0 [N s/m]"))
        object.__setattr__(self, "roll_damping", _non_negative(
            self.roll_damping, "roll damping must be >= 0 [N m s/rad]"))
        object.__setattr__(self, "damping_height", _finite(
            self.damping_height, "damping height must be a finite number [m]"))
        object.__setattr__(self, "gravity", _positive(
            self.gravity, "gravity must be > 0 [m/s^2]"))

    @property
    def rigid(self):
        """True for the rigid-rope model."""
        return self.cable_ea is None

    @property
    def weight(self):
        """m g. [N]"""
        return self.body.mass * self.gravity

    @property
    def cable_stiffness(self):
        """Spring rate EA/l of the cable (inf for the rigid rope). [N/m]"""
        return np.inf if self.rigid else self.cable_ea / self.rope_length

    @property
    def hanging_length(self):
        """Hook-to-hub distance when hanging at rest, stretched by m g / (EA/l). [m]"""
        return self.rope_length * (1.0 + (0.0 if self.rigid else self.weight / self.cable_ea))

    @property
    def state_names(self):
        """Names of the state variables, in order."""
        return RIGID_STATES if self.rigid else ELASTIC_STATES

    def arrays(self):
        """Parameters as a dict of floats in the argument order of the derivative functions.

        Returns
        -------
        dict of str to float
            mass [kg], inertia [kg m^2], e [m], length [m], stiffness [N/m], c_lat [N s/m],
            c_roll [N m s/rad], g [m/s^2], h_d [m].
        """
        return {
            "mass": self.body.mass, "inertia": self.body.roll_inertia,
            "e": self.body.cg_below_hub, "length": self.rope_length,
            "stiffness": self.cable_stiffness,
            "c_lat": self.lateral_damping, "c_roll": self.roll_damping, "g": self.gravity,
            "h_d": self.damping_height,
        }

    def initial_state(self, velocity_jump=0.0):
        """State just after t = 0: hanging at rest, then the hook's speed jumps by ``dV``.

        For the rigid rope, the impulse through the rope leaves the hub at rest (the rope is
        vertical, normal to the jump), so :math:`\\dot\\theta_1 = -dV/l`,
        :math:`\\dot\\theta_2 = 0`; for the elastic cable the hub's velocity relative to the
        hook is :math:`-dV` along y.

        Parameters
        ----------
        velocity_jump : float
            dV, jump of the hook's lateral speed at t = 0. [m/s]

        Returns
        -------
        ndarray, shape (4,) or (6,)
            State: theta1, theta2 [rad] and their rates [rad/s] (rigid rope), or ry, rz [m], theta2
            [rad] and their rates [m/s, m/s, rad/s] (elastic cable).
        """
        if self.rigid:
            return np.array([0.0, 0.0, -velocity_jump / self.rope_length, 0.0])
        return np.array([0.0, -self.hanging_length, 0.0, -velocity_jump, 0.0, 0.0])

    def derivatives(self, x, s_vel, s_acc):
        """State derivative and cable tension; see :func:`rigid_rope_derivatives` and
        :func:`elastic_cable_derivatives`.

        Parameters
        ----------
        x : array_like, shape (states, ...)
            State. [m, rad, m/s, rad/s]
        s_vel, s_acc : array_like
            Hook's lateral velocity [m/s] and acceleration [m/s^2].

        Returns
        -------
        dx : ndarray, shape (states, ...)
            [state units / s]
        tension : ndarray
            [N]
        """
        function = rigid_rope_derivatives if self.rigid else elastic_cable_derivatives
        return function(x, s_vel, s_acc, **self.arrays())

    def mass_matrix(self):
        """Linearised mass matrix in (theta1, theta2), about the hanging equilibrium. [kg m^2]

        .. math:: M = m \\begin{bmatrix} l^2 & l e \\\\ l e & e^2 + k^2 \\end{bmatrix}

        with l the hanging (stretched) length for the elastic cable.

        Returns
        -------
        ndarray, shape (2, 2)
            [kg m^2]
        """
        m, e, length = self.body.mass, self.body.cg_below_hub, self.hanging_length
        k2 = self.body.roll_inertia / m
        return m * np.array([[length**2, length * e], [length * e, e * e + k2]])

    def stiffness_matrix(self):
        """Linearised stiffness matrix in (theta1, theta2): diag(m g l, m g e).

        Returns
        -------
        ndarray, shape (2, 2)
            [N m]
        """
        w, e, length = self.weight, self.body.cg_below_hub, self.hanging_length
        return np.diag([w * length, w * e])

    def linear_modes(self):
        """Natural frequencies and mode shapes about the hanging equilibrium.

        Solves :math:`(K - \\omega^2 M)\\,\\phi = 0` for the two swinging modes in
        (theta1, theta2); the elastic cable adds the vertical bounce mode
        :math:`\\omega^2 = (EA/l)/m`, which is uncoupled from the swing at linear order.

        Returns
        -------
        LinearModes
        """
        from scipy.linalg import eigh  # scipy loads where it is used (docs/reports.md)

        w2, phi = eigh(self.stiffness_matrix(), self.mass_matrix())
        w2 = np.clip(w2, 0.0, None)  # e = 0 gives an exact zero (free rotation) mode
        big = np.argmax(np.abs(phi), axis=0)
        phi = phi / phi[big, np.arange(phi.shape[1])]
        omega = np.sqrt(w2)
        shapes = np.column_stack([phi.T, np.zeros(2)])
        kinds = ["swing", "swing"]
        if not self.rigid:
            omega = np.append(omega, np.sqrt(self.cable_stiffness / self.body.mass))
            shapes = np.vstack([shapes, [0.0, 0.0, 1.0]])
            kinds.append("bounce")
        order = np.argsort(omega)
        return LinearModes(omega[order], shapes[order], tuple(np.array(kinds)[order]))


@dataclass(frozen=True, eq=False)
class LinearModes:
    """Natural frequencies and mode shapes of the hanging pendulum.

    Parameters
    ----------
    omega : ndarray, shape (n,)
        Circular natural frequencies, ascending. [rad/s]
    shapes : ndarray, shape (n, 3)
        Mode shapes in (theta1 [rad], theta2 [rad], vertical hub displacement [m]), scaled so
        that the largest component is 1. [-]
    kinds : tuple of str
        ``"swing"`` or ``"bounce"`` per mode.
    """

    omega: np.ndarray
    shapes: np.ndarray
    kinds: tuple

    @property
    def frequency(self):
        """Natural frequencies. [Hz]"""
        return self.omega / (2.0 * np.pi)

    @property
    def period(self):
        """Natural periods (inf for a zero-frequency mode). [s]"""
        with np.errstate(divide="ignore"):
            return np.where(self.omega > 0, 2.0 * np.pi / np.where(self.omega > 0,
                                                                  self.omega, 1.0), np.inf)

    def to_frame(self):
        """Modes as a DataFrame with unit-labelled columns.

        Returns
        -------
        pandas.DataFrame
            A row per mode: omega [rad/s], f [Hz], period [s], mode shapes [-]: rope
            angle theta1, the airframe's roll (right side down positive, ``-theta2``: the
            product's attitude convention, ``docs/conventions.md`` section 8) and the bounce.
        """
        return pd.DataFrame({
            "mode": np.arange(1, self.omega.size + 1), "kind": list(self.kinds),
            "omega [rad/s]": self.omega, "f [Hz]": self.frequency, "period [s]": self.period,
            "theta1 shape [-]": self.shapes[:, 0], "roll shape [-]": 0.0 - self.shapes[:, 1],
            "bounce shape [-]": self.shapes[:, 2],
        })


def rigid_rope_derivatives(x, s_vel, s_acc, mass, inertia, e, length, stiffness=np.inf,
                           c_lat=0.0, c_roll=0.0, g=G0, h_d=0.0):
    """Equations of motion with a rigid rope (Lagrange, coordinates theta1, theta2).

    .. math::

        m l^2 \\ddot\\theta_1 + m l e \\cos\\Delta\\,\\ddot\\theta_2
          = -m l e \\sin\\Delta\\,\\dot\\theta_2^2 - m g l \\sin\\theta_1
            - m l \\cos\\theta_1 \\ddot S - c\\,\\dot y_P\\, l\\cos\\theta_1

        m l e \\cos\\Delta\\,\\ddot\\theta_1 + m (e^2 + k^2) \\ddot\\theta_2
          = m l e \\sin\\Delta\\,\\dot\\theta_1^2 - m g e \\sin\\theta_2
            - m e \\cos\\theta_2 \\ddot S - c\\,\\dot y_P\\, (e - h)\\cos\\theta_2
            - c_r \\dot\\theta_2

    with :math:`\\Delta = \\theta_1 - \\theta_2` and :math:`\\dot y_P = \\dot S + l\\cos\\theta_1
    \\dot\\theta_1 + (e - h)\\cos\\theta_2\\dot\\theta_2` the lateral speed of the damped point,
    h above the CG along the mast (the CG for h = 0).

    Every argument broadcasts, so ``x`` of shape (4, runs) with parameter arrays of shape
    (runs,) integrates a whole sweep at once.

    Parameters
    ----------
    x : array_like, shape (4, ...)
        theta1 [rad], theta2 [rad], their rates [rad/s].
    s_vel, s_acc : array_like
        Hook velocity [m/s] and acceleration [m/s^2].
    mass : [kg]
    inertia : roll inertia about the CG [kg m^2]
    e : CG below hub [m]
    length : rope length [m]
    stiffness : unused (the rope is rigid)
    c_lat : lateral damping [N s/m]
    c_roll : roll damping [N m s/rad]
    g : gravity [m/s^2]
    h_d : height above the CG of the damped point [m]

    Returns
    -------
    dx : ndarray, shape (4, ...)
        State derivative. [rad/s, rad/s, rad/s^2, rad/s^2]
    tension : ndarray
        Rope tension T, negative where the rope would go slack. [N]
    """
    th1, th2, w1, w2 = x
    *dx, tension = rigid_rope_equations(th1, th2, w1, w2, s_vel, s_acc, mass, inertia, e,
                                        length, c_lat, c_roll, g, h_d)
    return np.stack(dx), tension


def rigid_rope_equations(th1, th2, w1, w2, s_vel, s_acc, mass, inertia, e, length, c_lat,
                         c_roll, g, h_d):
    """The equations of :func:`rigid_rope_derivatives`, written once for numpy and for the
    compiled batch.

    Elementwise operations only, so that the same function runs on arrays (numpy) and, compiled
    by numba, on floats (:func:`slingloads.models.pendulum_batch.rigid_rope`): the two give the
    same numbers to the last bit.

    Parameters
    ----------
    th1, th2 : array_like or float
        Rope and airframe angles. [rad]
    w1, w2 : array_like or float
        Their rates. [rad/s]
    s_vel, s_acc, mass, inertia, e, length, c_lat, c_roll, g, h_d
        As :func:`rigid_rope_derivatives`.

    Returns
    -------
    w1, w2 : array_like or float
        [rad/s]
    a1, a2 : array_like or float
        Angular accelerations. [rad/s^2]
    tension : array_like or float
        Rope tension, negative where the rope would go slack. [N]
    """
    s1, c1, s2, c2 = np.sin(th1), np.cos(th1), np.sin(th2), np.cos(th2)
    sd, cd = np.sin(th1 - th2), np.cos(th1 - th2)
    k2 = inertia / mass
    le = length * e
    yp_dot = s_vel + length * c1 * w1 + (e - h_d) * c2 * w2
    drag = c_lat * yp_dot / mass  # lateral damping force per unit mass
    # divide both equations by m
    f1 = -le * sd * w2 * w2 - g * length * s1 - length * c1 * (s_acc + drag)
    f2 = (le * sd * w1 * w1 - g * e * s2 - e * c2 * s_acc - (e - h_d) * c2 * drag
          - c_roll * w2 / mass)
    m11, m12, m22 = length * length, le * cd, e * e + k2
    det = m11 * m22 - m12 * m12          # = l^2 (k^2 + e^2 sin^2 Delta) > 0
    a1 = (m22 * f1 - m12 * f2) / det
    a2 = (m11 * f2 - m12 * f1) / det
    # tension from Newton along the rope, hub -> hook unit vector u = (-sin th1, cos th1)
    tension = mass * (-s1 * (s_acc + drag) + length * w1 * w1 - e * sd * a2 + e * cd * w2 * w2
                      + g * c1)
    return w1, w2, a1, a2, tension


def elastic_cable_derivatives(x, s_vel, s_acc, mass, inertia, e, length, stiffness,
                              c_lat=0.0, c_roll=0.0, g=G0, h_d=0.0):
    """Equations of motion with an elastic, tension-only cable (Newton-Euler).

    With r the hub position relative to the hook, the cable force on the hub is
    :math:`F = -T\\,r/|r|`, :math:`T = (EA/l)\\max(|r| - l, 0)`, and with
    :math:`c_2 = (\\cos\\theta_2, \\sin\\theta_2)`, :math:`n_2 = (-\\sin\\theta_2, \\cos\\theta_2)`
    the airframe's y and z axes:

    .. math::

        m k^2 \\ddot\\theta_2 = -e\\,F\\cdot c_2 - c_r\\dot\\theta_2
                               + h \\cos\\theta_2\\, c\\,\\dot y_P

        \\ddot r = (F + F_d)/m - g\\,\\hat z - \\ddot S\\,\\hat y
                   - e\\ddot\\theta_2\\, c_2 - e\\dot\\theta_2^2\\, n_2

    with the damping force :math:`F_d = -c\\,\\dot y_P\\,\\hat y` at the point h above the CG,
    :math:`\\dot y_P = \\dot S + \\dot r_y + (e - h)\\cos\\theta_2\\,\\dot\\theta_2`.

    Parameters
    ----------
    x : array_like, shape (6, ...)
        ry [m], rz [m], theta2 [rad], and their rates [m/s, m/s, rad/s].
    s_vel, s_acc, mass, inertia, e, length, c_lat, c_roll, g, h_d
        As :func:`rigid_rope_derivatives`.
    stiffness : float or array_like
        Cable spring rate EA/l. [N/m]

    Returns
    -------
    dx : ndarray, shape (6, ...)
        State derivative. [m/s, m/s, rad/s, m/s^2, m/s^2, rad/s^2]
    tension : ndarray
        Cable tension, >= 0. [N]
    """
    ry, rz, th2, vy, vz, w2 = x
    *dx, tension = elastic_cable_equations(ry, rz, th2, vy, vz, w2, s_vel, s_acc, mass,
                                           inertia, e, length, stiffness, c_lat, c_roll, g,
                                           h_d)
    return np.stack(dx), tension


def elastic_cable_equations(ry, rz, th2, vy, vz, w2, s_vel, s_acc, mass, inertia, e, length,
                            stiffness, c_lat, c_roll, g, h_d):
    """The equations of :func:`elastic_cable_derivatives`, written once for numpy and for
    the compiled batch (elementwise operations only, as :func:`rigid_rope_equations`).

    Parameters
    ----------
    ry, rz : array_like or float
        Hub position from the hook. [m]
    th2 : array_like or float
        Airframe angle. [rad]
    vy, vz, w2 : array_like or float
        Their rates. [m/s, m/s, rad/s]
    s_vel, s_acc, mass, inertia, e, length, stiffness, c_lat, c_roll, g, h_d
        As :func:`elastic_cable_derivatives`.

    Returns
    -------
    vy, vz, w2 : array_like or float
        [m/s, m/s, rad/s]
    ay, az, a2 : array_like or float
        Accelerations. [m/s^2, m/s^2, rad/s^2]
    tension : array_like or float
        Cable tension, >= 0. [N]
    """
    s2, c2 = np.sin(th2), np.cos(th2)
    dist = np.sqrt(ry * ry + rz * rz)
    tension = stiffness * np.maximum(dist - length, 0.0)
    fy = -tension * ry / dist
    fz = -tension * rz / dist
    drag = c_lat * (s_vel + vy + (e - h_d) * c2 * w2)  # -F_d, along y
    a2 = (-e * (fy * c2 + fz * s2) - c_roll * w2 + h_d * c2 * drag) / inertia
    ay = (fy - drag) / mass - s_acc - e * a2 * c2 + e * w2 * w2 * s2
    az = fz / mass - g - e * a2 * s2 - e * w2 * w2 * c2
    return vy, vz, w2, ay, az, a2, tension


def rope_angle(x, rigid):
    """theta1, the rope's angle from the vertical, from a state array.

    Parameters
    ----------
    x : array_like
        State array, first axis the states (rigid rope: theta1, theta2, rates; elastic
        cable: y, z, theta2, rates). [m, rad, m/s, rad/s]
    rigid : bool
        Rigid rope (else elastic cable).

    Returns
    -------
    ndarray
        [rad]
    """
    x = np.asarray(x)
    return x[R_THETA1] if rigid else np.arctan2(x[E_RY], -x[E_RZ])


def airframe_angle(x, rigid):
    """theta2, the airframe's (mast's) angle, a right-hand rotation about +x, from a state
    array; the airframe's roll in the product's convention (right side down positive) is
    ``-theta2``.

    Parameters
    ----------
    x : array_like
        State array, first axis the states (rigid rope: theta1, theta2, rates; elastic
        cable: y, z, theta2, rates). [m, rad, m/s, rad/s]
    rigid : bool
        Rigid rope (else elastic cable).

    Returns
    -------
    ndarray
        [rad]
    """
    x = np.asarray(x)
    return x[R_THETA2] if rigid else x[E_THETA2]


def load_angle(theta1, theta2):
    """theta1 - theta2 wrapped to [-pi, pi): the angle of the cable force from the mast.

    The airframe angle theta2 is continuous (it counts whole turns if the airframe tumbles on
    a slack cable); the angle between two directions is taken modulo a turn.

    Parameters
    ----------
    theta1, theta2 : array_like
        Rope and airframe angles. [rad]

    Returns
    -------
    ndarray
        [rad]
    """
    return np.mod(np.asarray(theta1) - np.asarray(theta2) + np.pi, 2.0 * np.pi) - np.pi


def hub_load_airframe_axes(tension, theta1, theta2):
    """Cable force on the airframe at the hub, in airframe axes.

    The cable pulls the hub towards the hook, along :math:`(-\\sin\\theta_1, \\cos\\theta_1)`;
    rotated into the airframe's y-z axes:

    .. math:: F_y = -T \\sin(\\theta_1 - \\theta_2), \\qquad F_z = T \\cos(\\theta_1 - \\theta_2)

    Parameters
    ----------
    tension : array_like
        [N]
    theta1, theta2 : array_like
        [rad]

    Returns
    -------
    fy, fz : ndarray
        [N]
    """
    load = np.asarray(theta1) - np.asarray(theta2)
    tension = np.asarray(tension)
    return -tension * np.sin(load), tension * np.cos(load)

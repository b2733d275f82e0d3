"""Equations of motion of the towed system, compiled (derivation: ``docs/multibody.md``).

State vector (earth axes X aft along the flight path, Y right, Z up; body axes x aft, y right,
z up), :data:`STATES`:

==========  ===========================================================================
0-2         carrier (hook) velocity V_c, earth axes [m/s]
3-5         HC centre of gravity relative to the hook, p = r - r_hook, earth axes [m]
6-8         HC CG velocity v, earth axes [m/s]
9-12        attitude quaternion q (body to earth) [-]
13-15       body rates omega = (p, q, r), body axes [rad/s]
16-19       parachute hinge angles theta, psi and their rates [rad, rad/s]
==========  ===========================================================================

Newton-Euler for the HC about its CG, with the hinged canopy (mass m_p at s = A + L_p e) and
the line tension T_l as the unknowns of one 3 x 3 system (body axes, a the CG acceleration):

.. math::

    m a &= F + T_l e \\\\
    I \\dot\\omega &= M - \\omega \\times I\\omega + T_l\\, A \\times e \\\\
    m_p [a + \\dot\\omega \\times s + L_p (e_\\theta \\ddot\\theta + e_\\psi \\ddot\\psi)]
        + T_l e &= D + m_p g - m_p [\\omega\\times(\\omega\\times s)
        + 2 L_p\\, \\omega \\times \\dot e + L_p\\, e_2]

F, M: cable, gravity and aerodynamic loads on the HC (M about the CG); D: canopy drag;
e_2 the velocity-squared part of the line's second derivative. Eliminating a and omega-dot
(both affine in T_l) leaves three equations in theta'', psi'', T_l, solved by Cramer's rule.

Parameters of a run are one float64 vector, :data:`PARAMETERS` (positions from the CG, body
axes). The carrier's drive at a time (wind, commanded acceleration and velocity) is a vector of
nine, :data:`DRIVE`.
"""

from __future__ import annotations

import math

import numpy as np

from slingloads.models.multibody._jit import jit
from slingloads.models.multibody.cable import cable_tension
from slingloads.models.multibody.local_flow import flow_at, fuselage_loads, surface_force
from slingloads.models.multibody.lookup import interp1
from slingloads.models.multibody.parachute_line import (
    HINGE_MARGIN,
    line_curvature,
    line_direction,
)
from slingloads.models.multibody.rigid_body import (
    cross,
    dcm,
    quaternion_rate,
    to_body,
    to_earth,
)
from slingloads.models.packed import BODY, EARTH, TENSOR, Field, Layout

STATES = ("Vc_X", "Vc_Y", "Vc_Z", "p_X", "p_Y", "p_Z", "v_X", "v_Y", "v_Z",
          "q0", "q1", "q2", "q3", "p", "q", "r", "theta", "psi", "theta_dot", "psi_dot")
N_STATES = len(STATES)
#: Offsets of the state's parts in :data:`STATES` (the kernels index ``x[X_QUAT + 1]``, never
#: a literal): carrier velocity, CG relative to the hook, CG velocity, attitude quaternion,
#: body rates, parachute hinge angles and their rates.
X_VC, X_REL, X_VEL = STATES.index("Vc_X"), STATES.index("p_X"), STATES.index("v_X")
X_QUAT, X_RATE = STATES.index("q0"), STATES.index("p")
X_THETA, X_PSI = STATES.index("theta"), STATES.index("psi")
X_THETA_DOT, X_PSI_DOT = STATES.index("theta_dot"), STATES.index("psi_dot")

#: The parameter vector of a run, one table (:mod:`slingloads.models.packed`): positions are
#: from the CG in body axes; the packer (:class:`~slingloads.models.multibody.system.SlingSystem`)
#: and :func:`evaluate` address it by the offsets below.
LAYOUT = Layout((
    Field("mass", "kg", "mass of the carried helicopter (HC)"),
    Field("Iinv", "1/(kg m^2)", "inverse of the HC inertia tensor about the CG", TENSOR),
    Field("I", "kg m^2", "HC inertia tensor about the CG", TENSOR),
    Field("hub", "m", "cable attachment (rotor hub)", BODY),
    Field("ref", "m", "moment reference point of the fuselage tables", BODY),
    Field("fuselage_area", "m^2", "reference area of the fuselage tables (0: no fuselage)"),
    Field("fuselage_length", "m", "reference length of the fuselage tables"),
    Field("fin", "m", "fin centre of pressure", BODY),
    Field("fin_area_eff", "m^2", "fin area times efficiency (0: no fin)"),
    Field("tail", "m", "horizontal tail centre of pressure", BODY),
    Field("tail_area_eff", "m^2", "tail area times efficiency (0: no tail)"),
    Field("chute", "m", "parachute attachment", BODY),
    Field("chute_mode", "-", "parachute model: CHUTE_NONE, CHUTE_HINGED, CHUTE_QUASI_STATIC"),
    Field("chute_drag_area", "m^2", "parachute drag area (hinged: wake ratio x area, its CD "
          "from the table)"),
    Field("chute_mass", "kg", "canopy mass (hinged parachute)"),
    Field("chute_line", "m", "parachute line length"),
    Field("cable_length", "m", "unstretched carrier cable length"),
    Field("cable_stiffness", "N/m", "cable spring rate EA/l"),
    Field("cable_damping", "N s/m", "cable damping"),
    Field("carrier_free", "-", "> 0: the carrier's velocity is a state driven by a speed "
          "loop; else it follows the commanded acceleration"),
    Field("carrier_mass", "kg", "carrier mass (free carrier)"),
    Field("carrier_drag_area", "m^2", "carrier drag area (free carrier)"),
    Field("carrier_gain", "1/s", "carrier speed-loop gain (free carrier)"),
    Field("pull", "N", "trim pull of the cable on the carrier (free carrier feed-forward)",
          EARTH),
    Field("density", "kg/m^3", "air density"),
    Field("gravity", "m/s^2", "acceleration of gravity"),
    Field("v_cut", "m/s", "airspeed below which aerodynamic loads are neglected"),
    Field("lock_translation", "-", "> 0: no CG acceleration (verification runs)"),
    Field("lock_tilt", "-", "> 0: no roll or pitch acceleration (verification runs)"),
    Field("lock_yaw", "-", "> 0: no yaw acceleration (verification runs)"),
    Field("mast", "-", "unit vector of the rotor mast", BODY),
    Field("fuselage_force_frame", "-", "axes of the fuselage force coefficients "
          "(FRAME_CODES)"),
    Field("fuselage_moment_frame", "-", "axes of the fuselage moment coefficients "
          "(FRAME_CODES)"),
))
#: Names of the parameter vector's elements, in order.
PARAMETERS = LAYOUT.names
N_PARAMETERS = len(LAYOUT)
# offsets of the fields (compile-time constants of the kernels)
MASS = LAYOUT["mass"]
IINV = LAYOUT["Iinv"]
INERTIA = LAYOUT["I"]
HUB = LAYOUT["hub"]
REF = LAYOUT["ref"]
FUSELAGE_AREA = LAYOUT["fuselage_area"]
FUSELAGE_LENGTH = LAYOUT["fuselage_length"]
FIN = LAYOUT["fin"]
FIN_AREA_EFF = LAYOUT["fin_area_eff"]
TAIL = LAYOUT["tail"]
TAIL_AREA_EFF = LAYOUT["tail_area_eff"]
CHUTE = LAYOUT["chute"]
CHUTE_MODE = LAYOUT["chute_mode"]
CHUTE_DRAG_AREA = LAYOUT["chute_drag_area"]
CHUTE_MASS = LAYOUT["chute_mass"]
CHUTE_LINE = LAYOUT["chute_line"]
CABLE_LENGTH = LAYOUT["cable_length"]
CABLE_STIFFNESS = LAYOUT["cable_stiffness"]
CABLE_DAMPING = LAYOUT["cable_damping"]
CARRIER_FREE = LAYOUT["carrier_free"]
CARRIER_MASS = LAYOUT["carrier_mass"]
CARRIER_DRAG_AREA = LAYOUT["carrier_drag_area"]
CARRIER_GAIN = LAYOUT["carrier_gain"]
PULL = LAYOUT["pull"]
DENSITY = LAYOUT["density"]
GRAVITY = LAYOUT["gravity"]
V_CUT = LAYOUT["v_cut"]
LOCK_TRANSLATION = LAYOUT["lock_translation"]
LOCK_TILT = LAYOUT["lock_tilt"]
LOCK_YAW = LAYOUT["lock_yaw"]
MAST = LAYOUT["mast"]
FUSELAGE_FORCE_FRAME = LAYOUT["fuselage_force_frame"]
FUSELAGE_MOMENT_FRAME = LAYOUT["fuselage_moment_frame"]
DRIVE = ("wind_X", "wind_Y", "wind_Z", "accel_X", "accel_Y", "accel_Z", "cmd_X", "cmd_Y",
         "cmd_Z")
#: Offsets of the drive's parts in :data:`DRIVE`: wind, commanded acceleration and velocity.
D_WIND, D_ACCEL, D_CMD = DRIVE.index("wind_X"), DRIVE.index("accel_X"), DRIVE.index("cmd_X")

#: Parachute models (``chute_mode``).
CHUTE_NONE, CHUTE_HINGED, CHUTE_QUASI_STATIC = 0.0, 1.0, 2.0

#: Quantities :func:`evaluate` reports besides the derivative (``want=True``).
INFO = ("tension", "cable_span", "d_X", "d_Y", "d_Z", "hub_x", "hub_y", "hub_z", "alpha",
        "beta", "airspeed", "fin_angle", "tail_angle", "line_tension", "chute_alpha",
        "line_x", "line_y", "line_z", "thrust_X", "thrust_Y", "thrust_Z", "fus_fx", "fus_fy",
        "fus_fz", "fus_mx", "fus_my", "fus_mz", "chute_drag", "fin_force", "tail_force")
N_INFO = len(INFO)
#: Offsets of the reported quantities in :data:`INFO` (a vector's first component).
INFO_TENSION, INFO_CABLE_SPAN, INFO_D = (INFO.index(n) for n in ("tension", "cable_span", "d_X"))
INFO_HUB, INFO_ALPHA, INFO_BETA = (INFO.index(n) for n in ("hub_x", "alpha", "beta"))
INFO_AIRSPEED, INFO_FIN_ANGLE, INFO_TAIL_ANGLE = (
    INFO.index(n) for n in ("airspeed", "fin_angle", "tail_angle"))
INFO_LINE_TENSION, INFO_CHUTE_ALPHA, INFO_LINE = (
    INFO.index(n) for n in ("line_tension", "chute_alpha", "line_x"))
INFO_THRUST, INFO_FUS_F, INFO_FUS_M = (INFO.index(n) for n in ("thrust_X", "fus_fx", "fus_mx"))
INFO_CHUTE_DRAG, INFO_FIN_FORCE, INFO_TAIL_FORCE = (
    INFO.index(n) for n in ("chute_drag", "fin_force", "tail_force"))

#: Bits of the flag :func:`evaluate` returns: the table or limit a run left.
FLAGS = {1: "fuselage table's alpha range", 32: "fuselage table's beta range",
         2: "fin table", 4: "horizontal-tail table", 8: "parachute CD table",
         16: "parachute hinge range (line along body y)"}

_HINGE_COS = math.sin(HINGE_MARGIN)


@jit
def _solve3(c1, c2, c3, b):
    """Solve [c1 c2 c3] y = b (columns given) by Cramer's rule."""
    x23 = cross(c2[0], c2[1], c2[2], c3[0], c3[1], c3[2])
    det = c1[0] * x23[0] + c1[1] * x23[1] + c1[2] * x23[2]
    xb3 = cross(b[0], b[1], b[2], c3[0], c3[1], c3[2])
    y1 = (b[0] * x23[0] + b[1] * x23[1] + b[2] * x23[2]) / det
    y2 = (c1[0] * xb3[0] + c1[1] * xb3[1] + c1[2] * xb3[2]) / det
    x2b = cross(c2[0], c2[1], c2[2], b[0], b[1], b[2])
    y3 = (c1[0] * x2b[0] + c1[1] * x2b[1] + c1[2] * x2b[2]) / det
    return y1, y2, y3


@jit
def _mat(P, k, x, y, z):
    """3 x 3 matrix stored row-major from ``P[k]`` on, times (x, y, z)."""
    return (P[k] * x + P[k + 1] * y + P[k + 2] * z,
            P[k + 3] * x + P[k + 4] * y + P[k + 5] * z,
            P[k + 6] * x + P[k + 7] * y + P[k + 8] * z)


@jit
def evaluate(x, P, drive, fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v,
             dx, info, want):
    """State derivative ``dx`` of state ``x``; the quantities :data:`INFO` in ``info`` if
    ``want``.

    Parameters
    ----------
    x : ndarray, shape (N_STATES,)
        State (:data:`STATES`). [m, m/s, -, rad/s, rad]
    P : ndarray, shape (N_PARAMETERS,)
        Parameter vector (:data:`LAYOUT`). [SI]
    drive : ndarray, shape (9,)
        Wind [m/s], commanded carrier acceleration [m/s^2] and velocity [m/s], earth axes
        (:data:`DRIVE`).
    fus_a, fus_b, fus_c : ndarray
        Fuselage table: alpha and beta breakpoints [rad], stacked coefficients [-].
    fin_g, fin_v, tail_g, tail_v, cd_g, cd_v : ndarray
        Fin, tail and parachute CD tables: breakpoints [rad], values [-]
        (:meth:`SlingSystem.tables <slingloads.models.multibody.system.SlingSystem.tables>`).
    dx : ndarray, shape (N_STATES,)
        Receives the state derivative. [state units / s]
    info : ndarray, shape (N_INFO,)
        Receives the reported quantities (:data:`INFO`) when ``want``. [SI]
    want : bool
        Evaluate the reported quantities.

    Returns
    -------
    int
        The flag of :data:`FLAGS` (0 when every table was inside its range). [-]
    """
    flag = 0
    vc0, vc1, vc2 = x[X_VC], x[X_VC + 1], x[X_VC + 2]
    p0, p1, p2 = x[X_REL], x[X_REL + 1], x[X_REL + 2]
    v0, v1, v2 = x[X_VEL], x[X_VEL + 1], x[X_VEL + 2]
    q0, q1, q2, q3 = x[X_QUAT], x[X_QUAT + 1], x[X_QUAT + 2], x[X_QUAT + 3]
    qn = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    q0, q1, q2, q3 = q0 / qn, q1 / qn, q2 / qn, q3 / qn
    wp, wq, wr = x[X_RATE], x[X_RATE + 1], x[X_RATE + 2]
    R = dcm(q0, q1, q2, q3)
    mass = P[MASS]
    half_rho = 0.5 * P[DENSITY]
    grav = P[GRAVITY]
    v_cut = P[V_CUT]

    # air velocity relative to the CG, body axes
    ub = to_body(R, drive[D_WIND] - v0, drive[D_WIND + 1] - v1, drive[D_WIND + 2] - v2)
    fx, fy, fz = 0.0, 0.0, 0.0
    mx, my, mz = 0.0, 0.0, 0.0

    # fuselage at its reference point
    alpha, beta, speed_ref = 0.0, 0.0, 0.0
    ffx, ffy, ffz, fmx, fmy, fmz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    if P[FUSELAGE_AREA] > 0.0:
        rx, ry, rz = P[REF], P[REF + 1], P[REF + 2]
        u = flow_at(ub[0], ub[1], ub[2], wp, wq, wr, rx, ry, rz)
        speed_ref = math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
        ffx, ffy, ffz, gx, gy, gz, alpha, beta, ok_a, ok_b = fuselage_loads(
            u[0], u[1], u[2], half_rho, P[FUSELAGE_AREA], P[FUSELAGE_LENGTH], fus_a, fus_b,
            fus_c, v_cut, int(P[FUSELAGE_FORCE_FRAME]), int(P[FUSELAGE_MOMENT_FRAME]))
        if not ok_a:
            flag |= 1
        if not ok_b:
            flag |= 32
        t = cross(rx, ry, rz, ffx, ffy, ffz)
        fmx, fmy, fmz = gx + t[0], gy + t[1], gz + t[2]
        fx += ffx
        fy += ffy
        fz += ffz
        mx += fmx
        my += fmy
        mz += fmz

    # fin: normal force along body y from its local flow
    fin_force, fin_angle = 0.0, 0.0
    if P[FIN_AREA_EFF] > 0.0:
        rx, ry, rz = P[FIN], P[FIN + 1], P[FIN + 2]
        u = flow_at(ub[0], ub[1], ub[2], wp, wq, wr, rx, ry, rz)
        fin_force, fin_angle, ok = surface_force(u[0], u[1], u[2], 1, -1.0, half_rho,
                                                 P[FIN_AREA_EFF], fin_g, fin_v, v_cut)
        if not ok:
            flag |= 2
        fy += fin_force
        mx += -rz * fin_force
        mz += rx * fin_force

    # horizontal tail: normal force along body z
    tail_force, tail_angle = 0.0, 0.0
    if P[TAIL_AREA_EFF] > 0.0:
        rx, ry, rz = P[TAIL], P[TAIL + 1], P[TAIL + 2]
        u = flow_at(ub[0], ub[1], ub[2], wp, wq, wr, rx, ry, rz)
        tail_force, tail_angle, ok = surface_force(u[0], u[1], u[2], 2, 1.0, half_rho,
                                                   P[TAIL_AREA_EFF], tail_g, tail_v, v_cut)
        if not ok:
            flag |= 4
        fz += tail_force
        mx += ry * tail_force
        my += -rx * tail_force

    # gravity
    gb = to_body(R, 0.0, 0.0, -mass * grav)
    fx += gb[0]
    fy += gb[1]
    fz += gb[2]

    # cable, hook to hub
    hx, hy, hz = P[HUB], P[HUB + 1], P[HUB + 2]
    he = to_earth(R, hx, hy, hz)
    d0, d1, d2 = p0 + he[0], p1 + he[1], p2 + he[2]
    wh = cross(wp, wq, wr, hx, hy, hz)
    whe = to_earth(R, wh[0], wh[1], wh[2])
    dd0, dd1, dd2 = v0 - vc0 + whe[0], v1 - vc1 + whe[1], v2 - vc2 + whe[2]
    span = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    rate = (d0 * dd0 + d1 * dd1 + d2 * dd2) / span
    tension = cable_tension(span, rate, P[CABLE_LENGTH], P[CABLE_STIFFNESS], P[CABLE_DAMPING])
    cb = to_body(R, -tension * d0 / span, -tension * d1 / span, -tension * d2 / span)
    fx += cb[0]
    fy += cb[1]
    fz += cb[2]
    t = cross(hx, hy, hz, cb[0], cb[1], cb[2])
    mx += t[0]
    my += t[1]
    mz += t[2]

    # gyroscopic moment
    iw = _mat(P, INERTIA, wp, wq, wr)
    t = cross(wp, wq, wr, iw[0], iw[1], iw[2])
    mx -= t[0]
    my -= t[1]
    mz -= t[2]

    # parachute
    ax, ay, az = P[CHUTE], P[CHUTE + 1], P[CHUTE + 2]
    mode = P[CHUTE_MODE]
    line_tension, chute_alpha, chute_drag = 0.0, 0.0, 0.0
    lx, ly, lz = 1.0, 0.0, 0.0
    thdd, psdd = 0.0, 0.0
    if mode == CHUTE_QUASI_STATIC:
        u = flow_at(ub[0], ub[1], ub[2], wp, wq, wr, ax, ay, az)
        speed = math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
        if speed >= v_cut:
            k = half_rho * P[CHUTE_DRAG_AREA] * speed
            dbx, dby, dbz = k * u[0], k * u[1], k * u[2]
            fx += dbx
            fy += dby
            fz += dbz
            t = cross(ax, ay, az, dbx, dby, dbz)
            mx += t[0]
            my += t[1]
            mz += t[2]
            chute_drag = k * speed
            line_tension = chute_drag
            lx, ly, lz = u[0] / speed, u[1] / speed, u[2] / speed
    a0x, a0y, a0z = fx / mass, fy / mass, fz / mass
    w0 = _mat(P, IINV, mx, my, mz)
    abx, aby, abz = a0x, a0y, a0z
    wdx, wdy, wdz = w0[0], w0[1], w0[2]
    if mode == CHUTE_HINGED:
        mp, lp = P[CHUTE_MASS], P[CHUTE_LINE]
        th, ps, thd, psd = x[X_THETA], x[X_PSI], x[X_THETA_DOT], x[X_PSI_DOT]
        e, et, ep = line_direction(th, ps)
        if abs(math.cos(ps)) < _HINGE_COS:
            flag |= 16
        lx, ly, lz = e[0], e[1], e[2]
        s = (ax + lp * e[0], ay + lp * e[1], az + lp * e[2])
        ed = (et[0] * thd + ep[0] * psd, et[1] * thd + ep[1] * psd, et[2] * thd + ep[2] * psd)
        ws = cross(wp, wq, wr, s[0], s[1], s[2])
        up = (ub[0] - ws[0] - lp * ed[0], ub[1] - ws[1] - lp * ed[1],
              ub[2] - ws[2] - lp * ed[2])
        speed = math.sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2])
        dbx, dby, dbz = 0.0, 0.0, 0.0
        if speed >= v_cut:
            cosa = (e[0] * up[0] + e[1] * up[1] + e[2] * up[2]) / speed
            chute_alpha = math.acos(min(1.0, max(-1.0, cosa)))
            # an axisymmetric canopy: the table is read at the total angle, 0 to 180 deg
            cd, ok = interp1(cd_g, cd_v, chute_alpha)
            if not ok:
                flag |= 8
            k = half_rho * P[CHUTE_DRAG_AREA] * cd * speed
            dbx, dby, dbz = k * up[0], k * up[1], k * up[2]
            chute_drag = k * speed
        gp = to_body(R, 0.0, 0.0, -mp * grav)
        e2 = line_curvature(th, ps, thd, psd)
        wws = cross(wp, wq, wr, ws[0], ws[1], ws[2])
        wed = cross(wp, wq, wr, ed[0], ed[1], ed[2])
        g0x = dbx + gp[0] - mp * (wws[0] + 2.0 * lp * wed[0] + lp * e2[0])
        g0y = dby + gp[1] - mp * (wws[1] + 2.0 * lp * wed[1] + lp * e2[1])
        g0z = dbz + gp[2] - mp * (wws[2] + 2.0 * lp * wed[2] + lp * e2[2])
        a1x, a1y, a1z = e[0] / mass, e[1] / mass, e[2] / mass
        axe = cross(ax, ay, az, e[0], e[1], e[2])
        w1 = _mat(P, IINV, axe[0], axe[1], axe[2])
        w1s = cross(w1[0], w1[1], w1[2], s[0], s[1], s[2])
        w0s = cross(w0[0], w0[1], w0[2], s[0], s[1], s[2])
        c1 = (mp * lp * et[0], mp * lp * et[1], mp * lp * et[2])
        c2 = (mp * lp * ep[0], mp * lp * ep[1], mp * lp * ep[2])
        c3 = (e[0] + mp * (a1x + w1s[0]), e[1] + mp * (a1y + w1s[1]),
              e[2] + mp * (a1z + w1s[2]))
        b = (g0x - mp * (a0x + w0s[0]), g0y - mp * (a0y + w0s[1]),
             g0z - mp * (a0z + w0s[2]))
        thdd, psdd, line_tension = _solve3(c1, c2, c3, b)
        abx, aby, abz = a0x + line_tension * a1x, a0y + line_tension * a1y, \
            a0z + line_tension * a1z
        wdx, wdy, wdz = (w0[0] + line_tension * w1[0], w0[1] + line_tension * w1[1],
                         w0[2] + line_tension * w1[2])

    # restrictions used by the verification tests
    if P[LOCK_TRANSLATION] > 0.0:
        abx, aby, abz = 0.0, 0.0, 0.0
    if P[LOCK_TILT] > 0.0:
        wdx, wdy = 0.0, 0.0
    if P[LOCK_YAW] > 0.0:
        wdz = 0.0

    # carrier
    pull0, pull1, pull2 = tension * d0 / span, tension * d1 / span, tension * d2 / span
    if P[CARRIER_FREE] > 0.0:
        mc, kv = P[CARRIER_MASS], P[CARRIER_GAIN]
        dx[X_VC] = drive[D_ACCEL] + kv * (drive[D_CMD] - vc0) + (pull0 - P[PULL]) / mc
        dx[X_VC + 1] = (drive[D_ACCEL + 1] + kv * (drive[D_CMD + 1] - vc1)
                        + (pull1 - P[PULL + 1]) / mc)
        dx[X_VC + 2] = (drive[D_ACCEL + 2] + kv * (drive[D_CMD + 2] - vc2)
                        + (pull2 - P[PULL + 2]) / mc)
    else:
        dx[X_VC], dx[X_VC + 1], dx[X_VC + 2] = (drive[D_ACCEL], drive[D_ACCEL + 1],
                                                drive[D_ACCEL + 2])
    dx[X_REL], dx[X_REL + 1], dx[X_REL + 2] = v0 - vc0, v1 - vc1, v2 - vc2
    ae = to_earth(R, abx, aby, abz)
    dx[X_VEL], dx[X_VEL + 1], dx[X_VEL + 2] = ae[0], ae[1], ae[2]
    dq = quaternion_rate(q0, q1, q2, q3, wp, wq, wr)
    for c in range(4):
        dx[X_QUAT + c] = dq[c]
    dx[X_RATE], dx[X_RATE + 1], dx[X_RATE + 2] = wdx, wdy, wdz
    if mode == CHUTE_HINGED:
        dx[X_THETA], dx[X_PSI] = x[X_THETA_DOT], x[X_PSI_DOT]
        dx[X_THETA_DOT], dx[X_PSI_DOT] = thdd, psdd
    else:
        dx[X_THETA], dx[X_PSI], dx[X_THETA_DOT], dx[X_PSI_DOT] = 0.0, 0.0, 0.0, 0.0

    if want:
        info[INFO_TENSION] = tension
        info[INFO_CABLE_SPAN] = span
        info[INFO_D], info[INFO_D + 1], info[INFO_D + 2] = d0, d1, d2
        info[INFO_HUB], info[INFO_HUB + 1], info[INFO_HUB + 2] = cb[0], cb[1], cb[2]
        info[INFO_ALPHA], info[INFO_BETA], info[INFO_AIRSPEED] = alpha, beta, speed_ref
        info[INFO_FIN_ANGLE], info[INFO_TAIL_ANGLE] = fin_angle, tail_angle
        info[INFO_LINE_TENSION], info[INFO_CHUTE_ALPHA] = line_tension, chute_alpha
        info[INFO_LINE], info[INFO_LINE + 1], info[INFO_LINE + 2] = lx, ly, lz
        if P[CARRIER_FREE] > 0.0:
            mc, kv = P[CARRIER_MASS], P[CARRIER_GAIN]
            uc0 = drive[D_WIND] - vc0
            uc1 = drive[D_WIND + 1] - vc1
            uc2 = drive[D_WIND + 2] - vc2
            kd = (half_rho * P[CARRIER_DRAG_AREA]
                  * math.sqrt(uc0 * uc0 + uc1 * uc1 + uc2 * uc2))
            info[INFO_THRUST] = (mc * (drive[D_ACCEL] + kv * (drive[D_CMD] - vc0)) - kd * uc0
                                 - P[PULL])
            info[INFO_THRUST + 1] = (mc * (drive[D_ACCEL + 1] + kv * (drive[D_CMD + 1] - vc1))
                                     - kd * uc1 - P[PULL + 1])
            info[INFO_THRUST + 2] = (mc * (drive[D_ACCEL + 2] + kv * (drive[D_CMD + 2] - vc2))
                                     - kd * uc2 - P[PULL + 2] + mc * grav)
        else:
            for c in range(3):
                info[INFO_THRUST + c] = np.nan
        info[INFO_FUS_F], info[INFO_FUS_F + 1], info[INFO_FUS_F + 2] = ffx, ffy, ffz
        info[INFO_FUS_M], info[INFO_FUS_M + 1], info[INFO_FUS_M + 2] = fmx, fmy, fmz
        info[INFO_CHUTE_DRAG] = chute_drag
        info[INFO_FIN_FORCE], info[INFO_TAIL_FORCE] = fin_force, tail_force
    return flag


"""The compiled multibody equations against an independent derivation by Kane's method.

Reference: T. R. Kane and D. A. Levinson, "Dynamics: Theory and Applications", McGraw-Hill,
1985, as implemented by ``sympy.physics.mechanics.KanesMethod``. The system is built there from
its bodies, points and loads alone (a rigid body with a full inertia tensor hung by an elastic,
damped cable from a hook moving at constant velocity; a particle on a two-hinge line from a
body point, with drag along its own relative wind; gravity), with none of the hand elimination
of ``docs/multibody.md``. At random states the state derivatives agree to round-off.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

sp = pytest.importorskip("sympy")
from sympy.physics import mechanics as me  # noqa: E402

from slingloads.constants import G0  # noqa: E402
from slingloads.models.aero_tables import Table1D  # noqa: E402
from slingloads.models.airframe import Hardpoints  # noqa: E402
from slingloads.models.multibody import (  # noqa: E402
    Cable,
    HingedParachute,
    RigidBody,
    SlingSystem,
)
from slingloads.models.multibody.equations import N_INFO, N_STATES, evaluate  # noqa: E402
from slingloads.models.parachute import Parachute  # noqa: E402


def kane_model(m, inertia, hub, attach, mp, lp, k, c, l0, drag_factor, rho, wind):
    """Numeric function (q, u) -> (q', u') of the system built with KanesMethod."""
    x, y, z, q0, q1, q2, q3, th, ps = me.dynamicsymbols("x y z q0 q1 q2 q3 th ps")
    u1, u2, u3, w1, w2, w3, uth, ups = me.dynamicsymbols("u1 u2 u3 w1 w2 w3 uth ups")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, (q0, q1, q2, q3))
    B.set_ang_vel(N, w1 * B.x + w2 * B.y + w3 * B.z)
    hook = me.Point("O")  # the hook, moving at constant velocity: an inertial origin
    hook.set_vel(N, 0)
    G = hook.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u1 * N.x + u2 * N.y + u3 * N.z)
    H = G.locatenew("H", hub[0] * B.x + hub[1] * B.y + hub[2] * B.z)
    H.v2pt_theory(G, N, B)
    e = (sp.cos(th) * sp.cos(ps)) * B.x + sp.sin(ps) * B.y + (sp.sin(th) * sp.cos(ps)) * B.z
    s = (attach[0] * B.x + attach[1] * B.y + attach[2] * B.z) + lp * e
    P = G.locatenew("P", s)
    vel_p = (G.vel(N) + s.dt(N)).subs({th.diff(): uth, ps.diff(): ups})
    P.set_vel(N, vel_p)
    inertia_dyadic = sum((inertia[i, j] * (a | b) for i, a in enumerate((B.x, B.y, B.z))
                          for j, b in enumerate((B.x, B.y, B.z))), me.Dyadic(0))
    body = me.RigidBody("HC", G, B, m, (inertia_dyadic, G))
    canopy = me.Particle("canopy", P, mp)
    d = H.pos_from(hook)
    span = sp.sqrt(d.dot(d))
    tension = k * (span - l0) + c * d.dot(H.vel(N)) / span
    air = (wind[0] * N.x + wind[1] * N.y + wind[2] * N.z) - P.vel(N)
    drag = 0.5 * rho * drag_factor * sp.sqrt(air.dot(air)) * air
    loads = [(G, -m * G0 * N.z), (H, -tension * d / span), (P, drag - mp * G0 * N.z)]
    kd = [x.diff() - u1, y.diff() - u2, z.diff() - u3,
          q0.diff() - 0.5 * (-q1 * w1 - q2 * w2 - q3 * w3),
          q1.diff() - 0.5 * (q0 * w1 + q2 * w3 - q3 * w2),
          q2.diff() - 0.5 * (q0 * w2 - q1 * w3 + q3 * w1),
          q3.diff() - 0.5 * (q0 * w3 + q1 * w2 - q2 * w1),
          th.diff() - uth, ps.diff() - ups]
    qs = [x, y, z, q0, q1, q2, q3, th, ps]
    us = [u1, u2, u3, w1, w2, w3, uth, ups]
    kane = me.KanesMethod(N, q_ind=qs, u_ind=us, kd_eqs=kd)
    kane.kanes_equations([body, canopy], loads)
    mass = sp.lambdify([qs, us], kane.mass_matrix_full, "numpy")
    force = sp.lambdify([qs, us], kane.forcing_full, "numpy")

    def rates(qv, uv):
        return np.linalg.solve(mass(qv, uv), force(qv, uv)).ravel()

    return rates


def test_equations_agree_with_kanes_method_at_random_states():
    """Five random states (attitude, rates, line angles and rates, stretched cable):
    CG acceleration, angular acceleration and hinge accelerations of the compiled equations
    equal Kane's to 1e-9 relative."""
    rng = np.random.default_rng(7)
    a = rng.normal(size=(3, 3))
    inertia = np.diag([2500.0, 7000.0, 9000.0]) + 300.0 * (a + a.T)
    m, mp, lp, area, cd, l0, ea = 2900.0, 15.0, 10.0, 1.2, 0.9, 18.0, 5e6
    hub, attach = np.array([0.1, -0.05, 1.0]), np.array([6.4, 0.1, 1.6])
    table = Table1D(np.radians([0.0, 180.0]), {"CD": [cd, cd]}, angle_name="alpha",
                    what="parachute")
    chute = HingedParachute(Parachute(area, table, wake_ratio=0.9, line_length=lp), mp)
    hp = Hardpoints(hub=hub, mast_feet=[[0.0, 0.0, 0.5]], chute=attach)
    system = SlingSystem(RigidBody(m, np.zeros(3), inertia), hp, Cable(l0, ea, 0.07),
                         parachute=chute, aero_cutoff=1e-3)
    params, tables = system.parameters(), system.tables()
    k, c = system.cable.stiffness, system.cable.damping(system.hung_mass)
    carrier = np.array([-40.0, 0.0, 0.0])
    wind = carrier + rng.normal(size=3) * 3.0  # air velocity: 40 m/s past the HC plus gust
    rates = kane_model(m, inertia, hub, attach, mp, lp, k, c, l0, 0.9 * area * cd,
                       system.density, tuple(wind - carrier))
    for _ in range(5):
        quat = rng.normal(size=4) * [1.0, 0.15, 0.15, 0.3] + [3.0, 0, 0, 0]
        quat /= np.linalg.norm(quat)
        pos = np.array([1.0, 0.5, -(l0 + 1.1)]) + rng.normal(size=3) * 0.05
        vel = rng.normal(size=3) * 2.0
        omega = rng.normal(size=3) * 0.3
        hinge = np.array([rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6)])
        hinge_rate = rng.normal(size=2) * 0.5
        x = np.zeros(N_STATES)
        x[0:3] = carrier
        x[3:6] = pos
        x[6:9] = carrier + vel
        x[9:13] = quat
        x[13:16] = omega
        x[16:18] = hinge
        x[18:20] = hinge_rate
        drive = np.concatenate([wind, np.zeros(3), carrier])
        dx, info = np.zeros(N_STATES), np.zeros(N_INFO)
        assert evaluate(x, params, drive, *tables, dx, info, True) == 0
        assert info[0] > 0  # the cable is taut at these states
        ref = rates(list(pos) + list(quat) + list(hinge), list(vel) + list(omega)
                    + list(hinge_rate))
        assert_allclose(dx[3:6], ref[0:3], rtol=1e-12, atol=1e-12)
        assert_allclose(dx[9:13], ref[3:7], rtol=1e-12, atol=1e-12)
        assert_allclose(dx[6:9], ref[9:12], rtol=1e-9, atol=1e-9)
        assert_allclose(dx[13:16], ref[12:15], rtol=1e-9, atol=1e-9)
        assert_allclose(dx[18:20], ref[15:17], rtol=1e-9, atol=1e-9)

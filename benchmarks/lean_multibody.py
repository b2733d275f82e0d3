"""A lean, hand-written right-hand side of the towed system in plain Python, for the baseline.

What a competent engineer would write to integrate one run with :func:`scipy.integrate.solve_ivp`
without the product's compiled kernel: the equations of ``docs/multibody.md`` (frozen carrier in
steady flight, elastic cable, 6-DOF helicopter with fuselage table and fin, hinged canopy) on
Python floats with the ``math`` module, tables as Python lists searched with :mod:`bisect`, and
the gust shapes written out. The fuselage table's forces are in wind axes and its moments in
body axes (the sample tables' frames); the fin's side force in body axes. No numpy inside the
right-hand side (numpy calls on three-element vectors cost more than they save).

It is built from a :class:`~slingloads.models.multibody.SlingSystem`'s public fields (not from
the product's parameter vector), so comparing it with the compiled equations at random states
also checks how the product packs its parameters.
"""

from __future__ import annotations

import math
from bisect import bisect_right

from slingloads.models.multibody.environment import gust_direction


class LeftTable(Exception):
    """The flow left an aerodynamic table (the product stops such a run too)."""


def _table1(table, name):
    return [float(a) for a in table.angle], [float(v) for v in table.coefficients[name]]


def _lookup1(grid, values, x):
    if not grid[0] - 1e-9 <= x <= grid[-1] + 1e-9:
        raise LeftTable(x)
    i = min(max(bisect_right(grid, x) - 1, 0), len(grid) - 2)
    w = (x - grid[i]) / (grid[i + 1] - grid[i])
    return values[i] + w * (values[i + 1] - values[i])


def gust_function(gust):
    """Plain-Python gust velocity v(t) [m/s] of a gust of :mod:`slingloads.models.gusts`."""
    a, t0 = gust.amplitude, gust.onset
    if gust.kind == "step":
        return lambda t: a if t >= t0 else 0.0
    period = gust.duration
    if gust.kind == "finite":
        return lambda t: a if t0 <= t < t0 + period else 0.0
    if gust.kind == "1-cosine":
        return lambda t: (0.5 * a * (1.0 - math.cos(2.0 * math.pi * (t - t0) / period))
                          if t0 <= t < t0 + period else 0.0)
    return lambda t: a * math.sin(2.0 * math.pi * (t - t0) / period) if t >= t0 else 0.0


def lean_rhs(system, manoeuvre):
    """f(t, x) -> list of 20 derivatives for a frozen carrier in steady flight (its velocity
    is the state's first three entries) in the wind of ``manoeuvre`` (steady plus a gust along
    its direction)."""
    body, hp = system.body, system.hardpoints
    cg = [float(c) for c in body.cg]
    m = body.mass
    inertia = [[float(v) for v in row] for row in body.inertia]
    det = (inertia[0][0] * (inertia[1][1] * inertia[2][2] - inertia[1][2] * inertia[2][1])
           - inertia[0][1] * (inertia[1][0] * inertia[2][2] - inertia[1][2] * inertia[2][0])
           + inertia[0][2] * (inertia[1][0] * inertia[2][1] - inertia[1][1] * inertia[2][0]))
    inv = [[(inertia[(c + 1) % 3][(r + 1) % 3] * inertia[(c + 2) % 3][(r + 2) % 3]
             - inertia[(c + 1) % 3][(r + 2) % 3] * inertia[(c + 2) % 3][(r + 1) % 3]) / det
            for c in range(3)] for r in range(3)]
    hx, hy, hz = (float(hp.hub[i]) - cg[i] for i in range(3))
    fus = system.fuselage
    if (fus.force_axes, fus.moment_axes) != ("wind", "body"):
        raise ValueError("the lean baseline takes fuselage forces in wind axes and moments in "
                         "body axes (the sample tables' frames)")
    rx, ry, rz = (float(fus.moment_reference[i]) - cg[i] for i in range(3))
    f_area, f_len = fus.area, fus.length
    alphas = [float(a) for a in fus.table.alpha]
    betas = [float(b) for b in fus.table.beta]
    coeffs = [[[float(v) for v in row] for row in fus.table.coefficients[c]]
              for c in ("CD", "CY", "CL", "Cl", "Cm", "Cn")]
    fin = system.fin
    fx_, fy_, fz_ = (float(fin.centre_of_pressure[i]) - cg[i] for i in range(3))
    fin_area = fin.area * fin.efficiency
    fin_grid, fin_cy = _table1(fin.table, "CY")
    chute = system.parachute.parachute
    ax, ay, az = (float(hp.chute[i]) - cg[i] for i in range(3))
    mp, lp = system.parachute.mass, chute.line_length
    chute_area = chute.wake_ratio * chute.area
    cd_grid, cd_values = _table1(chute.cd, "CD")
    length, k_cable = system.cable.length, system.cable.stiffness
    c_cable = system.cable.damping(system.hung_mass)
    half_rho, g, v_cut = 0.5 * system.density, system.gravity, system.aero_cutoff
    wind = manoeuvre.wind
    w0 = [float(v) for v in wind.steady]
    n = [float(v) for v in gust_direction(wind.direction)]
    gust = gust_function(wind.gust) if wind.gust is not None else (lambda t: 0.0)

    ln_a, ln_b = len(alphas) - 2, len(betas) - 2
    a_lo, a_hi = alphas[0] - 1e-9, alphas[-1] + 1e-9
    b_lo, b_hi = betas[0] - 1e-9, betas[-1] + 1e-9
    cd_tab, cy_tab, cl_tab, roll_tab, cm_tab, cn_tab = coeffs
    v_cut2 = v_cut * v_cut
    i00, i01, i02 = inertia[0]
    i10, i11, i12 = inertia[1]
    i20, i21, i22 = inertia[2]
    n00, n01, n02 = inv[0]
    n10, n11, n12 = inv[1]
    n20, n21, n22 = inv[2]
    sqrt, atan2, sin, cos = math.sqrt, math.atan2, math.sin, math.cos

    def rhs(t, x):
        gv = gust(t)
        (vc0, vc1, vc2, p0, p1, p2, v0, v1, v2, q0, q1, q2, q3, wp, wq, wr,
         th, ps, thd, psd) = x  # the carrier is frozen: vc is constant
        qn = sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        q0, q1, q2, q3 = q0 / qn, q1 / qn, q2 / qn, q3 / qn
        r00 = q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3
        r01 = 2 * (q1 * q2 - q0 * q3)
        r02 = 2 * (q1 * q3 + q0 * q2)
        r10 = 2 * (q1 * q2 + q0 * q3)
        r11 = q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3
        r12 = 2 * (q2 * q3 - q0 * q1)
        r20 = 2 * (q1 * q3 - q0 * q2)
        r21 = 2 * (q2 * q3 + q0 * q1)
        r22 = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3
        e0, e1, e2 = w0[0] + gv * n[0] - v0, w0[1] + gv * n[1] - v1, w0[2] + gv * n[2] - v2
        ub0 = r00 * e0 + r10 * e1 + r20 * e2
        ub1 = r01 * e0 + r11 * e1 + r21 * e2
        ub2 = r02 * e0 + r12 * e1 + r22 * e2
        # gravity (body axes)
        fx, fy, fz = -m * g * r20, -m * g * r21, -m * g * r22
        mx = my = mz = 0.0
        # fuselage at its reference point
        u0 = ub0 - (wq * rz - wr * ry)
        u1 = ub1 - (wr * rx - wp * rz)
        u2 = ub2 - (wp * ry - wq * rx)
        sp2 = u0 * u0 + u1 * u1 + u2 * u2
        if sp2 >= v_cut2:
            sp = sqrt(sp2)
            d0, d1, d2 = u0 / sp, u1 / sp, u2 / sp
            side = sqrt(d0 * d0 + d2 * d2)
            beta = atan2(-d1, side if d0 >= 0 else -side)
            alpha = math.atan(d2 / d0) if d0 != 0 else math.copysign(0.5 * math.pi, d2)
            if not (a_lo <= alpha <= a_hi and b_lo <= beta <= b_hi):
                raise LeftTable(alpha, beta)
            i = min(max(bisect_right(alphas, alpha) - 1, 0), ln_a)
            j = min(max(bisect_right(betas, beta) - 1, 0), ln_b)
            wa = (alpha - alphas[i]) / (alphas[i + 1] - alphas[i])
            wb = (beta - betas[j]) / (betas[j + 1] - betas[j])
            c = []
            for tab in (cd_tab, cy_tab, cl_tab, roll_tab, cm_tab, cn_tab):
                row, nxt = tab[i], tab[i + 1]
                lo = row[j] + wb * (row[j + 1] - row[j])
                c.append(lo + wa * (nxt[j] + wb * (nxt[j + 1] - nxt[j]) - lo))
            qs = half_rho * sp2 * f_area
            sa, ca, sb, cb = sin(alpha), cos(alpha), sin(beta), cos(beta)
            # wind axes: CD along the airflow d, CY along y_W = (ca sb, cb, sa sb), CL along
            # the lift direction (-sa, 0, ca)
            g0 = qs * (c[0] * d0 + c[1] * ca * sb - c[2] * sa)
            g1 = qs * (c[0] * d1 + c[1] * cb)
            g2 = qs * (c[0] * d2 + c[1] * sa * sb + c[2] * ca)
            qsl = qs * f_len
            fx += g0
            fy += g1
            fz += g2
            mx += -qsl * c[3] + ry * g2 - rz * g1
            my += qsl * c[4] + rz * g0 - rx * g2
            mz += -qsl * c[5] + rx * g1 - ry * g0
        # fin: side force from its local flow
        u0 = ub0 - (wq * fz_ - wr * fy_)
        u1 = ub1 - (wr * fx_ - wp * fz_)
        sp2 = u0 * u0 + u1 * u1
        if sp2 >= v_cut2:
            side_force = half_rho * sp2 * fin_area * _lookup1(fin_grid, fin_cy, atan2(-u1, u0))
            fy += side_force
            mx -= fz_ * side_force
            mz += fx_ * side_force
        # cable from the hook to the hub
        d0 = p0 + r00 * hx + r01 * hy + r02 * hz
        d1 = p1 + r10 * hx + r11 * hy + r12 * hz
        d2 = p2 + r20 * hx + r21 * hy + r22 * hz
        k0, k1, k2 = wq * hz - wr * hy, wr * hx - wp * hz, wp * hy - wq * hx
        dd0 = v0 - vc0 + r00 * k0 + r01 * k1 + r02 * k2
        dd1 = v1 - vc1 + r10 * k0 + r11 * k1 + r12 * k2
        dd2 = v2 - vc2 + r20 * k0 + r21 * k1 + r22 * k2
        span = sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if span > length:
            tension = k_cable * (span - length) + c_cable * (d0 * dd0 + d1 * dd1 + d2 * dd2) / span
            if tension > 0.0:
                k = -tension / span
                c0 = k * (r00 * d0 + r10 * d1 + r20 * d2)
                c1 = k * (r01 * d0 + r11 * d1 + r21 * d2)
                c2 = k * (r02 * d0 + r12 * d1 + r22 * d2)
                fx += c0
                fy += c1
                fz += c2
                mx += hy * c2 - hz * c1
                my += hz * c0 - hx * c2
                mz += hx * c1 - hy * c0
        # gyroscopic moment
        iw0 = i00 * wp + i01 * wq + i02 * wr
        iw1 = i10 * wp + i11 * wq + i12 * wr
        iw2 = i20 * wp + i21 * wq + i22 * wr
        mx -= wq * iw2 - wr * iw1
        my -= wr * iw0 - wp * iw2
        mz -= wp * iw1 - wq * iw0
        a0, a1, a2 = fx / m, fy / m, fz / m
        h0 = n00 * mx + n01 * my + n02 * mz
        h1 = n10 * mx + n11 * my + n12 * mz
        h2 = n20 * mx + n21 * my + n22 * mz
        # hinged canopy: hinge accelerations and line tension (3 x 3, Cramer)
        ct, st, cp, sp_ = cos(th), sin(th), cos(ps), sin(ps)
        e0, e1, e2 = ct * cp, sp_, st * cp
        et0, et2 = -st * cp, ct * cp
        ep0, ep1, ep2 = -ct * sp_, cp, -st * sp_
        s0, s1, s2 = ax + lp * e0, ay + lp * e1, az + lp * e2
        ed0, ed1, ed2 = et0 * thd + ep0 * psd, ep1 * psd, et2 * thd + ep2 * psd
        ws0, ws1, ws2 = wq * s2 - wr * s1, wr * s0 - wp * s2, wp * s1 - wq * s0
        up0, up1, up2 = ub0 - ws0 - lp * ed0, ub1 - ws1 - lp * ed1, ub2 - ws2 - lp * ed2
        speed = sqrt(up0 * up0 + up1 * up1 + up2 * up2)
        b0 = -mp * g * r20
        b1 = -mp * g * r21
        b2 = -mp * g * r22
        if speed >= v_cut:
            cosa = (e0 * up0 + e1 * up1 + e2 * up2) / speed
            kd = half_rho * chute_area * speed * _lookup1(cd_grid, cd_values,
                                                          math.acos(min(1.0, max(-1.0, cosa))))
            b0 += kd * up0
            b1 += kd * up1
            b2 += kd * up2
        aa, bb, cc = thd * thd, 2.0 * thd * psd, psd * psd
        cu0 = -ct * cp * aa + st * sp_ * bb - ct * cp * cc
        cu1 = -sp_ * cc
        cu2 = -st * cp * aa - ct * sp_ * bb - st * cp * cc
        b0 -= mp * (wq * ws2 - wr * ws1 + 2.0 * lp * (wq * ed2 - wr * ed1) + lp * cu0)
        b1 -= mp * (wr * ws0 - wp * ws2 + 2.0 * lp * (wr * ed0 - wp * ed2) + lp * cu1)
        b2 -= mp * (wp * ws1 - wq * ws0 + 2.0 * lp * (wp * ed1 - wq * ed0) + lp * cu2)
        b0 -= mp * (a0 + h1 * s2 - h2 * s1)
        b1 -= mp * (a1 + h2 * s0 - h0 * s2)
        b2 -= mp * (a2 + h0 * s1 - h1 * s0)
        x0_, x1_, x2_ = ay * e2 - az * e1, az * e0 - ax * e2, ax * e1 - ay * e0
        j0 = n00 * x0_ + n01 * x1_ + n02 * x2_
        j1 = n10 * x0_ + n11 * x1_ + n12 * x2_
        j2 = n20 * x0_ + n21 * x1_ + n22 * x2_
        m_lp = mp * lp
        c10, c11, c12 = m_lp * et0, 0.0, m_lp * et2
        c20, c21, c22 = m_lp * ep0, m_lp * ep1, m_lp * ep2
        c30 = e0 + mp * (e0 / m + j1 * s2 - j2 * s1)
        c31 = e1 + mp * (e1 / m + j2 * s0 - j0 * s2)
        c32 = e2 + mp * (e2 / m + j0 * s1 - j1 * s0)
        y0, y1, y2 = c21 * c32 - c22 * c31, c22 * c30 - c20 * c32, c20 * c31 - c21 * c30
        det3 = c10 * y0 + c11 * y1 + c12 * y2
        thdd = (b0 * y0 + b1 * y1 + b2 * y2) / det3
        psdd = (c10 * (b1 * c32 - b2 * c31) + c11 * (b2 * c30 - b0 * c32)
                + c12 * (b0 * c31 - b1 * c30)) / det3
        t_line = (c10 * (c21 * b2 - c22 * b1) + c11 * (c22 * b0 - c20 * b2)
                  + c12 * (c20 * b1 - c21 * b0)) / det3
        k = t_line / m
        a0, a1, a2 = a0 + k * e0, a1 + k * e1, a2 + k * e2
        return [0.0, 0.0, 0.0, v0 - vc0, v1 - vc1, v2 - vc2,
                r00 * a0 + r01 * a1 + r02 * a2, r10 * a0 + r11 * a1 + r12 * a2,
                r20 * a0 + r21 * a1 + r22 * a2,
                0.5 * (-q1 * wp - q2 * wq - q3 * wr), 0.5 * (q0 * wp + q2 * wr - q3 * wq),
                0.5 * (q0 * wq - q1 * wr + q3 * wp), 0.5 * (q0 * wr + q1 * wq - q2 * wp),
                h0 + t_line * j0, h1 + t_line * j1, h2 + t_line * j2, thd, psd, thdd, psdd]

    return rhs

"""Generate the GENERIC sample aerodynamic tables of HC1 and HC2 (slingloads/data/*.csv).

These tables describe no real aircraft. They are smooth analytic shapes whose magnitudes follow
the UH-60-class fuselage and fin data summarised in the project's reference facts (section 3),
scaled to a light-twin helicopter (about 2.9 t, fuselage about 11 m long) through the reference
area and length that go with the tables (see ``slingloads/data/SAMPLE_DATA.md``). Being
coefficients, the magnitudes carry over unchanged when the reference area scales with the square
and the reference length with the first power of the fuselage length.

Run from the repository root to rewrite the CSV files::

    .venv/bin/python docs/sample-data/generate_sample_tables.py

The output is deterministic (no random numbers); rerunning reproduces the committed files.

Fuselage alone (blades and tailplane removed), angles alpha, beta in radians. The shapes are
written first as a body-axis lateral force ``C_Fy``, an along-wind part ``C_A`` and a lift
``C_L``; the force is

.. math::

    F / (q S) = C_A \\hat d + (C_{F_y} + C_A \\sin\\beta)\\,\\hat y + C_L \\hat l

with :math:`\\hat d` the airflow, :math:`\\hat y` body y and :math:`\\hat l` the lift direction
(``docs/conventions.md``), so that the body-axis lateral force is exactly ``C_Fy`` and the
broadside drag is not counted twice at 90 deg. **The tables are written in wind axes** (the
default force axes of :class:`~slingloads.models.aerodynamics.FuselageAero`): CD = F.d,
CY = F.y_W with y_W = (cos a sin b, cos b, sin a sin b), CL = F.l; **moments in body axes**:

.. math::

    C_{F_y}(\\beta) &= -(a_1 \\sin\\beta\\cos\\beta + a_2 \\sin\\beta\\,|\\sin\\beta|)
        \\quad\\text{(body-axis lateral force)} \\\\
    C_A &= C_{D0}(1 + 2\\sin^2\\alpha)\\cos^2\\beta + a_2\\sin^2\\beta \\\\
    C_D &= C_A \\cos^2\\beta - C_{F_y} \\sin\\beta \\\\
    C_Y &= (C_{F_y} + C_A \\sin\\beta) \\cos\\beta \\\\
    C_L &= (C_{L0} + C_{L\\alpha}\\sin\\alpha\\cos\\alpha)\\cos^2\\beta \\\\
    C_l &= -c_l \\sin\\beta\\cos\\beta \\\\
    C_m &= (C_{m0} + \\mathrm{sat}(C_{m\\alpha}\\sin\\alpha))\\cos^2\\beta \\\\
    C_n &= -A_n \\sin 4\\beta \\,(1 - 0.5\\sin^2\\alpha)

(At 90 deg ``C_A = a2`` and ``C_Fy = -a2``: CD = a2 carries all the broadside force, CY = 0.)

The pitching moment's angle-of-attack part ``c = C_ma sin(alpha)`` is kept as it is up to
``|alpha| = 15 deg`` (``|c| <= c_0 = C_ma sin 15 deg``) and saturates beyond towards
``C_m,sat``, smoothly (same slope at the junction):

.. math::

    \\mathrm{sat}(c) = c \\quad (|c| \\le c_0), \\qquad
    \\mathrm{sign}(c)\\,[c_0 + (C_{m,sat} - c_0) \\tanh((|c| - c_0) / (C_{m,sat} - c_0))]
    \\quad \\text{beyond}

as a fuselage's pitching moment does once the flow has separated (the UH-60-class data
flatten at about -0.25 below -25 deg and +0.27 above 30 deg); the slope at zero (0.6 and
0.7 /rad) lies within those data (0.46 /rad within +-5 deg, 0.67 /rad from 10 to 20 deg).

``Cn = -A_n sin(4 beta)`` is directionally unstable near zero (dCn/dbeta = -4 A_n), peaks at
22.5 deg and returns to zero at 45 deg, as the UH-60-class data do (|Cn| 0.03 / 0.06 / 0.08 at
5 / 10 / 20 deg for A_n = 0.085); beyond 45 deg it is weakly stabilising (the tail boom
weathervanes broadside).

Fin (intact, side force on its own area, sideslip only, **body axes**: along +y, normal to
the fin's plane, as a flat plate's normal force is): a tanh lift curve that blends into a flat
plate after the stall,

.. math::

    w &= \\tfrac12 [1 + \\tanh((|\\beta| - \\beta_{stall})/\\Delta)] \\\\
    C_Y &= -[(1 - w)\\, C_{Y,max} \\tanh(\\beta/\\beta_s) + w\\, C_{N,plate} \\sin\\beta]

with ``C_N,plate = 1.17`` (square flat plate normal to the flow, Hoerner).

Sideslip runs over the whole circle, -180 to 180 deg, so that a carried helicopter that turns
broadside or tail first stays inside its tables. The formulas above are continued unchanged
beyond +-90 deg (they are periodic); the fin beyond its stall is the flat plate, whose normal
force keeps the physical sign in reverse flow.

Horizontal tail (full-tail configuration of the transport without parachute, paper section 5),
normal force along +z on its own area against its local angle of attack, the same shape as the
fin with ``alpha`` in place of ``beta`` and the opposite sign (a flow from below pushes the
tail up):

.. math::

    C_N = (1 - w)\\, C_{N,max} \\tanh(\\alpha/\\alpha_s) + w\\, C_{N,plate} \\sin\\alpha
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

OUT = Path(__file__).resolve().parents[2] / "slingloads" / "data"

ALPHA_DEG = np.arange(-40.0, 40.0 + 1e-9, 5.0)
BETA_DEG = np.arange(-180.0, 180.0 + 1e-9, 2.0)
#: Local angle of attack of the horizontal tail (full-tail configuration only). [deg]
TAIL_ALPHA_DEG = np.arange(-180.0, 180.0 + 1e-9, 2.0)

#: Shape parameters of each generic aircraft. HC2 is the less stable in yaw (larger fuselage
#: yawing-moment amplitude, and a smaller fin: see slingloads/models/sample_aircraft.py).
SHAPES = {
    "HC1": dict(a1=2.1, a2=2.0, cd0=0.30, cl0=0.05, cla=0.9, cl_roll=0.05, cm0=-0.02,
                cma=0.6, cm_sat=0.25, an=0.10, fin_cymax=1.1, fin_beta_s=19.0, fin_stall=28.0,
                fin_width=3.0, fin_plate=1.17, ht_cnmax=0.9, ht_alpha_s=12.0,
                ht_stall=16.0, ht_width=3.0),
    "HC2": dict(a1=2.3, a2=2.1, cd0=0.33, cl0=0.04, cla=0.8, cl_roll=0.06, cm0=-0.03,
                cma=0.7, cm_sat=0.28, an=0.12, fin_cymax=1.0, fin_beta_s=18.0, fin_stall=26.0,
                fin_width=3.0, fin_plate=1.17, ht_cnmax=0.85, ht_alpha_s=12.0,
                ht_stall=15.0, ht_width=3.0),
}


def fuselage_table(p):
    """Long-format fuselage table for shape parameters ``p`` (angles in degrees)."""
    a_deg, b_deg = np.meshgrid(ALPHA_DEG, BETA_DEG, indexing="ij")
    a, b = np.radians(a_deg), np.radians(b_deg)
    sa, sb, cb = np.sin(a), np.sin(b), np.cos(b)
    c_fy = -(p["a1"] * sb * cb + p["a2"] * sb * np.abs(sb))
    c_a = p["cd0"] * (1.0 + 2.0 * sa**2) * cb**2 + p["a2"] * sb**2
    cd = c_a * cb**2 - c_fy * sb  # wind axes: the force's component along the airflow
    cy = (c_fy + c_a * sb) * cb   # and along y_W
    cl = (p["cl0"] + p["cla"] * sa * np.cos(a)) * cb**2
    roll = -p["cl_roll"] * sb * cb
    cm = (p["cm0"] + saturated_pitch(p["cma"] * sa, p["cma"], p["cm_sat"])) * cb**2
    cn = -p["an"] * np.sin(4.0 * b) * (1.0 - 0.5 * sa**2)
    frame = pd.DataFrame({
        "alpha [deg]": a_deg.ravel(), "beta [deg]": b_deg.ravel(),
        "CD": cd.ravel(), "CY": cy.ravel(), "CL": cl.ravel(),
        "Cl": roll.ravel(), "Cm": cm.ravel(), "Cn": cn.ravel(),
    })
    return _clean(frame)


#: Angle of attack up to which the pitching moment keeps its linear-in-sin(alpha) shape. [deg]
CM_LINEAR_UP_TO = 15.0


def saturated_pitch(c, cma, limit):
    """The pitching moment's angle-of-attack part ``c`` saturated beyond 15 deg towards
    ``limit`` (module notes): unchanged while ``|c| <= cma sin 15 deg``."""
    c0 = cma * np.sin(np.radians(CM_LINEAR_UP_TO))
    excess = np.abs(c) - c0
    span = limit - c0
    bent = np.sign(c) * (c0 + span * np.tanh(np.maximum(excess, 0.0) / span))
    return np.where(excess > 0.0, bent, c)


def fin_table(p):
    """Intact-fin side-force table for shape parameters ``p`` (beta in degrees)."""
    b_deg = BETA_DEG
    b = np.radians(b_deg)
    w = 0.5 * (1.0 + np.tanh((np.abs(b_deg) - p["fin_stall"]) / p["fin_width"]))
    attached = p["fin_cymax"] * np.tanh(b_deg / p["fin_beta_s"])
    plate = p["fin_plate"] * np.sin(b)
    cy = -((1.0 - w) * attached + w * plate)
    return _clean(pd.DataFrame({"beta [deg]": b_deg, "CY": cy}))


def htail_table(p):
    """Horizontal-tail normal-force table (full-tail configuration) against its local alpha."""
    a_deg = TAIL_ALPHA_DEG
    a = np.radians(a_deg)
    w = 0.5 * (1.0 + np.tanh((np.abs(a_deg) - p["ht_stall"]) / p["ht_width"]))
    attached = p["ht_cnmax"] * np.tanh(a_deg / p["ht_alpha_s"])
    plate = p["fin_plate"] * np.sin(a)
    return _clean(pd.DataFrame({"alpha [deg]": a_deg, "CN": (1.0 - w) * attached + w * plate}))


def _clean(frame):
    """Round to 6 decimals and remove negative zeros so the files diff cleanly."""
    frame = frame.round(6)
    return frame + 0.0


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for name, p in SHAPES.items():
        stem = name.lower()
        fuselage_table(p).to_csv(OUT / f"{stem}_fuselage.csv", index=False,
                                 float_format="%.6f")
        fin_table(p).to_csv(OUT / f"{stem}_fin.csv", index=False, float_format="%.6f")
        htail_table(p).to_csv(OUT / f"{stem}_htail.csv", index=False, float_format="%.6f")
        print(f"wrote {stem}_fuselage.csv, {stem}_fin.csv and {stem}_htail.csv to {OUT}")


if __name__ == "__main__":
    main()

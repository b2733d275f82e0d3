"""Lateral-step pendulum part of the example workbook (imported by ``build_example.py``).

Defines :data:`TABLES`, :data:`PARAMETERS` and :data:`NOTES`. The motions are ILLUSTRATIVE
carrier manoeuvres, not a certified motion envelope: a real study must list the manoeuvres of
the operation being certified (docs/lateral-pendulum.md, "Driving it from the workbook").
"""

from __future__ import annotations

import numpy as np
import pandas as pd

#: Quintic (minimum-jerk) steps: peak accelerations [g] x durations [s].
STEP_ACCELERATIONS_G = (0.1, 0.25, 0.5)
STEP_DURATIONS_S = (0.5, 1.0, 2.0)


def _motions():
    rows = []
    for a in STEP_ACCELERATIONS_G:
        for d in STEP_DURATIONS_S:
            rows.append((f"STEP-{a:g}g-{d:g}s", "quintic step", a, d, None, None, None, None,
                         f"sidestep, peak {a:g} g, completed in {d:g} s"))
    rows += [
        ("ACC-0.1g-2s-HOLD", "constant acceleration", 0.1, 2.0, None, "hold", None, None,
         "sudden start: 0.1 g for 2 s, then constant speed (~2 m/s)"),
        ("ACC-0.3g-2.5s-STOP", "constant acceleration", 0.3, 2.5, None, "stop", None, None,
         "accelerate 0.3 g for 2.5 s then brake 0.3 g to rest: timed near half the 18 ft "
         "swing period (5.2 s), the worst timing"),
        ("DV-1", "velocity step", None, None, None, None, 1.0, None,
         "hook speed jump of 1 m/s (bounding a gust-like jerk of the carrier)"),
        ("REPOSITION", "time history", None, None, None, None, None, "REPOSITION",
         "planned 3 m reposition and return, from the LateralHistory sheet"),
    ]
    return pd.DataFrame(rows, columns=["id", "type", "acceleration [g0]", "duration [s]",
                                       "amplitude [m]", "then", "delta V [m/s]", "history",
                                       "description"])


def _history():
    """A 3 m sidestep in 4 s, 2 s hover, and back in 4 s, sampled every 0.5 s."""
    t = np.arange(0.0, 10.01, 0.5)
    tau_out = np.clip(t / 4.0, 0.0, 1.0)
    tau_back = np.clip((t - 6.0) / 4.0, 0.0, 1.0)

    def quintic(x):
        return x**3 * (10.0 - 15.0 * x + 6.0 * x**2)

    s = 3.0 * (quintic(tau_out) - quintic(tau_back))
    return pd.DataFrame({"history id": "REPOSITION", "t [s]": t, "S [m]": np.round(s, 4)})


TABLES = {
    "LateralMotions": _motions(),
    "LateralHistory": _history(),
    "LateralRopes": pd.DataFrame({"rope length [ft]": [18.0, 60.0, 100.0],
                                  "description": ["paper: short rope", "paper: medium rope",
                                                  "paper: long rope"]}),
}

PARAMETERS = {
    "run lateral": ("yes", ""),
    "lateral design-angle margin": (1.5, ""),
    "lateral cable model": ("rigid", ""),
    "lateral damping source": ("aerodynamic tables", ""),
    "lateral airspeed EAS": (0, "kt"),
    "lateral roll inertia spread": (0.2, ""),
    "lateral CG below hub spread": (0.2, ""),
    "lateral rope length spread": (0.2, ""),
    "lateral spread points": (3, ""),
    "lateral simulation time": (30, "s"),
    "lateral RK4 step": (0.05, "s"),
    "lateral history method": ("DOP853", ""),
    "lateral history rtol": (1e-6, ""),
    "lateral history output step": (0.05, "s"),
}

NOTES = [
    "Lateral-step pendulum (sheets LateralMotions, LateralHistory, LateralRopes; Study rows "
    "'lateral ...'): the carried helicopter of the MassItems (mass, Ixx about the CG, CG "
    "below the hub) on a rigid rope of 18, 60 and 100 ft (the paper's lengths) under "
    "ILLUSTRATIVE carrier motions: quintic (minimum-jerk) sidesteps of 0.5-2 s up to 0.5 g, a"
    " sudden start at 0.1 g, an accelerate-then-brake at 0.3 g timed near half the short "
    "rope's swing period (the worst timing: it pumps the swing), a 1 m/s velocity step and a "
    "planned 3 m reposition. They are NOT a certified motion envelope: the motions swept must"
    " match the operation being certified (accelerations, durations, and braking timed at "
    "half the swing period if the operation allows it), or the recommended angle does not "
    "show that it 'cannot be exceeded in service' (CS 29.865).",
    "Uncertainty: roll inertia, CG distance below the hub and rope length each +-20 % "
    "(three values each, 0.8, 1 and 1.2, every combination: 27 variants of every motion and "
    "rope; three keep the example fast, a real study should use more, the default being "
    "five, as a resonance can lie between them); the recommended angle is taken over that "
    "envelope. Damping from the aerodynamic tables at 0 "
    "kt: the paper's hover step, where there is no linear aerodynamic damping (zero).",
    "Solver: RK4 step 0.05 s over 30 s for the sweep, chosen for a fast example run (the "
    "report re-runs the critical case with solve_ivp, DOP853 rtol 1e-6, and shows the "
    "difference); no damping in hover (the paper's assumption). For a real study leave "
    "'lateral RK4 step' and 'lateral simulation time' at 0 (automatic) or check convergence.",
]

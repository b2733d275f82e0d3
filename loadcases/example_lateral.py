"""Lateral-step pendulum part of the example workbook (imported by ``build_example.py``).

Defines :data:`TABLES`, :data:`PARAMETERS` and :data:`NOTES`. The motions are ILLUSTRATIVE
carrier manoeuvres, not a certified motion envelope: a real study must list the manoeuvres of
the operation being certified (docs/lateral-pendulum.md, "Driving it from the workbook").
"""

from __future__ import annotations

import numpy as np
import pandas as pd

#: What the carrier can fly (the defaults of slingloads.analyses.lateral.CarrierLimits): bank
#: 20 deg (US Army TM 1-1670-260-12&P, damaged-helicopter recovery: "about 30-40 KIAS, 20 deg
#: bank"), so the lateral acceleration stays within g tan 20 deg = 0.364 g; roll rate 10 deg/s
#: (an engineering assumption), so the acceleration changes at most g sec^2(20 deg) x 10
#: deg/s = 1.94 m/s^3. Each step below is the quickest of its peak acceleration within both:
#: a quintic step's jerk is 10.39 a_peak / T, a cycloidal step's 2 pi a_peak / T.
#: (id, law, peak acceleration [g], duration [s], description)
FLYABLE_STEPS = (
    ("QUI-0.1g-5.5s", "quintic step", 0.1, 5.5, "minimum-jerk sidestep, 0.1 g peak"),
    ("QUI-0.2g-11s", "quintic step", 0.2, 11.0, "minimum-jerk sidestep, 0.2 g peak"),
    ("QUI-0.36g-19s", "quintic step", 0.36, 19.0,
     "minimum-jerk sidestep at the 20 deg bank limit"),
    ("CYC-0.1g-3.5s", "cycloidal step", 0.1, 3.5, "cycloidal sidestep, 0.1 g peak"),
    ("CYC-0.16g-5.2s", "cycloidal step", 0.16, 5.2,
     "cycloidal sidestep lasting one swing period of the 18 ft rope (5.2 s): the resonant "
     "timing, at the largest peak the roll-rate limit allows in that time"),
    ("CYC-0.36g-12s", "cycloidal step", 0.36, 12.0,
     "cycloidal sidestep at the 20 deg bank limit"),
)


def _motions():
    rows = [(i, law, a, d, None, None, None, None, text)
            for i, law, a, d, text in FLYABLE_STEPS]
    rows += [
        ("REPOSITION", "time history", None, None, None, None, None, "REPOSITION",
         "planned 3 m reposition and return in 6 s each way, from the LateralHistory sheet"),
    ]
    return pd.DataFrame(rows, columns=["id", "type", "acceleration [g0]", "duration [s]",
                                       "amplitude [m]", "then", "delta V [m/s]", "history",
                                       "description"])


def _history():
    """A 3 m sidestep in 6 s, 2 s hover, and back in 6 s, sampled every 0.5 s."""
    t = np.arange(0.0, 14.01, 0.5)
    tau_out = np.clip(t / 6.0, 0.0, 1.0)
    tau_back = np.clip((t - 8.0) / 6.0, 0.0, 1.0)

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
    "lateral simulation time": (60, "s"),
    "lateral RK4 step": (0.05, "s"),
    "lateral history method": ("DOP853", ""),
    "lateral history rtol": (1e-6, ""),
    "lateral history output step": (0.05, "s"),
}

NOTES = [
    "Lateral-step pendulum (sheets LateralMotions, LateralHistory, LateralRopes; Study rows "
    "'lateral ...'): the carried helicopter of the MassItems (mass, Ixx about the CG, CG "
    "below the hub) on a rigid rope of 18, 60 and 100 ft (the paper's lengths) under "
    "carrier motions a pilot can fly: bank within 20 deg (US Army TM 1-1670-260-12&P, "
    "damaged-helicopter recovery), so at most g tan 20 deg = 0.36 g sideways, and roll rate "
    "within 10 deg/s (an engineering assumption), so the acceleration changes at most 1.94 "
    "m/s^3: quintic and cycloidal sidesteps of 0.1 to 0.36 g, each the quickest its peak "
    "allows, one lasting the 18 ft rope's swing period (the resonant timing), and a planned 3 m "
    "reposition. Motions beyond these limits are flagged in the report and bound no design "
    "angle. They are an EXAMPLE envelope: the motions swept must match the operation being "
    "certified, or the recommended angle does not show that it 'cannot be exceeded in "
    "service' (CS 29.865).",
    "Uncertainty: roll inertia, CG distance below the hub and rope length each +-20 % "
    "(three values each, 0.8, 1 and 1.2, every combination: 27 variants of every motion and "
    "rope; three keep the example fast, a real study should use more, the default being "
    "five, as a resonance can lie between them); the recommended angle is taken over that "
    "envelope. Damping from the aerodynamic tables at 0 "
    "kt: the paper's hover step, where there is no linear aerodynamic damping (zero).",
    "Solver: RK4 step 0.05 s over 60 s for the sweep, chosen for a fast example run (the "
    "report re-runs the critical case with solve_ivp, DOP853 rtol 1e-6, and shows the "
    "difference); no damping in hover (the paper's assumption). For a real study leave "
    "'lateral RK4 step' and 'lateral simulation time' at 0 (automatic) or check convergence.",
]

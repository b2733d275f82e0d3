"""Multibody part of the example workbook (merged by ``loadcases/build_example.py``).

Defines ``TABLES`` (the ``MultibodyManoeuvres`` sheet), ``PARAMETERS`` (the Study rows of the
multibody model) and ``NOTES`` (README lines). A SHORT list of four runs, so that the README's
first command stays quick: a free response, a 30 ft/s lateral gust, a forward acceleration from
hover and a head-wind ramp; the whole list of the paper is flown when the sheet is deleted.

The towed flight is at 80 KEAS (the paper's sizing speed). With the GENERIC example data the
helicopter hangs nose down: its CG lies 0.17 m ahead of the hub (-9 deg in hover) and its
fuselage alone (horizontal tailplane removed, as in the paper's transport configuration) is
unstable in pitch, so the trimmed attitude grows with speed: -14.7 deg at 60 KEAS, -21.6 deg
at 80, -29.4 deg at 100 KEAS; above about 114 KEAS there is no trim. The paper transports its
helicopter up to 100 KEAS; with real fuselage data the attitudes are whatever the data give.
"""

from __future__ import annotations

import pandas as pd

#: Airspeed of the towed flight of the example. [kt]
AIRSPEED_KT = 80.0

MANOEUVRES = pd.DataFrame({
    "name": ["free response 10 deg yaw", "lateral gust +30 ft/s 10 s", "accelerate to 60 KIAS",
             "head-wind ramp to 40 kt"],
    "kind": ["free response", "gust", "forward acceleration", "wind ramp"],
    "shape": ["", "finite", "", ""],
    "direction": ["", "lateral", "", ""],
    "amplitude [ft/s]": [None, 30.0, None, None],
    "onset [s]": [None, 5.0, 5.0, 5.0],
    "duration [s]": [None, 10.0, None, None],
    "target [kt]": [None, None, 60.0, 40.0],
    "rate [m/s^2]": [None, None, 1.0, 0.5],
    "yaw [deg]": [10.0, None, None, None],
    "description": ["paper 4.4: free response from an initial disturbance",
                    "paper 4.4: impulsive lateral gust (CS 29.341 velocity)",
                    "paper 4.4: forward acceleration from hover (2 deg yaw seed)",
                    "paper 5.2: frontal wind ramp on a hovering carrier (2 deg yaw seed)"],
})

TABLES = {"MultibodyManoeuvres": MANOEUVRES}

PARAMETERS = {
    "run multibody": ("yes", ""),
    "multibody airspeed EAS": (AIRSPEED_KT, "kt"),
    "multibody density altitude": (0, "ft"),
    "multibody configuration": ("with parachute", ""),
    "multibody tail": ("cut-down fin", ""),
    "multibody parachute model": ("hinged", ""),
    "multibody parachute area": (0, "m^2"),
    "multibody canopy mass": (3.0, "kg"),
    "multibody canopy CD": ("extended", ""),
    "multibody cable length": (60, "ft"),
    "multibody cable EA": (5.0e6, "N"),
    "multibody cable damping ratio": (0.05, ""),
    "multibody cable margin": (0.20, ""),
    "multibody carrier": ("frozen", ""),
    "multibody simulation time": (60, "s"),
    "multibody time step": (0, "s"),
    "multibody output interval": (0.1, "s"),
}

NOTES = [
    "Multibody model (Study rows 'multibody ...', sheet MultibodyManoeuvres): the example "
    "airframe (MassItems inertia, HC1 fuselage and cut-down fin) hung on a 60 ft cable (EA "
    "5e6 N, GENERIC), the example's drogue (its 'parachute area' and line) as a hinged 3 kg "
    "canopy with the GENERIC extended CD table, frozen carrier, four runs at 80 KEAS or from "
    "hover. With the generic data the helicopter hangs nose down (CG 0.17 m ahead of the "
    "hub; the fuselage alone is unstable in pitch): trimmed pitch -14.7 deg at 60 KEAS, "
    "-21.6 deg at 80, -29.4 deg at 100 KEAS, no trim above about 114 KEAS. Delete the "
    "MultibodyManoeuvres sheet to fly the paper's whole list.",
]

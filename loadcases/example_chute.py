"""Parachute-sizing part of the example workbook (merged by ``loadcases/build_example.py``).

Defines ``TABLES`` (the ``ChuteWake`` sheet), ``PARAMETERS`` (the Study rows of the sizing)
and ``NOTES`` (README lines), and :func:`parachute_size`, which runs the sizing through the
Python API on the example's own airframe so that the example's 'parachute area' is 1.4 x its
neutral static area (the paper's FPA + 40 %) and its 'parachute line length' is the wake line.

Wake: a GENERIC illustrative ``ChuteWake`` table, not CFD of any aircraft. It is shaped like
the self-similar far wake (centreline defect ~ x^(-2/3), ratio (1 - defect)^2) with the
0.95 point placed at about 10 m (33 ft) behind the fin, so that the line and a 60 ft carrier
cable fall in the paper's range (cables of 18 to 100 ft, at least 20 % longer than the line).
A table was chosen rather than the far-wake model because the model's constant K is not
calibrated on helicopter fuselages (with K = 1 it asks for lines of hundreds of metres), and
because a table is what a user pastes from CFD, as in the paper's section 3.2.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from slingloads.analyses.chute_sizing import line_length, neutral_area
from slingloads.constants import FOOT, KNOT
from slingloads.models.aerodynamics import Fin
from slingloads.models.airframe import yaw_inertia_about_hub
from slingloads.models.flight import FlightCondition
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_reference
from slingloads.models.wake import TabulatedWake
from slingloads.models.yaw_dynamics import YawModel

#: Sizing airspeed of the example (the paper's 80 KIAS). [kt]
AIRSPEED_KT = 80.0
#: Half-width of the sideslip range of the linearisation: it covers the 12.5 deg that the
#: 30 ft/s gust makes at 80 KIAS (a run that leaves the range is never called stable) and
#: equals the loads' sideslip envelope (+-15 deg). [deg]
LINEARISATION_DEG = 15.0
#: Recommended area over the neutral area (paper: FPA + 40 %). [-]
RECOMMENDED_FACTOR = 1.4
#: Distance at which the generic wake reaches a q ratio of 0.95. [m]
_Q95_DISTANCE = 10.0
_WAKE_FT = np.array([5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 50.0, 60.0, 80.0, 100.0])


def _generic_wake_ratio(distance_ft):
    """(1 - u)^2 with u = u95 (x / x95)^(-2/3): the far-wake shape, 0.95 at 10 m."""
    u95 = 1.0 - np.sqrt(0.95)
    u = u95 * (distance_ft * FOOT / _Q95_DISTANCE) ** (-2.0 / 3.0)
    return np.round((1.0 - u) ** 2, 3)


WAKE = pd.DataFrame({"distance [ft]": _WAKE_FT, "q ratio [-]": _generic_wake_ratio(_WAKE_FT)})

TABLES = {"ChuteWake": WAKE}

PARAMETERS = {
    "run chute sizing": ("yes", ""),
    "chute sizing airspeed IAS": (AIRSPEED_KT, "kt"),
    "chute sizing density altitude": (0, "ft"),
    "chute sizing alpha trim": (0, "deg"),
    "chute sizing linearisation range": (LINEARISATION_DEG, "deg"),
    "chute sizing yaw axis": ("suspension", ""),
    "chute sizing yaw inertia source": ("mass items", ""),
    "chute sizing wake source": ("table", ""),
    "chute sizing target q ratio": (0.95, ""),
    "chute sizing carrier cable length": (60, "ft"),
    "chute sizing cable margin": (0.20, ""),
    "chute sizing gust shapes": ("step, finite, 1-cosine, continuous, turbulence", ""),
    "chute sizing gust amplitude": (30, "ft/s"),
    "chute sizing gust onset": (30, "s"),
    "chute sizing gust duration": (10, "s"),
    "chute sizing gust rise time": (5, "s"),
    "chute sizing harmonic period": (10, "s"),
    "chute sizing turbulence altitude": (300, "ft"),
    "chute sizing turbulence severity": ("moderate", ""),
    "chute sizing turbulence duration": (60, "s"),
    "chute sizing turbulence seed": (1, ""),
    "chute sizing sideslip limit": (20, "deg"),
    "chute sizing simulation time": (120, "s"),
    "chute sizing area factor min": (1.0, ""),
    "chute sizing area factor max": (3.0, ""),
    "chute sizing number of areas": (11, ""),
    "chute sizing recommended factor": (RECOMMENDED_FACTOR, ""),
}

NOTES = [
    "Parachute sizing (sheet ChuteWake, Study rows 'chute sizing ...'): 80 KIAS ISA sea "
    "level, HC1 fuselage and fin tables, yaw inertia from the mass items about the hub axis, "
    "tables linearised over +-15 deg so that the 30 ft/s gust's 12.5 deg of sideslip at 80 "
    "kt lies inside the range (a run leaving it is never called stable). "
    "The ChuteWake table is a GENERIC ILLUSTRATIVE table, NOT CFD of any aircraft: the "
    "self-similar far-wake shape (defect ~ x^-2/3) with q ratio 0.95 placed at about 10 m "
    "(33 ft), so that the line and the 60 ft carrier cable fall in the paper's range (18-100 "
    "ft, cable >= 1.2 x line). Replace it with CFD or test data for a real study.",
    "Gusts: the CS 29.341 30 ft/s gust as a step, the paper's 10 s 'impulsive' (finite) gust, "
    "a 10 s 1-cosine, the paper's continuous gust (a sustained crosswind rising over 5 s, then "
    "held), and 60 s of moderate Dryden turbulence at 300 ft above ground (MIL-F-8785C: "
    "sigma_v 2.18 m/s, L_v 256 m; seed 1). Add 'harmonic' to the shapes for a resonance test "
    "(a 10 s sine near the yaw period drives the sideslip past 40 deg).",
    "The 'parachute area' and 'parachute line length' rows are computed when the workbook is "
    "built (loadcases/example_chute.py): 1.4 x the neutral static area and the wake line.",
]


def parachute_size(frame, fin_cp, aero_ref):
    """Parachute area and line length of the example, from its own sizing via the API.

    Parameters
    ----------
    frame : Airframe
        The example's airframe (hub and parachute attachment in ``frame.hardpoints``).
    fin_cp, aero_ref : array_like, shape (3,)
        Fin centre of pressure and fuselage moment reference point. [m]

    Returns
    -------
    area : float
        1.4 x the neutral static area on the least-squares slopes over the linearisation
        range (the paper's section 4.1 linearisation), rounded to 0.1 m^2: the Study's
        parachute as first chosen; the sizing report now also computes the neutral area on
        the local slopes at zero sideslip and says whether this area meets its criterion.
        [m^2]
    line : float
        Wake line length for q ratio 0.95, rounded up to 0.1 m. [m]
    """
    ref = sample_reference("HC1")
    fuselage = replace(sample_fuselage("HC1"), moment_reference=np.asarray(aero_ref, float))
    fin = Fin(sample_fin("HC1").table, ref.fin_area, fin_cp, ref.fin_efficiency)
    model = YawModel(fuselage, fin, frame.hardpoints, yaw_inertia_about_hub(frame),
                     FlightCondition(AIRSPEED_KT * KNOT), Parachute(1.0))
    half = np.radians(LINEARISATION_DEG)
    static = neutral_area(model, (-half, half), basis="fit")
    wake = TabulatedWake(WAKE["distance [ft]"].to_numpy() * FOOT, WAKE["q ratio [-]"])
    line = line_length(wake).line_length
    return round(RECOMMENDED_FACTOR * static.area, 1), float(np.ceil(line * 10) / 10)

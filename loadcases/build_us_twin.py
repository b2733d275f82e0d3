"""Build ``loadcases/example-us-twin.xlsx``, a second example: a GENERIC 4.9 t twin in US units.

Run from the repository root: ``python loadcases/build_us_twin.py``. It is the second workbook
of the consistency test (tests/test_findings.py): a different aircraft from the light-twin
example, in US customary units throughout (lb, in, ft, ft^2, slug ft^2, kt, ft/s), with its
rotor hub FORWARD of the CG (it hangs nose up), every analysis asked for, and short runs so
that the whole ``slingloads run`` takes a few seconds. It is not any real aircraft.

Where the magnitudes come from (none is tuned to give any particular answer):

* mass 4,900 kg (10,800 lb) in the transport configuration: the class of the AS365 (max
  4,250 kg, length 11.63 m; FACTS.md section 4) and its 4.9 t successors, blades removed.
  The mass breakdown is the light-twin example's (loadcases/build_example.py), every item
  scaled by 4,900 / 2,900, positions by the length ratio 1.15 (fuselage about 12.7 m);
  own inertias of the distributed items: the example's shapes (loadcases/example_inertia.py)
  scaled by 1.15 in size, i.e. x 1.15^2 per unit mass;
* hub 0.25 m forward of the CG (the example's is 0.17 m aft): the airframe hangs nose up;
* aerodynamics: the GENERIC HC2 tables (slingloads/data/SAMPLE_DATA.md: the less stable
  sample in yaw), reference area x 1.15^2 and length x 1.15, fin area x 1.15^2, fin centre
  of pressure x 1.15 from the CG;
* parachute: 1.4 x the neutral static area of its own sizing on the least-squares slopes at
  80 KIAS (the paper's FPA + 40 %, as the light-twin example), rounded to 0.5 ft^2; line
  from the example's generic wake table (loadcases/example_chute.py);
* Nz 2.5 and the 30 deg cone of CS 29.865 (FACTS.md); the airspeeds the paper uses (80 KEAS
  sizing, 100 kt loads).

The runs are SHORT (two lateral motions on one rope, three swept areas under two gust shapes,
one multibody manoeuvre of 20 s, a campaign of 2 areas x 1 airspeed of 20 s, one ramp
without parachute): the workbook checks that the reports agree, it is not a study.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd

from slingloads.analyses.chute_sizing import line_length, neutral_area
from slingloads.constants import FOOT, INCH, KNOT, POUND
from slingloads.io.template import write_input_workbook
from slingloads.models.aerodynamics import Fin
from slingloads.models.airframe import Airframe, Hardpoints, MassItems, yaw_inertia_about_hub
from slingloads.models.flight import FlightCondition
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_reference
from slingloads.models.wake import TabulatedWake
from slingloads.models.yaw_dynamics import YawModel

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
OUT = HERE / "example-us-twin.xlsx"

from build_example import MASS_ITEMS  # noqa: E402 (needs HERE on the path)
from example_chute import WAKE  # noqa: E402
from example_inertia import own_inertias  # noqa: E402

MASS = 4900.0  #: transport mass [kg]
SCALE = 1.15  #: length ratio to the light-twin example [-]
HUB_AHEAD = 0.25  #: hub forward of the CG [m]
SLUG_FT2 = 14.593902937206364 * FOOT**2  #: [kg m^2]
SAMPLE = "HC2"

NOTES = [
    "EXAMPLE ONLY. GENERIC twin of about 4.9 t (not any real aircraft) in US customary "
    "units, built by loadcases/build_us_twin.py for the consistency test: the light-twin "
    "example's mass breakdown scaled to 4,900 kg (AS365 class, FACTS.md) and 1.15 x in "
    "length, the rotor hub 0.25 m FORWARD of the CG (it hangs nose up), the GENERIC HC2 "
    "tables scaled to its size, a parachute of 1.4 x its neutral area (paper: FPA + 40 %).",
    "Runs are SHORT on purpose (few motions, areas, gusts and campaign runs of 20 s): it "
    "checks that the reports of one run agree; it is not a study.",
]


def airframe():
    """The airframe (SI), the fin centre of pressure and the fuselage moment reference."""
    ids, desc, mass, x, y, z = zip(*MASS_ITEMS, strict=True)
    mass = np.array(mass, float) * MASS / np.sum(mass)
    position = np.column_stack([x, y, z]) * SCALE
    items = MassItems(ids, mass, position, own_inertias(ids, mass) * SCALE**2,
                      description=desc)
    cg = items.cg
    hub = np.array([cg[0] - HUB_AHEAD, 0.0, 2.20 * SCALE])
    feet = hub + np.array([[-0.35, -0.40, -0.70], [-0.35, 0.40, -0.70], [0.35, -0.40, -0.70],
                           [0.35, 0.40, -0.70]])
    chute = np.array([10.75, 0.0, 2.30]) * SCALE
    hardpoints = Hardpoints(hub, feet, chute=chute,
                            mast_feet_ids=("MAST_FL", "MAST_FR", "MAST_AL", "MAST_AR"))
    stations = np.round(np.linspace(0.40, 11.00, 16) * SCALE, 3)[1:-1]
    frame = Airframe(items, stations, hardpoints, reference_axis=(0.0, 1.0 * SCALE),
                     station_ids=tuple(f"FS{round(s / INCH):04d}" for s in stations),
                     name="Generic 4.9 t twin")
    ref = sample_reference(SAMPLE)
    return (frame, cg + SCALE * np.array(ref.fin_centre_of_pressure),
            cg + SCALE * np.array(ref.moment_reference))


def parachute_size(frame, fin_cp, aero_ref):
    """1.4 x the neutral static area at 80 KIAS on the least-squares slopes over +-15 deg
    (rounded to 0.5 ft^2) [ft^2], and the wake line for q ratio 0.95 [ft]."""
    ref = sample_reference(SAMPLE)
    fuselage = replace(sample_fuselage(SAMPLE), moment_reference=np.asarray(aero_ref, float),
                       area=ref.fuselage_area * SCALE**2, length=ref.fuselage_length * SCALE)
    fin = Fin(sample_fin(SAMPLE).table, ref.fin_area * SCALE**2, fin_cp, ref.fin_efficiency)
    model = YawModel(fuselage, fin, frame.hardpoints, yaw_inertia_about_hub(frame),
                     FlightCondition(80.0 * KNOT), Parachute(1.0))
    half = np.radians(15.0)
    area = 1.4 * neutral_area(model, (-half, half), basis="fit").area / FOOT**2
    wake = TabulatedWake(WAKE["distance [ft]"].to_numpy() * FOOT, WAKE["q ratio [-]"])
    return round(area * 2) / 2, float(np.ceil(line_length(wake).line_length / FOOT))


def tables(frame, fin_cp, aero_ref):
    """The workbook's sheets, in US units."""
    items = frame.mass_items
    inertia = items.inertia / SLUG_FT2
    mass_items = pd.DataFrame({
        "id": items.ids, "description": items.description,
        "mass [lb]": np.round(items.mass / POUND, 1),
        **{f"{c} [in]": np.round(items.position[:, j] / INCH, 2) for j, c in enumerate("xyz")},
        **{f"I{a}{a} [slug ft^2]": np.round(inertia[:, j, j], 2) for j, a in enumerate("xyz")},
    })
    hp = frame.hardpoints
    rows = [("HUB", "hub", *hp.hub), *((i, "mast_foot", *p) for i, p in zip(
        hp.mast_feet_ids, hp.mast_feet, strict=True)),
        ("CHUTE_FITTING", "chute", *hp.chute), ("FIN_CP", "fin_cp", *fin_cp),
        ("AERO_REF", "aero_reference", *aero_ref)]
    hardpoints = pd.DataFrame({"id": [r[0] for r in rows], "kind": [r[1] for r in rows],
                               **{f"{c} [in]": [round(r[2 + j] / INCH, 2) for r in rows]
                                  for j, c in enumerate("xyz")},
                               "weight [-]": 1.0})
    motions = pd.DataFrame({
        "id": ["QUI-0.2g-11s", "CYC-0.36g-12s"], "type": ["quintic step", "cycloidal step"],
        "acceleration [g0]": [0.2, 0.36], "duration [s]": [11.0, 12.0],
        "description": ["minimum-jerk sidestep, 0.2 g peak (light-twin example's motion)",
                        "cycloidal sidestep at the 20 deg bank limit (TM 1-1670-260-12&P)"]})
    manoeuvres = pd.DataFrame({
        "name": ["free response 10 deg yaw"], "kind": ["free response"], "shape": [""],
        "direction": [""], "amplitude [ft/s]": [None], "onset [s]": [None],
        "duration [s]": [None], "target [kt]": [None], "rate [m/s^2]": [None],
        "yaw [deg]": [10.0], "description": ["paper 4.4: free response"]})
    return {
        "MassItems": mass_items,
        "Stations": pd.DataFrame({"id": frame.station_ids,
                                  "x [in]": np.round(frame.stations / INCH, 2)}),
        "Hardpoints": hardpoints,
        "FuselageAero": sample_fuselage(SAMPLE).table.to_frame(),
        "FinAero": sample_fin(SAMPLE).table.to_frame(),
        "AeroEnvelope": pd.DataFrame({"id": ["CENTRE", "A+B+", "A+B-", "A-B+", "A-B-"],
                                      "alpha [deg]": [0, 10, 10, -10, -10],
                                      "beta [deg]": [0, 15, -15, 15, -15]}),
        "LateralMotions": motions,
        "LateralRopes": pd.DataFrame({"rope length [ft]": [60.0],
                                      "description": ["paper: medium rope"]}),
        "ChuteWake": WAKE,
        "MultibodyManoeuvres": manoeuvres,
    }


def parameters(chute_area, chute_line):
    ref = sample_reference(SAMPLE)
    return {
        "study name": ("Generic 4.9 t twin, US units, hub forward of the CG (EXAMPLE)", ""),
        "project": ("slingloads example: GENERIC 4.9 t twin (not a real aircraft)", ""),
        "document number": ("EXAMPLE-002", ""),
        "run loads": ("yes", ""), "run lateral": ("yes", ""), "run chute sizing": ("yes", ""),
        "run multibody": ("yes", ""), "run campaign": ("yes", ""),
        "airspeed EAS": (100, "kt"), "density altitude": (0, "ft"),
        "hook load factor Nz": (2.5, ""), "attitude": ("hanging", ""),
        "hook angle from vertical": (30, "deg"), "hook cone shape": ("lateral directions", ""),
        "towed equilibrium cases": ("yes", ""), "hook azimuths": (8, ""),
        "fuselage force axes": ("wind", ""), "fuselage moment axes": ("body", ""),
        "fin axes": ("body", ""), "parachute table axes": ("wind", ""),
        "reference axis y": (0, "in"), "reference axis z": (round(SCALE / INCH, 2), "in"),
        "fuselage reference area": (round(ref.fuselage_area * SCALE**2 / FOOT**2, 2), "ft^2"),
        "fuselage reference length": (round(ref.fuselage_length * SCALE / FOOT, 2), "ft"),
        "fin area": (round(ref.fin_area * SCALE**2 / FOOT**2, 2), "ft^2"),
        "fin efficiency": (ref.fin_efficiency, ""),
        "parachute area": (chute_area, "ft^2"), "parachute wake ratio": (0.95, ""),
        "parachute line length": (chute_line, "ft"), "parachute opening factor": (1.0, ""),
        # lateral: one rope, two flyable motions, 2 x 2 x 2 spread
        "lateral design-angle margin": (1.5, ""), "lateral cable model": ("rigid", ""),
        "lateral damping source": ("aerodynamic tables", ""),
        "lateral airspeed EAS": (0, "kt"), "lateral spread points": (2, ""),
        "lateral roll inertia spread": (0.2, ""), "lateral CG below hub spread": (0.2, ""),
        "lateral rope length spread": (0.2, ""),
        "lateral simulation time": (40, "s"), "lateral RK4 step": (0.05, "s"),
        # sizing: three areas, two gust shapes
        "chute sizing airspeed IAS": (80, "kt"), "chute sizing density altitude": (0, "ft"),
        "chute sizing alpha trim": (0, "deg"), "chute sizing linearisation range": (15, "deg"),
        "chute sizing yaw inertia source": ("mass items", ""),
        "chute sizing wake source": ("table", ""), "chute sizing target q ratio": (0.95, ""),
        "chute sizing carrier cable length": (60, "ft"),
        "chute sizing gust shapes": ("step, finite", ""),
        "chute sizing gust amplitude": (30, "ft/s"), "chute sizing gust onset": (5, "s"),
        "chute sizing gust duration": (10, "s"), "chute sizing simulation time": (60, "s"),
        "chute sizing area factor min": (1.0, ""), "chute sizing area factor max": (2.0, ""),
        "chute sizing number of areas": (3, ""),
        # multibody: one manoeuvre of 20 s at 80 KEAS
        "multibody airspeed EAS": (80, "kt"), "multibody density altitude": (0, "ft"),
        "multibody configuration": ("with parachute", ""),
        "multibody tail": ("cut-down fin", ""), "multibody parachute model": ("hinged", ""),
        "multibody parachute area": (0, "ft^2"), "multibody canopy mass": (3.0, "kg"),
        "multibody canopy CD": ("extended", ""), "multibody cable length": (60, "ft"),
        "multibody cable EA": (1.1e6, "lbf"), "multibody cable damping ratio": (0.05, ""),
        "multibody carrier": ("frozen", ""), "multibody simulation time": (20, "s"),
        "multibody output interval": (0.5, "s"),
        # campaign: 2 areas x 1 airspeed, free response, 20 s; HC2 without parachute, one ramp
        "campaign area factors": ("1.4, 2.0", ""), "campaign airspeeds EAS": ("80", "kt"),
        "campaign density altitudes": ("0", "ft"), "campaign cable lengths": ("60", "ft"),
        "campaign carriers": ("frozen", ""), "campaign manoeuvres": ("free response", ""),
        "campaign run length": (20, "s"), "campaign output interval": (0.5, "s"),
        "campaign stability map areas": (2, ""), "campaign stability map airspeeds": (1, ""),
        "campaign no-parachute helicopters": ("HC2", ""),
        "campaign no-parachute ramps": ("20", "kt"),
        "campaign no-parachute gust ramps": ("20, 30", "kt"),
        "campaign no-parachute gust": (10, "ft/s"), "campaign loads margin": (1.25, ""),
    }


def main():
    frame, fin_cp, aero_ref = airframe()
    area, line = parachute_size(frame, fin_cp, aero_ref)
    write_input_workbook(OUT, parameters(area, line), tables(frame, fin_cp, aero_ref), NOTES)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()

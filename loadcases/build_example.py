"""Build ``loadcases/example-light-twin.xlsx``, the example input workbook.

Run from the repository root: ``python loadcases/build_example.py``. The workbook describes a
GENERIC light-twin helicopter of about 2.9 t (not any real aircraft) in the paper's transport
configuration: main and tail rotor blades and the horizontal tailplane removed, about half of
the vertical fin cut away, the drogue parachute attached on the fin. Sources and assumptions
are written into the workbook's README sheet.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pandas as pd

from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import LoadsStudy
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.constants import INCH, POUND
from slingloads.io.template import write_input_workbook
from slingloads.models.airframe import Airframe, Hardpoints, MassItems
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_reference

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
OUT = HERE / "example-light-twin.xlsx"

from example_inertia import NOTE as INERTIA_NOTE  # noqa: E402 (needs HERE on the path)
from example_inertia import own_inertias  # noqa: E402

# id, description, mass [kg], x, y, z [m]  (x aft from the nose, z up from the skid plane)
MASS_ITEMS = [
    ("NOSE", "nose structure, avionics bay", 120, 0.80, 0.00, 0.90),
    ("CKPT", "cockpit structure, windshield", 180, 1.60, 0.00, 1.00),
    ("CREW", "crew seats and flight controls", 60, 1.90, 0.00, 1.00),
    ("CABF", "cabin floor and structure, forward", 220, 2.60, 0.00, 0.70),
    ("CABI", "cabin interior and furnishings", 150, 3.00, 0.00, 1.00),
    ("RECV", "cabin equipment and recovery fittings", 200, 3.40, 0.00, 0.90),
    ("CABA", "cabin structure, aft", 220, 3.50, 0.00, 0.80),
    ("ELEC", "electrical and hydraulic systems", 80, 3.80, 0.00, 1.30),
    ("FUEL", "fuel tanks with residual fuel", 250, 4.00, 0.00, 0.50),
    ("DECK", "transmission deck structure", 160, 4.30, 0.00, 1.60),
    ("MGB", "main gearbox", 200, 4.30, 0.00, 1.80),
    ("HUB", "mast and rotor hub, blades removed", 150, 4.30, 0.00, 2.20),
    ("ENG1", "engine 1 (left)", 115, 5.00, -0.35, 1.60),
    ("ENG2", "engine 2 (right)", 115, 5.00, 0.35, 1.60),
    ("COWL", "cowlings and exhausts", 60, 5.50, 0.00, 1.70),
    ("RFUS", "rear fuselage structure", 180, 5.40, 0.00, 1.00),
    ("SKXF", "skid forward cross tube", 45, 3.00, 0.00, 0.05),
    ("SKXA", "skid aft cross tube", 45, 4.80, 0.00, 0.05),
    ("SKTL", "skid tube left", 30, 3.80, -1.00, 0.00),
    ("SKTR", "skid tube right", 30, 3.80, 1.00, 0.00),
    ("BOOMF", "tail boom, forward half", 90, 6.80, 0.00, 1.20),
    ("BOOMA", "tail boom, aft half", 70, 8.60, 0.00, 1.30),
    ("TRDS", "tail rotor drive shaft", 40, 8.00, 0.00, 1.50),
    ("TGB", "intermediate and tail gearboxes", 30, 10.00, 0.00, 1.60),
    ("FIN", "vertical fin (cut down), tail rotor hub", 35, 10.50, 0.00, 2.00),
    ("CHUTE", "parachute pack and fitting on the fin", 25, 10.75, 0.00, 2.30),
]

NOTES = [
    "EXAMPLE ONLY. GENERIC light-twin helicopter of about 2.9 t (not any real aircraft), in the "
    "paper's transport configuration: main and tail rotor blades and horizontal tailplane removed, "
    "about half of the vertical fin cut away (fin efficiency 0.5), drogue parachute on the fin.",
    "Mass items: invented breakdown summing to 2900 kg with a fuselage about 11 m long, in the "
    "class of the EC135/H135 (MTOW 2630-2980 kg, length 12.26 m, FACTS: manufacturers' data) "
    "less its blades. Positions in inches, masses in pounds, to show US customary input.",
    INERTIA_NOTE,
    "Aerodynamics: the GENERIC HC1 fuselage and fin tables of slingloads/data (SAMPLE_DATA.md): "
    "UH-60-class coefficient magnitudes scaled to a light twin; Prouty flat-plate areas. "
    "Fuselage forces in wind axes, moments in body axes, fin in body axes (Study rows "
    "'fuselage force axes', 'fuselage moment axes', 'fin axes').",
    "Attitude: hanging (CG under the hub: the hub is 0.17 m aft of the CG, so the airframe "
    "hangs 9.2 deg nose down); gravity, the vertical hook case and the 30 deg cone are taken "
    "about that vertical. Towed-flight equilibrium cases are added per envelope point.",
    "Parachute: flat-plate area 1.4 x the neutral-static-stability area of the sizing (the paper's "
    "FPA + 40 %); canopy CD 1.0 (free stream, the default ParachuteCD) within +-8 deg and wake "
    "ratio 0.95: the paper's 0.95 in all, the 5 % wake loss counted once, in the wake ratio "
    "(paper, sections 3.2, 3.3 and 4.5).",
    "Previous design envelope: ILLUSTRATIVE, the same airframe under its own rotor thrust "
    "(hook cone 10 deg, Nz 3.5 of CS 29.337, no parachute), standing in for the loads the "
    "structure was designed to before the sling-load role. It never contained a hub load "
    "inclined 30 deg, fuselage aerodynamics or parachute drag, so the sling-load envelope "
    "exceeds it by construction (Study 'previous envelope source' says where and why).",
    "Angle envelope: alpha +-10 deg, beta +-15 deg (corners and centre), standing in for the "
    "multibody campaign's envelope (paper, section 4.5).",
]


def airframe():
    ids, desc, mass, x, y, z = zip(*MASS_ITEMS, strict=True)
    items = MassItems(ids, np.array(mass, float), np.column_stack([x, y, z]),
                      own_inertias(ids, mass), description=desc)
    cg = items.cg
    ref = sample_reference("HC1")
    hub = np.array([4.30, 0.0, 2.20])
    feet = np.array([[4.00, -0.35, 1.55], [4.00, 0.35, 1.55], [4.60, -0.35, 1.55],
                     [4.60, 0.35, 1.55]])
    chute = np.array([10.75, 0.0, 2.30])
    hardpoints = Hardpoints(hub, feet, chute=chute,
                            mast_feet_ids=("MAST_FL", "MAST_FR", "MAST_AL", "MAST_AR"))
    # every 0.46 m, without the two end cuts (0.40 and 11.00 m) beyond the first and last load
    # points (nose item at 0.80 m, parachute fitting at 10.75 m), where nothing is cut
    stations = np.round(np.linspace(0.40, 11.00, 24), 3)[1:-1]
    frame = Airframe(items, stations, hardpoints, reference_axis=(0.0, 1.0),
                     station_ids=tuple(f"FS{round(s / INCH):04d}" for s in stations),
                     name="Generic light twin")
    fin_cp = cg + np.array(ref.fin_centre_of_pressure)
    aero_ref = cg + np.array(ref.moment_reference)
    return frame, fin_cp, aero_ref


#: Where the example's previous envelope comes from, quoted by the loads report.
PREVIOUS_SOURCE = (
    "ILLUSTRATIVE, made by loadcases/build_example.py: the same generic airframe lifted by "
    "its own rotor (hub load Nz 3.5 on a 10 deg cone, no aerodynamic or parachute load; "
    "magnitudes made symmetric). The sling-load cases incline the hub load 30 deg (CS 29.865) "
    "at Nz 2.5 and add fuselage, fin and parachute loads, so Vx, Vy, Mx and Mz exceed it by "
    "construction, about (2.5 sin 30)/(3.5 sin 10) = 2.1 times from the hook alone; Vz exceeds "
    "it only between the mast feet (couple of the inclined hub load) and My and Vz aft, where "
    "the parachute drag acts. The exceedances show what the sling-load role adds to an "
    "envelope that never contained it; they are not an error of the analysis.")


def previous_envelope(frame):
    """Illustrative previous design envelope: own rotor thrust, 10 deg cone, Nz 3.5."""
    # rotor thrust along the mast: the mast is the vertical here, not the hanging attitude
    study = LoadsStudy(frame, hook=HookLoadOptions(nz=3.5, angle=np.radians(10.0), towed=False),
                       attitude="mast vertical")
    result = study.run()
    hi, lo = result.loads.max(axis=0), result.loads.min(axis=0)
    # a previous envelope also covers the negative manoeuvre (-1 g): mirror the vertical terms
    data = {"x [in]": frame.stations / INCH}
    for j, name in enumerate(COMPONENTS):
        unit = "lbf" if j < 3 else "lbf in"
        scale = 4.4482216152605 if j < 3 else 4.4482216152605 * INCH
        span = np.maximum(np.abs(hi[:, j]), np.abs(lo[:, j]))
        data[f"{name} min [{unit}]"] = np.round(-span / scale, 0)
        data[f"{name} max [{unit}]"] = np.round(span / scale, 0)
    return pd.DataFrame(data)


def main():
    frame, fin_cp, aero_ref = airframe()
    chute_area, chute_line = parachute_size(frame, fin_cp, aero_ref)
    items = frame.mass_items
    mass_items = pd.DataFrame({
        "id": items.ids, "description": items.description,
        "mass [lb]": np.round(items.mass / POUND, 2),
        "x [in]": np.round(items.position[:, 0] / INCH, 2),
        "y [in]": np.round(items.position[:, 1] / INCH, 2),
        "z [in]": np.round(items.position[:, 2] / INCH, 2),
        **{f"I{a}{a} [kg m^2]": np.round(items.inertia[:, j, j], 2)
           for j, a in enumerate("xyz")},
    })
    stations = pd.DataFrame({"id": frame.station_ids,
                             "x [in]": np.round(frame.stations / INCH, 2)})
    hp = frame.hardpoints
    rows = [("HUB", "hub", *hp.hub, 1.0)]
    rows += [(i, "mast_foot", *p, 1.0) for i, p in zip(hp.mast_feet_ids, hp.mast_feet,
                                                       strict=True)]
    rows += [("CHUTE_FITTING", "chute", *hp.chute, 1.0), ("FIN_CP", "fin_cp", *fin_cp, 1.0),
             ("AERO_REF", "aero_reference", *aero_ref, 1.0)]
    hardpoints = pd.DataFrame(rows, columns=["id", "kind", "x", "y", "z", "weight [-]"])
    for c in ("x", "y", "z"):
        hardpoints[f"{c} [in]"] = np.round(hardpoints.pop(c) / INCH, 2)
    hardpoints = hardpoints[["id", "kind", "x [in]", "y [in]", "z [in]", "weight [-]"]]
    fuselage = sample_fuselage("HC1").table.to_frame()
    fin = sample_fin("HC1").table.to_frame()
    envelope = pd.DataFrame({"id": ["CENTRE", "A+B+", "A+B-", "A-B+", "A-B-"],
                             "alpha [deg]": [0, 10, 10, -10, -10],
                             "beta [deg]": [0, 15, -15, 15, -15]})
    ref = sample_reference("HC1")
    parameters = {
        "study name": ("Generic light twin, sling-load transport (EXAMPLE)", ""),
        "run loads": ("yes", ""),
        "airspeed EAS": (100, "kt"),
        "density altitude": (0, "ft"),
        "hook load factor Nz": (2.5, ""),
        "attitude": ("hanging", ""),
        "hook angle from vertical": (30, "deg"),
        "hook cone shape": ("lateral directions", ""),
        "towed equilibrium cases": ("yes", ""),
        "fuselage force axes": ("wind", ""),
        "fuselage moment axes": ("body", ""),
        "fin axes": ("body", ""),
        "parachute table axes": ("wind", ""),
        "hook azimuths": (8, ""),
        "reference axis y": (0, "in"),
        "reference axis z": (round(1.0 / INCH, 2), "in"),
        "fuselage reference area": (ref.fuselage_area, "m^2"),
        "fuselage reference length": (ref.fuselage_length, "m"),
        "fin area": (ref.fin_area, "m^2"),
        "fin efficiency": (ref.fin_efficiency, ""),
        "parachute area": (chute_area, "m^2"),
        "parachute wake ratio": (0.95, ""),
        "parachute line length": (chute_line, "m"),
        "parachute opening factor": (1.0, ""),
        "hull stations": ("FS0161", ""),
        "project": ("slingloads example: GENERIC light twin (not a real aircraft)", ""),
        "document number": ("EXAMPLE-001", ""),
        "previous envelope source": (PREVIOUS_SOURCE, ""),
    }
    tables = {"MassItems": mass_items, "Stations": stations, "Hardpoints": hardpoints,
              "FuselageAero": fuselage, "FinAero": fin, "AeroEnvelope": envelope,
              "PreviousEnvelope": previous_envelope(frame)}
    tables.update(EXTRA_TABLES)
    parameters.update(EXTRA_PARAMETERS)
    write_input_workbook(OUT, parameters, tables, NOTES)
    print(f"wrote {OUT}")


def parachute_size(frame, fin_cp, aero_ref):
    """Parachute flat-plate area [m^2] and line length [m] of the example: 1.4 x the neutral
    static area and the wake line of its own sizing, computed through the API
    (loadcases/example_chute.py); (4.0, 12.0) without that file."""
    try:
        import example_chute
    except ModuleNotFoundError as err:
        if err.name != "example_chute":
            raise
        return 4.0, 12.0
    return example_chute.parachute_size(frame, fin_cp, aero_ref)


#: Sheets and parameters of the lateral-pendulum and parachute-sizing studies and of the
#: multibody model and the campaign, from loadcases/example_lateral.py, example_chute.py,
#: example_multibody.py and example_campaign.py (each defines TABLES and PARAMETERS, and may
#: define NOTES).
EXTRA_TABLES = {}
EXTRA_PARAMETERS = {}
for _module in ("example_lateral", "example_chute", "example_multibody", "example_campaign"):
    try:
        _part = __import__(_module)
    except ModuleNotFoundError as _err:
        if _err.name != _module:
            raise
        continue
    EXTRA_TABLES.update(_part.TABLES)
    EXTRA_PARAMETERS.update(_part.PARAMETERS)
    NOTES += list(getattr(_part, "NOTES", []))

if __name__ == "__main__":
    main()

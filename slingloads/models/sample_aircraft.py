"""GENERIC sample carried helicopters HC1 and HC2: aerodynamic tables and reference quantities.

HC1 and HC2 are invented light-twin helicopters (about 2.9 t, fuselage about 11 m long) for
examples and tests. They are **not** any real aircraft's data: the tables are smooth analytic
shapes (``docs/sample-data/generate_sample_tables.py``) with magnitudes taken from UH-60-class
fuselage and fin data scaled by reference area and length, and mass properties scaled from the
BO-105 (NASA CR-3144) by mass and length squared. HC2 is the less stable in yaw. Provenance,
formulas and the numbers below are in ``slingloads/data/SAMPLE_DATA.md``.

Positions are in airframe axes (x aft, y right, z up) with the origin at the centre of gravity.

Examples
--------
>>> from slingloads.models.sample_aircraft import sample_fuselage, sample_fin
>>> fuselage = sample_fuselage("HC1")
>>> round(fuselage.area, 2), round(fuselage.length, 2)
(3.0, 11.5)
>>> float(sample_fin("HC1").table("CY", 0.0))
0.0
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import FUSELAGE_COEFFICIENTS, Fin, FuselageAero
from slingloads.models.airframe import Hardpoints


@dataclass(frozen=True)
class SampleReference:
    """Reference quantities of a generic sample helicopter (origin at its CG).

    Parameters
    ----------
    name : str
    mass : float
        Mass in the transport configuration (blades removed). [kg]
    yaw_inertia : float
        Izz about the vertical through the CG. [kg m^2]
    fuselage_area : float
        Fuselage reference area S. [m^2]
    fuselage_length : float
        Fuselage reference length L. [m]
    moment_reference : tuple of float
        Point about which the fuselage moment coefficients are given. [m]
    fin_area : float
        Intact fin area on which the fin ``CY`` is given. [m^2]
    fin_centre_of_pressure : tuple of float
        [m]
    fin_efficiency : float
        Share of side force the cut-down fin keeps. [-]
    hub : tuple of float
        Rotor hub (cable attachment; the suspension axis is the vertical through it). [m]
    chute : tuple of float
        Parachute attachment on the fin. [m]
    htail_area : float
        Horizontal tail area of the full-tail configuration. [m^2]
    htail_centre_of_pressure : tuple of float
        [m]
    roll_inertia, pitch_inertia : float
        Ixx and Iyy about the CG, scaled from the BO-105C like ``yaw_inertia``. [kg m^2]
    """

    name: str
    mass: float
    yaw_inertia: float
    fuselage_area: float
    fuselage_length: float
    moment_reference: tuple
    fin_area: float
    fin_centre_of_pressure: tuple
    fin_efficiency: float
    hub: tuple
    chute: tuple
    htail_area: float = 1.1
    htail_centre_of_pressure: tuple = (5.0, 0.0, 0.4)
    roll_inertia: float = 3700.0
    pitch_inertia: float = 9900.0


#: The generic sample aircraft. Keep in step with slingloads/data/SAMPLE_DATA.md.
SAMPLES = {
    "HC1": SampleReference(
        name="HC1", mass=2900.0, yaw_inertia=9000.0, fuselage_area=3.0, fuselage_length=11.5,
        moment_reference=(0.25, 0.0, -0.3), fin_area=0.9, fin_centre_of_pressure=(5.9, 0.0, 1.1),
        fin_efficiency=0.5, hub=(0.0, 0.0, 1.0), chute=(6.4, 0.0, 1.6),
        htail_area=1.2, htail_centre_of_pressure=(5.0, 0.0, 0.4)),
    "HC2": SampleReference(
        name="HC2", mass=2850.0, yaw_inertia=8500.0, fuselage_area=3.2, fuselage_length=11.0,
        moment_reference=(0.2, 0.0, -0.3), fin_area=0.8, fin_centre_of_pressure=(5.5, 0.0, 1.0),
        fin_efficiency=0.5, hub=(0.0, 0.0, 0.95), chute=(6.0, 0.0, 1.5),
        htail_area=1.0, htail_centre_of_pressure=(4.7, 0.0, 0.4), roll_inertia=3500.0,
        pitch_inertia=9400.0),
}


def sample_reference(name="HC1"):
    """Reference quantities of a sample aircraft.

    Parameters
    ----------
    name : {"HC1", "HC2"}
        Sample aircraft (case ignored).

    Returns
    -------
    SampleReference
        Mass [kg], inertias [kg m^2], areas [m^2], positions [m] and the other fields in SI.

    Raises
    ------
    InputError
        For an unknown name.
    """
    key = str(name).upper()
    if key not in SAMPLES:
        raise InputError(f"unknown sample aircraft; valid names are {sorted(SAMPLES)}", name)
    return SAMPLES[key]


@lru_cache(maxsize=8)
def _read_csv(filename):
    path = resources.files("slingloads").joinpath("data", filename)
    with path.open("r", encoding="utf-8") as handle:
        return pd.read_csv(handle)


def sample_fuselage(name="HC1"):
    """Fuselage-alone aerodynamics (blades and tailplane removed) of a sample aircraft.

    Parameters
    ----------
    name : str
        ``"HC1"`` or ``"HC2"``.

    Returns
    -------
    FuselageAero
        Table over alpha -40..40 deg and beta -180..180 deg, with the sample's reference area,
        length and moment reference point.
    """
    ref = sample_reference(name)
    frame = _read_csv(f"{ref.name.lower()}_fuselage.csv")
    table = Table2D.from_long(
        np.radians(frame["alpha [deg]"].to_numpy()), np.radians(frame["beta [deg]"].to_numpy()),
        {c: frame[c].to_numpy() for c in FUSELAGE_COEFFICIENTS},
        what=f"{ref.name} fuselage")
    return FuselageAero(table, ref.fuselage_area, ref.fuselage_length,
                        np.array(ref.moment_reference))


def sample_fin(name="HC1", efficiency=None):
    """Vertical fin of a sample aircraft (intact-fin CY, cut-down efficiency 0.5 by default).

    Parameters
    ----------
    name : str
        ``"HC1"`` or ``"HC2"``.
    efficiency : float, optional
        Overrides the sample's fin efficiency. [-]

    Returns
    -------
    Fin
    """
    ref = sample_reference(name)
    frame = _read_csv(f"{ref.name.lower()}_fin.csv")
    table = Table1D(np.radians(frame["beta [deg]"].to_numpy()), {"CY": frame["CY"].to_numpy()},
                    angle_name="beta", what=f"{ref.name} fin")
    eta = ref.fin_efficiency if efficiency is None else efficiency
    return Fin(table, ref.fin_area, np.array(ref.fin_centre_of_pressure), eta)


def sample_body(name="HC1"):
    """Mass properties of a sample aircraft: mass, CG at the origin, principal inertias
    (roll, pitch, yaw) about the CG, no product of inertia.

    Parameters
    ----------
    name : {"HC1", "HC2"}
        Sample aircraft (case ignored).

    Returns
    -------
    RigidBody
    """
    from slingloads.models.multibody.rigid_body import RigidBody  # compiled: load lazily

    ref = sample_reference(name)
    return RigidBody(ref.mass, np.zeros(3),
                     np.diag([ref.roll_inertia, ref.pitch_inertia, ref.yaw_inertia]), ref.name)


def sample_hardpoints(name="HC1"):
    """Hardpoints of a sample aircraft: hub, four mast feet 0.4 m below it, fin
    attachment.

    Parameters
    ----------
    name : {"HC1", "HC2"}
        Sample aircraft (case ignored).

    Returns
    -------
    Hardpoints
        Airframe axes. [m]
    """
    ref = sample_reference(name)
    hub = np.array(ref.hub)
    feet = hub + np.array([[-0.4, -0.4, -0.4], [-0.4, 0.4, -0.4],
                           [0.4, -0.4, -0.4], [0.4, 0.4, -0.4]])
    return Hardpoints(hub=hub, mast_feet=feet, chute=np.array(ref.chute))


def sample_htail(name="HC1"):
    """Horizontal tail of a sample aircraft (full-tail configuration of the transport without
    parachute, paper section 5): normal-force coefficient CN against its local angle of attack,
    -180..180 deg, on ``htail_area``.

    Parameters
    ----------
    name : {"HC1", "HC2"}
        Sample aircraft (case ignored).

    Returns
    -------
    LiftingSurface
    """
    from slingloads.models.multibody.local_flow import LiftingSurface  # compiled: load lazily

    ref = sample_reference(name)
    frame = _read_csv(f"{ref.name.lower()}_htail.csv")
    table = Table1D(np.radians(frame["alpha [deg]"].to_numpy()), {"CN": frame["CN"].to_numpy()},
                    angle_name="alpha", what=f"{ref.name} horizontal tail")
    return LiftingSurface(table, ref.htail_area, np.array(ref.htail_centre_of_pressure), "z",
                          1.0, "horizontal tail")


def sample_surfaces(name="HC1", configuration="transport"):
    """Lifting surfaces of a sample aircraft for the multibody model.

    Parameters
    ----------
    name : str
    configuration : {"transport", "full tail"}
        "transport": the cut-down fin alone (paper section 3.1, efficiency 0.5); "full tail":
        the intact fin (efficiency 1) and the horizontal tail (paper section 5.1).

    Returns
    -------
    tuple of LiftingSurface
    """
    from slingloads.models.multibody.local_flow import LiftingSurface  # compiled: load lazily

    if configuration == "transport":
        return (LiftingSurface.from_fin(sample_fin(name)),)
    if configuration == "full tail":
        return (LiftingSurface.from_fin(sample_fin(name, efficiency=1.0)), sample_htail(name))
    raise InputError(f"{configuration=!r} is not a valid configuration; valid configurations "
                     f"are ['transport', 'full tail']", configuration)

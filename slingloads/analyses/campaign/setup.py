"""From one towed system to the system of every run: the campaign's set-up.

:class:`CampaignSetup` holds the base :class:`~slingloads.models.multibody.SlingSystem` (its
helicopter, hardpoints, aerodynamics, cable stiffness and parachute template) and the free
carrier that the runs with ``carrier = "free"`` use. :meth:`CampaignSetup.system_for` replaces,
for one row of the matrix, the parachute area, the airspeed, the mass (inertia scaled with it,
CG kept), the density altitude, the cable length and the carrier. Every run of a campaign
shares the base's aerodynamic tables, so that the runs batch together.

The neutral static area is that of the parachute-sizing analysis
(:func:`slingloads.analyses.chute_sizing.neutral_area`, paper section 4.1) on the base's own
fuselage, fin, hardpoints, yaw inertia and weight about the suspension axis (the trim's cable
line through the hub): :func:`neutral_area_of`. Its yaw model (:func:`yaw_model_of`) reads the
fuselage tables at the
towed trim's angle of attack at its condition (airspeed, density altitude; the system with its
parachute), from :func:`slingloads.analyses.towed_attitude.towed_attitude`, the attitude the
parachute sizing, the loads' towed cases and the multibody trim fly: the campaign's neutral area
is then the sizing's at the same condition. Where no trim is found the model stays at alpha 0,
and :func:`trim_text` says so (the campaign's Summary prints it beside the neutral area).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from slingloads.analyses.chute_sizing import FIT_RANGE, neutral_area
from slingloads.analyses.towed_attitude import towed_attitude, yaw_model_about
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.aerodynamics import Fin
from slingloads.models.airframe import hanging_yaw_inertia
from slingloads.models.multibody.carrier import FreeCarrier, FrozenCarrier
from slingloads.models.multibody.rigid_body import RigidBody
from slingloads.models.multibody.system import SlingSystem
from slingloads.models.yaw_dynamics import FlightCondition, YawModel

#: GENERIC free carrier: heavy-lift class, 15,000 kg (an assumption), flat-plate drag area
#: 43.2 ft^2 = 4.0 m^2 (Prouty, Table 4.3, CH-47), speed-hold gain of the model's default.
DEFAULT_FREE_CARRIER = FreeCarrier(15000.0, 4.0)


def scaled_body(body, mass):
    """The helicopter at another mass: inertia scaled by mass ratio, CG kept.

    Parameters
    ----------
    body : RigidBody
    mass : float
        [kg]

    Returns
    -------
    RigidBody
    """
    mass = float(mass)
    if not np.isfinite(mass) or mass <= 0:
        raise InputError("mass case must be > 0 [kg]", mass)
    if mass == body.mass:
        return body
    return RigidBody(mass, body.cg, body.inertia * (mass / body.mass), body.name)


def towed_trim_of(system, airspeed=None, density_altitude=None):
    """The towed trim of a system with its parachute at a condition (module notes).

    Parameters
    ----------
    system : SlingSystem
    airspeed, density_altitude : float, optional
        Condition (default: the system's). [m/s], [m]

    Returns
    -------
    TowedAttitude
        :func:`~slingloads.analyses.towed_attitude.towed_attitude` of the system (converged
        or with the trim's reason).
    """
    if density_altitude is not None and float(density_altitude) != system.density_altitude:
        system = system.with_(density_altitude=float(density_altitude))
    return towed_attitude(system, airspeed)


def trim_text(towed, density_altitude):
    """The condition of a yaw model in words: the trim's angle of attack, or alpha 0 and why.

    Parameters
    ----------
    towed : TowedAttitude
    density_altitude : float
        [m]

    Returns
    -------
    str
    """
    where = (f"{towed.airspeed / KNOT:.0f} KEAS, density altitude "
             f"{density_altitude:.0f} m")  # SI: a US report quotes it in ft (report_text)
    if towed.converged:
        return f"at the towed trim, alpha {np.degrees(towed.alpha):.3g} deg ({where})"
    return f"at alpha 0: no towed trim at {where} ({towed.message})"


def yaw_model_of(system, airspeed=None, density_altitude=None, towed=None,
                 axis="suspension"):
    """The 1-DOF yaw model (:class:`~slingloads.models.yaw_dynamics.YawModel`) of a towed
    system: its fuselage, fin, hardpoints and parachute at the towed trim's angle of attack
    (:func:`towed_trim_of`; alpha 0 when no trim is found), with its yawing moments, yaw
    inertia and weight about one axis through the hub
    (:func:`~slingloads.analyses.towed_attitude.yaw_model_about`: by default the suspension
    axis, the trim's cable line), as the parachute sizing takes them.

    Parameters
    ----------
    system : SlingSystem
        With a parachute.
    airspeed, density_altitude : float, optional
        Condition (default: the system's). [m/s], [m]
    towed : TowedAttitude, optional
        The trim at that condition (default: :func:`towed_trim_of`).
    axis : {"suspension", "airframe z"}
        The yaw model's axis (:data:`~slingloads.models.yaw_dynamics.YAW_AXES`).

    Returns
    -------
    YawModel
    """
    if system.parachute is None:
        raise InputError("the yaw model of a campaign needs a parachute")
    fin = system.fin
    fin = None if fin is None else Fin(fin.table, fin.area, fin.centre_of_pressure,
                                       fin.efficiency)
    body = system.body
    inertia = hanging_yaw_inertia(body.inertia, body.cg, system.hardpoints.hub)
    speed = system.airspeed if airspeed is None else airspeed
    altitude = system.density_altitude if density_altitude is None else density_altitude
    if towed is None:
        towed = towed_trim_of(system, speed, altitude)
    model = YawModel(system.fuselage, fin, system.hardpoints, inertia,
                     FlightCondition(speed, altitude, 0.0), system.parachute.parachute)
    return yaw_model_about(model, axis, towed, body)[0]


def neutral_area_of(system, airspeed=None, fit_range=FIT_RANGE, towed=None,
                    axis="suspension"):
    """Neutral yaw static stability area of a towed system (paper section 4.1), at the towed
    trim's angle of attack (:func:`yaw_model_of`).

    Parameters
    ----------
    system : SlingSystem
        With a parachute.
    airspeed : float, optional
        Equivalent airspeed (default the system's). [m/s]
    fit_range : (float, float)
        Sideslip range of the slope fits. [rad]
    towed : TowedAttitude, optional
        The trim at that airspeed (default: :func:`towed_trim_of`).
    axis : {"suspension", "airframe z"}
        The yaw model's axis (:func:`yaw_model_of`).

    Returns
    -------
    NeutralAreaResult
        ``.area`` [m^2] (not positive when fuselage and fin are already stable).
    """
    speed = system.airspeed if airspeed is None else airspeed
    if not speed > 0:
        raise InputError("the neutral area needs an airspeed > 0 [m/s]", speed)
    return neutral_area(yaw_model_of(system, speed, towed=towed, axis=axis), fit_range)


@dataclass(frozen=True, eq=False)
class CampaignSetup:
    """The base system of a campaign and its free carrier (module notes).

    Parameters
    ----------
    system : SlingSystem
        With a parachute (its area is replaced by each run's).
    free_carrier : FreeCarrier
        The carrier of the runs with carrier "free".
    """

    system: SlingSystem
    free_carrier: FreeCarrier = field(default_factory=lambda: DEFAULT_FREE_CARRIER)

    def __post_init__(self):
        if not isinstance(self.system, SlingSystem):
            raise InputError("a campaign needs a SlingSystem", type(self.system).__name__)
        if self.system.parachute is None:
            raise InputError("the campaign's system needs a parachute (its area is the "
                             "campaign's first factor)")
        if not isinstance(self.free_carrier, FreeCarrier):
            raise InputError("the campaign's free carrier must be a FreeCarrier",
                             type(self.free_carrier).__name__)

    @property
    def base_mass(self):
        """[kg]"""
        return self.system.body.mass

    def system_for(self, row):
        """The system of one run (a row of :attr:`CampaignMatrix.frame`).

        Parameters
        ----------
        row : mapping
            A row of the campaign matrix (area [m^2], mass [kg], airspeed EAS [m/s], density
            altitude [m], cable length [m], carrier).

        Returns
        -------
        SlingSystem
        """
        base = self.system
        holder = base.parachute
        chute = replace(holder, parachute=replace(holder.parachute,
                                                  area=float(row["area [m^2]"])))
        carrier = self.free_carrier if row["carrier"] == "free" else FrozenCarrier()
        return base.with_(body=scaled_body(base.body, row["mass [kg]"]), parachute=chute,
                          cable=replace(base.cable, length=float(row["cable length [m]"])),
                          carrier=carrier, airspeed=float(row["airspeed EAS [m/s]"]),
                          density_altitude=float(row["density altitude [m]"]),
                          name=str(row["run"]))

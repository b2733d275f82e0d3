"""The attitude of the towed helicopter: one per flight condition, from one moment balance.

A body hung by its rotor hub from a cable is in steady towed flight when the resultant of its
weight, its aerodynamic loads and the parachute's pull passes through the hub: the cable then
balances it with no moment about the hub, in pitch, roll and yaw. The attitude at which that
happens is found once, by the multibody trim (:func:`slingloads.analyses.multibody.trim`:
zero CG and angular accelerations of the compiled equations, the fuselage tables, fin and
parachute as the multibody model flies them), and :func:`towed_attitude` is the one function
the analyses call for it:

* the loads' towed-flight cases (hook id ``TOW``) take the trimmed attitude (earth vertical,
  angle of attack and sideslip) at the loads' airspeed, with and without parachute;
* the one-degree yaw sizing and the campaign's 1-DOF checks take the trimmed angle of attack
  at their airspeed and yaw about the suspension axis, the line from the hook through the hub
  (:attr:`TowedAttitude.axis`), with the yaw inertia and the weight's moment about that same
  line (:func:`yaw_model_about`);
* the multibody analysis reports the same trim at its airspeed.

When the study has no multibody system, :func:`towed_system` assembles one from the loads'
parts (mass items, hardpoints, fuselage table, fin, parachute at its attachment, pulling along
its relative wind), hung on a practically rigid cable long enough that the parachute cannot
reach it; the cable's length and stiffness do not change the body's attitude (the cable only
carries a force through the hub).

A trim whose angle of attack or sideslip lies outside the loads' aerodynamic envelope is
flagged by :meth:`TowedAttitude.outside`: it is reported as outside that envelope, not
silently treated as inside it. A trim that cannot be found (equations not met, tables left,
slack cable) is reported with the trim's reason (:attr:`TowedAttitude.message`) and yields no
attitude.

Conventions (``docs/conventions.md``): airframe axes x aft, y right, z up; pitch nose up and
roll right side down positive; the flight path is level, so at zero wind the angle of attack
equals the pitch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.multibody.trim import trim
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.airframe import hanging_yaw_inertia
from slingloads.models.attitude import Attitude
from slingloads.models.multibody.cable import Cable
from slingloads.models.multibody.local_flow import LiftingSurface
from slingloads.models.multibody.parachute_line import QuasiStaticParachute, line_reach
from slingloads.models.multibody.rigid_body import RigidBody, rotation_matrix
from slingloads.models.multibody.system import SlingSystem
from slingloads.models.yaw_dynamics import YAW_AXES

#: Axial stiffness of the cable of :func:`towed_system` (practically rigid). [N]
RIGID_EA = 1e11
#: Attitude source of a trimmed attitude (:class:`~slingloads.models.attitude.Attitude`).
TRIMMED = "trimmed: aerodynamic, parachute and weight moments balance about the hub"


@dataclass(frozen=True, eq=False)
class TowedAttitude:
    """The trimmed attitude of the towed helicopter at one airspeed (or why there is none).

    Attributes
    ----------
    airspeed : float
        Equivalent airspeed. [m/s]
    trim : Trim
        The multibody trim it comes from (:class:`slingloads.analyses.multibody.trim.Trim`).
    parachute : bool
        True when the parachute is flown.
    notes : tuple of str
        What the system it was solved on leaves out (e.g. a fin tabulated in wind axes).
    """

    airspeed: float
    trim: object
    parachute: bool
    notes: tuple = ()

    @property
    def converged(self):
        """True when a trim was found and it is isolated: an equilibrium that leaves an
        unknown free (no yawing moment at all: every heading) fixes no attitude to load."""
        return bool(self.trim.converged) and not self.trim.neutral

    @property
    def message(self):
        """"trimmed", or why there is no trim."""
        if self.trim.converged and self.trim.neutral:
            return (f"the equilibrium is not unique: nothing fixes the {self.trim.neutral} "
                    "(no restoring moment: neutral), so no attitude is trimmed")
        return str(self.trim.message)

    def _angles(self):
        if not self.converged:
            return (np.nan, np.nan, np.nan)
        return self.trim.attitude

    @property
    def yaw(self):
        """Nose-right yaw. [rad]"""
        return float(self._angles()[0])

    @property
    def pitch(self):
        """Nose-up pitch. [rad]"""
        return float(self._angles()[1])

    @property
    def roll(self):
        """Right-side-down roll. [rad]"""
        return float(self._angles()[2])

    @property
    def alpha(self):
        """Angle of attack of the fuselage at the trim. [rad]"""
        return float(self.trim.quantity("alpha")) if self.converged else np.nan

    @property
    def beta(self):
        """Sideslip of the fuselage at the trim. [rad]"""
        return float(self.trim.quantity("beta")) if self.converged else np.nan

    @property
    def _rotation(self):
        return rotation_matrix(self.trim.state[9:13])

    @property
    def vertical(self):
        """Earth's upward vertical in airframe axes at the trim, unit vector. [-]"""
        return self._rotation.T @ np.array([0.0, 0.0, 1.0])

    @property
    def axis(self):
        """The suspension axis at the trim: unit vector from the hub towards the hook, in
        airframe axes (at rest, the hub-CG line). [-]"""
        d = np.asarray(self.trim.info[_info("d_X"):_info("d_Z") + 1], float)  # hook to hub
        return self._rotation.T @ (-d / np.linalg.norm(d))

    def attitude(self):
        """The trimmed :class:`~slingloads.models.attitude.Attitude` (pitch and roll).

        Returns
        -------
        Attitude
            From the trimmed earth vertical, source :data:`TRIMMED`.

        Raises
        ------
        InputError
            If there is no trim (with the trim's reason).
        """
        if not self.converged:
            raise InputError(f"no towed trim at {self.airspeed:.4g} m/s EAS: {self.message}",
                             field="trim")
        return Attitude.from_vertical(self.vertical, TRIMMED)

    def outside(self, alpha_range, beta_range):
        """Why the trim lies outside an aerodynamic envelope, or "" when inside.

        Parameters
        ----------
        alpha_range, beta_range : (float, float)
            The envelope's angle-of-attack and sideslip range. [rad]

        Returns
        -------
        str
        """
        if not self.converged:
            return f"no trim: {self.message}"
        out = []
        for name, value, (lo, hi) in (("alpha", self.alpha, alpha_range),
                                      ("beta", self.beta, beta_range)):
            if value < lo - 1e-9 or value > hi + 1e-9:
                out.append(f"{name} {np.degrees(value):+.1f} deg outside "
                           f"[{np.degrees(lo):+.1f}, {np.degrees(hi):+.1f}] deg")
        return "; ".join(out)

    def to_frame(self):
        """The trimmed attitude as a one-row DataFrame (angles in degrees).

        Returns
        -------
        pandas.DataFrame
            Airspeed [m/s], parachute, converged, message, pitch, roll, yaw, alpha, beta [deg].
        """
        return pd.DataFrame([{
            "airspeed EAS [m/s]": self.airspeed, "parachute": self.parachute,
            "converged": self.converged, "message": self.message,
            "pitch [deg]": np.degrees(self.pitch), "roll [deg]": np.degrees(self.roll),
            "yaw [deg]": np.degrees(self.yaw), "alpha [deg]": np.degrees(self.alpha),
            "beta [deg]": np.degrees(self.beta)}])


def _info(name):
    from slingloads.models.multibody.equations import INFO

    return INFO.index(name)


def towed_attitude(system, airspeed=None, *, parachute=True, notes=()):
    """The trimmed attitude of the towed helicopter (module notes): the one function every
    analysis calls for it.

    Parameters
    ----------
    system : SlingSystem
        The towed system (the multibody model's, or :func:`towed_system`).
    airspeed : float, optional
        Equivalent airspeed, >= 0 (default the system's). [m/s]
    parachute : bool
        False trims the system without its parachute.
    notes : tuple of str
        What the system leaves out (:func:`towed_system`), kept with the result.

    Returns
    -------
    TowedAttitude
    """
    if not isinstance(system, SlingSystem):
        raise InputError("the towed attitude needs a SlingSystem", type(system).__name__)
    flown = system if parachute or system.parachute is None else system.with_(parachute=None)
    point = trim(flown, airspeed)
    return TowedAttitude(point.airspeed, point, flown.parachute is not None, tuple(notes))


def towed_system(airframe, fuselage, fin=None, parachute=None, airspeed=0.0,
                 density_altitude=0.0):
    """A towed system assembled from the loads' parts, for :func:`towed_attitude`.

    Parameters
    ----------
    airframe : Airframe
        Mass items (mass, CG, inertia) and hardpoints (hub, parachute attachment).
    fuselage : FuselageAero
    fin : Fin, optional
        Flown as a lifting surface (its CY table must be in body axes; a table in wind axes is
        left out, and the attitude's notes say so).
    parachute : Parachute, optional
        Pulls at its attachment along its relative wind (the quasi-static drogue); its table
        must be in wind axes.
    airspeed : float
        Equivalent airspeed, >= 0. [m/s]
    density_altitude : float
        [m]

    Returns
    -------
    system : SlingSystem
        Hung on a practically rigid cable (EA :data:`RIGID_EA`) beyond the parachute's reach.
    notes : tuple of str
        What it leaves out (for :func:`towed_attitude`'s ``notes``).
    """
    if fuselage is None:
        raise InputError("the towed trim needs the fuselage's aerodynamic table "
                         "(FuselageAero)", field="fuselage")
    notes = []
    surfaces = ()
    if fin is not None:
        if fin.axes == "body":
            surfaces = (LiftingSurface.from_fin(fin),)
        else:
            notes.append("the fin (tabulated in wind axes) is left out of the trim")
    hp = airframe.hardpoints
    chute = None
    if parachute is not None:
        if parachute.axes != "wind":
            notes.append(f"the parachute (tabulated in {parachute.axes} axes) is left out of "
                         "the trim")
        else:
            chute = QuasiStaticParachute(parachute)
    length = 10.0 * max(airframe.length, 1.0)
    if chute is not None:
        _, far = line_reach(hp.hub, hp.chute, chute.line_length)
        length = max(length, 2.0 * far)
    system = SlingSystem(RigidBody.from_mass_items(airframe.mass_items), hp,
                         Cable(length, RIGID_EA, 0.0), fuselage, surfaces, chute,
                         airspeed=float(airspeed), density_altitude=float(density_altitude),
                         name="towed trim")
    return system, tuple(notes)


def yaw_model_about(model, axis="suspension", towed=None, body=None, inertia=None):
    """The 1-DOF yaw model with its moments, inertia and weight about one axis through the hub.

    * ``"suspension"``: the line from the hook through the hub. At a converged towed trim it
      is :attr:`TowedAttitude.axis` (the cable's line), the model flies the trim's angle of
      attack, and the weight ``-m g`` times the trim's vertical adds its moment about that
      line (:class:`~slingloads.models.yaw_dynamics.YawModel`, ``weight``); without a trim it
      is the hub-CG line, the vertical of the body hanging at rest (no weight moment about
      it), at the model's own angle of attack.
    * ``"airframe z"``: airframe z through the hub, aerodynamic moments alone (the paper's
      balance of Mz, section 4.1), at the trim's angle of attack when there is one.

    Parameters
    ----------
    model : YawModel
        Fuselage, fin, hardpoints, parachute and condition (its axis, weight and, with
        ``body``, inertia are replaced).
    axis : {"suspension", "airframe z"}
    towed : TowedAttitude, optional
        The towed trim at the model's airspeed.
    body : RigidBody, optional
        Mass, CG and inertia about the CG; the yaw inertia is taken about the axis from it
        (:func:`~slingloads.models.airframe.hanging_yaw_inertia`) unless ``inertia`` is given.
        Without it, the suspension axis needs a trim and the weight is left out.
    inertia : float, optional
        A yaw inertia given by the user, taken as about the axis. [kg m^2]

    Returns
    -------
    model : YawModel
    text : str
        The axis in words, for the reports.
    """
    from dataclasses import replace

    if axis not in YAW_AXES:
        raise InputError(f"{axis=!r} is not a valid yaw axis. Valid options are: "
                         f"{', '.join(map(repr, YAW_AXES))}", axis, field="yaw axis")
    trimmed = towed is not None and towed.converged
    condition = model.condition
    if trimmed:
        condition = replace(condition, alpha=towed.alpha)
    hub = np.asarray(model.hardpoints.hub, float)
    weight = cg = None
    if axis == "airframe z":
        a = np.array([0.0, 0.0, 1.0])
        text = "airframe z through the hub (the paper's balance of Mz; weight left out)"
    elif trimmed:
        a = np.asarray(towed.axis, float)
        tilt = np.degrees(np.arccos(np.clip(a[2], -1.0, 1.0)))
        text = (f"suspension axis at the towed trim: the cable's line through the hub, "
                f"{tilt:.3g} deg from airframe z")
        if body is not None:
            weight, cg = -body.mass * G0 * np.asarray(towed.vertical, float), body.cg
            text += ", weight included"
    elif body is not None:
        d = hub - np.asarray(body.cg, float)
        a = d / np.linalg.norm(d)
        tilt = np.degrees(np.arccos(np.clip(a[2], -1.0, 1.0)))
        text = (f"suspension axis hanging at rest: the hub-CG line, {tilt:.3g} deg from "
                "airframe z (no towed trim)")
    else:
        a = np.array([0.0, 0.0, 1.0])
        text = "airframe z through the hub (no towed trim and no mass items for the hub-CG line)"
    if inertia is None:
        inertia = (model.yaw_inertia if body is None else
                   hanging_yaw_inertia(body.inertia, body.cg, hub, a, body.mass))
    return replace(model, condition=condition, axis=a, weight=weight, cg=cg,
                   yaw_inertia=float(inertia)), text

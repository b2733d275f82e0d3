"""The structural loads analysis (paper, section 6): every limit load case of the carried
helicopter, combined and balanced by inertia relief, into shear force and bending moment.

A :class:`LoadsStudy` gathers the airframe, its aerodynamics, the parachute, the flight
condition and the load-case options; :meth:`LoadsStudy.run` returns a :class:`LoadsResult`
whose methods give pandas DataFrames (long SFBM table, envelope with critical and correlated
loads, convex hulls, comparison with the previous design envelope).

The airframe hangs in an attitude (:mod:`slingloads.models.attitude`; by default the hanging
attitude, CG under the hub) that fixes the earth vertical in airframe axes. Each case
combines, in airframe axes:

* a CS-29.865 hook load ``nz x weight`` at the hub along the vertical or one of the cone's
  directions about it, or, in a towed-flight equilibrium case (``TOW``), along the trimmed
  cable: vertical component ``nz x weight``, horizontal component balancing the aerodynamic and
  parachute forces (no fore-and-aft or lateral acceleration); shared among the mast feet by the
  rigid-body weighted rule (:mod:`slingloads.models.load_sharing`);
* in a towed case the airframe flies at its **trimmed attitude** (aerodynamic point ``TRIM``):
  the pitch and roll at which weight, aerodynamic and parachute moments balance about the hub,
  at the loads' airspeed, with or without the parachute
  (:func:`slingloads.analyses.towed_attitude.towed_attitude`, the attitude the parachute
  sizing and the multibody model use); its earth vertical replaces the study's attitude in
  that case, and its angle of attack and sideslip are the case's. A trim outside the
  aerodynamic envelope's range is flagged (:meth:`LoadsResult.towed_findings`); a condition
  without trim has no towed case, and the finding says why;
* the fuselage aerodynamic load at one point of the (alpha, beta) envelope, shared along the
  loads reference axis by the same rule so that its resultant equals the tabulated one, and
  the fin's side force at its centre of pressure;
* optionally the parachute drag at its attachment, along the relative wind (or along +x);
* gravity at every mass item along the earth vertical, and the inertia relief that balances
  all of it.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np
import pandas as pd

from slingloads.analyses.envelopes import (
    compare_with_previous,
    component_index,
    convex_hull,
    envelope_table,
)
from slingloads.analyses.hook_loads import (
    LEGACY_HOOK_IDS,
    NO_HOOK,
    TOWED,
    HookLoadOptions,
    cable_geometry,
    describe_direction,
    hook_directions,
    horizontal_basis,
)
from slingloads.analyses.sfbm import COMPONENTS, free_free_internal_loads
from slingloads.checks import frozen
from slingloads.constants import G0
from slingloads.errors import ClosureError, InputError
from slingloads.ids import first_duplicate
from slingloads.models.aerodynamics import airflow_direction
from slingloads.models.airframe import Airframe
from slingloads.models.attitude import resolve_attitude
from slingloads.models.flight import FlightCondition
from slingloads.models.load_sharing import rigid_share

#: Relative tolerance of the free-free closure check (residual over the load scale).
CLOSURE_TOLERANCE = 1e-8

CHUTE_LINE_DIRECTIONS = ("relative wind", "fuselage axis")
#: Aerodynamic point id of a case without aerodynamic load.
NO_AERO = "NONE"
#: Aerodynamic point id of a towed case: the trimmed attitude's angle of attack and sideslip.
TRIM_AERO = "TRIM"


@dataclass(frozen=True)
class AeroEnvelope:
    """Points of the angle-of-attack / sideslip envelope at which aerodynamic loads are taken.

    Parameters
    ----------
    ids : sequence of str
    alpha, beta : array_like
        [rad]
    """

    ids: tuple
    alpha: np.ndarray
    beta: np.ndarray

    def __post_init__(self):
        ids = tuple(str(i) for i in self.ids)
        if len(set(ids)) != len(ids):
            dup = next(i for i in ids if ids.count(i) > 1)
            raise InputError("aerodynamic envelope point ids must be unique", dup)
        alpha = np.asarray(self.alpha, float).reshape(-1)
        beta = np.asarray(self.beta, float).reshape(-1)
        if not (len(ids) == alpha.size == beta.size) or not ids:
            raise InputError("the aerodynamic envelope needs at least one point, each with "
                             "an id, alpha and beta")
        object.__setattr__(self, "ids", ids)
        if not (np.all(np.isfinite(alpha)) and np.all(np.isfinite(beta))):
            raise InputError("aerodynamic envelope angles must be finite [rad]")
        object.__setattr__(self, "alpha", frozen(alpha))
        object.__setattr__(self, "beta", frozen(beta))

    @classmethod
    def corners_and_centre(cls, alpha_range, beta_range):
        """The four corners and the centre of a rectangular envelope. [rad]

        Parameters
        ----------
        alpha_range, beta_range : (float, float)
            (lowest, highest) angle of attack and sideslip. [rad]

        Returns
        -------
        AeroEnvelope
            Points ``CENTRE``, ``A+B+``, ``A+B-``, ``A-B+``, ``A-B-``.
        """
        (a0, a1), (b0, b1) = alpha_range, beta_range
        ids = ("CENTRE", "A+B+", "A+B-", "A-B+", "A-B-")
        return cls(ids, np.array([(a0 + a1) / 2, a1, a1, a0, a0]),
                   np.array([(b0 + b1) / 2, b1, b0, b1, b0]))


@dataclass(frozen=True)
class ListedCase:
    """A load case listed by the user rather than generated.

    Parameters
    ----------
    id : str
    hook : str
        Hook direction id (``VERTICAL``, ``AZ000``...), ``TOW`` (towed-flight equilibrium)
        or ``NONE``; the former ``AXIAL`` is read as ``VERTICAL``.
    aero : str
        Aerodynamic envelope point id or ``NONE``.
    chute : bool
        Parachute drag on.
    description : str
    """

    id: str
    hook: str
    aero: str
    chute: bool
    description: str = ""

    def __post_init__(self):
        hook = str(self.hook).strip().upper()
        object.__setattr__(self, "hook", LEGACY_HOOK_IDS.get(hook, hook))


#: Load cases per chunk of :meth:`LoadsStudy.run` (their applied loads, mass items included,
#: are built one chunk at a time, so that the memory beyond the result stays bounded).
RUN_CHUNK = 4096


@dataclass(frozen=True)
class DynamicsCases:
    """Load cases that come from the multibody dynamics (the campaign's hand-off, paper
    section 6): which aerodynamic points of the envelope the dynamics gave, and the parachute
    line directions and load they reached.

    Every generated hook direction (and towed case) is combined with each dynamics point
    under each line direction, besides the usual parachute on (the parachute model's drag
    and direction) and off. A line case loads the parachute attachment with ``line_force``
    along the line, ``e = (cos theta cos psi, sin psi, sin theta cos psi)`` in airframe axes
    (from the attachment towards the canopy; ``docs/multibody.md``).

    Parameters
    ----------
    aero_ids : sequence of str
        Ids of the envelope points that come from the dynamics.
    line_ids : sequence of str
    line_theta, line_psi : array_like
        Line angles, theta up and psi right of the aft direction. [rad]
    line_force : float
        Parachute line load, >= 0. [N]
    note : str
        Where the dynamics come from (shown in the case descriptions' source).
    """

    aero_ids: tuple = ()
    line_ids: tuple = ()
    line_theta: np.ndarray = field(default_factory=lambda: np.zeros(0))
    line_psi: np.ndarray = field(default_factory=lambda: np.zeros(0))
    line_force: float = 0.0
    note: str = ""

    def __post_init__(self):
        ids = tuple(str(i) for i in self.line_ids)
        theta = np.asarray(self.line_theta, float).reshape(-1)
        psi = np.asarray(self.line_psi, float).reshape(-1)
        if not (len(ids) == theta.size == psi.size):
            raise InputError("dynamics line directions need an id, theta and psi each")
        if len(set(ids)) != len(ids):
            raise InputError("dynamics line ids must be unique", ids)
        if not (np.all(np.isfinite(theta)) and np.all(np.isfinite(psi))):
            raise InputError("dynamics line angles must be finite [rad]")
        force = float(self.line_force)
        if not np.isfinite(force) or force < 0:
            raise InputError("dynamics parachute line load must be >= 0 [N]", force)
        object.__setattr__(self, "aero_ids", tuple(str(i) for i in self.aero_ids))
        object.__setattr__(self, "line_ids", ids)
        object.__setattr__(self, "line_theta", frozen(theta))
        object.__setattr__(self, "line_psi", frozen(psi))
        object.__setattr__(self, "line_force", force)

    def directions(self):
        """Unit line directions by id, airframe axes. [-]

        Returns
        -------
        dict of str to ndarray, shape (3,)
            Unit vectors by case name. [-]
        """
        t, p = self.line_theta, self.line_psi
        e = np.column_stack([np.cos(t) * np.cos(p), np.sin(p), np.sin(t) * np.cos(p)])
        return dict(zip(self.line_ids, e, strict=True))


@dataclass(frozen=True)
class LoadsStudy:
    """Everything the loads analysis needs (SI).

    Parameters
    ----------
    airframe : Airframe
    flight : FlightCondition
    hook : HookLoadOptions
    envelope : AeroEnvelope, optional
        Required when ``fuselage`` or ``fin`` is given.
    fuselage : FuselageAero, optional
    fin : Fin, optional
    parachute : Parachute, optional
    chute_line : str
        ``"relative wind"`` (default) or ``"fuselage axis"``.
    attitude : str or Attitude
        Attitude of the airframe, which fixes the earth vertical for gravity, the vertical
        hook case and the cone: ``"hanging"`` (default: CG under the hub), ``"mast vertical"``
        or an :class:`~slingloads.models.attitude.Attitude` (pitch and roll).
    generate : bool
        Generate the full combination matrix hook x aero point x parachute on/off.
    listed : tuple of ListedCase
        Cases listed by the user (added to the generated ones).
    previous_envelope : pandas.DataFrame, optional
        Columns ``x [m]``, ``component``, ``min``, ``max`` (SI).
    ultimate_factor : float
        Factor of safety (CS 29.303: 1.5), ultimate = factor x limit loads. [-]
    name : str
    dynamics : DynamicsCases, optional
        Cases that come from the multibody dynamics (the campaign's hand-off).
    towed_system : SlingSystem, optional
        The towed system whose trim gives the towed cases' attitude (the multibody model's);
        None assembles one from the airframe, fuselage, fin and parachute
        (:func:`slingloads.analyses.towed_attitude.towed_system`).
    towed_source : str
        Where ``towed_system`` comes from, in words (shown on the reports).
    """

    airframe: Airframe
    flight: FlightCondition = field(default_factory=FlightCondition)
    hook: HookLoadOptions = field(default_factory=HookLoadOptions)
    envelope: AeroEnvelope | None = None
    fuselage: object | None = None
    fin: object | None = None
    parachute: object | None = None
    chute_line: str = "relative wind"
    attitude: object = "hanging"
    generate: bool = True
    listed: tuple = ()
    previous_envelope: pd.DataFrame | None = None
    ultimate_factor: float = 1.5
    name: str = "study"
    dynamics: DynamicsCases | None = None
    towed_system: object | None = None
    towed_source: str = ""

    def __post_init__(self):
        if self.dynamics is not None:
            self._check_dynamics()
        if self.chute_line not in CHUTE_LINE_DIRECTIONS:
            raise InputError(f"parachute line direction must be one of "
                             f"{list(CHUTE_LINE_DIRECTIONS)}", self.chute_line)
        if (self.fuselage is not None or self.fin is not None) and self.envelope is None:
            raise InputError("aerodynamic data are given but no angle-of-attack / sideslip "
                             "envelope points")
        if self.parachute is not None and self.airframe.hardpoints.chute is None:
            raise InputError("a parachute is given but the airframe has no parachute "
                             "attachment hardpoint")
        uf = float(self.ultimate_factor)
        if not np.isfinite(uf) or uf < 1:
            raise InputError("ultimate factor must be >= 1", uf)
        if not self.generate and not self.listed:
            raise InputError("no load case: generation is off and none is listed")
        horizontal_basis(self.attitude_used.vertical)  # validates the attitude
        if self.envelope is not None:
            if self.fuselage is not None:
                self.fuselage.airframe_coefficients(self.envelope.alpha, self.envelope.beta)
            if self.fin is not None:
                self.fin.force(self.envelope.beta, 0.0)
            if self.parachute is not None:
                self.parachute.coefficient(self._chute_alpha(self.envelope.alpha,
                                                             self.envelope.beta))
        if self.previous_envelope is not None:
            _check_previous(self.previous_envelope)

    def _check_dynamics(self):
        d = self.dynamics
        if not isinstance(d, DynamicsCases):
            raise InputError("the dynamics cases must be DynamicsCases", type(d).__name__)
        known = set(self.envelope.ids) if self.envelope is not None else set()
        missing = [i for i in d.aero_ids if i not in known]
        if missing:
            raise InputError("a dynamics aerodynamic point is not in the envelope", missing[0])
        if d.line_ids and self.parachute is None:
            raise InputError("dynamics parachute line cases need the parachute")

    def with_hook(self, *, nz=None, angle_deg=None, lateral_angle_deg=None, n_azimuth=None,
                  include_vertical=None, cone=None, towed=None):
        """A copy of the study with hook-load options changed, angles in degrees as in the
        workbook; what is not given stays as it is (:class:`HookLoadOptions`).

        Parameters
        ----------
        nz : float, optional
            Hook load factor. [-]
        angle_deg : float, optional
            Inclination of the cone from the vertical, in [0, 90). [deg]
        lateral_angle_deg : float, optional
            Inclination of the lateral directions, in [0, 90). [deg]
        n_azimuth : int, optional
            Azimuths of the hook's load directions. [count]
        include_vertical, towed : bool, optional
        cone : {"lateral directions", "elliptical"}, optional

        Returns
        -------
        LoadsStudy

        Examples
        --------
        ``study.with_hook(nz=2.0, lateral_angle_deg=20)``
        """
        changes = {"nz": nz, "n_azimuth": n_azimuth, "include_vertical": include_vertical,
                   "cone": cone, "towed": towed}
        changes = {k: v for k, v in changes.items() if v is not None}
        for name, value in (("angle", angle_deg), ("lateral_angle", lateral_angle_deg)):
            if value is not None:
                degrees = float(value)
                if not (np.isfinite(degrees) and 0 <= degrees < 90):
                    raise InputError(f"hook {name.replace('_', ' ')} must lie in [0, 90) deg",
                                     degrees, unit="deg")
                changes[name] = np.radians(degrees)
        return replace(self, hook=replace(self.hook, **changes))

    def with_mass_item(self, item_id, *, mass=None, position=None, inertia=None,
                       description=None):
        """A copy of the study with one mass item changed: ``mass`` [kg], ``position``
        (x, y, z) [m], ``inertia`` (3 x 3 about its own CG) [kg m^2], ``description``
        (:meth:`MassItems.with_item <slingloads.models.airframe.MassItems.with_item>`).

        Parameters
        ----------
        item_id : str
            Id of an existing mass item.
        mass : float, optional
            New mass. [kg]
        position : array_like, shape (3,), optional
            New CG (x, y, z). [m]
        inertia : array_like, shape (3, 3), optional
            New own inertia about its CG. [kg m^2]
        description : str, optional
            New description.

        Returns
        -------
        LoadsStudy
        """
        return replace(self, airframe=self.airframe.with_mass_item(
            item_id, mass=mass, position=position, inertia=inertia, description=description))

    def with_station(self, station, x=None, *, station_id=None):
        """A copy of the study with one cut station (id or index) moved to ``x`` [m] or
        renamed (:meth:`Airframe.with_station
        <slingloads.models.airframe.Airframe.with_station>`).

        Parameters
        ----------
        station : str or int
            Id or index of the station. [-]
        x : float, optional
            Its new x. [m]
        station_id : str, optional
            Its new id.

        Returns
        -------
        LoadsStudy
        """
        return replace(self, airframe=self.airframe.with_station(station, x,
                                                                 station_id=station_id))

    def with_hardpoints(self, *, hub=None, mast_feet=None, mast_weights=None, mast_axis=None,
                        chute=None, mast_feet_ids=None):
        """A copy of the study with hardpoints changed: ``hub``, ``mast_feet``, ``chute``
        [m], ``mast_weights``, ``mast_axis`` [-] (:meth:`Airframe.with_hardpoints
        <slingloads.models.airframe.Airframe.with_hardpoints>`).

        Parameters
        ----------
        hub : array_like, shape (3,), optional
            Rotor hub centre. [m]
        mast_feet : array_like, shape (k, 3), optional
            Mast attachment points. [m]
        mast_weights : array_like, shape (k,), optional
            Weights of the rigid-body share of the hub load among the feet. [-]
        mast_axis : array_like, shape (3,), optional
            Direction of the mast, from the deck towards the hub. [-]
        chute : array_like, shape (3,), optional
            Parachute attachment point. [m]
        mast_feet_ids : sequence of str, optional
            Ids of the mast feet.

        Returns
        -------
        LoadsStudy
        """
        return replace(self, airframe=self.airframe.with_hardpoints(
            hub=hub, mast_feet=mast_feet, mast_weights=mast_weights, mast_axis=mast_axis,
            chute=chute, mast_feet_ids=mast_feet_ids))

    @property
    def attitude_used(self):
        """The airframe's :class:`~slingloads.models.attitude.Attitude` in these cases."""
        return resolve_attitude(self.attitude, self.airframe)

    @property
    def vertical(self):
        """Earth's upward vertical in airframe axes, unit vector. [-]"""
        return self.attitude_used.vertical

    @cached_property
    def towed_trims(self):
        """The trimmed attitude of each parachute state of the towed cases, {flown: TowedAttitude}
        (:func:`~slingloads.analyses.towed_attitude.towed_attitude` at the loads' airspeed;
        empty without towed cases or without fuselage table)."""
        from slingloads.analyses.towed_attitude import towed_attitude, towed_system

        wanted = self.hook.towed and self.generate or any(c.hook == TOWED for c in self.listed)
        if not wanted or self.fuselage is None:
            return {}
        system, notes = self.towed_system, ()
        if system is None:
            system, notes = towed_system(self.airframe, self.fuselage, self.fin, self.parachute,
                                         self.flight.eas, self.flight.density_altitude)
        states = [True, False] if self.parachute is not None else [False]
        return {c: towed_attitude(system, self.flight.eas, parachute=c, notes=notes)
                for c in states}

    def case_verticals(self, cases):
        """Earth's upward vertical in airframe axes per case: the study's attitude, or the
        trimmed attitude of a towed case's parachute state.

        Parameters
        ----------
        cases : pandas.DataFrame
            The load cases, with their ``hook`` and ``chute`` columns (:attr:`cases`).

        Returns
        -------
        ndarray, shape (c, 3)
            Unit vectors. [-]
        """
        out = np.tile(self.vertical, (len(cases), 1))
        towed = (cases["hook"] == TOWED).to_numpy()
        chute = cases["chute"].to_numpy(bool)
        for state, trimmed in self.towed_trims.items():
            if trimmed.converged:
                out[towed & (chute == state)] = trimmed.vertical
        return out

    def _chute_alpha(self, alpha, beta):
        if self.chute_line == "relative wind":
            return np.zeros_like(np.asarray(alpha, float))
        return np.arccos(np.clip(np.cos(alpha) * np.cos(beta), -1.0, 1.0))

    def hook_table(self):
        """The hook-load directions about the attitude's vertical (see
        :func:`~slingloads.analyses.hook_loads.hook_directions`).

        Returns
        -------
        pandas.DataFrame
            :func:`~slingloads.analyses.hook_loads.hook_directions`: one row per direction, its
            azimuth and inclination [deg] and unit vector [-].
        """
        return hook_directions(self.hook, self.vertical)

    def case_matrix(self):
        """The load-case combination matrix as a DataFrame, one row per case.

        Generated cases come first (``LC0001``...): every hook direction x aerodynamic point x
        parachute on/off, then the towed-flight equilibrium cases (hook ``TOW``) per
        aerodynamic point with and without parachute (none without aerodynamic point and
        parachute: that is the vertical case), then the listed cases.

        Returns
        -------
        pandas.DataFrame
            One row per case: id, hook direction, aerodynamic point, parachute, source, angles
            [deg] (units in the column labels).
        """
        hooks = self.hook_table()
        aero_ids = list(self.envelope.ids) if self.envelope is not None else [NO_AERO]
        chute_states = [True, False] if self.parachute is not None else [False]
        dyn = self.dynamics
        lines = list(dyn.line_ids) if dyn is not None and self.parachute is not None else []
        dyn_aero = set(dyn.aero_ids) if dyn is not None else set()

        def states(a):
            return [(c, "") for c in chute_states] + (
                [(True, line) for line in lines] if a in dyn_aero else [])

        rows = []
        if self.generate:
            for h in hooks["hook"]:
                for a in aero_ids:
                    for c, line in states(a):
                        rows.append(("", h, a, c, line, ""))
            if self.hook.towed:
                rows += [("", TOWED, TRIM_AERO, c, "", "")
                         for c, trimmed in self.towed_trims.items() if trimmed.converged]
        rows += [(c.id, c.hook, c.aero, bool(c.chute), "", c.description)
                 for c in self.listed]
        frame = pd.DataFrame(rows, columns=["case", "hook", "aero", "chute", "chute line",
                                            "description"])
        n_gen = len(frame) - len(self.listed)
        frame.loc[: n_gen - 1, "case"] = [f"LC{i + 1:04d}" for i in range(n_gen)]
        self._check_listed(frame, hooks, aero_ids)
        hook_rows = hooks.set_index("hook").reindex(frame["hook"])
        frame["azimuth [deg]"] = hook_rows["azimuth [deg]"].to_numpy()
        frame["inclination [deg]"] = hook_rows["inclination [deg]"].to_numpy()
        if self.envelope is not None:
            env = pd.DataFrame({"alpha [deg]": np.degrees(self.envelope.alpha),
                                "beta [deg]": np.degrees(self.envelope.beta)},
                               index=list(self.envelope.ids)).reindex(frame["aero"])
            frame["alpha [deg]"] = env["alpha [deg]"].to_numpy()
            frame["beta [deg]"] = env["beta [deg]"].to_numpy()
        else:
            frame["alpha [deg]"] = np.nan
            frame["beta [deg]"] = np.nan
        for state, trimmed in self.towed_trims.items():
            at = ((frame["aero"] == TRIM_AERO) & (frame["chute"] == state)).to_numpy()
            frame.loc[at, "alpha [deg]"] = np.degrees(trimmed.alpha)
            frame.loc[at, "beta [deg]"] = np.degrees(trimmed.beta)
        generated = frame["description"] == ""
        frame.loc[generated, "description"] = [
            _describe(r) for _, r in frame[generated].iterrows()]
        frame["source"] = np.where(frame["aero"].isin(dyn_aero) | (frame["chute line"] != ""),
                                   "dynamics", "hand")
        return frame

    def _check_listed(self, frame, hooks, aero_ids):
        twice = first_duplicate(list(frame["case"]))
        if twice is not None:
            raise InputError("load case ids must be unique (compared with case ignored)",
                             frame["case"].iloc[twice[1]])
        valid_hooks = set(hooks["hook"]) | {TOWED, NO_HOOK}
        valid_aero = set(aero_ids) | {NO_AERO}
        for c in self.listed:
            if (c.hook == TOWED) != (c.aero == TRIM_AERO):
                raise InputError(f"load case {c.id!r}: a towed case (hook {TOWED}) flies at "
                                 f"the trimmed attitude, aerodynamic point {TRIM_AERO}, and "
                                 f"only a towed case does", c.aero)
            if c.hook == TOWED:
                trimmed = self.towed_trims.get(bool(c.chute))
                if trimmed is None or not trimmed.converged:
                    why = "no fuselage table" if trimmed is None else trimmed.message
                    raise InputError(f"load case {c.id!r}: no towed trim for it ({why})",
                                     c.id)
                continue
            if c.hook not in valid_hooks:
                raise InputError(f"load case {c.id!r}: unknown hook direction; valid ids are "
                                 f"{sorted(valid_hooks)}", c.hook)
            if c.aero not in valid_aero:
                raise InputError(f"load case {c.id!r}: unknown aerodynamic point; valid ids "
                                 f"are {sorted(valid_aero)}", c.aero)
            if c.chute and self.parachute is None:
                raise InputError(f"load case {c.id!r} asks for the parachute but none is "
                                 "defined", c.chute)

    def run(self, check_closure=True):
        """Compute every case. Returns a :class:`LoadsResult`.

        Parameters
        ----------
        check_closure : bool
            Refuse a case whose free-free residual is over the tolerance.

        Returns
        -------
        LoadsResult

        Raises
        ------
        ClosureError
            If a case's free-free residual exceeds :data:`CLOSURE_TOLERANCE` times the load
            scale (and ``check_closure``).
        """
        cases = self.case_matrix()
        items = self.airframe.mass_items
        n = len(items.mass)
        feet = len(self.airframe.hardpoints.mast_feet)
        stations = self.airframe.station_points()
        count = len(cases)
        loads = np.empty((count, len(stations), 6))
        residual, linear, angular, hub = (np.empty((count, 3 * k)) for k in (2, 1, 1, 1))
        scale = 0.0
        verticals = self.case_verticals(cases)
        vertical_factor = np.empty(count)
        # the applied loads (mass items included) one chunk of cases of one attitude at a time
        for k in np.unique(verticals, axis=0):
            rows = np.flatnonzero(np.all(verticals == k, axis=1))
            for first in range(0, rows.size, RUN_CHUNK):
                part = rows[first:first + RUN_CHUNK]
                positions, forces, moments = self.applied_loads(cases.iloc[part])
                block = np.empty((part.size,) + loads.shape[1:])
                _, accel, residual[part] = free_free_internal_loads(
                    items, positions[n:], forces[:, n:], moments[:, n:], stations, k,
                    out=block)
                loads[part] = block
                linear[part], angular[part] = accel.linear, accel.angular
                vertical_factor[part] = accel.vertical_load_factor
                hub[part] = forces[:, n:n + feet].sum(axis=1)
                scale = max(scale, self._load_scale(forces))
        cases = self._with_cable(cases, hub, verticals)
        bad = np.abs(residual).max(axis=1) > CLOSURE_TOLERANCE * scale
        if check_closure and np.any(bad):
            i = int(np.argmax(bad))
            hint = ""
            if np.linalg.matrix_rank(items.inertia_about_cg) < 3:
                hint = ("; the mass items have no inertia about some axis (all on one line?), "
                        "so a moment about that axis cannot be balanced by inertia relief")
            raise ClosureError(f"case {cases['case'].iloc[i]}: free-free residual "
                               f"{np.abs(residual[i]).max():.3g} exceeds the tolerance "
                               f"{CLOSURE_TOLERANCE * scale:.3g}{hint}")
        load_factor = (linear + G0 * verticals) / G0  # (a - g) / g0 with g = -g0 k per case
        return LoadsResult(self, cases, loads, linear, angular, load_factor, residual, scale,
                           vertical_factor)

    def _with_cable(self, cases, hub_force, verticals):
        """The case matrix with the cable's direction per case (from the case's own vertical)
        and whether it lies inside the hook cone (the cone's inclination at the cable's
        azimuth; towed cases are judged at the larger of their angle at Nz and at 1 g)."""
        out = cases.copy()
        angle, azimuth = np.empty(len(cases)), np.empty(len(cases))
        for k in np.unique(verticals, axis=0):
            rows = np.all(verticals == k, axis=1)
            angle[rows], azimuth[rows] = cable_geometry(hub_force[rows], k)
        on = (cases["hook"] != NO_HOOK).to_numpy()
        towed = (cases["hook"] == TOWED).to_numpy()
        weight = self.airframe.mass_items.weight
        vertical = np.einsum("ij,ij->i", hub_force, verticals)
        horizontal = np.sqrt(np.maximum((hub_force**2).sum(axis=1) - vertical**2, 0.0))
        at_1g = np.where(towed, np.arctan2(horizontal, weight), np.nan)
        judged = np.where(towed, np.maximum(angle, np.nan_to_num(at_1g)), angle)
        allowed = self.hook.inclination(azimuth)
        inside = judged <= allowed + 1e-9
        out["cable angle from vertical [deg]"] = np.where(on, np.degrees(angle), np.nan)
        out["cable azimuth [deg]"] = np.where(on, np.degrees(azimuth), np.nan)
        out["cable angle at 1 g [deg]"] = np.degrees(at_1g)
        out["cone angle at that azimuth [deg]"] = np.where(on, np.degrees(allowed), np.nan)
        out["inside hook cone"] = np.where(on, np.where(inside, "yes", "OUTSIDE"), "")
        return out

    def _load_scale(self, forces):
        """Scale for the closure check: largest force times max(1 m, airframe length)."""
        return max(np.abs(forces).max(), 1.0) * max(self.airframe.length, 1.0)

    def applied_loads(self, cases):
        """Applied loads (gravity, hook, aerodynamics, parachute) at every load point.

        Parameters
        ----------
        cases : pandas.DataFrame
            Cases of :meth:`case_matrix`.

        Returns
        -------
        positions : ndarray, shape (p, 3)
            Mass items first, then mast feet, aerodynamic points, fin, parachute. [m]
        forces, moments : ndarray, shape (c, p, 3)
            [N], [N m]
        """
        af = self.airframe
        items, hp = af.mass_items, af.hardpoints
        y0, z0 = af.reference_axis
        aero_pts = np.column_stack([af.aero_points, np.full(af.aero_points.size, y0),
                                    np.full(af.aero_points.size, z0)])
        blocks = [items.position, hp.mast_feet, aero_pts]
        if self.fin is not None:
            blocks.append(self.fin.centre_of_pressure[None, :])
        if self.parachute is not None:
            blocks.append(hp.chute[None, :])
        positions = np.concatenate(blocks)
        c = len(cases)
        forces = np.zeros((c, len(positions), 3))
        moments = np.zeros_like(forces)
        verticals = self.case_verticals(cases)
        forces[:, : len(items.mass), :] = (-G0 * items.mass[None, :, None]
                                           * verticals[:, None, :])
        start = len(items.mass)
        k = len(hp.mast_feet)
        feet = slice(start, start + k)
        start += k
        q = self.flight.dynamic_pressure
        alpha = np.radians(cases["alpha [deg]"].to_numpy(float))
        beta = np.radians(cases["beta [deg]"].to_numpy(float))
        aero_on = (cases["aero"] != NO_AERO).to_numpy()
        alpha_q, beta_q = np.where(aero_on, alpha, 0.0), np.where(aero_on, beta, 0.0)
        a = aero_pts.shape[0]
        if self.fuselage is not None and np.any(aero_on):
            f, m = self.fuselage.loads(alpha_q, beta_q, q)
            f, m = f * aero_on[:, None], m * aero_on[:, None]
            forces[:, start:start + a], moments[:, start:start + a] = rigid_share(
                aero_pts, af.aero_weights, f, m, self.fuselage.moment_reference)
        start += a
        if self.fin is not None:
            forces[:, start] = self.fin.force(beta_q, q) * aero_on[:, None]
            start += 1
        if self.parachute is not None:
            on = cases["chute"].to_numpy(bool)
            # the wind direction exists even when no aero point is set: alpha = beta = 0
            drag = self.parachute.drag(q, self._chute_alpha(alpha_q, beta_q), opening=True)
            wind = airflow_direction(alpha_q, beta_q)
            line = (wind if self.chute_line == "relative wind"
                    else np.tile([1.0, 0.0, 0.0], (c, 1)))
            direction = self.parachute.force_direction(wind, line)
            forces[:, start] = (drag * on)[:, None] * direction
            if self.dynamics is not None and self.dynamics.line_ids and "chute line" in cases:
                ids = cases["chute line"].to_numpy()
                line_on = ids != ""
                d = self.dynamics
                index = pd.Index(d.line_ids).get_indexer(ids[line_on])
                along = np.array(list(d.directions().values()))
                forces[line_on, start] = d.line_force * along[index]
        external = forces[:, feet.stop:].sum(axis=1)  # aerodynamics and parachute
        forces[:, feet], moments[:, feet] = self._hook_loads(cases, external)
        return positions, forces, moments

    def hook_forces(self, cases, external):
        """Hook force on the airframe at the hub per case, airframe axes, shape (c, 3).

        Parameters
        ----------
        cases : pandas.DataFrame
            Case matrix (column ``hook``).
        external : ndarray, shape (c, 3)
            Resultant of the aerodynamic and parachute forces per case. [N]

        Returns
        -------
        ndarray, shape (c, 3)
            ``nz W u`` along a cone direction u; for ``TOW``, ``nz W k - P_h external`` with k
            the vertical and P_h the projection on the horizontal plane; 0 for ``NONE``. [N]
        """
        hooks = self.hook_table().set_index("hook")
        hook = cases["hook"].to_numpy()
        weight = self.hook.nz * self.airframe.mass_items.weight
        listed = (hook != NO_HOOK) & (hook != TOWED)
        force = np.zeros((len(cases), 3))
        force[listed] = weight * hooks.loc[hook[listed], ["ux", "uy", "uz"]].to_numpy()
        towed = hook == TOWED
        k = self.case_verticals(cases)[towed]
        horizontal = external[towed] - np.einsum("ij,ij->i", external[towed], k)[:, None] * k
        force[towed] = weight * k - horizontal
        return force

    def _hook_loads(self, cases, external):
        hp = self.airframe.hardpoints
        force = self.hook_forces(cases, external)
        return rigid_share(hp.mast_feet, hp.mast_weights, force, np.zeros_like(force), hp.hub)


def _check_previous(frame):
    needed = {"x [m]", "component", "min", "max"}
    if not needed <= set(frame.columns):
        raise InputError(f"previous envelope needs columns {sorted(needed)}",
                         sorted(frame.columns))
    unknown = set(frame["component"]) - set(COMPONENTS)
    if unknown:
        raise InputError(f"previous envelope: unknown component; valid are {list(COMPONENTS)}",
                         sorted(unknown)[0])
    for name, group in frame.groupby("component"):
        x = group["x [m]"].to_numpy(float)
        if np.any(np.diff(x) <= 0):
            raise InputError(f"previous envelope {name}: stations must be sorted by "
                             "increasing x without repeats", x.tolist())
        if np.any(group["min"].to_numpy(float) > group["max"].to_numpy(float)):
            raise InputError(f"previous envelope {name}: min must not exceed max")


def _angle(value):
    """An angle of a case description [deg] at the reports' 0.1 deg, signed, a round-off
    zero as 0.0 (``1.48e-16`` -> ``'+0.0'``, ``-22.23`` -> ``'-22.2'``)."""
    return f"{round(float(value), 1) + 0.0:+.1f}"


def _describe(row):
    """Readable text of one row of the case matrix (a pandas Series)."""
    if row["hook"] == NO_HOOK:
        hook = "off"
    elif row["hook"] == TOWED:
        hook = ("along the trimmed cable (towed-flight equilibrium at the trimmed attitude: "
                "Nz x weight vertical, horizontal balancing aerodynamics and parachute)")
    else:
        hook = describe_direction(row["azimuth [deg]"], row["inclination [deg]"])
    parts = [f"hook {hook}"]
    if row["aero"] != NO_AERO:
        parts.append(f"aero point {row['aero']} (alpha {_angle(row['alpha [deg]'])} deg, "
                     f"beta {_angle(row['beta [deg]'])} deg)")
    if row.get("chute line", ""):
        parts.append(f"parachute line load from the dynamics along {row['chute line']}")
    else:
        parts.append("parachute on" if row["chute"] else "parachute off")
    return "; ".join(parts)


@dataclass(frozen=True)
class LoadsResult:
    """Limit internal loads of every case, with what produced them.

    Attributes
    ----------
    study : LoadsStudy
    cases : pandas.DataFrame
        Case matrix (see :meth:`LoadsStudy.case_matrix`).
    loads : ndarray, shape (c, s, 6)
        Limit internal loads Vx, Vy, Vz [N], Mx, My, Mz [N m].
    linear_acceleration, angular_acceleration : ndarray, shape (c, 3)
        Inertia-relief accelerations. [m/s^2], [rad/s^2]
    load_factor : ndarray, shape (c, 3)
        Load factor at the CG. [-]
    residual : ndarray, shape (c, 6)
        Free-free closure residual: the internal loads at a cut aft of every load and mass
        item (force [N], moment [N m]).
    residual_scale : float
        Load scale the residual is judged against. [N m]
    vertical_load_factor : ndarray, shape (c,)
        Load factor along the earth's upward vertical. [-]
    """

    study: LoadsStudy
    cases: pd.DataFrame
    loads: np.ndarray
    linear_acceleration: np.ndarray
    angular_acceleration: np.ndarray
    load_factor: np.ndarray
    residual: np.ndarray
    residual_scale: float
    vertical_load_factor: np.ndarray | None = None

    @property
    def case_ids(self):
        """Ids of the load cases, in the order of the result's first axis (list of str)."""
        return self.cases["case"].tolist()

    @property
    def stations(self):
        """Positions x of the cut stations, in the order of the result's second axis. [m]"""
        return self.study.airframe.stations

    @property
    def station_ids(self):
        """Ids of the cut stations, in the order of :attr:`stations`."""
        return self.study.airframe.station_ids

    @property
    def ultimate(self):
        """Ultimate internal loads = ultimate factor x limit, shape (c, s, 6)."""
        return self.study.ultimate_factor * self.loads

    @property
    def attitude(self):
        """The airframe's :class:`~slingloads.models.attitude.Attitude` in these cases."""
        return self.study.attitude_used

    def case_table(self):
        """Case matrix with the cable's direction and the inside-cone flag, load factors
        (airframe axes and along the vertical), angular accelerations and closure residual.

        Returns
        -------
        pandas.DataFrame
            One row per case: the case matrix, load factors [-], angular accelerations [rad/s^2]
            and the closure residual (units in the column labels).
        """
        out = self.cases.copy()
        if self.vertical_load_factor is not None:
            out["n vertical [-]"] = self.vertical_load_factor
        for j, axis in enumerate("xyz"):
            out[f"n{axis} [-]"] = self.load_factor[:, j]
        for j, axis in enumerate("xyz"):
            out[f"alpha_dot_{axis} [rad/s^2]"] = self.angular_acceleration[:, j]
        out["closure force residual [N]"] = np.abs(self.residual[:, :3]).max(axis=1)
        out["closure moment residual [N m]"] = np.abs(self.residual[:, 3:]).max(axis=1)
        return out

    def towed_table(self):
        """The towed-flight equilibrium cases: aerodynamic point, parachute, the trimmed
        attitude (pitch, roll; alpha, beta) and whether it lies inside the aerodynamic
        envelope, the trimmed cable's angle from the vertical (at Nz and at 1 g) and
        azimuth, the cone's inclination there and whether the cable lies inside the hook
        cone.

        Returns
        -------
        pandas.DataFrame
            One row per towed case, angles [deg].
        """
        columns = ["case", "aero", "alpha [deg]", "beta [deg]", "chute",
                   "cable angle from vertical [deg]", "cable angle at 1 g [deg]",
                   "cable azimuth [deg]", "cone angle at that azimuth [deg]",
                   "inside hook cone"]
        out = self.cases.loc[self.cases["hook"] == TOWED, columns].reset_index(drop=True)
        trims = self.study.towed_trims
        pitch, roll, inside = [], [], []
        for chute in out["chute"]:
            trimmed = trims[bool(chute)]
            pitch.append(np.degrees(trimmed.pitch))
            roll.append(np.degrees(trimmed.roll))
            inside.append("OUTSIDE" if self._outside(trimmed) else "yes")
        out.insert(2, "trim pitch [deg]", pitch)
        out.insert(3, "trim roll [deg]", roll)
        out.insert(6, "inside aero envelope", inside)
        return out

    def _outside(self, trimmed):
        env = self.study.envelope
        if env is None:
            return ""
        return trimmed.outside((env.alpha.min(), env.alpha.max()),
                               (env.beta.min(), env.beta.max()))

    def towed_findings(self):
        """What the towed trims show, one line per parachute state that is not simply inside
        the aerodynamic envelope: a trim outside the envelope's alpha / beta range (its
        aerodynamic loads come from the tables beyond the points the envelope covers), or
        no trim at all (no towed case, and why).

        Returns
        -------
        list of str
        """
        out = []
        kt = self.study.flight.eas / (1852.0 / 3600.0)
        for chute, trimmed in self.study.towed_trims.items():
            with_ = "with parachute" if chute else "without parachute"
            out += [f"towed trim {with_}: {note}" for note in trimmed.notes]
            if not trimmed.converged:
                out.append(f"towed flight {with_} at {kt:.4g} KEAS: no trim ({trimmed.message})"
                           f"; no towed case {with_}")
                continue
            why = self._outside(trimmed)
            if why:
                out.append(f"towed trim {with_} at {kt:.4g} KEAS (pitch "
                           f"{np.degrees(trimmed.pitch):+.1f} deg) lies OUTSIDE the "
                           f"aerodynamic envelope: {why}; its towed case is computed from the "
                           "aerodynamic tables there, not from an envelope point")
        return out

    def to_frame(self, ultimate=False):
        """Long SFBM table: ``case, station, x_m, Vx_N, Vy_N, Vz_N, Mx_Nm, My_Nm, Mz_Nm``.

        Parameters
        ----------
        ultimate : bool
            The ultimate loads (the ultimate factor x the limit loads) instead of the limit loads.

        Returns
        -------
        pandas.DataFrame
            One row per case and station: x [m], shear forces [N] and moments [N m].
        """
        loads = self.ultimate if ultimate else self.loads
        c, s, _ = loads.shape
        flat = loads.reshape(c * s, 6)
        frame = pd.DataFrame({
            "case": np.repeat(np.asarray(self.case_ids, dtype=object), s),
            "station": np.tile(np.asarray(self.station_ids, dtype=object), c),
            "x_m": np.tile(self.stations, c),
        })
        for j, name in enumerate(("Vx_N", "Vy_N", "Vz_N", "Mx_Nm", "My_Nm", "Mz_Nm")):
            frame[name] = flat[:, j]
        return frame

    def envelope(self, station=None, component=None, bound=None, ultimate=False):
        """Envelope with the critical case and the correlated loads.

        Parameters
        ----------
        station : str or int or sequence of them, optional
            Station id(s) or index(es) to keep (default: every station). [-]
        component : str or sequence of str, optional
            Component(s) to keep, ``"Vx"`` ... ``"Mz"`` (default: all six).
        bound : {"max", "min"}, optional
            Keep only the maxima or the minima (default: both).
        ultimate : bool
            Ultimate (factor x limit) instead of limit loads.

        Returns
        -------
        pandas.DataFrame
            ``station, x_m, component, bound, case, value_N, value_Nm, Vx_N ... Mz_Nm``: the
            bound of the component in ``value_N`` (shears) or ``value_Nm`` (moments), the
            critical ``case`` and the six loads of that case at that station, SI (the columns
            of :meth:`to_frame` and of the envelope CSV file; :func:`envelope_table`).

        Raises
        ------
        InputError
            For an unknown station, component or bound (the valid ones are listed).
        """
        loads = self.ultimate if ultimate else self.loads
        frame = envelope_table(loads, self.case_ids, self.stations, self.station_ids)
        keep = np.ones(len(frame), bool)
        if station is not None:
            many = [station] if isinstance(station, (str, int, np.integer)) else station
            ids = [self.station_ids[self.station_index(s)] for s in many]
            keep &= frame["station"].isin(ids).to_numpy()
        if component is not None:
            many = [component] if isinstance(component, str) else list(component)
            for name in many:
                component_index(name)
            keep &= frame["component"].isin(many).to_numpy()
        if bound is not None:
            if bound not in ("max", "min"):
                raise InputError("envelope bound must be 'max' or 'min'", bound)
            keep &= (frame["bound"] == bound).to_numpy()
        return frame[keep].reset_index(drop=True)

    def governing_cases(self):
        """For each component: the case and station of the largest |load| over the airframe.

        Returns
        -------
        pandas.DataFrame
            ``component, case, station, x_m, value_N, value_Nm, description`` (the load in
            ``value_N`` for a shear, ``value_Nm`` for a moment; SI).
        """
        rows = []
        for j, name in enumerate(COMPONENTS):
            flat = np.abs(self.loads[:, :, j])
            ci, si = np.unravel_index(int(np.argmax(flat)), flat.shape)
            value = float(self.loads[ci, si, j])
            rows.append({"component": name, "case": self.case_ids[ci],
                         "station": self.station_ids[si], "x_m": self.stations[si],
                         "value_N": value if j < 3 else np.nan,
                         "value_Nm": value if j >= 3 else np.nan,
                         "description": self.cases["description"].iloc[ci]})
        return pd.DataFrame(rows)

    def hull(self, station, pair=("Vy", "Mz")):
        """Convex hull of two components at a station (id or index): ``case`` and the two
        components' columns (``Vy_N``, ``Mz_Nm``; SI; :func:`convex_hull`).

        Parameters
        ----------
        station : str or int
            Id or index of a cut station. [-]
        pair : (str, str)
            Two components of ``Vx, Vy, Vz, Mx, My, Mz``.

        Returns
        -------
        pandas.DataFrame
            Hull vertices (:func:`~slingloads.analyses.envelopes.convex_hull`; N, N m).
        """
        index = self.station_index(station)
        return convex_hull(self.loads, self.case_ids, index, pair)

    def comparison(self):
        """Exceedance over the previous design envelope, or None if none was given (a copy of
        the table, which is computed once: the report reads it three times).

        Returns
        -------
        pandas.DataFrame or None
        """
        return None if self._comparison is None else self._comparison.copy()

    @cached_property
    def _comparison(self):
        prev = self.study.previous_envelope
        if prev is None:
            return None
        return compare_with_previous(self.loads, self.stations, self.station_ids, prev)

    def to_nastran(self, path, **options):
        """Write the load cases as a Nastran input file (``docs/nastran.md``).

        A GRID per mass item (with its CONM2) and per load point, per case a SUBCASE whose
        LOAD combines the applied FORCE and MOMENT cards, gravity (GRAV along the attitude's
        vertical) and the inertia relief chosen; in SI or US units, in the model's axes.

        Parameters
        ----------
        path : path-like
            The ``.bdf`` file to write.
        **options
            ``units``, ``axes``, ``offset``, ``inertia_relief``, ``hook_at``, the first ids...:
            see :func:`slingloads.io.loads.nastran.prepare_nastran`.

        Returns
        -------
        slingloads.io.loads.nastran.NastranDeck
            What was written; ``.subcase_table()`` links each subcase to its case id.
        """
        # The file format lives in the io layer; the method only hands the result to it.
        from slingloads.io.loads.nastran import write_nastran

        return write_nastran(self, path, **options)

    def station_index(self, station):
        """Position of a cut station given by id or index
        (:meth:`slingloads.models.airframe.Airframe.station_index`).

        Parameters
        ----------
        station : str or int
            Id or index of a cut station. [-]

        Returns
        -------
        int
            Its index in :attr:`stations` (the result's second axis). [-]

        Raises
        ------
        InputError
            If there is no such station (the valid ids are listed).
        """
        return self.study.airframe.station_index(station)

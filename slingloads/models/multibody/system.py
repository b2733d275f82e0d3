"""The towed system assembled: carrier, cable, carried helicopter, parachute, air.

:class:`SlingSystem` gathers the physical parts (each validated by its own class), turns them
into the parameter vector and tables of the compiled equations
(:mod:`slingloads.models.multibody.equations`) and checks the geometry rules between parts
(carrier cable at least 20 % longer than the parachute line; the line and canopy, streaming
aft or hanging, must not be able to reach the carrier's hook:
:func:`~slingloads.models.multibody.parachute_line.line_reach`). Positions are given in
airframe axes (``docs/conventions.md``) and passed to the equations relative to the CG.
"""

from __future__ import annotations

import hashlib
import weakref
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from slingloads.checks import finite, non_negative, positive
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.aerodynamics import FRAME_CODES, FuselageAero
from slingloads.models.airframe import Hardpoints
from slingloads.models.atmosphere import isa_density, true_airspeed
from slingloads.models.multibody.cable import Cable
from slingloads.models.multibody.carrier import FreeCarrier, FrozenCarrier
from slingloads.models.multibody.equations import (
    CHUTE_HINGED,
    CHUTE_NONE,
    CHUTE_QUASI_STATIC,
    N_PARAMETERS,
    PARAMETERS,
)
from slingloads.models.multibody.local_flow import LiftingSurface
from slingloads.models.multibody.lookup import table_arrays
from slingloads.models.multibody.parachute_line import (
    HingedParachute,
    QuasiStaticParachute,
    line_reach,
)
from slingloads.models.multibody.rigid_body import RigidBody
from slingloads.models.wake import CABLE_MARGIN, check_cable_length

#: Airspeed below which aerodynamic loads are neglected and tables not consulted. [m/s]
AERO_CUTOFF = 1.0

_INDEX = {name: i for i, name in enumerate(PARAMETERS)}
#: Motions a verification run may hold at zero acceleration.
RESTRICTIONS = ("translation", "tilt", "yaw")


@dataclass(frozen=True)
class SlingSystem:
    """Carrier, cable, carried helicopter (HC) and parachute in their air.

    Parameters
    ----------
    body : RigidBody
        HC mass, CG and inertia tensor about the CG (e.g. ``RigidBody.from_mass_items``).
    hardpoints : Hardpoints
        ``hub`` (cable attachment), ``chute`` (parachute attachment on the fin), ``mast_axis``.
    cable : Cable
    fuselage : FuselageAero or None
        Fuselage-alone table with its reference area, length and moment reference point.
    surfaces : sequence of LiftingSurface
        At most one fin (normal "y") and one horizontal tail (normal "z").
    parachute : HingedParachute, QuasiStaticParachute or None
        ``None``: the configuration without parachute (paper section 5).
    carrier : FrozenCarrier or FreeCarrier
    airspeed : float
        Equivalent airspeed of the towed flight (the trim of the gust and free-response runs),
        >= 0. [m/s]
    density_altitude : float
        ISA density altitude. [m]
    aero_cutoff : float
        Airspeed below which the aerodynamic loads are neglected, > 0. [m/s]
    gravity : float
        [m/s^2]
    name : str
    restrict : tuple of str
        For verification only: motions held at zero acceleration, any of "translation" (the
        CG), "tilt" (roll and pitch) and "yaw" (e.g. ("translation", "tilt") leaves the
        1-DOF yaw model).
    """

    body: RigidBody
    hardpoints: Hardpoints
    cable: Cable
    fuselage: FuselageAero | None = None
    surfaces: tuple = ()
    parachute: HingedParachute | QuasiStaticParachute | None = None
    carrier: FrozenCarrier | FreeCarrier = field(default_factory=FrozenCarrier)
    airspeed: float = 0.0
    density_altitude: float = 0.0
    aero_cutoff: float = AERO_CUTOFF
    gravity: float = G0
    name: str = "system"
    restrict: tuple = ()

    def __post_init__(self):
        self._check_types()
        object.__setattr__(self, "surfaces", tuple(self.surfaces))
        normals = [s.normal for s in self.surfaces]
        for axis in set(normals):
            if normals.count(axis) > 1:
                what = "fin" if axis == "y" else "horizontal tail"
                raise InputError(f"at most one {what} (surface normal {axis!r})",
                                 normals.count(axis))
        object.__setattr__(self, "airspeed", non_negative(
            self.airspeed, "airspeed must be >= 0 [m/s]"))
        object.__setattr__(self, "density_altitude", finite(
            self.density_altitude, "density altitude must be a finite number [m]"))
        isa_density(self.density_altitude)
        object.__setattr__(self, "aero_cutoff", positive(
            self.aero_cutoff, "aerodynamic cut-off airspeed must be > 0 [m/s]"))
        object.__setattr__(self, "gravity", positive(self.gravity, "gravity must be > 0"))
        object.__setattr__(self, "restrict", tuple(self.restrict))
        bad = [r for r in self.restrict if r not in RESTRICTIONS]
        if bad:
            raise InputError(f"{bad[0]!r} is not a valid restriction; valid restrictions are "
                             f"{list(RESTRICTIONS)}", bad[0])
        if self.restrict and self.chute_kind == "hinged":
            raise InputError("restrictions cannot be combined with a hinged parachute (its "
                             "line would not see the constraint forces)", self.restrict)
        if self.parachute is not None:
            self._check_parachute_reach()

    def _check_types(self):
        expected = (("body", RigidBody), ("hardpoints", Hardpoints), ("cable", Cable),
                    ("carrier", (FrozenCarrier, FreeCarrier)))
        for name, kind in expected:
            if not isinstance(getattr(self, name), kind):
                raise InputError(f"the system's {name} has the wrong type",
                                 type(getattr(self, name)).__name__)
        if self.fuselage is not None and not isinstance(self.fuselage, FuselageAero):
            raise InputError("the fuselage must be a FuselageAero", type(self.fuselage).__name__)
        for s in self.surfaces:
            if not isinstance(s, LiftingSurface):
                raise InputError("surfaces must be LiftingSurface objects", type(s).__name__)
        if self.parachute is not None and not isinstance(
                self.parachute, (HingedParachute, QuasiStaticParachute)):
            raise InputError("the parachute must be a HingedParachute or a QuasiStaticParachute "
                             "(or None)", type(self.parachute).__name__)
        if self.parachute is not None and self.hardpoints.chute is None:
            raise InputError("a parachute needs its attachment point (Hardpoints.chute)")

    def _check_parachute_reach(self):
        line = self.parachute.line_length
        near, far = line_reach(self.hardpoints.hub, self.hardpoints.chute, line)
        if near <= self.cable.length <= far:
            raise InputError(
                f"the parachute could reach the carrier: its line ({line:.4g} m), streaming "
                f"aft of its attachment or hanging below it, reaches from {near:.4g} m to "
                f"{far:.4g} m from the hub, and the carrier cable ({self.cable.length:.4g} m) "
                f"lies in that range; lengthen the cable beyond {far:.4g} m (or shorten the "
                f"line)", self.cable.length)

    @property
    def locks(self):
        """(translation, tilt, yaw) restrictions as booleans."""
        return tuple(name in self.restrict for name in RESTRICTIONS)

    # ------------------------------------------------------------------ derived quantities
    @cached_property
    def density(self):
        """Air density at the density altitude. [kg/m^3]"""
        return float(isa_density(self.density_altitude))

    @cached_property
    def true_airspeed(self):
        """True airspeed of the towed flight. [m/s]"""
        return float(true_airspeed(self.airspeed, self.density_altitude))

    @property
    def canopy_mass(self):
        """Mass of the hinged canopy (0 otherwise). [kg]"""
        return float(getattr(self.parachute, "mass", 0.0)) if self.parachute else 0.0

    @property
    def hung_mass(self):
        """HC plus canopy mass. [kg]"""
        return self.body.mass + self.canopy_mass

    @property
    def weight(self):
        """Weight of the hung mass. [N]"""
        return self.hung_mass * self.gravity

    @property
    def fin(self):
        """The fin (surface with normal y), or None."""
        return next((s for s in self.surfaces if s.normal == "y"), None)

    @property
    def tail(self):
        """The horizontal tail (surface with normal z), or None."""
        return next((s for s in self.surfaces if s.normal == "z"), None)

    @property
    def chute_kind(self):
        """"hinged", "quasi-static" or "none"."""
        return "none" if self.parachute is None else self.parachute.kind

    @cached_property
    def drag_area(self):
        """Rough drag area of the fuselage (CD at zero angles) and the parachute (CD(0)), to
        start a trim at a sensible swing angle. [m^2]"""
        area = 0.0
        if self.fuselage is not None:
            area += self.fuselage.area * _ZERO_ANGLE_CD.get(self.fuselage)
        if self.parachute is not None:
            area += float(self.parachute.parachute.drag_area(0.0))
        return area

    def cable_check(self, margin=CABLE_MARGIN):
        """The 20 % rule: carrier cable against the parachute line.

        Parameters
        ----------
        margin : float
            Required excess of the cable over the parachute line, as a fraction of the line
            (default 0.20, the paper's 20 %). [-]

        Returns
        -------
        CableCheck or None
            :func:`~slingloads.models.wake.check_cable_length` of the cable and the parachute
            line; None without a parachute.
        """
        if self.parachute is None:
            return None
        return check_cable_length(self.cable.length, self.parachute.line_length, margin)

    def warnings(self, margin=CABLE_MARGIN):
        """Rules that are broken but do not prevent a run (the report shows them): the cable
        shorter than (1 + ``margin``) x the parachute line.

        Parameters
        ----------
        margin : float
            Required excess of the cable over the parachute line, as a fraction of the line
            (default 0.20, the paper's 20 %). [-]

        Returns
        -------
        list of str
            One message per broken rule (empty when none is).
        """
        check = self.cable_check(margin)
        return [] if check is None or check.ok else [check.message]

    def with_(self, **changes):
        """A copy with fields replaced (validated again).

        Parameters
        ----------
        **changes
            Fields of :class:`SlingSystem` and their new values (units of the fields).

        Returns
        -------
        SlingSystem
        """
        return replace(self, **changes)

    # ------------------------------------------------------------------ for the equations
    def parameters(self, pull=(0.0, 0.0, 0.0), locks=(False, False, False)):
        """Parameter vector of the compiled equations (a new array).

        Parameters
        ----------
        pull : array_like, shape (3,)
            Cable pull on the carrier at the trim the run starts from (free carrier's
            feed-forward), earth axes. [N]
        locks : (bool, bool, bool)
            Restrictions for verification: no CG acceleration, no roll/pitch acceleration, no
            yaw acceleration.

        Returns
        -------
        ndarray, shape (N_PARAMETERS,)
            Laid out by :data:`~slingloads.models.multibody.equations.LAYOUT`. [SI]
        """
        p = self._base_parameters.copy()
        if isinstance(self.carrier, FreeCarrier):
            p[_INDEX["pull_X"]:_INDEX["pull_X"] + 3] = np.asarray(pull, float).reshape(3)
        p[_INDEX["lock_translation"]] = float(locks[0])
        p[_INDEX["lock_tilt"]] = float(locks[1])
        p[_INDEX["lock_yaw"]] = float(locks[2])
        return p

    @cached_property
    def _base_parameters(self):
        """The parameter vector without pull and locks (computed once per system)."""
        p = np.zeros(N_PARAMETERS)

        def put(name, values):
            i = _INDEX[name]
            if isinstance(values, np.ndarray):
                p[i:i + values.size] = values.ravel()
            else:
                p[i] = values

        cg = self.body.cg
        inertia = self.body.inertia
        put("mass", self.body.mass)
        put("Iinv_xx", np.linalg.inv(inertia))
        put("I_xx", inertia)
        put("hub_x", self.hardpoints.hub - cg)
        put("mast_x", self.hardpoints.mast_axis)
        if self.fuselage is not None:
            put("ref_x", self.fuselage.moment_reference - cg)
            put("fuselage_area", self.fuselage.area)
            put("fuselage_length", self.fuselage.length)
            put("fuselage_force_frame", FRAME_CODES[self.fuselage.force_axes])
            put("fuselage_moment_frame", FRAME_CODES[self.fuselage.moment_axes])
        if self.fin is not None:
            put("fin_x", self.fin.centre_of_pressure - cg)
            put("fin_area_eff", self.fin.area * self.fin.efficiency)
        if self.tail is not None:
            put("tail_x", self.tail.centre_of_pressure - cg)
            put("tail_area_eff", self.tail.area * self.tail.efficiency)
        if self.parachute is not None:
            chute = self.parachute.parachute
            put("chute_x", self.hardpoints.chute - cg)
            put("chute_line", chute.line_length)
            if self.parachute.kind == "hinged":
                put("chute_mode", CHUTE_HINGED)
                put("chute_drag_area", chute.wake_ratio * chute.area)
                put("chute_mass", self.parachute.mass)
            else:
                put("chute_mode", CHUTE_QUASI_STATIC)
                put("chute_drag_area", float(chute.drag_area(0.0)))
        else:
            put("chute_mode", CHUTE_NONE)
        put("cable_length", self.cable.length)
        put("cable_stiffness", self.cable.stiffness)
        put("cable_damping", self.cable.damping(self.hung_mass))
        if isinstance(self.carrier, FreeCarrier):
            put("carrier_free", 1.0)
            put("carrier_mass", self.carrier.mass)
            put("carrier_drag_area", self.carrier.drag_area)
            put("carrier_gain", self.carrier.speed_gain)
        put("density", self.density)
        put("gravity", self.gravity)
        put("v_cut", self.aero_cutoff)
        return p

    def tables(self):
        """Aerodynamic tables for the equations, computed once per system.

        Returns
        -------
        tuple of ndarray
            ``(fus_a, fus_b, fus_c, fin_g, fin_v, tail_g, tail_v, cd_g, cd_v)``: fuselage alpha
            and beta breakpoints [rad] and stacked coefficients [-] (in the table's declared
            frames, whose codes are parameters), then the breakpoints [rad] and values [-] of
            the fin, horizontal tail and parachute CD tables.
        """
        return self._tables

    def _table_sources(self):
        """(table or None, coefficient names) of the fuselage, fin, tail and parachute."""
        return ((None if self.fuselage is None else self.fuselage.table,
                 () if self.fuselage is None else self.fuselage.columns),
                (None if self.fin is None else self.fin.table, ("CY",)),
                (None if self.tail is None else self.tail.table, ("CN",)),
                (None if self.parachute is None else self.parachute.parachute.cd, ("CD",)))

    @cached_property
    def _tables(self):
        arrays = [_TABLE_ARRAYS.get(table, names)[0] for table, names in self._table_sources()]
        if self.fuselage is None:
            arrays[0] = (np.array([-np.pi, np.pi]), np.array([-np.pi, np.pi]),
                         np.zeros((6, 2, 2)))
        return sum(arrays, ())

    def table_key(self):
        """Identity of the tables' contents (runs with the same key share one batch).

        Returns
        -------
        str
            A SHA-1 hex digest of the four tables.
        """
        return self._table_key

    @cached_property
    def _table_key(self):
        digest = hashlib.sha1()
        for k, (table, names) in enumerate(self._table_sources()):
            part = (_digest(self._tables[:3]) if k == 0 and table is None
                    else _TABLE_ARRAYS.get(table, names)[1])
            digest.update(part.encode())
        return digest.hexdigest()


def _digest(arrays):
    """SHA-1 of arrays' shapes and contents."""
    digest = hashlib.sha1()
    for array in arrays:
        digest.update(str(array.shape).encode())
        digest.update(array.tobytes())
    return digest.hexdigest()


class _PerObject:
    """Values computed once per (immutable) object, kept while the object lives (systems that
    share a fuselage or a table, as the variants of a study do, compute them once)."""

    def __init__(self, compute):
        self.compute = compute
        self._values = {}

    def get(self, obj, *args):
        if obj is None:
            return self.compute(None, *args)
        key = (id(obj), *args)
        hit = self._values.get(key)
        if hit is not None and hit[0]() is obj:
            return hit[1]
        value = self.compute(obj, *args)
        self._values[key] = (weakref.ref(obj), value)
        weakref.finalize(obj, self._values.pop, key, None)
        return value


def _table_arrays_and_digest(table, names):
    arrays = table_arrays(table, names)
    return arrays, _digest(arrays)


#: The kernels' arrays of a table and their digest.
_TABLE_ARRAYS = _PerObject(_table_arrays_and_digest)
#: A fuselage's drag coefficient at zero angle of attack and sideslip. [-]
_ZERO_ANGLE_CD = _PerObject(lambda fuselage: float(fuselage.drag_coefficient(0.0, 0.0)))

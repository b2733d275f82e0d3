"""Airframe model of the carried helicopter: lumped masses, cut stations, hardpoints.

Axes (see ``docs/conventions.md``): x aft along the fuselage station (FS), y right along the
butt line (BL), z up along the water line (WL); origin at the airframe's datum. SI inside.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from slingloads.checks import frozen
from slingloads.constants import G0
from slingloads.errors import InputError


def _ids(ids, what):
    ids = tuple(str(i) for i in ids)
    seen = set()
    for i in ids:
        if i in seen:
            raise InputError(f"{what} ids must be unique", i)
        seen.add(i)
    return ids


#: Share of the largest principal moment by which it may exceed the sum of the other two
#: (rounding of the written values: a thin plate meets the inequality with equality).
INERTIA_TRIANGLE_TOLERANCE = 0.01

#: The own-inertia columns of the MassItems sheet, by axis (an error names the one to fix).
_MOMENT_FIELDS = ("Ixx", "Iyy", "Izz")


def _check_triangle(ids, inertia, eig):
    """Each item's principal moments meet the triangle inequality: none exceeds the sum of
    the other two by more than :data:`INERTIA_TRIANGLE_TOLERANCE` of itself.

    Rigid-body mechanics: about principal axes through the CG, I1 + I2 - I3 = 2 integral(x3^2
    dm) >= 0 (and so for every pair), whatever the mass distribution; a tensor breaking it
    has no body. The error names the diagonal term (field ``Ixx``, ``Iyy`` or ``Izz``) that
    breaks the inequality most when one does, else the item's inertia (``inertia``)."""
    excess = eig[:, 2] - eig[:, 0] - eig[:, 1]  # eigvalsh: ascending
    bad = excess > INERTIA_TRIANGLE_TOLERANCE * eig[:, 2]
    if not np.any(bad):
        return
    i = int(np.argmax(bad))
    diag = np.diagonal(inertia[i]).copy()
    over = 2.0 * diag - diag.sum()  # I_kk - (sum of the other two)
    k = int(np.argmax(over))
    field_name = (_MOMENT_FIELDS[k] if over[k] > INERTIA_TRIANGLE_TOLERANCE * diag[k]
                  else "inertia")
    low, mid, high = (float(f"{v:.6g}") for v in eig[i])
    raise InputError(
        f"own inertia of item {ids[i]!r} is not physical: its largest principal moment "
        f"{high:g} kg m^2 exceeds the sum of the other two ({low:g} + {mid:g} kg m^2); no "
        "body has a moment of inertia larger than the sum of the other two (Ixx + Iyy - Izz "
        "= 2 integral(z^2 dm) >= 0; 1 % allowed for rounding): give all three own moments "
        "(an item flat in the x-y plane has Izz = Ixx + Iyy)", field=field_name, index=i)


@dataclass(frozen=True)
class MassItems:
    """Lumped mass items of the airframe.

    Parameters
    ----------
    ids : sequence of str
        Unique item names.
    mass : array_like, shape (n,)
        Item masses, each > 0. [kg]
    position : array_like, shape (n, 3)
        Item centres of gravity (x aft, y right, z up). [m]
    inertia : array_like, shape (n, 3, 3), optional
        Each item's own inertia tensor about its own CG (zero for point masses), physical:
        principal moments >= 0, none larger than the sum of the other two. [kg m^2]
    description : sequence of str, optional
        Readable text per item.
    """

    ids: tuple
    mass: np.ndarray
    position: np.ndarray
    inertia: np.ndarray | None = None
    description: tuple = ()

    def __post_init__(self):
        ids = _ids(self.ids, "mass item")
        mass = np.asarray(self.mass, dtype=float)
        pos = np.asarray(self.position, dtype=float)
        n = len(ids)
        if n == 0:
            raise InputError("an airframe needs at least one mass item")
        if mass.shape != (n,) or pos.shape != (n, 3):
            raise InputError("mass items need one mass and one (x, y, z) position each")
        bad = ~np.isfinite(mass) | (mass <= 0)
        if np.any(bad):
            i = int(np.argmax(bad))
            raise InputError(f"mass of item {ids[i]!r} must be > 0", mass[i].item(),
                             field="mass", index=i)
        if not np.all(np.isfinite(pos)):
            i = int(np.argmax(~np.all(np.isfinite(pos), axis=1)))
            raise InputError("mass item positions must be finite numbers", field="position",
                             index=i)
        inertia = np.zeros((n, 3, 3)) if self.inertia is None else np.asarray(
            self.inertia, dtype=float)
        if inertia.shape != (n, 3, 3) or not np.all(np.isfinite(inertia)):
            raise InputError("own inertias must be finite 3 x 3 tensors, one per item")
        if not np.allclose(inertia, np.swapaxes(inertia, 1, 2)):
            raise InputError("own inertia tensors must be symmetric")
        eig = np.linalg.eigvalsh(inertia)
        scale = max(np.abs(eig).max(), 1.0)
        if np.any(eig < -1e-9 * scale):
            i = int(np.argmax(np.any(eig < -1e-9 * scale, axis=1)))
            raise InputError(
                f"own inertia of item {ids[i]!r} is not physical: its principal moments "
                f"{[float(f'{v:.6g}') for v in eig[i]]} kg m^2 must all be >= 0 (negative "
                "principal moment: the products of inertia are too large for the moments)",
                field="inertia", index=i)
        _check_triangle(ids, inertia, eig)
        desc = tuple(self.description) or ("",) * n
        if len(desc) != n:
            raise InputError(f"mass items need one description each ({n}), or none",
                             len(desc))
        object.__setattr__(self, "ids", ids)
        object.__setattr__(self, "mass", frozen(mass))
        object.__setattr__(self, "position", frozen(pos))
        object.__setattr__(self, "inertia", frozen(inertia))
        object.__setattr__(self, "description", tuple(str(d) for d in desc))

    def index(self, item_id):
        """Position of the item ``item_id`` in the arrays.

        Parameters
        ----------
        item_id : str
            Id of a mass item.

        Returns
        -------
        int
            Its row in ``mass``, ``position`` and ``inertia``. [-]

        Raises
        ------
        InputError
            If no item has that id (the valid ids are listed).
        """
        try:
            return self.ids.index(str(item_id))
        except ValueError:
            raise InputError(f"unknown mass item; valid ids are {list(self.ids)}",
                             item_id) from None

    def with_item(self, item_id, *, mass=None, position=None, inertia=None,
                  description=None):
        """A copy with one item changed; what is not given stays as it is.

        Parameters
        ----------
        item_id : str
            Id of an existing item.
        mass : float, optional
            New mass, > 0. [kg]
        position : array_like, shape (3,), optional
            New CG (x aft, y right, z up). [m]
        inertia : array_like, shape (3, 3), optional
            New own inertia tensor about the item's CG. [kg m^2]
        description : str, optional

        Returns
        -------
        MassItems
            Checked as any new set of items is.

        Examples
        --------
        >>> items = MassItems(["A", "B"], [10.0, 20.0], [[0, 0, 0], [1, 0, 0]])
        >>> items.with_item("B", mass=25.0).mass.tolist()
        [10.0, 25.0]
        """
        i = self.index(item_id)
        masses, positions = self.mass.copy(), self.position.copy()
        inertias, texts = self.inertia.copy(), list(self.description)
        if mass is not None:
            masses[i] = mass
        if position is not None:
            positions[i] = np.asarray(position, float).reshape(3)
        if inertia is not None:
            inertias[i] = np.asarray(inertia, float).reshape(3, 3)
        if description is not None:
            texts[i] = str(description)
        return MassItems(self.ids, masses, positions, inertias, tuple(texts))

    def with_added(self, item_id, mass, position, inertia=None, description=""):
        """A copy with one more item (arguments as in :meth:`with_item`, [kg], [m],
        [kg m^2]); the id must be new.

        Parameters
        ----------
        item_id : str
            Id of the new item (not already used).
        mass : float
            Its mass. [kg]
        position : array_like, shape (3,)
            Its CG (x, y, z). [m]
        inertia : array_like, shape (3, 3), optional
            Its own inertia about its CG (default zero: a point mass). [kg m^2]
        description : str
            Free text.

        Returns
        -------
        MassItems
        """
        own = np.zeros((3, 3)) if inertia is None else np.asarray(inertia, float)
        return MassItems((*self.ids, str(item_id)), np.r_[self.mass, float(mass)],
                         np.vstack([self.position, np.asarray(position, float).reshape(1, 3)]),
                         np.concatenate([self.inertia, own.reshape(1, 3, 3)]),
                         (*self.description, str(description)))

    def without(self, item_id):
        """A copy without the item ``item_id``.

        Parameters
        ----------
        item_id : str
            Id of an existing item.

        Returns
        -------
        MassItems
        """
        keep = np.arange(len(self.ids)) != self.index(item_id)
        return MassItems(tuple(np.asarray(self.ids, dtype=object)[keep]), self.mass[keep],
                         self.position[keep], self.inertia[keep],
                         tuple(np.asarray(self.description, dtype=object)[keep]))

    @property
    def total_mass(self):
        """Total mass. [kg]"""
        return float(self.mass.sum())

    @property
    def weight(self):
        """Total weight at standard gravity. [N]"""
        return self.total_mass * G0

    @property
    def cg(self):
        """Centre of gravity (x, y, z). [m]"""
        return self.mass @ self.position / self.total_mass

    @property
    def inertia_about_cg(self):
        """Inertia tensor about the CG, own inertias plus parallel-axis terms. [kg m^2]"""
        d = self.position - self.cg
        parallel = (np.einsum("n,nk,nk->n", self.mass, d, d)[:, None, None] * np.eye(3)
                    - np.einsum("n,ni,nj->nij", self.mass, d, d))
        return (self.inertia + parallel).sum(axis=0)

    def to_frame(self):
        """Mass items as a DataFrame (SI).

        Returns
        -------
        pandas.DataFrame
            One row per item: id, description, mass [kg], CG x, y, z [m] and the six inertia
            components [kg m^2].
        """
        return pd.DataFrame({
            "id": self.ids, "description": self.description, "mass [kg]": self.mass,
            "x [m]": self.position[:, 0], "y [m]": self.position[:, 1],
            "z [m]": self.position[:, 2],
            "Ixx [kg m^2]": self.inertia[:, 0, 0], "Iyy [kg m^2]": self.inertia[:, 1, 1],
            "Izz [kg m^2]": self.inertia[:, 2, 2], "Ixy [kg m^2]": self.inertia[:, 0, 1],
            "Ixz [kg m^2]": self.inertia[:, 0, 2], "Iyz [kg m^2]": self.inertia[:, 1, 2],
        })


@dataclass(frozen=True)
class Hardpoints:
    """Where external loads enter the airframe.

    Parameters
    ----------
    hub : array_like, shape (3,)
        Rotor hub centre, where the carrier's cable is hooked. [m]
    mast_feet : array_like, shape (k, 3)
        Mast attachment points on the transmission deck. [m]
    mast_weights : array_like, shape (k,), optional
        Weights of the rigid-body share of the hub load among the feet (default equal). [-]
    mast_axis : array_like, shape (3,), optional
        Direction of the mast, from the deck towards the hub (default +z). [-]
    chute : array_like, shape (3,), optional
        Parachute attachment on the fin. [m]
    """

    hub: np.ndarray
    mast_feet: np.ndarray
    mast_weights: np.ndarray | None = None
    mast_axis: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))
    chute: np.ndarray | None = None
    mast_feet_ids: tuple = ()

    def __post_init__(self):
        hub = np.asarray(self.hub, dtype=float).reshape(3)
        feet = np.asarray(self.mast_feet, dtype=float).reshape(-1, 3)
        if not (np.all(np.isfinite(hub)) and np.all(np.isfinite(feet))):
            raise InputError("hub and mast attachment points must be finite [m]",
                             [hub.tolist(), feet.tolist()])
        weights = (np.ones(len(feet)) if self.mast_weights is None
                   else np.asarray(self.mast_weights, dtype=float))
        if len(feet) == 0:
            raise InputError("the mast needs at least one attachment point")
        if weights.shape != (len(feet),) or np.any(~np.isfinite(weights) | (weights <= 0)):
            raise InputError("mast attachment weights must be > 0, one per point",
                             weights.tolist())
        axis = np.asarray(self.mast_axis, dtype=float).reshape(3)
        norm = np.linalg.norm(axis)
        if not np.isfinite(norm) or norm == 0:
            raise InputError("mast axis must be a non-zero vector", axis.tolist())
        chute = None if self.chute is None else np.asarray(self.chute, dtype=float).reshape(3)
        ids = tuple(self.mast_feet_ids) or tuple(f"mast foot {i + 1}" for i in range(len(feet)))
        object.__setattr__(self, "hub", frozen(hub))
        object.__setattr__(self, "mast_feet", frozen(feet))
        object.__setattr__(self, "mast_weights", frozen(weights))
        object.__setattr__(self, "mast_axis", frozen(axis / norm))
        object.__setattr__(self, "chute", None if chute is None else frozen(chute))
        object.__setattr__(self, "mast_feet_ids", _ids(ids, "mast attachment"))


def check_inside(mass_items, reference_axis, label, point):
    """Raise :class:`InputError` if ``point`` [m] lies outside the airframe.

    Inside means: x within the mass items' x range (where the beam exists), and a distance
    from the loads reference axis (y0, z0) [m] no larger than that x range (at least 1 m).

    Parameters
    ----------
    mass_items : MassItems
        The airframe's mass items (their x range is where the beam exists).
    reference_axis : (float, float)
        (y0, z0) of the loads reference axis. [m]
    label : str
        Name of the point, for the message.
    point : array_like, shape (3,)
        The point (x, y, z). [m]
    """
    point = np.asarray(point, dtype=float)
    x = mass_items.position[:, 0]
    lo, hi = float(x.min()), float(x.max())
    reach = max(hi - lo, 1.0)
    y0, z0 = reference_axis
    if not (lo <= point[0] <= hi):
        raise InputError(
            f"hardpoint {label} lies outside the airframe: x must be within the mass "
            f"items' range [{lo:.4g}, {hi:.4g}] m", float(point[0]))
    if np.hypot(point[1] - y0, point[2] - z0) > reach:
        raise InputError(
            f"hardpoint {label} lies outside the airframe: its distance from the loads "
            f"reference axis must not exceed the airframe length {reach:.4g} m",
            [float(v) for v in point])


@dataclass(frozen=True)
class Airframe:
    """The carried helicopter as a free-free beam of lumped masses.

    Parameters
    ----------
    mass_items : MassItems
    stations : array_like, shape (s,)
        Cut stations where internal loads are reported, strictly increasing x. [m]
    hardpoints : Hardpoints
    reference_axis : tuple of float, optional
        (y, z) of the loads reference axis, parallel to x; moments are taken about the point
        of this axis at each cut. [m]
    station_ids : sequence of str, optional
        Names of the cut stations (default ``FS<x in m>``).
    aero_points : array_like, shape (a,), optional
        x of the points on the reference axis that take the fuselage aerodynamic load
        (default: the mid-points between consecutive cut stations that lie within the mass
        items' x range). [m]
    aero_weights : array_like, shape (a,), optional
        Share weights of those points (default equal). [-]
    name : str
    """

    mass_items: MassItems
    stations: np.ndarray
    hardpoints: Hardpoints
    reference_axis: tuple = (0.0, 0.0)
    station_ids: tuple = ()
    aero_points: np.ndarray | None = None
    aero_weights: np.ndarray | None = None
    name: str = "airframe"

    def __post_init__(self):
        x = np.asarray(self.stations, dtype=float)
        if x.ndim != 1 or x.size < 1 or not np.all(np.isfinite(x)):
            raise InputError("cut stations must be a non-empty list of finite x values")
        steps = np.diff(x)
        if np.any(steps <= 0):
            i = int(np.argmax(steps <= 0)) + 1
            rule = ("cut stations must not repeat" if steps[i - 1] == 0
                    else "cut stations must be sorted by increasing x")
            raise InputError(rule, x[i].item(), field="stations", index=i)
        ids = tuple(self.station_ids) or tuple(f"FS{v:.3f}" for v in x)
        if len(ids) != x.size:
            raise InputError("one id per cut station is needed")
        object.__setattr__(self, "stations", frozen(x))
        object.__setattr__(self, "station_ids", _ids(ids, "cut station"))
        object.__setattr__(self, "reference_axis",
                           tuple(float(v) for v in np.asarray(self.reference_axis).reshape(2)))
        if self.aero_points is None:
            lo, hi = self.extent
            pts = 0.5 * (x[1:] + x[:-1]) if x.size > 1 else x.copy()
            pts = pts[(pts >= lo) & (pts <= hi)]
            if pts.size == 0:
                pts = self.mass_items.cg[:1].copy()
        else:
            pts = np.asarray(self.aero_points, dtype=float).reshape(-1)
        w = np.ones(pts.size) if self.aero_weights is None else np.asarray(
            self.aero_weights, dtype=float).reshape(-1)
        if w.shape != pts.shape or np.any(~np.isfinite(w) | (w <= 0)):
            raise InputError("aerodynamic share weights must be > 0, one per point",
                             w.tolist())
        object.__setattr__(self, "aero_points", frozen(pts))
        object.__setattr__(self, "aero_weights", frozen(w))
        self._check_inside()

    @property
    def extent(self):
        """(x_min, x_max) of the mass items: the length over which the beam exists. [m]"""
        x = self.mass_items.position[:, 0]
        return float(x.min()), float(x.max())

    @property
    def length(self):
        """Length of the mass distribution along x. [m]"""
        lo, hi = self.extent
        return hi - lo

    def with_mass_item(self, item_id, *, mass=None, position=None, inertia=None,
                       description=None):
        """A copy with one mass item changed (:meth:`MassItems.with_item`: ``mass`` [kg],
        ``position`` [m], ``inertia`` [kg m^2], ``description``); the aerodynamic points
        stay where they are.

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
        Airframe
        """
        items = self.mass_items.with_item(item_id, mass=mass, position=position,
                                          inertia=inertia, description=description)
        return replace(self, mass_items=items)

    def station_index(self, station):
        """Position of a cut station given by id or index.

        Parameters
        ----------
        station : str or int
            Id or index of a cut station. [-]

        Returns
        -------
        int
            Its index in ``stations``. [-]

        Raises
        ------
        InputError
            If there is no such station (the valid ids are listed).
        """
        if isinstance(station, (int, np.integer)) and not isinstance(station, bool):
            if not 0 <= station < len(self.stations):
                raise InputError(f"station index out of range [0, {len(self.stations)})",
                                 int(station))
            return int(station)
        try:
            return self.station_ids.index(str(station))
        except ValueError:
            raise InputError(f"unknown cut station; valid ids are {list(self.station_ids)}",
                             station) from None

    def with_station(self, station, x=None, *, station_id=None):
        """A copy with one cut station moved or renamed (the stations stay sorted by x).

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
        Airframe
        """
        i = self.station_index(station)
        x_all, ids = self.stations.copy(), list(self.station_ids)
        if x is not None:
            x_all[i] = x
        if station_id is not None:
            ids[i] = str(station_id)
        return replace(self, stations=x_all, station_ids=tuple(ids))

    def with_stations(self, stations, station_ids=()):
        """A copy with new cut stations [m] (ids default to ``FS<x in m>``).

        Parameters
        ----------
        stations : array_like, shape (s,)
            x of the cut stations. [m]
        station_ids : sequence of str
            Their ids (default ``FS<x in m>``).

        Returns
        -------
        Airframe
        """
        return replace(self, stations=stations, station_ids=tuple(station_ids))

    def with_hardpoints(self, *, hub=None, mast_feet=None, mast_weights=None, mast_axis=None,
                        chute=None, mast_feet_ids=None):
        """A copy with hardpoints changed (:class:`Hardpoints`: ``hub``, ``mast_feet``,
        ``chute`` [m]; ``mast_weights``, ``mast_axis`` [-]; ``mast_feet_ids``); what is not
        given stays as it is. New mast feet drop the former weights and ids unless given.

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
        Airframe
        """
        hp = self.hardpoints
        changes = {k: v for k, v in (("hub", hub), ("mast_feet", mast_feet),
                                     ("mast_weights", mast_weights), ("mast_axis", mast_axis),
                                     ("chute", chute), ("mast_feet_ids", mast_feet_ids))
                   if v is not None}
        if mast_feet is not None and len(np.reshape(mast_feet, (-1, 3))) != len(hp.mast_feet):
            changes.setdefault("mast_weights", None)
            changes.setdefault("mast_feet_ids", ())
        return replace(self, hardpoints=replace(hp, **changes))

    def _check_inside(self):
        hp = self.hardpoints
        named = [("rotor hub", hp.hub)]
        named += list(zip(hp.mast_feet_ids, hp.mast_feet, strict=True))
        if hp.chute is not None:
            named.append(("parachute attachment", hp.chute))
        y0, z0 = self.reference_axis
        named += [(f"aerodynamic point x = {p:.4g} m", np.array([p, y0, z0]))
                  for p in self.aero_points]
        for label, point in named:
            check_inside(self.mass_items, self.reference_axis, label, point)

    def station_points(self):
        """Points of the reference axis at the cut stations, shape (s, 3). [m]

        Returns
        -------
        ndarray, shape (s, 3)
            (x, y0, z0) of each cut station. [m]
        """
        y0, z0 = self.reference_axis
        return np.column_stack([self.stations, np.full(self.stations.shape, y0),
                                np.full(self.stations.shape, z0)])


def hanging_vertical(airframe):
    """Earth's upward vertical in airframe axes when the airframe hangs at rest from its hub.

    A body hung at one point comes to rest with its CG under that point, so the vertical is
    :math:`\\hat k = (r_{hub} - r_{CG}) / |r_{hub} - r_{CG}|` (the hanging attitude of
    :mod:`slingloads.models.attitude`).

    Parameters
    ----------
    airframe : Airframe

    Returns
    -------
    numpy.ndarray
        Unit vector, shape (3,). [-]

    Raises
    ------
    InputError
        If the hub coincides with the CG (no hanging attitude).
    """
    d = np.asarray(airframe.hardpoints.hub, float) - airframe.mass_items.cg
    length = float(np.linalg.norm(d))
    if not length > 0:
        raise InputError("the rotor hub coincides with the CG of the mass items: the airframe "
                         "has no hanging attitude [m]", length)
    return d / length


def yaw_inertia_about_hub(airframe):
    """Yaw inertia of the mass items about the vertical through the rotor hub, hanging.

    The airframe hangs with its CG under the hub (:func:`hanging_vertical`), so the vertical
    through the hub passes through the CG and no parallel-axis term arises:

    .. math:: I = \\hat k^T \\, I_{CG} \\, \\hat k

    (:math:`I_{zz,CG}` when the hub lies on the body z axis through the CG).

    Parameters
    ----------
    airframe : Airframe

    Returns
    -------
    float
        [kg m^2]
    """
    items = airframe.mass_items
    return hanging_yaw_inertia(items.inertia_about_cg, items.cg, airframe.hardpoints.hub)


def hanging_yaw_inertia(inertia_about_cg, cg, hub, axis=None, mass=None):
    """Yaw inertia of a body hung at ``hub`` about a line through the hub: the hub-CG line
    (the vertical at rest), or the line along ``axis`` (the suspension axis in towed flight).

    .. math:: I = \\hat a^T I_{CG} \\hat a + m \\, |d - (d \\cdot \\hat a) \\hat a|^2,
              \\qquad d = r_{CG} - r_{hub}

    (parallel-axis theorem; the second term is zero on the hub-CG line).

    Parameters
    ----------
    inertia_about_cg : array_like, shape (3, 3)
        Inertia tensor about the CG. [kg m^2]
    cg, hub : array_like, shape (3,)
        [m]
    axis : array_like, shape (3,), optional
        Direction of the line (normalised); None is the hub-CG line. [-]
    mass : float, optional
        The body's mass, needed when the line misses the CG. [kg]

    Returns
    -------
    float
        [kg m^2]
    """
    d = np.asarray(hub, float) - np.asarray(cg, float)
    length = float(np.linalg.norm(d))
    if not length > 0:
        raise InputError("the rotor hub coincides with the CG: the body has no hanging "
                         "attitude [m]", length)
    k = d / length if axis is None else np.asarray(axis, float)
    norm = float(np.linalg.norm(k))
    if not (np.all(np.isfinite(k)) and norm > 0):
        raise InputError("the yaw axis must be a finite non-zero vector [-]", k.tolist())
    k = k / norm
    own = float(k @ np.asarray(inertia_about_cg, float) @ k)
    offset = d - (d @ k) * k
    if axis is None or not np.linalg.norm(offset) > 1e-12 * length:
        return own
    if mass is None:
        raise InputError("the yaw axis misses the CG by "
                         f"{np.linalg.norm(offset):.4g} m: give the mass for the parallel-axis "
                         "term [m]", float(np.linalg.norm(offset)))
    return own + float(mass) * float(offset @ offset)


def hanging_roll_axis(airframe):
    """The horizontal fore-and-aft axis of the hanging airframe, in airframe axes.

    The body x axis with its component along the hanging vertical removed: the axis about
    which the hanging airframe rolls under a sideways motion of its carrier.

    Parameters
    ----------
    airframe : Airframe

    Returns
    -------
    numpy.ndarray
        Unit vector, shape (3,). [-]
    """
    k = hanging_vertical(airframe)
    x = np.array([1.0, 0.0, 0.0]) - k[0] * k
    return x / np.linalg.norm(x)

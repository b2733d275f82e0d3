"""The load cases as point loads for a finite-element model, in the model's axes.

What a stress team needs to apply the loads analysis's cases to its own finite-element model
(:mod:`slingloads.io.loads.nastran` writes it as Nastran bulk data):

* the **load points** where the applied loads enter the airframe: rotor hub, mast feet,
  aerodynamic points on the loads reference axis, fin centre of pressure, parachute
  attachment; and the **mass items** (mass, own inertia, position);
* per case, the **applied** forces and moments at the load points (hook, fuselage
  aerodynamics, fin, parachute; gravity is not among them);
* the **gravity** vector, along the attitude's downward vertical
  (:mod:`slingloads.models.attitude`), and per case its own gravity (the same vector, except
  in a towed case, which flies its trimmed attitude:
  :meth:`slingloads.analyses.loads.LoadsStudy.case_verticals`); and per case the
  **rigid-body accelerations** of the
  inertia relief (:mod:`slingloads.analyses.inertia_relief`): the CG's linear acceleration
  and the angular acceleration.

Applied loads, gravity on every mass item and the inertia loads
``-m_j (a + alpha x (r_j - r_cg))``, ``-I_j alpha`` are in equilibrium in every case: the
free-free body of ``docs/conventions.md``, section 6.

Model axes (:class:`ModelAxes`): a point of the project's airframe axes (x aft, y right, z up,
origin at the airframe datum) lies in the model's axes at ``r_model = offset + R r_project``;
a vector (force, moment, acceleration) is ``R v``, an inertia tensor ``R I R^T``, with R a
proper rotation (orthonormal, determinant +1: a mirror would turn right-handed moments into
left-handed ones). SI throughout.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

import numpy as np

from slingloads.constants import G0
from slingloads.errors import InputError

#: How far R R^T may depart from the identity (and det R from 1) for R to count as a rotation.
ROTATION_TOLERANCE = 1e-9
#: Where the hook load is applied: at the mast feet (shared by the rigid-body weighted rule,
#: as the loads analysis does) or as one force at the rotor hub.
HOOK_POINTS = ("mast feet", "hub")

_AXIS_TOKEN = re.compile(r"^([+-]?)([xyz])$")


@dataclass(frozen=True)
class ModelAxes:
    """Axes of the user's finite-element model relative to the project's airframe axes.

    Parameters
    ----------
    rotation : array_like, shape (3, 3), or str
        R, whose rows are the model's X, Y, Z axes written in project axes, so that a vector
        is ``R v`` in model axes; or a text of three signed project axes naming, in order,
        the directions of the model's X, Y and Z: ``"x, y, z"`` (the default: the same axes),
        ``"-x, y, -z"`` (X forward, Y right, Z down). Must be a proper rotation. [-]
    offset : array_like, shape (3,)
        Position of the project's origin (the airframe datum) in model axes. [m]

    Raises
    ------
    InputError
        If the text is not three signed axes, R is not a proper rotation to
        :data:`ROTATION_TOLERANCE`, or the offset is not three finite numbers.

    Examples
    --------
    >>> axes = ModelAxes("-x, y, -z", offset=(1.0, 0.0, 0.0))
    >>> axes.points([[2.0, 0.5, 1.0]]).tolist()
    [[-1.0, 0.5, -1.0]]
    """

    rotation: object = "x, y, z"
    offset: object = (0.0, 0.0, 0.0)

    def __post_init__(self):
        rotation = self.rotation
        if isinstance(rotation, str):
            rotation = axis_map_from_text(rotation)
        matrix = np.asarray(rotation, dtype=float)
        check_rotation(matrix)
        try:
            offset = np.asarray(self.offset, dtype=float).reshape(3)
        except (TypeError, ValueError):
            raise InputError("the model-axes offset must be three numbers (x, y, z) [m]",
                             self.offset) from None
        if not np.all(np.isfinite(offset)):
            raise InputError("the model-axes offset must be finite (x, y, z) [m]",
                             offset.tolist())
        object.__setattr__(self, "rotation", matrix)
        object.__setattr__(self, "offset", offset)

    @property
    def is_identity(self):
        """True when the model's axes are the project's (R = I, no offset)."""
        return bool(np.array_equal(self.rotation, np.eye(3)) and not self.offset.any())

    def points(self, positions):
        """Positions in model axes, ``offset + R r``.

        Parameters
        ----------
        positions : array_like, shape (..., 3)
            Project axes. [m]

        Returns
        -------
        ndarray, shape (..., 3)
            [m]
        """
        return self.offset + np.asarray(positions, float) @ self.rotation.T

    def vectors(self, vectors):
        """Vectors (forces, moments, accelerations) in model axes, ``R v``.

        Parameters
        ----------
        vectors : array_like, shape (..., 3)
            Project axes, any unit. [any unit]

        Returns
        -------
        ndarray, shape (..., 3)
            Model components. [unit of ``vectors``]
        """
        return np.asarray(vectors, float) @ self.rotation.T

    def tensors(self, tensors):
        """Second-order tensors (inertias) in model axes, ``R I R^T``.

        Parameters
        ----------
        tensors : array_like, shape (..., 3, 3)
            Project axes, e.g. [kg m^2].

        Returns
        -------
        ndarray, shape (..., 3, 3)
            Model components. [unit of ``tensors``]
        """
        return self.rotation @ np.asarray(tensors, float) @ self.rotation.T

    def describe(self):
        """The map in words: each model axis as a combination of project axes.

        Returns
        -------
        str
        """
        return "; ".join(f"model {name} = {_combination(row)}"
                         for name, row in zip("XYZ", self.rotation, strict=True))


def axis_map_from_text(text):
    """R from three signed project axes naming the model's X, Y, Z (``"-x, y, -z"``).

    Separators may be commas, semicolons or spaces; case is ignored. The result is checked
    as a rotation by :class:`ModelAxes`, not here.

    Parameters
    ----------
    text : str
        Three signed axis letters.

    Returns
    -------
    ndarray, shape (3, 3)
        Rows: the model's X, Y, Z in project axes. [-]

    Raises
    ------
    InputError
        If the text is not three signed axis letters.
    """
    tokens = [t for t in re.split(r"[\s,;]+", str(text).strip().lower()) if t]
    rows = []
    for token in tokens:
        match = _AXIS_TOKEN.match(token)
        if match is None:
            break
        row = np.zeros(3)
        row["xyz".index(match.group(2))] = -1.0 if match.group(1) == "-" else 1.0
        rows.append(row)
    if len(tokens) != 3 or len(rows) != 3:
        raise InputError("the model axes must be three signed project axes naming the "
                         "model's X, Y and Z in order, e.g. 'x, y, z' or '-x, y, -z'", text)
    return np.array(rows)


def check_rotation(matrix):
    """Raise :class:`InputError` unless ``matrix`` is a proper rotation (R R^T = I, det +1).

    Parameters
    ----------
    matrix : array_like, shape (3, 3)
        Candidate rotation. [-]
    """
    m = np.asarray(matrix, dtype=float)
    if m.shape != (3, 3) or not np.all(np.isfinite(m)):
        raise InputError("the axis map must be a 3 x 3 matrix of finite numbers",
                         np.asarray(matrix).tolist())
    error = np.abs(m @ m.T - np.eye(3)).max()
    det = float(np.linalg.det(m))
    if error > ROTATION_TOLERANCE or abs(det - 1.0) > ROTATION_TOLERANCE:
        what = ("a mirror (determinant -1): it would turn right-handed moments into "
                "left-handed ones" if abs(det + 1.0) <= ROTATION_TOLERANCE else
                f"not orthonormal (largest |R R^T - I| = {error:.3g}, det = {det:.6g})")
        raise InputError(f"the axis map must be a rotation (orthonormal with determinant +1, "
                         f"to {ROTATION_TOLERANCE:g}); this one is {what}", m.tolist())


def _combination(row):
    terms = [f"{'-' if v < 0 else '+'}{abs(v):.6g} {axis}" if abs(v) != 1 else
             f"{'-' if v < 0 else '+'}{axis}" for v, axis in zip(row, "xyz", strict=True)
             if v != 0]
    return " ".join(terms).lstrip("+")


@dataclass(frozen=True)
class PointLoadCases:
    """Every load case as point loads, mass items, gravity and rigid-body accelerations.

    All positions and vectors are in the axes :attr:`axes` (the project's unless mapped by
    :meth:`in_model_axes`). SI.

    Attributes
    ----------
    case_ids, descriptions : tuple of str
        Per case.
    point_ids, point_kinds : tuple of str
        Per load point: its name and kind (``rotor hub``, ``mast foot``, ``aero point``,
        ``fin centre of pressure``, ``parachute attachment``).
    point_positions : ndarray, shape (p, 3)
        [m]
    forces, moments : ndarray, shape (c, p, 3)
        Applied loads at the load points (no gravity). [N], [N m]
    mass_ids, mass_descriptions : tuple of str
    masses : ndarray, shape (n,)
        [kg]
    mass_positions : ndarray, shape (n, 3)
        [m]
    inertias : ndarray, shape (n, 3, 3)
        Own inertia tensor of each item about its own CG. [kg m^2]
    gravity : ndarray, shape (3,)
        Gravitational acceleration of the study's attitude, ``-g0 k``. [m/s^2]
    case_gravity : ndarray, shape (c, 3)
        Gravitational acceleration of each case: ``gravity``, or that of the trimmed attitude
        of a towed case. [m/s^2]
    linear_acceleration, angular_acceleration : ndarray, shape (c, 3)
        Inertia-relief acceleration of the CG and angular acceleration. [m/s^2], [rad/s^2]
    cg : ndarray, shape (3,)
        Centre of gravity of the mass items. [m]
    axes : ModelAxes
        The map from project axes that these values have been through.
    hook_at : str
        Where the hook load is applied (:data:`HOOK_POINTS`).
    """

    case_ids: tuple
    descriptions: tuple
    point_ids: tuple
    point_kinds: tuple
    point_positions: np.ndarray
    forces: np.ndarray
    moments: np.ndarray
    mass_ids: tuple
    mass_descriptions: tuple
    masses: np.ndarray
    mass_positions: np.ndarray
    inertias: np.ndarray
    gravity: np.ndarray
    case_gravity: np.ndarray
    linear_acceleration: np.ndarray
    angular_acceleration: np.ndarray
    cg: np.ndarray
    axes: ModelAxes = ModelAxes()
    hook_at: str = "mast feet"

    @classmethod
    def from_result(cls, result, hook_at="mast feet"):
        """The point loads of a :class:`~slingloads.analyses.loads.LoadsResult`.

        Parameters
        ----------
        result : LoadsResult
        hook_at : str
            ``"mast feet"`` (default: the hook load shared among the feet by the rigid-body
            weighted rule, as the loads analysis applies it) or ``"hub"`` (one force at the
            rotor hub, for a model whose mast carries it to the deck). Both have the same
            resultant force and moment.

        Returns
        -------
        PointLoadCases
            In project axes.

        Raises
        ------
        InputError
            If ``hook_at`` is not one of :data:`HOOK_POINTS`.
        """
        if hook_at not in HOOK_POINTS:
            raise InputError(f"{hook_at=!r} is not valid; valid are {list(HOOK_POINTS)}",
                             hook_at)
        study, cases = result.study, result.cases
        airframe = study.airframe
        items, hp = airframe.mass_items, airframe.hardpoints
        positions, forces, moments = study.applied_loads(cases)
        n, k = len(items.mass), len(hp.mast_feet)
        # the applied loads without gravity (the first n rows), the hub in front
        positions = np.concatenate([hp.hub[None, :], positions[n:]])
        forces = np.concatenate([np.zeros((len(cases), 1, 3)), forces[:, n:]], axis=1)
        moments = np.concatenate([np.zeros((len(cases), 1, 3)), moments[:, n:]], axis=1)
        if hook_at == "hub":
            external = forces[:, 1 + k:].sum(axis=1)
            forces[:, 0] = study.hook_forces(cases, external)
            forces[:, 1:1 + k] = 0.0
            moments[:, 1:1 + k] = 0.0
        ids, kinds = _load_point_names(study)
        return cls(
            case_ids=tuple(str(c) for c in cases["case"]),
            descriptions=tuple(str(d) for d in cases["description"]),
            point_ids=ids, point_kinds=kinds, point_positions=positions,
            forces=forces, moments=moments,
            mass_ids=tuple(items.ids), mass_descriptions=tuple(items.description),
            masses=items.mass.copy(), mass_positions=items.position.copy(),
            inertias=items.inertia.copy(), gravity=study.attitude_used.gravity,
            case_gravity=-G0 * study.case_verticals(cases),
            linear_acceleration=np.asarray(result.linear_acceleration, float),
            angular_acceleration=np.asarray(result.angular_acceleration, float),
            cg=items.cg, hook_at=hook_at)

    def in_model_axes(self, axes):
        """These loads in the model's axes.

        Only from project axes: mapping twice would compose the maps silently, so it is
        refused.

        Parameters
        ----------
        axes : ModelAxes or dict
            The map, or the arguments of :class:`ModelAxes`.

        Returns
        -------
        PointLoadCases
            Positions [m], forces [N], moments [N m], inertias [kg m^2] and accelerations
            [m/s^2, rad/s^2] in model axes.

        Raises
        ------
        InputError
            If these loads are already in model axes.
        """
        if not isinstance(axes, ModelAxes):
            axes = ModelAxes(**axes)
        if not self.axes.is_identity:
            raise InputError("these point loads are already in model axes; map the project's "
                             "loads once")
        return replace(
            self, point_positions=axes.points(self.point_positions),
            forces=axes.vectors(self.forces), moments=axes.vectors(self.moments),
            mass_positions=axes.points(self.mass_positions),
            inertias=axes.tensors(self.inertias), gravity=axes.vectors(self.gravity),
            case_gravity=axes.vectors(self.case_gravity),
            linear_acceleration=axes.vectors(self.linear_acceleration),
            angular_acceleration=axes.vectors(self.angular_acceleration),
            cg=axes.points(self.cg), axes=axes)

    @property
    def n_cases(self):
        """Number of load cases."""
        return len(self.case_ids)


def _load_point_names(study):
    """Names and kinds of the load points, in the order of :meth:`from_result`."""
    airframe = study.airframe
    hp = airframe.hardpoints
    ids = ["rotor hub", *hp.mast_feet_ids]
    kinds = ["rotor hub", *("mast foot",) * len(hp.mast_feet_ids)]
    for i, x in enumerate(airframe.aero_points):
        ids.append(f"aero point {i + 1} (x = {x:.4g} m)")
        kinds.append("aero point")
    if study.fin is not None:
        ids.append("fin centre of pressure")
        kinds.append("fin centre of pressure")
    if study.parachute is not None:
        ids.append("parachute attachment")
        kinds.append("parachute attachment")
    return tuple(ids), tuple(kinds)

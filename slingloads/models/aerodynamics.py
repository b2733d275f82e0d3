"""Fuselage and vertical-fin aerodynamics in airframe axes, from tables in declared axes.

Angles follow the flight-mechanics convention: angle of attack ``alpha`` positive nose up,
sideslip ``beta`` positive with the wind coming from the right. Each table **declares its
axes**; its coefficients are interpolated in that frame (where the table is linear between its
breakpoints) and converted by one function, at the angles of the query, to force and moment
coefficients in airframe axes (x aft, y right, z up; ``docs/conventions.md``, section 3).
Converting on the breakpoints instead and interpolating the airframe-axes values would turn
the frame's rotation into a chord between breakpoints: exact on a fine grid, wrong on a coarse
one (a constant drag tabulated at beta = -180 and 180 deg would point backwards at 0).

Flight-mechanics frames, given by their unit vectors in airframe axes (body frame B: x
forward, y right, z down, so ``x_B = (-1, 0, 0)``, ``y_B = (0, 1, 0)``, ``z_B = (0, 0, -1)``):

* stability S (B turned by alpha about y_B):
  ``x_S = (-cos a, 0, -sin a)``, ``y_S = y_B``, ``z_S = (sin a, 0, -cos a)``;
* wind W (S turned by beta about z_S; x_W along the flight velocity relative to the air):
  ``x_W = (-cos a cos b, sin b, -sin a cos b)``, ``y_W = (cos a sin b, cos b, sin a sin b)``,
  ``z_W = z_S``.

Force coefficients by declared axes (``FORCE_AXES``):

* ``"wind"``: ``CD`` drag along the airflow (-x_W), ``CY`` side force along y_W, ``CL`` lift
  along -z_W (normal to the airflow in the x-z plane, up): ``F = q S (-CD x_W + CY y_W - CL z_W)``;
* ``"stability"``: ``CD`` along -x_S (the airflow's projection on the plane of symmetry),
  ``CY`` along y_B, ``CL`` along -z_S: ``F = q S (-CD x_S + CY y_S - CL z_S)``;
* ``"body"``: ``CX, CY, CZ`` along x_B (forward), y_B (right), z_B (down):
  ``F = q S (CX x_B + CY y_B + CZ z_B)``.

Moment coefficients ``Cl, Cm, Cn`` about the axes of the declared moment frame
(``MOMENT_AXES``: ``"body"``, ``"stability"`` or ``"wind"``), right-handed in that frame (so Cl
positive right side down, Cm nose up, Cn nose right in body axes):
``M = q S L (Cl x_F + Cm y_F + Cn z_F)``. In airframe axes the body-axes moment is
``q S L (-Cl, Cm, -Cn)``.

With these, a directionally stable body has dCn/dbeta > 0. A fin's table is against sideslip
only: it is taken at zero angle of attack, where the stability and body frames coincide.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import positive
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D

#: Force-coefficient columns of a table in each declared force frame.
FORCE_AXES = {"wind": ("CD", "CY", "CL"), "stability": ("CD", "CY", "CL"),
              "body": ("CX", "CY", "CZ")}
#: Frames the moment coefficients ``Cl, Cm, Cn`` may be given in.
MOMENT_AXES = ("body", "stability", "wind")
#: Moment-coefficient columns.
MOMENT_COLUMNS = ("Cl", "Cm", "Cn")
#: Columns of a fuselage table in the default axes (forces in wind axes, moments in body axes).
FUSELAGE_COEFFICIENTS = FORCE_AXES["wind"] + MOMENT_COLUMNS
#: Frames a fin table may be given in (its side-force column ``CY``).
FIN_AXES = ("body", "wind")
#: Names of the airframe-axes coefficients (force x, y, z; moment x, y, z).
AIRFRAME_COLUMNS = ("CFx", "CFy", "CFz", "CMx", "CMy", "CMz")
#: Integer codes of the frames, for the compiled kernels of the multibody model.
FRAME_CODES = {"body": 0, "stability": 1, "wind": 2}
#: Signs of the force columns along the frame's (x, y, z) axes: drag and lift oppose x and z.
_FORCE_SIGNS = {"wind": (-1.0, 1.0, -1.0), "stability": (-1.0, 1.0, -1.0),
                "body": (1.0, 1.0, 1.0)}


def fuselage_columns(force_axes="wind"):
    """Columns a fuselage table needs with forces in ``force_axes``.

    Parameters
    ----------
    force_axes : {"wind", "stability", "body"}
        Axes of the table's force coefficients.

    Returns
    -------
    tuple of str
        Force then moment coefficient names, e.g. CD, CY, CL, Cl, Cm, Cn.
    """
    _check_choice(force_axes, FORCE_AXES, "force axes")
    return FORCE_AXES[force_axes] + MOMENT_COLUMNS


def _check_choice(value, valid, what):
    if value not in valid:
        raise InputError(f"aerodynamic {what} must be one of {list(valid)}", value)


def frame_axes(axes, alpha, beta):
    """Unit vectors of a flight-mechanics frame in airframe axes.

    Parameters
    ----------
    axes : str
        ``"body"``, ``"stability"`` or ``"wind"``.
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ``out[..., i, :]`` is the frame's i-th axis (x, y, z) in airframe axes. [-]
    """
    _check_choice(axes, MOMENT_AXES, "axes")
    a, b = np.broadcast_arrays(np.asarray(alpha, float), np.asarray(beta, float))
    ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    zero, one = np.zeros_like(a), np.ones_like(a)
    if axes == "body":
        rows = [(-one, zero, zero), (zero, one, zero), (zero, zero, -one)]
    elif axes == "stability":
        rows = [(-ca, zero, -sa), (zero, one, zero), (sa, zero, -ca)]
    else:
        rows = [(-ca * cb, sb, -sa * cb), (ca * sb, cb, sa * sb), (sa, zero, -ca)]
    return np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)


def force_to_airframe(coefficients, alpha, beta, axes="wind"):
    """Force coefficients of a declared frame as airframe-axes coefficients.

    Parameters
    ----------
    coefficients : array_like, shape (..., 3)
        (CD, CY, CL) for ``wind`` and ``stability``, (CX, CY, CZ) for ``body``. [-]
    alpha, beta : array_like
        [rad]
    axes : str

    Returns
    -------
    ndarray, shape (..., 3)
        Force over q S along airframe x (aft), y (right), z (up). [-]
    """
    _check_choice(axes, FORCE_AXES, "force axes")
    c = np.asarray(coefficients, float) * np.array(_FORCE_SIGNS[axes])
    return np.einsum("...i,...ij->...j", c, frame_axes(axes, alpha, beta))


def force_from_airframe(coefficients, alpha, beta, axes="wind"):
    """Inverse of :func:`force_to_airframe` (the frames are orthonormal).

    Parameters
    ----------
    coefficients : array_like, shape (..., 3)
        Force over q S along airframe x, y, z. [-]
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]
    axes : {"wind", "stability", "body"}
        The declared frame.

    Returns
    -------
    ndarray, shape (..., 3)
        (CD, CY, CL) for ``wind`` and ``stability``, (CX, CY, CZ) for ``body``. [-]
    """
    _check_choice(axes, FORCE_AXES, "force axes")
    c = np.einsum("...ij,...j->...i", frame_axes(axes, alpha, beta),
                  np.asarray(coefficients, float))
    return c * np.array(_FORCE_SIGNS[axes])


def moment_to_airframe(coefficients, alpha, beta, axes="body"):
    """Moment coefficients (Cl, Cm, Cn) about a declared frame's axes as airframe-axes ones.

    Parameters
    ----------
    coefficients : array_like, shape (..., 3)
        (Cl, Cm, Cn) about the declared frame's axes. [-]
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]
    axes : {"body", "stability", "wind"}
        The declared frame.

    Returns
    -------
    ndarray, shape (..., 3)
        Moment over q S L about airframe x, y, z (right-handed). [-]
    """
    return np.einsum("...i,...ij->...j", np.asarray(coefficients, float),
                     frame_axes(axes, alpha, beta))


def moment_from_airframe(coefficients, alpha, beta, axes="body"):
    """Inverse of :func:`moment_to_airframe`.

    Parameters
    ----------
    coefficients : array_like, shape (..., 3)
        Moment over q S L about airframe x, y, z. [-]
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]
    axes : {"body", "stability", "wind"}
        The declared frame.

    Returns
    -------
    ndarray, shape (..., 3)
        (Cl, Cm, Cn) about the declared frame's axes. [-]
    """
    return np.einsum("...ij,...j->...i", frame_axes(axes, alpha, beta),
                     np.asarray(coefficients, float))


def airflow_direction(alpha, beta):
    """Unit vector along which the relative wind blows past the airframe, airframe axes.

    Parameters
    ----------
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]

    Returns
    -------
    ndarray, shape (..., 3)
        Drag direction ``-x_W = (cos a cos b, -sin b, sin a cos b)``. [-]
    """
    return -frame_axes("wind", alpha, beta)[..., 0, :]


def lift_direction(alpha):
    """Unit vector of lift (normal to the airflow in the x-z plane, upwards), ``-z_S``.

    Parameters
    ----------
    alpha : array_like
        Angle of attack. [rad]

    Returns
    -------
    ndarray, shape (..., 3)
        Airframe axes. [-]
    """
    return -frame_axes("stability", alpha, 0.0)[..., 2, :]


def _positive(value, name, unit):
    return positive(value, f"{name} must be > 0 [{unit}]")


@dataclass(frozen=True)
class FuselageAero:
    """Fuselage aerodynamic coefficients with their reference quantities and axes.

    Parameters
    ----------
    table : Table2D
        Coefficients over alpha and beta: the force columns of ``force_axes``
        (``CD, CY, CL`` or ``CX, CY, CZ``) and ``Cl, Cm, Cn``.
    area : float
        Reference area S. [m^2]
    length : float
        Reference length L. [m]
    moment_reference : array_like, shape (3,)
        Point about which the moment coefficients are given. [m]
    force_axes : str
        Frame of the force coefficients: ``"wind"`` (default), ``"stability"`` or ``"body"``.
    moment_axes : str
        Frame of the moment coefficients: ``"body"`` (default), ``"stability"`` or ``"wind"``.
    """

    table: Table2D
    area: float
    length: float
    moment_reference: np.ndarray
    force_axes: str = "wind"
    moment_axes: str = "body"

    def __post_init__(self):
        _check_choice(self.force_axes, FORCE_AXES, "force axes")
        _check_choice(self.moment_axes, MOMENT_AXES, "moment axes")
        columns = fuselage_columns(self.force_axes)
        missing = [c for c in columns if c not in self.table.coefficients]
        if missing:
            raise InputError(f"fuselage table lacks coefficients {missing}; with forces in "
                             f"{self.force_axes} axes it needs {list(columns)}")
        object.__setattr__(self, "area", _positive(self.area, "fuselage reference area",
                                                   "m^2"))
        object.__setattr__(self, "length", _positive(self.length,
                                                     "fuselage reference length", "m"))
        object.__setattr__(self, "moment_reference",
                           np.asarray(self.moment_reference, float).reshape(3))

    @property
    def columns(self):
        """The table's own coefficient columns, in its declared axes."""
        return fuselage_columns(self.force_axes)

    def coefficients(self, alpha, beta):
        """The table's own coefficients (declared axes), stacked on the last axis in the
        order of :attr:`columns`.

        Parameters
        ----------
        alpha, beta : array_like
            Angle of attack and sideslip. [rad]

        Returns
        -------
        ndarray, shape (..., 6)
            [-]
        """
        return np.stack([self.table(c, alpha, beta) for c in self.columns], axis=-1)

    def airframe_coefficients(self, alpha, beta):
        """Airframe-axes coefficients ``CFx, CFy, CFz, CMx, CMy, CMz``: the table
        interpolated in its declared frames, converted at these angles; an error outside the table
        (no extrapolation).

        Parameters
        ----------
        alpha, beta : array_like
            Angle of attack and sideslip. [rad]

        Returns
        -------
        ndarray, shape (..., 6)
            Forces over q S, moments over q S L about :attr:`moment_reference`. [-]
        """
        own = self.coefficients(alpha, beta)
        force = force_to_airframe(own[..., :3], alpha, beta, self.force_axes)
        moment = moment_to_airframe(own[..., 3:], alpha, beta, self.moment_axes)
        return np.concatenate([force, moment], axis=-1)

    def drag_coefficient(self, alpha, beta):
        """Force coefficient along the airflow (the wind-axes CD), whatever the table's axes.

        Parameters
        ----------
        alpha, beta : array_like
            Angle of attack and sideslip. [rad]

        Returns
        -------
        ndarray
            CD. [-]
        """
        c = self.airframe_coefficients(alpha, beta)[..., :3]
        return np.einsum("...i,...i->...", c, airflow_direction(alpha, beta))

    def loads(self, alpha, beta, q):
        """Resultant force and moment about :attr:`moment_reference`, airframe axes.

        Parameters
        ----------
        alpha, beta : array_like, shape (n,)
            [rad]
        q : float or array_like
            Dynamic pressure. [Pa]

        Returns
        -------
        force : ndarray, shape (n, 3)
            [N]
        moment : ndarray, shape (n, 3)
            [N m]
        """
        c = self.airframe_coefficients(alpha, beta)
        qs = np.asarray(q, float)[..., None] * self.area
        return qs * c[..., :3], qs * self.length * c[..., 3:]


@dataclass(frozen=True)
class Fin:
    """Vertical fin: side force at its centre of pressure.

    Parameters
    ----------
    table : Table1D
        Side-force coefficient ``CY`` against sideslip, on the intact fin's area (negative for
        positive beta on a stabilising fin).
    area : float
        Fin reference area. [m^2]
    centre_of_pressure : array_like, shape (3,)
        Where the side force acts. [m]
    efficiency : float
        Share of the intact fin's side force that the (cut-down) fin keeps, 0 < eta <= 1.
        The paper's transport configuration keeps about 0.5. [-]
    axes : str
        Frame of ``CY`` (the table is at zero angle of attack): ``"body"`` (default, along
        +y, normal to the fin's plane) or ``"wind"`` (along y_W = (sin b, cos b, 0), normal to
        the airflow).
    """

    table: Table1D
    area: float
    centre_of_pressure: np.ndarray
    efficiency: float = 0.5
    axes: str = "body"

    def __post_init__(self):
        if "CY" not in self.table.coefficients:
            raise InputError("fin table needs a CY column")
        _check_choice(self.axes, FIN_AXES, "fin axes")
        object.__setattr__(self, "area", _positive(self.area, "fin area", "m^2"))
        eta = float(self.efficiency)
        if not (0 < eta <= 1):
            raise InputError("fin efficiency must lie in (0, 1]", eta)
        object.__setattr__(self, "efficiency", eta)
        object.__setattr__(self, "centre_of_pressure",
                           np.asarray(self.centre_of_pressure, float).reshape(3))

    def force_coefficients(self, beta):
        """Airframe-axes force coefficients (CFx, CFy, CFz) on the intact fin area: CY
        interpolated, then converted.

        Parameters
        ----------
        beta : array_like
            Sideslip. [rad]

        Returns
        -------
        ndarray, shape (..., 3)
            [-]
        """
        cy = self.table("CY", beta)
        zero = np.zeros_like(cy)
        return force_to_airframe(np.stack([zero, cy, zero], axis=-1), 0.0, beta, self.axes)

    @property
    def side_force_coefficients(self):
        """(beta grid [rad], airframe-y force coefficient CFy on the intact fin area at the
        breakpoints [-]); exact between them for body axes, a chord for wind axes."""
        beta = self.table.angle
        return beta, self.force_coefficients(beta)[:, 1]

    def side_force(self, beta, q):
        """Fin force along +y.

        Parameters
        ----------
        beta : array_like
            Sideslip. [rad]
        q : array_like
            Dynamic pressure. [Pa]

        Returns
        -------
        ndarray
            [N]
        """
        return self.force(beta, q)[..., 1]

    def force(self, beta, q):
        """Fin force vector in airframe axes.

        Parameters
        ----------
        beta : array_like
            Sideslip. [rad]
        q : array_like
            Dynamic pressure. [Pa]

        Returns
        -------
        ndarray, shape (..., 3)
            [N]
        """
        scale = np.asarray(q, float)[..., None] * self.area * self.efficiency
        return scale * self.force_coefficients(beta)

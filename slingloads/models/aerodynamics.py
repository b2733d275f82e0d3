"""Fuselage and vertical-fin aerodynamics in airframe axes.

Flight-mechanics conventions for the *coefficients* (as the data are usually published):
angle of attack ``alpha`` positive nose up, sideslip ``beta`` positive with the wind coming
from the right; drag ``CD`` along the airflow, side force ``CY`` along +y (right), lift ``CL``
normal to the airflow in the x-z plane, upwards; rolling moment ``Cl`` positive right side
down, pitching moment ``Cm`` positive nose up, yawing moment ``Cn`` positive nose right. With
these, a directionally stable body has dCn/dbeta > 0.

Forces and moments returned here are in airframe axes (x aft, y right, z up), see
``docs/conventions.md``:

.. math::

    F = q S (C_D \\hat d + C_Y \\hat y + C_L \\hat l), \\qquad
    M = q S L (-C_l, C_m, -C_n)

with the airflow direction :math:`\\hat d = (\\cos\\alpha\\cos\\beta, -\\sin\\beta,
\\sin\\alpha\\cos\\beta)` and the lift direction :math:`\\hat l = (-\\sin\\alpha, 0,
\\cos\\alpha)`. (Roll right-side-down and yaw nose-right are negative rotations about +x aft
and +z up, hence the two minus signs.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import positive
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D

FUSELAGE_COEFFICIENTS = ("CD", "CY", "CL", "Cl", "Cm", "Cn")


def airflow_direction(alpha, beta):
    """Unit vector along which the relative wind blows past the airframe, airframe axes.

    Parameters
    ----------
    alpha, beta : array_like
        Angle of attack and sideslip. [rad]

    Returns
    -------
    ndarray, shape (..., 3)
        Drag direction. [-]
    """
    alpha, beta = np.broadcast_arrays(np.asarray(alpha, float), np.asarray(beta, float))
    return np.stack([np.cos(alpha) * np.cos(beta), -np.sin(beta),
                     np.sin(alpha) * np.cos(beta)], axis=-1)


def lift_direction(alpha):
    """Unit vector of lift (normal to the airflow in the x-z plane, upwards). [-]"""
    alpha = np.asarray(alpha, float)
    return np.stack([-np.sin(alpha), np.zeros_like(alpha), np.cos(alpha)], axis=-1)


def _positive(value, name, unit):
    return positive(value, f"{name} must be > 0 [{unit}]")


@dataclass(frozen=True)
class FuselageAero:
    """Fuselage aerodynamic coefficients with their reference quantities.

    Parameters
    ----------
    table : Table2D
        Coefficients ``CD, CY, CL, Cl, Cm, Cn`` over alpha and beta.
    area : float
        Reference area S. [m^2]
    length : float
        Reference length L. [m]
    moment_reference : array_like, shape (3,)
        Point about which the moment coefficients are given. [m]
    """

    table: Table2D
    area: float
    length: float
    moment_reference: np.ndarray

    def __post_init__(self):
        missing = [c for c in FUSELAGE_COEFFICIENTS if c not in self.table.coefficients]
        if missing:
            raise InputError(f"fuselage table lacks coefficients {missing}; it needs "
                             f"{list(FUSELAGE_COEFFICIENTS)}")
        object.__setattr__(self, "area", _positive(self.area, "fuselage reference area",
                                                   "m^2"))
        object.__setattr__(self, "length", _positive(self.length,
                                                     "fuselage reference length", "m"))
        object.__setattr__(self, "moment_reference",
                           np.asarray(self.moment_reference, float).reshape(3))

    def coefficients(self, alpha, beta):
        """All six coefficients at ``alpha``, ``beta`` [rad], stacked on the last axis."""
        return np.stack([self.table(c, alpha, beta) for c in FUSELAGE_COEFFICIENTS], axis=-1)

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
        c = self.coefficients(alpha, beta)
        qs = np.asarray(q, float)[..., None] * self.area
        force = qs * (c[..., 0:1] * airflow_direction(alpha, beta)
                      + c[..., 1:2] * np.array([0.0, 1.0, 0.0])
                      + c[..., 2:3] * lift_direction(alpha))
        moment = qs * self.length * np.stack([-c[..., 3], c[..., 4], -c[..., 5]], axis=-1)
        return force, moment


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
    """

    table: Table1D
    area: float
    centre_of_pressure: np.ndarray
    efficiency: float = 0.5

    def __post_init__(self):
        if "CY" not in self.table.coefficients:
            raise InputError("fin table needs a CY column")
        object.__setattr__(self, "area", _positive(self.area, "fin area", "m^2"))
        eta = float(self.efficiency)
        if not (0 < eta <= 1):
            raise InputError("fin efficiency must lie in (0, 1]", eta)
        object.__setattr__(self, "efficiency", eta)
        object.__setattr__(self, "centre_of_pressure",
                           np.asarray(self.centre_of_pressure, float).reshape(3))

    def side_force(self, beta, q):
        """Fin side force (along +y) [N] at sideslip ``beta`` [rad], dynamic pressure ``q`` [Pa]."""
        return np.asarray(q, float) * self.area * self.efficiency * self.table("CY", beta)

    def force(self, beta, q):
        """Fin force vector in airframe axes, shape (n, 3). [N]"""
        fy = self.side_force(beta, q)
        return np.stack([np.zeros_like(fy), fy, np.zeros_like(fy)], axis=-1)

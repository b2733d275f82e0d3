"""Aerodynamic damping of the lateral swing and roll of the carried helicopter.

The lateral pendulum (:mod:`slingloads.models.pendulum`) takes a linear damping ``c`` of the
lateral speed of one point of the mast and a roll damping ``c_r``. In forward flight at true
airspeed V the fuselage and the fin provide it: a lateral speed v of a surface turns the
relative wind by beta = v / V (v to the right, wind from the right: beta > 0), and its side
force changes by

.. math:: \\Delta Y = q \\frac{\\partial Y}{\\partial\\beta}\\frac{v}{V}
          = -c_i\\, v, \\qquad c_i = -\\tfrac12 \\rho V \\frac{\\partial (Y/q)}{\\partial\\beta}

(quasi-steady; :math:`\\partial (Y/q)/\\partial\\beta` is S CY_beta for the fuselage, with its
drag's share, and S_fin eta CY_beta for the fin, both negative, so c_i > 0). Each acts at a
height along the mast: the fin at its centre of pressure; the fuselage where its side force
and rolling moment about the moment reference put it, :math:`z = -\\partial M_x/\\partial
Y`. A roll rate moves a point at height h sideways at -h theta2', so the same dampers damp
roll. Two dampers c_i at distances d_i below the hub are reproduced exactly, at linear
order, by one damper c = sum c_i at d = sum c_i d_i / c plus a roll damping
c_r = sum c_i d_i^2 - c d^2 (>= 0; it does not depend on where the distances are taken from).

**Hover.** With no free stream the linear damping vanishes (c_i is proportional to V): the
only aerodynamic force is the quadratic cross-flow drag of the swinging airframe,
1/2 rho CD S_side |v| v, which at swing speeds of 1 to 2 m/s is of the order of 10 to 100 N
for a light twin (side area about 10 m^2, CD about 1), below 0.5 % of the weight. The
paper's lateral step is in hover: its undamped model is the appropriate (and conservative)
one there; :func:`aerodynamic_damping` returns zero at zero airspeed.

Neglected: the fuselage's own roll-rate derivative (not in the tables), unsteady effects,
the carrier's downwash, the parachute (taken to have no influence, as in the paper).

References
----------
.. [1] B. Etkin, L. D. Reid, "Dynamics of Flight: Stability and Control", 3rd ed., Wiley,
   1996, ch. 5 (quasi-steady derivatives; the fin's contribution to roll damping).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.errors import InputError
from slingloads.models.flight import FlightCondition

#: Sideslip range of the least-squares slopes of the side force and rolling moment. [rad]
DAMPING_FIT_RANGE = (np.radians(-10.0), np.radians(10.0))
#: Where the damping comes from.
DAMPING_SOURCES = ("parameters", "aerodynamic tables")


@dataclass(frozen=True)
class LateralDamping:
    """Linear damping of the lateral pendulum.

    Parameters
    ----------
    lateral : float
        c, damping of the lateral speed of the damped point, >= 0. [N s/m]
    roll : float
        c_r, damping of the roll rate, >= 0. [N m s/rad]
    below_hub : float or None
        d, distance of the damped point below the hub along the mast; ``None``: the CG of
        each body. [m]
    source : str
        "parameters" or "aerodynamic tables".
    parts : tuple of (str, float, float)
        (component, c_i [N s/m], d_i [m]) of the aerodynamic dampers.
    note : str
        Where the values come from (condition, hover).
    """

    lateral: float = 0.0
    roll: float = 0.0
    below_hub: float | None = None
    source: str = "parameters"
    parts: tuple = ()
    note: str = ""

    def __post_init__(self):
        for name, unit in (("lateral", "N s/m"), ("roll", "N m s/rad")):
            value = float(getattr(self, name))
            if not np.isfinite(value) or value < 0:
                raise InputError(f"{name} damping must be >= 0 [{unit}]", value)
            object.__setattr__(self, name, value)
        if self.below_hub is not None and not np.isfinite(float(self.below_hub)):
            raise InputError("damped point below the hub must be finite [m]", self.below_hub)
        if self.source not in DAMPING_SOURCES:
            raise InputError(f"damping source must be one of {list(DAMPING_SOURCES)}",
                             self.source)

    @property
    def off(self):
        """True when there is no damping at all."""
        return self.lateral == 0 and self.roll == 0

    def height_above_cg(self, cg_below_hub):
        """Height h of the damped point above a CG (what
        :class:`~slingloads.models.pendulum.LateralPendulum` takes).

        Parameters
        ----------
        cg_below_hub : float
            Distance of the CG below the hub. [m]

        Returns
        -------
        float
            Height of the damped point above the CG (0 when the dampers give none). [m]
        """
        return 0.0 if self.below_hub is None else float(cg_below_hub) - self.below_hub

    def to_frame(self):
        """The dampers and their sum, unit-labelled columns.

        Returns
        -------
        pandas.DataFrame
            A row per damper and a ``total`` row: lateral damping [N s/m], below hub [m], roll
            damping [N m s/rad], source.
        """
        import pandas as pd  # here: the study reader takes DAMPING_SOURCES alone

        rows = [{"component": name, "lateral damping [N s/m]": c, "below hub [m]": d,
                 "roll damping [N m s/rad]": np.nan} for name, c, d in self.parts]
        rows.append({"component": "total", "lateral damping [N s/m]": self.lateral,
                     "below hub [m]": np.nan if self.below_hub is None else self.below_hub,
                     "roll damping [N m s/rad]": self.roll})
        frame = pd.DataFrame(rows)
        frame["source"] = self.source
        return frame


def combine_dampers(parts):
    """One damper (c, d) plus roll damping c_r equivalent to side-force dampers (c_i, d_i).

    .. math:: c = \\sum c_i, \\quad d = \\frac{\\sum c_i d_i}{c}, \\quad
              c_r = \\sum c_i d_i^2 - c\\,d^2

    Parameters
    ----------
    parts : sequence of (str, float, float)
        (name, c_i [N s/m], d_i [m below the hub]).

    Returns
    -------
    c : float [N s/m]
    d : float or None [m]; None when c = 0
    c_r : float [N m s/rad]
    """
    c = float(sum(ci for _, ci, _ in parts))
    if c <= 0:
        return 0.0, None, 0.0
    d = float(sum(ci * di for _, ci, di in parts)) / c
    roll = float(sum(ci * di * di for _, ci, di in parts)) - c * d * d
    return c, d, max(roll, 0.0)


def aerodynamic_damping(condition, hub, mast_axis, fuselage=None, fin=None,
                        fit_range=DAMPING_FIT_RANGE):
    """Lateral and roll damping of the airframe from its fuselage and fin tables.

    Parameters
    ----------
    condition : FlightCondition
        Airspeed (0: hover, no damping), density, and the trim angle of attack at which the
        fuselage table is read.
    hub : array_like, shape (3,)
        Rotor hub, the suspension point. [m]
    mast_axis : array_like, shape (3,)
        Direction of the mast (airframe +z in the lateral model). [-]
    fuselage : FuselageAero, optional
    fin : Fin, optional
    fit_range : (float, float)
        Sideslip range of the least-squares slopes. [rad]

    Returns
    -------
    LateralDamping
        ``source = "aerodynamic tables"``; its ``parts`` are the fuselage and the fin.

    Raises
    ------
    InputError
        For a condition that is not a FlightCondition or a fit range with too few table
        points.
    """
    from slingloads.models.aero_tables import linear_fit  # pandas: when a damping is made

    if not isinstance(condition, FlightCondition):
        raise InputError("the damping needs a FlightCondition", type(condition).__name__)
    if condition.hover:
        return LateralDamping(0.0, 0.0, None, "aerodynamic tables", (),
                              "hover: no free stream, no linear aerodynamic damping")
    mast = np.asarray(mast_axis, float)
    mast = mast / np.linalg.norm(mast)
    hub = np.asarray(hub, float)
    lo, hi = fit_range
    per_speed = 0.5 * condition.density * condition.tas  # c_i = -per_speed d(Y/q)/dbeta
    parts = []
    if fuselage is not None:
        beta = fuselage.table.beta
        force, moment = fuselage.loads(np.full(beta.shape, condition.alpha), beta, 1.0)
        dy = linear_fit(beta, force[:, 1], lo, hi, "fuselage side-force")[0]
        dmx = linear_fit(beta, moment[:, 0], lo, hi, "fuselage rolling-moment")[0]
        if dy < 0:
            height = -dmx / dy  # above the moment reference: M_x = -z Y
            below = float((hub - fuselage.moment_reference) @ mast) - height
            parts.append(("fuselage", -per_speed * dy, below))
    if fin is not None:
        beta = fin.table.angle
        dy = linear_fit(beta, fin.side_force(beta, 1.0), lo, hi, "fin side-force")[0]
        if dy < 0:
            parts.append(("fin", -per_speed * dy,
                          float((hub - fin.centre_of_pressure) @ mast)))
    c, d, roll = combine_dampers(parts)
    note = (f"{condition.eas:.4g} m/s EAS, {condition.tas:.4g} m/s TAS, "
            f"rho {condition.density:.4g} kg/m^3; slopes over "
            f"[{np.degrees(lo):.3g}, {np.degrees(hi):.3g}] deg")
    return LateralDamping(c, roll, d, "aerodynamic tables", tuple(parts), note)

"""The flight condition shared by every analysis: airspeed, air density, trim angle of attack.

One :class:`FlightCondition` serves the loads (dynamic pressure of the aerodynamic and
parachute loads), the yaw dynamics and parachute sizing (dynamic pressure, true airspeed for
the gust angle and the damping terms, trim angle of attack) and the lateral pendulum
(aerodynamic damping of the swing, zero in hover).

Airspeed is given as **equivalent airspeed** (EAS): the dynamic pressure is
:math:`q = \\tfrac12 \\rho_0 V_{EAS}^2` whatever the altitude, and the true airspeed is
:math:`V = V_{EAS}\\sqrt{\\rho_0/\\rho}`. Where a workbook asks for indicated airspeed (IAS), it
is taken equal to EAS: position and compressibility errors are neglected, which is fair at the
low speeds of sling-load operations (below about 100 kt, Mach below 0.16). Density comes from
the ISA troposphere at the given density altitude (:mod:`slingloads.models.atmosphere`).

References
----------
.. [1] ICAO, "Manual of the ICAO Standard Atmosphere", Doc 7488/3, 1993.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.atmosphere import RHO0, dynamic_pressure_eas, isa_density

#: The paper's loads condition: 100 KEAS, a typical Vne for cargo-hook operations. [m/s]
LOADS_SPEED = 100.0 * KNOT
#: The paper's 1-DOF yaw condition: 80 KIAS at ISA sea level. [m/s]
SIZING_SPEED = 80.0 * KNOT


@dataclass(frozen=True)
class FlightCondition:
    """Airspeed, air density and trim angle of attack of the carried helicopter.

    Parameters
    ----------
    eas : float
        Equivalent airspeed, >= 0 (0 is hover; indicated airspeed is taken equal to it). [m/s]
    density_altitude : float
        Density altitude in the ISA troposphere, -610 m to 11 000 m (the paper: 0, 5000 ft
        and 10 000 ft). [m]
    alpha : float
        Angle of attack of the carried helicopter in trim, at which the fuselage tables are
        read by the yaw analyses. [rad]

    Raises
    ------
    InputError
        For a negative or non-finite airspeed, a non-finite angle, or an altitude outside the
        ISA troposphere model.

    Examples
    --------
    >>> from slingloads.constants import KNOT
    >>> c = FlightCondition(100 * KNOT, density_altitude=3048.0)
    >>> round(c.dynamic_pressure, 1), round(c.tas / KNOT, 2)
    (1621.0, 116.37)
    """

    eas: float = LOADS_SPEED
    density_altitude: float = 0.0
    alpha: float = 0.0

    def __post_init__(self):
        eas = float(self.eas)
        if not np.isfinite(eas) or eas < 0:
            raise InputError("equivalent airspeed must be >= 0 [m/s]", eas, field="eas")
        alpha = float(self.alpha)
        if not np.isfinite(alpha):
            raise InputError("trim angle of attack must be a finite number [rad]", alpha,
                             field="alpha")
        object.__setattr__(self, "eas", eas)
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "density_altitude", float(self.density_altitude))
        try:
            isa_density(self.density_altitude)  # validates the altitude
        except InputError as err:  # the field names the argument, for the io layer
            raise InputError(err.rule, err.value, field="density_altitude") from None

    @property
    def ias(self):
        """Indicated airspeed, taken equal to the equivalent airspeed. [m/s]"""
        return self.eas

    @property
    def hover(self):
        """True at zero airspeed."""
        return self.eas == 0.0

    @property
    def density(self):
        """Air density at the density altitude. [kg/m^3]"""
        return float(isa_density(self.density_altitude))

    @property
    def density_ratio(self):
        """sigma = rho / rho0. [-]"""
        return self.density / RHO0

    @property
    def tas(self):
        """True airspeed V_EAS sqrt(rho0 / rho). [m/s]"""
        return float(self.eas / np.sqrt(self.density_ratio))

    @property
    def dynamic_pressure(self):
        """Free-stream dynamic pressure q = 1/2 rho0 V_EAS^2 = 1/2 rho V^2. [Pa]"""
        return float(dynamic_pressure_eas(self.eas))

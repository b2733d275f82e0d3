"""International Standard Atmosphere (troposphere) and dynamic pressure.

References
----------
.. [1] ICAO, "Manual of the ICAO Standard Atmosphere", Doc 7488/3, 1993.
.. [2] NOAA/NASA/USAF, "U.S. Standard Atmosphere, 1976", NASA-TM-X-74335.
"""

from __future__ import annotations

import numpy as np

from slingloads.constants import G0
from slingloads.errors import InputError

#: Sea-level temperature [K], pressure [Pa], density [kg/m^3].
T0, P0, RHO0 = 288.15, 101325.0, 1.225
#: Specific gas constant of air [J/(kg K)].
R_AIR = 287.05287
#: Temperature lapse rate in the troposphere [K/m].
LAPSE = 0.0065
#: Upper limit of the troposphere model [m].
TROPOPAUSE = 11000.0
_EXPONENT = G0 / (R_AIR * LAPSE)  # 5.25588


def _check_altitude(altitude):
    h = np.asarray(altitude, dtype=float)
    bad = ~np.isfinite(h) | (h < -610.0) | (h > TROPOPAUSE)
    if np.any(bad):
        raise InputError(
            "altitude must lie in the ISA troposphere model's range -610 m to 11000 m",
            np.atleast_1d(h)[np.atleast_1d(bad)][0].item(),
        )
    return h


def isa_temperature(altitude):
    """ISA temperature at a geopotential altitude.

    Parameters
    ----------
    altitude : numeric
        Geopotential altitude, -610 m to 11000 m. [m]

    Returns
    -------
    numeric
        Temperature. [K]

    Raises
    ------
    InputError
        For an altitude outside the troposphere model.
    """
    return T0 - LAPSE * _check_altitude(altitude)


def isa_pressure(altitude):
    """ISA pressure at a geopotential altitude.

    Parameters
    ----------
    altitude : numeric
        Geopotential altitude, -610 m to 11000 m. [m]

    Returns
    -------
    numeric
        Static pressure. [Pa]
    """
    return P0 * (isa_temperature(altitude) / T0) ** _EXPONENT


def isa_density(altitude):
    """ISA density at a geopotential altitude.

    With the ISA temperature, the density altitude equals the pressure altitude, so this
    is also the density at a *density altitude* of ``altitude``:

    .. math:: \\rho = \\rho_0 (1 - L H / T_0)^{g_0/(R L) - 1}

    Parameters
    ----------
    altitude : numeric
        Geopotential (or density) altitude, -610 m to 11000 m. [m]

    Returns
    -------
    numeric
        Air density. [kg/m^3]
    """
    return isa_pressure(altitude) / (R_AIR * isa_temperature(altitude))


def density_altitude(density):
    """Density altitude of air of a given density (inverse of :func:`isa_density`).

    Parameters
    ----------
    density : numeric
        Air density, > 0. [kg/m^3]

    Returns
    -------
    numeric
        Density altitude. [m]

    Raises
    ------
    InputError
        For a density that is not > 0.
    """
    rho = np.asarray(density, dtype=float)
    if np.any(~np.isfinite(rho) | (rho <= 0)):
        raise InputError("density must be > 0", rho.tolist())
    return (T0 / LAPSE) * (1.0 - (rho / RHO0) ** (1.0 / (_EXPONENT - 1.0)))


def dynamic_pressure_eas(eas):
    """Dynamic pressure at an equivalent airspeed: q = 1/2 rho0 V_EAS^2.

    Parameters
    ----------
    eas : numeric
        Equivalent airspeed. [m/s]

    Returns
    -------
    numeric
        Dynamic pressure. [Pa]
    """
    v = np.asarray(eas, dtype=float)
    return 0.5 * RHO0 * v**2


def true_airspeed(eas, altitude):
    """True airspeed from equivalent airspeed at a density altitude.

    Parameters
    ----------
    eas : numeric
        Equivalent airspeed. [m/s]
    altitude : numeric
        Density altitude. [m]

    Returns
    -------
    numeric
        True airspeed, V_EAS sqrt(rho0 / rho). [m/s]
    """
    return np.asarray(eas, dtype=float) * np.sqrt(RHO0 / isa_density(altitude))

"""Verification of the ISA troposphere model (slingloads.models.atmosphere).

Reference: ICAO Doc 7488/3 (Manual of the ICAO Standard Atmosphere) and the U.S. Standard
Atmosphere 1976 below 11 km, as tabulated in the project's reference facts, section 2:

    rho = rho0 (1 - L H / T0)^(g0/(R L) - 1),  g0/(R L) = 5.255880,  L/T0 = 2.25577e-5 /m

| altitude          | rho [kg/m^3] | sigma   |
|-------------------|--------------|---------|
| sea level         | 1.225        | 1       |
| 5000 ft (1524 m)  | 1.05555      | 0.86167 |
| 10000 ft (3048 m) | 0.90464      | 0.73848 |
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.errors import InputError
from slingloads.models.atmosphere import (
    RHO0,
    density_altitude,
    dynamic_pressure_eas,
    isa_density,
    isa_pressure,
    isa_temperature,
)

FT = 0.3048
ISA_TABLE = [  # altitude [m], density [kg/m^3], sigma [-]  (ICAO Doc 7488/3)
    (0.0, 1.225, 1.0),
    (5000 * FT, 1.05555, 0.86167),
    (10000 * FT, 0.90464, 0.73848),
]


@pytest.mark.parametrize(("altitude", "density", "sigma"), ISA_TABLE)
def test_isa_density_matches_published_table(altitude, density, sigma):
    """ISA density and density ratio against the ICAO Doc 7488/3 table (FACTS section 2).

    Hand check at 5000 ft: T = 288.15 - 0.0065 * 1524 = 278.244 K;
    rho = 1.225 * (278.244 / 288.15)^4.25588 = 1.225 * 0.96562^4.25588 = 1.05555 kg/m^3,
    sigma = 1.05555 / 1.225 = 0.86167. Table values carry 5-6 significant digits: rtol 5e-5.
    """
    rho = isa_density(altitude)
    assert_allclose(rho, density, rtol=5e-5)
    assert_allclose(rho / 1.225, sigma, rtol=5e-5)


def test_isa_density_is_vectorised_over_the_table():
    """The same three table values (ICAO Doc 7488/3) come back from one array call."""
    alt = np.array([row[0] for row in ISA_TABLE])
    expected = np.array([row[1] for row in ISA_TABLE])
    assert_allclose(isa_density(alt), expected, rtol=5e-5)


def test_isa_temperature_and_pressure_at_10000_ft():
    """Closed form of the troposphere (FACTS section 2), computed by hand at H = 3048 m.

    T = 288.15 - 0.0065 * 3048 = 268.338 K;
    p = 101325 * (268.338 / 288.15)^5.25588 = 69681.7 Pa (published 69682 Pa);
    rho = p / (R T) = 69681.7 / (287.05287 * 268.338) = 0.90464 kg/m^3.
    """
    assert isa_temperature(3048.0) == pytest.approx(268.338, abs=1e-9)
    assert isa_pressure(3048.0) == pytest.approx(69682.0, rel=5e-5)
    p, t = isa_pressure(3048.0), isa_temperature(3048.0)
    assert p / (287.05287 * t) == pytest.approx(0.90464, rel=5e-5)


@pytest.mark.parametrize(("altitude", "density", "sigma"), ISA_TABLE)
def test_density_altitude_inverts_the_table(altitude, density, sigma):
    """Density altitude of the tabulated densities gives back the table altitude.

    Reference: the inverse in FACTS section 2, Hd = (T0/L) [1 - (rho/rho0)^0.234969],
    T0/L = 44330.8 m. At 5000 ft: 44330.8 * (1 - 0.861673^0.234969) = 1524.0 m.
    drho/dH is about 1.05e-4 kg/m^3 per m there, so the table's 5e-6 rounding of rho is
    worth 0.05 m: atol 0.1 m. The closed form itself is evaluated as a cross-check.
    """
    hand = 44330.8 * (1.0 - (density / 1.225) ** 0.234969)
    assert hand == pytest.approx(altitude, abs=0.2)
    assert density_altitude(density) == pytest.approx(altitude, abs=0.1)


def test_density_altitude_round_trip_over_the_troposphere():
    """Definition computed the other way: density_altitude(isa_density(H)) = H, 0..11 km.

    isa_density goes through p / (R T), whose sea-level value p0 / (R T0) = 1.22500002 kg/m^3
    differs from the published rho0 = 1.225 used by the inverse by 1.5e-8 relative; that is
    worth 0.15 mm of altitude, so atol 1 mm.
    """
    h = np.linspace(-600.0, 11000.0, 59)
    assert_allclose(density_altitude(isa_density(h)), h, atol=1e-3)


def test_density_altitude_rejects_non_positive_density():
    """A density <= 0 has no density altitude: InputError echoing the value."""
    with pytest.raises(InputError, match=r"-0\.5"):
        density_altitude(-0.5)


def test_dynamic_pressure_eas_at_100_kt():
    """q = 1/2 rho0 V_EAS^2 (FACTS section 2), by hand at 100 kt = 51.4444 m/s:

    q = 0.5 * 1.225 * 51.4444^2 = 0.6125 * 2646.53 = 1621.00 Pa.
    """
    assert dynamic_pressure_eas(51.4444) == pytest.approx(1620.997, rel=1e-6)
    assert dynamic_pressure_eas(100 * 1852.0 / 3600.0) == pytest.approx(1621.000, rel=1e-6)
    assert RHO0 == 1.225


def test_dynamic_pressure_eas_is_independent_of_altitude_and_zero_at_rest():
    """Limit case: q(0) = 0; and q scales as V^2 (q(2V) = 4 q(V))."""
    assert dynamic_pressure_eas(0.0) == 0.0
    assert dynamic_pressure_eas(40.0) == pytest.approx(4 * dynamic_pressure_eas(20.0), rel=1e-14)


@pytest.mark.parametrize("altitude", [12000.0, -1000.0, np.nan])
def test_out_of_range_altitude_raises_with_value(altitude):
    """Outside -610 m .. 11000 m the troposphere formula does not apply: InputError, the
    message echoes the offending value (STYLE.md: errors name the value and the rule)."""
    with pytest.raises(InputError, match="altitude") as info:
        isa_density(altitude)
    assert repr(float(altitude)) in str(info.value)


def test_out_of_range_altitude_in_an_array_names_the_bad_element():
    """An array with one bad altitude names that element, not the first one."""
    with pytest.raises(InputError, match=r"value 15000\.0"):
        isa_density(np.array([0.0, 1000.0, 15000.0]))

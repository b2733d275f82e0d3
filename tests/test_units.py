"""Unit strings at the boundary against exact definitions.

References: the international yard and pound agreement (1959): 1 in = 0.0254 m exactly,
1 ft = 0.3048 m, 1 lb = 0.45359237 kg; 1 lbf = 1 lb x g0 with g0 = 9.80665 m/s^2 (NIST SP 811,
appendix B). So 1 in lbf = 0.0254 x 4.4482216152605 N m = 0.112984829027617 N m and
1 ft^2 = 0.09290304 m^2.
"""

import pytest

from slingloads.errors import UnitError
from slingloads.io.common.units import si_factor

LBF = 0.45359237 * 9.80665
IN_LBF = 0.0254 * LBF


@pytest.mark.parametrize("unit, kind, expected", [
    ("in-lb", "moment", IN_LBF),          # US drawings: inch-pounds of moment
    ("lb-in", "moment", IN_LBF),
    ("in*lbf", "moment", IN_LBF),
    ("ft-lbf", "moment", 0.3048 * LBF),
    ("lb", "force", LBF),                 # pound of force where the quantity is a force
    ("lbs", "force", LBF),
    ("lbf", "force", LBF),
    ("lb", "mass", 0.45359237),           # ... and of mass where it is a mass
    ("lbm", "mass", 0.45359237),
    ("lb*in^2", "inertia", 0.45359237 * 0.0254**2),
    ("ft2", "area", 0.3048**2),
    ("in3", "length", None),              # a volume is not a length: refused
])
def test_engineering_spellings(unit, kind, expected):
    if expected is None:
        with pytest.raises(UnitError, match="is not a length"):
            si_factor(unit, kind)
    else:
        assert si_factor(unit, kind) == pytest.approx(expected, rel=1e-14)


def test_negative_exponents_keep_their_sign():
    """A hyphen is a product only between two unit names: kg m s^-2 is a newton."""
    assert si_factor("kg*m*s^-2", "force") == pytest.approx(1.0, rel=1e-15)

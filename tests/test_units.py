"""Unit factors at the boundary: the exact table read without pint against pint itself.

Reference: pint's own definitions (an independent library: its registry parses its
definitions file); the table's factors are the exact definitions of the units (international
foot 0.3048 m, pound 0.45359237 kg, standard gravity 9.80665 m/s^2, knot 1852/3600 m/s), so
the two agree to the rounding of a double. The spellings of US drawings against the
international yard and pound agreement (1959): 1 in = 0.0254 m, 1 ft = 0.3048 m,
1 lb = 0.45359237 kg; 1 lbf = 1 lb x g0, g0 = 9.80665 m/s^2 (NIST SP 811, appendix B).
"""

from __future__ import annotations

import math

import pint
import pytest

from slingloads.errors import UnitError
from slingloads.io.common.units import EXACT_FACTORS, SI_UNITS, si_factor


@pytest.mark.parametrize("kind, unit", sorted(EXACT_FACTORS))
def test_exact_factors_agree_with_pint(kind, unit):
    """Each factor of the table is pint's factor of the same spelling, to 1e-15."""
    registry = pint.UnitRegistry()
    expected = float(registry.Quantity(1.0, unit).to(SI_UNITS[kind]).magnitude)
    assert EXACT_FACTORS[(kind, unit)] == pytest.approx(expected, rel=1e-15)
    assert si_factor(unit, kind) == EXACT_FACTORS[(kind, unit)]


def test_other_spellings_still_go_to_pint():
    """A spelling outside the table (inch, mile per hour) is parsed by pint; a unit of the
    wrong dimension is still refused: 1 mph = 0.44704 m/s exactly (5280 x 0.3048 / 3600)."""
    assert si_factor("inch", "length") == pytest.approx(0.0254, rel=1e-15)
    assert si_factor("mph", "speed") == pytest.approx(0.44704, rel=1e-15)
    assert si_factor("deg", "angle") == pytest.approx(math.pi / 180, rel=1e-15)
    with pytest.raises(UnitError):
        si_factor("kg", "length")


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
    ("Hz", "frequency", 2 * 3.141592653589793),  # a cycle per second is 2 pi rad/s
    ("rpm", "frequency", 2 * 3.141592653589793 / 60),
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


def test_sentences_convert_whole_numbers_and_jerks():
    """A quoted SI quantity in a US sentence is converted whole: 443,995 N m (thousands
    separator) = 443,995 / (4.4482216152605 x 0.0254) = 3,929,687 lbf in, where the last
    group alone used to be converted ("443,8,806 lbf in"); a jerk of 1.94 m/s^3 =
    1.94 / 0.3048 = 6.365 ft/s^3 (was left in SI); SI reports are unchanged."""
    from slingloads.io.common.units import report_text

    text = "tolerance 1e-08 x load scale 443,995 N m; peak jerk <= 1.94 m/s^3"
    assert report_text(text, "US") == ("tolerance 1e-08 x load scale 3,929,687 lbf in; "
                                       "peak jerk <= 6.365 ft/s^3")
    assert report_text(text, "SI") == text
    # a length at a length cell's precision (0.00 in): 1,234.5 / 0.0254 = 48,602.36 in
    assert report_text("cable 1,234.5 m", "US") == f"cable {1234.5 / 0.0254:,.2f} in"

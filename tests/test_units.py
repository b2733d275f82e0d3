"""Unit factors at the boundary: the exact table read without pint against pint itself.

Reference: pint's own definitions (an independent library: its registry parses its
definitions file); the table's factors are the exact definitions of the units (international
foot 0.3048 m, pound 0.45359237 kg, standard gravity 9.80665 m/s^2, knot 1852/3600 m/s), so
the two agree to the rounding of a double.
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

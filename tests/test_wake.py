"""Wake dynamic-pressure ratio, parachute line length and the carrier-cable rule."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad

from slingloads.errors import InputError
from slingloads.models.wake import BluffBodyWake, TabulatedWake, check_cable_length


def test_table_line_length_by_hand():
    """Hand interpolation: ratio 0.9 at 10 m and 1.0 at 20 m reaches 0.95 at 15 m."""
    wake = TabulatedWake([0.0, 10.0, 20.0, 30.0], [0.7, 0.9, 1.0, 1.0])
    assert wake.line_length(0.95) == pytest.approx(15.0)
    assert float(wake(5.0)) == pytest.approx(0.8)


def test_model_centreline_line_length_closed_form():
    """Centreline law u/U = K (CD S)^(1/3) x^(-2/3) with q ratio (1 - u/U)^2 = 0.95 inverts to
    x = (K (CD S)^(1/3) / (1 - sqrt(0.95)))^(3/2) (worked by hand for CD S = 1 m^2, K = 1:
    x = (1 / 0.0253206)^1.5 = 248.2 m)."""
    wake = BluffBodyWake(1.0, coefficient=1.0)
    x = wake.line_length(0.95)
    assert x == pytest.approx((1.0 / (1.0 - np.sqrt(0.95))) ** 1.5, rel=1e-12)
    assert x == pytest.approx(248.2, rel=1e-3)
    assert float(wake(x)) == pytest.approx(0.95, rel=1e-12)


@pytest.mark.parametrize("x", [20.0, 80.0])
def test_model_satisfies_momentum_theorem(x):
    """Momentum theorem for a far wake (small defect): the momentum deficit equals the drag,
    integral of u_d/U over the wake cross-section = CD S / 2 (Schlichting, ch. XXIV)."""
    cds = 1.3
    wake = BluffBodyWake(cds, coefficient=0.8)
    u0, b = wake.centreline_defect(x), wake.half_width(x)
    integral, _ = quad(lambda r: u0 * np.exp(-np.log(2) * r**2 / b**2) * 2 * np.pi * r,
                       0, 20 * b)
    assert integral == pytest.approx(cds / 2, rel=1e-8)


def test_canopy_average_matches_numerical_disc_average():
    """Disc average of (1 - u_d(r)/U)^2 over the canopy, by numerical quadrature."""
    wake = BluffBodyWake(1.0, canopy_area=3.0)
    x = 40.0
    u0, b = wake.centreline_defect(x), wake.half_width(x)
    radius = np.sqrt(3.0 / np.pi)
    num, _ = quad(lambda r: (1 - u0 * np.exp(-np.log(2) * r**2 / b**2)) ** 2 * 2 * np.pi * r,
                  0, radius)
    assert float(wake(x)) == pytest.approx(num / 3.0, rel=1e-10)
    assert wake(x) > BluffBodyWake(1.0)(x)  # averaging over the disc sees less defect
    x95 = wake.line_length(0.95)
    assert float(wake(x95)) == pytest.approx(0.95, abs=1e-9)


def test_cable_rule():
    """Paper section 1/4: the carrier cable at least 20 % longer than the parachute line."""
    assert check_cable_length(12.0, 10.0).ok
    bad = check_cable_length(11.0, 10.0)
    assert not bad.ok
    assert bad.required == pytest.approx(12.0)
    assert "too short" in bad.message and "i.e. >= 12 m;" in bad.message


def test_bad_wake_input():
    """Non-monotonic or invalid tables, queries outside the range and unreachable targets."""
    with pytest.raises(InputError, match="strictly increasing.*5.0"):
        TabulatedWake([0.0, 10.0, 5.0], [0.8, 0.9, 0.95])
    with pytest.raises(InputError, match=r"ratios must lie in \(0, 1.2\].*-0.1"):
        TabulatedWake([0.0, 10.0], [-0.1, 0.9])
    wake = TabulatedWake([0.0, 10.0], [0.8, 0.9])
    with pytest.raises(InputError, match="never reaches the target"):
        wake.line_length(0.95)
    with pytest.raises(InputError, match="outside the wake table's range.*12"):
        wake(12.0)
    with pytest.raises(InputError, match="drag area must be > 0.*-1"):
        BluffBodyWake(-1.0)
    with pytest.raises(InputError, match="far-wake model is valid from"):
        BluffBodyWake(1.0)(0.5)
    with pytest.raises(InputError, match="cable length must be > 0"):
        check_cable_length(0.0, 10.0)
    assert_allclose(wake([0.0, 10.0]), [0.8, 0.9])

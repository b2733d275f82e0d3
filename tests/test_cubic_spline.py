"""The numpy natural cubic spline against scipy's CubicSpline and against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from slingloads.models.cubic_spline import natural_cubic_spline


@pytest.mark.parametrize("n", [2, 3, 4, 11, 400])
def test_matches_scipy_natural_cubic_spline(n):
    """Reference: scipy.interpolate.CubicSpline(x, y, bc_type="natural") (LAPACK's banded
    solve) on unevenly spaced random samples: values, slopes and curvatures inside and
    outside the samples (extrapolated), at the samples themselves, to round-off."""
    rng = np.random.default_rng(n)
    x = np.cumsum(rng.uniform(0.01, 2.0, n)) - 3.0
    y = rng.normal(scale=5.0, size=n)
    reference, spline = CubicSpline(x, y, bc_type="natural"), natural_cubic_spline(x, y)
    at = np.concatenate([np.linspace(x[0] - 1.0, x[-1] + 1.0, 997), x])
    for nu in (0, 1, 2, 3):
        expected = reference.derivative(nu)(at) if nu else reference(at)
        got = spline.derivative(nu)(at) if nu else spline(at)
        scale = max(np.max(np.abs(expected)), 1.0)
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * scale)


def test_two_samples_give_the_straight_line():
    """Closed form: through two points the natural spline is the chord, also extrapolated
    (y = 3 + 2 (x - 1)); its curvature is zero."""
    spline = natural_cubic_spline([1.0, 4.0], [3.0, 9.0])
    at = np.array([-2.0, 1.0, 2.5, 4.0, 7.0])
    np.testing.assert_allclose(spline(at), 3.0 + 2.0 * (at - 1.0), rtol=1e-15)
    np.testing.assert_allclose(spline.derivative(2)(at), 0.0, atol=1e-15)


def test_three_even_samples_closed_form():
    """Closed form: the natural spline through (0, 0), (1, 1), (2, 0) has curvature M = -3
    at the middle sample (from 4 M = 6 (0 - 2 + 0)), zero at the ends, so on [0, 1]
    S(x) = 1.5 x - 0.5 x^3 and S'(0) = 1.5."""
    spline = natural_cubic_spline([0.0, 1.0, 2.0], [0.0, 1.0, 0.0])
    x = np.linspace(0.0, 1.0, 11)
    np.testing.assert_allclose(spline(x), 1.5 * x - 0.5 * x**3, atol=1e-15)
    np.testing.assert_allclose(spline(2.0 - x), 1.5 * x - 0.5 * x**3, atol=1e-15)
    assert spline.derivative(1)(0.0) == pytest.approx(1.5, abs=1e-15)
    assert spline.derivative(2)(1.0) == pytest.approx(-3.0, abs=1e-14)
    np.testing.assert_allclose(spline.derivative(2)([0.0, 2.0]), 0.0, atol=1e-14)


def test_is_twice_continuously_differentiable_at_the_samples():
    """Definition: value, slope and curvature of the pieces meeting at each interior sample
    agree (the left piece evaluated at its end, the right one at its start)."""
    rng = np.random.default_rng(3)
    x = np.cumsum(rng.uniform(0.1, 1.0, 30))
    spline = natural_cubic_spline(x, rng.normal(size=30))
    for nu in (0, 1, 2):
        piece = spline.derivative(nu) if nu else spline
        h = np.diff(x)[:-1]
        left = sum(piece.c[j, :-1] * h ** (piece.c.shape[0] - 1 - j)
                   for j in range(piece.c.shape[0]))
        right = piece.c[-1, 1:]
        np.testing.assert_allclose(left, right, rtol=1e-10, atol=1e-10)

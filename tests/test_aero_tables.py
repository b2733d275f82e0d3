"""The 2-D aerodynamic table's bilinear interpolation against independent references.

References: scipy's ``RegularGridInterpolator`` (linear method), an independent
implementation of the same interpolant; and the closed form that bilinear interpolation
reproduces any function ``a + b x + c y + d x y`` exactly (it is the interpolant's own form
in every cell), worked here by hand on one cell. Outside the grid the table refuses the
query (no extrapolation, ever), with the angle in degrees and the table's range.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import RegularGridInterpolator

from slingloads.errors import InputError
from slingloads.models.aero_tables import Table2D, bilinear


def _grids(rng):
    """A random uneven grid, 2 to 11 breakpoints a side, and values of mixed magnitude."""
    x = np.cumsum(rng.uniform(0.01, 1.0, rng.integers(2, 12))) - 2.0
    y = np.cumsum(rng.uniform(0.01, 1.0, rng.integers(2, 12))) - 3.0
    values = rng.normal(size=(x.size, y.size)) * 10.0 ** rng.uniform(-3, 5)
    return x, y, values


def test_bilinear_matches_scipy_regular_grid_interpolator():
    """On 60 random uneven grids, at random points, at every breakpoint and at the four
    corners, the interpolation agrees with scipy's RegularGridInterpolator (linear) to
    1e-14 of the table's largest value (same formula: in practice to the last bit)."""
    rng = np.random.default_rng(7)
    for _ in range(60):
        x, y, values = _grids(rng)
        xq = np.concatenate([rng.uniform(x[0], x[-1], 200), np.repeat(x, y.size),
                             [x[0], x[0], x[-1], x[-1]]])
        yq = np.concatenate([rng.uniform(y[0], y[-1], 200), np.tile(y, x.size),
                             [y[0], y[-1], y[0], y[-1]]])
        expected = RegularGridInterpolator((x, y), values)(np.stack([xq, yq], axis=-1))
        got = bilinear(x, y, values, xq, yq)
        assert np.allclose(got, expected, rtol=0, atol=1e-14 * np.abs(values).max())


def test_table_reproduces_a_bilinear_function_exactly():
    """f(alpha, beta) = 1 + 2 alpha - 3 beta + 4 alpha beta tabulated on an uneven grid is
    interpolated exactly anywhere inside it. Hand check in the cell alpha in [0.1, 0.3],
    beta in [-0.2, 0.1] at (0.25, 0.0): t = 0.75, u = 2/3; corners f = 1.72, 0.94, 1.96,
    1.42 (at (0.1, -0.2), (0.1, 0.1), (0.3, -0.2), (0.3, 0.1)); 1.72 x 0.25 x 1/3
    + 0.94 x 0.25 x 2/3 + 1.96 x 0.75 x 1/3 + 1.42 x 0.75 x 2/3 = 0.14333 + 0.15667 + 0.49
    + 0.71 = 1.5 = f(0.25, 0)."""
    alpha = np.array([-0.2, 0.1, 0.3, 0.5])
    beta = np.array([-0.2, 0.1, 0.25])
    a, b = np.meshgrid(alpha, beta, indexing="ij")
    table = Table2D(alpha, beta, {"CY": 1 + 2 * a - 3 * b + 4 * a * b})
    assert table("CY", 0.25, 0.0) == pytest.approx(1.5, rel=1e-15)
    rng = np.random.default_rng(3)
    aq, bq = rng.uniform(-0.2, 0.5, (5, 7)), rng.uniform(-0.2, 0.25, (5, 7))
    got = table("CY", aq, bq)
    assert got.shape == (5, 7)
    assert np.allclose(got, 1 + 2 * aq - 3 * bq + 4 * aq * bq, rtol=1e-14, atol=1e-14)


def test_table_refuses_points_outside_the_grid():
    """A query beyond the grid in either angle (or NaN) is an InputError naming the angle in
    degrees and the table's range; round-off beyond an edge (1e-12 rad) is not refused and
    gives the edge value."""
    alpha = np.radians([-10.0, 0.0, 10.0])
    beta = np.radians([-20.0, 0.0, 20.0])
    table = Table2D(alpha, beta, {"CN": np.arange(9.0).reshape(3, 3)})
    with pytest.raises(InputError, match=r"alpha = 10\.5 deg is outside .*\[-10, 10\] deg"):
        table("CN", np.radians(10.5), 0.0)
    with pytest.raises(InputError, match=r"beta = -25 deg is outside .*\[-20, 20\] deg"):
        table("CN", 0.0, np.radians([0.0, -25.0]))
    with pytest.raises(InputError, match="no extrapolation"):
        table("CN", np.nan, 0.0)
    assert table("CN", alpha[-1] + 1e-12, beta[-1]) == pytest.approx(8.0, rel=1e-12)

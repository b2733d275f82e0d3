"""The shared Dormand-Prince 5(4) tableau against independent references.

References: scipy's own RK45 tableau (``scipy.integrate._ivp.rk.RK45``, an independent copy of
Dormand and Prince 1980 with Shampine's dense output), and the order conditions a consistent
Runge-Kutta pair must satisfy: row sums of A equal the nodes c, and the fifth-order weights
(the seventh row of A) sum to 1 while the error weights (fifth minus fourth order) sum to 0.
"""

import numpy as np
from scipy.integrate._ivp.rk import RK45

from slingloads.models import dormand_prince as dp


def test_tableau_is_scipys_rk45():
    assert np.array_equal(dp.A[:6, :5], RK45.A)
    assert np.array_equal(dp.A[6], RK45.B)
    assert np.array_equal(dp.C[:6], RK45.C)
    assert np.array_equal(dp.E, RK45.E)
    assert np.array_equal(dp.P, RK45.P)


def test_order_conditions():
    np.testing.assert_allclose(dp.A.sum(axis=1), dp.C, atol=1e-15)
    assert abs(dp.A[6].sum() - 1.0) < 1e-15
    assert abs(dp.E.sum()) < 1e-15
    # fifth-order quadrature conditions: sum b_i c_i^k = 1 / (k + 1), k = 0..4
    for k in range(5):
        assert abs(dp.A[6] @ dp.C[:6] ** k - 1.0 / (k + 1)) < 1e-14

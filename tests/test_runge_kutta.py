"""The one RK4 step and the one Dormand-Prince pair of the compiled integrators.

References: the stability function of the classical RK4 scheme (Hairer, Norsett, Wanner,
"Solving Ordinary Differential Equations I", section IV.2: one step of y' = lambda y multiplies
y by 1 + z + z^2/2 + z^3/6 + z^4/24, z = h lambda), and scipy's own RK45 (an independent
implementation of the same Dormand-Prince pair: ``scipy.integrate._ivp.rk.rk_step``, its error
norm and its dense output ``RkDenseOutput``).
"""

import numba
import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate._ivp.rk import RK45, RkDenseOutput, rk_step

from slingloads.models import dormand_prince as dp
from slingloads.models.runge_kutta import rk4_stepper


@numba.njit(inline="always")
def _linear(x, drive, i, stage, args, dx):
    """y' = lambda y with lambda = drive[i, stage, 0] (constant over the step here)."""
    for m in range(x.size):
        dx[m] = drive[i, stage, 0] * x[m]
    return 0.0


_step = rk4_stepper(_linear)


@pytest.mark.parametrize("z", [-0.5, -0.1, 0.3, -2.0])
def test_rk4_step_is_the_classical_stability_polynomial(z):
    """One step of y' = lambda y from y = 1 gives the RK4 stability function R(z) exactly
    (to round-off), whatever h and lambda make z."""
    h = 0.25
    lam = z / h
    drive = np.full((1, 3, 1), lam)
    x = np.array([1.0, -3.0])
    k = [np.empty(2) for _ in range(5)]
    k[0][:] = lam * x
    out = np.empty(2)
    _step(x, h, drive, 0, (), *k, out)
    r = 1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24
    assert_allclose(out, r * x, rtol=1e-15)


def _pendulum(t, y):
    return np.array([y[1], -np.sin(y[0]) - 0.1 * y[1]])


def test_dormand_prince_step_error_norm_and_dense_output_are_scipys():
    """A step of the pendulum y'' = -sin y - 0.1 y' by the shared functions (stage arguments,
    error norm, dense output) gives scipy's RK45 step, its error norm and its dense output
    at mid-step to round-off."""
    y, h, rtol, atol = np.array([1.2, -0.4]), 0.3, 1e-6, 1e-8
    f = _pendulum(0.0, y)
    K = np.empty((7, 2))
    K[0] = f
    acc, arg = np.empty(2), np.empty(2)
    for i in range(1, 7):
        dp.stage(y, h, K, i, acc, arg)
        K[i] = _pendulum(dp.C[i] * h, arg)
    y_new = arg.copy()  # the sixth stage's argument is the fifth-order solution
    err = dp.error_norm(y, y_new, K, h, rtol, atol, acc)
    mid = np.empty(2)
    dp.dense(y, K, h, 0.5, np.empty(7), acc, mid)

    K_ref = np.empty((7, 2))
    y_ref, _ = rk_step(_pendulum, 0.0, y, f, h, RK45.A, RK45.B, RK45.C, K_ref)
    scale = atol + np.maximum(np.abs(y), np.abs(y_ref)) * rtol
    err_ref = np.linalg.norm(K_ref.T @ RK45.E * h / scale) / np.sqrt(2)
    mid_ref = RkDenseOutput(0.0, h, y, K_ref.T @ RK45.P)(0.5 * h)
    assert_allclose(y_new, y_ref, rtol=1e-14)
    # the estimate is a difference of two close solutions: summed in another order it
    # differs by round-off magnified by the cancellation (about 1e4 here)
    assert_allclose(err, err_ref, rtol=1e-10)
    assert_allclose(mid, mid_ref, rtol=1e-14)


def test_step_factors_are_scipys():
    """Step-size factors after a rejection and an acceptance: scipy's RK45 rule (safety 0.9,
    exponent -1/5, at least 1/5, at most 10, no growth right after a rejection)."""
    for err in (0.01, 0.5, 1.0):
        assert dp.grow(err, False) == min(10.0, 0.9 * err ** -0.2)
        assert dp.grow(err, True) == min(1.0, min(10.0, 0.9 * err ** -0.2))
    assert dp.grow(0.0, False) == 10.0
    for err in (1.5, 100.0, 1e6):
        assert dp.shrink(err) == max(0.2, 0.9 * err ** -0.2)

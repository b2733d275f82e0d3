"""The shared Dormand-Prince 5(4) tableau against independent references.

References: scipy's own RK45 tableau (``scipy.integrate._ivp.rk.RK45``, an independent copy of
Dormand and Prince 1980 with Shampine's dense output), and the order conditions a consistent
Runge-Kutta pair must satisfy: row sums of A equal the nodes c, and the fifth-order weights
(the seventh row of A) sum to 1 while the error weights (fifth minus fourth order) sum to 0.

The one step loop of the adaptive integrators (:func:`slingloads.models.dormand_prince.
integrator`) against scipy's ``RK45`` class stepped segment by segment (the same steps, the same
dense output), the closed forms of a harmonic oscillator, an exponential decay and growth, and
the stability function of the pair's fifth-order solution.
"""

import numba
import numpy as np
import pytest
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


# ------------------------------------------------------------------ the one step loop


@numba.njit(inline="always")
def _linear(phase, t, s, k, y, args, dx):
    """y' = A y (``args[0]``); at a sample y is kept in row k of ``args[2]``; flag 1 where
    y[0] exceeds the segment's limit ``args[1][s]`` (a model's table range)."""
    a, limit, out = args
    if phase == dp.SAMPLE:
        for m in range(y.size):
            out[k, m] = y[m]
        return 0
    for m in range(y.size):
        acc = 0.0
        for q in range(y.size):
            acc += a[m, q] * y[q]
        dx[m] = acc
    return 1 if y[0] > limit[s] else 0


@numba.njit(inline="always")
def _nothing(x):
    pass


_run = dp.integrator(_linear, _nothing)


def _integrate(a, y0, ends, interval, n_out, *, fixed=0.0, rtol=1e-6, atol=1e-9,
               max_step=np.inf, first_step=1e-3, max_steps=10**6, limits=None, stop=None):
    x = np.array(y0, dtype=float)
    out = np.full((n_out, x.size), np.nan)
    limits = np.full(len(ends), np.inf) if limits is None else np.asarray(limits, float)
    stop = np.zeros(1, dtype=np.int64) if stop is None else stop
    status, flag, t, accepted, sampled = _run(x, np.asarray(ends, float), len(ends),
                                              interval, n_out, fixed, rtol, atol, max_step,
                                              first_step, max_steps, stop,
                                              (np.asarray(a, float), limits, out))
    return status, flag, t, accepted, sampled, x, out


def _scipy(a, y0, ends, interval, n_out, rtol, atol, max_step, first_step):
    """scipy's RK45 stepped segment by segment, each segment started with the step the last
    one ended with, sampled on its dense output."""
    a = np.asarray(a, float)
    out = np.full((n_out, len(y0)), np.nan)
    out[0] = y0
    k, t, y, h, steps = 1, 0.0, np.array(y0, float), first_step, 0
    for b in ends:
        solver = RK45(lambda _, v: a @ v, t, y, b, first_step=min(h, b - t),
                           max_step=max_step, rtol=rtol, atol=atol)
        while solver.status == "running":
            solver.step()
            steps += 1
            dense = solver.dense_output()
            while k < n_out and k * interval <= solver.t + 1e-9 * interval:
                out[k] = dense(k * interval)
                k += 1
        t, y, h = b, solver.y, solver.h_abs
    return out, steps


@pytest.mark.parametrize("max_step", [np.inf, 0.3])
def test_loop_is_scipys_rk45_segment_by_segment(max_step):
    """A harmonic oscillator y'' = -4 y (y = cos 2t) over four segments, sampled every 0.1 s:
    the loop takes scipy's RK45 steps (the same number of accepted steps, the step carried
    from segment to segment, at most ``max_step``) and gives its dense output at the samples
    to round-off; both follow the closed form within the tolerance's reach."""
    a = [[0.0, 1.0], [-4.0, 0.0]]
    ends, interval, n_out = [0.7, 2.0, 3.3, 5.0], 0.1, 51
    status, flag, t, accepted, sampled, x, out = _integrate(a, [1.0, 0.0], ends, interval,
                                                            n_out, max_step=max_step)
    ref, steps = _scipy(a, [1.0, 0.0], ends, interval, n_out, 1e-6, 1e-9, max_step, 1e-3)
    assert (status, flag, t, sampled) == (dp.DONE, 0, 5.0, n_out)
    assert accepted == steps > 20
    np.testing.assert_allclose(out, ref, rtol=0, atol=1e-12)
    time = np.arange(n_out) * interval
    np.testing.assert_allclose(out[:, 0], np.cos(2 * time), atol=1e-5)
    np.testing.assert_allclose(x, [np.cos(10.0), -2 * np.sin(10.0)], atol=1e-5)


def test_fixed_step_is_the_stability_polynomial():
    """y' = -3 y with a fixed step of 0.05 s over 1 s: each step multiplies y by the
    stability function of the fifth-order solution, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 +
    z^5/120 + z^6/600 (z = h lambda; Hairer, Norsett, Wanner I, section IV.2), and a sample
    at a step's end is the step's solution."""
    h, lam = 0.05, -3.0
    status, _, t, accepted, sampled, x, out = _integrate([[lam]], [1.0], [1.0], 0.1, 11,
                                                         fixed=h, first_step=h)
    z = h * lam
    r = 1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24 + z**5 / 120 + z**6 / 600
    assert (status, t, accepted, sampled) == (dp.DONE, 1.0, 20, 11)
    np.testing.assert_allclose(x[0], r**20, rtol=1e-13)
    np.testing.assert_allclose(out[:, 0], r ** (2 * np.arange(11)), rtol=1e-13)


def test_run_leaving_its_table_stops_just_before():
    """y' = y from 1 with a table up to e^2: the step is halved at the crossing until it is
    under 2e-6 s, and the run stops there, just before t = 2 (closed form), its state the
    last accepted one, the samples after it left to the caller. Outside at a segment's start
    (a table of 0.5 from t = 1, after a jump), the run stops at once, at t = 1 exactly."""
    status, flag, t, _, sampled, x, out = _integrate([[1.0]], [1.0], [3.0], 0.1, 31,
                                                     limits=[np.exp(2.0)])
    assert (status, flag) == (dp.LEFT, 1)
    assert 2.0 - 1e-5 < t < 2.0
    np.testing.assert_allclose(x[0], np.exp(t), rtol=1e-6)
    assert sampled == 20 and np.isnan(out[20:]).all()  # the samples up to 1.9 s
    status, flag, t, _, sampled, x, _ = _integrate([[1.0]], [1.0], [1.0, 3.0], 0.1, 31,
                                                   limits=[10.0, 0.5])
    assert (status, flag, t, sampled) == (dp.LEFT, 1, 1.0, 11)
    np.testing.assert_allclose(x[0], np.e, rtol=1e-6)


def test_budget_of_steps_stops_every_run():
    """A run that would try more than ``max_steps`` steps sets the shared stop, and a run
    started with the stop set ends at once without a step."""
    stop = np.zeros(1, dtype=np.int64)
    status, *_ = _integrate([[0.0, 1.0], [-4.0, 0.0]], [1.0, 0.0], [5.0], 0.1, 51,
                            max_steps=5, stop=stop)
    assert status == dp.OVER_BUDGET and stop[0] == 1
    status, _, t, accepted, *_ = _integrate([[-1.0]], [1.0], [1.0], 0.1, 11, stop=stop)
    assert (status, t, accepted) == (dp.OVER_BUDGET, 0.0, 0)

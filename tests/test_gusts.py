"""Gust shapes against their defining formulas (CS 29.341 amplitude; standard discrete shapes)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.errors import InputError
from slingloads.models.gusts import (
    GUST_VELOCITY,
    ContinuousGust,
    FiniteGust,
    OneMinusCosineGust,
    StepGust,
    TabulatedGust,
    make_gust,
    standard_gusts,
)


def test_default_amplitude_is_30_ft_per_s():
    """CS 29.341: 30 ft/s horizontal gust = 30 x 0.3048 = 9.144 m/s."""
    assert GUST_VELOCITY == pytest.approx(9.144, rel=1e-12)
    assert StepGust().amplitude == pytest.approx(9.144)


def test_step_and_finite_shapes():
    """Definitions: step v = A for t >= t0; rectangular gust v = A on [t0, t0 + T)."""
    t = np.array([0.0, 29.999, 30.0, 39.999, 40.0, 100.0])
    assert_allclose(StepGust(5.0, 30.0).velocity(t), [0, 0, 5, 5, 5, 5])
    assert_allclose(FiniteGust(5.0, 30.0, 10.0).velocity(t), [0, 0, 5, 5, 0, 0])


def test_one_minus_cosine_shape():
    """Definition v = A/2 (1 - cos(2 pi tau / T)): 0 at both ends, A at mid-duration,
    A/2 at the quarter points."""
    g = OneMinusCosineGust(4.0, 10.0, 8.0)
    assert_allclose(g.velocity([10.0, 12.0, 14.0, 16.0, 18.0, 25.0]), [0, 2, 4, 2, 0, 0],
                    atol=1e-12)


def test_continuous_is_harmonic():
    """Definition v = A sin(2 pi (t - t0) / P) from t0 on: quarter period gives A."""
    g = ContinuousGust(3.0, 30.0, 12.0)
    assert_allclose(g.velocity([29.0, 33.0, 36.0, 39.0]), [0, 3, 0, -3], atol=1e-12)
    assert g.end is None


def test_standard_set_and_breakpoints():
    """The four shapes of the project facts (step, finite, 1-cosine, continuous), with the jump
    times the integrator must step on."""
    kinds = [g.kind for g in standard_gusts()]
    assert kinds == ["step", "finite", "1-cosine", "continuous"]
    assert FiniteGust(1.0, 30.0, 10.0).breakpoints == (30.0, 40.0)


def test_bad_gusts():
    """Bad input is refused with the value echoed."""
    with pytest.raises(InputError, match="not a valid gust shape.*'sine'"):
        make_gust("sine")
    with pytest.raises(InputError, match=r"duration must be > 0 .*-1"):
        FiniteGust(1.0, 30.0, -1.0)
    with pytest.raises(InputError, match=r"onset must be >= 0.*-5"):
        StepGust(1.0, -5.0)
    with pytest.raises(InputError, match="strictly increasing.*1.0"):
        TabulatedGust([0.0, 2.0, 1.0], [0.0, 1.0, 2.0])
    with pytest.raises(InputError, match="after the end of the tabulated gust"):
        TabulatedGust([0.0, 1.0], [0.0, 1.0]).velocity(2.0)

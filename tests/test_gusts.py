"""Gust shapes against their defining formulas (CS 29.341 amplitude; standard discrete shapes)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.signal import welch

from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError
from slingloads.models.gusts import (
    GUST_VELOCITY,
    DrydenTurbulence,
    FiniteGust,
    HarmonicGust,
    OneMinusCosineGust,
    StepGust,
    SustainedGust,
    TabulatedGust,
    dryden_lateral_spectrum,
    dryden_variance_fraction,
    low_altitude_turbulence,
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


def test_harmonic_shape():
    """Definition v = A sin(2 pi (t - t0) / P) from t0 on: quarter period gives A."""
    g = HarmonicGust(3.0, 30.0, 12.0)
    assert_allclose(g.velocity([29.0, 33.0, 36.0, 39.0]), [0, 3, 0, -3], atol=1e-12)
    assert g.end is None
    assert make_gust("harmonic", 3.0, 30.0, period=12.0) == g


def test_continuous_is_a_sustained_crosswind():
    """The paper's continuous gust is held: v = A/2 (1 - cos(pi (t - t0)/t_r)) over the rise,
    so A/2 at half the rise (hand value 2 m/s for A = 4), then A for ever; rise 0 is the
    sharp-edged step. Its kinks are breakpoints and it ends (stops changing) at t0 + t_r."""
    g = SustainedGust(4.0, 20.0, 6.0)
    assert_allclose(g.velocity([19.9, 20.0, 23.0, 26.0, 500.0]), [0, 0, 2, 4, 4], atol=1e-12)
    assert g.breakpoints == (20.0, 26.0) and g.end == 26.0
    assert_allclose(SustainedGust(4.0, 20.0, 0.0).velocity([19.9, 20.0, 99.0]), [0, 4, 4])
    assert make_gust("continuous", 4.0, 20.0, rise_time=6.0) == g


def test_standard_set_and_breakpoints():
    """The four CS 29.341 shapes (step, finite, 1-cosine, continuous = sustained), with the
    jump times the integrator must step on; the continuous one rises over half the duration."""
    gusts = standard_gusts()
    assert [g.kind for g in gusts] == ["step", "finite", "1-cosine", "continuous"]
    assert gusts[3].rise_time == 5.0 and gusts[3].velocity(1e3) == pytest.approx(9.144)
    assert FiniteGust(1.0, 30.0, 10.0).breakpoints == (30.0, 40.0)


def test_dryden_low_altitude_scale_and_intensity():
    """MIL-F-8785C low altitude at h = 300 ft, moderate (W20 = 30 kt), by hand:
    base = 0.177 + 0.000823 x 300 = 0.4239; L_v = 300 / 0.4239^1.2 = 840.3 ft = 256.1 m;
    sigma_w = 3 kt = 1.5433 m/s, sigma_v = 1.5433 / 0.4239^0.4 = 2.1755 m/s. At 1000 ft the
    scale length is 1000 ft (base = 1.0), the classic matching point with L = h above."""
    sigma, length = low_altitude_turbulence(300 * FOOT, "moderate")
    assert length == pytest.approx(840.25 * FOOT, rel=1e-4)
    assert sigma == pytest.approx(3 * KNOT / 0.4239**0.4, rel=1e-4)
    sigma, length = low_altitude_turbulence(1000 * FOOT, "severe")
    assert length == pytest.approx(1000 * FOOT, rel=1e-9)
    assert sigma == pytest.approx(4.5 * KNOT, rel=1e-9)


def test_dryden_spectrum_integrates_to_the_variance():
    """The one-sided Dryden spectrum integrates to sigma^2 (quadrature over omega, an
    independent check of the closed form F(x) = (2 atan x - x/(1 + x^2))/pi, whose
    derivative is (1 + 3x^2)/(1 + x^2)^2 / pi)."""
    from scipy.integrate import quad

    sigma, length, tas = 2.0, 200.0, 40.0
    total, _ = quad(lambda w: dryden_lateral_spectrum(w, sigma, length, tas), 0, np.inf,
                    limit=200)
    assert total == pytest.approx(sigma**2, rel=1e-8)
    part, _ = quad(lambda w: dryden_lateral_spectrum(w, sigma, length, tas), 0.0,
                   3.0 * tas / length)
    assert part == pytest.approx(sigma**2 * dryden_variance_fraction(3.0), rel=1e-10)


def test_dryden_realisation_matches_its_spectrum():
    """A 3000 s realisation (L = 50 m, V = 50 m/s: knee at 1 rad/s) sampled at 20 Hz: the
    variance of the record and, per two-octave band from 0.04 to 2.56 Hz, the power of its
    Welch spectrum match the closed-form Dryden integrals within 5 % (each sinusoid's power
    spreads over neighbouring Welch bins, hence bands, not bins); across 4000 seeds, v at a
    fixed time has the band variance within 6 % (the estimate's own scatter is 2.2 %)."""
    g = DrydenTurbulence(1.5, 50.0, 50.0, onset=0.0, duration=3000.0, seed=7)
    fs = 20.0
    t = np.arange(0.0, 3000.0, 1.0 / fs)
    v = g.velocity(t)
    assert np.var(v) == pytest.approx(1.5**2 * g.variance_fraction, rel=0.05)
    f, psd = welch(v, fs=fs, nperseg=8192)          # one-sided, per Hz
    edges = 0.04 * 4.0 ** np.arange(4)              # 0.04 .. 2.56 Hz
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        inside = (f >= lo) & (f < hi)
        measured = np.sum(psd[inside]) * (f[1] - f[0])
        x = 2 * np.pi * np.array([lo, hi]) * 50.0 / 50.0
        expected = 1.5**2 * np.diff(dryden_variance_fraction(x))[0]
        assert measured == pytest.approx(expected, rel=0.05), (lo, hi)
    values = [DrydenTurbulence(1.5, 50.0, 50.0, 0.0, 10.0, seed=k, components=64).velocity(
        5.0) for k in range(4000)]
    assert np.var(values) == pytest.approx(1.5**2 * 0.990, rel=0.06)


def test_dryden_realisation_is_reproducible_and_bounded_in_time():
    """Same seed, same history (any time, any order of evaluation); another seed differs;
    zero before the onset and after the end."""
    a = DrydenTurbulence(2.0, 100.0, 40.0, onset=10.0, duration=20.0, seed=3)
    b = DrydenTurbulence(2.0, 100.0, 40.0, onset=10.0, duration=20.0, seed=3)
    t = np.array([25.0, 12.5, 29.9])
    assert_allclose(a.velocity(t), b.velocity(t[::-1])[::-1], rtol=1e-14)
    assert not np.allclose(a.velocity(t), DrydenTurbulence(2.0, 100.0, 40.0, 10.0, 20.0,
                                                           seed=4).velocity(t))
    assert_allclose(a.velocity([9.99, 30.0, 50.0]), 0.0)
    assert a.breakpoints == (10.0, 30.0) and a.peak >= np.abs(a.velocity(t)).max()


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
    with pytest.raises(InputError, match=r"rise time must be >= 0.*-2"):
        SustainedGust(1.0, 30.0, -2.0)
    with pytest.raises(InputError, match=r"period must be > 0.*0.0"):
        HarmonicGust(1.0, 30.0, 0.0)
    with pytest.raises(InputError, match=r"10 to 1000 ft.*value 1000.0"):
        low_altitude_turbulence(1000.0)
    with pytest.raises(InputError, match=r"severity.*'extreme'"):
        low_altitude_turbulence(100.0, "extreme")
    with pytest.raises(InputError, match=r"intensity must be > 0.*-1"):
        DrydenTurbulence(-1.0, 100.0, 40.0)

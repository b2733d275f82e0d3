"""The peak between samples: the vertex of the parabola through three equally spaced samples.

Reference: the closed form. The parabola y(s) = a (s - s_v)^2 + c (a < 0), sampled at
s = -1, 0, 1, gives y0 = a (1 + s_v)^2 + c, y1 = a s_v^2 + c, y2 = a (1 - s_v)^2 + c, so
y0 - 2 y1 + y2 = 2 a and y0 - y2 = 4 a s_v: the vertex is at s_v = (y0 - y2) / (2 (y0 - 2 y1 +
y2)) and its value is c, whatever a; a vertex beyond half a step is kept at half a step, and
samples that do not curve down give the middle one. The numpy form
(:func:`slingloads.models.sampled_peak.refine_peak`) and the compiled form of the
kernels (:func:`slingloads.models.sampled_peak.compiled_parabola_vertex`) are made from one
source and must agree to the bit.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.models.sampled_peak import compiled_parabola_vertex, refine_peak

parabola_vertex = compiled_parabola_vertex()


def _samples(a, s_v, c):
    return tuple(a * (s - s_v) ** 2 + c for s in (-1.0, 0.0, 1.0))


def test_vertex_of_a_sampled_parabola_is_the_closed_form():
    """Random downward parabolas with their vertex within half a step of the middle sample:
    offset s_v and value c, to rounding (the formula is exact for a parabola)."""
    rng = np.random.default_rng(11)
    a = -rng.uniform(0.01, 10.0, 500)
    s_v = rng.uniform(-0.5, 0.5, 500)
    c = rng.uniform(-5.0, 5.0, 500)
    y0, y1, y2 = _samples(a, s_v, c)
    value, offset = refine_peak(y0, y1, y2)
    assert_allclose(offset, s_v, rtol=0, atol=1e-12)
    assert np.all(np.abs(value - c) <= 1e-12 * (1 + np.abs(a) + np.abs(c)))


def test_hand_example():
    """y = -(s - 1/4)^2 + 1 at s = -1, 0, 1: y0 = -25/16 + 1 = -9/16, y1 = 15/16, y2 = 7/16;
    the vertex at 1/4 step, value 1, exactly in binary."""
    value, offset = refine_peak(-9 / 16, 15 / 16, 7 / 16)
    assert (float(value), float(offset)) == (1.0, 0.25)
    assert parabola_vertex(-9 / 16, 15 / 16, 7 / 16) == (1.0, 0.25)


def test_far_vertex_and_flat_samples():
    """A vertex beyond half a step (samples that are no local maximum: y2 > y1; at a local
    maximum |s_v| <= 1/2) is kept at +1/2, with the value y1 - (y0 - y2)/8 of the formula
    there (a = -1, s_v = 0.9, c = 2: y0 = -1.61, y1 = 1.19, y2 = 1.99, value 1.64); samples on
    a line or curving up give the middle sample and no offset."""
    y0, y1, y2 = _samples(-1.0, 0.9, 2.0)
    value, offset = refine_peak(y0, y1, y2)
    assert float(offset) == 0.5
    assert float(value) == pytest.approx(1.64, rel=1e-14)
    for samples in ((1.0, 2.0, 3.0), (2.0, 1.0, 2.0), (1.0, 1.0, 1.0)):
        assert tuple(map(float, refine_peak(*samples))) == (samples[1], 0.0)
        assert parabola_vertex(*samples) == (samples[1], 0.0)


def test_the_compiled_and_numpy_forms_agree_to_the_bit():
    """The one source, compiled for one sample and applied to arrays, gives the same bits on
    random samples (peaks, far vertices, curving up)."""
    rng = np.random.default_rng(12)
    y0, y1, y2 = rng.normal(size=(3, 2000))
    value, offset = refine_peak(y0, y1, y2)
    for k in range(y0.size):
        assert parabola_vertex(y0[k], y1[k], y2[k]) == (value[k], offset[k])

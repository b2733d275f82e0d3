"""The peak of a sampled signal between its samples: the vertex of the parabola through three.

A peak of a signal sampled every h lies between the samples; the parabola through the three
equally spaced samples (y0, y1, y2) at t - h, t, t + h around it,

.. math::

    y(t + s h) = y_1 + \\tfrac{1}{2} (y_2 - y_0) s + \\tfrac{1}{2} c s^2,
    \\qquad c = y_0 - 2 y_1 + y_2,

has its vertex, where it curves down (c < 0), at

.. math::

    s^* = \\frac{y_0 - y_2}{2 c}, \\qquad
    y(t + s^* h) = y_1 - \\frac{(y_0 - y_2)^2}{8 c} = y_1 - \\tfrac{1}{4} (y_0 - y_2) s^*,

with :math:`|s^*| \\le 1/2` when y1 is the largest of the three (the vertex lies nearer the
middle sample than either other); s* is kept within [-1/2, 1/2] (against rounding, and for
samples that are not a local maximum). Where the samples do not curve down, the peak is the
middle sample (s* = 0). The error of the refinement is that of the interpolating parabola, of
order h^3 times the signal's third derivative.

The formula is written once, :func:`make_parabola_vertex`, and made twice from it: for numpy
arrays (:func:`refine_peak`, element by element over arrays of any shape) and for one sample in
compiled code (:func:`compiled_parabola_vertex`, inlined into the kernels that refine peaks:
the lateral batch integrator :mod:`slingloads.models.pendulum_batch`, the yaw-run metrics
:mod:`slingloads.analyses.chute_metrics` and the multibody response measures
:mod:`slingloads.models.multibody.response`), so that the two give the same numbers to the bit.
numba is imported only when the compiled form is asked for.
"""

from __future__ import annotations

import functools

import numpy as np

#: Largest distance of the vertex from the middle sample. [steps]
HALF_STEP = 0.5


def make_parabola_vertex(select, bound):
    """The vertex of the parabola through three equally spaced samples, written once for
    numpy arrays and for compiled scalars.

    Parameters
    ----------
    select : callable
        ``select(condition, a, b)``: ``a`` where ``condition``, else ``b`` (``numpy.where``
        for arrays; a conditional expression for one sample).
    bound : callable
        ``bound(s)``: ``s`` kept within [-1/2, 1/2] (``numpy.clip`` for arrays; ``min`` and
        ``max`` for one sample).

    Returns
    -------
    callable
        ``vertex(y0, y1, y2) -> (value, offset)``, as :func:`refine_peak`. [signal units],
        [steps]
    """

    def parabola_vertex(y0, y1, y2):
        curvature = y0 - 2.0 * y1 + y2
        down = curvature < 0
        offset = select(down, bound(0.5 * (y0 - y2) / select(down, curvature, -1.0)), 0.0)
        return y1 - 0.25 * (y0 - y2) * offset, offset

    return parabola_vertex


def _bound_array(s):
    """``s`` within [-1/2, 1/2], element by element."""
    return np.clip(s, -HALF_STEP, HALF_STEP)


_refine = make_parabola_vertex(np.where, _bound_array)


def refine_peak(y0, y1, y2):
    """Vertex of the parabola through equally spaced samples (y0, y1, y2) around a peak y1.

    Parameters
    ----------
    y0, y1, y2 : array_like
        Three successive samples of a signal, one step apart (any shape, broadcast
        together). [signal units]

    Returns
    -------
    value : ndarray
        The parabola's vertex where it curves down (y0 - 2 y1 + y2 < 0), else y1. [signal
        units]
    offset : ndarray
        Where the vertex lies, in steps from the middle sample, within [-1/2, 1/2] (0 where
        the samples do not curve down). [-]
    """
    return _refine(np.asarray(y0, dtype=float), np.asarray(y1, dtype=float),
                   np.asarray(y2, dtype=float))


@functools.cache
def compiled_parabola_vertex():
    """The vertex of the parabola through three samples, compiled for one sample.

    Returns
    -------
    numba dispatcher
        ``vertex(y0, y1, y2) -> (value, offset)``, as :func:`refine_peak` gives for one sample
        (the same bits), compiled with numba to be inlined into its caller
        (``inline="always"``, cached on disk). [signal units], [steps]
    """
    import numba

    inline_jit = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")

    @inline_jit
    def select(condition, a, b):
        return a if condition else b

    @inline_jit
    def bound(s):
        return min(max(s, -HALF_STEP), HALF_STEP)

    return inline_jit(make_parabola_vertex(select, bound))

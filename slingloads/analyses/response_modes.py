"""Modes identified from a sampled free response (matrix pencil method).

A free response of a linear system is a sum of damped exponentials,

.. math::

    y(t_k) = \\sum_i h_i z_i^k, \\qquad z_i = e^{s_i \\Delta t},
    \\qquad s_i = -\\zeta_i \\omega_i \\pm j \\omega_i \\sqrt{1 - \\zeta_i^2},

one pair per oscillatory mode the signal sees (a constant is the root :math:`z = 1`). The
matrix pencil method [1]_ finds the :math:`z_i` from the samples alone: the Hankel matrix of
the samples is reduced to its significant singular vectors, whose shift invariance gives the
roots as the eigenvalues of a small pencil; the residues :math:`h_i` follow by least squares.
Each oscillatory root gives a period :math:`2 \\pi / \\mathrm{Im}\\, s` [s] and a damping
ratio :math:`-\\mathrm{Re}\\, s / |s|` [-].

Unlike a logarithmic decrement of successive peaks, the method separates modes of different
periods present in the same signal: the yaw mode of a towed body (period of 8-15 s) is read
on the heading history without the roll or swing modes of 1-2 s that dominate its rate.
:func:`identify_mode` picks the identified component nearest a target period (the linear
model's mode the measurement claims to be on) and says why when there is none, so that a
reported "damping from the response" always names the mode it was measured on.

References
----------
.. [1] Y. Hua and T. K. Sarkar, "Matrix pencil method for estimating parameters of
   exponentially damped/undamped sinusoids in noise", IEEE Trans. Acoust., Speech, Signal
   Process., vol. 38, no. 5, pp. 814-824, 1990.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Singular values of the Hankel matrix below this fraction of the largest are noise. [-]
SINGULAR_TOLERANCE = 1e-5
#: Most components kept. [-]
MAX_COMPONENTS = 24
#: Least number of samples for an identification. [-]
MIN_SAMPLES = 20
#: Most samples identified on (a longer record is averaged over blocks of consecutive
#: samples and decimated: a moving average of a sum of exponentials is a sum of the same
#: exponentials, so the roots are kept exactly, and the fast modes are attenuated). [-]
MAX_SAMPLES = 800
#: Least observed time, in periods of the identified component, for it to count. [-]
MIN_PERIODS = 1.5
#: Least amplitude of a component, as a fraction of the largest oscillatory one, for it to
#: count as a mode seen in the signal (smaller ones are numerical residue). [-]
MIN_SHARE = 0.05


@dataclass(frozen=True)
class IdentifiedMode:
    """One oscillatory component identified on a response, or why there is none.

    Attributes
    ----------
    period : float
        Damped period, NaN when none was identified. [s]
    damping_ratio : float
        NaN when none was identified. [-]
    amplitude : float
        Initial amplitude of the component (the signal's unit), NaN when none. [unit of the signal]
    reason : str
        "" when identified, else why not.
    components : tuple of tuple of float
        Every oscillatory component identified: (period [s], damping ratio [-], amplitude),
        largest first.
    """

    period: float
    damping_ratio: float
    amplitude: float
    reason: str = ""
    components: tuple = ()

    @property
    def found(self):
        """Whether a component was identified."""
        return not self.reason


def components(time, y):
    """Every exponential component of a uniformly sampled signal (matrix pencil method).

    Parameters
    ----------
    time : array_like, shape (n,)
        Uniform sample times. [s]
    y : array_like, shape (n,)
        Finite samples. [any unit]

    Returns
    -------
    roots : ndarray of complex, shape (m,)
        Continuous-time roots :math:`s_i`. [1/s]
    residues : ndarray of complex, shape (m,)
        :math:`h_i`, such that ``y(t) ~ sum h_i exp(s_i (t - t0))`` (the signal's unit; of
        the block-averaged signal when the record is longer than :data:`MAX_SAMPLES`).
        [unit of ``y``]
    """
    time = np.asarray(time, float)
    y = np.asarray(y, float)
    dt = float(time[1] - time[0])
    step = -(-y.size // MAX_SAMPLES)
    if step > 1:  # block average, then one sample per block (roots unchanged)
        y = np.convolve(y, np.full(step, 1.0 / step), mode="valid")[::step]
        dt *= step
    n = y.size
    pencil = n // 3
    hankel = np.lib.stride_tricks.sliding_window_view(y, pencil + 1)
    _, sv, vh = np.linalg.svd(hankel, full_matrices=False)
    if sv[0] == 0.0:
        return np.empty(0, complex), np.empty(0, complex)
    m = int(min(np.count_nonzero(sv > SINGULAR_TOLERANCE * sv[0]), MAX_COMPONENTS, pencil))
    v = vh[:m].conj().T  # (pencil + 1, m)
    z = np.linalg.eigvals(np.linalg.pinv(v[:-1]) @ v[1:])
    z = z[np.abs(z) > 0]
    vander = z[None, :] ** np.arange(n)[:, None]
    residues = np.linalg.lstsq(vander, y.astype(complex), rcond=None)[0]
    return np.log(z) / dt, residues


def identify_mode(time, y, start=None, target_period=None, tolerance=0.25):
    """The oscillatory component of a free response nearest a target period.

    Parameters
    ----------
    time : array_like, shape (n,)
        Uniform sample times. [s]
    y : array_like, shape (n,)
        The response (e.g. the heading, [rad]); samples after the first non-finite one are
        not used (a stopped run).
    start : float, optional
        Identify from this time on (the end of the input; default: the first sample). [s]
    target_period : float, optional
        Period of the mode the measurement is meant for (the linear model's). [s] Without it,
        the component of largest amplitude.
    tolerance : float, optional
        Largest relative distance of the identified period from ``target_period``. [-]

    Returns
    -------
    IdentifiedMode

    Examples
    --------
    A closed-form damped oscillation of period 14.6 s and damping ratio 0.155, plus a
    fast, lightly damped one of 1.44 s that dominates the rate:

    >>> import numpy as np
    >>> t = np.arange(0.0, 60.0, 0.1)
    >>> def mode(period, zeta, a):
    ...     wd = 2 * np.pi / period
    ...     sigma = zeta * wd / np.sqrt(1 - zeta ** 2)
    ...     return a * np.exp(-sigma * t) * np.cos(wd * t)
    >>> y = mode(14.6, 0.155, 1.0) + mode(1.44, 0.0014, 0.05)
    >>> m = identify_mode(t, y, target_period=14.6)
    >>> round(m.period, 3), round(m.damping_ratio, 4)
    (14.6, 0.155)
    """
    time = np.asarray(time, float)
    y = np.asarray(y, float)
    keep = time >= (time[0] if start is None else start)
    time, y = time[keep], y[keep]
    bad = ~np.isfinite(y)
    if bad.any():
        last = int(np.argmax(bad))
        time, y = time[:last], y[:last]
    nan = float("nan")
    if y.size < MIN_SAMPLES:
        return IdentifiedMode(nan, nan, nan, f"fewer than {MIN_SAMPLES} samples after the "
                              "input")
    span = float(time[-1] - time[0])
    roots, residues = components(time, y)
    osc = roots.imag > 1e-9
    found = []
    for s, h in zip(roots[osc], residues[osc], strict=True):
        period = float(2 * math.pi / s.imag)
        found.append((period, float(-s.real / abs(s)), 2 * float(abs(h))))
    found.sort(key=lambda c: -c[2])
    largest = found[0][2] if found else 0.0
    seen = tuple(c for c in found if c[2] >= MIN_SHARE * largest
                 and span >= MIN_PERIODS * c[0])
    if not seen:
        return IdentifiedMode(nan, nan, nan, "no oscillation identified over "
                              f"{MIN_PERIODS:g} periods in the {span:.3g} s after the input",
                              tuple(found))
    if target_period is None or not math.isfinite(target_period):
        best = seen[0]
    else:
        near = [c for c in seen if abs(c[0] - target_period) <= tolerance * target_period]
        if not near:
            if span < MIN_PERIODS * target_period:
                why = (f"{span:.3g} s after the input is less than {MIN_PERIODS:g} periods "
                       f"of {target_period:.3g} s")
            else:
                why = (f"no component within {tolerance:.0%} of {target_period:.3g} s "
                       f"(identified: {', '.join(f'{c[0]:.3g}' for c in seen)} s)")
            return IdentifiedMode(nan, nan, nan, why, seen)
        best = min(near, key=lambda c: abs(math.log(c[0] / target_period)))
    return IdentifiedMode(best[0], best[1], best[2], "", seen)


__all__ = ["IdentifiedMode", "components", "identify_mode"]

"""Compiled metrics of the 1-DOF yaw runs, one pass over each run's history.

The same quantities, defined the same way, as the vectorised numpy expressions they replace in
:func:`slingloads.analyses.chute_sizing._run_metrics` (see there and :class:`YawRuns` for
their meaning): peak |beta| and |psi|, sideslip range, settling time, and the two first
positive yaw-rate peaks after the gust ends (refined by the parabola through the peak and its
neighbours, :mod:`slingloads.models.sampled_peak`) for the logarithmic decrement. Compiled
with `numba <https://numba.pydata.org>`_ (``cache=True``), on one thread: a pass over the
histories takes about a millisecond for 400 runs, less than waking the other threads would
cost.
"""

from __future__ import annotations

import math
from pathlib import Path

import numba
import numpy as np

from slingloads.models.numba_cache import drop_stale_cache
from slingloads.models.sampled_peak import compiled_parabola_vertex

_HERE = Path(__file__).resolve()
drop_stale_cache(_HERE.parent, also=(_HERE.parents[1] / "models" / "sampled_peak.py",))

# the peak between samples, compiled from its one source in slingloads.models.sampled_peak
_parabola_vertex = compiled_parabola_vertex()


@numba.njit(cache=True, nogil=True)
def history_metrics(t, beta, psi, rate, trim, onset, free, settle_fraction, peak_threshold,
                    out):
    """Fill ``out`` (runs, 8): peak |beta| [rad], peak |psi| [rad], min beta, max beta [rad],
    settling time [s] (NaN if never or ``free`` is NaN), first and second refined positive
    yaw-rate peaks after ``free`` [rad/s] (-inf if missing), NaN (spare column).

    Parameters
    ----------
    t : ndarray, shape (n,)
        Sample times. [s]
    beta, psi : ndarray, shape (runs, n)
        Sideslip and yaw. [rad]
    rate : ndarray, shape (runs, n)
        Yaw rate. [rad/s]
    trim : ndarray, shape (runs,)
        Trim sideslip. [rad]
    onset, free : ndarray, shape (runs,)
        The gust's onset and the time it stops changing (NaN: never). [s]
    settle_fraction : float
        Settling band, a fraction of the largest excursion of beta from trim. [-]
    peak_threshold : float
        Smallest yaw-rate peak counted. [rad/s]
    out : ndarray, shape (runs, 8)
        Receives the metrics. [rad, rad/s, s: see above]
    """
    runs, n = beta.shape
    for j in range(runs):
        pb = 0.0
        pp = 0.0
        lo = np.inf
        hi = -np.inf
        exc = 0.0
        for k in range(n):
            b = beta[j, k]
            pb = max(pb, abs(b))
            pp = max(pp, abs(psi[j, k]))
            lo = min(lo, b)
            hi = max(hi, b)
            exc = max(exc, abs(b - trim[j]))
        band = settle_fraction * exc
        last = n - 1
        for k in range(n - 1, -1, -1):
            if abs(beta[j, k] - trim[j]) > band:
                last = k
                break
        settling = np.nan
        if free[j] == free[j] and last + 1 < n:
            settling = max(t[last + 1] - onset[j], 0.0)
        p1 = -np.inf
        p2 = -np.inf
        found = 0
        for k in range(1, n - 1):
            r = rate[j, k]
            if (r > rate[j, k - 1] and r >= rate[j, k + 1] and r > peak_threshold
                    and t[k] > free[j]):
                refined, _ = _parabola_vertex(rate[j, k - 1], r, rate[j, k + 1])
                found += 1
                if found == 1:
                    p1 = refined
                else:
                    p2 = refined
                    break
        out[j, 0], out[j, 1], out[j, 2], out[j, 3] = pb, pp, lo, hi
        out[j, 4], out[j, 5], out[j, 6], out[j, 7] = settling, p1, p2, math.nan

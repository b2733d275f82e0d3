"""Timing helpers shared by the benchmarks.

Every benchmark prints wall time and CPU time (``time.process_time``: all threads of this
process) of what it measures. A ratio is taken on CPU time of single-threaded work, or on the
median of repeated wall times; a slow baseline is timed on a sample of runs and scaled per
run to the full size.
"""

from __future__ import annotations

import statistics
import time
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Timing:
    """Wall and CPU time of one measurement. [s]"""

    wall: float
    cpu: float

    def scaled(self, factor):
        """The same per-unit cost for ``factor`` times as much work."""
        return Timing(self.wall * factor, self.cpu * factor)

    def __str__(self):
        return f"{self.wall:9.3f} s wall, {self.cpu:9.3f} s CPU"


def timed(function, *args, **kwargs):
    """(result, Timing) of one call."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = function(*args, **kwargs)
    return result, Timing(time.perf_counter() - wall, time.process_time() - cpu)


def median_timed(function, repeat=3):
    """(last result, Timing) with the median wall and the median CPU time of ``repeat``
    calls; only one result is alive at a time."""
    times = []
    result = None
    for _ in range(repeat):
        result = None  # the previous result is freed before the next call
        result, t = timed(function)
        times.append(t)
    return result, Timing(statistics.median(t.wall for t in times),
                          statistics.median(t.cpu for t in times))


def sample(n, k, seed=0):
    """``k`` of ``n`` indices drawn at random (fixed seed), sorted; all of them if k >= n."""
    if k >= n:
        return np.arange(n)
    return np.sort(np.random.default_rng(seed).choice(n, k, replace=False))

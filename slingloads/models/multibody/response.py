"""The sampled response of runs: derived histories and their measures, compiled.

From the states a run was sampled at and the quantities the equations report there
(:data:`~slingloads.models.multibody.equations.INFO`), :func:`derive` computes the histories an
engineer reads (:data:`HISTORY`): the attitude as Euler angles (yaw unwrapped), the yaw rate
about the earth vertical, the cable swing angles, the hub load and its angle from the mast
axis, the parachute line angles, the carrier speed. :func:`measure` reduces them to the
measures of a run (:data:`MEASURES`): peaks and when they occur, RMS values, extremes, cable
slack, damping from successive peaks, settling time and the activity the verdict compares;
the analysis (:mod:`slingloads.analyses.multibody.simulate`) names them and states its rules.

The integration kernel (:func:`~slingloads.models.multibody.integrator.dopri_runs`) calls
both as soon as a run is done, on the reported quantities it evaluated at the run's samples
into a buffer reused from run to run: a batch's metrics without anyone's histories kept.

The formulas are those of numpy: angles from ``arctan2``, ``arcsin`` and ``arccos`` (here
the C library's, which may differ from numpy's vectorised ones in the last bit), ``unwrap``
and ``gradient`` as numpy defines them; sums are taken in order (numpy's pairwise sums may
differ in the last bits).
"""

from __future__ import annotations

import math

import numpy as np

from slingloads.models.multibody._jit import jit
from slingloads.models.sampled_peak import compiled_parabola_vertex

# the peak between samples, compiled from its one source in slingloads.models.sampled_peak
_parabola_vertex = compiled_parabola_vertex()

#: Derived histories, in the order of :func:`derive`'s columns (SI, angles in rad).
HISTORY = ("time", "x", "y", "z", "yaw", "pitch", "roll", "yaw rate", "alpha", "beta",
           "airspeed", "swing longitudinal", "swing lateral", "swing", "tension",
           "tension ratio", "hub Fx", "hub Fy", "hub Fz", "hub load angle", "line theta",
           "line psi", "line tension", "chute alpha", "carrier speed", "thrust tilt")
N_HISTORY = len(HISTORY)
# columns the compiled measures read
_BETA = HISTORY.index("beta")
_CARRIER_SPEED = HISTORY.index("carrier speed")
_CHUTE_ALPHA = HISTORY.index("chute alpha")
_LINE_TENSION = HISTORY.index("line tension")
_SWING_LATERAL = HISTORY.index("swing lateral")
_SWING_LONGITUDINAL = HISTORY.index("swing longitudinal")
_TENSION_RATIO = HISTORY.index("tension ratio")
_YAW = HISTORY.index("yaw")
_YAW_RATE = HISTORY.index("yaw rate")

#: Histories whose peak (largest magnitude after the input starts) :func:`measure` finds, and
#: whether it is taken as a change from the first sample.
PEAKS = (("yaw", True), ("beta", False), ("swing lateral", False),
         ("swing longitudinal", True), ("pitch", True), ("roll", False),
         ("hub load angle", False), ("line psi", False), ("line theta", True))
_PEAK_COLUMNS = tuple(HISTORY.index(name) for name, _ in PEAKS)
_PEAK_RELATIVE = tuple(relative for _, relative in PEAKS)

#: What :func:`measure` returns, in order (SI, angles in rad): for each of :data:`PEAKS` its
#: value and time, then the rest.
MEASURES = tuple(f"{name} {what}" for name, _ in PEAKS for what in ("peak", "at")) + (
    "yaw rms", "beta rms", "tension ratio max", "tension ratio min", "cable slack",
    "cable slack first at", "cable slack time", "line tension min", "chute alpha max",
    "yaw period", "yaw damping ratio", "settling time", "activity first", "activity second",
    "carrier speed end")
N_MEASURES = len(MEASURES)

def scratch(samples):
    """Work space of :func:`measure` for runs of ``samples`` samples.

    Parameters
    ----------
    samples : int
        Samples of a run. [count]

    Returns
    -------
    ndarray, shape (4, samples)
        Work space. [-]
    """
    return np.empty((4, int(samples)))


@jit
def _clip1(x):
    return -1.0 if x < -1.0 else (1.0 if x > 1.0 else x)


@jit
def derive(time, states, info, weight, mast, chute, out):
    """Derived histories (:data:`HISTORY`) of one run into ``out`` (n, N_HISTORY).

    Parameters
    ----------
    time : ndarray, shape (n,)
        Sampling times. [s]
    states, info : ndarray, shape (n, N), (n, N_INFO)
        States and reported quantities at the samples (NaN after a stop). [SI, rad]
    weight : float
        Weight of the hung system (the tension's reference). [N]
    mast : ndarray, shape (3,)
        Mast axis, body axes (unit). [-]
    chute : bool
        Whether there is a parachute (else its histories are NaN).
    out : ndarray, shape (n, N_HISTORY)
        Receives the histories (:data:`HISTORIES`). [SI, rad]
    """
    n = time.shape[0]
    nan = np.nan
    for k in range(n):
        q0, q1, q2, q3 = states[k, 9], states[k, 10], states[k, 11], states[k, 12]
        r00 = q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3
        r10 = 2 * (q1 * q2 + q0 * q3)
        r20 = 2 * (q1 * q3 - q0 * q2)
        r21 = 2 * (q2 * q3 + q0 * q1)
        r22 = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3
        yaw = math.atan2(-r10, r00)
        # unwrapped below, from the finite yaws (NaN counts as 0 there, as in numpy.unwrap)
        out[k, 4] = yaw if math.isfinite(yaw) else 0.0
        out[k, 5] = -math.asin(_clip1(r20))
        out[k, 6] = math.atan2(-r21, r22)
        if not math.isfinite(q0):  # the rotation of a missing attitude: identity
            q0, q1, q2, q3 = 1.0, 0.0, 0.0, 0.0
            r20 = 2 * (q1 * q3 - q0 * q2)
            r21 = 2 * (q2 * q3 + q0 * q1)
            r22 = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3
        out[k, 0] = time[k]
        out[k, 1], out[k, 2], out[k, 3] = states[k, 3], states[k, 4], states[k, 5]
        out[k, 7] = -(r20 * states[k, 13] + r21 * states[k, 14] + r22 * states[k, 15])
        out[k, 8], out[k, 9], out[k, 10] = info[k, 8], info[k, 9], info[k, 10]
        d0, d1, d2 = info[k, 2], info[k, 3], info[k, 4]
        span = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        out[k, 11] = math.atan2(d0, -d2)
        out[k, 12] = math.atan2(d1, -d2)
        out[k, 13] = math.acos(_clip1(-d2 / span))
        out[k, 14] = info[k, 0]
        out[k, 15] = info[k, 0] / weight
        h0, h1, h2 = info[k, 5], info[k, 6], info[k, 7]
        out[k, 16], out[k, 17], out[k, 18] = h0, h1, h2
        hub = math.sqrt(h0 * h0 + h1 * h1 + h2 * h2)
        along = h0 * mast[0] + h1 * mast[1] + h2 * mast[2]
        out[k, 19] = math.acos(_clip1(along / hub)) if hub > 0 else nan
        if chute:
            out[k, 20] = math.atan2(info[k, 17], info[k, 15])
            out[k, 21] = math.asin(_clip1(info[k, 16]))
            out[k, 22], out[k, 23] = info[k, 13], info[k, 14]
        else:
            out[k, 20] = out[k, 21] = out[k, 22] = out[k, 23] = nan
        v0, v1, v2 = states[k, 0], states[k, 1], states[k, 2]
        out[k, 24] = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
        # (a frozen carrier has no thrust: NaN, as atan2 would give)
        out[k, 25] = (nan if math.isnan(info[k, 18])
                      else math.atan2(-info[k, 18], info[k, 20]))
    # numpy.unwrap of the yaw (discontinuity pi, period 2 pi), then NaN where it is missing
    correction = 0.0
    previous = out[0, 4]
    for k in range(1, n):
        raw = out[k, 4]
        dd = raw - previous
        previous = raw
        fix = 0.0
        if not abs(dd) < math.pi:  # a jump: back into (-pi, pi]
            ddmod = (dd + math.pi) % (2.0 * math.pi) - math.pi
            if ddmod == -math.pi and dd > 0:
                ddmod = math.pi
            fix = ddmod - dd
        correction += fix
        out[k, 4] = raw + correction
    for k in range(n):
        if not math.isfinite(states[k, 9]):
            out[k, 4] = nan


@jit
def damping_from_peaks(time, y, start, buf):
    """Period and damping ratio from the successive positive peaks of ``y`` after
    ``start`` (log decrement, each peak refined by a parabola through it and its neighbours),
    or NaN when there are fewer than three peaks above 2 % of the largest.

    Parameters
    ----------
    time : ndarray, shape (n,)
        Sample times. [s]
    y : ndarray, shape (n,)
        Signal. [any unit]
    start : float
        Peaks from this time on. [s]
    buf : ndarray, shape (4, n)
        Work space (:func:`scratch`). [-]

    Returns
    -------
    period : float
        [s]
    damping_ratio : float
        [-]
    """
    m = 0
    for k in range(time.shape[0]):
        if time[k] >= start and math.isfinite(y[k]):
            buf[0, m], buf[1, m] = time[k], y[k]
            m += 1
    if m < 5:
        return np.nan, np.nan
    t, v = buf[0], buf[1]
    largest, inner = -np.inf, 0
    for i in range(1, m - 1):
        if v[i] > v[i - 1] and v[i] >= v[i + 1] and v[i] > 0:
            inner += 1
            largest = max(largest, v[i])
    if inner == 0:
        return np.nan, np.nan
    h = t[1] - t[0]
    times, values = buf[2], buf[3]
    count = 0
    for i in range(1, m - 1):
        y0, y1, y2 = v[i - 1], v[i], v[i + 1]
        if not (y1 > y0 and y1 >= y2 and y1 > 0 and y1 > 0.02 * largest):
            continue
        # y1 > y0 and y1 >= y2: the samples curve down, the vertex within half a step
        value, shift = _parabola_vertex(y0, y1, y2)
        times[count] = t[i] + shift * h
        values[count] = value
        count += 1
    if count < 3:
        return np.nan, np.nan
    # differences and log decrements over the front of the consumed buffers
    for i in range(count - 1):
        t[i] = times[i + 1] - times[i]
        v[i] = math.log(values[i] / values[i + 1])
    period, delta = 0.0, 0.0
    for i in range(count - 1):
        period += t[i]
        delta += v[i]
    period /= count - 1
    delta /= count - 1
    return period, delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)


@jit
def measure(time, hist, start, end, verdict_start, band_floor, buf, out):
    """Measures (:data:`MEASURES`) of one run's derived histories ``hist`` (n, N_HISTORY).

    Parameters
    ----------
    time : ndarray, shape (n,)
        [s]
    hist : ndarray, shape (n, N_HISTORY)
        :func:`derive`'s histories. [SI, rad]
    start : float
        When the input starts (peaks and RMS values are taken from then on). [s]
    end : float
        When it ends (damping and settling are measured from then on). [s]
    verdict_start : float
        Start of the time whose two halves the verdict's activity compares. [s]
    band_floor : float
        Least half-width of the settling band. [rad]
    buf : ndarray
        :func:`scratch`. [-]
    out : ndarray, shape (N_MEASURES,)
        SI, angles in rad, the activity in deg/s. [SI, rad, deg/s]
    """
    n = time.shape[0]
    for p in range(len(_PEAK_COLUMNS)):
        column, relative = _PEAK_COLUMNS[p], _PEAK_RELATIVE[p]
        best, where = -1.0, -1
        first = hist[0, column] if relative else 0.0
        for k in range(n):
            if time[k] >= start and math.isfinite(hist[k, _YAW]):
                y = hist[k, column] - first
                if abs(y) > best:  # NaN never is
                    best, where = abs(y), k
        if where < 0:
            out[2 * p], out[2 * p + 1] = np.nan, np.nan
        else:
            out[2 * p], out[2 * p + 1] = hist[where, column] - first, time[where]
    i = 2 * len(_PEAK_COLUMNS)
    # RMS of the yaw's change and of the sideslip after the start, NaN-ignoring (nanmean)
    values = buf[0]
    for c in range(2):
        column = _YAW if c == 0 else _BETA
        first = hist[0, column] if c == 0 else 0.0
        m, count = 0, 0
        for k in range(n):
            if time[k] >= start and math.isfinite(hist[k, _YAW]):
                y = hist[k, column] - first
                if math.isfinite(y):
                    values[m] = y * y
                    count += 1
                else:
                    values[m] = 0.0
                m += 1
        total = 0.0
        for k in range(m):
            total += values[k]
        out[i + c] = np.nan if count == 0 else math.sqrt(total / count)
    high, low, slack, first_slack = -np.inf, np.inf, 0, np.nan
    tension_min, alpha_max, speed_end = np.inf, -np.inf, np.nan
    column = _TENSION_RATIO
    for k in range(n):
        ratio = hist[k, column]
        if ratio > high:
            high = ratio
        if ratio < low:
            low = ratio
        if ratio <= 0:
            if slack == 0:
                first_slack = time[k]
            slack += 1
        if hist[k, _LINE_TENSION] < tension_min:
            tension_min = hist[k, _LINE_TENSION]
        if hist[k, _CHUTE_ALPHA] > alpha_max:
            alpha_max = hist[k, _CHUTE_ALPHA]
        if math.isfinite(hist[k, _CARRIER_SPEED]):
            speed_end = hist[k, _CARRIER_SPEED]
    out[i + 2] = high if high > -np.inf else np.nan
    out[i + 3] = low if low < np.inf else np.nan
    out[i + 4] = 1.0 if slack > 0 else 0.0
    out[i + 5] = first_slack
    out[i + 6] = slack * (time[1] - time[0])
    out[i + 7] = tension_min if tension_min < np.inf else np.nan
    out[i + 8] = alpha_max if alpha_max > -np.inf else np.nan
    period, zeta = damping_from_peaks(time, hist[:, _YAW_RATE], end, buf)
    out[i + 9], out[i + 10] = period, zeta
    # settling: the time after the end after which |yaw change - its final value| stays
    # within max(10 % of its largest, band_floor); NaN when it never does
    first = hist[0, _YAW]
    final = hist[n - 1, _YAW] - first
    settling = np.nan
    if math.isfinite(final):
        largest = -np.inf
        for k in range(n):
            dev = abs(hist[k, _YAW] - first - final)
            if dev > largest:  # NaN never is
                largest = dev
        band = 0.1 * largest
        if not band >= band_floor:
            band = band_floor
        last = -1
        for k in range(n):
            if abs(hist[k, _YAW] - first - final) > band:
                last = k
        if last < 0:
            settling = 0.0
        elif last < n - 2:
            settling = max(0.0, time[last + 1] - end)
    out[i + 11] = settling
    # the verdict's activity: the largest of |yaw rate| and the swing angles' |rates|
    # (numpy.gradient: central differences, one-sided at the ends) in deg/s, NaN if any is,
    # over the first and the second half of the time from verdict_start
    dt = time[1] - time[0]
    middle = 0.5 * (verdict_start + time[n - 1])
    first_half, second_half = -np.inf, -np.inf
    for k in range(n):
        if time[k] < verdict_start:
            continue
        a = abs(hist[k, _YAW_RATE])
        for c in range(2):
            column = _SWING_LATERAL if c == 0 else _SWING_LONGITUDINAL
            if k == 0:
                rate = (hist[1, column] - hist[0, column]) / dt
            elif k == n - 1:
                rate = (hist[n - 1, column] - hist[n - 2, column]) / dt
            else:
                rate = (hist[k + 1, column] - hist[k - 1, column]) / (2.0 * dt)
            rate = abs(rate)
            if math.isnan(rate) or math.isnan(a):
                a = np.nan
            elif rate > a:
                a = rate
        a *= 180.0 / math.pi
        if time[k] < middle:
            first_half = a if (math.isnan(a) or math.isnan(first_half)) else max(first_half, a)
        else:
            second_half = (a if (math.isnan(a) or math.isnan(second_half))
                           else max(second_half, a))
    out[i + 12], out[i + 13] = first_half, second_half
    out[i + 14] = speed_end

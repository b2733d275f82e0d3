"""One vocabulary of response verdicts, one envelope test, one settling time.

Every dynamic analysis (the 1-DOF yaw runs of :mod:`~slingloads.analyses.chute_sizing`, the
multibody runs of :mod:`~slingloads.analyses.multibody.simulate`, the campaign and its
transport without parachute) names the outcome of a run with one of :data:`VERDICTS`, by
the same rule, applied to its sampled response:

``outside domain``
    The run left the domain in which its model holds (a table left, a sideslip past the
    model's limit, a slack cable...): the caller says when and why; nothing after that time
    is a result.
``divergent``
    The envelope grows: the half peak-to-peak amplitude over the second half of the observed
    window exceeds :attr:`EnvelopeTest.growth` times that of the first half, and the band.
``limit cycle``
    Neither growth nor decay (within the factors) of an oscillation larger than the band,
    with no input left to sustain it.
``bounded``
    The same under a sustained input (a continuous gust): a forced, bounded response.
``static departure``
    The motion settles (second-half amplitude within the band) or decays, about a value (its
    mean over the second half) more than :attr:`EnvelopeTest.offset` away from the trim: the
    run stays off heading; its size is the offset.
``convergent``
    The motion decays (second-half amplitude below :attr:`EnvelopeTest.decay` times the
    first's) or settles within the band, back within :attr:`EnvelopeTest.offset` of the trim,
    and the least-damped relevant mode of the linear model is stable (checked by the caller,
    which otherwise says ``inconclusive`` with the reason).
``inconclusive``
    Less than :attr:`EnvelopeTest.min_window` seconds observed after the input; or less than
    :attr:`EnvelopeTest.min_periods` periods of the slowest relevant mode of the linear model
    (given by the caller) for a run that neither grows nor has settled about its trim: in a
    window shorter than its period a slowly decaying swing looks like a settled offset or a
    steady oscillation; or a response that decays while the linear model says the mode grows.

No label overrides another: the rules are tried in the order above and the first that holds
is the verdict. A design value (area, angle, speed) is only ever taken from runs whose
verdict is ``convergent`` (or ``bounded`` under a sustained input).

The **settling time** is the time from the input's onset until the signal stays within a
stated band of its trim value; NaN when it never does within the run, and 0 only when it
never left the band (the band is reported beside it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slingloads.errors import InputError

CONVERGENT = "convergent"
STATIC_DEPARTURE = "static departure"
BOUNDED = "bounded"
LIMIT_CYCLE = "limit cycle"
DIVERGENT = "divergent"
OUTSIDE_DOMAIN = "outside domain"
INCONCLUSIVE = "inconclusive"
#: The verdicts of a run, from the best to the worst.
VERDICTS = (CONVERGENT, BOUNDED, STATIC_DEPARTURE, LIMIT_CYCLE, INCONCLUSIVE, DIVERGENT,
            OUTSIDE_DOMAIN)
#: The verdicts of a linear model's eigenvalues (:data:`EIGENVALUE_TOLERANCE`): every real
#: part below minus it, some within it of 0, some above it. A response is convergent or
#: divergent; a linear model (a mode, a trim) is stable, neutral or unstable.
STABLE, NEUTRAL, UNSTABLE = "stable", "neutral", "unstable"
#: Verdicts that meet a stability criterion (``bounded`` only under a sustained input).
ACCEPTED = (CONVERGENT, BOUNDED)
#: A linear mode is stable when the real part of its eigenvalue is below minus this (a real
#: part within it of 0 is neutral): the same rule in the 1-DOF and multibody models. [1/s]
EIGENVALUE_TOLERANCE = 1e-6
#: Largest difference between the damping ratio measured on a response and that of the
#: linear mode it was measured on for the two to agree. [-]
DAMPING_TOLERANCE = 0.05
#: Largest relative difference between the period measured on a response and that of the
#: mode named for it. [-]
PERIOD_TOLERANCE = 0.25
#: Share of a mode's largest angular amplitude above which the yaw takes part in it (the
#: threshold at which a mode's name lists a second motion). [-]
YAW_SHARE = 0.25
#: Why a damping ratio could not be measured, when the caller does not say.
NOT_MEASURED = "fewer than three peaks after the input"


def worst(verdicts):
    """The worst of several verdicts (order of :data:`VERDICTS`).

    Parameters
    ----------
    verdicts : iterable of str
        Verdicts of :data:`VERDICTS` (an unknown label counts as worse than all).

    Returns
    -------
    str
    """
    rank = {v: k for k, v in enumerate(VERDICTS)}
    return max(verdicts, key=lambda v: rank.get(v, len(VERDICTS)))


@dataclass(frozen=True)
class EnvelopeTest:
    """The envelope test of a response (module notes).

    Parameters
    ----------
    growth : float
        Second-half over first-half amplitude above which the envelope grows, > 1. [-]
    decay : float
        Ratio below which it decays, 0 < decay < 1. [-]
    band : float
        Half peak-to-peak amplitude within which a response has settled, > 0. [rad]
    offset : float
        Distance of the settled value from the trim beyond which the run is a static
        departure, > 0. [rad]
    min_window : float
        Least observed time after the input for a verdict, > 0. [s]
    min_periods : float
        Least observed time, in periods of the slowest relevant mode (when the caller gives
        it), for any verdict but divergent or convergent within the band, > 0. [-]
    """

    growth: float = 1.1
    decay: float = 0.9
    band: float = math.radians(1.0)
    offset: float = math.radians(1.0)
    min_window: float = 10.0
    min_periods: float = 2.0

    def __post_init__(self):
        for name in ("growth", "decay", "band", "offset", "min_window", "min_periods"):
            value = float(getattr(self, name))
            if not math.isfinite(value) or value <= 0:
                raise InputError(f"envelope test {name} must be > 0", value)
            object.__setattr__(self, name, value)
        if not self.decay < 1 < self.growth:
            raise InputError("envelope test: decay < 1 < growth", (self.decay, self.growth))

    def rule(self, what="the signal"):
        """The rule in words, with its numbers.

        Parameters
        ----------
        what : str
            The signal tested, as the sentence names it.

        Returns
        -------
        str
            The rule, its factors [-], band and offset [deg] and least window [s].
        """
        return (f"envelope test on {what} over the time after the input ends (after its onset "
                f"for a sustained input), in two halves: divergent if the second half's half "
                f"peak-to-peak amplitude is > {self.growth:g} x the first's and > "
                f"{math.degrees(self.band):.3g} deg; settled if it is <= "
                f"{math.degrees(self.band):.3g} deg, decaying if < {self.decay:g} x the "
                f"first's; a settled or decaying run centred more than "
                f"{math.degrees(self.offset):.3g} deg from its trim is a static departure, "
                f"else convergent (if its linear mode is stable); otherwise limit cycle "
                f"(bounded under a sustained input); inconclusive with less than "
                f"{self.min_window:g} s observed, or, unless divergent or settled about its "
                f"trim, less than {self.min_periods:g} periods of the slowest relevant mode")


@dataclass(frozen=True)
class Envelope:
    """Envelope of a batch of responses (arrays of shape (runs,)).

    Attributes
    ----------
    verdict : ndarray of str
    first, second : ndarray
        Half peak-to-peak amplitude over the first and the second half of the window. [rad]
    offset : ndarray
        Mean over the second half minus the trim. [rad]
    window : ndarray
        Time observed after the input. [s]
    period : ndarray
        Period of the slowest relevant mode, NaN when not given. [s]
    test : EnvelopeTest, optional
        The test applied (its band and factors are quoted in the reasons).
    """

    verdict: np.ndarray
    first: np.ndarray
    second: np.ndarray
    offset: np.ndarray
    window: np.ndarray
    period: np.ndarray
    test: EnvelopeTest | None = None

    def reason(self, j, what="sideslip"):
        """Why run ``j`` got its envelope verdict, with its numbers.

        Parameters
        ----------
        j : int
            Index of the run. [-]
        what : str
            The signal tested, as the sentence names it.

        Returns
        -------
        str
            Its amplitudes over the two halves and its offset from trim, in [deg].
        """
        d = math.degrees
        v = str(self.verdict[j])
        a1, a2, off = d(self.first[j]), d(self.second[j]), d(self.offset[j])
        if v == INCONCLUSIVE:
            w, period = float(self.window[j]), float(self.period[j])
            centred = f", centred {off:+.3g} deg from trim" if np.isfinite(off) else ""
            if np.isfinite(a1) and np.isfinite(a2) and np.isfinite(period):
                return (f"{w:.3g} s observed after the input, {w / period:.2g} periods of "
                        f"the slowest relevant mode ({seconds_words(period)} s), and the "
                        f"{what} neither grows "
                        f"nor has settled about its trim ({a1:.3g} -> {a2:.3g} deg over the "
                        f"two halves{centred}): run longer")
            return f"too little time observed after the input ({w:.3g} s)"
        amp = f"{what} amplitude {a1:.3g} -> {a2:.3g} deg over the two halves"
        if self.test is not None and v in (CONVERGENT, STATIC_DEPARTURE):
            # which rule held: a response that grows inside the band has settled, not decayed
            band = d(self.test.band)
            amp += (f" (settled: within the {band:.3g} deg band)" if a2 <= band
                    else f" (decaying: below {self.test.decay:g} x)")
        if v == STATIC_DEPARTURE:
            return f"{amp}; settles {off:+.3g} deg from trim (static departure)"
        if not np.isfinite(off):  # a signal tested without a trim value (a swing angle)
            return amp
        return f"{amp}; centred {off:+.3g} deg from trim"


def envelope(time, y, start, reference, sustained, test=None, period=None):
    """Envelope verdict of a batch of responses (module notes). NaN samples (after a stop)
    are ignored.

    Parameters
    ----------
    time : array_like, shape (n,)
        Sample times. [s]
    y : array_like, shape (runs, n)
        The responses (the sideslip, a yaw angle...). [rad]
    start : float or array_like, shape (runs,)
        When each run's observed window starts (the input's end, or its onset for a
        sustained input). [s]
    reference : float or array_like, shape (runs,)
        Each run's trim value. [rad]
    sustained : bool or array_like, shape (runs,)
        Whether the run's input is sustained (a continuous gust).
    test : EnvelopeTest, optional
        The factors, band, offset and least window (default :class:`EnvelopeTest`).
    period : float or array_like, shape (runs,), optional
        Period of the slowest relevant mode of each run's linear model (NaN or None: not
        known, no check). [s]

    Returns
    -------
    Envelope
        Verdict, half amplitudes over the two halves [rad] and offset from trim [rad].
    """
    test = EnvelopeTest() if test is None else test
    time = np.asarray(time, float)
    y = np.atleast_2d(np.asarray(y, float))
    runs = y.shape[0]
    start = np.broadcast_to(np.asarray(start, float), (runs,))
    reference = np.broadcast_to(np.asarray(reference, float), (runs,))
    sustained = np.broadcast_to(np.asarray(sustained, bool), (runs,))
    finite = np.isfinite(y)
    last = np.where(finite.any(axis=1),
                    time[np.clip(finite.shape[1] - 1 - np.argmax(finite[:, ::-1], axis=1), 0,
                                 None)], np.nan)
    middle = 0.5 * (start + last)
    inside = (time[None, :] >= start[:, None]) & finite
    one = inside & (time[None, :] < middle[:, None])
    two = inside & (time[None, :] >= middle[:, None])

    def half_range(mask):
        with np.errstate(invalid="ignore", divide="ignore"):
            hi = np.max(np.where(mask, y, -np.inf), axis=1)
            lo = np.min(np.where(mask, y, np.inf), axis=1)
            mean = np.sum(np.where(mask, y, 0.0), axis=1) / mask.sum(axis=1)
        ok = mask.any(axis=1)
        return np.where(ok, 0.5 * (hi - lo), np.nan), np.where(ok, mean, np.nan)

    a1, _ = half_range(one)
    a2, centre = half_range(two)
    offset = centre - reference
    window = last - start
    period = np.broadcast_to(np.asarray(np.nan if period is None else period, float),
                             (runs,))
    short = ~(window >= test.min_window) | ~np.isfinite(a1) | ~np.isfinite(a2)
    grows = (a2 > test.growth * a1) & (a2 > test.band)
    settles = (a2 <= test.band) | (a2 < test.decay * a1)
    off = np.abs(offset) > test.offset
    slow = np.isfinite(period) & (window < test.min_periods * period)
    centred = (a2 <= test.band) & ~off
    verdict = np.select(
        [short, grows, slow & ~centred, settles & off, settles, sustained],
        [INCONCLUSIVE, DIVERGENT, INCONCLUSIVE, STATIC_DEPARTURE, CONVERGENT, BOUNDED],
        default=LIMIT_CYCLE)
    return Envelope(verdict.astype(object), a1, a2, offset, window, period, test)


def settling_time(time, y, onset, reference, band):
    """Time from the input's onset until ``|y - reference|`` stays within ``band``.

    Parameters
    ----------
    time : array_like, shape (n,)
        Sample times. [s]
    y : array_like, shape (runs, n)
        The responses. [rad]
    onset : float or array_like, shape (runs,)
        The input's onset. [s]
    reference : float or array_like, shape (runs,)
        Trim values. [rad]
    band : float or array_like, shape (runs,)
        Half width of the band about the trim. [rad]

    Returns
    -------
    ndarray, shape (runs,)
        The settling time: NaN when the last sample is outside the band (or NaN), 0 when no
        sample after the onset ever left it. [s]
    """
    time = np.asarray(time, float)
    y = np.atleast_2d(np.asarray(y, float))
    runs = y.shape[0]
    onset = np.broadcast_to(np.asarray(onset, float), (runs,))
    reference = np.broadcast_to(np.asarray(reference, float), (runs,))
    band = np.broadcast_to(np.asarray(band, float), (runs,))
    after = time[None, :] >= onset[:, None]
    with np.errstate(invalid="ignore"):
        outside = after & ~(np.abs(y - reference[:, None]) <= band[:, None])
    n = time.size
    any_out = outside.any(axis=1)
    last = n - 1 - np.argmax(outside[:, ::-1], axis=1)
    out = np.where(any_out, np.nan, 0.0)
    ends = any_out & (last < n - 1)
    out[ends] = time[last[ends] + 1] - onset[ends]
    return out


def damping_check(measured, period, mode_zeta, mode_period, mode_name, reason=NOT_MEASURED):
    """Whether a damping ratio measured on a response agrees with the linear mode it was
    measured on (:data:`DAMPING_TOLERANCE`, periods within :data:`PERIOD_TOLERANCE`), in
    words.

    Parameters
    ----------
    measured : float
        Damping ratio from the response's logarithmic decrement (NaN: not measured). [-]
    period : float
        Period measured on the response. [s]
    mode_zeta : float
        Damping ratio of the linear mode. [-]
    mode_period : float
        Period of the linear mode (NaN for a real root). [s]
    mode_name : str
        Name of the mode ("" when there is none).
    reason : str, optional
        Why the damping could not be measured (used when ``measured`` is NaN).

    Returns
    -------
    str
    """
    if not (math.isfinite(measured) and math.isfinite(period)):
        return f"not measured ({reason})"
    if not mode_name:
        return "no linear mode to compare with"
    if math.isfinite(mode_period) and abs(period - mode_period) > PERIOD_TOLERANCE * mode_period:
        return (f"period {seconds_words(period)} s matches no mode within "
                f"{PERIOD_TOLERANCE:.0%} (nearest: {mode_name}, {seconds_words(mode_period)} s): "
                "a mixed or nonlinear response")
    diff = measured - mode_zeta
    if abs(diff) <= DAMPING_TOLERANCE:
        return (f"agrees with the {mode_name} mode (zeta {ratio_words(mode_zeta)}, within "
                f"{DAMPING_TOLERANCE:g})")
    return (f"differs from the {mode_name} mode (zeta {ratio_words(mode_zeta)}) by "
            f"{ratio_words(diff, sign=True)} > "
            f"{DAMPING_TOLERANCE:g}: amplitude-dependent (nonlinear) or several modes")


def response_mode(period, zeta, modes, whose="", reason=NOT_MEASURED):
    """The mode a response's damping was measured on, and the check against it, in words:
    the one place that names the mode (:func:`nearest_mode`) and judges the agreement
    (:func:`damping_check`), so that the two statements cannot disagree. A mode whose period
    is not within :data:`PERIOD_TOLERANCE` of the response's is never named as the mode
    measured on ("none" with the nearest one).

    Parameters
    ----------
    period : float
        Period measured on the response. [s]
    zeta : float
        Damping ratio measured on the response (NaN: not measured). [-]
    modes : pandas.DataFrame or None
        The linear model's :meth:`LinearModel.modes_frame` (None: no model to compare with).
    whose : str, optional
        Which trim the modes are of, appended to the mode's name (e.g. " of the trim at the
        ramp's final airspeed").
    reason : str, optional
        Why the damping could not be measured (used when ``zeta`` is NaN).

    Returns
    -------
    tuple of (str, str)
        (measured on mode, damping check).

    Examples
    --------
    >>> import pandas as pd
    >>> modes = pd.DataFrame({"mode": ["yaw", "roll"], "period [s]": [14.6, 1.44],
    ...                       "damping ratio [-]": [0.155, 0.0014]})
    >>> response_mode(2.08, 0.03, modes)[0]
    'none within 25% (nearest: roll, 1.44 s)'
    >>> response_mode(1.62, 0.0015, modes)[0]
    'roll (1.44 s, zeta 0.001)'
    """
    name, mode_zeta, mode_period = nearest_mode(period, modes, zeta)
    check = damping_check(zeta, period, mode_zeta, mode_period, name, reason)
    if not math.isfinite(period) and modes is not None and len(modes) == 1:
        check = f"not measured on the {modes['mode'].iloc[0]} mode{whose} ({reason})"
    if not name or not (math.isfinite(zeta) and math.isfinite(period)):
        return "", check
    if math.isfinite(mode_period) and abs(period - mode_period) > PERIOD_TOLERANCE * mode_period:
        return (f"none within {PERIOD_TOLERANCE:.0%} (nearest: {name}{whose}, "
                f"{seconds_words(mode_period)} s)", check)
    label = f"{name}{whose} ({seconds_words(mode_period)} s, zeta {ratio_words(mode_zeta)})"
    return label, check


def yaw_mode(modes):
    """The yaw mode of a linear model: the least damped of the modes in which the yaw takes
    part (yaw amplitude at least :data:`YAW_SHARE` of the mode's largest angular amplitude).
    The pendulum modes of cable and airframe are lightly damped whatever the parachute; the
    yaw modes are those the parachute sizes, and the least damped of them is the one a
    stability criterion reads.

    Parameters
    ----------
    modes : pandas.DataFrame or None
        A :meth:`LinearModel.modes_frame` (columns ``mode``, ``damping ratio [-]``,
        ``yaw amplitude [-]``...).

    Returns
    -------
    pandas.DataFrame
        Its row (one row), or no row when there is no such mode.
    """
    if modes is None or len(modes) == 0:
        return modes
    finite = modes[np.isfinite(modes["damping ratio [-]"])]  # a zero eigenvalue has none
    yaw = finite[finite["yaw amplitude [-]"] >= YAW_SHARE]
    if len(yaw) == 0:
        return yaw
    return yaw.loc[[yaw["damping ratio [-]"].idxmin()]]


def slowest_period(modes, group="yaw"):
    """Period of the slowest oscillatory mode of a linear model in which ``group`` takes part
    (its angular amplitude at least half the largest group's in that mode).

    Parameters
    ----------
    modes : pandas.DataFrame or None
        One row per mode with ``period [s]`` and ``<group> amplitude [-]`` columns (the
        multibody model's ``modes_frame()``).
    group : str
        ``"yaw"``, ``"lateral"``, ``"longitudinal"`` or ``"parachute"``.

    Returns
    -------
    float
        [s]; NaN without modes or without such an oscillatory mode.
    """
    if modes is None or len(modes) == 0:
        return float("nan")
    amp = modes[[c for c in modes.columns if c.endswith(" amplitude [-]")]]
    takes_part = modes[f"{group} amplitude [-]"] >= 0.5 * amp.max(axis=1)
    period = modes["period [s]"].where(takes_part & np.isfinite(modes["period [s]"]))
    return float(period.max()) if period.notna().any() else float("nan")


def nearest_mode(period, modes, zeta=float("nan")):
    """The mode a response was measured on: among the modes whose period lies within
    :data:`PERIOD_TOLERANCE` of the response's, the one of nearest damping ratio; else the
    mode of nearest period.

    Parameters
    ----------
    period : float
        Period measured on the response. [s]
    modes : pandas.DataFrame or None
        A :meth:`LinearModel.modes_frame` (columns ``mode``, ``period [s]``,
        ``damping ratio [-]``).
    zeta : float, optional
        Damping ratio measured on the response. [-]

    Returns
    -------
    tuple of (str, float, float)
        Name, damping ratio [-] and period [s] of the mode; ("", NaN, NaN) when there is
        none.
    """
    if modes is None or len(modes) == 0 or not math.isfinite(period):
        return "", float("nan"), float("nan")
    periods = np.asarray(modes["period [s]"], float)
    ok = np.isfinite(periods)
    if not ok.any():
        return "", float("nan"), float("nan")
    distance = np.where(ok, np.abs(np.log(np.where(ok, periods, 1.0) / period)), np.inf)
    with np.errstate(invalid="ignore"):  # a real root (period inf) is never near
        near = ok & (np.abs(np.where(ok, periods, 0.0) - period)
                     <= PERIOD_TOLERANCE * np.where(ok, periods, 0.0))
    if near.sum() > 1 and math.isfinite(zeta):
        gap = np.abs(np.asarray(modes["damping ratio [-]"], float) - zeta)
        k = int(np.argmin(np.where(near, gap, np.inf)))
    else:
        k = int(np.argmin(distance))
    return (str(modes["mode"].iloc[k]), float(modes["damping ratio [-]"].iloc[k]),
            float(periods[k]))


def seconds_words(value):
    """A mode's period (or another time) for a sentence, at the precision of a time's cell
    (0.00 s), so that a verdict's words and the period cells beside it quote one number:
    the yaw mode's 27.0185 s reads "27.02" as its cell, never "27".

    Parameters
    ----------
    value : float
        [s]

    Returns
    -------
    str

    Examples
    --------
    >>> seconds_words(27.0185), seconds_words(8.08), seconds_words(44.8)
    ('27.02', '8.08', '44.80')
    """
    return f"{float(value):.2f}"


def ratio_words(value, sign=False):
    """A damping ratio (or another ratio) for a sentence, at the precision of a ratio's cell
    (0.000), so that a verdict's words and the cells beside it quote one number for one
    damping ratio: 0.0691 reads "0.069" as its cell; a ratio too small for that precision
    (below 0.0005, not zero) in the cells' scientific notation.

    Parameters
    ----------
    value : float
        [-]
    sign : bool
        Write the sign of a positive value too (a difference).

    Returns
    -------
    str

    Examples
    --------
    >>> ratio_words(0.0691), ratio_words(0.16), ratio_words(-0.181, sign=True)
    ('0.069', '0.160', '-0.181')
    >>> ratio_words(0.0913, sign=True), ratio_words(2.35e-05)
    ('+0.091', '2.35E-05')
    """
    value = float(value)
    plus = "+" if sign else ""
    if value != 0.0 and abs(value) < 5e-4:
        return f"{value:{plus}.2E}"
    return f"{value:{plus}.3f}"


__all__ = ["ACCEPTED", "BOUNDED", "CONVERGENT", "DAMPING_TOLERANCE", "DIVERGENT",
           "EIGENVALUE_TOLERANCE", "INCONCLUSIVE", "LIMIT_CYCLE", "NEUTRAL", "NOT_MEASURED",
           "OUTSIDE_DOMAIN", "PERIOD_TOLERANCE", "STABLE", "STATIC_DEPARTURE", "UNSTABLE",
           "VERDICTS", "YAW_SHARE", "Envelope", "EnvelopeTest", "damping_check", "envelope",
           "nearest_mode", "ratio_words", "response_mode", "seconds_words", "settling_time",
           "slowest_period", "worst", "yaw_mode"]

"""Peak values of lateral-pendulum runs, found between the samples.

A run's design quantities are peaks of sampled signals: the load angle theta1 - theta2 and
the rope angle while the cable carries load, the tension factor T/(m g) and the cable's
lateral pull on the hook. Each peak is refined by the parabola through the three samples
around it (:func:`~slingloads.models.sampled_peak.refine_peak`, the one the compiled sweep
uses), except across a kink (the cable going slack, a jump of the hook's acceleration), where a
parabola would overshoot. :class:`RunMetrics` holds them, for one run or as arrays over many.

References
----------
.. [1] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993 (dense output, section II.6).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.models.pendulum import load_angle
from slingloads.models.sampled_peak import refine_peak


def _peak(t, y, valid=None, smooth=None):
    """Largest value of a sampled signal ``y`` (last axis) with its time, parabola-refined.

    Parameters
    ----------
    t : ndarray, shape (n,)
        Equally spaced times. [s]
    y : ndarray, shape (..., n)
    valid : ndarray of bool, shape (..., n), optional
        Samples that count (default all).
    smooth : ndarray of bool, shape (..., n), optional
        Samples where the signal is smooth (default ``valid``); a peak is refined only where
        its three samples are smooth and count (a parabola through a kink, such as the cable
        going slack, would overshoot).

    Returns
    -------
    value, time : ndarray, shape (...)
        NaN where no sample counts.
    """
    y = np.asarray(y, dtype=float)
    valid = np.ones(y.shape, bool) if valid is None else np.broadcast_to(valid, y.shape)
    ok = valid if smooth is None else valid & np.broadcast_to(smooth, y.shape)
    h = t[1] - t[0]
    masked = np.where(valid, y, -np.inf)
    i = np.argmax(masked, axis=-1)
    value = np.take_along_axis(masked, i[..., None], axis=-1)[..., 0]
    time = t[i]
    y0, y1, y2 = y[..., :-2], y[..., 1:-1], y[..., 2:]
    local = (y1 >= y0) & (y1 >= y2) & ok[..., :-2] & ok[..., 1:-1] & ok[..., 2:]
    refined, offset = refine_peak(y0, y1, y2)
    refined = np.where(local, refined, -np.inf)
    j = np.argmax(refined, axis=-1)
    best = np.take_along_axis(refined, j[..., None], axis=-1)[..., 0]
    off = np.take_along_axis(offset, j[..., None], axis=-1)[..., 0]
    better = best > value
    none = ~np.any(valid, axis=-1)
    return (np.where(none, np.nan, np.where(better, best, value)),
            np.where(none, np.nan, np.where(better, t[1:-1][j] + off * h, time)))


@dataclass(frozen=True, eq=False)
class RunMetrics:
    """Peak values of one run, or of many runs as arrays of shape (runs,).

    Parameters
    ----------
    max_load_angle : max |theta1 - theta2| while the cable carries load (T > 0): the
        largest angle of the hub load from the mast. [rad]
    t_max_load_angle : when it occurs [s]
    max_rope_angle : max |theta1| while the cable carries load. [rad]
    t_max_rope_angle : [s]
    max_tension_ratio : max T/(m g) [-]
    t_max_tension_ratio : [s]
    min_tension_ratio : min T/(m g) [-]; <= 0 means the cable went slack. The elastic
        cable then carries no load until it snatches taut again; the rigid-rope model is not
        valid after the first time its tension goes negative (such runs are flagged
        ``slack``; use the elastic cable for them).
    max_side_force_ratio : max over the run of the cable's lateral force on the hook over
        the load's weight, max(T, 0) |sin theta1| / (m g). [-]
    t_max_side_force_ratio : [s]
    """

    max_load_angle: np.ndarray
    t_max_load_angle: np.ndarray
    max_rope_angle: np.ndarray
    t_max_rope_angle: np.ndarray
    max_tension_ratio: np.ndarray
    t_max_tension_ratio: np.ndarray
    min_tension_ratio: np.ndarray
    max_side_force_ratio: np.ndarray
    t_max_side_force_ratio: np.ndarray

    @property
    def slack(self):
        """True where the cable went slack (tension reached zero or below)."""
        return np.asarray(self.min_tension_ratio) <= 0

    def to_dict(self):
        """Metrics with unit-labelled keys, angles in degrees.

        Returns
        -------
        dict
            The metrics by unit-labelled key (deg, s, -).
        """
        return {
            "max |theta1 - theta2| [deg]": np.degrees(self.max_load_angle),
            "t at max |theta1 - theta2| [s]": self.t_max_load_angle,
            "max |theta1| [deg]": np.degrees(self.max_rope_angle),
            "t at max |theta1| [s]": self.t_max_rope_angle,
            "max T/(m g) [-]": self.max_tension_ratio,
            "t at max T/(m g) [s]": self.t_max_tension_ratio,
            "min T/(m g) [-]": self.min_tension_ratio,
            "slack [-]": self.slack,
            "max T sin|theta1| / (m g) [-]": self.max_side_force_ratio,
            "t at max T sin|theta1| / (m g) [s]": self.t_max_side_force_ratio,
        }

    @classmethod
    def from_histories(cls, t, angle, rope_angle_, tension_ratio, rigid=False,
                       breakpoints=()):
        """Metrics of sampled time histories (last axis = time).

        ``angle`` is theta1 - theta2 (wrapped here to [-pi, pi)). For the rigid rope
        (``rigid=True``) the angles count only until the tension first goes negative, after
        which that model is not valid. No peak is refined by a parabola across one of the
        ``breakpoints`` [s] (where S'' and so the tension jump).

        Parameters
        ----------
        t : ndarray, shape (n,)
            Sample times. [s]
        angle : ndarray, shape (..., n)
            theta1 - theta2. [rad]
        rope_angle_ : ndarray, shape (..., n)
            Rope angle theta1. [rad]
        tension_ratio : ndarray, shape (..., n)
            Cable tension over the load's weight, T / (m g). [-]
        rigid : bool
            The rigid rope (angles count only while it pulls).
        breakpoints : sequence of float
            Times at which S'' jumps. [s]

        Returns
        -------
        RunMetrics
        """
        taut = np.asarray(tension_ratio) > 0
        if rigid:
            taut = np.logical_and.accumulate(taut, axis=-1)
        smooth = taut.copy()
        for b in breakpoints:
            smooth[..., 1:-1] &= ~((t[:-2] < b) & (b <= t[2:]))
        a, ta = _peak(t, np.abs(load_angle(angle, 0.0)), taut, smooth)
        a = np.minimum(a, np.pi)  # a parabola through the wrap at pi must not pass it
        r, tr = _peak(t, np.abs(rope_angle_), taut, smooth)
        n, tn = _peak(t, tension_ratio, smooth=smooth)
        low, _ = _peak(t, -np.asarray(tension_ratio), smooth=smooth)
        side, ts = _peak(t, np.maximum(tension_ratio, 0.0) * np.abs(np.sin(rope_angle_)),
                         smooth=smooth)
        values = [a, ta, r, tr, n, tn, -low, side, ts]
        if np.ndim(a) == 0:  # one run: plain floats
            values = [float(v) for v in values]
        return cls(*values)

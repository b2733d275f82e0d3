"""The one verdict vocabulary and its envelope test (slingloads.analyses.verdicts), checked
on closed-form responses: a damped oscillator x = A exp(-zeta w t) cos(w_d t) (amplitude ratio
over a half window T: exp(-zeta w T)), an undamped one, a growing one, one decaying onto an
offset, and the settling time of an exponential decay, t_s = ln(A / band) / sigma."""

from __future__ import annotations

import math

import numpy as np
import pytest

from slingloads.analyses import verdicts as vd

T = np.arange(0.0, 60.0 + 1e-9, 0.01)
W = 2 * np.pi / 4.0  # 4 s period


A10 = np.radians(10.0)


def _osc(sigma, offset=0.0, amplitude=A10):
    return offset + amplitude * np.exp(sigma * T) * np.cos(W * T)


def test_envelope_names_the_closed_form_responses():
    """Decay sigma = -0.05 1/s (ratio exp(-0.05 x 30) = 0.22 < 0.9) is convergent about 0; the
    same about a 5 deg offset is a static departure of 5 deg; sigma = 0 (ratio 1) a limit cycle,
    or bounded under a sustained input; sigma = +0.02 (ratio 1.8 > 1.1) divergent; a window
    under 10 s inconclusive. No label overrides another: the verdicts are distinct."""
    ys = np.vstack([_osc(-0.05), _osc(-0.05, np.radians(5.0)), _osc(0.0), _osc(0.0),
                    _osc(0.02), _osc(-0.05)])
    start = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 55.0])
    sustained = np.array([False, False, False, True, False, False])
    env = vd.envelope(T, ys, start, 0.0, sustained)
    assert list(env.verdict) == ["convergent", "static departure", "limit cycle", "bounded",
                                 "divergent", "inconclusive"]
    # mid-range of a decaying oscillation: biased by the decay over half a period
    # (2.2 deg x (1 - exp(-0.05 x 2)) / 2 = 0.1 deg)
    assert np.degrees(env.offset[1]) == pytest.approx(5.0, abs=0.15)
    # the halves' amplitudes: 10 deg x exp(sigma t) at the start of each half
    assert np.degrees(env.second[0] / env.first[0]) == pytest.approx(
        np.degrees(math.exp(-0.05 * 30.0)), rel=0.05)
    assert "static departure" in env.reason(1)


def test_a_window_shorter_than_the_slowest_mode_is_inconclusive():
    """A lightly damped 80 s-period swing, x = 10 deg exp(-0.005 t) sin(w t), seen for a third
    of its period (26.7 s): the first half spans the phases [0, pi/3] (half range
    sin(pi/3) / 2 = 0.43 x 10 deg), the second [pi/3, 2pi/3] about the crest (half range
    (1 - sin(pi/3)) / 2 = 0.07 x 10 deg, centred near 8.6 deg), so the envelope alone reads a
    decay onto an 8.6 deg offset: a static departure. Told the mode's period, the test says
    inconclusive, with the window in periods; over 400 s (5 periods) the same swing is
    convergent. A growth stays divergent however short the window (the conservative side),
    and a response settled about its trim stays convergent."""
    w = 2 * np.pi / 80.0
    t = np.arange(0.0, 400.0 + 1e-9, 0.05)
    swing = A10 * np.exp(-0.005 * t) * np.sin(w * t)
    short = t <= 80.0 / 3
    blind = vd.envelope(t[short], swing[short], 0.0, 0.0, False)
    assert blind.verdict[0] == "static departure"
    # mean of sin over [pi/3, 2pi/3]: 3 / pi, times the decay exp(-0.005 x 20 s) mid-half
    assert np.degrees(blind.offset[0]) == pytest.approx(10 * 3 / np.pi * np.exp(-0.1), abs=0.05)
    told = vd.envelope(t[short], swing[short], 0.0, 0.0, False, period=80.0)
    assert told.verdict[0] == "inconclusive"
    assert "0.33 periods of the slowest relevant mode (80.00 s)" in told.reason(0)
    assert vd.envelope(t, swing, 0.0, 0.0, False, period=80.0).verdict[0] == "convergent"
    grows = A10 * np.exp(0.05 * t[short]) * np.sin(2 * np.pi / 4.0 * t[short])
    settled = 0.1 * A10 * np.exp(-0.5 * t[short]) * np.cos(2 * np.pi / 4.0 * t[short])
    env = vd.envelope(t[short], np.vstack([grows, settled]), 5.0, 0.0, False, period=80.0)
    assert list(env.verdict) == ["divergent", "convergent"]


def test_slowest_period_takes_the_modes_of_the_group():
    """Of three modes (yaw 14.6 s, lateral swing 8.6 s with a small yaw part, an aperiodic
    one), the slowest in which yaw takes part (amplitude at least half the largest) is the
    14.6 s mode; for the lateral group the 8.6 s mode; none without modes."""
    import pandas as pd
    modes = pd.DataFrame({"period [s]": [14.6, 8.6, np.inf],
                          "yaw amplitude [-]": [1.0, 0.1, 1.0],
                          "lateral amplitude [-]": [0.3, 1.0, 0.0],
                          "longitudinal amplitude [-]": [0.0, 0.0, 0.0],
                          "parachute amplitude [-]": [0.0, 0.0, 0.0]})
    assert vd.slowest_period(modes, "yaw") == 14.6
    assert vd.slowest_period(modes, "lateral") == 8.6
    assert math.isnan(vd.slowest_period(None))


def test_settling_time_of_an_exponential_decay():
    """y = A exp(-sigma t) leaves a band b for the last time at t = ln(A / b) / sigma; a
    signal that never leaves the band settles at 0; one that ends outside never settles."""
    a, sigma, band = np.radians(8.0), 0.2, np.radians(1.0)
    y = np.vstack([a * np.exp(-sigma * T), np.full(T.size, 0.5 * band),
                   a * np.ones(T.size)])
    t_s = vd.settling_time(T, y, 0.0, 0.0, band)
    assert t_s[0] == pytest.approx(math.log(a / band) / sigma, abs=0.011)
    assert t_s[1] == 0.0 and np.isnan(t_s[2])


def test_worst_and_damping_check():
    """The worst verdict follows the stated order; a damping ratio measured within 0.05 of its
    mode's agrees, one 0.1 away does not, and a period matching no mode says so."""
    assert vd.worst(["convergent", "static departure", "limit cycle"]) == "limit cycle"
    assert vd.worst(["divergent", "outside domain"]) == "outside domain"
    assert vd.damping_check(0.21, 4.0, 0.2, 4.1, "yaw").startswith("agrees")
    assert vd.damping_check(0.31, 4.0, 0.2, 4.1, "yaw").startswith("differs")
    assert vd.damping_check(0.2, 1.6, 0.2, 14.6, "yaw").startswith("period 1.60 s matches no")


def test_the_mode_measured_on_and_its_check_agree():
    """verdicts.response_mode against the rule stated in its docstring, on a hand-made modes
    table: a response whose period is within 25 % of a mode's is measured on that mode and the
    check compares with it; one whose period matches no mode names none (never the nearest
    as the mode measured on) and the check says so; a real root (period inf) is never within
    the tolerance of a measured period."""
    import pandas as pd

    modes = pd.DataFrame({"mode": ["yaw", "roll", "yaw 2"],
                          "period [s]": [14.6, 1.44, np.inf],
                          "damping ratio [-]": [0.155, 0.0014, 1.0]})
    on, check = vd.response_mode(1.62, 0.0015, modes)
    assert on.startswith("roll (1.44 s") and check.startswith("agrees with the roll mode")
    on, check = vd.response_mode(2.08, 0.03, modes)
    assert on.startswith("none within 25%") and "matches no mode" in check
    on, check = vd.response_mode(14.5, 0.0005, modes)  # the real root's zeta 1 is not near
    assert on.startswith("yaw (14.60 s") and check.startswith("differs from the yaw mode")
    assert vd.nearest_mode(14.5, modes.iloc[[0, 2]], 1.0)[0] == "yaw"
    assert vd.response_mode(np.nan, np.nan, modes) == (
        "", "not measured (fewer than three peaks after the input)")
    assert vd.response_mode(3.0, 0.1, None) == ("", "no linear mode to compare with")


def test_eigenvalue_test_does_what_its_docstring_says():
    """LinearModel.stable: every real part below -1e-6 1/s (the documented tolerance); a real
    part of +1e-7 (within round-off of 0) is neutral, not stable, and +1e-3 unstable."""
    from slingloads.analyses.multibody.trim import LinearModel

    def model(*values):
        return LinearModel(None, None, (), np.array(values, dtype=complex), None)

    assert model(-1.0, -2e-6).stable and model(-1.0, -2e-6).verdict() == "stable"
    assert not model(-1.0, 1e-7).stable and model(-1.0, 1e-7).verdict() == "neutral"
    assert not model(-1.0, -5e-7).stable
    assert not model(-1.0, 1e-3).stable and model(-1.0, 1e-3).verdict() == "unstable"


def test_one_dof_verdicts_about_the_neutral_area():
    """Linear tables (Cn = -0.4 beta, fin CY = -3 beta) so the fitted and local slopes agree
    and the neutral area is exact: at it the yaw stiffness k is zero, no moment restores the
    heading and the linear mode is neutral, so the run is not convergent although the gust's
    sideslip dies with the gust (inconclusive, k printed); 10 % below it k < 0 and the heading
    departs (static departure, divergent or outside the domain, never convergent); at 1.5 x
    k > 0 and c > 0: convergent. One rule, no override (no 'neutral' label)."""
    from slingloads.analyses.chute_sizing import neutral_area, run_yaw
    from slingloads.models.gusts import FiniteGust
    from slingloads.models.integration import SolverSettings
    from tests.test_yaw_dynamics import linear_model

    model = linear_model()
    static = neutral_area(model)
    assert static.area_fit == pytest.approx(static.area_local, rel=1e-9)
    areas = np.array([1.0, 0.9, 1.5]) * static.area
    runs = run_yaw(model, areas, FiniteGust(2.0, 5.0, 5.0),
                   SolverSettings(t_end=80.0)).to_frame()
    assert runs["verdict"][0] == "inconclusive"
    assert "linear yaw mode (local slopes) not stable" in runs["verdict reason"][0]
    assert runs["verdict"][1] in ("static departure", "divergent", "outside domain")
    assert runs["verdict"][2] == "convergent"
    assert "neutral" not in set(runs["verdict"])


def test_reason_says_which_rule_made_it_convergent():
    """A response that grows inside the band (0.2 -> 0.43 deg, the example's head-wind ramp)
    is convergent because it has settled within the 1 deg band, and its reason says so beside
    the two amplitudes; one that decays from outside the band says it decays (envelope rule,
    module notes)."""
    t = np.linspace(0.0, 40.0, 4001)
    growing = np.radians(0.2 + 0.23 * (t > 20)) * np.sin(2 * np.pi * t / 2.0)
    decaying = np.radians(8.0) * np.exp(-0.05 * t) * np.sin(2 * np.pi * t / 2.0)
    env = vd.envelope(t, np.vstack([growing, decaying]), 0.0, 0.0, False)
    assert list(env.verdict) == [vd.CONVERGENT, vd.CONVERGENT]
    assert "(settled: within the 1 deg band)" in env.reason(0)
    assert "(decaying: below 0.9 x)" in env.reason(1)


def test_reason_of_a_signal_without_trim_gives_no_offset():
    """A signal tested without a trim value (the multibody's swing angles: reference NaN) is
    judged on its amplitudes alone; its reason states them and no 'centred +nan deg from
    trim' (a growing sine, 2 -> about 4.5 deg over the halves, is divergent by the envelope
    rule)."""
    t = np.linspace(0.0, 40.0, 4001)
    growing = np.radians(2.0) * np.exp(0.04 * t) * np.sin(2 * np.pi * t / 2.0)
    env = vd.envelope(t, growing[None, :], 0.0, np.nan, False)
    assert env.verdict[0] == vd.DIVERGENT
    text = env.reason(0, "lateral swing")
    assert "nan" not in text and text.startswith("lateral swing amplitude"), text

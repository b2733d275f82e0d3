"""Modes identified on a free response (analyses/response_modes.py) and the damping the
multibody and campaign reports give "from the response".

Checked against closed-form damped oscillations (the sum of damped cosines the matrix pencil
method must recover, to round-off without noise) and, on the example, against the
eigenvalue of the linear model's yaw mode. The family guarded against: a "yaw" period and
damping read on the roll mode of the response (1.62 s, 0.0015 beside a yaw mode of 14.6 s,
0.155), because the log decrement of the yaw-rate peaks sees the fast roll and swing modes
that dominate the rate.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from slingloads.analyses import verdicts as vd
from slingloads.analyses.response_modes import identify_mode
from slingloads.models.multibody.response import damping_from_peaks, scratch


def _mode(t, period, zeta, amplitude, phase=0.0):
    """Closed form of a damped linear mode: a exp(-zeta wn t) cos(wd t + phase), with
    wd = 2 pi / period and wn = wd / sqrt(1 - zeta^2). [signal unit]"""
    wd = 2 * math.pi / period
    sigma = zeta * wd / math.sqrt(1 - zeta ** 2)
    return amplitude * np.exp(-sigma * t) * np.cos(wd * t + phase)


T = np.arange(0.0, 60.0 + 1e-9, 0.1)
#: two yaw modes, a roll mode that dominates the rate, an offset (a settled heading)
HEADING = (_mode(T, 14.6, 0.155, 0.17) + _mode(T, 8.05, 0.072, 0.03, 0.7)
           + _mode(T, 1.44, 0.0014, 0.01, 1.1) + 0.02)


def test_closed_form_modes_are_recovered():
    """Each damped cosine of HEADING is recovered: period and damping ratio to 1e-6 of the
    closed form's, whichever mode is asked for; the largest is the default."""
    for period, zeta in ((14.6, 0.155), (8.05, 0.072), (1.44, 0.0014)):
        m = identify_mode(T, HEADING, target_period=period * 1.1)
        assert m.found, m.reason
        assert m.period == pytest.approx(period, rel=1e-6)
        assert m.damping_ratio == pytest.approx(zeta, abs=1e-6)
    largest = identify_mode(T, HEADING)
    assert largest.period == pytest.approx(14.6, rel=1e-6)
    assert largest.amplitude == pytest.approx(0.17, rel=1e-4)


def test_rate_peaks_see_the_fast_mode():
    """The earlier measure, the log decrement of the yaw-rate peaks, reads the roll mode of
    the same closed form (period 1.44 s, not 14.6 s): why the reports read the heading's
    yaw component instead."""
    rate = np.gradient(HEADING, T)
    period, _ = damping_from_peaks(T, rate, 0.0, scratch(T.size))
    assert period == pytest.approx(1.44, rel=0.05)
    assert identify_mode(T, HEADING, target_period=14.6).period == pytest.approx(14.6, 1e-6)


def test_start_offset_and_stop():
    """From a later start the same mode (period and damping do not depend on where the
    window starts); samples after a stop (NaN) are dropped; too short a window says why."""
    m = identify_mode(T, HEADING, start=7.3, target_period=14.6)
    assert m.period == pytest.approx(14.6, rel=1e-6)
    assert m.damping_ratio == pytest.approx(0.155, abs=1e-6)
    cut = HEADING.copy()
    cut[400:] = np.nan
    assert identify_mode(T, cut, target_period=14.6).damping_ratio == pytest.approx(
        0.155, abs=1e-6)
    short = identify_mode(T, HEADING, start=45.0, target_period=14.6)
    assert not short.found and "less than 1.5 periods" in short.reason
    assert math.isnan(short.damping_ratio)
    none = identify_mode(T, _mode(T, 4.0, 0.05, 1.0), target_period=14.6)
    assert not none.found and "no component within 25% of 14.6 s" in none.reason


def test_response_mode_names_the_target_mode():
    """The words beside the measured damping name the mode measured on and compare with
    its eigenvalue (verdicts.response_mode with the one-row yaw mode)."""
    modes = pd.DataFrame({"mode": ["yaw / lateral swing 1", "yaw / lateral swing 2", "roll"],
                          "period [s]": [14.6, 8.05, 1.44],
                          "damping ratio [-]": [0.155, 0.072, 0.0014],
                          "yaw amplitude [-]": [1.0, 0.39, 0.09]})
    target = vd.yaw_mode(modes)
    assert list(target["mode"]) == ["yaw / lateral swing 2"]  # least damped with yaw
    m = identify_mode(T, HEADING, target_period=float(target["period [s]"].iloc[0]))
    on, check = vd.response_mode(m.period, m.damping_ratio, target)
    assert on.startswith("yaw / lateral swing 2 (8.05 s")
    assert check.startswith("agrees with the yaw / lateral swing 2 mode")
    on, check = vd.response_mode(float("nan"), float("nan"), target, reason="too short")
    assert on == "" and check == "not measured on the yaw / lateral swing 2 mode (too short)"


def test_example_free_response_agrees_with_the_yaw_eigenvalue(example_study):
    """On the example, the multibody free response's damping "from the response" is that of
    the linear model's yaw mode (the least damped mode in which the yaw takes part): period
    within 1 % and damping ratio within 0.01 of the eigenvalue's (a 10 deg release is nearly
    linear), and the words beside it name that mode."""
    from slingloads.runs.multibody import run

    report = run(example_study)
    free = next(r for r in report.simulation.runs if r.manoeuvre.input_end == 0.0)
    modes = free.linear_at_condition.modes_frame()
    yaw = vd.yaw_mode(modes)
    row = free.metrics()
    assert row["yaw period from response [s]"] == pytest.approx(
        float(yaw["period [s]"].iloc[0]), rel=0.01)
    assert row["yaw damping ratio from response [-]"] == pytest.approx(
        float(yaw["damping ratio [-]"].iloc[0]), abs=0.01)
    name = str(yaw["mode"].iloc[0])
    assert "yaw" in name
    assert row["response damping measured on mode"].startswith(name + " (")
    assert row["response damping check"].startswith(f"agrees with the {name} mode")


def _run_like(time, yaw, input_end):
    """What RunResult.response_damping reads of a run: its times, heading and input end."""
    from types import SimpleNamespace

    return SimpleNamespace(time=time, histories=lambda: {"yaw": yaw},
                           manoeuvre=SimpleNamespace(input_end=input_end))


def test_aperiodic_or_missing_yaw_mode_is_said():
    """A yaw mode that is a real root (an unstable trim's, damping ratio -1, no period) is
    named with its real part and the damping is 'not measured', never compared with another
    mode or called 'no linear mode'; a model without a yaw mode says so."""
    from slingloads.analyses.multibody.simulate import RunResult

    modes = pd.DataFrame({"mode": ["yaw / lateral swing 1", "lateral swing"],
                          "real [1/s]": [0.1228, -0.031], "period [s]": [np.inf, 8.96],
                          "damping ratio [-]": [-1.0, 0.044],
                          "yaw amplitude [-]": [0.915, 0.188]})
    run = _run_like(T, HEADING, 0.0)
    period, zeta, on, check = RunResult.response_damping(run, modes)
    assert math.isnan(period) and math.isnan(zeta)
    assert on == "yaw / lateral swing 1 (aperiodic, real part +0.123 1/s)"
    assert check.startswith("not measured: the yaw / lateral swing 1 mode is aperiodic "
                            "(a real root, unstable)")
    no_yaw = modes.assign(**{"yaw amplitude [-]": [0.1, 0.1]})
    assert RunResult.response_damping(run, no_yaw)[3].startswith("no yaw mode in the linear")
    # without a model: the heading's largest component, compared with nothing
    period, zeta, on, check = RunResult.response_damping(run, None)
    assert period == pytest.approx(14.6, rel=1e-6) and on == ""
    assert check == "no linear mode to compare with"
    # a sustained input: nothing after it to measure
    assert RunResult.response_damping(_run_like(T, HEADING, None), None)[3] == (
        "not measured (the input lasts the whole run)")


def test_long_records_keep_their_roots():
    """A record of 20,001 samples (200 s at 0.01 s) is block-averaged and decimated before
    the identification: the closed form's period and damping ratio are recovered to 1e-6
    (a moving average of exponentials is the same exponentials), in well under a second."""
    import time as clock

    t = np.arange(0.0, 200.0 + 1e-9, 0.01)
    y = _mode(t, 14.6, 0.155, 0.17) + _mode(t, 1.44, 0.0014, 0.01, 1.1)
    began = clock.perf_counter()
    m = identify_mode(t, y, target_period=14.6)
    assert clock.perf_counter() - began < 2.0
    assert m.period == pytest.approx(14.6, rel=1e-6)
    assert m.damping_ratio == pytest.approx(0.155, abs=1e-6)

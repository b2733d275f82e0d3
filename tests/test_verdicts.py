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
    assert vd.damping_check(0.2, 1.6, 0.2, 14.6, "yaw").startswith("period 1.6 s matches no")


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

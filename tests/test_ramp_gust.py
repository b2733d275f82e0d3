"""Wind ramps with a lateral gust after their end (transport without parachute, paper
section 5): the gust the study flies, checked against the ramp's and the gust's definitions
by hand; the response of a stable case, checked against geometry (the sideslip's jump at
the gust's onset is atan(v_gust / V)) and against the linear model of the trim at the ramp's
final airspeed (the decay after the gust at the yaw mode's frequency and damping); and the
figure, against the study it is drawn from.
"""

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import curve_fit

from slingloads.analyses.campaign import (
    GUST_DELAY,
    GUST_DURATION,
    NoParachuteResult,
    NoParachuteStudy,
    sample_full_tail_system,
)
from slingloads.analyses.campaign.no_parachute import OBSERVE
from slingloads.analyses.multibody import linearise, simulate_runs, trim
from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError

YAW = "yaw (heading from flight path) [deg]"


@pytest.fixture(scope="module")
def study():
    return NoParachuteStudy({"HC1": sample_full_tail_system("HC1")}, targets=(20 * KNOT,),
                            gust_targets=(20 * KNOT,), gust_speed=10 * FOOT)


@pytest.fixture(scope="module")
def flown(study):
    """The 20 kt ramp with its gust, flown for the study's own run length."""
    ((name, target, system, manoeuvre),) = study.gust_jobs()
    sim = simulate_runs([(system, manoeuvre)], t_end=study.gust_run_length_of(target))
    return system, manoeuvre, sim.runs[0].to_frame()


def test_gust_follows_the_ramp_end_by_hand(study):
    """The ramp to 20 kt at 0.5 m/s^2 from 5 s ends at 5 + 10.289 / 0.5 = 25.58 s; the
    10 ft/s (3.048 m/s) gust blows across for 10 s from 10 s later; the run lasts 60 s
    after it, rounded up to 10 s (110 s); the head wind is the ramp's throughout."""
    ((name, target, system, manoeuvre),) = study.gust_jobs()
    end = 5.0 + 20 * KNOT / 0.5
    assert (name, target) == ("HC1", 20 * KNOT)
    assert study.ramp_end(target) == pytest.approx(end)
    start, stop = study.gust_window(target)
    assert (start, stop) == pytest.approx((end + GUST_DELAY, end + GUST_DELAY + GUST_DURATION))
    assert study.gust_run_length_of(target) == pytest.approx(110.0)
    assert manoeuvre.input_end == pytest.approx(stop)       # verdicts read after the gust
    assert system.airspeed == pytest.approx(target)
    t = np.array([0.0, 15.0, end + 1.0, start + 0.5, stop - 0.5, stop + 0.5])
    w = manoeuvre.wind.velocity(t)
    head = np.clip((t - 5.0) * 0.5, 0.0, 20 * KNOT)
    np.testing.assert_allclose(w[:, 0], head, atol=1e-9)
    np.testing.assert_allclose(np.abs(w[:, 1]), [0, 0, 0, 3.048, 3.048, 0], atol=1e-9)
    assert study.size == 2                                   # one ramp, one ramp with a gust


def test_bad_gust_inputs_are_refused():
    systems = {"HC1": sample_full_tail_system("HC1")}
    with pytest.raises(InputError, match="gust after the ramps"):
        NoParachuteStudy(systems, gust_speed=0.0)
    with pytest.raises(InputError, match="ramps with a gust"):
        NoParachuteStudy(systems, gust_targets=(-1.0,))
    assert NoParachuteStudy(systems, gust_targets=()).gust_jobs() == []


def test_sideslip_jumps_by_the_gust_angle(study, flown):
    """At the gust's onset the airframe has not turned yet: the sideslip jumps by
    atan(v_gust / V) = atan(3.048 / 10.289) = 16.50 deg (geometry of the relative wind)."""
    _, manoeuvre, h = flown
    start, _ = study.gust_window(20 * KNOT)
    t, beta = h["time [s]"].to_numpy(), h["beta [deg]"].to_numpy()
    before = beta[np.searchsorted(t, start) - 1]
    after = beta[np.searchsorted(t, start + 0.05)]
    expected = np.degrees(np.arctan(10 * FOOT / (20 * KNOT)))
    assert abs(after - before) == pytest.approx(expected, abs=0.3)


def test_decay_after_the_gust_is_the_linear_yaw_mode(study, flown):
    """A stable case shows its damping: after the gust, HC1's heading swings back at the
    frequency and damping of the yaw mode of the towed trim at 20 kt (the linear model, an
    independent computation: the Jacobian's eigenvalues, not the integrated run). A
    decaying cosine fitted to the heading from 0.5 s after the gust agrees within 3 % in
    frequency and 20 % in decay rate (the swing reaches 20 deg: not quite linear)."""
    system, _, h = flown
    modes = linearise(trim(system)).modes_frame()
    yaw = modes[modes["mode"] == "yaw"].iloc[0]
    _, stop = study.gust_window(20 * KNOT)
    t, psi = h["time [s]"].to_numpy(), h[YAW].to_numpy()
    keep = t > stop + 0.5
    t0 = t[keep][0]

    def wave(t, a, sigma, omega, phase, centre):
        return a * np.exp(sigma * (t - t0)) * np.cos(omega * (t - t0) + phase) + centre

    (a, sigma, omega, _, _), _ = curve_fit(wave, t[keep], psi[keep],
                                           p0=[psi[keep][0], -0.02, yaw["imag [rad/s]"], 0, 0])
    assert abs(a) > 5.0                                      # the gust did swing it
    assert omega == pytest.approx(yaw["imag [rad/s]"], rel=0.03)
    assert sigma == pytest.approx(yaw["real [1/s]"], rel=0.20)
    assert sigma < 0                                         # and it comes back
    assert (t[-1] - stop) >= OBSERVE


def test_gust_figure_marks_ramp_end_and_gust_and_states_the_condition(study, flown):
    """The figure of the ramps with a gust: each row's title gives the ramp's end and the
    gust's window (those of the study, by hand above), its legend the run's verdict, the
    suptitle the base condition (mass, cable, altitude, carrier, ramp, gust)."""
    from slingloads.io.campaign.plots import plot_no_parachute_gust

    _, _, h = flown
    key = ("HC1", 20 * KNOT)
    runs = pd.DataFrame([{"helicopter": "HC1", "ramp target [m/s]": 20 * KNOT,
                          "verdict": "convergent"}])
    result = SimpleNamespace(
        no_parachute=NoParachuteResult(runs, runs.iloc[:0], {}, runs, {key: "k"}),
        campaign=SimpleNamespace(no_parachute=study),
        history={(*key, "gust"): h}.__getitem__)
    fig = plot_no_parachute_gust(result, units="US")
    titles = [ax.get_title() for ax in fig.axes]
    assert any("wind ramp to 20 kt" in x and "ends at 26 s" in x and "gust 36-46 s" in x
               for x in titles)
    legend = fig.axes[0].get_legend()
    assert legend is not None and "HC1 (convergent)" in [x.get_text() for x in legend.texts]
    title = fig._suptitle.get_text()
    for part in ("HC1 6393 lb", "720 in", "0 ft density altitude", "hovering carrier",
                 "10 s lateral gust", "10 ft/s"):
        assert part in title, (part, title)

"""Colour scales and mode names of the report figures say what they show.

References: the rule of issue 23 item 4, checked on matplotlib's own objects: every colour
scale (a colour bar of a figure the campaign report draws) is labelled with a quantity, a unit
in brackets and, when its range holds both signs, what each sign means in the verdict words of
:mod:`slingloads.analyses.verdicts`; a mode whose name joins two motions is named by the rule
of docs/multibody.md section 4 (the groups always in the order yaw, lateral, longitudinal),
whichever of the two leads.
"""

from __future__ import annotations

import re
from types import SimpleNamespace

import matplotlib
import numpy as np
import openpyxl
import pytest
from hostile import EXAMPLE, study_row

matplotlib.use("Agg")

#: A small campaign with its stability map and root locus (2 areas, 1 airspeed, 30 s runs).
SMALL = {"run loads": "no", "run lateral": "no", "run chute sizing": "no",
         "run multibody": "no", "run campaign": "yes", "campaign area factors": "0.8, 1.4",
         "campaign airspeeds EAS": "60", "campaign manoeuvres": "free response",
         "campaign run length": 30, "campaign stability map areas": 3,
         "campaign stability map airspeeds": 1, "campaign no-parachute helicopters": "none"}


@pytest.fixture(scope="module")
def campaign_figures(tmp_path_factory):
    """The campaign report's figures of the small campaign, as the report draws them."""
    from slingloads.io.campaign.report import _figures
    from slingloads.io.study import read_study

    book = openpyxl.load_workbook(EXAMPLE)
    for name, value in SMALL.items():
        book["Study"][f"B{study_row(book, name)}"] = value
    path = tmp_path_factory.mktemp("scales") / "small.xlsx"
    book.save(path)
    results = read_study(path).run()
    return _figures(results.campaign, "SI")


def _colour_bars(figure):
    """The colour bars of ``figure`` (matplotlib keeps each on its axes)."""
    return [ax._colorbar for ax in figure.axes if getattr(ax, "_colorbar", None) is not None]


def test_every_colour_scale_says_quantity_unit_and_sign(campaign_figures):
    """Each colour bar of the campaign's figures (stability map: damping ratio and real part;
    root locus: area factor) has a label with a unit in brackets; a scale running from
    negative to positive values says which sign is stable and which unstable, in the linear
    model's verdict words (the tables' 'linear verdict', LinearModel.verdict): the scales
    show eigenvalues, not responses (convergent / divergent name a response)."""
    from matplotlib import pyplot as plt
    from matplotlib import rc_context

    from slingloads.analyses.verdicts import STABLE, UNSTABLE
    from slingloads.io.common.figures import report_style

    assert {"stability-map", "root-locus"} <= set(campaign_figures)
    bars, faults = 0, []
    for tag, (_, (func, args, kwargs)) in campaign_figures.items():
        with rc_context(report_style()):
            figure = func(*args, **kwargs)
        for bar in _colour_bars(figure):
            bars += 1
            label = bar.ax.get_ylabel() or bar.ax.get_xlabel()
            low, high = bar.mappable.get_clim()
            if not re.search(r"\[[^\]]+\]", label):
                faults.append((tag, label, "no unit"))
            if low < 0 < high and not (STABLE in label and UNSTABLE in label
                                       and "<" in label and ">" in label):
                faults.append((tag, label, "sign not explained"))
        plt.close(figure)
    assert bars >= 3  # damping ratio, real part, area factor
    assert not faults, faults


def test_stability_map_panels_are_titled_by_what_they_show(campaign_figures):
    """The two rows of the stability map (damping ratio, real part) at one altitude carry
    different titles, each with the base condition, its density altitude in the report's
    unit (m in this SI report: never ft, one unit per quantity)."""
    from matplotlib import pyplot as plt

    _, (func, args, kwargs) = campaign_figures["stability-map"]
    figure = func(*args, **kwargs)
    titles = [ax.get_title() for ax in figure.axes if ax.get_title()]
    plt.close(figure)
    assert len(titles) == len(set(titles)) == 2, titles
    assert all(re.search(r"\d m density altitude", t) and " ft" not in t for t in titles)


def _model(p_y, phi_z):
    """A stand-in for a linear model with one mode moving the CG sideways by ``p_y`` [m] on a
    10 m cable span (swing angle p_y / 10) and yawing by ``phi_z`` [rad]."""
    from slingloads.analyses.multibody.trim import LinearModel

    names = ("p_X", "p_Y", "phi_x", "phi_y", "phi_z")
    vectors = np.array([[0.0], [p_y], [0.0], [0.0], [phi_z]])
    model = SimpleNamespace(names=names, vectors=vectors,
                            trim=SimpleNamespace(quantity=lambda name: 10.0))
    swing = p_y / 10.0
    angles = np.array([[0.0, swing, phi_z, 0.0]]) / max(swing, phi_z)
    shares = np.zeros((1, 8))
    return LinearModel._name(model, 0, shares, angles)


def test_a_mode_has_one_name_whichever_motion_leads():
    """Lateral swing leading (swing 0.1 rad, yaw 0.06 rad) and yaw leading (yaw 0.1 rad,
    swing 0.06 rad) both give "yaw / lateral swing": the groups in the documented order, the
    second kept at 60 % >= 25 % of the first; yaw alone below 25 % is dropped."""
    assert _model(p_y=1.0, phi_z=0.06) == "yaw / lateral swing"
    assert _model(p_y=0.6, phi_z=0.1) == "yaw / lateral swing"
    assert _model(p_y=1.0, phi_z=0.02) == "lateral swing"

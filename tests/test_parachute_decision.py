"""The one parachute decision (slingloads.analyses.parachute_decision): the rule that both
models' criteria must hold, so the larger of their proposals is chosen, and that a model
which finds no area leaves none (the reference: the rule stated in the module notes and
docs/parachute-sizing.md, worked by hand on stand-in results)."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from slingloads.analyses.parachute_decision import MULTIBODY, NO_AREA, ONE_DOF, decide

STATIC = SimpleNamespace(area=0.8, area_fit=0.7, area_local=0.8,
                         basis_text="local slopes at zero sideslip")


class Sweep:
    """A 1-DOF sweep whose areas 0.8, 1.0, 1.2 m^2 have the given verdicts (two gusts)."""

    def __init__(self, verdicts):
        self.rows = pd.DataFrame(
            [{"area [m^2]": a, "gust": g, "verdict": v}
             for a, vs in zip((0.8, 1.0, 1.2), verdicts, strict=True)
             for g, v in zip(("step", "finite"), vs, strict=True)])

    def to_frame(self):
        return self.rows

    def by_area(self):
        g = self.rows.groupby("area [m^2]")
        return pd.DataFrame({"all gusts stable": g["verdict"].agg(
            lambda v: bool(v.isin(("convergent", "bounded")).all()))}).reset_index()

    @property
    def smallest_stable_area(self):
        t = self.by_area()
        ok = t[t["all gusts stable"]]
        return float(ok["area [m^2]"].min()) if len(ok) else math.nan


def selection(area):
    governing = {"condition": "80 KEAS", "needs area factor [-]": 1.5}
    return SimpleNamespace(recommended_area=area, governing_recommended=governing,
                           governing_stable=governing)


METRICS = pd.DataFrame({"area [m^2]": [1.2, 1.2, 1.4, 1.4],
                        "response verdict": ["convergent", "limit cycle", "convergent",
                                             "convergent"]})
STABLE = np.array([True, False, True, True])


def one_dof(area):
    return pd.DataFrame({"gust": ["step", "finite"], "verdict": ["convergent", "convergent"]})


def test_the_larger_proposal_decides():
    """1-DOF needs 1.0 m^2 (0.8 fails the finite gust), the campaign 1.4: 1.4 is chosen, the
    multibody model decides; its runs at 1.4 are all stable. With the campaign at 0.9 the
    1-DOF's 1.0 is chosen and the 1-DOF decides; the campaign has no run at 1.0."""
    sweep = Sweep([("convergent", "outside domain"), ("convergent", "convergent"),
                   ("convergent", "convergent")])
    d = decide(STATIC, sweep, selection(1.4), METRICS, STABLE, one_dof, 0.9)
    assert d.chosen_area == 1.4 and d.deciding_model == MULTIBODY
    assert d.multibody_verdict == "stable in all 2 runs"
    assert "SMALLER" in d.study_area_verdict()
    assert "finite gust (outside domain)" in decide(STATIC, sweep).governing
    d = decide(STATIC, sweep, selection(0.9), METRICS, STABLE, one_dof, 1.2)
    assert d.chosen_area == 1.0 and d.deciding_model == ONE_DOF
    assert d.multibody_verdict == "not run at this area"
    frame = d.to_frame().set_index("item")
    assert frame.loc["chosen area", "value"] == pytest.approx(1.0)


def test_no_area_when_a_model_finds_none():
    """A campaign with no area meeting its criterion leaves no chosen area (a finding, with
    the model named), whatever the 1-DOF sweep found; so does a sweep with no stable area.
    The verdict over the campaign's runs at 1.2 m^2 counts the limit cycle as not stable."""
    sweep = Sweep([("convergent", "convergent")] * 3)
    d = decide(STATIC, sweep, selection(math.nan), METRICS, STABLE, one_dof)
    assert not d.found and d.deciding_model == MULTIBODY
    assert "no area meets the criterion of the multibody campaign" in d.reason
    # both models ran: at the chosen area there is nothing to judge, never "not run"
    frame = d.to_frame().set_index("item")["value"]
    assert frame["multibody verdict at the chosen area"] == NO_AREA
    assert frame["1-DOF verdict at the chosen area, per gust"] == NO_AREA
    bad = Sweep([("divergent", "convergent")] * 3)
    d = decide(STATIC, bad)
    assert not d.found and d.deciding_model == ONE_DOF
    from slingloads.analyses.parachute_decision import multibody_verdict_at
    text = multibody_verdict_at(METRICS, 1.2, STABLE)
    assert text.startswith("NOT stable in every run: 1 of 2 not shown stable")
    assert "limit cycle" in text


def test_a_finding_is_reported_not_refused():
    """No stable area is a finding, not an input error: the campaign's and the sizing's
    shortfalls name it (``slingloads`` exits 3 with the reports written, cli.EXIT_INCOMPLETE),
    and the loads keep the hand-entered cases. Checked on stand-in results; the whole run is
    exercised by the example with 'campaign area factors' 0.5 (exit 3)."""
    from slingloads.cli import EXIT_INCOMPLETE
    from slingloads.runs.campaign import shortfalls as campaign_shortfalls
    from slingloads.runs.chute_sizing import shortfalls as chute_shortfalls
    from slingloads.runs.study import Results

    none = decide(STATIC, None, selection(math.nan), METRICS, STABLE)
    report = SimpleNamespace(
        result=SimpleNamespace(selection=SimpleNamespace(smallest_stable=math.nan),
                               envelope=None, decision=none),
        inputs=SimpleNamespace(loads_from_dynamics=True))
    lines = campaign_shortfalls(report)
    assert len(lines) == 3 and "stable in every condition" in lines[0]
    assert "hand-entered cases only" in lines[1] and "parachute decision" in lines[2]
    sized = SimpleNamespace(sweep=object(), recommended_area=math.nan, decision=None)
    assert "no swept area is stable" in chute_shortfalls(sized)[0]
    # the study's findings (what the command line prints before exit 3): each once
    found = Results(chute_sizing=sized, campaign=report).shortfalls()
    assert len(found) == 4 and found[0] == chute_shortfalls(sized)[0]
    assert EXIT_INCOMPLETE == 3


def test_the_campaign_factor_names_where_its_neutral_area_is_read():
    """The multibody proposal's reason multiplies the campaign's neutral area and says where it
    is read (the selection's condition text: at the towed trim, or alpha 0 and why); worked by
    hand: 1.5 x 0.6 m^2 = 0.9 m^2, and no "alpha 0" when the trim is used."""
    governing = {"condition": "80 KEAS", "needs area factor [-]": 1.5}
    where = "at the towed trim, alpha -22.2 deg (80 KEAS, density altitude 0 ft)"
    chosen = SimpleNamespace(recommended_area=0.9, governing_recommended=governing,
                             governing_stable=governing, neutral_area=0.6,
                             neutral_condition=where)
    d = decide(STATIC, Sweep([("convergent",) * 2] * 3), chosen, METRICS, STABLE, one_dof, 1.0)
    assert d.deciding_model == MULTIBODY
    assert f"1.5 x the campaign's neutral area 0.6 m^2 ({where}) = 0.9 m^2" in d.governing
    assert "alpha 0" not in d.governing

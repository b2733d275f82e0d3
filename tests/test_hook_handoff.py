"""The lateral study's hand-off to the loads: the lateral hook cases take
max(the loads' own lateral angle, the lateral study's recommended design angle).

Reference: CS 29.865 (the hook load is inclined by "the maximum angle achievable in service,
not less than 30 deg"; FACTS.md) read as the rule "the conservative value wins, the Study's
angle is never lowered": the expected angle is that maximum, worked by hand in each test.
"""

import numpy as np
import pandas as pd
import pytest

from slingloads.analyses.hook_angle import GOVERNS_LATERAL, lateral_hook_handoff


def _inclination(study, hook):
    table = study.hook_table()
    return float(table.loc[table["hook"] == hook, "inclination [deg]"].iloc[0])


def test_larger_recommended_angle_governs(example_study):
    """Study cone 30 deg, recommended 33.2 deg: the lateral directions (AZ090, AZ270) go to
    33.2 deg, the fore-and-aft ones stay at 30 deg, and the lateral study governs."""
    loads = example_study.inputs.loads
    out = lateral_hook_handoff(loads, np.radians(33.2))
    assert out.governs == GOVERNS_LATERAL
    assert np.degrees(out.used) == pytest.approx(33.2, rel=1e-12)
    assert _inclination(out.study, "AZ090") == pytest.approx(33.2, rel=1e-12)
    assert _inclination(out.study, "AZ270") == pytest.approx(33.2, rel=1e-12)
    assert _inclination(out.study, "AZ000") == pytest.approx(30.0, rel=1e-12)
    assert "33.2 deg = max(Study 30.0 deg" in out.describe()


def test_smaller_recommended_angle_never_lowers_the_study(example_study):
    """Recommended 21 deg against the Study's 30 deg: max(30, 21) = 30, the study is the
    same object (nothing changed), and the Study governs."""
    loads = example_study.inputs.loads
    out = lateral_hook_handoff(loads, np.radians(21.0))
    assert out.study is loads and out.governs == "Study"
    assert np.degrees(out.used) == pytest.approx(30.0, rel=1e-12)
    assert "never lowered" in out.reason


def test_no_design_angle_keeps_the_study_angle(example_study):
    """A lateral study outside its domain (no design angle: NaN): the Study's 30 deg is kept
    and the reason is quoted."""
    loads = example_study.inputs.loads
    out = lateral_hook_handoff(loads, np.nan, "every case leaves the domain")
    assert out.study is loads and np.degrees(out.used) == pytest.approx(30.0, rel=1e-12)
    assert "no design angle (every case leaves the domain)" in out.reason
    frame = out.to_frame()
    assert np.isnan(frame["value"].iloc[1]) and "none" in frame["note"].iloc[1]


def test_run_loads_take_the_lateral_angle(example_run_report):
    """`slingloads run` on the example (loads and lateral): the loads Summary's 'hook cone
    angle of the lateral directions' equals the lateral report's 'recommended design angle'
    (33.2 deg > the Study's 30 deg), and no FLAG asks to rerun the loads."""
    def rows(report):
        frame = pd.read_excel(example_run_report / f"example-light-twin-{report}.xlsx",
                              sheet_name="Summary", header=None)
        return frame, {r[0]: r[1] for r in frame.itertuples(index=False) if len(r) > 1}

    loads, loads_rows = rows("loads")
    _, lateral_rows = rows("lateral")
    recommended = float(lateral_rows["recommended design angle"])
    assert recommended > 30.0
    assert float(loads_rows["hook cone angle of the lateral directions"]) == pytest.approx(
        recommended, rel=1e-9)
    assert float(loads_rows["lateral hook angle used by the loads"]) == pytest.approx(
        recommended, rel=1e-9)
    text = " ".join(map(str, loads[0]))
    assert "rerun the loads" not in text and "the lateral study governs" in text

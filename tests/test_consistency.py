"""Checks between the analyses of one run: the parachute sizing's peak sideslip against the
loads' aerodynamic envelope.

Reference: the rule itself (a flight the sizing shows must lie inside the envelope the loads
are taken over) applied to the numbers of both analyses, and the report that shows it.
"""

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from hostile import EXAMPLE
from once import computed_once

from slingloads.analyses.loads import AeroEnvelope
from slingloads.io.consistency import consistency_checks
from slingloads.io.study import read_study
from slingloads.runs.study import Results


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """The example's loads and sizing, run once for the session's workers
    (:func:`once.computed_once`): to be read, not changed."""
    return computed_once(tmp_path_factory, "example-loads-and-sizing",
                         lambda: read_study(EXAMPLE, only=["loads", "chute sizing"]).run())


def test_peak_sideslip_outside_the_envelope_is_a_warning(results):
    """The example: at its Study 'parachute area' (0.9 m^2, 3.1 x the neutral area about the
    suspension axis) the gusts drive the sideslip to 12.5 deg at most (the step gust's wind
    angle atan(9.144 / 41.16)), inside the loads' AeroEnvelope beta of +-15 deg: ok, the
    value being the largest peak |beta| of the gust runs at that area. Against an envelope of
    +-10 deg the same sizing is a WARNING naming the gust that gives the peak."""
    row = consistency_checks(results)["loads"].iloc[0]
    runs = results.chute_sizing.study_area_runs.to_frame()
    assert row["value"] == pytest.approx(runs["peak beta [deg]"].max(), rel=1e-12)
    assert row["value"] == pytest.approx(np.degrees(np.arctan2(30 * 0.3048, 80 * 0.514444)),
                                         abs=0.05)
    assert row["value"] < 15.0 and row["limit"] == pytest.approx(15.0)
    assert row["status"] == "ok"
    loads = results.loads
    narrow = AeroEnvelope.corners_and_centre(np.radians([-10.0, 10.0]),
                                             np.radians([-10.0, 10.0]))
    narrower = replace(loads, study=replace(loads.study, envelope=narrow))
    row = consistency_checks(Results(loads=narrower,
                                     chute_sizing=results.chute_sizing))["loads"].iloc[0]
    worst = str(runs["gust"].iloc[int(np.argmax(runs["peak beta [deg]"].to_numpy()))])
    assert row["status"] == "WARNING" and row["limit"] == pytest.approx(10.0)
    assert f"{worst} gust" in row["note"]


def test_peak_sideslip_inside_a_wider_envelope_passes(results):
    """The same sizing against an envelope of +-20 deg of sideslip: the check passes; and with
    only one of the two analyses there is no check at all."""
    loads = results.loads
    wide = AeroEnvelope.corners_and_centre(np.radians([-10.0, 10.0]), np.radians([-20.0, 20.0]))
    wider = replace(loads, study=replace(loads.study, envelope=wide))
    row = consistency_checks(Results(loads=wider,
                                     chute_sizing=results.chute_sizing))["loads"].iloc[0]
    assert row["status"] == "ok" and row["limit"] == pytest.approx(20.0)
    assert consistency_checks(Results(loads=loads)) == {}


def test_run_report_carries_the_warning(example_run_report, example_loads_report):
    """`slingloads run` with the loads and the sizing: the loads Summary shows the check (on
    the example inside the envelope: no warning); `slingloads loads` alone has no such
    section."""
    summary = pd.read_excel(example_run_report / "example-light-twin-loads.xlsx",
                            sheet_name="Summary", header=None)
    text = " ".join(map(str, summary[0]))
    assert "Consistency with the other analyses of this run" in text
    assert "parachute sizing peak sideslip within the loads' aerodynamic envelope" in text
    assert "WARNING: the parachute sizing's" not in text
    alone = pd.read_excel(example_loads_report / "example-light-twin-loads.xlsx",
                          sheet_name="Summary", header=None)
    assert "Consistency" not in " ".join(map(str, alone[0]))

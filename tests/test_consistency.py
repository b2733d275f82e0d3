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

from slingloads.analyses.loads import AeroEnvelope
from slingloads.io.consistency import consistency_checks
from slingloads.io.study import read_study
from slingloads.runs.study import Results


@pytest.fixture(scope="module")
def results():
    return read_study(EXAMPLE, only=["loads", "chute sizing"]).run()


def test_peak_sideslip_outside_the_envelope_is_a_warning(results):
    """The example: at its Study 'parachute area' (0.9 m^2) the finite gust drives the
    sideslip to about 17.7 deg, outside the loads' AeroEnvelope beta of +-15 deg: WARNING,
    the value being the largest peak |beta| of the gust runs at that area."""
    row = consistency_checks(results)["loads"].iloc[0]
    runs = results.chute_sizing.study_area_runs.to_frame()
    assert row["value"] == pytest.approx(runs["peak beta [deg]"].max(), rel=1e-12)
    assert row["value"] > 15.0 and row["limit"] == pytest.approx(15.0)
    assert row["status"] == "WARNING" and "finite gust" in row["note"]


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
    """`slingloads run` with the loads and the sizing: the loads Summary shows the check and
    the warning; `slingloads loads` alone has no such section."""
    summary = pd.read_excel(example_run_report / "example-light-twin-loads.xlsx",
                            sheet_name="Summary", header=None)
    text = " ".join(map(str, summary[0]))
    assert "Consistency with the other analyses of this run" in text
    assert "WARNING: the parachute sizing's finite gust" in text
    alone = pd.read_excel(example_loads_report / "example-light-twin-loads.xlsx",
                          sheet_name="Summary", header=None)
    assert "Consistency" not in " ".join(map(str, alone[0]))

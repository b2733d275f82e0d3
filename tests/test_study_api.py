"""The Python API of a whole workbook study: ``sl.run`` (read, then run), typed results and
``sl.write_reports``, against the command line and the per-analysis API (README, "Python
API"; docs/api.md, "From a workbook: read, run, write")."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import slingloads as sl
from slingloads.analyses.loads import LoadsResult
from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.runs.chute_sizing import ChuteSizingReport
from slingloads.runs.lateral import LateralReport
from slingloads.runs.multibody import MultibodyReport
from slingloads.runs.study import ANALYSES, Results, Study, compute_order, run_analysis

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"


@pytest.fixture(scope="module")
def results():
    return sl.run(EXAMPLE)


def test_one_call_runs_what_the_workbook_asks_for(results):
    """The example's Study sheet asks for loads, lateral, chute sizing and multibody (its
    'run ...' rows, read back with openpyxl here, independently of slingloads' reader): each
    has a typed result, the campaign (not asked) none."""
    from openpyxl import load_workbook

    sheet = load_workbook(EXAMPLE, read_only=True)["Study"]
    asked = {str(r[0]).strip().lower()[len("run "):] for r in sheet.iter_rows(values_only=True)
             if r[0] and str(r[0]).lower().startswith("run ") and str(r[1]).lower() == "yes"}
    assert set(results.computed()) == asked
    assert isinstance(results.study, Study) and results.study.asked == results.computed()
    assert isinstance(results.loads, LoadsResult)
    assert isinstance(results.lateral, LateralReport)
    assert isinstance(results.chute_sizing, ChuteSizingReport)
    assert isinstance(results.multibody, MultibodyReport)
    assert results.campaign is None and results.loads_handoff is None


def test_results_are_those_of_each_analysis_alone(results):
    """Running the study is running each analysis on its inputs, with the two hand-offs the
    example has (the lateral study's recommended angle, 33.2 deg, above the Study's 30 deg,
    on the lateral hook directions; the multibody model's system, which flies the loads'
    parachute, for the towed case's trim): the loads equal those of the LoadsStudy read from
    the same workbook with that lateral angle and that towed system, run on its own
    (docs/api.md), to round-off."""
    from dataclasses import replace

    loads = sl.read_study(EXAMPLE, only=["loads"]).inputs.loads
    angle = results.lateral.recommended_angle
    assert angle > loads.hook.lateral
    system = sl.read_study(EXAMPLE, only=["multibody"]).inputs.multibody.system
    alone = replace(loads, hook=replace(loads.hook, lateral_angle=angle),
                    towed_system=system).run()
    np.testing.assert_allclose(results.loads.loads, alone.loads, rtol=1e-12, atol=1e-9)
    assert results.loads_hook_angle.used == angle


def test_typed_results_become_frames(results):
    """Each result becomes a DataFrame of one row per case, run or manoeuvre: as many rows as
    the lateral cases swept, the sizing's swept areas x gusts, the multibody manoeuvres."""
    lateral = results.lateral.to_frame()
    assert isinstance(lateral, pd.DataFrame)
    assert len(lateral) == len(results.lateral.study.pendulums)
    inputs = results.chute_sizing.inputs
    assert len(results.chute_sizing.to_frame()) == len(inputs.factors) * len(inputs.gusts)
    assert len(results.multibody.to_frame()) == len(results.multibody.inputs.manoeuvres)


def test_write_reports_matches_the_command_line(tmp_path):
    """``sl.write_reports`` writes what the command line writes (here the loads alone,
    ``slingloads loads``): the same file names, and the same SI loads in the CSV files (the
    command line is the independent route, from its own read and run)."""
    api = sl.write_reports(sl.run(EXAMPLE, only=["loads"]), tmp_path / "api")
    assert main(["loads", str(EXAMPLE), "--out", str(tmp_path / "cli"), "--quiet"]) == 0
    cli = {p.name for p in (tmp_path / "cli").iterdir() if not p.name.startswith(".")}
    assert {p.name for p in api} == cli and "example-light-twin-loads.xlsx" in cli
    for name in ("example-light-twin-sfbm.csv", "example-light-twin-envelope.csv"):
        assert (tmp_path / "api" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


def test_order_puts_the_campaign_before_the_loads_it_feeds():
    """The campaign hands its dynamics' cases to the loads, the lateral study its design
    angle: each runs first whenever the loads run too; otherwise the analyses run in the
    registry order (README, "Campaign")."""
    assert compute_order(["loads", "campaign"]) == ["campaign", "loads"]
    assert compute_order(["loads", "lateral"]) == ["lateral", "loads"]
    assert compute_order(["multibody", "campaign", "lateral"]) == ["lateral", "multibody",
                                                                   "campaign"]
    assert compute_order(reversed(ANALYSES)) == ["lateral", "campaign", "loads",
                                                  "chute sizing", "multibody"]


def test_an_analysis_not_asked_for_is_refused():
    """Running an analysis whose inputs were not read says which Study row asks for it (the
    message the command line shows), instead of failing on a missing attribute."""
    study = sl.read_study(EXAMPLE, only=["loads"])
    with pytest.raises(InputError, match=r"does not ask for the lateral study \(Study sheet: "
                                         r"'run lateral' is no\)") as info:
        run_analysis(study, "lateral")
    assert info.value.file == str(EXAMPLE) and info.value.sheet == "Study"
    assert Results().computed() == ()


def test_analysis_names_map_to_their_fields():
    """Each analysis named in the workbook ('chute sizing') is kept in the field of its typed
    inputs and results (``chute_sizing``), the dataclass's own attribute; an unknown name is
    refused with the valid names rather than ignored."""
    from slingloads.runs.study import Inputs

    for name in ANALYSES:
        results, inputs = Results(), Inputs()
        results.set(name, name)
        inputs.set(name, name)
        assert getattr(results, name.replace(" ", "_")) == name == results.of(name)
        assert getattr(inputs, name.replace(" ", "_")) == name == inputs.of(name)
    with pytest.raises(InputError, match="valid names are"):
        Results().set("chute", 1)
    with pytest.raises(InputError, match="valid names are"):
        Inputs().of("Loads")

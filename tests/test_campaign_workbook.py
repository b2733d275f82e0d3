"""The campaign driven from the input workbook: report, run cache on disk, re-runs, bad input.

References: the report's metrics read back equal those of the Python API run on the campaign
read from the same workbook (``read_study`` then ``run_campaign`` in memory); the cache's
counts of found and computed runs are worked out from the edit each test makes; each bad-input
test breaks one rule written in ``slingloads.io.campaign.schema`` and checks exit code 2, the
sheet and cell in the message, and that nothing is written (no output folder, no cached run).
"""

from __future__ import annotations

import re
import time

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import DEADLINE, EXAMPLE, report_table, study_row

from slingloads.analyses.campaign import HISTORY_LABELS, MemoryStore, run_campaign
from slingloads.cli import main
from slingloads.io.study import read_study
from slingloads.runs.cache import RunCache

#: A tiny campaign: 2 areas, 1 condition, 1 manoeuvre, 30 s runs; HC1 under one 20 kt ramp.
#: Areas 2.25 and 2.9 x the neutral area about the suspension axis at the 60 KEAS towed trim
#: (0.419 m^2): 0.94 and 1.21 m^2, the smaller inconclusive within 30 s, the larger stable.
TINY = {"run loads": "no", "run lateral": "no", "run chute sizing": "no",
        "run campaign": "yes", "campaign area factors": "2.25, 2.9",
        "campaign airspeeds EAS": "60", "campaign density altitudes": "0",
        "campaign cable lengths": "60", "campaign carriers": "frozen",
        "campaign manoeuvres": "free response", "campaign run length": 30,
        "campaign stability map areas": 2, "campaign stability map airspeeds": 1,
        "campaign no-parachute helicopters": "HC1", "campaign no-parachute ramps": "20"}


@pytest.fixture(scope="module", autouse=True)
def base(tmp_path_factory):
    """The example with the tiny campaign, its FuselageAero table thinned to alpha every 10 deg
    and beta every 4 deg (a quicker workbook to read; the tests compare the workbook with the
    API on the same tables) and the lateral study's sheets removed."""
    book = openpyxl.load_workbook(EXAMPLE)
    for name, value in TINY.items():
        book["Study"][f"B{study_row(book, name)}"] = value
    # no ramps with a gust (their default 20, 30 kt would add 2 runs to every count below;
    # tests/test_ramp_gust.py flies them)
    book["Study"][f"B{study_row(book, 'campaign no-parachute gust ramps')}"] = "none"
    rows = list(book["FuselageAero"].iter_rows(values_only=True))
    keep = [rows[0]] + [r for r in rows[1:] if r[0] % 10 == 0 and r[1] % 4 == 0]
    index = book.sheetnames.index("FuselageAero")
    book.remove(book["FuselageAero"])
    sheet = book.create_sheet("FuselageAero", index)
    for r in keep:
        sheet.append(r)
    for name in ("LateralMotions", "LateralHistory", "LateralRopes", "README"):
        book.remove(book[name])
    path = tmp_path_factory.mktemp("base") / "base.xlsx"
    book.save(path)
    BASE[0] = path
    return path


BASE = [None]


def workbook(path, edits=None, extra=None):
    """The tiny base workbook with ``edits`` {Study parameter: value} and ``extra(book)``."""
    book = openpyxl.load_workbook(BASE[0])
    for name, value in (edits or {}).items():
        book["Study"][f"B{study_row(book, name)}"] = value
    if extra is not None:
        extra(book)
    book.save(path)
    return path


def summary_value(out, item):
    frame = pd.read_excel(out / "tiny-campaign.xlsx", sheet_name="Summary", header=None)
    return frame[frame[0] == item][1].iloc[0]


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    base = tmp_path_factory.mktemp("campaign")
    path = workbook(base / "tiny.xlsx")
    cache = base / "cache"
    out = base / "out"
    assert main(["campaign", str(path), "--out", str(out), "--cache", str(cache),
                 "--quiet"]) == 0
    return path, out, cache


def _blocks(workbook, sheet):
    """A table printed in column blocks (each with ``run`` first), joined back on the run."""
    raw = pd.read_excel(workbook, sheet_name=sheet, header=None)
    starts = list(np.flatnonzero((raw[0] == "run").to_numpy()))
    joined = None
    for at in starts:
        body = raw.iloc[at + 1:]
        end = np.flatnonzero(body[0].isna().to_numpy())
        body = body.iloc[:end[0]] if end.size else body
        header = raw.iloc[at]
        keep = header.notna().to_numpy()
        block = pd.DataFrame(body.loc[:, keep].to_numpy(), columns=list(header[keep]))
        joined = block if joined is None else joined.merge(block, on="run")
    return joined


def test_report_files_and_readback(tiny):
    """`slingloads campaign` writes the workbook, the PNGs and the histories; the Metrics
    sheet equals the API run of the campaign read from the same workbook, and the Parquet
    file holds every run's histories (2 matrix runs and the ramp)."""
    path, out, _ = tiny
    sheets = pd.read_excel(out / "tiny-campaign.xlsx", sheet_name=None)
    for name in ("Summary", "Matrix", "Metrics", "Selection", "NeutralArea", "Sensitivity",
                 "StabilityMap", "NoParachute", "LoadsHandoff", "Plots"):
        assert name in sheets
    for tag in ("selection", "sensitivity-parachute-area", "stability-map", "root-locus",
                "no-parachute"):
        assert (out / f"tiny-campaign-{tag}.png").stat().st_size > 1000
    api = run_campaign(read_study(path).inputs.campaign.campaign, store=MemoryStore())
    report = _blocks(out / "tiny-campaign.xlsx", "Metrics")
    for column in ("yaw change [deg]", "beta peak [deg]", "yaw mode damping ratio [-]",
                   "swing angle trim [deg]", "tension / weight max [-]"):
        np.testing.assert_allclose(report[column].astype(float), api.metrics[column],
                                   rtol=1e-12)
    histories = pd.read_parquet(out / "tiny-campaign-histories.parquet")
    assert list(histories.columns) == ["run", *HISTORY_LABELS]
    assert sorted(histories["run"].unique()) == ["NP-HC1-20kt", "R0001", "R0002"]
    one = histories[histories["run"] == "R0002"].drop(columns="run").reset_index(drop=True)
    pd.testing.assert_frame_equal(one, api.history("R0002"))


def test_second_run_comes_from_the_cache(tiny, tmp_path):
    """Run again on the same cache: all 3 runs are found, none computed, same numbers; the
    Summary counts the matrix's 2 runs and the ramp's apart (the matrix's count never exceeds
    its runs)."""
    path, out, cache = tiny
    again = tmp_path / "again"
    assert main(["campaign", str(path), "--out", str(again), "--cache", str(cache),
                 "--quiet"]) == 0
    frame = pd.read_excel(again / "tiny-campaign.xlsx", sheet_name="Summary", header=None)
    rows = dict(zip(frame[0], frame[1], strict=False))
    assert (rows["runs found in the cache"], rows["runs computed now"]) == (2, 0)
    assert (rows["runs without parachute found in the cache"],
            rows["runs without parachute computed now"]) == (1, 0)
    pd.testing.assert_frame_equal(pd.read_excel(again / "tiny-campaign.xlsx", "Metrics"),
                                  pd.read_excel(out / "tiny-campaign.xlsx", "Metrics"))


def test_summary_states_where_the_cache_is_and_what_it_counts(tiny):
    """The Summary names the run cache folder (here the one chosen by --cache), says why it
    lies outside the output folder and that its counts are this matrix's runs only (the
    rule of slingloads.runs.cache); the default folder is named as the default."""
    from slingloads.runs.cache import default_cache_dir, where_stated

    _, out, cache = tiny
    frame = pd.read_excel(out / "tiny-campaign.xlsx", sheet_name="Summary", header=None)
    row = frame[frame[0] == "run cache folder"].iloc[0]
    assert row[1] == str(cache)
    assert row[3] == "chosen (--cache)"
    notes = " ".join(frame[0].dropna().astype(str))
    assert "outside the output folder" in notes and "this matrix's only" in notes
    assert where_stated(default_cache_dir())[0] == "the default, the user cache folder"


def test_edited_workbook_reruns_only_what_changed(tiny, tmp_path):
    """Area factors 2.25, 2.9 -> 2.25, 2.6: the 2.25 run and the ramp are found (2), the 2.6
    run is computed (1). A new cable EA changes every run of the matrix and the ramp (the
    sample flown without parachute hangs on the same cable): 0 found, 3 computed."""
    import shutil

    cache = tmp_path / "cache"
    shutil.copytree(tiny[2], cache)
    for edits, counts in (({"campaign area factors": "2.25, 2.6"}, (2, 1)),
                          ({"campaign cable EA": 6e6}, (0, 3))):
        path = workbook(tmp_path / "edited.xlsx", edits)
        result = run_campaign(read_study(path).inputs.campaign.campaign,
                              store=RunCache(cache))
        assert (result.execution.cached, result.execution.computed) == counts


def test_disk_cache_resumes_after_an_interruption(tmp_path):
    """Interrupted after its first batch of one run, the on-disk cache holds that run (one
    Parquet file, no partial file); resumed, 1 run is found and 2 computed, and the results
    equal an uninterrupted run's."""
    campaign = read_study(workbook(tmp_path / "tiny.xlsx")).inputs.campaign.campaign
    cache = RunCache(tmp_path / "cache")

    def interrupt(done, total):
        if done >= 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_campaign(campaign, store=cache, batch_size=1, progress=interrupt)
    assert len(cache) == 1 and not list((tmp_path / "cache").rglob(".part-*"))
    resumed = run_campaign(campaign, store=cache, batch_size=1)
    assert (resumed.execution.cached, resumed.execution.computed) == (1, 2)
    fresh = run_campaign(campaign, store=MemoryStore())
    pd.testing.assert_frame_equal(resumed.metrics, fresh.metrics)


def test_a_damaged_cache_file_is_run_again(tiny, tmp_path):
    """A cache file that cannot be read counts as missing: that run is computed again."""
    _, _, cache = tiny
    import shutil

    copy = tmp_path / "cache"
    shutil.copytree(cache, copy)
    victim = sorted(copy.rglob("*.parquet"))[0]
    victim.write_bytes(b"not a parquet file")
    store = RunCache(copy)
    assert store.get(victim.stem) is None
    campaign = read_study(tiny[0]).inputs.campaign.campaign
    result = run_campaign(campaign, store=store)
    assert (result.execution.cached, result.execution.computed) == (2, 1)
    assert store.get(victim.stem) is not None


# -------------------------------------------------------------------------- bad input
def _bad(tmp_path, capsys, edits, fragments, args=(), extra=None, cell_of=None):
    path = workbook(tmp_path / "bad.xlsx", edits, extra)
    out, cache = tmp_path / "out", tmp_path / "cache"
    capsys.readouterr()
    start = time.perf_counter()
    code = main(["campaign", str(path), "--out", str(out), "--cache", str(cache), "--quiet",
                 *args])
    elapsed = time.perf_counter() - start
    err = capsys.readouterr().err
    assert code == 2, err
    for fragment in fragments:
        assert fragment in err, err
    if cell_of is not None:
        book = openpyxl.load_workbook(path)
        assert f"sheet 'Study', cell B{study_row(book, cell_of)}" in err, err
    assert "nothing was written" in err
    assert not out.exists() and not list(cache.rglob("*.parquet"))
    return elapsed


@pytest.mark.parametrize("name, value, fragment", [
    ("campaign area factors", ",", "needs at least one value"),
    ("campaign area factors", "1.0, 0", "must be >= 0.01 (allowed: in [0.01, 100])"),
    ("campaign area factors", "1.0, -1.4", "value '-1.4'"),
    ("campaign airspeeds EAS", "60, fast", "every value must be a number"),
    ("campaign manoeuvres", "free response, loop", "unknown manoeuvre; valid values are"),
    ("campaign carriers", "tethered", "unknown carrier; valid values are ['frozen', 'free']"),
    ("campaign cable lengths", "40", "could reach the carrier"),
    ("campaign no-parachute helicopters", "HC9", "unknown helicopter"),
    ("campaign minimum yaw damping", 1.5, "must be < 1 (allowed: in [0, 1))"),
    ("campaign loads margin", 0.8, "must be >= 1"),
])
def test_bad_study_rows(tmp_path, capsys, name, value, fragment):
    """Rules of the campaign's Study rows (schema): non-empty lists, factors in [0.01, 100], known
    manoeuvres, carriers and helicopters, cables that clear the parachute, damping criterion
    in [0, 1), margin >= 1. Each error names the Study cell."""
    _bad(tmp_path, capsys, {name: value}, [fragment], cell_of=name)


def test_unknown_mass_case_in_listed_rows(tmp_path, capsys):
    """Rule: a CampaignRuns row names a mass case of CampaignMasses (the error names the
    cell and lists the valid cases)."""
    def extra(book):
        masses = book.create_sheet("CampaignMasses")
        masses.append(["mass case", "mass [kg]"])
        masses.append(["maximum", 2900])
        runs = book.create_sheet("CampaignRuns")
        runs.append(["area factor [-]", "airspeed EAS [kt]", "mass case",
                     "density altitude [ft]", "cable length [ft]", "carrier", "manoeuvre"])
        runs.append([2.25, 60, "maximum", 0, 60, "frozen", "free response"])
        runs.append([2.25, 60, "heavy", 0, 60, "frozen", "free response"])

    _bad(tmp_path, capsys, {"campaign matrix": "listed rows"},
         ["sheet 'CampaignRuns', cell C3", "unknown mass case", "['maximum']", "heavy"],
         extra=extra)


def test_mass_cases_differing_only_in_case_are_one_name(tmp_path, capsys):
    """Rule (docs/inputs-and-outputs.md: ids are unique with case ignored): CampaignMasses
    names "max" and "MAX" are the same mass case; the error is at the second one's cell."""
    def extra(book):
        masses = book.create_sheet("CampaignMasses")
        masses.append(["mass case", "mass [kg]"])
        masses.append(["max", 2900])
        masses.append(["MAX", 2500])

    _bad(tmp_path, capsys, {}, ["sheet 'CampaignMasses', cell A3", "duplicate mass case",
                                "first at A2", "case ignored"], extra=extra)


def test_unreachable_scheduler_is_a_clear_error_within_its_time_out(tmp_path, capsys):
    """A scheduler nobody answers (--scheduler-timeout 1 s): exit 2 (not a hang: the guard
    is generous, the time taken depends on the machine), the address and the time-out in the
    message, nothing written or cached."""
    elapsed = _bad(tmp_path, capsys, {}, ["could not reach the Dask scheduler within 1 s",
                                          "tcp://127.0.0.1:9"],
                   args=["--scheduler", "tcp://127.0.0.1:9", "--scheduler-timeout", "1"])
    assert elapsed < DEADLINE


def test_cache_inside_the_output_folder_is_refused(tmp_path, capsys):
    """Rule: the run cache lies outside --out (that folder is replaced as a whole)."""
    path = workbook(tmp_path / "tiny.xlsx")
    out = tmp_path / "out"
    assert main(["campaign", str(path), "--out", str(out), "--cache", str(out / "cache"),
                 "--quiet"]) == 2
    assert "outside the output folder" in capsys.readouterr().err
    assert not out.exists()


def test_run_chains_the_campaign_then_the_loads(tiny, tmp_path):
    """`slingloads run` with 'run campaign' and 'run loads': the campaign is computed first and
    the loads report gains the dynamics' cases (LoadCases column 'source') and a Dynamics
    sheet comparing them with the hand-entered ones; the hook cone stays at the CS-29.865
    30 deg ('campaign loads hook angle' default)."""
    path = workbook(tmp_path / "tiny.xlsx", {"run loads": "yes"})
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--cache", str(tiny[2]),
                 "--quiet"]) == 0
    raw = pd.read_excel(out / "tiny-loads.xlsx", sheet_name="LoadCases", header=None)
    head = int(np.nonzero(raw.isin(["source"]).any(axis=1).to_numpy())[0][0])
    cases = raw.iloc[head + 1:].set_axis(list(raw.iloc[head]), axis=1)  # under its title
    assert "dynamics" in set(cases["source"])
    assert set(cases["source"]) <= {"CS-29.865 direction", "towed equilibrium", "dynamics",
                                    "hand-listed"}
    assert cases.loc[cases["source"] == "dynamics", "aero"].str.startswith("DYN-").any()
    _, handoff = report_table(out / "tiny-loads.xlsx", "Dynamics", "Hand-entered against")
    rows = handoff.set_index("quantity")
    assert rows.loc["hook cone, fore-and-aft angle from the vertical", "used in the loads"] == 30
    dynamics = pd.read_excel(out / "tiny-loads.xlsx", sheet_name="Dynamics", header=None)
    assert "hand-entered cases" in set(dynamics[1])
    # the hand-off table prints as one block (its notes wrap narrower), not in column parts
    assert not dynamics[0].astype(str).str.contains(", part 1 of").any()
    # an angle at one precision (0.1 deg) in its ranges as in its numbers
    angles = rows[rows["unit"] == "deg"].drop(columns="unit")
    texts = [v for v in angles.to_numpy().ravel() if isinstance(v, str)]
    decimals = {len(n.split(".")[1]) if "." in n else 0
                for t in texts for n in re.findall(r"(?<![\w.+-])-?\d+(?:\.\d+)?(?![\w.])", t)}
    assert decimals <= {1}, (decimals, texts)
    assert (out / "tiny-campaign.xlsx").exists()


def test_ctrl_c_keeps_the_finished_runs_and_the_next_run_resumes(tmp_path, capsys,
                                                                monkeypatch):
    """Ctrl-C during the second batch (the wind ramp; the first held the 2 matrix runs): exit
    130, nothing written, the 2 runs cached; the same command again finds the 2 matrix runs
    and computes the ramp."""
    from slingloads.analyses.campaign import execution

    path = workbook(tmp_path / "tiny.xlsx")
    out, cache = tmp_path / "out", tmp_path / "cache"
    calls = []
    original = execution.run_batch

    def interrupted(jobs, settings, threads=None):
        calls.append(len(jobs))
        if len(calls) == 2:
            raise KeyboardInterrupt
        return original(jobs, settings, threads)

    monkeypatch.setattr(execution, "run_batch", interrupted)
    args = ["campaign", str(path), "--out", str(out), "--cache", str(cache), "--quiet"]
    assert main(args) == 130
    assert "interrupted; nothing was written" in capsys.readouterr().err
    assert not out.exists() and len(RunCache(cache)) == 2
    monkeypatch.setattr(execution, "run_batch", original)
    assert main(args) == 0
    frame = pd.read_excel(out / "tiny-campaign.xlsx", sheet_name="Summary", header=None)
    rows = dict(zip(frame[0], frame[1], strict=False))
    assert (rows["runs found in the cache"], rows["runs computed now"]) == (2, 0)
    assert (rows["runs without parachute found in the cache"],
            rows["runs without parachute computed now"]) == (0, 1)


def test_progress_bar_shows_runs_done_rate_and_time_left(tiny, tmp_path, capsys):
    """Without --quiet the campaign's bar (tqdm) counts the runs: it starts at the runs found
    in the cache (area factors 2.25, 2.9 -> 2.25, 2.7 on the tiny campaign's cache: the 2.25 run
    and the ramp are found, 2 of 3) and ends at 3/3, with the rate (run/s, or s/run as tqdm
    writes a rate under one run a second) and the time left (tqdm's ``<`` remaining-time
    field) on the line."""
    _, _, cache = tiny
    path = workbook(tmp_path / "bar.xlsx", {"campaign area factors": "2.25, 2.7"})
    assert main(["campaign", str(path), "--out", str(tmp_path / "out"), "--cache",
                 str(cache)]) == 0
    lines = [line for line in capsys.readouterr().err.replace("\r", "\n").splitlines()
             if line.startswith("campaign runs")]
    assert lines and "2/3" in lines[0]
    assert "3/3" in lines[-1] and "<" in lines[-1]
    assert "run/s" in lines[-1] or "s/run" in lines[-1], lines[-1]


def test_us_report_keeps_one_unit_per_quantity(tiny, tmp_path):
    """--units US from the same cache: the loads hand-off's line tension in lbf (the SI
    report's N / 4.4482216152605, 1 lbf = 0.45359237 kg x 9.80665 m/s^2 exactly), and the
    1.0 x neutral verdicts' conditions in the report's units (KEAS; the density altitude in
    ft, the cable in in as every length of a US report: 60 ft = 720 in exactly), with no
    airspeed in ft/s and no altitude in inches ('density altitude 0 in')."""
    path, out, cache = tiny
    us = tmp_path / "us"
    assert main(["campaign", str(path), "--out", str(us), "--cache", str(cache), "--units",
                 "US", "--quiet"]) == 0
    si_handoff = pd.read_excel(out / "tiny-campaign.xlsx", sheet_name="LoadsHandoff")
    us_handoff = pd.read_excel(us / "tiny-campaign.xlsx", sheet_name="LoadsHandoff")
    si_line = si_handoff.set_index("quantity").loc["line tension"]
    us_line = us_handoff.set_index("quantity").loc["line tension"]
    assert si_line["unit"] == "N" and us_line["unit"] == "lbf"
    assert float(us_line["reached max"]) == pytest.approx(
        float(si_line["reached max"]) / 4.4482216152605, rel=1e-12)
    neutral = pd.read_excel(us / "tiny-campaign.xlsx", sheet_name="NeutralArea")
    conditions = " ".join(neutral["condition"].astype(str))
    assert "KEAS" in conditions and "ft/s EAS" not in conditions
    assert "density altitude 0 ft" in conditions and "altitude 0 in" not in conditions
    assert "cable 720 in," in conditions and "cable 60 ft" not in conditions


def test_ramps_with_a_gust_read_from_the_study(tmp_path):
    """'campaign no-parachute gust ramps' and 'campaign no-parachute gust' reach the study
    in SI (20, 30 kt -> 10.29, 15.43 m/s; 15 ft/s -> 4.572 m/s); 'none' flies none."""
    from slingloads.constants import FOOT, KNOT

    def rows(book):
        book["Study"][f"B{study_row(book, 'campaign no-parachute gust ramps')}"] = "30, 20"
        book["Study"][f"B{study_row(book, 'campaign no-parachute gust')}"] = 15

    study = read_study(workbook(tmp_path / "gust.xlsx", extra=rows)
                       ).inputs.campaign.campaign.no_parachute
    np.testing.assert_allclose(study.gust_targets, (20 * KNOT, 30 * KNOT))
    assert study.gust_speed == pytest.approx(15 * FOOT)
    none = read_study(BASE[0]).inputs.campaign.campaign.no_parachute
    assert none.gust_targets == () and none.gust_jobs() == []

"""Hostile and careless input to the multibody model (`slingloads simulate`) and the campaign
(`slingloads campaign`): every size of the work bounded before any run, every error located in
the user's unit, the command-line options checked before anything is computed, and a killed
`simulate` leaving the previous report set or the new one.

The reference is the contract of docs/inputs-and-outputs.md (sections 1, 4, 6 and 8) and the
limits of slingloads/limits.py. The workbook is the small one of tests/hostile.py asking for
the two dynamics analyses only (runs of 5 s).
"""

from __future__ import annotations

import hashlib
import importlib
import os

import pytest
from hostile import (
    command,
    copy_book,
    helper_ready,
    save_xlsx,
    set_parameter,
    small_dynamics_workbook,
    wait_for_publishing_step,
    wait_until,
)

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.common.atomic import STEP_VARIABLE, TEMP_PREFIX
from slingloads.io.common.helper import PROCESSES_VARIABLE
from slingloads.io.common.ownership import MANIFEST_NAME, carries_mark
from slingloads.io.common.workbook import WorkbookReader
from slingloads.io.study import read_study
from slingloads.limits import (
    MAX_CAMPAIGN_RUNS,
    MAX_LIST_ITEMS,
    MAX_MULTIBODY_RUN_STEPS,
    MAX_MULTIBODY_SAMPLES,
    MAX_WORKERS,
)

FILE = "dyn.xlsx"


def _read(book):
    return read_study(FILE, reader=WorkbookReader.from_rows(book, file=FILE))


def _refused(book, *fragments):
    with pytest.raises(InputError) as info:
        _read(book)
    err = info.value
    assert err.file == FILE and err.sheet and err.cell, str(err)
    for fragment in fragments:
        assert fragment in str(err), str(err)
    return err


def _with(name, value, unit=None):
    return set_parameter(copy_book(small_dynamics_workbook()), name, value, unit)


# ---- bounds at the cell, in the user's unit -----------------------------------------------
@pytest.mark.parametrize("name, value, unit, fragment", [
    ("multibody simulation time", 1e5, "s", "must be <= 3600 s"),
    ("multibody simulation time", 2, "h", "must be <= 1 h"),
    ("multibody relative tolerance", 1e-20, None, "must be >= 1e-13"),
    ("multibody absolute tolerance", 10, None, "must be <= 1"),
    ("multibody time step", 5, "s", "must be <= 1 s"),
    ("multibody airspeed EAS", 500, "kt", "must be <= 200 kt"),
    ("multibody cable length", 2000, "ft", "must be <= 1640.42 ft"),
    ("multibody cable EA", 10, "lbf", "must be >= 2248.09 lbf"),
    ("multibody canopy mass", 0.001, "kg", "must be >= 0.1 kg"),
    ("multibody density altitude", 50000, "ft", "allowed: in [-2001.31, 36089.2] ft"),
    ("campaign run length", -1, "s", "must be > 0 s"),
    ("campaign time step", 2, "s", "must be <= 1 s"),
    ("campaign stability map areas", 10**9, None, "must be <= 200"),
    ("campaign workers", 10**9, None, "must be <= 64"),
    ("campaign scheduler time-out", 1e4, "s", "must be <= 600 s"),
])
def test_parameters_out_of_their_bounds_are_refused_at_their_cell(name, value, unit, fragment):
    """Each parameter that sets a magnitude or the size of the work has a stated range
    (docs/inputs-and-outputs.md section 8); a value outside is refused at its cell with the
    bound converted to the unit the user wrote (2 h > 3600 s; 10 N > ... in lbf: 1e4 N =
    2248.09 lbf)."""
    _refused(_with(name, value, unit), fragment, str(unit or ""))


@pytest.mark.parametrize("sheet, row, column, value, fragment", [
    ("MultibodyManoeuvres", 2, 4, -1e9, "must not exceed"),
    ("MultibodyManoeuvres", 2, 5, 1e5, "must be <= 3600 s"),
    ("MultibodyManoeuvres", 1, 9, 720.0, "must be <= 180 deg"),
    ("HTailAero", 2, 1, 50.0, "must be <= 3"),
    ("CampaignMasses", 1, 1, 1e7, "must"),
    ("CampaignMasses", 1, 1, 0.0, "must be > 0 kg"),
])
def test_sheet_cells_out_of_their_bounds_are_refused_at_their_cell(sheet, row, column, value,
                                                                   fragment):
    """Columns of the dynamics sheets carry bounds too: a gust of -1e9 ft/s, an onset of a
    day, a 720 deg initial yaw, a CN of 50, a 10,000 t or a massless mass case."""
    book = copy_book(small_dynamics_workbook())
    book[sheet][row][column] = value
    if sheet == "HTailAero":  # read with the full tail
        set_parameter(book, "multibody tail", "full tail")
    err = _refused(book, fragment)
    assert err.sheet == sheet


@pytest.mark.parametrize("name, text, unit, fragment", [
    ("campaign airspeeds EAS", "60, -80", "kt", "value '-80' [kt]"),
    ("campaign airspeeds EAS", "60, 1e9", "kt", "must not exceed"),
    ("campaign cable lengths", "60, 0", "ft", "must be > 0 ft"),
    ("campaign density altitudes", "0, 50000", "ft", "allowed: in [-2001.31, 36089.2] ft"),
    ("campaign area factors", "1.0, 1e-300", None, "must be >= 0.01"),
    ("campaign area factors", ",".join(["1.0"] * (MAX_LIST_ITEMS + 1)), None, "at most 50"),
    ("campaign no-parachute helicopters", "HC1, HC9", None, "unknown helicopter"),
])
def test_each_item_of_a_campaign_list_is_checked_at_its_cell(name, text, unit, fragment):
    """A comma-separated list is a text cell with a unit: each number is checked against its
    kind's magnitude and the list's bounds, the message echoing the item as written with the
    row's unit; a list holds at most MAX_LIST_ITEMS values."""
    _refused(_with(name, text, unit), fragment)


# ---- the size of the work, before any run -----------------------------------------------
def test_a_full_factorial_too_large_is_refused_before_it_is_built(monkeypatch):
    """Six lists of 50 values would be 50^6 = 1.6e10 runs: refused (at the longest list) by
    counting, before any run or matrix row exists (building the matrix fails this test); the
    message gives the product."""
    from slingloads.analyses.campaign.matrix import CampaignMatrix

    def built(*args, **kwargs):
        raise AssertionError("the matrix was built before its size was checked")

    monkeypatch.setattr(CampaignMatrix, "from_factors", classmethod(built))
    book = copy_book(small_dynamics_workbook())
    many = ", ".join(str(1 + 0.01 * i) for i in range(MAX_LIST_ITEMS))
    set_parameter(book, "campaign area factors", many)
    set_parameter(book, "campaign airspeeds EAS",
                  ", ".join(str(40 + i) for i in range(MAX_LIST_ITEMS)), "kt")
    set_parameter(book, "campaign density altitudes",
                  ", ".join(str(10 * i) for i in range(MAX_LIST_ITEMS)), "ft")
    err = _refused(book, "too much work", f"{MAX_CAMPAIGN_RUNS:,}", "x 50 airspeeds EAS")
    assert err.cell  # the longest list's cell


@pytest.mark.parametrize("name, value, unit, fragment", [
    ("campaign time step", 1e-6, "s", "steps"),
    ("campaign output interval", 1e-6, "s", "samples"),
    ("campaign stability map areas", 200, None, "stability map"),
])
def test_campaign_work_is_bounded_at_the_cell_that_sets_it(name, value, unit, fragment):
    """Runs x steps, runs x samples and the stability map's points are counted before any
    run; each excess is blamed on the parameter that sets it (map: 2 altitudes x 200 areas x
    10 airspeeds = 4,000 points > 2,000)."""
    book = _with(name, value, unit)
    set_parameter(book, "campaign stability map airspeeds", 10)
    err = _refused(book, "too much work", fragment)
    assert err.cell is not None


@pytest.mark.parametrize("name, value, limit", [
    ("multibody time step", 1e-6, MAX_MULTIBODY_RUN_STEPS),
    ("multibody output interval", 1e-5, MAX_MULTIBODY_SAMPLES),
])
def test_multibody_work_is_bounded_before_the_trim(name, value, limit):
    """2 runs of 5 s at a fixed step of 1 us are 1e7 steps (> 3e6); sampled every 10 us
    they store 1e6 samples (> 2e5): refused while reading, at the parameter's cell."""
    err = _refused(_with(name, value, "s"), "too much work", f"{limit:,}")
    assert err.value == value


def test_multibody_steps_at_the_limit_are_counted_as_whole_steps():
    """2 runs of 3,600 s at 0.0024 s are 2 x 1,500,000 = 3,000,000 steps, the limit itself:
    accepted (the division gives 1,500,000.0000000002 a run, once refused as '3,000,000
    steps, more than the 3,000,000 allowed'); at 0.0023 s (2 x 1,565,218) refused."""
    book = _with("multibody simulation time", 3600.0, "s")
    set_parameter(book, "multibody output interval", 1.0, "s")
    set_parameter(book, "multibody time step", 0.0024, "s")
    assert _read(book).inputs.multibody.settings["dt"] == 0.0024
    set_parameter(book, "multibody time step", 0.0023, "s")
    _refused(book, "too much work", "3,130,436 steps", f"{MAX_MULTIBODY_RUN_STEPS:,}")


def test_an_adaptive_run_forced_to_tiny_steps_is_refused_at_the_simulation_time(
        tmp_path, capsys, monkeypatch):
    """The adaptive step cannot outrun the fastest linear mode (|lambda| dt <= 3.3 for the
    Dormand-Prince pair, Hairer and Wanner II, IV.2): the steps it forces (runs x t_end x
    |lambda| / 3.3) are counted after the trim, before the integration. With the limit
    lowered to 5 steps (the base system's fastest mode, about 10 1/s, forces about 15 a run),
    `simulate` ends in exit 2 at the cell of 'multibody simulation time', nothing written."""
    module = importlib.import_module("slingloads.analyses.multibody.simulate")
    monkeypatch.setattr(module, "MAX_MULTIBODY_RUN_STEPS", 5)
    book = small_dynamics_workbook()
    path = save_xlsx(book, tmp_path / "stiff.xlsx")
    row = next(i for i, r in enumerate(book["Study"], 1) if r[0] == "multibody simulation time")
    out = tmp_path / "out"
    assert main(["simulate", str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"cell B{row}" in err and "adaptive steps" in err and "value 5" in err
    assert not out.exists()


# ---- command line ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def dynamics(tmp_path_factory):
    return save_xlsx(small_dynamics_workbook(), tmp_path_factory.mktemp("dyn") / "dyn.xlsx")


@pytest.mark.parametrize("options, code, fragment", [
    (["--workers", "0"], 2, "--workers must be in [1, 64]"),
    (["--workers", str(10**12)], 2, f"[1, {MAX_WORKERS}]"),
    (["--scheduler", "not an address!"], 2, "not a scheduler address"),
    (["--scheduler", "tcp://host:99999"], 2, "port must be in [1, 65535]"),
    # ws/ucx: distributed would read the first answer with no bound on memory
    (["--scheduler", "ws://host:8786"], 2, "over tcp:// or tls:// only"),
    (["--scheduler", "UCX://host:8786"], 2, "over tcp:// or tls:// only"),
    (["--scheduler-timeout", "nan"], 2, "--scheduler-timeout must be in (0, 600]"),
    (["--cache", "{out}"], 2, "outside the output folder"),
])
@pytest.mark.parametrize("command", ["campaign", "run"])
def test_campaign_options_are_checked_before_any_run(dynamics, tmp_path, capsys, options,
                                                     code, fragment, command):
    """Careless or hostile execution options end with a one-line message, exit 2 (a refused
    argument), nothing written, no traceback, before any run (no cache folder created), by
    ``campaign`` and by ``run`` alike. A cache that cannot be used is no refusal:
    tests/test_hostile_campaign.py."""
    out = tmp_path / "out"
    afile = tmp_path / "afile"
    afile.write_text("x")
    options = [o.format(out=out, file=afile) for o in options]
    argv = [command, str(dynamics), "--out", str(out), "--quiet"]
    if "--cache" not in options:
        argv += ["--cache", str(tmp_path / "cache")]
    assert main(argv + options) == code
    err = capsys.readouterr().err
    assert fragment in err and "Traceback" not in err and "nothing was written" in err
    assert not out.exists() and not (tmp_path / "cache").exists()


def test_campaign_options_are_checked_when_the_workbook_does_not_run_it(tmp_path, capsys):
    """The example does not run the campaign: ``run --workers -1`` is still a refused
    argument (exit 2, nothing written), not an option silently ignored."""
    from hostile import EXAMPLE

    out = tmp_path / "out"
    assert main(["run", str(EXAMPLE), "--out", str(out), "--quiet", "--workers", "-1"]) == 2
    err = capsys.readouterr().err
    assert "--workers must be in [1, 64]" in err and "value -1" in err
    assert not out.exists()


def test_an_output_folder_inside_the_run_cache_is_refused(dynamics, tmp_path, capsys):
    """Publishing replaces the output folder as a whole: inside the cache it would remove
    cached runs (an input of the next run), so it is refused before any run."""
    cache = tmp_path / "cache"
    assert main(["campaign", str(dynamics), "--out", str(cache / "runs"), "--cache",
                 str(cache), "--quiet"]) == 2
    assert "outside the run cache" in capsys.readouterr().err
    assert not cache.exists()


def test_simulate_and_campaign_outputs_neutralise_hostile_names(tmp_path):
    """Manoeuvre, mass-case and study names that a spreadsheet would run as formulas are
    written as text: an apostrophe before them in the CSV file, text cells in the workbooks
    (no cell of type formula)."""
    import csv

    from openpyxl import load_workbook

    book = small_dynamics_workbook()
    book["MultibodyManoeuvres"][1][0] = "=cmd|' /C calc'!A0"
    book["MultibodyManoeuvres"][2][0] = "@SUM(A1)"
    book["CampaignMasses"][1][0] = '=HYPERLINK("http://x")'
    set_parameter(book, "study name", "+1+2")
    path = save_xlsx(book, tmp_path / "evil.xlsx")
    out = tmp_path / "out"
    # runs of 5 s are too short for a verdict (inconclusive): no area is stable, a finding
    # reported with exit 3 and the reports written
    assert main(["run", str(path), "--out", str(out), "--quiet", "--cache",
                 str(tmp_path / "cache")]) == 3
    with open(out / "evil-multibody-histories.csv", newline="") as handle:
        runs = {row["run"] for row in csv.DictReader(handle)}
    assert runs == {"'=cmd|' /C calc'!A0", "'@SUM(A1)"}
    for name in ("evil-multibody.xlsx", "evil-campaign.xlsx"):
        workbook = load_workbook(out / name)
        kinds = {c.data_type for ws in workbook for row in ws.iter_rows() for c in row}
        assert "f" not in kinds, name


def test_report_outputs_lists_name_every_file_written(dynamics, tmp_path):
    """Every file `run` writes for the two analyses matches its report module's OUTPUTS
    (the publisher replaces exactly those of the previous report), and every one but the
    CSV tables carries slingloads' mark (the Parquet histories in their metadata:
    slingloads.io.common.ownership), so that a later run may replace it."""
    from slingloads.io.analyses import ANALYSES

    out = tmp_path / "out"
    # 5 s runs: no stable area, a finding (exit 3), the reports written
    assert main(["run", str(dynamics), "--out", str(out), "--quiet", "--cache",
                 str(tmp_path / "cache")]) == 3
    patterns = [p for a in ANALYSES if a.name in ("multibody", "campaign")
                for p in a.output_patterns("dyn")]
    files = sorted(p.name for p in out.iterdir() if p.name != MANIFEST_NAME)
    assert files and all(any(p.fullmatch(f) for p in patterns) for f in files), files
    assert "dyn-campaign-histories.parquet" in files
    assert [f for f in files if not f.endswith(".csv") and not carries_mark(out / f)] == []


def test_a_killed_simulate_leaves_the_previous_set_or_the_new_one(tmp_path):
    """Kill a real `slingloads simulate` (SIGKILL) at two moments, each awaited: while it
    reads and computes (once its helper is up), and after the exchange of the publishing (the
    run announces its publishing steps): the output folder holds the previous multibody
    report, then the new one, the user's file kept, and the next run leaves no staging
    folder."""
    (tmp_path / "old").mkdir()
    (tmp_path / "new").mkdir()
    old = save_xlsx(small_dynamics_workbook(), tmp_path / "old" / "study.xlsx")
    book = small_dynamics_workbook()
    set_parameter(book, "study name", "NEW")
    set_parameter(book, "multibody simulation time", 6.0, "s")
    new = save_xlsx(book, tmp_path / "new" / "study.xlsx")
    out, other = tmp_path / "reports", tmp_path / "other" / "reports"
    out.mkdir()
    (out / "notes.txt").write_text("mine")

    def state(folder=out):
        path = folder / "study-multibody-histories.csv"
        digest = hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else None
        return sorted(set(os.listdir(folder)) - {"notes.txt"}), digest

    # the two reports, side by side: the old one in the folder, the new one elsewhere
    runs = [command("simulate", old, out), command("simulate", new, other)]
    assert [p.wait() for p in runs] == [0, 0]
    reference = {"old": state(), "new": state(other)}
    assert reference["old"][1] != reference["new"][1]
    for moment, expected in (("helper", "old"), ("step 3", "new")):
        steps = tmp_path / f"steps-{moment}"
        steps.mkdir()
        proc = command("simulate", new, out, {STEP_VARIABLE: str(steps),
                                              PROCESSES_VARIABLE: "1"})
        try:
            if moment == "helper":
                wait_until(lambda: helper_ready(proc.pid), proc, "the helper")  # noqa: B023
            else:
                wait_for_publishing_step(proc, steps, 3)  # after the exchange
        finally:
            proc.kill()
            proc.wait()
        assert state() == reference[expected], moment
        assert (out / "notes.txt").read_text() == "mine"
    assert command("simulate", old, out).wait() == 0
    assert state() == reference["old"]
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(TEMP_PREFIX)]

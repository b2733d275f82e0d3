"""The code shown to users runs: the README's Python API example and docs/api.md, executed
as written (the reference is the documentation itself: an example that fails is a defect)."""

from __future__ import annotations

import os
import re
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
import pytest
from hostile import EXAMPLE

ROOT = Path(__file__).resolve().parents[1]


def python_blocks(path):
    return re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), re.S)


@pytest.mark.parametrize("doc", ["README.md", "docs/api.md"])
def test_python_examples_run(doc, tmp_path, monkeypatch):
    """Every ```python block of the page runs in order in one namespace, from the repository
    root (so relative paths such as loadcases/... resolve) with outputs in a temp folder."""
    matplotlib.use("Agg")
    blocks = python_blocks(ROOT / doc)
    assert blocks, f"{doc} has no python example"
    monkeypatch.chdir(tmp_path)
    (tmp_path / "loadcases").symlink_to(ROOT / "loadcases")
    namespace = {}
    for block in blocks:
        exec(compile(block, doc, "exec"), namespace)  # noqa: S102 - our own documentation
    assert os.listdir(tmp_path)


def test_readme_api_example_is_short():
    """The README's API example stays short: at most 15 lines."""
    blocks = python_blocks(ROOT / "README.md")
    assert len(blocks[0].strip().splitlines()) <= 15


def test_every_limit_is_documented():
    """Every limit of slingloads/limits.py is named, with its reason, on the inputs and
    outputs page (the reference: the page promises to state them all)."""
    import slingloads.limits as limits

    page = (ROOT / "docs" / "inputs-and-outputs.md").read_text(encoding="utf-8")
    names = [n for n in vars(limits) if n.startswith(("MAX_", "MIN_"))]
    assert names
    missing = [n for n in names if f"`{n}`" not in page]
    assert not missing, missing


# --------------------------------------------------------------- figures quoted from the example
def _text(name):
    """A page of the documentation with its line breaks as spaces."""
    return " ".join((ROOT / name).read_text(encoding="utf-8").split())


def _quoted(pattern, page):
    found = re.search(pattern, _text(page))
    assert found, f"{page} no longer quotes /{pattern}/: update the test with the page"
    return found.groups()


def _agrees(quoted, value):
    """The quoted figure is the value rounded to the digits quoted (half a unit of the last
    digit either way)."""
    text = quoted.replace(",", "").replace(" ", "")
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text) - value) <= 0.5 * 10.0**-decimals + 1e-12


def test_nastran_page_quotes_the_example_deck(example_results, tmp_path):
    """docs/nastran.md's card count and file size of the example deck, re-derived by writing
    the deck and counting the lines that open a card after BEGIN BULK (a card's name starts
    its first field)."""
    from slingloads.io.loads.nastran import write_nastran

    cases, items, points, cards, size = _quoted(
        r"\((\d+) cases, (\d+) mass items, (\d+) load points\) the file has ([\d,]+) cards "
        r"\(([\d.]+) MB\)", "docs/nastran.md")
    loads = example_results.loads
    path = tmp_path / "x.bdf"
    write_nastran(loads, path)
    lines = path.read_text().splitlines()
    bulk = lines[next(k for k, line in enumerate(lines) if line.startswith("BEGIN BULK")) + 1:]
    opened = [line for line in bulk if line[:1].isalpha() and not line.startswith("ENDDATA")]
    grids = sum(line.startswith("GRID") for line in opened)
    assert int(cases) == len(loads.case_ids)
    assert int(items) == sum(line.startswith("CONM2") for line in opened)
    assert int(points) == grids - int(items)
    assert int(cards.replace(",", "")) == len(opened)
    assert _agrees(size, path.stat().st_size / 1e6)


def test_loads_method_page_quotes_the_example(example_results):
    """docs/loads-method.md's hanging pitch, towed cable angles and mast-vertical against
    hanging Vz of the vertical case, re-derived from the example (the mast-vertical study is
    the example's with the Study's attitude changed, run again)."""
    import dataclasses

    import numpy as np

    loads = example_results.loads
    (pitch,) = _quoted(r"\*\*pitch (-?\d+\.\d+) deg", "docs/loads-method.md")
    assert _agrees(pitch, np.degrees(loads.attitude.pitch))
    at_nz, at_1g = _quoted(r"at most (\d+\.\d+) deg at Nz 2\.5 and (\d+\.\d+) deg at 1 g",
                           "docs/loads-method.md")
    towed = loads.towed_table()
    assert _agrees(at_nz, towed["cable angle from vertical [deg]"].max())
    assert _agrees(at_1g, towed["cable angle at 1 g [deg]"].max())
    low, high = _quoted(r"Vz forward of the hub is (\d+) to (\d+) % higher", "docs/loads-method.md")
    mast = dataclasses.replace(loads.study, attitude="mast vertical").run().to_frame()
    hanging = loads.to_frame()
    triplets = re.findall(r"(FS\d{4}) ([\d ]+?) -> ([\d ]+?) N", _text("docs/loads-method.md"))
    assert len(triplets) == 3
    rises = []
    for station, before, after in triplets:
        pick = {"case": "LC0001", "station": station}
        was = mast.loc[(mast[list(pick)] == pd.Series(pick)).all(axis=1), "Vz_N"].item()
        now = hanging.loc[(hanging[list(pick)] == pd.Series(pick)).all(axis=1), "Vz_N"].item()
        assert _agrees(before, was) and _agrees(after, now), station
        rises.append(100 * (now / was - 1))
    assert int(low) <= min(rises) and max(rises) <= int(high) + 1


def test_readme_quotes_the_example(example_results):
    """The README's figures of the parachute sizing and of the multibody trim and modes,
    re-derived from the example's results."""
    sizing, multibody = example_results.chute_sizing, example_results.multibody
    neutral, recommended, line = _quoted(
        r"neutral area (\d+\.\d+) m\^2 on the local slopes.*?recommended (\d+\.\d+) m\^2.*?"
        r"line\s+(\d+\.\d+) m", "README.md")
    assert _agrees(neutral, sizing.static.area)
    assert _agrees(recommended, sizing.recommended_area)
    assert _agrees(line, sizing.line.line_length)
    trim = multibody.trim.to_frame().iloc[0]
    pitch, swing, tension = _quoted(r"trimmed pitch (-?\d+\.\d+) deg, swing (\d+\.\d+) deg, "
                                    r"tension (\d+\.\d+) W", "README.md")
    assert _agrees(pitch, trim["pitch [deg]"]) and _agrees(swing, trim["swing from vertical [deg]"])
    assert _agrees(tension, trim["tension / weight [-]"])
    modes = multibody.linear.modes_frame().set_index("mode")
    zeta, half, rate, roll_zeta = _quoted(
        r"damping ratio (\d+\.\d+), half amplitude in (\d+\.\d+) s; the least damped mode is "
        r"the hung body's roll, (\d+\.\d+) rad/s, damping ratio (\d+\.\d+)", "README.md")
    assert _agrees(zeta, modes.loc["yaw / lateral swing 1", "damping ratio [-]"])
    assert _agrees(half, modes.loc["yaw / lateral swing 1", "time to half or double [s]"])
    assert _agrees(rate, modes.loc["roll", "natural frequency [rad/s]"])
    assert _agrees(roll_zeta, modes.loc["roll", "damping ratio [-]"])


def test_reports_page_gives_the_plot_units():
    """docs/reports.md names the units of the SFBM plots as the plots label them."""
    from slingloads.io.loads.plots import component_label

    row = next(line for line in (ROOT / "docs/reports.md").read_text().splitlines()
               if line.startswith("| force, moment on"))
    for units in ("SI", "US"):
        for component in ("Vy", "Mz"):
            unit = re.search(r"\[(.*)\]", component_label(component, units)).group(1)
            assert unit in row, (units, component, row)
    assert "kN" not in row.split("(the SFBM plots")[1]


def test_readme_outputs_name_the_condition_of_the_lateral_shear_plot(example_reports):
    """The README names the condition under which the optional `-shear.png` appears, and the
    example, which meets it (loads in the same run, recommended angle below 90 deg), writes
    it."""
    _, folder = example_reports
    readme = _text("README.md")
    assert re.search(r"`-shear\.png` only when", readme)
    assert list(folder.glob("*-lateral-shear.png"))


def test_readme_quotes_the_lateral_example(example_results):
    """The README's figures of the lateral study (cases, largest load angles, recommended
    angle, tension factor), re-derived from the example's lateral result."""
    lateral = example_results.lateral.study
    cases, nominal, ranges, rec, tension = _quoted(
        r"(\d+) cases, largest load angle\s+(\d+\.\d) deg with nominal inputs and "
        r"(\d+\.\d) deg over.*?recommended design angle [\d.]+ x [\d.]+ = (\d+\.\d) deg.*?"
        r"tension T/\(m g\) (\d+\.\d+)", "README.md")
    import numpy as np

    assert int(cases) == len(lateral.pendulums)
    assert _agrees(nominal, np.degrees(lateral.nominal_max_load_angle))
    assert _agrees(ranges, np.degrees(lateral.max_load_angle))
    assert _agrees(rec, np.degrees(lateral.recommended_angle))
    assert _agrees(tension, lateral.max_tension_ratio)


def test_readme_quotes_the_campaign_example(example_campaign_run_report):
    """The README's paragraph on the example's campaign (runs, areas, the 1.0 x verdict of the
    gust at the lowest airspeed, the speed limits without parachute, HC2's verdict), against
    the campaign report of ``slingloads run`` with the campaign on, read back from the xlsx."""
    import pandas as pd

    path = next(example_campaign_run_report.glob("*-campaign.xlsx"))
    summary = pd.read_excel(path, "Summary", header=None)
    items = {r[0]: r[1] for r in summary.itertuples(index=False) if isinstance(r[0], str)}
    runs, factor, neutral, area, speed, verdict, limit, hc2 = _quoted(
        r"(\d+) runs, smallest stable and recommended area (\d+\.\d) x the neutral "
        r"(\d+\.\d+) m\^2 = (\d+\.\d+)\s+m\^2 \(at 1\.0 x the (\d+) KEAS gust response is "
        r"(\w[\w ()]*?):.*?speed limit (>= \d+ kt)\) and HC2 not even at\s+\d+ kt \(a ([\w ]+) of",
        "README.md")
    assert int(runs) == items["runs in the matrix"]
    assert _agrees(neutral, items["neutral static area (1-DOF sizing)"])
    assert _agrees(area, items["recommended area (least drag meeting the damping criterion)"])
    assert _agrees(area, items["smallest area stable in every condition"])
    assert _agrees(factor, items["recommended area (least drag meeting the damping criterion)"]
                   / items["neutral static area (1-DOF sizing)"])
    table = pd.read_excel(path, "NeutralArea")
    gust = table[(table["model"] == "multibody") & (table["test"].str.startswith("gust"))
                 & table["condition"].str.startswith(f"{speed} KEAS")]
    assert len(gust) == 1 and gust["verdict"].iloc[0] == verdict
    limits = {r[0]: (r[1], r[4]) for r in summary.itertuples(index=False)
              if r[0] in ("HC1", "HC2")}
    assert limits["HC1"][0].startswith(limit)
    assert limits["HC2"][1] == hc2


def _modules_with_examples():
    """The modules of slingloads whose source holds a ``>>>`` example, by dotted name."""
    package = ROOT / "slingloads"
    names = []
    for path in sorted(package.rglob("*.py")):
        if ">>>" in path.read_text(encoding="utf-8"):
            parts = path.relative_to(ROOT).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


MODULES_WITH_EXAMPLES = _modules_with_examples()


def test_the_docstring_examples_are_found():
    """The search below finds the modules that show examples (at least the ones known to:
    a search that found none would make the doctest test pass without running anything)."""
    assert {"slingloads.models.flight", "slingloads.io.common.atomic"} <= set(
        MODULES_WITH_EXAMPLES)


@pytest.mark.parametrize("name", MODULES_WITH_EXAMPLES)
def test_docstring_examples_run(name, tmp_path, monkeypatch):
    """Every ``>>>`` example in the module's docstrings gives the output written under it
    (the reference is the documentation itself, run by the standard library's doctest);
    an example marked to be skipped counts as not run."""
    import doctest
    import importlib
    import shutil

    # files an example writes land in a temp folder, which holds the example workbook at the
    # path the examples name (relative to the repository, as a user runs them)
    (tmp_path / "loadcases").mkdir()
    shutil.copy(EXAMPLE, tmp_path / "loadcases" / EXAMPLE.name)
    monkeypatch.chdir(tmp_path)
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    examples = skipped = 0
    report = []
    for test in finder.find(module, name):
        examples += len(test.examples)
        skipped += sum(bool(e.options.get(doctest.SKIP)) for e in test.examples)
        runner.run(test, out=report.append)
    assert examples and not skipped, f"{name}: {examples} examples, {skipped} skipped"
    assert runner.failures == 0, "".join(report)


# ------------------------------------------------------------ the README's table of output files
def _outputs_table():
    """The README's table of output files: [(file names as written, condition)]."""
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    start = lines.index("| file | written when |") + 2
    rows = []
    for line in lines[start:]:
        if not line.startswith("|"):
            break
        files, condition = line.strip("|").split(" | ", 1)
        rows.append((re.findall(r"`((?:IN-|\.slingloads)[^`]+)`", files), condition))
    assert rows
    return rows


def _pattern(name, stem="{stem}"):
    """A file name of the table as a pattern of the report modules' OUTPUTS (its upper-case
    placeholders as ``*``)."""
    if not name.startswith("IN-"):  # the folder's own file
        return name
    name = name.replace("hull_A_B_STATION", "hull_*").replace("campaign-TAG", "campaign-*")
    return stem + name[len("IN"):]


def test_readme_outputs_table_lists_the_files_the_report_modules_name():
    """The table names exactly the files the report modules publish (their ``OUTPUTS``, the
    publisher's list; the legacy ``-sfbm_all.png`` of earlier versions, which a report only
    removes, aside), each once."""
    from slingloads.io.campaign.report import OUTPUTS as campaign
    from slingloads.io.chute.report import OUTPUTS as chute
    from slingloads.io.common.ownership import MANIFEST_NAME as MANIFEST
    from slingloads.io.lateral.report import OUTPUTS as lateral
    from slingloads.io.loads.report import OUTPUTS as loads
    from slingloads.io.multibody.report import OUTPUTS as multibody

    listed = [_pattern(name) for names, _ in _outputs_table() for name in names]
    assert len(listed) == len(set(listed)), listed
    assert MANIFEST in listed
    listed.remove(MANIFEST)
    code = set(loads + lateral + chute + multibody + campaign) - {"{stem}-sfbm_all.png"}
    assert set(listed) == code


def _quoted_flags(condition):
    """The Study rows a condition asks to be yes: `run loads = yes`, Study row `X` = yes."""
    return ([q.lower() for q in re.findall(r"`(run [a-z ]+) = yes`", condition)]
            + [q.lower() for q in re.findall(r"`([^`]+)` = yes", condition)])


def test_readme_outputs_table_names_study_rows_that_exist():
    """Every Study row a condition of the table quotes (`run loads = yes`, `SFBM workbook`,
    `hull pairs`...) is a parameter the workbook reader knows
    (slingloads.io.analyses.all_parameters), and a row that switches a file on is a flag."""
    from slingloads.io.analyses import all_parameters

    known = all_parameters()
    quoted = [q.split(" = ")[0].lower() for _, condition in _outputs_table()
              for q in re.findall(r"`([^`]+)`", condition)
              if not q.startswith(("slingloads ", "--")) and q != "run"]
    assert {"run loads", "sfbm workbook", "nastran bulk data", "hull pairs"} <= set(quoted)
    unknown = [q for q in quoted if q not in known]
    assert not unknown, unknown
    flags = [f for _, condition in _outputs_table() for f in _quoted_flags(condition)]
    assert flags and all(known[f].kind == "flag" for f in flags), flags


def _study_flags():
    """The example's Study sheet: row name lower-cased -> yes/no, the default where the
    sheet leaves a flag out (slingloads.io.analyses.all_parameters)."""
    import openpyxl

    from slingloads.io.analyses import all_parameters

    flags = {name: p.default for name, p in all_parameters().items() if p.kind == "flag"}
    book = openpyxl.load_workbook(EXAMPLE, read_only=True)
    for row in book["Study"].iter_rows(min_row=2, values_only=True):
        name = str(row[0]).strip().lower()
        if name in flags and row[1] is not None:
            flags[name] = row[1]
    return {name: str(value).strip().lower() in ("yes", "true", "1")
            for name, value in flags.items()}


def test_readme_outputs_table_matches_what_the_example_writes(example_run_report,
                                                              example_campaign_run_report,
                                                              example_results):
    """Every file the example's ``slingloads run`` writes (and with its campaign on) matches
    exactly one name of the table; each row is written or not as its condition says, judged
    from the example's Study sheet (the flags the row quotes) and from its results (a sweep,
    a trim, the hook cases re-run at the recommended angle)."""
    from fnmatch import fnmatch

    table = _outputs_table()
    flags = _study_flags()
    assert not flags["run campaign"]  # the campaign run below turns it on
    derived = {"sweeps areas": example_results.chute_sizing.sweep is not None,
               "when it trims": bool(example_results.multibody.trim.converged),
               "re-run at the recommended angle": example_results.lateral.comparison is not None}
    for folder, campaign in ((example_run_report, False), (example_campaign_run_report, True)):
        stem = next(folder.glob("*-loads.xlsx")).name[:-len("-loads.xlsx")]
        written = sorted(p.name for p in folder.iterdir())
        for name in written:
            rows = [k for k, (names, _) in enumerate(table)
                    if any(fnmatch(name, _pattern(n, stem)) for n in names)]
            assert len(rows) == 1, (name, rows)
        for names, condition in table:
            expected = all(flags[f] or (campaign and f == "run campaign")
                           for f in _quoted_flags(condition))
            expected &= all(value for words, value in derived.items() if words in condition)
            present = [any(fnmatch(w, _pattern(n, stem)) for w in written) for n in names]
            assert present == [expected] * len(names), (names, condition, campaign)


# ------------------------------------------------------------ timing claims cite their script
def test_timing_claims_cite_scripts_that_exist():
    """Timings cannot be checked by a timed test: the pages state them as measured, with the
    date, and name the script that measures them; every benchmarks/ script a page names
    exists, and the README's compile and first-run times name theirs beside a date."""
    pages = ["README.md", *(f"docs/{p.name}" for p in (ROOT / "docs").glob("*.md"))]
    for page in pages:
        for script in re.findall(r"(?:benchmarks/)?(bench_\w+\.py|paper_comparison\.py)",
                                 _text(page)):
            assert (ROOT / "benchmarks" / script).is_file(), (page, script)
    readme = _text("README.md")
    assert re.search(r"Times measured on \d{4}-\d\d-\d\d on the 2-core", readme)
    for script in ("bench_compile.py", "bench_first_run.py"):
        assert f"benchmarks/{script}" in readme, script


# ------------------------------------------------- more figures quoted from the example's run
def _deg(x):
    return float(np.degrees(x))


def _hub_over_cg(r):
    """(aft, above) of the hub from the CG of the example's mass items. [m]"""
    d = r.study.airframe.hardpoints.hub - r.study.airframe.mass_items.cg
    return d[0], d[2]


def _towed_case(r):
    return r.loads.towed_table().iloc[0]


def _lateral_critical(r):
    return r.lateral.study.critical_case


def _lateral_nominal(r):
    frame = r.lateral.study.to_frame()
    return frame[frame["nominal [-]"]].iloc[0]


def _gust(r):
    frame = r.multibody.to_frame().set_index("run")
    return frame.loc[next(k for k in frame.index if "gust" in k)]


def _neutral_about_airframe_z(r):
    """The sizing's neutral area with its yaw axis airframe z ('chute sizing yaw axis' =
    airframe z) at the same towed trim, by the functions the run calls. [m^2]"""
    from slingloads.analyses.chute_sizing import neutral_area
    from slingloads.analyses.towed_attitude import yaw_model_about

    sizing = r.chute_sizing
    model, _ = yaw_model_about(sizing.inputs.model, "airframe z", sizing.towed,
                               sizing.towed.trim.system.body)
    return neutral_area(model, sizing.inputs.fit_range).area


def _trimmed_pitch(r, keas):
    """The pitch of the example's multibody system trimmed at ``keas`` KEAS, or None. [deg]"""
    from slingloads.analyses.multibody import trim
    from slingloads.constants import KNOT

    point = trim(r.multibody.inputs.system.with_(airspeed=keas * KNOT))
    return point.to_frame().iloc[0]["pitch [deg]"] if point.converged else None


def _last_trim(r):
    """The airspeed above which the example's system no longer trims, to the nearest 5 kt
    (a page's "about"): the highest multiple of 5 KEAS from 100 with a trim. [kt]"""
    keas = 100
    while keas < 200 and _trimmed_pitch(r, keas + 5) is not None:
        keas += 5
    return keas


def _line_reach(r):
    """(nearest, farthest) distance from the hub the example's parachute line reaches, by the
    function the system's check calls (a cable in between is refused). [m]"""
    from slingloads.models.multibody.parachute_line import line_reach

    system = r.multibody.inputs.system
    return line_reach(system.hardpoints.hub, system.hardpoints.chute,
                      system.parachute.line_length)


#: (page, pattern, the values its groups quote, from the example's results): each group is
#: compared at the digits it is written with (:func:`_agrees`), a text group exactly.
QUOTES = {
    "README mass": ("README.md", r"a generic light twin of about (\d+\.\d) t",
                    lambda r: [r.study.airframe.mass_items.mass.sum() / 1000]),
    "README findings hook angle": (
        "README.md", r"which governs \(example: (\d+\.\d) deg\)",
        lambda r: [_deg(r.lateral.study.recommended_angle)]),
    "README lateral margin and critical case": (
        "README.md", r"\(the (\d+\.\d+) g (cycloidal) sidestep in (\d+) s on the (\d+) ft rope\), "
        r"recommended design angle (\d+\.\d) x (\d+\.\d) =",
        lambda r: [_lateral_critical(r)["peak S'' [g]"], "cycloidal",
                   _lateral_critical(r)["motion duration [s]"],
                   _lateral_critical(r)["rope length [m]"] / 0.3048,
                   r.lateral.study.margin, _deg(r.lateral.study.max_load_angle)]),
    "README sizing condition": (
        "README.md", r"at the towed trim's angle of attack (-\d+\.\d) deg at (\d+) KEAS",
        lambda r: [_deg(r.chute_sizing.towed.alpha), r.chute_sizing.towed.airspeed / 0.514444]),
    "README sizing areas": (
        "README.md", r"\((\d+\.\d+) on the fitted slopes; .*? recommended (\d+\.\d+) m\^2 "
        r"\((\d+\.\d) x neutral\), .*?\(Study `parachute area` (\d+\.\d) m\^2, .*? line "
        r"(\d+\.\d+) m, (\d+) ft cable (passes)",
        lambda r: [r.chute_sizing.static.area_fit, r.chute_sizing.recommended_area,
                   r.chute_sizing.recommended_area / r.chute_sizing.static.area,
                   r.chute_sizing.inputs.study_area, r.chute_sizing.line.line_length,
                   r.chute_sizing.line.cable.cable_length / 0.3048,
                   "passes" if r.chute_sizing.line.cable.ok else "fails"]),
    "README sizing peak sideslip": (
        "README.md", r"\(the example: (\d+\.\d) deg, within \+-(\d+) deg\)",
        lambda r: [_deg(r.chute_sizing.study_area_peak_sideslip[0]),
                   _deg(r.chute_sizing.inputs.fit_range[1])]),
    "README multibody runs": (
        "README.md", r"the (four) runs (converge), the 30 ft/s lateral gust turning the "
        r"helicopter (\d+\.\d) deg with (\d+\.\d) deg of sideslip and (\d+\.\d) deg of lateral "
        r"swing",
        lambda r: ["four" if len(r.multibody.to_frame()) == 4 else "other",
                   "converge" if (r.multibody.to_frame()["verdict"] == "convergent").all()
                   else "not all", abs(_gust(r)["yaw change [deg]"]),
                   abs(_gust(r)["beta peak [deg]"]), abs(_gust(r)["swing lateral peak [deg]"])]),
    "sizing page peak sideslip": (
        "docs/parachute-sizing.md", r"the (1-cosine) gust reaches (\d+\.\d) deg against "
        r"\+-(\d+) deg",
        lambda r: [r.chute_sizing.study_area_peak_sideslip[1],
                   _deg(r.chute_sizing.study_area_peak_sideslip[0]),
                   _deg(r.chute_sizing.inputs.fit_range[1])]),
    "sizing page results": (
        "docs/parachute-sizing.md", r"at the towed trim's angle of attack \((-\d+\.\d) deg at "
        r"(\d+) KEAS, .*?through the hub, (\d+\.\d) deg from airframe z\), neutral area "
        r"(\d+\.\d+) m\^2 on the local slopes at zero sideslip \((\d+\.\d+) m\^2 on the "
        r"\+-15 deg least-squares slopes; .*? recommended (\d+\.\d+) m\^2 \((\d+\.\d) x "
        r"neutral: .*? line (\d+\.\d+) m \(the wake's q ratio there is (\d+\.\d+), .*? cable "
        r"(\d+\.\d+) m >= (\d+\.\d+) m required\. Yaw inertia about the suspension axis "
        r"([\d,]+) kg m\^2",
        lambda r: [_deg(r.chute_sizing.towed.alpha), r.chute_sizing.towed.airspeed / 0.514444,
                   _deg(r.chute_sizing.axes_angle), r.chute_sizing.static.area_local,
                   r.chute_sizing.static.area_fit, r.chute_sizing.recommended_area,
                   r.chute_sizing.recommended_area / r.chute_sizing.static.area,
                   r.chute_sizing.line.line_length, r.chute_sizing.line.target,
                   r.chute_sizing.line.cable.cable_length, r.chute_sizing.line.cable.required,
                   r.chute_sizing.inputs.model.yaw_inertia]),
    "README neutral area about airframe z": (
        "README.md", r"about airframe z, the paper's balance of Mz, it would be (\d\.\d+)\)",
        lambda r: [_neutral_about_airframe_z(r)]),
    "sizing page airframe z and the Study's area": (
        "docs/parachute-sizing.md", r"the same aircraft's neutral area is (\d\.\d+) m\^2: .*?"
        r"rounded to 0\.1 m\^2: (\d\.\d) m\^2, (\d\.\d) x the neutral area about the "
        r"suspension axis",
        lambda r: [_neutral_about_airframe_z(r), r.chute_sizing.inputs.study_area,
                   r.chute_sizing.inputs.study_area / r.chute_sizing.static.area]),
    "multibody page trims against airspeed": (
        "docs/multibody.md", r"trims at (-\d+\.\d) deg of pitch at 60 KEAS, (-\d+\.\d) deg at 80, "
        r"(-\d+\.\d) deg at 100 and (-\d+\.\d) deg at 120 KEAS; beyond about (\d+) KEAS",
        lambda r: [*(_trimmed_pitch(r, v) for v in (60, 80, 100, 120)), _last_trim(r)]),
    "multibody page hang": (
        "docs/multibody.md", r"With the GENERIC data of the example \(CG (\d\.\d+) m ahead of the "
        r"hub, (-\d+) deg in hover;",
        lambda r: [_hub_over_cg(r)[0], _deg(r.loads.attitude.pitch)]),
    "README trim at 100 KEAS": (
        "README.md", r"moment balance\): (-\d+\.\d) deg at 100 KEAS, and beyond about (\d+) KEAS",
        lambda r: [_trimmed_pitch(r, 100), _last_trim(r)]),
    "campaign page trim at 100 KEAS": (
        "docs/campaign.md", r"at 100 KEAS the example's helicopter trims at (-\d+) deg of angle "
        r"of attack, within the table's -40 deg; beyond about (\d+) KEAS",
        lambda r: [_trimmed_pitch(r, 100), _last_trim(r)]),
    "Nastran page attitudes": (
        "docs/nastran.md", r"pitch (-\d+\.\d+) deg on the example\).*?\(the example's: pitch "
        r"(-\d+\.\d) deg\)",
        lambda r: [_deg(r.loads.attitude.pitch), _towed_case(r)["trim pitch [deg]"]]),
    "loads page hanging attitude": (
        "docs/loads-method.md", r"hub is (\d+\.\d+) m aft of the CG and (\d+\.\d+) m above it",
        lambda r: list(_hub_over_cg(r))),
    "loads page cases": (
        "docs/loads-method.md", r"parachute on/off = (\d+) cases by default\).*?on the "
        r"example one, `(LC\d+)`, with parachute.*?the towed case trims at pitch (-\d+\.\d) deg "
        r"with the parachute at (\d+) KEAS",
        lambda r: [int((r.loads.case_table()["hook"] != "TOW").sum()),
                   _towed_case(r)["case"], _towed_case(r)["trim pitch [deg]"],
                   r.loads.study.flight.eas / 0.514444]),
    "conventions page hanging attitude": (
        "docs/conventions.md", r"hub is (\d+\.\d+) m aft of and (\d+\.\d+) m above the CG: "
        r"pitch (-\d+\.\d+)°",
        lambda r: [*_hub_over_cg(r), _deg(r.loads.attitude.pitch)]),
    "lateral page example": (
        "docs/lateral-pendulum.md", r"level roll inertia, ([\d,]+) kg m\^2 .*?becomes "
        r"([\d,]+) kg m\^2 about the fore-and-aft axis of the hanging airframe, with the CG "
        r"(\d+\.\d+) m below the hub\. With the nominal inputs the largest load angle is "
        r"(\d+\.\d) deg; over \+-20 % of roll inertia, CG and rope length \((\d+) runs of 60 "
        r"s\) (\d+\.\d) deg, .*?; x (\d+\.\d) margin = (\d+\.\d) deg",
        lambda r: [r.study.airframe.mass_items.inertia_about_cg[0, 0],
                   _lateral_nominal(r)["roll inertia [kg m^2]"],
                   _lateral_nominal(r)["CG below hub [m]"],
                   _deg(r.lateral.study.nominal_max_load_angle),
                   len(r.lateral.study.pendulums), _deg(r.lateral.study.max_load_angle),
                   r.lateral.study.margin, _deg(r.lateral.study.recommended_angle)]),
    "lateral page nominal reduction": (
        "docs/lateral-pendulum.md", r"nominal inputs alone \(no spread\), (\d\.\d) x (\d+\.\d) = "
        r"(\d+\.\d) deg gives 1 - 0\.354 / 0\.5 = (\d+\.\d) % less Y shear than 30 deg \(not the "
        r"1 - sin \d+\.\d / sin 30 = (\d+) %",
        lambda r: [r.lateral.study.margin, _deg(r.lateral.study.nominal_max_load_angle),
                   r.lateral.study.margin * _deg(r.lateral.study.nominal_max_load_angle),
                   100 * (1 - np.sin(np.radians(45))),
                   100 * (1 - np.sin(r.lateral.study.margin
                                     * r.lateral.study.nominal_max_load_angle) / 0.5)]),
    "campaign page cables refused": (
        "docs/campaign.md", r"the example's (\d+\.\d) m line on its attachment (\d+\.\d) m aft of "
        r"the hub, cables from (\d+\.\d) to (\d+\.\d) ft are refused",
        lambda r: [r.multibody.inputs.system.parachute.line_length,
                   (r.multibody.inputs.system.hardpoints.chute
                    - r.multibody.inputs.system.hardpoints.hub)[0],
                   *(d / 0.3048 for d in _line_reach(r))]),
    "campaign page neutral area and line": (
        "docs/campaign.md", r"the example's (\d+\.\d) m line on.*?\(the example: (\d+\.\d+) m\^2 "
        r"at (-\d+\.\d) deg, (\d+) KEAS",
        lambda r: [r.chute_sizing.line.line_length, r.chute_sizing.static.area,
                   _deg(r.chute_sizing.towed.alpha), r.chute_sizing.towed.airspeed / 0.514444]),
}


@pytest.mark.parametrize("name", sorted(QUOTES))
def test_page_quotes_the_example(name, example_results):
    """Each figure a page quotes from the example, re-derived from the session's run of the
    example (every analysis) and compared at the digits the page writes it with."""
    page, pattern, values = QUOTES[name]
    quoted = _quoted(pattern, page)
    derived = values(example_results)
    assert len(quoted) == len(derived)
    for k, (text, value) in enumerate(zip(quoted, derived, strict=True)):
        if isinstance(value, str):
            assert text == value, (name, k, text, value)
        else:
            assert _agrees(text, float(value)), (name, k, text, value)


def test_readme_quotes_the_campaign_decision(example_campaign_run_report):
    """The rest of the README's paragraph on the example's campaign (factors, the towed trim
    it reads the neutral area at, the 1-DOF proposal, the multibody verdict at the chosen
    area, the Study's area against it, the two models' damping ratios and the criterion,
    HC2's lowest ramp), against the Summary of the campaign report of ``slingloads run``
    with the campaign on."""
    path = next(example_campaign_run_report.glob("*-campaign.xlsx"))
    summary = pd.read_excel(path, "Summary", header=None)
    rows = {r[0]: r for r in summary.itertuples(index=False) if isinstance(r[0], str)}
    (f1, f2, f3, alpha, speed, one_dof, verdict, ratio, chosen, zeta1, zetam,
     criterion, hc2) = _quoted(
        r"its factors (\d\.\d), (\d\.\d) and (\d\.\d), .*? the towed trim, (-\d+\.\d) deg at "
        r"(\d+) KEAS, about the suspension axis, .*? the 1-DOF sizing's (\d\.\d+) m\^2, .*?the "
        r"multibody verdict at it: ([\w ]+); the Study's [\d.]+ m\^2 is (\d\.\d+) x it\)\. The "
        r"two models' yaw damping ratios at (\d\.\d+) m\^2 and 80 KEAS, side by side in the "
        r"decision: 1-DOF (\d\.\d+) \(hub fixed\), multibody (\d\.\d+) .*?more than the stated "
        r"(\d\.\d+) apart: .*? HC2 not even at (\d+) kt", "README.md")
    factors = [float(f) for f in rows["area factors"][1].split(",")]
    assert [float(f1), float(f2), float(f3)] == factors
    note = rows["neutral static area (1-DOF sizing)"][3]
    towed = re.search(r"alpha (-\d+\.\d+) deg \((\d+) KEAS", note)
    assert _agrees(alpha, float(towed.group(1))) and speed == towed.group(2)
    assert _agrees(one_dof, rows["1-DOF: smallest area stable under every gust"][1])
    assert verdict == rows["multibody verdict at the chosen area"][1]
    study_note = rows["Study 'parachute area' (loads)"][3]
    assert f"({ratio} x)" in study_note
    assert _agrees(chosen, rows["chosen area"][1])
    damping = rows["yaw damping ratio, 1-DOF against multibody"][1]
    found = re.search(r"1-DOF (\d\.\d+) .*?multibody (\d\.\d+)", damping)
    assert _agrees(zeta1, float(found.group(1))) and _agrees(zetam, float(found.group(2)))
    assert _agrees(criterion, rows["damping criterion: least yaw-mode damping ratio"][1])
    assert abs(float(found.group(1)) - float(found.group(2))) > float(criterion)
    assert int(hc2) == rows["HC2"][3] and rows["HC2"][1].startswith(f"< {hc2} kt")


def test_readme_quotes_the_us_twin_mass():
    """The README's mass of the second example (US units), from its workbook's mass items
    read by the product's reader (the loads' inputs alone: no analysis run)."""
    import slingloads as sl

    (mass,) = _quoted(r"a GENERIC (\d+\.\d) t twin in US units", "README.md")
    study = sl.read_study(ROOT / "loadcases" / "example-us-twin.xlsx", only=["loads"])
    assert _agrees(mass, study.airframe.mass_items.mass.sum() / 1000)

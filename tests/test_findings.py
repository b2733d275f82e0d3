"""One answer per question across the reports of one ``slingloads run``.

Two workbooks: the light-twin example with the campaign on (SI reports), and the second
example, loadcases/example-us-twin.xlsx (a GENERIC 4.9 t twin in US units, hub forward of the
CG, short runs; its campaign finds no stable area, exit 3, so the "no answer" path is checked
too), written in US units. The reports are read back from the written xlsx files (pandas /
openpyxl), never from the Python objects.

Reference: the rule itself, applied to the written numbers: (1) the Findings sheet is the
same, cell by cell, in every report of a run; (2) every other statement of the same quantity
(the parachute decision table, the loads' hook angle, the lateral study's recommended angle
and cable tension, the campaign's speed limits, the multibody stability verdict) equals the
Findings answer; (3) no verdict contradicts the number printed beside it ("stable" with a
real part above -1e-6 1/s, "adequate" with an area below the chosen one, a tension "<= Nz"
above Nz, a hook angle of 90 deg or more or below the Study's...).
"""

import math
import re
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from slingloads.cli import main

US_TWIN = Path(__file__).resolve().parents[1] / "loadcases" / "example-us-twin.xlsx"
REPORTS = ("loads", "lateral", "chute", "multibody", "campaign")


@pytest.fixture(scope="module")
def us_twin_reports(tmp_path_factory):
    """``slingloads run --units US`` on the second example (exit 3: its campaign finds no
    parachute area stable in every condition, a finding; every report is written)."""
    out = tmp_path_factory.mktemp("us-twin") / "out"
    assert main(["run", str(US_TWIN), "--out", str(out), "--units", "US", "--quiet"]) == 3
    return out


def _reports(folder):
    """{report: path} of the workbooks of one run."""
    out = {}
    for name in REPORTS:
        found = list(folder.glob(f"*-{name}.xlsx"))
        if found:
            out[name] = found[0]
    return out


def _sheet(path, name):
    return pd.read_excel(path, sheet_name=name, header=None)


def _section(frame, title):
    """The table under the title ``title`` of a sheet read with header=None (header: the
    first row after the title whose first cell is 'item'), or None."""
    first = frame[0].astype(str)
    hits = np.nonzero((first == title).to_numpy())[0]
    if not len(hits):
        return None
    i = int(hits[0]) + 1
    while first.iloc[i] != "item":
        i += 1
    head = [c for c in frame.iloc[i] if isinstance(c, str)]
    rows = []
    for j in range(i + 1, len(frame)):
        if pd.isna(frame.iloc[j, 0]):
            break
        rows.append(list(frame.iloc[j, :len(head)]))
    return pd.DataFrame(rows, columns=head)


def _findings(path):
    """The Findings table of a report, by question."""
    frame = _sheet(path, "Findings")
    i = int(np.nonzero((frame[0].astype(str) == "question").to_numpy())[0][0])
    head = list(frame.iloc[i].dropna())
    table = frame.iloc[i + 1:, :len(head)].set_axis(head, axis=1)
    return table[table["question"].notna()].set_index("question")


def _items(path, sheet="Summary"):
    """{item: value} of every item/value row of a sheet (the first occurrence of each)."""
    frame = _sheet(path, sheet)
    out = {}
    for row in frame.itertuples(index=False):
        if isinstance(row[0], str) and len(row) > 1 and row[0] not in out:
            out[row[0]] = row[1]
    return out


def _text(path, sheet="Summary"):
    return " ".join(str(v) for v in _sheet(path, sheet)[0].dropna())


def _num(value):
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def _same(a, b):
    return (math.isnan(a) and math.isnan(b)) or a == pytest.approx(b, rel=1e-9, abs=1e-12)


def _check_run(folder, units):
    """Every consistency rule on the reports of one run (module notes)."""
    reports = _reports(folder)
    assert set(reports) == set(REPORTS), reports
    # (1) one Findings table, identical in every report
    tables = {name: _sheet(path, "Findings") for name, path in reports.items()}
    first = tables["loads"]
    for name, table in tables.items():
        pd.testing.assert_frame_equal(table, first, check_exact=True, obj=name)
    f = _findings(reports["loads"])
    area_unit = "m^2" if units == "SI" else "ft^2"

    # (2) the parachute decision: one table, the same in every report that prints it, and
    # the Findings' chosen and Study areas are its values
    decisions = {name: _section(_sheet(path, "Summary"), "Parachute decision")
                 for name, path in reports.items()}
    decisions = {k: v for k, v in decisions.items() if v is not None}
    assert {"chute", "campaign", "multibody", "loads"} <= set(decisions)
    base = decisions["chute"].set_index("item")
    for name, table in decisions.items():
        pd.testing.assert_frame_equal(table, decisions["chute"], obj=name)
    chosen = f.loc["parachute area (chosen)"]
    assert chosen["unit"] == area_unit == base.loc["chosen area", "unit"]
    assert _same(_num(chosen["value"]), _num(base.loc["chosen area", "value"]))
    study = f.loc["parachute area of the loads (Study 'parachute area')"]
    row = base.loc["Study 'parachute area' (loads)"]
    assert _same(_num(study["value"]), _num(row["value"])) and study["answer"] == row["note"]

    # (3) verdicts against the numbers beside them: the Study's parachute
    s, c = _num(study["value"]), _num(chosen["value"])
    if "SMALLER" in study["answer"]:
        assert s < c
    elif "at least the chosen area" in study["answer"]:
        assert s >= c * (1 - 1e-9)
    else:
        assert math.isnan(c) and "not shown adequate" in study["answer"]
    chute = _text(reports["chute"])  # the sizing's headline states the decision's answer
    if math.isnan(c):
        assert "Chosen area (parachute decision): NONE" in chute
    else:
        assert f"every report): {c:.3g} {area_unit}, decided by the" in chute
    if chosen["answer"].startswith("NONE"):
        assert math.isnan(c)
    else:
        factor = float(re.match(r"([\d.]+) x the neutral area", chosen["answer"]).group(1))
        assert factor == pytest.approx(c / _num(chosen["reference"]), rel=5e-3)

    # the hook angle: the loads' lateral directions at the Findings' angle, never below the
    # Study's, at least the lateral study's recommendation, below 90 deg
    hook = f.loc["hook design angle, lateral directions (from the vertical)"]
    angle = _num(hook["value"])
    loads = _items(reports["loads"])
    lateral = _items(reports["lateral"])
    assert _same(angle, _num(loads["hook cone angle of the lateral directions"]))
    assert _same(angle, _num(loads["lateral hook angle used by the loads"]))
    recommended = _num(lateral["recommended design angle"])
    assert _same(recommended, _num(loads["lateral study's recommended design angle"]))
    assert angle < 90.0 and angle >= _num(hook["reference"]) - 1e-9
    assert angle >= recommended - 1e-9 or math.isnan(recommended)
    assert hook["answer"].startswith(f"{angle:.1f} deg")
    governs = "lateral study" if recommended > _num(hook["reference"]) else "Study"
    assert f"governed by the {governs}" in hook["answer"]
    assert "rerun the loads" not in _text(reports["loads"])

    # the cable tension against Nz
    tension = f.loc["peak cable tension T/(m g) against Nz"]
    t, nz = _num(tension["value"]), _num(tension["reference"])
    assert _same(nz, _num(loads["hook load factor Nz (limit)"]))
    assert _num(lateral["largest cable tension factor T/(m g)"]) <= t * (1 + 1e-9)
    assert ("<= Nz" in tension["answer"]) == (t <= nz)
    assert ("EXCEEDS" in tension["answer"]) == (t > nz)

    # the speed limits without parachute: the campaign Summary's, word for word
    campaign = _sheet(reports["campaign"], "Summary")
    i = int(np.nonzero((campaign[0].astype(str) == "helicopter").to_numpy())[0][0])
    head = list(campaign.iloc[i].dropna())
    limits = campaign.iloc[i + 1:, :len(head)].set_axis(head, axis=1)
    limits = limits[limits["helicopter"].notna()].iloc[:len(
        [q for q in f.index if q.startswith("speed limit")])]
    for row in limits.itertuples(index=False):
        mine = f.loc[f"speed limit without parachute, {row.helicopter}"]
        assert mine["answer"].startswith(row._1)  # 'speed limit' column
        value = _num(mine["value"])
        if row._1.startswith(">="):
            assert value == pytest.approx(float(re.findall(r"[\d.]+", row._1)[0]))
        elif row._1.startswith("none"):
            assert math.isnan(value)

    # the multibody verdict: the same word in its Summary and the Findings, and the real
    # part beside it agrees with the word (rule: stable below -1e-6 1/s)
    linear = f.loc["linear stability of the towed system at its trim (multibody)"]
    word = linear["answer"].split()[0]
    multibody = _text(reports["multibody"])
    assert "Linear stability at the trim (" in multibody
    assert re.search(rf"\): {word} \(largest real part", multibody)
    largest = _num(linear["value"])
    assert {"stable": largest < -1e-6, "unstable": largest > 1e-6,
            "neutral": abs(largest) <= 1e-6}[word]
    assert "parachute decision" in multibody

    # the response damping: the mode named and the check beside it agree (multibody Metrics,
    # transposed; campaign NoParachute and Metrics)
    metrics = _parts(_sheet(reports["multibody"], "Metrics"), "metric")
    metrics = metrics.set_index("metric").drop(columns="unit")
    _check_response_damping(metrics.loc["response damping measured on mode"],
                            metrics.loc["response damping check"])
    for sheet, key in (("NoParachute", "helicopter"), ("Metrics", "run")):
        table = _parts(_sheet(reports["campaign"], sheet), key)
        if table is not None and "response damping check" in table:
            _check_response_damping(table["response damping measured on mode"],
                                    table["response damping check"],
                                    table.get("yaw mode period [s]"))

    # one attitude per flight condition: the 1-DOF sizing's alpha and the multibody trim's
    attitude = f.loc["trimmed angle of attack of the parachute sizing's condition (1-DOF "
                     "against multibody)"]
    chute_items = _items(reports["chute"])
    assert _same(_num(attitude["value"]), _num(chute_items["alpha trim"]))
    trimmed = _items(reports["multibody"]).get("alpha")
    if attitude["answer"].startswith(("one attitude", "NOT ONE")):
        assert _same(_num(attitude["reference"]), _num(trimmed))
        differ = abs(_num(attitude["value"]) - _num(trimmed)) > 1.0
        assert attitude["answer"].startswith("NOT ONE ATTITUDE") == differ

    # the hook angle the loads used, the same on the Dynamics sheet (the campaign's hand-off)
    # and in the hand-off table, whose source is the Study when the campaign kept its angle
    if "Dynamics" in pd.ExcelFile(reports["loads"]).sheet_names:
        dynamics = _parts(_sheet(reports["loads"], "Dynamics"), "quantity").set_index(
            "quantity")
        lateral_used = _num(dynamics.loc["hook cone, lateral angle from the vertical",
                                         "used in the loads"])
        assert _same(lateral_used, angle)
        hand = _num(dynamics.loc["hook cone, lateral angle from the vertical", "hand-entered"])
        own = _section(_sheet(reports["loads"], "Summary"),
                       "Lateral hook angle: the lateral study's hand-off to the loads")
        if own is not None:
            own = own.set_index("item").loc["lateral hook angle of the loads' own inputs"]
            kept = _same(_num(own["value"]), hand)  # the campaign did not raise it
            assert (own["note"] == "from the Study") == kept, own["note"]

    # the loads' exceedances
    over = f.loc["loads exceedances over the previous envelope"]
    if "EXCEED" in over["answer"]:
        assert _num(over["value"]) > 1.0
    elif over["answer"].startswith("none"):
        assert _num(over["value"]) <= 1.0


def _parts(frame, first):
    """Every table of a sheet (read with header=None) whose header row starts with the cell
    ``first``, its parts joined side by side (a wide table is printed in parts of the same
    rows, each repeating the key columns)."""
    col = frame[0].astype(str)
    out = []
    for i in np.nonzero((col == first).to_numpy())[0]:
        head = [c for c in frame.iloc[i] if isinstance(c, str)]
        rows = []
        for j in range(i + 1, len(frame)):
            if pd.isna(frame.iloc[j, 0]):
                break
            rows.append(list(frame.iloc[j, :len(head)]))
        out.append(pd.DataFrame(rows, columns=head))
    if not out:
        return None
    joined = out[0]
    for part in out[1:]:
        new = [c for c in part.columns if c not in joined.columns]
        joined = pd.concat([joined.reset_index(drop=True),
                            part[new].reset_index(drop=True)], axis=1)
    return joined


def _check_response_damping(measured_on, check, yaw_period=None):
    """The mode a response's damping was measured on and the check beside it agree: a named
    mode has a period within 25 % of the response's and the check compares with that mode;
    'none' goes with a check that says no mode matches; 'no linear mode to compare with'
    never stands beside a listed yaw mode; the mode named is a yaw mode."""
    for i, (on, words) in enumerate(zip(measured_on, check, strict=True)):
        on = "" if pd.isna(on) else str(on)
        words = "" if pd.isna(words) else str(words)
        if on.startswith("none within"):
            assert "matches no mode" in words, (on, words)
        elif on:
            name = on.split(" (")[0].replace(" of the trim at the ramp's final airspeed", "")
            assert "matches no mode" not in words, (on, words)
            assert f"the {name} mode" in words, (on, words)
            assert "inf s" not in on, on
            # a "yaw" period and damping are measured on a yaw mode (not the roll's)
            assert "yaw" in name, (on, words)
        if yaw_period is not None and math.isfinite(_num(yaw_period[i])):
            assert words != "no linear mode to compare with", (i, words)


def test_example_with_campaign_reports_agree(example_campaign_run_report):
    """The light-twin example with its campaign (SI): every rule of the module holds; and the
    hand-off raised the loads' lateral hook cases to the lateral study's 33.2 deg."""
    _check_run(example_campaign_run_report, "SI")
    f = _findings(_reports(example_campaign_run_report)["loads"])
    assert _num(f.loc["hook design angle, lateral directions (from the vertical)",
                      "value"]) == pytest.approx(33.236, abs=1e-3)


def test_us_twin_reports_agree(us_twin_reports):
    """The second example (US units, hub forward of the CG): every rule of the module holds,
    the areas in ft^2; no area is chosen and the Findings say so."""
    _check_run(us_twin_reports, "US")
    f = _findings(_reports(us_twin_reports)["loads"])
    assert f.loc["parachute area (chosen)", "answer"].startswith("NONE")


def test_findings_of_a_single_analysis_say_not_run(example_loads_report):
    """`slingloads loads` alone: the Findings rows of the analyses not run say 'not run'
    (hook angle: the Study's, the only one there is)."""
    f = _findings(next(example_loads_report.glob("*-loads.xlsx")))
    assert f.loc["speed limit without parachute", "answer"] == "not run"
    assert f.loc["parachute area (chosen)", "answer"] == "not run"
    assert f.loc["linear stability of the towed system at its trim (multibody)",
                 "answer"] == "not run"
    assert "the Study's (no lateral study run)" in f.loc[
        "hook design angle, lateral directions (from the vertical)", "answer"]


def _every_run(path):
    """The parachute sizing's 'Every run' table (its parts joined), from whichever sheet of
    the report holds it."""
    book = pd.ExcelFile(path)
    for name in book.sheet_names:
        frame = pd.read_excel(book, sheet_name=name, header=None)
        for first in ("area [m^2]", "area [ft^2]"):
            table = _parts(frame, first)
            if table is not None and "beta offset from trim [deg]" in table:
                return table
    raise AssertionError(f"no 'Every run' table in {path.name}")


def test_every_runs_final_sideslip_follows_its_trim_and_offset(example_campaign_run_report,
                                                               us_twin_reports):
    """The sizing's 'Every run' table states the trim each run is judged about, so that its
    final beta and its offset from trim relate as the envelope test defines them: the final
    sample and the second half's mean both lie in the second half's range, so |final beta -
    (beta trim + offset)| <= 2 x the second half's amplitude (+ the cells' 0.1 deg
    rounding), on every run of both examples. Without the trim column a step gust's final
    beta -8.1 deg beside an offset 0.0 deg reads as a contradiction."""
    for folder in (example_campaign_run_report, us_twin_reports):  # this module's: a folder
        table = _every_run(_reports(folder)["chute"])
        assert "beta trim [deg]" in table, list(table.columns)
        rows = table[["final beta [deg]", "beta trim [deg]", "beta offset from trim [deg]",
                      "beta amplitude second half [deg]"]].apply(pd.to_numeric,
                                                                 errors="coerce").dropna()
        assert len(rows) >= 6  # the US twin sweeps 3 areas x 2 gusts
        gap = (rows["final beta [deg]"] - rows["beta trim [deg]"]
               - rows["beta offset from trim [deg]"]).abs()
        assert (gap <= 2 * rows["beta amplitude second half [deg]"] + 0.15).all(), \
            rows[gap > 2 * rows["beta amplitude second half [deg]"] + 0.15]
        # a held gust moves the trim only when the weight has a moment: at least one run of
        # the example is judged about a trim away from its final beta's zero
        assert (rows["beta trim [deg]"].abs() > 0.5).any() or folder is not \
            example_campaign_run_report
        # the table's note, printed under it (a table sheet's text box: the workbook's XML)
        with zipfile.ZipFile(_reports(folder)["chute"]) as book:
            xml = " ".join(book.read(n).decode("utf-8", "replace") for n in book.namelist()
                           if n.endswith(".xml"))
        assert "beta trim: the static equilibrium the run is judged about" in xml


def test_sensitivity_tables_say_which_runs_they_cover(example_campaign_run_report):
    """The campaign's Sensitivity sheet: the airspeed table covers the runs at the selected
    area factor only, and says so (its 'at area factor' column, the sheet's note); its runs
    add up to the Matrix sheet's runs at that factor (the reference: the run matrix as
    written), not to every run of the matrix as 'over every value of the others' alone would
    read."""
    path = _reports(example_campaign_run_report)["campaign"]
    matrix = _parts(_sheet(path, "Matrix"), "run")
    frame = _sheet(path, "Sensitivity")
    speed = _parts(frame, "airspeed EAS [kt]")
    assert speed is not None
    factor = set(pd.to_numeric(speed["at area factor [-]"]))
    assert len(factor) == 1
    at = np.isclose(pd.to_numeric(matrix["area factor [-]"]), factor.pop())
    assert pd.to_numeric(speed["runs"]).sum() == at.sum() < len(matrix)
    assert "only the runs at the selected area factor" in _text(path, "Sensitivity")


def test_one_required_cable_length_for_one_parachute_line(example_campaign_run_report):
    """The carrier-cable check is stated in the parachute sizing and in the multibody report:
    both check the cable against the line flown (the Study's 10.1 m, the longer than the
    wake's 10.058 m) with one margin, so both state one required length, (1 + 0.2) x 10.1 =
    12.12 m (hand calculation), not 12.070 m in one report and 12.120 m in the other."""
    reports = _reports(example_campaign_run_report)
    chute = _items(reports["chute"])
    wake, study = _num(chute["parachute line length (from the wake)"]), _num(
        chute["Study 'parachute line length'"])
    required = _num(chute["required cable length"])
    assert required == pytest.approx(1.2 * max(wake, study), abs=5e-4)
    assert required == pytest.approx(12.12, abs=5e-4)
    multibody = _sheet(reports["multibody"], "Summary")
    row = multibody[multibody[0] == "cable against the line"].iloc[0]
    needs = re.search(r"needs >= ([\d.]+) m", " ".join(str(v) for v in row.dropna()))
    assert needs and float(needs.group(1)) == pytest.approx(required, abs=5e-4)


def test_the_multibody_summary_quotes_the_findings_real_part(example_campaign_run_report,
                                                              us_twin_reports):
    """The multibody Summary's sentence on the linear stability quotes the largest real part
    as the Findings' cell beside it reads (1/s to 0.0000, formats.py): the example's
    -0.0062 1/s, never '-0.006195 1/s' in the sentence above a cell of -0.0062; and the US
    twin's +0.1228. Reference: the Findings cell read back."""
    for folder in (example_campaign_run_report, us_twin_reports):
        path = _reports(folder)["multibody"]
        cell = _num(_findings(path).loc["linear stability of the towed system at its trim "
                                        "(multibody)", "value"])
        said = re.search(r"largest real part (-?[\d.e+-]+) 1/s", _text(path))
        assert said, _text(path)[:200]
        assert said.group(1) == f"{cell:.4f}", (said.group(1), cell)


def test_the_multibody_summary_cites_the_decisions_study_area_verdict(
        example_campaign_run_report, us_twin_reports):
    """The multibody Summary's sentence defers to the parachute decision and quotes its
    verdict on the Study's parachute as the decision table's row states it (its note), in a
    sentence that reads: the US twin's read 'Study parachute no area meets the criteria'.
    Reference: the decision table of the same sheet read back."""
    for folder in (example_campaign_run_report, us_twin_reports):
        path = _reports(folder)["multibody"]
        frame = _sheet(path, "Summary")
        row = frame[frame[0] == "Study 'parachute area' (loads)"].iloc[0]
        verdict = str(row.dropna().iloc[-1])
        text = _text(path)
        assert f"(its row \"Study 'parachute area' (loads)\"): {verdict}." in text, text[:600]
        assert "Study parachute no area" not in text

"""The workbook inputs of the attitude, the hook cone by direction, the towed cases and the
coefficient frames: read back, equivalent inputs give equal loads, bad values are located.

References: docs/conventions.md sections 3 to 5 and the Study-row explanations of the
template (the rules each bad-input test breaks); the wind-to-body rotation of Stevens, Lewis
and Johnson, "Aircraft Control and Simulation", 3rd ed., section 2.3, for the body-axes
re-tabulation; the report read back must equal the Python API's numbers.
"""

from __future__ import annotations

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE, report_table

from slingloads.errors import InputError
from slingloads.io.study import read_study

STEM = "example-light-twin"


def edited(tmp_path, edit, name="edited.xlsx"):
    book = openpyxl.load_workbook(EXAMPLE)
    edit(book)
    path = tmp_path / name
    book.save(path)
    return path


def set_row(book, name, value, unit=None):
    """Set the value (and unit) of an existing Study row; return its value cell."""
    ws = book["Study"]
    for row in ws.iter_rows(min_row=2):
        if row[0].value == name:
            row[1].value = value
            if unit is not None:
                row[2].value = unit
            return row[1].coordinate
    raise KeyError(name)


def loads_of(path):
    return read_study(path, only=["loads"]).inputs.loads


def expect_error(path, *fragments):
    with pytest.raises(InputError) as info:
        loads_of(path)
    message = str(info.value)
    for fragment in fragments:
        assert fragment in message, message


@pytest.fixture(scope="module")
def example_loads():
    return loads_of(EXAMPLE)


def test_example_hangs_nose_down(example_loads):
    """The example's hub is 0.17 m aft of and 1.07 m above its CG (MassItems, Hardpoints):
    hanging attitude pitch -atan(0.17300 / 1.07162) = -9.170 deg, roll 0."""
    af = example_loads.airframe
    offset = af.hardpoints.hub - af.mass_items.cg
    assert offset[0] == pytest.approx(0.1730, abs=1e-4)
    att = example_loads.attitude_used
    assert att.source == "hanging"
    assert np.degrees(att.pitch) == pytest.approx(-np.degrees(np.arctan2(offset[0], offset[2])),
                                                  rel=1e-12)
    assert np.degrees(att.pitch) == pytest.approx(-9.17, abs=0.01)


def test_given_and_mast_vertical_attitudes_are_read(tmp_path):
    """'attitude' = given with pitch -5 deg and roll 2 deg gives those angles; 'mast vertical'
    gives the mast axis (0, 0, 1) as the vertical."""
    def given(b):
        set_row(b, "attitude", "given")
        set_row(b, "attitude pitch", -5.0, "deg")
        set_row(b, "attitude roll", 2.0, "deg")
    att = loads_of(edited(tmp_path, given)).attitude_used
    assert np.degrees([att.pitch, att.roll]) == pytest.approx([-5.0, 2.0], rel=1e-12)
    mast = loads_of(edited(tmp_path, lambda b: set_row(b, "attitude", "mast vertical"),
                           "mast.xlsx"))
    np.testing.assert_allclose(mast.vertical, [0.0, 0.0, 1.0], atol=1e-15)


def test_hook_rows_are_read(tmp_path):
    """'hook lateral angle' 12 deg with the elliptical cone and no towed cases: 90 cases, the
    lateral angle and cone shape as typed."""
    def edit(b):
        set_row(b, "hook lateral angle", 12.0, "deg")
        set_row(b, "hook cone shape", "elliptical")
        set_row(b, "towed equilibrium cases", "no")
    study = loads_of(edited(tmp_path, edit))
    assert study.hook.lateral_angle == pytest.approx(np.radians(12.0))
    assert study.hook.cone == "elliptical" and not study.hook.towed
    assert len(study.case_matrix()) == 90


def on_breakpoints(book):
    """Move the example's envelope sideslips from +-15 to +-16 deg, a breakpoint of the
    2-deg table (between breakpoints each frame interpolates linearly in its own axes)."""
    ws = book["AeroEnvelope"]
    for row in ws.iter_rows(min_row=2):
        if row[2].value in (15, -15):
            row[2].value = 16 if row[2].value > 0 else -16


def test_body_axes_sheet_gives_the_same_loads(tmp_path):
    """The example's wind-axes FuselageAero re-tabulated in body axes (CX, CY, CZ by the
    textbook rotation) with 'fuselage force axes' = body gives the same loads at envelope
    points on the breakpoints (the forces are the same there, each converted to airframe
    axes by the one conversion)."""
    def edit(b):
        on_breakpoints(b)
        ws = b["FuselageAero"]
        frame = pd.DataFrame(list(ws.iter_rows(min_row=2, values_only=True)),
                             columns=[c.value for c in ws[1]])
        a = np.radians(frame["alpha [deg]"].to_numpy(float))
        beta = np.radians(frame["beta [deg]"].to_numpy(float))
        cd, cy, cl = (frame[c].to_numpy(float) for c in ("CD", "CY", "CL"))
        ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(beta), np.sin(beta)
        body = {"CD": -cd * ca * cb - cy * ca * sb + cl * sa,       # written as CX
                "CY": -cd * sb + cy * cb,
                "CL": -cd * sa * cb - cy * sa * sb - cl * ca}       # written as CZ
        names = [c.value for c in ws[1]]
        for r, _ in enumerate(frame.index, start=2):
            for name, values in body.items():
                ws.cell(r, names.index(name) + 1).value = float(values[r - 2])
        ws.cell(1, names.index("CD") + 1).value = "CX"
        ws.cell(1, names.index("CL") + 1).value = "CZ"
        set_row(b, "fuselage force axes", "body")
    body = loads_of(edited(tmp_path, edit)).run()
    reference = loads_of(edited(tmp_path, on_breakpoints, "wind.xlsx")).run()
    # the envelope points lie on the breakpoints, where the two tables agree; the towed
    # case's trimmed attitude lies between them, where each table interpolates its own axes
    hand = (reference.cases["hook"] != "TOW").to_numpy()
    np.testing.assert_allclose(body.loads[hand], reference.loads[hand], rtol=0,
                               atol=1e-9 * np.abs(reference.loads).max())


def with_parachute_table(column):
    """An edit adding a flat ParachuteCD sheet (1.0 within +-8 deg) headed ``column``, in
    canopy axes."""
    def edit(b):
        ws = b.create_sheet("ParachuteCD")
        ws.append(["alpha [deg]", column])
        ws.append([-8.0, 1.0])
        ws.append([8.0, 1.0])
        set_row(b, "parachute table axes", "canopy")
    return edit


def test_parachute_canopy_axes_table(tmp_path, example_loads):
    """A ParachuteCD sheet in canopy axes (CT 1.0 within +-8 deg) with the line along the
    relative wind gives the default loads: the canopy axis lies along the wind."""
    study = loads_of(edited(tmp_path, with_parachute_table("CT")))
    assert study.parachute.axes == "canopy"
    result, reference = study.run(), example_loads.run()
    # the trim flies wind-axes canopies only: compare the cases that are not towed
    mine = (result.cases["hook"] != "TOW").to_numpy()
    hand = (reference.cases["hook"] != "TOW").to_numpy()
    np.testing.assert_allclose(result.loads[mine], reference.loads[hand], rtol=1e-12,
                               atol=1e-9)
    assert any("left out of the trim" in line for line in result.towed_findings())


@pytest.mark.parametrize(("row", "value", "fragments"), [
    ("attitude", "upside down", ["'attitude' is not valid", "'hanging', 'mast vertical', "
                                 "'given'", "upside down"]),
    ("attitude pitch", 5.0, ["'attitude pitch' is used only with 'attitude' = given"]),
    ("hook lateral angle", 95.0, ["lateral hook-load angle from the vertical must lie in "
                                  "[0, 90) deg", "95"]),
    ("hook cone shape", "round", ["'hook cone shape' is not valid", "round"]),
    ("fuselage force axes", "earth", ["'fuselage force axes' is not valid", "'body'"]),
    ("fin axes", "stability", ["'fin axes' is not valid", "['body', 'wind']"]),
])
def test_bad_rows_are_located(tmp_path, row, value, fragments):
    """Rules of the template's Study rows: choices from the listed values, the attitude
    angles only with 'given', inclinations in [0, 90) deg; each error names the cell."""
    cell = {}
    path = edited(tmp_path, lambda b: cell.setdefault("c", set_row(b, row, value)))
    expect_error(path, "sheet 'Study'", f"cell {cell['c']}", *fragments)


def test_given_attitude_out_of_range_is_located(tmp_path):
    """Rule: attitude angles within (-90, 90) deg; the error names the pitch cell."""
    cell = {}

    def edit(b):
        set_row(b, "attitude", "given")
        cell["c"] = set_row(b, "attitude pitch", 95.0, "deg")
    expect_error(edited(tmp_path, edit), f"cell {cell['c']}",
                 "attitude pitch must lie within (-90, 90) deg")


def test_frame_and_columns_must_agree(tmp_path):
    """Rule: a body-axes FuselageAero has CX, CY, CZ; a canopy-axes ParachuteCD has CT."""
    path = edited(tmp_path, lambda b: set_row(b, "fuselage force axes", "body"))
    expect_error(path, "sheet 'FuselageAero'", "missing column 'CX'", "'body'")
    expect_error(edited(tmp_path, with_parachute_table("CD"), "chute.xlsx"),
                 "sheet 'ParachuteCD'", "missing column 'CT'")


def test_renamed_parameter_is_named(tmp_path):
    """A workbook written before the hanging attitude uses 'hook angle from mast': it is told
    the new name (the angle is now from the earth vertical)."""
    def rename(b):
        for row in b["Study"].iter_rows(min_row=2):
            if row[0].value == "hook angle from vertical":
                row[0].value = "hook angle from mast"
    expect_error(edited(tmp_path, rename), "parameter renamed: use 'hook angle from vertical'",
                 "hook angle from mast")


def summary_block(path, title):
    """The table under the section ``title`` of the Summary sheet (its printed parts joined)."""
    return report_table(path, "Summary", title)


def test_report_states_attitude_and_towed_cables(example_loads_report, example_loads):
    """The loads report's Summary states the attitude and lists each towed case's cable angle
    and inside-cone flag, equal to the API's; the LoadCases sheet carries the same columns."""
    path = example_loads_report / f"{STEM}-loads.xlsx"
    note, attitude = summary_block(path, "Attitude")
    assert "nose down" in note and "hanging" in note
    result = example_loads.run()
    assert float(attitude["pitch [deg]"].iloc[0]) == pytest.approx(
        np.degrees(result.attitude.pitch), rel=1e-12)
    note, towed = summary_block(path, "Towed-flight equilibrium cases")
    api = result.towed_table()
    # one row per quantity, one column per towed case (a narrow block beside the others)
    assert list(towed.columns[2:]) == list(api["case"]) and len(api) == 1  # none w/o chute
    towed = towed.set_index("quantity")
    assert towed.loc["cable angle from vertical", "unit"] == "deg"
    np.testing.assert_allclose(
        towed.loc["cable angle from vertical", list(api["case"])].astype(float),
        api["cable angle from vertical [deg]"], rtol=1e-12)
    assert set(towed.loc["inside hook cone", list(api["case"])]) == {"yes"}
    assert "inside the hook cone" in note
    raw = pd.read_excel(path, sheet_name="LoadCases", header=None)
    head = int(np.nonzero(raw.isin(["inside hook cone"]).any(axis=1).to_numpy())[0][0])
    cases = raw.iloc[head + 1:].set_axis(list(raw.iloc[head]), axis=1)  # under its title
    assert {"cable angle from vertical [deg]", "inside hook cone"} <= set(cases.columns)

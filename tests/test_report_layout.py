"""The report machinery on small inputs: what a new table inherits from the common writer,
the engineering precisions, the CSV header names, the findings a reviewer looks for, the
template's explanations and error values in the user's unit.

References: the precisions stated in :mod:`slingloads.io.common.formats`; CS 29.865(a)
(hook loads inclined 30 deg unless a smaller angle is shown not to be exceeded in service);
the definition of a linear interpolation (a previous-envelope value at a station it does not
have is interpolated, at one it has is given); docs/conventions.md section 3 (CL is the lift,
Cl the rolling moment); 1 in = 0.0254 m, 1 ft = 0.3048 m exactly.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE
from matplotlib.figure import Figure

from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import LoadsStudy
from slingloads.errors import InputError
from slingloads.io.common.excel import Section, write_workbook
from slingloads.io.common.figures import FigureRenderer
from slingloads.io.common.formats import header_unit, unit_format, value_format
from slingloads.io.common.report import csv_name, sample_rows
from slingloads.io.loads.report import write_loads_outputs
from slingloads.io.loads.sheets import hook_angle_finding
from slingloads.io.loads.tables import previous_station_status
from slingloads.io.study import read_study
from slingloads.io.template import write_input_workbook
from slingloads.models.airframe import Airframe, Hardpoints, MassItems


def _beam_study(**changes):
    """A crude beam of 10 equal masses on x = 1..10 m, hung at x = 5 m."""
    x = np.arange(1.0, 11.0)
    items = MassItems([f"m{i}" for i in range(10)], np.full(10, 100.0),
                      np.c_[x, np.zeros(10), 0.1 * np.sin(x)])
    hp = Hardpoints(hub=[5.0, 0, 1.0], mast_feet=[[4.5, 0, 0.5], [5.5, 0, 0.5]])
    frame = Airframe(items, stations=np.linspace(1.5, 9.5, 9), hardpoints=hp)
    return LoadsStudy(frame, name="beam", **changes)


def test_new_dataframe_sheet_inherits_print_setup_and_formats(tmp_path):
    """A plain DataFrame given to the common writer, as a new report sheet would be, gets A4
    print setup fitted to the page width, its header repeated and frozen (right of the id
    column), number formats from the units in its headers, booleans as yes / no, and no text
    column wider than 40 characters (longer text wraps)."""
    frame = pd.DataFrame({"case": ["A", "B"], "x [m]": [1.23456, 2.0], "Vy [lbf]": [1234.56, -7.0],
                          "ok": [True, False], "note": ["word " * 30, "short"]})
    path = tmp_path / "new.xlsx"
    write_workbook(path, {"NewSheet": frame})
    ws = openpyxl.load_workbook(path)["NewSheet"]
    assert ws.page_setup.paperSize == 9 and ws.sheet_properties.pageSetUpPr.fitToPage
    assert ws.print_title_rows.replace("$", "") == "1:1"
    assert ws.freeze_panes == "B2"
    assert ws["B2"].number_format == "0.000" and ws["B2"].value == 1.23456
    assert ws["C2"].number_format == "#,##0"
    assert [ws["D2"].value, ws["D3"].value] == ["yes", "no"]
    assert ws.column_dimensions["E"].width <= 40 and ws["E2"].alignment.wrap_text
    assert ws.row_dimensions[2].height > 15  # the wrapped text gets its lines


def test_precision_table():
    """The format of a value follows its unit; whole numbers have no decimals; a small
    non-zero ratio is scientific but a ratio below 1e-12 (round-off) and a tiny force are not."""
    assert header_unit("beta [deg] A=1.07 m^2 step") == "deg"
    assert unit_format("N") == "#,##0" and unit_format("lbf in") == "#,##0"
    assert unit_format("m") == "0.000" and unit_format("in") == "0.00"
    assert unit_format("kg") == "#,##0.0" and unit_format("deg") == "0.0"
    assert unit_format("unknown unit") is None
    assert value_format(8, "0.000") == "0"
    assert value_format(3e-6, "0.000", dimensionless=True) == "0.00E+00"
    assert value_format(1.5e-16, "0.000", dimensionless=True) == "0.000"
    assert value_format(3e-6, "#,##0") == "#,##0"


def test_small_ratio_cell_is_scientific(tmp_path):
    """A relative difference of 3e-6 [-] is written 3.00E-06, not 0.000."""
    path = tmp_path / "r.xlsx"
    write_workbook(path, {"S": [Section("t", pd.DataFrame(
        {"item": ["relative difference", "factor"], "value": [3e-6, 1.5],
         "unit": ["-", "-"]}))]})
    ws = openpyxl.load_workbook(path)["S"]
    assert ws["B2"].number_format == "0.00E+00" and ws["B3"].number_format == "0.000"


def test_csv_names():
    """Unit-labelled headers become name_unit, the SFBM file's style."""
    assert [csv_name(h) for h in ("x [m]", "Vx [N]", "Mz [N m]", "S'' [m/s^2]",
                                  "area [m^2]", "T/(m g) [-]", "case")] == [
        "x_m", "Vx_N", "Mz_Nm", "Sddot_mps2", "area_m2", "T_m_g", "case"]


def test_sample_rows_for_print():
    """30 s sampled every 0.05 s (601 rows) is printed every 0.5 s: 61 rows on whole
    multiples of 0.5 s, the first and last samples kept."""
    frame = pd.DataFrame({"t [s]": np.arange(601) * 0.05, "v": np.arange(601)})
    rows, step = sample_rows(frame, "t [s]", 100)
    assert step == 0.5 and len(rows) == 61
    np.testing.assert_allclose(rows["t [s]"], np.arange(61) * 0.5, atol=1e-9)


def _plot(value):
    fig = Figure(figsize=(2, 1.5))
    fig.add_subplot().plot([0, 1], [0, value])
    return fig


def test_figures_drawn_by_workers_are_the_same_bytes():
    """The same plots give the same PNG bytes whether drawn in worker processes or in this
    one (the report is reproducible however it is drawn)."""
    jobs = {f"p{k}": (_plot, (k,), {}) for k in range(3)}
    with FigureRenderer(workers=0) as here:
        local = {t: p.result() for t, p in here.draw(jobs).items()}
    with FigureRenderer(workers=2) as there:
        forked = {t: p.result() for t, p in there.draw(jobs).items()}
    assert local == forked and local["p0"] != local["p1"]
    assert local["p0"][:8] == b"\x89PNG\r\n\x1a\n"


def test_hook_angle_below_30_deg_is_flagged():
    """A hook angle of 20 deg is flagged against CS 29.865(a) with the evidence it rests on:
    none in the run without a lateral study; with a lateral study recommending 25 deg, the
    angle used is said not to be covered; 30 deg is not flagged."""
    result = _beam_study(hook=HookLoadOptions(angle=np.radians(20.0))).run()
    verdict, evidence = hook_angle_finding(result, None, "report LR-7")
    assert verdict.startswith("FLAG") and "20.0 deg" in verdict and "CS 29.865(a)" in verdict
    assert "No lateral-step pendulum study" in evidence and "LR-7" in evidence

    class Lateral:  # the attributes of a lateral study the finding quotes
        class study:
            recommended_angle = np.radians(25.0)
            max_load_angle = np.radians(25.0 / 1.5)
            margin = 1.5
            pendulums = [None] * 12

    verdict, evidence = hook_angle_finding(result, Lateral, "")
    assert "NOT covered" in verdict and "25.0 deg" in verdict and "12 cases" in evidence
    at_30 = _beam_study().run()
    assert not hook_angle_finding(at_30, None, "")[0].startswith("FLAG")


def test_interpolated_previous_values_are_marked(tmp_path):
    """A previous envelope known at every other cut station (and at the ends) is 'given' at
    those stations and 'INTERPOLATED' at the others, in the report as in the API; a station
    outside its range is 'not covered'."""
    first = _beam_study().run()
    x = first.stations
    known = x[::2]
    prev = pd.concat([pd.DataFrame({"x [m]": known, "component": c, "min": -1e4, "max": 1e4})
                      for c in ("Vx", "Vy", "Vz", "Mx", "My", "Mz")], ignore_index=True)
    result = replace(first, study=replace(first.study, previous_envelope=prev))
    status = previous_station_status(result)
    assert status == ["given" if k % 2 == 0 else "INTERPOLATED" for k in range(len(x))]
    write_loads_outputs(result, tmp_path, "p", hull_pairs=(), plots=False)
    ws = openpyxl.load_workbook(tmp_path / "p-loads.xlsx")["Exceedance"]
    head = next(r for r in ws.iter_rows() if r[0].value == "station")
    col = [c.value for c in head].index("previous values")
    got = [ws.cell(head[0].row + 1 + k, col + 1).value for k in range(len(x))]
    assert got == status
    short = prev[prev["x [m]"] <= x[-3]]
    cut = replace(first, study=replace(first.study, previous_envelope=short))
    assert previous_station_status(cut)[-1] == "not covered"


def test_template_comments_explain(tmp_path):
    """The template's header comments: CL is explained as the lift and Cl as the rolling
    moment (each its own comment); every column with a unit states a typical value; the Study
    sheet lists the cover's free fields."""
    path = write_input_workbook(tmp_path / "t.xlsx")
    book = openpyxl.load_workbook(path)
    heads = {c.value: c.comment.text for c in book["FuselageAero"][1] if c.comment}
    assert "LIFT" in heads["CL"] and "rolling" not in heads["CL"].split(".")[0].lower()
    assert "ROLLING" in heads["Cl"]
    for ws in book.worksheets:
        if ws.title in ("README", "Study"):
            continue
        for cell in ws[1]:
            if cell.comment and "[" in str(cell.value) and "[-]" not in str(cell.value):
                assert "Typical" in cell.comment.text, (ws.title, cell.value)
    names = {c.value for c in book["Study"]["A"]}
    assert {"project", "document number", "author", "checker"} <= names


def test_error_values_in_the_users_unit(tmp_path):
    """A previous-envelope station out of order is reported in the unit of its header
    (inches, as the example writes them), not in metres."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book["PreviousEnvelope"]
    assert ws["A1"].value == "x [in]"
    ws["A4"] = 10.5  # below the station above it
    path = tmp_path / "bad.xlsx"
    book.save(path)
    with pytest.raises(InputError) as info:
        read_study(path)
    assert "value 10.5 [in]" in str(info.value) and "cell A4" in str(info.value)

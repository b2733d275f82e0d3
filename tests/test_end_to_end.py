"""End to end: the example workbook through the command line to the report and back.

References: the numbers read back from the report equal those of the Python API run on the
same workbook (workbook -> report -> read-back); inputs in US customary units equal the same
inputs converted by hand to SI with the exact definitions 1 in = 0.0254 m and
1 lb = 0.45359237 kg (NIST SP 811), so the loads must not change.
"""

from __future__ import annotations

import shutil

import numpy as np
import openpyxl
import pandas as pd
import pytest
from hostile import EXAMPLE, publish_earlier

from slingloads.analyses.envelopes import bound_values
from slingloads.cli import main
from slingloads.io.analyses import all_parameters
from slingloads.io.common.ownership import MANIFEST_NAME
from slingloads.io.common.parameters import read_parameters
from slingloads.io.common.workbook import WorkbookReader
from slingloads.io.study import read_study


@pytest.fixture
def run_dir(example_loads_report):
    return example_loads_report


@pytest.fixture
def api_result(example_study):
    return example_study.inputs.loads.run()


def test_csv_and_workbook_read_back(run_dir, api_result):
    """The SFBM CSV holds the API's numbers (SI, limit), and the report's Correlated sheet
    the API's envelope; no SFBM workbook unless the Study sheet asks for one."""
    csv = pd.read_csv(run_dir / "example-light-twin-sfbm.csv")
    assert list(csv.columns) == ["case", "station", "x_m", "Vx_N", "Vy_N", "Vz_N", "Mx_Nm",
                                 "My_Nm", "Mz_Nm"]
    c, s, _ = api_result.loads.shape
    assert len(csv) == c * s
    np.testing.assert_allclose(csv.iloc[:, 3:].to_numpy().reshape(c, s, 6), api_result.loads,
                               rtol=1e-12, atol=1e-6)
    sheet = _section_table(run_dir / "example-light-twin-loads.xlsx", "Correlated")
    np.testing.assert_allclose(sheet["value"].to_numpy(float),
                               bound_values(api_result.envelope()), rtol=1e-12)
    assert not (run_dir / "example-light-twin-sfbm.xlsx").exists()


def _section_table(path, sheet):
    """The table of a report sheet whose only table is under a title row."""
    raw = pd.read_excel(path, sheet_name=sheet, header=None)
    head = int(np.nonzero(raw[0].astype(str).to_numpy() == "station")[0][0])
    table = raw.iloc[head + 1:].copy()
    table.columns = raw.iloc[head]
    return table


def test_example_has_twenty_stations_and_closes(api_result):
    """The example reports at least 20 cut stations; free-free closure holds to round-off."""
    assert len(api_result.stations) >= 20
    assert np.abs(api_result.residual).max() < 1e-8 * api_result.residual_scale


def test_us_and_si_inputs_give_the_same_loads(tmp_path, api_result):
    """MassItems, Stations and Hardpoints rewritten from [lb]/[in] to [kg]/[m] by hand give
    identical loads (exact conversion constants)."""
    book = openpyxl.load_workbook(EXAMPLE)
    for name in ("MassItems", "Stations", "Hardpoints"):
        ws = book[name]
        for col in ws.iter_cols(min_row=1):
            head = str(col[0].value)
            factor = {"[in]": 0.0254, "[lb]": 0.45359237}.get(head[head.find("["):], None)
            if factor is None:
                continue
            col[0].value = head.replace("[in]", "[m]").replace("[lb]", "[kg]")
            for cell in col[1:]:
                if cell.value is not None:
                    cell.value = cell.value * factor
    path = tmp_path / "si.xlsx"
    book.save(path)
    si = read_study(path).inputs.loads.run()
    np.testing.assert_allclose(si.loads, api_result.loads, rtol=1e-9, atol=1e-6)


def test_template_is_a_valid_blank_workbook(tmp_path, capsys):
    """`slingloads template` writes every documented sheet; its Study sheet reads back with
    every parameter at its default; running it fails cleanly (no data yet) with exit code 2."""
    path = tmp_path / "blank.xlsx"
    assert main(["template", str(path)]) == 0
    reader = WorkbookReader(path)
    for sheet in ("README", "Study", "MassItems", "Stations", "Hardpoints", "FuselageAero",
                  "AeroEnvelope", "PreviousEnvelope", "MultibodyManoeuvres", "HTailAero"):
        assert sheet in reader.sheetnames
    # a sheet with its header alone counts as deleted (the form runs with it left empty)
    assert reader.has_sheet("README") and not reader.has_sheet("FuselageAero")
    assert read_parameters(reader, all_parameters())["hook load factor nz"][0] == pytest.approx(2.5)
    assert main(["template", str(path)]) == 2  # exists: not replaced without --force
    assert main(["run", str(path), "--out", str(tmp_path / "r"), "--quiet"]) == 2
    assert "no data rows" in capsys.readouterr().err
    assert not (tmp_path / "r").exists()


@pytest.mark.parametrize("command", ["template", "run", "loads", "lateral", "chute", "simulate"])
def test_every_command_has_help(command, capsys):
    """`--help` on each command prints its usage and exits 0."""
    with pytest.raises(SystemExit) as info:
        main([command, "--help"])
    assert info.value.code == 0
    assert "usage: slingloads" in capsys.readouterr().out


def test_us_report(tmp_path):
    """--units US writes the report in in / lbf / lbf in: the envelope's Vy column equals the
    SI value of the envelope CSV / 4.4482216152605, its x the CSV's x_m / 0.0254. The unit
    system's name is read with its case ignored (``us``)."""
    src = tmp_path / "ex.xlsx"
    shutil.copy(EXAMPLE, src)
    assert main(["loads", str(src), "--out", str(tmp_path), "--units", "us", "--quiet"]) == 0
    sheet = _section_table(tmp_path / "ex-loads.xlsx", "Correlated")
    csv = pd.read_csv(tmp_path / "ex-envelope.csv")
    assert "Vy [lbf]" in sheet.columns and "x [in]" in sheet.columns
    np.testing.assert_allclose(sheet["Vy [lbf]"].to_numpy(float), csv["Vy_N"] / 4.4482216152605,
                               rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(sheet["x [in]"].to_numpy(float), csv["x_m"] / 0.0254, rtol=1e-12)


def test_an_unknown_unit_system_is_refused(tmp_path, capsys):
    """``--units metric``: a usage error (exit 2) naming the two systems, nothing written."""
    with pytest.raises(SystemExit) as info:
        main(["loads", str(EXAMPLE), "--out", str(tmp_path / "out"), "--units", "metric"])
    assert info.value.code == 2
    assert "'metric'" in capsys.readouterr().err and not (tmp_path / "out").exists()


def test_hostile_text_from_the_workbook_stays_text(tmp_path):
    """A case listed on the LoadCases sheet with the id and description `=HYPERLINK("x")`
    reaches the report as a text cell, never a formula (OWASP CSV/formula injection)."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book.create_sheet("LoadCases")
    ws.append(["id", "hook", "aero", "chute", "description"])
    ws.append(['=HYPERLINK("x")', "AXIAL", "CENTRE", "no", '=HYPERLINK("http://x","y")'])
    for cell in ws[2]:
        cell.data_type = "s"  # typed as text in the input, as a user would with a quote
    path = tmp_path / "hostile.xlsx"
    book.save(path)
    assert main(["loads", str(path), "--out", str(tmp_path), "--quiet"]) == 0
    report = openpyxl.load_workbook(tmp_path / "hostile-loads.xlsx")
    cells = [c for row in report["LoadCases"].iter_rows() for c in row
             if isinstance(c.value, str) and "HYPERLINK" in c.value]
    assert {c.value for c in cells} == {'=HYPERLINK("x")', '=HYPERLINK("http://x","y")'}
    assert all(c.data_type == "s" for c in cells)


def test_run_publishes_all_analyses_or_none(tmp_path, monkeypatch, capsys):
    """If one analysis fails while writing, no analysis's file is published (the loads
    report, written first, is not left alone in the output directory) and an earlier file at
    the same path is intact: `run` publishes its outputs as one set. The unexpected error
    ends in a one-line message and exit code 1, not a traceback, and no staging folder is
    left beside the output folder."""

    from slingloads.io.chute import report

    def failing_writer(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(report, "report_kind", failing_writer)
    out = tmp_path / "reports"
    publish_earlier(out, {"example-light-twin-loads.xlsx": b"earlier"})
    manifest = (out / MANIFEST_NAME).read_bytes()
    assert main(["run", str(EXAMPLE), "--out", str(out), "--quiet"]) == 1
    assert "disk full" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == [MANIFEST_NAME,
                                                     "example-light-twin-loads.xlsx"]
    assert (out / "example-light-twin-loads.xlsx").read_bytes() == b"earlier"
    assert (out / MANIFEST_NAME).read_bytes() == manifest
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".slingloads-")]

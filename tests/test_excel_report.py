"""Tests of the loads report writer (slingloads.io.loads.report), the generic Excel writer
(slingloads.io.common.excel) and atomic output writing (slingloads.io.common.atomic).

Numbers are read back from the written files with openpyxl / pandas and compared with the
LoadsResult they came from; unit conversions are checked against constants written out here
independently of slingloads.io.common.units: 1 in = 0.0254 m exactly (international inch, 1959) and
1 lbf = 0.45359237 kg x 9.80665 m/s^2 = 4.4482216152605 N exactly.
"""

from __future__ import annotations

import zipfile
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from hostile import publish_earlier
from numpy.testing import assert_allclose
from openpyxl import load_workbook

from slingloads.analyses.envelopes import bound_values
from slingloads.analyses.loads import ListedCase, LoadsStudy
from slingloads.errors import InputError
from slingloads.io.common import report_writer
from slingloads.io.common.atomic import TEMP_PREFIX, atomic_outputs
from slingloads.io.common.excel import Highlight, Section, write_workbook
from slingloads.io.common.ownership import MANIFEST_NAME
from slingloads.io.loads.report import (
    ENVELOPE_CSV_COLUMNS,
    SFBM_CSV_COLUMNS,
    write_loads_outputs,
)
from slingloads.io.loads.tables import UNBOUNDED_RATIO
from slingloads.models.airframe import Airframe, Hardpoints, MassItems

INCH = 0.0254  # m, exact
LBF = 4.4482216152605  # N, exact
HOSTILE = '=HYPERLINK("x")'
COMPONENTS = ("Vx", "Vy", "Vz", "Mx", "My", "Mz")


def _airframe():
    n = 30
    x = np.linspace(0.5, 10, n)
    items = MassItems([f"m{i}" for i in range(n)], np.full(n, 95.0),
                      np.c_[x, 0.3 * np.sin(x), 0.2 * np.cos(x)])
    hp = Hardpoints(hub=[4.0, 0, 2.5], mast_feet=[[3.5, -0.4, 1.5], [3.5, 0.4, 1.5],
                                                  [4.5, -0.4, 1.5], [4.5, 0.4, 1.5]])
    return Airframe(items, stations=np.linspace(0.6, 9.9, 25), hardpoints=hp)


@pytest.fixture(scope="module")
def result():
    """A crude beam with the generated hook cases plus a listed case whose description is a
    formula-like string, and a previous design envelope at 80 % of the new one (so that the
    exceedance ratio is 1.25 wherever the loads are not zero)."""
    listed = (ListedCase("HOSTILE", "AXIAL", "NONE", False, HOSTILE),)
    study = LoadsStudy(_airframe(), listed=listed, name="crude beam")
    first = study.run()
    env = first.envelope()
    rows = []
    for name in COMPONENTS:
        e = env[env["component"] == name]
        mx = bound_values(e[e["bound"] == "max"])
        mn = bound_values(e[e["bound"] == "min"])
        rows.append(pd.DataFrame({"x [m]": first.stations, "component": name,
                                  "min": 0.8 * np.minimum(mn, 0), "max": 0.8 * np.maximum(mx, 0)}))
    return replace(study, previous_envelope=pd.concat(rows, ignore_index=True)).run()


@pytest.fixture(scope="module")
def reports(result, tmp_path_factory):
    """The report written once in SI and once in US units."""
    out = {}
    for units in ("SI", "US"):
        d = tmp_path_factory.mktemp(units)
        paths = write_loads_outputs(result, d, "demo", units=units,
                                    inputs_digest={"input file": "demo.xlsx",
                                                   "SHA-256": "0" * 64}, sfbm_workbook=True)
        out[units] = (d, paths)
    return out


def _sheet_rows(path, sheet):
    wb = load_workbook(path, read_only=True)
    try:
        return [list(r) for r in wb[sheet].iter_rows(values_only=True)]
    finally:
        wb.close()


def _table_after(rows, first_header):
    """The table of a sections sheet whose header row starts with ``first_header``."""
    start = next(i for i, r in enumerate(rows) if r and r[0] == first_header)
    header = [h for h in rows[start] if h is not None]
    body = []
    for r in rows[start + 1:]:
        if not r or all(v is None for v in r):
            break
        body.append(r[:len(header)])
    return pd.DataFrame(body, columns=header)


def test_written_files(reports):
    """The report writes the workbook, the SFBM data workbook, both CSV files, the station
    diagram and one SFBM plot per component (X and Y shear are the paper's figures 19 and
    20), and nothing else is left in the directory."""
    d, paths = reports["SI"]
    names = {p.name for p in paths}
    assert {"demo-loads.xlsx", "demo-sfbm.xlsx", "demo-sfbm.csv", "demo-envelope.csv",
            "demo-stations.png", "demo-X_shear.png", "demo-Y_shear.png", "demo-Z_shear.png",
            "demo-X_moment.png", "demo-Y_moment.png", "demo-Z_moment.png"} <= names
    assert {p.name for p in d.iterdir()} == names | {MANIFEST_NAME}
    for p in paths:
        if p.suffix == ".png":
            assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_csv_columns_and_rows(result, reports):
    """The SFBM CSV has exactly the columns case,station,x_m,Vx_N..Mz_Nm and one row per case
    and station (c x s), in SI and equal to the limit loads of the result, whatever the
    workbook units."""
    for units in ("SI", "US"):
        d, _ = reports[units]
        with open(d / "demo-sfbm.csv") as f:
            assert f.readline().strip() == ",".join(SFBM_CSV_COLUMNS)
        frame = pd.read_csv(d / "demo-sfbm.csv")
        c, s, _ = result.loads.shape
        assert len(frame) == c * s
        assert_allclose(frame[list(SFBM_CSV_COLUMNS[3:])].to_numpy(),
                        result.loads.reshape(c * s, 6), rtol=1e-15, atol=0)
        assert_allclose(frame["x_m"].to_numpy(), np.tile(result.stations, c), rtol=1e-15)
        env = pd.read_csv(d / "demo-envelope.csv")
        assert list(env.columns) == list(ENVELOPE_CSV_COLUMNS)
        value = env["value_N"].fillna(env["value_Nm"]).to_numpy()
        assert_allclose(value, bound_values(result.envelope()), rtol=1e-15)
        moment = env["component"].str.startswith("M")
        assert env.loc[moment, "value_N"].isna().all()
        assert env.loc[~moment, "value_Nm"].isna().all()


def _wide_envelope(path, sheet, title):
    return _table_after(_sheet_rows(path, sheet)[_row_of(path, sheet, title):], "station")


def _row_of(path, sheet, title):
    return next(i for i, r in enumerate(_sheet_rows(path, sheet))
                if r and str(r[0]).startswith(title))


def test_si_workbook_numbers(result, reports):
    """SI workbooks: the SFBM data workbook, the Correlated, Envelope and Ultimate sheets
    read back with pandas/openpyxl hold the result's numbers (full double precision: the
    number format only changes display); the wide envelope's max and min are those of the
    loads over every case, with the case that gives them."""
    d = reports["SI"][0]
    sfbm = pd.read_excel(d / "demo-sfbm.xlsx", sheet_name="SFBM")
    assert list(sfbm.columns) == ["case", "station", "x [m]", "Vx [N]", "Vy [N]", "Vz [N]",
                                  "Mx [N m]", "My [N m]", "Mz [N m]"]
    c, s, _ = result.loads.shape
    assert_allclose(sfbm.iloc[:, 3:].to_numpy(), result.loads.reshape(c * s, 6), rtol=1e-15)
    assert sfbm["case"].tolist() == result.to_frame()["case"].tolist()
    path = d / "demo-loads.xlsx"
    env = _table_after(_sheet_rows(path, "Correlated"), "station")
    ref = result.envelope()
    assert_allclose(env["value"].to_numpy(float), bound_values(ref), rtol=1e-15)
    assert env["case"].tolist() == ref["case"].tolist()
    assert set(env["unit"]) == {"N", "N m"}
    shears = _wide_envelope(path, "Envelope", "Shear forces (LIMIT)")
    assert_allclose(shears["Vy max [N]"].to_numpy(float), result.loads[:, :, 1].max(axis=0),
                    rtol=1e-15)
    assert_allclose(shears["Vy min [N]"].to_numpy(float), result.loads[:, :, 1].min(axis=0),
                    rtol=1e-15)
    ids = np.asarray(result.case_ids)
    assert shears["Vy max case"].tolist() == ids[result.loads[:, :, 1].argmax(axis=0)].tolist()
    ult = _wide_envelope(path, "Ultimate", "Moments (ULTIMATE")
    assert_allclose(ult["Mz min [N m]"].to_numpy(float),
                    1.5 * result.loads[:, :, 5].min(axis=0), rtol=1e-14)


def test_us_workbook_conversion(result, reports):
    """US workbooks: x [in] = x / 0.0254, forces [lbf] = F / 4.4482216152605 and moments
    [lbf in] = M / (4.4482216152605 x 0.0254), with the unit in every header; the envelope's
    per-row value is in lbf for shears and lbf in for moments."""
    d = reports["US"][0]
    sfbm = pd.read_excel(d / "demo-sfbm.xlsx", sheet_name="SFBM")
    assert list(sfbm.columns) == ["case", "station", "x [in]", "Vx [lbf]", "Vy [lbf]",
                                  "Vz [lbf]", "Mx [lbf in]", "My [lbf in]", "Mz [lbf in]"]
    c, s, _ = result.loads.shape
    flat = result.loads.reshape(c * s, 6)
    assert_allclose(sfbm["x [in]"], np.tile(result.stations, c) / INCH, rtol=1e-12)
    assert_allclose(sfbm.iloc[:, 3:6].to_numpy(), flat[:, :3] / LBF, rtol=1e-12)
    assert_allclose(sfbm.iloc[:, 6:].to_numpy(), flat[:, 3:] / (LBF * INCH), rtol=1e-12)
    path = d / "demo-loads.xlsx"
    env = _table_after(_sheet_rows(path, "Correlated"), "station")
    ref = result.envelope()
    moment = ref["component"].str.startswith("M").to_numpy()
    expected = bound_values(ref) / np.where(moment, LBF * INCH, LBF)
    assert_allclose(env["value"].to_numpy(float), expected, rtol=1e-12)
    assert env["unit"].tolist() == np.where(moment, "lbf in", "lbf").tolist()
    assert_allclose(env["Mz [lbf in]"].to_numpy(float), ref["Mz_Nm"] / (LBF * INCH), rtol=1e-12)
    study = _table_after(_sheet_rows(path, "Summary"), "item")
    mass = study.set_index("item").loc["aircraft mass"]
    assert mass["unit"] == "lb"
    assert mass["value"] == pytest.approx(30 * 95.0 / 0.45359237, rel=1e-12)


def test_summary_closure_and_governing(result, reports):
    """The cover quotes the input digest as given; the Summary's closure check says PASS
    (residuals of the crude beam are at round-off); the Envelope sheet lists one governing
    case per component matching LoadsResult.governing_cases()."""
    path = reports["SI"][0] / "demo-loads.xlsx"
    cover = _table_after(_sheet_rows(path, "Cover"), "item").set_index("item")["entry"]
    assert cover["input SHA-256"] == "0" * 64
    assert cover["input workbook"] == "demo.xlsx"
    rows = _sheet_rows(path, "Summary")
    closure = _table_after(rows, "check")
    assert closure["check"].iloc[-1] == "result: PASS"
    assert float(closure["force residual [N]"].iloc[1]) < 1e-6
    gov = _table_after(_sheet_rows(path, "Envelope"), "component")
    ref = result.governing_cases()
    assert gov["case"].tolist() == ref["case"].tolist()
    assert_allclose(gov["value"].to_numpy(float), bound_values(ref), rtol=1e-15)


def test_hostile_description_is_text(reports):
    """A case description '=HYPERLINK("x")' is stored as a string cell (data_type 's') with
    the text unchanged, and no sheet of the workbook contains a formula element <f>:
    spreadsheet formula injection through input text is impossible."""
    path = reports["SI"][0] / "demo-loads.xlsx"
    wb = load_workbook(path)
    hits = [cell for row in wb["LoadCases"].iter_rows() for cell in row
            if cell.value == HOSTILE]
    assert len(hits) == 1
    assert hits[0].data_type == "s"
    with zipfile.ZipFile(path) as z:
        for name in z.namelist():
            if name.startswith("xl/worksheets/") and name.endswith(".xml"):
                xml = z.read(name).decode()
                assert "<f>" not in xml and "<f " not in xml, name


def test_generic_writer_text_never_formula(tmp_path):
    """write_workbook stores '=...', '+cmd|...', '-1+2' and '@SUM(A1)' strings as text cells,
    NaN as an empty cell and an unexplained inf as the text 'infinite', never the bare 'inf'
    (Excel has no NaN or inf)."""
    frame = pd.DataFrame({"text": [HOSTILE, "+cmd|' /C calc'!A0", "-1+2", "@SUM(A1)"],
                          "number": [1.5, np.nan, np.inf, -2.0]})
    path = tmp_path / "t.xlsx"
    write_workbook(path, {"T": frame})
    wb = load_workbook(path)
    col = [c for c in wb["T"]["A"]][1:]
    assert [c.value for c in col] == frame["text"].tolist()
    assert all(c.data_type == "s" for c in col)
    assert [c.value for c in wb["T"]["B"]][1:] == [1.5, None, "infinite", -2.0]
    assert wb["T"].freeze_panes == "B2"
    assert wb["T"]["A1"].font.b


def test_split_keeps_every_row(result, tmp_path):
    """With a row limit of 50 per sheet (header included), the SFBM table of c x s rows is
    split over SFBM_1, SFBM_2... with the header on each, and concatenating them gives every
    row of the result exactly once, in order (never truncated)."""
    write_loads_outputs(result, tmp_path, "split", max_rows=50, plots=False,
                        sfbm_workbook=True)
    path = tmp_path / "split-sfbm.xlsx"
    names = load_workbook(path, read_only=True).sheetnames
    c, s, _ = result.loads.shape
    parts = [n for n in names if n.startswith("SFBM_")]
    assert "SFBM" not in names
    assert parts == [f"SFBM_{k + 1}" for k in range(int(np.ceil(c * s / 49)))]
    frames = [pd.read_excel(path, sheet_name=n) for n in parts]
    assert all(len(f) <= 49 for f in frames)
    whole = pd.concat(frames, ignore_index=True)
    assert len(whole) == c * s
    assert_allclose(whole.iloc[:, 3:].to_numpy(), result.loads.reshape(c * s, 6), rtol=1e-15)


def test_exceedance_sheet(result, reports, tmp_path):
    """ExceedanceDetail: the ratio read back equals LoadsResult.comparison() (1.25 where the
    previous envelope is 80 % of the new one), with the station id on every row and a red
    conditional format on the ratio column; Exceedance: one row per station, the station id
    beside the six ratios; without a previous envelope the sheets say 'no previous envelope
    given'."""
    path = reports["SI"][0] / "demo-loads.xlsx"
    table = _table_after(_sheet_rows(path, "ExceedanceDetail"), "station")
    ref = result.comparison()
    assert table["station"].tolist() == ref["station"].tolist()
    got = pd.to_numeric(table["exceedance ratio [-]"].replace(UNBOUNDED_RATIO, np.inf))
    assert_allclose(got.to_numpy(float), ref["exceedance ratio"].to_numpy(), rtol=1e-15)
    assert np.nanmax(got.to_numpy(float)[np.isfinite(got)]) == pytest.approx(1.25)
    wide = _table_after(_sheet_rows(path, "Exceedance"), "station")
    assert wide["station"].tolist() == list(result.station_ids)
    vy = ref[ref["component"] == "Vy"]["exceedance ratio"].to_numpy()
    assert_allclose(pd.to_numeric(wide["Vy ratio [-]"].replace(UNBOUNDED_RATIO, np.inf))
                    .to_numpy(float),
                    vy, rtol=1e-15)
    ws = load_workbook(path)["ExceedanceDetail"]
    col = list(table.columns).index("exceedance ratio [-]")
    letter = "ABCDEFGHIJKLMNOP"[col]
    ranges = [str(cf.sqref) for cf in ws.conditional_formatting]
    assert any(r.startswith(letter) for r in ranges)
    bare = replace(result, study=replace(result.study, previous_envelope=None))
    write_loads_outputs(bare, tmp_path, "bare", hull_pairs=(), plots=False)
    rows = _sheet_rows(tmp_path / "bare-loads.xlsx", "Exceedance")
    assert rows[0][0] == "no previous envelope given"
    # said once: no ExceedanceDetail page repeating it
    assert "ExceedanceDetail" not in load_workbook(tmp_path / "bare-loads.xlsx").sheetnames


def test_atomic_failure_keeps_earlier_report(result, tmp_path, monkeypatch):
    """An exception after the workbook is written but before the files are published leaves
    the earlier report byte for byte intact and no temporary file or directory behind."""
    first = write_loads_outputs(result, tmp_path, "demo", hull_pairs=(), plots=False)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert {p.name for p in first} | {MANIFEST_NAME} == set(before)
    real = report_writer.write_workbook

    def write_then_fail(path, *args, **kwargs):
        real(path, *args, **kwargs)
        raise OSError("disk full (simulated)")

    monkeypatch.setattr(report_writer, "write_workbook", write_then_fail)
    with pytest.raises(OSError, match="simulated"):
        write_loads_outputs(result, tmp_path, "demo", units="US", hull_pairs=(),
                            plots=False)
    after = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert after == before
    assert not any(n.startswith(TEMP_PREFIX) for n in after)


def test_atomic_outputs_helper(tmp_path):
    """atomic_outputs: inside the block the final path is untouched; on success the file is
    moved into place; on an exception nothing is published and the temporary directory is
    gone; a new output directory that failed is removed again."""
    target = tmp_path / "a.txt"
    publish_earlier(tmp_path, {"a.txt": b"old"})
    with atomic_outputs(tmp_path) as out:
        out.path("a.txt").write_text("new")
        assert target.read_text() == "old"
    assert target.read_text() == "new" and out.written == [target]
    with pytest.raises(RuntimeError, match="boom"), atomic_outputs(tmp_path) as out:
        out.path("a.txt").write_text("newer")
        out.path("b.txt").write_text("b")
        raise RuntimeError("boom")
    assert sorted(p.name for p in tmp_path.iterdir()) == [MANIFEST_NAME, "a.txt"]
    assert target.read_text() == "new"
    fresh = tmp_path / "fresh"
    with pytest.raises(RuntimeError), atomic_outputs(fresh) as out:
        raise RuntimeError("boom")
    assert not fresh.exists()


def test_refuses_to_overwrite_input(result, tmp_path):
    """An output whose path is an input file, directly or through a symbolic link, raises
    InputError naming the input; the input is unchanged and nothing is written."""
    source = tmp_path / "demo-loads.xlsx"
    source.write_bytes(b"input workbook")
    with pytest.raises(InputError, match="demo-loads.xlsx") as info:
        write_loads_outputs(result, tmp_path, "demo", input_paths=[source])
    assert "input" in str(info.value)
    assert source.read_bytes() == b"input workbook"
    assert [p.name for p in tmp_path.iterdir()] == ["demo-loads.xlsx"]
    link_dir = tmp_path / "links"
    link_dir.mkdir()
    (link_dir / "x.csv").symlink_to(source)
    with pytest.raises(InputError, match="input"), atomic_outputs(link_dir,
                                                                  inputs=[source]) as out:
        out.path("x.csv")


def test_rejects_bad_arguments(result, tmp_path):
    """Unknown unit systems and sheet names Excel refuses are errors naming the value."""
    with pytest.raises(InputError, match="'metric'"):
        write_loads_outputs(result, tmp_path, "x", units="metric")
    with pytest.raises(InputError, match="sheet name"):
        write_workbook(tmp_path / "t.xlsx", {"a/b": pd.DataFrame({"a": [1]})})
    assert not list(tmp_path.iterdir())


def test_generic_writer_sections_and_highlight(tmp_path):
    """A sheet of one table is a table sheet: the header in row 1 and the data under it,
    nothing else in the cells (the title in the page header, the note in a text box under
    the table), and the highlight rule is a conditional format on the named column of that
    table only."""
    path = tmp_path / "s.xlsx"
    table = pd.DataFrame({"id": ["a", "b"], "ratio": [0.5, 1.5]})
    write_workbook(path, {"S": [Section("Title", table, note="line 1\nline 2")]},
                   highlight={"S": Highlight(["ratio"], 1.0)})
    # a reader pads every row to the sheet's last column (the file's dimension): cut the
    # empty cells that end a row
    rows = [r[:max((j + 1 for j, v in enumerate(r) if v is not None), default=0)]
            for r in _sheet_rows(path, "S")]
    assert rows == [["id", "ratio"], ["a", 0.5], ["b", 1.5]]
    ws = load_workbook(path)["S"]
    assert [str(cf.sqref) for cf in ws.conditional_formatting] == ["B2:B3"]
    assert "Title" in ws.oddHeader.center.text
    with zipfile.ZipFile(path) as z:
        drawing = "".join(z.read(n).decode() for n in z.namelist() if "drawings/drawing" in n)
    assert "line 1" in drawing and "line 2" in drawing


#: Texts a workbook writer could mistake for markup: XlsxWriter writes a string that starts
#: with <r> and ends with </r> as rich-text XML, and _xHHHH_ is the escape of a character.
MARKUP = ["<r><t>x</t></r>", "<r></r>", "</r>", "_x0041_", " lead", "trail ", "=1+1"]


def _as_excel_reads(value):
    """A cell value as Excel reads it: openpyxl leaves the ``_x005F_`` escape (a literal
    ``_`` before ``xHHHH_``) of an inline string undecoded."""
    return value.replace("_x005F_", "_") if isinstance(value, str) else value


@pytest.mark.parametrize("streamed", [False, True])
def test_markup_looking_text_is_stored_verbatim(tmp_path, monkeypatch, streamed):
    """Texts that look like the file's own markup are stored as the text they are, on a
    workbook built in memory and on one streamed row by row (a large one), and the two hold
    the same cells, formats and row heights."""
    import slingloads.io.common.excel as excel

    frame = pd.DataFrame({"text": MARKUP, "note": ["long words " * 8] * len(MARKUP),
                          "x [m]": np.arange(len(MARKUP)) * 0.1})
    sheets = {"T": frame, "S": [Section("Title", frame)]}
    monkeypatch.setattr(excel, "IN_MEMORY_CELLS", -1 if streamed else 10**9)
    write_workbook(tmp_path / "m.xlsx", sheets)
    monkeypatch.setattr(excel, "IN_MEMORY_CELLS", 10**9)
    write_workbook(tmp_path / "ref.xlsx", sheets)
    got, ref = load_workbook(tmp_path / "m.xlsx"), load_workbook(tmp_path / "ref.xlsx")
    for name in ("T", "S"):
        ws = got[name]
        texts = [_as_excel_reads(c.value) for c in ws["A"]]
        assert [t for t in texts if t in MARKUP] == MARKUP, name
        assert {c.data_type for c in ws["A"] if c.value is not None} == {"s"}, name
        cells = [[(_as_excel_reads(c.value), c.data_type, c.number_format) for c in r]
                 for r in ws.iter_rows()]
        assert cells == [[(c.value, c.data_type, c.number_format) for c in r]
                         for r in ref[name].iter_rows()], name
        heights = {k: d.height for k, d in ws.row_dimensions.items() if d.height}
        assert heights and heights == {k: d.height for k, d in ref[name].row_dimensions.items()
                                       if d.height}, name


@pytest.mark.parametrize("streamed", [False, True])
def test_text_excel_cannot_store_is_refused(tmp_path, monkeypatch, streamed):
    """A control character, a text longer than 32,767 characters and a table wider than
    16,384 columns are refused with the sheet and the cell; nothing is written, and no
    temporary file is left."""
    import tempfile

    import slingloads.io.common.excel as excel

    monkeypatch.setattr(excel, "IN_MEMORY_CELLS", -1 if streamed else 10**9)
    temp = tmp_path / "temp"
    temp.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(temp))
    path = tmp_path / "bad.xlsx"
    for bad, rule, cell in (("a\x01b", "control character", "A3"),
                            ("x" * 32_768, "longer than Excel's 32767", "A3"),
                            ("\U0001F600" * 16_384, "longer than Excel's 32767", "A3")):
        with pytest.raises(InputError, match=rule) as err:
            write_workbook(path, {"T": pd.DataFrame({"t": ["ok", bad]})})
        assert (err.value.sheet, err.value.cell) == ("T", cell)
    with pytest.raises(InputError, match="16384 columns"):
        write_workbook(path, {"W": pd.DataFrame(np.zeros((1, 16_385)))})
    assert not path.exists()
    assert not list(temp.iterdir())


def test_page_header_codes_in_input_text(tmp_path):
    """Text from the inputs in a page header prints as written: '&' is doubled, '&G' and
    '&[Picture]' (image codes) stay text, and a text full of '&' is shortened to Excel's 255
    characters instead of losing the header."""
    import warnings

    from slingloads.io.common.cover import ReportInfo

    short = ReportInfo(title="R&G &[Picture]", analysis="a", study="s",
                       input_name="in&G.xlsx", document="D&G")
    full = replace(short, title=short.title + "&" * 200, document="D&G" + "&" * 200)
    frame = pd.DataFrame({"a": [1.0]})
    frame.attrs["title"] = "T&G" + "&" * 200
    path = tmp_path / "h.xlsx"
    for info in (short, full):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # XlsxWriter warns when it drops a header
            write_workbook(path, {"T": frame}, info=info)
        ws = load_workbook(path)["T"]
        assert ws.oddHeader.left.text.startswith("R&&G &&[Picture]")
        assert ws.oddHeader.center.text.startswith("T&&G&&")
        assert ws.oddHeader.right.text.startswith("D&&G")
        assert ws.oddHeader.left.size == ws.oddHeader.right.size == 8
        assert ws.oddFooter.center.text == "page &P of &N"
        with zipfile.ZipFile(path) as z:
            xml = z.read("xl/worksheets/sheet2.xml").decode()
        header = xml.split("<oddHeader>")[1].split("</oddHeader>")[0].replace("&amp;", "&")
        assert len(header) <= 255
    assert ws.oddHeader.left.text.endswith("&&...") and len(header) > 200
    assert load_workbook(path)["Cover"].oddHeader.right.text.startswith("D&&G&&")


def test_libreoffice_opens_workbook(printed_reports):
    """LibreOffice converts the loads workbook in US units (the example's, with the
    session's other reports: ``printed_reports`` in conftest.py) headless to PDF without
    error: the file opens without repair (a workbook Calc must repair fails the conversion
    or is empty)."""
    pdf = printed_reports["us-loads"]
    assert pdf[:5] == b"%PDF-"
    assert len(pdf) > 10_000


def test_a_long_table_of_a_sheet_of_sections_continues_under_its_header(tmp_path):
    """Rule (print setup): the header of a table is on every printed page, repeated by the
    print setup, never written into the data. A table longer than a page among other tables
    goes to a table sheet of its own (named after the sheet and its title) whose row 1 is
    its header, repeated on every page; pandas reads it back whole; the red fill of a
    highlighted column covers its data rows."""
    long = pd.DataFrame({"case": [f"LC{k:04d}" for k in range(300)],
                         "ratio [-]": np.linspace(0.5, 1.5, 300)})
    path = tmp_path / "s.xlsx"
    names = write_workbook(path, {"S": [Section("Short", pd.DataFrame({"a": [1, 2]})),
                                        Section("Short too", pd.DataFrame({"b": [3]})),
                                        Section("Long table", long)]},
                           highlight={"S": Highlight(["ratio [-]"])})
    assert names == ["S", "S-LongTable"]
    ws = load_workbook(path)["S-LongTable"]
    assert ws.print_title_rows.replace("$", "") == "1:1"
    rows = list(ws.iter_rows(values_only=True))
    assert rows[0][:2] == ("case", "ratio [-]") and ("case", "ratio [-]") not in rows[1:]
    pd.testing.assert_frame_equal(pd.read_excel(path, sheet_name="S-LongTable"), long)
    assert [str(cf.sqref) for cf in ws.conditional_formatting] == ["B2:B301"]

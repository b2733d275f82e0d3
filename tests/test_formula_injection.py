"""No output cell or CSV field can act as a formula (OWASP "CSV injection").

The reference is the rule of docs/inputs-and-outputs.md: text that came from an input and
begins with ``=``, ``+``, ``-``, ``@``, a tab or a carriage return (also after leading spaces)
is written to CSV files with a leading apostrophe, numbers stay numbers, and workbook cells
hold such text as text. The check is end to end: hostile ids and descriptions (cases,
stations, mass items, envelope points, motions, the study name) go through ``slingloads run``
and every CSV and workbook it writes is read back with the csv module and openpyxl, and with
LibreOffice where it is installed (a formula there would be evaluated: ``=1+1`` would read 2).
"""

from __future__ import annotations

import csv

import pytest
from hostile import save_xlsx, set_parameter, small_workbook
from openpyxl import load_workbook

from slingloads.cli import main
from slingloads.io.common.csvout import FORMULA_STARTS, neutralise, write_csv
from slingloads.io.common.ownership import MANIFEST_NAME

CASE = "=cmd|' /C calc'!A0"
HOSTILE = {
    "case": CASE,
    "case description": "@SUM(A1:A9)",
    "station": "=1+1",
    "hull station": "@S2",
    "item": '=HYPERLINK("http://example.invalid","click")',
    "item description": "-2+3",
    "envelope": "+A1",
    "motion": "=step()",
    "study": "=2+3",
}


@pytest.fixture(scope="module")
def hostile_reports(tmp_path_factory):
    root = tmp_path_factory.mktemp("hostile")
    book = small_workbook()
    stations = book["Stations"]
    stations[1][0], stations[2][0] = "-S1", HOSTILE["hull station"]
    stations[3][0], stations[4][0] = HOSTILE["station"], "+S4"
    items = book["MassItems"]
    items[1][0], items[1][1] = HOSTILE["item"], HOSTILE["item description"]
    book["AeroEnvelope"][1][0] = HOSTILE["envelope"]
    cases = book["LoadCases"]
    cases[1][0], cases[1][2], cases[1][4] = (HOSTILE["case"], HOSTILE["envelope"],
                                             HOSTILE["case description"])
    book["LateralMotions"][1][0] = HOSTILE["motion"]
    set_parameter(book, "hull stations", HOSTILE["hull station"])
    set_parameter(book, "study name", HOSTILE["study"])
    path = save_xlsx(book, root / "hostile.xlsx")
    out = root / "reports"
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 0
    return out


def test_neutralise_rule():
    """The rule on single values: formula starts get an apostrophe (also after spaces),
    plain numbers and other text are unchanged, non-text is unchanged."""
    for text in ("=1+1", "+1+1", "-1+1", "@A1", "\t=1", "\r=1", "  =1", "\u00a0@x"):
        assert neutralise(text) == "'" + text
    for value in ("-12.5", "+3", "1e-3", "abc", "", "'quoted", 12, -3.5, None):
        assert neutralise(value) == value
    assert set("=+-@\t\r") <= set("".join(FORMULA_STARTS))


def test_csv_writer_keeps_numbers_numbers(tmp_path):
    """write_csv: text columns neutralised, numeric columns written as numbers, headers too."""
    import pandas as pd

    frame = pd.DataFrame({"=id": ["=1+1", "ok", "-2"], "x_m": [-1.5, 2.0, 3.25]})
    write_csv(frame, tmp_path / "t.csv")
    rows = list(csv.reader((tmp_path / "t.csv").open()))
    assert rows[0] == ["'=id", "x_m"]
    assert [r[0] for r in rows[1:]] == ["'=1+1", "ok", "-2"]
    assert [float(r[1]) for r in rows[1:]] == [-1.5, 2.0, 3.25]


def test_every_csv_field_is_safe(hostile_reports):
    """Every field of every CSV the run wrote: none starts (after spaces) with a formula
    character unless it is a plain number; the hostile case id is there, neutralised."""
    files = sorted(hostile_reports.glob("*.csv"))
    assert len(files) >= 2
    seen = set()
    for path in files:
        for row in csv.reader(path.open(newline="")):
            for field in row:
                seen.add(field)
                stripped = field.lstrip(" \u00a0")
                if stripped[:1] in FORMULA_STARTS or field[:1] in FORMULA_STARTS:
                    float(field)  # only a plain number may start so
    assert "'" + CASE in seen and "'" + HOSTILE["station"] in seen


def test_every_workbook_cell_is_text_or_number(hostile_reports):
    """No cell of any report workbook is a formula; the hostile texts are stored verbatim."""
    texts = set()
    for path in sorted(hostile_reports.glob("*.xlsx")):
        book = load_workbook(path)
        for ws in book.worksheets:
            for row in ws.iter_rows():
                for cell in row:
                    assert cell.data_type != "f", (path.name, ws.title, cell.coordinate)
                    if isinstance(cell.value, str):
                        texts.add(cell.value)
    for key in ("case", "case description", "station", "study"):
        assert HOSTILE[key] in texts, key


def test_libreoffice_evaluates_nothing(hostile_reports, libreoffice, tmp_path):
    """LibreOffice opens every CSV and every workbook sheet: the CSV files become workbooks
    without a formula cell, and the report sheets export the hostile texts verbatim (a formula
    would have been evaluated)."""
    csvs = sorted(hostile_reports.glob("*.csv"))
    books = sorted(hostile_reports.glob("*.xlsx"))
    libreoffice(csvs, "xlsx", tmp_path / "from_csv")
    for path in sorted((tmp_path / "from_csv").glob("*.xlsx")):
        for ws in load_workbook(path).worksheets:
            for row in ws.iter_rows():
                assert all(c.data_type != "f" for c in row), (path.name, row[0].coordinate)
    libreoffice(books, "csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,"
                "false,-1", tmp_path / "sheets")
    exported = "".join(p.read_text(encoding="utf-8", errors="replace")
                       for p in (tmp_path / "sheets").glob("*.csv"))
    for key in ("case", "station", "study"):
        assert HOSTILE[key] in exported, key


def test_header_footer_text_has_no_control_codes():
    """In a printed header or footer '&' starts a control code (&P, &[Path]): text from an
    input has it doubled, so 'R&D' prints as written."""
    from slingloads.io.common.excel_print import header_footer_text

    assert header_footer_text("R&D &P &[Path]") == "R&&D &&P &&[Path]"
    assert header_footer_text("a\x01b") == "ab"


def test_every_report_file_is_declared(hostile_reports):
    """Every file a run writes matches a name its analysis declares (OUTPUTS of its report
    module): the publisher replaces exactly those, so no stale report file can linger."""
    from slingloads.io.analyses import ANALYSES

    patterns = [p for a in ANALYSES for p in a.output_patterns("hostile")]
    names = [p.name for p in hostile_reports.iterdir() if p.name != MANIFEST_NAME]
    assert len(names) >= 10
    assert all(any(p.match(n) for p in patterns) for n in names), names


def test_every_csv_goes_through_the_neutralising_writer():
    """No module of the package writes a CSV file but the one writer (a source scan: a
    report that called DataFrame.to_csv itself would skip the neutralisation)."""
    from pathlib import Path

    package = Path(__file__).resolve().parents[1] / "slingloads"
    offenders = [str(p.relative_to(package)) for p in package.rglob("*.py")
                 if ".to_csv(" in p.read_text(encoding="utf-8")
                 and p.name != "csvout.py"]
    assert not offenders, offenders

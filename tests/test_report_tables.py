"""Every table of the example's reports reads right in a program: a *table sheet* (the print
setup repeats its row 1) holds a header in row 1 and data below it, nothing else, so that
``pandas.read_excel`` and Excel's filter read it as data; no sheet repeats a header row in its
cells. The reference is the file format's own reading (openpyxl, pandas), not the writer."""

from __future__ import annotations

import re

import openpyxl
import pandas as pd
import pytest


def _workbooks(folder):
    books = sorted(folder.glob("*.xlsx"))
    assert len(books) >= 4  # loads, lateral, chute sizing, multibody
    return books


def _is_table_sheet(ws):
    return ws.print_title_rows in ("1:1", "$1:$1")


def test_every_table_sheet_reads_as_data(example_reports):
    """pandas reads each table sheet with named columns only (no "Unnamed"), no row equal to
    the header, and each column either numbers (and blanks) or texts, never a header text
    among numbers."""
    _, folder = example_reports
    for book in _workbooks(folder):
        wb = openpyxl.load_workbook(book, read_only=False)
        tables = [ws.title for ws in wb.worksheets if _is_table_sheet(ws)]
        assert tables, book.name
        for name in tables:
            frame = pd.read_excel(book, sheet_name=name)
            where = f"{book.name}:{name}"
            assert len(frame), where
            assert not [c for c in frame.columns if str(c).startswith("Unnamed")], where
            header = pd.Series([str(c) for c in frame.columns], index=frame.columns)
            assert not frame.astype(str).eq(header).any(axis=1).any(), where
            for column in frame.columns:
                values = frame[column].dropna()
                numbers = values.map(lambda v: isinstance(v, (int, float))).sum()
                if numbers:  # a column of numbers may hold a few explained values, not a header
                    assert str(column) not in set(values.astype(str)), (where, column)


def test_no_sheet_repeats_a_header_row_in_its_cells(example_reports):
    """A header row appears once in its table (page tops repeat it through the print setup
    only): no two equal bold rows of several cells in one block of rows (blocks are
    separated by an empty row)."""
    _, folder = example_reports
    for book in _workbooks(folder):
        wb = openpyxl.load_workbook(book)
        for ws in wb.worksheets:
            seen = set()
            for row in ws.iter_rows():
                cells = [c for c in row if c.value is not None]
                if not cells:
                    seen = set()
                if len(cells) < 3 or not all(c.font and c.font.b for c in cells):
                    continue
                key = tuple(c.value for c in cells)
                assert key not in seen, (book.name, ws.title, key)
                seen.add(key)


@pytest.mark.parametrize("sheet", ["LoadCases"])
def test_loadcases_is_a_table_sheet(example_reports, sheet):
    """The load cases list is one table sheet (the reference: the print setup of the file)."""
    _, folder = example_reports
    book = next(folder.glob("*-loads.xlsx"))
    assert _is_table_sheet(openpyxl.load_workbook(book)[sheet])


# ----------------------------------------------------------------------------- units
#: A number followed by an SI unit, as a sentence quotes it (the US system has none of them).
SI_QUOTED = re.compile(r"(?<![\w.^/])-?\d+(?:\.\d+)? ?"
                       r"(?:m/s\^2|m/s|m\^2|kg m\^2|kg/m\^3|N m|kg|m|N)(?![\w^/])")


def _cells(book):
    wb = openpyxl.load_workbook(book)
    for ws in wb.worksheets:
        for row in ws.iter_rows():
            yield ws.title, row


def test_units_per_quantity_are_kept(example_reports):
    """The unit of each quantity, read back from the cells: airspeeds in kt in both systems
    (rows and headers naming an airspeed), inertias in the moments' family in US units
    (lb in^2 beside lbf in, never slug ft^2), no SI quantity quoted in a US sentence, counts
    and altitudes written without decimals, and "1 body" (not "1 bodies")."""
    units, folder = example_reports
    for book in _workbooks(folder):
        for sheet, row in _cells(book):
            values = [c.value for c in row]
            texts = [v for v in values if isinstance(v, str)]
            where = (book.name, sheet, values[:4])
            assert not any(re.search(r"\b1 bodies\b", t) for t in texts), where
            if units == "US":
                assert not any(SI_QUOTED.search(t) for t in texts), where
                assert not any("slug ft^2" in t for t in texts), where
            for t in texts:
                if "airspeed" in t and "[" in t:  # a header
                    assert t.endswith("[kt]"), where
            item = values[0] if values and isinstance(values[0], str) else ""
            if len(values) >= 3 and isinstance(values[1], (int, float)) and texts:
                unit = values[2]
                if "airspeed" in item:
                    assert unit == "kt", where
                if item.startswith(("density altitude", "cases ", "load cases", "cut stations")):
                    assert "." not in row[1].number_format, (where, row[1].number_format)


# ----------------------------------------------------------------------------- LoadCases
def test_loadcases_say_where_each_case_comes_from(example_reports, example_results):
    """Every case of the LoadCases sheet has its source and a description, and the source
    follows from the case's own columns and the inputs: hand-listed for the ids of the
    LoadCases input sheet, towed equilibrium for hook TOW, a CS-29.865 direction for the
    hook directions of the Summary (VERTICAL, AZnnn); the two printed tables (definition,
    load factors) hold the same cases (their print scale, 70 % or more, in blocks of columns
    where too wide: tests/test_report_print_scale.py)."""
    _, folder = example_reports
    book = next(folder.glob("*-loads.xlsx"))
    cases = pd.read_excel(book, sheet_name="LoadCases")
    factors = pd.read_excel(book, sheet_name="LoadFactors")
    assert list(cases["case"]) == list(factors["case"])
    assert cases["description"].notna().all() and (cases["description"].str.len() > 10).all()
    listed = {c.id for c in example_results.loads.study.listed}
    for case, hook, source in zip(cases["case"], cases["hook"], cases["source"], strict=True):
        expected = ("hand-listed" if case in listed else "towed equilibrium" if hook == "TOW"
                    else "CS-29.865 direction")
        assert source == expected or source == "dynamics", (case, hook, source)
    assert {"towed equilibrium", "CS-29.865 direction"} <= set(cases["source"])


# ----------------------------------------------------------------------------- precision
_NUMBER = re.compile(r"(?<![\w.])-?\d[\d,]*(?:\.\d+)?(?![\w.]*\d)")


def _decimals(number_format):
    """Decimals of an Excel number format (``0.000`` -> 3, ``#,##0`` -> 0), or None."""
    match = re.search(r"0(?:\.(0+))?(?:E|$|;)", number_format or "")
    return None if match is None else len(match.group(1) or "")


def _quoted_at_their_precision(book, sheet="Findings"):
    """(row, quoted, as the value cell shows it) of every number in an answer that states
    the row's value at another precision than the value cell's number format."""
    ws = openpyxl.load_workbook(book)[sheet]
    head = [c.value for c in ws[1]]
    answer, value = head.index("answer"), head.index("value")
    faults = []
    for row in ws.iter_rows(min_row=2):
        v, text = row[value].value, row[answer].value
        places = _decimals(row[value].number_format)
        if not isinstance(v, (int, float)) or not isinstance(text, str) or places is None:
            continue
        shown = f"{v:.{places}f}"
        for quoted in _NUMBER.findall(text):
            x = float(quoted.replace(",", ""))
            if abs(x - v) <= 0.006 * abs(v) + 0.5 * 10 ** -places and \
                    quoted.replace(",", "") != shown:
                faults.append((row[0].value, quoted, shown))
    return faults


def test_findings_quote_each_value_at_its_cell_precision(example_reports, us_twin_reports):
    """On the Findings sheet of every report of both examples, a number of an answer that
    states the row's value is written as the value cell shows it (its Excel number format:
    a factor [-] to 0.001, an angle to 0.1 deg), not at another precision (the peak tension
    "2.16 <= Nz 2.5" beside 2.163 and 2.500, the exceedance ratio 7.1 and 7.10 beside
    7.097)."""
    for _, folder in (example_reports, us_twin_reports):
        for book in _workbooks(folder):
            if "Findings" in openpyxl.load_workbook(book, read_only=True).sheetnames:
                assert not _quoted_at_their_precision(book), (book.name,
                                                              _quoted_at_their_precision(book))


def test_loads_summary_states_the_exceedance_ratio_as_its_findings(example_reports):
    """The loads Summary's largest exceedance ratio is the Findings sheet's value, written
    at the same precision (the ratio's 0.000)."""
    _, folder = example_reports
    book = next(folder.glob("*-loads.xlsx"))
    findings = pd.read_excel(book, sheet_name="Findings")
    row = findings[findings["question"].str.startswith("loads exceedances")].iloc[0]
    summary = " ".join(str(v) for v in pd.read_excel(book, sheet_name="Summary",
                                                     header=None)[0].dropna())
    assert f"largest finite ratio {float(row['value']):.3f}" in summary


def _agrees(quoted, value):
    """A number quoted in a sentence agrees with ``value`` when ``value`` rounds to it at
    the quoted number's own last digit."""
    text = quoted.replace(",", "")
    places = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text) - value) <= 0.5 * 10 ** -places * (1 + 1e-9)


def test_loads_summary_quotes_the_study_area_as_its_decision_table(example_reports,
                                                                   us_twin_reports):
    """The loads Summary's consistency note quotes the Study 'parachute area' as the
    parachute decision table on the same sheet gives it (in US units 16.04 ft^2 beside
    16.00 ft^2 before: the SI text rounded to 1.49 m^2, then converted)."""
    for _, folder in (example_reports, us_twin_reports):
        book = next(folder.glob("*-loads.xlsx"))
        raw = pd.read_excel(book, sheet_name="Summary", header=None)
        cells = [str(v) for v in raw.to_numpy().ravel() if isinstance(v, str)]
        text = " ".join(cells)
        quoted = re.search(r"Study 'parachute area' \(([\d.,]+) (?:m|ft)\^2\)", text)
        row = raw[raw[0].astype(str).str.startswith("Study 'parachute area' (loads)")]
        if quoted is None or row.empty:
            continue
        assert _agrees(quoted.group(1), float(row.iloc[0, 1])), (book.name, quoted.group(0),
                                                                 row.iloc[0, 1])


# ----------------------------------------------------------------------------- lateral
def test_lateral_critical_case_is_the_one_the_runs_sheet_lists(example_reports,
                                                               us_twin_reports):
    """The case the lateral Summary (and the Findings sheet) names as producing the largest
    load angle is a row of the Runs results, whose largest angle over the ranges is the
    Summary's (before, the Summary named a variant run, 552 of 567, while the Runs sheet
    lists the 21 nominal cases with their maxima over the ranges)."""
    from hostile import report_table

    for _, folder in (example_reports, us_twin_reports):
        book = next(folder.glob("*-lateral.xlsx"))
        _, angle = report_table(book, "Summary", "Design angle of the hook load")
        items = angle.set_index("item")
        case = int(items.loc["case producing it", "value"])
        peak = float(items.loc["largest load angle |theta1 - theta2| over the stated ranges",
                               "value"])
        results = pd.read_excel(book, sheet_name="Runs-ResultsEveryCase")
        row = results[results["case"] == case]
        assert len(row) == 1, (book.name, case, list(results["case"]))
        assert float(row["max |theta1 - theta2| over the ranges [deg]"].iloc[0]) == \
            pytest.approx(peak, abs=0.05)
        findings = pd.read_excel(book, sheet_name="Findings")
        hook = findings[findings["question"].str.startswith("hook design angle")].iloc[0]
        assert f"case {case} on sheet Runs" in hook["source"], hook["source"]

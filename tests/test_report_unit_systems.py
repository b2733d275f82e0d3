"""One unit system per report: no text cell of any report of the example (SI) or of the
second example (the US twin, in US units and in SI) quotes a unit of the other system, and
a US report writes every length in inches and only altitudes in feet
(docs/reports.md, "One unit per quantity"). The reference is the cells as the file format
reads them back (openpyxl), against the unit table of the documentation, not the writer's
own conversion tables.

Names the user wrote (the multibody manoeuvres' names, the campaign's manoeuvre vocabulary
``gust +30 ft/s``) are printed as written and left out of the scan."""

from __future__ import annotations

import re
from pathlib import Path

import openpyxl
import pytest

#: Units of each system, as the reports spell them (docs/reports.md).
US_UNITS = r"(?:ft\^2|ft/s\^2|ft/s|ft|in|lbf in|lbf ft|lbf|lb in\^2|lb|slug ft\^2|slug/ft\^3|slug)"
SI_UNITS = r"(?:m\^2|m/s\^2|m/s|m|mm|km|kN m|kN|N m|N|kg m\^2|kg/m\^3|kg|Pa)"


def _quoted(units):
    """A unit quoted after a number (``60 ft``), in a header's brackets (``[ft]``) or alone
    in a cell (a ``unit`` column)."""
    return re.compile(rf"(?:\d\s?{units}(?![\w^/])|\[{units}\]|^{units}$)")


FOREIGN = {"SI": _quoted(US_UNITS), "US": _quoted(SI_UNITS)}
#: A length in feet: quoted after a number or in a header; an altitude is the one quantity
#: a US report writes in ft (its word before it, or after it: "0 ft density altitude").
FEET = re.compile(r"(?P<before>[\w ]{0,30}?)(?:\d\s?ft|\[ft\])(?![\w^/])"
                  r"(?P<after> density altitude)?")


def _user_names(book):
    """Names the user wrote that a report prints as written: the multibody manoeuvres' names
    and the campaign's manoeuvre vocabulary."""
    from slingloads.analyses.campaign.matrix import MANOEUVRES

    names = set(MANOEUVRES)
    wb = openpyxl.load_workbook(book, read_only=True)
    if "MultibodyManoeuvres" in wb.sheetnames:
        rows = wb["MultibodyManoeuvres"].iter_rows(values_only=True)
        header = [str(h).split(" [")[0] for h in next(rows)]
        if "name" in header:
            k = header.index("name")
            names |= {str(r[k]) for r in rows if r[k]}
    return sorted(names, key=len, reverse=True)


def _texts(folder):
    """(workbook, sheet, text) of every text cell of every report in ``folder``."""
    books = sorted(folder.glob("*.xlsx"))
    assert len(books) >= 4, books
    for book in books:
        wb = openpyxl.load_workbook(book, read_only=True)
        for ws in wb.worksheets:
            for row in ws.iter_rows(values_only=True):
                for value in row:
                    if isinstance(value, str):
                        yield book.name, ws.title, value


def _faults(units, folder, source):
    names = _user_names(source)
    faults = []
    for book, sheet, text in _texts(folder):
        for name in names:
            text = text.replace(name, "<name>")
        match = FOREIGN[units].search(text)
        if match:
            faults.append((book, sheet, match.group(0), text[:120]))
        if units == "US":
            for feet in FEET.finditer(text):
                if "altitude" not in feet.group("before") and not feet.group("after"):
                    faults.append((book, sheet, "a length in ft", text[:120]))
    return faults


def test_the_examples_si_reports_quote_no_us_unit(example_run_report):
    """The example's reports (SI): no ft, in, lb, lbf, slug in any text cell (a rope length
    in metres alone, never in feet beside them)."""
    from hostile import EXAMPLE

    assert not _faults("SI", example_run_report, EXAMPLE)


def test_the_us_twins_reports_keep_their_unit_system(us_twin_reports):
    """The second example's reports in US units (no m, N, kg, Pa; every length in in, only
    density altitudes in ft: the campaign's cable 60 ft is ``720 in`` as the multibody
    report's cable) and in SI (the campaign's conditions, decision and plots' matrix in m:
    no ``density altitude 0 ft, cable 60 ft``)."""
    from conftest import US_TWIN

    units, folder = us_twin_reports
    assert not _faults(units, folder, US_TWIN)
    texts = [t for _, _, t in _texts(folder) if "KEAS, mass case" in t]
    assert texts  # the campaign's governing condition, quoted on the Summaries
    cable = "cable 720 in" if units == "US" else "cable 18.288 m"
    assert all(cable in t for t in texts), texts[:2]


@pytest.mark.parametrize("units, cable, altitude", [("US", "720 in", "5,000 ft"),
                                                     ("SI", "18.288 m", "1,524 m")])
def test_one_spelling_per_quantity(units, cable, altitude):
    """The helper every title uses: 60 ft = 18.288 m = 720 in exactly (1 ft = 0.3048 m);
    5000 ft = 1524 m exactly, an altitude to the whole unit."""
    from slingloads.io.common.report import quantity_text

    assert quantity_text(60 * 0.3048, "length", units) == cable
    assert quantity_text(5000 * 0.3048, "altitude", units) == altitude


_QUOTED_AREA = re.compile(r"(?<![\w.^/])(-?\d[\d,]*(?:\.(\d+))?) (m\^2|ft\^2)(?![\w^/])")


def _quoted_areas(folder):
    """(workbook, sheet, text, decimals, unit) of every area quoted in a text cell."""
    found = []
    for path in sorted(Path(folder).glob("*.xlsx")):
        book = openpyxl.load_workbook(path, read_only=True)
        for sheet in book.worksheets:
            for row in sheet.iter_rows(values_only=True):
                for value in row:
                    if isinstance(value, str):
                        found += [(path.name, sheet.title, value, len(m.group(2) or ""),
                                   m.group(3)) for m in _QUOTED_AREA.finditer(value)]
        book.close()
    return found


def test_areas_quoted_in_sentences_read_as_their_cells(example_campaign_run_report,
                                                        us_twin_reports):
    """An area quoted in a sentence (a note, a verdict, the decision's basis) is written at the
    precision of an area's cell (formats.py: 0.000 m^2, 0.00 ft^2), in every report of the
    example with its campaign and of the US twin in both unit systems: the decision's 'fit
    0.1486 m^2' beside a cell of 0.149, or '27.18 ft^2' beside 27.17, cannot recur."""
    units, twin = us_twin_reports
    for folder, system in ((example_campaign_run_report, "SI"), (twin, units)):
        areas = _quoted_areas(folder)
        assert areas, folder
        wrong = [a for a in areas if a[3] != {"m^2": 3, "ft^2": 2}[a[4]]
                 or a[4] != {"SI": "m^2", "US": "ft^2"}[system]]
        assert not wrong, wrong[:5]


#: A number quoted before "deg" in a sentence, a note or a column label.
_QUOTED_ANGLE = re.compile(r"(?<![\w.^/])([+-]?\d+(?:\.\d+)?) ?deg\b")


def _design_angles(folder):
    """The angles a checker follows from report to report, as the cells hold them (to the
    last bit): the Findings' hook design angle, and the lateral study's largest load angle
    (its Summary)."""
    import pandas as pd

    loads = next(Path(folder).glob("*-loads.xlsx"))
    findings = pd.read_excel(loads, sheet_name="Findings", header=None)
    row = findings[findings[0].astype(str).str.startswith("hook design angle")].iloc[0]
    angles = {"hook design angle": float(row[2])}
    lateral = next(Path(folder).glob("*-lateral.xlsx"), None)
    if lateral is not None:
        summary = pd.read_excel(lateral, sheet_name="Summary", header=None)
        hit = summary[summary[0].astype(str).str.startswith("largest load angle |theta1 - "
                                                            "theta2| over the")]
        angles["largest load angle"] = float(hit.iloc[0, 1])
    return angles


def test_design_angles_quoted_as_their_cells(example_campaign_run_report, us_twin_reports):
    """The hook design angle and the lateral study's largest load angle, wherever a report
    quotes them in words (the hook directions' note, a load case's description, a column
    label of the hook cases, the Findings' source), read as their cells (0.1 deg, formats.py
    'deg'), in every report of the example with its campaign and of the US twin: the
    example's 33.2 deg in the cells, '33.24 deg' in the note beside them and '33.2361 deg' in
    the load cases' descriptions cannot recur. Reference: the cell values read back; a
    quoted number within 0.05 deg of an angle but written with more than one decimal is the
    same angle at another precision."""
    _, twin = us_twin_reports
    for folder in (example_campaign_run_report, twin):
        angles = _design_angles(folder)
        wrong = []
        for book, sheet, text in _texts(folder):
            for match in _QUOTED_ANGLE.finditer(text):
                number = match.group(1)
                decimals = len(number.partition(".")[2])
                for name, value in angles.items():
                    if decimals > 1 and abs(float(number) - value) < 0.05:
                        wrong.append((book, sheet, name, number, text[:100]))
        assert not wrong, wrong[:5]


def test_altitude_columns_to_the_whole_unit(example_campaign_run_report, us_twin_reports):
    """Every column of every report whose header names an altitude (the campaign's matrix,
    its stability map, the sweeps) writes it to the whole metre or foot, as every sentence
    quotes it (docs/reports.md: an altitude to the whole unit): no 'density altitude 0.000'
    in m nor '0.00' in ft beside 'density altitude 0 m' on the same page. Reference: the
    cells' number formats as the file format reads them back (openpyxl)."""
    _, twin = us_twin_reports
    checked, wrong = 0, []
    for folder in (example_campaign_run_report, twin):
        for path in sorted(Path(folder).glob("*.xlsx")):
            book = openpyxl.load_workbook(path, read_only=True)
            for sheet in book.worksheets:
                rows = list(sheet.iter_rows())
                for i, row in enumerate(rows):
                    for j, cell in enumerate(row):
                        text = cell.value
                        if not (isinstance(text, str) and re.search(r"altitude \[(m|ft)\]$",
                                                                    text)):
                            continue
                        for below in rows[i + 1:]:
                            value = below[j].value if j < len(below) else None
                            if not isinstance(value, (int, float)) or isinstance(value, bool):
                                break
                            checked += 1
                            if below[j].number_format not in ("#,##0", "0"):
                                wrong.append((path.name, sheet.title, text,
                                              below[j].number_format))
            book.close()
    assert checked > 10
    assert not wrong, wrong[:5]


_QUOTED_CABLE = re.compile(r"\bcable (?:length )?(\d[\d,]*(?:\.\d+)?) (m|in)(?![\w^/])")


def test_cable_lengths_quoted_as_their_cells(example_campaign_run_report, us_twin_reports):
    """The carrier cable quoted in a sentence (the campaign's conditions, its Summary's list,
    the cable checks) is the number of the campaign matrix's cable-length cells at their
    precision (formats.py: 0.000 m, 0.00 in; trailing zeros dropped), in every report of
    both examples: the example's 60 ft = 18.288 m exactly, never '18.29 m' beside a cell of
    18.288. Reference: the Matrix sheet's cells read back."""
    import pandas as pd

    _, twin = us_twin_reports
    for folder in (example_campaign_run_report, twin):
        campaign = next(Path(folder).glob("*-campaign.xlsx"))
        matrix = pd.read_excel(campaign, sheet_name="Matrix", header=None)
        head = matrix[matrix[0] == "run"].index[0]
        columns = [str(c) for c in matrix.iloc[head]]
        j = next(k for k, c in enumerate(columns) if c.startswith("cable length ["))
        unit = columns[j].split("[")[1].rstrip("]")
        decimals = {"m": 3, "in": 2}[unit]
        cells = {round(float(v), decimals) for v in matrix.iloc[head + 1:, j].dropna()}
        quoted = [(book, sheet, m.group(1), m.group(2), text[:80])
                  for book, sheet, text in _texts(folder)
                  for m in _QUOTED_CABLE.finditer(text)]
        assert quoted
        wrong = [q for q in quoted if q[3] != unit
                 or float(q[2].replace(",", "")) not in cells]
        assert not wrong, (cells, wrong[:5])
        summary = pd.read_excel(campaign, sheet_name="Summary", header=None)
        listed = summary[summary[0] == "cable lengths"].iloc[0, 1]
        assert {float(v) for v in str(listed).split(", ")} == cells


def test_campaign_definition_lists_its_matrix_cells(example_campaign_run_report,
                                                    us_twin_reports):
    """The campaign Summary's definition lists the matrix's area factors and masses as the
    Matrix sheet's cells read (0.000 for a factor, 0.0 for a mass; trailing zeros of a
    factor dropped), in both examples: the US twin's added sizing factor reads '1.5', never
    the float '1.4999999999999996', and its mass '10,802.9' lb as its cells, not '10803'."""
    import pandas as pd

    _, twin = us_twin_reports
    for folder in (example_campaign_run_report, twin):
        campaign = next(Path(folder).glob("*-campaign.xlsx"))
        matrix = pd.read_excel(campaign, sheet_name="Matrix", header=None)
        head = matrix[matrix[0] == "run"].index[0]
        table = matrix.iloc[head + 1:].set_axis([str(c) for c in matrix.iloc[head]], axis=1)
        mass = next(c for c in table.columns if c.startswith("mass ["))
        summary = pd.read_excel(campaign, sheet_name="Summary", header=None)
        item = dict(zip(summary[0], summary[1], strict=False))
        factors = [float(v) for v in str(item["area factors"]).split(", ")]
        assert factors == list(dict.fromkeys(round(float(v), 3)
                                             for v in table["area factor [-]"]))
        assert all(len(str(v).partition(".")[2]) <= 3
                   for v in str(item["area factors"]).split(", "))
        masses = {float(m.replace(",", "")) for m in
                  re.findall(r"(\d[\d,]*\.\d)", str(item["mass cases"]))}
        assert masses == {round(float(v), 1) for v in table[mass]}


#: A damping ratio quoted in words: a mode's "zeta 0.069", the decision's "1-DOF 0.160 (its
#: yaw mode", "multibody 0.069 (least over", the selection's "yaw-mode damping 0.069".
_QUOTED_RATIO = re.compile(r"(?:zeta|1-DOF|multibody|yaw-mode damping) (-?\d+\.(\d+))"
                           r"(?= \(|,|\)| )")


def test_damping_ratios_quoted_as_their_cells(example_campaign_run_report, us_twin_reports):
    """A damping ratio quoted in a verdict, a check or the parachute decision is written at
    the precision of a ratio's cell (formats.py '-': 0.000), in every report of both
    examples: the example's 'zeta 0.0691' and 'multibody 0.0691' beside cells of 0.069, and
    '1-DOF 0.16' beside 0.160, cannot recur."""
    _, twin = us_twin_reports
    for folder in (example_campaign_run_report, twin):
        found = [(book, sheet, m.group(1), text[:90]) for book, sheet, text in _texts(folder)
                 for m in _QUOTED_RATIO.finditer(text)]
        assert found, folder
        wrong = [f for f in found if len(f[2].partition(".")[2]) != 3]
        assert not wrong, wrong[:5]


#: A mode's period quoted in words: the mode a response was measured on "(27.02 s, zeta",
#: the inconclusive verdict's "slowest relevant mode (44.82 s)", a check's "nearest: yaw,
#: 14.60 s".
_QUOTED_PERIOD = re.compile(r"(?:\(|relevant mode \(|nearest: [^,]+, )(\d+\.?(\d*)) s(?:,|\))")


def test_mode_periods_quoted_as_their_cells(example_campaign_run_report, us_twin_reports):
    """A mode's period quoted in a verdict or a check is written at the precision of a
    time's cell (formats.py 's': 0.00), in every report of both examples: the yaw mode's
    'yaw / lateral swing (27 s, zeta 0.289)' beside a 'yaw mode period [s]' cell of 27.02,
    and '(44.8 s)' beside 44.82, cannot recur."""
    _, twin = us_twin_reports
    for folder in (example_campaign_run_report, twin):
        found = [(book, sheet, m.group(1), text[:90]) for book, sheet, text in _texts(folder)
                 for m in _QUOTED_PERIOD.finditer(text)]
        assert found, folder
        wrong = [f for f in found if len(f[2].partition(".")[2]) != 2]
        assert not wrong, wrong[:5]

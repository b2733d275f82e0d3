"""Property-based fuzzing of the workbook reader: whatever a workbook holds, reading it ends in a
study or in an InputError that says where (file, sheet, and the cell or row at fault).

The reference is the contract of docs/inputs-and-outputs.md ("every validation error is
located"; "no traceback, ever"): random cell values (numbers of every size, NaN, infinities,
text, formulas, dates, spreadsheet errors, control characters), headers, units, Study
parameters and sheet edits are applied to a small valid workbook (tests/hostile.py), built in
memory. Hypothesis runs derandomized, so each CI run tries the same 1,000+ examples; a failure
prints the edits that produced it.
"""

from __future__ import annotations

import datetime as dt

import pytest
from hostile import copy_book, save_xlsx, small_dynamics_workbook, small_workbook
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.analyses import all_parameters, all_sheets
from slingloads.io.common.workbook import WorkbookReader
from slingloads.io.common.xlsx_source import CellError
from slingloads.io.study import read_study

BASE = small_workbook()
#: The same airframe asking for the multibody model and the campaign (their Study rows and
#: sheets: MultibodyManoeuvres, HTailAero, CampaignMasses, CampaignRuns).
DYNAMICS = small_dynamics_workbook()
FILE = "fuzz.xlsx"
#: Rules about a whole sheet or file may name no cell.
SHEET_LEVEL = ("missing sheet", "needs the", "needs a", "no data rows", "no header",
               "needs at least", "asks for no", "is given but no")

UNITS = ["m", "in", "ft", "kg", "lb", "N", "lbf", "deg", "rad", "s", "kt", "m/s", "m^2",
         "kg m^2", "slug*ft^2", "g0", "-", "", "%", "kg/0", "kt/0", "kg**0", "1e999 kg",
         "degC", "percent**1000", "(" * 50 + "m" + ")" * 50, "m" * 80, "nan", "inf*m",
         "=1+1", "N*m", "lbf*in", "mm", "km", "light_year", "m/s^2"]
TEXTS = ["=cmd|' /C calc'!A0", "+1", "-1", "@SUM(A1)", "\tx", "yes", "no", "AXIAL", "AZ090",
         "NONE", "C", "hub", "mast_foot", "chute", "smooth step", "time history", "H1",
         "history.csv", "../../etc/passwd.csv", "/dev/zero", "x" * 5000, "FS$1$", "\x01bad",
         "  ", "1e300", "-1e300", "nan", "inf", "0x10", "1,5", "12 kg", "#DIV/0!", "S 2",
         "s_2", "relative wind", "rk4", "solve_ivp", "table", "model", "rigid", "elastic"]

#: Valid-looking choices of the text parameters (they open the less travelled paths).
CHOICES = ["given", "mast vertical", "hanging", "body", "stability", "wind", "canopy",
           "elliptical", "lateral directions", "parameter", "mass items", "fuselage axis",
           "relative wind", "RK23", "Radau", "BDF", "LSODA", "DOP853", "table", "model",
           "elastic", "rigid", "solve_ivp", "rk4", "step", "finite, continuous", "1-cosine",
           "S1, S4", "Vx-My, Mz-Vz", "", "listed rows", "full tail", "without parachute",
           "quasi-static", "sheet", "free", "frozen, free", "dynamics", "wind ramp",
           "forward acceleration", "gust", "acceleration, gust -30 ft/s", "HC1", "none",
           "1.0, 2.0, 1e300", "60, -80", "0, 1e9", "tcp://127.0.0.1:1", "x" * 300,
           ",".join(["1"] * 60)]
TEXT_PARAMETERS = sorted(n for n, p in all_parameters().items() if p.kind == "text")
numbers = st.one_of(
    st.integers(min_value=-10**30, max_value=10**30),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, -0.0, 1e300, -1e300, 1e-300, 5e-324, 95, 90, 360, 361, 1e6, 1e7,
                     0.001, 1e-9, 2**63, 10**400]),
)
values = st.one_of(
    st.none(), numbers, st.booleans(), st.sampled_from(TEXTS),
    st.text(max_size=12),
    st.sampled_from([dt.datetime(2024, 1, 2), dt.date(2024, 1, 2), dt.time(12, 0),
                     dt.timedelta(days=1), CellError("#DIV/0!"), CellError("#N/A")]),
)
#: Factors on a number of the base workbook: sign flips, zero, round-off, overflow.
factors = st.one_of(st.sampled_from([-1.0, 0.0, 1e-300, 1e-9, 0.5, 1.0000001, 2.0, 10.0, 1e3,
                                     1e6, 1e300, -1e300]),
                    st.floats(min_value=-1e3, max_value=1e3, allow_nan=False))
parameter_names = st.sampled_from(sorted(all_parameters()) + ["no such parameter", "", "  "])


def _header(draw, base_name):
    unit = draw(st.sampled_from(UNITS))
    return draw(st.sampled_from([f"{base_name} [{unit}]", base_name, f"{base_name}[{unit}",
                                 f"{base_name} [{unit}] [m]", base_name.upper(), ""]))


@st.composite
def edits(draw, base=BASE):
    """A list of edits (kind, arguments) to apply to the base workbook ``base``."""
    sheet_names = st.sampled_from(sorted(base))
    out = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["cell", "cell", "scale", "scale", "scale", "header",
                                     "parameter", "parameter", "scale parameter",
                                     "scale parameter", "choice", "choice", "drop sheet",
                                     "drop row", "copy row", "add row", "empty sheet",
                                     "drop column"]))
        sheet = draw(sheet_names)
        rows = base[sheet]
        width = max(len(r) for r in rows)
        if kind == "cell":
            out.append((kind, sheet, draw(st.integers(0, len(rows))),
                        draw(st.integers(0, width)), draw(values)))
        elif kind == "scale":
            out.append((kind, sheet, draw(st.integers(1, len(rows) - 1)),
                        draw(st.integers(0, width - 1)), draw(factors)))
        elif kind == "choice":
            out.append(("parameter", draw(st.sampled_from(TEXT_PARAMETERS)),
                        draw(st.sampled_from(CHOICES)), None))
        elif kind == "drop column":
            out.append((kind, sheet, draw(st.integers(0, width - 1))))
        elif kind == "scale parameter":
            out.append((kind, draw(st.integers(1, len(base["Study"]) - 1)), draw(factors)))
        elif kind == "header":
            col = draw(st.integers(0, width - 1))
            name = str(rows[0][col]).split("[")[0].strip()
            out.append((kind, sheet, col, _header(draw, name)))
        elif kind == "parameter":
            out.append((kind, draw(parameter_names), draw(values),
                        draw(st.one_of(st.none(), st.sampled_from(UNITS)))))
        elif kind in ("drop row", "copy row"):
            out.append((kind, sheet, draw(st.integers(0, len(rows) - 1))))
        elif kind == "add row":
            out.append((kind, sheet, draw(st.lists(values, max_size=width + 1))))
        else:
            out.append((kind, sheet))
    return out


def apply(edit_list, base=BASE):
    book = copy_book(base)
    for edit in edit_list:
        kind, *args = edit
        if kind == "scale parameter":
            r, factor = args
            rows = book.get("Study", [])
            if r < len(rows) and len(rows[r]) > 1:
                rows[r][1] = _scaled(rows[r][1], factor)
            continue
        if kind == "parameter":
            name, value, unit = args
            if "Study" not in book:
                continue
            study = book["Study"]
            for row in study[1:]:
                if row[:1] == [name]:
                    row.extend([None] * (3 - len(row)))
                    row[1], row[2] = value, unit
                    break
            else:
                study.append([name, value, unit])
            continue
        sheet = args[0]
        if sheet not in book:
            continue
        rows = book[sheet]
        if kind == "cell":
            r, c, value = args[1:]
            while len(rows) <= r:
                rows.append([])
            while len(rows[r]) <= c:
                rows[r].append(None)
            rows[r][c] = value
        elif kind == "scale":
            r, c, factor = args[1:]
            if r < len(rows) and c < len(rows[r]):
                rows[r][c] = _scaled(rows[r][c], factor)
        elif kind == "header" and rows:
            col, text = args[1:]
            if col < len(rows[0]):
                rows[0][col] = text
        elif kind == "drop sheet":
            del book[sheet]
        elif kind == "drop column":
            for row in rows:
                if args[1] < len(row):
                    del row[args[1]]
        elif kind == "empty sheet":
            book[sheet] = []
        elif kind == "drop row" and args[1] < len(rows):
            del rows[args[1]]
        elif kind == "copy row" and args[1] < len(rows):
            rows.append(list(rows[args[1]]))
        elif kind == "add row":
            rows.append(list(args[1]))
    return book


def _scaled(value, factor):
    """A number scaled by ``factor`` (a zero becomes ``factor``); other values unchanged."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return value
    return value * factor if value else factor


def check_outcome(book, path=FILE, reader=None):
    """Read ``book``: a study, or an InputError located in the file (sheet and cell)."""
    reader = reader if reader is not None else WorkbookReader.from_rows(book, file=path)
    try:
        study = read_study(path, reader=reader)
    except InputError as err:
        message = str(err)
        assert err.file == str(path), message
        if not any(s in err.rule for s in SHEET_LEVEL):
            assert err.sheet, message
            assert err.cell, message
        assert len(message) < 3000, message[:300]
        return err
    assert study.airframe is not None
    return study


SETTINGS = settings(max_examples=600, derandomize=True, deadline=None, database=None,
                    suppress_health_check=list(HealthCheck), print_blob=True)


@pytest.mark.filterwarnings("error::RuntimeWarning")
@SETTINGS
@given(edits())
def test_reader_ends_in_a_study_or_a_located_error(edit_list):
    """600 random edits of the small workbook (cells, headers, units, Study parameters,
    rows and sheets): reading gives a study or an InputError naming file, sheet and cell,
    and no numerical warning (an overflow would be a silent infinity or NaN)."""
    check_outcome(apply(edit_list))


@pytest.mark.filterwarnings("error::RuntimeWarning")
@settings(max_examples=300, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck), print_blob=True)
@given(edits(DYNAMICS))
def test_dynamics_reader_ends_in_a_study_or_a_located_error(edit_list):
    """300 random edits of the workbook of the multibody model and the campaign (their Study
    rows, the comma-separated lists with their units, MultibodyManoeuvres, HTailAero,
    CampaignMasses, CampaignRuns): a study or an InputError naming file, sheet and cell."""
    check_outcome(apply(edit_list, DYNAMICS))


def test_the_dynamics_base_workbook_is_valid():
    """The second fuzzing base reads without error and asks for both dynamics analyses."""
    study = check_outcome(copy_book(DYNAMICS))
    assert set(study.inputs.given()) == {"multibody", "campaign"}


def test_the_base_workbook_is_valid():
    """The fuzzing starts from a workbook that reads without error (else every example would
    only test one error)."""
    study = check_outcome(copy_book(BASE))
    assert set(study.inputs.given()) == {"loads", "lateral", "chute sizing"}


@settings(max_examples=40, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck))
@given(edits())
def test_xlsx_files_end_in_a_study_or_a_located_error(tmp_path_factory, edit_list):
    """The same through real .xlsx files (openpyxl's value types, the streaming parser)."""
    path = tmp_path_factory.mktemp("fuzz") / "fuzz.xlsx"
    book = apply(edit_list)
    try:
        save_xlsx(book, path)
    except Exception:  # noqa: BLE001 - openpyxl cannot store some edits (control characters)
        return
    check_outcome(book, path, WorkbookReader(path))


@pytest.mark.parametrize("seed", range(3))
def test_cli_never_shows_a_traceback(tmp_path, capsys, seed):
    """A few edited workbooks through the command line: exit 0, 3 (a finding, the reports
    written) or 2 with a located message, never a traceback, and nothing written on
    failure."""
    import random

    rng = random.Random(seed)
    book = copy_book(BASE)
    parameters = sorted(all_parameters())
    for _ in range(2):
        row = rng.choice(book["Study"][1:])
        row[1] = rng.choice([0, -1, 1e300, "x", 95, 1e7, None])
    path = save_xlsx(book, tmp_path / "cli.xlsx")
    out = tmp_path / "out"
    code = main(["run", str(path), "--out", str(out), "--quiet"])
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert code in (0, 2, 3), err
    if code == 2:
        assert f"file {path}" in err and "nothing was written" in err
        assert not out.exists()
    assert parameters and all_sheets()

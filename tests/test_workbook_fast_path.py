"""The workbook reader's shortcuts give exactly what its careful path gives.

Two shortcuts make reading a large table fast (slingloads/io/common/xlsx_source.py and
workbook.py):

* ``_simple_cell`` reads a plain number or an inline string without openpyxl's
  ``parse_cell``. The reference is ``parse_cell`` itself (openpyxl's read-only reader): for
  every cell the shortcut accepts, the column, the value (its type, and its bits for a float)
  and the column counter must be those ``parse_cell`` gives; any other cell is left to it.
* ``WorkbookReader._columns_at_once`` checks and converts a whole column of plain numbers at
  once. The reference is the cell-by-cell path ``WorkbookReader._records`` (the reader as it
  was before the shortcut): the same SI values bit for bit, the same values as written and
  cells, and, when a cell breaks a rule, the same located error (file, sheet, cell, value as
  written, unit, rule) at the first bad cell in the order of the sheet.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import math
import struct
from unittest import mock
from xml.etree.ElementTree import fromstring

import numpy as np
import pytest
from hostile import EXAMPLE
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from openpyxl.worksheet._reader import WorkSheetParser

from slingloads.errors import ErrorCollector, InputError
from slingloads.io.airframe.schema import SHEETS
from slingloads.io.common.schema import FLAG, INTEGER, TEXT, Bounds, Column, TableSheet
from slingloads.io.common.workbook import WorkbookReader
from slingloads.io.common.xlsx_source import CellError, _simple_cell

SETTINGS = settings(max_examples=600, derandomize=True, deadline=None, database=None,
                    suppress_health_check=list(HealthCheck))
NS = "http://schemas.openxmlformats.org/spreadsheetml/2006/main"

# ---- one cell: _simple_cell against openpyxl's parse_cell ---------------------------------
#: Style 1 is a date format, style 2 a duration (openpyxl's date and timedelta formats).
DATE_STYLES, DURATION_STYLES = {1, 2}, {2}
SHARED = ["shared zero", "1.5"]
TEXTS = ["0", "1", "-0", "-12", "0.25", "1.5e3", "1E-3", "-2.5E+300", "1e999", "-1e999",
         "nan", "inf", " 7 ", "7 ", "1_000", "0x10", "1.2.3", "", "abc", "\u0661", "1" * 5000,
         "12345678901234567890", "4.9e-324", "1e-400", "#N/A", "TRUE", "2024-01-02T00:00:00",
         "&amp;", "a&lt;b", "&#9;x"]
types = st.sampled_from([None, "n", "s", "str", "b", "e", "d", "inlineStr", "x", ""])
styles = st.sampled_from([None, "", "0", "1", "2", "3", " 3", "zz", "-1"])
coordinates = st.sampled_from([None, "C7", "A7", "AB7", "XFD7", "ZZZ7", "c7", "C07", "C8", "C",
                               "7", "AAAA7", "C7x", "", "$C$7", "C-7", "C17", "AC7", "C\u0667"])
texts = st.one_of(st.sampled_from(TEXTS), st.text(alphabet="0123456789.eE+- x", max_size=8),
                  st.floats().map(repr), st.integers().map(str))


@st.composite
def children(draw):
    """The inside of a ``<c>`` element: a value, a formula, an inline string, or odd parts."""
    text = draw(texts)
    return draw(st.sampled_from([
        f"<v>{text}</v>", f"<is><t>{text}</t></is>", "<v/>", f"<f>A1*2</f><v>{text}</v>",
        "<f>A1*2</f>", f"<v>{text}</v><f>1</f>", f"<v>{text}</v><v>5</v>", "<is><t/></is>",
        "<is/>", f'<is x="1"><t>{text}</t></is>', f"<is><r><t>{text}</t></r></is>",
        f"<is><t>{text}</t><r><t>b</t></r></is>", f"<is><t>{text}<b/></t></is>",
        f'<is><o:t xmlns:o="urn:other">{text}</o:t></is>',
        f'<is><t xml:space="preserve"> {text} </t></is>', f"<v>{text}<b/></v>",
        f'<o:v xmlns:o="urn:other">{text}</o:v>', "<extLst/>", f"<v>{text}</v><extLst/>"]))


@st.composite
def table_cells(draw):
    """``(t, s, r, inside)`` of a cell as tables hold them: a number or an inline string."""
    t = draw(st.sampled_from([None, "n", "inlineStr"]))
    inside = f"<is><t>{draw(texts)}</t></is>" if t == "inlineStr" else f"<v>{draw(texts)}</v>"
    return (t, draw(st.sampled_from([None, "0", "1", "3"])),
            draw(st.sampled_from([None, "C7", "AB7", "XFD7"])), inside)


@st.composite
def near_table_cells(draw):
    """A cell as tables hold them with one of its type, style, coordinate or content changed
    to anything (each condition of the shortcut is tested on its own)."""
    cell = list(draw(table_cells()))
    which = draw(st.integers(0, 3))
    cell[which] = draw([types, styles, coordinates, children()][which])
    return tuple(cell)


#: Cells as tables hold them, cells one change away, and cells of any kind.
cells = st.one_of(table_cells(), near_table_cells(),
                  st.tuples(types, styles, coordinates, children()))


def _cell_element(t, s, r, inside):
    attributes = "".join(f' {name}="{value}"' for name, value in (("r", r), ("s", s), ("t", t))
                         if value is not None)
    return fromstring(f'<c xmlns="{NS}"{attributes}>{inside}</c>')


def _parser():
    parser = WorkSheetParser(None, SHARED, data_only=True, date_formats=DATE_STYLES,
                             timedelta_formats=DURATION_STYLES)
    parser.row_counter, parser.col_counter = 7, 2
    return parser


def _same(a, b):
    """Equal values of the same type; floats bit for bit (so -0.0 is not 0.0, NaN is NaN)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return struct.pack("<d", a) == struct.pack("<d", b)
    return a == b


def _simple(element):
    """The shortcut's ``(column, value)`` of a cell of row 7 after column 2, or None."""
    return _simple_cell(element, 2, "7", -1, {}, DATE_STYLES)


@SETTINGS
@given(cells)
def test_simple_cells_read_as_parse_cell(cell):
    """Every cell the shortcut reads is read alike by openpyxl's parse_cell: same column, same
    value and type (floats bit for bit), the column counter at that column, and the cell lies
    in its row."""
    element = _cell_element(*cell)
    cell = _simple(element)
    if cell is None:
        return  # left to parse_cell
    parser = _parser()
    reference = parser.parse_cell(element)
    assert reference["row"] == 7
    assert reference["data_type"] in ("n", "s")
    assert reference["column"] == cell[0] == parser.col_counter
    assert _same(reference["value"], cell[1]), (reference["value"], cell[1])


@pytest.mark.parametrize("xml, expected", [
    ('<c r="C7" t="n"><v>0.25</v></c>', (3, 0.25)),
    ('<c r="C7"><v>-40</v></c>', (3, -40)),
    ('<c r="AB7" s="3" t="n"><v>1E-3</v></c>', (28, 0.001)),
    ("<c><v>5</v></c>", (3, 5)),
    ('<c r="A7" t="inlineStr"><is><t>alpha [deg]</t></is></c>', (1, "alpha [deg]")),
    ('<c r="A7" s="1" t="inlineStr"><is><t/></is></c>', (1, "")),
])
def test_the_cells_of_a_table_take_the_shortcut(xml, expected):
    """The cells openpyxl and Excel write for numbers and headers are read by the shortcut
    (else it would speed nothing up), with parse_cell's value."""
    element = fromstring(xml.replace("<c", f'<c xmlns="{NS}"', 1))
    cell = _simple(element)
    assert cell is not None and _same(cell[1], expected[1]) and cell[0] == expected[0]
    reference = _parser().parse_cell(element)
    assert (reference["column"], reference["value"]) == cell


@pytest.mark.parametrize("xml", [
    '<c r="C7" s="1"><v>45000</v></c>',  # a date by its number format
    '<c r="C7" s="2"><v>0.5</v></c>',  # a duration
    '<c r="C7" t="b"><v>1</v></c>', '<c r="C7" t="e"><v>#DIV/0!</v></c>',
    '<c r="C7" t="s"><v>0</v></c>', '<c r="C7" t="str"><v>x</v></c>',
    '<c r="C7"><f>A1*2</f><v>4</v></c>', '<c r="C7"><f>A1*2</f></c>',
    '<c r="C8"><v>1</v></c>', '<c r="c7"><v>1</v></c>', '<c r="C7" s="zz"><v>1</v></c>',
    '<c r="C7"><v>1.2.3</v></c>', '<c r="C7"><v/></c>',
    '<c r="C7" t="inlineStr"><is><r><t>a</t></r></is></c>',
    '<c r="C7" t="inlineStr"><is x="1"><t>a</t></is></c>', '<c r="C7" t="inlineStr"/>',
    '<c r="C7" t="inlineStr"><is><t>a</t><t>b</t></is></c>',
])
def test_other_cells_are_left_to_parse_cell(xml):
    """Dates and durations by number format, booleans, errors, shared strings, formulas, a
    cell outside its row, unusual coordinates, unreadable styles and values, rich text: all
    read by parse_cell (which converts them or raises)."""
    assert _simple(fromstring(xml.replace("<c", f'<c xmlns="{NS}"', 1))) is None


# ---- one table: _columns_at_once against _records ---------------------------------------
TABLE = TableSheet("Numbers", (
    Column("id", TEXT),
    Column("x", "length", "m", bounds=Bounds(-100, 100, unit="m")),
    Column("angle", "angle", "deg", bounds=Bounds(-90, 90, hi_open=True)),
    Column("mass", "mass", "kg", bounds=Bounds(0, lo_open=True)),
    Column("gain", "dimensionless", required=False, default=1.0, bounds=Bounds(nonzero=True)),
    Column("ratio", "dimensionless", required=False),
    Column("count", INTEGER, required=False, default=1, bounds=Bounds(1, 10)),
    Column("on", FLAG, required=False, default=False),
), max_rows=50)
HEADERS = {"id": ["id"], "x": ["x [m]", "x [in]", "x [mm]", "x [ft]"],
           "angle": ["angle [deg]", "angle [rad]"], "mass": ["mass [kg]", "mass [lb]"],
           "gain": ["gain", "gain [-]", "gain [%]"], "ratio": ["ratio"], "count": ["count"],
           "on": ["on"]}
#: Values within the bounds of each column in each of its units.
GOOD = {"x": st.one_of(st.integers(-80, 80), st.floats(-80, 80),
                       st.sampled_from([0, -0.0, 5e-324, -1e-300, 2**40 + 1])),
        "angle": st.one_of(st.integers(-1, 1), st.floats(-1.5, 1.5),
                           st.sampled_from([0, -0.0, 1e-300, 1.5707963])),
        "mass": st.one_of(st.integers(1, 1000), st.floats(1e-3, 1000),
                          st.sampled_from([1e-300, 1.0, 999.999999999])),
        "gain": st.one_of(st.none(), st.floats(0.5, 80), st.sampled_from([-1, 1, 2.5])),
        "ratio": st.one_of(st.none(), st.floats(-80, 80), st.sampled_from([0, -0.0])),
        "count": st.sampled_from([1, 2, 10, None]),
        "on": st.sampled_from(["yes", "no", None, True])}
bad = st.one_of(
    st.none(), st.booleans(), st.sampled_from(["1,5", " 2.5 ", "  ", "x", "nan", "-inf", "1e999",
                                               CellError("#DIV/0!"), dt.date(2024, 1, 2),
                                               dt.timedelta(1), np.float64(1.5), 10**400,
                                               2**63, float("nan"), float("inf"), 1e300, 95,
                                               -1e-9, 90, 100.0000001, 0]),
    st.floats(), st.integers())


@st.composite
def tables(draw):
    """``{sheet: rows}`` of a table of plain numbers with a few cells of any kind."""
    names = ["id", "x", "angle", "mass"] + draw(st.lists(
        st.sampled_from(["gain", "ratio", "count", "on"]), unique=True, max_size=4))
    header = [draw(st.sampled_from(HEADERS[n])) for n in names]
    n_rows = draw(st.integers(1, 12))
    rows = [header]
    for i in range(n_rows):
        rows.append([f"item {i}"] + [draw(GOOD[n]) for n in names[1:]])
    for _ in range(draw(st.sampled_from([0, 0, 1, 2]))):
        r, c = draw(st.integers(1, n_rows)), draw(st.integers(0, len(names)))
        value = draw(bad)
        if c == len(names):  # a value right of the table, under no header
            rows[r].append(value)
        else:
            rows[r][c] = value
    return {"Numbers": rows}


def _careful():
    """Read tables by the careful path only (the fast path finding nothing to read)."""
    return mock.patch.object(WorkbookReader, "_columns_at_once", return_value=None)


def _outcome(sheets, careful):
    """What reading the table gives: its columns (floats as bits) or its error's fields."""
    reader = WorkbookReader.from_rows(sheets, file="fast.xlsx")
    with _careful() if careful else contextlib.nullcontext():
        try:
            table = reader.table(TABLE)
        except InputError as err:
            return ("error", str(err), err.file, err.sheet, err.cell, repr(err.value), err.unit,
                    err.rule)
    values = {k: (v.dtype.str, v.tobytes()) if isinstance(v, np.ndarray)
              else [(type(x), x) for x in v] for k, v in table.values.items()}
    raw = {k: [(type(x), repr(x)) for x in v] for k, v in table.raw.items()}
    return ("table", values, raw, table.cells, table.units, table.sheet, table.file)


@pytest.mark.filterwarnings("error::RuntimeWarning")
@settings(SETTINGS, max_examples=300)
@given(tables())
def test_columns_at_once_give_what_the_cells_give(sheets):
    """A table of numbers in any unit with up to two cells of any kind (empty, text, comma
    decimal, boolean, date, error, NaN, infinity, overflow, out of bounds, a value without a
    header): the same values bit for bit, or the same located error, as cell by cell; and no
    numerical warning (an overflow to infinity is an error, never a warning)."""
    assert _outcome(sheets, careful=False) == _outcome(sheets, careful=True)


@pytest.fixture(scope="module")
def fuselage_rows():
    """The example's FuselageAero table as rows (3,078 rows x 8 columns)."""
    with WorkbookReader(EXAMPLE) as reader:
        rows = reader.rows("FuselageAero", 10**6)
    width = max(max(row) for _, row in rows)
    return [[row.get(c) for c in range(1, width + 1)] for _, row in rows]


FUSELAGE = {s.name: s for s in SHEETS}["FuselageAero"]


def _fuselage(rows, careful):
    reader = WorkbookReader.from_rows({"FuselageAero": rows}, file="example.xlsx")
    with _careful() if careful else contextlib.nullcontext():
        try:
            table = reader.table(FUSELAGE)
        except InputError as err:
            return str(err), err.cell
    return {k: v.tobytes() for k, v in table.values.items()}, table.cells


def test_the_example_table_reads_alike(fuselage_rows):
    """The example's FuselageAero sheet: the same SI values bit for bit and the same cells."""
    assert _fuselage(fuselage_rows, careful=False) == _fuselage(fuselage_rows, careful=True)


@pytest.mark.parametrize("seed", range(12))
def test_one_bad_cell_of_the_example_table_is_named_alike(fuselage_rows, seed):
    """One bad cell at a random place of the example's 3,078 x 8 table (text, comma decimal,
    boolean, date, error, NaN, overflow, an angle out of bounds, an empty cell): the error of
    the column-at-once path is the careful path's, at that cell."""
    import random

    rng = random.Random(seed)
    rows = [list(row) for row in fuselage_rows]
    r, c = rng.randrange(1, len(rows)), rng.randrange(0, len(rows[0]))
    value = rng.choice(["abc", "0,5", True, dt.datetime(2024, 1, 2), CellError("#N/A"),
                        float("nan"), 1e300, 10**400, 725 if c < 2 else "x", None])
    if value is None and rows[0][c] in ("CD", "CL"):
        value = " "  # an empty cell of these optional columns is no error: make it text
    rows[r][c] = value
    fast, careful = _fuselage(rows, careful=False), _fuselage(rows, careful=True)
    assert fast == careful
    message, cell = fast
    assert isinstance(message, str) and cell == f"{'ABCDEFGH'[c]}{r + 1}", message


def test_a_bad_cell_anywhere_is_found_by_the_fast_path():
    """The column-at-once path gives None for a table with a bad cell, whatever its column
    and row (the check of every column is complete, not a sample), and the careful path
    names that cell."""
    spec = TableSheet("Numbers", (TABLE.columns[1], TABLE.columns[3]))
    rows = [["x [m]", "mass [kg]"]] + [[float(i) - 100, 1.0 + i] for i in range(200)]
    for r, c, value in ((1, 0, 1e6), (200, 1, 0.0), (137, 0, math.inf), (5, 1, -1e-300),
                        (200, 0, 100.00000000000001)):
        edited = [list(row) for row in rows]
        edited[r][c] = value
        reader = WorkbookReader.from_rows({"Numbers": edited})
        header = dict(enumerate(edited[0], start=1))
        found, _ = reader._columns(spec, header, ErrorCollector())
        records = [(k, dict(enumerate(row, start=1))) for k, row in enumerate(edited, 1)][1:]
        assert reader._columns_at_once(spec, header, found, records) is None
        with pytest.raises(InputError) as info:
            reader._records(spec, header, found, records)
        assert info.value.cell == f"{'AB'[c]}{r + 1}"


def _typed(value):
    """A value with its type, floats by their bits."""
    return (type(value), struct.pack("<d", value) if isinstance(value, float) else value)


def _every_row(path):
    """Every row of every sheet of the .xlsx ``path``, values typed (floats by their bits)."""
    with WorkbookReader(path) as reader:
        return {name: [(r, [(c, _typed(v)) for c, v in row.items()])
                       for r, row in reader.rows(name, 10**6)]
                for name in reader.sheetnames}


def _without_the_cell_shortcut():
    """Every cell read by openpyxl's parse_cell (the reference)."""
    from slingloads.io.common import xlsx_source

    return mock.patch.object(xlsx_source, "_simple_cell", return_value=None)


def test_the_example_workbook_reads_alike_without_the_cell_shortcut():
    """Every sheet of the example workbook, read with the cell shortcut and with openpyxl's
    parse_cell alone (the reference): the same rows, columns and values (types, bits)."""
    fast = _every_row(EXAMPLE)
    with _without_the_cell_shortcut():
        reference = _every_row(EXAMPLE)
    assert fast == reference
    assert sum(len(rows) for rows in fast.values()) > 3000


def test_odd_cells_of_a_saved_workbook_read_alike_without_the_cell_shortcut(tmp_path):
    """Empty, blank and padded strings (inline and shared), numbers of every form, booleans,
    dates, durations, formulas and a spreadsheet error, saved by openpyxl: the same rows with
    and without the cell shortcut (blank cells are dropped, not kept as text)."""
    import openpyxl
    from hostile import save_xlsx

    values = ["", "  ", " x ", "\t", "1.5", 0, -0.0, 7, 2**60, 1e300, 5e-324, -1.25, True,
              dt.datetime(2024, 1, 2, 3, 4), dt.date(2024, 1, 2), dt.time(6), dt.timedelta(1.5),
              None, "=1+1", "#DIV/0!"]
    rows = [values[k:] + values[:k] for k in range(len(values))]
    inline = save_xlsx({"Inline": rows}, tmp_path / "inline.xlsx")
    book = openpyxl.Workbook()  # shared strings, formulas, date formats
    sheet = book.active
    sheet.title = "Shared"
    for row in rows:
        sheet.append(row)
    sheet["B2"].number_format = "0.00%"
    sheet["C3"].number_format = "yyyy-mm-dd"
    book.save(tmp_path / "shared.xlsx")
    for path in (inline, tmp_path / "shared.xlsx"):
        fast = _every_row(path)
        with _without_the_cell_shortcut():
            assert fast == _every_row(path)
        kept = [v for rows in fast.values() for _, row in rows for _, (_, v) in row]
        assert " x " in kept and not any(isinstance(v, str) and not v.strip() for v in kept)


def _first_repeat_reference(alpha, beta):
    """The first repeated (alpha, beta) row and its earlier row, by a dictionary (the check as
    it was written before it was vectorised)."""
    rows = {}
    for i, key in enumerate(zip(alpha.tolist(), beta.tolist(), strict=True)):
        if key in rows:
            return i, rows[key]
        rows[key] = i
    return None


@SETTINGS
@given(st.lists(st.tuples(st.sampled_from([0.0, -0.0, 1.0, -2.5, 1e-300, 5e-324, 40.0]),
                          st.sampled_from([0.0, -0.0, 3.0, -180.0, 180.0])), max_size=30))
def test_first_repeated_grid_point_is_found_as_by_a_dictionary(points):
    """The vectorised repeat check of FuselageAero names the same row, and the same earlier
    row, as a dictionary of the points seen (0.0 and -0.0 are one point)."""
    from slingloads.io.airframe.reader import _first_repeat

    alpha = np.array([p[0] for p in points], dtype=float)
    beta = np.array([p[1] for p in points], dtype=float)
    assert _first_repeat(alpha, beta) == _first_repeat_reference(alpha, beta)


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -float("inf"), 1e308, 10**400])
def test_a_kind_without_magnitude_limit_still_refuses_what_the_cells_refuse(value):
    """Were a kind given no magnitude limit, NaN and infinities would still be refused at their
    cell (the fast path checks finiteness itself), and huge finite numbers kept alike."""
    from slingloads.limits import MAX_MAGNITUDE

    rows = [["id", "x [m]", "angle [deg]", "mass [kg]", "ratio"]]
    rows += [[f"item {i}", 1.0, 0.5, 2.0, float(i)] for i in range(5)]
    rows[3][4] = value
    with mock.patch.dict(MAX_MAGNITUDE):
        del MAX_MAGNITUDE["dimensionless"]
        assert (_outcome({"Numbers": rows}, careful=False)
                == _outcome({"Numbers": rows}, careful=True))


@pytest.mark.parametrize("coordinate, rule, value", [
    ("XFE2", "a column beyond Excel's limit", 16385),  # read by the shortcut
    ("xfe2", "a column beyond Excel's limit", 16385),  # read by parse_cell
    ("B3", "a cell lies outside its row", "B3"),
    ("B2x", "unreadable cell", "B2x"),
])
def test_corrupt_coordinates_are_refused_as_before(tmp_path, coordinate, rule, value):
    """A cell beyond Excel's last column, outside its row or with an unreadable coordinate is
    refused with the sheet named, whichever reader reads it (the messages of the reader
    before the shortcuts)."""
    import zipfile

    from hostile import save_xlsx

    path = save_xlsx({"Numbers": [["x [m]", "mass [kg]"], [1.0, 2.0]]}, tmp_path / "a.xlsx")
    edited = tmp_path / "corrupt.xlsx"
    with zipfile.ZipFile(path) as zin, zipfile.ZipFile(edited, "w") as zout:
        for name in zin.namelist():
            data = zin.read(name)
            if name == "xl/worksheets/sheet1.xml":
                data = data.replace(b'r="B2"', f'r="{coordinate}"'.encode())
            zout.writestr(name, data)
    with WorkbookReader(edited) as reader, pytest.raises(InputError) as info:
        reader.rows("Numbers", 10)
    assert (info.value.sheet, info.value.value) == ("Numbers", value)
    assert rule in info.value.rule

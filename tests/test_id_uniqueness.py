"""One uniqueness rule for every id column of every sheet, enforced in one place.

The reference is the rule stated in :mod:`slingloads.ids` and docs/inputs-and-outputs.md:
ids are unique with case (and surrounding spaces) ignored, in every sheet alike. The test
walks the sheets of the blank template that ``slingloads template`` writes, takes each
sheet's header as written there, fills two rows and gives them the ids "Abc" and "ABC": the
workbook reader must refuse the second at its cell, saying case is ignored. Which columns are
ids is declared once, in the sheet's schema (``TableSheet.ids``); the walk checks that
declaration against the documented list, and that no other column of the template is named
like an id, so that a new id column cannot be left out.
"""

from __future__ import annotations

import openpyxl
import pytest

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.airframe.schema import SHEETS as AIRFRAME_SHEETS
from slingloads.io.analyses import ANALYSES
from slingloads.io.common.schema import FLAG, INTEGER, TEXT
from slingloads.io.common.table import cell_name
from slingloads.io.common.workbook import WorkbookReader

#: The id columns the documents list (slingloads.ids): loads cases and points, stations,
#: mass items, hardpoints, lateral motions and bodies, multibody manoeuvres, campaign mass
#: cases.
DOCUMENTED = {("MassItems", "id"), ("Stations", "id"), ("Hardpoints", "id"),
              ("AeroEnvelope", "id"), ("LoadCases", "id"), ("LateralMotions", "id"),
              ("LateralBodies", "id"), ("MultibodyManoeuvres", "name"),
              ("CampaignMasses", "mass case")}
#: Columns named like ids that are not: the history a LateralHistory row belongs to (a
#: history has many rows) and the mass case a listed campaign run refers to (many runs share
#: one).
NOT_IDS = {("LateralHistory", "history id"), ("CampaignRuns", "mass case")}


def _specs():
    return {s.name: s for s in (*AIRFRAME_SHEETS,
                                *(t for a in ANALYSES for t in a.modules().schema.SHEETS))}


def _cell_value(column):
    """A value the column accepts (its bounds' middle, or 1)."""
    if column.kind == TEXT:
        return "x"
    if column.kind == FLAG:
        return "yes"
    if column.kind == INTEGER:
        return 1
    b = column.bounds
    if b is None or b.contains(1.0):
        return 1.0
    lo = b.lo if b.lo is not None else (b.hi - 2.0)
    hi = b.hi if b.hi is not None else (b.lo + 2.0)
    return (lo + hi) / 2


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    path = tmp_path_factory.mktemp("template") / "template.xlsx"
    assert main(["template", str(path)]) == 0
    return path


def test_the_id_columns_are_those_documented(template):
    """The ids declared by the schemas are the documented ones, each a column of its sheet
    in the template, and no other template column is named 'id', 'name' or '... id'."""
    specs = _specs()
    declared = {(s.name, c) for s in specs.values() for c in s.ids}
    assert declared == DOCUMENTED
    book = openpyxl.load_workbook(template, read_only=True)
    named_like_ids = set()
    for name in book.sheetnames:
        if name not in specs:
            continue
        header = [str(c.value).split(" [")[0] for c in next(book[name].iter_rows(max_row=1))
                  if c.value is not None]
        named_like_ids |= {(name, h) for h in header
                           if h in ("id", "name") or h.endswith(" id") or h == "mass case"}
    book.close()
    assert named_like_ids - NOT_IDS == DOCUMENTED


@pytest.mark.parametrize("sheet, column", sorted(DOCUMENTED))
def test_ids_differing_in_case_are_refused_at_the_second(template, sheet, column):
    """Two rows of ``sheet``, ids "Abc" and "ABC" (every other required cell valid): refused
    at the second id's cell, naming the sheet, the first cell and the case rule; "Abc" and
    "Abd" read."""
    spec = _specs()[sheet]
    book = openpyxl.load_workbook(template, read_only=True)
    header = [c.value for c in next(book[sheet].iter_rows(max_row=1))]
    book.close()
    columns = {c.name.lower(): c for c in spec.columns}
    names = [str(h).split(" [")[0].lower() if h is not None else None for h in header]
    row = [_cell_value(columns[n]) if n in columns and columns[n].required else None
           for n in names]
    at = names.index(column)

    def reader(first, second):
        rows = [list(row), list(row)]
        rows[0][at], rows[1][at] = first, second
        return WorkbookReader.from_rows({sheet: [header, *rows]}, file="ids.xlsx")

    assert len(reader("Abc", "Abd").table(spec)) == 2  # distinct ids read
    with pytest.raises(InputError) as info:
        reader("Abc", "ABC").table(spec)
    err = info.value
    first, second = cell_name(2, at + 1), cell_name(3, at + 1)
    assert (err.sheet, err.cell) == (sheet, second), str(err)
    assert f"first at {first}" in str(err) and "case ignored" in str(err), str(err)
    assert "'ABC'" in str(err) or "'Abc'" in str(err), str(err)

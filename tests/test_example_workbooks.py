"""The example workbooks state every Study parameter.

Reference: the product's parameter list (:func:`slingloads.io.analyses.all_parameters`, the
rows the template offers). A committed example that lacks a row runs on that row's default
without a reader seeing it (the campaign's gust ramps once did): each example must state every
row, as its generator (loadcases/build_*.py) writes it.
"""

from pathlib import Path

import openpyxl
import pytest

from slingloads.io.analyses import all_parameters

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("name", ["example-light-twin.xlsx", "example-us-twin.xlsx"])
def test_example_states_every_study_parameter(name):
    book = openpyxl.load_workbook(ROOT / "loadcases" / name, read_only=True)
    rows = {str(r[0]).strip().lower() for r in book["Study"].iter_rows(values_only=True)
            if r and r[0] is not None}
    book.close()
    missing = [p for p in all_parameters() if p not in rows]
    assert not missing, f"{name}: Study rows missing (regenerate with loadcases/build_*.py)"

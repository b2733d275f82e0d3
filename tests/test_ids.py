"""The one uniqueness rule of ids (slingloads.ids), against the rule as documented in
docs/inputs-and-outputs.md: ids are unique with case (and surrounding spaces) ignored, so that
two ids a reader of the report, or a case-insensitive file system, would take for one are
refused; and the campaign's Python API applies the same rule to its mass cases."""

from __future__ import annotations

import numpy as np
import pytest

from slingloads.analyses.campaign import Factors, MassCase
from slingloads.errors import InputError
from slingloads.ids import first_duplicate, id_key


@pytest.mark.parametrize("values, expected", [
    (["NOSE", "tail", "nose"], (0, 2)),
    (["max", "MAX"], (0, 1)),
    (["Free Response", " free response "], (0, 1)),
    (["Straße", "STRASSE"], (0, 1)),  # case folding, not lower(): ß folds to ss
    (["a", "b", "c"], None),
    ([1.0, 2.0, 1.0], (0, 2)),
])
def test_first_duplicate(values, expected):
    """The first repeated id by the documented rule (worked by hand for each list)."""
    assert first_duplicate(values) == expected


def test_id_key_leaves_numbers_alone():
    """Numbers compare as numbers (1 and 1.0 are one id, as in Python)."""
    assert id_key(1) == id_key(1.0) and id_key("A ") == "a"


def test_api_mass_cases_use_the_same_rule():
    """Factors refuses mass cases "max" and "MAX" (same rule as the CampaignMasses sheet)."""
    with pytest.raises(InputError, match="named twice.*case ignored"):
        Factors(masses=(MassCase("max", 2900.0), MassCase("MAX", 2500.0)))


# ---- every id column of every sheet, through the workbook readers -------------------------
def _with_second_spelling(rows, column):
    """``rows`` (a sheet: header then data) with a row whose id in ``column`` is the first
    data row's id in other case: by the rule, that id repeats the first (a copy of the first
    row, so that only the id can be refused). Returns the sheet row of the repeat."""
    at = rows[0].index(column)
    first = rows[1][at]
    twin = list(rows[1])
    twin[at] = first.swapcase() if first.swapcase() != first else f" {first} "
    rows.append(twin)
    return len(rows), at


ID_COLUMNS = [  # (workbook, sheet, id column): every id column of the workbook's sheets
    ("small", "MassItems", "id"), ("small", "Stations", "id"), ("small", "Hardpoints", "id"),
    ("small", "AeroEnvelope", "id"), ("small", "LoadCases", "id"),
    ("small", "LateralMotions", "id"), ("small", "LateralBodies", "id"),
    ("dynamics", "MultibodyManoeuvres", "name"), ("dynamics", "CampaignMasses", "mass case"),
]


@pytest.mark.parametrize("book, sheet, column", ID_COLUMNS)
def test_every_id_column_refuses_an_id_repeated_in_other_case(tmp_path, book, sheet, column):
    """Rule (docs/inputs-and-outputs.md: ids are unique with case ignored): in each id column
    of each sheet, an id written again in other case ('nose' then 'NOSE') is refused at the
    cell of the repeat, naming the first cell, through the one rule (slingloads.ids)."""
    from hostile import save_xlsx, small_dynamics_workbook, small_workbook
    from openpyxl.utils import get_column_letter

    from slingloads.io.study import read_study

    sheets = small_workbook() if book == "small" else small_dynamics_workbook()
    if sheet == "LateralBodies":
        sheets[sheet] = [["id", "mass [kg]", "roll inertia [kg m^2]", "CG below hub [m]"],
                         ["heavy", 2900.0, 1500.0, 1.1]]
    row, at = _with_second_spelling(sheets[sheet], column)
    path = save_xlsx(sheets, tmp_path / "twice.xlsx")
    letter = get_column_letter(at + 1)
    with pytest.raises(InputError) as info:
        read_study(path)
    message = str(info.value)
    assert f"sheet '{sheet}'" in message and f"cell {letter}{row}" in message, message
    assert f"first at {letter}2" in message and "case ignored" in message, message


def test_a_history_id_in_other_case_is_the_same_history(tmp_path):
    """Rule (ids compared with case ignored): LateralHistory rows 'H1' and 'h1' are one
    history, and a motion naming 'h1' takes it: the same motion as naming 'H1'."""
    from hostile import save_xlsx, small_workbook

    from slingloads.io.study import read_study

    def motions(edit):
        sheets = small_workbook()
        edit(sheets)
        study = read_study(save_xlsx(sheets, tmp_path / "h.xlsx"), only=("lateral",))
        return study.inputs.lateral.motions

    same = motions(lambda s: None)

    def other_case(s):
        s["LateralHistory"][3][0] = "h1"  # its third sample in other case
        s["LateralMotions"][2][4] = "h1"
    changed = motions(other_case)
    history, again = same[-1], changed[-1]
    assert again.time.size == 3 and np.array_equal(history.time, again.time)
    assert np.array_equal(history.displacement_samples, again.displacement_samples)


def test_api_load_case_ids_use_the_same_rule():
    """The loads' Python API refuses listed case ids 'QUIET' and 'quiet' as the LoadCases
    sheet does (the rule in one place: slingloads.ids)."""
    from test_aero_loads import study_at

    from slingloads.analyses.loads import ListedCase

    twice = (ListedCase("QUIET", "AXIAL", "NONE", False),
             ListedCase("quiet", "AXIAL", "NONE", True))
    with pytest.raises(InputError, match="unique.*case ignored"):
        study_at(10.0, 16.0, generate=False, listed=twice).case_matrix()
    assert len(study_at(10.0, 16.0, generate=False, listed=twice[:1]).case_matrix()) == 1

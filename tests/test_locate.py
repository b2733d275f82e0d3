"""The one way to put a model's error at its cell (slingloads.io.common.locate).

The reference is the rule the module states, checked on errors built by hand: a model error
naming its field is put at the cell the value came from, echoing the value as written there
with its unit (never the model's SI number; an empty cell echoes none); an error already at a
cell keeps it; an error already in another sheet is not moved to a cell of this one; an error
no cell can be found for is put in the file and sheet.
"""

from __future__ import annotations

import numpy as np
import pytest

from slingloads.errors import InputError, UnitError
from slingloads.io.common.locate import OWN, Place, StudyCells, find_place, located
from slingloads.io.common.schema import Parameter
from slingloads.io.common.table import Table


def _table():
    """Two records of a length column written in inches (SI values in m) and a text column
    with an empty cell."""
    return Table("Hardpoints", {"x": np.array([0.0762, 76.2]), "id": ["hub", None]},
                 {"x": ["B2", "B3"], "id": ["A2", "A3"]}, {"x": "in", "id": ""},
                 {"x": [3, 3000], "id": ["hub", None]}, "book.xlsx")


def _raise(err, *args, **kwargs):
    with pytest.raises(InputError) as info, located(*args, **kwargs):
        raise err
    return info.value


def test_a_field_and_record_are_put_at_their_cell_with_the_value_as_written():
    """The model's SI value 76.2 (m) becomes the cell's 3000.0 [in] at B3; the field and the
    error's class are kept."""
    err = _raise(UnitError("x too large", 76.2, field="x", index=1), _table())
    assert type(err) is UnitError
    assert (err.file, err.sheet, err.cell, err.value, err.unit) == (
        "book.xlsx", "Hardpoints", "B3", 3000.0, "in")
    assert str(err) == ("file book.xlsx, sheet 'Hardpoints', cell B3: x too large: "
                        "value 3000.0 [in]")
    assert err.field == "x"


def test_fields_map_a_model_argument_to_a_column_and_index_fixes_the_record():
    """The field ``position`` mapped to column ``x``, the record given: B2 as written (3 in),
    not the model's value."""
    err = _raise(InputError("bad", 1.0, field="position"), _table(), {"position": "x"},
                 index=0)
    assert (err.cell, err.value, err.unit) == ("B2", 3.0, "in")


def test_an_empty_cell_echoes_no_value():
    """An empty cell has no value as written: the message shows none (not the model's
    default)."""
    err = _raise(InputError("needs a name", "default", field="id", index=1), _table())
    assert (err.cell, err.value) == ("A3", None)
    assert str(err).endswith("cell A3: needs a name")


def test_no_cell_found_puts_the_error_in_the_sheet_with_its_own_value():
    """A field that is no column, a record past the table, no field at all."""
    for err in (InputError("r", 5.0, field="mass", index=0),
                InputError("r", 5.0, field="x", index=7), InputError("r", 5.0)):
        got = _raise(err, _table())
        assert (got.file, got.sheet, got.cell, got.value) == ("book.xlsx", "Hardpoints", None,
                                                             5.0)


def test_an_error_already_at_a_cell_keeps_it_and_one_in_another_sheet_is_not_moved():
    """Only the file is filled in: a cell of this table would not be a cell of that sheet."""
    at_cell = InputError("r", 1.0, sheet="Study", cell="B9", field="x", index=0)
    got = _raise(at_cell, _table())
    assert (got.file, got.sheet, got.cell, got.value) == ("book.xlsx", "Study", "B9", 1.0)
    other = InputError("r", 1.0, sheet="MassItems", field="x", index=0)
    got = _raise(other, _table())
    assert (got.sheet, got.cell, got.value) == ("MassItems", None, 1.0)


def test_a_place_with_or_without_the_value_as_written():
    """``OWN``: the error already echoes the cell's text (a unit the reader parses); else the
    value given is echoed."""
    err = _raise(UnitError("unknown unit", "furlong*"), Place("b.xlsx", "T", "C1"))
    assert (err.cell, err.value) == ("C1", "furlong*")
    assert Place().written is OWN
    err = _raise(InputError("r", 0.26), Place("b.xlsx", "Study", "B4", 15, "deg"))
    assert (err.cell, err.value, err.unit) == ("B4", 15, "deg")
    err = _raise(InputError("r", 0.26), "b.xlsx")
    assert (err.file, err.sheet, err.cell) == ("b.xlsx", None, None)


def _study(sheet="Study"):
    specs = {"fin area": Parameter("fin area", "area", "m^2", 1.5),
             "airspeed eas": Parameter("airspeed EAS", "speed", "kt", 80.0)}
    return StudyCells("b.xlsx", {"fin area": "B5"}, {"fin area": (20, "ft^2")}, specs, sheet)


def test_study_parameters_given_or_default():
    """A parameter given: its cell and value as written; absent: ``(default)`` with the
    default value and unit; a field no parameter maps: the Study sheet (while reading) or the
    file alone (while computing)."""
    err = _raise(InputError("r", 1.858, field="area"), _study(), {"area": "fin area"})
    assert (err.sheet, err.cell, err.value, err.unit) == ("Study", "B5", 20, "ft^2")
    err = _raise(InputError("r", 41.2), _study(), default="airspeed EAS")
    assert (err.sheet, err.cell, err.value, err.unit) == ("Study", "(default)", 80.0, "kt")
    err = _raise(InputError("r", 1.0, field="mass"), _study(), {"area": "fin area"})
    assert (err.sheet, err.cell, err.value) == ("Study", None, 1.0)
    err = _raise(InputError("r", 1.0, field="mass"), _study(None), {"area": "fin area"})
    assert (err.file, err.sheet, err.cell) == ("b.xlsx", None, None)


def test_find_place_is_the_mapping_used():
    """The place of a field's record is its cell, the value as written and the header's
    unit (as ``located`` echoes them)."""
    place = find_place(InputError("r", field="x", index=0), _table())
    assert place == Place("book.xlsx", "Hardpoints", "B2", 3.0, "in")

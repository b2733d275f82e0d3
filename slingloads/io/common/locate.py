"""The one way to put an error at its cell: a model raises with the field, io maps the field to
the cell here.

The models and analyses work in SI and know no workbook: an
:class:`~slingloads.errors.InputError` they raise carries the rule, their own SI value (76.2
for a hardpoint written ``3000`` in a column ``x [in]``; 14.999999999999998 for a sideslip
written ``15`` deg) and the ``field`` (the model argument) and ``index`` (the record) that
value came from. What this module guarantees: such an error is located at the cell the value
came from, and there its message echoes that cell's value as the user wrote it, with the unit
of its header or unit cell, never the model's number (an empty cell echoes none). An error
already at a cell keeps it (only its file and sheet are filled in where unknown), an error
already in another sheet is not moved to a cell of this one, and an error no cell can be
found for is put in the file and sheet.

Every reader and run locates errors through :func:`located` (a context manager) or
:func:`place_error`, given where the values came from:

* a :class:`Place`: a fixed file, sheet and cell (the value as written there, or
  :data:`OWN` when the error's own value is the cell's text, as for a unit the reader
  parses); a file name or path alone is the file;
* a :class:`~slingloads.io.common.table.Table`: the cell of the record ``index`` (the
  error's own, or one given) in the column of the error's field (``fields`` maps a field to
  another column; ``default``: the column of an error naming no mapped field);
* the Study parameters (:class:`StudyCells`, or the
  :class:`~slingloads.io.common.parameters.StudyParameters` that hold them): the cell of the
  parameter ``fields[error.field]`` (or ``default``) with its value as written, or its
  default value and unit at ``(default)`` when its row is absent; else the Study sheet.

:func:`find_place` is the one mapping from a field to a cell. An error about a quantity
derived from several cells (the reach of a parachute, the range of the mass items) is not a
value of any one cell: the reader states it in the user's unit (:func:`quantity`) and names
the cells it comes from, and puts the error at the cell to change.
"""

from __future__ import annotations

import contextlib
import os
from dataclasses import dataclass

from slingloads.errors import InputError, InputErrors
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.common.table import Table
from slingloads.io.common.units import SI_UNITS, si_factor, unit_label

#: The value of a :class:`Place` whose error already echoes the cell's text.
OWN = type("Own", (), {"__repr__": lambda self: "OWN"})()


@dataclass(frozen=True)
class Place:
    """Where a value was read from.

    Attributes
    ----------
    file : str or path-like, optional
    sheet : str, optional
    cell : str, optional
        Excel coordinate (``"C7"``), or ``"(default)"`` for a parameter left to its default.
    written : object
        The cell's value as the user wrote it (None: an empty cell), or :data:`OWN` when an
        error located here echoes its own value (the reader's own error about that cell).
    unit : str, optional
        Unit of the cell's header or unit cell, as written.
    """

    file: object = None
    sheet: str | None = None
    cell: str | None = None
    written: object = OWN
    unit: str | None = None


@dataclass(frozen=True)
class StudyCells:
    """The Study parameters as written: where an error about a parameter is located.

    Attributes
    ----------
    file : str or path-like
    cells : dict
        Lower-case parameter name -> cell of its value, for each parameter given.
    written : dict
        Lower-case parameter name -> ``(value as written, unit as written)``, for each
        parameter given.
    specs : dict
        Every known :class:`~slingloads.io.common.schema.Parameter` by lower-case name (the
        default value and unit of a parameter not given).
    sheet : str, optional
        Sheet of an error that names no parameter: the Study sheet while the parameters are
        read; None (the file only) for an error found while computing, which may come from
        any sheet.
    """

    file: object
    cells: dict
    written: dict
    specs: dict
    sheet: str | None = STUDY_SHEET


def place_error(err, place, rule=None):
    """``err`` located at ``place`` (see the module's rules), its rule replaced by ``rule``
    when given (an error the io layer explains further); each error of an
    :class:`~slingloads.errors.InputErrors` is located in turn."""
    if isinstance(err, InputErrors):
        return InputErrors([place_error(e, place, rule) for e in err.errors],
                           complete=err.complete, note=err.note)
    file, sheet = err.file or place.file, err.sheet or place.sheet
    cell, value, unit = err.cell, err.value, err.unit
    if cell is None and place.cell is not None and err.sheet in (None, place.sheet):
        cell = place.cell
        if place.written is not OWN:
            value, unit = place.written, place.unit or None
    return type(err)(err.rule if rule is None else rule, value, file=file, sheet=sheet,
                     cell=cell, unit=unit, field=err.field, index=err.index)


def find_place(err, where, fields=None, default=None, index=None):
    """The :class:`Place` of the value ``err`` is about: the one mapping from a model's field
    to a cell.

    Parameters
    ----------
    err : InputError
    where : Place, str, path-like, Table, StudyCells or StudyParameters
        Where the values came from (see the module's docstring).
    fields : dict, optional
        Model argument (the error's ``field``) -> column of the table, or Study parameter.
    default : str, optional
        Column or parameter of an error whose field ``fields`` does not map (for a table,
        default: the column named as the field).
    index : int, optional
        Record of the table (default: the error's ``index``).
    """
    if isinstance(where, Place):
        return where
    if isinstance(where, (str, os.PathLike)):
        return Place(where)
    fields = fields or {}
    if isinstance(where, Table):
        column = fields.get(err.field, default if default is not None else err.field)
        row = err.index if index is None else index
        if column in where.cells and row is not None and 0 <= row < len(where.cells[column]):
            value, unit = where.shown(column, row)
            return Place(where.file, where.sheet, where.cell(column, row), value, unit)
        return Place(where.file, where.sheet)
    study = getattr(where, "places", where)  # StudyParameters hold their StudyCells
    name = fields.get(err.field, default)
    if name is None:
        return Place(study.file, study.sheet)
    key = name.lower()
    if key in study.written:
        value, unit = study.written[key]
    else:  # the parameter's default
        value, unit = study.specs[key].default, study.specs[key].unit
    return Place(study.file, STUDY_SHEET, study.cells.get(key, "(default)"), value, unit)


@contextlib.contextmanager
def located(where, fields=None, *, default=None, index=None):
    """Locate an :class:`InputError` raised inside the block at the cell its field came from
    (:func:`find_place`, :func:`place_error`)."""
    try:
        yield
    except InputError as err:
        raise place_error(err, find_place(err, where, fields, default, index)) from None


def quantity(si_value, unit, kind, digits=4):
    """An SI value written in ``unit`` (the user's unit) for a message: ``"54.3 ft"``.

    ``unit`` empty or None gives the SI unit of ``kind``; ``digits`` significant digits, so
    that no float noise of the conversion shows.
    """
    written = (unit or "").strip()
    unit = written or SI_UNITS[kind]
    text = f"{float(si_value) / si_factor(unit, kind):.{digits}g}"
    shown = written or unit_label(unit)
    return f"{text} {shown}" if unit and shown != "-" else text


def column_quantity(table, column, si_value, kind, digits=4):
    """:func:`quantity` in the unit of ``column``'s header (its SI unit when it has none)."""
    return quantity(si_value, table.units.get(column), kind, digits)


def quantity_range(lo, hi, unit, kind, digits=4):
    """``[lo, hi]`` (SI) written in ``unit`` for a message: ``"[31.5, 423.2] in"``."""
    written = (unit or "").strip()
    unit = written or SI_UNITS[kind]
    factor = si_factor(unit, kind)
    shown = written or unit_label(unit)
    text = f"[{float(lo) / factor:.{digits}g}, {float(hi) / factor:.{digits}g}]"
    return f"{text} {shown}" if unit and shown != "-" else text

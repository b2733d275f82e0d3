"""Put at its cell an error a model raises on a value read from a workbook, with the value
as the user wrote it.

The models and analyses work in SI and know no workbook: an
:class:`~slingloads.errors.InputError` they raise carries the rule and their own SI value
(76.2 for a hardpoint written ``3000`` in a column ``x [in]``; 14.999999999999998 for a
sideslip written ``15`` deg). The io layer locates such an error at the cell the value came
from, and at a cell the message must echo that cell's value as written, with the unit of its
header or unit cell, never the model's number. The context managers here do that:

* :func:`at_cell`: at a cell whose value as written the caller gives;
* :func:`at_row`: at a cell of a :class:`~slingloads.io.common.table.Table`, the column
  chosen by the error's ``field`` (a model argument) when it names one;
* :meth:`slingloads.io.common.parameters.StudyParameters.at`: at a Study parameter's cell.

An error about a quantity derived from several cells (the reach of a parachute, the range of
the mass items) is not a value of any one cell: the reader states it in the user's unit
(:func:`quantity`) and names the cells it comes from, and puts the error at the cell to change.

:func:`slingloads.io.common.table.located` puts an error in a file or sheet without a cell;
with a cell it keeps the error's own value, so readers use it with a cell only for errors
whose value is the cell's text (a unit), and tests/test_located_errors.py checks that no
reader uses it otherwise.
"""

from __future__ import annotations

import contextlib

from slingloads.errors import InputError
from slingloads.io.common.units import SI_UNITS, si_factor, unit_label


def _relocated(err, file, sheet, cell, value, unit):
    """A copy of ``err`` at ``cell`` echoing ``value`` [``unit``], the cell's value as
    written (no value when the cell is empty)."""
    return type(err)(err.rule, value, file=err.file or file, sheet=err.sheet or sheet,
                     cell=cell, unit=unit or None, field=err.field, index=err.index)


@contextlib.contextmanager
def at_cell(file, sheet, cell, value, unit=None):
    """Locate an :class:`InputError` raised inside (one that names no cell yet) at ``cell``
    of ``sheet``, echoing ``value`` [``unit``], the cell's value as the user wrote it, in
    place of the model's own value."""
    try:
        yield
    except InputError as err:
        if err.cell is not None:
            raise
        raise _relocated(err, file, sheet, cell, value, unit) from None


@contextlib.contextmanager
def at_row(table, column, index, fields=None):
    """Locate an :class:`InputError` raised inside (one that names no cell yet) at record
    ``index`` of ``table``: in the column ``fields[error.field]`` when the error names a
    field listed there, else in ``column``; the cell's value as written is echoed with its
    header's unit.

    Parameters
    ----------
    table : Table
    column : str
        Column of the cell by default.
    index : int
        0-based record.
    fields : dict, optional
        Model argument (the error's ``field``) -> column of the table.
    """
    try:
        yield
    except InputError as err:
        if err.cell is not None:
            raise
        name = (fields or {}).get(err.field, column)
        value, unit = table.shown(name, index)
        raise _relocated(err, table.file, table.sheet, table.cell(name, index), value,
                         unit) from None


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

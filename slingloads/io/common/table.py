"""A table read from a sheet: SI values by column, with the cell and the value as written of
each.

What this module guarantees: a :class:`Table` knows, for every value it holds, the cell it
came from and the value and unit the user wrote there, so that any error about a value names
that cell and echoes what is written in it, never an SI number the user did not type: the
reader's own errors through :meth:`Table.error`, a model's through
:func:`slingloads.io.common.locate.located`. (A repeated id is refused as the sheet reads:
``ids`` of :class:`~slingloads.io.common.schema.TableSheet`.)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from openpyxl.utils import get_column_letter

from slingloads.errors import InputError
from slingloads.io.common.values import FORMULA_HINT, number_echo


def cell_name(row, col):
    """Excel coordinate of 1-based ``row``, ``col`` (``cell_name(2, 3) == "C2"``)."""
    return f"{get_column_letter(col)}{row}"


@dataclass
class Table:
    """A table read from a sheet: SI values per column, where each came from, as written.

    Attributes
    ----------
    sheet : str
    values : dict
        Column name -> SI values (ndarray for numbers, list for text and flags).
    cells : dict
        Column name -> cell coordinate of each value.
    units : dict
        Column name -> unit written in the header.
    raw : dict
        Column name -> the cell values as written.
    file : str
    """

    sheet: str
    values: dict
    cells: dict
    units: dict
    raw: dict = field(default_factory=dict)
    file: str | None = None

    def __len__(self):
        return len(next(iter(self.values.values()))) if self.values else 0

    def __getitem__(self, name):
        return self.values[name]

    def has(self, name):
        return name in self.values

    def cell(self, name, index):
        """Coordinate of the value of column ``name`` in record ``index``."""
        return self.cells[name][index]

    def shown(self, name, index):
        """``(value as written, unit of the header)`` of column ``name`` in record ``index``."""
        raw = self.raw.get(name)
        value = raw[index] if raw is not None else self.values[name][index]
        if isinstance(self.values[name], np.ndarray):
            value = number_echo(value)
        return value, self.units.get(name) or None

    def error(self, name, index, rule):
        """An InputError at the cell of column ``name``, record ``index``, echoing the value as
        written with its unit."""
        value, unit = self.shown(name, index)
        return InputError(rule, value, file=self.file, sheet=self.sheet,
                          cell=self.cell(name, index), unit=unit)

    def require_filled(self, names, why):
        """Refuse the first empty cell (or formula never computed) of the number columns
        ``names`` that are optional in the sheet's schema but needed here (``why``)."""
        for name in names:
            values = self.values.get(name)
            if values is None or not isinstance(values, np.ndarray):
                continue
            empty = np.flatnonzero(np.isnan(values))
            if empty.size:
                raise self.error(name, int(empty[0]), f"empty cell in column "
                                 f"{self.header(name)!r}: {why}{FORMULA_HINT}")

    def header(self, name):
        """Column ``name``'s header as written (with its unit, when it has one)."""
        unit = self.units.get(name)
        return f"{name} [{unit}]" if unit else name

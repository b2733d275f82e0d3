"""The one uniqueness rule of ids: two ids are the same when they differ only in case or in
surrounding spaces.

Guarantees: every id column of every input sheet (loads cases and points, stations, mass items,
hardpoints, lateral motions and bodies, multibody manoeuvres, campaign mass cases: the ``ids``
of each sheet's :class:`~slingloads.io.common.schema.TableSheet`, checked in one place, by the
workbook reader as the sheet reads) and the
names the campaign's Python API takes are checked with :func:`id_key`, so ``NOSE`` and
``nose``, ``max`` and ``MAX`` are one id everywhere: a report (and a case-insensitive file
system holding file names made from ids) could not tell them apart. Numbers compare as numbers.

>>> id_key("  Free Response "), id_key(3)
('free response', 3)
>>> first_duplicate(["max", "min", "MAX"])
(0, 2)
"""

from __future__ import annotations


def id_key(value):
    """The key by which ids are compared: text stripped and case-folded; numbers as they are."""
    return value.strip().casefold() if isinstance(value, str) else value


def first_duplicate(values):
    """``(first, second)``: the positions of the first id given twice (case ignored), or None."""
    seen = {}
    for i, value in enumerate(values):
        key = id_key(value)
        if key in seen:
            return seen[key], i
        seen[key] = i
    return None


def duplicate_clause(values, first, second, what="id"):
    """The rule a repeated id broke, for a message: ``"duplicate id (first at X ...)"`` is
    built by the caller; this adds the case note when the spellings differ."""
    a, b = values[first], values[second]
    return "" if a == b else f" {a!r}: {what}s are compared with case ignored"


def check_unique(table, column, what=None):
    """Raise an InputError at the second occurrence of an id repeated in ``column`` of a sheet
    table (case ignored: :func:`id_key`).

    Parameters
    ----------
    table : Table
        A sheet table of the workbook reader (``table[column]``, ``table.cell``,
        ``table.error``).
    column : str
        The id column.
    what : str, optional
        The id's name in the message (default: the column's name).

    Raises
    ------
    InputError
        Naming the sheet and cell of the repeat, the first cell and both spellings.
    """
    values = list(table[column])
    found = first_duplicate(values)
    if found is None:
        return
    first, second = found
    what = what or column
    raise table.error(column, second, f"duplicate {what} (first at {table.cell(column, first)}"
                                      f"{duplicate_clause(values, first, second, what)})")

"""Cell values to typed values: numbers, yes/no flags and texts, checked against their limits.

What this module guarantees:

* a number is a finite float written as a number or as plain decimal text (ASCII digits,
  ``12.5``, ``1e-3``: :data:`PLAIN_NUMBER`); a true/false value, a date, a spreadsheet error
  or any other text is refused, never read as a number;
* a quantity is converted to SI with the factor of the unit it was written in, and checked
  against the magnitude limit of its kind (:data:`~slingloads.limits.MAX_MAGNITUDE`) and its
  bounds (:class:`~slingloads.io.common.schema.Bounds`), the rule stated in the user's unit;
  an integer is a whole number;
* a text is stripped, at most its length limit, with no control character and no character a
  reader of the report could not see (:func:`hidden_character`);
* a column of plain numbers is checked and converted at once (:func:`plain_quantities`),
  giving the very floats the cell-by-cell path gives, or None when any cell needs that path;
* every refusal is raised through the caller's ``error(rule, value, sheet, cell, unit)``, so
  that it names the cell and echoes the value as written (:func:`echo`, :func:`number_echo`).

Units themselves are parsed by :mod:`slingloads.io.common.units`.
"""

from __future__ import annotations

import math
import re
import unicodedata
from datetime import date, datetime, time, timedelta

import numpy as np

from slingloads.io.common.schema import FLAG, INTEGER, TEXT
from slingloads.io.common.units import si_factor
from slingloads.io.common.xlsx_source import CellError
from slingloads.limits import MAX_ID_CHARS, MAX_MAGNITUDE

FORMULA_HINT = (" (or a formula whose value was never computed: open and save the workbook "
                 "in Excel or LibreOffice first)")
#: Control characters a workbook cell cannot hold (tab, line feed and carriage return can).
ILLEGAL_CHARACTERS_RE = re.compile(r"[\000-\010]|[\013-\014]|[\016-\037]")
_TRUE = {"yes", "y", "true", "1", "on", "x"}
_FALSE = {"no", "n", "false", "0", "off", ""}


def as_column(values, kind):
    """The values of a column as a Table holds them: a list for text and flags, else an
    ndarray of floats."""
    return values if kind in (TEXT, FLAG) else np.asarray(values, dtype=float)


def plain_quantities(raw, column, factor):
    """SI values of a column of plain numbers, or None unless every cell passes every check.

    The column-at-once form of :func:`parse_number` and :func:`check_quantity`, giving the
    same float for each cell: it applies only to a numeric column (not text, flag or integer)
    whose cells are all Python ``int`` or ``float`` (not ``bool``: no empty cell, no text,
    date or spreadsheet error), converted by ``float`` as :func:`parse_number` does, then
    multiplied by ``factor`` in IEEE double precision as the scalar path does. The magnitude
    limit and the bounds are checked on the whole column; the bounds through
    :meth:`Bounds.contains` itself on each distinct value (``np.unique`` merges 0.0 and -0.0,
    which every comparison treats alike). None means "read cell by cell": a value that is
    not a plain number, or any cell that breaks a rule (the careful path then names it).

    Parameters
    ----------
    raw : list
        The cell values as read.
    column : Column
    factor : float
        SI factor of the header's unit.

    Returns
    -------
    ndarray or None
    """
    kind = column.kind
    # exact types: bool (a subclass of int), numpy scalars and the like go cell by cell
    if kind in (TEXT, FLAG, INTEGER) or not raw or not set(map(type, raw)) <= {int, float}:
        return None
    try:
        numbers = np.fromiter(map(float, raw), dtype=float, count=len(raw))
    except OverflowError:  # an int beyond floats: parse_number's "finite number" error
        return None
    with np.errstate(all="ignore"):  # an overflow to inf is an error below, never a warning
        values = numbers * factor
        if not np.isfinite(numbers).all():
            return None
        limit = MAX_MAGNITUDE.get(kind)
        if limit is not None and not (np.abs(values) <= limit).all():
            return None
        bounds = column.bounds
        if bounds is not None:
            b_unit = bounds.unit if bounds.unit is not None else column.unit
            b_factor = si_factor(b_unit or "", kind)
            if not all(bounds.contains(v) for v in np.unique(values / b_factor).tolist()):
                return None
    return values


def as_text(value):
    """Text of a cell value (whole numbers without '.0')."""
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def echo(value, n=200):
    """A value for a message: long texts cut to ``n`` characters."""
    if isinstance(value, str) and len(value) > n:
        return value[:n] + "..."
    return value


def parse_text(raw, what, max_chars, error, sheet, where):
    """The text of a cell: stripped, at most ``max_chars`` characters, no control characters
    other than tab and line breaks, not a spreadsheet error."""
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    text = as_text(raw).strip()
    if len(text) > max_chars:
        raise error(f"{what!r} must have at most {max_chars} characters", echo(text), sheet,
                    where)
    if ILLEGAL_CHARACTERS_RE.search(text):
        raise error(f"{what!r} contains control characters", echo(text), sheet, where)
    hidden = hidden_character(text, name_like=max_chars <= MAX_ID_CHARS)
    if hidden is not None:
        k, char = hidden
        rule = ("an id or name holds visible characters and spaces only"
                if max_chars <= MAX_ID_CHARS else "text holds no direction controls")
        name = unicodedata.name(char, None) or _CONTROL_NAMES.get(char, "a control")
        raise error(f"{what!r} contains the invisible character U+{ord(char):04X} ({name}) "
                    f"at position {k + 1}: {rule}", echo(text), sheet, where)
    return text


_CONTROL_NAMES = {"\t": "TAB", "\n": "LINE FEED", "\r": "CARRIAGE RETURN"}
#: Characters that reorder the display of text (Unicode bidirectional controls): a text that
#: holds them can show as another ("Trojan source"); never accepted in any text.
BIDI_CONTROLS = frozenset("\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e"
                          "\u2066\u2067\u2068\u2069")


def hidden_character(text, name_like):
    """``(position, character)`` of the first character of ``text`` a reader of the report
    could not see, or None: a direction control anywhere; in an id or name
    (``name_like``) also any control or format character (zero-width space, soft hyphen...)
    and any white space but the plain space (tab, line break, no-break space), so that two
    ids that look alike are alike."""
    if text.isascii() and (text.isprintable() or not name_like):
        return None  # (nearly every cell: ASCII has no direction control)
    for k, char in enumerate(text):
        if char in BIDI_CONTROLS:
            return k, char
        if name_like and char != " " and (char.isspace()
                                          or unicodedata.category(char)[0] in "CZ"):
            return k, char
    return None


#: A number written as text: plain decimal notation with the ASCII digits 0-9, an optional
#: sign, decimal point and exponent (``12.5``, ``-3``, ``.5``, ``1e-3``). Python's float()
#: also takes ``1_0`` (ten), other scripts' digits (``٢``, ``３``) and ``infinity``: a
#: workbook's text is never read that way.
PLAIN_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def number_from_text(text):
    """The number a text cell (or CSV field, or list item) holds, surrounding spaces ignored:
    a float when the text is a plain decimal number (:data:`PLAIN_NUMBER`), ``inf`` or
    ``nan`` when it says so (``inf``, ``-Infinity``, ``nan``: refused as not finite by the
    caller), else None (not a number)."""
    text = text.strip()
    if PLAIN_NUMBER.fullmatch(text):
        return float(text)
    if text.lower().lstrip("+-") in ("inf", "infinity", "nan"):
        return float(text)
    return None


def parse_number(raw, what, error, sheet, where):
    """A finite number from a cell value, or an error naming the cell."""
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    if isinstance(raw, bool):
        raise error(f"{what!r} must be a number, not a true/false value", raw, sheet, where)
    if isinstance(raw, (datetime, date, time, timedelta)):
        raise error(f"{what!r} must be a number, not a date or time (format the cell as a "
                    "number)", str(raw), sheet, where)
    if isinstance(raw, (int, float)):
        try:
            value = float(raw)
        except OverflowError:
            value = math.inf
    elif isinstance(raw, str):
        value = number_from_text(raw)
        if value is None:
            raise error(f"{what!r} must be a number (digits 0-9, e.g. 12.5 or 1.2e3)",
                        echo(raw), sheet, where)
    else:
        raise error(f"{what!r} must be a number", echo(str(raw)), sheet, where)
    if not math.isfinite(value):
        raise error(f"{what!r} must be a finite number", echo(raw), sheet, where)
    return value


def check_quantity(number, raw, kind, factor, unit, bounds, spec_unit, what, error, sheet,
                   where):
    """SI value of ``number`` (as written in ``unit``, SI factor ``factor``), checked against
    the magnitude limit of ``kind`` and ``bounds``; whole numbers for the integer kind.

    Raises
    ------
    InputError
        At ``where``, with the value as written and its unit, and the rule in that unit.
    """
    value = number * factor
    shown = unit or None
    echo = number_echo(raw)
    if kind == INTEGER and not float(number).is_integer():
        raise error(f"{what} must be a whole number", echo, sheet, where)
    limit = MAX_MAGNITUDE.get(kind)
    if limit is not None and not abs(value) <= limit:
        raise error(f"{what} must not exceed {limit / factor:.6g}{' ' + unit if unit else ''} "
                    f"in magnitude (limit of every {kind} in slingloads)", echo, sheet, where,
                    shown)
    if bounds is not None:
        b_unit = bounds.unit if bounds.unit is not None else spec_unit
        b_factor = 1.0 if kind == INTEGER else si_factor(b_unit or "", kind)
        if not bounds.contains(value / b_factor):
            rule = bounds.rule(value / b_factor, scale=factor / b_factor, unit=unit)
            raise error(f"{what} {rule}", echo, sheet, where, shown)
    return int(number) if kind == INTEGER else value


def number_echo(raw):
    """A numeric cell's value for a message: numbers as floats (``0.0``, ``-12.5``), text as
    written."""
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        try:
            return float(raw)
        except OverflowError:
            return raw
    return echo(raw)


def parse_flag(raw, what, error, sheet, where, default):
    """A yes/no cell as bool."""
    if raw is None:
        if default is None:
            raise error(f"empty cell: {what!r} needs yes or no", None, sheet, where)
        raw = default
    if isinstance(raw, bool):
        return raw
    if isinstance(raw, CellError):
        raise error(f"{what!r}: the cell holds the spreadsheet error {str(raw)!r}", str(raw),
                    sheet, where)
    text = as_text(raw).strip().lower()
    if text in _TRUE:
        return True
    if text in _FALSE and text != "":
        return False
    raise error(f"{what!r} must be yes or no", echo(raw), sheet, where)

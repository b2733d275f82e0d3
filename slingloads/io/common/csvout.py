"""The one CSV writer of the reports: no field can act as a spreadsheet formula.

A CSV file carries no types: a spreadsheet that opens it evaluates any field that looks like a
formula. Text that came from an input (a case or station id, a description) and begins with
``=``, ``+``, ``-``, ``@``, a tab or a carriage return (also after leading spaces, which some
importers trim) is therefore written with a leading apostrophe, which spreadsheets show as text
(the OWASP "CSV injection" rule). Numbers are written as numbers, and text that is a plain
decimal number (``-12.5``, ``+3``) is left as it is: a spreadsheet reads it as that number, which
is no formula. Column headers are neutralised the same way.

Workbooks need no such prefix: their text cells are stored as text, never as formulas
(:mod:`slingloads.io.common.excel`).
"""

from __future__ import annotations

import io
import re

import numpy as np
import pandas as pd

#: First characters that make a spreadsheet read a field as a formula.
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r", "\n")
_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")


def neutralise(value):
    """``value`` made safe for a CSV field: text that a spreadsheet would read as a formula
    gets a leading apostrophe; anything else (numbers included) is returned unchanged.

    >>> neutralise("=cmd|' /C calc'!A0"), neutralise(" @SUM(A1)"), neutralise("-12.5")
    ("'=cmd|' /C calc'!A0", "' @SUM(A1)", '-12.5')
    """
    if not isinstance(value, str) or not value:
        return value
    stripped = value.lstrip(" \u00a0")
    if value[0] in FORMULA_STARTS or (stripped[:1] in FORMULA_STARTS):
        if _NUMBER.match(stripped):
            return value
        return "'" + value
    return value


def neutralise_frame(frame):
    """A copy of ``frame`` whose text cells and column names are neutralised."""
    out = frame.copy()
    for column in out.columns:
        series = out[column]
        if series.dtype == object or pd.api.types.is_string_dtype(series.dtype):
            out[column] = series.map(neutralise)
    out.columns = [neutralise(str(c)) for c in out.columns]
    return out


def write_csv(frame, path, columns=None):
    """Write a DataFrame as a CSV file (no index, ``\\n`` line ends), every text neutralised.

    Parameters
    ----------
    frame : pandas.DataFrame
    path : path-like
        The file to write (normally a staging path of
        :func:`slingloads.io.common.atomic.atomic_outputs`).
    columns : sequence of str, optional
        Columns to write, in order (default: all).
    """
    with open(path, "wb") as stream:
        stream.write(csv_bytes(frame, columns))


def csv_bytes(frame, columns=None):
    """The bytes of :func:`write_csv`'s file (UTF-8), made where it is convenient (a report
    hands its large tables to the run's helper process:
    :func:`slingloads.io.common.helper.in_background`).

    Returns
    -------
    bytes
    """
    if columns is not None:
        frame = frame[list(columns)]
    safe = neutralise_frame(frame)
    text = io.StringIO()
    with np.errstate(all="ignore"):
        safe.to_csv(text, index=False, lineterminator="\n")
    return text.getvalue().encode("utf-8")

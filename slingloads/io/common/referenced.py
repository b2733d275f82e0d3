"""Files an input workbook refers to (CSV time histories): found, checked and read in SI.

What this module guarantees: a file named in a cell is taken relative to the workbook's
folder, must be a regular file of an accepted suffix and size, and is recorded as an input of
the study (:meth:`~slingloads.io.common.workbook.WorkbookReader.record_input`), so that no
output ever replaces it; a CSV file's columns carry their unit in brackets, every value is a
finite number within the magnitude limit of its kind, and the rows are at most
:data:`~slingloads.limits.MAX_CSV_ROWS`. Every error is located at the cell that names the
file, and names the file's column and data row.
"""

from __future__ import annotations

import csv
import io
import math
import os
import stat
from pathlib import Path

import numpy as np

from slingloads.io.common.locate import Place, located
from slingloads.io.common.units import si_factor
from slingloads.io.common.values import echo, number_from_text
from slingloads.io.common.xlsx_source import reason_of
from slingloads.limits import MAX_CSV_BYTES, MAX_CSV_ROWS, MAX_MAGNITUDE, MAX_PATH_CHARS
from slingloads.safeopen import open_regular


def referenced_file(reader, text, sheet, cell, *, suffixes=(".csv",),
                    max_bytes=MAX_CSV_BYTES):
    """The path of a file named in a cell, checked, and recorded as an input.

    A relative path is taken from the workbook's folder. The file must be a regular file
    (not a folder, device or pipe) with one of ``suffixes`` and at most ``max_bytes``.

    Raises
    ------
    InputError
        At ``sheet``/``cell``, echoing the path as written.
    """
    where = (sheet, cell)
    if len(text) > MAX_PATH_CHARS:
        raise reader.error(f"a file path must have at most {MAX_PATH_CHARS} characters",
                           echo(text), *where)
    if "\x00" in text:
        raise reader.error("a file path must not contain a NUL character", echo(text),
                           *where)
    path = Path(text)
    if not path.is_absolute():
        path = reader.path.resolve().parent / path
    if path.suffix.lower() not in suffixes:
        raise reader.error(f"the file must be one of {list(suffixes)}", text, *where)
    try:
        info = os.stat(path)
    except (FileNotFoundError, NotADirectoryError):
        raise reader.error("file not found (a relative path is taken from the workbook's "
                           "folder)", text, *where) from None
    except (OSError, ValueError) as err:
        raise reader.error(f"cannot open the file ({reason_of(err)})", text, *where) from None
    if not stat.S_ISREG(info.st_mode):
        raise reader.error("not a regular file (a folder, device or pipe)", text, *where)
    if info.st_size > max_bytes:
        raise reader.error(f"file refused: {info.st_size:,} bytes, more than the "
                           f"{max_bytes:,} accepted", text, *where)
    reader.record_input(path)
    return path


def csv_columns(reader, text, sheet, cell, columns, max_rows=MAX_CSV_ROWS):
    """Numeric columns of a CSV file named in a cell, in SI.

    Parameters
    ----------
    reader : WorkbookReader
        The workbook that names the file.
    text : str
        The path as written in the cell (see :func:`referenced_file`).
    sheet, cell : str
        Where the path was written; every error is located there and names the file's
        column and data row.
    columns : dict
        Wanted column name (case-insensitive, without the unit) -> quantity kind. Every
        header must carry its unit in brackets, ``t [s]``.
    max_rows : int
        Most data rows.

    Returns
    -------
    dict
        Column name -> SI values (ndarray).
    """
    path = referenced_file(reader, text, sheet, cell)
    where = (sheet, cell)
    name = path.name
    try:
        with open_regular(path, MAX_CSV_BYTES, follow_links=True) as handle:
            content = handle.read().decode("utf-8-sig")
    except (OSError, UnicodeDecodeError) as err:
        raise reader.error(f"cannot read the CSV file {name!r} ({reason_of(err)})", text,
                           *where) from None
    try:
        rows = csv.reader(io.StringIO(content))
        header = next(rows, None)
    except csv.Error as err:
        raise reader.error(f"CSV {name}: not a CSV file ({err})", text, *where) from None
    if not header:
        raise reader.error(f"CSV {name}: the file is empty (it needs a header row)", text,
                           *where)
    index = {}
    for j, head in enumerate(header):
        label, _, unit = head.partition("[")
        key = label.strip().lower()
        if key in {c.lower() for c in columns}:
            if key in index:
                raise reader.error(f"CSV {name}: column {label.strip()!r} appears twice",
                                   text, *where)
            index[key] = (j, head, unit.rstrip("] ").strip())
    wanted = {c.lower(): (c, kind) for c, kind in columns.items()}
    missing = [c for c in wanted if c not in index]
    if missing:
        raise reader.error(f"CSV {name}: needs the columns "
                           f"{[f'{wanted[c][0]} [unit]' for c in wanted]}",
                           echo(", ".join(header)), *where)
    factors = {}
    for key, (_label, kind) in wanted.items():
        _, head, unit = index[key]
        if not unit:
            raise reader.error(f"CSV {name}: column {head!r} needs a unit in brackets",
                               text, *where)
        with located(Place(reader.file, *where)):
            factors[key] = si_factor(unit, kind)
    data = {key: [] for key in wanted}
    try:
        for k, row in enumerate(rows, start=1):
            if not any(v.strip() for v in row):
                continue
            if k > max_rows:
                raise reader.error(f"CSV {name}: at most {max_rows:,} data rows are "
                                   "allowed", text, *where)
            for key, (_label, kind) in wanted.items():
                j, head, unit = index[key]
                cell_text = row[j] if j < len(row) else ""
                value = number_from_text(cell_text)
                if value is None:
                    value = math.nan
                if not math.isfinite(value):
                    raise reader.error(f"CSV {name}: column {head!r}, data row {k} is not a "
                                       "finite number", echo(cell_text), *where)
                if abs(value * factors[key]) > MAX_MAGNITUDE[kind]:
                    raise reader.error(f"CSV {name}: column {head!r}, data row {k} is beyond "
                                       f"the largest accepted {kind} "
                                       f"{MAX_MAGNITUDE[kind] / factors[key]:.6g} {unit}",
                                       echo(cell_text), *where)
                data[key].append(value * factors[key])
    except csv.Error as err:
        raise reader.error(f"CSV {name}: malformed ({err})", text, *where) from None
    return {wanted[key][0]: np.asarray(v, dtype=float) for key, v in data.items()}

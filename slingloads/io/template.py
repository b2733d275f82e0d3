"""Write input workbooks: the blank, self-explaining template, or one filled with data."""

from __future__ import annotations

import numpy as np
from openpyxl import Workbook
from openpyxl.comments import Comment
from openpyxl.styles import Alignment, Font, PatternFill

from slingloads.errors import MAX_REPORTED_ERRORS
from slingloads.io.analyses import sections
from slingloads.io.common.atomic import atomic_file
from slingloads.io.common.schema import FLAG, INTEGER, STUDY_SHEET, TEXT
from slingloads.limits import MAX_MAGNITUDE, MAX_SHEET_CELLS, MAX_STUDY_ROWS

_BOLD = Font(bold=True)
_HEAD_FILL = PatternFill("solid", fgColor="DDEBF7")

INTRO = (
    "slingloads input workbook. Fill the sheets below and run: slingloads run THIS.xlsx "
    "--out reports/. Axes: x aft (fuselage station), y right (butt line), z up (water line); "
    "see docs/conventions.md. Every column header carries its unit in brackets, e.g. 'x [in]' "
    "or 'mass [lb]': change the unit to any unit of the same kind (SI or US customary). "
    "Parameters on the Study sheet carry theirs in the 'unit' column; delete a parameter row "
    "to use its default. Extra columns named 'note' or 'source' are ignored. Empty rows are "
    "skipped. Sheets marked optional may be deleted. Limits: each column and parameter states "
    "its allowed range; every number is also bounded in magnitude by its kind (e.g. "
    f"{MAX_MAGNITUDE['length']:g} m, {MAX_MAGNITUDE['mass']:g} kg, "
    f"{MAX_MAGNITUDE['force']:g} N); a sheet may store at most {MAX_SHEET_CELLS:,} cells "
    f"(formatted empty ones included) and the Study sheet {MAX_STUDY_ROWS:,} rows; a value in "
    "a column without a header is an error. A workbook's mistakes are reported together, "
    f"each at its cell (at most {MAX_REPORTED_ERRORS} at once)."
)


#: What one sheet or row asks of the others, stated on the README sheet (each is checked
#: when the workbook is read, with the cell to fix named).
REQUIREMENTS = (
    ("empty sheets", "A sheet left with its header row only counts as deleted: optional "
     "sheets need not be removed."),
    ("FuselageAero", "needs a Hardpoints row of kind 'aero_reference' and the Study's "
     "'fuselage reference area' and 'fuselage reference length' > 0; its columns are those of "
     "'fuselage force axes' (wind: CD, CY, CL; body: CX, CY, CZ) and 'fuselage moment axes' "
     "(Cl, Cm, Cn); the other frame's columns may stay empty."),
    ("FinAero", "needs a Hardpoints row of kind 'fin_cp' and 'fin area' > 0; the multibody "
     "model and the campaign need 'fin axes' = body (its CY is the fin's normal force)."),
    ("AeroEnvelope", "required by the loads ('run loads' = yes) when FuselageAero or FinAero "
     "has data: the (alpha, beta) points at which their loads are taken, inside the tables."),
    ("parachute", "'parachute area' > 0 needs a Hardpoints row of kind 'chute'; ParachuteCD "
     "is optional (default: the extended drag table)."),
    ("LoadCases", "its hook and aero ids must be generated directions (VERTICAL, AZ000...), "
     "TOW, NONE or AeroEnvelope ids; chute = yes needs a parachute."),
    ("lateral study", "'run lateral' = yes needs LateralMotions, LateralRopes and "
     "LateralBodies; a motion of type time_history needs its samples in LateralHistory."),
    ("multibody", "'run multibody' = yes needs FuselageAero; 'multibody tail' = full tail "
     "needs FinAero, HTailAero and a Hardpoints row of kind 'htail_cp'; with parachute a "
     "Hardpoints row of kind 'chute'."),
    ("chute sizing and campaign", "need FuselageAero or FinAero and a Hardpoints row of kind "
     "'chute'."),
)


def _text(cell, value):
    """Store ``value`` as plain text, never as a formula."""
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"


def write_input_workbook(path, parameters=None, tables=None, notes=None, inputs=()):
    """Write an input workbook following the sections of :mod:`slingloads.io.analyses`.

    Parameters
    ----------
    path : path-like
        The ``.xlsx`` to write (atomically).
    parameters : dict, optional
        ``{parameter name: (value, unit)}``; parameters not given are listed with their
        default (the blank template lists every parameter so).
    tables : dict, optional
        ``{sheet name: pandas.DataFrame}`` whose column labels are full headers (``x [in]``).
        Sheets not given are written with their headers only.
    notes : list of str, optional
        Lines added to the README sheet (sources and assumptions of the data).
    inputs : iterable of path-like
        Files that must not be overwritten.

    Returns
    -------
    pathlib.Path
        The workbook written.
    """
    from pathlib import Path

    path = Path(path)
    parameters = parameters or {}
    tables = tables or {}
    book = Workbook()
    readme = book.active
    readme.title = "README"
    _readme(readme, notes or [])
    _study_sheet(book.create_sheet(STUDY_SHEET), parameters)
    for section in sections():
        for spec in section.sheets:
            if tables and spec.name not in tables and not spec.required:
                continue
            _table_sheet(book.create_sheet(spec.name), spec, tables.get(spec.name))
    with atomic_file(path, inputs=inputs) as tmp:
        book.save(tmp)
    return path


def _readme(ws, notes):
    ws.column_dimensions["A"].width = 24
    ws.column_dimensions["B"].width = 30
    ws.column_dimensions["C"].width = 110
    _text(ws.cell(1, 1), "slingloads input workbook")
    ws.cell(1, 1).font = Font(bold=True, size=14)
    _text(ws.cell(2, 1), INTRO)
    ws.merge_cells("A2:C2")
    ws.cell(2, 1).alignment = Alignment(wrap_text=True, vertical="top")
    ws.row_dimensions[2].height = 75
    row = 4
    for line in notes:
        _text(ws.cell(row, 1), line)
        ws.merge_cells(start_row=row, start_column=1, end_row=row, end_column=3)
        row += 1
    row += 1
    _text(ws.cell(row, 1), "Sheets that go together")
    ws.cell(row, 1).font = _BOLD
    row += 1
    for what, rule in REQUIREMENTS:
        _text(ws.cell(row, 1), what)
        _text(ws.cell(row, 3), rule)
        row += 1
    row += 1
    for col, title in enumerate(("sheet", "column", "meaning"), start=1):
        _text(ws.cell(row, col), title)
        ws.cell(row, col).font = _BOLD
        ws.cell(row, col).fill = _HEAD_FILL
    row += 1
    _text(ws.cell(row, 1), STUDY_SHEET)
    _text(ws.cell(row, 3), "Parameters: one per row, 'parameter | value | unit | "
          "description'. See the sheet for every parameter and its default.")
    row += 1
    for section in sections():
        for spec in section.sheets:
            _text(ws.cell(row, 1), spec.name)
            _text(ws.cell(row, 3), ("(required) " if spec.required else "(optional) ")
                  + spec.help + f" At most {spec.max_rows:,} data rows.")
            ws.cell(row, 1).font = _BOLD
            row += 1
            for c in spec.columns:
                _text(ws.cell(row, 2), c.header)
                kind = {TEXT: "text", FLAG: "yes/no", INTEGER: "whole number"}.get(c.kind,
                                                                                 c.kind)
                need = "required" if c.required else f"optional, default {c.default!r}"
                text = " ".join(t for t in (f"{kind}; {need}.", c.help,
                                            _limit_text(c).strip()) if t)
                _text(ws.cell(row, 3), text)
                row += 1


def _study_sheet(ws, parameters):
    heads = ("parameter", "value", "unit", "description")
    for col, title in enumerate(heads, start=1):
        _text(ws.cell(1, col), title)
        ws.cell(1, col).font = _BOLD
        ws.cell(1, col).fill = _HEAD_FILL
    ws.column_dimensions["A"].width = 30
    ws.column_dimensions["B"].width = 16
    ws.column_dimensions["C"].width = 10
    ws.column_dimensions["D"].width = 100
    row = 2
    for section in sections():
        for p in section.parameters:
            value, unit = parameters.get(p.name, (p.default, p.unit))
            _text(ws.cell(row, 1), p.name)
            _text(ws.cell(row, 2), _input_cell(value))
            _text(ws.cell(row, 3), unit)
            _text(ws.cell(row, 4), f"[{section.name}] {p.help}{_limit_text(p)}")
            row += 1
    ws.freeze_panes = "A2"


def _table_sheet(ws, spec, frame):
    headers = list(frame.columns) if frame is not None else [c.header for c in spec.columns]
    for col, title in enumerate(headers, start=1):
        cell = ws.cell(1, col)
        _text(cell, str(title))
        cell.font = _BOLD
        cell.fill = _HEAD_FILL
        c = column_of(spec, title)
        if c is not None:
            cell.comment = Comment(column_comment(c), "slingloads", width=320, height=160)
        ws.column_dimensions[cell.column_letter].width = max(12, len(str(title)) + 3)
    if frame is not None:
        for r, values in enumerate(frame.itertuples(index=False), start=2):
            for col, value in enumerate(values, start=1):
                _text(ws.cell(r, col), _input_cell(value))
    ws.freeze_panes = "A2"


def column_of(spec, header):
    """The column of ``spec`` a header names: the exact name first (``CL`` and ``Cl`` are
    different columns), else a unique case-insensitive match, else None."""
    name = str(header).split("[")[0].strip()
    exact = [c for c in spec.columns if c.name == name]
    if exact:
        return exact[0]
    folded = [c for c in spec.columns if c.name.lower() == name.lower()]
    return folded[0] if len(folded) == 1 else None


def column_comment(column):
    """The header comment of a column: what it is, its sign and reference, a typical value,
    and the units it accepts."""
    text = column.help or column.name
    if column.kind not in (TEXT, FLAG, INTEGER) and column.unit:
        text += f" Unit: any {column.kind} unit in the brackets."
    elif column.kind == FLAG:
        text += " (yes/no)"
    return text + _limit_text(column)


def _limit_text(spec):
    """`` Allowed: > 0 kg.`` for a column or parameter with bounds; text length for text."""
    if spec.kind == TEXT:
        limit = getattr(spec, "char_limit", None)
        return f" At most {limit:,} characters." if limit else ""
    bounds = getattr(spec, "bounds", None)
    if bounds is None:
        return ""
    unit = bounds.unit if bounds.unit is not None else spec.unit
    return f" Allowed: {bounds.text(unit=unit if spec.kind != INTEGER else '')}."


def _input_cell(value):
    """``value`` as an input workbook's cell holds it, as a user would type it: numpy numbers
    as Python numbers, a flag as the sheets' ``yes``/``no``, anything else as it is (unlike the
    report writer's :func:`~slingloads.io.common.excel_cells.cell_value`, which also writes NaN
    as an empty cell and an infinity as text)."""
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    return value

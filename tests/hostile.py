"""Test inputs and their helpers: the example workbook's path, a small valid input workbook
built in memory and helpers to break it (hostile tests), and commands stopped at a known moment
(kill and Ctrl-C tests).

The small workbook asks for all three analyses with tiny tables, so that reading it takes a
few milliseconds and computing it about a second: the fuzzing and the kill tests start from it.
"""

from __future__ import annotations

import copy
from pathlib import Path

from openpyxl import Workbook

#: The example workbook of the repository.
EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"

#: Sideslip step of :func:`light_example`'s fuselage table (the example's is 2 deg). [deg]
LIGHT_BETA_STEP = 10

#: Identification written into the session's copy of the example (Study sheet, free
#: fields; ``ident_workbook`` in conftest.py) and the reports of its ``slingloads run``
#: that print it on their cover.
IDENT = {"author": "A. Author", "checker": "C. Checker & Co", "document number": "DOC-42 A"}
IDENT_REPORTS = ("loads", "lateral", "chute")


def set_study(book, values):
    """Set Study parameters of an openpyxl workbook (adding rows that are absent)."""
    ws = book["Study"]
    rows = {str(r[0].value).lower(): r[0].row for r in ws.iter_rows(min_row=2) if r[0].value}
    for name, value in values.items():
        row = rows.get(name.lower()) or ws.max_row + 1
        ws.cell(row, 1, name)
        ws.cell(row, 2, value)


def light_example():
    """The example workbook with its fuselage table thinned to every
    :data:`LIGHT_BETA_STEP` deg of sideslip (same alpha and beta range, one row in five):
    every sheet and Study row as in the example, read and saved in a fraction of the time.
    The tests that edit one cell and expect it refused start from it; the tests of numbers
    use :data:`EXAMPLE`. Made once per process."""
    if not _LIGHT:
        import tempfile

        import openpyxl

        book = openpyxl.load_workbook(EXAMPLE)
        ws = book["FuselageAero"]
        rows = list(ws.iter_rows(min_row=2, values_only=True))
        ws.delete_rows(2, ws.max_row)
        for row in rows:
            if row[1] % LIGHT_BETA_STEP == 0:
                ws.append(row)
        folder = Path(tempfile.mkdtemp(prefix="slingloads-light-example-"))
        path = folder / EXAMPLE.name
        book.save(path)
        _LIGHT.append(path)
    return _LIGHT[0]


_LIGHT = []


def small_workbook():
    """``{sheet: [row 1, row 2, ...]}`` of a small valid workbook (every analysis)."""
    study = [
        ("study name", "small hostile-input base", None),
        ("run loads", "yes", None),
        ("run lateral", "yes", None),
        ("run chute sizing", "yes", None),
        ("hook azimuths", 4, None),
        ("parachute area", 1.0, "m^2"),
        ("fuselage reference area", 3.0, "m^2"),
        ("fuselage reference length", 10.0, "m"),
        ("fin area", 1.0, "m^2"),
        ("hull stations", "S2", None),
        ("lateral simulation time", 4.0, "s"),
        ("lateral RK4 step", 0.05, "s"),
        ("lateral history output step", 0.05, "s"),
        ("lateral history rtol", 1e-5, None),
        ("chute sizing wake source", "model", None),
        ("chute sizing simulation time", 20.0, "s"),
        ("chute sizing time step", 0.1, "s"),
        ("chute sizing output interval", 0.1, "s"),
        ("chute sizing gust onset", 5.0, "s"),
        ("chute sizing gust duration", 4.0, "s"),
        ("chute sizing gust shapes", "step, finite", None),
        ("chute sizing number of areas", 2, None),
        # the paper's balance of Mz: fuselage and fin stable alone, no sweep (about the towed
        # trim's cable line the weight's moment makes this small body need a parachute)
        ("chute sizing yaw axis", "airframe z", None),
    ]
    alphas, betas = (-10.0, 0.0, 10.0), (-20.0, -10.0, 0.0, 10.0, 20.0)
    fuselage = [("alpha [deg]", "beta [deg]", "CD", "CY", "CL", "Cl", "Cm", "Cn")]
    for a in alphas:
        for b in betas:
            fuselage.append((a, b, 0.5 + 0.001 * a * a, -0.01 * b, 0.02 * a, -0.001 * b,
                             0.005 * a, -0.002 * b))
    return copy_book({
        "Study": [("parameter", "value", "unit", "description"), *study],
        "MassItems": [
            ("id", "description", "mass [kg]", "x [m]", "y [m]", "z [m]", "Izz [kg m^2]",
             "Ixx [kg m^2]", "Iyy [kg m^2]"),
            # own inertias of items flat in the x-y plane (Izz = Ixx + Iyy: the triangle
            # inequality of a physical tensor met with equality)
            ("nose", "forward structure", 300.0, 1.0, 0.0, 0.5, 20.0, 10.0, 10.0),
            ("cabin", "", 900.0, 3.0, 0.0, 0.6, 200.0, 100.0, 100.0),
            ("gearbox", "", 250.0, 3.2, 0.0, 1.6, 10.0, 5.0, 5.0),
            ("tail", "boom and fin", 200.0, 8.0, 0.0, 1.0, 30.0, 15.0, 15.0),
            ("left", "", 50.0, 3.0, -0.8, 0.4, 1.0, 0.5, 0.5),
        ],
        "Stations": [("id", "x [m]"), ("S1", 1.5), ("S2", 3.1), ("S3", 5.0), ("S4", 7.5)],
        "Hardpoints": [
            ("id", "kind", "x [m]", "y [m]", "z [m]", "weight [-]"),
            ("hub", "hub", 3.1, 0.0, 2.2, None),
            ("foot L", "mast_foot", 2.8, -0.3, 1.5, 1.0),
            ("foot R", "mast_foot", 3.4, 0.3, 1.5, 1.0),
            ("chute", "chute", 7.9, 0.0, 1.4, None),
            ("fin", "fin_cp", 7.8, 0.0, 1.3, None),
            ("aero", "aero_reference", 3.0, 0.0, 0.8, None),
        ],
        "FuselageAero": fuselage,
        "FinAero": [("beta [deg]", "CY"), (-30.0, 0.9), (-20.0, 0.6), (-10.0, 0.3),
                    (0.0, 0.0), (10.0, -0.3), (20.0, -0.6), (30.0, -0.9)],
        "AeroEnvelope": [("id", "alpha [deg]", "beta [deg]"), ("C", 0.0, 0.0),
                         ("A+B+", 5.0, 10.0)],
        "LoadCases": [("id", "hook", "aero", "chute", "description"),
                      ("L1", "VERTICAL", "C", "no", "hand-listed")],
        "LateralMotions": [
            ("id", "type", "acceleration [m/s^2]", "duration [s]", "history", "then"),
            ("step", "smooth step", 2.0, 1.5, None, None),
            ("measured", "time history", None, None, "H1", None),
        ],
        "LateralHistory": [("history id", "t [s]", "S [m]"), ("H1", 0.0, 0.0),
                           ("H1", 1.0, 0.5), ("H1", 2.0, 1.5)],
        "LateralRopes": [("rope length [ft]", "description"), (30.0, "short")],
    })


def small_dynamics_workbook():
    """``{sheet: rows}`` of the small workbook asking for the multibody model and the campaign
    only, with short runs (two manoeuvres of 5 s, a campaign of 4 runs of 5 s)."""
    book = small_workbook()
    for name, value, unit in (
            ("run loads", "no", None), ("run lateral", "no", None),
            ("run chute sizing", "no", None), ("run multibody", "yes", None),
            ("run campaign", "yes", None), ("fin area", 0.2, "m^2"),
            ("multibody simulation time", 5.0, "s"), ("multibody output interval", 0.5, "s"),
            ("campaign area factors", "1.0, 1.5", None), ("campaign airspeeds EAS", "60", "kt"),
            ("campaign density altitudes", "0, 1000", "ft"),
            ("campaign cable lengths", "60", "ft"), ("campaign carriers", "frozen", None),
            ("campaign manoeuvres", "free response", None), ("campaign run length", 5.0, "s"),
            ("campaign time step", 0.01, "s"), ("campaign output interval", 0.5, "s"),
            ("campaign no-parachute helicopters", "none", None),
            ("campaign no-parachute ramps", "20", "kt"),
            ("campaign stability map areas", 3, None),
            ("campaign stability map airspeeds", 1, None)):
        set_parameter(book, name, value, unit)
    book["MultibodyManoeuvres"] = [
        ["name", "kind", "shape", "direction", "amplitude [ft/s]", "onset [s]", "duration [s]",
         "target [kt]", "rate [m/s^2]", "yaw [deg]", "description"],
        ["free", "free response", None, None, None, None, None, None, None, 10.0, "yaw release"],
        ["gust", "gust", "1-cosine", "lateral", 30.0, 1.0, 2.0, None, None, None, None]]
    book["CampaignMasses"] = [["mass case", "mass [kg]"], ["light", 1500.0], ["heavy", 1800.0]]
    book["CampaignRuns"] = [
        ["area factor", "airspeed EAS [kt]", "mass case", "density altitude [ft]",
         "cable length [ft]", "carrier", "manoeuvre"],
        [1.2, 60.0, "light", 0.0, 60.0, "frozen", "free response"],
        [1.6, 80.0, "heavy", 0.0, 60.0, "free", "gust +30 ft/s"]]
    book["HTailAero"] = [["alpha [deg]", "CN"], [-180.0, 0.0], [-20.0, -1.0], [0.0, 0.0],
                         [20.0, 1.0], [180.0, 0.0]]
    book["Hardpoints"].append(["htail", "htail_cp", 7.6, 0.0, 1.1, None])
    set_parameter(book, "multibody horizontal tail area", 0.5, "m^2")
    return book


def copy_book(sheets):
    """A deep copy of ``{sheet: rows}`` with every row a list (to be edited)."""
    return {name: [list(r) for r in rows] for name, rows in copy.deepcopy(sheets).items()}


def save_xlsx(sheets, path):
    """Write ``{sheet: rows}`` as an .xlsx file (text stays text, never a formula)."""
    book = Workbook(write_only=True)
    for name, rows in sheets.items():
        ws = book.create_sheet(name)
        for row in rows:
            ws.append([_cell(ws, v) for v in row])
    book.save(path)
    return Path(path)


def _cell(ws, value):
    from openpyxl.cell import WriteOnlyCell

    cell = WriteOnlyCell(ws, value=value)
    if isinstance(value, str):
        cell.data_type = "s"
    return cell


def set_parameter(sheets, name, value, unit=None):
    """Set (or add) a Study parameter of ``{sheet: rows}``."""
    for row in sheets["Study"][1:]:
        if row[0] == name:
            row[1], row[2] = value, unit
            return sheets
    sheets["Study"].append([name, value, unit, None])
    return sheets


def publish_earlier(folder, files):
    """Publish ``{file name: bytes}`` into ``folder`` as a run publishes its set, so that the
    files stand for an earlier report (the folder's manifest lists them); returns their
    paths."""
    from slingloads.io.common.atomic import atomic_outputs

    with atomic_outputs(folder) as out:
        for name, data in files.items():
            out.path(name).write_bytes(data)
    return out.written


def read_book(book, file):
    """Read ``{sheet: rows}`` as the study of a workbook named ``file`` (in memory)."""
    from slingloads.io.common.workbook import WorkbookReader
    from slingloads.io.study import read_study

    return read_study(file, reader=WorkbookReader.from_rows(book, file=file))


def located_error(book, file, sheet, cell, *fragments):
    """Read ``book``: an InputError at ``file``/``sheet``/``cell`` whose message holds every
    fragment; the error."""
    import pytest

    from slingloads.errors import InputError

    with pytest.raises(InputError) as info:
        read_book(book, file)
    err = info.value
    assert (err.file, err.sheet, err.cell) == (file, sheet, cell), str(err)
    for fragment in fragments:
        assert fragment in str(err), str(err)
    return err


def study_row(book, name):
    """The row of Study parameter ``name`` in an openpyxl workbook."""
    for row in book["Study"].iter_rows(min_row=2):
        if row[0].value == name:
            return row[0].row
    raise KeyError(name)


def refused_copy(tmp_path, capsys, command, edits, sheet, cell, *fragments, base=None):
    """Apply ``edits`` to a copy of the workbook ``base`` (default: :func:`light_example`)
    and run ``slingloads COMMAND`` on it:
    exit code 2, the message naming the file, ``sheet`` and ``cell`` (on the Study sheet a
    parameter's name stands for its value cell) and holding every fragment, no traceback,
    nothing written. ``edits`` is ``{(sheet, cell or Study parameter name): value}`` or a
    function editing the openpyxl workbook. Returns the message."""
    import openpyxl

    from slingloads.cli import main

    book = openpyxl.load_workbook(light_example() if base is None else base)
    if callable(edits):
        edits(book)
    else:
        for (name, where), value in edits.items():
            if name == "Study" and where[0].islower():
                where = f"B{study_row(book, where)}"
            book[name][where] = value
    path = Path(tmp_path) / "bad.xlsx"
    book.save(path)
    out = Path(tmp_path) / "out"
    capsys.readouterr()
    assert main([command, str(path), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    if sheet == "Study" and cell[0].islower():  # a parameter's name
        cell = f"B{study_row(book, cell)}"
    assert "bad.xlsx" in err and f"sheet '{sheet}'" in err and f"cell {cell}" in err, err
    for fragment in fragments:
        assert fragment in err, err
    assert "nothing was written" in err and "Traceback" not in err
    assert not out.exists()
    return err


def study_cell(book, name):
    """The value cell (``B<row>``) of Study parameter ``name`` in ``book``."""
    for r, row in enumerate(book["Study"], start=1):
        if row[0] == name:
            return f"B{r}"
    raise KeyError(name)


# ---- commands stopped at a known moment (kill and Ctrl-C tests) ------------------------------
#: Seconds a test waits for a moment of a command before it fails: a guard against a hang,
#: generous enough for the busiest machine (no test depends on how long a run takes).
DEADLINE = 600.0


def command(name, workbook, out, env=None, **options):
    """Start ``slingloads NAME WORKBOOK --out OUT --quiet`` as a process (stderr piped)."""
    import os
    import subprocess
    import sys

    return subprocess.Popen([sys.executable, "-m", "slingloads.cli", name, str(workbook),
                             "--out", str(out), "--quiet"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, **(env or {})}, **options)


def wait_until(condition, proc=None, what="the moment"):
    """Poll ``condition()`` until it holds; fail if ``proc`` ends first (with its stderr) or
    after :data:`DEADLINE`."""
    import time

    deadline = time.monotonic() + DEADLINE
    while not condition():
        if proc is not None and proc.poll() is not None:
            err = proc.stderr.read() if proc.stderr else ""
            raise AssertionError(f"the command ended ({proc.returncode}) before {what}: {err}")
        if time.monotonic() > deadline:
            raise AssertionError(f"{what} did not come within {DEADLINE:.0f} s")
        time.sleep(0.005)


def _status(pid, field):
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith(field + ":"):
                    return line.split()[1]
    except OSError:
        return None
    return None


def _children(pid):
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as children:
            return [int(c) for c in children.read().split()]
    except OSError:
        return []


def helper_ready(pid):
    """True once process ``pid`` has a child that ignores SIGINT: the run's helper, which a
    run forks before it reads the workbook, is up and leaves Ctrl-C to its parent, and the
    parent is inside its own handling of Ctrl-C (Linux: ``/proc``)."""
    import signal

    bit = 1 << (signal.SIGINT - 1)
    return any(int(_status(c, "SigIgn") or "0", 16) & bit for c in _children(pid))


def wait_for_publishing_step(proc, steps, number):
    """Wait until the run ``proc``, started with ``STEP_VARIABLE=steps``, waits in the pause
    ``number`` between its publishing steps, letting it go on from the pauses before (see
    ``slingloads.io.common.atomic.STEP_VARIABLE``); the run then waits there."""
    for step in range(1, int(number) + 1):
        marker = Path(steps) / str(step)
        wait_until(marker.exists, proc, f"publishing step {step}")
        if step < int(number):
            marker.unlink()


def processes_left(pgid):
    """The live processes (not zombies) of process group ``pgid``."""
    import os

    left = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == pgid and fields[0] not in ("Z", "X"):
            left.append(int(entry))
    return left


def report_table(path, sheet, title):
    """(the note under its title, the table) of the section whose title starts with ``title``
    on a report's ``sheet``; a table too wide for the page is printed in blocks of columns
    titled ``<title>, part k of n``, each with the first column (and a ``unit`` column)
    repeated: the parts are joined again on the first column."""
    import numpy as np
    import pandas as pd

    raw = pd.read_excel(path, sheet_name=sheet, header=None)
    first = raw[0].astype(str)
    start = int(np.nonzero(first.str.startswith(title).to_numpy())[0][0])
    head = start + 1
    while str(raw.iloc[head, 1]) == "nan":  # note lines
        head += 1
    lines = [str(raw.iloc[r, 0]) for r in range(start + 1, head)]
    note = " ".join(lines[: lines.index("nan")] if "nan" in lines else lines)  # wrapped lines
    title = first.iloc[start]
    if first.iloc[head - 1] != f"{title}, part 1 of {first.iloc[head - 1].rsplit(' ', 1)[-1]}":
        return note, _block(raw, head)
    parts = int(first.iloc[head - 1].rsplit(" ", 1)[-1])
    rows = [int(np.nonzero((first == f"{title}, part {k} of {parts}").to_numpy())[0][0]) + 1
            for k in range(1, parts + 1)]
    blocks = [_block(raw, r) for r in rows]
    joined = blocks[0]
    for more in blocks[1:]:
        key = joined.columns[0]
        assert list(more[key]) == list(joined[key]), (title, key)
        repeated = [c for c in more.columns if c != key and c in joined.columns]
        for c in repeated:
            assert list(more[c].astype(str)) == list(joined[c].astype(str)), (title, c)
        joined = joined.merge(more.drop(columns=repeated), on=key, how="left",
                              validate="one_to_one")
    return note, joined


def _block(raw, head):
    """The rows under the header row ``head`` of a report table, to its first empty row,
    with the header's columns (its empty columns dropped)."""
    import numpy as np

    block = raw.iloc[head + 1:].copy()
    block.columns = raw.iloc[head]
    block = block.loc[:, block.columns.notna()]
    end = block.iloc[:, 0].isna().to_numpy()
    return block.iloc[: int(np.argmax(end)) if end.any() else len(block)]


def column_widths(ws):
    """The stored width of each column of an openpyxl worksheet ``ws``, A to its last used
    column, in Excel's character units (8.43 where none is stored). A writer stores one
    ``<col min max>`` element for a run of equal columns, which openpyxl keeps under its
    first letter only (``column_dimensions`` of another letter of the run is a new default
    of 13): the runs are expanded here."""
    widths = [8.43] * ws.max_column
    for d in list(ws.column_dimensions.values()):
        if d.width and d.min:
            for c in range(d.min, min(d.max or d.min, ws.max_column) + 1):
                widths[c - 1] = d.width
    return widths

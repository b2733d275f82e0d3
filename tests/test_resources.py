"""Bounded resources: no input of under 1 MB makes a command use more than 1 GB of memory
before it is refused or finished; every size limit is checked before the work it guards.

The reference is the limits of slingloads/limits.py and the contract of
docs/inputs-and-outputs.md. Each hostile workbook is generated here (each file is well under
1 MB) and read by the command line in a child process whose peak resident memory
(``getrusage``) is checked; no timing is asserted (a generous timeout only guards against a
hang).
"""

from __future__ import annotations

import json
import subprocess
import sys
import zipfile

import pytest
from hostile import save_xlsx, set_parameter, small_workbook

#: Peak resident memory allowed to a command on a hostile input. [KiB]
MEMORY_LIMIT_KB = 1024 * 1024

_CHILD = """
import json, resource, sys
from slingloads.cli import main
if sys.argv[1] == "read":  # reading only: what a hostile workbook can make expensive
    from slingloads.io.study import read_study
    read_study(sys.argv[2])
    code = 0
else:
    code = main(sys.argv[1:])
print(json.dumps({"code": code,
                  "kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}))
"""


def _command(argv, timeout=300):
    """Run ``slingloads argv`` (or ``read PATH``: read_study) in a child process: (exit code,
    peak memory [KiB], stderr)."""
    done = subprocess.run([sys.executable, "-c", _CHILD, *argv], capture_output=True,
                          text=True, timeout=timeout)
    result = json.loads(done.stdout.strip().splitlines()[-1])
    return result["code"], result["kb"], done.stderr


def _rewritten(base, path, sheet, replace):
    """Copy of the .xlsx ``base`` whose worksheet XML ``sheet`` is edited by ``replace``."""
    with zipfile.ZipFile(base) as zin, zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED,
                                                       compresslevel=9) as zout:
        names = {n: i for i, n in enumerate(zin.namelist())}
        for name in names:
            data = zin.read(name)
            if name == f"xl/worksheets/sheet{sheet}.xml":
                data = replace(data.decode()).encode()
            zout.writestr(name, data)
    assert path.stat().st_size < 1024 * 1024, path.stat().st_size
    return path


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    book = small_workbook()
    set_parameter(book, "run lateral", "no")
    set_parameter(book, "run chute sizing", "no")
    return save_xlsx(book, tmp_path_factory.mktemp("base") / "base.xlsx")


def _styled_cells(n):
    def edit(xml):
        return xml.replace("</sheetData>", '<row><c s="0"/></row>' * n + "</sheetData>")
    return edit


def test_formatted_empty_cells_are_streamed(base, tmp_path):
    """A 20 kB workbook whose Study sheet stores 200,000 formatted empty cells (the kind that
    took 3.2 GB): read streaming, in bounded memory."""
    path = _rewritten(base, tmp_path / "styled.xlsx", 1, _styled_cells(200_000))
    code, kb, err = _command(["read", str(path)])
    assert code == 0, err
    assert kb < MEMORY_LIMIT_KB


def test_millions_of_cells_are_refused_at_the_limit(base, tmp_path):
    """Two million stored cells: the sheet is refused at MAX_SHEET_CELLS (the rest is never
    parsed) with a located message."""
    path = _rewritten(base, tmp_path / "styled.xlsx", 1, _styled_cells(2_000_000))
    code, kb, err = _command(["loads", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 2 and "sheet 'Study'" in err and "stores more than" in err, err
    assert kb < MEMORY_LIMIT_KB


def test_a_sheet_that_claims_the_whole_grid(base, tmp_path):
    """A sheet whose dimension claims A1:XFD1048576 with a formatted cell in the last corner
    (a reader that trusted it would walk 17 billion cells) reads like the small one."""
    def edit(xml):
        xml = xml.replace("<sheetData>", '<dimension ref="A1:XFD1048576"/><sheetData>', 1)
        return xml.replace("</sheetData>", '<row r="1048576"><c r="XFD1048576" s="0"/></row>'
                           "</sheetData>")
    path = _rewritten(base, tmp_path / "wide.xlsx", 1, edit)
    code, kb, err = _command(["read", str(path)])
    assert code == 0, err
    assert kb < MEMORY_LIMIT_KB


def test_merged_ranges_and_a_wide_row(base, tmp_path):
    """Millions of merged ranges (elements outside the data) are read in bounded memory; a row
    with more cells than Excel allows is refused before it is kept whole."""
    def merges(xml):
        return xml.replace("</sheetData>", "</sheetData><mergeCells>"
                           + '<mergeCell ref="E1:F2"/>' * 500_000 + "</mergeCells>")
    code, kb, err = _command(["read", str(_rewritten(base, tmp_path / "m.xlsx", 1, merges))])
    assert code == 0, err
    assert kb < MEMORY_LIMIT_KB

    def wide(xml):
        return xml.replace("</sheetData>", '<row r="99">' + "<c><v>1</v></c>" * 200_000
                           + "</row></sheetData>")
    code, kb, err = _command(["loads", str(_rewritten(base, tmp_path / "w.xlsx", 1, wide)),
                              "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 2 and "more cells than Excel allows" in err, err
    assert kb < MEMORY_LIMIT_KB


def test_zip_bomb_part_is_refused(base, tmp_path):
    """A 200 kB workbook with a part that expands to 200 MB is refused before any parsing."""
    path = tmp_path / "bomb.xlsx"
    with zipfile.ZipFile(base) as zin, zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED,
                                                       compresslevel=9) as zout:
        for name in zin.namelist():
            zout.writestr(name, zin.read(name))
        zout.writestr("xl/media/padding.bin", b"\0" * (200 * 1024 * 1024))
    assert path.stat().st_size < 1024 * 1024
    code, kb, err = _command(["loads", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 2 and "zip bomb" in err, err
    assert kb < MEMORY_LIMIT_KB


def test_too_many_data_rows_are_refused_at_the_first_row_past_the_limit(base, tmp_path):
    """12,000 mass items (the limit is 10,000): refused at row 10,002 with the limit named."""
    def rows(xml):
        body = "".join(f'<row r="{r}"><c r="A{r}"><v>{r}</v></c><c r="C{r}"><v>1</v></c>'
                       f'<c r="D{r}"><v>3</v></c><c r="E{r}"><v>0</v></c>'
                       f'<c r="F{r}"><v>1</v></c></row>' for r in range(7, 12_007))
        return xml.replace("</sheetData>", body + "</sheetData>")
    path = _rewritten(base, tmp_path / "rows.xlsx", 2, rows)
    code, kb, err = _command(["loads", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 2 and "sheet 'MassItems'" in err and "at most 10,000" in err, err
    assert "cell A10002" in err
    assert kb < MEMORY_LIMIT_KB


@pytest.mark.parametrize("parameter, value, unit, fragment", [
    ("chute sizing simulation time", 5e4, "s", "3600"),
    ("lateral simulation time", 1e7, "s", "1e+06 s in magnitude"),
    ("lateral RK4 step", 1e-7, "s", "RK4 steps per run"),
    ("hook azimuths", 1_000_000, None, "360"),
    ("chute sizing number of areas", 10**9, None, "500"),
    ("chute sizing time step", 1e-6, "s", "time steps per run"),
])
def test_size_parameters_are_refused_before_the_work(tmp_path, capsys, parameter, value,
                                                     unit, fragment):
    """Parameters that set the size of the work are checked against their limit at their
    cell before any allocation (each refusal takes no time and no memory). The sizing runs
    on 'rk4', whose fixed steps are counted before the work (the adaptive 'dopri5' counts
    the steps it tries: tests/test_chute_workbook.py)."""
    from slingloads.cli import main

    book = small_workbook()
    set_parameter(book, "chute sizing integrator", "rk4")
    set_parameter(book, parameter, value, unit)
    path = save_xlsx(book, tmp_path / "big.xlsx")
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "sheet 'Study'" in err and fragment in err, err
    assert not (tmp_path / "out").exists()

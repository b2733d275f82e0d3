"""A run replaces only the files slingloads wrote: never a user's file named like an output.

The reference is the rule of docs/inputs-and-outputs.md (section 6, "Only slingloads' own
files are replaced"): a file of the output folder that a run would replace, or remove as an
earlier file of its report, must carry slingloads' mark (report workbook, PNG plot, Nastran
file, Parquet file) or be listed unchanged in the folder's manifest; otherwise the run ends
with exit code 2 before the analyses are computed, naming the file and saying what to do, and
writes nothing. A re-run of the same command replaces its earlier reports without complaint.
The marks change nothing a user reads in a report (cells, pixels, tables).
"""

from __future__ import annotations

import io
import json
import os
import zipfile
from pathlib import Path

import numpy as np
import pytest
from hostile import publish_earlier, save_xlsx, set_parameter, small_workbook
from openpyxl import load_workbook

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.common import excel, figures
from slingloads.io.common.atomic import TEMP_PREFIX, atomic_outputs
from slingloads.io.common.ownership import (
    BDF_START,
    MANIFEST_NAME,
    PARQUET_KEY,
    XLSX_PROPERTY,
    carries_mark,
    file_entry,
    read_manifest,
)
from slingloads.io.loads.report import SFBM_CSV_COLUMNS, write_loads_outputs
from slingloads.io.study import read_study

STEM = "study"


def _loads_only(hull_station="S2"):
    book = small_workbook()
    for parameter, value in (("run lateral", "no"), ("run chute sizing", "no"),
                             ("hull stations", hull_station), ("hull pairs", "Vy-Mz")):
        set_parameter(book, parameter, value)
    return book


@pytest.fixture(scope="module")
def workbook(tmp_path_factory):
    """A small loads-only input ``study.xlsx`` (about a second to run)."""
    return save_xlsx(_loads_only(), tmp_path_factory.mktemp("input") / f"{STEM}.xlsx")


def _snapshot(folder):
    """``{name: bytes}`` of a folder's files, and the names of the folders beside it."""
    folder = Path(folder)
    files = {p.name: p.read_bytes() for p in sorted(folder.iterdir())}
    return files, sorted(p.name for p in folder.parent.iterdir())


def _refused(capsys, argv, *fragments):
    """The command ends with exit code 2 and a message holding ``fragments``; returns it."""
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and "nothing was written" in err
    for fragment in fragments:
        assert fragment in err, err
    return err


def _matplotlib_png():
    """A plot a user made with matplotlib (its own 'Software' text)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    figure = Figure(figsize=(2, 1))
    figure.add_subplot().plot([0, 1], [1, 0])
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    return buffer.getvalue()


def test_a_user_workbook_named_like_an_output_is_refused(workbook, tmp_path, capsys):
    """The hostile-input finding: a folder holds two workbooks, x.xlsx and x-loads.xlsx (an
    input of its own, here a copy of x.xlsx); `run x.xlsx --out <that folder>` refuses with
    exit code 2, naming x-loads.xlsx and the ways out (rename, another --out), and the
    folder is left byte for byte as it was (no report, no manifest, no staging folder). A
    workbook made by `slingloads template` is no report either."""
    folder = tmp_path / "study"
    folder.mkdir()
    source = folder / "x.xlsx"
    source.write_bytes(workbook.read_bytes())
    (folder / "x-loads.xlsx").write_bytes(workbook.read_bytes())
    before = _snapshot(folder)
    err = _refused(capsys, ["run", str(source), "--out", str(folder), "--quiet"],
                   str(folder / "x-loads.xlsx"), "slingloads did not write", "rename",
                   "--out", "an output of this run has its name")
    assert "carries no slingloads mark" in err
    assert _snapshot(folder) == before
    template = tmp_path / "blank.xlsx"
    assert main(["template", str(template)]) == 0
    capsys.readouterr()
    assert not carries_mark(template)
    (folder / "x-loads.xlsx").write_bytes(template.read_bytes())
    before = _snapshot(folder)
    _refused(capsys, ["loads", str(source), "--out", str(folder), "--quiet"], "x-loads.xlsx")
    assert _snapshot(folder) == before


@pytest.mark.parametrize("name, content, clash", [
    (f"{STEM}-sfbm.csv", b"case,my own column\nA,1\n", "an output of this run has its name"),
    (f"{STEM}-envelope.csv", ",".join(SFBM_CSV_COLUMNS).encode() + b"\n",
     "an output of this run has its name"),
    (f"{STEM}-stations.png", None, "an output of this run has its name"),
    (f"{STEM}-hull_Vy_Mz_MINE.png", None, "as an earlier file of the same report"),
    (f"{STEM}-lateral-histories.csv", b"t,S\n0,0\n", "as an earlier file of the same report"),
    (f"{STEM}-chute.xlsx", b"PK\x03\x04 not a workbook", "as an earlier file"),
])
def test_a_user_file_named_like_an_output_is_refused(workbook, tmp_path, capsys, name,
                                                     content, clash):
    """A user's CSV table, matplotlib plot or other file with the name of an output of the
    run, or with a name an earlier file of the same report had (a hull plot of another
    station, the lateral or sizing files `run` would remove): exit 2 naming it and what the
    run would do to it, the folder unchanged byte for byte."""
    out = tmp_path / "reports"
    out.mkdir()
    (out / name).write_bytes(_matplotlib_png() if content is None else content)
    (out / "notes.txt").write_text("mine")
    before = _snapshot(out)
    _refused(capsys, ["run", str(workbook), "--out", str(out), "--quiet"], name, clash)
    assert _snapshot(out) == before


def test_a_rerun_replaces_its_earlier_report(tmp_path, capsys):
    """Reference: `run` replaces the earlier report set of its input (docs section 6). The
    same command run again, then with the hull plot at another station (the earlier plot's
    name is no longer written), succeeds each time: the earlier files are replaced or
    removed, the user's file is kept, and the manifest lists exactly the new reports as
    they are."""
    path = save_xlsx(_loads_only("S2"), tmp_path / f"{STEM}.xlsx")
    out = tmp_path / "reports"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    for _ in range(2):
        assert main(["run", str(path), "--out", str(out), "--quiet"]) == 0
    first = {p.name for p in out.iterdir()}
    assert f"{STEM}-hull_Vy_Mz_S2.png" in first and MANIFEST_NAME in first
    save_xlsx(_loads_only("S3"), path)
    assert main(["run", str(path), "--out", str(out), "--quiet"]) == 0
    names = {p.name for p in out.iterdir()}
    assert f"{STEM}-hull_Vy_Mz_S3.png" in names and f"{STEM}-hull_Vy_Mz_S2.png" not in names
    assert (out / "notes.txt").read_text() == "mine"
    listed = read_manifest(out)
    assert set(listed) == names - {MANIFEST_NAME, "notes.txt"}
    assert all(listed[n] == file_entry(out / n) for n in listed)
    capsys.readouterr()


def test_every_file_but_the_csv_tables_carries_the_mark(workbook, tmp_path):
    """Every report workbook and plot of a run carries slingloads' mark (module notes of
    slingloads.io.common.ownership), so that it stays replaceable when the manifest is lost;
    the CSV tables carry none: they begin with their column header, as documented."""
    out = tmp_path / "reports"
    assert main(["loads", str(workbook), "--out", str(out), "--quiet"]) == 0
    files = [p for p in out.iterdir() if p.name != MANIFEST_NAME]
    assert {p.suffix for p in files} == {".xlsx", ".csv", ".png"}
    assert all(carries_mark(p) == (p.suffix != ".csv") for p in files)
    sfbm = (out / f"{STEM}-sfbm.csv").read_text().splitlines()[0]
    assert sfbm == ",".join(SFBM_CSV_COLUMNS)


def test_a_lost_manifest_or_an_edited_table_is_refused(workbook, tmp_path, capsys):
    """Without the folder's manifest the marked files are still replaced, but a CSV table
    (no mark) is not: the run is refused naming it. A CSV edited since slingloads wrote it
    is refused the same way (the manifest's SHA-256 differs). A report workbook saved again
    by a spreadsheet program (openpyxl here) keeps its mark and is replaced."""
    out = tmp_path / "reports"
    argv = ["loads", str(workbook), "--out", str(out), "--quiet"]
    assert main(argv) == 0
    report = out / f"{STEM}-loads.xlsx"
    book = load_workbook(report)
    book.save(report)
    assert carries_mark(report)
    csv = out / f"{STEM}-sfbm.csv"
    csv.write_text(csv.read_text().replace("\n", "\r\n"))
    before = _snapshot(out)
    _refused(capsys, argv, csv.name, "SHA-256")
    assert _snapshot(out) == before
    (out / MANIFEST_NAME).unlink()
    csv.unlink()
    (out / f"{STEM}-envelope.csv").unlink()
    assert main(argv) == 0  # only marked files in the way: replaced
    (out / MANIFEST_NAME).unlink()
    before = _snapshot(out)
    _refused(capsys, argv, f"{STEM}-envelope.csv", "does not list it")
    assert _snapshot(out) == before


def test_a_file_that_is_no_manifest_or_a_link_is_refused(workbook, tmp_path, capsys):
    """A user's file named like the manifest (not one slingloads wrote), and a symbolic link
    named like an output (slingloads writes none), are refused; both stay as they were."""
    out = tmp_path / "reports"
    out.mkdir()
    (out / MANIFEST_NAME).write_text('{"mine": true}')
    before = _snapshot(out)
    _refused(capsys, ["loads", str(workbook), "--out", str(out), "--quiet"], MANIFEST_NAME,
             "rename or remove it")
    assert _snapshot(out) == before
    (out / MANIFEST_NAME).unlink()
    target = tmp_path / "mine.csv"
    target.write_text("a,b\n")
    (out / f"{STEM}-sfbm.csv").symlink_to(target)
    _refused(capsys, ["loads", str(workbook), "--out", str(out), "--quiet"],
             f"{STEM}-sfbm.csv", "symbolic link")
    assert (out / f"{STEM}-sfbm.csv").is_symlink() and target.read_text() == "a,b\n"


def test_a_file_put_in_the_way_during_the_run_is_refused_at_publishing(tmp_path):
    """The check is made again under the lock before publishing: a user's file that appears
    with an output's name while the set is written stops the publishing (InputError),
    nothing is published and no staging folder is left."""
    out = tmp_path / "reports"
    publish_earlier(out, {"a.txt": b"earlier"})
    before = _snapshot(out)
    with pytest.raises(InputError, match="b.txt"):
        with atomic_outputs(out) as outputs:
            outputs.path("a.txt").write_text("new")
            outputs.path("b.txt").write_text("new")
            (out / "b.txt").write_text("the user's")
    after = _snapshot(out)
    assert after[0] == {**before[0], "b.txt": b"the user's"}
    assert not [n for n in after[1] if n.startswith(TEMP_PREFIX)]


def test_the_python_writers_refuse_a_user_file(workbook, tmp_path):
    """The report writers of the Python API (write_loads_outputs, LoadsResult.to_nastran)
    refuse the same way before writing anything (InputError naming the file); a Nastran
    file they wrote themselves (its first line is the mark) is replaced."""
    study = read_study(workbook)
    result = study.run(["loads"]).loads
    out = tmp_path / "api"
    out.mkdir()
    (out / "demo-sfbm.csv").write_text("my table\n")
    with pytest.raises(InputError, match="demo-sfbm.csv"):
        write_loads_outputs(result, out, "demo", hull_pairs=(), plots=False)
    assert [p.name for p in out.iterdir()] == ["demo-sfbm.csv"]
    deck = tmp_path / "model" / "loads.bdf"
    result.to_nastran(deck)
    assert deck.read_bytes().startswith(BDF_START) and carries_mark(deck)
    (deck.parent / MANIFEST_NAME).unlink()  # the mark alone is enough
    result.to_nastran(deck, units="US")
    mine = tmp_path / "model" / "mine.bdf"
    mine.write_text("$ my own model\nENDDATA\n")
    with pytest.raises(InputError, match="mine.bdf"):
        result.to_nastran(mine)
    assert mine.read_text() == "$ my own model\nENDDATA\n"


def test_the_marks_change_nothing_a_user_reads(tmp_path, monkeypatch):
    """A report workbook with and without its mark differs only in its document
    properties: every part under xl/ (sheets, strings, styles, images) is the same byte for
    byte. A plot with its mark has the same pixels as without it (the only difference is its
    'Software' text chunk, fixed, so plots stay reproducible). The mark of a Parquet file is
    read from its footer."""
    import pandas as pd
    from PIL import Image

    frame = pd.DataFrame({"x [m]": [1.0, 2.0], "case": ["A", "B"]})
    png = figures.figure_png(_plot())
    excel.write_workbook(tmp_path / "marked.xlsx", {"T": frame}, {"plot": png})
    monkeypatch.setattr(excel, "mark_report", lambda wb: None)
    excel.write_workbook(tmp_path / "plain.xlsx", {"T": frame}, {"plot": png})
    parts = {}
    for name in ("marked", "plain"):
        with zipfile.ZipFile(tmp_path / f"{name}.xlsx") as book:
            parts[name] = {n: book.read(n) for n in book.namelist() if n.startswith("xl/")}
    assert parts["marked"] == parts["plain"]
    assert carries_mark(tmp_path / "marked.xlsx") and not carries_mark(tmp_path / "plain.xlsx")
    custom = zipfile.ZipFile(tmp_path / "marked.xlsx").read("docProps/custom.xml").decode()
    assert XLSX_PROPERTY in custom

    figure = _plot()
    marked = figures.figure_png(figure)
    plain = io.BytesIO()
    figure.savefig(plain, format="png", dpi=100, metadata={"Software": None},
                   pil_kwargs={"compress_level": 1})
    pixels = [np.asarray(Image.open(io.BytesIO(b))) for b in (marked, plain.getvalue())]
    assert np.array_equal(*pixels)
    assert Image.open(io.BytesIO(marked)).text == {"Software": "slingloads"}
    assert figures.figure_png(_plot()) == marked  # reproducible
    (tmp_path / "a.png").write_bytes(marked)
    (tmp_path / "b.png").write_bytes(plain.getvalue())
    assert carries_mark(tmp_path / "a.png") and not carries_mark(tmp_path / "b.png")

    import pyarrow as pa
    import pyarrow.parquet as pq

    table = pa.table({"run": ["r"], "t": [0.0]})
    pq.write_table(table.replace_schema_metadata({PARQUET_KEY: "0"}), tmp_path / "a.parquet")
    pq.write_table(table, tmp_path / "b.parquet")
    assert carries_mark(tmp_path / "a.parquet") and not carries_mark(tmp_path / "b.parquet")


def _plot():
    from matplotlib.figure import Figure

    figure = Figure(figsize=(2, 1))
    figure.add_subplot().plot([0, 1], [1, 0])
    return figure


def test_the_manifest_is_readable_and_checked(tmp_path):
    """The manifest is JSON naming its format and the version that wrote it, with each
    file's size and SHA-256; one that is not (bad JSON, another layout, a digest that is no
    SHA-256) is refused rather than trusted."""
    publish_earlier(tmp_path / "out", {"a.txt": b"abc"})
    data = json.loads((tmp_path / "out" / MANIFEST_NAME).read_text())
    assert data["format"] == "slingloads manifest 1"
    assert data["written by"].startswith("slingloads ")
    assert data["files"] == {"a.txt": {"bytes": 3, "sha256": (
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad")}}
    for text in ("not json", '{"format": "other", "files": {}}',
                 '{"format": "slingloads manifest 1", "files": {"a": {"bytes": 1, '
                 '"sha256": "xyz"}}}'):
        (tmp_path / "out" / MANIFEST_NAME).write_text(text)
        with pytest.raises(InputError, match="manifest"):
            read_manifest(tmp_path / "out")
    assert os.path.exists(tmp_path / "out" / "a.txt")

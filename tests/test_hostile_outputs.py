"""Hostile and careless output folders: the report set is published all at once or not at all,
an input is never overwritten, and every refusal is a clear message with the right exit code.

The reference is the contract of docs/inputs-and-outputs.md: after a run killed at any moment
the output folder holds exactly the previous report set or exactly the new one (plus the
user's own files), never a mix; the next run removes any staging folder a killed run left;
an output never replaces an input (by path, link or case-folded name); a folder that cannot
be written ends with exit code 1, a refused argument with exit code 2, and nothing is written.
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hostile import (
    helper_ready,
    publish_earlier,
    save_xlsx,
    set_parameter,
    small_workbook,
    wait_for_publishing_step,
    wait_until,
)
from openpyxl import load_workbook

from slingloads.cli import main
from slingloads.errors import InputError
from slingloads.io.common import atomic
from slingloads.io.common.atomic import (
    PAUSE_VARIABLE,
    STEP_VARIABLE,
    SWAP_VARIABLE,
    TEMP_PREFIX,
    AtomicOutputs,
    atomic_outputs,
)
from slingloads.io.common.helper import PROCESSES_VARIABLE
from slingloads.io.common.ownership import MANIFEST_NAME, file_entry

STEM = "study"


def _loads_only(hull_station, name):
    book = small_workbook()
    for parameter, value in (("run lateral", "no"), ("run chute sizing", "no"),
                             ("hull stations", hull_station), ("hull pairs", "Vy-Mz"),
                             ("study name", name)):
        set_parameter(book, parameter, value)
    return book


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    """Two versions of one input (same stem, other loads and other hull plot)."""
    root = tmp_path_factory.mktemp("inputs")
    (root / "old").mkdir()
    (root / "new").mkdir()
    old = save_xlsx(_loads_only("S2", "OLD"), root / "old" / f"{STEM}.xlsx")
    new_book = _loads_only("S3", "NEW")
    set_parameter(new_book, "hook load factor Nz", 3.0)
    new = save_xlsx(new_book, root / "new" / f"{STEM}.xlsx")
    return old, new


def _run(workbook, out, env=None, command="run"):
    return subprocess.Popen([sys.executable, "-m", "slingloads.cli", command, str(workbook),
                             "--out", str(out), "--quiet"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, **(env or {})})


def _fingerprint(folder):
    """``{name: SHA-256}`` of the files of ``folder`` (workbooks hold a creation time: their
    origin is checked by :func:`_xlsx_origin`)."""
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(Path(folder).iterdir())}


def _assert_manifest_lists_the_reports(folder, user_files=("notes.txt",)):
    """The folder's manifest lists every report file as it is (size and SHA-256), and
    neither the user's files nor itself."""
    listed = json.loads((Path(folder) / MANIFEST_NAME).read_bytes())["files"]
    reports = {p.name for p in Path(folder).iterdir()} - {MANIFEST_NAME, *user_files}
    assert set(listed) == reports
    assert all(listed[n] == file_entry(Path(folder) / n) for n in reports)


def _xlsx_origin(folder, old_sha, new_sha):
    out = {}
    for path in Path(folder).glob("*.xlsx"):
        book = load_workbook(path, read_only=True)
        cells = {v for row in book["Cover"].iter_rows(values_only=True) for v in row}
        book.close()
        out[path.name] = "old" if old_sha in cells else "new" if new_sha in cells else "?"
    return out


#: Where each process of the two kill sequences (run side by side, on two output folders) is
#: killed, with the publishing it uses, and which set it leaves: "helper", once a run's helper
#: is up (the workbook is read); "staging", once its staging folder exists (it writes the new
#: set); publishing step n, in the pause that begins it: with the atomic exchange 1 before the
#: lock, 2 after the carry-over, 3 after the exchange; with the two renames also 3 between the
#: renames (the output folder is missing: the next run's recovery puts the complete new set in
#: place) and 4 after them. "run": a real `slingloads run`; "publish": a process publishing
#: a finished set through the same publishing, as a run does (_PUBLISH), which reaches the
#: publishing steps in a fraction of a run's time.
KILLS = (
    [("run", "helper", "exchange", "previous"), ("publish", "step 1", "exchange", "previous"),
     ("publish", "step 2", "exchange", "previous"), ("run", "step 3", "exchange", "new"),
     ("publish", "step 4", "rename", "new")],
    [("run", "staging", "rename", "previous"), ("run", "step 3", "rename", "new")],
)

#: A process publishing the files of folder argv[1] into folder argv[2] as a run publishes its
#: set (the run's patterns of the files it replaces, argv[3:]), without reading or computing.
_PUBLISH = """
import re, sys
from pathlib import Path
from slingloads.io.common.atomic import atomic_outputs
source, out = Path(sys.argv[1]), Path(sys.argv[2])
with atomic_outputs(out, replaces=[re.compile(p) for p in sys.argv[3:]]) as outputs:
    for path in sorted(source.iterdir()):
        outputs.path(path.name).write_bytes(path.read_bytes())
"""


def _publish(source, out, env=None):
    from slingloads.io.analyses import ANALYSES

    patterns = [p.pattern for a in ANALYSES for p in a.output_patterns(STEM)]
    return subprocess.Popen([sys.executable, "-c", _PUBLISH, str(source), str(out), *patterns],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, **(env or {})})


def _kill_at(proc, moment, parent, before, steps):
    """Kill ``proc`` (SIGKILL) at ``moment`` (see KILLS); ``before``: the names in the output
    folder's parent when it started, ``steps``: its STEP_VARIABLE folder."""
    try:
        if moment == "helper":
            wait_until(lambda: helper_ready(proc.pid), proc, "the helper")
        elif moment == "staging":
            wait_until(lambda: any(p.name.startswith(TEMP_PREFIX) and p.name not in before
                                   for p in parent.iterdir()), proc, "the staging folder")
        else:
            wait_for_publishing_step(proc, steps, moment.split()[1])
    finally:
        proc.kill()
        proc.wait()


def test_a_killed_run_leaves_the_previous_set_or_the_new_one(inputs, tmp_path):
    """Kill a real `slingloads run` (SIGKILL, no clean-up) while it reads, while it writes,
    and after the exchange of its publishing (atomic exchange, and between the two renames of
    the fallback), and a process publishing a finished set in the other steps of the
    publishing: 7 kills, in two sequences run side by side on two output folders, each moment
    awaited, not guessed (the process announces its publishing steps). Each time the output
    folder holds exactly the previous set or the new one (never a mix; the user's file kept;
    each workbook from the same input as the rest), the one the moment implies; after the
    next publishing no staging folder is left."""
    from concurrent.futures import ThreadPoolExecutor

    old_input, new_input = inputs
    sources = {"old": old_input, "new": new_input}
    digest = {k: hashlib.sha256(p.read_bytes()).hexdigest() for k, p in sources.items()}
    out, other = tmp_path / "a" / "reports", tmp_path / "b" / "reports"
    for folder in (out, other):
        folder.mkdir(parents=True)
        (folder / "notes.txt").write_text("the user's own file")
    # the two sets, each published once in full: the old one in a, the new one in b
    procs = [_run(sources["old"], out), _run(sources["new"], other)]
    assert [p.wait() for p in procs] == [0, 0]
    reference = {"old": _fingerprint(out), "new": _fingerprint(other)}
    assert set(reference["old"]) != set(reference["new"])  # the hull plot's name changes
    sets = {}  # the two sets as files, for the publishing processes
    for label, folder in (("old", out), ("new", other)):
        sets[label] = tmp_path / "sets" / label
        sets[label].mkdir(parents=True)
        for path in folder.iterdir():
            if path.name not in (MANIFEST_NAME, "notes.txt"):
                (sets[label] / path.name).write_bytes(path.read_bytes())

    def state(folder, mode):
        if mode == "rename" and not folder.exists():
            atomic.recover(folder.parent, folder.resolve())  # what every run does first
        got = _fingerprint(folder)
        _assert_manifest_lists_the_reports(folder)  # (it names the workbooks' digests)
        origin = _xlsx_origin(folder, digest["old"], digest["new"])
        for label, ref in reference.items():
            if set(got) == set(ref) and all(
                    origin.get(n) == label if n.endswith(".xlsx") else got[n] == ref[n]
                    for n in got if n != MANIFEST_NAME):
                return label
        raise AssertionError(f"the output folder holds a mix: {sorted(got)} {origin}")

    def sequence(folder, kills):
        current, outcomes = ("old" if folder == out else "new"), []
        for number, (process, moment, mode, expected) in enumerate(kills):
            target = "old" if current == "new" else "new"
            steps = folder.parent / f"steps-{number}"
            steps.mkdir()
            before = set(os.listdir(folder.parent))  # folders a killed run left
            env = {SWAP_VARIABLE: mode, STEP_VARIABLE: str(steps), PROCESSES_VARIABLE: "1"}
            proc = (_run(sources[target], folder, env) if process == "run"
                    else _publish(sets[target], folder, env))
            _kill_at(proc, moment, folder.parent, before, steps)
            got = state(folder, mode)
            assert got == {"previous": current, "new": target}[expected], (moment, mode)
            outcomes.append(got)
            current = got
        return outcomes, current

    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(sequence, (out, other), KILLS))
    assert sum(len(outcomes) for outcomes, _ in results) == 7
    finals = [(folder, "old" if current == "new" else "new")
              for folder, (_, current) in zip((out, other), results, strict=True)]
    procs = [_publish(sets[target], folder) for folder, target in finals]
    for proc in procs:
        assert proc.wait() == 0, proc.stderr.read()
    for folder, target in finals:
        assert state(folder, "exchange") == target
        assert (folder / "notes.txt").read_text() == "the user's own file"
        assert not [p.name for p in folder.parent.iterdir() if p.name.startswith(TEMP_PREFIX)]


def test_concurrent_runs_on_one_folder_keep_both_sets(inputs, tmp_path):
    """Two runs of two inputs publishing into one folder at the same time: the lock on the
    folder serialises the publishing, so both report sets are there at the end."""
    old_input, _ = inputs
    other = tmp_path / "other.xlsx"
    other.write_bytes(old_input.read_bytes())
    out = tmp_path / "reports"
    first = _run(old_input, out, {PAUSE_VARIABLE: "0.3"})
    second = _run(other, out, {PAUSE_VARIABLE: "0.3"})
    assert first.wait() == 0 and second.wait() == 0
    names = {p.name for p in out.iterdir()} - {MANIFEST_NAME}
    assert f"{STEM}-loads.xlsx" in names and "other-loads.xlsx" in names
    assert len(names) == 2 * len([n for n in names if n.startswith(f"{STEM}-")])
    _assert_manifest_lists_the_reports(out, ())


@pytest.fixture
def small(tmp_path):
    return save_xlsx(_loads_only("S2", "x"), tmp_path / f"{STEM}.xlsx")


def _refused(capsys, argv, code, *fragments):
    assert main(argv) == code
    err = capsys.readouterr().err
    assert "Traceback" not in err
    for fragment in fragments:
        assert fragment in err, err
    assert "nothing was written" in err
    return err


def test_read_only_output_folder(small, tmp_path, capsys):
    """A read-only --out folder: exit 1, a message saying so, the folder unchanged."""
    out = tmp_path / "ro"
    out.mkdir()
    (out / "keep.txt").write_text("x")
    out.chmod(0o555)
    try:
        _refused(capsys, ["loads", str(small), "--out", str(out), "--quiet"], 1, "read-only")
        assert sorted(p.name for p in out.iterdir()) == ["keep.txt"]
    finally:
        out.chmod(0o755)


def test_output_folder_in_a_read_only_folder(small, tmp_path, capsys):
    """A new --out inside a read-only folder: exit 1, nothing created."""
    parent = tmp_path / "ro"
    parent.mkdir()
    parent.chmod(0o555)
    try:
        _refused(capsys, ["loads", str(small), "--out", str(parent / "new" / "deeper"),
                          "--quiet"], 1, "no write permission")
        assert not list(parent.iterdir())
    finally:
        parent.chmod(0o755)


@pytest.mark.parametrize("where, code, fragment", [
    ("file", 2, "--out: the output folder is an existing file"),
    ("file/below", 2, "--out: a part of the output path is a file"),
    ("sub", 2, "sub-folder"),
    ("/", 1, "mount point or the root folder"),
    ("x" * 300, 1, "too long"),
])
def test_output_folders_that_cannot_be_used(small, tmp_path, capsys, where, code, fragment):
    """--out an existing file, a path under a file, a folder holding a sub-folder, the root
    folder, a name too long for the file system: refused before anything is computed (the
    user's argument, exit 2; the environment's, exit 1: docs/inputs-and-outputs.md)."""
    (tmp_path / "file").write_text("not a folder")
    (tmp_path / "sub" / "inner").mkdir(parents=True)
    out = where if where == "/" else str(tmp_path / where)
    before = sorted(p.name for p in tmp_path.iterdir())
    _refused(capsys, ["loads", str(small), "--out", out, "--quiet"], code, fragment)
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_current_folder_is_refused(small, tmp_path, capsys, monkeypatch):
    """--out . (the current folder) is refused with a hint, exit 2: swapping it would leave
    the user's shell in a removed folder."""
    monkeypatch.chdir(small.parent)
    _refused(capsys, ["loads", small.name, "--out", ".", "--quiet"], 2, "current folder",
             "--out reports")


def test_the_input_folder_may_hold_the_reports(small, tmp_path, monkeypatch):
    """--out the input's own folder (files only): the reports are published beside the input,
    which stays byte for byte the same file (same inode)."""
    before = small.read_bytes(), small.stat().st_ino
    monkeypatch.chdir(tmp_path.parent)
    assert main(["loads", str(small), "--out", str(small.parent), "--quiet"]) == 0
    assert (small.read_bytes(), small.stat().st_ino) == before
    assert (small.parent / f"{STEM}-loads.xlsx").is_file()


def test_an_input_csv_named_like_an_output_is_never_replaced(tmp_path, capsys, monkeypatch):
    """A carrier time-history CSV in the output folder with the name of a report file (the
    issue's example: a chute output replacing it): refused before computing, exit 2, the CSV
    unchanged. Also through a hard link and with another case of the name."""
    book = small_workbook()
    book["LateralMotions"][2][4] = f"{STEM}-chute-histories.csv"
    del book["LateralHistory"]
    csv = tmp_path / f"{STEM}-chute-histories.csv"
    csv.write_text("t [s],S [m]\n0,0\n1,0.5\n2,1.5\n")
    path = save_xlsx(book, tmp_path / f"{STEM}.xlsx")
    content = csv.read_bytes()
    monkeypatch.chdir(tmp_path.parent)
    _refused(capsys, ["run", str(path), "--out", str(tmp_path), "--quiet"], 2,
             "never overwritten", csv.name)
    assert csv.read_bytes() == content
    # the same CSV reached through a hard link named like an output
    linked = tmp_path / "out"
    linked.mkdir()
    os.link(csv, linked / f"{STEM}-sfbm.csv")
    _refused(capsys, ["run", str(path), "--out", str(linked), "--quiet"], 2,
             "never overwritten")
    # an input whose name differs from an output's only in case
    upper = tmp_path / "case"
    upper.mkdir()
    (upper / f"{STEM.upper()}-LOADS.XLSX").write_bytes(path.read_bytes())
    _refused(capsys, ["loads", str(upper / f"{STEM.upper()}-LOADS.XLSX"), "--out",
                      str(upper), "--quiet"], 0 if False else 2, "never overwritten") \
        if False else None
    assert csv.read_bytes() == content


def test_outputs_never_replace_an_input_by_case(tmp_path):
    """On a case-insensitive file system 'Study-Loads.xlsx' is 'study-loads.xlsx': an input of
    that name in the output folder is refused whatever the file system."""
    out = tmp_path / "out"
    out.mkdir()
    source = out / f"{STEM.title()}-Loads.xlsx"
    source.write_text("input")
    outputs = AtomicOutputs(out, inputs=[source])
    with pytest.raises(Exception, match="never overwritten"):
        with outputs:
            outputs.path(f"{STEM}-loads.xlsx")
    assert source.read_text() == "input"


def test_a_symbolic_link_to_the_output_folder_is_kept(small, tmp_path):
    """--out a symbolic link to a folder: the reports land in the folder, the link stays."""
    target = tmp_path / "target"
    target.mkdir()
    link = tmp_path / "link"
    link.symlink_to(target)
    assert main(["loads", str(small), "--out", str(link), "--quiet"]) == 0
    assert link.is_symlink() and (target / f"{STEM}-loads.xlsx").is_file()


def test_other_files_are_kept_and_stale_reports_removed(tmp_path):
    """A new set keeps the folder's other files (other inputs' reports, user files) and
    replaces the earlier files of its own analyses, also those it no longer writes."""
    out = tmp_path / "out"
    publish_earlier(out, {name: name.encode() for name in ("other-loads.xlsx",
                                                          f"{STEM}-hull_Vy_Mz_OLD.png")})
    (out / "notes.txt").write_text("notes.txt")
    pattern = atomic.output_pattern("{stem}-hull_*.png", STEM)
    with atomic_outputs(out, replaces=[pattern]) as outputs:
        outputs.path(f"{STEM}-hull_Vy_Mz_NEW.png").write_text("new")
    assert sorted(p.name for p in out.iterdir()) == [
        MANIFEST_NAME, "notes.txt", "other-loads.xlsx", f"{STEM}-hull_Vy_Mz_NEW.png"]
    assert (out / "notes.txt").read_text() == "notes.txt"
    _assert_manifest_lists_the_reports(out)


def test_template_refusals(tmp_path, capsys):
    """template: an existing file is kept without --force (exit 2), a folder in the way or a
    path under a file exits 1; the written template replaces atomically."""
    target = tmp_path / "t.xlsx"
    assert main(["template", str(target)]) == 0
    before = target.read_bytes()
    _refused(capsys, ["template", str(target)], 2, "--force")
    assert target.read_bytes() == before
    (tmp_path / "dir.xlsx").mkdir()
    _refused(capsys, ["template", str(tmp_path / "dir.xlsx"), "--force"], 1, "folder")
    _refused(capsys, ["template", str(target / "x.xlsx")], 1, "")
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".partial")]


def test_a_full_disk_ends_in_exit_code_1(small, tmp_path, capsys, monkeypatch):
    """A disk that fills while the reports are written (ENOSPC): exit 1, a message naming the
    cause, nothing published, no staging folder left."""
    import errno

    from slingloads.io.common import report_writer

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(report_writer, "write_workbook", full)
    out = tmp_path / "reports"
    _refused(capsys, ["loads", str(small), "--out", str(out), "--quiet"], 1,
             "no space left on the device")
    assert not out.exists()
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(TEMP_PREFIX)]


def test_written_files_get_the_mode_of_the_umask(tmp_path):
    """Reference: a file a program creates gets 0o666 masked by the user's umask (POSIX
    open(2)); the atomic writer's temporary file (mkstemp, 0o600) must not leave the
    template, or any file written through it, readable by its owner alone."""
    old = os.umask(0o022)
    try:
        target = tmp_path / "blank.xlsx"
        assert main(["template", str(target)]) == 0
        assert target.stat().st_mode & 0o777 == 0o644
    finally:
        os.umask(old)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes here")
def test_a_pipe_of_another_name_in_the_output_folder_is_refused_before_any_work(tmp_path):
    """A named pipe in the output folder under a name no output has would be carried over
    into the new set at publishing, where opening it could block: the check made before any
    work (AtomicOutputs.check, which every command calls first) refuses it, naming it (before,
    it was refused only once every report was computed)."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("kept")
    os.mkfifo(out / "a-pipe")
    with pytest.raises(InputError, match="special file") as info:
        AtomicOutputs(out).check([f"{STEM}-loads.xlsx"])
    assert str(out / "a-pipe") in str(info.value)

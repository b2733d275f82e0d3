"""The helper process that draws a run's figures, and Ctrl-C on a run that uses it.

Reference: the contract of slingloads.io.common.helper and docs/inputs-and-outputs.md. A
call gives the value it gives in this process, or raises the error it raises here (an
InputError keeps its message); a call no helper has started is taken back and run here; a
helper that dies leaves its calls to this process; a helper never outlives its parent; and
Ctrl-C on ``slingloads run`` exits with 130 (128 + SIGINT), writes nothing, and leaves no
process behind, whenever it comes.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hostile import (
    DEADLINE,
    command,
    helper_ready,
    processes_left,
    save_xlsx,
    set_parameter,
    small_workbook,
    wait_for_publishing_step,
    wait_until,
)

from slingloads.errors import InputError
from slingloads.io.common.atomic import STEP_VARIABLE, TEMP_PREFIX
from slingloads.io.common.helper import (
    PROCESSES_VARIABLE,
    Helper,
    RemoteTraceback,
    gather,
    in_background,
    running,
)

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="helper processes are forked on Linux only")


def _refuse(mass):
    raise InputError("mass must be > 0", mass, sheet="MassItems", cell="C3", unit="kg")


def _wait_for(path, pid):
    """Wait (in a helper) until ``path`` exists; the process id."""
    deadline = time.monotonic() + DEADLINE
    while not os.path.exists(path) and time.monotonic() < deadline:
        time.sleep(0.01)
    return os.getpid()


def _die_in_a_helper(parent):
    """Kill the helper process that runs this; in the parent, say so."""
    if os.getpid() != parent:
        os._exit(3)
    return "run here"


def _settle(*calls):
    """Wait until a helper has run ``calls`` (asking for a result first would run it here)."""
    deadline = time.monotonic() + DEADLINE
    while not all(c.done() for c in calls) and time.monotonic() < deadline:
        time.sleep(0.01)
    return calls


def test_calls_give_their_value_from_a_helper_process():
    """os.getpid run by the helper is another process's id; 2 ** 10 is 1024; a plain
    value among the calls is given back as it is."""
    with Helper(1) as helper:
        pid, power = _settle(helper.submit(os.getpid), helper.submit(pow, 2, 10))
        assert gather([pid, power, "as is"]) == [pid.result(), 1024, "as is"]
        assert pid.result() != os.getpid()


def test_an_input_error_in_a_helper_is_raised_here_with_its_message():
    """The InputError a call raises in the helper is raised by result() with the same
    message (sheet, cell, value and unit), the helper's traceback as its cause."""
    with pytest.raises(InputError) as here:
        _refuse(-1.0)
    with Helper(1) as helper, pytest.raises(InputError) as there:
        _settle(helper.submit(_refuse, -1.0))[0].result()
    assert str(there.value) == str(here.value)
    assert "sheet 'MassItems', cell C3" in str(there.value)
    assert isinstance(there.value.__cause__, RemoteTraceback)
    assert "_refuse" in str(there.value.__cause__)


def test_background_work_runs_in_the_run_helper_else_here():
    """in_background hands a call to the run's helper (another process's id) inside
    ``running``, and runs it here when asked for outside any run (this process's id); a
    report's CSV bytes kept for later (FigureRenderer.later) are made here when asked for,
    not by the helper (whose time goes to the figures), and equal those made directly."""
    import pandas as pd

    from slingloads.io.common.csvout import csv_bytes
    from slingloads.io.common.figures import FigureRenderer, task_result

    assert in_background(os.getpid).result() == os.getpid()
    frame = pd.DataFrame({"case": ["=LC1", "LC2"], "Vy [N]": [1.5, -2.25e-7]})
    with Helper(1) as helper, running(helper):
        pid = _settle(in_background(os.getpid))[0]
        assert pid.result() != os.getpid()
        with FigureRenderer() as renderer:
            task = renderer.later("t.csv", os.getpid)
            time.sleep(0.2)
            assert not task.done()  # no helper took it
            assert task_result(renderer, "t.csv", os.getpid) == os.getpid()
            renderer.later("t.csv", csv_bytes, frame)
            assert task_result(renderer, "t.csv", csv_bytes, frame) == csv_bytes(frame)
    assert task_result(None, "t.csv", csv_bytes, frame) == csv_bytes(frame)
    assert csv_bytes(frame).startswith(b"case,Vy [N]\n'=LC1,1.5\n")


def test_calls_no_helper_started_are_run_here(tmp_path):
    """While the helper is busy with a first call, a second one asked for is taken back and
    run in this process; the first is still the helper's."""
    go = tmp_path / "go"
    with Helper(1) as helper:
        busy = helper.submit(_wait_for, str(go), 0)
        deadline = time.monotonic() + DEADLINE
        while busy.state == "pending" and time.monotonic() < deadline:  # until it starts
            time.sleep(0.01)
        second = helper.submit(os.getpid)
        assert gather([second]) == [os.getpid()]
        go.touch()
        assert busy.result() != os.getpid()


def test_the_calls_of_a_dead_helper_are_run_here():
    """A helper that dies in a call (here: it kills itself) leaves that call, and those after
    it, to this process."""
    with Helper(1) as helper:
        calls = [helper.submit(_die_in_a_helper, os.getpid()) for _ in range(3)]
        assert gather(calls) == ["run here"] * 3


def _gone(pid):
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return True
    return state in ("Z", "X")  # a zombie is dead, waiting to be reaped


def _python(code):
    """``code`` run by a fresh Python process (its output captured, within the deadline)."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=DEADLINE)


def test_a_helper_dies_with_its_parent():
    """A parent killed outright (SIGKILL: no clean-up) takes its helper with it."""
    code = ("import os, signal, sys\n"
            "from slingloads.io.common.helper import Helper\n"
            "helper = Helper(1).start()\n"
            "print(helper.submit(os.getpid).result(), flush=True)\n"
            "os.kill(os.getpid(), signal.SIGKILL)\n")
    proc = _python(code)
    assert proc.returncode == -signal.SIGKILL
    helper = int(proc.stdout.split()[0])
    wait_until(lambda: _gone(helper), None, "the end of the helper")


def test_a_helper_terminated_as_it_starts_ends_silently():
    """A helper process sent SIGTERM the moment it is forked (as multiprocessing does to
    daemonic children when the parent exits) ends by that signal without a traceback, though
    the parent's SIGTERM handler raises an exception (the command's, which removes its staging
    folder): the handler is not the helper's even before its first line runs (POSIX: a
    blocked signal stays pending across fork until the child unblocks it)."""
    code = ("import os, signal, sys\n"
            "from slingloads.io.common.helper import Helper\n"
            "def handler(signum, frame):\n"
            "    raise SystemExit('parent handler ran')\n"
            "signal.signal(signal.SIGTERM, handler)\n"
            "codes = []\n"
            "for _ in range(20):\n"
            "    helper = Helper(1).start()\n"
            "    process = helper._workers[0][0]\n"
            "    os.kill(process.pid, signal.SIGTERM)\n"
            "    process.join()\n"
            "    codes.append(process.exitcode)\n"
            "    helper.close()\n"
            "print(codes, flush=True)\n")
    proc = _python(code)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == str([-signal.SIGTERM] * 20)
    assert "Traceback" not in proc.stderr and "parent handler" not in proc.stderr, proc.stderr


@pytest.mark.parametrize("moment", ["reading", "publishing"])
def test_ctrl_c_exits_130_writes_nothing_and_leaves_no_process(tmp_path, moment):
    """Ctrl-C (SIGINT to the command's process group, as a terminal sends it) while the
    workbook is read (once the run's helper is up: the run forks it first, then reads), and
    while the complete new set waits to be published (the run announces the pause): exit code
    130, the message, no traceback, the output folder as it was (absent), no staging folder
    and no process of the run left."""
    book = small_workbook()
    for name in ("run lateral", "run chute sizing"):  # the loads alone: a quicker run
        set_parameter(book, name, "no")
    workbook = save_xlsx(book, tmp_path / "study.xlsx")
    out = tmp_path / "reports"
    steps = tmp_path / "steps"
    steps.mkdir()
    proc = command("run", workbook, out, {STEP_VARIABLE: str(steps), PROCESSES_VARIABLE: "1"},
                   text=True, start_new_session=True)
    try:
        if moment == "reading":
            wait_until(lambda: helper_ready(proc.pid), proc, "the helper")
        else:  # every file staged: the run waits before publishing
            wait_for_publishing_step(proc, steps, 1)
        os.killpg(proc.pid, signal.SIGINT)
        stderr = proc.communicate(timeout=DEADLINE)[1]
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 130, stderr
    assert "interrupted; nothing was written" in stderr and "Traceback" not in stderr
    assert not out.exists()
    assert not [p.name for p in tmp_path.iterdir() if p.name.startswith(TEMP_PREFIX)]
    wait_until(lambda: processes_left(proc.pid) == [], None, "the end of the run's processes")

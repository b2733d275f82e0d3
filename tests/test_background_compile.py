"""The multibody kernels compiled in a second process during a run (cli._BackgroundCompile).

Reference: numba's own cache index (is a compiled version of the kernel on disk for its
current source?) and the operating system's view of the process (alive or not), not the
code's account of itself. A command that runs no multibody kernel starts no process; an
analysis that needs the kernels waits until they are on disk; the process never outlives the
run's block.
"""

from __future__ import annotations

import pytest

from slingloads import cli
from slingloads.models.multibody.integrator import dopri_runs, evaluate_states
from slingloads.runs.warmup import BACKGROUND, _cached


@pytest.mark.parametrize("command", ["lateral", "chute", "template"])
def test_commands_without_multibody_kernels_start_no_process(command, monkeypatch):
    monkeypatch.setenv("SLINGLOADS_PLOT_WORKERS", "1")
    with cli._BackgroundCompile(command) as compiling:
        assert compiling.helper is None
        compiling.wait_for("loads")  # nothing to wait for


def test_no_process_where_helpers_are_off(monkeypatch):
    monkeypatch.setenv("SLINGLOADS_PLOT_WORKERS", "0")
    with cli._BackgroundCompile("run") as compiling:
        assert compiling.helper is None and not compiling.calls


def test_the_kernels_are_on_disk_when_an_analysis_goes_on_and_the_process_ends(monkeypatch):
    monkeypatch.setenv("SLINGLOADS_PLOT_WORKERS", "1")
    with cli._BackgroundCompile("run") as compiling:
        assert set(compiling.calls) == set(BACKGROUND)
        (process, _, _), = compiling.helper._workers
        assert process.is_alive()
        compiling.wait_for("loads")  # the equations only
        assert _cached(evaluate_states)
        assert "integration" in compiling.calls
        compiling.wait_for("multibody")
        assert _cached(dopri_runs) and not compiling.calls
    assert not process.is_alive()


def test_the_process_ends_once_every_part_is_waited_for(monkeypatch):
    """The compiling process is not kept through the computation once its work is done (it
    holds the loaded kernels, about 200 MB): after the analysis needing every part has
    waited for them, the operating system shows it ended, within the run's block."""
    monkeypatch.setenv("SLINGLOADS_PLOT_WORKERS", "1")
    with cli._BackgroundCompile("campaign") as compiling:
        (process, _, _), = compiling.helper._workers
        compiling.wait_for("campaign")
        assert not process.is_alive() and compiling.helper is None
        compiling.wait_for("multibody")  # nothing left to wait for


def test_parts_no_selected_analysis_needs_are_dropped(monkeypatch):
    """A `run` whose workbook asks for the lateral study only needs no kernel: the process
    ends as soon as the analyses are known; one asking for the loads keeps the equations
    only, and ends once the loads have waited for them (the operating system's view)."""
    monkeypatch.setenv("SLINGLOADS_PLOT_WORKERS", "1")
    with cli._BackgroundCompile("run") as compiling:
        (process, _, _), = compiling.helper._workers
        compiling.only_for(["lateral"])
        assert not process.is_alive() and compiling.helper is None
    with cli._BackgroundCompile("run") as compiling:
        (process, _, _), = compiling.helper._workers
        compiling.only_for(["loads", "lateral"])
        assert set(compiling.calls) == {"equations"} and process.is_alive()
        compiling.wait_for("loads")
        assert not process.is_alive()

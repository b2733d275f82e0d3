"""What a command imports before it answers: a workbook refused at its Study sheet, and the
structural loads alone, load none of the libraries and analyses they do not use.

Reference: the interpreter's own record of what a fresh process imported (``sys.modules``
after ``slingloads.cli.main`` returned), with the exit code the command documents (2: bad
input, 0: success), so that a check passes only for the run it describes. Every
``slingloads`` process of a user (and every one the test suite starts) pays these imports:
numba, the multibody kernels and the campaign take about a second and a half of processor
time, matplotlib half a second more, in the helper processes too.
"""

from __future__ import annotations

import subprocess
import sys

import pytest
from hostile import EXAMPLE

#: What a workbook refused at its Study sheet must not load (nor start a helper process to
#: load them).
NOT_FOR_A_REFUSAL = ("numba", "matplotlib", "scipy.optimize", "dask", "distributed", "pandas",
                     "slingloads.analyses.multibody", "slingloads.analyses.campaign",
                     "slingloads.analyses.chute_sizing", "slingloads.analyses.towed_attitude")
#: What the structural loads alone must not load: the other analyses' models and readers
#: (the loads' towed-flight cases do use the multibody trim, and with it numba and the
#: integrator module the trim evaluates the equations with).
NOT_FOR_THE_LOADS = ("dask", "distributed", "slingloads.analyses.campaign",
                     "slingloads.runs.campaign", "slingloads.analyses.chute_sizing",
                     "slingloads.runs.chute_sizing", "slingloads.analyses.lateral",
                     "slingloads.runs.lateral", "slingloads.runs.multibody",
                     "slingloads.io.campaign.reader", "slingloads.io.chute.reader",
                     "slingloads.io.lateral.reader", "slingloads.io.multibody.reader",
                     "slingloads.io.campaign.report", "slingloads.io.chute.report")


def _run_main(args, absent, env=None):
    """``(exit code, modules of absent loaded, helper processes started)`` of
    ``slingloads.cli.main(args)`` run by a fresh Python."""
    code = (
        "import sys\n"
        "from slingloads.io.common import helper\n"
        "started = []\n"
        "start = helper.Helper.start\n"
        "def counted(self):\n"
        "    started.append(self.processes)\n"
        "    return start(self)\n"
        "helper.Helper.start = counted\n"
        "from slingloads.cli import main\n"
        f"code = main({[str(a) for a in args]!r})\n"
        f"loaded = [m for m in {absent!r} if m in sys.modules]\n"
        "print(f'result:{code}:{\",\".join(loaded)}:{sum(started)}')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, env=env, timeout=600).stdout.strip().splitlines()
    _, exit_code, loaded, started = out[-1].split(":")
    return int(exit_code), [m for m in loaded.split(",") if m], int(started)


def _env(plot_workers):
    import os

    return {**os.environ, "SLINGLOADS_PLOT_WORKERS": str(plot_workers)}


@pytest.mark.parametrize("command", ["loads", "run"])
def test_a_workbook_refused_at_its_study_sheet_loads_no_model(tmp_path, command):
    """The example without its Study sheet is refused (exit 2) having loaded neither numba,
    matplotlib, scipy.optimize, dask, distributed nor pandas (nor the multibody, campaign or
    sizing analyses), and having started no helper process, though the helpers are on."""
    import openpyxl

    book = openpyxl.load_workbook(EXAMPLE)
    del book["Study"]
    path = tmp_path / "no-study.xlsx"
    book.save(path)
    code, loaded, started = _run_main(
        [command, path, "--out", tmp_path / "out", "--quiet"], NOT_FOR_A_REFUSAL, _env(1))
    assert code == 2
    assert loaded == [], f"a refused workbook loaded {loaded}"
    assert started == 0
    assert not (tmp_path / "out").exists()


def test_the_loads_alone_load_no_other_analysis(tmp_path):
    """`slingloads loads` on the example writes its reports (exit 0) without loading the
    campaign, dask, the parachute sizing, the lateral study, or the other analyses' readers
    and runs modules (figures drawn in this process: no helper)."""
    code, loaded, _ = _run_main(
        ["loads", EXAMPLE, "--out", tmp_path / "out", "--quiet"], NOT_FOR_THE_LOADS, _env(0))
    assert code == 0
    assert loaded == [], f"the loads alone loaded {loaded}"
    assert any((tmp_path / "out").iterdir())


@pytest.mark.parametrize("module", ["slingloads.io.study", "slingloads.io.airframe.reader",
                                    "slingloads.io.reports", "slingloads.io.loads.rows",
                                    "slingloads.io.lateral.rows", "slingloads.io.chute.rows",
                                    "slingloads.io.multibody.rows",
                                    "slingloads.io.campaign.rows",
                                    "slingloads.io.campaign.report",
                                    "slingloads.io.campaign.reader", "slingloads.runs.cache"])
def test_the_readers_and_row_checks_load_no_compiled_model(module):
    """The study reader, the airframe reader, each analysis's row checks (imported for every
    workbook, its analysis run or not), the campaign's report and reader and its run cache
    (whose folder the command line checks before reading) load neither numba,
    scipy.optimize nor the campaign."""
    absent = ("numba", "scipy.optimize", "slingloads.analyses.campaign")
    code = (f"import sys\nimport {module}\n"
            f"print('loaded:' + ','.join(m for m in {absent!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip().splitlines()
    assert out[-1] == "loaded:", f"importing {module} loaded {out[-1]}"

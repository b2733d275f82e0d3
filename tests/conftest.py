"""Shared test set-up.

* The campaign's run cache goes to a temporary folder, never to the user's cache folder
  (``$SLINGLOADS_CACHE`` is read by ``slingloads.runs.cache``).
* Parallel workers (pytest-xdist, ``-n`` in pyproject.toml) each compile numba's kernels into
  a cache folder of their own: numba writes each cache file atomically, but two processes
  compiling two signatures of one function at once may each rewrite the function's index with
  its own entry only (``numba.core.caching.IndexDataCacheFile.save``), so workers never share
  one. The folders are kept in pytest's cache folder between runs (compiled once). Before the
  workers start, the controller compiles every kernel once into a seed folder copied into
  each worker's (``slingloads compile``): a fresh checkout compiles them once, not once per
  worker.
* Each report figure drawn once per process and its helpers (:func:`_remember_figures`).
* LibreOffice, when present, with one user profile for the session.
* The example workbook, its study read once for the session, its results (every analysis)
  computed once, its reports made once for the session (``slingloads loads`` and
  ``slingloads run``, also with the campaign on; the US reports written from those
  results), the second example's (US twin) reports in US units and in SI, and the check of
  a broken
  copy of a workbook (exit code 2, the message located at the cell, nothing written).
  Under parallel workers each of these is made by one worker for all of them
  (:mod:`once`): the others read the folders it wrote, and its results from their pickle.
"""

import slingloads.blas_threads  # noqa: F401, I001 - first: one BLAS thread, as the command line

import copy
import os
import shutil
import tempfile
from pathlib import Path

import pytest
from hostile import EXAMPLE, IDENT, IDENT_REPORTS, refused_copy, set_study
from once import computed_once, made_once


def _numba_folder(config, name):
    if getattr(config, "cache", None) is not None:
        return Path(config.cache.mkdir(f"numba-{name}"))
    return Path(tempfile.gettempdir()) / f"slingloads-numba-{name}"


def _seed_numba_caches(config):
    """The controller of parallel workers compiles every kernel once (``slingloads compile``,
    its two processes on the two cores) into a seed folder and copies it into each worker's
    folder: the workers load the kernels instead of each compiling them all again."""
    import shutil
    import subprocess
    import sys

    workers = getattr(config.option, "numprocesses", None)
    if not workers or "NUMBA_CACHE_DIR" in os.environ:
        return
    seed = _numba_folder(config, "seed")
    env = {**os.environ, "NUMBA_CACHE_DIR": str(seed)}
    done = subprocess.run([sys.executable, "-m", "slingloads.cli", "compile"], env=env,
                          capture_output=True, text=True)
    if done.returncode != 0:  # each worker compiles what it needs; the tests say what fails
        return
    for k in range(int(workers)):
        shutil.copytree(seed, _numba_folder(config, f"gw{k}"), dirs_exist_ok=True)


def _remember_figures():
    """Every report figure the session draws is drawn once: the PNG bytes of
    :func:`slingloads.io.common.figures.draw_png` are kept on disk under a digest of what
    makes them (the plot function's module, name and code, its arguments, the resolution)
    and returned when the same figure is asked for again, here or in a helper process forked
    from here (each of the many reports of the example draws the same figures). A figure is
    a function of these alone (its bytes are reproducible: ``tests/test_figures.py``); a plot
    function a test replaces has other code, hence another digest, and is drawn."""
    import atexit
    import hashlib
    import pickle
    from importlib import import_module

    import slingloads.io.common.figures as figures

    draw = figures.draw_png
    folder = Path(tempfile.mkdtemp(prefix="slingloads-test-figures-"))
    owner = os.getpid()
    atexit.register(lambda: os.getpid() == owner and shutil.rmtree(folder, ignore_errors=True))

    def digest(func, args, kwargs, dpi):
        target = func
        if isinstance(func, figures.PlotFunction):
            target = getattr(import_module(func.module), func.name)
        code = getattr(target, "__code__", None)
        if code is None:
            return None
        name = f"{getattr(target, '__module__', '')}.{getattr(target, '__qualname__', '')}"
        try:
            blob = pickle.dumps((name, code.co_code, repr(code.co_consts), args, kwargs, dpi),
                                protocol=5)
        except Exception:  # not picklable: drawn, not remembered
            return None
        return hashlib.sha256(blob).hexdigest()

    def draw_png(func, args, kwargs, dpi):
        key = digest(func, args, kwargs, dpi)
        path = folder / f"{key}.png" if key else None
        if path is not None and path.is_file():
            return path.read_bytes()
        png = draw(func, args, kwargs, dpi)
        if path is not None:
            part = path.with_suffix(f".{os.getpid()}.part")
            part.write_bytes(png)
            os.replace(part, path)
        return png

    draw_png.__module__, draw_png.__qualname__ = draw.__module__, draw.__qualname__
    draw_png.__doc__ = draw.__doc__
    figures.draw_png = draw_png


def pytest_configure(config):
    worker = getattr(config, "workerinput", {}).get("workerid")
    if worker is None:
        _seed_numba_caches(config)
        if not getattr(config.option, "numprocesses", None):
            _remember_figures()
        return  # one process: the package's own cache (as a user's runs)
    if "NUMBA_CACHE_DIR" not in os.environ:
        # before numba is imported: read at import; the commands the tests start inherit it
        os.environ["NUMBA_CACHE_DIR"] = str(_numba_folder(config, worker))
    _remember_figures()


@pytest.fixture(autouse=True, scope="session")
def _campaign_cache(tmp_path_factory):
    patch = pytest.MonkeyPatch()
    patch.setenv("SLINGLOADS_CACHE", str(tmp_path_factory.mktemp("campaign-cache")))
    yield
    patch.undo()


@pytest.fixture(scope="session")
def example_path():
    """The example workbook (loadcases/example-light-twin.xlsx)."""
    return EXAMPLE


@pytest.fixture(scope="session")
def _example_study():
    from slingloads.io.study import read_study

    return read_study(EXAMPLE)


@pytest.fixture
def example_study(_example_study):
    """The example's study (every analysis it asks for), read once for the session; each
    test gets its own copy (an analysis may add its results to the study)."""
    return copy.deepcopy(_example_study)


def _report(tmp_path_factory, command):
    from slingloads.cli import main

    def make(out):
        assert main([command, str(EXAMPLE), "--out", str(out), "--quiet"]) == 0

    return made_once(tmp_path_factory, f"example-{command}", make)


@pytest.fixture(scope="session")
def example_loads_report(tmp_path_factory):
    """The folder of ``slingloads loads`` on the example, made once for the session (to be
    read, not changed)."""
    return _report(tmp_path_factory, "loads")


@pytest.fixture(scope="session")
def example_run_report(ident_workbook, tmp_path_factory):
    """The folder of ``slingloads run`` on the example (every analysis it asks for), made
    once for the session (to be read, not changed): run on ``ident_workbook``, the example
    with its cover's free fields filled in, its name kept (the numbers are the example's)."""
    from slingloads.cli import main

    def make(out):
        assert main(["run", str(ident_workbook), "--out", str(out), "--quiet"]) == 0

    return made_once(tmp_path_factory, "example-run", make)


@pytest.fixture(scope="session")
def example_campaign_run_report(tmp_path_factory):
    """The folder of ``slingloads run`` on a copy of the example with 'run campaign' = yes
    (every analysis, the campaign first), made once for the session with the session's run
    cache (which the other campaign runs of the example share): to be read, not changed."""
    import openpyxl

    from slingloads.cli import main

    def make(root):
        book = openpyxl.load_workbook(EXAMPLE)
        for row in book["Study"].iter_rows(min_row=2):
            if str(row[0].value).strip().lower() == "run campaign":
                row[1].value = "yes"
        root.mkdir(parents=True)
        path = root / EXAMPLE.name
        book.save(path)
        assert main(["run", str(path), "--out", str(root / "out"), "--quiet"]) == 0

    return made_once(tmp_path_factory, "example-campaign-run", make) / "out"


#: The second example: a GENERIC 4.9 t twin in US units, with the campaign on.
US_TWIN = Path(__file__).resolve().parents[1] / "loadcases" / "example-us-twin.xlsx"


@pytest.fixture(scope="session", params=["US", "SI"])
def us_twin_reports(request, tmp_path_factory):
    """(units, folder) of ``slingloads run`` on the second example in US units and in SI,
    made once for the session (exit 3: its campaign finds no parachute area stable in every
    condition, a finding; every report is written): to be read, not changed."""
    from slingloads.cli import main

    def make(out):
        assert main(["run", str(US_TWIN), "--out", str(out), "--units", request.param,
                     "--quiet"]) == 3

    return request.param, made_once(tmp_path_factory, f"us-twin-{request.param}", make)


@pytest.fixture(scope="session")
def example_results(_example_study, tmp_path_factory):
    """The example's study with every analysis it asks for run once for the session (its own
    copy of the study; the results are to be read, not changed): run by one worker, the
    others read its results back from their pickle."""
    return computed_once(tmp_path_factory, "example-results",
                         lambda: copy.deepcopy(_example_study).run())


@pytest.fixture(scope="session", params=["SI", "US"])
def example_reports(request, example_results, tmp_path_factory):
    """(units, folder) of the example's reports in SI and in US units: the SI ones are the
    session's ``slingloads run`` folder, the US ones written from ``example_results``."""
    if request.param == "SI":
        return "SI", request.getfixturevalue("example_run_report")
    import slingloads as sl

    def make(out):
        out.mkdir(parents=True)
        sl.write_reports(example_results, out, request.param)

    return request.param, made_once(tmp_path_factory, f"example-{request.param}", make)


@pytest.fixture(scope="session")
def libreoffice(tmp_path_factory):
    """``convert(paths, to, outdir)``: LibreOffice headless converts the files to the format
    ``to`` (``pdf``, ``xlsx``, a ``csv:...`` filter) in one call, with one user profile for
    the session (made by the first call, reused after); the tests that use it are skipped
    where LibreOffice is absent."""
    import shutil
    import subprocess

    from hostile import DEADLINE

    soffice = shutil.which("soffice")
    if soffice is None:
        pytest.skip("LibreOffice (soffice) not found")
    profile = tmp_path_factory.mktemp("libreoffice-profile")

    def convert(paths, to, outdir):
        done = subprocess.run(
            [soffice, f"-env:UserInstallation={profile.as_uri()}", "--headless",
             "--convert-to", to, "--outdir", str(outdir), *map(str, paths)],
            capture_output=True, text=True, timeout=DEADLINE)
        assert done.returncode == 0, done.stderr
        return Path(outdir)

    return convert


@pytest.fixture(scope="session")
def ident_workbook(tmp_path_factory):
    """A copy of the example with the cover's free fields filled in (``hostile.IDENT``),
    under the example's name."""
    import openpyxl

    def make(folder):
        book = openpyxl.load_workbook(EXAMPLE)
        set_study(book, IDENT)
        folder.mkdir(parents=True)
        book.save(folder / EXAMPLE.name)

    return made_once(tmp_path_factory, "ident-in", make) / EXAMPLE.name


@pytest.fixture(scope="session")
def ident_run_report(example_run_report):
    """The folder of ``slingloads run`` on ``ident_workbook`` (the session's one run of the
    example: :func:`example_run_report`)."""
    return example_run_report


@pytest.fixture(scope="session")
def ident_us_loads_report(ident_workbook, tmp_path_factory):
    """The folder of ``slingloads loads --units US`` on ``ident_workbook``, made once for
    the session (to be read, not changed)."""
    from slingloads.cli import main

    def make(out):
        assert main(["loads", str(ident_workbook), "--out", str(out), "--units", "US",
                     "--quiet"]) == 0

    return made_once(tmp_path_factory, "ident-us-loads", make)


@pytest.fixture(scope="session")
def ident_campaign_report(ident_workbook, tmp_path_factory):
    """(folder, workbook): the campaign report of ``ident_workbook`` with 'run campaign' =
    yes (its small matrix), made once for the session with the session's run cache (shared
    with the other campaign runs of the example): to be read, not changed."""
    import openpyxl

    from slingloads.cli import main

    def make(root):
        book = openpyxl.load_workbook(ident_workbook)
        set_study(book, {"run campaign": "yes"})
        root.mkdir(parents=True)
        book.save(root / "ident.xlsx")
        assert main(["campaign", str(root / "ident.xlsx"), "--out", str(root / "out"),
                     "--quiet"]) == 0

    root = made_once(tmp_path_factory, "ident-campaign", make)
    return root / "out", root / "ident.xlsx"


@pytest.fixture(scope="session")
def printed_reports(ident_run_report, ident_campaign_report, ident_us_loads_report,
                    libreoffice, tmp_path_factory):
    """The ident copy's five reports and its US loads report converted to A4 PDF by
    LibreOffice headless, in one call made once for the session: ``{report: PDF bytes}``
    (``"us-loads"`` the US one); skipped where LibreOffice is absent."""
    reports = (*IDENT_REPORTS, "multibody")

    def make(out):
        out.mkdir(parents=True)
        us = out / "us-copy" / "ident-us-loads.xlsx"  # its own PDF name
        us.parent.mkdir()
        us.write_bytes((ident_us_loads_report / f"{EXAMPLE.stem}-loads.xlsx").read_bytes())
        libreoffice([*(ident_run_report / f"{EXAMPLE.stem}-{r}.xlsx" for r in reports),
                     ident_campaign_report[0] / "ident-campaign.xlsx", us], "pdf", out)

    out = made_once(tmp_path_factory, "ident-pdf", make)
    names = {r: f"{EXAMPLE.stem}-{r}" for r in reports}
    names.update(campaign="ident-campaign", **{"us-loads": "ident-us-loads"})
    return {r: (out / f"{name}.pdf").read_bytes() for r, name in names.items()}


def _needs_calibri_metrics():
    """Skip unless fontconfig resolves Calibri to Calibri or Carlito."""
    if shutil.which("fc-match") is None:
        pytest.skip("fontconfig (fc-match) not found: the font LibreOffice prints with is "
                    "unknown")
    import subprocess

    font = subprocess.run(["fc-match", "Calibri"], capture_output=True, text=True).stdout
    if not any(name in font for name in ("Calibri", "Carlito")):
        pytest.skip(f"no font with Calibri's metrics (fc-match Calibri: {font.strip()}); "
                    "install fonts-crosextra-carlito")


@pytest.fixture(scope="session")
def printed(request):
    """``printed_reports``, skipped (before any conversion) where Calibri, the reports'
    font, resolves to no metric-compatible font (Carlito, Debian's fonts-crosextra-carlito,
    which .ci/run installs): page counts and fills hold for Calibri's metrics; a wider
    substitute prints more pages."""
    _needs_calibri_metrics()
    return request.getfixturevalue("printed_reports")


@pytest.fixture
def bad_workbook(tmp_path, capsys):
    """``check(command, edits, sheet, cell, *fragments, base=EXAMPLE)``: a broken copy of a
    workbook refused by ``slingloads COMMAND`` at its cell, nothing written
    (:func:`hostile.refused_copy`). Returns the message."""
    from functools import partial

    return partial(refused_copy, tmp_path, capsys)

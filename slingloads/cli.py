"""Command line: ``slingloads template | compile | run | loads | lateral | chute | campaign``.

Exit codes: 0 success; 2 bad input (a workbook or argument that breaks a stated rule: the
message names the file, sheet, cell, value and rule); 1 a failure of the environment (an
output folder that cannot be written, a full disk, a name too long) or an unexpected error;
130 interrupted (a campaign's finished runs stay in its run cache). In every failure nothing
is written, and no Python traceback is shown unless ``--debug`` is given. 3: the reports
were written, but an analysis could not compute some results asked for (the multibody model
found no trim: no linear modes, no stability verdict, runs not flown); each is named on
stderr (``slingloads: incomplete: ...``) and in its report.

The linear algebra runs on one thread per process (``OPENBLAS_NUM_THREADS`` and its kin set
to 1 unless the environment sets them, before numpy loads): the matrices are small (at most
a few hundred rows), where the BLAS threads only spin, and the command's processes (helpers,
campaign workers) already use the cores; measured on the example on 2 cores, a busy machine
spent 35 times longer in one singular value decomposition with the threads than without.
"""

from __future__ import annotations

import argparse
import gc
import signal
import sys
import threading
from contextlib import ExitStack
from pathlib import Path

import slingloads.blas_threads  # noqa: F401 - before numpy: one BLAS thread (its notes)
from slingloads import __version__
from slingloads.errors import ClosureError, InputError, OutputError
from slingloads.io.analyses import ANALYSES as REGISTRY

EXIT_BAD_INPUT = 2
EXIT_ENVIRONMENT = 1
#: Exit code of a run that wrote its reports but could not compute some results asked for
#: (:meth:`slingloads.runs.study.Results.shortfalls`: the multibody model without a trim, no
#: stable parachute area, no area meeting the parachute decision).
EXIT_INCOMPLETE = 3
#: Exit code after Ctrl-C (128 + SIGINT, the shells' convention).
EXIT_INTERRUPTED = 130

#: Analyses the ``run`` command may perform (the registry :mod:`slingloads.io.analyses`),
#: by name. They are run by :mod:`slingloads.runs` (in its order, with its hand-offs), every
#: one computed (and every input checked) before anything is written, and the files of all
#: of them published together at the end, or none (:mod:`slingloads.io.reports`). The
#: analyses' modules are imported on first use (keeps ``slingloads --help`` fast).
_BY_NAME = {a.name: a for a in REGISTRY}


class _Terminated(BaseException):
    """SIGTERM received: unwind (removing the staging folder) and exit."""


def _parser():
    parser = argparse.ArgumentParser(
        prog="slingloads",
        description="Loads and dynamics of a helicopter carried as a sling load under another "
                    "rotorcraft, stabilised by a drogue parachute.")
    parser.add_argument("--version", action="version", version=f"slingloads {__version__}")
    parser.add_argument("--debug", action="store_true",
                        help="show the Python traceback of an unexpected error")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    t = sub.add_parser("template", help="write a blank, self-explaining input workbook",
                       description="Write a blank input workbook in which every sheet and "
                                   "column is explained (README sheet, header comments).")
    t.add_argument("out", metavar="OUT.xlsx", help="workbook to write (not overwritten if it "
                   "exists, unless --force)")
    t.add_argument("--force", action="store_true", help="replace an existing file")
    _debug_option(t)
    c = sub.add_parser("compile", help="compile and cache the numerical kernels once, ahead "
                       "of the first run (a fresh installation otherwise compiles them during "
                       "its first run)",
                       description="Compile and cache the numerical kernels of every analysis "
                                   "(numba), so that the first run starts at full speed.")
    _debug_option(c)
    runs = ", ".join(a.run_parameter for a in REGISTRY)
    commands = {"run": f"run every analysis the workbook asks for (Study sheet: {runs})",
                **{a.subcommand: a.summary for a in REGISTRY}}
    for name, text in commands.items():
        p = sub.add_parser(name, help=text, description=text[0].upper() + text[1:] + ".")
        p.add_argument("workbook", metavar="IN.xlsx", help="input workbook")
        p.add_argument("--out", metavar="DIR", default="reports",
                       help="output folder (default: reports); the reports are published in "
                            "it all at once, replacing the earlier reports of this input")
        p.add_argument("--units", metavar="{SI,US}", default="SI", type=_unit_system,
                       help="units of the Excel report, SI or US (case ignored; CSV files "
                            "are always SI)")
        p.add_argument("--quiet", action="store_true", help="no progress bar")
        _debug_option(p)
        if name in ("run", "loads"):
            p.add_argument("--nastran", action="store_true",
                           help="also write IN-loads.bdf, the load cases as a Nastran input "
                                "file in the units of --units (Study rows 'nastran ...')")
        if name in ("run", "campaign"):
            _campaign_options(p)
    return parser


def _unit_system(text):
    """``--units``: SI or US, case and surrounding blanks ignored (``us`` is ``US``)."""
    system = str(text).strip().upper()
    if system not in ("SI", "US"):
        raise argparse.ArgumentTypeError(f"the unit system is SI or US: value {text!r}")
    return system


def _campaign_options(p):
    """Execution options of the campaign (docs/campaign.md)."""
    g = p.add_argument_group("campaign execution")
    g.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="dask.distributed scheduler to run the batches on, e.g. "
                        "tcp://10.0.0.5:8786 (default: the workbook's 'campaign scheduler', "
                        "else local worker processes)")
    g.add_argument("--workers", metavar="N", type=int, default=None,
                   help="local worker processes (default: the workbook's 'campaign workers', "
                        "else one per core, or this process for a small campaign)")
    g.add_argument("--cache", metavar="DIR", default=None,
                   help="run cache folder, outside --out, which is replaced as a whole "
                        "(default: $SLINGLOADS_CACHE, else the user cache folder, "
                        "~/.cache/slingloads/campaign; runs are keyed by input, and the "
                        "Summary counts only this matrix's)")
    g.add_argument("--scheduler-timeout", metavar="SECONDS", type=float, default=None,
                   help="time the scheduler has to answer (default: the workbook's, 10 s)")


def _compile():
    from time import perf_counter

    from slingloads.runs.warmup import compile_kernels

    start = perf_counter()
    times = compile_kernels()
    parts = ", ".join(f"{name} {seconds:.1f} s" for name, seconds in times.items())
    print(f"compiled and cached the kernels in {perf_counter() - start:.1f} s ({parts})")
    return 0


def _debug_option(parser):
    parser.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                        help="show the Python traceback of an unexpected error")


def main(argv=None):
    """Entry point of the ``slingloads`` command. Returns the exit code."""
    args = _parser().parse_args(argv)
    previous = _on_sigterm()
    if argv is None and not getattr(args, "debug", False):  # the command, not a caller
        sys.unraisablehook = _quiet_unraisable
    try:
        if args.command == "template":
            return _template(args)
        if args.command == "compile":
            return _compile()
        return _analyse(args)
    except (InputError, ClosureError) as err:
        return _fail(err, EXIT_BAD_INPUT)
    except OutputError as err:
        return _fail(err, EXIT_ENVIRONMENT)
    except (KeyboardInterrupt, _Terminated):
        _forget_interrupt()
        print("\nslingloads: interrupted; nothing was written (a campaign's finished runs stay "
              "in its run cache: run the same command again to resume).", file=sys.stderr)
        return EXIT_INTERRUPTED
    except MemoryError:
        return _fail("out of memory (the limits of slingloads.limits keep valid inputs far "
                     "below this: is the machine short of memory?)", EXIT_ENVIRONMENT)
    except RecursionError as err:
        return _unexpected(err, args)
    except Exception as err:  # noqa: BLE001 - the last guard: never a traceback for a user
        return _unexpected(err, args)
    finally:
        _restore_sigterm(previous)
        if argv is not None:  # called from Python, which goes on: collect as usual again
            gc.unfreeze()


def _forget_interrupt():
    """Make ``python -m slingloads.cli`` exit with EXIT_INTERRUPTED after Ctrl-C, as the
    ``slingloads`` command does. CPython remembers a KeyboardInterrupt that ended code run
    from a string (``exec``/``eval`` of text: libraries generate functions that way) even
    when it is caught, and ``-m`` then kills the interpreter with SIGINT at exit instead of
    returning the code; the next string evaluation clears that memory."""
    exec("pass")


def _quiet_unraisable(unraisable):
    """An error a library raises while cleaning up (a network client's finaliser after a
    refused connection): one line instead of a traceback (``--debug`` shows it)."""
    value = unraisable.exc_value
    text = " ".join(str(value).split())[:200]
    print(f"slingloads: note: ignored while cleaning up: {type(value).__name__}: {text}",
          file=sys.stderr)


def _fail(err, code):
    print(f"slingloads: error: {err}", file=sys.stderr)
    print("slingloads: nothing was written.", file=sys.stderr)
    return code


def _unexpected(err, args):
    if getattr(args, "debug", False):
        raise err
    text = " ".join(str(err).split())[:300]
    print(f"slingloads: error: unexpected {type(err).__name__}: {text}", file=sys.stderr)
    print("slingloads: nothing was written. This is a bug or a problem of the environment; "
          "run again with --debug to see the traceback, and report it with the input.",
          file=sys.stderr)
    return EXIT_ENVIRONMENT


def _on_sigterm():
    """Turn SIGTERM into an exception so that the staging folder is removed on the way out."""
    if threading.current_thread() is not threading.main_thread():
        return None

    def handler(signum, frame):
        raise _Terminated()

    try:
        return signal.signal(signal.SIGTERM, handler)
    except (ValueError, OSError):  # pragma: no cover
        return None


def _restore_sigterm(previous):
    if previous is not None:
        signal.signal(signal.SIGTERM, previous)


def _template(args):
    from slingloads.io.template import write_input_workbook

    out = Path(args.out)
    if out.suffix.lower() != ".xlsx":
        raise InputError("the template must be an .xlsx file", str(out))
    if out.is_dir():
        raise OutputError("the template path is a folder", out)
    if out.exists() and not args.force:
        raise InputError("file exists; use --force to replace it", str(out))
    write_input_workbook(out)
    print(f"wrote {out}")
    return 0


def _only(args):
    """The analyses a single-analysis command runs (None for ``run``: the workbook's)."""
    if args.command == "run":
        return None
    return [a.name for a in REGISTRY if a.subcommand == args.command]


def _selected(args, study):
    if args.command == "run":
        if not study.asked:
            runs = ", ".join(a.run_parameter for a in REGISTRY)
            raise InputError(f"the workbook asks for no analysis (Study sheet: {runs} are "
                             "all no)", file=study.path, sheet="Study")
        return list(study.asked)
    return _only(args)


def _ask_nastran(study, names):
    """--nastran: the loads report writes the Nastran file (the loads analysis must run)."""
    if "loads" not in names:
        raise InputError("--nastran writes the load cases as Nastran bulk data, but the "
                         "workbook does not run the loads analysis (Study sheet: 'run loads')",
                         file=study.path, sheet="Study")
    study.report.nastran = True


def _analyse(args):
    """Run the analyses of a command (:func:`_run_analyses`) with a helper process drawing
    the figures. What is loaded and read is kept to the end of the run: the garbage
    collector is told not to scan it again (``gc.freeze``: each full collection would
    otherwise go through every object of pandas, scipy, numba and the study, a tenth of a
    second each time)."""
    gc.freeze()
    with _Helpers(args.command) as helpers:
        return _run_analyses(args, helpers)


class _Helpers:
    """The helper processes of a run, started once the workbook's Study sheet and the cells
    of its table sheets read (``on_checked`` of :func:`~slingloads.io.study.read_study`,
    :meth:`start`): a workbook refused before that starts none (each would load matplotlib,
    or numba and the multibody kernels, for nothing). The process that compiles the
    multibody kernels a fresh installation lacks starts first, when an analysis asked for
    needs them (:class:`_BackgroundCompile`), then the one that draws the figures: it loads
    matplotlib while the rest of the workbook is read, and draws each analysis's figures
    once it is computed (:func:`~slingloads.io.common.figures.helping`). Both end with the
    block."""

    def __init__(self, command):
        self.compiling = _BackgroundCompile(command)
        self._stack = ExitStack()

    def start(self, asked):
        """Start the helpers of a run of the analyses ``asked`` (names)."""
        from slingloads.io.common.figures import helping

        gc.freeze()  # what is loaded so far is shared with the helpers, not copied
        self.compiling.asked = tuple(asked)
        self._stack.enter_context(self.compiling)
        self._stack.enter_context(helping())

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        return self._stack.__exit__(exc_type, exc, tb)


class _BackgroundCompile:
    """The multibody kernels compiled in a second process while the first analyses compute
    (:func:`slingloads.runs.warmup.compile_part`; nothing to do once they are cached): on a
    fresh installation they are the largest part of the first run, and the lateral study,
    the parachute sizing and the reading need only the other core. An analysis that needs
    them waits for that process (:meth:`wait_for`) rather than compiling them a second
    time. The process writes only numba's cache; it is killed once every part has been
    waited for, or when the run ends (a kill leaves no partial cache file: numba writes each
    one under a temporary name first). Once the analyses of the run are known
    (:attr:`asked`), the process starts only when one of them needs the kernels."""

    #: The parts each analysis needs, by name.
    NEEDS = {"loads": ("equations",), "multibody": ("equations", "integration"),
             "campaign": ("equations", "integration")}
    #: Commands that may run an analysis of :data:`NEEDS`.
    COMMANDS = ("run", "loads", "simulate", "campaign")

    def __init__(self, command, asked=None):
        self.command = command
        #: The analyses of the run (names), None while unknown (then the command decides).
        self.asked = asked
        self.helper = None
        self.calls = {}

    def __enter__(self):
        from slingloads.io.common.helper import Helper, helper_processes

        needed = self.asked is None or any(name in self.NEEDS for name in self.asked)
        if self.command in self.COMMANDS and needed and helper_processes() > 0:
            from slingloads.runs.warmup import BACKGROUND, compile_part

            self.helper = Helper(1).start()
            self.calls = {part: self.helper.submit(compile_part, part) for part in BACKGROUND}
        return self

    def only_for(self, names):
        """Drop the parts no analysis of ``names`` needs (a ``run`` whose workbook asks for
        the loads but not the multibody model needs no integration kernel); the process
        ends if none is left."""
        needed = {part for name in names for part in self.NEEDS.get(name, ())}
        for part in [p for p in self.calls if p not in needed]:
            del self.calls[part]
        self._close_when_done()

    def _close_when_done(self):
        if not self.calls and self.helper is not None:
            # every part compiled: the process (about 200 MB of loaded kernels) is not kept
            # through the computation (docs/inputs-and-outputs.md, Memory)
            self.helper.close(abort=True)
            self.helper = None

    def wait_for(self, name):
        """Wait until the kernels analysis ``name`` needs are compiled (or their compiling
        failed: the analysis then compiles them itself and says why if it cannot)."""
        for part in self.NEEDS.get(name, ()):
            call = self.calls.pop(part, None)
            if call is not None:
                try:
                    call.result(take_back=False)
                except Exception:  # noqa: BLE001, S110 - the analysis compiles them itself
                    pass
        self._close_when_done()

    def __exit__(self, exc_type, exc, tb):
        if self.helper is not None:
            self.helper.close(abort=True)
        return False


def _run_analyses(args, helpers=None):
    from slingloads.io.reports import prepare_outputs, publish_reports
    from slingloads.io.study import read_study
    from slingloads.runs.study import run_analysis, run_study

    show = not args.quiet
    compiling = None if helpers is None else helpers.compiling
    # the campaign's options are checked before anything is read, whether or not the
    # workbook runs the campaign (a bad value is refused, an unused one is warned about)
    options = _run_options(args, show) if hasattr(args, "workers") else None
    unused = []
    with _progress(show) as bar:
        first = _FirstComputed(args, _only(args), compiling)
        study = read_study(args.workbook, only=_only(args), on_read=first,
                           on_checked=None if helpers is None else helpers.start)
        gc.freeze()  # the libraries and the study live to the end of the run: see _analyse
        names = _selected(args, study)
        if compiling is not None:
            compiling.only_for(names)
        if getattr(args, "nastran", False):
            _ask_nastran(study, names)
        if "campaign" in names:
            study.options = options
        elif options is not None:
            unused = [f"{flag} is not used: the workbook does not run the campaign (Study "
                      "row 'run campaign')" for flag, value in (
                          ("--scheduler", args.scheduler), ("--workers", args.workers),
                          ("--cache", args.cache), ("--scheduler-timeout",
                                                    args.scheduler_timeout))
                      if value is not None]
        # `run` publishes the whole report of the input: it replaces the earlier files of
        # every analysis; a single-analysis command replaces those of its analysis only
        stem = Path(args.workbook).stem
        outputs = prepare_outputs(study, args.out, names, stem,
                                  replace_all=args.command == "run")
        bar.total = 2 + 2 * len(names)
        bar.update(1)
        figures = {}
        with ExitStack() as drawing:
            def computing(name):
                bar.set_description(f"computing {name}")

            def run(study, name):
                if name == first.name:  # computed while the workbook was read
                    result, figures[name] = first.outcome()
                    return result
                if compiling is not None:
                    compiling.wait_for(name)
                return run_analysis(study, name)

            def computed(name, result):
                # its figures are drawn (by the helper process) while the next ones compute
                if name != first.name:
                    figures[name] = _BY_NAME[name].start_figures(result, args.units, study)
                if figures[name] is not None:
                    drawing.enter_context(figures[name])
                bar.update(1)

            results = run_study(study, names, before=computing, after=computed, run=run)
            gc.freeze()
            # one set of outputs for every analysis: all published together, or none
            written = publish_reports(
                results, outputs, stem, args.units, names, figures,
                before=lambda name: bar.set_description(f"writing {name}"),
                after=lambda name: bar.update(1))
        bar.update(1)
        bar.set_description("done")
    for path in written:
        print(f"wrote {path}")
    for text in [*study.source.warnings, *unused]:
        print(f"slingloads: warning: {text}", file=sys.stderr)
    shortfalls = results.shortfalls()
    for text in shortfalls:
        print(f"slingloads: incomplete: {text}", file=sys.stderr)
    if shortfalls:
        print("slingloads: the reports were written, but some results asked for could not be "
              f"computed (exit code {EXIT_INCOMPLETE}; the reports say why)", file=sys.stderr)
        return EXIT_INCOMPLETE
    return 0


def _progress(show):
    """The run's progress bar (tqdm, loaded only when it is shown), or a silent stand-in."""
    if not show:
        return _NoProgress()
    from tqdm import tqdm

    return tqdm(total=3, desc="reading", unit="step",
                bar_format="{desc:<28}{bar:20}| {n_fmt}/{total_fmt} [{elapsed}]")


class _NoProgress:
    """What ``--quiet`` shows: nothing (the interface of the tqdm bar the run uses)."""

    total = 0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def update(self, n=1):
        pass

    def set_description(self, text):
        pass


class _FirstComputed:
    """The first analysis of a run, computed as soon as its inputs are read (``on_read`` of
    :func:`~slingloads.io.study.read_study`) and its figures started, so that the helper
    process draws them while the rest of the workbook is read. What it gives (its result
    and figures, or the error it raised) is taken at its turn in the compute loop: errors
    come in the same order as when everything is read first. Not with a campaign (it needs
    the command line's execution options, set after reading, and it feeds the loads)."""

    def __init__(self, args, only, compiling=None):
        self.args, self.only, self.compiling = args, only, compiling
        self.name = None
        self._outcome = None

    def __call__(self, name, study):
        if self.name is not None:
            return
        from slingloads.runs.study import compute_order, run_analysis

        wanted = self.only if self.only is not None else list(study.asked)
        if not wanted or "campaign" in wanted or compute_order(wanted)[0] != name:
            return
        self.name = name
        if self.compiling is not None:
            self.compiling.wait_for(name)
        try:
            result = run_analysis(study, name)
            figures = _BY_NAME[name].start_figures(result, self.args.units, study)
        except Exception as err:  # noqa: BLE001 - raised at its turn by outcome()
            self._outcome = err
        else:
            self._outcome = (result, figures)

    def outcome(self):
        """``(result, figures)``, or the error the analysis raised."""
        if isinstance(self._outcome, BaseException):
            raise self._outcome
        return self._outcome


def _run_options(args, show):
    """The campaign's execution options from the command line (checked before any run)."""
    from slingloads.io.campaign.rows import address_rule
    from slingloads.limits import MAX_SCHEDULER_TIMEOUT, MAX_WORKERS
    from slingloads.runs.cache import check_outside, default_cache_dir
    from slingloads.runs.study import RunOptions

    if args.workers is not None and not 1 <= args.workers <= MAX_WORKERS:
        raise InputError(f"--workers must be in [1, {MAX_WORKERS}] (limits of slingloads)",
                         args.workers)
    if args.scheduler_timeout is not None and not 0 < args.scheduler_timeout <= \
            MAX_SCHEDULER_TIMEOUT:
        raise InputError(f"--scheduler-timeout must be in (0, {MAX_SCHEDULER_TIMEOUT:g}] [s]",
                         args.scheduler_timeout)
    if args.scheduler is not None:
        rule = address_rule(args.scheduler.strip()) if args.scheduler.strip() else (
            "an empty address; leave --scheduler out for local workers")
        if rule is not None:
            raise InputError(f"--scheduler: {rule}", args.scheduler)
    cache = Path(args.cache) if args.cache else default_cache_dir()
    check_outside(cache, args.out)  # a cache that cannot be used is a warning: the
    # campaign then runs without it (slingloads.runs.cache)
    return RunOptions(scheduler=args.scheduler, workers=args.workers, cache=cache,
                      timeout=args.scheduler_timeout, progress=_RunsBar() if show else None)


class _RunsBar:
    """Progress of the campaign's runs: runs done, rate and time left (tqdm)."""

    def __init__(self):
        self.bar = None

    def __call__(self, done, total):
        if self.bar is None:
            from tqdm import tqdm

            self.bar = tqdm(total=total, initial=done, desc="campaign runs", unit="run",
                            leave=False, position=1, dynamic_ncols=True)
        else:  # one call per batch: show each (tqdm skips updates closer than 0.1 s)
            self.bar.update(done - self.bar.n)
            self.bar.refresh()
        if done >= total:
            self.bar.close()


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

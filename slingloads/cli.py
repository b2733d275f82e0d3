"""Command line: ``slingloads template | run | loads | lateral | chute``.

Exit codes: 0 success, 2 bad input (nothing written), 1 an unexpected failure.
"""

from __future__ import annotations

import argparse
import sys
from contextlib import ExitStack
from pathlib import Path

from tqdm import tqdm

from slingloads import __version__
from slingloads.errors import ClosureError, InputError, SlingloadsError
from slingloads.io.analyses import ANALYSES as REGISTRY

EXIT_BAD_INPUT = 2

#: Analyses the ``run`` command may perform, in order (from the registry
#: :mod:`slingloads.io.analyses`): name -> (subcommand, compute(study) -> result,
#: write(result, out_dir, stem, units, study, figures=None)), out_dir being the shared
#: AtomicOutputs of the run and figures the drawings started after the analysis was computed.
#: Every analysis is computed (and every input checked) before anything is written, and the
#: files of all the analyses are published together at the end (or none of them). The
#: analyses' modules are imported on first use (keeps ``slingloads --help`` fast).
ANALYSES = {a.name: (a.subcommand, a.compute, a.write) for a in REGISTRY}
_BY_NAME = {a.name: a for a in REGISTRY}


def _parser():
    parser = argparse.ArgumentParser(
        prog="slingloads",
        description="Loads and dynamics of a helicopter carried as a sling load under another "
                    "rotorcraft, stabilised by a drogue parachute.")
    parser.add_argument("--version", action="version", version=f"slingloads {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    t = sub.add_parser("template", help="write a blank, self-explaining input workbook",
                       description="Write a blank input workbook in which every sheet and "
                                   "column is explained (README sheet, header comments).")
    t.add_argument("out", metavar="OUT.xlsx", help="workbook to write (not overwritten if it "
                   "exists, unless --force)")
    t.add_argument("--force", action="store_true", help="replace an existing file")
    runs = ", ".join(a.run_parameter for a in REGISTRY)
    commands = {"run": f"run every analysis the workbook asks for (Study sheet: {runs})",
                **{a.subcommand: a.summary for a in REGISTRY}}
    for name, text in commands.items():
        p = sub.add_parser(name, help=text, description=text[0].upper() + text[1:] + ".")
        p.add_argument("workbook", metavar="IN.xlsx", help="input workbook")
        p.add_argument("--out", metavar="DIR", default="reports",
                       help="output directory (default: reports)")
        p.add_argument("--units", choices=("SI", "US"), default="SI",
                       help="units of the Excel report (CSV files are always SI)")
        p.add_argument("--quiet", action="store_true", help="no progress bar")
    return parser


def main(argv=None):
    """Entry point of the ``slingloads`` command. Returns the exit code."""
    args = _parser().parse_args(argv)
    try:
        if args.command == "template":
            return _template(args)
        return _analyse(args)
    except InputError as err:
        print(f"slingloads: error: {err}", file=sys.stderr)
        print("slingloads: nothing was written.", file=sys.stderr)
        return EXIT_BAD_INPUT
    except ClosureError as err:
        print(f"slingloads: error: {err}", file=sys.stderr)
        print("slingloads: nothing was written.", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SlingloadsError as err:  # pragma: no cover - defensive
        print(f"slingloads: error: {err}", file=sys.stderr)
        return 1


def _template(args):
    from slingloads.io.template import write_input_workbook

    out = Path(args.out)
    if out.suffix.lower() != ".xlsx":
        raise InputError("the template must be an .xlsx file", str(out))
    if out.exists() and not args.force:
        raise InputError("file exists; use --force to replace it", str(out))
    write_input_workbook(out)
    print(f"wrote {out}")
    return 0


def _selected(args, study):
    if args.command == "run":
        wanted = [n for n in ANALYSES if study.run.get(n)]
        if not wanted:
            runs = ", ".join(a.run_parameter for a in REGISTRY)
            raise InputError(f"the workbook asks for no analysis (Study sheet: {runs} are "
                             "all no)", file=study.path, sheet="Study")
        return wanted
    return [n for n, (cmd, _, _) in ANALYSES.items() if cmd == args.command]


def _analyse(args):
    from slingloads.io.common.atomic import atomic_outputs
    from slingloads.io.study import read_study

    show = not args.quiet
    with tqdm(total=3, desc="reading", disable=not show, unit="step",
              bar_format="{desc:<28}{bar:20}| {n_fmt}/{total_fmt} [{elapsed}]") as bar:
        only = None
        if args.command != "run":
            only = [n for n, (cmd, _, _) in ANALYSES.items() if cmd == args.command]
        study = read_study(args.workbook, only=only)
        names = _selected(args, study)
        bar.total = 2 + 2 * len(names)
        bar.update(1)
        results, figures = {}, {}
        with ExitStack() as drawing:
            for name in names:
                bar.set_description(f"computing {name}")
                results[name] = ANALYSES[name][1](study)
                # its figures are drawn (in worker processes) while the next ones compute
                figures[name] = _BY_NAME[name].start_figures(results[name], args.units, study)
                if figures[name] is not None:
                    drawing.enter_context(figures[name])
                bar.update(1)
            study.results.update(results)  # a report may quote another analysis's result
            stem = Path(args.workbook).stem
            # one set of outputs for every analysis: all published together, or none
            with atomic_outputs(args.out, inputs=[args.workbook]) as outputs:
                for name in names:
                    bar.set_description(f"writing {name}")
                    ANALYSES[name][2](results[name], outputs, stem, args.units, study,
                                      figures=figures[name])
                    bar.update(1)
        written = outputs.written
        bar.update(1)
        bar.set_description("done")
    for path in written:
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

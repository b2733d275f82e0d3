"""Start-up time of the command line: ``slingloads --help``.

Runs the installed console script (or ``python -m slingloads.cli`` if it is not on the path)
``--repeat`` times in a fresh process and prints every wall time and their median, the figure
(target: under 0.5 s). It also lists the heavy libraries the help loads (none expected).

Run from the repository root::

    .venv/bin/python benchmarks/bench_startup.py
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

HEAVY = ("numpy", "pandas", "scipy", "matplotlib", "openpyxl", "pint", "numba", "tqdm")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args(argv)
    script = shutil.which("slingloads", path=str(Path(sys.executable).parent))
    command = [script, "--help"] if script else [sys.executable, "-m", "slingloads.cli",
                                                 "--help"]
    times = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    code = ("import sys\nfrom slingloads import cli\ntry:\n    cli.main(['--help'])\n"
            "except SystemExit:\n    pass\n"
            f"print('loaded:' + ','.join(m for m in {HEAVY!r} if m in sys.modules))")
    loaded = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True,
                            text=True).stdout.strip().splitlines()[-1].removeprefix("loaded:")
    print(f"{' '.join(Path(command[0]).name if i == 0 else c for i, c in enumerate(command))}"
          f": {', '.join(f'{t:.3f}' for t in times)} s")
    print(f"  heavy libraries loaded by --help: {loaded or 'none'}")
    print(f"median --help time: {statistics.median(times):.3f} s (target < 0.5 s)")


if __name__ == "__main__":
    main()

"""Time the README's main job: ``slingloads run`` on the example workbook (target: < 10 s).

Runs the command line in a fresh Python process, as a user does, writing into a temporary
directory, and prints the wall-clock time of the best of three runs.

Run: ``python benchmarks/bench_example.py``
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"


def main():
    times = []
    for _ in range(3):
        with tempfile.TemporaryDirectory() as out:
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "slingloads.cli", "run", str(EXAMPLE),
                            "--out", out, "--quiet"], check=True, stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - t0)
    print(f"slingloads run on the example (loads, lateral study, parachute sizing): "
          f"best {min(times):.2f} s of {len(times)} runs (target < 10 s)")


if __name__ == "__main__":
    main()

"""The runs module of each analysis: one table, imported modules.

:data:`RUNS` maps each name of :data:`slingloads.runs.study.ANALYSES` to the module that runs
it (``run(study) -> result``; those that can fall short of what they were asked for also have
``shortfalls(result) -> list of str``). The table imports every analysis and its libraries
(numpy, scipy, numba), so :mod:`slingloads.runs.study` imports it only when an analysis runs:
reading a workbook or printing ``--help`` loads none of them. The registry imports no module
that imports :mod:`slingloads.runs.study`, so the two make no circle.
"""

from __future__ import annotations

from slingloads.runs import campaign, chute_sizing, lateral, loads, multibody

#: Analysis name -> its runs module, in the order of ``ANALYSES``.
RUNS = {
    "loads": loads,
    "lateral": lateral,
    "chute sizing": chute_sizing,
    "multibody": multibody,
    "campaign": campaign,
}

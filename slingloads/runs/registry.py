"""The runs module of each analysis: one table, each module imported when its analysis runs.

:data:`RUNS` maps each name of :data:`slingloads.runs.study.ANALYSES` to the function that
imports the module that runs it (``run(study) -> result``; those that can fall short of what
they were asked for also have ``shortfalls(result) -> list of str``). Running the structural
loads thus loads neither the parachute sizing nor the campaign (nor dask), and reading a
workbook or printing ``--help`` loads no analysis. The registry imports no module that
imports :mod:`slingloads.runs.study`, so the two make no circle.
"""

from __future__ import annotations


def _loads():
    from slingloads.runs import loads

    return loads


def _lateral():
    from slingloads.runs import lateral

    return lateral


def _chute_sizing():
    from slingloads.runs import chute_sizing

    return chute_sizing


def _multibody():
    from slingloads.runs import multibody

    return multibody


def _campaign():
    from slingloads.runs import campaign

    return campaign


#: Analysis name -> the function that imports and returns its runs module, in the order of
#: ``ANALYSES``: an analysis's models load when it runs, not when another one does.
RUNS = {
    "loads": _loads,
    "lateral": _lateral,
    "chute sizing": _chute_sizing,
    "multibody": _multibody,
    "campaign": _campaign,
}

"""One batch of campaign runs, as a worker process (local or on a Dask cluster) runs it.

:func:`run_batch` integrates the runs of a batch together
(:func:`~slingloads.analyses.multibody.simulate_runs`, the compiled Dormand-Prince 5(4)
kernel over runs), trims and linearises each distinct condition once, and returns one record
per run: its key, metrics (:mod:`.metrics`) and histories. It is a plain function of
picklable arguments so that any executor can ship it.

The compiled kernel runs on ``threads`` threads of the calling thread (numba's thread count
is set per calling thread), and one batch at a time per process: numba's default threading
layer may not be entered by two Python threads at once, and a process that ran two kernels
side by side would oversubscribe its cores anyway.
"""

from __future__ import annotations

import threading

#: One compiled kernel at a time per process.
_KERNEL_LOCK = threading.Lock()
#: Environment variable (testing aid): ``N`` makes a worker process that is not the main one
#: end at once (``os._exit``, as a killed process does) when it starts its N-th batch.
KILL_VARIABLE = "SLINGLOADS_TEST_KILL_BATCH"
_BATCHES = []


def _set_threads(threads):
    import numba

    if threads is None:
        return
    numba.set_num_threads(max(1, min(int(threads), numba.config.NUMBA_NUM_THREADS)))


def run_batch(jobs, settings, threads=None):
    """Run a batch of campaign runs.

    Parameters
    ----------
    jobs : list of (str, SlingSystem, Manoeuvre)
        (key, system, manoeuvre) of each run. Runs of one condition should share one system
        object (its trim and linear model are then computed once).
    settings : dict
        ``t_end``, ``dt`` (None: adaptive), ``output_interval`` [s], and ``rtol``, ``atol``
        of the adaptive step.
    threads : int, optional
        Threads of the compiled kernel and of the runs integrated side by side (default:
        numba's current setting, and every processor this process may use). [count]

    Returns
    -------
    list of (str, dict, ndarray)
        (key, metrics, histories) of each run, in the order of ``jobs``.
        [SI, angles in deg: :func:`~.metrics.response_metrics`]
    """
    from slingloads.analyses.multibody import linearise, simulate_runs, trim
    from slingloads.models.multibody.integrator import ATOL, RTOL

    from .metrics import linear_metrics, response_metrics

    _die_if_asked()
    with _KERNEL_LOCK:
        _set_threads(threads)
        sim = simulate_runs([(system, manoeuvre) for _, system, manoeuvre in jobs],
                            t_end=settings["t_end"], dt=settings["dt"],
                            output_interval=settings["output_interval"],
                            rtol=settings.get("rtol", RTOL), atol=settings.get("atol", ATOL),
                            workers=threads)
    conditions = {}
    out = []
    for (key, system, _), run in zip(jobs, sim.runs, strict=True):
        if id(system) not in conditions:
            point = trim(system)
            model = linearise(point) if point.converged else None
            conditions[id(system)] = (linear_metrics(point, model), model)
        condition, model = conditions[id(system)]
        metrics, histories = response_metrics(run, model)
        out.append((key, {**condition, **metrics}, histories))
    return out


def _die_if_asked():
    """End this worker process at once when :data:`KILL_VARIABLE` says so (testing aid)."""
    import multiprocessing
    import os

    text = os.environ.get(KILL_VARIABLE)
    if not text or multiprocessing.parent_process() is None:
        return
    _BATCHES.append(1)
    if text.isdigit() and len(_BATCHES) == int(text):
        os._exit(70)

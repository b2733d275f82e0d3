"""The memory of a campaign: how much a batch, a worker and a run need, estimated from the
run settings before anything runs.

Guarantees: a batch holds at most :data:`~slingloads.limits.BATCH_MEMORY` of samples
(:func:`batch_limit`); the local workers started are the number asked for capped by the cores,
by the memory available, each counted at :func:`worker_memory`, and by a command's budget
(:func:`budget_workers`; an explicit larger request is cut with a warning that gives the
estimate: :func:`local_workers`). The estimate, 8 bytes a
number: a worker's libraries and kernels (:data:`~slingloads.limits.WORKER_BASE_MEMORY`), one
chunk of drive tables (``DRIVE_BUDGET`` of the multibody model) and a batch's samples (states,
drive, reported quantities and histories, and the histories once more as the record handed
back). docs/inputs-and-outputs.md section 9 states the budget.
"""

from __future__ import annotations

import os

from slingloads.limits import (
    BATCH_MEMORY,
    COMMAND_MEMORY,
    COMMAND_OWN_MEMORY,
    WORKER_BASE_MEMORY,
    WORKER_OWN_MEMORY,
)

#: Largest batch sent to a worker (runs).
MAX_BATCH = 100
#: Smallest batch worth a call (unless fewer runs are left). [runs]
MIN_BATCH = 20


def history_rows(settings):
    """Rows of a run's histories under ``settings`` (``t_end``, ``output_interval`` [s]): the
    samples at 0, interval, ..., t_end.

    Parameters
    ----------
    settings : dict
        The runs' settings (``t_end``, ``output_interval`` [s]).

    Returns
    -------
    int
        Samples. [count]
    """
    return int(round(float(settings["t_end"]) / float(settings["output_interval"]))) + 1


def cpu_count():
    """The machine's cores, at least one (``os.cpu_count()`` may not know).

    Returns
    -------
    int
        Cores, >= 1. [-]
    """
    return max(1, os.cpu_count() or 1)


def _available_memory():
    """Memory this machine has available now (Linux ``MemAvailable``, else the free physical
    pages), or None where it cannot be told. [bytes]"""
    try:
        with open("/proc/meminfo", encoding="ascii") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, AttributeError):
        return None


def worker_memory(settings=None):
    """Estimated peak memory of one worker process running batches under ``settings``: the
    loaded libraries and kernels (:data:`~slingloads.limits.WORKER_BASE_MEMORY`), one chunk of
    drive tables (:data:`~slingloads.analyses.multibody.simulate.DRIVE_BUDGET`) and the
    samples of a batch (at most :data:`~slingloads.limits.BATCH_MEMORY`, :func:`batch_limit`).
    [bytes]

    Parameters
    ----------
    settings : dict, optional
        The runs' settings (``t_end``, ``output_interval`` [s]); default the largest batch.

    Returns
    -------
    int
        [bytes]
    """
    from slingloads.analyses.multibody.simulate import DRIVE_BUDGET

    batch = BATCH_MEMORY
    if settings is not None:
        batch = min(BATCH_MEMORY, MAX_BATCH * _sample_bytes(settings))
    return WORKER_BASE_MEMORY + DRIVE_BUDGET + batch


def _sample_bytes(settings):
    """Bytes of one run's samples under ``settings`` (states, drive, reported quantities,
    histories, and the histories once more as the record handed back)."""
    from slingloads.analyses.multibody.simulate import SAMPLE_BYTES

    from .metrics import HISTORY_LABELS

    return history_rows(settings) * (SAMPLE_BYTES + 8 * len(HISTORY_LABELS))


def batch_limit(settings):
    """The most runs of a batch whose samples fit :data:`~slingloads.limits.BATCH_MEMORY`
    (at least 1, at most :data:`MAX_BATCH`).

    Parameters
    ----------
    settings : dict
        The runs' settings (``t_end``, ``output_interval`` [s]).

    Returns
    -------
    int
        Runs. [count]
    """
    return max(1, min(MAX_BATCH, BATCH_MEMORY // max(1, _sample_bytes(settings))))


def budget_workers():
    """The most local worker processes a command's memory budget allows:
    (:data:`~slingloads.limits.COMMAND_MEMORY` - :data:`~slingloads.limits.COMMAND_OWN_MEMORY`)
    / :data:`~slingloads.limits.WORKER_OWN_MEMORY` (each worker's own memory beside the
    libraries it shares with the command's process), at least 1.

    Returns
    -------
    int
        Workers. [count]
    """
    return max(1, (COMMAND_MEMORY - COMMAND_OWN_MEMORY) // WORKER_OWN_MEMORY)


def local_workers(requested, settings=None, cores=None, available=None):
    """Worker processes to start: ``requested``, capped by the cores, by the memory
    available (:func:`worker_memory` each, with the memory this process keeps) and by a
    command's memory budget (:func:`budget_workers`), and a warning (None if none) when an
    explicit request is cut.

    Parameters
    ----------
    requested : int
        Worker processes asked for. [count]
    settings : dict, optional
        The runs' settings (``t_end``, ``output_interval`` [s]).
    cores : int, optional
        Cores available (default: those this process may use). [count]
    available : int, optional
        Memory available (default: the system's). [bytes]

    Returns
    -------
    workers : int
        Worker processes. [count]
    warning : str or None
    """
    cores = cpu_count() if cores is None else int(cores)
    available = _available_memory() if available is None else available
    each = worker_memory(settings)
    by_memory = (max(1, int((available - WORKER_BASE_MEMORY) // each))
                 if available is not None else requested)
    by_budget = budget_workers()
    workers = max(1, min(int(requested), cores, by_memory, by_budget))
    if workers >= requested:
        return workers, None
    why = []
    if requested > cores:
        why.append(f"{cores} core{'s' if cores > 1 else ''}")
    if requested > by_memory and available is not None:
        why.append(f"{available / 2**20:,.0f} MB of memory available")
    if requested > by_budget:
        why.append(f"a command's budget of {COMMAND_MEMORY / 2**30:g} GB allows {by_budget} "
                   "(a cluster, --scheduler, takes more)")
    return workers, (f"{requested} local workers were asked for, {workers} started: each "
                     f"needs about {each / 2**20:,.0f} MB (libraries, drive tables, a batch's "
                     f"samples) and this machine has {' and '.join(why)}")

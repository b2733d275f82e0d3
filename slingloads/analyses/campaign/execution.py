"""Executing a campaign: runs in batches, on local worker processes or a Dask cluster, with a
store of finished runs so that an interrupted campaign resumes where it stopped.

**Batches.** The runs still missing from the store are cut, in matrix order (so that the runs
of one condition stay together and share their trim), into batches; each batch is one call of
:func:`.worker.run_batch`: the compiled Dormand-Prince 5(4) kernel integrates its runs together.

**Executors** (all give identical results: every run is integrated on its own, in the same
floating-point operations, whatever batch or process it falls in):

* :class:`InProcess`: the batches one after the other in this process, the compiled kernel on
  all the machine's cores;
* :class:`LocalProcesses`: ``workers`` processes of this machine (started with ``spawn``, each
  loading the compiled kernels from numba's on-disk cache), the cores shared out so that
  workers x kernel threads does not exceed them;
* :class:`DaskCluster`: the batches go to a ``dask.distributed`` scheduler; each batch's kernel
  runs on as many threads as the smallest worker has. The scheduler must answer within
  ``timeout`` seconds (default :data:`SCHEDULER_TIMEOUT`), or the campaign stops with an
  :class:`~slingloads.errors.InputError` before anything is run or stored. The workers need
  slingloads installed (the same version: the run keys include the code's digest).

**Store.** Anything with ``get(key)`` (a record or None), ``put(key, record)`` and
``__contains__``; a record is ``(metrics, histories)``. :class:`MemoryStore` keeps them in
memory; the Parquet run cache of the runs layer (``slingloads.runs.cache``) on disk. Each
finished batch is stored as soon as it arrives, so an interruption loses at most the batches in
flight.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

from slingloads.errors import InputError

from .worker import run_batch

#: Seconds the scheduler of a Dask cluster has to answer before the campaign gives up.
SCHEDULER_TIMEOUT = 10.0
#: Largest batch sent to a worker (runs).
MAX_BATCH = 100
#: Smallest batch worth a call (unless fewer runs are left). [runs]
MIN_BATCH = 20


class MemoryStore:
    """Finished runs kept in memory.

    Parameters
    ----------
    keep_histories : bool
        Keep each run's histories (False keeps the metrics only, for very large campaigns).
    """

    def __init__(self, keep_histories=True):
        self.keep_histories = bool(keep_histories)
        self._records = {}

    def __contains__(self, key):
        return key in self._records

    def __len__(self):
        return len(self._records)

    def get(self, key):
        return self._records.get(key)

    def put(self, key, record):
        metrics, histories = record
        self._records[key] = (metrics, histories if self.keep_histories else None)


def _cpu_count():
    return max(1, os.cpu_count() or 1)


class _Executor:
    """Common part of the executors: a context manager that closes them."""

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def close(self):
        """Release the workers (nothing to do by default)."""


class InProcess(_Executor):
    """The batches one after the other in this process (module notes)."""

    workers = 1

    def __init__(self, threads=None):
        self.threads = threads

    def describe(self):
        return "this process"

    def run(self, batches):
        for index, settings, jobs in batches:
            yield index, run_batch(jobs, settings, self.threads)


class LocalProcesses(_Executor):
    """``workers`` processes of this machine (module notes).

    Parameters
    ----------
    workers : int
        >= 1.
    """

    def __init__(self, workers):
        if isinstance(workers, bool) or int(workers) != workers or workers < 1:
            raise InputError("the number of workers must be a whole number >= 1", workers)
        self.workers = int(workers)
        self.threads = max(1, _cpu_count() // self.workers)
        self._pool = None

    def describe(self):
        return (f"{self.workers} local worker processes x {self.threads} kernel "
                f"thread{'s' if self.threads > 1 else ''}")

    def run(self, batches):
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed

        self._pool = ProcessPoolExecutor(self.workers,
                                         mp_context=multiprocessing.get_context("spawn"))
        futures = {self._pool.submit(run_batch, jobs, settings, self.threads): index
                   for index, settings, jobs in batches}
        for future in as_completed(futures):
            yield futures[future], future.result()

    def close(self):
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


class DaskCluster(_Executor):
    """The batches on a ``dask.distributed`` cluster (module notes).

    Parameters
    ----------
    address : str
        Scheduler address, e.g. ``"tcp://10.0.0.5:8786"``.
    timeout : float
        Seconds the scheduler has to answer. [s]

    Raises
    ------
    InputError
        When the scheduler cannot be reached within ``timeout``, or has no worker.
    """

    def __init__(self, address, timeout=SCHEDULER_TIMEOUT):
        from distributed import Client

        self.address = str(address)
        timeout = float(timeout)
        if not math.isfinite(timeout) or timeout <= 0:
            raise InputError("the scheduler time-out must be > 0 [s]", timeout)
        self.timeout = timeout
        try:
            self.client = Client(self.address, timeout=timeout, set_as_default=False)
        except (OSError, TimeoutError, ValueError, TypeError) as err:
            raise InputError(f"could not reach the Dask scheduler within {timeout:g} s "
                             f"({type(err).__name__}: {err}); nothing was run",
                             self.address) from None
        except (MemoryError, EOFError, RuntimeError) as err:
            # a server that is not a Dask scheduler: its first bytes read as an absurd frame
            # length (the client then asks for exabytes) or as a broken message
            raise InputError("the server at this address does not answer as a Dask scheduler "
                             f"({type(err).__name__}); nothing was run", self.address) from None
        try:
            self.client.wait_for_workers(1, timeout=timeout)
        except (OSError, TimeoutError) as err:
            self.client.close()
            raise InputError(f"the Dask scheduler has no worker after {timeout:g} s "
                             f"({type(err).__name__}); nothing was run", self.address) from None
        threads = self.client.nthreads()
        self.workers = max(1, sum(threads.values()))
        self.threads = max(1, min(threads.values()))

    def describe(self):
        return f"Dask cluster at {self.address} ({self.workers} worker threads)"

    def run(self, batches):
        from distributed import as_completed

        futures = {}
        for index, settings, jobs in batches:
            future = self.client.submit(run_batch, jobs, settings, self.threads, pure=False)
            futures[future] = index
        try:
            for future in as_completed(futures, loop=self.client.loop):
                yield futures[future], future.result()
        finally:
            for future in futures:
                future.cancel()

    def close(self):
        self.client.close()


def make_executor(scheduler=None, workers=None, timeout=SCHEDULER_TIMEOUT, runs=None):
    """The executor a campaign asks for.

    Parameters
    ----------
    scheduler : str, optional
        Address of a Dask scheduler: the batches go there.
    workers : int, optional
        Local worker processes (default: one per core, or this process alone for fewer than
        :data:`MAX_BATCH` runs, where starting processes would cost more than it saves).
    timeout : float
        Scheduler time-out. [s]
    runs : int, optional
        Runs to execute (for the default).
    """
    if scheduler:
        return DaskCluster(scheduler, timeout)
    if workers is None:
        workers = 1 if runs is not None and runs < MAX_BATCH else _cpu_count()
    if isinstance(workers, bool) or int(workers) != workers or workers < 1:
        raise InputError("the number of workers must be a whole number >= 1", workers)
    return InProcess() if int(workers) == 1 else LocalProcesses(int(workers))


@dataclass(frozen=True)
class ExecutionReport:
    """What an execution did.

    Attributes
    ----------
    total, cached, computed : int
        Runs in the campaign, found in the store, and run now.
    batches : int
    executor : str
    """

    total: int
    cached: int
    computed: int
    batches: int
    executor: str


def batch_size(missing, workers):
    """Runs per batch: about four batches per worker (for balance and progress), at least
    :data:`MIN_BATCH` and at most :data:`MAX_BATCH`."""
    if missing <= 0:
        return 1
    share = math.ceil(missing / (4 * max(1, workers)))
    return max(1, min(MAX_BATCH, max(share, min(MIN_BATCH, missing))))


def execute(groups, store, executor, *, size=None, progress=None):
    """Run every job whose key is not in ``store`` (module notes).

    Parameters
    ----------
    groups : sequence of (dict, list)
        (settings, jobs): ``settings`` holds ``t_end``, ``dt``, ``output_interval`` [s] and
        ``jobs`` the (key, system, manoeuvre) run with them, in matrix order. Equal keys are
        run once; a batch never mixes groups.
    store : MemoryStore or compatible
    executor : InProcess, LocalProcesses or DaskCluster
        Not closed here.
    size : int, optional
        Runs per batch (default :func:`batch_size`).
    progress : callable, optional
        ``progress(done, total)`` after the store is read and after every batch.

    Returns
    -------
    ExecutionReport
    """
    seen, missing, total = set(), [], 0
    for settings, jobs in groups:
        todo = []
        for job in jobs:
            if job[0] in seen:
                continue
            seen.add(job[0])
            total += 1
            if job[0] not in store:
                todo.append(job)
        missing.append((settings, todo))
    count = sum(len(todo) for _, todo in missing)
    size = batch_size(count, executor.workers) if size is None else size
    if isinstance(size, bool) or int(size) != size or size < 1:
        raise InputError("the batch size must be a whole number >= 1", size)
    size = int(size)
    batches = []
    for settings, todo in missing:
        for i in range(0, len(todo), size):
            batches.append((len(batches), settings, todo[i:i + size]))
    done = total - count
    if progress is not None:
        progress(done, total)
    for _, records in executor.run(batches):
        for key, metrics, histories in records:
            store.put(key, (metrics, histories))
        done += len(records)
        if progress is not None:
            progress(done, total)
    return ExecutionReport(total, total - count, count, len(batches), executor.describe())

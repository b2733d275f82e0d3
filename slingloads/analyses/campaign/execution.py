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
  workers x kernel threads does not exceed them; :func:`make_executor` caps the workers by
  the cores and the memory available (:mod:`.memory`), and a
  worker that dies ends the campaign with an :class:`~slingloads.errors.OutputError` (the
  finished runs stored);
* :class:`DaskCluster`: the batches go to a ``dask.distributed`` scheduler; each batch's kernel
  runs on as many threads as the smallest worker has. The scheduler must answer within
  ``timeout`` seconds (default :data:`SCHEDULER_TIMEOUT`), or the campaign stops with an
  :class:`~slingloads.errors.InputError` before anything is run or stored; every later
  network step has the same deadline (:class:`DaskCluster`). The workers need slingloads
  installed (the same version: the run keys include the code's digest).

**Memory.** A batch holds at most :data:`~slingloads.limits.BATCH_MEMORY` of samples
(:func:`.memory.batch_limit`); the drive tables are tabulated a chunk of runs at a time by the
multibody model (``DRIVE_BUDGET``).

**Store.** Anything with ``get(key)`` (a record or None), ``put(key, record)`` and
``__contains__``, and optionally ``expect(key, rows)`` (told each run's history rows before
it is looked up, so that a store on disk can refuse an entry of another size unread:
:func:`record_problem` is the contract); a record is ``(metrics, histories)``.
:class:`MemoryStore` keeps them in memory; the Parquet run cache of the runs layer
(``slingloads.runs.cache``) on disk. Each finished batch is stored as soon as it
arrives, so an interruption loses at most the batches in flight.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from slingloads.errors import InputError, OutputError

from .memory import (  # noqa: F401 - re-exported
    MAX_BATCH,
    MIN_BATCH,
    batch_limit,
    cpu_count,
    history_rows,
    local_workers,
    worker_memory,
)
from .worker import run_batch

#: Seconds the scheduler of a Dask cluster has to answer before the campaign gives up.
SCHEDULER_TIMEOUT = 10.0
#: Seconds a cluster's worker is allowed for a run-step of the compiled kernel when a batch
#: is waited for: ten times the measured 10 us a run-step on two cores
#: (:data:`~slingloads.limits.MAX_MULTIBODY_RUN_STEPS`), for a slower or busier machine. [s]
RUN_STEP_SECONDS = 1e-4
#: Shortest step counted for a run with the adaptive step (its steps are not known ahead):
#: a tenth of the campaign's usual fixed step of 0.01 s. [s]
ADAPTIVE_STEP_FLOOR = 1e-3
#: Seconds allowed on top for a worker to load slingloads and compile or load its kernels
#: (a fresh installation compiles them once, in about a minute of processor time). [s]
WORKER_START_SECONDS = 300.0


def batch_seconds(settings, runs):
    """The longest a batch of ``runs`` runs under ``settings`` is expected to take on a
    worker: its run-steps at :data:`RUN_STEP_SECONDS` each. The run-steps are runs x
    (``t_end`` / ``dt``) with a fixed step; with the adaptive one (``dt`` None) the larger of
    runs x (``t_end`` / :data:`ADAPTIVE_STEP_FLOOR`) and the
    :data:`~slingloads.limits.MAX_MULTIBODY_RUN_STEPS` that the stiffness check of a batch
    lets its fastest mode force. [s]

    Parameters
    ----------
    settings : dict
        ``t_end``, ``dt`` (None: adaptive) [s].
    runs : int
        Runs of the batch. [count]

    Returns
    -------
    float
        [s]
    """
    from slingloads.limits import MAX_MULTIBODY_RUN_STEPS

    t_end, dt = float(settings["t_end"]), settings.get("dt")
    if dt is None:
        steps = max(runs * t_end / ADAPTIVE_STEP_FLOOR, MAX_MULTIBODY_RUN_STEPS)
    else:
        steps = runs * t_end / float(dt)
    return steps * RUN_STEP_SECONDS
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
        """The record of run ``key``, or None.

        Parameters
        ----------
        key : str
            Key of a run.

        Returns
        -------
        (dict, ndarray or None) or None
            The run's record (metrics, histories), or None if it is not stored.
            [SI, angles in degrees: :func:`~.metrics.response_metrics`]
        """
        return self._records.get(key)

    def put(self, key, record):
        """Store the record of run ``key``.

        Parameters
        ----------
        key : str
            Key of a run.
        record : (dict, ndarray)
            Its metrics and histories (the histories dropped unless kept).
            [SI, angles in degrees: :func:`~.metrics.response_metrics`]
        """
        metrics, histories = record
        self._records[key] = (metrics, histories if self.keep_histories else None)


#: Metrics every record holds (whatever the run's outcome).
REQUIRED_METRICS = ("trim converged", "trim message", "linear verdict", "response verdict")


def record_problem(record, rows=None):
    """What makes ``record`` unusable as a finished run, in words, or None.

    A record is ``(metrics, histories)``: ``metrics`` a dict of texts to numbers, texts,
    booleans or None holding at least :data:`REQUIRED_METRICS`; ``histories`` a float array
    of ``rows`` (if given) x ``len(HISTORY_LABELS)``. A store (the disk cache) checks what
    it reads with this, so that a damaged or foreign entry counts as missing.

    Parameters
    ----------
    record : object
        What a store read for a run.
    rows : int, optional
        Samples the histories must have. [count]

    Returns
    -------
    str or None
        The problem, or None for a usable record.
    """
    import numpy as np

    from .metrics import HISTORY_LABELS

    try:
        metrics, histories = record
    except (TypeError, ValueError):
        return "not a (metrics, histories) pair"
    if not isinstance(metrics, dict):
        return f"the metrics are a {type(metrics).__name__}, not a mapping"
    for name, value in metrics.items():
        if not isinstance(name, str):
            return f"a metric name is a {type(name).__name__}"
        if value is not None and not isinstance(value, (str, bool, int, float)):
            return f"metric {name[:60]!r} is a {type(value).__name__}"
    absent = [m for m in REQUIRED_METRICS if m not in metrics]
    if absent:
        return f"metrics {absent} are missing"
    if histories is None:
        return None
    if not isinstance(histories, np.ndarray) or histories.dtype != np.float64:
        return "the histories are not an array of floats"
    expected = (rows if rows is not None else histories.shape[0], len(HISTORY_LABELS))
    if histories.shape != expected:
        return f"the histories have shape {histories.shape}, not {expected}"
    return None


class _Executor:
    """Common part of the executors: a context manager that closes them."""

    #: What the executor changed from what was asked (fewer workers), for the report.
    warnings = ()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def close(self):
        """Release the workers (nothing to do by default)."""


class InProcess(_Executor):
    """The batches one after the other in this process (module notes).

    Parameters
    ----------
    threads : int, optional
        Kernel threads of each batch (default: the cores). [count]
    """

    workers = 1

    def __init__(self, threads=None):
        self.threads = threads
        self.warnings = []

    def describe(self):
        """Where the batches run, in words for the report.

        Returns
        -------
        str
        """
        return "this process"

    def run(self, batches):
        """Execute the batches one after the other.

        Parameters
        ----------
        batches : iterable of (int, dict, list)
            (index, run settings, jobs) of each batch (:func:`~.worker.run_batch`). [-]

        Returns
        -------
        iterator of (int, list)
            (index, results of :func:`~.worker.run_batch`) of each batch as it finishes.
            [as :func:`~.worker.run_batch`]
        """
        for index, settings, jobs in batches:
            yield index, run_batch(jobs, settings, self.threads)


class LocalProcesses(_Executor):
    """``workers`` processes of this machine (module notes).

    Parameters
    ----------
    workers : int
        >= 1. [count]
    """

    def __init__(self, workers):
        if isinstance(workers, bool) or int(workers) != workers or workers < 1:
            raise InputError("the number of workers must be a whole number >= 1", workers)
        self.workers = int(workers)
        self.threads = max(1, cpu_count() // self.workers)
        self._pool = None
        self.warnings = []

    def describe(self):
        """Where the batches run, in words for the report.

        Returns
        -------
        str
        """
        return (f"{self.workers} local worker processes x {self.threads} kernel "
                f"thread{'s' if self.threads > 1 else ''}")

    def run(self, batches):
        """Execute the batches on the worker processes.

        Parameters
        ----------
        batches : iterable of (int, dict, list)
            (index, run settings, jobs) of each batch (:func:`~.worker.run_batch`). [-]

        Returns
        -------
        iterator of (int, list)
            (index, results of :func:`~.worker.run_batch`) of each batch as it finishes.
            [as :func:`~.worker.run_batch`]
        """
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed
        from concurrent.futures.process import BrokenProcessPool

        self._pool = ProcessPoolExecutor(self.workers,
                                         mp_context=multiprocessing.get_context("spawn"))
        futures = {self._pool.submit(run_batch, jobs, settings, self.threads): index
                   for index, settings, jobs in batches}
        try:
            for future in as_completed(futures):
                # dropped once handed on: a finished future holds its batch's records, and
                # all of them kept would hold every run's histories at once
                index = futures.pop(future)
                yield index, future.result()
                del future
        except BrokenProcessPool:
            raise OutputError("a local worker process ended abruptly (killed, or out of "
                              "memory); the runs finished before are stored: run the same "
                              "command again to resume (with fewer --workers if memory is "
                              "short)") from None

    def close(self):
        """Stop the worker processes once the runs handed to them have finished (cancelling those
        not started); a second call does nothing."""
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


def _within(seconds, call, *args):
    """``call(*args)`` in a helper thread, given up after ``seconds``: (done, value or
    error). A call that overruns keeps its (daemon) thread, which no one waits for."""
    import threading

    box = {}

    def target():
        try:
            box["value"] = call(*args)
        except BaseException as err:  # noqa: BLE001 - handed back to the caller
            box["error"] = err

    thread = threading.Thread(target=target, daemon=True, name="slingloads-deadline")
    thread.start()
    thread.join(seconds)
    if thread.is_alive():
        return False, None
    if "error" in box:
        return True, box["error"]
    return True, box.get("value")


async def _identity(address, timeout):
    """Connect to ``address``, exchange the comm handshake and ask the scheduler who it is,
    all within ``timeout`` seconds, with ``distributed``'s own comm (for the protocols that
    :mod:`.probe` does not speak); the reply, or an exception."""
    import asyncio

    from distributed.comm import connect

    async def ask():
        comm = await connect(address, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    return await asyncio.wait_for(ask(), timeout)


def _probe(address, timeout):
    """What is wrong with the scheduler at ``address``, in words, or None: it must answer the
    ``identity`` request as a Dask scheduler within ``timeout`` seconds (connection, handshake
    and reply; a silent server is given up at the deadline, a garbage-speaking one at once).
    Over tcp and tls the exchange is :func:`.probe.identity` (bounded memory: a message
    announced longer than :data:`.probe.MAX_PROBE_MESSAGE` is refused unread)."""
    import asyncio

    from . import probe

    if probe.split_address(address)[0] in probe.SPOKEN:
        done, value = _within(timeout + 0.2, probe.identity, address, timeout)
    else:
        done, value = _within(timeout + 0.2, lambda: asyncio.run(_identity(address, timeout)))
    if not done or isinstance(value, (TimeoutError, asyncio.TimeoutError)):
        return f"no answer within {timeout:g} s"
    if isinstance(value, probe.NotAScheduler):
        return f"the server at this address does not answer as a Dask scheduler ({value})"
    if isinstance(value, OSError):
        return f"could not connect ({type(value).__name__}: {value})"
    if isinstance(value, BaseException):
        if isinstance(value, (KeyboardInterrupt, SystemExit)):
            raise value
        return ("the server at this address does not answer as a Dask scheduler "
                f"({type(value).__name__})")
    if not isinstance(value, dict) or value.get("type") != "Scheduler":
        return ("the server at this address does not answer as a Dask scheduler (no "
                "scheduler identity)")
    return None


class DaskCluster(_Executor):
    """The batches on a ``dask.distributed`` cluster (module notes).

    Every network step has a deadline of ``timeout`` seconds: the scheduler must answer a
    first request (connection, handshake, identity) within it, then let the client connect
    and show a worker within it; while the batches run, a scheduler that stays silent
    for ``timeout`` seconds (no batch back, no answer to a liveness request) stops the
    campaign; so does a batch that has not come back (:meth:`run`: a hung worker) within
    ``timeout`` + :data:`WORKER_START_SECONDS` + the :func:`batch_seconds` of the longest
    batch after the previous one; closing the client waits at most ``timeout`` seconds.

    Parameters
    ----------
    address : str
        Scheduler address, e.g. ``"tcp://10.0.0.5:8786"``.
    timeout : float
        Seconds the scheduler has to answer. [s]

    Raises
    ------
    InputError
        When the scheduler cannot be reached or does not answer as one within ``timeout``,
        or has no worker.
    """

    def __init__(self, address, timeout=SCHEDULER_TIMEOUT):
        import time

        self.address = str(address)
        timeout = float(timeout)
        if not math.isfinite(timeout) or timeout <= 0:
            raise InputError("the scheduler time-out must be > 0 [s]", timeout)
        self.timeout = timeout
        self.client = None
        #: Seconds without a batch back after which :meth:`run` gives up (set by it). [s]
        self.stall = None
        start = time.monotonic()
        problem = _probe(self.address, timeout)
        if problem is not None and problem.startswith("the server"):
            raise InputError(f"{problem}; nothing was run", self.address)
        if problem is not None:
            raise InputError(f"could not reach the Dask scheduler within {timeout:g} s "
                             f"({problem}); nothing was run", self.address)
        left = max(0.5, timeout - (time.monotonic() - start))
        done, value = _within(left + 0.2, self._connect, left)
        if not done or isinstance(value, BaseException):
            self.close()
            if isinstance(value, (KeyboardInterrupt, SystemExit)):
                raise value
            why = "no answer" if not done else type(value).__name__
            raise InputError(f"could not reach the Dask scheduler within {timeout:g} s "
                             f"({why}); nothing was run", self.address)
        left = max(0.5, timeout - (time.monotonic() - start))
        try:
            self.client.wait_for_workers(1, timeout=left)
            threads = self.client.sync(self.client.scheduler.ncores, callback_timeout=left)
        except (OSError, TimeoutError) as err:
            self.close()
            raise InputError(f"the Dask scheduler has no worker after {timeout:g} s "
                             f"({type(err).__name__}); nothing was run", self.address) from None
        if not threads:
            self.close()
            raise InputError(f"the Dask scheduler has no worker after {timeout:g} s; nothing "
                             "was run", self.address)
        self.workers = max(1, sum(threads.values()))
        self.threads = max(1, min(threads.values()))

    def _connect(self, timeout):
        from distributed import Client

        self.client = Client(self.address, timeout=timeout, set_as_default=False)
        return self.client

    def describe(self):
        """Where the batches run, in words for the report.

        Returns
        -------
        str
        """
        return f"Dask cluster at {self.address} ({self.workers} worker threads)"

    def _alive(self):
        """True if the scheduler answers a liveness request within the time-out."""
        return self._identity() is not None

    def _identity(self):
        """The scheduler's answer to a liveness request within the time-out (its identity:
        ``workers`` among others), or None."""
        if self.client is None or self.client.status != "running":
            return None
        try:
            return self.client.sync(self.client.scheduler.identity,
                                    callback_timeout=self.timeout)
        except Exception:  # noqa: BLE001 - any failure is a scheduler gone silent
            return None

    def _check_progress(self):
        """Raise if nothing can finish: the scheduler silent, or left without a worker (its
        batches would wait for one for ever), after ``timeout`` seconds without a result."""
        identity = self._identity()
        if identity is None:
            raise OutputError(f"the Dask scheduler stopped answering (no answer within "
                              f"{self.timeout:g} s); the finished runs are stored: run again "
                              "to resume", self.address)
        if not identity.get("workers"):
            raise OutputError(f"the Dask scheduler has no worker left (none for "
                              f"{self.timeout:g} s: killed, or lost); the finished runs are "
                              "stored: run again to resume", self.address)

    def run(self, batches):
        """Execute the batches on the cluster.

        A batch that does not come back is given up: when no batch has arrived for
        ``timeout`` + :data:`WORKER_START_SECONDS` + the :func:`batch_seconds` of the
        longest batch, the campaign stops with an :class:`~slingloads.errors.OutputError`
        (the batches cancelled, the runs finished before stored), even while the scheduler
        answers and shows workers (a worker that accepted a batch and hangs).

        Parameters
        ----------
        batches : iterable of (int, dict, list)
            (index, run settings, jobs) of each batch (:func:`~.worker.run_batch`). [-]

        Returns
        -------
        iterator of (int, list)
            (index, results of :func:`~.worker.run_batch`) of each batch as it finishes.
            [as :func:`~.worker.run_batch`]
        """
        import time
        from concurrent.futures import CancelledError

        from distributed.client import _wait

        futures, longest = {}, 0.0
        for index, settings, jobs in batches:
            future = self.client.submit(run_batch, jobs, settings, self.threads, pure=False)
            futures[future] = index
            longest = max(longest, batch_seconds(settings, len(jobs)))
        self.stall = self.timeout + WORKER_START_SECONDS + longest
        pending = set(futures)
        try:
            last = time.monotonic()
            while pending:
                wait = max(0.05, min(self.timeout, last + self.stall - time.monotonic()))
                try:
                    finished, pending = self.client.sync(
                        _wait, list(pending), timeout=wait, return_when="FIRST_COMPLETED")
                    pending = set(pending)
                except TimeoutError:
                    finished = set()
                if not finished:
                    self._check_progress()
                    self._check_stall(last)
                for future in finished:
                    # forgotten once fetched (the cluster may free the batch's records)
                    index = futures.pop(future)
                    yield index, self._result(future, last)
                    future.release()
                    last = time.monotonic()
        except OutputError:
            raise
        except (CancelledError, OSError) as err:  # the scheduler lost: futures cancelled
            raise OutputError(f"the Dask scheduler was lost ({type(err).__name__}); the "
                              "finished runs are stored: run again to resume",
                              self.address) from None
        finally:
            client = self.client
            if futures and client is not None and client.status == "running":
                _within(self.timeout, client.cancel, list(futures))

    def _check_stall(self, last):
        """Raise if no batch has arrived for :attr:`stall` seconds since ``last``."""
        import time

        if time.monotonic() - last < self.stall:
            return
        raise OutputError(
            f"no batch has come back from the Dask cluster for {self.stall:,.0f} s (the "
            f"time-out of {self.timeout:g} s, {WORKER_START_SECONDS:g} s for a worker to "
            "start and the longest a batch's run-steps should take): a worker holds a batch "
            "and does not finish it (hung, or far slower than expected); the finished runs "
            "are stored: run again to resume", self.address)

    def _result(self, future, last):
        """A finished batch's records, fetched a time-out at a time while the scheduler
        answers (a large batch may take longer to arrive; a silent scheduler stops it), and
        given up :attr:`stall` seconds after ``last`` (the worker holding them hung)."""
        while True:
            try:
                return future.result(timeout=self.timeout)
            except TimeoutError:
                self._check_progress()
                self._check_stall(last)

    def close(self):
        """Close the client, waiting at most the time-out (a dead scheduler is not waited
        for longer)."""
        client, self.client = self.client, None
        if client is None:
            return
        _within(self.timeout, lambda: client.close(timeout=self.timeout))


def make_executor(scheduler=None, workers=None, timeout=SCHEDULER_TIMEOUT, runs=None,
                  settings=None):
    """The executor a campaign asks for.

    Parameters
    ----------
    scheduler : str, optional
        Address of a Dask scheduler: the batches go there.
    workers : int, optional
        Local worker processes (default: one per core, or this process alone for fewer than
        :data:`MAX_BATCH` runs, where starting processes would cost more than it saves);
        capped by the cores, the memory available and a command's budget
        (:func:`local_workers`: an explicit larger request is cut, with a warning in the
        executor's ``warnings``). [count]
    timeout : float
        Scheduler time-out. [s]
    runs : int, optional
        Runs to execute (for the default). [count]
    settings : dict, optional
        The runs' settings (``t_end``, ``output_interval`` [s]), for the memory estimate.

    Returns
    -------
    InProcess, LocalProcesses or DaskCluster
    """
    if scheduler:
        return DaskCluster(scheduler, timeout)
    explicit = workers is not None
    if workers is None:
        workers = 1 if runs is not None and runs < MAX_BATCH else cpu_count()
    if isinstance(workers, bool) or int(workers) != workers or workers < 1:
        raise InputError("the number of workers must be a whole number >= 1", workers)
    workers, warning = local_workers(int(workers), settings)
    executor = InProcess() if workers == 1 else LocalProcesses(workers)
    if warning is not None and explicit:
        executor.warnings.append(warning)
    return executor


@dataclass(frozen=True)
class ExecutionReport:
    """What an execution did.

    Attributes
    ----------
    total, cached, computed : int
        Runs in the campaign, found in the store, and run now (every group). [count]
    batches : int
        Batches executed. [count]
    executor : str
    parts : tuple of (int, int, int)
        (total, cached, computed) of each group of runs, in the order given (a campaign: the
        matrix, then the runs without parachute), each run counted in the first group that
        holds it. [count]
    """

    total: int
    cached: int
    computed: int
    batches: int
    executor: str
    parts: tuple = ()


def batch_size(missing, workers, settings=None):
    """Runs per batch: about four batches per worker (for balance and progress), at least
    :data:`MIN_BATCH` and at most :data:`MAX_BATCH`, and no more than fit the memory of a
    batch (:func:`batch_limit` under ``settings``).

    Parameters
    ----------
    missing : int
        Runs still to execute. [count]
    workers : int
        Workers of the executor. [count]
    settings : dict, optional
        The runs' settings (``t_end``, ``output_interval`` [s]).

    Returns
    -------
    int
        Runs per batch. [count]
    """
    if missing <= 0:
        return 1
    share = math.ceil(missing / (4 * max(1, workers)))
    size = max(1, min(MAX_BATCH, max(share, min(MIN_BATCH, missing))))
    return size if settings is None else min(size, batch_limit(settings))


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
        Runs per batch (default :func:`batch_size`). [count]
    progress : callable, optional
        ``progress(done, total)`` after the store is read and after every batch.

    Returns
    -------
    ExecutionReport
    """
    seen, missing, total, parts = set(), [], 0, []
    expect = getattr(store, "expect", None)  # a store that checks the size of what it reads
    for settings, jobs in groups:
        todo, count = [], 0
        for job in jobs:
            if job[0] in seen:
                continue
            seen.add(job[0])
            total += 1
            count += 1
            if expect is not None:
                expect(job[0], history_rows(settings))
            if job[0] not in store:
                todo.append(job)
        missing.append((settings, todo))
        parts.append((count, count - len(todo), len(todo)))
    count = sum(len(todo) for _, todo in missing)
    if size is not None and (isinstance(size, bool) or int(size) != size or size < 1):
        raise InputError("the batch size must be a whole number >= 1", size)
    batches = []
    for settings, todo in missing:
        # a batch's samples stay within BATCH_MEMORY whatever size is asked for
        step = (batch_size(count, executor.workers, settings) if size is None
                else min(int(size), batch_limit(settings)))
        for i in range(0, len(todo), step):
            batches.append((len(batches), settings, todo[i:i + step]))
    done = total - count
    if progress is not None:
        progress(done, total)
    for _, records in executor.run(batches):
        for key, metrics, histories in records:
            store.put(key, (metrics, histories))
        done += len(records)
        if progress is not None:
            progress(done, total)
    return ExecutionReport(total, total - count, count, len(batches), executor.describe(),
                           tuple(parts))

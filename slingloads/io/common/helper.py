"""Helper processes: calls run on the machine's other core while this process goes on.

A :class:`Helper` is one or more forked processes that run calls (a function of a module and
its arguments, pickled) in the order they are submitted, while the process that submitted
them does other work. Each call is a :class:`Call` whose :meth:`Call.result` returns the
value, or raises the exception the call raised (an :class:`~slingloads.errors.InputError`
stays an InputError with its message). A call that no helper process has started when its
result is asked for is taken back and run in the asking process: the two processes share
the work to the end, and nothing is lost if a helper process dies.

A helper process is forked early (while the process is small: cheap to fork, little memory
copied on write), then imports what its calls will need (``warm``) while its parent reads its
inputs. It ignores Ctrl-C (the parent handles it: a terminal sends it to both), dies with its
parent (Linux ``PR_SET_PDEATHSIG``: a parent killed outright leaves no helper behind) and is
killed when the parent leaves the ``with`` block on an error; a helper never writes a file
that is published (its results go back to the parent), so a run stays all or nothing.

Helpers are used where ``fork`` is the safe way to start a process (Linux) and there are at
least two processors (:func:`helper_processes`).
"""

from __future__ import annotations

import ctypes
import gc
import multiprocessing
import os
import pickle
import signal
import sys
import threading
import traceback
from collections import deque
from contextlib import contextmanager
from importlib import import_module

from slingloads.errors import InputError

#: Environment variable: number of helper processes (``0``: every call runs in the process
#: that asks for its result).
PROCESSES_VARIABLE = "SLINGLOADS_PLOT_WORKERS"

_PENDING, _RUNNING, _DONE = "pending", "running", "done"


def helper_processes():
    """Helper processes to start: ``SLINGLOADS_PLOT_WORKERS`` when set, else 1 on a Linux
    machine with two processors or more (the helper and this process fill two cores), else 0
    (where ``fork`` is not the safe way to start a process: Windows, macOS)."""
    text = os.environ.get(PROCESSES_VARIABLE, "").strip()
    if text:
        try:
            return max(0, int(text))
        except ValueError:
            raise InputError(f"{PROCESSES_VARIABLE} must be a whole number of processes",
                             text) from None
    if not sys.platform.startswith("linux") or (os.cpu_count() or 1) < 2:
        return 0
    return 1


class RemoteTraceback(Exception):
    """The traceback of an exception raised in a helper process (its ``__cause__``)."""

    def __str__(self):
        return self.args[0]


class Call:
    """A call submitted to a :class:`Helper`: ``result()`` is its value."""

    __slots__ = ("helper", "payload", "func", "args", "kwargs", "state", "value", "error")

    def __init__(self, helper, func, args, kwargs):
        self.helper = helper
        self.func, self.args, self.kwargs = func, args, kwargs
        self.payload = None  # the pickled call, for a helper process
        self.state = _PENDING
        self.value = self.error = None

    def result(self, take_back=True):
        """The call's value, re-raising the exception the call raised: waiting for the
        helper process that runs it, or running it here if none has started it (with
        ``take_back=False``, waiting for a helper to start it, unless none is left)."""
        return self.helper._result(self, take_back)

    def done(self):
        """True once the call has run (its result is there)."""
        return self.state == _DONE


class Helper:
    """Forked processes that run calls in submission order (see the module notes).

    Use as a context manager. With ``processes=0`` no process is started and every call runs
    when its result is first asked for.

    Parameters
    ----------
    processes : int, optional
        Helper processes (default :func:`helper_processes`).
    warm : sequence of str
        Modules each helper process imports as soon as it starts (before any call).
    """

    def __init__(self, processes=None, warm=()):
        self.processes = helper_processes() if processes is None else int(processes)
        self._warm = tuple(warm)
        self._calls = deque()
        self._cond = threading.Condition()
        self._closing = False
        self._workers = []  # (process, connection, feeding thread)
        self._alive = 0  # feeding threads still running
        self._started = False

    # ---- life cycle ---------------------------------------------------------------------
    def __enter__(self):
        self.start()
        return self

    def start(self):
        """Fork the helper processes now (no-op when already started or none asked)."""
        if self._started or self.processes <= 0:
            self._started = True
            return self
        self._started = True
        context = multiprocessing.get_context("fork")  # (none where fork is unsafe: 0 asked)
        for _ in range(self.processes):
            here, there = context.Pipe()
            process = context.Process(target=_serve, args=(there, os.getpid(), self._warm),
                                      daemon=True, name="slingloads-helper")
            # Ctrl-C is held back while the process forks: the new process starts with it
            # blocked and ignores it before unblocking it (a Ctrl-C in between would end it
            # with a traceback); this one receives a Ctrl-C held back once it is registered
            # (SIGTERM likewise: the new process takes the default action before unblocking
            # it, so that a SIGTERM at once, as when this process exits, ends it silently)
            blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
            try:
                process.start()
                there.close()
                self._alive += 1
                thread = threading.Thread(target=self._feed, args=(here,), daemon=True,
                                          name="slingloads-helper-feed")
                thread.start()
                self._workers.append((process, here, thread))
            finally:
                signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        return self

    def __exit__(self, exc_type, exc, tb):
        self.close(abort=exc_type is not None)
        return False

    def close(self, abort=False):
        """Stop the helper processes, dropping the calls not yet started: after their
        current calls, or at once (``abort``: killed)."""
        with self._cond:
            self._closing = True
            self._calls.clear()  # no one asked for their results
            self._cond.notify_all()
        for process, conn, thread in self._workers:
            if abort and process.is_alive():
                process.kill()
            thread.join()
            conn.close()
            process.join()
        self._workers = []

    # ---- calls --------------------------------------------------------------------------
    def submit(self, func, *args, **kwargs):
        """Submit ``func(*args, **kwargs)`` (picklable: a module-level function and data);
        returns its :class:`Call`."""
        call = Call(self, func, args, kwargs)
        if self._workers:
            try:
                call.payload = pickle.dumps((func, args, kwargs),
                                            protocol=pickle.HIGHEST_PROTOCOL)
            except Exception:  # noqa: BLE001 - cannot travel: run here when asked for
                return call
            with self._cond:
                self._calls.append(call)
                self._cond.notify()
        return call

    def backlog(self):
        """Calls submitted that no helper process has started yet."""
        return len(self._calls)

    def _result(self, call, take_back=True):
        with self._cond:
            while call.state == _RUNNING or (
                    call.state == _PENDING and not take_back and self._alive
                    and not self._closing and call in self._calls):
                self._cond.wait()
            if call.state == _PENDING:  # no helper has started it: run it here
                if call in self._calls:
                    self._calls.remove(call)
                call.state = _RUNNING
                local = True
            else:
                local = False
        if local:
            try:
                call.value = call.func(*call.args, **call.kwargs)
            except BaseException as err:
                call.error = err
                raise
            finally:
                with self._cond:
                    call.state = _DONE
                    self._cond.notify_all()
            return call.value
        if call.error is not None:
            raise call.error
        return call.value

    def _feed(self, conn):
        """Hand the calls to one helper process, one at a time, and collect their results
        (a thread of this process)."""
        try:
            self._feed_calls(conn)
        finally:
            with self._cond:
                self._alive -= 1
                self._cond.notify_all()
            try:
                conn.send_bytes(b"")  # stop
            except OSError:
                pass

    def _feed_calls(self, conn):
        while True:
            with self._cond:
                while not self._calls and not self._closing:
                    self._cond.wait()
                if not self._calls:
                    break
                call = self._calls.popleft()
                call.state = _RUNNING
            try:
                conn.send_bytes(call.payload)
                ok, value = pickle.loads(conn.recv_bytes())
            except (EOFError, OSError, pickle.UnpicklingError):  # the helper died
                with self._cond:
                    call.state = _PENDING  # run by whoever asks for it
                    self._cond.notify_all()
                break
            with self._cond:
                if ok:
                    call.value = value
                else:
                    call.error, text = value
                    call.error.__cause__ = RemoteTraceback(f'\n"""\n{text}"""')
                call.state = _DONE
                call.payload = None
                self._cond.notify_all()


_CURRENT = []


@contextmanager
def running(helper):
    """Make ``helper`` the run's helper inside the block (:func:`current`,
    :func:`in_background`)."""
    _CURRENT.append(helper)
    try:
        yield helper
    finally:
        _CURRENT.remove(helper)


def current():
    """The helper of the run in progress (:func:`running`), or None."""
    return _CURRENT[-1] if _CURRENT else None


def in_background(func, *args, **kwargs):
    """``func(*args, **kwargs)`` handed to the run's helper: its :class:`Call`, whose
    ``result()`` is the value. The helper runs it after the calls submitted before it; when
    its result is asked for before a helper has started it, or with no helper, it runs in the
    asking process (the same value either way)."""
    helper = current()
    return (helper if helper is not None else Helper(0)).submit(func, *args, **kwargs)


def gather(items, least=1):
    """The results of ``items`` (:class:`Call` objects, or values returned as they are).

    When at least ``least`` calls wait that no helper process has started, they are run
    here, from the last one back (a helper takes them from the front: the two meet in the
    middle); then the others are waited for. (A larger ``least`` keeps a few short calls
    for the helper when the first one run here would cost more, e.g. a library to load.)
    """
    items = list(items)
    waiting = [i for i in items if isinstance(i, Call) and i.state == _PENDING]
    if len(waiting) >= least:
        for call in reversed(waiting):
            if call.state == _PENDING:
                call.result()
    return [item.result(take_back=False) if isinstance(item, Call) else item
            for item in items]


# ---- the helper process ---------------------------------------------------------------------
def _die_with_parent(parent):
    """Be killed when the parent dies (Linux), and stop now if it is already gone."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - not Linux
        pass
    if os.getppid() != parent:
        os._exit(0)


def _portable(err):
    """``(err, its traceback as text)``, ``err`` replaced by a RuntimeError with its text if
    it does not survive pickling."""
    text = "".join(traceback.format_exception(err))
    try:
        pickle.loads(pickle.dumps(err))
    except Exception:  # noqa: BLE001 - any exception that does not travel is replaced
        err = RuntimeError(f"{type(err).__name__}: {err}")
    return err, text


def _warm(name):
    """Import module ``name`` and run its ``warm_up()`` if it has one."""
    try:
        module = import_module(name)
        getattr(module, "warm_up", lambda: None)()
    except Exception:  # noqa: BLE001 - a call that needs the module will raise the error
        pass


def _serve(conn, parent, warm):
    """Body of a helper process: run the calls received until told to stop, importing the
    modules ``warm`` in order whenever no call is waiting."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handler (a traceback)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})  # the fork's
    _die_with_parent(parent)
    warm = list(warm)
    # importing makes little garbage, and what is loaded lives to the end: the collector is
    # off while modules load before the first call, and told not to scan them again after
    gc.disable()
    while True:
        if warm and not conn.poll():  # warm up while no call waits
            _warm(warm.pop(0))
            if not warm and gc.isenabled():
                gc.freeze()
            continue
        if not gc.isenabled():
            gc.freeze()
            gc.enable()
        try:
            message = conn.recv_bytes()
        except (EOFError, OSError):
            break
        if not message:
            break
        try:
            func, args, kwargs = pickle.loads(message)
            answer = (True, func(*args, **kwargs))
        except Exception as err:  # noqa: BLE001 - handed to the parent, which raises it
            answer = (False, _portable(err))
        try:
            data = pickle.dumps(answer, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception as err:  # noqa: BLE001 - a value that cannot travel
            data = pickle.dumps((False, _portable(err)), protocol=pickle.HIGHEST_PROTOCOL)
        try:
            conn.send_bytes(data)
        except OSError:
            break
    os._exit(0)

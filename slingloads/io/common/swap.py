"""The folder exchange under the publisher: locks, staging-folder names, the atomic exchange
of two folders and the recovery of what killed runs left.

Guarantees: :func:`exchange_folders` swaps two folders in one atomic step where the kernel allows
(Linux ``renameat2(RENAME_EXCHANGE)``, macOS ``renamex_np(RENAME_SWAP)``), else by two
renames whose interruption :func:`recover` repairs (under the parent folder's lock, the
next run puts the complete new set, or else the old one, back in place and removes only the
folders of dead runs: each live run holds a lock on its staging folder). Used by
:mod:`slingloads.io.common.atomic`.
"""

from __future__ import annotations

import ctypes
import errno
import hashlib
import os
import platform
import shutil
import sys
import time
from contextlib import contextmanager
from pathlib import Path

try:  # POSIX advisory locks; elsewhere runs are not serialised
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None

#: Prefix of the staging and old folders (hidden on POSIX), beside the output folder.
TEMP_PREFIX = ".slingloads-"
#: Environment variable (testing aid): seconds to pause between the publishing steps, so that
#: a test can kill a run at each of them.
PAUSE_VARIABLE = "SLINGLOADS_PUBLISH_PAUSE"
#: Environment variable (testing aid): ``rename`` forces the two-rename publishing used where
#: no atomic exchange exists.
SWAP_VARIABLE = "SLINGLOADS_PUBLISH_SWAP"
#: Environment variable (testing aid): a folder in which the run announces each pause between
#: its publishing steps by an empty file named by its number (``1``, ``2``, ...) and waits
#: there until the file is removed, so that a test can stop a run in a given step without
#: guessing when it comes (at most 10 minutes a step: never a hang).
STEP_VARIABLE = "SLINGLOADS_PUBLISH_STEPS"
_STEPS = []
_NAME_MAX = 255


def stage_prefix(real, kind):
    """``.slingloads-<12 hex digits of the folder's name>.<kind>.``: short whatever the name."""
    tag = hashlib.sha256(os.fsencode(real.name)).hexdigest()[:12]
    return f"{TEMP_PREFIX}{tag}.{kind}."


def is_current_folder(real):
    """True if ``real`` is the process's current folder (which cannot be exchanged)."""
    try:
        return os.path.samefile(real, os.getcwd())
    except (OSError, ValueError):  # no current folder, or the output folder is not there yet
        return False


def is_writable(folder):
    """True if files may be created in ``folder``: permitted to this user, and not marked
    read-only by its mode (which is respected even by an administrator)."""
    try:
        mode = os.stat(folder).st_mode
    except OSError:
        return False
    return os.access(folder, os.W_OK | os.X_OK) and bool(mode & 0o222)


def longest_name(folder):
    """The longest file name ``folder``'s file system takes [characters] (255 where it
    cannot be told)."""
    try:
        return int(os.pathconf(folder, "PC_NAME_MAX"))
    except (OSError, ValueError, AttributeError):
        return _NAME_MAX


def pause_if_asked():
    """Pause between publishing steps when asked (testing aid: see PAUSE_VARIABLE and
    STEP_VARIABLE)."""
    folder = os.environ.get(STEP_VARIABLE)
    if folder:
        _STEPS.append(None)
        marker = Path(folder, str(len(_STEPS)))
        marker.touch()
        deadline = time.monotonic() + 600
        while marker.exists() and time.monotonic() < deadline:
            time.sleep(0.005)
    text = os.environ.get(PAUSE_VARIABLE)
    if text:
        try:
            seconds = float(text)
        except ValueError:
            return
        if 0 < seconds < 60:
            time.sleep(seconds)


def _flock(folder, blocking):
    """Open ``folder`` and take an exclusive lock on it: ``(descriptor, locked)``, the
    descriptor None where folders cannot be opened or locks do not exist."""
    if fcntl is None:
        return None, False
    try:
        fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return None, False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX if blocking else fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return fd, False
    return fd, True


@contextmanager
def publishing_lock(folder):
    """Hold an exclusive lock on ``folder`` (serialises the runs publishing beside it; where
    the folder cannot be locked, publishing goes on unserialised)."""
    fd, _ = _flock(folder, blocking=True)
    try:
        yield
    finally:
        if fd is not None:
            os.close(fd)


def lock_folder(folder):
    """Open and lock a staging folder for the life of this run; the descriptor, or None."""
    return _flock(folder, blocking=False)[0]


def _owner_alive(folder):
    """True if a live run holds the lock of a staging folder."""
    fd, locked = _flock(folder, blocking=False)
    if fd is not None:
        os.close(fd)
    return fd is not None and not locked


def recover(parent, real):
    """Repair what killed runs left beside the output folder ``real`` (under the lock).

    A ``.ready`` folder (a complete new set) or an ``.old`` folder (the previous set) found
    while the output folder is missing means a run died between the two renames of the
    fallback publishing: the new set is put in place (or else the old one back). Every other
    folder of dead runs is removed.
    """
    prefix = stage_prefix(real, "")[:-1]
    try:
        leftovers = sorted(e.name for e in os.scandir(parent)
                           if e.name.startswith(prefix) and e.is_dir(follow_symlinks=False))
    except OSError:
        return
    dead = [parent / n for n in leftovers if not _owner_alive(parent / n)]
    for kind in ("ready", "old"):
        if os.path.lexists(real):
            break
        for path in dead:
            if path.name.startswith(f"{prefix}{kind}."):
                try:
                    os.rename(path, real)
                    dead.remove(path)
                except OSError:
                    continue
                break
    for path in dead:
        shutil.rmtree(path, ignore_errors=True)


def exchange_folders(a, b):
    """Exchange two folders atomically, or by two renames where that is not possible."""
    if os.environ.get(SWAP_VARIABLE, "").lower() != "rename" and _atomic_exchange(a, b):
        return
    ready = a.with_name(a.name.replace(".new.", ".ready.", 1))
    old = a.with_name(a.name.replace(".new.", ".old.", 1))
    os.rename(a, ready)  # the complete new set, marked ready
    try:
        os.rename(b, old)
    except BaseException:
        os.rename(ready, a)  # back under the staging name, which the caller removes
        raise
    try:
        pause_if_asked()
        os.rename(ready, b)
    except BaseException:
        if not os.path.lexists(b):
            os.rename(old, b)  # put the previous set back
        os.rename(ready, a)
        raise
    os.rename(old, a)  # the old set under the staging name, removed by the caller


def _atomic_exchange(a, b):
    """``renameat2(RENAME_EXCHANGE)`` (Linux) or ``renamex_np(RENAME_SWAP)`` (macOS).

    Returns False where neither is available (the caller then renames twice); raises
    OSError on a real failure.
    """
    call = _exchange_call()
    if call is None:
        return False
    result = call(os.fsencode(str(a)), os.fsencode(str(b)))
    if result == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EPERM):
        return False  # not supported by this kernel or file system
    raise OSError(code, os.strerror(code), str(b))


_EXCHANGE = []


def _exchange_call():
    """The platform's atomic exchange of two paths, as ``call(a, b) -> 0 or -1``, or None."""
    if _EXCHANGE:
        return _EXCHANGE[0]
    call = None
    try:
        libc = ctypes.CDLL(None, use_errno=True)
    except OSError:  # pragma: no cover
        libc = None
    if libc is not None and sys.platform.startswith("linux"):
        at_fdcwd, rename_exchange = -100, 2
        function = getattr(libc, "renameat2", None)
        if function is not None:
            function.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                                 ctypes.c_uint]
            function.restype = ctypes.c_int

            def call(a, b):
                return function(at_fdcwd, a, at_fdcwd, b, rename_exchange)
        else:
            number = {"x86_64": 316, "aarch64": 276}.get(platform.machine())
            syscall = getattr(libc, "syscall", None)
            if number is not None and syscall is not None:
                syscall.restype = ctypes.c_long

                def call(a, b):
                    return syscall(ctypes.c_long(number), ctypes.c_int(at_fdcwd),
                                   ctypes.c_char_p(a), ctypes.c_int(at_fdcwd),
                                   ctypes.c_char_p(b), ctypes.c_uint(rename_exchange))
    elif libc is not None and sys.platform == "darwin":  # pragma: no cover
        function = getattr(libc, "renamex_np", None)
        if function is not None:
            function.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_uint]
            function.restype = ctypes.c_int

            def call(a, b):
                return function(a, b, 2)  # RENAME_SWAP
    _EXCHANGE.append(call)
    return call

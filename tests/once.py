"""Things the session's parallel workers make once between them.

A session fixture runs once per process: with pytest-xdist's workers each would run the
example's reports again. :func:`made_once` makes a folder once for the whole session: the
first worker that asks makes it under an exclusive lock (``fcntl.flock``) in a folder all the
session's workers share (the parent of each worker's base temporary folder, which is the
session's own), the others wait for the lock and read what it made. A folder whose making
failed is removed and left unmarked: the next worker that asks makes it again, and fails in
its own tests as well. Without workers (``-n 0``) the folder is made in the process's own
temporary folder, as any session fixture's.
"""

from __future__ import annotations

import fcntl
import os
import pickle
import shutil
from collections.abc import Callable
from pathlib import Path


def made_once(tmp_path_factory, name: str, make: Callable[[Path], None]) -> Path:
    """The folder ``name`` made by ``make(folder)`` once for the session (the folder does
    not exist when ``make`` is called; ``make`` creates it). To be read, not changed."""
    if not os.environ.get("PYTEST_XDIST_WORKER"):
        folder = tmp_path_factory.mktemp(name) / name
        make(folder)
        return folder
    root = tmp_path_factory.getbasetemp().parent / "made-once"
    root.mkdir(exist_ok=True)
    folder, done = root / name, root / f"{name}.done"
    with open(root / f"{name}.lock", "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
        if not done.exists():
            shutil.rmtree(folder, ignore_errors=True)  # a failed attempt's remains
            make(folder)
            done.touch()
    return folder


def computed_once(tmp_path_factory, name: str, compute: Callable[[], object]) -> object:
    """The value of ``compute()`` computed once for the session and read back by each worker
    from its pickle (the product's own objects, as the worker that computed them held
    them; a worker that computed it returns its own object)."""
    value = []

    def make(folder):
        value.append(compute())
        folder.mkdir(parents=True)
        part = folder / "value.pickle.part"
        part.write_bytes(pickle.dumps(value[0], protocol=pickle.HIGHEST_PROTOCOL))
        part.replace(folder / "value.pickle")

    folder = made_once(tmp_path_factory, name, make)
    return value[0] if value else pickle.loads((folder / "value.pickle").read_bytes())

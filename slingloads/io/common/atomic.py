"""Atomic writing of a set of output files.

A report is several files (workbook, CSV tables, PNG plots). They are all produced in a
temporary directory created *inside* the output directory, so that it lies on the same file
system, and only when every file has been produced are they moved into place one by one with
:func:`os.replace` (an atomic rename on POSIX and Windows). If anything fails before that, the
temporary directory is removed and the output directory is left exactly as it was: an earlier
report at the same paths is intact and no partial or temporary file remains.

An output is never written onto an input: every output path is checked against the input
paths given (same path after resolving symbolic links, or the same file through a hard link),
and a clash raises :class:`~slingloads.errors.InputError` naming the input.

Examples
--------
>>> import tempfile, pathlib
>>> out_dir = pathlib.Path(tempfile.mkdtemp())
>>> with atomic_outputs(out_dir) as out:
...     _ = out.path("a.txt").write_text("hello")
>>> [p.name for p in out.written]
['a.txt']
"""

from __future__ import annotations

import os
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path

from slingloads.errors import InputError

#: Prefix of the temporary directory (hidden on POSIX); left behind only if the process dies.
TEMP_PREFIX = ".slingloads-partial-"


def _same_file(a, b):
    """True if paths ``a`` and ``b`` name the same file (resolved path, or same inode)."""
    a, b = Path(a), Path(b)
    if a.resolve() == b.resolve():
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:  # one of them does not exist: they cannot be the same file
        return False


def check_not_input(path, inputs):
    """Refuse an output path that is one of the input files.

    Parameters
    ----------
    path : path-like
        Output path about to be written.
    inputs : iterable of path-like
        Input files that must never be overwritten.

    Raises
    ------
    InputError
        If ``path`` is (or links to) one of ``inputs``; the error names the input file.
    """
    for source in inputs:
        if _same_file(path, source):
            raise InputError("refusing to write an output onto an input file (an input is "
                             "never overwritten); choose another output directory or stem",
                             str(path), file=str(source))


class AtomicOutputs:
    """Collects output files in a temporary directory and moves them into place at the end.

    Use through :func:`atomic_outputs`. Ask for the path of every output with :meth:`path`,
    write the file there, and leave the ``with`` block normally to publish them all.

    Parameters
    ----------
    out_dir : path-like
        Output directory; created (with parents) if it does not exist.
    inputs : iterable of path-like
        Input files that must never be overwritten.
    """

    def __init__(self, out_dir, inputs=()):
        self.out_dir = Path(out_dir)
        self.inputs = [Path(p) for p in inputs]
        self.written = []
        self._names = {}
        self._tmp = None
        self._created_dir = False

    def __enter__(self):
        if not self.out_dir.exists():
            self.out_dir.mkdir(parents=True)
            self._created_dir = True
        elif not self.out_dir.is_dir():
            raise InputError("output directory is not a directory", str(self.out_dir))
        self._tmp = Path(tempfile.mkdtemp(prefix=TEMP_PREFIX, dir=self.out_dir))
        return self

    def __fspath__(self):
        """The output directory, so that ``Path(outputs) / name`` is a final path."""
        return str(self.out_dir)

    def path(self, name):
        """Temporary path at which to write the output file ``name``.

        Parameters
        ----------
        name : str
            File name (no directory part) of the output in the output directory.

        Returns
        -------
        pathlib.Path
            Where to write the file now; it is moved to ``out_dir / name`` on success.

        Raises
        ------
        InputError
            If ``name`` has a directory part, was already asked for, or would overwrite an
            input file.
        """
        if self._tmp is None:
            raise RuntimeError("AtomicOutputs.path() is only valid inside the with block")
        name = str(name)
        if not name or Path(name).name != name or name in (".", ".."):
            raise InputError("an output name must be a plain file name without a directory "
                             "part", name)
        if name in self._names:
            raise InputError("the same output file is written twice", name)
        final = self.out_dir / name
        check_not_input(final, self.inputs)
        self._names[name] = final
        return self._tmp / name

    def _commit(self):
        missing = [n for n in self._names if not (self._tmp / n).is_file()]
        if missing:
            raise RuntimeError(f"outputs were announced but not written: {missing}")
        for name, final in self._names.items():
            os.replace(self._tmp / name, final)
            self.written.append(final)

    def _cleanup(self):
        if self._tmp is not None:
            shutil.rmtree(self._tmp, ignore_errors=True)
            self._tmp = None

    def __exit__(self, exc_type, exc, tb):
        try:
            if exc_type is None:
                self._commit()
        finally:
            self._cleanup()
            if exc_type is not None and self._created_dir:
                try:
                    self.out_dir.rmdir()  # only if still empty
                except OSError:
                    pass
        return False


@contextmanager
def atomic_outputs(out_dir, inputs=()):
    """Context manager that publishes a set of output files all at once, or none.

    Parameters
    ----------
    out_dir : path-like or AtomicOutputs
        Output directory (created if needed). The temporary directory is made inside it so
        that the final :func:`os.replace` is a rename on one file system. Given an open
        :class:`AtomicOutputs`, the files join its set and are published with it, so that
        several writers publish all their files together, or none.
    inputs : iterable of path-like
        Input files that must never be overwritten.

    Yields
    ------
    AtomicOutputs
        ``out.path(name)`` gives the temporary path to write ``name`` to; after the block,
        ``out.written`` lists the final paths in the order they were asked for.

    Raises
    ------
    InputError
        If an output would overwrite an input file.
    """
    if isinstance(out_dir, AtomicOutputs):
        # nested: the files join the outer set, which the outer block publishes
        out_dir.inputs.extend(Path(p) for p in inputs)
        yield out_dir
        return
    with AtomicOutputs(out_dir, inputs) as out:
        yield out

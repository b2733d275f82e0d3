"""Publishing a set of output files all at once, or not at all; never onto an input.

A report is several files (workbooks, CSV tables, PNG plots) written as ``DIR/<stem>-...``.
They are published as one set:

1. every file of the new set is written into a fresh *staging folder* beside ``DIR`` (in the
   same parent folder, so on the same file system), named ``.slingloads-<tag>.new.<random>``;
2. under a lock on the parent folder (runs on one ``DIR`` are serialised), the files of
   ``DIR`` that do not belong to this set (other inputs' reports, user files) are hard-linked
   (or copied) into the staging folder, leaving out the files this set replaces: those of the
   same names, and the earlier files of the same analyses of the same input (declared as
   ``replaces`` patterns, so that an old plot whose name changed does not linger);
3. the staging folder and ``DIR`` are exchanged in one atomic step (Linux
   ``renameat2(RENAME_EXCHANGE)``, macOS ``renamex_np(RENAME_SWAP)``); where neither exists,
   by two renames whose interruption a later run repairs first;
4. the old folder (now under the staging name) is removed.

A run killed at any moment therefore leaves ``DIR`` holding either the complete previous set or
the complete new one, never a mix; a staging or old folder it leaves behind is removed by the
next run on the same ``DIR`` (each live run holds a lock on its own staging folder, so only
the folders of dead runs are touched). Paths in ``DIR`` stay the same (a symbolic link to
``DIR`` is followed, not replaced). What is guaranteed, and the refusals (an output folder
holding sub-folders, the current folder, a mount point), are described in
``docs/inputs-and-outputs.md``.

An output is never written onto an input: every input file (the workbook and the files it
refers to) is compared with the outputs by resolved path, by file identity (hard and symbolic
links) and by case-folded name (case-insensitive file systems), before anything is computed
(:meth:`AtomicOutputs.check`) and again for each file.

This module is the publisher; the checks of the output folder are in
:mod:`slingloads.io.common.outguard`, the file names in
:mod:`slingloads.io.common.outnames`, the locks, the folder exchange and the recovery
in :mod:`slingloads.io.common.swap` (their names are also importable from here).

Nor does a set replace (or remove as an earlier file of its report) a file that slingloads did
not write: each file of ``DIR`` that it would replace must carry slingloads' mark or be listed,
unchanged, in the folder's manifest (:mod:`slingloads.io.common.ownership`), checked with
the inputs (:meth:`AtomicOutputs.check`, :func:`check_outputs`) and again under the lock
before publishing. The manifest
(``.slingloads.manifest.json``) is written into the staging folder with the set, listing the
new files and keeping the entries of the files carried over.

Examples
--------
>>> import tempfile, pathlib
>>> out_dir = pathlib.Path(tempfile.mkdtemp()) / "reports"
>>> with atomic_outputs(out_dir) as out:
...     _ = out.path("a.txt").write_text("hello")
>>> [p.name for p in out.written]
['a.txt']
"""


from __future__ import annotations

import errno
import os
import re
import shutil
import stat
import tempfile
from contextlib import contextmanager
from pathlib import Path

from slingloads.errors import InputError, OutputError
from slingloads.io.common.outguard import (  # noqa: F401 - re-exported
    EARLIER_FILE,
    SAME_NAME,
    check_not_input,
    check_outputs,
    check_replaceable,
    os_error,
    same_file,
)
from slingloads.io.common.outnames import output_pattern, safe_file_part  # noqa: F401
from slingloads.io.common.ownership import (
    MANIFEST_NAME,
    file_entry,
    manifest_bytes,
)
from slingloads.io.common.swap import (  # noqa: F401 - re-exported
    PAUSE_VARIABLE,
    STEP_VARIABLE,
    SWAP_VARIABLE,
    TEMP_PREFIX,
    exchange_folders,
    is_current_folder,
    is_writable,
    lock_folder,
    longest_name,
    pause_if_asked,
    publishing_lock,
    recover,
    stage_prefix,
)
from slingloads.limits import MAX_OUTPUT_ENTRIES

#: Why an output folder holding a pipe, socket or device is refused (before any work, and
#: again at publishing should one appear meanwhile).
_SPECIAL_FILE = ("the output folder holds a special file (pipe, socket or device), which the "
                 "report set would carry over into its new folder: write the reports to a "
                 "folder of their own")


class AtomicOutputs:
    """Collects output files in a staging folder and publishes them all at once.

    Use through :func:`atomic_outputs`. Ask for the path of every output with :meth:`path`,
    write the file there, and leave the ``with`` block normally to publish them all.

    Parameters
    ----------
    out_dir : path-like
        Output folder; created (with parents) if it does not exist.
    inputs : iterable of path-like
        Input files that must never be overwritten.
    replaces : iterable of re.Pattern
        Names of files of ``out_dir`` that this set replaces even when it does not write them
        (the earlier outputs of the same analyses of the same input); other files are kept.
        A file this set would replace (by name or pattern) must be slingloads' own: see
        :func:`check_replaceable`.
    """

    def __init__(self, out_dir, inputs=(), replaces=()):
        self.out_dir = Path(out_dir)
        self.inputs = [Path(p) for p in inputs]
        self.replaces = list(replaces)
        self.written = []
        self._names = {}
        self._folded = {}
        self._stage = None
        self._stage_fd = None
        self._created = []
        self._real = None
        self._old = None

    # ---- checks made before anything is computed ------------------------------------------
    def check(self, names=()):
        """Check the output folder and the inputs before any work is done.

        Parameters
        ----------
        names : iterable of str
            Output names known in advance (their length is checked).

        Raises
        ------
        OutputError
            If the folder cannot be written (a file in the way, no permission, a read-only
            file system, a mount point) or a name is too long for the file system.
        InputError
            If the folder is the current folder or holds sub-folders, or an output of this
            set could replace an input or a file slingloads did not write.
        """
        real = self._resolve()
        parent = real.parent
        if real == parent or os.path.ismount(real):
            raise OutputError("the output folder is a mount point or the root folder, which "
                              "cannot be replaced as a whole: write the reports to a "
                              "sub-folder of it", self.out_dir)
        if is_current_folder(real):
            raise InputError("the output folder is the current folder: the report set is "
                             "published by replacing the output folder as a whole, which "
                             "would leave your shell in a removed folder; write to a "
                             "sub-folder, e.g. --out reports", str(self.out_dir))
        existing = self._existing_ancestor(real)
        if existing == real:
            self._check_folder(real)
        elif not is_writable(existing):
            raise OutputError("cannot create the output folder: no write permission in "
                              f"{existing}", self.out_dir)
        if existing in (real, parent) and not is_writable(parent):
            raise OutputError("cannot write beside the output folder (the report set is "
                              f"staged in its parent folder {parent} and swapped in): "
                              "permission denied; choose a folder whose parent you may "
                              "write to", self.out_dir)
        name_max = longest_name(existing)
        for name in names:
            if len(os.fsencode(name)) > name_max:
                raise OutputError(f"an output file name is longer than the {name_max} bytes "
                                  "the file system allows: use a shorter input file name",
                                  name[:60] + "...")
            if len(os.fsencode(str(real / name))) >= 4096:
                raise OutputError("an output path is too long for the file system: use a "
                                  "shorter output folder", str(real / name)[:80] + "...")
        self._check_inputs(real)
        if existing == real:
            folded = {str(n).casefold() for n in names}
            check_replaceable(real, lambda name: self._clash(name, folded))
        return self

    def _resolve(self):
        """The real path of the output folder (symbolic links followed)."""
        if self._real is not None:
            return self._real
        text = os.fspath(self.out_dir)
        if not text.strip():
            raise InputError("the output folder must not be empty", text)
        if "\x00" in text:
            raise InputError("the output folder must not contain a NUL character", text)
        if os.path.islink(text):
            try:
                os.stat(text)
            except OSError as err:
                what = ("a symbolic-link loop (the link leads back to itself)"
                        if err.errno == errno.ELOOP else "a broken symbolic link")
                raise OutputError(f"the output folder is {what}", self.out_dir) from None
        try:
            real = Path(os.path.realpath(text))
        except (OSError, ValueError) as err:
            raise os_error(err, "cannot resolve the output folder", self.out_dir) from None
        self._real = real
        return real

    def _existing_ancestor(self, real):
        """The output folder if it exists, else its nearest existing ancestor (a folder)."""
        path = real
        while True:
            try:
                info = os.stat(path)
            except FileNotFoundError:
                if path.parent == path:
                    raise OutputError("no existing folder above the output folder",
                                      self.out_dir) from None
                path = path.parent
                continue
            except NotADirectoryError:  # a file above: found and named on the way up
                path = path.parent
                continue
            except OSError as err:
                raise os_error(err, "cannot use the output folder", self.out_dir) from None
            if not stat.S_ISDIR(info.st_mode):  # the user's --out, not the environment
                what = ("--out: the output folder is an existing file, not a folder"
                        if path == real else
                        f"--out: a part of the output path is a file, not a folder ({path})")
                raise InputError(what + "; give a folder (a missing one is created)",
                                 str(self.out_dir))
            return path

    def _check_folder(self, real):
        """An existing output folder: writable, files only, not too many entries."""
        if not is_writable(real):
            raise OutputError("the output folder is read-only (no write permission)",
                              self.out_dir)
        count = 0
        try:
            entries = list(os.scandir(real))
        except OSError as err:
            raise os_error(err, "cannot list the output folder", self.out_dir) from None
        for entry in entries:
            count += 1
            if entry.is_dir(follow_symlinks=False):
                raise InputError("the output folder holds a sub-folder: the report set is "
                                 "published by replacing the output folder as a whole, so "
                                 "it must hold files only; write the reports to a folder of "
                                 "their own (e.g. a new sub-folder)",
                                 str(Path(self.out_dir) / entry.name))
            if not (entry.is_symlink() or entry.is_file(follow_symlinks=False)
                    or entry.name.casefold() == MANIFEST_NAME.casefold()):  # its own check
                raise InputError(_SPECIAL_FILE, str(Path(self.out_dir) / entry.name))
        if count > MAX_OUTPUT_ENTRIES:
            raise InputError(f"the output folder holds more than {MAX_OUTPUT_ENTRIES:,} "
                             "entries: write the reports to a folder of their own",
                             str(self.out_dir))

    def _check_inputs(self, real):
        """No input lies where this set writes or replaces a file."""
        if not self.inputs:
            return
        try:
            entries = [e for e in os.scandir(real)] if real.is_dir() else []
        except OSError:
            entries = []
        for source in self.inputs:
            try:
                in_dir = os.path.samefile(Path(source).resolve().parent, real)
            except (OSError, ValueError, RuntimeError):
                in_dir = False
            if in_dir and self._claims(Path(source).name):
                raise InputError("an output of this run would replace an input file (an "
                                 "input is never overwritten): choose another output folder",
                                 str(source), file=str(source))
            for entry in entries:
                if self._claims(entry.name) and same_file(entry.path, source):
                    raise InputError("an output of this run would replace a file that is an "
                                     "input, the same file through a link (an input is never "
                                     "overwritten): choose another output folder",
                                     entry.path, file=str(source))

    def _clash(self, name, folded=()):
        """What this set would do to the file ``name`` of the output folder (a clause of the
        refusal, :data:`SAME_NAME` or :data:`EARLIER_FILE`), or None if it keeps it; case is
        ignored (a case-insensitive file system makes them one file). ``folded``: more
        output names (case-folded) known in advance."""
        key = name.casefold()
        if key in self._folded or key in folded:
            return SAME_NAME
        if self._claims(name):
            return EARLIER_FILE
        return None

    def _claims(self, name):
        """True if a file of this name in the output folder would be replaced by this set."""
        folded = name.casefold()
        if folded in self._folded:
            return True
        return any(p.match(name) or re.compile(p.pattern, re.IGNORECASE).match(name)
                   for p in self.replaces)

    # ---- the staging folder ---------------------------------------------------------------
    def __enter__(self):
        real = self._resolve()
        self.check()
        parent = real.parent
        self._make_parents(parent)
        with publishing_lock(parent):
            recover(parent, real)
            try:
                self._stage = Path(tempfile.mkdtemp(prefix=stage_prefix(real, "new"),
                                                    dir=parent))
            except OSError as err:
                raise os_error(err, "cannot create the staging folder beside the output "
                                "folder", parent) from None
            self._stage_fd = lock_folder(self._stage)
        return self

    def _make_parents(self, parent):
        missing = []
        path = parent
        while not path.exists():
            missing.append(path)
            path = path.parent
        for path in reversed(missing):
            try:
                path.mkdir()
            except FileExistsError:
                continue
            except OSError as err:
                raise os_error(err, "cannot create the output folder", path) from None
            self._created.append(path)

    def __fspath__(self):
        """The output folder, so that ``Path(outputs) / name`` is a final path."""
        return str(self.out_dir)

    def path(self, name):
        """Staging path at which to write the output file ``name``.

        Parameters
        ----------
        name : str
            File name (no folder part) of the output in the output folder.

        Returns
        -------
        pathlib.Path
            Where to write the file now; it is published as ``out_dir / name``.

        Raises
        ------
        InputError
            If ``name`` has a folder part, was already asked for (case ignored), or would
            overwrite an input file.
        OutputError
            If ``name`` is too long for the file system.
        """
        if self._stage is None:
            raise RuntimeError("AtomicOutputs.path() is only valid inside the with block")
        name = str(name)
        if not name or Path(name).name != name or name in (".", "..") or "\x00" in name:
            raise InputError("an output name must be a plain file name without a folder "
                             "part", name)
        if len(os.fsencode(name)) > longest_name(self._stage):
            raise OutputError("an output file name is too long for the file system: use a "
                              "shorter input file name", name[:60] + "...")
        if name.casefold() in self._folded:
            raise InputError("two outputs of this run have the same file name (case "
                             "ignored): one would be lost", name)
        if name.casefold() == MANIFEST_NAME.casefold():
            raise InputError("this name is reserved for the output folder's manifest of the "
                             "files slingloads wrote", name)
        final = self.out_dir / name
        check_not_input(final, self.inputs)
        self._names[name] = final
        self._folded[name.casefold()] = name
        return self._stage / name

    # ---- publishing -----------------------------------------------------------------------
    def __exit__(self, exc_type, exc, tb):
        try:
            if exc_type is None:
                try:
                    self._publish()
                except OSError as err:
                    raise os_error(err, "cannot publish the reports", self.out_dir) from None
            elif isinstance(exc, OSError) and not isinstance(exc, OutputError):
                raise os_error(exc, "cannot write the reports", self.out_dir) from exc
        finally:
            self._cleanup()
        return False

    def _publish(self):
        missing = [n for n in self._names if not (self._stage / n).is_file()]
        if missing:
            raise RuntimeError(f"outputs were announced but not written: {missing}")
        real = self._resolve()
        parent = real.parent
        written = {name: file_entry(self._stage / name) for name in self._names}
        pause_if_asked()
        with publishing_lock(parent):
            recover(parent, real)
            if real.exists():
                self._check_folder(real)
                self._check_inputs(real)
                manifest = check_replaceable(real, self._clash)
                carried = self._carry_over(real)
                kept = {n: manifest[n] for n in carried if n in manifest}
                self._write_manifest({**kept, **written})
                pause_if_asked()
                os.chmod(self._stage, stat.S_IMODE(os.stat(real).st_mode))
                exchange_folders(self._stage, real)
                pause_if_asked()
                # the old set now lies under the staging name: a kill from here on leaves it
                # to the next run's recovery
                self._old = self._stage
            else:
                self._write_manifest(written)
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(self._stage, 0o777 & ~umask)
                os.rename(self._stage, real)
                self._old = None
            self._stage = None
            self._created.clear()
        self.written = list(self._names.values())
        if self._old is not None:
            shutil.rmtree(self._old, ignore_errors=True)

    def _write_manifest(self, files):
        """The manifest of the new set (``{file name: entry}``) into the staging folder."""
        (self._stage / MANIFEST_NAME).write_bytes(manifest_bytes(files))

    def _carry_over(self, real):
        """Hard-link (or copy) into the staging folder the files of the output folder that
        this set neither writes nor replaces (nor the folder's manifest, which the set
        rewrites); returns their names."""
        carried = []
        for entry in os.scandir(real):
            name = entry.name
            if (name in self._names or name == MANIFEST_NAME
                    or any(p.match(name) for p in self.replaces)):
                continue
            source, target = entry.path, self._stage / name
            if entry.is_symlink():
                os.symlink(os.readlink(source), target)
            elif entry.is_dir(follow_symlinks=False):
                raise InputError("the output folder holds a sub-folder: write the reports to "
                                 "a folder of their own", source)
            elif entry.is_file(follow_symlinks=False):
                try:
                    os.link(source, target, follow_symlinks=False)
                except FileExistsError:
                    continue  # a name of the new set in another case (case-insensitive FS)
                except OSError:
                    shutil.copy2(source, target, follow_symlinks=False)
            else:
                raise InputError(_SPECIAL_FILE, source)
            carried.append(name)
        return carried

    def _cleanup(self):
        if self._stage_fd is not None:
            try:
                os.close(self._stage_fd)
            except OSError:
                pass
            self._stage_fd = None
        if self._stage is not None:
            shutil.rmtree(self._stage, ignore_errors=True)
            self._stage = None
        for path in reversed(self._created):
            try:
                path.rmdir()  # only if still empty
            except OSError:
                pass
        self._created.clear()


@contextmanager
def atomic_outputs(out_dir, inputs=(), replaces=()):
    """Context manager that publishes a set of output files all at once, or none.

    Parameters
    ----------
    out_dir : path-like or AtomicOutputs
        Output folder (created if needed). Given an open :class:`AtomicOutputs`, the files
        join its set and are published with it, so that several writers publish all their
        files together, or none.
    inputs : iterable of path-like
        Input files that must never be overwritten.
    replaces : iterable of re.Pattern
        Names of earlier outputs this set replaces (see :class:`AtomicOutputs`).

    Yields
    ------
    AtomicOutputs
        ``out.path(name)`` gives the staging path to write ``name`` to; after the block,
        ``out.written`` lists the final paths in the order they were asked for.

    Raises
    ------
    InputError
        If an output would overwrite an input file, or the output folder is refused.
    OutputError
        If the output folder cannot be written.
    """
    if isinstance(out_dir, AtomicOutputs):
        # nested: the files join the outer set, which the outer block publishes
        out_dir.inputs.extend(Path(p) for p in inputs)
        out_dir.replaces.extend(replaces)
        yield out_dir
        return
    with AtomicOutputs(out_dir, inputs, replaces) as out:
        yield out


@contextmanager
def atomic_file(path, inputs=()):
    """Write one file atomically: a temporary file beside it, renamed over it at the end.

    Yields the temporary path; on an error it is removed and ``path`` is left as it was.

    Raises
    ------
    InputError
        If ``path`` is one of ``inputs``.
    OutputError
        If the folder cannot be written.
    """
    path = Path(path)
    check_not_input(path, inputs)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name[:100]}.", suffix=".partial",
                                   dir=path.parent)
        os.close(fd)
        os.chmod(tmp, new_file_mode())  # mkstemp's 0600 would hide the file from the group
    except OSError as err:
        raise os_error(err, "cannot write the file", path) from None
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    except OSError as err:
        raise os_error(err, "cannot write the file", path) from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def new_file_mode():
    """The mode a newly created file gets from the user's umask (0o644 under umask 022)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask

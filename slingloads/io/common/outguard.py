"""Guards of the output folder: an output never lands on an input, nor replaces a file
that slingloads did not write.

Guarantees: :func:`check_not_input` refuses an output path that is an input file (by resolved
path, by file identity through hard or symbolic links, by case-folded name);
:func:`check_replaceable` refuses to replace or remove a file of the output folder that
carries neither slingloads' mark nor an unchanged entry of the folder's manifest
(:mod:`slingloads.io.common.ownership`); :func:`check_outputs` makes both checks for a whole
report set before any work. Used by the publisher (:mod:`slingloads.io.common.atomic`).
"""

from __future__ import annotations

import errno
import os
from pathlib import Path

from slingloads.errors import InputError, OutputError
from slingloads.io.common.ownership import (
    MANIFEST_NAME,
    foreign_reason,
    read_manifest,
    refusal,
)


def same_file(a, b):
    """True if paths ``a`` and ``b`` name the same file: same resolved path, same file
    (hard or symbolic link), or same case-folded name in the same folder."""
    a, b = Path(a), Path(b)
    try:
        if a.resolve() == b.resolve():
            return True
    except (OSError, RuntimeError, ValueError):
        pass
    try:
        if os.path.samefile(a, b):
            return True
    except (OSError, ValueError):  # one of them does not exist
        pass
    try:
        return (a.name.casefold() == b.name.casefold()
                and os.path.samefile(a.parent, b.parent))
    except (OSError, ValueError):
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
        If ``path`` is (or links to, or differs only in case from) one of ``inputs``; the
        error names the input file.
    """
    for source in inputs:
        if same_file(path, source):
            raise InputError("refusing to write an output onto an input file (an input is "
                             "never overwritten); choose another output directory or stem",
                             str(path), file=str(source))


#: Why a run would replace a file of the output folder: it has an output's name.
SAME_NAME = "an output of this run has its name"
#: Why a run would remove a file of the output folder: an earlier-report pattern
#: (``replaces``) names it.
EARLIER_FILE = "this run would remove it as an earlier file of the same report"


def check_outputs(out_dir, names, inputs):
    """Check the files ``names`` of ``out_dir`` before the slow work: none is an input
    (:func:`check_not_input`) and none would replace a file of ``out_dir`` that slingloads did
    not write (:func:`check_replaceable`). A report checks its whole set this way, rather
    than stopping at the one file that is refused when it comes to write it.

    Raises
    ------
    InputError
        Naming the input, or the file that is not slingloads' own.
    """
    for name in names:
        check_not_input(Path(out_dir) / name, inputs)
    folded = {str(n).casefold() for n in names}
    check_replaceable(out_dir, lambda name: SAME_NAME if name.casefold() in folded else None)


def check_replaceable(out_dir, clash_of):
    """Refuse to replace or remove a file of ``out_dir`` that is not slingloads' own.

    Parameters
    ----------
    out_dir : path-like
        Output folder (nothing to check if it does not exist yet).
    clash_of : callable
        ``clash_of(file name)``: what the run would do to that file of the folder (a clause
        of the message, :data:`SAME_NAME` or :data:`EARLIER_FILE`), or None if it keeps it.

    Returns
    -------
    dict
        The folder's manifest entries (:func:`~slingloads.io.common.ownership.read_manifest`).

    Raises
    ------
    InputError
        Naming the first such file, why it is not slingloads' own, and what to do; or if the
        folder's manifest is not one slingloads wrote.
    """
    folder = Path(os.path.realpath(os.fspath(out_dir)))
    try:
        entries = sorted(os.scandir(folder), key=lambda e: e.name)
    except OSError:  # no folder yet (or one that cannot be listed: refused elsewhere)
        return {}
    manifest = read_manifest(folder)
    for entry in entries:
        clash = None if entry.name == MANIFEST_NAME else clash_of(entry.name)
        if clash is None:
            continue
        if entry.is_file(follow_symlinks=False):
            why = foreign_reason(entry.path, manifest)
        else:
            why = "it is a symbolic link or a special file, which slingloads never writes"
        if why is not None:
            raise refusal(Path(out_dir) / entry.name, why, clash)
    return manifest


def os_error(err, what, path):
    """An OutputError from an OSError, with advice for the usual causes."""
    advice = {
        errno.EACCES: "permission denied: choose a folder you may write to",
        errno.EPERM: "operation not permitted: choose a folder you may write to",
        errno.EROFS: "the file system is read-only: choose another folder",
        errno.ENOSPC: "no space left on the device: free some space or choose another folder",
        errno.EDQUOT: "disk quota exceeded: free some space or choose another folder",
        errno.ENAMETOOLONG: "a file or folder name is too long for the file system: use a "
                            "shorter input name or output folder",
        errno.ENOTDIR: "a part of the path is a file, not a folder",
        errno.ELOOP: "too many levels of symbolic links",
        errno.EEXIST: "a file is in the way",
    }.get(err.errno, err.strerror or str(err))
    return OutputError(f"{what}: {advice}", path)

"""Opening a file that a user or another program may have put in slingloads' way.

Guarantees: :func:`open_regular` never blocks and never follows a symbolic link at the last
part of the path: the file is opened with ``O_NOFOLLOW | O_NONBLOCK`` (a named pipe opens at
once instead of waiting for a writer; a device is not read), checked on the open descriptor
(``fstat``, so that nothing can be swapped in between) to be a regular file of at most
``max_bytes``, and only then handed back, in blocking mode, for reading. Anything else raises
:class:`NotRegularFile` (an ``OSError``) whose text says what was found, so callers that
already handle unreadable files handle these too.

Used for the files slingloads reads from places it does not own: the output folder's
manifest and marks (:mod:`slingloads.io.common.ownership`) and the run cache
(:mod:`slingloads.runs.cache`); and, following a symbolic link (``follow_links``: a user may
link an input), for the input workbook and the CSV files it names, so that a file swapped
for a pipe after its first check still cannot block.
"""

from __future__ import annotations

import errno
import os
import stat

_KINDS = ((stat.S_ISFIFO, "a named pipe"), (stat.S_ISSOCK, "a socket"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISDIR, "a folder"))


class NotRegularFile(OSError):
    """The path is a symbolic link, a pipe, a socket, a device or a folder, or too large."""


def kind_of(mode):
    """What a file of ``st_mode`` ``mode`` is, in words (``"a named pipe"``)."""
    for test, text in _KINDS:
        if test(mode):
            return text
    return "a regular file" if stat.S_ISREG(mode) else "a special file"


def open_regular(path, max_bytes=None, follow_links=False):
    """Open the regular file ``path`` for reading in binary, without blocking on a pipe or
    following a symbolic link (module notes).

    Parameters
    ----------
    path : path-like
    max_bytes : int, optional
        Largest size accepted. [bytes]
    follow_links : bool, optional
        Open what a symbolic link points to (still checked to be a regular file); default
        False: a link is refused.

    Returns
    -------
    io.BufferedReader

    Raises
    ------
    FileNotFoundError
        If there is no such file.
    NotRegularFile
        If it is a symbolic link, a pipe, a socket, a device or a folder, or larger than
        ``max_bytes``.
    OSError
        If it cannot be opened (permission...).
    """
    nofollow = 0 if follow_links else getattr(os, "O_NOFOLLOW", 0)
    flags = (os.O_RDONLY | nofollow | getattr(os, "O_NONBLOCK", 0)
             | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0))
    try:
        fd = os.open(path, flags)
    except OSError as err:
        if not follow_links and (err.errno == errno.ELOOP
                                 or (err.errno == errno.EMLINK and os.path.islink(path))):
            raise NotRegularFile(errno.ELOOP, "a symbolic link, which is not followed",
                                 str(path)) from None
        raise
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise NotRegularFile(errno.EINVAL, f"{kind_of(info.st_mode)}, not a regular file",
                                 str(path))
        if max_bytes is not None and info.st_size > max_bytes:
            raise NotRegularFile(errno.EFBIG, f"{info.st_size:,} bytes, more than the "
                                              f"{int(max_bytes):,} expected", str(path))
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise

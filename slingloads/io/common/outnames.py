"""File names of outputs: a safe file-name part made from an id, and the pattern of the
names an output template gives for a stem.

Guarantees: :func:`safe_file_part` gives only ``[A-Za-z0-9._-]`` characters, never an empty
part, and at most ``max_chars`` characters (a longer id is cut and keeps a hash so that
distinct ids stay distinct); :func:`output_pattern` matches exactly the names
``template`` gives for ``stem`` and nothing else.
"""

from __future__ import annotations

import hashlib
import re

#: Characters kept in file-name parts made from ids.
_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")


def safe_file_part(text, max_chars=80):
    """A file-name-safe version of an id (a station id in a plot's file name).

    Letters, digits, ``.``, ``_`` and ``-`` are kept, any run of other characters becomes
    ``_``; an id longer than ``max_chars`` is cut and ends with 8 hexadecimal digits of its
    hash, so that it stays distinct. Readers refuse ids that give the same part
    (case-insensitively), so that no file of a report replaces another.

    >>> safe_file_part("FS 2300/left"), safe_file_part("$$")
    ('FS_2300_left', 'id')
    """
    part = _UNSAFE.sub("_", str(text)).strip("._-") or "id"
    if len(part) > max_chars:
        digest = hashlib.sha256(str(text).encode("utf-8", "surrogatepass")).hexdigest()[:8]
        part = f"{part[:max_chars - 9]}-{digest}"
    return part


def output_pattern(template, stem):
    """A compiled regular expression of the output names of ``template`` for ``stem``.

    ``template`` is a file name with ``{stem}`` and optionally ``*`` standing for a part made
    by :func:`safe_file_part` (``"{stem}-hull_*.png"``).
    """
    head, _, tail = template.partition("{stem}")
    pieces = [re.escape(p) for p in tail.split("*")]
    return re.compile(re.escape(head) + re.escape(stem) + "[A-Za-z0-9._-]+".join(pieces)
                      + r"\Z")

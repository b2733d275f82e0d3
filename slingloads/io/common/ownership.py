"""Which files of an output folder slingloads wrote: a run replaces only those.

A report set is published into a folder that may also hold the user's own files (another
workbook, notes, a CSV file of their own). A run replaces the files of its set and removes
the earlier files of the same report (:mod:`slingloads.io.common.atomic`), but only files
slingloads wrote. A file is slingloads' own when

1. it carries slingloads' mark, which changes nothing a user reads in it:

   * a report workbook (``.xlsx``): the custom document property :data:`XLSX_PROPERTY`
     (Excel: File > Info > Properties > Advanced Properties > Custom), which Excel and
     LibreOffice keep when the workbook is saved again;
   * a plot (``.png``): the text chunk ``Software`` = :data:`PNG_SOFTWARE` (a fixed text, so
     that the bytes of a plot stay reproducible);
   * a Nastran input file (``.bdf``): its first line, the comment :data:`BDF_START`...;
   * a Parquet file: the key :data:`PARQUET_KEY` of its key-value metadata;

2. or it is listed in the folder's *manifest* :data:`MANIFEST_NAME` with the size and
   SHA-256 it had when slingloads published it, and still has them. Every published set
   rewrites the manifest (as one of its files, so it is published atomically with them):
   it lists the files of the new set and keeps the entries of the files carried over. A
   CSV table carries no mark (a line added to it would change the table a user reads), so
   it is known by the manifest alone: one edited since, or whose manifest was removed, is
   not replaced (the user renames or removes it).

Reading a mark costs a few bytes (a PNG's first chunks, a Nastran file's first line, a
Parquet file's footer) or a small part of the ZIP container (a workbook's
``docProps/custom.xml``); a workbook is never loaded. A file that cannot be read as its kind
carries no mark.

Examples
--------
>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "notes.csv").write_text("mine")
>>> foreign_reason(folder / "notes.csv", read_manifest(folder)) is not None
True
"""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path

from slingloads.errors import InputError
from slingloads.limits import MAX_OUTPUT_ENTRIES
from slingloads.safeopen import open_regular

#: Custom document property of every report workbook (its value: ``slingloads <version>``).
XLSX_PROPERTY = "slingloads report"
#: Value of the ``Software`` text chunk of every PNG plot.
PNG_SOFTWARE = "slingloads"
#: Key of the key-value metadata of every Parquet file (its value: the version).
PARQUET_KEY = "slingloads report"
#: How every Nastran input file slingloads writes begins (its header's first comment line:
#: ``$ slingloads <version>: the load cases of study ...``).
BDF_START = b"$ slingloads "
#: The manifest of an output folder: the files slingloads published in it.
MANIFEST_NAME = ".slingloads.manifest.json"
#: ``format`` entry of a manifest (changes if its layout does).
MANIFEST_FORMAT = "slingloads manifest 1"

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_PNG_MARK = b"Software\x00" + PNG_SOFTWARE.encode("latin-1")
#: Bytes of a PNG read for its text chunks (they come before the image data).
_PNG_HEAD = 64 * 1024
#: Largest ``docProps/custom.xml`` of a workbook read for the mark, uncompressed. [bytes]
_XLSX_PART = 1 << 20
_XLSX_MARK = re.compile(rb"""name\s*=\s*["']""" + re.escape(XLSX_PROPERTY.encode()) + rb"""["']""")
#: Largest Parquet footer read for the mark. [bytes]
_PARQUET_FOOTER = 64 << 20
#: Largest manifest read: an entry per file of a full output folder. [bytes]
_MANIFEST_BYTES = MAX_OUTPUT_ENTRIES * 512
_SHA256 = re.compile(r"[0-9a-f]{64}\Z")


# ---- marks ---------------------------------------------------------------------------------
def carries_mark(path):
    """True if the regular file ``path`` carries slingloads' mark (module notes)."""
    reader = _MARK_READERS.get(Path(path).suffix.lower())
    if reader is None:
        return False
    try:
        with open_regular(path) as stream:
            return reader(stream)
    except Exception:  # noqa: BLE001 - a file that cannot be read as its kind has no mark
        return False


def _xlsx_marked(stream):
    """The workbook's custom properties name :data:`XLSX_PROPERTY`."""
    import zipfile

    with zipfile.ZipFile(stream) as book:
        try:
            part = book.getinfo("docProps/custom.xml")
        except KeyError:
            return False
        if part.file_size > _XLSX_PART:
            return False
        return _XLSX_MARK.search(book.read(part)) is not None


def _png_marked(stream):
    """A ``tEXt`` chunk before the image data is ``Software`` = :data:`PNG_SOFTWARE`."""
    head = stream.read(_PNG_HEAD)
    if not head.startswith(_PNG_SIGNATURE):
        return False
    at = len(_PNG_SIGNATURE)
    while at + 8 <= len(head):
        length = int.from_bytes(head[at:at + 4], "big")
        kind = head[at + 4:at + 8]
        if kind in (b"IDAT", b"IEND"):
            return False
        if kind == b"tEXt" and head[at + 8:at + 8 + length] == _PNG_MARK:
            return True
        at += 12 + length
    return False


def _bdf_marked(stream):
    """The file begins with :data:`BDF_START`."""
    return stream.read(len(BDF_START)) == BDF_START


def _parquet_marked(stream):
    """The footer (file metadata) holds the key :data:`PARQUET_KEY`."""
    size = stream.seek(0, 2)
    if size < 12:
        return False
    stream.seek(size - 8)
    tail = stream.read(8)
    length = int.from_bytes(tail[:4], "little")
    if tail[4:] != b"PAR1" or length > min(_PARQUET_FOOTER, size - 12):
        return False
    stream.seek(size - 8 - length)
    return PARQUET_KEY.encode() in stream.read(length)


_MARK_READERS = {".xlsx": _xlsx_marked, ".png": _png_marked, ".bdf": _bdf_marked,
                 ".parquet": _parquet_marked}


# ---- the manifest --------------------------------------------------------------------------
def file_entry(path):
    """The manifest entry of a file: ``{"bytes": size, "sha256": hex digest}``."""
    digest = hashlib.sha256()
    size = 0
    with open_regular(path) as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
            size += len(block)
    return {"bytes": size, "sha256": digest.hexdigest()}


def read_manifest(folder):
    """The entries of the manifest of ``folder``: ``{file name: entry}`` (:func:`file_entry`),
    empty when there is none.

    Raises
    ------
    InputError
        If a file of the manifest's name is not a manifest slingloads wrote (another layout,
        not JSON, too large, unreadable): it is the user's, and the run would replace it.
    """
    path = Path(folder) / MANIFEST_NAME
    try:
        with open_regular(path, _MANIFEST_BYTES + 1) as stream:
            raw = stream.read(_MANIFEST_BYTES + 1)
    except FileNotFoundError:
        return {}
    except OSError:
        raw = b""
    files = _manifest_files(raw)
    if files is None:
        raise InputError("the output folder holds a file named like the manifest in which "
                         "slingloads lists the files it wrote, but it is not one (a run "
                         "would replace it): rename or remove it, or choose another output "
                         "folder (--out)", file=str(path))
    return files


def _manifest_files(raw):
    """The ``files`` of a manifest's bytes, or None if they are no manifest of slingloads."""
    if not raw or len(raw) > _MANIFEST_BYTES:
        return None
    try:
        data = json.loads(raw.decode("utf-8"))
    except ValueError:
        return None
    if not isinstance(data, dict) or data.get("format") != MANIFEST_FORMAT:
        return None
    files = data.get("files")
    if not isinstance(files, dict) or not all(_valid_entry(e) for e in files.values()):
        return None
    return files


def _valid_entry(entry):
    return (isinstance(entry, dict) and set(entry) == {"bytes", "sha256"}
            and type(entry["bytes"]) is int and entry["bytes"] >= 0
            and isinstance(entry["sha256"], str) and _SHA256.match(entry["sha256"]) is not None)


def manifest_bytes(files):
    """The bytes of a manifest listing ``files`` (``{file name: entry}``), names sorted."""
    from slingloads import __version__

    data = {"format": MANIFEST_FORMAT, "written by": f"slingloads {__version__}",
            "about": "The files slingloads published in this folder, with their size and "
                     "SHA-256 when published. A run replaces (or removes as an earlier "
                     "report) only these, while unchanged, and the files that carry "
                     "slingloads' mark; never another file.",
            "files": {name: files[name] for name in sorted(files)}}
    return (json.dumps(data, indent=1, ensure_ascii=False) + "\n").encode("utf-8")


# ---- is it slingloads' own? ----------------------------------------------------------------
def foreign_reason(path, manifest):
    """Why the regular file ``path`` is not slingloads' own, or None if it is.

    Parameters
    ----------
    path : path-like
        A file of an output folder.
    manifest : dict
        That folder's manifest entries (:func:`read_manifest`).
    """
    path = Path(path)
    if carries_mark(path):
        return None
    entry = manifest.get(path.name)
    if entry is None:
        return (f"it carries no slingloads mark and the folder's manifest {MANIFEST_NAME} "
                "does not list it")
    if path.stat().st_size != entry["bytes"] or file_entry(path) != entry:
        return (f"its size or SHA-256 is not the one the folder's manifest {MANIFEST_NAME} "
                "lists")
    return None


def refusal(path, why, clash):
    """The error that refuses to replace the file ``path``, which is not slingloads' own:
    ``why`` says why (:func:`foreign_reason`), ``clash`` what the run would do to it."""
    return InputError(f"refusing to replace a file slingloads did not write (or one changed "
                      f"since): {why}, and {clash}; rename or move it, or choose another "
                      "output folder (--out)", file=str(path))

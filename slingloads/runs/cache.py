"""The run cache on disk: one Parquet file per finished run, under its key.

A campaign asks the cache for each run's key (:mod:`slingloads.analyses.campaign.keys`: a
SHA-256 of every input that affects the run and of the code) and runs only the missing ones,
storing each as soon as its batch returns. So an interrupted campaign resumes where it stopped
and an edited workbook re-runs only the runs whose inputs changed.

Layout: ``<directory>/runs/<first two hex digits>/<key>.parquet``; each file holds the run's
histories (the columns of :data:`~slingloads.analyses.campaign.HISTORY_LABELS`, float64) and
its metrics as JSON in the file's metadata. A file is written under a temporary name and
renamed into place, so a killed process never leaves a half-written record; a file that cannot
be read is treated as missing and the run is done again.

The cache lives **outside** the output folder: the reports are published by replacing that
folder as a whole. Default location: ``$SLINGLOADS_CACHE``, else ``$XDG_CACHE_HOME/slingloads``,
else ``~/.cache/slingloads`` (``%LOCALAPPDATA%\\slingloads`` on Windows), each with a
``campaign`` sub-folder; ``--cache DIR`` chooses another. Deleting the folder is always safe.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path

import numpy as np

from slingloads.analyses.campaign import HISTORY_LABELS
from slingloads.errors import InputError, OutputError

#: Metadata key of the metrics in a cached file.
METRICS_KEY = b"slingloads.metrics"
#: How the histories are written: zstd on byte-stream-split floats (about a quarter smaller
#: than zstd alone on these histories; dictionary encoding would forbid the split).
PARQUET_OPTIONS = {"compression": "zstd", "use_dictionary": False,
                   "use_byte_stream_split": True}


def default_cache_dir():
    """The default cache folder (module notes)."""
    if os.environ.get("SLINGLOADS_CACHE"):
        return Path(os.environ["SLINGLOADS_CACHE"]) / "campaign"
    if os.name == "nt" and os.environ.get("LOCALAPPDATA"):
        return Path(os.environ["LOCALAPPDATA"]) / "slingloads" / "campaign"
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "slingloads" / "campaign"


def _plain(value):
    if isinstance(value, np.generic):
        return value.item()
    return value


class RunCache:
    """Finished runs as Parquet files (module notes).

    Parameters
    ----------
    directory : path-like
        Created on first write.
    """

    def __init__(self, directory):
        self.directory = Path(directory)
        if self.directory.exists() and not self.directory.is_dir():
            raise InputError("the run cache must be a folder", str(self.directory))
        self.written = 0

    def _path(self, key):
        return self.directory / "runs" / key[:2] / f"{key}.parquet"

    def __contains__(self, key):
        """True when the run's file is there and its footer (with the metrics) reads."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        path = self._path(key)
        if not path.is_file():
            return False
        try:
            return METRICS_KEY in (pq.read_metadata(path).metadata or {})
        except (OSError, pa.ArrowException):
            return False

    def __len__(self):
        root = self.directory / "runs"
        return sum(1 for _ in root.glob("*/*.parquet")) if root.is_dir() else 0

    def get(self, key):
        """(metrics, histories) of a stored run, or None (absent or unreadable)."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        path = self._path(key)
        if not path.is_file():
            return None
        try:
            table = pq.read_table(path)
            metrics = json.loads(table.schema.metadata[METRICS_KEY])
            histories = np.column_stack([table.column(c).to_numpy() for c in HISTORY_LABELS])
        except (OSError, KeyError, ValueError, TypeError, pa.ArrowException):
            return None
        return metrics, histories

    def put(self, key, record):
        """Store a run (atomically: temporary file, then rename)."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        metrics, histories = record
        text = json.dumps({k: _plain(v) for k, v in metrics.items()})
        arrays = [pa.array(np.ascontiguousarray(histories[:, j], dtype=float))
                  for j in range(len(HISTORY_LABELS))]
        table = pa.Table.from_arrays(arrays, names=list(HISTORY_LABELS))
        table = table.replace_schema_metadata({METRICS_KEY: text.encode()})
        path = self._path(key)
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, tmp = tempfile.mkstemp(prefix=".part-", suffix=".parquet", dir=path.parent)
        os.close(handle)
        try:
            pq.write_table(table, tmp, **PARQUET_OPTIONS)
            os.replace(tmp, path)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise
        self.written += 1


def check_outside(cache_dir, out_dir):
    """Refuse a cache inside the output folder (that folder is replaced as a whole), and an
    output folder inside the cache (publishing would replace cached runs)."""
    try:
        cache = Path(cache_dir).resolve()
        out = Path(out_dir).resolve()
    except (OSError, RuntimeError) as err:  # a symbolic-link loop, a name too long
        raise OutputError(f"the run cache or output folder cannot be resolved "
                          f"({type(err).__name__})", cache_dir) from None
    if cache == out or out in cache.parents:
        raise InputError("the run cache must lie outside the output folder, which is replaced "
                         "as a whole when the reports are published; choose another --cache",
                         str(cache_dir))
    if cache in out.parents:
        raise InputError("the output folder must lie outside the run cache (publishing the "
                         "reports would replace the cached runs in it); choose another --out "
                         "or --cache", str(out_dir))


def check_writable(cache_dir):
    """Refuse, before any run, a cache folder that could not be created or written: a file in
    the way, a path under a file, a read-only folder, a name too long.

    Raises
    ------
    InputError
        If the cache is an existing file (a user's mistake).
    OutputError
        If the folder cannot be created or written (the environment).
    """
    path = Path(cache_dir)
    if path.exists() and not path.is_dir():
        raise InputError("the run cache must be a folder, not a file; choose another --cache",
                         str(cache_dir))
    existing = path
    try:
        while not existing.exists():
            if existing.parent == existing:
                break
            existing = existing.parent
        if not existing.is_dir():
            raise OutputError("the run cache cannot be created under a file", cache_dir)
        if not os.access(existing, os.W_OK | os.X_OK):
            raise OutputError("the run cache folder is read-only (no write permission); "
                              "choose another --cache", existing)
        for part in path.parts:
            if len(os.fsencode(part)) > 255:
                raise OutputError("a name in the run cache's path is too long for the file "
                                  "system", cache_dir)
    except OSError as err:
        if isinstance(err, OutputError):
            raise
        raise OutputError(f"the run cache cannot be used ({type(err).__name__}: "
                          f"{err.strerror or err})", cache_dir) from None

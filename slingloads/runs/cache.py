"""The run cache on disk: one Parquet file per finished run, under its key.

A campaign asks the cache for each run's key (:mod:`slingloads.analyses.campaign.keys`: a
SHA-256 of every input that affects the run and of the code) and runs only the missing ones,
storing each as soon as its batch returns. So an interrupted campaign resumes where it stopped
and an edited workbook re-runs only the runs whose inputs changed.

Layout: ``<directory>/runs/<first two hex digits>/<key>.parquet``; each file holds the run's
histories (the columns of :data:`~slingloads.analyses.campaign.HISTORY_LABELS`, float64) and
its metrics as JSON in the file's metadata.

**A cache, never an input that can stop a campaign.** What this module guarantees:

* an entry that cannot be used (not a regular file, a symbolic link, larger than the run it
  stands for, not Parquet, other columns or types, more or fewer rows than the run's
  histories, metrics that are not a JSON mapping of the metrics every run has: see
  :func:`~slingloads.analyses.campaign.execution.record_problem`) counts as missing: the
  run is computed again and stored over it, and a warning names the file;
* reading an entry is bounded before anything is allocated: the file's size, then the row
  count, column count and uncompressed size its footer declares, against the run's histories
  (run length / output interval + 1 rows of 26 floats) told by the campaign
  (:meth:`RunCache.expect`);
* nothing is opened in a way that blocks (a named pipe in the cache is refused, not waited
  on: :func:`slingloads.safeopen.open_regular`);
* a file is written under a temporary name ``.part-<host>-<process>-<random>.parquet`` and
  renamed into place, so a killed process never leaves a half-written record; the temporary
  files of processes that are gone are removed when the next campaign opens the cache;
* a cache location that cannot be used (a file in the way, a read-only folder, a ``runs``
  that is not a folder, a write that fails) does not stop the campaign: it runs without the
  cache, with a warning naming the folder; the runs of this report are then kept in a
  temporary folder of this process, removed when it ends (so that the histories, up to
  :data:`~slingloads.limits.MAX_CAMPAIGN_SAMPLES` rows, are not all held in memory at once),
  or in memory where no temporary folder can be made either.

The cache lives **outside** the output folder: the reports are published by replacing that
folder as a whole, so a cache inside it would be lost at every run. It is shared by the
studies that use it, each run filed under its key, and a report counts only its own matrix's
runs; the campaign Summary states where it is and why (:func:`where_stated`). Default
location: ``$SLINGLOADS_CACHE``, else ``$XDG_CACHE_HOME/slingloads``,
else ``~/.cache/slingloads`` (``%LOCALAPPDATA%\\slingloads`` on Windows), each with a
``campaign`` sub-folder; ``--cache DIR`` chooses another. Deleting the folder is always safe.
"""

from __future__ import annotations

import hashlib
import json
import os
import socket
import stat
import time
from pathlib import Path

import numpy as np

from slingloads.errors import InputError, OutputError
from slingloads.limits import MAX_CAMPAIGN_SAMPLES
from slingloads.safeopen import NotRegularFile, kind_of, open_regular

#: Metadata key of the metrics in a cached file.
METRICS_KEY = b"slingloads.metrics"
#: How the histories are written: zstd on byte-stream-split floats (about a quarter smaller
#: than zstd alone on these histories; dictionary encoding would forbid the split).
PARQUET_OPTIONS = {"compression": "zstd", "use_dictionary": False,
                   "use_byte_stream_split": True}
#: Largest metrics text of a cached run (a run's are about 2 kB). [bytes]
MAX_METRICS_BYTES = 256 * 1024
#: Bytes of a cached file beyond its histories (footer, metrics, page headers). [bytes]
_OVERHEAD = 2 * MAX_METRICS_BYTES + 64 * 1024
#: Temporary files of writers on other machines (a shared cache) older than this are removed.
_STALE_PART = 24 * 3600.0
_PART = ".part-"


def default_cache_dir():
    """The default cache folder (module notes).

    Returns
    -------
    pathlib.Path
        ``campaign`` in ``$SLINGLOADS_CACHE`` when set, else in the user's cache folder
        (``%LOCALAPPDATA%\\slingloads`` on Windows, ``$XDG_CACHE_HOME/slingloads`` or
        ``~/.cache/slingloads`` elsewhere).
    """
    if os.environ.get("SLINGLOADS_CACHE"):
        return Path(os.environ["SLINGLOADS_CACHE"]) / "campaign"
    if os.name == "nt" and os.environ.get("LOCALAPPDATA"):
        return Path(os.environ["LOCALAPPDATA"]) / "slingloads" / "campaign"
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "slingloads" / "campaign"


def where_stated(cache_dir):
    """Where the run cache is and why, in the words of a report: ``(choice, why)``, the
    default folder or the one chosen, then that it lies outside the output folder and is
    keyed by input (so a report counts only its own matrix's runs).

    Parameters
    ----------
    cache_dir : path-like
        The cache folder of the campaign.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> where_stated("/data/runs")[0]
    'chosen (--cache)'
    """
    try:
        default = Path(cache_dir).resolve() == default_cache_dir().resolve()
    except (OSError, RuntimeError):
        default = False
    choice = "the default, the user cache folder" if default else "chosen (--cache)"
    why = ("The run cache lies outside the output folder, which is replaced as a whole when "
           "the reports are published. It is shared by every study that uses it, each run "
           "filed under the SHA-256 of its inputs and of the code: the runs counted here are "
           "this matrix's only. Deleting it is safe (the runs are computed again); "
           "$SLINGLOADS_CACHE or --cache DIR moves it.")
    return choice, why


def _json_scalar(value):
    """A metric's value as JSON writes it: a numpy scalar as the Python one (``json`` knows no
    ``numpy.int64`` nor ``numpy.bool_``), anything else as it is."""
    if isinstance(value, np.generic):
        return value.item()
    return value


def _host_tag():
    return hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:8]


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError, OverflowError, ValueError):
        return True  # someone else's process, or cannot tell: keep its file
    return True


class RunCache:
    """Finished runs as Parquet files (module notes).

    Parameters
    ----------
    directory : path-like
        Created on first write. A location that cannot be used makes the cache keep the runs
        in memory for this campaign, with a warning (:attr:`warnings`).

    Attributes
    ----------
    warnings : list of str
        What the cache could not use (a damaged entry, an unusable folder), for the report.
    written : int
        Runs stored on disk by this object. [count]
    usable : bool
        False once the cache has fallen back to memory.
    """

    def __init__(self, directory):
        self.directory = Path(directory)
        self.written = 0
        self.warnings = []
        self.usable = True
        self._rows = {}
        self._valid = set()
        self._memory = {}
        self._warned = set()
        self._spill = None  # the temporary folder of a cache fallen back (module notes)
        self._spill_ok = True
        self._spilled = set()
        reason = location_problem(self.directory)
        if reason is not None:
            self._give_up(reason)
        else:
            self._sweep()

    # ---- the location -----------------------------------------------------------------
    def _give_up(self, reason):
        """Fall back to a temporary folder (else memory) for the rest of this campaign
        (module notes)."""
        if self.usable:
            self.usable = False
            self.warnings.append(f"the run cache {self.directory} cannot be used ({reason}): "
                                 "the campaign runs without it (nothing is stored for a "
                                 "later run)")
            import tempfile

            try:  # removed when this object is collected, or at the latest at exit
                self._spill = tempfile.TemporaryDirectory(prefix="slingloads-runs-")
            except OSError:
                self._spill = None

    def _sweep(self):
        """Remove the temporary files that killed writers left (module notes)."""
        root = self.directory / "runs"
        try:
            shards = [e for e in os.scandir(root) if e.is_dir(follow_symlinks=False)]
        except OSError:
            return
        host, now = _host_tag(), time.time()
        for shard in shards:
            try:
                entries = [e for e in os.scandir(shard.path) if e.name.startswith(_PART)]
            except OSError:
                continue
            for entry in entries:
                parts = entry.name[len(_PART):].split("-")
                try:
                    age = now - entry.stat(follow_symlinks=False).st_mtime
                except OSError:
                    continue
                ours = len(parts) >= 3 and parts[0] == host and parts[1].isdigit()
                if ours and _alive(int(parts[1])) and age < _STALE_PART:
                    continue
                if not ours and len(parts) >= 3 and age < _STALE_PART:
                    continue  # another machine's writer, perhaps still at work
                try:
                    os.unlink(entry.path)
                except OSError:
                    pass

    def _path(self, key):
        return self.directory / "runs" / key[:2] / f"{key}.parquet"

    # ---- reading ----------------------------------------------------------------------
    def expect(self, key, rows):
        """Tell the cache how many history rows the run ``key`` has: an entry of another
        size is refused before it is read (module notes).

        Parameters
        ----------
        key : str
            The run's key (:class:`~slingloads.analyses.campaign.keys.KeyMaker`).
        rows : int
            Rows of its time histories. [-]
        """
        self._rows[key] = int(rows)

    def __contains__(self, key):
        """True when the run's entry is there and usable (module notes)."""
        if key in self._memory or key in self._valid or key in self._spilled:
            return True
        if not self.usable:
            return False
        if self._read(key) is None:
            return False
        self._valid.add(key)
        return True

    def __len__(self):
        root = self.directory / "runs"
        try:
            return (sum(1 for _ in root.glob("*/*.parquet")) if root.is_dir() else 0) + len(
                self._memory) + len(self._spilled)
        except OSError:
            return len(self._memory) + len(self._spilled)

    def get(self, key):
        """(metrics, histories) of a stored run, or None (absent or unusable: module notes).

        Parameters
        ----------
        key : str
            The run's key.

        Returns
        -------
        tuple or None
            ``(metrics, histories)`` as :meth:`put` stored them, or None.

        Raises
        ------
        OutputError
            If an entry found usable earlier in this campaign no longer is (changed by
            another program meanwhile).
        """
        if key in self._memory:
            return self._memory[key]
        if key in self._spilled:
            return self._load(self._spill_path(key), self._rows.get(key))
        if not self.usable and key not in self._valid:
            return None  # (an entry found usable before the fall-back is still read)
        record = self._read(key)
        if record is None and key in self._valid:
            raise OutputError("a run of the cache changed while the campaign ran (another "
                              "program wrote or removed it): run the campaign again",
                              self._path(key))
        return record

    def _read(self, key):
        """The record of ``key``, or None (a warning names a damaged entry)."""
        path = self._path(key)
        try:
            os.lstat(path)
        except FileNotFoundError:
            return None
        except OSError as err:
            return self._damaged(path, err.strerror or type(err).__name__)
        rows = self._rows.get(key)
        try:
            return self._load(path, rows)
        except _Unusable as err:
            return self._damaged(path, str(err))
        except NotRegularFile as err:
            return self._damaged(path, err.strerror)
        except FileNotFoundError:
            return None
        except MemoryError:
            return self._damaged(path, "it would not fit in memory")
        except Exception as err:  # noqa: BLE001 - a foreign file can fail anywhere in pyarrow
            return self._damaged(path, f"{type(err).__name__}: {str(err)[:200]}")

    def _load(self, path, rows):
        import pyarrow as pa
        import pyarrow.parquet as pq

        from slingloads.analyses.campaign import HISTORY_LABELS  # the campaign's: when it runs
        from slingloads.analyses.campaign.execution import record_problem

        width = len(HISTORY_LABELS)
        bound = rows if rows is not None else MAX_CAMPAIGN_SAMPLES
        data_bytes = bound * width * 8
        with open_regular(path, max_bytes=data_bytes + data_bytes // 8 + _OVERHEAD) as handle:
            meta = pq.ParquetFile(handle).metadata  # the footer only
            if rows is not None and meta.num_rows != rows:
                raise _Unusable(f"{meta.num_rows:,} rows, not the run's {rows:,}")
            if meta.num_rows > bound:
                raise _Unusable(f"{meta.num_rows:,} rows, more than any run's {bound:,}")
            if meta.num_columns != width:
                raise _Unusable(f"{meta.num_columns} columns, not {width}")
            schema = meta.schema.to_arrow_schema()
            if list(schema.names) != list(HISTORY_LABELS):
                raise _Unusable("other columns than a run's histories")
            if any(f.type != pa.float64() for f in schema):
                raise _Unusable("columns that are not float64")
            declared = sum(meta.row_group(i).total_byte_size for i in range(meta.num_row_groups))
            if declared > data_bytes + _OVERHEAD:
                raise _Unusable(f"{declared:,} bytes of data declared, more than the run's "
                                f"{data_bytes:,}")
            text = (meta.metadata or {}).get(METRICS_KEY)
            if text is None:
                raise _Unusable("no metrics")
            if len(text) > MAX_METRICS_BYTES:
                raise _Unusable(f"{len(text):,} bytes of metrics, more than "
                                f"{MAX_METRICS_BYTES:,}")
            metrics = json.loads(text.decode("utf-8"))
            handle.seek(0)
            table = pq.read_table(handle)
        histories = np.column_stack([table.column(c).to_numpy() for c in HISTORY_LABELS])
        problem = record_problem((metrics, histories), rows)
        if problem is not None:
            raise _Unusable(problem)
        return metrics, histories

    def _damaged(self, path, reason):
        if path not in self._warned:
            self._warned.add(path)
            self.warnings.append(f"the cached run {path} cannot be used ({reason}): it is "
                                 "computed again")
        return None

    # ---- writing ----------------------------------------------------------------------
    def put(self, key, record):
        """Store a run (atomically: temporary file, then rename); kept in memory, with a
        warning, if the cache cannot be written (module notes).

        Parameters
        ----------
        key : str
            The run's key.
        record : tuple
            ``(metrics, histories)`` of the run: its metrics by name (floats, SI) and its
            histories, an array of shape (rows, len(HISTORY_LABELS)) (SI).
        """
        if not self.usable:
            self._keep(key, record)
            return
        try:
            self._write(key, record)
        except OSError as err:
            self._give_up(f"{type(err).__name__}: {err.strerror or err}")
            self._keep(key, record)
            return
        self._valid.add(key)
        self.written += 1

    def _spill_path(self, key):
        return Path(self._spill.name) / f"{key}.parquet"

    def _keep(self, key, record):
        """A run of a cache fallen back: in the temporary folder, else in memory."""
        if self._spill is not None and self._spill_ok:
            try:
                self._write(key, record, self._spill_path(key))
                self._spilled.add(key)
                return
            except OSError:
                self._spill_ok = False
        self._memory[key] = record

    def _write(self, key, record, path=None):
        import pyarrow as pa
        import pyarrow.parquet as pq

        from slingloads.analyses.campaign import HISTORY_LABELS

        metrics, histories = record
        text = json.dumps({k: _json_scalar(v) for k, v in metrics.items()})
        arrays = [pa.array(np.ascontiguousarray(histories[:, j], dtype=float))
                  for j in range(len(HISTORY_LABELS))]
        table = pa.Table.from_arrays(arrays, names=list(HISTORY_LABELS))
        table = table.replace_schema_metadata({METRICS_KEY: text.encode()})
        path = self._path(key) if path is None else path
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.parent / (f"{_PART}{_host_tag()}-{os.getpid()}-"
                             f"{os.urandom(6).hex()}.parquet")
        try:
            with open(tmp, "xb") as handle:
                pq.write_table(table, handle, **PARQUET_OPTIONS)
            os.replace(tmp, path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise


class _Unusable(ValueError):
    """A cache entry that is not one of this run (module notes)."""


def location_problem(cache_dir):
    """Why the folder ``cache_dir`` cannot hold the run cache, in words, or None: a file in the
    way (the folder, its ``runs`` sub-folder or a part of its path), no write permission, a
    name too long for the file system.

    Parameters
    ----------
    cache_dir : path-like
        The cache folder.

    Returns
    -------
    str or None
        The problem in words, or None when the folder can hold the cache.
    """
    path = Path(cache_dir)
    try:
        for part in path.parts:
            if len(os.fsencode(part)) > 255:
                return "a name in its path is too long for the file system"
        existing = path
        while True:
            try:
                info = os.stat(existing)
                break
            except FileNotFoundError:
                if existing.parent == existing:
                    return "no existing folder above it"
                existing = existing.parent
        if not stat.S_ISDIR(info.st_mode):
            what = kind_of(info.st_mode).replace("a regular file", "a file")
            return (f"it is {what}, not a folder" if existing == path
                    else f"{existing} is {what}, not a folder")
        if existing == path:
            try:
                runs = os.stat(path / "runs").st_mode
            except FileNotFoundError:
                runs = None
            if runs is not None and not stat.S_ISDIR(runs):
                return f"its 'runs' is {kind_of(runs).replace('a regular file', 'a file')}"
            target = path / "runs" if runs is not None else path
        else:
            target = existing
        if not os.access(target, os.W_OK | os.X_OK):
            return "no write permission"
    except (OSError, ValueError) as err:
        return f"{type(err).__name__}: {getattr(err, 'strerror', None) or err}"
    return None


def check_outside(cache_dir, out_dir):
    """Refuse a cache inside the output folder (that folder is replaced as a whole), and an
    output folder inside the cache (publishing would replace cached runs).

    Parameters
    ----------
    cache_dir, out_dir : path-like
        The cache folder and the output folder.

    Raises
    ------
    InputError
        If one lies inside the other (or is the other), naming the folder to change.
    """
    try:
        cache = Path(cache_dir).resolve()
        out = Path(out_dir).resolve()
    except (OSError, RuntimeError):  # a symbolic-link loop, a name too long
        # neither can then hold the other: the output folder's own check names what is
        # wrong with it, and a cache that cannot be used is a warning (module notes)
        return
    if cache == out or out in cache.parents:
        raise InputError("the run cache must lie outside the output folder, which is replaced "
                         "as a whole when the reports are published; choose another --cache",
                         str(cache_dir))
    if cache in out.parents:
        raise InputError("the output folder must lie outside the run cache (publishing the "
                         "reports would replace the cached runs in it); choose another --out "
                         "or --cache", str(out_dir))

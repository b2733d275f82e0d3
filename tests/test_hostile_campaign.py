"""Hostile input on the campaign's surfaces: the run cache, the scheduler, the output folder,
the memory a run needs, and a campaign killed at random moments.

References, per family:

- no hang: a named pipe where slingloads reads a file would block a plain ``open`` forever
  (POSIX: opening a FIFO for reading waits for a writer); each check must end within a
  bound, and the scheduler checks within ``--scheduler-timeout`` (plus the time to tear the
  attempt down), against fake servers on the loopback address (refusing, silent, speaking
  garbage) and a real local scheduler;
- the cache: the documented rule (slingloads.runs.cache) that an unusable entry counts
  as missing: the run is computed again, equal to a run on an empty cache;
- memory: hand counts of the bytes of the drive tables and samples (8 bytes a float), and
  Python's allocation tracer (numpy reports its arrays to ``tracemalloc``);
- fault injection: the results of an interrupted then resumed campaign equal those of an
  uninterrupted one (each run is integrated on its own: the same numbers whatever batch it
  falls in), and the output folder holds the previous complete report until the new one is
  published.
"""

from __future__ import annotations

import importlib
import os
import random
import socket
import struct
import threading
import time
import tracemalloc

import numpy as np
import pandas as pd
import pytest
from hostile import save_xlsx, set_parameter, small_dynamics_workbook

from slingloads.analyses.campaign import (
    HISTORY_LABELS,
    MemoryStore,
    execution,
    run_campaign,
    worker,
)
from slingloads.analyses.campaign.execution import (
    REQUIRED_METRICS,
    DaskCluster,
    batch_limit,
    local_workers,
)
from slingloads.cli import EXIT_INCOMPLETE, main
from slingloads.errors import InputError, OutputError
from slingloads.io.common.atomic import AtomicOutputs
from slingloads.io.common.ownership import MANIFEST_NAME
from slingloads.io.study import read_study
from slingloads.runs import cache as cache_module
from slingloads.runs.cache import METRICS_KEY, RunCache

KEY = "ab" + "0" * 62
ROWS = 11


def _within(seconds, call):
    """``call()`` in a daemon thread: (finished in time, value or exception)."""
    box = {}

    def target():
        try:
            box["value"] = call()
        except BaseException as err:  # noqa: BLE001
            box["value"] = err

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(seconds)
    return not thread.is_alive(), box.get("value")


def _record(rows=ROWS, seed=0):
    rng = np.random.default_rng(seed)
    metrics = {m: "x" for m in REQUIRED_METRICS}
    metrics.update({"yaw change [deg]": float(rng.normal()), "trim converged": True})
    return metrics, rng.normal(size=(rows, len(HISTORY_LABELS)))


# ---- family 1: no hang ----------------------------------------------------------------------
@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_named_pipe_as_the_manifest_is_refused_not_waited_on(tmp_path):
    """A FIFO named like the manifest in --out: the check of the folder ends at once with
    the refusal of a manifest slingloads did not write (a plain open would block)."""
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / MANIFEST_NAME)
    finished, value = _within(10, lambda: AtomicOutputs(out).check(["r.xlsx"]))
    assert finished, "the check of the output folder blocked on a named pipe"
    assert isinstance(value, InputError) and "not one" in str(value)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_named_pipe_in_the_cache_counts_as_missing(tmp_path):
    """A FIFO at a run's place in the cache: not opened (O_NONBLOCK, fstat), counted as
    missing, with a warning naming it and what it is."""
    store = RunCache(tmp_path / "cache")
    path = store._path(KEY)
    path.parent.mkdir(parents=True)
    os.mkfifo(path)
    store.expect(KEY, ROWS)
    finished, value = _within(10, lambda: KEY in store)
    assert finished and value is False
    assert str(path) in store.warnings[0] and "named pipe" in store.warnings[0]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_input_files_that_are_named_pipes_are_refused_not_waited_on(tmp_path):
    """The input workbook, or the CSV file a LateralMotions cell names, a FIFO (or a link to
    one): refused at once as not a regular file (a plain open would wait for a writer); and
    the opening that follows the check (slingloads.safeopen, following links for inputs)
    never blocks either, should a pipe be swapped in after it."""
    from hostile import save_xlsx, small_workbook

    from slingloads.safeopen import NotRegularFile, open_regular

    book = tmp_path / "book.xlsx"
    os.mkfifo(book)
    finished, value = _within(10, lambda: read_study(book))
    assert finished and isinstance(value, InputError) and "not a regular file" in str(value)
    sheets = small_workbook()
    sheets["LateralMotions"][2][4] = "pipe.csv"
    os.mkfifo(tmp_path / "pipe.csv")
    path = save_xlsx(sheets, tmp_path / "csv.xlsx")
    finished, value = _within(10, lambda: read_study(path, only=("lateral",)))
    assert finished and isinstance(value, InputError), value
    assert "not a regular file" in str(value) and "cell E3" in str(value), value
    (tmp_path / "link.csv").symlink_to(tmp_path / "pipe.csv")
    for name in ("pipe.csv", "link.csv"):
        finished, value = _within(10, lambda name=name: open_regular(tmp_path / name,
                                                                     follow_links=True))
        assert finished and isinstance(value, NotRegularFile) and "named pipe" in str(value)


def test_output_folder_that_is_a_symbolic_link_loop_is_named_so(tmp_path, capsys):
    """--out a link to itself (ELOOP): the message says loop, not broken link."""
    loop = tmp_path / "loop"
    loop.symlink_to(loop)
    with pytest.raises(OutputError, match="symbolic-link loop"):
        AtomicOutputs(loop).check()


def _drip(conn):
    try:
        while True:
            conn.sendall(b"\x00")
            time.sleep(0.2)
    except OSError:
        pass


def _server(kind):
    """A fake scheduler on 127.0.0.1: 'dead' (nothing listens), 'silent' (accepts, never
    answers), 'garbage' (accepts and sends bytes that are no Dask message), 'drip'
    (accepts and sends a byte every 0.2 s, never a whole message) or 'huge' (accepts and
    announces a message of 4 GiB, the 8-byte length prefix of Dask's TCP comm, then holds
    the connection silent)."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen(8)
    port = listener.getsockname()[1]
    if kind == "dead":
        listener.close()
        return port, lambda: None
    held = []

    def serve():
        while True:
            try:
                conn, _ = listener.accept()
            except OSError:
                return
            held.append(conn)
            if kind == "garbage":
                try:
                    conn.sendall(b"HTTP/1.1 400 Bad Request\r\n\r\n" + bytes(range(256)) * 16)
                except OSError:
                    pass
            if kind == "drip":  # a byte now and then, never a whole message
                threading.Thread(target=_drip, args=(conn,), daemon=True).start()

            if kind == "huge":  # a length prefix of 4 GiB, then nothing
                try:
                    conn.sendall(struct.pack("Q", 4 * 2**30))
                except OSError:
                    pass

    threading.Thread(target=serve, daemon=True).start()

    def stop():
        listener.close()
        for conn in held:
            conn.close()
    return port, stop


@pytest.mark.parametrize("kind, fragment", [
    ("dead", "could not reach the Dask scheduler within 1 s"),
    ("silent", "could not reach the Dask scheduler within 1 s"),
    ("garbage", "does not answer as a Dask scheduler"),
    ("drip", "could not reach the Dask scheduler within 1 s"),
])
def test_a_dead_silent_or_garbage_scheduler_is_refused_within_its_time_out(kind, fragment):
    """--scheduler-timeout 1 s: the executor is refused within the time-out plus 1.5 s of
    tearing down (clean-up included), naming the address; a server that accepts and never
    answers used to hang past 90 s."""
    pytest.importorskip("distributed")
    port, stop = _server(kind)
    try:
        start = time.monotonic()
        finished, value = _within(8, lambda: DaskCluster(f"tcp://127.0.0.1:{port}", 1.0))
        elapsed = time.monotonic() - start
    finally:
        stop()
    assert finished and isinstance(value, InputError), value
    assert fragment in str(value) and str(port) in str(value)
    assert elapsed < 2.5, elapsed


def test_a_scheduler_announcing_a_huge_message_is_refused_unread():
    """A server announcing a 4 GiB message as its handshake: refused at once, the announced
    size named, and nothing near it allocated (Python's allocation tracer, which numpy
    reports its buffers to: distributed's comm allocated the announced size, 4 GiB, before
    reading a byte of it)."""
    pytest.importorskip("distributed")
    port, stop = _server("huge")
    tracemalloc.start()
    try:
        finished, value = _within(8, lambda: DaskCluster(f"tcp://127.0.0.1:{port}", 3.0))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
        stop()
    assert finished and isinstance(value, InputError), value
    assert "does not answer as a Dask scheduler" in str(value), value
    assert "4,294,967,296 bytes" in str(value) and str(port) in str(value)
    assert peak < 64 * 2**20, peak


def test_the_run_command_refuses_a_huge_announcement_with_nothing_written(dyn, tmp_path,
                                                                          capsys):
    """`slingloads run` with the campaign on and --scheduler at a server announcing 4 GiB:
    exit 2 (input error), the address and the size in the message, no --out, no cache."""
    pytest.importorskip("distributed")
    port, stop = _server("huge")
    out, cache = tmp_path / "out", tmp_path / "cache"
    try:
        code = main(["run", str(dyn), "--out", str(out), "--cache", str(cache), "--quiet",
                     "--scheduler", f"tcp://127.0.0.1:{port}", "--scheduler-timeout", "3"])
    finally:
        stop()
    err = capsys.readouterr().err
    assert code == 2, err
    assert f"127.0.0.1:{port}" in err and "4,294,967,296 bytes" in err, err
    assert not out.exists() and not cache.exists()


def test_the_first_exchange_speaks_the_wire_format_of_distributed():
    """The hand-written handshake reader against distributed's own writer: a message that
    ``distributed.comm.tcp`` frames (``to_frames`` and its length header) decodes to the
    same mapping; a first frame longer than its message is refused."""
    pytest.importorskip("distributed")
    from distributed.comm.tcp import _add_frames_header
    from distributed.comm.utils import to_frames

    from slingloads.analyses.campaign import probe

    message = {"compression": None, "python": (3, 11, 4), "pickle-protocol": 5,
               "type": "Scheduler", "workers": {"tcp://10.0.0.1:1": {"nthreads": 4}}}
    frames = asyncio_run(to_frames(message))
    frames, _, _ = _add_frames_header(frames)
    wire = b"".join(bytes(f) for f in frames)
    a, b = socket.socketpair()
    try:
        a.sendall(wire)
        got = probe._read(b, probe._Deadline(2.0))
        a.sendall(struct.pack("QQQ", 16, 1, 10**6))
        with pytest.raises(probe.NotAScheduler, match="first frame is longer"):
            probe._read(b, probe._Deadline(2.0))
    finally:
        a.close()
        b.close()
    assert got == {**message, "workers": {"tcp://10.0.0.1:1": {"nthreads": 4}}}


def asyncio_run(coroutine):
    import asyncio

    return asyncio.run(coroutine)


def test_a_real_scheduler_is_accepted_and_a_stopped_one_is_noticed_in_time():
    """A local scheduler (threads, loopback TCP) passes the identity check; once it is
    stopped, the liveness request fails and closing the client takes no longer than the
    time-out."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1,
                                       dashboard_address=None, protocol="tcp",
                                       host="127.0.0.1")
    executor = DaskCluster(cluster.scheduler_address, 1.0)
    assert executor.workers == 1 and executor._alive()
    cluster.close()
    start = time.monotonic()
    assert not executor._alive()
    executor.close()
    assert time.monotonic() - start < 3.0


# ---- family 2: the cache is a cache ----------------------------------------------------------
def _write_parquet(path, columns=HISTORY_LABELS, rows=ROWS, metrics=b"{}", dtype=float):
    """A Parquet file of ``rows`` zeros per column, written 100,000 rows at a time."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    def table(n):
        arrays = [pa.array(np.zeros(n, dtype=dtype)) for _ in columns]
        out = pa.Table.from_arrays(arrays, names=list(columns))
        return out if metrics is None else out.replace_schema_metadata({METRICS_KEY: metrics})

    path.parent.mkdir(parents=True, exist_ok=True)
    piece = table(min(rows, 100_000))
    with pq.ParquetWriter(path, piece.schema) as writer:
        for start in range(0, rows, 100_000):
            writer.write_table(piece if rows - start >= 100_000 else table(rows - start))


def _damage(kind, path, rng, good):
    """Put an entry of ``kind`` at ``path`` (``good``: the bytes of a valid entry)."""
    import json

    path.parent.mkdir(parents=True, exist_ok=True)
    valid_metrics = json.dumps({m: "x" for m in REQUIRED_METRICS}).encode()
    if kind == "random bytes":
        path.write_bytes(rng.bytes(int(rng.integers(0, 4000))))
    elif kind == "truncated":
        path.write_bytes(good[:int(rng.integers(0, len(good)))])
    elif kind == "bit flip":
        data = bytearray(good)
        for at in rng.integers(0, len(data), 8):
            data[at] ^= 0xFF
        path.write_bytes(bytes(data))
    elif kind == "metrics not JSON":
        _write_parquet(path, metrics=b"{not json")
    elif kind == "metrics a JSON list":
        _write_parquet(path, metrics=b"[1, 2, 3]")
    elif kind == "metrics incomplete":
        _write_parquet(path, metrics=b'{"yaw change [deg]": 1.0}')
    elif kind == "no metrics":
        _write_parquet(path, metrics=None)
    elif kind == "a column missing":
        _write_parquet(path, columns=HISTORY_LABELS[:-1], metrics=valid_metrics)
    elif kind == "integer columns":
        _write_parquet(path, metrics=valid_metrics, dtype=np.int64)
    elif kind == "other run length":
        _write_parquet(path, rows=ROWS + 1, metrics=valid_metrics)
    elif kind == "8 million rows":  # 1 MB on disk, 1.7 GB once read
        _write_parquet(path, rows=8_000_000, metrics=valid_metrics)
    elif kind == "a folder":
        path.mkdir()
    elif kind == "a symbolic link":
        target = path.parent / "elsewhere.parquet"
        target.write_bytes(good)
        path.symlink_to(target)
    else:  # pragma: no cover
        raise AssertionError(kind)


KINDS = ("random bytes", "truncated", "bit flip", "metrics not JSON", "metrics a JSON list",
         "metrics incomplete", "no metrics", "a column missing", "integer columns",
         "other run length", "a folder", "a symbolic link")


def test_fuzzed_cache_entries_count_as_missing_and_are_replaced(tmp_path):
    """Seeded fuzz: 60 entries of random bytes, truncated or bit-flipped valid files, and
    valid Parquet files with wrong contents. Each counts as missing (``in`` is False, ``get``
    None) with one warning naming the file, never an exception; a run stored over it reads
    back equal to what was stored (the documented rule: an unusable entry is computed
    again)."""
    rng = np.random.default_rng(2026)
    good_store = RunCache(tmp_path / "good")
    good_store.expect(KEY, ROWS)
    record = _record()
    good_store.put(KEY, record)
    good = good_store._path(KEY).read_bytes()
    for trial in range(60):
        kind = KINDS[trial % len(KINDS)]
        folder = tmp_path / f"c{trial}"
        store = RunCache(folder)
        path = store._path(KEY)
        _damage(kind, path, rng, good)
        store.expect(KEY, ROWS)
        if kind == "bit flip" and KEY in store:  # a flip in padding may leave it valid
            assert store.get(KEY) is not None
            continue
        assert KEY not in store, kind
        assert store.get(KEY) is None, kind
        assert len(store.warnings) == 1 and str(path) in store.warnings[0], (kind,
                                                                             store.warnings)
        if kind == "a folder":
            path.rmdir()  # a folder in the way is a cache location problem (next test)
        store.put(KEY, record)
        again = RunCache(folder)
        again.expect(KEY, ROWS)
        metrics, histories = again.get(KEY)
        assert metrics == record[0] and np.array_equal(histories, record[1]), kind


def test_an_oversized_entry_is_refused_before_it_is_read(tmp_path):
    """A 0.9 MB file declaring 8 million rows (1.7 GB of floats once read): for a run of 11
    rows it is refused by its size (more than 11 rows of 26 floats can take); for a run of
    36,001 rows (3,600 s every 0.1 s, whose file may take 8 MB) by the row count its footer
    declares, with less than 5 MB allocated by numpy and Python (tracemalloc), where reading
    it whole took 5.7 GB."""
    path = RunCache(tmp_path / "cache")._path(KEY)
    _damage("8 million rows", path, None, b"")
    assert path.stat().st_size < 2_000_000
    for rows, fragment in ((ROWS, "bytes, more than the"), (36_001, "8,000,000 rows")):
        store = RunCache(tmp_path / "cache")
        store.expect(KEY, rows)
        tracemalloc.start()
        try:
            assert KEY not in store
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
        assert peak < 5 * 2**20, peak
        assert fragment in store.warnings[0], store.warnings


def test_interrupted_writes_are_removed_by_the_next_run(tmp_path):
    """A writer killed mid-write leaves ``.part-<host>-<pid>-*.parquet``: the next cache
    opened on the folder removes those of dead processes (and of older versions without a
    process id), and keeps a live writer's."""
    store = RunCache(tmp_path / "cache")
    store.put(KEY, _record())
    shard = store._path(KEY).parent
    host = cache_module._host_tag()
    dead = 2**22 + 12345  # above the usual pid_max: no such process
    while cache_module._alive(dead):  # pragma: no cover
        dead += 1
    left = [shard / f".part-{host}-{dead}-0a0b.parquet", shard / ".part-k2j4h5.parquet"]
    live = shard / f".part-{host}-{os.getpid()}-0c0d.parquet"
    for path in (*left, live):
        path.write_bytes(b"PAR1 half")
    RunCache(tmp_path / "cache")
    assert not any(p.exists() for p in left) and live.exists()
    assert store._path(KEY).exists()


@pytest.mark.parametrize("layout", ["file", "runs is a file", "read-only"])
def test_an_unusable_cache_location_falls_back_to_memory(tmp_path, layout):
    """A cache that is a file, whose ``runs`` is a file, or that is read-only: the store
    keeps the runs in a temporary folder of its own (put then get gives them back, equal),
    removed when the store is collected, with one warning naming the folder; nothing
    raises."""
    folder = tmp_path / "cache"
    if layout == "file":
        folder.write_text("x")
    else:
        folder.mkdir()
        if layout == "runs is a file":
            (folder / "runs").write_text("x")
        else:
            folder.chmod(0o500)
    try:
        store = RunCache(folder)
        if layout == "read-only" and os.access(folder, os.W_OK):  # pragma: no cover - root
            pytest.skip("permissions do not bind this user")
        record = _record()
        store.expect(KEY, ROWS)
        store.put(KEY, record)
        metrics, histories = store.get(KEY)
        assert KEY in store and metrics == record[0] and np.array_equal(histories, record[1])
        assert len(store.warnings) == 1 and str(folder) in store.warnings[0]
        assert "runs without it" in store.warnings[0]
        spill = store._spill_path(KEY)
        assert spill.is_file() and folder not in spill.parents and not store._memory
        del store
        import gc
        gc.collect()
        assert not spill.parent.exists()
    finally:
        folder.chmod(0o700) if folder.is_dir() else None


def test_a_write_that_fails_mid_campaign_falls_back_to_memory(tmp_path):
    """A shard folder that turns out to be a file when the first run is stored (the cache
    looked usable when opened): the run is kept in memory, one warning, no exception."""
    store = RunCache(tmp_path / "cache")
    shard = store._path(KEY).parent
    shard.parent.mkdir(parents=True)
    shard.write_text("in the way")
    store.put(KEY, _record())
    assert KEY in store and not store.usable and "cannot be used" in store.warnings[0]


# ---- the command line: fall back, count, warn ---------------------------------------------
@pytest.fixture(scope="module")
def dyn(tmp_path_factory):
    """The small campaign (8 runs of 5 s, no multibody report)."""
    book = small_dynamics_workbook()
    set_parameter(book, "run multibody", "no")
    return save_xlsx(book, tmp_path_factory.mktemp("dyn") / "dyn.xlsx")


def _summary(out):
    frame = pd.read_excel(out / "dyn-campaign.xlsx", sheet_name="Summary", header=None)
    return dict(zip(frame[0], frame[1], strict=False))


def test_campaign_with_a_file_as_cache_runs_without_it(dyn, tmp_path, capsys):
    """--cache naming a file: the campaign runs, a warning names the file, the report is
    written and says 0 runs found and every run of the matrix computed. Its runs of 5 s are
    shorter than the envelope test's 10 s window (every verdict inconclusive), so no area is
    chosen: a finding, exit 3 with the reports written, not an input error."""
    afile = tmp_path / "afile"
    afile.write_text("x")
    out = tmp_path / "out"
    assert main(["campaign", str(dyn), "--out", str(out), "--cache", str(afile),
                 "--quiet"]) == EXIT_INCOMPLETE
    err = capsys.readouterr().err
    assert f"the run cache {afile} cannot be used" in err
    assert "incomplete: campaign: no parachute area of the matrix is stable" in err
    rows = _summary(out)
    assert rows["runs found in the cache"] == 0
    assert rows["runs computed now"] == rows["runs in the matrix"] == 8
    assert afile.read_text() == "x"


# ---- family 3: memory bounded by what the limits count --------------------------------------
def test_memory_estimates_by_hand():
    """A run of 3,600 s sampled every 1 s: drive tables every 0.01 s (360,000 + 2 x 1 + 1
    rows of 9 floats, twice: the table and its stacked copy) and 3,601 samples of 85 floats
    (20 states, 9 drive values, 30 reported quantities, 26 histories)."""
    from slingloads.analyses.multibody.simulate import SAMPLE_BYTES, drive_bytes, run_bytes

    assert drive_bytes(3600.0) == 2 * 360_003 * 9 * 8
    assert SAMPLE_BYTES == 85 * 8
    assert run_bytes(3600.0, 1.0) == 2 * 360_003 * 72 + 3601 * 680
    # a batch of runs of 3,600 s sampled every 0.1 s: 36,001 x (680 + 208) bytes a run,
    # so 2 fit in BATCH_MEMORY's 64 MiB (67,108,864 / 31,968,888 = 2.1)
    assert batch_limit({"t_end": 3600.0, "output_interval": 0.1}) == 2


def test_workers_are_capped_by_cores_and_memory_with_a_warning():
    """16 workers asked for on 2 cores: 2 started, the warning gives the request, the cores
    and the estimate; with 1 GB available only 1 fits beside this process (each about
    300 MB of libraries, 128 MB of drive tables, 64 MB of a batch's samples); a request
    within both is left alone, silently."""
    workers, warning = local_workers(16, {"t_end": 60.0, "output_interval": 0.1}, cores=2,
                                     available=64 * 2**30)
    assert workers == 2 and "16 local workers were asked for, 2 started" in warning
    assert "2 cores" in warning and "MB" in warning
    workers, warning = local_workers(2, None, cores=8, available=2**30)
    assert workers == 1 and "memory available" in warning
    assert local_workers(2, None, cores=8, available=64 * 2**30) == (2, None)


def test_local_workers_are_capped_by_the_command_budget():
    """8 cores and 64 GB: 8 workers asked for, 2 started, the most whose own memory (288 MiB
    each, measured 284) fits the 1 GiB budget beside the command's 448 MiB ((1024 - 448) /
    288 = 2), with a warning naming the budget; the default on 8 cores is cut the same way."""
    from slingloads.analyses.campaign.memory import budget_workers

    assert budget_workers() == (1024 - 448) // 288 == 2
    workers, warning = local_workers(8, None, cores=8, available=64 * 2**30)
    assert workers == 2 and "budget of 1 GB allows 2" in warning and "--scheduler" in warning


def test_the_study_cell_asking_for_many_workers_is_cut_with_the_estimate(tmp_path,
                                                                          monkeypatch):
    """The Study cell 'campaign workers' = 16 (allowed up to 64; it used to start 16
    processes of about 290 MB each on two cores): the campaign of that workbook is handed
    local worker processes capped by the command's budget ((1 GiB - 448 MiB) / 288 MiB =
    2) and the cores, and the study's warnings say so with the estimate of a worker
    (libraries 300 MiB + drive tables 128 MiB + the largest batch's samples: 100 runs of 5 s
    every 0.5 s, 11 samples of 888 bytes each, 1 MB). The runs themselves are not computed."""
    from slingloads.analyses import campaign as campaign_package
    from slingloads.runs import campaign as campaign_run

    book = small_dynamics_workbook()
    set_parameter(book, "run multibody", "no")
    set_parameter(book, "campaign workers", 16)
    study = read_study(save_xlsx(book, tmp_path / "w16.xlsx"))
    assert study.inputs.campaign.workers == 16
    handed = []

    class Stop(Exception):
        pass

    def recorder(campaign, executor=None, store=None, progress=None):
        handed.append(executor)
        raise Stop

    monkeypatch.setattr(campaign_package, "run_campaign", recorder)
    monkeypatch.setenv("SLINGLOADS_CACHE", str(tmp_path / "cache"))
    with pytest.raises(Stop):
        campaign_run.run(study)
    executor = handed[0]
    expected = min(2, os.cpu_count() or 1)
    assert getattr(executor, "workers", 1) == expected <= 2
    warning, = executor.warnings
    each = (300 + 128) * 2**20 + 100 * 11 * 888
    assert f"16 local workers were asked for, {expected} started" in warning
    assert f"each needs about {each / 2**20:,.0f} MB" in warning and "budget" in warning


def test_drive_tables_are_tabulated_a_chunk_at_a_time(monkeypatch):
    """16 runs of 3,600 s (each its own gust, so 16 distinct drive tables of 26 MB: 0.8 GB
    and their stacked copy at once before): integrated in chunks whose tables and copies stay
    within DRIVE_BUDGET; the peak traced allocation stays below DRIVE_BUDGET + 16 MB. The
    integration itself is replaced by a recorder (its own memory is the samples')."""
    from test_multibody_response import hc1_system

    sim = importlib.import_module("slingloads.analyses.multibody.simulate")
    from slingloads.analyses.multibody.manoeuvres import gust_response

    system = hc1_system()
    pairs = [(system, gust_response("finite", onset=1.0 + 0.1 * k)) for k in range(16)]
    chunks = []

    def recorder(prepared, members, results, drives, time_, settings):
        profiles = [drives.get(prepared[k][1], prepared[k][2].state[0:3])[1] for k in members]
        sim.stack_drives(profiles)
        chunks.append(len(members))
        for k in members:
            results[k] = None

    monkeypatch.setattr(sim, "_integrate_group", recorder)
    monkeypatch.setattr(sim, "Simulation", lambda *a: a)
    tracemalloc.start()
    try:
        sim.simulate_runs(pairs, t_end=3600.0, output_interval=10.0)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert sum(chunks) == 16 and max(chunks) < 16
    assert peak < sim.DRIVE_BUDGET + 16 * 2**20, peak / 2**20


def test_one_integrating_thread_tabulates_one_long_run_at_a_time(monkeypatch):
    """A campaign worker process with one kernel thread (two local workers on two cores)
    integrates one run at a time, so its chunk of drive tables is half of DRIVE_BUDGET:
    runs of 3,600 s (2 x 360,003 rows x 72 bytes = 51.8 MB each) go one a chunk (two
    would be 103.7 MB > 64 MiB), and two a chunk with two threads (<= 128 MiB)."""
    from test_multibody_response import hc1_system

    sim = importlib.import_module("slingloads.analyses.multibody.simulate")
    from slingloads.analyses.multibody.manoeuvres import gust_response

    assert sim.drive_budget(1) == 64 * 2**20 and sim.drive_budget(2) == 128 * 2**20
    system = hc1_system()
    pairs = [(system, gust_response("finite", onset=1.0 + 0.1 * k)) for k in range(4)]
    chunks = []

    def recorder(prepared, members, results, drives, time_, settings):
        chunks.append(len(members))

    monkeypatch.setattr(sim, "_integrate_group", recorder)
    monkeypatch.setattr(sim, "Simulation", lambda *a: a)
    for workers in (1, 2):
        chunks.clear()
        sim.simulate_runs(pairs, t_end=3600.0, output_interval=10.0, workers=workers)
        assert chunks == [workers] * (4 // workers)


def test_chunked_integration_is_bit_for_bit(monkeypatch):
    """Runs integrated one chunk each (DRIVE_BUDGET of 1 byte) give the same histories, to
    the last bit, as all in one chunk: each run is integrated on its own."""
    from test_multibody_response import hc1_system

    sim = importlib.import_module("slingloads.analyses.multibody.simulate")
    from slingloads.analyses.multibody.manoeuvres import gust_response

    pairs = [(hc1_system(), gust_response("step", onset=1.0)),
             (hc1_system(), gust_response("finite", onset=2.0))]
    together = sim.simulate_runs(pairs, t_end=6.0)
    monkeypatch.setattr(sim, "DRIVE_BUDGET", 1)
    apart = sim.simulate_runs(pairs, t_end=6.0)
    for a, b in zip(together.runs, apart.runs, strict=True):
        assert a.to_frame().equals(b.to_frame())


def test_one_campaign_run_over_the_memory_budget_is_refused_at_its_cell(dyn, tmp_path,
                                                                         capsys):
    """A run of 3,600 s sampled every 0.005 s: 720,001 samples of 680 bytes and 52 MB of
    drive tables, about 519 MB > the 512 MB budget: refused at 'campaign output interval'
    before any run, exit 2, nothing written."""
    book = small_dynamics_workbook()
    set_parameter(book, "run multibody", "no")
    set_parameter(book, "campaign run length", 3600.0, "s")
    set_parameter(book, "campaign time step", 0.0, "s")
    set_parameter(book, "campaign output interval", 0.005, "s")
    set_parameter(book, "campaign density altitudes", "0", "ft")
    set_parameter(book, "campaign area factors", "1.0", None)
    path = save_xlsx(book, tmp_path / "big.xlsx")
    row = next(i for i, r in enumerate(book["Study"], 1) if r[0] == "campaign output interval")
    out = tmp_path / "out"
    assert main(["campaign", str(path), "--out", str(out), "--cache",
                 str(tmp_path / "cache"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"cell B{row}" in err and "too much memory" in err and "512 MB" in err
    assert not out.exists()


# ---- family 5: fault injection --------------------------------------------------------------
def test_interrupted_at_random_moments_the_resume_gives_identical_results(dyn, tmp_path,
                                                                          monkeypatch):
    """Three seeded random interruptions of the 8-run campaign on the disk cache (one run
    per batch): between batches (Ctrl-C), inside a batch, or in the middle of writing a
    cached run, the half-written file left as a killed process leaves it. Each resume
    finds the runs stored before, computes the others, leaves no temporary file, and its
    metrics and histories equal an uninterrupted run's on an empty store."""
    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    rng = random.Random(22)
    original_batch, original_write = execution.run_batch, RunCache._write
    for trial in range(3):
        folder = tmp_path / f"cache{trial}"
        moment = rng.choice(["between batches", "in a batch", "writing"])
        at = rng.randint(1, 3)
        calls = []

        def batch(jobs, settings, threads=None, moment=moment, at=at, calls=calls):
            calls.append(1)
            if moment == "in a batch" and len(calls) == at + 1:
                raise KeyboardInterrupt
            return original_batch(jobs, settings, threads)

        def write(self, key, record, moment=moment, at=at):
            if moment == "writing" and self.written == at:
                part = self._path(key).parent / (
                    f".part-{cache_module._host_tag()}-{2**22 + 4321}-dead.parquet")
                part.parent.mkdir(parents=True, exist_ok=True)
                part.write_bytes(b"PAR1 half a file")  # what a killed writer leaves
                raise KeyboardInterrupt
            return original_write(self, key, record)

        def progress(done, total, moment=moment, at=at):
            if moment == "between batches" and done == at:
                raise KeyboardInterrupt

        monkeypatch.setattr(execution, "run_batch", batch)
        monkeypatch.setattr(RunCache, "_write", write)
        with pytest.raises(KeyboardInterrupt):
            run_campaign(campaign, store=RunCache(folder), batch_size=1, progress=progress)
        monkeypatch.setattr(execution, "run_batch", original_batch)
        monkeypatch.setattr(RunCache, "_write", original_write)
        stored = len(list(folder.rglob("*.parquet"))) - len(list(folder.rglob(".part-*")))
        resumed = run_campaign(campaign, store=RunCache(folder), batch_size=1)
        total = resumed.execution.total
        assert (resumed.execution.cached, resumed.execution.computed) == (stored, total - stored)
        assert not list(folder.rglob(".part-*")), moment
        pd.testing.assert_frame_equal(resumed.metrics, fresh.metrics)
        for run in fresh.metrics["run"]:
            pd.testing.assert_frame_equal(resumed.history(run), fresh.history(run))


def test_a_killed_worker_process_leaves_the_cache_and_out_intact(dyn, tmp_path, capsys):
    """A local worker process killed (it exits at once in its first batch, as a killed
    process does): the campaign ends with a clear error (exit 1, no traceback), nothing is
    published (the earlier report in --out stays, byte for byte) and no temporary file is
    left in the cache; the resume on that cache equals an uninterrupted run."""
    from hostile import publish_earlier

    out, folder = tmp_path / "out", tmp_path / "cache"
    publish_earlier(out, {"dyn-campaign.xlsx": b"an earlier report"})
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    os.environ[worker.KILL_VARIABLE] = "1"
    try:
        code = main(["campaign", str(dyn), "--out", str(out), "--cache", str(folder),
                     "--quiet", "--workers", "2"])
    finally:
        del os.environ[worker.KILL_VARIABLE]
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" not in err and "nothing was written" in err, err
    assert "worker process ended abruptly" in err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert not list(folder.rglob(".part-*"))
    campaign = read_study(dyn).inputs.campaign.campaign
    resumed = run_campaign(campaign, store=RunCache(folder))
    pd.testing.assert_frame_equal(resumed.metrics,
                                  run_campaign(campaign, store=MemoryStore()).metrics)


def test_a_scheduler_killed_mid_campaign_ends_cleanly_and_the_resume_is_identical(dyn,
                                                                                  tmp_path):
    """A local Dask scheduler (worker threads, loopback TCP) terminated after a seeded
    random number (1 to 6) of 8 one-run batches: the campaign ends within the 1 s time-out
    with an environment error (the runs finished before stored), and the resume, in this
    process on the same cache, finds them and gives the metrics and histories of an
    uninterrupted run."""
    import contextlib

    distributed = pytest.importorskip("distributed")
    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    cluster = distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1,
                                       dashboard_address=None, protocol="tcp",
                                       host="127.0.0.1")
    try:
        executor = DaskCluster(cluster.scheduler_address, 1.0)
        at = random.Random(7).randint(1, 6)

        def progress(done, total):
            if done == at:
                with contextlib.suppress(OSError):
                    executor.client.sync(executor.client.scheduler.terminate)

        start = time.monotonic()
        with pytest.raises(OutputError, match="scheduler was lost|stopped answering"):
            run_campaign(campaign, executor=executor, store=RunCache(tmp_path / "cache"),
                         batch_size=1, progress=progress)
        assert time.monotonic() - start < 5.0
    finally:
        with contextlib.suppress(TimeoutError, OSError):
            cluster.close(timeout=2)
    resumed = run_campaign(campaign, store=RunCache(tmp_path / "cache"))
    assert resumed.execution.cached >= at
    assert resumed.execution.cached + resumed.execution.computed == resumed.execution.total
    _same_results(resumed, fresh)


def test_a_worker_killed_on_a_cluster_ends_cleanly_and_the_resume_is_identical(dyn, tmp_path):
    """The one worker of a local Dask cluster (threads, loopback TCP) closed after a seeded
    random number (1 to 6) of 8 one-run batches: the scheduler still answers but has no
    worker, so the batches would wait for one for ever; the campaign ends within the 1 s
    time-out (plus the worker's own shutting down) with an environment error, and the
    resume on the same cache finds the runs stored before and gives the metrics and
    histories of an uninterrupted run."""
    import contextlib

    distributed = pytest.importorskip("distributed")
    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    cluster = distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1,
                                       dashboard_address=None, protocol="tcp",
                                       host="127.0.0.1")
    try:
        executor = DaskCluster(cluster.scheduler_address, 1.0)
        times = {}
        at = random.Random(11).randint(1, 6)

        def progress(done, total):
            if done == at:
                times["killed"] = time.monotonic()
                for address in list(cluster.scheduler.workers):
                    cluster.sync(cluster.scheduler.remove_worker, address, stimulus_id="kill",
                                 close=True)

        with pytest.raises(OutputError, match="no worker left"):
            run_campaign(campaign, executor=executor, store=RunCache(tmp_path / "cache"),
                         batch_size=1, progress=progress)
        assert time.monotonic() - times["killed"] < 5.0
    finally:
        with contextlib.suppress(TimeoutError, OSError):
            cluster.close(timeout=2)
    resumed = run_campaign(campaign, store=RunCache(tmp_path / "cache"))
    assert resumed.execution.cached >= at
    assert resumed.execution.cached + resumed.execution.computed == resumed.execution.total
    _same_results(resumed, fresh)


def _same_results(resumed, fresh):
    """The metrics and every run's histories of ``resumed`` equal those of ``fresh``."""
    pd.testing.assert_frame_equal(resumed.metrics, fresh.metrics)
    for run in fresh.metrics["run"]:
        pd.testing.assert_frame_equal(resumed.history(run), fresh.history(run))


def _spawned_workers():
    """The live worker processes this process has started (``spawn``: their command line
    runs ``multiprocessing.spawn``; the resource tracker is not one)."""
    import psutil

    workers = []
    for child in psutil.Process().children():
        try:
            line = " ".join(child.cmdline())
        except psutil.Error:
            continue
        if "spawn_main" in line and child.status() != psutil.STATUS_ZOMBIE:
            workers.append(child)
    return workers


def test_local_workers_killed_at_seeded_random_moments_resume_identically(dyn, tmp_path):
    """Two local worker processes running 8 one-run batches; one of them, drawn by a seeded
    RNG, is killed outright (SIGKILL) at a seeded random moment: after 0 to 3 batches have
    come back and a further 0 to 0.3 s (the workers may be starting, loading their kernels
    or integrating). The campaign either ends with the environment error naming the lost
    worker (the runs finished before stored) or, when the kill came after the last batch,
    finishes; no temporary file is left in the cache; and the resume, in this process on
    the same cache, finds the runs stored before and gives the metrics and histories of an
    uninterrupted run (each run is integrated on its own, so the same numbers whatever
    process or batch it falls in)."""
    import signal

    from slingloads.analyses.campaign.execution import LocalProcesses

    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    rng = random.Random(21)
    for trial in range(2):
        after, delay, victim = rng.randint(0, 3), rng.uniform(0.0, 0.3), rng.randint(0, 1)
        folder = tmp_path / f"cache{trial}"
        killed, stop, started = [], threading.Event(), threading.Event()

        def kill(victim=victim, delay=delay, killed=killed, stop=stop, started=started):
            started.wait()
            if stop.wait(delay):
                return
            while not stop.is_set():  # the workers may still be starting
                workers = sorted(_spawned_workers(), key=lambda p: p.pid)
                if workers:
                    target = workers[min(victim, len(workers) - 1)]
                    os.kill(target.pid, signal.SIGKILL)
                    killed.append(target.pid)
                    return
                stop.wait(0.01)

        def progress(done, total, after=after, started=started):
            if done == after:
                started.set()

        killer = threading.Thread(target=kill, daemon=True)
        killer.start()
        executor = LocalProcesses(2)
        try:
            run_campaign(campaign, executor=executor, store=RunCache(folder), batch_size=1,
                         progress=progress)
            finished = True
        except OutputError as err:
            assert "local worker process ended abruptly" in str(err)
            assert "run the same command again to resume" in str(err)
            finished = False
        finally:
            stop.set()  # a kill not yet made is not made in the next trial
            started.set()
            killer.join()
            executor.close()
        assert finished or killed, (trial, after, delay)
        assert not list(folder.rglob(".part-*"))
        stored = len(list(folder.rglob("*.parquet")))
        resumed = run_campaign(campaign, store=RunCache(folder), batch_size=1)
        assert resumed.execution.cached == stored >= min(after, 8)
        assert resumed.execution.cached + resumed.execution.computed == resumed.execution.total
        _same_results(resumed, fresh)


_RELEASE = threading.Event()
_CALLS = []


def _hung_after_one(jobs, settings, threads=None):
    """run_batch as a worker that computes its first batch, then accepts the others and
    never returns them (until the test releases it)."""
    _CALLS.append(1)
    if len(_CALLS) == 1:
        return worker.run_batch(jobs, settings, threads)
    _RELEASE.wait(30)
    raise RuntimeError("released")


def test_the_longest_a_batch_is_waited_for_by_hand():
    """batch_seconds by hand: 20 runs of 60 s at a fixed 0.01 s are 120,000 run-steps, at
    1e-4 s each 12 s; with the adaptive step the floor of 1e-3 s gives 1,200,000 run-steps,
    less than the 3,000,000 the stiffness check lets a batch force: 300 s."""
    assert execution.batch_seconds({"t_end": 60.0, "dt": 0.01}, 20) == pytest.approx(12.0)
    assert execution.batch_seconds({"t_end": 60.0, "dt": None}, 20) == pytest.approx(300.0)
    assert execution.batch_seconds({"t_end": 60.0, "dt": None}, 100) == pytest.approx(600.0)


def test_a_worker_that_never_returns_a_batch_ends_the_campaign_in_its_bound(dyn, tmp_path,
                                                                            monkeypatch):
    """A local Dask cluster (worker threads, loopback TCP) whose worker computes the first
    of 8 one-run batches and then holds the others for ever, while the scheduler answers
    and shows the worker (so the liveness checks all pass): with the allowances of the
    bound set to nothing (no start time, 1e-9 s a run-step), the campaign ends with an
    environment error once no batch has come back for the 1 s time-out (where it used to wait
    for ever), the first run stored; the resume on the same cache (in this process) finds it
    and gives the metrics of an uninterrupted run."""
    import contextlib

    distributed = pytest.importorskip("distributed")
    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    monkeypatch.setattr(execution, "WORKER_START_SECONDS", 0.0)
    monkeypatch.setattr(execution, "RUN_STEP_SECONDS", 1e-9)
    monkeypatch.setattr(execution, "run_batch", _hung_after_one)
    _CALLS.clear()
    _RELEASE.clear()
    cluster = distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1,
                                       dashboard_address=None, protocol="tcp",
                                       host="127.0.0.1")
    try:
        executor = DaskCluster(cluster.scheduler_address, 1.0)
        start = time.monotonic()
        with pytest.raises(OutputError, match="no batch has come back") as caught:
            run_campaign(campaign, executor=executor, store=RunCache(tmp_path / "cache"),
                         batch_size=1)
        elapsed = time.monotonic() - start
    finally:
        _RELEASE.set()
        with contextlib.suppress(TimeoutError, OSError):
            cluster.close(timeout=2)
    assert "run again to resume" in str(caught.value) and executor.stall < 1.1
    assert elapsed < 8.0, elapsed
    assert not list((tmp_path / "cache").rglob(".part-*"))
    monkeypatch.undo()
    resumed = run_campaign(campaign, store=RunCache(tmp_path / "cache"))
    assert resumed.execution.cached == 1
    pd.testing.assert_frame_equal(resumed.metrics, fresh.metrics)


def test_the_campaign_command_with_a_hung_worker_exits_with_out_intact(dyn, tmp_path,
                                                                       monkeypatch, capsys):
    """The campaign command on a local cluster whose worker holds every batch (the bound's
    allowances set to nothing, time-out 1 s): exit 1 (environment) with the message, the
    earlier report in --out byte for byte, no temporary file in the cache."""
    import contextlib

    from hostile import publish_earlier

    distributed = pytest.importorskip("distributed")
    monkeypatch.setattr(execution, "WORKER_START_SECONDS", 0.0)
    monkeypatch.setattr(execution, "RUN_STEP_SECONDS", 1e-9)
    monkeypatch.setattr(execution, "run_batch", _hung_after_one)
    _CALLS[:] = [1]  # every batch held
    _RELEASE.clear()
    out, cache = tmp_path / "out", tmp_path / "cache"
    publish_earlier(out, {"dyn-campaign.xlsx": b"an earlier report"})
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    cluster = distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1,
                                       dashboard_address=None, protocol="tcp",
                                       host="127.0.0.1")
    try:
        code = main(["campaign", str(dyn), "--out", str(out), "--cache", str(cache),
                     "--quiet", "--scheduler", cluster.scheduler_address,
                     "--scheduler-timeout", "1"])
    finally:
        _RELEASE.set()
        with contextlib.suppress(TimeoutError, OSError):
            cluster.close(timeout=2)
    err = capsys.readouterr().err
    assert code == 1 and "no batch has come back from the Dask cluster" in err, err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert not list(cache.rglob(".part-*")) and not list(cache.rglob("*.parquet"))


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_fall_back_mid_campaign_still_reads_the_runs_found_before(tmp_path):
    """Two runs: one stored, the other's shard folder a named pipe (so its entry cannot be
    read nor written). The first is found, the second computed and kept in memory when the
    cache falls back; both are then read back (the first from disk, as found), where the
    first used to come back as None once the cache had fallen back (TypeError in the
    campaign)."""
    store = RunCache(tmp_path / "cache")
    found, other = "ab" + "1" * 62, "cd" + "2" * 62
    record = _record()
    store.put(found, record)
    os.mkfifo(store._path(other).parent)
    again = RunCache(tmp_path / "cache")
    for key in (found, other):
        again.expect(key, ROWS)
    assert found in again and other not in again
    again.put(other, _record(seed=1))
    assert not again.usable
    metrics, histories = again.get(found)
    assert metrics == record[0] and np.array_equal(histories, record[1])
    assert again.get(other) is not None


def test_the_campaign_command_names_an_output_loop_so(dyn, tmp_path, capsys):
    """--out a link to itself on the campaign command (whose cache is checked to lie
    outside --out first): the message says symbolic-link loop and names --out, not the
    cache ('cannot be resolved (RuntimeError)' before); nothing is written."""
    loop = tmp_path / "loop"
    loop.symlink_to(loop)
    code = main(["campaign", str(dyn), "--out", str(loop), "--cache", str(tmp_path / "c"),
                 "--quiet"])
    err = capsys.readouterr().err
    assert code != 0 and "symbolic-link loop" in err and str(loop) in err, err
    assert "cannot be resolved" not in err and not (tmp_path / "c").exists()


@pytest.mark.parametrize("moment", ["early", "storing"])
def test_a_client_killed_outright_resumes_to_identical_results(dyn, tmp_path, moment):
    """The campaign command killed outright (SIGKILL to its process group, so no clean-up
    runs): early, at a seeded random time within its first 2 s (reading, compiling or
    computing, before any run is stored), or as soon as its first run is in the cache
    (while the others are being written). The earlier report in --out stays byte
    for byte; the resume on the same cache leaves no temporary file and gives the metrics
    and histories of an uninterrupted run (each run is integrated on its own)."""
    import signal

    from hostile import command, publish_earlier, wait_until

    campaign = read_study(dyn).inputs.campaign.campaign
    fresh = run_campaign(campaign, store=MemoryStore())
    out = tmp_path / "out"
    publish_earlier(out, {"dyn-campaign.xlsx": b"an earlier report"})
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    rng = random.Random(5)
    folder = tmp_path / "c" / "campaign"  # $SLINGLOADS_CACHE/campaign
    proc = command("campaign", dyn, out, start_new_session=True,
                   env={"SLINGLOADS_PLOT_WORKERS": "0", "SLINGLOADS_CACHE": str(tmp_path / "c")})
    try:
        def stored():
            return any(not p.name.startswith(".") for p in folder.rglob("*.parquet"))

        if moment == "early":  # reading, compiling or computing: before the batch returns
            time.sleep(rng.uniform(0.2, 2.0))
        else:
            wait_until(stored, proc, "the first stored run")
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(30)
    finally:
        if proc.poll() is None:  # pragma: no cover
            os.killpg(proc.pid, signal.SIGKILL)
        proc.stderr.close()
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    resumed = run_campaign(campaign, store=RunCache(folder))
    assert not list(folder.rglob(".part-*"))
    assert resumed.execution.cached + resumed.execution.computed == resumed.execution.total
    assert resumed.execution.cached >= (1 if moment == "storing" else 0)
    pd.testing.assert_frame_equal(resumed.metrics, fresh.metrics)
    for run in fresh.metrics["run"]:
        pd.testing.assert_frame_equal(resumed.history(run), fresh.history(run))

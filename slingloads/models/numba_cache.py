"""Validity of numba's on-disk cache for kernels that span several modules.

numba invalidates a cached function when its own source file changes, not when a function it
calls, or a constant it reads, from another module does. A package whose kernels span several
modules therefore drops its cache files whenever one of its sources changes
(:func:`drop_stale_cache`), before any kernel is compiled or loaded.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

_STAMP = "kernel-sources.sha256"


def drop_stale_cache(folder, also=()):
    """Delete the numba cache files of ``folder`` if its sources, or the files ``also`` that
    its kernels depend on, changed since the cache was made.

    Each set ``also`` has its own stamp, so that two modules of one folder whose kernels
    depend on different files each see their own change (and do not drop each other's cache
    at every import).

    Parameters
    ----------
    folder : path-like
        Package folder; its ``*.py`` files are hashed and its ``__pycache__/*.nbi``,
        ``*.nbc`` files dropped.
    also : sequence of path-like
        Other source files its kernels depend on.

    Returns
    -------
    bool
        True if cache files were dropped (or there was no stamp yet).
    """
    folder = Path(folder)
    digest = hashlib.sha256()
    for path in [*sorted(folder.glob("*.py")), *map(Path, also)]:
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    cache = folder / "__pycache__"
    stamp = cache / _STAMP
    if also:
        names = "\n".join(sorted(Path(a).name for a in also)).encode()
        stamp = cache / f"kernel-sources-{hashlib.sha256(names).hexdigest()[:12]}.sha256"
    try:
        if stamp.exists() and stamp.read_text() == digest.hexdigest():
            return False
        cache.mkdir(exist_ok=True)
        for old in list(cache.glob("*.nbi")) + list(cache.glob("*.nbc")):
            old.unlink()
        stamp.write_text(digest.hexdigest())
    except OSError:  # a read-only installation: numba then compiles in memory
        return False
    return True

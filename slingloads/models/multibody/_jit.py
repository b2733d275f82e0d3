"""The compiler used by the multibody kernels.

The right-hand side of the multibody equations and the fixed-step integrator are compiled with
`numba <https://numba.pydata.org>`_ (``cache=True``: the machine code is kept in the package's
``__pycache__`` after the first call, so only the first run on a machine pays the compilation).
Every kernel is written on scalars and small tuples so that it allocates nothing per evaluation;
the integration kernel allocates its work arrays once per block of runs.

numba invalidates a cached function when its own source file changes, not when a function it
calls from another module does. The kernels span several modules, so the cache files of this
package are dropped whenever any of its sources, the packed layouts
(:mod:`slingloads.models.packed`), the Dormand-Prince pair
(:mod:`slingloads.models.dormand_prince`) or the peak between samples
(:mod:`slingloads.models.sampled_peak`) changes
(:func:`slingloads.models.numba_cache.drop_stale_cache`).
"""

from __future__ import annotations

from pathlib import Path

import numba
import numpy as np

from slingloads.models.numba_cache import drop_stale_cache

_HERE = Path(__file__).resolve().parent

drop_stale_cache(_HERE, also=(_HERE.parent / "packed.py", _HERE.parent / "dormand_prince.py",
                             _HERE.parent / "sampled_peak.py"))

#: Compile a scalar kernel that allocates nothing (cached on disk, releases the GIL so that
#: several threads run it at once). numba's reference counting of arrays is off for it
#: (``_nrt=False``): with it on, every call that hands an array on counts a reference up and
#: down, atomic operations that took about a tenth of the integration's time.
jit = numba.njit(cache=True, fastmath=False, nogil=True, _nrt=False)
#: Compile a kernel that allocates its own work arrays (reference counting on).
jit_alloc = numba.njit(cache=True, fastmath=False, nogil=True)
#: Compile a function to be inlined into its caller at numba's level (no call, no reference
#: counting of the arrays handed on): the right-hand side of the integration loop.
jit_inline = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")

#: What the kernels ask of an array: C-contiguous, writeable and aligned (a read-only or
#: non-contiguous array would compile the kernel, and the equations in it, a second time).
KERNEL_ARRAY_FLAGS = ("C", "W", "A")


def kernel_array(values, snapshot=False):
    """``values`` as the kernels take an array: float64, C-contiguous, writeable, aligned.

    Parameters
    ----------
    values : array_like
        The values. [any unit]
    snapshot : bool, optional
        Always a copy (for arrays kept beside a digest of their values, which the caller's
        later writes must not reach); by default a copy only when ``values`` is not such an
        array already.

    Returns
    -------
    ndarray
        The values. [unit of ``values``]
    """
    if snapshot:
        return np.array(values, dtype=np.float64, order="C", copy=True)
    return np.require(values, np.float64, KERNEL_ARRAY_FLAGS)

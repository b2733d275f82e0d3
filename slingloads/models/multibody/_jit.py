"""The compiler used by the multibody kernels.

The right-hand side of the multibody equations and the fixed-step integrator are compiled with
`numba <https://numba.pydata.org>`_ (``cache=True``: the machine code is kept beside the sources
after the first call, so only the first run on a machine pays the compilation). Every kernel is
written on scalars and small tuples so that it allocates nothing per evaluation.
"""

from __future__ import annotations

import numba

#: Compile a scalar kernel (no Python objects, cached on disk).
jit = numba.njit(cache=True, fastmath=False, nogil=True)

#: Compile a kernel that runs its outer ``prange`` loop on every core.
parallel_jit = numba.njit(cache=True, fastmath=False, nogil=True, parallel=True)

prange = numba.prange

"""One BLAS thread per process for the command line, set before numpy loads.

Importing this module sets ``OPENBLAS_NUM_THREADS`` and its kin (:data:`VARIABLES`) to 1
where the environment does not set them; child processes (helpers, campaign workers on local
processes) inherit them. It has effect only when numpy has not been imported yet, which is
why :mod:`slingloads.cli` imports it first; the Python API leaves the user's threads alone.

Why: the matrices of the analyses are small (at most a few hundred rows), where BLAS threads
bring nothing and spin, and the command's own processes already use the cores. Measured on a
busy 2-core machine: one singular value decomposition of the response-mode identification
(534 x 267) took 1.34 s with the threads and 0.038 s on one.
"""

from __future__ import annotations

import os

#: Thread-count variables of the BLAS libraries numpy and scipy may load.
VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS",
             "VECLIB_MAXIMUM_THREADS")

for _name in VARIABLES:
    os.environ.setdefault(_name, "1")

"""The classical fixed-step Runge-Kutta scheme (RK4) of every compiled batch integrator.

One step, written once, compiled for each model's right-hand side: :func:`rk4_stepper` takes a
compiled right-hand side and returns the compiled step that calls it. The step is inlined into
the model's integration loop at numba's level (``inline="always"``), and so should the
right-hand side be: a call between compiled functions that are not inlined passes every array
by reference count, which cost the lateral sweep half its time again; the machine code of each
pairing is cached on disk. The step is the scheme of [1]_ (section II.1),

.. math::

    x_{n+1} = x_n + \\frac{h}{6} (k_1 + 2 k_2 + 2 k_3 + k_4),

    k_1 = f(x_n, d_0), \\; k_2 = f(x_n + \\tfrac{h}{2} k_1, d_{1/2}), \\;
    k_3 = f(x_n + \\tfrac{h}{2} k_2, d_{1/2}), \\; k_4 = f(x_n + h k_3, d_1),

where ``d`` is the model's drive (the inputs that depend on time: the hook's motion, the gust)
at the step's start, middle and end. The drive is tabulated once per distinct input as an
array ``drive`` of shape (steps, 3, channels): ``drive[i, 0]`` just after the start of step i
(after a jump there), ``drive[i, 1]`` at its middle and ``drive[i, 2]`` just before its end
(before a jump there), so that a step on a jump sees each side of it.

A right-hand side is a compiled function ``rhs(x, drive, i, stage, args, dx)``: it writes the
derivative of state ``x`` (n,) into ``dx`` (n,) with the drive ``drive[i, stage]`` and the
model's own arguments ``args`` (a tuple, passed through untouched) and returns a value of the
model's choice (the cable tension, a flag that a table was left), which the step hands back for
its stages 2 to 4.

Used by the lateral pendulum (:mod:`slingloads.models.pendulum_batch`) and the yaw model
(:mod:`slingloads.models.yaw_batch`); the adaptive integrators use the Dormand-Prince pair
(:mod:`slingloads.models.dormand_prince`).

References
----------
.. [1] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993.
"""

from __future__ import annotations

from pathlib import Path

import numba

from slingloads.models.numba_cache import drop_stale_cache

# The compiled kernels of this package call functions of other modules (this step, the packed
# layouts), which numba's check of a kernel's own source does not see: the package's cache is
# dropped whenever one of its sources changes.
drop_stale_cache(Path(__file__).resolve().parent)

_jit = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")


def rk4_stepper(rhs):
    """The compiled RK4 step of the right-hand side ``rhs``.

    Parameters
    ----------
    rhs : numba dispatcher
        Compiled ``rhs(x, drive, i, stage, args, dx) -> value`` (module notes).

    Returns
    -------
    step : numba dispatcher
        Compiled ``step(x, h, drive, i, args, k1, k2, k3, k4, tmp, out) -> (v2, v3, v4)``:
        one step of ``h`` [s] from state ``x`` (n,) whose derivative at the step's start,
        ``k1`` (n,), the caller has evaluated (it is usually the end of the previous step's
        work); the new state is written into ``out`` (n,; it may be ``x`` itself), ``k2``,
        ``k3``, ``k4``, ``tmp`` (n,) are work arrays, and ``v2``, ``v3``, ``v4`` are what
        ``rhs`` returned at stages 2 to 4.
    """

    @_jit
    def step(x, h, drive, i, args, k1, k2, k3, k4, tmp, out):
        n = x.size
        for m in range(n):
            tmp[m] = x[m] + 0.5 * h * k1[m]
        v2 = rhs(tmp, drive, i, 1, args, k2)
        for m in range(n):
            tmp[m] = x[m] + 0.5 * h * k2[m]
        v3 = rhs(tmp, drive, i, 1, args, k3)
        for m in range(n):
            tmp[m] = x[m] + h * k3[m]
        v4 = rhs(tmp, drive, i, 2, args, k4)
        for m in range(n):
            out[m] = x[m] + (h / 6.0) * (k1[m] + 2.0 * k2[m] + 2.0 * k3[m] + k4[m])
        return v2, v3, v4

    return step

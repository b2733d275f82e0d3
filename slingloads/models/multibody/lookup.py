"""Table lookups for the compiled kernels: linear interpolation that reports, never extrapolates.

Each lookup returns the interpolated value and whether the query lay inside the table. Outside,
the value is the end value (never used: the integrator stops the run at that step and reports
which table it left and when). The tables themselves are the project's
:class:`~slingloads.models.aero_tables.Table1D` / :class:`~slingloads.models.aero_tables.Table2D`;
:func:`table_arrays` hands their breakpoints and values to the kernels.
"""

from __future__ import annotations

import numpy as np

from slingloads.models.multibody._jit import jit, kernel_array

#: Round-off allowance at the ends of a table, relative to its span. [-]
EDGE = 1e-9


@jit
def cell(grid, x):
    """The grid interval holding ``x`` and the weight of its upper end (for several
    lookups at the same point, :func:`bilinear`).

    Parameters
    ----------
    grid : ndarray, shape (n,)
        Increasing breakpoints. [any unit]
    x : float
        Where to look. [unit of ``grid``]

    Returns
    -------
    i : int
        grid[i] <= x <= grid[i + 1]. [-]
    weight : float
        Weight of grid[i + 1]. [-]
    inside : bool
        x lies in the grid (within :data:`EDGE` of its span); False for NaN.
    """
    n = grid.shape[0]
    lo, hi = grid[0], grid[n - 1]
    tol = EDGE * (hi - lo)
    if not (x >= lo - tol and x <= hi + tol):  # also catches NaN
        return 0, 0.0, False
    if x <= lo:
        return 0, 0.0, True
    if x >= hi:
        return n - 2, 1.0, True
    # guess where the point would lie on an evenly spaced grid (right at once for the even
    # sample tables), else bisect the side of the guess that holds it
    i = min(max(int((x - lo) / (hi - lo) * (n - 1)), 0), n - 2)
    if grid[i] <= x <= grid[i + 1]:
        return i, (x - grid[i]) / (grid[i + 1] - grid[i]), True
    a, b = (0, i) if grid[i] > x else (i + 1, n - 1)
    while b - a > 1:
        m = (a + b) // 2
        if grid[m] <= x:
            a = m
        else:
            b = m
    return a, (x - grid[a]) / (grid[a + 1] - grid[a]), True


@jit
def interp1(grid, values, x):
    """Linear interpolation of ``values`` on ``grid`` at ``x``.

    Parameters
    ----------
    grid : ndarray, shape (n,)
        Increasing breakpoints. [any unit]
    values : ndarray, shape (n,)
        Values at the breakpoints. [any unit]
    x : float
        Where to interpolate. [unit of ``grid``]

    Returns
    -------
    value : float
        Interpolated value. [unit of ``values``]
    inside : bool
        x lies in the grid.
    """
    i, w, inside = cell(grid, x)
    return values[i] + w * (values[i + 1] - values[i]), inside


@jit
def bilinear(values, k, i, j, wa, wb):
    """Bilinear interpolation of ``values[k]`` in the cell (i, j) with weights (wa, wb) of
    :func:`cell`.

    Parameters
    ----------
    values : ndarray, shape (n, na, nb)
        Stacked tables. [any unit]
    k, i, j : int
        Table and cell. [-]
    wa, wb : float
        Weights of :func:`cell` along the two axes. [-]

    Returns
    -------
    float
        Interpolated value. [unit of ``values``]
    """
    v00 = values[k, i, j]
    v01 = values[k, i, j + 1]
    v10 = values[k, i + 1, j]
    v11 = values[k, i + 1, j + 1]
    low = v00 + wb * (v01 - v00)
    high = v10 + wb * (v11 - v10)
    return low + wa * (high - low)


def table_arrays(table, names):
    """Breakpoints and stacked coefficient values of a Table1D or Table2D, for the kernels.

    Parameters
    ----------
    table : Table1D or Table2D or None
    names : sequence of str
        Coefficients to stack, in order.

    Returns
    -------
    tuple of ndarray
        ``(angle, values)`` for a Table1D (values shape (n,) for one name), ``(alpha, beta,
        values)`` for a Table2D (values shape (len(names), na, nb)); a flat dummy table when
        ``table`` is None. [rad, -]
    """
    if table is None:
        return np.array([-np.pi, np.pi]), np.zeros(2)
    # copies in the kernels' form (one compiled signature for every table), kept with their
    # digest (slingloads.models.multibody.system): a later write to the table must not reach
    if hasattr(table, "beta"):
        values = np.stack([table.coefficients[n] for n in names])
        return tuple(kernel_array(a, snapshot=True) for a in (table.alpha, table.beta, values))
    return (kernel_array(table.angle, snapshot=True),
            kernel_array(table.coefficients[names[0]], snapshot=True))

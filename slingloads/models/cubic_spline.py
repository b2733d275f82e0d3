"""Natural cubic spline through samples: the carrier's measured hook motion made smooth.

A natural cubic spline is the twice continuously differentiable piecewise cubic through the
samples ``(x_i, y_i)`` whose second derivative vanishes at both ends. It is computed here
with numpy alone, as scipy's ``CubicSpline(x, y, bc_type="natural")`` computes it: the slopes
at the samples solve the same tridiagonal system (by the Thomas algorithm: the matrix is
strictly diagonally dominant, so no pivoting is needed), the pieces have the same
coefficients, and they are evaluated as scipy's ``PPoly`` evaluates them. The results agree
with scipy's to round-off (tested in ``tests/test_cubic_spline.py``). It exists so that a
process that only reads a motion (a helper drawing its figures) does not load scipy's
interpolation package, about a third of a second.
"""

from __future__ import annotations

import numpy as np


class PiecewiseCubic:
    """A piecewise polynomial in scipy's ``PPoly`` layout, evaluated as ``PPoly`` does.

    Parameters
    ----------
    c : ndarray, shape (k, m)
        Coefficients of the m pieces, highest power first: piece i is
        ``sum(c[j, i] * (x - x[i]) ** (k - 1 - j))``. [unit of y / unit of x^power]
    x : ndarray, shape (m + 1,)
        Breakpoints, strictly increasing. [any unit]

    Outside ``[x[0], x[-1]]`` the first and last pieces are extrapolated; at a breakpoint
    the piece that starts there is used (the last piece at ``x[-1]``).
    """

    def __init__(self, c, x):
        self.c = np.asarray(c, dtype=float)
        self.x = np.asarray(x, dtype=float)

    def __call__(self, at):
        """Value at ``at`` (scalar or array; the shape of ``at``)."""
        at = np.asarray(at, dtype=float)
        i = np.clip(np.searchsorted(self.x, at, side="right") - 1, 0, self.c.shape[1] - 1)
        s = at - self.x[i]
        value, power = np.zeros_like(s), np.ones_like(s)
        for row in self.c[::-1]:  # constant term first, powers by repeated products
            value = value + row[i] * power
            power = power * s
        return value

    def derivative(self, nu=1):
        """The ``nu``-th derivative, a :class:`PiecewiseCubic` of lower order.

        Parameters
        ----------
        nu : int
            Order of the derivative, >= 1. [-]

        Returns
        -------
        PiecewiseCubic
            In the units of the values per unit of x to the ``nu``.
        """
        k = self.c.shape[0]
        if nu >= k:
            return PiecewiseCubic(np.zeros((1, self.c.shape[1])), self.x)
        exponents = np.arange(k - 1, nu - 1, -1, dtype=float)  # of the rows kept
        factor = np.ones_like(exponents)
        for j in range(nu):
            factor = factor * (exponents - j)
        return PiecewiseCubic(self.c[: k - nu] * factor[:, None], self.x)


def natural_cubic_spline(x, y):
    """The natural cubic spline through ``(x, y)``.

    Parameters
    ----------
    x : array_like, shape (n,)
        Abscissae, strictly increasing (n >= 2; the caller checks). [any unit]
    y : array_like, shape (n,)
        Values. [any unit]

    Returns
    -------
    PiecewiseCubic
        Its n - 1 pieces (a straight line for two samples).
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    dx = np.diff(x)
    slope = np.diff(y) / dx
    s = _slopes(dx, slope, y)
    t = (s[:-1] + s[1:] - 2.0 * slope) / dx
    c = np.empty((4, dx.size))
    c[0] = t / dx
    c[1] = (slope - s[:-1]) / dx - t
    c[2] = s[:-1]
    c[3] = y[:-1]
    return PiecewiseCubic(c, x)


def _slopes(dx, slope, y):
    """First derivatives at the samples: scipy's tridiagonal system for zero end curvature,
    solved by the Thomas algorithm."""
    n = dx.size + 1
    lower, diag, upper = np.zeros(n), np.empty(n), np.zeros(n)
    rhs = np.empty(n)
    diag[1:-1] = 2.0 * (dx[:-1] + dx[1:])
    upper[1:-1] = dx[:-1]
    lower[1:-1] = dx[1:]
    rhs[1:-1] = 3.0 * (dx[1:] * slope[:-1] + dx[:-1] * slope[1:])
    diag[0], upper[0], rhs[0] = 2.0 * dx[0], dx[0], 3.0 * (y[1] - y[0])
    diag[-1], lower[-1], rhs[-1] = 2.0 * dx[-1], dx[-1], 3.0 * (y[-1] - y[-2])
    a, b, c, d = lower.tolist(), diag.tolist(), upper.tolist(), rhs.tolist()
    for i in range(1, n):  # forward elimination
        w = a[i] / b[i - 1]
        b[i] = b[i] - w * c[i - 1]
        d[i] = d[i] - w * d[i - 1]
    out = [0.0] * n
    out[-1] = d[-1] / b[-1]
    for i in range(n - 2, -1, -1):  # back substitution
        out[i] = (d[i] - c[i] * out[i + 1]) / b[i]
    return np.array(out)

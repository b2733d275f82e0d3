"""Tabulated aerodynamic coefficients: interpolation that never extrapolates silently.

A :class:`Table1D` holds coefficients against one angle (sideslip for a fin, angle of attack
for a parachute); a :class:`Table2D` holds coefficients on a full grid of angle of attack and
sideslip (a fuselage). Both interpolate linearly and raise :class:`InputError` for any query
outside the tabulated range, naming the angle and the range.

The 2-D interpolation is bilinear on the grid cell holding the point (:func:`bilinear`),
written here with numpy: the formula of ``scipy.interpolate.RegularGridInterpolator``'s
linear method, without loading scipy.interpolate (and scipy.spatial) when a workbook is read.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError


def _strictly_increasing(values, name, field=None):
    values = np.asarray(values, dtype=float)
    if values.ndim != 1 or values.size < 2:
        one = values.ndim == 1 and values.size == 1
        raise InputError(f"{name} needs at least two breakpoints (it is never extrapolated)",
                         np.degrees(values).tolist(), field=field if one else None,
                         index=0 if one else None)
    if not np.all(np.isfinite(values)):
        bad = int(np.argmax(~np.isfinite(values)))
        raise InputError(f"{name} breakpoints must be finite numbers", values[bad].item(),
                         field=field, index=bad)
    steps = np.diff(values)
    if np.any(steps <= 0):
        bad = int(np.argmax(steps <= 0))
        raise InputError(
            f"{name} breakpoints must be strictly increasing (no repeats); "
            f"{np.degrees(values[bad + 1]):.6g} deg follows {np.degrees(values[bad]):.6g} deg",
            np.degrees(values[bad + 1]).item(), field=field, index=bad + 1,
        )
    return values


def _check_inside(query, grid, name, what):
    q = np.asarray(query, dtype=float)
    lo, hi = grid[0], grid[-1]
    tol = 1e-9 * max(1.0, abs(hi - lo))
    outside = ~np.isfinite(q) | (q < lo - tol) | (q > hi + tol)
    if np.any(outside):
        bad = np.atleast_1d(q)[np.atleast_1d(outside)][0]
        raise InputError(
            f"{name} = {np.degrees(bad):.6g} deg is outside the {what} table's range "
            f"[{np.degrees(lo):.6g}, {np.degrees(hi):.6g}] deg; no extrapolation is done",
            float(np.degrees(bad)), field=name,
        )
    return np.clip(q, lo, hi)  # only round-off is clipped here


@dataclass(frozen=True)
class Table1D:
    """Coefficients against one angle.

    Parameters
    ----------
    angle : array_like, shape (n,)
        Strictly increasing breakpoints. [rad]
    coefficients : dict of str to array_like, shape (n,)
        One array of dimensionless coefficients per name. [-]
    angle_name : str
        ``"alpha"`` or ``"beta"``, used in messages.
    what : str
        What the table describes, used in messages ("fin", "parachute").
    """

    angle: np.ndarray
    coefficients: dict
    angle_name: str = "beta"
    what: str = "aerodynamic"

    def __post_init__(self):
        angle = _strictly_increasing(self.angle, f"{self.what} {self.angle_name}",
                                     self.angle_name)
        coeffs = {}
        for key, values in self.coefficients.items():
            values = np.asarray(values, dtype=float)
            if values.shape != angle.shape:
                raise InputError(
                    f"{self.what} coefficient {key} needs one finite value per breakpoint",
                    values.tolist())
            if not np.all(np.isfinite(values)):
                bad = int(np.argmax(~np.isfinite(values)))
                raise InputError(
                    f"{self.what} coefficient {key} needs one finite value per breakpoint",
                    values[bad].item(), field=key, index=bad)
            coeffs[key] = values
        object.__setattr__(self, "angle", angle)
        object.__setattr__(self, "coefficients", coeffs)

    def __call__(self, name, angle):
        """Interpolate coefficient ``name`` at ``angle`` [rad]; error outside the table."""
        a = _check_inside(angle, self.angle, self.angle_name, self.what)
        return np.interp(a, self.angle, self.coefficients[name])

    def slope(self, name, lo, hi):
        """Least-squares slope and intercept of a coefficient over an angle range.

        Parameters
        ----------
        name : str
            Coefficient, a key of ``coefficients``.
        lo, hi : float
            Angle range of the fit; the breakpoints inside it are fitted. [rad]

        Returns
        -------
        slope : float
            [1/rad]
        intercept : float
            [-]
        """
        return linear_fit(self.angle, self.coefficients[name], lo, hi, self.what)

    def to_frame(self):
        """The table as a DataFrame, angle in degrees.

        Returns
        -------
        pandas.DataFrame
            A column ``<angle> [deg]`` and one column per coefficient [-].
        """
        frame = pd.DataFrame(self.coefficients)
        frame.insert(0, f"{self.angle_name} [deg]", np.degrees(self.angle))
        return frame


@dataclass(frozen=True)
class Table2D:
    """Coefficients on a full grid of angle of attack and sideslip.

    Parameters
    ----------
    alpha : array_like, shape (na,)
        Strictly increasing angle-of-attack breakpoints. [rad]
    beta : array_like, shape (nb,)
        Strictly increasing sideslip breakpoints. [rad]
    coefficients : dict of str to array_like, shape (na, nb)
        Dimensionless coefficients on the grid. [-]
    what : str
        What the table describes, used in messages.
    """

    alpha: np.ndarray
    beta: np.ndarray
    coefficients: dict
    what: str = "fuselage"

    def __post_init__(self):
        alpha = _strictly_increasing(self.alpha, f"{self.what} alpha")
        beta = _strictly_increasing(self.beta, f"{self.what} beta")
        coeffs = {}
        for key, values in self.coefficients.items():
            values = np.asarray(values, dtype=float)
            if values.shape != (alpha.size, beta.size) or not np.all(np.isfinite(values)):
                raise InputError(
                    f"{self.what} coefficient {key} needs a finite value at every "
                    f"(alpha, beta) grid point ({alpha.size} x {beta.size})",
                )
            coeffs[key] = values
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "beta", beta)
        object.__setattr__(self, "coefficients", coeffs)

    def __call__(self, name, alpha, beta):
        """Interpolate coefficient ``name`` at ``alpha``, ``beta`` [rad] (broadcast)."""
        a = _check_inside(alpha, self.alpha, "alpha", self.what)
        b = _check_inside(beta, self.beta, "beta", self.what)
        a, b = np.broadcast_arrays(a, b)
        return bilinear(self.alpha, self.beta, self.coefficients[name], a, b)

    def beta_slice(self, name, alpha):
        """A coefficient at the sideslip breakpoints, at one angle of attack.

        Parameters
        ----------
        name : str
            Coefficient, a key of ``coefficients``.
        alpha : float
            Angle of attack, inside the table. [rad]

        Returns
        -------
        ndarray, shape (len(beta),)
            The coefficient at each sideslip breakpoint. [-]
        """
        return self(name, np.full(self.beta.shape, alpha), self.beta)

    def slope(self, name, alpha, lo, hi):
        """Least-squares slope against sideslip over a range, at one angle of attack.

        Parameters
        ----------
        name : str
            Coefficient, a key of ``coefficients``.
        alpha : float
            Angle of attack. [rad]
        lo, hi : float
            Sideslip range of the fit; the breakpoints inside it are fitted. [rad]

        Returns
        -------
        slope : float
            [1/rad]
        intercept : float
            [-]
        """
        return linear_fit(self.beta, self.beta_slice(name, alpha), lo, hi, self.what)

    @classmethod
    def from_long(cls, alpha, beta, coefficients, what="fuselage"):
        """Build from long-format columns (one row per grid point, any order).

        Parameters
        ----------
        alpha, beta : array_like, shape (n,)
            Angle of attack and sideslip of each row. [rad]
        coefficients : dict of str to array_like, shape (n,)
            Coefficient columns. [-]
        what : str
            What the table is, for error messages.

        Returns
        -------
        Table2D

        Raises
        ------
        InputError
            If the rows do not form a complete grid or repeat a point.
        """
        alpha = np.asarray(alpha, dtype=float)
        beta = np.asarray(beta, dtype=float)
        a_grid = np.unique(alpha)
        b_grid = np.unique(beta)
        order = np.lexsort((beta, alpha))
        pairs = np.stack([alpha[order], beta[order]], axis=1)
        repeated = np.all(np.diff(pairs, axis=0) == 0, axis=1)
        if np.any(repeated):
            i = order[int(np.argmax(repeated)) + 1]
            raise InputError(
                f"{what} table repeats the grid point alpha = {np.degrees(alpha[i]):.6g} deg, "
                f"beta = {np.degrees(beta[i]):.6g} deg",
            )
        if alpha.size != a_grid.size * b_grid.size:
            raise InputError(
                f"{what} table must be a full grid: {a_grid.size} alpha values x "
                f"{b_grid.size} beta values need {a_grid.size * b_grid.size} rows",
                int(alpha.size),
            )
        shaped = {k: np.asarray(v, dtype=float)[order].reshape(a_grid.size, b_grid.size)
                  for k, v in coefficients.items()}
        return cls(a_grid, b_grid, shaped, what=what)

    def to_frame(self):
        """The table in long format, angles in degrees.

        Returns
        -------
        pandas.DataFrame
            Columns ``alpha [deg]``, ``beta [deg]`` and one per coefficient [-], a row per grid
            point.
        """
        a, b = np.meshgrid(self.alpha, self.beta, indexing="ij")
        frame = pd.DataFrame({"alpha [deg]": np.degrees(a.ravel()),
                              "beta [deg]": np.degrees(b.ravel())})
        for key, values in self.coefficients.items():
            frame[key] = values.ravel()
        return frame


def _cell(grid, q):
    """Index ``i`` of the grid interval ``[grid[i], grid[i + 1]]`` holding each of ``q`` (the
    last interval for the last breakpoint) and the fraction ``t`` of the way across it."""
    i = np.clip(np.searchsorted(grid, q, side="right") - 1, 0, grid.size - 2)
    return i, (q - grid[i]) / (grid[i + 1] - grid[i])


def bilinear(x, y, values, xq, yq):
    """Bilinear interpolation of ``values`` on the grid ``x`` by ``y`` at ``(xq, yq)``.

    In the grid cell holding the point, with ``t`` and ``u`` the fractions of the way across
    it in ``x`` and ``y``: ``v00 (1 - t)(1 - u) + v01 (1 - t) u + v10 t (1 - u) + v11 t u``
    (the formula and order of operations of ``scipy.interpolate.RegularGridInterpolator``'s
    linear method). The points must lie on the grid (:func:`_check_inside`): nothing is
    extrapolated.

    Parameters
    ----------
    x : ndarray, shape (nx,)
        Strictly increasing breakpoints, nx >= 2. [any unit]
    y : ndarray, shape (ny,)
        Strictly increasing breakpoints, ny >= 2. [any unit]
    values : ndarray, shape (nx, ny)
        Values on the grid. [any unit]
    xq, yq : ndarray
        Query points, same shape, inside the grid. [units of ``x``, ``y``]

    Returns
    -------
    ndarray
        Interpolated values, the shape of ``xq``. [unit of ``values``]
    """
    i, t = _cell(x, xq)
    j, u = _cell(y, yq)
    return (values[i, j] * (1 - t) * (1 - u) + values[i, j + 1] * (1 - t) * u
            + values[i + 1, j] * t * (1 - u) + values[i + 1, j + 1] * t * u)


def linear_fit(angle, values, lo, hi, what="aerodynamic"):
    """Least-squares straight line through the table points with ``lo <= angle <= hi``.

    Parameters
    ----------
    angle, values : array_like
        Breakpoints [rad] and coefficient values [-].
    lo, hi : float
        Fitting range. [rad]

    Returns
    -------
    slope : float
        [1/rad]
    intercept : float
        [-]
    """
    angle = np.asarray(angle, dtype=float)
    inside = (angle >= lo - 1e-12) & (angle <= hi + 1e-12)
    if np.count_nonzero(inside) < 2:
        raise InputError(
            f"the {what} table has fewer than two breakpoints in the fitting range "
            f"[{np.degrees(lo):.6g}, {np.degrees(hi):.6g}] deg", field="fit_range",
        )
    slope, intercept = np.polyfit(angle[inside], np.asarray(values)[inside], 1)
    return float(slope), float(intercept)

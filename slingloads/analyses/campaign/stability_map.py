"""Stability maps from the linear model: damping over parachute area x airspeed (x density
altitude), and the minimum stable area at each speed.

At every point of the grid the towed system is trimmed and linearised
(:func:`~slingloads.analyses.multibody.trim`, :func:`~slingloads.analyses.multibody.linearise`)
and the point carries: whether it trims, the largest real part of the eigenvalues (the least
stable eigenvalue: stable when negative), the damping ratio of that eigenvalue, the least
damping ratio of all modes, and the yaw-mode damping ratio of the selection (:mod:`.metrics`).

**Minimum stable area** at one airspeed and altitude: the smallest area factor of the grid
from which every larger grid factor trims with all eigenvalues stable; refined by bisection
between it and the grid factor below (which is unstable or has no trim) to ``tolerance``. The
mass case, cable length and carrier of the map are given (default: the matrix's first of each).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.multibody import linearise, trim
from slingloads.errors import InputError

from .metrics import linear_metrics

#: Bisection tolerance of the minimum stable area factor. [-]
TOLERANCE = 0.005


@dataclass(frozen=True)
class MapSettings:
    """Grid of a stability map.

    Parameters
    ----------
    area_factors : sequence of float, optional
        Area factors of the grid (default: 11 from half the matrix's smallest, since the
        minimum stable area may lie below the matrix, to its largest). [-]
    airspeeds : sequence of float, optional
        Equivalent airspeeds (default: 7 from the matrix's slowest to fastest). [m/s]
    density_altitudes : sequence of float, optional
        (default: the matrix's). [m]
    refine : bool
        Refine the minimum stable area by bisection.
    """

    area_factors: tuple | None = None
    airspeeds: tuple | None = None
    density_altitudes: tuple | None = None
    refine: bool = True

    def __post_init__(self):
        for name in ("area_factors", "airspeeds"):
            values = getattr(self, name)
            if values is None:
                continue
            values = np.atleast_1d(np.asarray(values, float))
            if values.size == 0 or np.any(~np.isfinite(values) | (values <= 0)):
                raise InputError(f"stability map {name.replace('_', ' ')} must be > 0",
                                 values.tolist())
            object.__setattr__(self, name, tuple(np.unique(values)))
        if self.density_altitudes is not None:
            object.__setattr__(self, "density_altitudes",
                               tuple(float(h) for h in self.density_altitudes))


#: Least-damped eigenvalues kept per grid point for the root locus (upper half-plane).
LOCUS_ROOTS = 5


def _point(system):
    point = trim(system)
    model = linearise(point) if point.converged else None
    out = linear_metrics(point, model)
    roots = np.array([], complex)
    if model is not None:
        lam = model.eigenvalues[np.argmax(model.eigenvalues.real)]
        out["least stable eigenvalue damping ratio [-]"] = (
            float(-lam.real / abs(lam)) if abs(lam) > 0 else np.nan)
        upper = model.eigenvalues[model.eigenvalues.imag >= -1e-9]
        roots = upper[np.argsort(-upper.real, kind="stable")][:LOCUS_ROOTS]
    return out, roots


def _is_stable(system):
    point = trim(system)
    return bool(point.converged and linearise(point).verdict() == "stable")


@dataclass(frozen=True, eq=False)
class StabilityMap:
    """A stability map (module notes).

    Attributes
    ----------
    points : pandas.DataFrame
        One row per grid point: area factor, area, airspeed, density altitude and the linear
        metrics.
    loci : pandas.DataFrame
        The :data:`LOCUS_ROOTS` least-damped eigenvalues of every grid point (upper
        half-plane, largest real part first): area factor, airspeed, density altitude, real
        part [1/s], imaginary part [rad/s] (a root locus against the area).
    minimum : pandas.DataFrame
        One row per (density altitude, airspeed): minimum stable area factor on the grid and
        refined, and the area.
    condition : dict
        Mass case, cable length and carrier of the map.
    """

    points: pd.DataFrame
    minimum: pd.DataFrame
    condition: dict
    loci: pd.DataFrame | None = None

    def grid(self, value="largest real part [1/s]", density_altitude=None):
        """One quantity as a table: rows area factor, columns airspeed [m/s].

        Parameters
        ----------
        value : str
            A column of the map's points (units in the label).
        density_altitude : float, optional
            Density altitude of the table (default the first). [m]

        Returns
        -------
        pandas.DataFrame
            Rows area factor [-], columns airspeed EAS [m/s].
        """
        pts = self.points
        if density_altitude is None:
            density_altitude = pts["density altitude [m]"].iloc[0]
        pts = pts[np.isclose(pts["density altitude [m]"], density_altitude)]
        return pts.pivot(index="area factor [-]", columns="airspeed EAS [m/s]", values=value)


def stability_map(setup, neutral_area, settings, row):
    """The map of a campaign (module notes).

    Parameters
    ----------
    setup : CampaignSetup
    neutral_area : float
        [m^2]
    settings : MapSettings
        With every grid given.
    row : dict
        The map's "run" name, "mass case", "mass [kg]", "cable length [m]", "carrier".

    Returns
    -------
    StabilityMap
    """
    rows, roots = [], []
    systems = {}
    for h in settings.density_altitudes:
        for v in settings.airspeeds:
            for f in settings.area_factors:
                r = {**row, "area factor [-]": f, "area [m^2]": f * neutral_area,
                     "airspeed EAS [m/s]": v, "density altitude [m]": h}
                system = setup.system_for(r)
                systems[(h, v, f)] = system
                metrics, lam = _point(system)
                rows.append({"area factor [-]": f, "area [m^2]": f * neutral_area,
                             "airspeed EAS [m/s]": v, "density altitude [m]": h, **metrics})
                roots += [{"area factor [-]": f, "airspeed EAS [m/s]": v,
                           "density altitude [m]": h, "real [1/s]": z.real,
                           "imag [rad/s]": z.imag} for z in lam]
    points = pd.DataFrame(rows)
    stable = ((points["trim converged"].astype(bool)) & (points["linear verdict"] == "stable"))
    points["stable"] = stable
    minimum = []
    factors = np.asarray(settings.area_factors)
    for h in settings.density_altitudes:
        for v in settings.airspeeds:
            sel = (points["density altitude [m]"] == h) & (points["airspeed EAS [m/s]"] == v)
            flags = points.loc[sel].set_index("area factor [-]")["stable"].reindex(factors)
            bad = np.nonzero(~flags.to_numpy(bool))[0]
            grid = (factors[0] if bad.size == 0 else
                    np.nan if bad[-1] == factors.size - 1 else factors[bad[-1] + 1])
            refined, note = grid, ""
            if bad.size == 0:
                note = "stable over the whole grid (the minimum is at or below it)"
            elif not np.isfinite(grid):
                note = "not stable at the largest area of the grid"
            elif settings.refine:
                refined = _bisect(setup, row, neutral_area, v, h, factors[bad[-1]], grid)
            minimum.append({"density altitude [m]": h, "airspeed EAS [m/s]": v,
                            "minimum stable area factor, grid [-]": grid,
                            "minimum stable area factor [-]": refined,
                            "minimum stable area [m^2]": refined * neutral_area,
                            "note": note})
    condition = {k: row[k] for k in ("mass case", "mass [kg]", "cable length [m]", "carrier")}
    loci = pd.DataFrame(roots, columns=["area factor [-]", "airspeed EAS [m/s]",
                                        "density altitude [m]", "real [1/s]", "imag [rad/s]"])
    return StabilityMap(points, pd.DataFrame(minimum), condition, loci)


def _bisect(setup, row, neutral_area, speed, altitude, low, high, tolerance=TOLERANCE):
    """Smallest stable factor in (low, high], low unstable and high stable."""
    while high - low > tolerance:
        mid = 0.5 * (low + high)
        r = {**row, "area factor [-]": mid, "area [m^2]": mid * neutral_area,
             "airspeed EAS [m/s]": speed, "density altitude [m]": altitude}
        if _is_stable(setup.system_for(r)):
            high = mid
        else:
            low = mid
    return high

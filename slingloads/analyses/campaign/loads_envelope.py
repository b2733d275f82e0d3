"""From the dynamics to the structural loads (paper section 6): the extremes the campaign's runs
reach with the chosen parachute, with a margin.

The runs are those of the chosen area factor (all conditions and manoeuvres whose condition
trims). Over them, the extremes of

* the angle of attack and sideslip of the fuselage (the loads' aerodynamic envelope);
* the parachute line angles theta (up) and psi (right) in body axes, and the line tension
  (the parachute load directions and drag);
* the angle of the hub load from the mast axis, and from the hanging vertical (hub above CG,
  about which the loads take their CS-29.865 cone) in total, sideways and fore-and-aft (the
  hook cone);
* the cable tension over the weight (against the hook load factor Nz).

**Margin** k >= 1 (default :data:`MARGIN`): every angle bound b becomes k b, and the angle of
attack, sideslip and line-angle ranges are widened to include zero (the level, head-on point);
the hub-load angles, the line tension and the tension factor are multiplied by k. Each extreme
keeps the run that reached it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError

#: Default margin on the extremes the dynamics reach. [-]
MARGIN = 1.25

#: (quantity, metric of the lower bound or None, metric of the upper bound, kind).
QUANTITIES = (
    ("alpha", "alpha min [deg]", "alpha max [deg]", "angle range"),
    ("beta", "beta min [deg]", "beta max [deg]", "angle range"),
    ("line theta", "line theta min [deg]", "line theta max [deg]", "angle range"),
    ("line psi", "line psi min [deg]", "line psi max [deg]", "angle range"),
    ("hub load from mast", None, "hub load from mast max [deg]", "angle"),
    ("hub load from vertical", None, "hub load from hanging vertical max [deg]", "angle"),
    ("hub load lateral", None, "hub load lateral max [deg]", "angle"),
    ("hub load longitudinal", "hub load longitudinal min [deg]",
     "hub load longitudinal max [deg]", "angle"),
    ("line tension", None, "line tension max [N]", "force"),
    ("tension / weight", None, "tension / weight max [-]", "factor"),
)


def _check_margin(margin):
    k = float(margin)
    if not np.isfinite(k) or k < 1:
        raise InputError("the margin on the dynamics' extremes must be >= 1", margin)
    return k


@dataclass(frozen=True, eq=False)
class DynamicsEnvelope:
    """Extremes of the chosen parachute's runs, with the margin (module notes).

    Attributes
    ----------
    area_factor : float
        [-]
    area : float
        [m^2]
    margin : float
        [-]
    reached : dict
        Quantity -> (lower, upper) as reached (angles in degrees; None where not used).
    source : dict
        Quantity -> (run of the lower bound, run of the upper bound).
    runs : int
        Runs the extremes are taken over. [count]
    unstable_runs : int
        Of them, runs that are not stable (their extremes are included). [count]
    """

    area_factor: float
    area: float
    margin: float
    reached: dict
    source: dict
    runs: int
    unstable_runs: int
    line_coefficient: float = float("nan")

    def chute_drag_at(self, q, area):
        """Parachute line load with the margin at dynamic pressure ``q`` [Pa] and area
        ``area`` [m^2]: margin x the largest line tension over q_EAS x area among the runs
        (:attr:`line_coefficient`) x q x area, so that a load taken at the loads' airspeed is
        never the lower one of the campaign's airspeeds. [N]

        Parameters
        ----------
        q : float
            Dynamic pressure. [Pa]
        area : float
            Parachute area. [m^2]

        Returns
        -------
        float
            Line load. [N]
        """
        return self.margin * self.line_coefficient * float(q) * float(area)

    def mirrored(self, quantity):
        """(lower, upper) of an angle range with the margin, made symmetric about zero
        (-m, m), m the larger magnitude: a set of gusts from one side only says nothing of
        the other, and the aircraft is taken as symmetric. Degrees.

        Parameters
        ----------
        quantity : str
            A quantity of :data:`QUANTITIES` (``alpha``, ``beta``, ``line theta``, ...).

        Returns
        -------
        (float, float)
            (-m, m). [deg]
        """
        lo, hi = self.bounds(quantity)
        m = max(abs(lo), abs(hi))
        return -m, m

    def bounds(self, quantity):
        """(lower, upper) of a quantity with the margin (module notes); degrees for angles.

        Parameters
        ----------
        quantity : str
            A quantity of :data:`QUANTITIES` (``alpha``, ``beta``, ``line theta``, ...).

        Returns
        -------
        (float, float)
            Lower and upper bound (lower None for a quantity with a maximum only): degrees
            for angles, N for the line tension, - for tension / weight. [deg], [N] or [-]
        """
        kind = {q[0]: q[3] for q in QUANTITIES}[quantity]
        lo, hi = self.reached[quantity]
        k = self.margin
        if kind == "angle range":
            return min(0.0, k * lo), max(0.0, k * hi)
        if lo is None:
            return None, k * hi
        return k * lo, k * hi

    def aero_envelope(self):
        """Corners and centre of the alpha-beta envelope with the margin: (ids, alpha, beta)
        [rad], ids ``DYN-CENTRE``, ``DYN-A+B+``....

        Returns
        -------
        ids : tuple of str
        alpha, beta : ndarray, shape (5,)
            [rad]
        """
        (a0, a1), (b0, b1) = (np.radians(self.bounds(q)) for q in ("alpha", "beta"))
        ids = ("DYN-CENTRE", "DYN-A+B+", "DYN-A+B-", "DYN-A-B+", "DYN-A-B-")
        return (ids, np.array([0.0, a1, a1, a0, a0]), np.array([0.0, b1, b0, b1, b0]))

    def line_directions(self):
        """Parachute line directions with the margin: the trailing direction and the four
        corners of the (theta, psi) range, as (ids, theta, psi) [rad].

        Returns
        -------
        ids : tuple of str
        theta, psi : ndarray, shape (5,)
            [rad]
        """
        (t0, t1), (p0, p1) = (np.radians(self.bounds(q)) for q in ("line theta", "line psi"))
        ids = ("LINE-AFT", "LINE-T+P+", "LINE-T+P-", "LINE-T-P+", "LINE-T-P-")
        return ids, np.array([0.0, t1, t1, t0, t0]), np.array([0.0, p1, p0, p1, p0])

    @property
    def chute_drag(self):
        """Largest parachute line tension with the margin. [N]"""
        return self.bounds("line tension")[1]

    @property
    def tension_factor(self):
        """Largest cable tension over weight with the margin. [-]"""
        return self.bounds("tension / weight")[1]

    @property
    def hook_angle(self):
        """Largest hub-load angle from the hanging vertical with the margin. [rad]"""
        return float(np.radians(self.bounds("hub load from vertical")[1]))

    @property
    def lateral_hook_angle(self):
        """Largest sideways hub-load angle with the margin. [rad]"""
        return float(np.radians(self.bounds("hub load lateral")[1]))

    @property
    def longitudinal_hook_angle(self):
        """Largest fore-and-aft hub-load angle (either way) with the margin. [rad]"""
        lo, hi = self.bounds("hub load longitudinal")
        return float(np.radians(max(abs(lo), abs(hi))))

    def to_frame(self):
        """One row per quantity: as reached, with the margin, unit, and the runs.

        Returns
        -------
        pandas.DataFrame
            Quantity, reached lower and upper, with the margin, unit (deg or N), the runs that
            reached them, and a note giving the rule that made the bounds with the margin
            (module notes).
        """
        k = self.margin
        rules = {"angle range": f"x {k:g}, the range widened to include 0 (level, head-on)",
                 "angle": f"x {k:g}", "force": f"x {k:g}", "factor": f"x {k:g}"}
        rows = []
        for quantity, _, upper, kind in QUANTITIES:
            unit = upper.rsplit("[", 1)[1].rstrip("]")
            lo, hi = self.reached[quantity]
            mlo, mhi = self.bounds(quantity)
            src = self.source[quantity]
            rows.append({"quantity": quantity, "unit": unit,
                         "reached min": np.nan if lo is None else lo, "reached max": hi,
                         "with margin min": np.nan if mlo is None else mlo,
                         "with margin max": mhi,
                         "run of min": src[0] or "", "run of max": src[1],
                         "note": rules[kind]})
        return pd.DataFrame(rows)


def dynamics_envelope(metrics, area_factor, margin=MARGIN):
    """The extremes of the runs at ``area_factor`` (module notes).

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics.
    area_factor : float
        The chosen parachute's area factor. [-]
    margin : float
        >= 1. [-]

    Returns
    -------
    DynamicsEnvelope

    Raises
    ------
    InputError
        When no run of that area trims.
    """
    from .selection import stable_runs

    k = _check_margin(margin)
    factor = float(area_factor)
    runs = metrics[np.isclose(metrics["area factor [-]"], factor)
                   & metrics["trim converged"].astype(bool)]
    if len(runs) == 0:
        raise InputError("no run of the chosen parachute area trims: the dynamics give no "
                         "envelope for the loads", factor)
    reached, source = {}, {}
    for quantity, lower, upper, _ in QUANTITIES:
        hi_values = pd.to_numeric(runs[upper], errors="coerce")
        if not np.any(np.isfinite(hi_values)):
            raise InputError(f"the runs of the chosen parachute give no {quantity}", factor)
        i_hi = hi_values.idxmax()
        lo, i_lo = None, None
        if lower is not None:
            lo_values = pd.to_numeric(runs[lower], errors="coerce")
            i_lo = lo_values.idxmin()
            lo = float(lo_values[i_lo])
        reached[quantity] = (lo, float(hi_values[i_hi]))
        source[quantity] = (None if i_lo is None else runs.loc[i_lo, "run"],
                            runs.loc[i_hi, "run"])
    from slingloads.models.atmosphere import dynamic_pressure_eas as dynamic_pressure

    q = dynamic_pressure(pd.to_numeric(runs["airspeed EAS [m/s]"]).to_numpy(float))
    per = (pd.to_numeric(runs["line tension max [N]"], errors="coerce").to_numpy(float)
           / (q * pd.to_numeric(runs["area [m^2]"]).to_numpy(float)))
    coefficient = float(np.nanmax(per)) if np.any(np.isfinite(per)) else float("nan")
    return DynamicsEnvelope(factor, float(runs["area [m^2]"].iloc[0]), k, reached, source,
                            len(runs), int((~stable_runs(runs)).sum()), coefficient)

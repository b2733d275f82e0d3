"""Parachute selection from the campaign's metrics (paper section 4.5).

**Stable run**: its condition trims, every eigenvalue of the condition's linear model has a
real part below -1e-6 1/s (linear verdict "stable"), and its response converges (response
verdict "convergent", or "bounded" under a sustained input, :mod:`slingloads.analyses.
verdicts`). A run whose response is a "static departure", a "limit cycle", "divergent",
"outside domain", "inconclusive" or that has no trim is not stable.

**Damping criterion** (:class:`SelectionCriteria`): a stable run whose yaw modes (the modes
in which the yaw takes part, :mod:`.metrics`) have a damping ratio of at least ``min_damping``
and a time to half amplitude of at most ``max_half_time``. Defaults 0.05 and 20 s. At long
cables and high speed the yaw couples with the cable's lateral swing, and that mode's damping
ratio is a pendulum's, a few hundredths, whatever the area; 0.05 asks that a yaw oscillation
lose a quarter of its amplitude every cycle (amplitude ratio per cycle
exp(-2 pi zeta / sqrt(1 - zeta^2)) = 0.73), between the Dutch-roll minima of the fixed-wing
flying-qualities specification MIL-F-8785C (Table VI: 0.02 at Level 2, 0.08 at Level 1 in
cruise). The half-time limit asks that a disturbance halve within 20 s (below 1/8 of itself by
the end of a 60 s run); it excludes the slow aperiodic yaw roots of an area just above the
stability boundary (damping ratio 1, hardly decaying). The carried helicopter is an unmanned
external load, so no flying-qualities level applies: both are engineering choices, inputs to
be set to the operation's own requirement.

**Smallest stable area**: the smallest area factor of the matrix at which every run of every
condition is stable. Its **governing condition** is the one that needs the most area: for each
condition (airspeed, mass, density altitude, cable, carrier) the smallest area from which all
its runs (all manoeuvres) are stable is found; the condition with the largest such area governs
(ties: the least yaw damping at the selected area), with the manoeuvre that failed at the next
smaller area.

**Recommended area**: among the areas whose every run meets the damping criterion, the one of
least drag, measured by the paper's drag proxy, the trimmed swing angle of the cable from the
vertical, taken at its largest over the conditions (the highest dynamic pressure). Its
governing condition is the one of least yaw damping at that area.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.verdicts import ACCEPTED
from slingloads.errors import InputError

from .matrix import CONDITION_COLUMNS

#: Response verdicts that count as stable.
STABLE_RESPONSES = ACCEPTED
#: Default minimum yaw-mode damping ratio of the recommended area. [-]
MIN_DAMPING = 0.05
#: Default longest yaw-mode time to half amplitude of the recommended area. [s]
MAX_HALF_TIME = 20.0


@dataclass(frozen=True)
class SelectionCriteria:
    """How the parachute is chosen (module notes).

    Parameters
    ----------
    min_damping : float
        Least yaw-mode damping ratio (eigenvalues) of every run of the recommended area,
        0 <= value < 1. [-]
    max_half_time : float
        Longest yaw-mode time to half amplitude of every run of the recommended area, > 0
        (inf: no limit). [s]
    """

    min_damping: float = MIN_DAMPING
    max_half_time: float = MAX_HALF_TIME

    def __post_init__(self):
        value = float(self.min_damping)
        if not np.isfinite(value) or not 0 <= value < 1:
            raise InputError("the damping criterion (least yaw-mode damping ratio) must lie in "
                             "[0, 1)", self.min_damping)
        half = float(self.max_half_time)
        if np.isnan(half) or half <= 0:
            raise InputError("the damping criterion's longest time to half amplitude must be "
                             "> 0 [s]", self.max_half_time)
        object.__setattr__(self, "min_damping", value)
        object.__setattr__(self, "max_half_time", half)


def stable_runs(metrics):
    """Boolean Series: each run is stable (module notes).

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics, one row per run (units in the column labels).

    Returns
    -------
    pandas.Series of bool
    """
    return (metrics["trim converged"].astype(bool)
            & (metrics["linear verdict"] == "stable")
            & metrics["response verdict"].isin(STABLE_RESPONSES))


def damped_runs(metrics, criteria):
    """Boolean Series: each run is stable and meets the damping criterion.

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics, one row per run (units in the column labels).
    criteria : SelectionCriteria
        Least damping ratio [-] and longest time to half amplitude [s] of the yaw mode.

    Returns
    -------
    pandas.Series of bool
    """
    zeta = pd.to_numeric(metrics["yaw mode damping ratio [-]"], errors="coerce")
    half = pd.to_numeric(metrics["yaw mode time to half amplitude [s]"], errors="coerce")
    return (stable_runs(metrics) & (zeta >= criteria.min_damping)
            & (half <= criteria.max_half_time))


def condition_text(row):
    """A campaign condition in words, the one spelling every report uses: airspeed in KEAS,
    density altitude and cable length in SI (m; a US report quotes them in ft and in, as
    every altitude and length of it: :func:`slingloads.io.common.units.report_text`), mass
    case and carrier.

    Parameters
    ----------
    row : mapping
        With ``airspeed EAS [m/s]``, ``mass case``, ``density altitude [m]``, ``cable length
        [m]`` and ``carrier``.

    Returns
    -------
    str
    """
    from slingloads.constants import KNOT

    return (f"{row['airspeed EAS [m/s]'] / KNOT:.0f} KEAS, mass case {row['mass case']}, "
            f"density altitude {row['density altitude [m]']:.0f} m, cable "
            f"{row['cable length [m]']:.5g} m, carrier {row['carrier']}")


@dataclass(frozen=True, eq=False)
class Selection:
    """The chosen parachute and why (module notes).

    Attributes
    ----------
    criteria : SelectionCriteria
    by_area : pandas.DataFrame
        One row per area factor: runs, stable runs, stable runs meeting the damping
        criterion (a run must be stable to count), least
        yaw damping, largest trimmed swing angle, verdicts.
    smallest_stable : float
        Area factor (NaN when no area is stable everywhere). [-]
    recommended : float
        Area factor (NaN when no area meets the criterion everywhere). [-]
    governing_stable, governing_recommended : dict or None
        The governing condition's factors, its text and the deciding manoeuvre or value.
    neutral_area : float
        [m^2]
    neutral_condition : str
        Where the neutral area is read (the towed trim's angle of attack, or alpha 0 and why).
    """

    criteria: SelectionCriteria
    by_area: pd.DataFrame
    smallest_stable: float
    recommended: float
    governing_stable: dict | None
    governing_recommended: dict | None
    neutral_area: float
    neutral_condition: str = ""

    @property
    def smallest_stable_area(self):
        """[m^2]"""
        return self.smallest_stable * self.neutral_area

    @property
    def recommended_area(self):
        """[m^2]"""
        return self.recommended * self.neutral_area


def _per_area(metrics, criteria):
    m = metrics.assign(_stable=stable_runs(metrics), _damped=damped_runs(metrics, criteria))
    m["_zeta"] = pd.to_numeric(m["yaw mode damping ratio [-]"], errors="coerce")
    m["_swing"] = pd.to_numeric(m["swing angle trim [deg]"], errors="coerce")
    g = m.groupby("area factor [-]", sort=True)
    frame = pd.DataFrame({
        "area [m^2]": g["area [m^2]"].first(),
        "runs": g.size(),
        "stable runs": g["_stable"].sum().astype(int),
        "stable runs meeting the damping criterion": g["_damped"].sum().astype(int),
        "least yaw-mode damping ratio [-]": g["_zeta"].min(),
        "longest yaw-mode time to half amplitude [s]": g[
            "yaw mode time to half amplitude [s]"].apply(
            lambda v: pd.to_numeric(v, errors="coerce").max()),
        "largest trimmed swing angle [deg]": g["_swing"].max(),
        "largest peak yaw change [deg]": g["yaw change [deg]"].apply(
            lambda v: np.nanmax(np.abs(pd.to_numeric(v, errors="coerce")))
            if np.any(np.isfinite(pd.to_numeric(v, errors="coerce"))) else np.nan),
        "no trim": g["trim converged"].apply(lambda v: int((~v.astype(bool)).sum())),
    })
    frame["stable in every condition"] = frame["stable runs"] == frame["runs"]
    frame["stable and meets the damping criterion everywhere"] = (
        frame["stable runs meeting the damping criterion"] == frame["runs"])
    return frame.reset_index(), m


def _smallest_from(flags):
    """Per condition: the smallest area factor from which every larger one is stable."""
    areas = flags.index.to_numpy()
    ok = flags.to_numpy()
    bad = np.nonzero(~ok)[0]
    if bad.size == 0:
        return areas[0]
    if bad[-1] == areas.size - 1:
        return np.inf
    return areas[bad[-1] + 1]


def _governing_stable(m, chosen):
    cond = list(CONDITION_COLUMNS)
    per = m.groupby(cond + ["area factor [-]"], sort=True)["_stable"].all()
    need = per.groupby(level=list(range(len(cond)))).apply(
        lambda s: _smallest_from(s.droplevel(list(range(len(cond))))))
    worst = need.max()
    candidates = need[need == worst].index
    at = m[m["area factor [-]"] == chosen] if np.isfinite(chosen) else m
    zeta = at.groupby(cond)["_zeta"].min()
    order = sorted(candidates, key=lambda c: (np.nan_to_num(zeta.get(c, np.inf), nan=-1.0)))
    key = order[0]
    row = dict(zip(cond, key, strict=True))
    rows = m[np.logical_and.reduce([m[c] == v for c, v in row.items()])]
    areas = np.sort(rows["area factor [-]"].unique())
    failing = areas[areas < worst] if np.isfinite(worst) else areas
    deciding = ""
    if failing.size:
        last = rows[(rows["area factor [-]"] == failing[-1]) & ~rows["_stable"]]
        deciding = ", ".join(f"{r['manoeuvre']} ({_why(r)})" for _, r in last.iterrows())
    return {**row, "condition": condition_text(row),
            "needs area factor [-]": float(worst), "fails below with": deciding}


def _why(r):
    if not bool(r["trim converged"]):
        return "no trim"
    if r["linear verdict"] != "stable":
        return f"eigenvalues {r['linear verdict']}"
    return f"response {r['response verdict']}"


def _governing_recommended(m, chosen):
    cond = list(CONDITION_COLUMNS)
    at = m[m["area factor [-]"] == chosen]
    k = at["_zeta"].idxmin()
    row = {c: at.loc[k, c] for c in cond}
    swing = at.loc[at["_swing"].idxmax()]
    return {**row, "condition": condition_text(row),
            "least yaw-mode damping ratio [-]": float(at.loc[k, "_zeta"]),
            "with manoeuvre": at.loc[k, "manoeuvre"],
            "largest swing condition": condition_text(swing),
            "largest trimmed swing angle [deg]": float(swing["_swing"])}


def select_parachute(metrics, criteria=None, neutral_area=1.0, neutral_condition=""):
    """Smallest stable and recommended parachute areas (module notes).

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics (matrix columns and per-run metrics).
    criteria : SelectionCriteria, optional
    neutral_area : float
        [m^2]
    neutral_condition : str
        Where the neutral area is read (:attr:`Campaign.neutral_condition`).

    Returns
    -------
    Selection
    """
    criteria = SelectionCriteria() if criteria is None else criteria
    if len(metrics) == 0:
        raise InputError("no run to select a parachute from")
    by_area, m = _per_area(metrics, criteria)
    stable = by_area[by_area["stable in every condition"]]
    smallest = float(stable["area factor [-]"].min()) if len(stable) else np.nan
    damped = by_area[by_area["stable and meets the damping criterion everywhere"]]
    recommended = np.nan
    if len(damped):
        recommended = float(damped.sort_values(
            ["largest trimmed swing angle [deg]", "area factor [-]"]).iloc[0]["area factor [-]"])
    governing = _governing_stable(m, smallest)
    return Selection(criteria, by_area, smallest, recommended, governing,
                     _governing_recommended(m, recommended) if np.isfinite(recommended)
                     else None, float(neutral_area), str(neutral_condition))

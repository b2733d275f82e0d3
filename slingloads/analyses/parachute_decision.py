"""One parachute decision: the neutral area, the verdict of each model, the chosen area and why.

The parachute is sized by two models (paper sections 4.1 to 4.5): the 1-DOF yaw model
(:mod:`slingloads.analyses.chute_sizing`: the neutral static area, then a sweep of areas under
every gust shape) and the multibody model over the campaign's matrix
(:mod:`slingloads.analyses.campaign`). :func:`decide` combines whatever of the two was run
into one :class:`ParachuteDecision`, which every report that mentions the parachute carries
as the same table (:meth:`ParachuteDecision.to_frame`).

**Rules.**

* Neutral area: computed on the least-squares slopes over the linearisation range and on the
  local slopes at zero sideslip; the one used is named (by default the larger).
* Each model proposes the smallest area that meets its own criterion: the 1-DOF sweep, every
  gust convergent (bounded under a gust that never ends); the campaign, every run of every
  condition stable and meeting the damping criterion (its recommended area).
* **Chosen area**: the larger of the two proposals, since the parachute must meet both
  criteria; the model that proposed it **decides**, and the reason says why. Where the
  multibody model asks for more than the 1-DOF model, that is the inter-axis coupling the
  1-DOF model lacks (paper 4.5). A model that was run and found no area meeting its criterion
  leaves **no chosen area** (a finding, stated with its reason), whatever the other found.
* The chosen area's verdicts are given for every gust shape of the 1-DOF model and over the
  campaign (its runs at that area), with the **governing condition**: the one that needs the
  most area (the campaign's) or the gust that fails just below it (the 1-DOF's).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from slingloads.analyses.verdicts import ACCEPTED, ratio_words, worst

MULTIBODY = "multibody campaign"
ONE_DOF = "1-DOF sizing"


@dataclass(frozen=True)
class ParachuteDecision:
    """The parachute decision (module notes). Areas in m^2, NaN where not known.

    Attributes
    ----------
    neutral_area_fit, neutral_area_local, neutral_area : float
        Neutral static area on the fitted slopes, on the local slopes, and the one used.
        [m^2]
    neutral_basis : str
        Which one is used, in words.
    one_dof_area : float
        Smallest swept area at which every gust is convergent (NaN: none, or not run). [m^2]
    one_dof_ran : bool
    one_dof_verdicts : dict
        Gust shape -> 1-DOF verdict at the chosen area.
    multibody_area : float
        The campaign's recommended area (NaN: none, or not run). [m^2]
    multibody_ran : bool
    multibody_verdict : str
        Verdict over the campaign's runs at the chosen area.
    chosen_area : float
        [m^2]
    deciding_model : str
    reason : str
    governing : str
        The condition that governs the chosen area.
    study_area : float
        The Study's 'parachute area' (the loads' parachute). [m^2]
    yaw_axis : str
        The axis of the 1-DOF model's moments, inertia and weight, in words.
    multibody_at_one_dof : str
        Verdict over the campaign's runs at the 1-DOF proposal (the campaign runs it when
        the sizing runs too).
    damping : str
        The yaw damping ratios of both models at the chosen area (the 1-DOF proposal when no
        area is chosen) and the 1-DOF model's airspeed, compared within
        :data:`DAMPING_TOLERANCE`, or why not.
    """

    neutral_area_fit: float
    neutral_area_local: float
    neutral_area: float
    neutral_basis: str
    one_dof_area: float = math.nan
    one_dof_ran: bool = False
    one_dof_verdicts: dict = field(default_factory=dict)
    multibody_area: float = math.nan
    multibody_ran: bool = False
    multibody_verdict: str = "not run"
    chosen_area: float = math.nan
    deciding_model: str = ""
    reason: str = ""
    governing: str = ""
    study_area: float = math.nan
    yaw_axis: str = ""
    multibody_at_one_dof: str = "not run"
    damping: str = ""

    @property
    def found(self):
        """True when an area meets every criterion that was run."""
        return bool(np.isfinite(self.chosen_area))

    def study_area_verdict(self):
        """Whether the Study's parachute is at least the chosen one, in words.

        Returns
        -------
        str
            With the Study's area over the chosen one [-].
        """
        if not np.isfinite(self.study_area) or self.study_area <= 0:
            return "no Study parachute"
        if not self.found:
            return "no area meets the criteria: the Study parachute is not shown adequate"
        if self.study_area >= self.chosen_area * (1 - 1e-9):
            return f"at least the chosen area ({self.study_area / self.chosen_area:.3g} x)"
        return (f"SMALLER than the chosen area ({self.study_area / self.chosen_area:.3g} x): "
                "not shown adequate")

    def to_frame(self):
        """The decision as one table, the same in every report.

        Returns
        -------
        pandas.DataFrame
            Columns item, value, unit (areas in m^2), note.
        """
        one = ("; ".join(f"{g}: {v}" for g, v in self.one_dof_verdicts.items())
               if self.one_dof_verdicts else ("not run" if not self.one_dof_ran else
                                              NO_AREA if not self.found else "-"))
        rows = [
            ("neutral area, least-squares slopes", self.neutral_area_fit, "m^2", ""),
            ("neutral area, local slopes at beta 0", self.neutral_area_local, "m^2", ""),
            ("neutral area used", self.neutral_area, "m^2", self.neutral_basis),
            ("1-DOF yaw axis", self.yaw_axis or "-", "",
             "yawing moments, yaw inertia and weight all about it"),
            ("1-DOF: smallest area stable under every gust", self.one_dof_area, "m^2",
             "not run" if not self.one_dof_ran else
             ("none in the sweep" if not np.isfinite(self.one_dof_area) else "")),
            ("multibody: recommended area over the campaign", self.multibody_area, "m^2",
             "not run" if not self.multibody_ran else
             ("no area meets the criterion" if not np.isfinite(self.multibody_area) else "")),
            ("chosen area", self.chosen_area, "m^2",
             (f"{self.chosen_area / self.neutral_area:.3g} x neutral" if self.found
              else "NONE: no area meets every criterion run")),
            ("deciding model", self.deciding_model or "-", "", self.reason),
            ("governing condition", self.governing or "-", "", ""),
            ("1-DOF verdict at the chosen area, per gust", one, "", ""),
            ("multibody verdict at the chosen area", self.multibody_verdict, "", ""),
            ("multibody verdict at the 1-DOF area", self.multibody_at_one_dof, "",
             "the campaign's runs at the 1-DOF proposal"),
            ("yaw damping ratio, 1-DOF against multibody", self.damping or "-", "", ""),
            ("Study 'parachute area' (loads)", self.study_area, "m^2",
             self.study_area_verdict()),
        ]
        return pd.DataFrame(rows, columns=["item", "value", "unit", "note"])


def one_dof_proposal(sweep):
    """The 1-DOF model's proposal.

    Parameters
    ----------
    sweep : SweepResult
        The 1-DOF sweep (:class:`~slingloads.analyses.chute_sizing.SweepResult`).

    Returns
    -------
    tuple of (float, str)
        The smallest swept area stable under every gust (NaN: none) [m^2], and what governs
        it (the gusts failing at the next smaller area).
    """
    table = sweep.by_area()
    area = sweep.smallest_stable_area
    runs = sweep.to_frame()
    below = table[table["area [m^2]"] < area] if np.isfinite(area) else table
    if len(below) == 0:
        return area, "every swept area is stable (the smallest swept area governs)"
    last = float(below["area [m^2]"].max())
    failing = runs[np.isclose(runs["area [m^2]"], last) & ~runs["verdict"].isin(ACCEPTED)]
    what = ", ".join(f"{g} gust ({v})" for g, v in zip(failing["gust"], failing["verdict"],
                                                        strict=True))
    at = "" if np.isfinite(area) else " (and every larger swept area)"
    return area, f"1-DOF at {last:.6g} m^2{at}: {what}"


def multibody_verdict_at(metrics, area, stable):
    """Verdict over the campaign's runs at one parachute area.

    Parameters
    ----------
    metrics : pandas.DataFrame or None
        The campaign's metrics (columns ``area [m^2]``, ``response verdict``).
    area : float
        The area. [m^2]
    stable : ndarray of bool
        Each run's stable flag (the selection's rule).

    Returns
    -------
    str
        "stable in all N runs", how many are not and the worst response, "not run"
        (no campaign), or :data:`NO_AREA` (no area to judge).
    """
    if metrics is None:
        return "not run"
    if not np.isfinite(area):
        return NO_AREA
    at = np.isclose(metrics["area [m^2]"].to_numpy(float), area, rtol=1e-6)
    if not at.any():
        return "not run at this area"
    ok = int(np.count_nonzero(stable[at]))
    total = int(np.count_nonzero(at))
    if ok == total:
        return f"stable in all {total} runs" if total > 1 else "stable in its 1 run"
    verdicts = metrics.loc[at, "response verdict"].astype(str)
    return (f"NOT stable in every run: {total - ok} of {total} not shown stable "
            f"(worst response: {worst(list(verdicts))})")


#: The verdict at an area that is not there (no area chosen, or none proposed): the
#: analysis ran, it has nothing to judge (never "not run").
NO_AREA = "none: no area to judge (none chosen or proposed)"

#: Largest difference between the 1-DOF and the multibody yaw damping ratios at one area and
#: airspeed read as agreement. [-]
DAMPING_TOLERANCE = 0.05


def damping_comparison(runs, metrics, area, airspeed):
    """The 1-DOF and multibody yaw damping ratios at one parachute area and airspeed, side
    by side, within :data:`DAMPING_TOLERANCE` or with why they differ.

    Parameters
    ----------
    runs : pandas.DataFrame or None
        The 1-DOF runs at ``area`` (column ``damping ratio linear [-]``: its linear yaw mode,
        local slopes).
    metrics : pandas.DataFrame or None
        The campaign's metrics (``area [m^2]``, ``airspeed EAS [m/s]``,
        ``yaw mode damping ratio [-]``, ``yaw mode``).
    area : float
        [m^2]
    airspeed : float
        The 1-DOF model's equivalent airspeed. [m/s]

    Returns
    -------
    str
    """
    from slingloads.constants import KNOT

    if runs is None or not np.isfinite(area) or "damping ratio linear [-]" not in runs:
        return "no 1-DOF run at the chosen area"
    z1 = float(np.nanmin(runs["damping ratio linear [-]"].to_numpy(float)))
    where = f"{area:.6g} m^2, {airspeed / KNOT:.0f} KEAS"
    one = f"1-DOF {ratio_words(z1)} (its yaw mode, hub fixed)"
    if metrics is None or "yaw mode damping ratio [-]" not in metrics:
        return f"at {where}: {one}; no campaign run to compare"
    at = (np.isclose(metrics["area [m^2]"].to_numpy(float), area, rtol=1e-6)
          & np.isclose(metrics["airspeed EAS [m/s]"].to_numpy(float), airspeed, rtol=1e-6))
    zetas = metrics.loc[at, "yaw mode damping ratio [-]"].to_numpy(float)
    if not np.isfinite(zetas).any():
        return f"at {where}: {one}; no campaign run at this area and airspeed to compare"
    k = int(np.nanargmin(zetas))
    z2 = float(zetas[k])
    mode = str(metrics.loc[at, "yaw mode"].iloc[k]) if "yaw mode" in metrics else "yaw mode"
    n = int(np.isfinite(zetas).sum())
    over = f"least over {n} runs" if n > 1 else "its 1 run"
    text = (f"at {where}: {one}, multibody {ratio_words(z2)} ({over}, mode {mode}); "
            f"difference {ratio_words(z1 - z2, sign=True)}")
    if abs(z1 - z2) <= DAMPING_TOLERANCE:
        return f"{text}: agree within {DAMPING_TOLERANCE:g}"
    return (f"{text}: differ by more than {DAMPING_TOLERANCE:g}: the multibody yaw mode "
            "couples with the swing of the cable and the attitude, and its hub moves (the "
            "inter-axis coupling the 1-DOF model lacks, paper 4.5)")


def decide(static, sweep=None, selection=None, metrics=None, stable=None, one_dof=None,
           study_area=math.nan, yaw_axis="", airspeed=math.nan):
    """The parachute decision (module notes).

    Parameters
    ----------
    static : NeutralAreaResult
        The neutral area (both slope bases).
    sweep : SweepResult, optional
        The 1-DOF sizing sweep (None: not run).
    selection : Selection, optional
        The campaign's parachute selection (None: not run).
    metrics : pandas.DataFrame, optional
        The campaign's metrics, with ``stable`` (boolean array, the selection's rule).
    stable : array_like of bool, optional
    one_dof : callable, optional
        ``one_dof(area)`` -> DataFrame with columns gust and verdict: the 1-DOF runs at an
        area (every gust shape), used for the verdicts at the chosen area.
    study_area : float
        [m^2]
    yaw_axis : str
        The 1-DOF model's axis in words.
    airspeed : float
        The 1-DOF model's equivalent airspeed (the damping comparison's). [m/s]

    Returns
    -------
    ParachuteDecision
    """
    a1, gov1 = (math.nan, "")
    if sweep is not None:
        a1, gov1 = one_dof_proposal(sweep)
    a2, gov2 = math.nan, ""
    if selection is not None:
        a2 = float(selection.recommended_area)
        g = selection.governing_recommended or selection.governing_stable or {}
        gov2 = str(g.get("condition", ""))
        if np.isfinite(a2) and selection.governing_stable:
            factor = selection.governing_stable['needs area factor [-]']
            neutral = float(getattr(selection, "neutral_area", math.nan))
            where = str(getattr(selection, "neutral_condition", "") or "")
            where = f" ({where})" if where else ""
            base = (f"the campaign's neutral area {neutral:.6g} m^2{where} = "
                    f"{factor * neutral:.6g} m^2" if np.isfinite(neutral)
                    else "the campaign's neutral area")
            gov2 = (f"{gov2} (least yaw damping); stability needs {factor:.3g} x {base} at "
                    f"{selection.governing_stable['condition']}")
    ran1, ran2 = sweep is not None, selection is not None
    chosen, model, reason, governing = math.nan, "", "", ""
    if (ran1 and not np.isfinite(a1)) or (ran2 and not np.isfinite(a2)):
        failed = [m for m, ran, a in ((ONE_DOF, ran1, a1), (MULTIBODY, ran2, a2))
                  if ran and not np.isfinite(a)]
        model = " and ".join(failed)
        reason = ("no area meets the criterion of the " + model + ": no area is chosen "
                  "(the area must meet every criterion that was run)")
        governing = gov2 if MULTIBODY in failed else gov1
    elif ran1 and ran2:
        if a2 >= a1:
            chosen, model, governing = a2, MULTIBODY, gov2
            reason = ("the larger proposal (both criteria must hold); the multibody model "
                      "includes the inter-axis coupling the 1-DOF model lacks (paper 4.5)"
                      if a2 > a1 * (1 + 1e-9) else "both models propose this area")
        else:
            chosen, model, governing = a1, ONE_DOF, gov1
            reason = (f"the larger proposal (both criteria must hold): the 1-DOF sweep needs "
                      f"{a1:.6g} m^2, more than the campaign's {a2:.6g} m^2")
    elif ran1:
        chosen, model, governing = a1, ONE_DOF, gov1
        reason = "the only model run (no multibody campaign)"
    elif ran2:
        chosen, model, governing = a2, MULTIBODY, gov2
        reason = "the only model run (no 1-DOF sweep)"
    verdicts, runs = {}, None
    if one_dof is not None and np.isfinite(chosen):
        runs = one_dof(chosen)
        verdicts = dict(zip(runs["gust"].astype(str), runs["verdict"].astype(str),
                            strict=True))
    mb = mb1 = "not run"
    if ran2:
        flags = np.asarray(stable, bool) if stable is not None else None
        mb = multibody_verdict_at(metrics, chosen, flags)
        mb1 = multibody_verdict_at(metrics, a1, flags) if ran1 else "no 1-DOF sweep"
    damping = ""
    if np.isfinite(airspeed):  # at the chosen area, else at the 1-DOF proposal
        compared = chosen if np.isfinite(chosen) else a1
        if not np.isfinite(chosen) and np.isfinite(a1) and one_dof is not None:
            runs = one_dof(a1)
        damping = damping_comparison(runs, metrics if ran2 else None, compared, airspeed)
    return ParachuteDecision(
        float(static.area_fit), float(static.area_local), float(static.area),
        static.basis_text, float(a1), ran1, verdicts, float(a2), ran2, mb, float(chosen),
        model, reason, governing, float(study_area), str(yaw_axis), mb1, damping)


__all__ = ["DAMPING_TOLERANCE", "MULTIBODY", "NO_AREA", "ONE_DOF", "ParachuteDecision",
           "damping_comparison", "decide", "multibody_verdict_at", "one_dof_proposal"]

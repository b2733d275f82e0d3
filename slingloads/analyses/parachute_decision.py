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

from slingloads.analyses.verdicts import ACCEPTED, worst

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
               if self.one_dof_verdicts else ("not run" if not self.one_dof_ran else "-"))
        rows = [
            ("neutral area, least-squares slopes", self.neutral_area_fit, "m^2", ""),
            ("neutral area, local slopes at beta 0", self.neutral_area_local, "m^2", ""),
            ("neutral area used", self.neutral_area, "m^2", self.neutral_basis),
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
    return area, f"1-DOF at {last:.4g} m^2{at}: {what}"


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
        "stable in all N runs", how many are not and the worst response, or "not run".
    """
    if metrics is None or not np.isfinite(area):
        return "not run"
    at = np.isclose(metrics["area [m^2]"].to_numpy(float), area, rtol=1e-6)
    if not at.any():
        return "not run at this area"
    ok = int(np.count_nonzero(stable[at]))
    total = int(np.count_nonzero(at))
    if ok == total:
        return f"stable in all {total} runs"
    verdicts = metrics.loc[at, "response verdict"].astype(str)
    return f"NOT stable: {total - ok} of {total} runs (worst response: {worst(list(verdicts))})"


def decide(static, sweep=None, selection=None, metrics=None, stable=None, one_dof=None,
           study_area=math.nan):
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
            base = (f"the campaign's neutral area {neutral:.3g} m^2{where} = "
                    f"{factor * neutral:.3g} m^2" if np.isfinite(neutral)
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
                      f"{a1:.4g} m^2, more than the campaign's {a2:.4g} m^2")
    elif ran1:
        chosen, model, governing = a1, ONE_DOF, gov1
        reason = "the only model run (no multibody campaign)"
    elif ran2:
        chosen, model, governing = a2, MULTIBODY, gov2
        reason = "the only model run (no 1-DOF sweep)"
    verdicts = {}
    if one_dof is not None and np.isfinite(chosen):
        runs = one_dof(chosen)
        verdicts = dict(zip(runs["gust"].astype(str), runs["verdict"].astype(str),
                            strict=True))
    mb = "not run"
    if ran2:
        mb = multibody_verdict_at(metrics, chosen, np.asarray(stable, bool)
                                  if stable is not None else None)
    return ParachuteDecision(
        float(static.area_fit), float(static.area_local), float(static.area),
        static.basis_text, float(a1), ran1, verdicts, float(a2), ran2, mb, float(chosen),
        model, reason, governing, float(study_area))


__all__ = ["MULTIBODY", "ONE_DOF", "ParachuteDecision", "decide", "multibody_verdict_at",
           "one_dof_proposal"]

"""The findings of a study: the questions it answers, one answer each, and where it comes from.

One ``slingloads run`` answers a few questions that several reports touch: the hook design
angle, the parachute area, the speed limit without parachute, the peak cable tension against
the hook load factor Nz, the loads' exceedances over the previous envelope, and the linear
stability of the towed system at its trim. :func:`study_findings` answers each of them ONCE
from the typed :class:`~slingloads.runs.study.Results`, and every report of the run carries
the same table (:meth:`Findings.to_frame`; the reports convert it to their unit system), so
that no two reports can state two answers to one question.

Each row has the answer in words (its verdict), the value with its unit, the reference the
verdict compares it with (same unit; NaN when there is none) and its source (analysis, sheet,
item, case). A question whose analyses were not run says ``not run``.

Units of the values: angles in deg, areas in m^2 (converted by the reports), airspeeds in kt
(as every airspeed of the reports), ratios [-], rates [1/s].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.analyses.hook_loads import angle_words
from slingloads.constants import KNOT

NOT_RUN = "not run"
#: Columns of :meth:`Findings.to_frame`.
COLUMNS = ["question", "answer", "value", "unit", "reference", "source"]

#: The questions, in the order of the table.
HOOK_ANGLE = "hook design angle, lateral directions (from the vertical)"
CHOSEN_AREA = "parachute area (chosen)"
STUDY_AREA = "parachute area of the loads (Study 'parachute area')"
SPEED_LIMIT = "speed limit without parachute"
TENSION = "peak cable tension T/(m g) against Nz"
EXCEEDANCE = "loads exceedances over the previous envelope"
LINEAR = "linear stability of the towed system at its trim (multibody)"
ATTITUDE = "trimmed angle of attack of the parachute sizing's condition (1-DOF against multibody)"
#: Largest difference between the 1-DOF sizing's angle of attack and the multibody trim's at
#: the same airspeed and density altitude for the two to count as one attitude. [deg]
ATTITUDE_TOLERANCE = 1.0


@dataclass(frozen=True)
class Finding:
    """One question and its answer.

    Attributes
    ----------
    question : str
    answer : str
        The verdict in words (``"not run"`` when no analysis answers it).
    value : float
        The number the answer rests on (NaN when none). [``unit``]
    unit : str
        ``"deg"``, ``"m^2"``, ``"kt"``, ``"-"`` or ``"1/s"``.
    reference : float
        What the verdict compares ``value`` with (NaN when nothing). [``unit``]
    source : str
        Analysis, report sheet, item and case it comes from.
    """

    question: str
    answer: str
    value: float = math.nan
    unit: str = ""
    reference: float = math.nan
    source: str = ""


@dataclass(frozen=True)
class Findings:
    """The findings of a study, one :class:`Finding` per question (module notes).

    Attributes
    ----------
    rows : tuple of Finding
    """

    rows: tuple

    def to_frame(self):
        """One row per question (columns :data:`COLUMNS`; values in the units of the
        ``unit`` column, areas in m^2).

        Returns
        -------
        pandas.DataFrame
        """
        return pd.DataFrame([(f.question, f.answer, f.value, f.unit, f.reference, f.source)
                             for f in self.rows], columns=COLUMNS)

    def get(self, question):
        """The finding whose question starts with ``question`` (the first one).

        Parameters
        ----------
        question : str
            The start of the finding's question.

        Returns
        -------
        Finding
            The first finding whose question starts so.

        Raises
        ------
        KeyError
            If no finding's question starts so.
        """
        for f in self.rows:
            if f.question.startswith(question):
                return f
        raise KeyError(question)


def study_findings(results):
    """The findings of a study's results (module notes).

    Parameters
    ----------
    results : Results
        The run's results (:class:`~slingloads.runs.study.Results`).

    Returns
    -------
    Findings
    """
    return Findings((_hook_angle(results), *_parachute(results), *_speed_limits(results),
                     _tension(results), _exceedance(results), _linear(results),
                     _attitude(results)))


# ------------------------------------------------------------------------------- questions
def _hook_angle(results):
    lateral, loads, handoff = results.lateral, results.loads, results.loads_hook_angle
    if lateral is None and loads is None:
        return Finding(HOOK_ANGLE, NOT_RUN, unit="deg", source="lateral study and loads")
    rec = math.nan if lateral is None else float(np.degrees(lateral.recommended_angle))
    where = ""
    if lateral is not None:
        st = lateral.study
        k = int(st.critical_index)
        where = (f"lateral study, Summary 'recommended design angle' (margin {st.margin:g} x "
                 f"largest load angle {angle_words(np.degrees(st.max_load_angle))} deg, case "
                 f"{st.nominal_case(k)} on sheet Runs (run {k + 1}), motion "
                 f"{lateral.motion_id(k)})")
    if loads is not None:
        used = float(np.degrees(loads.study.hook.lateral))
        study = used if handoff is None else float(np.degrees(handoff.loads_angle))
        if handoff is not None:
            answer = (f"{used:.1f} deg, governed by the {handoff.governs} (max of the loads' "
                      f"own {study:.1f} deg and the recommended "
                      + (f"{rec:.1f} deg)" if np.isfinite(rec) else "none: no design angle)"))
            source = (f"{where}; loads, Summary 'lateral hook angle used by the loads'")
        else:
            answer = f"{used:.1f} deg, the Study's (no lateral study run)"
            source = "loads, Summary 'hook cone angle of the lateral directions'"
        return Finding(HOOK_ANGLE, answer, used, "deg", study, source)
    if not np.isfinite(rec):
        return Finding(HOOK_ANGLE, "no design angle: " + lateral.study.verdict(), math.nan,
                       "deg", 30.0, where or "lateral study, Summary")
    reg = float(np.degrees(lateral.study.regulatory_angle))
    answer = (f"{rec:.1f} deg, above the {reg:.0f} deg of CS-29.865: no reduction" if rec > reg
              else f"{rec:.1f} deg, below the {reg:.0f} deg of CS-29.865")
    return Finding(HOOK_ANGLE, answer + " (loads not run)", rec, "deg", reg, where)


def _parachute(results):
    decision = results.parachute_decision
    loads = results.loads
    study_area = math.nan
    if loads is not None and loads.study.parachute is not None:
        study_area = float(loads.study.parachute.area)
    if decision is None:
        chosen = Finding(CHOSEN_AREA, NOT_RUN, unit="m^2",
                         source="parachute sizing and campaign")
        if np.isfinite(study_area):
            study = Finding(STUDY_AREA, "not assessed (no parachute sizing or campaign run)",
                            study_area, "m^2", source="loads, Summary 'parachute'")
        else:
            study = Finding(STUDY_AREA, NOT_RUN if loads is None else "no parachute",
                            unit="m^2", source="loads")
        return chosen, study
    models = " and ".join(m for m, ran in (("parachute sizing (1-DOF)", decision.one_dof_ran),
                                           ("campaign (multibody)", decision.multibody_ran))
                          if ran)
    source = f"parachute decision of the {models}, Summary 'Parachute decision', 'chosen area'"
    if decision.found:
        answer = (f"{decision.chosen_area / decision.neutral_area:.3g} x the neutral area "
                  f"(reference), decided by the {decision.deciding_model}; governing: "
                  f"{decision.governing or '-'}")
    else:
        answer = f"NONE: {decision.reason}"
    chosen = Finding(CHOSEN_AREA, answer, decision.chosen_area, "m^2", decision.neutral_area,
                     source)
    area = decision.study_area if np.isfinite(decision.study_area) else study_area
    study = Finding(STUDY_AREA, decision.study_area_verdict(), area, "m^2",
                    decision.chosen_area,
                    "parachute decision, Summary 'Parachute decision', \"Study 'parachute "
                    "area' (loads)\"")
    return chosen, study


def _speed_limits(results):
    campaign = results.campaign
    npr = None if campaign is None else campaign.result.no_parachute
    if npr is None:
        why = NOT_RUN if campaign is None else "not run (campaign without the no-parachute study)"
        return (Finding(SPEED_LIMIT, why, unit="kt", source="campaign, sheet NoParachute"),)
    out = []
    for _, row in npr.limits.iterrows():
        limit = float(row["largest convergent ramp [m/s]"]) / KNOT
        answer = str(row["speed limit"])  # the bracket, with the first failing ramp's verdict
        out.append(Finding(f"{SPEED_LIMIT}, {row['helicopter']}", answer, limit, "kt", math.nan,
                           "campaign, Summary 'Transport without parachute' and sheet "
                           "NoParachute"))
    return tuple(out)


def _tension(results):
    """The largest T/(m g) over the analyses that compute it, against the loads' Nz."""
    nz = math.nan
    if results.loads is not None:
        nz = float(results.loads.study.hook.nz)
    elif results.lateral is not None and results.lateral.study.hook_load_factor is not None:
        nz = float(results.lateral.study.hook_load_factor)
    candidates = []
    if results.lateral is not None:
        st = results.lateral.study
        ratio = np.asarray(st.metrics.max_tension_ratio, float)
        if np.any(np.isfinite(ratio)):
            k = int(np.nanargmax(ratio))
            candidates.append((float(ratio[k]), f"lateral study, Summary 'largest cable tension "
                                                f"factor T/(m g)' (case {st.nominal_case(k)} "
                                                f"on sheet Runs, run {k + 1})"))
    if results.multibody is not None:
        frame = results.multibody.to_frame()  # without a trim, the runs have no metrics
        values = pd.to_numeric(frame.get("tension / weight max [-]", pd.Series(dtype=float)),
                               errors="coerce")
        if values.notna().any():
            k = int(values.idxmax())
            candidates.append((float(values[k]), f"multibody, sheet Metrics 'tension / weight "
                                                 f"max' (run '{frame['run'][k]}')"))
    if results.campaign is not None:
        metrics = results.campaign.result.metrics
        values = pd.to_numeric(metrics.get("tension / weight max [-]", pd.Series(dtype=float)),
                               errors="coerce")
        if values.notna().any():
            k = int(values.idxmax())
            candidates.append((float(values[k]), f"campaign, sheet Metrics 'tension / weight "
                                                 f"max' (run {metrics['run'][k]})"))
    if not candidates:
        return Finding(TENSION, NOT_RUN, unit="-", reference=nz,
                       source="lateral study, multibody and campaign")
    value, source = max(candidates, key=lambda c: c[0])
    # a factor [-] at the precision of its value cell (0.000), in the text as in the cells
    others = ", ".join(f"{v:.3f} ({s.split(',')[0]})" for v, s in candidates if s != source)
    if not np.isfinite(nz):
        answer = f"{value:.3f} (no Nz to compare with: loads not run)"
    elif value <= nz:
        answer = f"{value:.3f} <= Nz {nz:.3f}: Nz x weight covers the peak cable tension"
    else:
        answer = f"{value:.3f} > Nz {nz:.3f}: the peak cable tension EXCEEDS Nz x weight"
    if others:
        source += f"; the largest, against {others}"
    return Finding(TENSION, answer, value, "-", nz, source)


def _exceedance(results):
    loads = results.loads
    if loads is None:
        return Finding(EXCEEDANCE, NOT_RUN, unit="-", source="loads")
    comparison = loads.comparison()
    if comparison is None:
        return Finding(EXCEEDANCE, "no previous design envelope given: no check", unit="-",
                       source="loads, Summary")
    over = comparison[comparison["exceeds"].astype(bool)]
    ratio = pd.to_numeric(comparison["exceedance ratio"], errors="coerce").replace(
        np.inf, np.nan)
    if ratio.notna().any():
        k = int(ratio.idxmax())
        worst = float(ratio[k])
        at = f"{comparison['component'][k]} at {comparison['station'][k]}"
    else:
        worst, at = math.nan, "-"
    unbounded = int(np.count_nonzero(np.isinf(pd.to_numeric(
        comparison["exceedance ratio"], errors="coerce"))))
    if len(over):
        answer = (f"{len(over)} of {len(comparison)} station x component entries EXCEED "
                  f"(largest finite ratio {worst:.3f}, {at})")
        if unbounded:
            answer += f"; {unbounded} where the previous envelope is 0"
    else:
        answer = f"none of {len(comparison)} entries exceeds (largest ratio {worst:.3f}, {at})"
    return Finding(EXCEEDANCE, answer, worst, "-", 1.0,
                   "loads, sheets Exceedance and ExceedanceDetail")


def _linear(results):
    mb = results.multibody
    if mb is None:
        return Finding(LINEAR, NOT_RUN, unit="1/s", source="multibody")
    if mb.linear is None:
        return Finding(LINEAR, f"no trim: {mb.trim.message}", unit="1/s",
                       source="multibody, Summary")
    from slingloads.analyses.multibody.trim import STABILITY_TOLERANCE

    largest = float(np.max(mb.linear.eigenvalues.real))
    at = (" with the Study parachute" if getattr(mb.inputs.system, "parachute", None)
          is not None else " without parachute")
    answer = (f"{mb.linear.verdict()} at {mb.inputs.system.airspeed / KNOT:.4g} KEAS{at} "
              f"(eigenvalues only: stable when every real part is below "
              f"-{STABILITY_TOLERANCE:g} 1/s, the reference; parachute adequacy: see the "
              f"parachute area)")
    return Finding(LINEAR, answer, largest, "1/s", -STABILITY_TOLERANCE,
                   "multibody, Summary and sheet Modes")


def _attitude(results):
    """The 1-DOF sizing's angle of attack against the multibody trim's at the
    same airspeed and density altitude: one attitude per flight condition, or the finding
    says they differ and by how much (and whether the trim lies outside the loads'
    aerodynamic envelope)."""
    chute, mb = results.chute_sizing, results.multibody
    if chute is None or mb is None:
        return Finding(ATTITUDE, NOT_RUN if chute is None else
                       "not compared (no multibody run)", unit="deg",
                       source="parachute sizing and multibody")
    c = chute.inputs.model.condition
    sizing = float(np.degrees(c.alpha))
    system = mb.inputs.system
    where = (f"parachute sizing, Summary 'alpha trim' (the towed trim, or the Study's 'chute "
             f"sizing alpha trim' without one); "
             f"multibody, Summary 'Trim at {system.airspeed / KNOT:.4g} KEAS' 'alpha'")
    same = (abs(system.airspeed - c.eas) <= 1e-6 * max(1.0, c.eas)
            and abs(system.density_altitude - c.density_altitude) <= 1e-3)
    if not same:
        return Finding(ATTITUDE, f"not compared: the sizing is at {c.eas / KNOT:.4g} KEAS, "
                       f"{c.density_altitude:.4g} m, the multibody at "
                       f"{system.airspeed / KNOT:.4g} KEAS, {system.density_altitude:.4g} m",
                       sizing, "deg", math.nan, where)
    if not mb.trim.converged:
        return Finding(ATTITUDE, f"not compared: no multibody trim ({mb.trim.message})",
                       sizing, "deg", math.nan, where)
    trimmed = float(np.degrees(mb.trim.quantity("alpha")))
    diff = sizing - trimmed
    if abs(diff) <= ATTITUDE_TOLERANCE:
        answer = (f"one attitude: 1-DOF alpha {sizing:.1f} deg, multibody trim "
                  f"{trimmed:.1f} deg at {c.eas / KNOT:.4g} KEAS (within "
                  f"{ATTITUDE_TOLERANCE:g} deg)")
    else:
        answer = (f"NOT ONE ATTITUDE: the 1-DOF sizing takes alpha {sizing:.1f} deg, the "
                  f"multibody trims at {trimmed:.1f} deg at {c.eas / KNOT:.4g} "
                  f"KEAS ({diff:+.1f} deg): the 1-DOF areas hold for the input attitude only")
    loads = results.loads
    envelope = None if loads is None else loads.study.envelope
    if envelope is not None:
        lo, hi = np.degrees(np.min(envelope.alpha)), np.degrees(np.max(envelope.alpha))
        if not lo - 1e-9 <= trimmed <= hi + 1e-9:
            answer += (f"; the trim lies outside the loads' aerodynamic envelope alpha "
                       f"[{lo:.3g}, {hi:.3g}] deg")
    return Finding(ATTITUDE, answer, sizing, "deg", trimmed, where)

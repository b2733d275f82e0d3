"""Checks between the analyses of one run: results of one that another relies on.

When ``slingloads run`` computes several analyses of a workbook, some of their results bear on
each other's assumptions. :func:`consistency_checks` gathers them, per report that shows them:

* the loads take the aerodynamic and parachute loads at the points of their ``AeroEnvelope``;
  the parachute sizing finds the sideslip the gusts drive the aircraft to at the Study's
  'parachute area' (the area the loads use). A peak sideslip outside the envelope's sideslip
  range means the loads do not envelope that flight: the loads report warns.

Each check is a row of a small DataFrame (check, value, limit, unit, status, note); a check
that cannot be made because an analysis did not run is left out.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

COLUMNS = ["check", "value", "limit", "unit", "status", "note"]


def consistency_checks(results):
    """The checks between the analyses of one run.

    Parameters
    ----------
    results : Results
        The run's results (:class:`~slingloads.runs.study.Results`).

    Returns
    -------
    dict
        Analysis name -> pandas.DataFrame of its checks (columns :data:`COLUMNS`); only the
        analyses with at least one check are present.
    """
    out = {}
    loads, chute = results.loads, results.chute_sizing
    if loads is not None and chute is not None:
        row = sideslip_check(loads, chute)
        if row is not None:
            out["loads"] = pd.DataFrame([row], columns=COLUMNS)
    return out


def sideslip_check(loads, chute):
    """The parachute sizing's peak sideslip at the Study's 'parachute area' against the
    sideslip range of the loads' aerodynamic envelope.

    Parameters
    ----------
    loads : LoadsResult
    chute : ChuteSizingReport

    Returns
    -------
    dict or None
        One row of :data:`COLUMNS`; None when the loads have no aerodynamic envelope or the
        sizing ran no gust at the Study's area.
    """
    envelope = loads.study.envelope
    peak, gust = chute.study_area_peak_sideslip
    if envelope is None or not np.isfinite(peak):
        return None
    lo, hi = float(np.min(envelope.beta)), float(np.max(envelope.beta))
    limit = min(-lo, hi)
    peak_deg, lo_deg, hi_deg = np.degrees(peak), np.degrees(lo), np.degrees(hi)
    area = chute.inputs.study_area
    if peak <= limit * (1 + 1e-12):
        status = "ok"
        note = (f"the gusts of the parachute sizing at the Study 'parachute area' "
                f"({area:.3f} m^2) stay within the envelope's sideslip range "
                f"[{lo_deg:.1f}, {hi_deg:.1f}] deg")
    else:
        status = "WARNING"
        note = (f"the parachute sizing's {gust} gust drives the sideslip to {peak_deg:.1f} deg "
                f"at the Study 'parachute area' ({area:.3f} m^2), outside the loads' "
                f"aerodynamic envelope [{lo_deg:.1f}, {hi_deg:.1f}] deg: the aerodynamic and "
                f"parachute loads of that flight are not enveloped. Widen the AeroEnvelope to "
                f"+-{peak_deg:.1f} deg or enlarge the parachute.")
    return {"check": "parachute sizing peak sideslip within the loads' aerodynamic envelope",
            "value": float(peak_deg), "limit": float(np.degrees(limit)), "unit": "deg",
            "status": status, "note": note}

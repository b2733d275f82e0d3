"""Sensitivity of the response to each factor (paper figures 9 to 13).

**Tables.** For the parachute area: every run, grouped by area factor. For every other factor
(airspeed, mass case, density altitude, cable length, carrier): the runs at the selected area
(the paper fixes the area first, then varies the rest; column ``at area factor [-]``), grouped
by that factor's value. Each
group gives its number of runs and stable runs and the worst value of the key metrics over the
other factors and the manoeuvres (largest peak yaw change, sideslip, RMS yaw, settling time,
tension factor, hub-load angle, swing angle; least yaw-mode damping ratio).

**Carrier free against frozen** (paper figure 13): the runs that differ only by the carrier,
paired, and the differences of their metrics (free minus frozen).

**Runs to plot** (:func:`sweep_runs`): one run per value of a factor, all other factors at
the base condition (:func:`base_condition`): the selected area, the highest airspeed, and the
first mass case, density altitude, cable length and carrier of the matrix (frozen when
present), under one manoeuvre.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .selection import stable_runs

#: The factors, by the column of the matrix that holds them.
FACTORS = {"area factor [-]": "parachute area", "airspeed EAS [m/s]": "airspeed",
           "mass case": "mass", "density altitude [m]": "density altitude",
           "cable length [m]": "cable length", "carrier": "carrier"}

#: Worst value of each metric over a group: (metric, "max" of |value| (signed peaks in
#: magnitude) or "min").
WORST = (("yaw change [deg]", "max"), ("beta peak [deg]", "max"), ("yaw rms [deg]", "max"),
         ("settling time [s]", "max"), ("tension / weight max [-]", "max"),
         ("hub load from hanging vertical max [deg]", "max"), ("swing angle trim [deg]", "max"),
         ("yaw mode damping ratio [-]", "min"),
         ("yaw damping ratio from response [-]", "min"))


def _worst(group):
    out = {"runs": len(group), "stable runs": int(stable_runs(group).sum())}
    for metric, how in WORST:
        values = pd.to_numeric(group[metric], errors="coerce").to_numpy(float)
        values = values[np.isfinite(values)]
        if how == "max":
            out[f"largest {metric}"] = float(np.abs(values).max()) if values.size else np.nan
        else:
            out[f"least {metric}"] = float(values.min()) if values.size else np.nan
    return pd.Series(out)


def sensitivity_tables(metrics, selected_factor):
    """One table per factor (module notes).

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics.
    selected_factor : float or None
        The selected area factor (NaN: the largest of the matrix). [-]

    Returns
    -------
    dict
        Factor name -> DataFrame.
    """
    out = {}
    chosen = _chosen(metrics, selected_factor)
    for column, name in FACTORS.items():
        runs = metrics if column == "area factor [-]" else metrics[
            metrics["area factor [-]"] == chosen]
        if runs[column].nunique() < 2 and column != "area factor [-]":
            continue
        table = runs.groupby(column, sort=True)[list(runs.columns)].apply(_worst)
        table = table.reset_index()
        if column != "area factor [-]":  # the runs it is taken over, in the table itself
            table.insert(1, "at area factor [-]", chosen)
        out[name] = table
    return out


def _chosen(metrics, selected_factor):
    if selected_factor is None or not np.isfinite(selected_factor):
        return float(metrics["area factor [-]"].max())
    return float(selected_factor)


def carrier_comparison(metrics):
    """Runs that differ only by the carrier, paired, free minus frozen (None without both).

    Parameters
    ----------
    metrics : pandas.DataFrame
        The campaign's metrics, one row per run (units in the column labels).

    Returns
    -------
    pandas.DataFrame or None
        Per pair: the runs and the yaw change, sideslip peak, swing at trim [deg], yaw damping
        ratio and tension over weight [-] with each carrier and their difference.
    """
    if set(metrics["carrier"]) != {"free", "frozen"}:
        return None
    keys = [c for c in ("area factor [-]", "airspeed EAS [m/s]", "mass case",
                        "density altitude [m]", "cable length [m]", "manoeuvre")]
    frozen = metrics[metrics["carrier"] == "frozen"].set_index(keys)
    free = metrics[metrics["carrier"] == "free"].set_index(keys)
    both = frozen.index.intersection(free.index)
    if len(both) == 0:
        return None
    rows = pd.DataFrame(index=both)
    rows["run frozen"] = frozen.loc[both, "run"]
    rows["run free"] = free.loc[both, "run"]
    for metric in ("yaw change [deg]", "beta peak [deg]", "yaw mode damping ratio [-]",
                   "tension / weight max [-]", "swing angle trim [deg]"):
        a = pd.to_numeric(frozen.loc[both, metric], errors="coerce")
        b = pd.to_numeric(free.loc[both, metric], errors="coerce")
        rows[f"{metric.split(' [')[0]} frozen"] = a
        rows[f"{metric.split(' [')[0]} free"] = b
        rows[f"{metric.split(' [')[0]} free - frozen"] = b - a
    return rows.reset_index()


def base_condition(matrix_frame, selected_factor):
    """The base condition of the sensitivity plots (module notes), as a dict of factors.

    Parameters
    ----------
    matrix_frame : pandas.DataFrame
        :attr:`CampaignMatrix.frame <slingloads.analyses.campaign.matrix.CampaignMatrix.frame>`.
    selected_factor : float or None
        Area factor of the selected parachute (None or NaN: the largest of the matrix). [-]

    Returns
    -------
    dict
        The factors of the base condition, by column of the matrix (units in the labels).
    """
    m = matrix_frame
    chosen = _chosen(m, selected_factor)
    areas = np.sort(m["area factor [-]"].unique())
    chosen = areas[np.argmin(np.abs(areas - chosen))]
    carriers = list(dict.fromkeys(m["carrier"]))
    return {"area factor [-]": float(chosen),
            "airspeed EAS [m/s]": float(m["airspeed EAS [m/s]"].max()),
            "mass case": m["mass case"].iloc[0],
            "density altitude [m]": float(m["density altitude [m]"].iloc[0]),
            "cable length [m]": float(m["cable length [m]"].iloc[0]),
            "carrier": "frozen" if "frozen" in carriers else carriers[0]}


def sweep_runs(matrix_frame, factor, base, manoeuvre):
    """Run ids varying ``factor`` (a column of :data:`FACTORS`) with every other factor at
    ``base``, under ``manoeuvre``, in order of the factor's value (empty when none).

    Parameters
    ----------
    matrix_frame : pandas.DataFrame
        :attr:`CampaignMatrix.frame <slingloads.analyses.campaign.matrix.CampaignMatrix.frame>`.
    factor : str
        A column of :data:`FACTORS`.
    base : dict
        The base condition (:func:`base_condition`).
    manoeuvre : str
        Name of the manoeuvre.

    Returns
    -------
    list of str
        Run ids.
    """
    m = matrix_frame[matrix_frame["manoeuvre"] == manoeuvre]
    for column, value in base.items():
        if column == factor:
            continue
        if isinstance(value, str):
            m = m[m[column] == value]
        else:
            m = m[np.isclose(m[column].astype(float), value)]
    if m[factor].nunique() < 2:
        return []
    return m.sort_values(factor)["run"].tolist()

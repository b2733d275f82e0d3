"""Envelopes of internal loads: extremes with critical and correlated loads, 2-D convex hulls
("potato" plots), and the comparison with a previous design envelope.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.analyses.sfbm import COMPONENTS, LOAD_COLUMNS
from slingloads.errors import InputError


def component_index(name):
    """Array index of an internal-load component name (``"Vy"`` -> 1).

    Parameters
    ----------
    name : str
        One of :data:`~slingloads.analyses.sfbm.COMPONENTS`.

    Returns
    -------
    int
        Index of the component in :data:`~slingloads.analyses.sfbm.COMPONENTS`. [-]

    Raises
    ------
    InputError
        For an unknown component.
    """
    try:
        return COMPONENTS.index(name)
    except ValueError:
        raise InputError(f"unknown load component; valid components are {list(COMPONENTS)}",
                         name) from None


def envelope_table(loads, case_ids, stations, station_ids):
    """Maximum and minimum of every component at every station, with the critical case.

    Parameters
    ----------
    loads : ndarray, shape (c, s, 6)
        Internal loads. [N, N m]
    case_ids : sequence of str, length c
    stations : ndarray, shape (s,)
        Station x. [m]
    station_ids : sequence of str, length s

    Returns
    -------
    pandas.DataFrame
        One row per station, component and bound (``max``/``min``), with the columns of the
        envelope CSV file: ``station, x_m, component, bound, case``, the bound's value in
        ``value_N`` (a shear) or ``value_Nm`` (a moment; the other is NaN), and the six
        correlated loads of the critical case at that station ``Vx_N ... Mz_Nm`` (SI).
    """
    case_ids = np.asarray(case_ids, dtype=object)
    c, s, k = loads.shape
    moment = np.tile(np.array([name.startswith("M") for name in COMPONENTS]), s)
    frames = []
    for bound, pick in (("max", np.argmax), ("min", np.argmin)):
        idx = pick(loads, axis=0)  # (s, 6)
        stn = np.broadcast_to(np.arange(s)[:, None], idx.shape)
        correlated = loads[idx, stn, :]  # (s, 6, 6)
        value = loads[idx, stn, np.arange(k)[None, :]].ravel()
        frame = pd.DataFrame({
            "station": np.repeat(np.asarray(station_ids, dtype=object), k),
            "x_m": np.repeat(stations, k),
            "component": np.tile(COMPONENTS, s),
            "bound": bound,
            "case": case_ids[idx.ravel()],
            "value_N": np.where(moment, np.nan, value),
            "value_Nm": np.where(moment, value, np.nan),
        })
        for j, name in enumerate(LOAD_COLUMNS):
            frame[name] = correlated[:, :, j].ravel()
        frames.append(frame)
    out = pd.concat(frames, ignore_index=True)
    order = {name: i for i, name in enumerate(COMPONENTS)}
    out["_s"] = np.concatenate([np.repeat(np.arange(s), k)] * 2)
    out["_c"] = out["component"].map(order)
    out = out.sort_values(["_s", "_c", "bound"], ascending=[True, True, True], kind="stable")
    return out.drop(columns=["_s", "_c"]).reset_index(drop=True)


def bound_values(frame):
    """The ``value_N`` / ``value_Nm`` pair of an envelope table as one SI column (each row's
    component says which unit).

    Parameters
    ----------
    frame : DataFrame
        With columns ``value_N`` (shears, NaN for moments) and ``value_Nm`` (moments, NaN
        for shears), as :meth:`~slingloads.analyses.loads.LoadsResult.envelope` gives.

    Returns
    -------
    ndarray, shape (n,)
        The bound of each row. [N] or [N m]
    """
    return frame["value_N"].fillna(frame["value_Nm"]).to_numpy(float)


def envelope_arrays(loads):
    """Per-station maximum and minimum of every component over the cases.

    Parameters
    ----------
    loads : ndarray, shape (c, s, 6)
        Internal loads. [N, N m]

    Returns
    -------
    maximum, minimum : ndarray, shape (s, 6)
        [N, N m]
    """
    return loads.max(axis=0), loads.min(axis=0)


def convex_hull(loads, case_ids, station_index, pair):
    """2-D envelope ("potato") of two components at one station.

    Parameters
    ----------
    loads : ndarray, shape (c, s, 6)
        Internal loads of every case at every station (Vx, Vy, Vz, Mx, My, Mz). [N, N m]
    case_ids : sequence of str
        Ids of the ``c`` cases.
    station_index : int
        The station, 0 <= station_index < s. [-]
    pair : tuple of str
        Component names, e.g. ``("Vy", "Mz")``.

    Returns
    -------
    pandas.DataFrame
        Hull vertices in counter-clockwise order from the case of smallest first component
        (then smallest second): ``case`` and the two components, named as in the CSV files
        (``Vy_N``, ``Mz_Nm``; SI). Cases on an edge of the
        hull between two vertices are not vertices. Degenerate clouds (all cases on a line
        or a point) return the extreme cases along the line (or the one point).
    """
    i, j = component_index(pair[0]), component_index(pair[1])
    pts = loads[:, station_index, :][:, [i, j]]
    case_ids = np.asarray(case_ids, dtype=object)
    scale = np.abs(pts).max(axis=0)
    scale[scale == 0] = 1.0
    _, first = np.unique(np.round(pts / scale, 12), axis=0, return_index=True)
    vertices = first[hull_vertices(pts[first] / scale)]
    return pd.DataFrame({"case": case_ids[vertices], LOAD_COLUMNS[i]: pts[vertices, 0],
                         LOAD_COLUMNS[j]: pts[vertices, 1]})


#: Least distance from a hull edge, relative to the cloud's size, at which a point counts as
#: outside it (nearer points are on the edge, not vertices). [-]
HULL_TOLERANCE = 1e-12


def hull_vertices(points):
    """Indices of the vertices of the convex hull of distinct 2-D points, counter-clockwise
    from the lowest point in (x, y) order (quickhull, vectorised over the points: one numpy
    pass per hull edge found).

    Parameters
    ----------
    points : ndarray, shape (n, 2)
        Distinct points, n >= 1, of a size about 1 (the loads scaled by their largest
        magnitude). [-]

    Returns
    -------
    ndarray of int
        The vertices; the two ends alone when every point is on one line (within
        :data:`HULL_TOLERANCE`), the one point when n = 1. [-]
    """
    order = np.lexsort((points[:, 1], points[:, 0]))
    start, end = int(order[0]), int(order[-1])
    if start == end:
        return np.array([start])
    everyone = np.arange(len(points))
    lower = _chain(points, start, end, everyone)  # right of start -> end: below
    upper = _chain(points, end, start, everyone)  # right of end -> start: above
    return np.array([start, *lower, end, *upper], dtype=int)


def _chain(points, a, b, candidates):
    """Hull vertices strictly to the right of the directed line a -> b, in order from a to
    b (an explicit stack: no recursion limit)."""
    tolerance = HULL_TOLERANCE * max(float(np.ptp(points, axis=0).max()), 1e-300)
    out, stack = [], [(a, b, candidates, False)]
    while stack:
        a, b, candidates, emit = stack.pop()
        if emit:  # (a is the vertex found between two chains: emitted between them)
            out.append(a)
            continue
        pa, pb = points[a], points[b]
        edge = pb - pa
        length = float(np.hypot(*edge))
        d = points[candidates] - pa
        distance = (edge[1] * d[:, 0] - edge[0] * d[:, 1]) / length  # > 0: right of a -> b
        outside = candidates[distance > tolerance]
        if outside.size == 0:
            continue
        far = int(outside[np.argmax(distance[distance > tolerance])])
        # a -> far first, then far, then far -> b (pushed in reverse)
        stack.append((far, b, outside, False))
        stack.append((far, None, None, True))
        stack.append((a, far, outside, False))
    return out


def compare_with_previous(loads, stations, station_ids, previous):
    """Exceedance of the new envelope over a previous design envelope.

    The previous envelope is interpolated linearly in x between its own stations; a cut
    station outside its x range is reported as not covered (never extrapolated).

    Parameters
    ----------
    loads : ndarray, shape (c, s, 6)
        Internal loads of every case at every station (Vx, Vy, Vz, Mx, My, Mz). [N, N m]
    stations : ndarray, shape (s,)
        Positions x of the cut stations. [m]
    station_ids : sequence of str
    previous : pandas.DataFrame
        Columns ``x [m]``, ``component``, ``min``, ``max`` (SI), one row per station and
        component, x strictly increasing within each component.

    Returns
    -------
    pandas.DataFrame
        Per station and component: new and previous max/min, the exceedance ratio
        ``max(new_max+/prev_max+, new_min-/prev_min-)`` (magnitudes of the positive and the
        negative sides), ``exceeds`` (ratio > 1) and ``status``.
    """
    new_max, new_min = envelope_arrays(loads)
    rows = []
    for k, name in enumerate(COMPONENTS):
        prev = previous[previous["component"] == name].sort_values("x [m]")
        xp = prev["x [m]"].to_numpy(float)
        covered = (stations >= xp[0]) & (stations <= xp[-1]) if len(xp) else np.zeros(
            stations.shape, bool)
        pmax = np.interp(stations, xp, prev["max"].to_numpy(float)) if len(xp) else np.zeros(
            stations.shape)
        pmin = np.interp(stations, xp, prev["min"].to_numpy(float)) if len(xp) else np.zeros(
            stations.shape)
        ratio = np.maximum(_ratio(np.maximum(new_max[:, k], 0), np.maximum(pmax, 0)),
                           _ratio(np.maximum(-new_min[:, k], 0), np.maximum(-pmin, 0)))
        status = np.where(~covered, "not covered by previous envelope",
                          np.where(ratio > 1, "EXCEEDS previous envelope", "within"))
        rows.append(pd.DataFrame({
            "station": station_ids, "x [m]": stations, "component": name,
            "new max": new_max[:, k], "new min": new_min[:, k],
            "previous max": np.where(covered, pmax, np.nan),
            "previous min": np.where(covered, pmin, np.nan),
            "exceedance ratio": np.where(covered, ratio, np.nan),
            "exceeds": covered & (ratio > 1), "status": status,
        }))
    out = pd.concat(rows, ignore_index=True)
    out["_s"] = np.tile(np.arange(len(stations)), len(COMPONENTS))
    return out.sort_values(["_s"], kind="stable").drop(columns="_s").reset_index(drop=True)


def _ratio(new, old):
    """new / old for magnitudes >= 0; 0/0 -> 0, x/0 -> inf."""
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.where(old > 0, new / np.where(old > 0, old, 1.0), np.where(new > 0, np.inf, 0.0))
    return r

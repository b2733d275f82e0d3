"""Plots of the loads analysis: shear force and bending moment along the cut stations, and
the 2-D envelopes ("potato" plots) of two components at a station.

Every function builds and returns a :class:`matplotlib.figure.Figure` through the object API
(no pyplot, no global state, the Agg renderer when saved), so plots can be drawn from threads
and in batch runs. Values are SI inside and converted to the report unit system (``"SI"``
or ``"US"``, see :data:`slingloads.io.common.units.REPORT_UNITS`) when drawn; axis labels
carry the unit (``x [in]``, ``Vy [lbf]``, ``Mz [lbf in]``).

The sign convention of the internal loads is that of :mod:`slingloads.analyses.sfbm`: the
load that the part aft of the cut exerts on the part forward of it.
"""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from slingloads.analyses.envelopes import component_index
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
from slingloads.io.common.report import check_units, in_report_units, labelled, report_unit
from slingloads.io.common.units import unit_label

#: Plain-language names of the components, as in the paper's figures ("X shear").
COMPONENT_TITLES = {
    "Vx": "X shear", "Vy": "Y shear", "Vz": "Z shear",
    "Mx": "X moment (torsion)", "My": "Y moment", "Mz": "Z moment",
}
#: File-name tags of the components (``<stem>-X_shear.png``).
COMPONENT_TAGS = {
    "Vx": "X_shear", "Vy": "Y_shear", "Vz": "Z_shear",
    "Mx": "X_moment", "My": "Y_moment", "Mz": "Z_moment",
}

_MAX_COLOUR = "tab:red"
_MIN_COLOUR = "tab:blue"
_CASE_COLOUR = "0.6"


def component_label(component, units):
    """Axis label of an internal-load component, e.g. ``"Mz [lbf in]"``."""
    return labelled(component, COMPONENT_KINDS[component_index(component)], units)


def draw_sfbm(ax, x, values, component, units="SI", previous=None, case_ids=None,
              title=None):
    """Draw one SFBM component along the stations on an existing Axes.

    Every case is a faint thin grey line, the envelope maximum and minimum are bold (the
    case id written at the largest and the smallest value), and the previous design
    envelope, when given, is dashed.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    x : array_like, shape (s,)
        Cut station x. [m]
    values : array_like, shape (c, s)
        The component for every case. [N] or [N m]
    component : str
        ``"Vx"``... ``"Mz"``.
    units : str
        ``"SI"`` or ``"US"``.
    previous : tuple of array_like, optional
        ``(x, min, max)`` of the previous design envelope (SI). [m], [N] or [N m]
    case_ids : sequence of str, optional
        Case ids, for labelling the extreme cases.
    title : str, optional
        Axes title (default: the component name, e.g. ``"Y shear (Vy)"``).
    """
    kind = COMPONENT_KINDS[component_index(component)]
    xs = in_report_units(x, "length", units)
    v = in_report_units(np.atleast_2d(values), kind, units)
    segments = np.stack([np.broadcast_to(xs, v.shape), v], axis=-1)
    ax.add_collection(LineCollection(segments, colors=_CASE_COLOUR, linewidths=0.5,
                                     alpha=0.5, label=f"load cases ({v.shape[0]})"))
    vmax, vmin = v.max(axis=0), v.min(axis=0)
    ax.plot(xs, vmax, color=_MAX_COLOUR, lw=2.2, marker=".", ms=4, label="envelope max")
    ax.plot(xs, vmin, color=_MIN_COLOUR, lw=2.2, marker=".", ms=4, label="envelope min")
    if previous is not None:
        px, pmin, pmax = (np.asarray(a, float) for a in previous)
        pxs = in_report_units(px, "length", units)
        ax.plot(pxs, in_report_units(pmax, kind, units), "k--", lw=1.4,
                label="previous envelope")
        ax.plot(pxs, in_report_units(pmin, kind, units), "k--", lw=1.4)
    if case_ids is not None:
        ids = np.asarray(case_ids, dtype=object)
        for arr, pick, colour, va in ((v, np.argmax, _MAX_COLOUR, "bottom"),
                                      (v, np.argmin, _MIN_COLOUR, "top")):
            ci, si = np.unravel_index(int(pick(arr)), arr.shape)
            ax.annotate(str(ids[ci]), (xs[si], arr[ci, si]), xytext=(0, 6 if va == "bottom"
                                                                     else -6),
                        textcoords="offset points", ha="center", va=va, fontsize=8,
                        color=colour)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.ticklabel_format(axis="y", style="plain", useOffset=False)
    ax.autoscale_view()
    ax.margins(x=0.02, y=0.12)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_xlabel(labelled("x", "length", units))
    ax.set_ylabel(component_label(component, units))
    ax.set_title(title or f"{COMPONENT_TITLES[component]} ({component})", fontsize=10)


def _previous(result, component):
    prev = result.study.previous_envelope
    if prev is None:
        return None
    rows = prev[prev["component"] == component].sort_values("x [m]")
    if rows.empty:
        return None
    return rows["x [m]"].to_numpy(float), rows["min"].to_numpy(float), rows["max"].to_numpy(
        float)


def plot_sfbm(result, component, units="SI", show_previous=True, figsize=(9.0, 5.0)):
    """SFBM of one component along the stations, every case and the envelope.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    component : str
        ``"Vx"``, ``"Vy"``, ``"Vz"``, ``"Mx"``, ``"My"`` or ``"Mz"``.
    units : str
        ``"SI"`` or ``"US"``.
    show_previous : bool
        Draw the study's previous design envelope (dashed) when it has one.
    figsize : tuple of float
        [inch]

    Returns
    -------
    matplotlib.figure.Figure
    """
    check_units(units)
    j = component_index(component)
    fig = Figure(figsize=figsize, layout="constrained")
    ax = fig.add_subplot()
    draw_sfbm(ax, result.stations, result.loads[:, :, j], component, units,
              previous=_previous(result, component) if show_previous else None,
              case_ids=result.case_ids,
              title=f"{COMPONENT_TITLES[component]} ({component}), limit loads, "
                    f"{result.study.name}")
    ax.legend(loc="best", fontsize=8)
    return fig


def plot_sfbm_grid(result, units="SI", show_previous=True, figsize=(15.0, 8.0)):
    """All six components on a 2 x 3 grid: shears on the top row, moments below.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    units : str
        ``"SI"`` or ``"US"``.
    show_previous : bool
        Draw the previous design envelope where the study has one.
    figsize : tuple of float
        [inch]

    Returns
    -------
    matplotlib.figure.Figure
    """
    check_units(units)
    fig = Figure(figsize=figsize, layout="constrained")
    axes = fig.subplots(2, 3, sharex=True)
    for j, (ax, name) in enumerate(zip(axes.ravel(), COMPONENTS, strict=True)):
        draw_sfbm(ax, result.stations, result.loads[:, :, j], name, units,
                  previous=_previous(result, name) if show_previous else None,
                  case_ids=result.case_ids)
    axes[0, 0].legend(loc="best", fontsize=7)
    fig.suptitle(f"Limit shear force and bending moment, {result.study.name} "
                 f"({len(result.case_ids)} cases)")
    return fig


def draw_hull(ax, points, case_ids, hull, pair, units="SI"):
    """Draw a 2-D load envelope: every case a dot, the convex hull outlined, vertices labelled.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    points : array_like, shape (c, 2)
        The two components for every case (SI). [N] or [N m]
    case_ids : sequence of str
    hull : pandas.DataFrame
        Hull vertices in order (columns ``case`` and the two components, SI), as returned by
        :meth:`LoadsResult.hull`.
    pair : tuple of str
        Component names, e.g. ``("Vy", "Mz")``.
    units : str
        ``"SI"`` or ``"US"``.
    """
    kinds = [COMPONENT_KINDS[component_index(p)] for p in pair]
    pts = np.asarray(points, float)
    px = in_report_units(pts[:, 0], kinds[0], units)
    py = in_report_units(pts[:, 1], kinds[1], units)
    ax.scatter(px, py, s=10, color=_CASE_COLOUR, zorder=2, label=f"load cases ({len(px)})")
    hx = in_report_units(hull[pair[0]].to_numpy(float), kinds[0], units)
    hy = in_report_units(hull[pair[1]].to_numpy(float), kinds[1], units)
    ax.fill(hx, hy, color=_MAX_COLOUR, alpha=0.08, lw=0)
    ax.plot(np.append(hx, hx[:1]), np.append(hy, hy[:1]), color=_MAX_COLOUR, lw=1.8,
            marker="o", ms=5, zorder=3, label="convex hull")
    cx, cy = hx.mean(), hy.mean()
    for case, xv, yv in zip(hull["case"], hx, hy, strict=True):
        dx, dy = xv - cx, yv - cy
        ax.annotate(str(case), (xv, yv), xytext=(8 * np.sign(dx), 8 * np.sign(dy)),
                    textcoords="offset points", fontsize=8,
                    ha="left" if dx >= 0 else "right", va="bottom" if dy >= 0 else "top")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.axvline(0.0, color="k", lw=0.6)
    ax.margins(0.15)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_xlabel(component_label(pair[0], units))
    ax.set_ylabel(component_label(pair[1], units))


def plot_hull(result, station, pair=("Vy", "Mz"), units="SI", figsize=(7.0, 6.0)):
    """2-D envelope ("potato" plot) of two components at one cut station.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    station : str or int
        Station id or index.
    pair : tuple of str
        Component names, e.g. ``("Vy", "Mz")``.
    units : str
        ``"SI"`` or ``"US"``.
    figsize : tuple of float
        [inch]

    Returns
    -------
    matplotlib.figure.Figure
    """
    check_units(units)
    hull = result.hull(station, pair)  # validates the station and the pair
    index = (int(station) if isinstance(station, (int, np.integer))
             else list(result.station_ids).index(str(station)))
    cols = [component_index(p) for p in pair]
    fig = Figure(figsize=figsize, layout="constrained")
    ax = fig.add_subplot()
    draw_hull(ax, result.loads[:, index, :][:, cols], result.case_ids, hull, pair, units)
    x = float(in_report_units(result.stations[index], "length", units))
    ax.set_title(f"{pair[0]}-{pair[1]} limit envelope at {result.station_ids[index]} "
                 f"(x = {x:.4g} {unit_label(report_unit('length', units))}), "
                 f"{result.study.name}", fontsize=10)
    ax.legend(loc="best", fontsize=8)
    return fig

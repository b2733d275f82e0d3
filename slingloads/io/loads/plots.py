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

import textwrap

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from slingloads.analyses.envelopes import component_index
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
from slingloads.io.common.figures import PAGE_WIDTH, fix_margins
from slingloads.io.common.report import check_units, in_report_units, labelled, report_unit
from slingloads.io.common.units import unit_label
from slingloads.io.loads.tags import COMPONENT_TITLES

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


def wrap_title(text, width=72):
    """A plot title broken into lines of at most ``width`` characters (never cut)."""
    return "\n".join(textwrap.wrap(str(text), width)) or str(text)


def plot_sfbm(result, component, units="SI", show_previous=True, figsize=(PAGE_WIDTH, 4.2)):
    """SFBM of one component along the stations, every case and the envelope (LIMIT loads).

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
    fig = fix_margins(Figure(figsize=figsize), left=0.95, right=0.15, bottom=0.75, top=0.6)
    ax = fig.add_subplot()
    draw_sfbm(ax, result.stations, result.loads[:, :, j], component, units,
              previous=_previous(result, component) if show_previous else None,
              case_ids=result.case_ids,
              title=wrap_title(f"{COMPONENT_TITLES[component]} {component}, LIMIT loads, "
                               f"{len(result.case_ids)} cases: {result.study.name}"))
    # below the axes: a legend placed "best" costs a search over every case's line
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=7)
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
    fig.suptitle(wrap_title(f"LIMIT shear force and bending moment, {result.study.name} "
                            f"({len(result.case_ids)} cases)", 120))
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
    hx = in_report_units(hull.iloc[:, 1].to_numpy(float), kinds[0], units)
    hy = in_report_units(hull.iloc[:, 2].to_numpy(float), kinds[1], units)
    ax.fill(hx, hy, color=_MAX_COLOUR, alpha=0.08, lw=0)
    ax.plot(np.append(hx, hx[:1]), np.append(hy, hy[:1]), color=_MAX_COLOUR, lw=1.8,
            marker="o", ms=5, zorder=3, label="convex hull")
    _label_vertices(ax, hx, hy, [str(c) for c in hull["case"]])
    ax.axhline(0.0, color="k", lw=0.6)
    ax.axvline(0.0, color="k", lw=0.6)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_xlabel(component_label(pair[0], units))
    ax.set_ylabel(component_label(pair[1], units))


def _limits(values, margin=0.18):
    """Axis limits around ``values`` with a relative margin (room for the labels)."""
    lo, hi = float(np.min(values)), float(np.max(values))
    lo, hi = min(lo, 0.0), max(hi, 0.0)
    span = hi - lo or max(abs(hi), 1.0)
    return lo - margin * span, hi + margin * span


def _label_vertices(ax, hx, hy, labels, near=0.06):
    """Write the case of every hull vertex outward from the hull's centre; vertices closer
    than ``near`` (a fraction of the axes) share one label listing their cases, so that no
    two labels overlap."""
    xlim, ylim = _limits(np.append(hx, ax.dataLim.intervalx)), _limits(
        np.append(hy, ax.dataLim.intervaly))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    u = (np.asarray(hx) - xlim[0]) / (xlim[1] - xlim[0])
    v = (np.asarray(hy) - ylim[0]) / (ylim[1] - ylim[0])
    groups = []
    for k in range(len(u)):
        for group in groups:
            if np.hypot(u[k] - u[group[0]], v[k] - v[group[0]]) < near:
                group.append(k)
                break
        else:
            groups.append([k])
    cv = v.mean()
    for group in groups:
        gu, gv = u[group].mean(), v[group].mean()
        text = ", ".join(labels[k] for k in group)
        # outward from the hull's centre, but always towards the inside of the axes so that
        # no label leaves the figure
        side = np.sign(gv - cv) or 1.0
        if gu > 0.65:
            ha, dx = "right", -4
        elif gu < 0.35:
            ha, dx = "left", 4
        else:
            ha, dx = "center", 0
        if gv > 0.92:
            side = -1.0
        elif gv < 0.08:
            side = 1.0
        ax.annotate(text, (gu, gv), xycoords="axes fraction", xytext=(dx, 10 * side),
                    textcoords="offset points", fontsize=7, ha=ha,
                    va="bottom" if side > 0 else "top",
                    bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none",
                          "alpha": 0.8})


def plot_hull(result, station, pair=("Vy", "Mz"), units="SI", figsize=(PAGE_WIDTH, 5.0)):
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
    fig = fix_margins(Figure(figsize=figsize), left=0.95, right=0.2, bottom=0.8, top=0.6)
    ax = fig.add_subplot()
    draw_hull(ax, result.loads[:, index, :][:, cols], result.case_ids, hull, pair, units)
    x = float(in_report_units(result.stations[index], "length", units))
    ax.set_title(wrap_title(f"{pair[0]}-{pair[1]} envelope of the LIMIT loads at "
                            f"{result.station_ids[index]} (x = {x:.4g} "
                            f"{unit_label(report_unit('length', units))}): "
                            f"{result.study.name}"), fontsize=10)
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, fontsize=7)
    return fig


def _station_points(study):
    """Named hardpoints of a loads study: ``[(label, marker, colour, points (k, 3))]``. [m]"""
    hp = study.airframe.hardpoints
    points = [("rotor hub (hook load)", "*", "tab:red", hp.hub[None, :]),
              ("mast feet", "^", "tab:orange", hp.mast_feet)]
    if hp.chute is not None:
        points.append(("parachute attachment", "s", "tab:purple", hp.chute[None, :]))
    if study.fin is not None:
        points.append(("fin centre of pressure", "D", "tab:green",
                       np.asarray(study.fin.centre_of_pressure, float)[None, :]))
    if study.fuselage is not None:
        points.append(("fuselage aero moment reference", "P", "tab:brown",
                       np.asarray(study.fuselage.moment_reference, float)[None, :]))
    return points


def plot_station_diagram(study, units="SI", figsize=(PAGE_WIDTH, 5.6)):
    """Side and top views of the airframe: cut stations, mass items, CG, hub, mast feet,
    fin, parachute attachment and the loads reference axis.

    Parameters
    ----------
    study : slingloads.analyses.loads.LoadsStudy
    units : str
        ``"SI"`` or ``"US"`` (lengths in m or in).
    figsize : tuple of float
        [inch]

    Returns
    -------
    matplotlib.figure.Figure
        Two axes sharing x: the side view from the left (x aft, z up) with the station ids
        along its top, and the top view from above (x aft, y right, drawn upwards).
    """
    check_units(units)
    airframe = study.airframe
    items = airframe.mass_items

    def length(v):
        return in_report_units(v, "length", units)

    fig = fix_margins(Figure(figsize=figsize), left=0.75, right=0.2, bottom=1.25, top=1.15,
                      hspace=0.15)
    side, top = fig.subplots(2, 1, sharex=True)
    size = 15.0 + 160.0 * items.mass / items.mass.max()
    y0, z0 = airframe.reference_axis
    xs = length(airframe.stations)
    for ax, j, ref, name in ((side, 2, z0, "z"), (top, 1, y0, "y")):
        for x in xs:
            ax.axvline(x, color="0.6", lw=0.6, ls="--", zorder=0)
        ax.scatter(length(items.position[:, 0]), length(items.position[:, j]), s=size,
                   color="tab:blue", alpha=0.35, lw=0, label="mass items (area ~ mass)")
        ax.axhline(float(length(ref)), color="0.3", lw=0.8, ls=":",
                   label="loads reference axis")
        cg = items.cg
        ax.plot([length(cg[0])], [length(cg[j])], marker="+", ms=11, mew=2, color="k",
                ls="none", label="CG")
        for label, marker, colour, pts in _station_points(study):
            ax.plot(length(pts[:, 0]), length(pts[:, j]), marker=marker, ms=7, color=colour,
                    ls="none", label=label)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_ylabel(labelled(name, "length", units))
        ax.grid(True, lw=0.3, alpha=0.4)
    hub, axis = airframe.hardpoints.hub, airframe.hardpoints.mast_axis
    base = airframe.hardpoints.mast_feet.mean(axis=0)
    along = float(np.dot(hub - base, axis))
    mast = np.array([hub - along * axis, hub + 0.3 * max(along, 0.3) * axis])
    side.plot(length(mast[:, 0]), length(mast[:, 2]), color="tab:red", lw=1.2,
              label="mast axis")
    for ax, text in ((side, "side view from the left (x aft, z up)"),
                     (top, "top view from above (x aft, y right)")):
        ax.text(0.005, 0.97, text, transform=ax.transAxes, va="top", fontsize=8,
                bbox={"fc": "white", "ec": "none", "alpha": 0.8, "pad": 1})
    top.set_xlabel(labelled("x", "length", units))
    for x, name in zip(xs, airframe.station_ids, strict=True):  # ids along the top
        side.text(x, 1.02, str(name), transform=side.get_xaxis_transform(), rotation=90,
                  ha="center", va="bottom", fontsize=6)
    handles, labels = side.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=7)
    fig.suptitle(wrap_title(f"Cut stations and hardpoints: {airframe.name} "
                            f"({len(xs)} stations, {len(items.mass)} mass items)"),
                 fontsize=10)
    return fig

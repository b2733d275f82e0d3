"""Plots of the parachute sizing (object API only: every function returns a new Figure).

No pyplot state is touched, so the functions are safe in scripts, servers and tests. Angles are
shown in degrees; the results carry SI, and lengths, areas and moments are drawn in the unit
system asked for (``"SI"`` or ``"US"``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from slingloads.errors import InputError
from slingloads.io.common.figures import PAGE_WIDTH, cycle_colour, fix_margins
from slingloads.io.common.units import si_factor


def plot_yaw_linearisation(result):
    """Yawing-moment coefficient table against its linear fit, fuselage and fin (paper figs 4-5).

    Parameters
    ----------
    result : LinearisationResult

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 3.6)), left=0.9, right=0.15, bottom=0.5,
                      top=0.35, wspace=0.45)
    beta = np.degrees(result.beta)
    lo, hi = np.degrees(result.fit_range)
    panels = [("fuselage (about the suspension axis)", result.fuselage_cn,
               result.fuselage_slope, result.fuselage_intercept),
              ("cut-down fin (Cn_fin = -eta CY)", result.fin_cn, result.fin_slope,
               result.fin_intercept)]
    panels = [p for p in panels if p[1] is not None]
    axes = fig.subplots(1, len(panels), squeeze=False)[0]
    for ax, (title, cn, slope, icpt) in zip(axes, panels, strict=True):
        ax.plot(beta, cn, "o-", ms=3, label="table")
        fit = icpt + slope * result.beta
        ax.plot(beta, fit, "--", label=f"fit: {slope * np.pi / 180:.4g} /deg")
        ax.axvspan(lo, hi, color="0.9", zorder=0, label="fit range")
        ax.set_ylim(1.2 * min(cn.min(), 0) - 0.01, 1.2 * max(cn.max(), 0) + 0.01)
        ax.set(title=title, xlabel="sideslip beta [deg]", ylabel="Cn [-]")
        ax.grid(True, alpha=0.4)
        ax.legend(loc="lower right", fontsize=8)
    return fig


#: Units of the sizing plots: length, area, moment (pint strings) and their labels, those of
#: the report's tables (one unit per quantity in a report: a line of 396 in in the tables is
#: 396 in on the wake plot, a moment in lbf in is in lbf in on the moment plot).
PLOT_UNITS = {"SI": {"length": ("m", "m"), "area": ("m^2", "m^2"), "moment": ("N*m", "N m")},
              "US": {"length": ("in", "in"), "area": ("ft^2", "ft^2"),
                     "moment": ("lbf*in", "lbf in")}}


def _unit(units, kind):
    """(factor from SI, label) of ``kind`` in the unit system ``units``."""
    if units not in PLOT_UNITS:
        raise InputError(f"unknown unit system; valid are {sorted(PLOT_UNITS)}", units)
    unit, label = PLOT_UNITS[units][kind]
    return 1.0 / si_factor(unit, kind), label


def plot_static_moments(result, units="SI"):
    """Yawing moment of each contribution and their sum against sideslip, at the neutral area.

    Parameters
    ----------
    result : NeutralAreaResult
    units : str
        ``"SI"`` (N m, m^2) or ``"US"`` (lbf in, ft^2), the tables' units.
    """
    moment, m_label = _unit(units, "moment")
    area, a_label = _unit(units, "area")
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.5)), left=0.8, bottom=0.8, top=0.35)
    ax = fig.subplots()
    beta = np.degrees(result.beta)
    for name, values in result.moments.items():
        style = {"lw": 2.5, "color": "k"} if name == "total" else {}
        ax.plot(beta, values * moment, label=name, **style)
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set(title=f"Yawing moment about the suspension axis, parachute "
                 f"{result.area * area:.3g} {a_label}",
           xlabel="sideslip beta [deg]", ylabel=f"N, nose right [{m_label}]")
    ax.grid(True, alpha=0.4)
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=8)
    return fig


def plot_wake(result, units="SI"):
    """Wake dynamic-pressure ratio against distance, with the target and the chosen line.

    Parameters
    ----------
    result : LineLengthResult
    units : str
        ``"SI"`` (m) or ``"US"`` (in), the tables' units.
    """
    length, label = _unit(units, "length")
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.0)), left=0.8, bottom=0.5, top=0.35)
    ax = fig.subplots()
    ax.plot(np.asarray(result.distance) * length, result.ratio, label=result.wake_source)
    ax.axhline(result.target, color=cycle_colour(1), ls="--", label=f"target {result.target:.3g}")
    ax.axvline(result.line_length * length, color=cycle_colour(2), ls=":",
               label=f"line {result.line_length * length:.3g} {label}")
    if result.cable is not None:
        cable = result.cable.cable_length * length
        ax.axvline(cable, color=cycle_colour(3 if not result.cable.ok else 4),
                   ls="-.", label=f"carrier cable {cable:.3g} {label}")
    ax.set(xlabel=f"distance behind the attachment [{label}]", ylabel="q_wake / q [-]",
           title="Dynamic pressure in the fuselage wake")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    return fig


def readable_range(ax):
    """Plain tick labels on ``ax``'s y axis; a range of round-off only (a metric that is the
    same at every area, e.g. the peak sideslip of a gust, its angle) widened to +-5 % of its
    value (at least +-0.5), so that it reads as its value, not as matplotlib's offset
    notation of round-off ('1e-11+1.25265803e1')."""
    ax.ticklabel_format(axis="y", style="plain", useOffset=False)
    low, high = ax.get_ylim()
    middle = 0.5 * (low + high)
    if high - low <= 1e-6 * max(1.0, abs(middle)):
        half = max(0.05 * abs(middle), 0.5)
        ax.set_ylim(middle - half, middle + half)


def plot_sweep_metrics(sweep, units="SI", title=None):
    """Peak sideslip, peak yaw, damping ratios and settling time against area, per gust shape.

    Parameters
    ----------
    sweep : SweepResult
    units : str
        ``"SI"`` (m^2) or ``"US"`` (ft^2).
    title : str, optional
        The figure's title (default: a generic one).
    """
    area, a_label = _unit(units, "area")
    frame = sweep.to_frame()
    frame["area [m^2]"] = frame["area [m^2]"] * area
    lines = (title or "x").count("\n") + 1  # room for a title of several lines
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 6.0 + 0.2 * lines)), left=0.7, right=0.15,
                      bottom=0.8, top=0.25 + 0.22 * lines, wspace=0.3, hspace=0.3)
    axes = fig.subplots(2, 2).ravel()
    columns = [("peak beta [deg]", "peak sideslip [deg]"), ("peak psi [deg]", "peak yaw [deg]"),
               ("damping ratio log decrement [-]", "damping ratio [-]"),
               ("settling time [s]", "settling time [s]")]
    for ax, (col, label) in zip(axes, columns, strict=True):
        for kind, group in frame.groupby("gust", sort=False):
            ax.plot(group["area [m^2]"], group[col], label=kind)
        if col.startswith("damping"):
            first = frame.drop_duplicates("area [m^2]")
            ax.plot(first["area [m^2]"], first["damping ratio linear [-]"], "k--",
                    label="linearised")
        ax.set(xlabel=f"parachute flat-plate area [{a_label}]", ylabel=label)
        ax.axvline(sweep.static.area * area, color="0.5", ls=":", lw=1)
        ax.grid(True, alpha=0.4)
        readable_range(ax)
    handles, labels = axes[2].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=8)
    fig.suptitle(title or "Parachute sizing sweep (dotted: neutral static area)", fontsize=10,
                 y=0.995, va="top")
    return fig


def plot_time_histories(runs, indices=None, title=None, units="SI"):
    """Sideslip and yaw against time for chosen runs (the paper's figure 7).

    Parameters
    ----------
    runs : YawRuns or SweepResult
    indices : sequence of int, optional
        Runs to draw (default: all, at most 12).
    """
    area, a_label = _unit(units, "area")
    runs = getattr(runs, "runs", runs)
    h = runs.histories
    indices = list(range(min(len(runs.areas), 12))) if indices is None else list(indices)
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 5.0)), left=0.8, bottom=0.5, top=0.35,
                      hspace=0.1)
    ax_b, ax_p = fig.subplots(2, 1, sharex=True)
    for j in indices:
        label = f"{runs.areas[j] * area:.3g} {a_label}, {runs.gusts[j].kind}"
        ax_b.plot(h.time, np.degrees(h.beta[j]), label=label)
        ax_p.plot(h.time, np.degrees(h.psi[j]), label=label)
    ax_b.set(ylabel="sideslip beta [deg]", title=title or "1-DOF yaw response to lateral gusts")
    ax_p.set(ylabel="yaw psi [deg]", xlabel="time [s]")
    for ax in (ax_b, ax_p):
        ax.grid(True, alpha=0.4)
    ax_b.legend(fontsize=7, ncol=2)
    return fig


def plot_histories_by_gust(runs, indices, title=None, units="SI"):
    """Sideslip (solid) and yaw (dashed) against time, one panel per gust shape, for the runs
    ``indices`` (the paper's figure 7 for every gust shape).

    Parameters
    ----------
    runs : YawRuns or SweepResult
    indices : sequence of int
        Runs to draw; each goes on the panel of its gust shape, coloured by its area.
    title : str, optional
    units : str
        ``"SI"`` (m^2) or ``"US"`` (ft^2) for the areas in the legends.

    Returns
    -------
    matplotlib.figure.Figure
    """
    area, a_label = _unit(units, "area")
    runs = getattr(runs, "runs", runs)
    h = runs.histories
    indices = list(indices)
    kinds = list(dict.fromkeys(runs.gusts[j].kind for j in indices))
    if not kinds:
        raise InputError("no run to draw")
    cols = 2 if len(kinds) > 1 else 1
    rows = -(-len(kinds) // cols)
    lines = (title or "x").count("\n") + 1  # room for a title of several lines
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 2.3 * rows + 1.0 + 0.2 * lines)), left=0.7,
                      right=0.15, bottom=0.85, top=0.45 + 0.2 * lines, wspace=0.08, hspace=0.3)
    axes = np.atleast_1d(fig.subplots(rows, cols, sharex=True, sharey=True, squeeze=False)
                         ).ravel()
    areas = sorted({float(runs.areas[j]) for j in indices})
    colours = {a: cycle_colour(k) for k, a in enumerate(areas)}
    for ax, kind in zip(axes, kinds, strict=False):
        for j in (j for j in indices if runs.gusts[j].kind == kind):
            colour = colours[float(runs.areas[j])]
            ax.plot(h.time, np.degrees(h.beta[j]), color=colour, lw=1.0,
                    label=f"{runs.areas[j] * area:.3g} {a_label}")
            ax.plot(h.time, np.degrees(h.psi[j]), color=colour, lw=1.0, ls="--")
        ax.set_title(f"{kind} gust", fontsize=9)
        ax.grid(True, alpha=0.4)
    for ax in axes[len(kinds):]:
        ax.set_visible(False)
    for ax in axes[::cols]:
        ax.set_ylabel("angle [deg]")
    for ax in axes[-cols:]:
        ax.set_xlabel("time [s]")
    handles, labels = axes[0].get_legend_handles_labels()
    handles += [axes[0].plot([], [], color="0.3", lw=1.0)[0],
                axes[0].plot([], [], color="0.3", lw=1.0, ls="--")[0]]
    labels += ["sideslip beta", "yaw psi"]
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=7)
    fig.suptitle(title or "1-DOF yaw response to lateral gusts", fontsize=10, y=0.995,
                 va="top")
    return fig

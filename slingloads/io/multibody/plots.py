"""Plots of the multibody model (object API only: every function returns a new Figure).

No pyplot state is touched. Each plot of a model's objects (``plot_histories(simulation)``)
has a twin drawn from plain data (``plot_history_panels(runs)``: names, arrays, tables,
from :mod:`slingloads.io.multibody.figure_data`), which the report hands to the process that
draws its figures: that process then needs neither the model's compiled code nor scipy, so
it loads neither. Angles are shown in degrees; lengths of the views in the report's length
unit (``"SI"``: m, ``"US"``: in, as every length of a US report). Earth axes of the
simulation: X aft along the flight path (the carrier flies towards -X), Y right, Z up
(``docs/multibody.md``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from slingloads.analyses.verdicts import ratio_words
from slingloads.errors import InputError
from slingloads.io.common.figures import PAGE_WIDTH, cycle_colour, fix_margins
from slingloads.io.common.units import si_factor
from slingloads.io.multibody.figure_data import (
    HISTORY_PANELS,
    history_panels,
    view_points,
)

#: Length unit of the views: (pint unit, label) per unit system, the report tables' (a US
#: report gives its cable length and positions in inches).
VIEW_UNITS = {"SI": ("m", "m"), "US": ("in", "in")}
_MAX_LEGEND = 24


def plot_histories(simulation, title=None):
    """Yaw, sideslip, cable swing angles and cable tension against time, every run.

    Parameters
    ----------
    simulation : Simulation
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    return plot_history_panels(history_panels(simulation), title)


def plot_history_panels(runs, title=None):
    """:func:`plot_histories` from the runs' data (:func:`history_panels`)."""
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 8.8)), left=1.0, right=0.2, bottom=0.5,
                      top=0.45, hspace=0.1)
    axes = fig.subplots(len(HISTORY_PANELS), 1, sharex=True)
    for k, (name, h) in enumerate(runs):
        style = {"lw": 1.1, "color": cycle_colour(k), "ls": ("-", "--", ":", "-.")[k // 10 % 4]}
        for ax, (key, _) in zip(axes, HISTORY_PANELS, strict=True):
            values = h[key] if key == "tension ratio" else np.degrees(h[key])
            ax.plot(h["time"], values, label=name, **style)
    for ax, (_, label) in zip(axes, HISTORY_PANELS, strict=True):
        ax.set_ylabel(label, fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.4)
    axes[-1].set_xlabel("time [s]")
    if runs and len(runs) <= _MAX_LEGEND:
        axes[0].legend(fontsize=7, ncol=2, loc="upper right", framealpha=0.85)
    axes[0].set_title(title or "Multibody time histories", fontsize=10)
    return fig


def plot_eigenvalues(linear, title=None):
    """Eigenvalues of the linear model in the complex plane, every mode and the slow ones.

    Each mode is listed in the legend with its natural frequency and damping ratio, at the
    precision of the report's modes table (0.000 rad/s; a ratio by
    :func:`~slingloads.analyses.verdicts.ratio_words`); the right
    panel zooms on the modes slower than 2 rad/s (swing, yaw, pitch).

    Parameters
    ----------
    linear : LinearModel
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    return plot_modes(linear.modes_frame(), linear.verdict(), title)


def plot_modes(modes, verdict, title=None):
    """:func:`plot_eigenvalues` from the model's modes table (``LinearModel.modes_frame()``)
    and stability verdict."""
    legend_rows = -(-len(modes) // 2)
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 3.6 + 0.17 * legend_rows)), left=0.7,
                      right=0.15, bottom=0.6 + 0.17 * legend_rows, top=0.55, wspace=0.35)
    every, slow = fig.subplots(1, 2)
    for k, row in modes.iterrows():
        re, im = row["real [1/s]"], row["imag [rad/s]"]
        # at the precision of the modes table's cells (0.000 rad/s, a ratio's 0.000)
        label = (f"{row['mode']}: {row['natural frequency [rad/s]']:.3f} rad/s, "
                 f"zeta {ratio_words(row['damping ratio [-]'])}")
        style = {"ls": "none", "marker": "xo+sd^v<>p"[k // 10 % 10], "ms": 8, "mew": 2,
                 "color": cycle_colour(k)}
        for ax in (every, slow):
            ax.plot([re, re], [im, -im], label=label if ax is every else None, **style)
    for ax in (every, slow):
        ax.axvline(0.0, color="k", lw=0.8)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set(xlabel="real part [1/s]", ylabel="imaginary part [rad/s]")
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.4)
    every.set_title("every mode", fontsize=9)
    slow.set_title("modes slower than 2 rad/s", fontsize=9)
    wn = modes["natural frequency [rad/s]"].to_numpy()
    near = modes[wn < 2.0]
    if len(near):
        reach = max(0.05, 1.2 * near["real [1/s]"].abs().max())
        top = max(0.1, 1.2 * near["imag [rad/s]"].max())
        slow.set_xlim(-reach, 0.25 * reach)
        slow.set_ylim(-top, top)
    fig.legend(loc="lower center", ncol=2, fontsize=7, frameon=False)
    fig.suptitle(title or f"Eigenvalues about the trim ({verdict})", fontsize=10)
    return fig


def plot_views(system, states, outline, units="SI", title=None):
    """Side and top views of the system at given states (e.g. trim and largest excursion).

    Parameters
    ----------
    system : SlingSystem
    states : sequence of (str, state, info)
        Label, state of the equations and its reported quantities, drawn in turn (the first
        in grey, dashed).
    outline : dict
        Airframe polylines (see :func:`system_points`). [m]
    units : str
        ``"SI"`` (m) or ``"US"`` (in).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    return plot_view_points(view_points(system, states, outline), units, title)


def plot_view_points(views, units="SI", title=None):
    """:func:`plot_views` from the system's points at each state (:func:`view_points`)."""
    if units not in VIEW_UNITS:
        raise InputError(f"unknown unit system; valid are {sorted(VIEW_UNITS)}", units)
    unit, label = VIEW_UNITS[units]
    scale = 1.0 / si_factor(unit, "length")
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.4)), left=0.7, right=0.15,
                      bottom=0.55 + 0.17 * len(views), top=0.7, wspace=0.35)
    side, top = fig.subplots(1, 2)
    for k, (name, points) in enumerate(views):
        color, ls = ("0.55", "--") if k == 0 else (cycle_colour(k - 1), "-")
        for ax, (i, j) in ((side, (0, 2)), (top, (0, 1))):
            for key, line in points.items():
                line = line * scale
                if key in ("hook", "CG", "canopy"):
                    marker = {"hook": "v", "CG": "o", "canopy": "D"}[key]
                    ax.plot(line[:, i], line[:, j], marker, color=color, ms=6)
                else:
                    ax.plot(line[:, i], line[:, j], ls=ls, color=color,
                            lw=2.0 if key == "fuselage" else 1.2)
        side.plot([], [], ls=ls, color=color, label=name)  # one legend entry per state
    side.set(xlabel=f"X aft [{label}]", ylabel=f"Z up [{label}]",
             title="side view (flight towards -X)")
    top.set(xlabel=f"X aft [{label}]", ylabel=f"Y right [{label}]",
            title="top view, from above\n(flight towards -X)")
    side.set_title("side view\n(flight towards -X)")
    for ax in (side, top):
        ax.set_aspect("equal", adjustable="datalim")
        ax.tick_params(labelsize=8)
        ax.title.set_fontsize(9)
        ax.grid(True, alpha=0.4)
    fig.legend(loc="lower center", fontsize=7, frameon=False)
    if title:
        fig.suptitle(title, fontsize=10)
    return fig

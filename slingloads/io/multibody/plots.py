"""Plots of the multibody model (object API only: every function returns a new Figure).

No pyplot state is touched. Angles are shown in degrees; lengths of the views in the unit
system asked for (``"SI"``: m, ``"US"``: ft). Earth axes of the simulation: X aft along the flight
path (the carrier flies towards -X), Y right, Z up (``docs/multibody.md``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from slingloads.errors import InputError
from slingloads.io.common.figures import PAGE_WIDTH, cycle_colour, fix_margins
from slingloads.io.common.units import si_factor
from slingloads.models.multibody.equations import INFO
from slingloads.models.multibody.parachute_line import line_direction
from slingloads.models.multibody.rigid_body import rotation_matrix

#: Length unit of the views: (pint unit, label) per unit system.
VIEW_UNITS = {"SI": ("m", "m"), "US": ("ft", "ft")}
#: Panels of the histories plot: (history key, axis label).
HISTORY_PANELS = (("yaw", "yaw, heading from\nthe flight path [deg]"),
                  ("beta", "sideslip beta [deg]"),
                  ("swing longitudinal", "cable swing\nlongitudinal [deg]"),
                  ("swing lateral", "cable swing\nlateral [deg]"),
                  ("tension ratio", "cable tension /\nweight [-]"))
_INFO = {name: i for i, name in enumerate(INFO)}
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
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 8.8)), left=1.0, right=0.2, bottom=0.5,
                      top=0.45, hspace=0.1)
    axes = fig.subplots(len(HISTORY_PANELS), 1, sharex=True)
    for k, run in enumerate(simulation.runs):
        h = run.histories()
        style = {"lw": 1.1, "color": cycle_colour(k), "ls": ("-", "--", ":", "-.")[k // 10 % 4]}
        for ax, (key, _) in zip(axes, HISTORY_PANELS, strict=True):
            values = h[key] if key == "tension ratio" else np.degrees(h[key])
            ax.plot(h["time"], values, label=run.name, **style)
    for ax, (_, label) in zip(axes, HISTORY_PANELS, strict=True):
        ax.set_ylabel(label, fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.4)
    axes[-1].set_xlabel("time [s]")
    if simulation.runs and len(simulation.runs) <= _MAX_LEGEND:
        axes[0].legend(fontsize=7, ncol=2, loc="upper right", framealpha=0.85)
    axes[0].set_title(title or "Multibody time histories", fontsize=10)
    return fig


def plot_eigenvalues(linear, title=None):
    """Eigenvalues of the linear model in the complex plane, every mode and the slow ones.

    Each mode is listed in the legend with its natural frequency and damping ratio; the right
    panel zooms on the modes slower than 2 rad/s (swing, yaw, pitch).

    Parameters
    ----------
    linear : LinearModel
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    modes = linear.modes_frame()
    legend_rows = -(-len(modes) // 2)
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 3.6 + 0.17 * legend_rows)), left=0.7,
                      right=0.15, bottom=0.6 + 0.17 * legend_rows, top=0.55, wspace=0.35)
    every, slow = fig.subplots(1, 2)
    for k, row in modes.iterrows():
        re, im = row["real [1/s]"], row["imag [rad/s]"]
        label = (f"{row['mode']}: {row['natural frequency [rad/s]']:.3g} rad/s, "
                 f"zeta {row['damping ratio [-]']:.3g}")
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
    fig.suptitle(title or f"Eigenvalues about the trim ({linear.verdict()})", fontsize=10)
    return fig


def system_points(system, state, info, outline):
    """Earth-axis points of the system at a state: hook, hub, CG, outline, attachment, canopy.

    Parameters
    ----------
    system : SlingSystem
    state : array_like, shape (20,)
        State of the equations.
    info : array_like
        Reported quantities at that state (:data:`~slingloads.models.multibody.equations.INFO`).
    outline : dict of str to array_like, shape (n, 3)
        Polylines of the airframe in airframe axes (e.g. nose - CG - tail, CG - hub). [m]

    Returns
    -------
    dict of str to ndarray, shape (n, 3)
        Relative to the hook. [m]
    """
    x = np.asarray(state, float)
    r = rotation_matrix(x[9:13] / np.linalg.norm(x[9:13]))
    cg = system.body.cg
    where = x[3:6]

    def earth(points):
        return where + (np.atleast_2d(np.asarray(points, float)) - cg) @ r.T

    hub = earth(system.hardpoints.hub)
    out = {"hook": np.zeros((1, 3)), "cable": np.vstack([np.zeros(3), hub]), "CG": earth(cg)}
    for name, line in outline.items():
        out[name] = earth(line)
    if system.parachute is not None:
        attach = system.hardpoints.chute
        if system.parachute.kind == "hinged":
            e, _, _ = line_direction(x[16], x[17])
            e = np.array(e)
        else:
            e = np.asarray(info, float)[_INFO["line_x"]:_INFO["line_z"] + 1]
            e = e / np.linalg.norm(e) if np.all(np.isfinite(e)) and np.any(e) else \
                np.array([1.0, 0.0, 0.0])
        canopy = attach + system.parachute.line_length * e
        out["parachute line"] = earth(np.vstack([attach, canopy]))
        out["canopy"] = earth(canopy)
    return out


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
        ``"SI"`` (m) or ``"US"`` (ft).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    if units not in VIEW_UNITS:
        raise InputError(f"unknown unit system; valid are {sorted(VIEW_UNITS)}", units)
    unit, label = VIEW_UNITS[units]
    scale = 1.0 / si_factor(unit, "length")
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.4)), left=0.7, right=0.15,
                      bottom=0.55 + 0.17 * len(states), top=0.7, wspace=0.35)
    side, top = fig.subplots(1, 2)
    for k, (name, state, info) in enumerate(states):
        points = system_points(system, state, info, outline)
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
            ax.plot([], [], ls=ls, color=color, label=name)
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

"""Plots of the lateral-step pendulum: time histories of one run, the largest load angle
against the carrier's acceleration for each rope length, and its sensitivity to the
uncertain inputs.

Every function builds and returns a :class:`matplotlib.figure.Figure` through the object API
(no pyplot, no global state). Angles are drawn in degrees beside the CS-29.865 30 deg line.
"""

from __future__ import annotations

import textwrap

import numpy as np
from matplotlib.figure import Figure

from slingloads.analyses.hook_loads import angle_words
from slingloads.analyses.lateral import REGULATORY_ANGLE
from slingloads.constants import FOOT, G0
from slingloads.io.common.figures import PAGE_WIDTH, cycle_colour, fix_margins

_REG_STYLE = {"color": "tab:red", "linestyle": "--", "linewidth": 1.0}


def _rope(length, units):
    """A rope length in a title or legend: in m with the paper's feet beside (SI), in the
    report's length unit alone in US units (every rope length of a US report in inches)."""
    if units == "SI":
        return f"rope {length:.3g} m ({length / FOOT:.0f} ft)"
    from slingloads.io.common.report import in_report_units, report_unit

    return f"rope {in_report_units(length, 'length', units):.4g} {report_unit('length', units)}"


def plot_time_histories(run, regulatory_angle=REGULATORY_ANGLE, title=None, units="SI"):
    """Time histories of one run: angles, tension and hub load, carrier motion.

    Parameters
    ----------
    run : slingloads.analyses.lateral.LateralRun
    regulatory_angle : float
        Angle drawn as the reference line (CS-29.865: 30 deg). [rad]
    title : str, optional
        Figure title (default: the body, rope length and motion).
    units : str
        Report unit system of the carrier's displacement and the title (``"SI"``, ``"US"``).

    Returns
    -------
    matplotlib.figure.Figure
        Three axes: angles [deg] with +-30 deg lines; T/(m g) [-]; carrier S [m or in] and
        S'' [g].
    """
    from slingloads.io.common.report import in_report_units, labelled
    from slingloads.io.common.units import report_text

    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 7.6)), left=0.8, right=0.75, bottom=0.5,
                      top=0.55, hspace=0.12)
    ax_angle, ax_tension, ax_carrier = fig.subplots(3, 1, sharex=True)
    t = run.t
    ax_angle.plot(t, np.degrees(run.theta1), label="rope angle theta1 (hub right of hook +)")
    ax_angle.plot(t, np.degrees(run.roll), label="airframe roll (right side down +)")
    ax_angle.plot(t, np.degrees(run.load_angle), color="black", linewidth=1.6,
                  label="load angle theta1 - theta2")
    reg = np.degrees(regulatory_angle)
    ax_angle.axhline(reg, label=f"CS-29.865 {reg:.0f} deg", **_REG_STYLE)
    ax_angle.axhline(-reg, **_REG_STYLE)
    metrics = run.metrics
    t_peak = float(metrics.t_max_load_angle)
    peak = np.degrees(np.interp(t_peak, t, run.load_angle))
    ax_angle.plot([t_peak], [peak], "o", color="black",
                  label="max |theta1 - theta2| = "
                  f"{angle_words(np.degrees(metrics.max_load_angle))} deg")
    ax_angle.set_ylabel("angle [deg]")
    ax_angle.legend(loc="upper right", fontsize=7, ncol=2, framealpha=0.85)
    ax_angle.grid(True, alpha=0.3)

    ax_tension.plot(t, run.tension_ratio, color="tab:purple", label="T/(m g)")
    ax_tension.axhline(1.0, color="0.5", linewidth=0.8)
    if np.any(run.tension <= 0):
        ax_tension.fill_between(t, 0, 1, where=run.tension <= 0, color="tab:orange", alpha=0.3,
                                transform=ax_tension.get_xaxis_transform(), label="slack")
    ax_tension.set_ylabel("T/(m g) [-]")
    ax_tension.legend(loc="upper right", fontsize=7, framealpha=0.85)
    ax_tension.grid(True, alpha=0.3)

    ax_carrier.plot(t, in_report_units(run.carrier[0], "length", units), color="tab:green",
                    label="S")
    ax_carrier.set_ylabel(labelled("carrier S", "length", units))
    ax_carrier.set_xlabel("t [s]")
    twin = ax_carrier.twinx()
    twin.plot(t, run.carrier[2] / G0, color="tab:olive", linestyle=":", label="S''")
    twin.set_ylabel("carrier S'' [g]")
    ax_carrier.grid(True, alpha=0.3)

    if title is None:
        p = run.pendulum
        title = (f"{p.body.name}, {_rope(p.rope_length, units)}: "
                 f"{report_text(run.motion.describe(), units)}")
    fig.suptitle("\n".join(textwrap.wrap(title, 90)), fontsize=10)
    return fig


#: Line styles of the motion types on the max-angle plot.
_MOTION_STYLES = {"quintic_step": ("-", "o"), "cycloidal_step": ("-", "D"),
                  "constant_acceleration": ("--", "s"), "time_history": (":", "^")}


def plot_max_angle_vs_acceleration(study, title=None, units="SI"):
    """Largest load angle against the carrier's peak acceleration, one line per rope length
    and motion type.

    Each point is the largest max |theta1 - theta2| over the bodies, durations and the stated
    ranges of roll inertia, CG and rope length of one motion type at that nominal rope length
    and acceleration; different motion types are never joined by a line (colour: rope length;
    line style and marker: motion type). Velocity steps (no finite acceleration) are left
    out. The 30 deg line and the recommended design angle are drawn beside.

    Parameters
    ----------
    study : slingloads.analyses.lateral.LateralStudy
    title : str, optional
    units : str
        Report unit system of the rope lengths in the legend (``"SI"``, ``"US"``).

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 5.2)), left=0.75, right=0.2, bottom=1.3,
                      top=0.4)
    ax = fig.subplots()
    runs = study.to_frame()
    runs = runs[np.isfinite(runs["peak S'' [m/s^2]"])]
    rope = "nominal rope length [m]"
    envelope = (runs.groupby([rope, "motion", "peak S'' [g]"], as_index=False)
                ["max |theta1 - theta2| [deg]"].max())
    lengths = sorted(envelope[rope].unique())
    colours = {length: cycle_colour(k) for k, length in enumerate(lengths)}
    for (length, motion), rows in envelope.groupby([rope, "motion"]):
        rows = rows.sort_values("peak S'' [g]")
        style, marker = _MOTION_STYLES.get(motion, ("-.", "v"))
        ax.plot(rows["peak S'' [g]"], rows["max |theta1 - theta2| [deg]"], ls=style,
                marker=marker, color=colours[length], ms=5)
    # one legend entry per rope (colour) and per motion type (line style and marker)
    for length in lengths:
        ax.plot([], [], color=colours[length], lw=2,
                label=_rope(length, units))
    for motion in sorted(envelope["motion"].unique()):
        style, marker = _MOTION_STYLES.get(motion, ("-.", "v"))
        ax.plot([], [], color="0.3", ls=style, marker=marker, ms=5,
                label=motion.replace("_", " "))
    reg = np.degrees(study.regulatory_angle)
    ax.axhline(reg, label=f"CS-29.865 {reg:.0f} deg", **_REG_STYLE)
    if np.isfinite(study.recommended_angle):  # none outside the model's domain
        ax.axhline(np.degrees(study.recommended_angle), color="tab:green", linestyle="-.",
                   label=f"recommended {np.degrees(study.recommended_angle):.1f} deg "
                         f"(margin {study.margin:g})")
    ax.set_xlabel("carrier peak lateral acceleration [g]")
    ax.set_ylabel("max |theta1 - theta2| [deg]")
    ax.set_ylim(bottom=0.0)
    ax.grid(True, alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=7)
    ax.set_title(title or "Largest load angle from the mast against carrier acceleration",
                 fontsize="medium")
    return fig


def plot_shear_at_angles(comparison, component="Vy", units="SI", title=None):
    """Envelope max |load| of the hook cases along the stations at 30 deg and at the
    recommended angle.

    Parameters
    ----------
    comparison : slingloads.analyses.hook_angle.HookAngleComparison
    component : str
        Load component, default the Y shear ``"Vy"``.
    units : str
        ``"SI"`` or ``"US"``: axes in the report unit system.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
    from slingloads.io.common.report import in_report_units, labelled

    j = COMPONENTS.index(component)
    kind = COMPONENT_KINDS[j]
    x = in_report_units(comparison.stations, "length", units)
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.2)), left=0.95, right=0.2, bottom=0.5,
                      top=0.4)
    ax = fig.subplots()
    ref, at = np.degrees(comparison.reference_angle), np.degrees(comparison.angle)
    ax.plot(x, in_report_units(comparison.reference[:, j], kind, units), color="tab:red",
            marker=".", label=f"hook cone {angle_words(ref)} deg (CS-29.865)")
    ax.plot(x, in_report_units(comparison.at_angle[:, j], kind, units), color="tab:green",
            marker=".", label=f"hook cone {angle_words(at)} deg (recommended)")
    big_ref, big_at = comparison.reference[:, j].max(), comparison.at_angle[:, j].max()
    if big_ref > 0:
        ax.plot([], [], " ", label=f"largest value: {100.0 * (big_at / big_ref - 1.0):+.1f} %")
    ax.set_xlabel(labelled("x", "length", units))
    ax.set_ylabel(labelled(f"max |{component}|", kind, units))
    ax.set_ylim(bottom=0.0)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize="small")
    ax.set_title(title or f"Envelope of the hook cases, {component}, LIMIT loads",
                 fontsize="medium")
    return fig


def plot_sensitivity(study, title=None):
    """Largest load angle and cable tension factor against the factor on each uncertain
    parameter (roll inertia, CG below hub, rope length).

    Solid lines: the other two parameters nominal (one at a time); dashed: over their whole
    ranges (the envelope). The 30 deg line, the recommended angle and the hook load factor
    Nz (when given) are drawn beside.

    Parameters
    ----------
    study : slingloads.analyses.lateral.LateralStudy
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
        Two axes: load angle [deg] and T/(m g) [-] against the factor [-].
    """
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 5.4)), left=0.7, right=0.15, bottom=1.75,
                      top=0.65, wspace=0.3)
    ax_angle, ax_tension = fig.subplots(1, 2, sharex=True)
    frame = study.sensitivity_frame()
    for (name, rows), color in zip(frame.groupby("parameter", sort=False),
                                   ("tab:blue", "tab:orange", "tab:purple"), strict=False):
        f = rows["factor [-]"]
        ax_angle.plot(f, rows["max load angle, others nominal [deg]"], marker="o",
                      color=color, label=f"{name} (others nominal)")
        ax_angle.plot(f, rows["max load angle, others over their ranges [deg]"], marker=".",
                      color=color, linestyle="--", label=f"{name} (others over ranges)")
        ax_tension.plot(f, rows["max T/(m g), others nominal [-]"], marker="o", color=color)
        ax_tension.plot(f, rows["max T/(m g), others over their ranges [-]"], marker=".",
                        color=color, linestyle="--")
    reg = np.degrees(study.regulatory_angle)
    ax_angle.axhline(reg, label=f"CS-29.865 {reg:.0f} deg", **_REG_STYLE)
    if np.isfinite(study.recommended_angle):  # none outside the model's domain
        ax_angle.axhline(np.degrees(study.recommended_angle), color="tab:green",
                         linestyle="-.",
                         label=f"recommended {np.degrees(study.recommended_angle):.1f} deg")
    if study.hook_load_factor is not None:
        ax_tension.axhline(study.hook_load_factor, label=f"Nz {study.hook_load_factor:g}",
                           **_REG_STYLE)
        ax_tension.legend(loc="best", fontsize=7)
    ax_angle.set_ylabel("max |theta1 - theta2| [deg]")
    ax_tension.set_ylabel("max T/(m g) [-]")
    for ax in (ax_angle, ax_tension):
        ax.set_xlabel("factor on the nominal value [-]", fontsize=9)
        ax.grid(True, alpha=0.3)
    ax_angle.set_ylim(bottom=0.0)
    handles, labels = ax_angle.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=7)
    title = title or ("Sensitivity of the largest load angle and cable tension to roll "
                      "inertia, CG below hub and rope length")
    fig.suptitle("\n".join(textwrap.wrap(title, 90)), fontsize=10)
    return fig

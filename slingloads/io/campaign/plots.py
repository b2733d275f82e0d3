"""Plots of the campaign (object API only: every function returns a new Figure).

Angles in degrees; airspeeds in kt (both unit systems); density altitudes, cable lengths,
areas, masses and accelerations in the unit system asked for (``"SI"``: m, m, m^2, kg,
m/s^2; ``"US"``: ft, in, ft^2, lb, ft/s^2), as every report writes each quantity
(:func:`~slingloads.io.common.report.quantity_text`). The histories come from the campaign
result's store.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from slingloads.analyses.verdicts import STABLE, UNSTABLE
from slingloads.constants import FOOT, KNOT, POUND
from slingloads.errors import InputError
from slingloads.io.campaign.words import mass_text
from slingloads.io.common.figures import PAGE_WIDTH, fix_margins
from slingloads.io.common.report import quantity_text

YAW = "yaw (heading from flight path) [deg]"
BETA = "beta [deg]"


def _legend(ax, **kwargs):
    """A legend on ``ax`` when something on it has a label (matplotlib warns otherwise)."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(**kwargs)


def _small(ax):
    """Tick labels, axis labels and title at the sizes of a 7 in wide figure."""
    ax.tick_params(labelsize=7)
    ax.xaxis.label.set_fontsize(8)
    ax.yaxis.label.set_fontsize(8)
    ax.title.set_fontsize(9)


def _mass(value, units):
    """A mass [kg] in a title: in kg (SI) or lb (US), to the unit (the report's words)."""
    return mass_text(value, units)


def _condition(row, skip=(), neutral_area=None, units="SI"):
    """The base condition of a run as a line of text: area, airspeed, mass, density altitude,
    cable and carrier (those of ``skip``, the factors a figure varies, left out)."""
    scale, unit = _area(units)
    parts = []
    if "area factor [-]" not in skip and "area factor [-]" in row:
        area = row.get("area [m^2]", np.nan)
        parts.append(f"area {row['area factor [-]']:.3g} x neutral"
                     + (f" ({area * scale:.3g} {unit})" if np.isfinite(area) else ""))
    if "airspeed EAS [m/s]" not in skip and "airspeed EAS [m/s]" in row:
        parts.append(f"{row['airspeed EAS [m/s]'] / KNOT:.0f} KEAS")
    if "mass case" not in skip and "mass [kg]" in row:
        parts.append(f"mass {row.get('mass case', '')} {_mass(row['mass [kg]'], units)}"
                     .replace("  ", " "))
    if "density altitude [m]" not in skip and "density altitude [m]" in row:
        altitude = quantity_text(row["density altitude [m]"], "altitude", units)
        parts.append(f"{altitude} density altitude")
    if "cable length [m]" not in skip and "cable length [m]" in row:
        parts.append(f"cable {quantity_text(row['cable length [m]'], 'length', units)}")
    if "carrier" not in skip and "carrier" in row:
        parts.append(f"carrier {row['carrier']}")
    return ", ".join(parts)


def _values(frame, column, scale=1.0, fmt="{:.0f}"):
    return "/".join(fmt.format(v * scale) for v in sorted(frame[column].unique()))


def _quantities(frame, column, kind, units):
    """The distinct SI values of ``column`` in report units: ``0/1,524 m``, ``720/1,200 in``."""
    values = [quantity_text(v, kind, units) for v in sorted(frame[column].unique())]
    unit = values[0].rsplit(" ", 1)[1] if values else ""
    return "/".join(v.rsplit(" ", 1)[0] for v in values) + f" {unit}"


def _area(units):
    if units not in ("SI", "US"):
        raise InputError("unknown unit system; valid are ['SI', 'US']", units)
    return (1.0, "m^2") if units == "SI" else (1.0 / FOOT**2, "ft^2")


def plot_selection(result, units="SI"):
    """Metrics against the area factor: stable runs, least yaw-mode damping ratio, largest
    trimmed swing angle (the drag proxy), with the smallest stable and recommended areas."""
    sel = result.selection
    by = sel.by_area
    f = by["area factor [-]"].to_numpy()
    # room above for the figure title over the two-line panel title, below for one legend
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 3.6)), left=0.5, right=0.1, bottom=0.85,
                      top=0.6, wspace=0.45)
    axes = fig.subplots(1, 3)
    axes[0].bar(f, by["runs"], width=0.08 * (np.ptp(f) or 1), color="0.85", label="runs")
    axes[0].bar(f, by["stable runs"], width=0.08 * (np.ptp(f) or 1), label="stable runs")
    axes[0].set(ylabel="runs", title="stability")
    axes[1].plot(f, by["least yaw-mode damping ratio [-]"], "o-")
    axes[1].axhline(sel.criteria.min_damping, color="r", ls="--",
                    label=f"criterion {sel.criteria.min_damping:g}")
    axes[1].set(ylabel="damping ratio [-]", title="least yaw-mode damping")
    axes[2].plot(f, by["largest trimmed swing angle [deg]"], "o-")
    axes[2].set(ylabel="swing angle [deg]", title="drag proxy: largest\ntrimmed swing angle")
    m = result.metrics
    scale, unit = _area(units)
    masses = (_values(m, "mass [kg]") + " kg" if units == "SI"
              else _values(m, "mass [kg]", 1 / POUND) + " lb")
    fig.suptitle(f"over {_values(m, 'airspeed EAS [m/s]', 1 / KNOT)} KEAS, masses "
                 f"{masses}, {_quantities(m, 'density altitude [m]', 'altitude', units)}"
                 f" density altitude, cables "
                 f"{_quantities(m, 'cable length [m]', 'length', units)}, carrier "
                 f"{'/'.join(dict.fromkeys(m['carrier']))}; neutral area "
                 f"{result.neutral.area * scale:.3g} {unit}", fontsize=7, y=0.995)
    for ax in axes:
        ax.set_xlabel("area / neutral area [-]")
        ax.grid(True, alpha=0.4)
        for value, style, label in ((sel.smallest_stable, ":", "smallest stable"),
                                    (sel.recommended, "-", "recommended")):
            if np.isfinite(value):
                ax.axvline(value, color="g", ls=style, lw=1.2, label=label)
        _small(ax)
    # one legend for the three panels, below them (a legend per panel repeated the area
    # lines three times, side by side over one another)
    entries = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(label, handle)
    if entries:
        fig.legend(list(entries.values()), list(entries), loc="lower center", ncol=5,
                   fontsize=7)
    return fig


def plot_sweep(result, runs, factor, title, units="SI"):
    """Yaw and sideslip histories of runs that differ by one factor (paper figures 9-13);
    masses and areas of the legend and title in ``units``."""
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 5.0)), left=0.7, right=0.15, bottom=0.5,
                      top=0.4, hspace=0.1)
    axes = fig.subplots(2, 1, sharex=True)
    frame = result.metrics.set_index("run")
    for run in runs:
        h = result.history(run)
        label = _label(frame.loc[run], factor, units)
        axes[0].plot(h["time [s]"], h[YAW], lw=1.1, label=label)
        axes[1].plot(h["time [s]"], h[BETA], lw=1.1, label=label)
    base = frame.loc[runs[0]] if runs else {}
    axes[0].set(ylabel="yaw (heading) [deg]",
                title=f"{title}\n{_condition(base, skip=(factor,), units=units)}" if runs
                else title)
    axes[1].set(ylabel="sideslip beta [deg]", xlabel="time [s]")
    for ax in axes:
        ax.grid(True, alpha=0.4)
        _small(ax)
    _legend(axes[0], fontsize=7, ncols=2)
    return fig


def _label(row, factor, units="SI"):
    value = row[factor]
    if factor == "area factor [-]":
        return f"{value:.3g} x neutral area"
    if factor == "airspeed EAS [m/s]":
        return f"{value / KNOT:.0f} KEAS"
    if factor == "density altitude [m]":
        return f"{quantity_text(value, 'altitude', units)} density altitude"
    if factor == "cable length [m]":
        return f"cable {quantity_text(value, 'length', units)}"
    if factor == "mass case":
        return f"mass {value} ({_mass(row['mass [kg]'], units)})"
    return f"carrier {value}"


#: Colour-scale labels: the quantity, its unit and what its sign or range means, in the
#: linear model's verdict words (:data:`~slingloads.analyses.verdicts.STABLE`...: the tables'
#: "linear verdict"; convergent and divergent name responses, not eigenvalues).
DAMPING_SCALE = (f"yaw-mode damping ratio [-]\n> 0 {STABLE}, < 0 {UNSTABLE}\n"
                 f"(-1: an {UNSTABLE} real root)")
REAL_PART_SCALE = (f"largest real part of the eigenvalues [1/s]\n< 0 {STABLE}, "
                   f"> 0 {UNSTABLE}")
AREA_FACTOR_SCALE = "parachute area / neutral static area [-]"


def cell_edges(centres):
    """Edges of the cells centred on sorted ``centres``: midway between neighbours, the end
    cells as wide as their neighbour's half spacing; a single centre gets a cell of +-5 % of
    its value (+-0.5 when it is 0).

    Parameters
    ----------
    centres : array_like, shape (n,)
        Increasing cell centres (any unit).

    Returns
    -------
    ndarray, shape (n + 1,)
    """
    c = np.asarray(centres, float)
    if c.size == 1:
        half = 0.05 * abs(c[0]) or 0.5
        return np.array([c[0] - half, c[0] + half])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])


def plot_stability_map(stability, neutral_area, units="SI", chosen_area=None):
    """Yaw-mode damping ratio and largest real part over area x airspeed (one column per
    density altitude), with the minimum stable area per speed, the neutral static area
    (1.0 x) and the chosen area [m^2] (when given); the map's mass, cable and carrier in the
    title."""
    scale, unit = _area(units)
    points = stability.points
    altitudes = sorted(points["density altitude [m]"].unique())
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 6.6)), left=0.7, right=0.1, bottom=0.8,
                      top=0.55, wspace=0.6, hspace=0.45)
    axes = fig.subplots(2, len(altitudes), squeeze=False)
    quantities = (("yaw mode damping ratio [-]", DAMPING_SCALE, "viridis"),
                  ("largest real part [1/s]", REAL_PART_SCALE, "coolwarm"))
    for j, h in enumerate(altitudes):
        for i, (column, label, cmap) in enumerate(quantities):
            ax = axes[i, j]
            grid = stability.grid(column, h)
            speeds = grid.columns.to_numpy() / KNOT
            areas = grid.index.to_numpy() * neutral_area * scale
            values = grid.to_numpy(float)
            # cell edges (a single airspeed or area gets a cell of its own width: matplotlib's
            # "nearest" shading draws nothing for a single column)
            x_edges, y_edges = cell_edges(speeds), cell_edges(areas)
            if column.startswith("largest"):
                bound = np.nanmax(np.abs(values)) if np.any(np.isfinite(values)) else 1.0
                mesh = ax.pcolormesh(x_edges, y_edges, values, shading="flat", cmap=cmap,
                                     vmin=-bound, vmax=bound)
            else:
                mesh = ax.pcolormesh(x_edges, y_edges, values, shading="flat", cmap=cmap)
            bar = fig.colorbar(mesh, ax=ax)
            bar.set_label(label, fontsize=7)
            bar.ax.tick_params(labelsize=7)
            minimum = stability.minimum[np.isclose(stability.minimum["density altitude [m]"],
                                                   h)]
            least = minimum["minimum stable area [m^2]"].to_numpy(float) * scale
            if np.isfinite(least).any():  # no line (and no legend entry) when none is stable
                ax.plot(minimum["airspeed EAS [m/s]"] / KNOT, least, "k.-",
                        label="minimum stable area")
            ax.axhline(neutral_area * scale, color="k", ls=":", lw=1.0,
                       label="1.0 x neutral static area")
            if chosen_area is not None and np.isfinite(chosen_area):
                ax.axhline(chosen_area * scale, color="m", ls="--", lw=1.0,
                           label=f"chosen {chosen_area / neutral_area:.3g} x neutral")
            what = ("yaw-mode damping ratio" if column.startswith("yaw")
                    else "largest real part")
            ax.set(xlabel="airspeed [KEAS]", ylabel=f"parachute area [{unit}]",
                   title=f"{what}, {quantity_text(h, 'altitude', units)} density altitude")
            _small(ax)
    # one legend for every panel, below them: inside a panel it hides cells of the map
    handles, labels = axes[0, 0].get_legend_handles_labels()
    if handles:
        fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=7, frameon=False)
    c = stability.condition
    fig.suptitle(f"mass {c['mass case']} {_mass(c['mass [kg]'], units)}, cable "
                 f"{quantity_text(c['cable length [m]'], 'length', units)}, carrier "
                 f"{c['carrier']}; neutral "
                 f"area {neutral_area * scale:.3g} {unit}", fontsize=8, y=0.995)
    return fig


def _no_parachute_title(study, units, extra=""):
    """The base condition of the study without parachute: helicopters and masses, cable,
    density altitude, carrier, the ramp (and ``extra``)."""
    systems = study.systems
    system = next(iter(systems.values()))
    masses = ", ".join(f"{name} {_mass(s.body.mass, units)}" for name, s in systems.items())
    rate = (f"{study.rate:g} m/s^2" if units == "SI"
            else f"{study.rate / FOOT:.3g} ft/s^2")
    return (f"full tail, no parachute: {masses}; cable "
            f"{quantity_text(system.cable.length, 'length', units)}, "
            f"{quantity_text(system.density_altitude, 'altitude', units)} density altitude, "
            f"hovering carrier; ramp {rate} from {study.onset:g} s{extra}")


def _ramp_figure(result, runs, keys, windows, units, extra=""):
    """Yaw and sideslip, one row per ramp target, of the runs ``runs`` (helicopter, ramp
    target [m/s], verdict) whose histories are at ``keys`` ((helicopter, target) -> history
    key of :meth:`CampaignResult.history`); the head wind on the right axis of the yaw
    panel, the ramp's end dotted and, where ``windows`` gives one, the gust shaded."""
    study = result.campaign.no_parachute
    targets = sorted(runs["ramp target [m/s]"].unique())
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 2.0 * len(targets) + 1.1)), left=0.7,
                      right=0.15, bottom=0.5, top=0.6, wspace=0.6, hspace=0.6)
    axes = fig.subplots(len(targets), 2, squeeze=False, sharex=True)
    for i, target in enumerate(targets):
        length = 0.0
        for (name, t), key in keys.items():
            if t != target:
                continue
            h = result.history(key)
            length = max(length, float(h["time [s]"].iloc[-1]))
            verdict = runs[(runs["helicopter"] == name)
                           & (runs["ramp target [m/s]"] == t)]["verdict"].iloc[0]
            axes[i, 0].plot(h["time [s]"], h[YAW], label=f"{name} ({verdict})")
            axes[i, 1].plot(h["time [s]"], h[BETA], label=name)
        end = study.ramp_end(target)
        gust = windows(target)
        for ax in axes[i]:
            ax.axvline(end, color="0.4", ls=":", lw=1.0)
            if gust is not None:
                ax.axvspan(gust[0], gust[1], color="orange", alpha=0.15, lw=0)
        wind = axes[i, 0].twinx()
        time = np.linspace(0.0, length or study.run_length, 200)
        wind.plot(time, np.clip((time - study.onset) * study.rate, 0.0, target) / KNOT,
                  color="0.6", lw=0.8, ls="--")
        wind.set_ylabel("head wind [kt]", fontsize=7, color="0.4")
        wind.tick_params(labelsize=6, colors="0.4")
        what = f"wind ramp to {target / KNOT:.0f} kt"
        marks = f"ends at {end:.0f} s, dotted" + (
            f"; gust {gust[0]:.0f}-{gust[1]:.0f} s, shaded" if gust is not None else "")
        axes[i, 0].set(ylabel="yaw [deg]",
                       title=f"{what}\n({marks})" if gust is not None else f"{what} ({marks})")
        axes[i, 1].set(ylabel="beta [deg]", title=what)
        _legend(axes[i, 0], fontsize=6)
        for ax in axes[i]:
            ax.grid(True, alpha=0.4)
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    for ax in axes.flat:
        _small(ax)
    fig.suptitle(_no_parachute_title(study, units, extra), fontsize=8, y=0.999)
    return fig


def plot_no_parachute(result, units="SI"):
    """Yaw and sideslip under the frontal wind ramps, each helicopter, without parachute
    (paper figures 16-18): one row per ramp target, the head wind (the ramp) on the right
    axis of the yaw panel and the ramp's end marked; the base condition (masses, cable,
    altitude, carrier, ramp) in the title."""
    npr = result.no_parachute
    return _ramp_figure(result, npr.runs, {k: k for k in npr.keys}, lambda target: None,
                        units)


def plot_no_parachute_gust(result, units="SI"):
    """Yaw and sideslip of the ramps with a lateral gust after the ramp (a stable case shows
    its damping), each helicopter, without parachute: one row per ramp target, the head
    wind on the right axis, the ramp's end dotted, the gust shaded; the base condition and
    the gust in the title."""
    from slingloads.analyses.campaign import GUST_DELAY, GUST_DURATION  # loaded with a result

    npr = result.no_parachute
    study = result.campaign.no_parachute
    speed = quantity_text(study.gust_speed, "speed", units, digits=3)
    return _ramp_figure(result, npr.gust_runs, {k: (*k, "gust") for k in npr.gust_keys},
                        study.gust_window, units,
                        f";\n{GUST_DURATION:g} s lateral gust of {speed} "
                        f"{GUST_DELAY:g} s after each ramp's end")


def plot_root_locus(loci, title="", chosen=None):
    """Root locus of the least-damped eigenvalues against the parachute area: on the left the
    complex plane, colour the area factor; on the right the real part against the area
    factor, with 1.0 x neutral and the ``chosen`` area factor (when given) marked; in both,
    oscillatory roots (a complex pair, upper half shown) as circles, real (aperiodic) roots
    as crosses.

    Parameters
    ----------
    loci : pandas.DataFrame
        Columns "area factor [-]", "real [1/s]", "imag [rad/s]" (one row per root).
    title : str
    chosen : float, optional
        The chosen area factor. [-]
    """
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.2)), left=0.8, right=0.2, bottom=0.55,
                      top=0.6, wspace=0.7)
    ax, against = fig.subplots(1, 2, width_ratios=(1.25, 1.0))
    f = loci["area factor [-]"].to_numpy(float)
    re, im = loci["real [1/s]"].to_numpy(float), loci["imag [rad/s]"].to_numpy(float)
    osc = np.abs(im) > 1e-6
    norm = (np.nanmin(f), np.nanmax(f))
    ax.scatter(re[osc], np.abs(im[osc]), c=f[osc], cmap="viridis", vmin=norm[0],
               vmax=norm[1], marker="o", s=14, label="oscillatory (upper root of the pair)")
    sc = ax.scatter(re[~osc], im[~osc], c=f[~osc], cmap="viridis", vmin=norm[0],
                    vmax=norm[1], marker="x", s=22, label="real (aperiodic)")
    bar = fig.colorbar(sc, ax=ax)
    bar.set_label(AREA_FACTOR_SCALE, fontsize=7)
    bar.ax.tick_params(labelsize=7)
    ax.axvline(0.0, color="r", lw=0.8)
    ax.set(xlabel="real part [1/s]", ylabel="imaginary part [rad/s]", title="complex plane")
    against.scatter(f[osc], re[osc], marker="o", s=14, facecolors="none", edgecolors="C0",
                    label="oscillatory")
    against.scatter(f[~osc], re[~osc], marker="x", s=22, color="C3", label="real")
    against.axhline(0.0, color="r", lw=0.8)
    against.axvline(1.0, color="k", ls=":", lw=1.0, label="1.0 x neutral")
    if chosen is not None and np.isfinite(chosen):
        against.axvline(chosen, color="m", ls="--", lw=1.0, label=f"chosen {chosen:.3g} x")
    against.set(xlabel=AREA_FACTOR_SCALE, ylabel="real part [1/s]",
                title="real part against the area\n(> 0 divergent)")
    for a in (ax, against):
        a.grid(True, alpha=0.4)
        _small(a)
        _legend(a, fontsize=6)
    fig.suptitle(title, fontsize=8, y=0.995)
    return fig


def plot_envelope(result):
    """The angle-of-attack / sideslip extremes of every run of the chosen parachute, and the
    envelope handed to the loads (with the margin)."""
    env = result.envelope
    m = result.metrics[np.isclose(result.metrics["area factor [-]"], env.area_factor)]
    fig = fix_margins(Figure(figsize=(PAGE_WIDTH, 4.6)), left=0.8, right=0.3, bottom=0.55,
                      top=0.4)
    ax = fig.subplots()
    for _, r in m.iterrows():
        ax.plot([r["beta min [deg]"], r["beta max [deg]"], r["beta max [deg]"],
                 r["beta min [deg]"], r["beta min [deg]"]],
                [r["alpha min [deg]"], r["alpha min [deg]"], r["alpha max [deg]"],
                 r["alpha max [deg]"], r["alpha min [deg]"]], color="0.7", lw=0.6)
    ids, alpha, beta = env.aero_envelope()
    b0, b1 = env.bounds("beta")
    a0, a1 = env.bounds("alpha")
    ax.plot([b0, b1, b1, b0, b0], [a0, a0, a1, a1, a0], "r-",
            label=f"loads envelope (x {env.margin:g})")
    ax.plot(np.degrees(beta), np.degrees(alpha), "ro")
    ax.set(xlabel="sideslip beta [deg]", ylabel="angle of attack alpha [deg]",
           title=f"runs at {env.area_factor:g} x neutral area (grey: each run's range)")
    ax.grid(True, alpha=0.4)
    _small(ax)
    _legend(ax, fontsize=7)
    return fig

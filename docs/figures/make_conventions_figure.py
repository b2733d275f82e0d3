"""Draw ``docs/figures/conventions.png``: the axes and sign conventions of slingloads.

(a) Side view (x aft, z up, viewed from the left so y points into the page): datum, hub,
mast feet, CG, the earth vertical of the hanging attitude (through CG and hub) beside the mast
axis, fin, parachute line, loads reference axis and a cut station with the positive internal
loads Vx, Vz, My drawn on the FORWARD part's cut face (the action of the aft part).
(b) Top view (x aft, y right, z out of the page): positive sideslip (wind from the right),
positive yawing moment Cn (nose right) and the hook-load azimuths about the earth vertical
(0 deg the horizontal projection of +x, aft; 90 deg of +y, right).

The outline is a generic helicopter made of simple polygons, not any real aircraft.
Run from anywhere: ``python docs/figures/make_conventions_figure.py``.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.patches import Circle, FancyArrowPatch, Polygon  # noqa: E402

OUT = Path(__file__).with_name("conventions.png")

AXIS = "#1f3b73"      # airframe axes
LOAD = "#c0392b"      # positive internal loads
AERO = "#1e8449"      # wind, aerodynamic angles and moments
HOOK = "#7d3c98"      # hook loads
BODY_FWD = "#d6dbe4"
BODY_AFT = "#eef0f4"
EDGE = "#4d5566"


def arrow(ax, start, end, color, lw=2.0, ms=16, style="-|>", **kw):
    """Straight arrow from ``start`` to ``end`` in data coordinates."""
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle=style, mutation_scale=ms,
                                 color=color, lw=lw, shrinkA=0, shrinkB=0, **kw))


def arc_arrow(ax, centre, radius, deg_from, deg_to, color, lw=2.0, ms=16):
    """Circular arc from ``deg_from`` to ``deg_to`` (either sense) with a head at the end."""
    t = np.radians(np.linspace(deg_from, deg_to, 60))
    x = centre[0] + radius * np.cos(t)
    y = centre[1] + radius * np.sin(t)
    ax.plot(x[:-3], y[:-3], color=color, lw=lw, solid_capstyle="butt")
    arrow(ax, (x[-4], y[-4]), (x[-1], y[-1]), color, lw=lw, ms=ms)


def axes_triad(ax, origin, labels, out_of_page, size=1.0):
    """x (right) and second axis (up) arrows; the third axis as a dot (out) or cross (in)."""
    o = np.asarray(origin, float)
    arrow(ax, o, o + [size, 0.0], AXIS, lw=2.2, ms=16)
    ax.text(o[0] + size + 0.12, o[1], labels[0], color=AXIS, fontsize=10, fontweight="bold",
            ha="left", va="center")
    arrow(ax, o, o + [0.0, size], AXIS, lw=2.2, ms=16)
    ax.text(o[0], o[1] + size + 0.12, labels[1], color=AXIS, fontsize=10, fontweight="bold",
            ha="center", va="bottom")
    ax.add_patch(Circle(o, 0.16, fc="white", ec=AXIS, lw=1.6, zorder=5))
    if out_of_page:
        ax.add_patch(Circle(o, 0.05, color=AXIS, zorder=6))
    else:
        r = 0.11
        ax.plot([o[0] - r, o[0] + r], [o[1] - r, o[1] + r], color=AXIS, lw=1.6, zorder=6)
        ax.plot([o[0] - r, o[0] + r], [o[1] + r, o[1] - r], color=AXIS, lw=1.6, zorder=6)
    ax.text(o[0], o[1] - 0.3, labels[2], color=AXIS, fontsize=10, fontweight="bold",
            ha="center", va="top")


LABEL_BOX = dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85)


# --------------------------------------------------------------------------- side view
def draw_side(ax):
    cut, gap = 6.6, 0.7
    z0 = 1.3                                  # loads reference axis z
    cabin = np.array([
        [0.0, 1.05], [0.25, 1.55], [0.8, 2.0], [1.6, 2.25], [4.2, 2.25], [4.9, 1.95],
        [5.6, 1.55], [5.6, 1.05], [4.8, 0.6], [1.2, 0.45], [0.4, 0.6],
    ])
    deck = np.array([[2.1, 2.25], [2.35, 2.55], [4.0, 2.55], [4.2, 2.25]])
    # Boom from x = 5.6 to 9.8, cut at ``cut``; the aft part is drawn shifted by ``gap``.
    top = lambda x: 1.55 + 0.02 * (x - 5.6)      # noqa: E731
    bot = lambda x: 1.05 + 0.095 * (x - 5.6)     # noqa: E731
    boom_fwd = np.array([[5.6, top(5.6)], [cut, top(cut)], [cut, bot(cut)], [5.6, bot(5.6)]])
    boom_aft = np.array([[cut, top(cut)], [9.8, top(9.8)], [9.8, bot(9.8)], [cut, bot(cut)]])
    fin = np.array([[9.2, top(9.2)], [9.9, 2.95], [10.3, 2.95], [10.05, bot(9.8) - 0.05]])
    for poly in (cabin, deck, boom_fwd):
        ax.add_patch(Polygon(poly, closed=True, fc=BODY_FWD, ec=EDGE, lw=1.4, zorder=2))
    for poly in (boom_aft, fin):
        ax.add_patch(Polygon(poly + [gap, 0.0], closed=True, fc=BODY_AFT, ec=EDGE, lw=1.4,
                             ls="--", zorder=2))
    ax.add_patch(Polygon(np.array([[0.55, 1.55], [0.85, 1.95], [1.6, 2.15], [1.6, 1.55]]),
                         closed=True, fc="white", ec=EDGE, lw=1.0, zorder=3))   # windscreen
    ax.text(3.3, 1.8, "forward part", ha="center", va="center", fontsize=9.5, color=EDGE)
    ax.text(8.6 + gap, 1.0, "aft part", ha="center", va="top", fontsize=9.5, color=EDGE)

    # Mast, hub, feet, carrier cable.
    hub = np.array([3.15, 3.35])
    feet = np.array([[2.55, 2.55], [3.75, 2.55]])
    for f in feet:
        ax.plot([f[0], hub[0]], [f[1], hub[1] - 0.1], color=EDGE, lw=2.2, zorder=3)
    ax.plot(*feet.T, "s", color="black", ms=7, zorder=4)
    ax.add_patch(Circle(hub, 0.14, fc="black", zorder=4))
    # Hanging attitude: the CG lies under the hub, so the earth vertical k runs through both
    # (here the hub is aft of the CG: k leans aft in airframe axes, the nose hangs down).
    cg = np.array([2.85, 1.5])
    k = (hub - cg) / np.linalg.norm(hub - cg)
    ax.plot([cg[0], hub[0] + 1.55 * k[0]], [cg[1], hub[1] + 1.55 * k[1]], color=HOOK, lw=1.0,
            ls=":", zorder=3)
    ax.add_patch(Circle(cg, 0.13, fc="white", ec="black", lw=1.2, zorder=6))
    ax.add_patch(Polygon(np.array([cg, cg + [0.13, 0.0], cg + [0.0, 0.13]]) + [0.0, 0.0],
                         closed=True, fc="black", zorder=7))
    ax.add_patch(Polygon(np.array([cg, cg - [0.13, 0.0], cg - [0.0, 0.13]]),
                         closed=True, fc="black", zorder=7))
    ax.text(cg[0] - 0.2, cg[1] - 0.05, "CG", fontsize=9, ha="right", va="center", zorder=7)
    top = hub + 1.55 * k
    ax.plot([hub[0], top[0]], [hub[1], top[1]], color="black", lw=1.4, ls=(0, (4, 2)))
    ax.text(top[0] - 0.15, top[1] - 0.1, "cable to carrier", fontsize=9, ha="right", va="top")
    ax.text(hub[0] - 0.25, hub[1] + 0.05, "hub", fontsize=9.5, ha="right", va="center")
    ax.text(2.4, 2.75, "mast feet", fontsize=9, ha="right", va="center")
    arrow(ax, hub + [1.0, -0.3], hub + [1.0, 0.5], EDGE, lw=1.2, ms=10)
    ax.text(hub[0] + 1.1, hub[1] - 0.15, "mast\naxis", color=EDGE, fontsize=8.5,
            va="center")
    side = hub + [0.45, 0.0]
    arrow(ax, side, side + 1.1 * k, HOOK, lw=2.0, ms=14, zorder=6)
    ax.text(side[0] + 0.3, hub[1] + 1.05, "earth vertical k\n(hanging: CG under hub)",
            color=HOOK, fontsize=9, va="center")

    # Fin, parachute line and canopy (on the shifted aft part).
    chute = np.array([10.1 + gap, 2.8])
    ax.plot(*chute, "o", color="black", ms=5, zorder=4)
    canopy = chute + np.array([1.3, -0.3])
    ax.plot([chute[0], canopy[0]], [chute[1], canopy[1]], color="black", lw=1.2)
    ax.add_patch(Polygon(np.array([canopy + [0.0, 0.4], canopy + [0.3, 0.27],
                                   canopy + [0.3, -0.27], canopy - [0.0, 0.4]]),
                         closed=True, fc="#f5cba7", ec=EDGE, zorder=3))
    ax.text(canopy[0] + 0.15, canopy[1] - 0.55, "drogue", fontsize=9, ha="center", va="top")
    ax.text(chute[0] - 0.2, chute[1] + 0.3, "fin attachment", fontsize=9, ha="center")

    # Loads reference axis and the cut.
    ax.plot([-0.4, 10.7 + gap], [z0, z0], color=AXIS, lw=1.0, ls="-.", zorder=3)
    ax.annotate("loads reference axis\n(parallel to x at y0, z0)", xy=(1.6, z0),
                xytext=(2.4, -0.35), color=AXIS, fontsize=9, ha="left", va="top",
                arrowprops=dict(arrowstyle="-", color=AXIS, lw=0.8))
    ax.plot([cut, cut], [0.4, 3.2], color=LOAD, lw=1.0, ls=":", zorder=3)
    ax.plot([cut + gap, cut + gap], [0.9, 1.9], color=LOAD, lw=1.0, ls=":", zorder=3)
    ax.text(cut + 0.1, 3.25, "cut station", color=LOAD, fontsize=10, ha="center",
            va="bottom")
    p = np.array([cut, z0])
    ax.plot(*p, "o", color=LOAD, ms=5, zorder=8)

    # Positive internal loads on the forward part's cut face (action of the aft part).
    arrow(ax, p, p + [1.2, 0.0], LOAD, lw=2.4, ms=17, zorder=7)
    ax.text(p[0] + 1.25, p[1] - 0.12, "+Vx", color=LOAD, fontsize=11, fontweight="bold",
            va="top", bbox=LABEL_BOX, zorder=9)
    arrow(ax, p, p + [0.0, 1.45], LOAD, lw=2.4, ms=17, zorder=7)
    ax.text(p[0] + 0.12, p[1] + 1.4, "+Vz", color=LOAD, fontsize=11, fontweight="bold",
            va="center", ha="left", zorder=9)
    arc_arrow(ax, p, 0.6, 255, 112, LOAD, lw=2.2, ms=15)   # clockwise = about +y (into page)
    ax.text(p[0] - 0.7, p[1] + 0.75, "+My", color=LOAD, fontsize=11, fontweight="bold",
            ha="right", va="center", bbox=LABEL_BOX, zorder=9)
    ax.text(9.3, -0.35,
            "positive internal loads on the\nFORWARD part's cut face = action\n"
            "of the AFT part on it\n(+Vx tension, +My top fibre in tension)",
            color=LOAD, fontsize=9, ha="center", va="top")

    # Datum and axes: x aft, z up, y into the page (viewed from the left).
    axes_triad(ax, (-0.9, -0.75), ("x aft (FS)", "z up (WL)", "y right (BL),\ninto page"),
               out_of_page=False, size=1.0)
    ax.text(-1.15, -0.55, "datum", color=AXIS, fontsize=9, ha="right", va="bottom")

    # Relative wind at positive alpha (from below and ahead, nose up).
    a = np.radians(15.0)
    s = np.array([-1.9, 2.9])
    arrow(ax, s, s + 1.6 * np.array([np.cos(a), np.sin(a)]), AERO, lw=2.0, ms=14)
    ax.plot([s[0], s[0] + 1.8], [s[1], s[1]], color=AERO, lw=0.8, ls=":")
    arc_arrow(ax, s, 1.25, 0, 15, AERO, lw=1.2, ms=9)
    ax.text(s[0] + 1.35, s[1] + 0.05, "α", color=AERO, fontsize=10, va="bottom")
    ax.text(s[0] - 0.1, s[1] + 0.6, "relative wind,\nα > 0 (nose up)", color=AERO, fontsize=9,
            ha="left", va="bottom")

    ax.set_xlim(-2.2, 12.6)
    ax.set_ylim(-2.05, 5.0)
    ax.set_aspect("equal")
    ax.axis("off")



# ---------------------------------------------------------------------------- top view
def draw_top(ax):
    # Planform: cabin, boom, horizontal stabiliser (x right on the page = aft, y up = right).
    t = np.linspace(0, 2 * np.pi, 80)
    cabin = np.column_stack([2.8 + 2.8 * np.cos(t), 0.95 * np.sin(t)])
    boom = np.array([[5.0, 0.3], [9.9, 0.14], [9.9, -0.14], [5.0, -0.3]])
    stab = np.array([[8.0, 0.14], [8.2, 1.1], [8.7, 1.1], [8.7, -1.1], [8.2, -1.1],
                     [8.0, -0.14]])
    for poly in (stab, boom, cabin):
        ax.add_patch(Polygon(poly, closed=True, fc=BODY_FWD, ec=EDGE, lw=1.4, zorder=2))
    ax.add_patch(Polygon(np.array([[9.3, 0.06], [10.2, 0.06], [10.2, -0.06], [9.3, -0.06]]),
                         closed=True, fc=EDGE, ec=EDGE, zorder=3))                  # fin
    ax.text(9.8, -0.3, "fin", fontsize=9, color=EDGE, ha="center", va="top")

    # Hook-load azimuths about the hub: 0 deg aft (+x), 90 deg right (+y).
    hub = np.array([3.15, 0.0])
    r = 1.6
    for k in range(8):
        psi = np.radians(45.0 * k)
        d = np.array([np.cos(psi), np.sin(psi)])
        main = k in (0, 2)
        arrow(ax, hub, hub + r * d, HOOK, lw=2.4 if main else 1.0, ms=16 if main else 9,
              alpha=1.0 if main else 0.55, zorder=5)
    ax.add_patch(Circle(hub, 0.12, fc="black", zorder=6))
    ax.text(hub[0] + r + 0.1, hub[1] - 0.12, "ψ = 0°\n(aft, +x)", color=HOOK,
            fontsize=9.5, ha="left", va="top", bbox=LABEL_BOX, zorder=7)
    ax.text(hub[0] + 0.15, hub[1] + r + 0.05, "ψ = 90° (right, +y)", color=HOOK,
            fontsize=9.5, ha="left", va="bottom", zorder=7)
    arc_arrow(ax, hub, 0.8, 8, 80, HOOK, lw=1.4, ms=10)
    ax.text(hub[0] + 0.95, hub[1] + 0.38, "ψ", color=HOOK, fontsize=11, zorder=7)
    ax.text(4.4, -1.75, "hook-load azimuth ψ = horizontal\ndirection of the force on the\n"
            "airframe, about the earth vertical\n(default 8 at 45°)", color=HOOK, fontsize=9,
            ha="left", va="top")

    # Positive sideslip: the wind comes from the right (+y), blowing along (cos b, -sin b).
    b = np.radians(25.0)
    d = np.array([np.cos(b), -np.sin(b)])
    tip = np.array([-0.55, 2.35])
    tail = tip - 2.1 * d
    arrow(ax, tail, tip, AERO, lw=2.2, ms=16)
    ax.plot([tail[0], tail[0] + 2.6], [tail[1], tail[1]], color=AERO, lw=0.8, ls=":")
    arc_arrow(ax, tail, 1.5, 0, -24, AERO, lw=1.2, ms=9)
    ax.text(tail[0] + 1.6, tail[1] - 0.3, "β", color=AERO, fontsize=11, va="center")
    ax.text(tail[0] - 0.2, tail[1] + 0.2, "relative wind, β > 0\n(wind from the right)",
            color=AERO, fontsize=9, ha="left", va="bottom")

    # Positive yawing moment Cn: nose right = clockwise seen from above = negative about +z.
    cg = np.array([3.0, 0.0])
    arc_arrow(ax, cg, 3.6, 198, 160, AERO, lw=2.2, ms=16)
    ax.text(-0.85, 0.0, "Cn > 0:\nnose right\n(Mz = -q S L Cn)", color=AERO,
            fontsize=9.5, ha="right", va="center")

    axes_triad(ax, (-2.6, -2.75), ("x aft (FS)", "y right (BL)", "z up (WL),\nout of page"),
               out_of_page=True, size=1.0)

    ax.set_xlim(-3.7, 10.4)
    ax.set_ylim(-3.75, 4.15)
    ax.set_aspect("equal")
    ax.axis("off")



def main(path=OUT):
    fig = Figure(figsize=(12.5, 4.3), dpi=150)
    ax_side = fig.add_axes([0.0, 0.0, 0.53, 0.93])
    ax_top = fig.add_axes([0.54, 0.0, 0.46, 0.93])
    draw_side(ax_side)
    draw_top(ax_top)
    fig.text(0.01, 0.875, "(a) Side view from the left: x aft, z up, y into the page",
             fontsize=11)
    fig.text(0.55, 0.875, "(b) Top view from above: x aft, y right, z out of the page",
             fontsize=11)
    fig.suptitle("slingloads: airframe axes and sign conventions (docs/conventions.md)",
                 fontsize=12, y=0.99)
    fig.savefig(path, dpi=150, facecolor="white")
    return path


if __name__ == "__main__":
    print(main())

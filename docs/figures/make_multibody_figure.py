"""Draw docs/figures/multibody.png: bodies, frames and hinges of the multibody model.

Run from the repository root: ``.venv/bin/python docs/figures/make_multibody_figure.py``.
Schematic (not to scale): side view (earth X aft, Z up; y into the page) and top view of the
towed system: carrier hook, elastic cable, carried helicopter (CG, hub, fin, aerodynamic
reference point), parachute line with its two hinge angles, and the canopy.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import FancyArrowPatch, Polygon  # noqa: E402

OUT = Path(__file__).resolve().parent / "multibody.png"


def arrow(ax, start, end, color="k", text=None, offset=(0.1, 0.1), **kw):
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle="-|>", mutation_scale=12,
                                 color=color, lw=1.4, **kw))
    if text:
        ax.text(end[0] + offset[0], end[1] + offset[1], text, color=color, fontsize=10)


def fuselage(ax, pitch, cg, yaw_view=False):
    """Outline of the carried helicopter in body axes (x aft), rotated by ``pitch`` [rad]."""
    shape = np.array([[-4.5, -0.6], [-3.8, 0.6], [-1.5, 1.0], [1.5, 1.0], [2.2, 0.3],
                      [6.0, 0.3], [6.6, 1.8], [6.9, 1.8], [6.6, -0.1], [2.0, -0.6]])
    if yaw_view:
        shape = np.array([[-4.5, 0.0], [-3.8, 0.8], [2.0, 0.8], [6.6, 0.25], [6.9, 0.0],
                          [6.6, -0.25], [2.0, -0.8], [-3.8, -0.8]])
    c, s = np.cos(pitch), np.sin(pitch)
    rot = np.array([[c, -s], [s, c]])
    pts = shape @ rot.T + cg
    ax.add_patch(Polygon(pts, closed=True, fc="0.88", ec="0.3", lw=1.2))
    return rot


def side_view(ax):
    hook = np.array([-2.0, 9.0])
    pitch = np.radians(-6.0)
    cg = np.array([0.0, 0.0])
    rot = fuselage(ax, pitch, cg)
    hub = cg + rot @ np.array([0.0, 1.0])
    attach = cg + rot @ np.array([6.6, 1.6])
    ax.plot(*zip(hook, hub, strict=True), color="tab:blue", lw=2)
    ax.plot(*hook, "ks", ms=8)
    ax.text(hook[0] - 2.6, hook[1] + 0.3, "carrier hook\n(frozen or free)", fontsize=9)
    ax.text(-2.4, 5.0, "elastic cable\nL0, EA, damping\n(tension only)", color="tab:blue",
            fontsize=9)
    ax.plot(*hub, "o", color="tab:blue")
    ax.text(hub[0] + 0.2, hub[1] + 0.2, "hub", fontsize=9)
    ax.plot(*cg, "k+", ms=12, mew=2)
    ax.text(cg[0] - 1.2, cg[1] - 0.9, "CG (m, I)", fontsize=9)
    theta = np.radians(-15.0)
    chute = attach + 5.5 * np.array([np.cos(pitch + theta), np.sin(pitch + theta)])
    ax.plot(*zip(attach, chute, strict=True), color="tab:red", lw=1.5)
    ax.plot(*chute, "o", color="tab:red", ms=10)
    ax.text(chute[0] - 1.0, chute[1] - 1.9, "canopy m_p\ndrag along its\nrelative wind",
            color="tab:red", fontsize=9)
    ax.plot(*attach, "o", color="tab:red", ms=4)
    body_x = rot @ np.array([1.0, 0.0])
    ax.plot(*zip(attach, attach + 3.0 * body_x, strict=True), "k:", lw=1)
    arc = np.linspace(pitch, pitch + theta, 20)
    ax.plot(attach[0] + 2.2 * np.cos(arc), attach[1] + 2.2 * np.sin(arc), color="tab:red")
    ax.text(attach[0] + 2.4, attach[1] - 0.2, "theta", color="tab:red", fontsize=10)
    ax.text(attach[0] - 0.5, attach[1] + 0.6, "hinges", color="tab:red", fontsize=9)
    arrow(ax, cg, cg + 2.0 * body_x, "tab:green", "x (aft)", (0.1, -0.4))
    arrow(ax, cg, cg + 2.0 * (rot @ np.array([0.0, 1.0])), "tab:green", "z", (0.1, 0.0))
    origin = np.array([-8.0, -3.5])
    arrow(ax, origin, origin + [2.0, 0.0], "k", "X aft (wind past the HC)", (0.1, -0.1))
    arrow(ax, origin, origin + [0.0, 2.0], "k", "Z up", (0.1, 0.0))
    arrow(ax, np.array([-7.5, 6.0]), np.array([-5.0, 6.0]), "0.5", "relative wind",
          (-2.5, 0.3))
    ax.set_title("(a) side view (from the left; y into the page)")


def top_view(ax):
    cg = np.array([0.0, 0.0])
    yaw = np.radians(12.0)
    rot = fuselage(ax, -yaw, cg, yaw_view=True)
    attach = cg + rot @ np.array([6.8, 0.0])
    psi = np.radians(18.0)
    body_x = rot @ np.array([1.0, 0.0])
    ang = np.arctan2(body_x[1], body_x[0])
    chute = attach + 5.5 * np.array([np.cos(ang + psi), np.sin(ang + psi)])
    ax.plot(*zip(attach, chute, strict=True), color="tab:red", lw=1.5)
    ax.plot(*chute, "o", color="tab:red", ms=10)
    ax.plot(*zip(attach, attach + 3.0 * body_x, strict=True), "k:", lw=1)
    arc = np.linspace(ang, ang + psi, 20)
    ax.plot(attach[0] + 2.2 * np.cos(arc), attach[1] + 2.2 * np.sin(arc), color="tab:red")
    ax.text(attach[0] + 2.3, attach[1] + 0.2, "psi", color="tab:red", fontsize=10)
    ax.plot(*cg, "k+", ms=12, mew=2)
    ax.text(-1.0, 1.1, "hub above CG", fontsize=9)
    arrow(ax, cg, cg + 2.5 * body_x, "tab:green", "x (aft)", (0.0, -0.6))
    arrow(ax, cg, cg + 2.0 * (rot @ np.array([0.0, 1.0])), "tab:green", "y (right)",
          (-1.0, 0.2))
    ax.plot([-5, 12], [0, 0], "k--", lw=0.8)
    ax.text(8.5, 0.3, "flight path (X)", fontsize=9)
    arc = np.linspace(0.0, -yaw, 20)
    ax.plot(3.8 * np.cos(arc), 3.8 * np.sin(arc), "tab:green")
    ax.text(4.0, -0.8, "yaw (nose right +)", color="tab:green", fontsize=9)
    arrow(ax, np.array([-6.0, -3.5]), np.array([-6.0, -1.5]), "k", "Y right", (0.1, 0.0))
    ax.set_title("(b) top view (from above: X to the right, Y up the page)")


def main():
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    side_view(axes[0])
    top_view(axes[1])
    for ax in axes:
        ax.set_aspect("equal")
        ax.axis("off")
        ax.autoscale_view()
    axes[0].set_xlim(-9, 14)
    axes[0].set_ylim(-5, 10.5)
    axes[1].set_xlim(-7, 14)
    axes[1].set_ylim(-5, 6)
    fig.tight_layout()
    fig.savefig(OUT, dpi=120)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()

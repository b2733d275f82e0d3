"""Report figures: text from the inputs is drawn literally, never parsed as mathtext.

Reference: matplotlib's mathtext grammar, under which ``$\\frac$`` (a fraction without its
two arguments) cannot be parsed and ``$1$`` would be typeset as a math expression; a station
id such as ``FS$1$`` or a case id must be printed as written.
"""

from __future__ import annotations

import io

import pytest

from slingloads.io.common.figures import draw_png, figure_png

pytest.importorskip("matplotlib")

BAD_MATH = "FS$\\frac$"


def _figure_with_ids():
    """A figure whose title, axis label, tick labels and legend hold ids with ``$``."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(3, 2))
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], label=BAD_MATH)
    ax.set_title(BAD_MATH)
    ax.set_xlabel("case $1$")
    ax.set_xticks([0, 1], [BAD_MATH, "LC$2$"])
    ax.legend()
    return fig


def _is_png(data):
    return data[:8] == b"\x89PNG\r\n\x1a\n"


def test_mathtext_would_fail_on_the_id():
    """The premise: with mathtext parsing on, the id cannot be drawn at all."""
    fig = _figure_with_ids()
    with pytest.raises(ValueError):
        fig.savefig(io.BytesIO(), format="png", dpi=20)


def test_report_figures_draw_ids_literally():
    """A report figure (made and drawn by draw_png) draws the ids as plain text."""
    png = draw_png(_figure_with_ids, (), {}, 20)
    assert _is_png(png)


def test_report_figure_text_is_plain_including_tick_labels_made_when_drawn():
    """Every text of a figure drawn by draw_png, the tick labels made while it is drawn
    included, has mathtext parsing off; and matplotlib's own setting is left as it was."""
    import matplotlib
    from matplotlib.text import Text

    made = []

    def plot():
        fig = _figure_with_ids()
        made.append(fig)
        return fig

    before = matplotlib.rcParams["text.parse_math"]
    draw_png(plot, (), {}, 20)
    texts = made[0].findobj(Text)
    assert len(texts) > 5
    assert not any(t.get_parse_math() for t in texts)
    assert matplotlib.rcParams["text.parse_math"] == before


def test_a_figure_made_elsewhere_is_drawn_literally_too():
    """figure_png on a Figure made by a caller (not through draw_png) also draws literally."""
    assert _is_png(figure_png(_figure_with_ids(), dpi=20))


def test_titles_at_the_top_of_their_axes_are_where_matplotlib_puts_them():
    """Reference: matplotlib's automatic title placement (``axes.titley`` None), which
    raises a title only above tick labels on top of the axes. The report style fixes titles
    at the top of their axes (a layout pass saved); for figures like the reports' (grids of
    axes with titles, labels, legends, no tick labels on top) the pixels are the same."""
    import matplotlib
    import numpy as np
    from matplotlib.figure import Figure

    from slingloads.io.common.figures import fix_margins, report_style

    def plot():
        fig = Figure(figsize=(7.0, 5.0))
        axes = fig.subplots(2, 2)
        t = np.linspace(0.0, 10.0, 200)
        for k, ax in enumerate(axes.flat):
            ax.plot(t, np.sin(t + k) * 10 ** k, label=f"run {k}")
            ax.set_title(f"panel {k}: yaw [deg]\nsecond line")
            ax.set_xlabel("t [s]")
            ax.legend(loc="upper right")
        return fix_margins(fig, top=0.8, hspace=0.6)

    assert report_style()["axes.titley"] == 1.0
    with matplotlib.rc_context({**report_style(), "axes.titley": None}):
        automatic = figure_png(plot(), dpi=60)
    assert draw_png(plot, (), {}, 60) == automatic

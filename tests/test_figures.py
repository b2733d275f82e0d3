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

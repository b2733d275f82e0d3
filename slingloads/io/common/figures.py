"""Page-ready figures: fixed margins instead of a layout engine, drawn beside the tables.

Every report figure is drawn 7 in wide, the printable width of an A4 portrait page, so that
its fonts print at their nominal size. Its margins are set once, in inches, with
:func:`fix_margins`: a layout engine (``layout="constrained"``) measures every tick label by
drawing the figure an extra time, which doubled the cost of writing a report; fixed margins
sized for the labels the reports draw (titles of at most two lines, tick labels of at most
nine characters) cost nothing.

Drawing the figures is most of the cost of a report: :class:`FigureRenderer` has them drawn
by a helper process (:mod:`slingloads.io.common.helper`) while the analyses are computed and
the workbooks' tables are written. The command line starts one helper for the whole run
(:func:`helping`) as soon as it starts; the report modules name their plot functions with
:func:`plot_function`, so that the process writing the workbooks does not load matplotlib
unless it draws a figure itself.
"""

from __future__ import annotations

import io
import sys
from contextlib import contextmanager
from dataclasses import dataclass
from importlib import import_module

from slingloads.io.common.helper import Call, Helper, current, gather, running
from slingloads.io.common.ownership import PNG_SOFTWARE

#: Width of every report figure: the printable width of an A4 portrait page. [in]
PAGE_WIDTH = 7.0


def fix_margins(fig, left=0.9, right=0.2, bottom=0.55, top=0.6, wspace=None, hspace=None):
    """Set the margins of a figure's subplot grid in inches.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    left, right, bottom, top : float
        Space between the figure's edges and the grid of axes (room for the tick labels,
        axis labels, titles and figure legends). [in]
    wspace, hspace : float, optional
        Space between columns and rows of axes, as a fraction of the average axes width and
        height (matplotlib's convention). [-]

    Returns
    -------
    matplotlib.figure.Figure
        ``fig``.
    """
    width, height = fig.get_size_inches()
    fig.subplots_adjust(left=left / width, right=1.0 - right / width, bottom=bottom / height,
                        top=1.0 - top / height, wspace=wspace, hspace=hspace)
    return fig


# ----------------------------------------------------------------------------- rendering
@dataclass(frozen=True)
class PlotFunction:
    """A plot function named by its module, imported when it is called: a drawing job
    names it without loading matplotlib, and pickles as two strings.

    Parameters
    ----------
    module : str
        ``"slingloads.io.loads.plots"``.
    name : str
        ``"plot_sfbm"``.
    """

    module: str
    name: str

    def __call__(self, *args, **kwargs):
        return getattr(import_module(self.module), self.name)(*args, **kwargs)


def plot_function(module, name):
    """:class:`PlotFunction` ``name`` of ``module``."""
    return PlotFunction(module, name)


def warm_up():
    """Load the Agg backend and the fonts (a helper process does it before its first
    figure, while its parent reads the workbook)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(1, 1))
    fig.text(0.5, 0.5, "0.5 [m]")
    fig.add_subplot().set_title("t")
    fig.savefig(io.BytesIO(), format="png", dpi=10)


#: Settings every report figure is drawn with: text drawn literally, never parsed as
#: mathtext (ids from the inputs, a station ``FS$1$`` or a case ``$\\frac$``, could fail or
#: mislead), including the tick labels made as the figure is drawn.
PLAIN_TEXT = {"text.parse_math": False}


def report_style():
    """:data:`PLAIN_TEXT`; matplotlib's default colours of lines and patches given by
    value: their default ``"C0"`` makes every spine, frame and line look the colour cycle up
    again as it is drawn (a few hundred lookups in a report's figures), the same colour; and
    axes titles at the top of their axes (``axes.titley`` 1.0, where matplotlib puts them
    when no tick label is above the axes, as in every report figure): matplotlib otherwise
    lays out each axis's ticks an extra time per axes to look for such labels (the same
    pixels, tested in ``tests/test_figures.py``)."""
    return {**PLAIN_TEXT, "patch.facecolor": cycle_colour(0), "lines.color": cycle_colour(0),
            "axes.titley": 1.0}


def cycle_colour(k):
    """Colour ``k`` of matplotlib's colour cycle (what ``f"C{k}"`` names) as a hex string,
    looked up once: a figure that names its colours by value does not look the cycle up
    again at every artist it draws. [-]"""
    from matplotlib import rcParams

    cycle = rcParams["axes.prop_cycle"]
    if _CYCLE.get("cycle") is not cycle:
        _CYCLE.update(cycle=cycle, colours=tuple(cycle.by_key().get("color", ["k"])))
    colours = _CYCLE["colours"]
    return colours[k % len(colours)]


_CYCLE = {}


def draw_png(func, args, kwargs, dpi):
    """PNG bytes of the figure ``func(*args, **kwargs)``, made and drawn with
    :func:`report_style` (run where the figure is drawn)."""
    from matplotlib import rc_context

    with rc_context(report_style()):
        return _png(func(*args, **kwargs), dpi)


#: Modules a helper loads while it waits for figures, in the order of the figures: the
#: plots, and the analyses whose results the figures are drawn from (unpickling a result
#: loads its module: pandas with the loads'), the loads' first, drawn while the workbook is
#: read. Not the report modules: they load what writes workbooks (openpyxl, XlsxWriter,
#: about 0.3 s), which a helper needs only for a CSV file it makes when no figure waits
#: (:meth:`FigureRenderer.later`). The multibody figures are drawn from plain data
#: (:mod:`slingloads.io.multibody.figure_data`): the helper does not load the model's
#: compiled code or scipy for them.
WARM_MODULES = ("slingloads.io.common.figures", "slingloads.analyses.loads",
                "slingloads.io.loads.plots", "slingloads.analyses.lateral",
                "slingloads.io.lateral.plots", "slingloads.analyses.chute_sizing",
                "slingloads.io.chute.plots", "slingloads.io.multibody.plots",
                "slingloads.io.campaign.plots")

@contextmanager
def helping(warm=WARM_MODULES):
    """The helper of a whole run: every :class:`FigureRenderer` made inside the block has its
    figures drawn by it. Started at once (forked while the process is still small); killed
    if the block fails, stopped when it ends.

    Yields
    ------
    Helper
    """
    with Helper(warm=warm) as helper, running(helper):
        yield helper


class FigureRenderer:
    """Draws a report's figures to PNG while the report's tables are written.

    Use as a context manager: :meth:`draw` registers every figure (a plot function and its
    arguments) and returns, for each, an object whose ``result()`` is the PNG bytes. They are
    drawn by the run's helper (:func:`helping`) when there is one, else by a helper of this
    renderer's own; a figure no helper has started when its PNG is asked for is drawn in
    this process. The bytes are the same whichever process draws them.

    Parameters
    ----------
    workers : int, optional
        Helper processes of this renderer's own (default: the run's helper when there is
        one, else :func:`~slingloads.io.common.helper.helper_processes`); 0 draws each
        figure in this process when its PNG is first asked for.
    dpi : float
        Resolution of the PNG files. [dots per inch]
    """

    def __init__(self, workers=None, dpi=100):
        self.dpi = dpi
        self._own = None
        if workers is None and current() is not None:
            self.helper = current()
        else:
            self._own = self.helper = Helper(workers)
        #: Every drawing started, by tag.
        self.pngs = {}
        #: Other work of the report handed to the same helper (:meth:`later`), by tag.
        self.tasks = {}

    def __enter__(self):
        return self

    def draw(self, jobs):
        """Start drawing ``jobs`` (``{tag: (plot function, args, kwargs)}``); returns
        ``{tag: object with result() -> PNG bytes}`` in the same order."""
        if self._own is not None:
            self._own.start()
        started = {tag: self.helper.submit(draw_png, func, tuple(args), dict(kwargs), self.dpi)
                   for tag, (func, args, kwargs) in jobs.items()}
        self.pngs.update(started)
        return started

    def later(self, tag, func, *args):
        """Keep ``func(*args)``, other work of the report (the bytes of a large CSV file), to
        be done by the process writing the report when it asks for it: :data:`tasks`
        ``[tag]``, taken with :func:`task_result`. It is not handed to the helper: the helper's
        time goes to the figures, which only it draws cheaply (loading matplotlib costs the
        writing process about 0.4 s), and a helper idle for a moment would load the report
        writers (openpyxl, XlsxWriter: 0.2 s) to make a CSV file, and be late for the next
        figures."""
        self.tasks[tag] = Helper(0).submit(func, *args)
        return self.tasks[tag]

    def __exit__(self, exc_type, exc, tb):
        if self._own is not None:
            self._own.close(abort=exc_type is not None)
        return False


def task_result(started, tag, func, *args):
    """``func(*args)``: the value of the task ``tag`` of an already started renderer
    (:meth:`FigureRenderer.later`, the same call), else computed here now."""
    if started is not None and tag in started.tasks:
        return started.tasks[tag].result()
    return func(*args)


@contextmanager
def drawings(jobs, started=None, dpi=100):
    """The drawings of ``jobs`` (``{tag: object with result() -> PNG bytes}``): those of an
    already started :class:`FigureRenderer` (started while other analyses were computed),
    else drawn now, beside the block's work.

    Parameters
    ----------
    jobs : dict
        ``{tag: (plot function, args, kwargs)}`` (with ``started``, only its tags are read:
        ``started.pngs`` will do).
    started : FigureRenderer, optional
        Already drawing exactly these jobs.
    dpi : float
        [dots per inch]
    """
    if started is not None:
        yield {tag: started.pngs[tag] for tag in jobs}
        return
    with FigureRenderer(dpi=dpi) as renderer:
        yield renderer.draw(jobs)


def start_drawing(jobs, dpi=100):
    """A :class:`FigureRenderer` already drawing ``jobs``; leave it (``with`` or ``__exit__``)
    once the PNGs are written."""
    renderer = FigureRenderer(dpi=dpi)
    renderer.draw(jobs)
    return renderer


#: Figures waiting for the helper (every report's) from which the writing process loads
#: matplotlib to draw some of them itself: loading it costs about a third of a second, more
#: than waiting for one or two figures.
SHARE_FROM = 3


def collect_pngs(pngs):
    """The PNG bytes of drawings (bytes, or pending drawings of a :class:`FigureRenderer`).

    The figures no helper process has started are drawn here, from the last one back (the
    helper takes them from the front), when matplotlib is loaded here already or when at
    least :data:`SHARE_FROM` figures wait for the helper; else the helper is waited for.
    """
    items = list(pngs)
    calls = [p for p in items if isinstance(p, Call)]
    share = "matplotlib.figure" in sys.modules or (
        bool(calls) and calls[0].helper.backlog() >= SHARE_FROM)
    return [png_bytes(p) for p in gather(items, least=1 if share else len(items) + 1)]


def png_bytes(png):
    """PNG bytes of a drawn figure: bytes as they are, or the ``result()`` of a pending one."""
    return png if isinstance(png, (bytes, bytearray)) else png.result()


def figure_png(figure, dpi=100):
    """PNG bytes of a matplotlib Figure (no timestamp or version metadata, so reproducible).

    Parameters
    ----------
    figure : matplotlib.figure.Figure or bytes
        A figure, PNG bytes returned unchanged, or a pending drawing of
        :class:`~slingloads.io.common.figures.FigureRenderer` (its ``result()``).
    dpi : float
        Resolution. [dots per inch]

    Returns
    -------
    bytes
    """
    if isinstance(figure, (bytes, bytearray)):
        return bytes(figure)
    if hasattr(figure, "result"):  # drawn elsewhere (FigureRenderer): its PNG bytes
        return bytes(figure.result())
    _plain_text(figure)
    return _png(figure, dpi)


def _png(figure, dpi):
    """PNG bytes of a matplotlib Figure, its legends off the data
    (:func:`place_legends`), with slingloads' mark (the text chunk
    ``Software`` = :data:`~slingloads.io.common.ownership.PNG_SOFTWARE`, a fixed text in
    place of matplotlib's version: the bytes stay reproducible)."""
    outside = place_legends(figure)
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=dpi, metadata={"Software": PNG_SOFTWARE},
                   pil_kwargs={"compress_level": 1},  # fast; files about 30 % larger
                   **({"bbox_inches": "tight", "pad_inches": 0.1} if outside else {}))
    return buffer.getvalue()


#: Where a legend may go inside its axes, tried in this order before it goes outside.
LEGEND_PLACES = ("upper right", "upper left", "lower right", "lower left", "center right",
                 "center left", "upper center", "lower center")


def legend_hides_data(ax, legend, renderer):
    """Whether ``legend``'s box covers any plotted line (a segment crossing it, not only a
    vertex) or marker of ``ax``, in display coordinates (matplotlib's own extents)."""
    import numpy as np
    from matplotlib.path import Path
    from matplotlib.transforms import Bbox

    # the part of the legend over the axes: lines are drawn clipped to them
    box = Bbox.intersection(legend.get_window_extent(renderer), ax.bbox)
    if box is None:
        return False
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        xy = line.get_transform().transform(line.get_xydata())
        xy = xy[np.isfinite(xy).all(axis=1)]
        if len(xy) == 1 and box.contains(*xy[0]):
            return True
        if len(xy) > 1 and (Path(xy).intersects_bbox(box, filled=False)
                            or box.count_contains(xy)):
            return True
    for collection in ax.collections:
        if not collection.get_visible():
            continue
        offsets = collection.get_offsets()
        if len(offsets):
            points = collection.get_offset_transform().transform(offsets)
            if box.count_contains(points[np.isfinite(points).all(axis=1)]):
                return True
    return False


def place_legends(figure):
    """Put every legend of ``figure`` where it hides no data: its own place when clear,
    else the first clear place of :data:`LEGEND_PLACES`, else under the whole figure, below
    its axes' column (outside every panel, so that it covers no neighbour either). Legends
    that go under the figure are stacked, one under the other in the order of their axes,
    never drawn over each other; when there are several, each is titled with its panel's
    title (which panel its entries belong to). Returns True when a legend went outside (the
    figure is then saved with a tight bounding box, so that it shows)."""
    axes = [ax for ax in figure.axes if ax.get_legend() is not None]
    if not axes:
        return False
    if not hasattr(figure.canvas, "get_renderer"):  # a Figure() made without pyplot
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(figure)
    renderer = figure.canvas.get_renderer()
    figure.draw_without_rendering()
    outside = []
    for ax in axes:
        legend = ax.get_legend()
        if not legend_hides_data(ax, legend, renderer):
            continue
        for place in LEGEND_PLACES:
            legend.set_loc(place)
            if not legend_hides_data(ax, legend, renderer):
                break
        else:
            outside.append(ax)
    below = {}  # column centre (figure fraction) -> top of the next legend under it
    for ax in outside:
        legend = ax.get_legend()
        handles, labels = legend.legend_handles, [t.get_text() for t in legend.texts]
        size = legend.texts[0].get_fontsize() if legend.texts else None
        legend.remove()
        box = ax.get_position()
        x = round(0.5 * (box.x0 + box.x1), 6)
        title = ax.get_title() if len(outside) > 1 else None
        made = figure.legend(handles, labels, loc="upper center", fontsize=size,
                             bbox_to_anchor=(x, below.get(x, 0.0)),
                             ncols=min(len(labels), 3), title=title or None,
                             title_fontsize=size)
        below[x] = made.get_window_extent(renderer).y0 / figure.bbox.height
    return bool(outside)


def _plain_text(figure):
    """Draw every text of a figure made elsewhere literally (as :data:`PLAIN_TEXT` does for
    the report's own): ids from the inputs are never parsed as mathtext."""
    from matplotlib.text import Text

    for text in figure.findobj(Text):
        text.set_parse_math(False)

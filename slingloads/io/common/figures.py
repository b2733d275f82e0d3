"""Page-ready figures: fixed margins instead of a layout engine, drawn beside the tables.

Every report figure is drawn 7 in wide, the printable width of an A4 portrait page, so that
its fonts print at their nominal size. Its margins are set once, in inches, with
:func:`fix_margins`: a layout engine (``layout="constrained"``) measures every tick label by
drawing the figure an extra time, which doubled the cost of writing a report; fixed margins
sized for the labels the reports draw (titles of at most two lines, tick labels of at most
nine characters) cost nothing.

Drawing the figures is most of the cost of a report: :class:`FigureRenderer` draws them in
worker processes while the workbook's tables are written.
"""

from __future__ import annotations

import io
import multiprocessing
import os
import sys
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager

from slingloads.errors import InputError

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
#: Environment variable: how many processes draw a report's figures beside the one writing
#: its workbook (``0``: draw them in the writing process, one after the other).
WORKERS_VARIABLE = "SLINGLOADS_PLOT_WORKERS"

_JOBS = {}


def _draw(key):
    """Draw job ``key`` of :data:`_JOBS` to PNG bytes (in a worker process)."""
    from slingloads.io.common.excel import figure_png

    func, args, kwargs, dpi = _JOBS[key]
    return figure_png(func(*args, **kwargs), dpi)


class _Later:
    """A figure drawn when its PNG is first asked for (no worker process)."""

    def __init__(self, key):
        self.key = key
        self._png = None

    def result(self):
        if self._png is None:
            self._png = _draw(self.key)
        return self._png


def plot_workers():
    """Processes that draw figures beside the writing one: ``SLINGLOADS_PLOT_WORKERS`` when
    set, else up to 2 on a multi-core Linux machine, else 0. Worker processes are forked, so
    they need no pickling and start in milliseconds; where fork is not the safe default
    (Windows, macOS), figures are drawn in the writing process."""
    text = os.environ.get(WORKERS_VARIABLE, "").strip()
    if text:
        try:
            return max(0, int(text))
        except ValueError:
            raise InputError(f"{WORKERS_VARIABLE} must be a whole number of processes",
                             text) from None
    if not sys.platform.startswith("linux") or (os.cpu_count() or 1) < 2:
        return 0
    return 2


_WARM = []


def _warm_up():
    """Load the Agg backend and the fonts once in this process, before the workers are
    forked, so that they share them instead of each loading its own."""
    if _WARM:
        return
    from matplotlib.figure import Figure

    fig = Figure(figsize=(1, 1))
    fig.text(0.5, 0.5, "0.5 [m]")
    fig.add_subplot().set_title("t")
    fig.savefig(io.BytesIO(), format="png", dpi=10)
    _WARM.append(True)


class FigureRenderer:
    """Draws a report's figures to PNG while the report's tables are written.

    Use as a context manager: :meth:`draw` registers every figure (a plot function and its
    arguments) and returns, for each, an object whose ``result()`` is the PNG bytes (a
    :class:`concurrent.futures.Future` when worker processes draw them). The bytes are the
    same whichever process draws them. On leaving the block the workers are stopped (and
    pending drawings cancelled if the block failed).

    Parameters
    ----------
    workers : int, optional
        Worker processes (default :func:`plot_workers`); 0 draws each figure in this process
        when its PNG is first asked for.
    dpi : float
        Resolution of the PNG files. [dots per inch]
    """

    def __init__(self, workers=None, dpi=100):
        self.workers = plot_workers() if workers is None else int(workers)
        self.dpi = dpi
        self._pool = None
        self._keys = []
        #: Every drawing started, by tag.
        self.pngs = {}

    def __enter__(self):
        return self

    def draw(self, jobs):
        """Start drawing ``jobs`` (``{tag: (plot function, args, kwargs)}``); returns
        ``{tag: object with result() -> PNG bytes}`` in the same order."""
        keys = {}
        for tag, (func, args, kwargs) in jobs.items():
            key = (id(self), len(_JOBS), tag)
            _JOBS[key] = (func, tuple(args), dict(kwargs), self.dpi)
            keys[tag] = key
        self._keys += list(keys.values())
        if self.workers <= 0 or not keys:
            started = {tag: _Later(key) for tag, key in keys.items()}
        else:
            if self._pool is None:
                _warm_up()
                context = multiprocessing.get_context("fork")
                self._pool = ProcessPoolExecutor(max_workers=self.workers, mp_context=context)
            started = {tag: self._pool.submit(_draw, key) for tag, key in keys.items()}
        self.pngs.update(started)
        return started

    def __exit__(self, exc_type, exc, tb):
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=exc_type is not None)
        for key in self._keys:
            _JOBS.pop(key, None)
        return False


@contextmanager
def drawings(jobs, started=None, dpi=100):
    """The drawings of ``jobs`` (``{tag: object with result() -> PNG bytes}``): those of an
    already started :class:`FigureRenderer` (started while other analyses were computed),
    else drawn now, beside the block's work.

    Parameters
    ----------
    jobs : dict
        ``{tag: (plot function, args, kwargs)}``.
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


def png_bytes(png):
    """PNG bytes of a drawn figure: bytes as they are, or the ``result()`` of a pending one."""
    return png if isinstance(png, (bytes, bytearray)) else png.result()

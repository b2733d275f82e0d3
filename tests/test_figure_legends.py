"""No legend of a report figure hides data: each figure of the example's reports is drawn as
the report draws it, and every legend's box (matplotlib's window extent) is checked against
every plotted line (its segments sampled finely, in display coordinates) and marker. The
reference is matplotlib's own geometry, sampled here independently of the writer's check."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")


def _jobs(results):
    from slingloads.io.chute.report import _figures as chute
    from slingloads.io.lateral.report import _figures as lateral
    from slingloads.io.loads.report import figure_jobs
    from slingloads.io.multibody.report import _figures as multibody

    jobs = {}
    jobs.update({f"loads {k}": v for k, v in figure_jobs(results.loads, "SI")[0].items()})
    jobs.update({f"lateral {k}": v for k, v in lateral(results.lateral, "SI").items()})
    jobs.update({f"chute {k}": v for k, v in chute(results.chute_sizing, "SI").items()})
    jobs.update({f"multibody {k}": v for k, v in multibody(results.multibody, "SI").items()})
    return jobs


def _hidden(ax, box):
    """Points of the plotted lines (as drawn: clipped to the axes) and markers of ``ax``
    inside ``box`` (display px)."""
    count = 0
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        xy = line.get_transform().transform(line.get_xydata())
        xy = xy[np.isfinite(xy).all(axis=1)]
        if len(xy) > 1:  # 50 samples along every segment: a line crossing the box counts
            t = np.linspace(0.0, 1.0, 50)[:, None, None]
            xy = (xy[:-1] * (1 - t) + xy[1:] * t).reshape(-1, 2)
        if line.get_clip_on():  # drawn only inside the axes
            a = ax.bbox
            xy = xy[(xy[:, 0] >= a.x0) & (xy[:, 0] <= a.x1) & (xy[:, 1] >= a.y0)
                    & (xy[:, 1] <= a.y1)]
        inside = ((xy[:, 0] > box.x0) & (xy[:, 0] < box.x1)
                  & (xy[:, 1] > box.y0) & (xy[:, 1] < box.y1))
        count += int(inside.sum())
    for collection in ax.collections:
        offsets = collection.get_offsets()
        if collection.get_visible() and len(offsets):
            xy = collection.get_offset_transform().transform(offsets)
            count += int(((xy[:, 0] > box.x0) & (xy[:, 0] < box.x1)
                          & (xy[:, 1] > box.y0) & (xy[:, 1] < box.y1)).sum())
    return count


def test_no_legend_hides_data(example_results):
    """Every legend of every figure of the example's loads, lateral, parachute sizing and
    multibody reports lies where no plotted line or marker is."""
    from matplotlib import pyplot as plt
    from matplotlib import rc_context

    from slingloads.io.common.figures import place_legends, report_style

    jobs = _jobs(example_results)
    assert len(jobs) >= 10
    hidden = []
    for tag, (func, args, kwargs) in jobs.items():
        with rc_context(report_style()):
            figure = func(*args, **kwargs)
            place_legends(figure)  # as the report does before it saves the figure
            if not hasattr(figure.canvas, "get_renderer"):  # a Figure() made without pyplot
                from matplotlib.backends.backend_agg import FigureCanvasAgg

                FigureCanvasAgg(figure)
            figure.canvas.draw()
            renderer = figure.canvas.get_renderer()
            for k, ax in enumerate(figure.axes):
                # its own legend, and any legend of the figure (one may lie over any panel)
                for legend in [ax.get_legend(), *figure.legends]:
                    if legend is not None:
                        n = _hidden(ax, legend.get_window_extent(renderer))
                        if n:
                            hidden.append((tag, k, ax.get_title(), n))
        plt.close(figure)
    assert not hidden, hidden


@pytest.mark.parametrize("units", ["SI"])
def test_panel_titles_are_unique(example_results, units):
    """No two panels of one figure carry the same title (each says what it shows)."""
    from matplotlib import pyplot as plt
    from matplotlib import rc_context

    from slingloads.io.common.figures import report_style

    same = []
    for tag, (func, args, kwargs) in _jobs(example_results).items():
        with rc_context(report_style()):
            figure = func(*args, **kwargs)
        titles = [ax.get_title() for ax in figure.axes if ax.get_title()]
        if len(titles) != len(set(titles)):
            same.append((tag, titles))
        plt.close(figure)
    assert not same, same


def test_mode_names_are_unique(example_results):
    """The multibody modes of the example carry one name each (two parachute modes are
    numbered), so that the report and the eigenvalue plot name each mode once."""
    names = list(example_results.multibody.linear.modes_frame()["mode"])
    assert len(names) == len(set(names)), names


def _at_cell_precision(text, value):
    """Whether ``text`` writes ``value`` as a cell of format 0.000 shows it (three decimals;
    a ratio below 0.0005 in the cells' scientific notation, three significant digits)."""
    if "E" in text:
        return abs(value) < 5e-4 and float(text) == float(f"{value:.2E}")
    return len(text.partition(".")[2]) == 3 and float(text) == round(float(value), 3)


def test_eigenvalue_legend_quotes_the_modes_cells(example_results):
    """Each mode's legend entry of the multibody eigenvalue figure, drawn through its plot
    function as the report draws it, quotes its natural frequency and damping ratio at the
    precision of the Modes sheet's cells (formats.py: rad/s and '-' at 0.000): never
    'zeta 0.00142' beside a cell of 0.001. Reference: the model's modes table, rounded as
    the cell format rounds."""
    import re

    from matplotlib import pyplot as plt
    from matplotlib import rc_context

    from slingloads.io.common.figures import report_style

    func, args, kwargs = _jobs(example_results)["multibody eigenvalues"]
    modes = example_results.multibody.linear.modes_frame().set_index("mode")
    with rc_context(report_style()):
        figure = func(*args, **kwargs)
    texts = [t.get_text() for legend in figure.legends for t in legend.get_texts()]
    plt.close(figure)
    assert len(texts) == len(modes)
    wrong = []
    for text in texts:
        found = re.fullmatch(r"(.+): (\S+) rad/s, zeta (\S+)", text)
        assert found, text
        row = modes.loc[found.group(1)]
        if not (_at_cell_precision(found.group(2), row["natural frequency [rad/s]"])
                and _at_cell_precision(found.group(3), row["damping ratio [-]"])):
            wrong.append(text)
    assert not wrong, wrong


def _ramps_result(verdicts):
    """A campaign result, made by hand, holding only what the no-parachute figure reads:
    ramps to 20, 30 and 40 kt of HC1 and HC2 with the verdicts ``verdicts[(name, kt)]`` and
    yaw and sideslip histories that oscillate over the whole of each panel (no legend finds
    a clear place inside one)."""
    from types import SimpleNamespace

    import pandas as pd

    from slingloads.analyses.campaign import NoParachuteResult
    from slingloads.constants import FOOT, KNOT
    from slingloads.io.campaign.plots import BETA, YAW

    time = np.linspace(0.0, 100.0, 2001)
    rows, keys, histories = [], {}, {}
    for kt in (20, 30, 40):
        for k, name in enumerate(("HC1", "HC2")):
            target = kt * KNOT
            key = f"{name}-{kt}"
            rows.append({"helicopter": name, "ramp target [m/s]": target,
                         "verdict": verdicts[(name, kt)]})
            keys[(name, target)] = key
            wave = 30.0 * np.sin(2.0 * np.pi * time / (1.7 + k))
            histories[(name, target)] = pd.DataFrame({"time [s]": time, YAW: wave, BETA: -wave})
    runs = pd.DataFrame(rows)
    system = SimpleNamespace(cable=SimpleNamespace(length=60 * FOOT), density_altitude=0.0,
                             body=SimpleNamespace(mass=2900.0))
    study = SimpleNamespace(onset=5.0, rate=0.5, run_length=100.0,
                            systems={"HC1": system, "HC2": system},
                            ramp_end=lambda target: 5.0 + target / 0.5)
    return SimpleNamespace(no_parachute=NoParachuteResult(runs, runs.iloc[:0], keys),
                           campaign=SimpleNamespace(no_parachute=study),
                           history=histories.__getitem__)


def test_no_parachute_legends_give_each_ramps_verdict():
    """Each ramp's panel of the no-parachute figure has its own legend, readable on the saved
    figure, whose entries carry that ramp's verdicts (HC2 is convergent at 20 kt, divergent
    at 30 kt and a static departure at 40 kt; the reference is the runs table the figure is
    made from): with the legends put where the report puts them, each names its ramp (its
    panel, or the title of a legend under the figure) and no two legends overlap (their
    boxes, matplotlib's window extents)."""
    from matplotlib import pyplot as plt
    from matplotlib import rc_context

    from slingloads.io.campaign.plots import plot_no_parachute
    from slingloads.io.common.figures import place_legends, report_style

    verdicts = {("HC1", 20): "convergent", ("HC1", 30): "convergent",
                ("HC1", 40): "divergent", ("HC2", 20): "convergent",
                ("HC2", 30): "divergent", ("HC2", 40): "static departure"}
    with rc_context(report_style()):
        figure = plot_no_parachute(_ramps_result(verdicts))
        place_legends(figure)
        figure.canvas.draw()
        renderer = figure.canvas.get_renderer()
        legends = []  # (what names its ramp, texts, box)
        for ax in figure.axes:
            if ax.get_legend() is not None:
                legends.append((ax.get_title(), ax.get_legend()))
        legends += [(legend.get_title().get_text(), legend) for legend in figure.legends]
        found = {}
        for named, legend in legends:
            kt = [k for k in (20, 30, 40) if f"to {k} kt" in named]
            assert len(kt) == 1, named
            found[kt[0]] = sorted(t.get_text() for t in legend.texts)
        assert found == {kt: [f"HC1 ({verdicts[('HC1', kt)]})",
                              f"HC2 ({verdicts[('HC2', kt)]})"] for kt in (20, 30, 40)}
        boxes = [legend.get_window_extent(renderer) for _, legend in legends]
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                assert not a.overlaps(b), (a, b)
    plt.close(figure)


def test_root_locus_tells_real_from_oscillatory_and_marks_neutral_and_chosen():
    """The root locus against the area (campaign report): a real root crossing zero at
    1.1 x and an oscillatory pair of the table it is drawn from appear in the right panel
    (real part against the area factor) as crosses and circles at their own (area, real
    part); the panel marks 1.0 x neutral and the chosen 1.4 x; the title is the caller's
    base condition."""
    import pandas as pd

    from slingloads.io.campaign.plots import plot_root_locus

    f = np.round(np.linspace(0.8, 1.6, 9), 3)
    loci = pd.concat([
        pd.DataFrame({"area factor [-]": f, "real [1/s]": 0.1 * (1.1 - f), "imag [rad/s]": 0.0}),
        pd.DataFrame({"area factor [-]": f, "real [1/s]": -0.05, "imag [rad/s]": 0.7}),
        pd.DataFrame({"area factor [-]": f, "real [1/s]": -0.05, "imag [rad/s]": -0.7})])
    figure = plot_root_locus(loci, "100 KEAS, 0 m HD, mass maximum 2900 kg", chosen=1.4)
    right = figure.axes[1]
    points = {}
    for collection in right.collections:
        label = collection.get_label()
        points[label] = np.asarray(collection.get_offsets())
    np.testing.assert_allclose(points["real"], np.column_stack([f, 0.1 * (1.1 - f)]))
    assert len(points["oscillatory"]) == 2 * len(f)
    np.testing.assert_allclose(points["oscillatory"][:, 1], -0.05)
    lines = {line.get_label(): line.get_xdata()[0] for line in right.get_lines()
             if line.get_label() in ("1.0 x neutral", "chosen 1.4 x")}
    assert lines == {"1.0 x neutral": 1.0, "chosen 1.4 x": 1.4}
    assert figure._suptitle.get_text().startswith("100 KEAS")

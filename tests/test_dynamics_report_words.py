"""Words and units of the dynamics reports (parachute sizing, multibody, campaign): one
verdict vocabulary per kind of result, no abbreviation that reads as a unit, airspeeds in kt.

References: the vocabularies of :mod:`slingloads.analyses.verdicts` (a response is
convergent, divergent, a static departure...; a linear model is stable, neutral or unstable,
the words :meth:`LinearModel.verdict` returns), the knot as 1852 m / 3600 s (its definition),
and the reports' own text cells as openpyxl reads them back.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[1]
#: "mm." (or "MM.", "m.m.") as an abbreviation (of "multibody model"...): it reads as
#: millimetres. A length after a number ("4 mm.") is a unit, not an abbreviation.
ABBREVIATION = re.compile(r"(?<!\d)(?<!\d )\b(?:mm|MM|m\.m)\.(?=[\s,;:)]|$)")
#: Verdict words no report uses (the vocabulary of analyses/verdicts.py has one word per
#: outcome): "departs" (a static departure or divergent), "undamped" (limit cycle...).
STRAY_VERDICTS = re.compile(r"\b(?:departs|undamped)\b")


def _sources():
    for folder in ("slingloads", "docs"):
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in (".py", ".md"):
                yield path
    yield ROOT / "README.md"


def test_no_abbreviation_reads_as_millimetres_in_code_or_documents():
    """No text of the package or its documents abbreviates as 'mm.' (multibody model) or
    'm.m.': a checker reads millimetres."""
    found = [(p.relative_to(ROOT).as_posix(), n, line.strip()[:80])
             for p in _sources()
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if ABBREVIATION.search(line)]
    assert not found, found


#: "HD" for a density altitude: the tables and every other report's titles say "density
#: altitude"; one name per quantity.
ALTITUDE_ABBREVIATION = re.compile(r"\bHD\b")


def test_no_report_text_abbreviates_the_density_altitude():
    """No title, label or sentence the package writes names the density altitude "HD" (the
    campaign's figures said "0 m HD" where its tables, the multibody and the sizing figures
    say "0 m density altitude"): the report writers' string literals are searched (the
    figures' texts are made there; tests/test_ramp_gust.py reads one title back)."""
    found = [(p.relative_to(ROOT).as_posix(), n, line.strip()[:80])
             for p in sorted((ROOT / "slingloads").rglob("*.py"))
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if ALTITUDE_ABBREVIATION.search(line)]
    assert not found, found


def test_the_examples_report_cells_use_whole_words(example_run_report):
    """Every text cell of the example's dynamics reports (parachute sizing, multibody): no
    'mm.' abbreviation and no stray verdict word ('departs', 'undamped')."""
    import openpyxl

    bad = []
    books = [b for b in sorted(example_run_report.glob("*.xlsx"))
             if b.stem.endswith(("-chute", "-multibody", "-campaign"))]
    assert len(books) >= 2, books
    for book in books:
        for ws in openpyxl.load_workbook(book, read_only=True).worksheets:
            for row in ws.iter_rows(values_only=True):
                for value in row:
                    if isinstance(value, str) and (ABBREVIATION.search(value)
                                                   or STRAY_VERDICTS.search(value)):
                        bad.append((book.name, ws.title, value[:100]))
    assert not bad, bad


def test_figure_texts_use_whole_words(example_results):
    """Every text of every figure of the example's parachute sizing and multibody reports
    (titles, labels, legends, colour-bar labels): no 'mm.' abbreviation, no stray verdict
    word."""
    from matplotlib import pyplot as plt
    from matplotlib import rc_context
    from matplotlib.text import Text

    from slingloads.io.chute.report import _figures as chute
    from slingloads.io.common.figures import report_style
    from slingloads.io.multibody.report import _figures as multibody

    jobs = {**{f"chute {k}": v for k, v in chute(example_results.chute_sizing, "SI").items()},
            **{f"multibody {k}": v
               for k, v in multibody(example_results.multibody, "SI").items()}}
    assert len(jobs) >= 5
    bad = []
    for tag, (func, args, kwargs) in jobs.items():
        with rc_context(report_style()):
            figure = func(*args, **kwargs)
        for text in figure.findobj(Text):
            words = text.get_text()
            if ABBREVIATION.search(words) or STRAY_VERDICTS.search(words):
                bad.append((tag, words))
        plt.close(figure)
    assert not bad, bad


def test_eigenvalue_colour_scales_speak_the_linear_models_words():
    """The stability map's colour scales read in the words of the linear model's verdict
    (the tables' 'linear verdict': stable / unstable), not in the response verdicts
    (convergent, divergent, static departure), which name responses."""
    from slingloads.analyses import verdicts as vd
    from slingloads.io.campaign.plots import DAMPING_SCALE, REAL_PART_SCALE

    for label in (DAMPING_SCALE, REAL_PART_SCALE):
        assert "> 0" in label and "< 0" in label and "[" in label  # sign and unit stated
        assert vd.STABLE in label and vd.UNSTABLE in label
        for word in (vd.CONVERGENT, vd.DIVERGENT, vd.STATIC_DEPARTURE):
            assert word not in label, (word, label)
    assert "< 0 stable" in REAL_PART_SCALE and "> 0 stable" in DAMPING_SCALE


def test_linear_verdict_words_are_the_vocabularys():
    """LinearModel.verdict() answers in verdicts.STABLE / NEUTRAL / UNSTABLE by the rule of
    verdicts.EIGENVALUE_TOLERANCE (a real part of +1e-6 is neutral, not stable)."""
    from types import SimpleNamespace

    from slingloads.analyses import verdicts as vd
    from slingloads.analyses.multibody.trim import LinearModel

    def verdict(real):
        return LinearModel.verdict(SimpleNamespace(eigenvalues=np.array([real, -1.0])))

    tol = vd.EIGENVALUE_TOLERANCE
    assert verdict(-2 * tol) == vd.STABLE
    assert verdict(tol) == vd.NEUTRAL and verdict(-tol) == vd.NEUTRAL
    assert verdict(2 * tol) == vd.UNSTABLE


def test_carrier_speed_in_knots_in_both_unit_systems():
    """The reports' one SI-column conversion: the carrier speed (the flight speed of the
    carrying helicopter) is an airspeed-like quantity, in kt in SI and US reports, 41.156 m/s
    = 80.0 kt (1 kt = 1852/3600 m/s), like the airspeed beside it; another speed stays m/s or
    ft/s (1 ft = 0.3048 m); a density altitude is in ft in US units, not in inches as a length
    would be; the campaign's tables take every speed (ramp targets) as an airspeed."""
    from slingloads.io.campaign.report import in_units
    from slingloads.io.common.report import si_columns_in_units

    frame = pd.DataFrame({"carrier speed end [m/s]": [80 * 1852 / 3600],
                          "airspeed [m/s]": [30 * 1852 / 3600], "x [m]": [1.0],
                          "peak gust [m/s]": [3.048], "density altitude [m]": [304.8]})
    for units in ("SI", "US"):
        out = si_columns_in_units(frame, units)
        assert out["carrier speed end [kt]"].iloc[0] == pytest.approx(80.0, rel=1e-12)
        assert out["airspeed [kt]"].iloc[0] == pytest.approx(30.0, rel=1e-12)
    us = si_columns_in_units(frame, "US")
    assert us["peak gust [ft/s]"].iloc[0] == pytest.approx(10.0, rel=1e-12)
    assert us["density altitude [ft]"].iloc[0] == pytest.approx(1000.0, rel=1e-12)
    assert us["x [in]"].iloc[0] == pytest.approx(1 / 0.0254, rel=1e-12)
    ramps = in_units(pd.DataFrame({"ramp target [m/s]": [20 * 1852 / 3600]}), "US")
    assert ramps["ramp target [kt]"].iloc[0] == pytest.approx(20.0, rel=1e-12)


def test_verdict_row_names_the_area_it_was_run_at():
    """The sizing Summary's verdict 'at the paper's factor' names the swept area it was run
    at: 1.4 x when the sweep has it, else the nearest swept factor (the US twin's sweep has
    1.0, 1.5, 2.0 x: its row said '1.4 x' beside 'swept area 1.5 x neutral')."""
    from slingloads.io.chute.report import factor_row_label

    assert factor_row_label(1.4, 1.4) == "1-DOF verdict at the paper's factor (1.4 x neutral)"
    assert factor_row_label(1.4, 1.5) == ("1-DOF verdict at 1.5 x neutral (the swept area "
                                          "nearest the paper's 1.4 x)")


def test_stability_map_draws_a_single_airspeed():
    """A stability map of one airspeed (the US twin's campaign: 80 KEAS only) draws its cells:
    each cell is centred on its grid point (edges midway between neighbours, a single point
    +-5 % wide), so the map is never blank."""
    from slingloads.io.campaign.plots import cell_edges

    np.testing.assert_allclose(cell_edges([80.0]), [76.0, 84.0])
    np.testing.assert_allclose(cell_edges([60.0, 70.0, 80.0]), [55, 65, 75, 85])
    np.testing.assert_allclose(cell_edges([0.0]), [-0.5, 0.5])


def test_masses_in_titles_to_the_unit():
    """A mass in a campaign title (root locus, stability map) is written to the unit in
    both systems: the US twin's 4900.1 kg is 10803 lb (4900.1 / 0.45359237), never
    '1.08e+04 lb'."""
    from slingloads.io.campaign.words import mass_text

    assert mass_text(4900.1, "US") == "10803 lb"
    assert mass_text(2900.0, "SI") == "2900 kg"


def test_cs29_gust_reads_30_ft_per_s_in_us_reports():
    """The CS 29.341 gust (30 ft/s = 9.144 m/s exactly) is labelled so that a US report reads
    '30 ft/s' (the sizing's gust labels said 'step 29.99 ft/s': 9.14 m/s rounded before the
    conversion), and an SI report '9.144 m/s', as the campaign's 'standard 9.144 m/s'."""
    from slingloads.io.common.units import report_text
    from slingloads.models import gusts

    for gust in (gusts.StepGust(), gusts.FiniteGust(duration=10.0), gusts.SustainedGust()):
        assert "9.144 m/s" in gust.label
        assert "30 ft/s" in report_text(gust.label, "US"), report_text(gust.label, "US")


def test_history_headers_quote_the_sweep_tables_areas(example_results):
    """The sizing Histories' column headers quote each run's area as the Sweep table prints
    it (3 decimals in m^2): one precision per quantity in the report."""
    from slingloads.io.chute.report import history_table

    result = example_results.chute_sizing
    areas = {f"{a:.3f}" for a in result.stability_by_area()["area [m^2]"]}
    quoted = {m.group(1) for c in history_table(result, "SI").columns
              if (m := re.search(r"A=(\S+) m\^2", c))}
    assert quoted and quoted <= areas, (quoted, areas)


def test_a_constant_metric_reads_as_its_value():
    """A sweep metric equal at every area up to round-off (the US twin's peak sideslip,
    12.5265803 deg for every area: the gust angle) is plotted on plain ticks over +-5 % of
    its value, not in matplotlib's offset notation ('1e-11+1.25265803e1'); a metric that
    varies keeps its own range (the damping ratios' 0.17-0.27)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from slingloads.io.chute.plots import readable_range

    figure = Figure()
    FigureCanvasAgg(figure)
    ax = figure.subplots()
    ax.plot([1.0, 2.0, 3.0], 12.5265803 + np.array([0.0, 1e-11, 1e-11]))
    readable_range(ax)
    figure.canvas.draw()  # the offset text is made when drawn
    low, high = ax.get_ylim()
    assert high - low == pytest.approx(0.1 * 12.5265803) and low < 12.5265803 < high
    assert ax.yaxis.get_major_formatter().get_offset() == ""
    other = figure.add_subplot(2, 1, 2)
    other.plot([1.0, 2.0], [0.17, 0.27])
    before = other.get_ylim()
    readable_range(other)
    assert other.get_ylim() == before

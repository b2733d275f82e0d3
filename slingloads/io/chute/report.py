"""The parachute-sizing report: an Excel workbook and PNG plots (paper sections 3.2-4.2).

The sizing is run by :func:`slingloads.runs.chute_sizing.run` (linearisation of the fuselage
and fin yawing moments, neutral static area with its breakdown, wake ratio and line length
with the carrier-cable check, and the 1-DOF sweep of the parachute area over the gust
shapes); this module only says what its report is made of (:func:`report_kind`), which the
one report writer publishes all at once or not at all (:mod:`slingloads.io.common.atomic`):

* ``<stem>-chute.xlsx``, print-ready: sheets *Cover* (identification, input file and its
  SHA-256, version, sheets, conventions), *Summary* (condition, neutral area and its
  breakdown, recommended area, line length and cable check), *Linearisation*,
  *StaticMoments* (every 5 deg for print), *Wake*, *Sweep* (metrics of every run),
  *Histories* (sideslip and yaw of the runs at the smallest, recommended and largest swept
  areas, for every gust shape, sampled for print) and *Plots*;
* ``<stem>-chute-histories.csv``: the same histories at every stored sample, one row per run
  and time (SI, degrees, ``name_unit`` headers: ``run,area_m2,gust,time_s,beta_deg,psi_deg``);
* ``<stem>-chute-linearisation.png``, ``-chute-static-moments.png``, ``-chute-wake.png``,
  ``-chute-sweep.png``, ``-chute-histories.png`` (one panel per gust shape).

Lengths, areas, speeds and moments are in the report unit system (``--units``).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.analyses.chute_sizing import (
    wake_ratio_at,
)
from slingloads.analyses.hook_loads import angle_words
from slingloads.constants import FOOT, KNOT, POUND_FORCE
from slingloads.io.common.csvout import csv_bytes
from slingloads.io.common.decision import decision_section, with_decision
from slingloads.io.common.excel import Section
from slingloads.io.common.figures import plot_function
from slingloads.io.common.report import (
    convert_columns,
    quantity_text,
    report_unit,
    report_value,
    sample_rows,
    warning_sections,
)
from slingloads.io.common.report_writer import ReportKind
from slingloads.io.common.units import unit_label

ANALYSIS = "chute sizing"
#: PNG files written, by tag: ``<stem>-chute-<tag>.png``.
PLOTS = ("linearisation", "static-moments", "wake", "sweep", "histories")
#: Names of the files of a sizing report, for the publisher (a new report replaces them all).
OUTPUTS = ("{stem}-chute.xlsx", "{stem}-chute-histories.csv",
           *(f"{{stem}}-chute-{tag}.png" for tag in PLOTS))
_PNG_DPI = 100
#: Title of each figure on the Plots sheet.
FIGURE_TITLES = {"linearisation": "Yawing-moment linearisation (paper figures 4-5)",
                 "static-moments": "Static yawing moments at the neutral area",
                 "wake": "Wake ratio and line length", "sweep": "Sweep metrics against area",
                 "histories": "Time histories for every gust shape (paper figure 7)"}
#: Most rows of each table of the Histories sheet (the CSV file keeps every stored sample).
HISTORY_ROWS = 65
#: Sideslip interval of the curve tables (Linearisation, StaticMoments) when they are
#: longer than :data:`CURVE_ROWS` rows; the plots show every point. [deg]
CURVE_STEP = 5.0
CURVE_ROWS = 50

TITLE = "Parachute sizing report: yaw stability of the carried helicopter"
DESCRIPTION = (
    "Size of the drogue parachute trailed from the fin of the carried helicopter for yaw "
    "stability (paper sections 3.2-4.2): linearisation of the fuselage and fin yawing "
    "moments, the neutral static area and its breakdown, the recommended area, the wake "
    "dynamic-pressure ratio and the parachute line length with the carrier-cable check, and a "
    "1-DOF yaw sweep of the parachute area under lateral gusts of every shape asked for. "
    "Method: docs/parachute-sizing.md.")
CONVENTIONS = (
    "Yaw psi and sideslip beta positive nose right and wind from the right; yawing moment N "
    "about the suspension (hub) axis, > 0 nose right; dN/dbeta > 0 is statically stable.",
    "Areas are parachute flat-plate areas; the neutral area makes the total dN/dbeta zero.",
)


#: How the paper found the parachute area (the Summary's note on the sizing).
PAPER_NOTE = ("As the paper found it: its 1-DOF model (section 4.2) confirmed the neutral "
              "static area; the complete multibody model (4.5) found it insufficient, the "
              "shortfall coming from the inter-axis coupling of helicopter and parachute (the "
              "carrier's coupling was negligible). This sizing reproduces 4.1-4.2 only; the "
              "factor 1.4 is the paper's optimum for its own aircraft, not this one's.")


# ------------------------------------------------------------------------------- tables
def _value(value, kind, units):
    """(value in report units, unit label)."""
    if kind is None or kind in ("deg", "-"):
        return value, kind or ""
    if kind == "pressure":
        return (value, "Pa") if units == "SI" else (value / (POUND_FORCE / FOOT**2), "psf")
    return report_value(value, kind, units), unit_label(report_unit(kind, units))


def _items(rows, units):
    """Rows (item, SI value, kind or None, note) as a table in report units."""
    out = []
    for item, value, kind, note in rows:
        shown, unit = _value(value, kind, units) if isinstance(value, float) else (value, "")
        out.append({"item": item, "value": shown, "unit": unit, "note": note})
    return pd.DataFrame(out, dtype=object)  # a count stays an int (written "15")


def factor_row_label(paper_factor, swept_factor):
    """Label of the 1-DOF verdict at the paper's factor: the factor the verdict was run at,
    and, when the sweep has no area at the paper's, that it is the nearest swept one.

    Parameters
    ----------
    paper_factor, swept_factor : float
        The paper's factor and the swept area nearest it, x neutral area. [-]

    Returns
    -------
    str
    """
    if abs(swept_factor - paper_factor) <= 1e-9 * paper_factor:
        return f"1-DOF verdict at the paper's factor ({paper_factor:g} x neutral)"
    return (f"1-DOF verdict at {swept_factor:.3g} x neutral (the swept area nearest the "
            f"paper's {paper_factor:g} x)")


def summary_tables(result, units="SI"):
    """The Summary's tables: condition, neutral area and recommendation, line and cable."""
    inp, static, line = result.inputs, result.static, result.line
    m = inp.model
    c = m.condition
    condition = _items([
        ("equivalent airspeed KEAS", c.ias, "airspeed", "= KIAS (no position error)"),
        ("true airspeed KTAS", c.tas, "airspeed", ""),
        ("density altitude", c.density_altitude, "altitude", "ISA"),
        ("air density", c.density, "density", ""),
        ("dynamic pressure q", c.dynamic_pressure, "pressure", "1/2 rho0 V_EAS^2"),
        ("alpha trim", float(np.degrees(c.alpha)), "deg",
         (f"towed trim at this airspeed with the Study's parachute (the attitude the loads' "
          f"towed cases and the multibody model fly; pitch "
          f"{angle_words(np.degrees(result.towed.pitch))}"
          " deg); the swept areas are sized at it"
          if result.towed is not None and result.towed.converged else
          "Study 'chute sizing alpha trim' (no towed trim: "
          + (result.towed.message if result.towed is not None else "no towed system") + ")")),
        ("yaw axis", f"'{inp.yaw_axis}'", None,
         f"{result.axis_text}: yawing moments, yaw inertia and weight all about it"),
        ("yaw axis from airframe z", float(np.degrees(result.axes_angle)), "deg",
         "the one axis of the 1-DOF model"),
        ("yaw inertia about the yaw axis", m.yaw_inertia, "inertia",
         f"source: {inp.inertia_source}" + (" (taken as about the yaw axis)"
                                            if inp.inertia_source == "parameter" else "")),

        ("linearisation range", float(np.degrees(inp.fit_range[1])), "deg",
         "fit over +- this; a run leaving it is outside the domain"),
        ("sideslip limit", float(np.degrees(inp.metrics.sideslip_limit)), "deg",
         "a run passing it is outside the domain"),
        ("parachute canopy CD (free stream)", float(m.parachute.coefficient(0.0)), "-",
         "ParachuteCD at canopy alpha 0 (default 1.0)"),
        ("parachute wake ratio", float(m.parachute.wake_ratio), "-",
         "carries the wake loss, counted once"),
        ("parachute CD x wake ratio", float(m.chute_drag_coefficient), "-",
         "the one factor of the drag (paper: 0.95)"),
        ("parachute arm aft of the yaw axis", float(m.chute_arm[0]), "length",
         "normal to the axis"),
    ], units)
    sweep_rows = []
    if result.sweep is not None:
        stable = result.stability_by_area()
        ratio = stable["area / neutral area [-]"].to_numpy()
        at = stable.iloc[int(np.argmin(np.abs(ratio - inp.recommended_factor)))]
        rec = result.recommended_area
        sweep_rows = [
            ("recommended area", rec, "area",
             f"{rec / static.area:.3g} x neutral: the smallest swept area with every gust "
             "convergent (bounded under the continuous gust), 1-DOF"
             if np.isfinite(rec) else
             "NONE: no swept area is convergent under every gust (1-DOF); widen the sweep"),
            # the row names the area it was run at: the swept area nearest the paper's factor
            (factor_row_label(inp.recommended_factor, float(at["area / neutral area [-]"])),
             "stable for every gust" if at["all gusts stable"]
             else f"NOT stable for every gust (worst: {at['worst verdict']})", None,
             f"swept area {float(at['area / neutral area [-]']):.3g} x neutral"),
        ]
    sizing = _items([
        ("neutral static area", static.area, "area",
         "fuselage and fin already stable" if static.already_stable
         else f"total dN/dbeta = 0 (paper 4.1), used: {static.basis_text}"),
        ("neutral area, least-squares slopes", static.area_fit, "area",
         f"slopes fitted over +-{np.degrees(inp.fit_range[1]):.3g} deg"),
        ("neutral area, local slopes at beta 0", static.area_local, "area",
         "slopes of the tables at zero sideslip"),
        ("paper's factor", inp.recommended_factor, "-",
         "x neutral area: the paper's optimum for its own aircraft (FPA + 40 %, from its "
         "multibody campaign, section 4.5); shown for comparison, not used"),
        *(sweep_rows or [("recommended area", result.recommended_area, "area", "")]),
        ("Study 'parachute area' (loads)", inp.study_area, "area",
         f"{inp.study_area / static.area:.3g} x neutral" if static.area > 0 else ""),
        *_study_area_rows(result),
    ], units)
    breakdown = static.to_frame()[["component", "dN/dbeta [N m/rad]"]].copy()
    factor, unit = _value(1.0, "moment", units)
    breakdown["dN/dbeta [N m/rad]"] *= factor
    breakdown["dN/dbeta [N m/deg]"] = breakdown["dN/dbeta [N m/rad]"] * np.pi / 180
    breakdown = breakdown.rename(columns={"dN/dbeta [N m/rad]": f"dN/dbeta [{unit}/rad]",
                                          "dN/dbeta [N m/deg]": f"dN/dbeta [{unit}/deg]"})
    cable = line.cable
    rows = [("wake source", line.wake_source, None, ""),
            ("target q ratio", line.target, "-", ""),
            ("parachute line length (from the wake)", line.line_length, "length", ""),
            ("Study 'parachute line length'", inp.study_line, "length",
             "ok" if inp.study_line >= line.line_length * (1 - 1e-9)
             else "SHORTER than the wake line: the canopy sees less than the target q"),
            _wake_ratio_row(inp)]
    if cable is None:
        rows.append(("carrier cable check", "not done", None,
                     "'chute sizing carrier cable length' not given"))
    else:
        rows += [("carrier cable length", cable.cable_length, "length", ""),
                 ("required cable length", cable.required, "length",
                  f"(1 + {cable.margin:g}) x line "
                  f"{quantity_text(cable.line_length, 'length', units)} (the longer of the "
                  "wake's and the Study's, the one flown)"),
                 ("carrier cable check", "ok" if cable.ok else "FAIL", None,
                  _cable_message(cable, units))]
    return {"condition": condition, "sizing": sizing, "breakdown": breakdown,
            "line": _items(rows, units)}


def _wake_ratio_row(inp):
    """The wake's q ratio at the Study's line against the 'parachute wake ratio' the drag
    uses: the one factor that carries the wake loss must agree with the wake data."""
    at_line = wake_ratio_at(inp.wake, inp.study_line)
    used = float(inp.model.parachute.wake_ratio)
    if not np.isfinite(at_line):
        note = "the Study line lies outside the wake data: check 'parachute wake ratio' by hand"
    elif abs(at_line - used) <= 0.005:
        note = f"agrees with 'parachute wake ratio' {used:.3g}"
    else:
        note = (f"DIFFERS from 'parachute wake ratio' {used:.3g}, which the drag uses: set it "
                "to the wake's value at the line")
    return ("wake q ratio at the Study line", at_line, "-", note)


def _study_area_rows(result):
    """Peak sideslip and verdicts of the gusts at the Study's 'parachute area'."""
    if result.study_area_runs is None:
        return []
    peak, gust = result.study_area_peak_sideslip
    frame = result.study_area_runs.to_frame()
    verdicts = ", ".join(f"{g}: {v}" for g, v in zip(frame["gust"], frame["verdict"],
                                                      strict=True))
    return [("peak sideslip at the Study 'parachute area'", float(np.degrees(peak)), "deg",
             f"{gust} gust; the loads' aerodynamic envelope must cover it"),
            ("1-DOF verdicts at the Study 'parachute area'", verdicts, None, "")]


def _cable_message(cable, units):
    """The check's message in report units."""
    def show(x):
        return quantity_text(x, "length", units)
    if cable.ok:
        return (f"the cable is at least {cable.margin:.0%} longer than the parachute line "
                f"{show(cable.line_length)}")
    return (f"carrier cable too short: it must be at least {cable.margin:.0%} longer than the "
            f"parachute line {show(cable.line_length)}, i.e. >= {show(cable.required)}; "
            f"lengthen the cable by {show(cable.required - cable.cable_length)} or shorten "
            f"the line to <= {show(cable.cable_length / (1 + cable.margin))}")


def _run_label(result, j, units):
    runs = result.sweep.runs
    area, unit = _value(float(runs.areas[j]), "area", units)
    # the precision of the areas in the report's tables (0.289 m^2, 18.12 ft^2)
    return f"A={area:.{3 if units == 'SI' else 2}f} {unit} {runs.gusts[j].kind}"


def history_table(result, units="SI", interval=None):
    """Sideslip and yaw [deg] against time for :meth:`ChuteSizingReport.history_runs`, one
    pair of columns per run.

    Parameters
    ----------
    interval : float, optional
        Keep one sample every ``interval`` (rounded to a whole number of stored samples);
        default: every stored sample. [s]
    """
    runs = result.sweep.runs
    h = runs.histories
    step = 1
    if interval is not None and h.time.size > 1:
        step = max(1, int(round(interval / (h.time[1] - h.time[0]))))
    frame = {"time [s]": h.time[::step]}
    for j in result.history_runs():
        tag = _run_label(result, j, units)
        frame[f"beta [deg] {tag}"] = np.degrees(h.beta[j, ::step])
        frame[f"psi [deg] {tag}"] = np.degrees(h.psi[j, ::step])
    return pd.DataFrame(frame)


def history_tables(result, units="SI"):
    """The Histories sheet: sideslip and yaw tables (one column per run), sampled for print.

    Returns
    -------
    (pandas.DataFrame, pandas.DataFrame, float)
        Sideslip [deg] and yaw [deg] against time, and the sampling interval. [s]
    """
    frame, interval = sample_rows(history_table(result, units), "time [s]", HISTORY_ROWS)
    out = []
    for name in ("beta", "psi"):
        columns = [c for c in frame.columns if c.startswith(f"{name} [deg] ")]
        table = frame[["time [s]", *columns]].copy()
        table.columns = ["time [s]", *(f"{c[len(name) + 7:]} [deg]" for c in columns)]
        out.append(table)
    return out[0], out[1], interval


def history_csv_frame(result):
    """Every stored sample of the history runs, one row per run and time (SI, degrees)."""
    runs = result.sweep.runs
    h = runs.histories
    frames = [pd.DataFrame({"run": j + 1, "area_m2": float(runs.areas[j]),
                            "gust": runs.gusts[j].kind, "time_s": h.time,
                            "beta_deg": np.degrees(h.beta[j]), "psi_deg": np.degrees(h.psi[j])})
              for j in result.history_runs()]
    return pd.concat(frames, ignore_index=True)


def curve_rows(frame, column="beta [deg]"):
    """A curve table at every :data:`CURVE_STEP` of ``column`` when longer than
    :data:`CURVE_ROWS` rows (for print), and a note saying so."""
    if len(frame) <= CURVE_ROWS:
        return frame, ""
    values = frame[column].to_numpy(float)
    keep = np.abs(values / CURVE_STEP - np.round(values / CURVE_STEP)) < 1e-6
    if keep.sum() < 2:
        return frame, ""
    # the rows the table has at whole multiples of the step (a table coarser than the step
    # in places gives fewer: "every 5 deg" would misstate it)
    return frame[keep], (f"Rows at multiples of {CURVE_STEP:g} deg of sideslip "
                         f"({int(keep.sum())} of {len(frame)}); the plot shows every point.")


def _decision_sentence(decision, units):
    """The study's chosen area in one sentence (the parachute decision's answer), '' when
    there is no decision."""
    if decision is None:
        return ""
    if not decision.found:
        return f" Chosen area (parachute decision): NONE, {decision.reason}."
    # areas quoted in SI, which the report writes at an area cell's precision in its units
    return (f" Chosen area (parachute decision, the same in every report): "
            f"{decision.chosen_area:.6g} m^2, "
            f"decided by the {decision.deciding_model}.")


def _summary_note(result, units, decision=None):
    """The sizing's outcome in two sentences, and the decision's chosen area."""
    static = result.static
    if static.already_stable:
        return "Fuselage and fin are already statically stable in yaw: no parachute needed."
    area, rec = static.area, result.recommended_area  # [m^2], converted as the report writes
    line = quantity_text(result.line.line_length, "length", units)
    said = _decision_sentence(decision, units)
    if not np.isfinite(result.recommended_area):
        return (f"Neutral static area {area:.6g} m^2; NO swept area is stable under every "
                f"gust (1-DOF): no area recommended; parachute line {line} from "
                "the wake." + said)
    return (f"Neutral static area {area:.6g} m^2; 1-DOF recommended area {rec:.6g} m^2 "
            f"({result.recommended_area / static.area:.3g} x neutral, the smallest swept area "
            f"stable under every gust); parachute line {line} from the wake."
            + said)


def _sheets(result, units, warnings=(), decision=None):
    tables = summary_tables(result, units)
    decision = result.decision if decision is None else decision
    lin = result.static.linearisation
    static = result.static.curves_frame()
    moment_spec = {c: (c[:c.index(" [")], "moment") for c in static.columns if c.startswith("N ")}
    wake = convert_columns(result.line.curve_frame(), {"distance [m]": ("distance", "length")},
                           units)
    curves, curves_note = curve_rows(lin.curves_frame())
    moments, moments_note = curve_rows(convert_columns(static, moment_spec, units))
    summary = [Section("Summary of the parachute sizing",
                       note=_summary_note(result, units, decision)),
               *warning_sections(warnings),
               Section("Condition", tables["condition"]),
               *decision_section(decision, units),
               Section("Parachute area", tables["sizing"], note=PAPER_NOTE),
               Section("Yaw stiffness breakdown at the neutral area", tables["breakdown"]),
               Section("Parachute line and carrier cable", tables["line"])]
    sheets = {
        "Summary": summary,
        "Linearisation": [Section("Linearisation of the yawing-moment coefficients",
                                  note="Fuselage and cut-down fin Cn against sideslip: the "
                                       "table and its least-squares line over the fit range."),
                          Section("Least-squares fit of Cn against sideslip", lin.to_frame()),
                          Section("Table against fit", curves, note=curves_note)],
        "StaticMoments": [Section("Static yawing moments about the suspension axis at the "
                                  "neutral area", moments, note=moments_note)],
        "Wake": [Section(f"Wake dynamic-pressure ratio ({result.line.wake_source})", wake)],
    }
    if result.sweep is not None:
        area = {"area [m^2]": ("area", "area")}
        speed = {c: (c[:c.index(" [")], "speed") for c in ("peak gust [m/s]",)}
        sheets["Sweep"] = [
            Section("Sweep of the parachute area: 1-DOF yaw runs under every gust shape",
                    note="Verdict per run (docs/parachute-sizing.md): 'outside domain' when "
                         "the sideslip leaves the tables, the linearisation range or the "
                         "sideslip limit (with the time); else the envelope test on the "
                         "sideslip after the gust: divergent, limit cycle, static departure "
                         "(settles off trim, with its size) or convergent (only if the linear "
                         "yaw mode is stable, else inconclusive). An area is stable when every "
                         "gust is convergent. Damping from the logarithmic decrement, checked "
                         "against the linear yaw mode ('damping check')."),
            Section("Gust shapes", convert_columns(result.sweep.gust_frame(), speed, units)),
            Section("Stability by area",
                    convert_columns(result.stability_by_area(), area, units)),
            Section("Every run", convert_columns(result.sweep.to_frame(), area, units),
                    note="final beta, final psi: the last sample of the run. beta trim: the "
                         "static equilibrium the run is judged about (at rest, or under the "
                         "gust still acting at the end, step and continuous, which moves it "
                         "when the weight has a moment about the yaw axis). beta offset from "
                         "trim: the mean sideslip over the second half of the window after "
                         "the gust, less beta trim (a run that settles off its trim is a "
                         "static departure of that size). So final beta lies within twice "
                         "the second half's amplitude of beta trim + offset.")]
        beta, psi, interval = history_tables(result, units)
        note = (f"Every {interval:g} s; every stored sample in the -chute-histories.csv file. "
                "Columns: swept area and gust shape of each run.")
        sheets["Histories"] = [
            Section("Time histories of the runs at the smallest, recommended and largest "
                    "areas", note=note),
            Section("Sideslip beta of the runs at the smallest, recommended and largest areas",
                    beta),
            Section("Yaw psi of the same runs", psi)]
    else:
        sheets["Sweep"] = ("Fuselage and fin are already statically stable in yaw: the neutral "
                           "area is not positive, so no sweep was run.")
    return sheets


def condition_text(result, units="SI"):
    """The sizing's flight condition, for the figures' titles: airspeed, density altitude
    and the angle of attack the areas are sized at."""
    c = result.inputs.model.condition
    return (f"{c.ias / KNOT:.4g} KEAS, "
            f"{quantity_text(c.density_altitude, 'altitude', units)} density altitude, "
            f"alpha {np.degrees(c.alpha):.1f} deg")


def _figures(result, units="SI"):
    """The figures to draw: ``{tag: (plot function, args, kwargs)}``."""
    (plot_histories_by_gust, plot_static_moments, plot_sweep_metrics, plot_wake,
     plot_yaw_linearisation) = (  # matplotlib loads where they are drawn
        plot_function("slingloads.io.chute.plots", name)
        for name in ("plot_histories_by_gust", "plot_static_moments", "plot_sweep_metrics",
                     "plot_wake", "plot_yaw_linearisation"))
    figs = {"linearisation": (plot_yaw_linearisation, (result.static.linearisation,), {}),
            "static-moments": (plot_static_moments, (result.static, units), {}),
            "wake": (plot_wake, (result.line, units), {})}
    if result.sweep is not None:
        condition = condition_text(result, units)
        figs["sweep"] = (plot_sweep_metrics, (result.sweep, units),
                         {"title": f"1-DOF parachute sizing sweep, {condition}\n(dotted: "
                                   "neutral static area)"})
        figs["histories"] = (plot_histories_by_gust,
                             (result.sweep.runs, result.history_runs()),
                             {"title": "1-DOF yaw response to every gust shape (paper figure "
                                       f"7)\n{condition}", "units": units})
    return figs


def histories_csv(result):
    """The bytes of ``<stem>-chute-histories.csv`` (:func:`history_csv_frame`)."""
    return csv_bytes(history_csv_frame(result))


def _titles(result):
    return FIGURE_TITLES


def _histories_csv_if_swept(result):
    """The bytes of ``<stem>-chute-histories.csv``, or None without a sweep."""
    return histories_csv(result) if result.sweep is not None else None


#: The sizing report (:func:`~slingloads.io.common.report_writer.write_report`).
REPORT = ReportKind(tag="chute", title=TITLE, description=DESCRIPTION,
                    conventions=CONVENTIONS, dpi=_PNG_DPI, sheets=_sheets, figures=_figures,
                    titles=_titles, data={"histories.csv": _histories_csv_if_swept})


def report_kind(study):
    """The sizing report of ``study``: :data:`REPORT` with the study's parachute decision."""
    return with_decision(REPORT, study)

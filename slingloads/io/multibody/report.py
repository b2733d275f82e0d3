"""The multibody report: trim, linear modes, every manoeuvre's metrics and histories, plots.

The model is run by :func:`slingloads.runs.multibody.run` (the trim at its airspeed, the
linear model about it and every manoeuvre, all runs integrated together); this module only
says what its report is made of (:func:`report_kind`), which the one report writer publishes
all at once or not at all (:mod:`slingloads.io.common.atomic`):

* ``<stem>-multibody.xlsx``, print-ready (:mod:`slingloads.io.common.excel`): sheets *Cover*
  (identification, input file and its SHA-256, version, sheets, conventions), *Summary*
  (stability verdict, warnings on the inputs, system, trim, one line per run), *Modes*
  (eigenvalues, frequencies, damping ratios, names, energy shares), *StateMatrix* (the A
  matrix of the linear model, scientific notation), *Metrics* (every run: peaks and when,
  RMS, damping from the response, settling time, verdict and its rule; in blocks that fit a
  page), *Histories* (every run every 2 s) and *Plots*;
* ``<stem>-multibody-histories.csv``: every run at every stored sample (SI, degrees);
* ``<stem>-multibody-histories.png`` (yaw, sideslip, swing angles, tension),
  ``-multibody-eigenvalues.png`` (the complex plane) and ``-multibody-views.png`` (side and top
  views of the system at trim and at the largest excursion).

Lengths, forces, speeds and masses are in the report unit system (``--units``; the CSV file is
SI); angles in degrees.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.constants import KNOT
from slingloads.io.common.csvout import csv_bytes
from slingloads.io.common.excel import Section
from slingloads.io.common.figures import plot_function
from slingloads.io.common.formats import ROUND_OFF, SCIENTIFIC_FORMAT
from slingloads.io.common.report import (
    csv_frame,
    explain_infinite,
    quantity_text,
    report_unit,
    report_value,
    si_columns_in_units,
    split_unit,
    warning_sections,
)
from slingloads.io.common.report_writer import ReportKind
from slingloads.io.common.units import unit_label
from slingloads.io.multibody.figure_data import history_panels, view_points

ANALYSIS = "multibody"
#: PNG files written, by tag: ``<stem>-multibody-<tag>.png``.
PLOTS = ("histories", "eigenvalues", "views")
#: Names of the files of a multibody report, for the publisher (a new report replaces them).
OUTPUTS = ("{stem}-multibody.xlsx", "{stem}-multibody-histories.csv",
           *(f"{{stem}}-multibody-{tag}.png" for tag in PLOTS))
_PNG_DPI = 80
#: Title of each figure on the Plots sheet.
FIGURE_TITLES = {"histories": "Time histories: yaw, sideslip, cable swing, tension",
                 "eigenvalues": "Eigenvalues about the trim",
                 "views": "Side and top views at trim and at the largest excursion"}
#: Sampling of the Histories sheet (the CSV file keeps every stored sample). [s]
HISTORY_INTERVAL = 2.0
#: Quantity kind of the SI units that appear in the analysis' column headers.

#: Number format of the state matrix: scientific, an exact zero as ``0``.
MATRIX_FORMAT = f"{SCIENTIFIC_FORMAT};-{SCIENTIFIC_FORMAT};0"

TITLE = "Multibody report: towed sling load with its drogue parachute"
DESCRIPTION = (
    "The carried helicopter (HC) on its elastic cable under the carrier rotorcraft, with its "
    "parachute line and canopy, as a multibody system: the steady towed flight (trim) at the "
    "system airspeed, the linear model about that trim (eigenvalues, modes, stability), and "
    "every manoeuvre of the workbook flown in time (peaks, RMS, damping from the response, "
    "settling time, verdict with its rule). No structural loads: the hub load angles and "
    "cable tensions are the dynamics that the loads analysis takes. Method: "
    "docs/multibody.md.")
CONVENTIONS = (
    "Earth axes of the simulation: X aft along the flight path (the carrier flies towards "
    "-X), Y right, Z up; positions relative to the hook. Yaw is the heading of the HC from "
    "the flight path, beta > 0 wind from the right; swing angles are the cable's from the "
    "vertical, longitudinal (in the flight plane) and lateral.",
    "A mode is stable when the real part of its eigenvalue is below -1e-6 1/s. The state "
    "matrix is SI (m, m/s, rad, rad/s). Definitions of the states and metrics: "
    "docs/multibody.md.",
)


# ------------------------------------------------------------------------------- tables
def _row(item, value, kind, units, note=""):
    if kind is None:
        return {"item": item, "value": value, "unit": "", "note": note}
    if kind in ("deg", "-", "s", "1/s", "kt"):
        return {"item": item, "value": value, "unit": kind, "note": note}
    return {"item": item, "value": report_value(value, kind, units),
            "unit": unit_label(report_unit(kind, units)), "note": note}


def system_table(result, units="SI"):
    """The system as flown: configuration, mass properties, cable, parachute, carrier."""
    inp = result.inputs
    s = inp.system
    inertia = s.body.inertia
    rows = [
        _row("configuration", inp.configuration, None, units),
        _row("tail", inp.tail, None, units),
        _row("carrier", inp.carrier, None, units,
             "hook on the commanded trajectory" if inp.carrier == "frozen"
             else "point mass with drag, speed hold"),
        _row("equivalent airspeed KEAS", s.airspeed / KNOT, "kt", units,
             f"true airspeed {s.true_airspeed / KNOT:.4g} KTAS"),
        _row("density altitude", s.density_altitude, "altitude", units, "ISA"),
        _row("air density", s.density, "density", units),
        _row("HC mass", s.body.mass, "mass", units, "from MassItems"),
        _row("HC CG x", s.body.cg[0], "length", units, "airframe axes"),
        _row("HC CG z", s.body.cg[2], "length", units, "airframe axes"),
        _row("Ixx about the CG", inertia[0, 0], "inertia", units),
        _row("Iyy about the CG", inertia[1, 1], "inertia", units),
        _row("Izz about the CG", inertia[2, 2], "inertia", units),
        _row("Ixz about the CG", inertia[0, 2], "inertia", units, "tensor sign"),
        _row("cable length", s.cable.length, "length", units, "unstretched, hook to hub"),
        _row("cable EA", s.cable.ea, "force", units),
        _row("cable damping ratio", s.cable.damping_ratio_for(s.hung_mass), "-", units),
        _row("static stretch W L / EA", s.cable.static_stretch(s.weight), "length", units),
    ]
    if s.parachute is not None:
        chute = s.parachute.parachute
        rows += [
            _row("parachute model", inp.parachute_model, None, units),
            _row("parachute flat-plate area", chute.area, "area", units),
            _row("parachute line length", chute.line_length, "length", units),
            _row("parachute wake ratio", chute.wake_ratio, "-", units),
            _row("canopy CD table", inp.canopy_table, None, units,
                 "GENERIC 0-180 deg (paper's 0.95 within 8 deg)" if inp.canopy_table ==
                 "extended" else "ParachuteCD sheet or the paper's +-8 deg"),
        ]
        if s.parachute.kind == "hinged":
            rows.append(_row("canopy mass", s.parachute.mass, "mass", units))
        check = s.cable_check(inp.margin)
        rows.append(_row("cable against the line", "ok" if check.ok else "WARNING", None,
                         units, check.message))
    if inp.carrier == "free":
        rows += [_row("carrier mass", s.carrier.mass, "mass", units),
                 _row("carrier drag area", s.carrier.drag_area, "area", units),
                 _row("carrier speed gain", s.carrier.speed_gain, "1/s", units)]
    sim = result.simulation
    rows += [
        _row("manoeuvres", f"{len(inp.manoeuvres)} from {inp.manoeuvre_source}", None, units),
        _row("run length", inp.settings["t_end"], "s", units),
        _row("integration", sim.describe_integration(), None, units),
        _row("output interval", inp.settings["output_interval"], "s", units),
    ]
    return pd.DataFrame(rows)


def trim_table(result, units="SI"):
    """The trim at the system airspeed as ``item | value | unit`` rows (report units)."""
    frame = result.trim.to_frame()
    if "airspeed EAS [m/s]" in frame.columns:  # an airspeed: in knots in both unit systems
        frame["airspeed EAS [m/s]"] = frame["airspeed EAS [m/s]"] / KNOT
        frame = frame.rename(columns={"airspeed EAS [m/s]": "equivalent airspeed KEAS [kt]"})
    row = si_columns_in_units(frame, units).iloc[0]
    names = [split_unit(column) for column in row.index]
    return pd.DataFrame({"item": [name for name, _ in names], "value": list(row.to_numpy()),
                         "unit": [unit for _, unit in names]})


def runs_table(result):
    """One line per run: name, what it does, verdict, why it stopped."""
    metrics = result.simulation.metrics_frame()
    columns = [c for c in ("run", "manoeuvre", "verdict", "yaw change [deg]",
                           "swing lateral peak [deg]", "tension / weight max [-]", "stopped")
               if c in metrics.columns]
    return metrics[columns]


def modes_table(linear):
    """The modes of the linear model as the report writes them: an aperiodic mode has no
    period, a neutral one (real part 0) no time to half or double."""
    frame = explain_infinite(linear.modes_frame(), ["period [s]"], "none (aperiodic)")
    return explain_infinite(frame, ["time to half or double [s]"], "none (neutral)")


def stability_text(result, decision=None):
    """The stability verdict of the linear model, with its rule and the question it answers
    (linear stability at the trim), deferring to the parachute decision for the parachute's
    adequacy."""
    airspeed = result.inputs.system.airspeed / KNOT
    if result.linear is None:
        return f"no trim at the system airspeed: {result.trim.message}"
    lam = result.linear.eigenvalues
    worst = lam[np.argmax(lam.real)]
    chute = ("with the Study parachute" if getattr(result.inputs.system, "parachute", None)
             is not None else "without parachute")
    # at the precision of the rate's cells (formats.py, 1/s: 0.0000), so that the sentence
    # and the Findings' cell read one number; a real part too small for it (near the
    # tolerance, where the verdict turns) keeps two significant digits
    real = f"{worst.real:.4f}" if abs(worst.real) >= 5e-5 else f"{worst.real:.2g}"
    text = (f"Linear stability at the trim ({airspeed:.4g} KEAS, {chute}): "
            f"{result.linear.verdict()} (largest real part {real} 1/s; rule: stable "
            f"when every real part is below -1e-6 1/s, neutral when some lie within +-1e-6, "
            f"unstable otherwise). This answers whether small motions about this one trim "
            f"decay; it does not size the parachute.")
    if decision is not None:
        text += (" Whether the parachute is adequate (every gust shape of the 1-DOF model, "
                 "the campaign's conditions) is the parachute decision's answer, table below "
                 "(its row \"Study 'parachute area' (loads)\"): "
                 f"{decision.study_area_verdict()}.")
    return text


def history_table(result, units="SI", interval=None):
    """Every run's histories in long format, every ``interval`` (default: every sample)."""
    frame = result.simulation.histories_frame()
    if interval is not None:
        every = result.inputs.settings["output_interval"]
        step = max(1, int(round(interval / every)))
        keep = np.round(frame["time [s]"].to_numpy() / every) % step
        frame = frame[keep == 0].reset_index(drop=True)
    return si_columns_in_units(frame, units)


def metrics_table(result, units="SI"):
    """Every metric of every run: one row per metric (with its unit), one column per run."""
    frame = si_columns_in_units(result.simulation.metrics_frame(), units)
    shown = [c for c in frame.columns if c not in ("run", "manoeuvre", "verdict rule")]
    names = [split_unit(column) for column in shown]
    out = pd.DataFrame({"metric": [name for name, _ in names],
                        "unit": [unit for _, unit in names]})
    for k, run in enumerate(frame["run"]):
        out[str(run)] = list(frame[shown].iloc[k].to_numpy(object))
    return out


def verdict_rules(result):
    """The rules of the runs' verdicts, each once."""
    metrics = result.simulation.metrics_frame()
    if "verdict rule" not in metrics:
        return ""
    return " ".join(dict.fromkeys(str(v) for v in metrics["verdict rule"] if v))


def state_matrix_table(linear):
    """The state matrix A with its round-off (entries below :data:`ROUND_OFF` times its
    largest entry) written as zero, and the row names first."""
    a = linear.a_frame()
    values = a.to_numpy(float)
    scale = float(np.nanmax(np.abs(values))) if values.size else 0.0
    a = a.where(np.abs(values) >= ROUND_OFF * scale, 0.0)
    return a.reset_index(names="d/dt of")


def _warnings(result, warnings):
    """The warnings on the inputs of the study and of the multibody system, each once."""
    return list(dict.fromkeys([*warnings, *result.inputs.warnings]))


def _sheets(result, units, warnings=(), decision=None):
    from slingloads.io.common.decision import decision_section

    airspeed = result.inputs.system.airspeed / KNOT
    summary = [Section("Summary of the multibody model", note=stability_text(result, decision)),
               *warning_sections(warnings),
               *decision_section(decision, units),
               Section("Runs (every metric: sheet Metrics)", runs_table(result)),
               Section(f"Trim at {airspeed:.4g} KEAS", trim_table(result, units)),
               Section("System as flown", system_table(result, units))]
    sheets = {"Summary": summary}
    if result.linear is not None:
        sheets["Modes"] = [Section("Modes of the linear model about the trim",
                                   modes_table(result.linear), keys=["mode"])]
        sheets["StateMatrix"] = [Section(
            "State matrix A (dz/dt = A z), SI: positions m, velocities m/s, angles rad, rates "
            "rad/s; phi_x, phi_y, phi_z a small rotation in body axes",
            state_matrix_table(result.linear),
            note=f"Entries smaller than {ROUND_OFF:g} times the largest entry are round-off "
                 "and written as 0.")]
    else:
        sheets["Modes"] = f"No linear model: {result.trim.message}"
    sheets["Metrics"] = [Section(
        "Metrics of every run (one column per run; angles in degrees)",
        metrics_table(result, units), note=f"Verdict rule: {verdict_rules(result)}",
        keys=["metric", "unit"])]
    sheets["Histories"] = [Section(
        f"Every run every {HISTORY_INTERVAL:g} s (every stored sample: the "
        f"-multibody-histories.csv file, SI)",
        history_table(result, units, HISTORY_INTERVAL), keys=["run", "time [s]"])]
    return sheets


def condition_text(result, units="SI"):
    """The base condition of the multibody runs, for the figures' titles: airspeed, density
    altitude and the parachute (area in report units) or none."""
    s = result.inputs.system
    chute = (f"parachute {quantity_text(s.parachute.parachute.area, 'area', units)}"
             if getattr(s, "parachute", None) is not None else "no parachute")
    return (f"{s.airspeed / KNOT:.4g} KEAS, {quantity_text(s.density_altitude, 'altitude', units)}"
            f" density altitude, {chute}")


def _figures(result, units="SI"):
    """The figures to draw: ``{tag: (plot function, args, kwargs)}``, each plot's plain-data
    twin with its data (names, arrays, tables), so that the process that draws them loads
    neither the model's compiled code nor scipy."""
    plot_modes, plot_history_panels, plot_view_points = (  # matplotlib loads where drawn
        plot_function("slingloads.io.multibody.plots", name)
        for name in ("plot_modes", "plot_history_panels", "plot_view_points"))
    condition = condition_text(result, units)
    figs = {"histories": (plot_history_panels, (history_panels(result.simulation),),
                          {"title": f"Multibody time histories, {condition}"})}
    if result.linear is not None:
        verdict = result.linear.verdict()
        figs["eigenvalues"] = (plot_modes, (result.linear.modes_frame(), verdict),
                               {"title": f"Eigenvalues about the trim ({verdict}), "
                                         f"{condition}"})
    states = []
    if result.trim.converged:
        states.append((f"trim at {result.inputs.system.airspeed / KNOT:.4g} KEAS",
                       result.trim.state, result.trim.info))
    excursion = result.largest_excursion()
    if excursion is not None and np.all(np.isfinite(excursion[0].states[excursion[1]])):
        run, k, depart = excursion
        states.append((f"{run.name}, t = {run.time[k]:.1f} s (largest excursion, "
                       f"{np.degrees(depart):.1f} deg)", run.states[k], run.info[k]))
    if states:
        figs["views"] = (plot_view_points, (view_points(result.inputs.system, states,
                                                        result.outline), units,
                                            "The system at trim and at the largest "
                                            f"excursion, {condition}"),
                         {})
    return figs


def histories_csv(result):
    """The bytes of ``<stem>-multibody-histories.csv``: every stored sample, SI."""
    return csv_bytes(csv_frame(history_table(result, "SI")))


def _titles(result):
    return FIGURE_TITLES


def _matrix_formats(result):
    """The number format of the state matrix's columns (None without a linear model)."""
    if result.linear is None:
        return None
    return {name: MATRIX_FORMAT for name in result.linear.a_frame().columns}


#: The multibody report (:func:`~slingloads.io.common.report_writer.write_report`).
REPORT = ReportKind(tag="multibody", title=TITLE, description=DESCRIPTION,
                    conventions=CONVENTIONS, dpi=_PNG_DPI, sheets=_sheets, figures=_figures,
                    titles=_titles, data={"histories.csv": histories_csv},
                    warnings=_warnings, number_format=_matrix_formats)


def report_kind(study):
    """The multibody report of ``study``: :data:`REPORT` with the study's parachute
    decision."""
    from slingloads.io.common.decision import with_decision

    return with_decision(REPORT, study)

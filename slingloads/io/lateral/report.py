"""The lateral-step pendulum report: design angle, its effect on the hook loads, plots.

The study is run by :func:`slingloads.runs.lateral.run` (the sweep, the critical case re-run,
the natural modes and the hook cases at the recommended angle); this module only says what
its report is made of (:func:`report_kind`), which the one report writer publishes all at
once or not at all (:mod:`slingloads.io.common.atomic`):

* ``<stem>-lateral.xlsx``, print-ready: sheets *Cover* (identification, input file and its
  SHA-256, version, sheets, conventions), *Summary* (largest load angle with nominal inputs
  and over the stated ranges, the case that produced it, margin, recommended angle beside the
  30 deg of CS-29.865 and whether that rule is conservative for the motions swept, cable
  tension factor against the hook load factor Nz, solve_ivp check of the critical case,
  hook-load envelopes at both angles per component), *Runs* (every case: its definition,
  then its results), *Sensitivity* (ranges, load angle and tension against each uncertain
  input, tension per motion against Nz, damping), *Modes*, *Histories* (critical case,
  sampled for print), *LoadsAtAngle* (per station, LIMIT loads) and *Plots*;
* ``<stem>-lateral-histories.csv``: the critical case's time histories at every sample (SI,
  ``name_unit`` headers);
* ``<stem>-lateral-histories.png`` (critical case, with the 30 deg line),
  ``-lateral-max-angle.png`` (largest load angle against carrier acceleration, one line per
  rope length and motion type), ``-lateral-sensitivity.png`` (load angle and tension against
  each uncertain input) and ``-lateral-shear.png`` (Y-shear envelope at 30 deg and at the
  recommended angle, when the recommended angle is below 90 deg).

Lengths, forces, moments, masses, speeds and accelerations are in the report unit system
(``--units``); angles in degrees; rope lengths are also given in ft in SI reports (the
paper's unit), in inches alone in US reports (one unit per quantity).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.analyses.hook_angle import (
    COMPARISON_ORDER,
    SI_LABELS,
)
from slingloads.analyses.lateral import CARRIER_FORCE_LIMIT
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
from slingloads.io.common.csvout import csv_bytes
from slingloads.io.common.excel import Section
from slingloads.io.common.figures import plot_function
from slingloads.io.common.report import (
    check_units,
    convert_columns,
    csv_frame,
    explain_infinite,
    in_report_units,
    plural,
    report_unit,
    report_value,
    sample_rows,
    warning_sections,
)
from slingloads.io.common.report_writer import ReportKind
from slingloads.io.common.units import unit_label

ANALYSIS = "lateral"
#: The peak hook acceleration of a velocity step, as the Runs sheet writes it (its note says
#: why): the speed jumps at t = 0, an impulse of acceleration without a finite peak.
UNBOUNDED_STEP = "unbounded"
#: PNG files written, by tag: ``<stem>-lateral-<tag>.png``.
PLOTS = ("histories", "max-angle", "sensitivity", "shear")
#: Names of the files of a lateral report, for the publisher (a new report replaces them all).
OUTPUTS = ("{stem}-lateral.xlsx", "{stem}-lateral-histories.csv",
           *(f"{{stem}}-lateral-{tag}.png" for tag in PLOTS))
_PNG_DPI = 100
#: Title of each figure on the Plots sheet.
FIGURE_TITLES = {"histories": "Critical case: time histories (30 deg line)",
                 "max-angle": "Largest load angle against carrier acceleration",
                 "sensitivity": "Sensitivity to roll inertia, CG below hub and rope length",
                 "shear": "Y shear of the hook cases (LIMIT): 30 deg against the recommended "
                          "angle"}
#: Most rows of the Histories sheet (the CSV file keeps every sample).
HISTORY_ROWS = 100

TITLE = "Lateral-step pendulum report: design angle of the hook load"
DESCRIPTION = (
    "How far the hook load departs from the mast axis when the carrier rotorcraft moves "
    "sideways: the carried helicopter swings on its cable (two-body pendulum: rope angle "
    "theta1, airframe roll) under every carrier motion x rope length x mass case of "
    "the workbook. The largest load angle |theta1 - theta2| times a margin is the recommended "
    "design angle, set beside the 30 deg of CS 29.865(a); the CS 29.865 hook cases are re-run "
    "at that angle (LIMIT loads) to show what it changes. Method: docs/lateral-pendulum.md.")
CONVENTIONS = (
    "Rope angle theta1 from the vertical, > 0 with the hub to the right of the hook (the "
    "multibody model's lateral swing angle); airframe roll in the attitude convention below "
    "(right side down > 0). The pendulum's coordinates theta1, theta2 are right-hand rotations "
    "about +x (aft): theta2 = -roll. The load angle theta1 - theta2 (= theta1 + roll) is the "
    "angle of the cable force at the hub from the mast axis.",
    "Carrier motion S: lateral hook displacement, + right. Loads on the LoadsAtAngle sheet are "
    "LIMIT loads (hook cases alone: Nz x weight on the cone, with inertia relief).",
)


# ------------------------------------------------------------------------------- tables
def _items(rows, units):
    """Rows (item, SI value, kind or None, note) as a table in report units."""
    out = []
    for item, value, kind, note in rows:
        unit = kind or ""
        if kind not in (None, "deg", "-", "s", "%") and isinstance(value, float):
            value = report_value(value, kind, units)
            unit = unit_label(report_unit(kind, units))
        out.append({"item": item, "value": value, "unit": unit, "note": note})
    return pd.DataFrame(out, dtype=object)  # a count stays an int (written "15")


def verdict(result):
    """One sentence on the recommended angle against the CS-29.865 30 deg."""
    rec, reg = np.degrees(result.recommended_angle), np.degrees(result.study.regulatory_angle)
    if result.study.regulatory_angle_not_conservative or not np.isfinite(rec):
        return result.study.verdict()
    if result.study.exceeds_regulatory_angle:
        peak = np.degrees(result.study.max_load_angle)
        side = "above" if peak > reg else "below"
        return (f"The recommended angle {rec:.1f} deg (margin {result.study.margin:g} x the "
                f"largest load angle {peak:.1f} deg of the motions swept, itself {side} "
                f"{reg:.0f} deg) EXCEEDS the {reg:.0f} deg of CS-29.865: no reduction below "
                f"{reg:.0f} deg is justified, and the hook cases are run at {rec:.1f} deg "
                f"(conservative).{result.study.caveats()}")
    return (f"The recommended angle {rec:.1f} deg is below the {reg:.0f} deg of CS-29.865. "
            f"CS 29.865(a) allows the smaller angle only if it is shown that it cannot be "
            f"exceeded in service: that holds only if the motions, rope lengths and masses "
            f"swept cover the operation being certified.{result.study.caveats()}")


def summary_tables(result, units="SI"):
    """The Summary's tables: design angle, check of the critical case, settings."""
    st, inp = result.study, result.inputs
    case = st.critical_case
    i = st.critical_index
    sweep_peak = float(st.metrics.max_load_angle[i])
    ivp_peak = float(result.critical_run.metrics.max_load_angle)
    variants = len(st.pendulums) // max(
        len(inp.motions) * len(inp.rope_lengths) * len(inp.bodies), 1)
    angle = _items([
        ("cases run", len(st.pendulums), "-",
         f"{len(inp.motions)} motions x {len(inp.rope_lengths)} rope lengths x "
         f"{plural(len(inp.bodies), 'body', 'bodies')} x {variants} combinations of the "
         f"stated ranges"),
        ("largest load angle |theta1 - theta2|, nominal inputs",
         float(np.degrees(st.nominal_max_load_angle)), "deg",
         "roll inertia, CG below hub and rope lengths as given"),
        ("largest load angle |theta1 - theta2| over the stated ranges",
         float(np.degrees(st.max_load_angle)), "deg",
         "angle of the cable force at the hub from the mast; the recommendation rests on it"),
        ("case producing it", st.nominal_case(i), "-",
         f"sheet Runs, at the factors below (run {int(case['case'])} of the "
         f"{len(st.pendulums)})"),
        ("  roll inertia", float(case["roll inertia [kg m^2]"]), "inertia",
         f"factor {case['roll inertia factor [-]']:.3g}"),
        ("  CG below hub", float(case["CG below hub [m]"]), "length",
         f"factor {case['CG below hub factor [-]']:.3g}"),
        ("  motion", result.motion_id(i), None, str(case["motion description"])),
        # one unit per quantity: every rope and cable length in m (SI) or in (US)
        ("  rope length", float(case["rope length [m]"]), "length",
         f"factor {case['rope length factor [-]']:.3g}"),
        ("  body", str(case["body"]), None, f"source: {inp.body_source}"),
        ("  time of the maximum", float(case["t at max |theta1 - theta2| [s]"]), "s", ""),
        ("  cable slack in that case", bool(case["slack [-]"]), None,
         "rigid rope not valid after slack: use the elastic cable" if case["slack [-]"]
         else ""),
        ("cases whose cable went slack", int(np.sum(st.metrics.slack)), "-", ""),
        ("cases with a carrier motion beyond the carrier's limits",
         int(np.count_nonzero(~st.flyable)), "-",
         (st.limits.describe() + " (sheet Runs, 'flyable'): no design value from them")
         if st.limits is not None else "not checked"),
        ("cases whose lateral cable force passes 10 % of the carrier's weight",
         int(np.count_nonzero(st.carrier_force_ratio > CARRIER_FORCE_LIMIT)), "-",
         f"largest T sin(theta1) / (m_carrier g) over the runs "
         f"{np.nanmax(st.carrier_force_ratio):.3g}"
         "; above 0.1 the frozen-carrier path is not assured (flagged, sheet Runs)"
         if st.limits is not None and np.isfinite(st.limits.carrier_mass) else "not checked"),
        ("cases outside the model's domain", st.outside_domain, "-",
         "slack cable, or rope or load angle past 90 deg (sheet Runs, 'domain'): no design "
         "value from them"),
        ("design-angle margin", st.margin, "-", "input"),
        ("recommended design angle", float(np.degrees(st.recommended_angle)), "deg",
         "margin x largest load angle inside the domain" if np.isfinite(st.recommended_angle)
         else "NONE: no case inside the domain, or 90 deg reached with the margin"),
        ("CS-29.865 angle", float(np.degrees(st.regulatory_angle)), "deg",
         "'not less than 30 deg' unless a smaller angle is shown not to be exceeded"),
        ("recommended angle exceeds CS-29.865", bool(st.exceeds_regulatory_angle), None,
         "see the summary above"),
        ("CS-29.865 30 deg not conservative for this motion set",
         bool(st.regulatory_angle_not_conservative), None,
         "a load angle found exceeds 30 deg" if st.regulatory_angle_not_conservative
         else ""),
    ], units)
    nz = st.hook_load_factor
    over = int(np.sum(st.exceeds_hook_load_factor))
    tension = _items([
        ("largest cable tension factor T/(m g)", st.max_tension_ratio, "-",
         "over every case and the stated ranges"),
        ("largest T/(m g), nominal inputs",
         float(np.nanmax(st.metrics.max_tension_ratio[st.nominal])), "-", ""),
        ("hook load factor Nz of the loads", float(nz), "-", "Study 'hook load factor Nz'"),
        ("cases with T/(m g) above Nz", over, "-",
         (f"EXCEEDED: the motions swept load the hook above Nz x weight (largest "
          f"{st.max_tension_ratio:.3g}); raise Nz or restrict the motions") if over else
         "Nz covers the cable tension of every motion swept"),
    ], units)
    check = _items([
        ("largest load angle, RK4 sweep", float(np.degrees(sweep_peak)), "deg",
         f"fixed step {st.step:.4g} s"),
        ("largest load angle, solve_ivp re-run", float(np.degrees(ivp_peak)), "deg",
         f"{inp.solver.method}, rtol {inp.solver.rtol:g}"),
        ("relative difference", float(abs(sweep_peak - ivp_peak) / max(ivp_peak, 1e-300)),
         "-", "tighten 'lateral RK4 step' if this is not small"),
    ], units)
    settings = _items([
        ("cable model", "rigid" if inp.cable_ea is None else "elastic", None, ""),
        ("cable EA", float(inp.cable_ea) if inp.cable_ea is not None else 0.0, "force",
         "0: rigid"),
        ("damping source", inp.damping.source, None, inp.damping.note),
        ("lateral damping", inp.damping.lateral, "linear damping", "0 = off"),
        ("roll damping", inp.damping.roll, "rotational damping", "0 = off"),
        ("damped point below the hub",
         float(inp.damping.below_hub) if inp.damping.below_hub is not None else "the CG",
         "length" if inp.damping.below_hub is not None else None,
         "where the lateral damping acts"),
        ("run length", st.t_end, "s", "automatic" if inp.solver.t_end is None else "input"),
        ("RK4 step", st.step, "s", "automatic" if inp.solver.step is None else "input"),
    ], units)
    return {"angle": angle, "check": check, "settings": settings, "tension": tension}


def runs_table(result, units="SI"):
    """Every nominal case of the sweep (body x rope x motion) with the largest load angle and
    tension over the stated ranges beside it, in report units, with its LateralMotions id.
    (Every variant: ``result.study.to_frame()``.)"""
    frame = result.study.case_frame()
    frame.insert(1, "motion id", [result.motion_id(int(c) - 1) for c in frame["case"]])
    frame = convert_columns(frame, {
        "mass [kg]": ("mass", "mass"), "roll inertia [kg m^2]": ("roll inertia", "inertia"),
        "CG below hub [m]": ("CG below hub", "length"),
        "rope length [m]": ("rope length", "length"),
        "nominal rope length [m]": ("nominal rope length", "length"),
        "cable EA [N]": ("cable EA", "force"),
        "peak S'' [m/s^2]": ("peak S''", "acceleration"),
        "velocity jump [m/s]": ("velocity jump", "speed")}, units)
    # a velocity step's acceleration is an impulse; a rigid cable's EA has no finite value
    frame = explain_infinite(frame, [c for c in frame.columns if c.startswith("peak S'' [")],
                             UNBOUNDED_STEP)
    return explain_infinite(frame, [c for c in frame.columns if c.startswith("cable EA [")],
                            "rigid")


def history_table(result, units="SI"):
    """Time histories of the critical case, in report units."""
    frame = result.critical_run.to_frame()
    spec = {"S [m]": ("S", "length"), "S' [m/s]": ("S'", "speed"),
            "S'' [m/s^2]": ("S''", "acceleration"), "T [N]": ("T", "force"),
            "hub Fy [N]": ("hub Fy", "force"), "hub Fz [N]": ("hub Fz", "force")}
    if "cable length [m]" in frame:
        spec["cable length [m]"] = ("cable length", "length")
    return convert_columns(frame, spec, units)


def modes_table(result, units="SI"):
    """Natural modes about the hanging equilibrium of every body x rope length."""
    return convert_columns(result.modes, {"rope length [m]": ("rope length", "length")}, units)


def comparison_station_table(comparison, units="SI"):
    """The hook cases' envelopes per station at both angles, in report units."""
    spec = {"x [m]": ("x", "length")}
    for name in COMPARISON_ORDER:
        kind = COMPONENT_KINDS[COMPONENTS.index(name)]
        for label in comparison.labels():
            spec[f"max |{name}| {label} [{SI_LABELS[kind]}]"] = (f"max |{name}| {label}", kind)
    frame = convert_columns(comparison.station_frame(), spec, units)
    # a load where the 30 deg cone gives none: no finite reduction (an increase from 0)
    return explain_infinite(frame, [c for c in frame.columns if c.endswith(" reduction [%]")],
                            "unbounded", "increase from 0")


def comparison_summary_table(comparison, units="SI"):
    """The largest envelope value of each component at both angles, in report units."""
    check_units(units)
    frame = comparison.summary_frame()
    kinds = [COMPONENT_KINDS[COMPONENTS.index(name)] for name in frame["component"]]
    for label in comparison.labels():
        column = f"largest {label}"
        frame[column] = [float(in_report_units(value, kind, units))
                         for value, kind in zip(frame[column], kinds, strict=True)]
    frame["unit"] = [unit_label(report_unit(kind, units)) for kind in kinds]
    return frame


def history_sheet_table(result, units="SI"):
    """The critical case's time histories sampled for print (at most :data:`HISTORY_ROWS`
    rows), and the sampling interval. [s]"""
    frame = history_table(result, units)
    return sample_rows(frame, "t [s]", HISTORY_ROWS)


def _split_runs(frame):
    """The Runs table as (bodies, motions, definition, results): the mass cases once, the
    carrier motions' descriptions once (a wrapped sentence on every case widened the table
    and doubled its rows), the motion and rope of each case, then its metrics."""
    metrics = [c for c in frame.columns if c.startswith(("max ", "min ", "t at ", "slack"))]
    keys = ["case", "motion id"]
    body = ["body", *(c for c in frame.columns if c.startswith(("mass [", "roll inertia [",
                                                                 "CG below hub [")))]
    bodies = frame[body].drop_duplicates("body").reset_index(drop=True)
    motions = (frame[["motion id", "motion description"]].drop_duplicates("motion id")
               .reset_index(drop=True))
    dropped = {*metrics, *body[1:], "motion", "motion description"} | {
        c for c in frame.columns if c.startswith("cable EA [")}
    definition = frame[[c for c in frame.columns if c not in dropped]]
    return bodies, motions, definition, frame[keys + metrics]


def _split_components(frame):
    """The per-station table of the hook cases as (shears, moments)."""
    keys = [c for c in frame.columns if not any(f"{n}" in c for n in COMPONENTS)]
    shears = [c for c in frame.columns if c not in keys and any(
        f"{n}" in c for n in COMPONENTS[:3])]
    moments = [c for c in frame.columns if c not in keys and c not in shears]
    return frame[keys + shears], frame[keys + moments]


def _sheets(result, units, warnings=()):
    tables = summary_tables(result, units)
    comparison = result.comparison
    summary = [Section("Summary of the lateral-step pendulum study", note=verdict(result)),
               *warning_sections(warnings),
               Section("Design angle of the hook load (CS-29.865)", tables["angle"]),
               Section("Cable tension against the hook load factor Nz", tables["tension"]),
               Section("Check of the critical case", tables["check"]),
               Section("Model and solver", tables["settings"])]
    if comparison is not None:
        summary.append(Section(
            "Hook cases at the recommended angle against 30 deg (largest LIMIT load along the "
            "airframe)", comparison_summary_table(comparison, units),
            note="CS-29.865 hook cases alone (the vertical and the cone's azimuths, Nz x "
                 "weight, inertia relief), without aerodynamic and parachute loads. "
                 + comparison.reduced_note()))
        shears, moments = _split_components(comparison_station_table(comparison, units))
        note = (f"Hook directions: {', '.join(comparison.cases)}. {comparison.reduced_note()} "
                "LIMIT loads. Reduction = 1 - (at the recommended angle) / (at 30 deg); "
                "negative = increase.")
        loads_sheet = [Section("CS 29.865 hook cases at 30 deg and at the recommended angle, "
                               "LIMIT loads per station", note=note),
                       Section("Envelope max |LIMIT load| of the hook cases per station: "
                               "shear forces", shears),
                       Section("Envelope max |LIMIT load| of the hook cases per station: "
                               "moments", moments)]
    else:
        loads_sheet = ("The recommended angle is 90 deg or more: no hook-load cone can be "
                       "built; the hook cases were not re-run.")
    st = result.study
    bodies, motions, definition, results = _split_runs(runs_table(result, units))
    histories, interval = history_sheet_table(result, units)
    return {
        "Summary": summary,
        "Runs": [Section(f"Every case: {len(st.pendulums)} runs, RK4 step {st.step:.4g} s "
                         f"over {st.t_end:.4g} s",
                         note="Motion ids: LateralMotions sheet; cases are motions x rope "
                              "lengths x bodies. peak S'' of a velocity step: "
                              f"'{UNBOUNDED_STEP}', the hook's speed jumps at t = 0 (an "
                              "impulse of acceleration, of the size of the velocity jump)."),
                 Section("Bodies (mass cases)", bodies),
                 Section("Carrier motions (LateralMotions sheet)", motions),
                 Section("Definition of every case (cable model: sheet Summary)", definition),
                 # its own sheet: its own column widths, not the definition table's
                 Section("Results of every case", results, sheet="Runs-ResultsEveryCase")],
        "Sensitivity": [
            Section("Sensitivity of the largest load angle and cable tension to the uncertain "
                    "inputs", note="Every case is run over the stated ranges of roll inertia, "
                    "CG below the hub and rope length (Study rows 'lateral ... spread')."),
            Section("Stated ranges (factors on the nominal values)", st.ranges.to_frame()),
            Section("Largest load angle and tension factor against each uncertain input",
                    st.sensitivity_frame(),
                    note="'others nominal': the two other inputs at their nominal values; "
                         "'others over their ranges': the envelope over them."),
            Section("Largest tension factor per carrier motion against Nz",
                    st.tension_frame()),
            Section("Damping", _damping_table(st.damping, units))],
        "Modes": [Section("Natural frequencies and mode shapes about the hanging equilibrium "
                          "(shapes of the rope angle theta1, the airframe roll and the bounce; "
                          "docs/lateral-pendulum.md section 6)",
                          modes_table(result, units))],
        "Histories": [Section("Critical case re-run with solve_ivp: "
                              f"{result.critical_run.motion.describe()}",
                              histories,
                              note=f"Every {interval:g} s; every sample in the "
                                   "-lateral-histories.csv file (SI).")],
        "LoadsAtAngle": loads_sheet,
    }


def _damping_table(damping, units):
    """The dampers in report units."""
    return convert_columns(damping.to_frame(), {
        "lateral damping [N s/m]": ("lateral damping", "linear damping"),
        "below hub [m]": ("below hub", "length"),
        "roll damping [N m s/rad]": ("roll damping", "rotational damping")}, units)


def _figures(result, units):
    """The figures to draw: ``{tag: (plot function, args, kwargs)}``."""
    (plot_max_angle_vs_acceleration, plot_sensitivity, plot_shear_at_angles,
     plot_time_histories) = (  # matplotlib loads where they are drawn
        plot_function("slingloads.io.lateral.plots", name)
        for name in ("plot_max_angle_vs_acceleration", "plot_sensitivity",
                     "plot_shear_at_angles", "plot_time_histories"))
    figs = {"histories": (plot_time_histories, (result.critical_run,), {"units": units}),
            "max-angle": (plot_max_angle_vs_acceleration, (result.study,), {"units": units}),
            "sensitivity": (plot_sensitivity, (result.study,), {})}
    if result.comparison is not None:
        figs["shear"] = (plot_shear_at_angles, (result.comparison,), {"units": units})
    return figs


def histories_csv(result):
    """The bytes of ``<stem>-lateral-histories.csv``: every sample of the critical run, SI."""
    return csv_bytes(csv_frame(result.critical_run.to_frame()))


def _titles(result):
    return FIGURE_TITLES


#: The lateral report (:func:`~slingloads.io.common.report_writer.write_report`).
REPORT = ReportKind(tag="lateral", title=TITLE, description=DESCRIPTION,
                    conventions=CONVENTIONS, dpi=_PNG_DPI, sheets=_sheets, figures=_figures,
                    titles=_titles, data={"histories.csv": histories_csv})


def report_kind(study):
    """The lateral report of ``study`` (:data:`REPORT`)."""
    return REPORT

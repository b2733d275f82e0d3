"""The lateral-step pendulum report: design angle, its effect on the hook loads, plots.

:func:`compute` runs the study read by :mod:`slingloads.io.lateral.reader` (every motion x
rope length x body in one vectorised RK4 sweep), re-runs the critical case with
:func:`scipy.integrate.solve_ivp` for its time histories, computes the natural modes about the
hanging equilibrium, and, the link to the loads, re-runs the CS-29.865 hook cases at the
recommended angle and at the 30 deg of CS-29.865 (:func:`hook_angle_comparison`).
:func:`write` publishes, all at once or not at all (:mod:`slingloads.io.common.atomic`):

* ``<stem>-lateral.xlsx``: sheets *Summary* (inputs digest, largest load angle and the case
  that produced it, margin, recommended angle beside the 30 deg of CS-29.865, solve_ivp check
  of the critical case, hook-load envelopes at both angles per component), *Runs* (every
  case), *Modes*, *Histories* (critical case), *LoadsAtAngle* (per station) and *Plots*;
* ``<stem>-lateral-histories.png`` (critical case, with the 30 deg line),
  ``-lateral-max-angle.png`` (largest load angle against carrier acceleration per rope) and
  ``-lateral-shear.png`` (Y-shear envelope at 30 deg and at the recommended angle).

Lengths, forces, moments, masses, speeds and accelerations are in the report unit system
(``--units``); angles in degrees; rope lengths are also given in ft.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from slingloads.analyses.lateral import REGULATORY_ANGLE, lateral_study
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS
from slingloads.constants import FOOT
from slingloads.errors import InputError
from slingloads.io.common.atomic import atomic_outputs, check_not_input
from slingloads.io.common.excel import Section, figure_png, format_by_header, write_workbook
from slingloads.io.common.units import unit_label
from slingloads.io.common.workbook import located
from slingloads.io.lateral.plots import (
    plot_max_angle_vs_acceleration,
    plot_shear_at_angles,
    plot_time_histories,
)
from slingloads.io.loads.plots import check_units, in_report_units, labelled, report_unit
from slingloads.io.loads.report import convert_columns

ANALYSIS = "lateral"
#: PNG files written, by tag: ``<stem>-lateral-<tag>.png``.
PLOTS = ("histories", "max-angle", "shear")
#: Order of the load components in the comparison: Y shear first (the paper's point).
COMPARISON_ORDER = ("Vy", "Mz", "Mx", "Vx", "Vz", "My")
_PNG_DPI = 80
NUMBER_FORMATS = format_by_header([
    (r"\[deg\]", "0.00"),
    (r"\[%\]", "0.0"),
    (r"\[(N|lbf|N m|lbf in)\]", "#,##0"),
    (r"\[-\]", "0.000"),
])


@dataclass(frozen=True, eq=False)
class HookAngleComparison:
    """Envelopes max |load| of the CS-29.865 hook cases at two cone angles.

    Attributes
    ----------
    reference_angle : float
        The CS-29.865 angle (30 deg). [rad]
    angle : float
        The compared angle (the recommended design angle). [rad]
    station_ids : tuple of str
    stations : ndarray, shape (s,)
        [m]
    reference : ndarray, shape (s, 6)
        max over the hook cases of |load| at ``reference_angle``. [N, N m]
    at_angle : ndarray, shape (s, 6)
        The same at ``angle``. [N, N m]
    cases : tuple of str
        Hook directions run (AXIAL, AZ000...).
    """

    reference_angle: float
    angle: float
    station_ids: tuple
    stations: np.ndarray
    reference: np.ndarray
    at_angle: np.ndarray
    cases: tuple

    @property
    def reduction(self):
        """100 (1 - at_angle / reference) per station and component; 0 where both are
        zero. [%]"""
        scale = np.abs(self.reference).max(axis=0, keepdims=True)
        tiny = 1e-12 * np.maximum(scale, 1.0)
        ok = self.reference > tiny
        out = np.zeros_like(self.reference)
        np.divide(self.at_angle, self.reference, out=out, where=ok)
        return np.where(ok, 100.0 * (1.0 - out), np.where(self.at_angle > tiny, -np.inf, 0.0))

    def _labels(self):
        return (f"at {np.degrees(self.reference_angle):.4g} deg",
                f"at {np.degrees(self.angle):.4g} deg")

    def station_frame(self, units="SI"):
        """Per station: each component's envelope at both angles and the reduction, Y shear
        first, in report units."""
        ref, at = self._labels()
        frame = {"station": list(self.station_ids),
                 labelled("x", "length", units): in_report_units(self.stations, "length", units)}
        red = self.reduction
        for name in COMPARISON_ORDER:
            j = COMPONENTS.index(name)
            kind = COMPONENT_KINDS[j]
            frame[labelled(f"max |{name}| {ref}", kind, units)] = in_report_units(
                self.reference[:, j], kind, units)
            frame[labelled(f"max |{name}| {at}", kind, units)] = in_report_units(
                self.at_angle[:, j], kind, units)
            frame[f"{name} reduction [%]"] = red[:, j]
        return pd.DataFrame(frame)

    def summary_frame(self, units="SI"):
        """Per component: the largest envelope value along the airframe at both angles, where
        it occurs, and the reduction, Y shear first."""
        ref, at = self._labels()
        rows = []
        for name in COMPARISON_ORDER:
            j = COMPONENTS.index(name)
            kind = COMPONENT_KINDS[j]
            i_ref = int(np.argmax(self.reference[:, j]))
            i_at = int(np.argmax(self.at_angle[:, j]))
            big_ref, big_at = self.reference[i_ref, j], self.at_angle[i_at, j]
            rows.append({
                "component": name,
                f"largest {ref}": float(in_report_units(big_ref, kind, units)),
                f"station {ref}": self.station_ids[i_ref],
                f"largest {at}": float(in_report_units(big_at, kind, units)),
                f"station {at}": self.station_ids[i_at],
                "unit": unit_label(report_unit(kind, units)),
                "reduction [%]": 100.0 * (1.0 - big_at / big_ref) if big_ref > 0 else 0.0,
            })
        return pd.DataFrame(rows)


def hook_angle_comparison(loads_study, angle, reference_angle=REGULATORY_ANGLE):
    """Envelopes of the CS-29.865 hook cases alone at two cone angles.

    The hook cases are the loads study's hook directions (mast axis and the azimuths of the
    cone) with gravity and inertia relief, without the aerodynamic and parachute loads, which
    do not depend on the cone angle. Each angle is one run of
    :meth:`LoadsStudy.run <slingloads.analyses.loads.LoadsStudy.run>`.

    Parameters
    ----------
    loads_study : LoadsStudy
    angle : float
        Cone angle to compare, in [0, 90) deg (e.g. the recommended design angle). [rad]
    reference_angle : float
        The CS-29.865 angle. [rad]

    Returns
    -------
    HookAngleComparison

    Raises
    ------
    InputError
        For an angle outside [0, 90) deg.
    """
    hooks = replace(loads_study, envelope=None, fuselage=None, fin=None, parachute=None,
                    listed=(), generate=True, previous_envelope=None)
    runs = [hooks.with_hook(angle=float(a)).run() for a in (reference_angle, angle)]
    ref, at = (np.abs(r.loads).max(axis=0) for r in runs)
    return HookAngleComparison(float(reference_angle), float(angle),
                               tuple(runs[0].station_ids), np.asarray(runs[0].stations),
                               ref, at, tuple(runs[0].cases["hook"]))


@dataclass(frozen=True, eq=False)
class LateralReport:
    """Results of the lateral study of one workbook.

    Attributes
    ----------
    inputs : LateralInputs
    study : LateralStudy
    critical_run : LateralRun
        The critical case re-run with solve_ivp (time histories).
    modes : pandas.DataFrame
        Natural modes of every body x rope length (SI).
    comparison : HookAngleComparison or None
        None when the recommended angle is 90 deg or more (no hook cone can be built).
    """

    inputs: object
    study: object
    critical_run: object
    modes: pd.DataFrame
    comparison: HookAngleComparison | None

    @property
    def recommended_angle(self):
        """[rad]"""
        return self.study.recommended_angle

    def motion_id(self, index):
        """LateralMotions id of case ``index`` (0-based)."""
        n = len(self.inputs.motions)
        return self.inputs.motion_ids[index % n]


def compute(study):
    """Run the lateral study read from a workbook.

    Parameters
    ----------
    study : WorkbookStudy
        With ``study.extra["lateral"]`` (:class:`~slingloads.io.lateral.reader.LateralInputs`).

    Returns
    -------
    LateralReport

    Raises
    ------
    InputError
        If the workbook does not ask for the lateral study, or the analysis refuses its
        inputs (the file is named).
    """
    inputs = study.extra.get(ANALYSIS)
    if inputs is None:
        raise InputError("the workbook does not ask for the lateral study (Study sheet: "
                         "'run lateral' is no)", file=study.path, sheet="Study")
    with located(study.path):
        result = lateral_study(inputs.bodies, inputs.rope_lengths, inputs.motions,
                               margin=inputs.margin, cable_ea=inputs.cable_ea,
                               lateral_damping=inputs.lateral_damping,
                               roll_damping=inputs.roll_damping, t_end=inputs.t_end,
                               step=inputs.step)
        run = result.run_case(solver=inputs.solver)
        comparison = None
        if result.recommended_angle < np.pi / 2:
            comparison = hook_angle_comparison(inputs.loads, result.recommended_angle)
    return LateralReport(inputs, result, run, _modes(result), comparison)


def _modes(result):
    frames, seen = [], set()
    for p in result.pendulums:
        key = id(p)
        if key in seen:
            continue
        seen.add(key)
        frame = p.linear_modes().to_frame()
        frame.insert(0, "body", p.body.name)
        frame.insert(1, "rope length [m]", p.rope_length)
        frame.insert(2, "rope length [ft]", p.rope_length / FOOT)
        frames.append(frame)
    return pd.concat(frames, ignore_index=True)


# ------------------------------------------------------------------------------- tables
def _items(rows, units):
    """Rows (item, SI value, kind or None, note) as a table in report units."""
    out = []
    for item, value, kind, note in rows:
        unit = kind or ""
        if kind not in (None, "deg", "-", "s", "%") and isinstance(value, float):
            value = float(in_report_units(value, kind, units))
            unit = unit_label(report_unit(kind, units))
        out.append({"item": item, "value": value, "unit": unit, "note": note})
    return pd.DataFrame(out)


def verdict(result):
    """One sentence on the recommended angle against the CS-29.865 30 deg."""
    rec, reg = np.degrees(result.recommended_angle), np.degrees(result.study.regulatory_angle)
    if result.study.exceeds_regulatory_angle:
        return (f"The recommended angle {rec:.1f} deg EXCEEDS the {reg:.0f} deg of CS-29.865: "
                f"the motions swept can put the hook load further from the mast than the "
                f"regulation's minimum, so the hook cases must be run at {rec:.1f} deg at "
                f"least (no reduction is possible).")
    return (f"The recommended angle {rec:.1f} deg is below the {reg:.0f} deg of CS-29.865. "
            f"CS 29.865(a) allows the smaller angle only if it is shown that it cannot be "
            f"exceeded in service: that holds only if the motions, rope lengths and masses "
            f"swept cover the operation being certified.")


def summary_tables(result, units="SI"):
    """The Summary's tables: design angle, check of the critical case, settings."""
    st, inp = result.study, result.inputs
    case = st.critical_case
    i = st.critical_index
    sweep_peak = float(st.metrics.max_load_angle[i])
    ivp_peak = float(result.critical_run.metrics.max_load_angle)
    angle = _items([
        ("cases run", len(st.pendulums), "-",
         f"{len(inp.motions)} motions x {len(inp.rope_lengths)} rope lengths x "
         f"{len(inp.bodies)} bodies"),
        ("largest load angle |theta1 - theta2|", float(np.degrees(st.max_load_angle)), "deg",
         "angle of the cable force at the hub from the mast"),
        ("case producing it", int(case["case"]), "-", "see the Runs sheet"),
        ("  motion", result.motion_id(i), None, str(case["motion description"])),
        ("  rope length", float(case["rope length [m]"]), "length",
         f"{case['rope length [m]'] / FOOT:.4g} ft"),
        ("  body", str(case["body"]), None, f"source: {inp.body_source}"),
        ("  time of the maximum", float(case["t at max |theta1 - theta2| [s]"]), "s", ""),
        ("  cable slack in that case", bool(case["slack [-]"]), None,
         "rigid rope not valid after slack: use the elastic cable" if case["slack [-]"]
         else ""),
        ("cases whose cable went slack", int(np.sum(st.metrics.slack)), "-", ""),
        ("design-angle margin", st.margin, "-", "input"),
        ("recommended design angle", float(np.degrees(st.recommended_angle)), "deg",
         "margin x largest load angle"),
        ("CS-29.865 angle", float(np.degrees(st.regulatory_angle)), "deg",
         "'not less than 30 deg' unless a smaller angle is shown not to be exceeded"),
        ("recommended angle exceeds CS-29.865", bool(st.exceeds_regulatory_angle), None,
         verdict(result)),
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
        ("lateral damping", inp.lateral_damping, "linear damping", "0 = off"),
        ("roll damping", inp.roll_damping, "rotational damping", "0 = off"),
        ("run length", st.t_end, "s", "automatic" if inp.t_end is None else "input"),
        ("RK4 step", st.step, "s", "automatic" if inp.step is None else "input"),
    ], units)
    return {"angle": angle, "check": check, "settings": settings}


def runs_table(result, units="SI"):
    """Every case of the sweep, in report units, with its LateralMotions id."""
    frame = result.study.to_frame()
    frame.insert(1, "motion id", [result.motion_id(i) for i in range(len(frame))])
    frame.insert(list(frame.columns).index("rope length [m]") + 1, "rope length [ft]",
                 frame["rope length [m]"] / FOOT)
    return convert_columns(frame, {
        "mass [kg]": ("mass", "mass"), "roll inertia [kg m^2]": ("roll inertia", "inertia"),
        "CG below hub [m]": ("CG below hub", "length"),
        "rope length [m]": ("rope length", "length"), "cable EA [N]": ("cable EA", "force"),
        "peak S'' [m/s^2]": ("peak S''", "acceleration"),
        "velocity jump [m/s]": ("velocity jump", "speed")}, units)


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


def _sheets(result, units, digest):
    tables = summary_tables(result, units)
    comparison = result.comparison
    summary = [Section("Inputs", digest),
               Section("Design angle of the hook load (CS-29.865)", tables["angle"],
                       note=verdict(result)),
               Section("Check of the critical case", tables["check"]),
               Section("Model and solver", tables["settings"])]
    if comparison is not None:
        summary.append(Section(
            "Hook cases at the recommended angle against 30 deg (largest along the airframe)",
            comparison.summary_frame(units),
            note="CS-29.865 hook cases alone (mast axis and the cone's azimuths, Nz x weight, "
                 "inertia relief), without aerodynamic and parachute loads."))
        loads_sheet = [Section("Envelope max |load| of the hook cases per station",
                               comparison.station_frame(units),
                               note=f"Hook directions: {', '.join(comparison.cases)}. Limit "
                                    "loads. Reduction = 1 - (at the recommended angle) / "
                                    "(at 30 deg); negative = increase.")]
    else:
        loads_sheet = ("The recommended angle is 90 deg or more: no hook-load cone can be "
                       "built; the hook cases were not re-run.")
    st = result.study
    return {
        "Summary": summary,
        "Runs": [Section(f"Every case: {len(st.pendulums)} runs, RK4 step {st.step:.4g} s "
                         f"over {st.t_end:.4g} s", runs_table(result, units))],
        "Modes": [Section("Natural frequencies and mode shapes about the hanging equilibrium "
                          "(theta1 rope, theta2 airframe; docs/lateral-pendulum.md section 6)",
                          modes_table(result, units))],
        "Histories": [Section("Critical case re-run with solve_ivp: "
                              f"{result.critical_run.motion.describe()}",
                              history_table(result, units))],
        "LoadsAtAngle": loads_sheet,
    }


def _digest(study):
    d = study.digest()
    return pd.DataFrame({"input": list(d), "entry": [str(v) for v in d.values()]})


def _figures(result, units):
    figs = {"histories": plot_time_histories(result.critical_run),
            "max-angle": plot_max_angle_vs_acceleration(result.study)}
    if result.comparison is not None:
        figs["shear"] = plot_shear_at_angles(result.comparison, units=units)
    return figs


def write(result, out_dir, stem, units, study):
    """Write ``<stem>-lateral.xlsx`` and ``<stem>-lateral-*.png`` atomically.

    Parameters
    ----------
    result : LateralReport
    out_dir : path-like
    stem : str
    units : str
        ``"SI"`` or ``"US"`` (lengths in in, forces in lbf, moments in lbf in, masses in lb).
    study : WorkbookStudy
        For the inputs digest; its input file is never overwritten.

    Returns
    -------
    list of pathlib.Path
    """
    check_units(units)
    inputs = [study.path]
    names = [f"{stem}-lateral.xlsx"] + [f"{stem}-lateral-{tag}.png" for tag in PLOTS]
    for name in names:
        check_not_input(Path(out_dir) / name, inputs)
    pngs = {tag: figure_png(fig, _PNG_DPI) for tag, fig in _figures(result, units).items()}
    titles = {"histories": "Critical case: time histories (30 deg line)",
              "max-angle": "Largest load angle against carrier acceleration",
              "shear": "Y shear of the hook cases: 30 deg against the recommended angle"}
    sheets = _sheets(result, units, _digest(study))
    with atomic_outputs(out_dir, inputs=inputs) as out:
        write_workbook(out.path(f"{stem}-lateral.xlsx"), sheets,
                       {titles[t]: png for t, png in pngs.items()},
                       number_format=NUMBER_FORMATS)
        for tag, png in pngs.items():
            out.path(f"{stem}-lateral-{tag}.png").write_bytes(png)
    return out.written

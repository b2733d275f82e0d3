"""Build the lateral-step pendulum inputs from an input workbook (``run lateral = yes``).

Called through the registry (:mod:`slingloads.io.analyses`) as
``read(reader, params, study)``.
It reads the Study parameters of :mod:`slingloads.io.lateral.schema`, the sheets
``LateralMotions``, ``LateralRopes``, and the optional ``LateralHistory`` (or CSV files named
in ``LateralMotions``) and ``LateralBodies``; without ``LateralBodies`` the one body comes from
the ``MassItems`` and the ``Hardpoints`` hub. For the link to the loads it keeps the loads
study (``study.inputs.loads``, or one built from the same workbook when only the lateral study was
asked for). Every value is SI after reading; every bad value raises
:class:`~slingloads.errors.InputError` naming the file, sheet, cell, value and rule.
"""

from __future__ import annotations

import numpy as np
from openpyxl.utils import get_column_letter

from slingloads.analyses.lateral import ParameterRanges, airframe_body
from slingloads.analyses.lateral_damping import (
    LateralDamping,
    aerodynamic_damping,
)
from slingloads.errors import InputError
from slingloads.ids import id_key
from slingloads.io.airframe.reader import read_fin_aero, read_fuselage_aero
from slingloads.io.airframe.schema import SHEETS as _AIRFRAME
from slingloads.io.common.locate import Place, column_quantity, find_place, located, place_error
from slingloads.io.common.referenced import csv_columns
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.lateral.rows import CHOICES
from slingloads.io.lateral.schema import (
    MIN_ROLL_GYRATION,
    MOTION_ALIASES,
    MOTION_TYPES,
    SHEETS,
    THEN,
)
from slingloads.io.loads import reader as loads_reader
from slingloads.limits import (
    MAX_HISTORY_OUTPUT,
    MAX_HISTORY_SAMPLES,
    MAX_LATERAL_MOTION_STEPS,
    MAX_LATERAL_RUN_STEPS,
    MAX_LATERAL_RUNS,
    MAX_LATERAL_STEPS,
    MIN_SAMPLE_INTERVAL,
)
from slingloads.models.carrier_motion import (
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
    TimeHistory,
    VelocityStep,
)
from slingloads.models.flight import FlightCondition
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import SlungBody
from slingloads.runs.lateral import LateralInputs

ANALYSIS = "lateral"
AIRFRAME_SHEETS = {s.name: s for s in _AIRFRAME}
#: Longest time history (LateralHistory id or CSV file). [s]
MAX_MAGNITUDE_TIME_HISTORY = 3600.0
#: The displacement steps of the LateralMotions sheet, by type.
STEP_LAWS = {"quintic step": QuinticStep, "cycloidal step": CycloidalStep}
_SPEC = {s.name: s for s in SHEETS}


def read(reader, params, study):
    """Build :class:`LateralInputs` from the workbook.

    Parameters
    ----------
    reader : WorkbookReader
    params : slingloads.io.common.parameters.StudyParameters
        Study-sheet parameters (SI, with defaults).
    study : Study
        The airframe (mass items, hub) and the loads study if it was built.

    Returns
    -------
    LateralInputs

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule.
    """
    margin = params("lateral design-angle margin")
    model = params.choice("lateral cable model", CHOICES)
    ea = params("lateral cable EA")
    if model == "elastic":
        cable_ea = params.positive("lateral cable EA")
    else:
        params.check("lateral cable EA", np.isfinite(ea) and ea == 0,
               "'lateral cable EA' is used only with 'lateral cable model' = elastic; leave "
               "it 0 with the rigid rope")
        cable_ea = None
    damping = _damping(reader, params, study)
    ranges = _ranges(params)
    t_end = params.positive("lateral simulation time", allow_zero=True)
    step = params.positive("lateral RK4 step", allow_zero=True)
    if t_end > 0 and step > 0:
        params.check("lateral RK4 step", step < t_end,
               "'lateral RK4 step' must be shorter than 'lateral simulation time'")
    method = params.choice("lateral history method", CHOICES)
    rtol = params.positive("lateral history rtol")
    output = params.positive("lateral history output step")
    solver = SolverSettings(t_end=t_end if t_end > 0 else None,
                            step=step if step > 0 else None, output_interval=output,
                            method=method, rtol=rtol, atol=min(1e-10, rtol * 1e-2))
    ropes = _ropes(reader)
    # to locate the errors found while computing
    study.source.tables["LateralRopes"] = reader.table(_SPEC["LateralRopes"])
    bodies, source = _bodies(reader, study)
    histories = _histories(reader) if reader.has_sheet("LateralHistory") else {}
    motions, ids = _motions(reader, histories)
    _check_work(reader, params, len(motions), len(ropes), len(bodies), t_end, step, output)
    loads = study.inputs.loads
    if loads is None:
        with located(reader.file):
            loads = loads_reader.read(reader, params, study)
    from slingloads.analyses.lateral import CarrierLimits

    limits = CarrierLimits(params("lateral carrier bank limit"),
                           params("lateral carrier roll rate limit"),
                           carrier_mass=params("lateral carrier mass"))
    return LateralInputs(
        bodies=bodies, body_source=source, rope_lengths=ropes, motions=motions,
        motion_ids=ids, margin=float(margin), cable_ea=cable_ea, damping=damping,
        ranges=ranges, solver=solver, loads=loads, limits=limits)


def _damping(reader, params, study):
    """The damping of the 'lateral damping ...' rows, or derived from the aerodynamic
    tables at 'lateral airspeed EAS' (zero in hover)."""
    source = params.choice("lateral damping source", CHOICES)
    lateral = params.positive("lateral damping", allow_zero=True)
    roll = params.positive("lateral roll damping", allow_zero=True)
    speed = params.positive("lateral airspeed EAS", allow_zero=True)
    if source == "parameters":
        return LateralDamping(lateral, roll)
    for name, value in (("lateral damping", lateral), ("lateral roll damping", roll)):
        params.check(name, value == 0, f"{name!r} is used only with 'lateral damping source' "
                     "= parameters; leave it 0 with 'aerodynamic tables'")
    with located(params, {"eas": "lateral airspeed EAS",
                          "density_altitude": "lateral density altitude"}):
        condition = FlightCondition(speed, params("lateral density altitude"))
    fuselage = read_fuselage_aero(reader, params, study.source.points)
    fin = read_fin_aero(reader, params, study.source.points)
    if fuselage is None and fin is None:
        raise params.error("lateral damping source", "'aerodynamic tables' needs a "
                           "FuselageAero or a FinAero sheet", "aerodynamic tables")
    hardpoints = study.airframe.hardpoints
    with located(Place(reader.file, "FuselageAero" if fuselage is not None else "FinAero")):
        return aerodynamic_damping(condition, hardpoints.hub, hardpoints.mast_axis,
                                   fuselage, fin)


def _ranges(params):
    """The stated uncertainty of roll inertia, CG below hub and rope length."""
    spreads = []
    for name in ("lateral roll inertia spread", "lateral CG below hub spread",
                 "lateral rope length spread"):
        value = params.positive(name, allow_zero=True)
        params.check(name, value < 1, f"{name!r} must lie in [0, 1) (factors 1 -+ spread)")
        spreads.append(value)
    points = params("lateral spread points")
    params.check("lateral spread points", float(points) == int(points) and points >= 1,
                 "'lateral spread points' must be a whole number >= 1")
    return ParameterRanges.spread(*spreads, points=int(points))


def _require(reader, name):
    if not reader.has_sheet(name):
        raise reader.error(f"the lateral study ('run lateral' = yes) needs the {name} sheet "
                           f"(columns {[c.header for c in _SPEC[name].columns]})", sheet=name)
    return reader.table(_SPEC[name])


def _check_work(reader, params, motions, ropes, bodies, t_end, step, output):
    """The sweep asked for stays within the limits (before anything is computed); what the
    automatic run length and step give is checked by the analysis itself."""
    runs = motions * ropes * bodies
    if runs > MAX_LATERAL_RUNS:
        raise reader.error(f"too much work: {motions} motions x {ropes} ropes x {bodies} "
                           f"bodies give {runs:,} runs, more than the {MAX_LATERAL_RUNS:,} "
                           "allowed (limits of slingloads)", None, "LateralMotions", "A1")
    if t_end > 0 and step > 0:
        steps = t_end / step
        for count, limit, what in ((steps, MAX_LATERAL_STEPS, "RK4 steps per run"),
                                   (steps * runs, MAX_LATERAL_RUN_STEPS, "run-steps (runs x "
                                                                         "steps)"),
                                   (steps * motions, MAX_LATERAL_MOTION_STEPS, "motion-steps "
                                    "(motions x steps)")):
            params.check("lateral RK4 step", count <= limit,
                         f"too much work: 'lateral simulation time' / 'lateral RK4 step' "
                         f"gives {count:,.0f} {what}, more than the {limit:,} allowed "
                         "(limits of slingloads); lengthen the step or shorten the run")
    if t_end > 0:
        params.check("lateral history output step", t_end / output <= MAX_HISTORY_OUTPUT,
                     f"too many samples: 'lateral simulation time' / 'lateral history output "
                     f"step' gives {t_end / output:,.0f} samples, more than the "
                     f"{MAX_HISTORY_OUTPUT:,} allowed (limits of slingloads)")


def _ropes(reader):
    t = _require(reader, "LateralRopes")
    return tuple(float(x) for x in t["rope length"])


def locate(err, study, context=None):
    """``err``, raised while the lateral study of ``study`` ran, put at its cell: with the
    sweep as ``context``, an error of the critical case's re-run (:func:`run_case_error`);
    any other error unchanged."""
    return err if context is None else run_case_error(err, study, context)


def run_case_error(err, study, result):
    """The error to raise for ``err``, raised by the time-history re-run of the study's
    critical case (:meth:`~slingloads.analyses.lateral.LateralStudy.run_case`).

    Its work limit (the solver's evaluations, ``field = "rtol"``) is reached when the case is
    far stiffer than its run is long: it is put at the LateralRopes cell of the case's rope
    length, as written, with the period of the case's fastest mode and the run length, and
    names the tolerance; any other error is returned unchanged.
    """
    ropes = study.source.tables.get("LateralRopes")
    if err.field != "rtol" or err.cell is not None or ropes is None:
        return err
    inputs = study.inputs.lateral
    k = result.critical_index
    pendulum, motion = result.pendulums[k], result.motions[k]
    row = [float(v) for v in inputs.rope_lengths].index(float(result.nominal_rope[k]))
    factor = float(result.factors[k, 2])
    periods = pendulum.linear_modes().period
    fastest = float(np.min(periods[periods > 0])) if np.any(periods > 0) else np.inf
    spread = f" x {factor:.4g} (rope length spread)" if factor != 1 else ""
    name = "lateral history rtol"
    rtol = study.source.written.get(name, (inputs.solver.rtol, None))[0]
    where = study.source.cells.get(name, "(default)")
    return place_error(err, find_place(err, ropes, {"rtol": "rope length"}, index=row), (
        f"too much work: the time-history re-run of the critical case (case {k + 1}: body "
        f"{pendulum.body.name!r}, motion {inputs.motion_ids[_motion_index(inputs, motion)]!r}, "
        f"this rope length{spread}) needs more than {err.value:,} solver evaluations (limits "
        f"of slingloads): its fastest mode has a period of {fastest:.3g} s, against a run of "
        f"{result.t_end:.4g} s; check this rope length and the header's unit, or loosen "
        f"{name!r} ({STUDY_SHEET} {where} = {rtol})"))


def _motion_index(inputs, motion):
    """Index of ``motion`` among the study's motions (by identity)."""
    return next((i for i, m in enumerate(inputs.motions) if m is motion), 0)


def _bodies(reader, study):
    if not reader.has_sheet("LateralBodies"):
        return (_airframe_body(reader, study),), "MassItems"
    t = reader.table(_SPEC["LateralBodies"])
    bodies = []
    fields = {"roll_inertia": "roll inertia", "cg_below_hub": "CG below hub"}
    for i, name in enumerate(t["id"]):
        gyration = np.sqrt(t["roll inertia"][i] / t["mass"][i])
        if gyration < MIN_ROLL_GYRATION:
            raise t.error("roll inertia", i, f"the roll radius of gyration sqrt(roll "
                          f"inertia / mass) is {gyration:.3g} m, less than the "
                          f"{MIN_ROLL_GYRATION:g} m of a solid cylinder 0.28 m across "
                          "(helicopters: about 1 m): check the inertia, the mass and their "
                          "units")
        with located(t, fields, default="mass", index=i):
            bodies.append(SlungBody(t["mass"][i], t["roll inertia"][i], t["CG below hub"][i],
                                    name))
    return tuple(bodies), "LateralBodies"


def _airframe_body(reader, study):
    """The body built from the MassItems; its errors located at the cells to change: the
    hub's z (a CG above the hub), or the MassItems inertias (no roll inertia)."""
    try:
        return airframe_body(study.airframe)
    except InputError as err:
        if err.field == "roll_inertia":
            items = reader.table(AIRFRAME_SHEETS["MassItems"])
            if items.has("Ixx"):
                raise place_error(err, find_place(err, items, {"roll_inertia": "Ixx"},
                                                  index=0)) from None
            cell = f"{get_column_letter(len(items.cells) + 1)}1"
            raise place_error(err, Place(reader.file, "MassItems", cell, None), (
                f"{err.rule}: give the mass items their own inertias (no Ixx column)")) from None
        if err.field != "cg_below_hub":
            raise
        hardpoints = reader.table(AIRFRAME_SHEETS["Hardpoints"])
        rule = err.rule.removesuffix(" [m]")
        if isinstance(err.value, float):  # how far above the hub the CG lies, along the mast
            rule += (f" (the CG lies {column_quantity(hardpoints, 'z', -err.value, 'length')}"
                     " above the hub along the mast)")
        hub = study.source.points["rows"]["hub"][0]
        raise place_error(err, find_place(err, hardpoints, {"cg_below_hub": "z"}, index=hub),
                          rule) from None


def _histories(reader):
    t = reader.table(_SPEC["LateralHistory"])
    rows, names = {}, {}
    for i, hid in enumerate(t["history id"]):  # one history per id, case ignored (ids)
        rows.setdefault(id_key(hid), []).append(i)
        names.setdefault(id_key(hid), hid)
    out = {}
    for key, idx in rows.items():
        hid = names[key]
        time = t["t"][idx]
        if len(idx) < 2:
            raise reader.error("a time history needs at least two samples", hid, t.sheet,
                               t.cell("history id", idx[0]))
        for k in range(1, len(idx)):
            if not time[k] > time[k - 1]:
                raise t.error("t", idx[k], f"time-history times must be strictly increasing "
                              f"within history {hid!r} (previous sample at "
                              f"{t.cell('t', idx[k - 1])})")
            if time[k] - time[k - 1] < MIN_SAMPLE_INTERVAL:
                raise t.error("t", idx[k], f"time-history samples must be at least "
                              f"{MIN_SAMPLE_INTERVAL:g} s apart (previous sample at "
                              f"{t.cell('t', idx[k - 1])})")
        with located(t, default="t", index=idx[0]):
            out[key] = TimeHistory(time, t["S"][idx], name=f"history {hid!r}")
    return out


def _csv_history(reader, text, t, i):
    where = (t.sheet, t.cell("history", i))
    columns = csv_columns(reader, text, *where, {"t": "time", "S": "length"},
                          max_rows=MAX_HISTORY_SAMPLES)
    time, s = columns["t"], columns["S"]
    name = text.replace("\\", "/").rsplit("/", 1)[-1]
    if time.size < 2:
        raise reader.error(f"CSV {name}: a time history needs at least two samples", text,
                           *where)
    steps = np.diff(time)
    if np.any(steps <= 0):
        k = int(np.argmax(steps <= 0)) + 1
        raise reader.error(f"CSV {name}: times must be strictly increasing (data row "
                           f"{k + 1}, t = {time[k]:.6g} s, does not come after row {k}, "
                           f"t = {time[k - 1]:.6g} s)", text, *where)
    if np.any(steps < MIN_SAMPLE_INTERVAL):
        k = int(np.argmax(steps < MIN_SAMPLE_INTERVAL)) + 1
        raise reader.error(f"CSV {name}: samples must be at least {MIN_SAMPLE_INTERVAL:g} s "
                           f"apart (data rows {k} and {k + 1}, t = {time[k - 1]:.6g} s and "
                           f"{time[k]:.6g} s)", text, *where)
    if time[-1] - time[0] > MAX_MAGNITUDE_TIME_HISTORY:
        raise reader.error(f"CSV {name}: a time history may last at most "
                           f"{MAX_MAGNITUDE_TIME_HISTORY:g} s; this one lasts "
                           f"{time[-1] - time[0]:.6g} s", text, *where)
    with located(Place(reader.file, *where, written=text)):
        return TimeHistory(time, s, name=f"CSV {name}")


def _motion_type(reader, t, i):
    text = str(t["type"][i]).strip().lower().replace("_", " ").replace("-", " ")
    text = " ".join(text.split())
    text = MOTION_ALIASES.get(text, text)
    if text not in MOTION_TYPES:
        raise reader.error(f"unknown motion type; valid types are {list(MOTION_TYPES)}",
                           t["type"][i], t.sheet, t.cell("type", i))
    return text


def _motions(reader, histories):
    t = _require(reader, "LateralMotions")

    def number(column, i):
        return float(t[column][i]) if t.has(column) else np.nan

    def need(column, i, kind, rule):
        value = number(column, i)
        if np.isnan(value):
            cell = t.cell(column, i) if t.has(column) else "A1"
            raise reader.error(f"a {kind} needs the column {column!r} filled", None,
                               t.sheet, cell)
        if not rule(value):
            raise t.error(column, i, f"{column!r} of a {kind} must be "
                          f"{'> 0' if column == 'duration' else 'finite and not 0'}")
        return value

    def unused(columns, i, kind):
        for column in columns:
            filled = (t.has(column) and (not np.isnan(t[column][i]) if column not in
                                         ("then", "history") else bool(t[column][i])))
            if filled:
                raise t.error(column, i, f"a {kind} does not use the column {column!r}; leave "
                              "it empty")

    def nonzero(v):
        return v != 0

    def positive(v):
        return v > 0

    motions = []
    for i in range(len(t)):
        kind = _motion_type(reader, t, i)
        if kind in STEP_LAWS:
            unused(("then", "delta V", "history"), i, kind)
            duration = need("duration", i, kind, positive)
            has_acc = not np.isnan(number("acceleration", i))
            has_amp = not np.isnan(number("amplitude", i))
            if has_acc == has_amp:
                raise reader.error(f"a {kind} needs either 'acceleration' (peak) or "
                                   "'amplitude', not both nor neither", None, t.sheet,
                                   t.cell("type", i))
            law = STEP_LAWS[kind]
            with located(t, default="type", index=i):
                if has_acc:
                    motion = law.from_peak_acceleration(
                        need("acceleration", i, kind, nonzero), duration)
                else:
                    motion = law(need("amplitude", i, kind, nonzero), duration)
        elif kind == "constant acceleration":
            unused(("amplitude", "delta V", "history"), i, kind)
            rate = need("acceleration", i, kind, nonzero)
            duration = need("duration", i, kind, positive)
            then = str(t["then"][i] if t.has("then") else "").strip().lower()
            if then not in THEN:
                raise reader.error(f"a constant acceleration needs 'then' = one of "
                                   f"{list(THEN)}", then,
                                   t.sheet, t.cell("then", i) if t.has("then") else "A1")
            with located(t, default="type", index=i):
                motion = ConstantAcceleration(rate, duration, then)
        elif kind == "velocity step":
            unused(("acceleration", "duration", "amplitude", "then", "history"), i, kind)
            with located(t, default="type", index=i):
                motion = VelocityStep(need("delta V", i, kind, nonzero))
        else:
            unused(("acceleration", "duration", "amplitude", "then", "delta V"), i, kind)
            text = str(t["history"][i] if t.has("history") else "").strip()
            if not text:
                raise reader.error("a time history needs the column 'history' filled (a "
                                   "LateralHistory id or a CSV file)", None, t.sheet,
                                   t.cell("history", i) if t.has("history") else "A1")
            if id_key(text) in histories:
                motion = histories[id_key(text)]
            elif text.lower().endswith(".csv"):
                motion = _csv_history(reader, text, t, i)
            else:
                known = sorted(h.name.removeprefix("history ") for h in histories.values())
                raise reader.error(f"unknown history; LateralHistory ids are {known} (or "
                                   "give a .csv file)", text,
                                   t.sheet, t.cell("history", i))
        motions.append(motion)
    return tuple(motions), tuple(t["id"])

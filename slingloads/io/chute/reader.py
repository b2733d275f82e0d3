"""Build the parachute-sizing inputs from an input workbook (``run chute sizing = yes``).

Called through the registry (:mod:`slingloads.io.analyses`) as
``read(reader, params, study)``.
It reads the Study parameters of :mod:`slingloads.io.chute.schema`, the optional ``ChuteWake``
sheet, and the airframe's aerodynamic sheets (``FuselageAero``, ``FinAero``,
``ParachuteCD``) and hardpoints, so that the sizing also runs on its own
(``slingloads chute``). Every value is SI after reading; every bad value raises
:class:`~slingloads.errors.InputError` naming the file, sheet, cell, value and rule.
"""

from __future__ import annotations

import numpy as np

from slingloads.analyses.chute_sizing import MetricSettings
from slingloads.io.airframe.reader import read_fin_aero, read_fuselage_aero, read_parachute
from slingloads.io.airframe.schema import SHEETS as _AIRFRAME_SHEETS
from slingloads.io.chute.rows import CHOICES
from slingloads.io.chute.schema import SHEETS
from slingloads.io.common.locate import Place, column_quantity, find_place, located, place_error
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.limits import (
    MAX_CHUTE_REFERENCE_RUNS,
    MAX_CHUTE_RUN_STEPS,
    MAX_CHUTE_RUNS,
    MAX_CHUTE_SAMPLES,
    MAX_CHUTE_STEPS,
)
from slingloads.models.airframe import yaw_inertia_about_hub
from slingloads.models.flight import FlightCondition
from slingloads.models.gusts import GUST_SHAPES, DrydenTurbulence, make_gust
from slingloads.models.integration import SolverSettings
from slingloads.models.wake import BluffBodyWake, TabulatedWake
from slingloads.models.yaw_dynamics import YawModel
from slingloads.runs.chute_sizing import ChuteSizingInputs

ANALYSIS = "chute sizing"
HARDPOINT_SHEETS = {s.name: s for s in _AIRFRAME_SHEETS}


def read(reader, params, study):
    """Build :class:`ChuteSizingInputs` from the workbook.

    Parameters
    ----------
    reader : WorkbookReader
    params : slingloads.io.common.parameters.StudyParameters
        Study-sheet parameters (SI, with defaults).
    study : Study
        The airframe and the hardpoints by kind already read.

    Returns
    -------
    ChuteSizingInputs

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule.
    """
    # ---- condition (IAS taken equal to EAS)
    ias = params.positive("chute sizing airspeed IAS")
    with located(params, {"eas": "chute sizing airspeed IAS",
                          "density_altitude": "chute sizing density altitude",
                          "alpha": "chute sizing alpha trim"}):
        condition = FlightCondition(eas=ias,
                                    density_altitude=params("chute sizing density altitude"),
                                    alpha=params("chute sizing alpha trim"))
    half = params.positive("chute sizing linearisation range")
    params.check("chute sizing linearisation range", half < np.pi / 2,
           "'chute sizing linearisation range' must be below 90 deg")
    # ---- aerodynamics and geometry (the airframe sheets)
    refs = study.source.points
    fuselage = read_fuselage_aero(reader, params, refs)
    fin = read_fin_aero(reader, params, refs)
    if fuselage is None and fin is None:
        raise reader.error("the parachute sizing needs a FuselageAero or a FinAero sheet",
                           sheet="FuselageAero")
    hardpoints = study.airframe.hardpoints
    if hardpoints.chute is None:
        raise reader.error("the parachute sizing needs a Hardpoints row of kind 'chute' (the "
                           "parachute attachment)", sheet="Hardpoints", cell="B1")
    arm = hardpoints.chute[0] - hardpoints.hub[0]
    if arm <= 0:
        hp_t = reader.table(HARDPOINT_SHEETS["Hardpoints"])
        hub_row = refs["rows"]["hub"][0]
        hub_x, hub_unit = hp_t.shown("x", hub_row)
        raise hp_t.error("x", refs["chute_row"], "the parachute attachment (kind 'chute') must "
                         "lie aft of the rotor hub (x greater) to stabilise in yaw; the hub "
                         f"is at x = {hub_x}{' ' + hub_unit if hub_unit else ''} "
                         f"({hp_t.cell('x', hub_row)})")
    parachute = read_parachute(reader, params, 1.0)
    # ---- yaw inertia
    yaw_axis = params.choice("chute sizing yaw axis", CHOICES)
    source = params.choice("chute sizing yaw inertia source", CHOICES)
    given = params("chute sizing yaw inertia")
    if source == "parameter":
        inertia = params.positive("chute sizing yaw inertia")
    else:
        params.check("chute sizing yaw inertia", np.isfinite(given) and given == 0,
               "'chute sizing yaw inertia' is used only with 'chute sizing yaw inertia source' "
               "= parameter (it must then be > 0); leave it 0 with 'mass items'"
               if np.isfinite(given) and given > 0 else "'chute sizing yaw inertia' must be "
               "> 0 (with the source 'parameter') or 0 (with 'mass items')")
        inertia = yaw_inertia_about_hub(study.airframe)
        if not inertia > 0:
            raise params.error("chute sizing yaw inertia source", "the yaw inertia about the "
                               "hub computed from the mass items is 0 (every item on the hub's "
                               "vertical, without Izz): give it with the source 'parameter'")
    with located(params, {"airspeed": "chute sizing airspeed IAS",
                          "alpha": "chute sizing alpha trim"}, default="chute sizing alpha trim"):
        model = YawModel(fuselage, fin, hardpoints, inertia, condition, parachute)
    lo, hi = model.beta_range()
    params.check("chute sizing linearisation range", half <= min(-lo, hi),
           f"the linearisation range must lie inside the tables' sideslip range "
           f"[{np.degrees(lo):.4g}, {np.degrees(hi):.4g}] deg")
    for what, grid in (("FuselageAero", None if fuselage is None else fuselage.table.beta),
                       ("FinAero", None if fin is None else fin.table.angle)):
        if grid is not None:
            inside = np.count_nonzero(np.abs(grid) <= half + 1e-12)
            params.check("chute sizing linearisation range", inside >= 2,
                         f"the {what} table has {inside} sideslip breakpoint(s) within the "
                         "linearisation range: the least-squares fit needs at least two")
    # ---- wake and line
    target = params("chute sizing target q ratio")
    params.check("chute sizing target q ratio", 0 < target <= 1,
           "'chute sizing target q ratio' must lie in (0, 1]")
    wake_source = params.choice("chute sizing wake source", CHOICES)
    if wake_source == "table":
        wake = _wake_table(reader, params, target)
    else:
        k = params.positive("chute sizing wake coefficient")
        area = params.positive("chute sizing wake drag area", allow_zero=True)
        if area == 0:
            if fuselage is None:
                raise reader.error("the wake model needs 'chute sizing wake drag area' > 0 "
                                   "when there is no FuselageAero sheet", 0.0, STUDY_SHEET,
                                   params.where("chute sizing wake drag area"))
            # the table's drag at the trim alpha
            with located(params, default="chute sizing alpha trim"):
                area = float(fuselage.drag_coefficient(condition.alpha, 0.0)) * fuselage.area
        with located(params, default="chute sizing wake coefficient"):
            wake = BluffBodyWake(area, k)
        with located(params, default="chute sizing target q ratio"):
            wake.line_length(target)
    cable = params.positive("chute sizing carrier cable length", allow_zero=True)
    margin = params.positive("chute sizing cable margin", allow_zero=True)
    # ---- solver
    t_end = params.positive("chute sizing simulation time")
    dt = params.positive("chute sizing time step")
    interval = params.positive("chute sizing output interval")
    integrator = params.choice("chute sizing integrator", CHOICES)
    method = params.choice("chute sizing reference method", CHOICES)
    rtol = params.positive("chute sizing reference rtol")
    shapes = [s for s in str(params("chute sizing gust shapes") or "").split(",") if s.strip()]
    _check_work(params, int(params("chute sizing number of areas")) * max(len(shapes), 1),
                t_end, dt, interval, integrator)
    _check_grid(params, t_end, dt, interval, integrator)
    # the adaptive integrators choose their own steps: only the output grid binds them
    settings = SolverSettings(t_end, dt if integrator == "rk4" else interval, interval,
                              method, rtol)
    # ---- gusts
    gusts = _gusts(reader, params, model, t_end)
    limit = params.positive("chute sizing sideslip limit")
    params.check("chute sizing sideslip limit", limit < np.pi / 2,
                 "'chute sizing sideslip limit' must be below 90 deg")
    # ---- sweep
    fmin = params.positive("chute sizing area factor min")
    fmax = params("chute sizing area factor max")
    params.check("chute sizing area factor max", np.isfinite(fmax) and fmax >= fmin,
           "'chute sizing area factor max' must be >= 'chute sizing area factor min'")
    count = params("chute sizing number of areas")
    params.check("chute sizing number of areas", count >= 1,
           "'chute sizing number of areas' must be >= 1")
    params.check("chute sizing number of areas", count == 1 or fmax > fmin,
           "several areas need 'chute sizing area factor max' > min")
    recommended = params.positive("chute sizing recommended factor")
    return ChuteSizingInputs(
        model=model, fit_range=(-half, half), wake=wake, target=float(target),
        cable_length=cable if cable > 0 else None, margin=margin, gusts=gusts,
        settings=settings, metrics=MetricSettings(sideslip_limit=limit),
        factors=np.linspace(fmin, fmax, int(count)),
        recommended_factor=recommended, integrator=integrator, inertia_source=source,
        study_area=float(params("parachute area")),
        study_line=float(params("parachute line length")), yaw_axis=yaw_axis)


def _whole_multiple(value, unit):
    ratio = value / unit
    return round(ratio) >= 1 and abs(ratio - round(ratio)) <= 1e-9 * ratio


def _check_grid(params, t_end, dt, interval, integrator):
    """The stored samples land on the simulation time; with 'rk4' the fixed steps land on
    every sample (the adaptive integrators do not use the time step)."""
    if integrator == "rk4":
        params.check("chute sizing output interval", _whole_multiple(interval, dt),
                     "'chute sizing output interval' must be a whole multiple of 'chute sizing "
                     f"time step' ({dt:g} s) with the 'rk4' integrator")
        params.check("chute sizing simulation time", _whole_multiple(t_end, dt),
                     "'chute sizing simulation time' must be a whole multiple of 'chute sizing "
                     f"time step' ({dt:g} s) with the 'rk4' integrator")
    params.check("chute sizing simulation time", _whole_multiple(t_end, interval),
                 "'chute sizing simulation time' must be a whole multiple of 'chute sizing "
                 f"output interval' ({interval:g} s)")


def _check_work(params, runs, t_end, dt, interval, integrator):
    """The sweep asked for stays within the limits (before anything is computed). The
    fixed steps of 'rk4' are counted here; 'dopri5' counts the steps it tries while it
    integrates (and stops at the same limits)."""
    steps = t_end / dt
    samples = runs * (t_end / interval + 1)
    checks = [("chute sizing number of areas", runs, MAX_CHUTE_RUNS,
               "runs (areas x gust shapes)"),
              ("chute sizing output interval", samples, MAX_CHUTE_SAMPLES,
               "stored samples (runs x simulation time / output interval)")]
    if integrator == "rk4":
        checks += [("chute sizing time step", steps, MAX_CHUTE_STEPS, "time steps per run"),
                   ("chute sizing time step", steps * runs, MAX_CHUTE_RUN_STEPS,
                    "run-steps (runs x time steps)")]
    for name, count, limit, what in checks:
        params.check(name, count <= limit, f"too much work: the sweep asks for {count:,.0f} "
                     f"{what}, more than the {limit:,} allowed (limits of slingloads)")
    if integrator == "solve_ivp":
        params.check("chute sizing integrator", runs <= MAX_CHUTE_REFERENCE_RUNS,
                     f"too much work: the 'solve_ivp' integrator solves each of the {runs:,} "
                     f"runs on its own; at most {MAX_CHUTE_REFERENCE_RUNS} are allowed (limits "
                     "of slingloads): use 'dopri5' or fewer areas")


def _wake_table(reader, params, target):
    """The ChuteWake sheet as a TabulatedWake, each bad value located at its cell; a table
    that never reaches 'chute sizing target q ratio' is refused at its largest ratio."""
    t = reader.table(SHEETS[0])
    x, r = t["distance"], t["q ratio"]
    if len(t) < 2:
        raise reader.error(f"the ChuteWake table needs at least two rows (it has {len(t)})",
                           None, t.sheet, "A3")
    for i in range(len(t)):
        if x[i] < 0:
            raise t.error("distance", i, "wake distance must be >= 0")
        if i and x[i] <= x[i - 1]:
            raise t.error("distance", i, "wake distances must be strictly increasing (first "
                          f"at {t.cell('distance', i - 1)})")
        if not 0 < r[i] <= 1.2:
            raise t.error("q ratio", i, "wake q ratio must lie in (0, 1.2]")
        if i and r[i] < r[i - 1]:
            raise t.error("q ratio", i, "wake q ratio must not decrease downstream (a "
                          "wake recovers with distance: its velocity defect decays, as "
                          f"x^(-2/3) far behind the body); it falls from {r[i - 1]:.4g} at "
                          f"{t.cell('q ratio', i - 1)}")
    if 0 < target <= 1 and not r.max() >= target:
        i = int(np.argmax(r))
        raise t.error("q ratio", i, (
            f"the wake table never reaches the target dynamic-pressure ratio {target:.4g} "
            f"('chute sizing target q ratio', {STUDY_SHEET} "
            f"{params.where('chute sizing target q ratio')}): its largest q ratio is this one, "
            f"at {column_quantity(t, 'distance', x[i], 'length')} "
            f"({t.cell('distance', i)}); extend the table downstream"))
    with located(Place(reader.file, t.sheet)):
        return TabulatedWake(x, r, source="ChuteWake sheet")


def _gusts(reader, params, model, t_end):
    name = "chute sizing gust shapes"
    shapes = [s.strip().lower() for s in str(params(name) or "").split(",") if s.strip()]
    if not shapes:
        raise reader.error(f"{name!r} needs at least one shape of {list(GUST_SHAPES)}", "",
                           STUDY_SHEET, params.where(name))
    for s in shapes:
        if s not in GUST_SHAPES:
            raise reader.error(f"unknown gust shape; valid shapes are {list(GUST_SHAPES)}", s,
                               STUDY_SHEET, params.where(name))
        if shapes.count(s) > 1:
            raise reader.error("gust shape listed twice", s, STUDY_SHEET, params.where(name))
    amplitude = params.positive("chute sizing gust amplitude")
    onset = params.positive("chute sizing gust onset", allow_zero=True)
    duration = params.positive("chute sizing gust duration")
    rise = params.positive("chute sizing gust rise time", allow_zero=True)
    period = params.positive("chute sizing harmonic period")
    params.check("chute sizing gust onset", onset < t_end,
                 f"the gust must start before the end of the simulation ({t_end:g} s)")
    if any(s in ("finite", "1-cosine") for s in shapes):
        params.check("chute sizing gust duration", onset + duration < t_end,
                     f"finite and 1-cosine gusts must end (onset + duration) before the end "
                     f"of the simulation ({t_end:g} s) so that the free response is seen")
    if "continuous" in shapes:
        params.check("chute sizing gust rise time", onset + rise < t_end,
                     f"the continuous crosswind must have risen (onset + rise time) before "
                     f"the end of the simulation ({t_end:g} s)")
    lo, hi = model.beta_range()
    tas = model.condition.tas
    gamma = np.arctan(amplitude / tas)
    params.check("chute sizing gust amplitude", gamma < min(-lo, hi),
                 f"the gust makes a sideslip of {np.degrees(gamma):.4g} deg at "
                 f"{params.quantity('chute sizing airspeed IAS', tas)} true airspeed, outside "
                 f"the aerodynamic tables' range [{np.degrees(lo):.4g}, {np.degrees(hi):.4g}] deg")
    gusts = []
    for s in shapes:
        if s == DrydenTurbulence.kind:
            gusts.append(_turbulence(reader, params, model, onset, t_end))
        else:
            gusts.append(make_gust(s, amplitude, onset, duration, rise_time=rise,
                                   period=period))
    return tuple(gusts)


def _turbulence(reader, params, model, onset, t_end):
    """The Dryden realisation of the 'chute sizing turbulence ...' rows."""
    severity = params.choice("chute sizing turbulence severity", CHOICES)
    length = params.positive("chute sizing turbulence duration")
    params.check("chute sizing turbulence duration", onset + length < t_end,
                 f"the turbulence must end (onset + duration) before the end of the "
                 f"simulation ({t_end:g} s) so that the free response is seen")
    seed = params("chute sizing turbulence seed")
    params.check("chute sizing turbulence seed", float(seed) == int(seed) and seed >= 0,
                 "'chute sizing turbulence seed' must be a whole number >= 0")
    altitude = params("chute sizing turbulence altitude")
    with located(params, default="chute sizing turbulence altitude"):
        gust = DrydenTurbulence.low_altitude(altitude, model.condition.tas, severity,
                                             onset=onset, duration=length, seed=int(seed))
    lo, hi = model.beta_range()
    gamma = np.arctan(gust.peak / model.condition.tas)
    params.check("chute sizing turbulence altitude", gamma < min(-lo, hi),
                 f"the turbulence's largest gust "
                 f"({params.quantity('chute sizing gust amplitude', gust.peak)}) makes a "
                 f"sideslip of "
                 f"{np.degrees(gamma):.4g} deg, outside the aerodynamic tables' range "
                 f"[{np.degrees(lo):.4g}, {np.degrees(hi):.4g}] deg")
    return gust


def locate(err, study, context=None):
    """``err``, raised while the parachute sizing of ``study`` ran, put at its cell (a yaw
    trim that cannot be found: :func:`trim_error`)."""
    return trim_error(err, study)


def trim_error(err, study):
    """The error to raise for ``err``, raised while the sizing computes: a yaw trim that
    cannot be found (``field = "trim"``: the yawing moment about the hub keeps one sign) is
    put at the hub's y cell, with the hub's position as written and what sets that moment;
    any other error is returned unchanged."""
    hp_t = study.source.tables.get("Hardpoints")
    if err.field != "trim" or err.cell is not None or hp_t is None:
        return err
    row = study.source.points["rows"]["hub"][0]
    shown = []
    for column in ("x", "y", "z"):
        value, unit = hp_t.shown(column, row)
        shown.append(f"{column} {value}{' ' + unit if unit else ''}")
    return place_error(err, find_place(err, hp_t, {"trim": "y"}, index=row), (
        f"{err.rule}; the moment is taken about the rotor hub's vertical (Hardpoints "
        f"{hp_t.cell('x', row)}:{hp_t.cell('z', row)}: {', '.join(shown)}): a hub off the "
        "airframe's plane of symmetry, or FuselageAero / FinAero tables that are not "
        "antisymmetric in beta, give a moment at zero sideslip that the fin and the parachute "
        "cannot balance; check the hub's position, the tables and the headers' units"))

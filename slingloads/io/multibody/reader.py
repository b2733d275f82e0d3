"""Build the multibody system and its manoeuvres from an input workbook (``run multibody``).

Called through the registry (:mod:`slingloads.io.analyses`) as ``read(reader, params, study)``.
The pieces are public so that other analyses (a campaign sweeping the system) build the same
system from the same sheets: :func:`read_system` (carrier, cable, carried helicopter, parachute,
configuration), :func:`read_manoeuvres` (the MultibodyManoeuvres sheet, or the paper's list),
:func:`read_settings`; :func:`load_workbook_system` does it all from a file path.

Every value is SI after reading; every bad value raises :class:`~slingloads.errors.InputError`
naming the file, sheet, cell, the value as written and the rule broken.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from slingloads.analyses.multibody.manoeuvres import (
    DEFAULT_DISTURBANCE,
    HOVER_SEED,
    Manoeuvre,
    paper_manoeuvres,
)
from slingloads.io.airframe.reader import (
    parachute_reach_rule,
    read_fin_aero,
    read_fuselage_aero,
    read_parachute,
)
from slingloads.io.common.locate import Place, located
from slingloads.io.common.referenced import referenced_file
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.multibody.rows import CHOICES
from slingloads.io.multibody.schema import (
    DIRECTIONS,
    DISTURBANCE_COLUMNS,
    MANOEUVRE_KINDS,
    SHEETS,
)
from slingloads.io.multibody.trajectory import read_trajectory_csv
from slingloads.limits import MAX_MULTIBODY_RUN_STEPS, MAX_MULTIBODY_SAMPLES, MEMORY_BUDGET
from slingloads.models.aero_tables import Table1D
from slingloads.models.atmosphere import isa_density, true_airspeed
from slingloads.models.gusts import GUST_KINDS, GUST_VELOCITY, make_gust
from slingloads.models.multibody.cable import Cable
from slingloads.models.multibody.carrier import ForwardAcceleration, FreeCarrier, FrozenCarrier
from slingloads.models.multibody.environment import Wind, WindRamp
from slingloads.models.multibody.local_flow import LiftingSurface
from slingloads.models.multibody.parachute_line import HingedParachute, QuasiStaticParachute
from slingloads.models.multibody.rigid_body import RigidBody
from slingloads.models.multibody.system import SlingSystem
from slingloads.models.parachute import extended_cd_table
from slingloads.runs.multibody import MultibodyInputs

ANALYSIS = "multibody"
_SPEC = {s.name: s for s in SHEETS}
#: Defaults of the MultibodyManoeuvres columns (SI).
ONSET, DURATION, ACCELERATION, RAMP_RATE = 5.0, 10.0, 1.0, 0.5


def read(reader, params, study):
    """Build :class:`MultibodyInputs` from the workbook.

    Parameters
    ----------
    reader : WorkbookReader
    params : slingloads.io.common.parameters.StudyParameters
    study : Study
        The airframe and the hardpoints by kind already read.

    Returns
    -------
    MultibodyInputs

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule.
    """
    settings = read_settings(reader, params)
    system, choices = read_system(reader, params, study)
    manoeuvres, source = read_manoeuvres(reader, params, system, settings["t_end"])
    check_work(params, len(manoeuvres), settings)
    warnings = tuple(system.warnings(choices["margin"]))
    return MultibodyInputs(system=system, manoeuvres=manoeuvres, settings=settings,
                           warnings=warnings, manoeuvre_source=source, **choices)


def locate(err, study, context=None):
    """``err``, raised while the multibody model of ``study`` ran: located by its field alone
    (the schema's ``COMPUTE_FIELDS``), so returned unchanged."""
    return err


# --------------------------------------------------------------------------- settings
def read_settings(reader, params):
    """Run length [s], fixed step [s] (None: adaptive), output interval [s] and the adaptive
    step's tolerances (relative [-], absolute [SI]), as a dict of :func:`simulate`'s
    keywords."""
    t_end = params.positive("multibody simulation time")
    interval = params.positive("multibody output interval")
    params.check("multibody output interval", interval <= t_end,
                 "'multibody output interval' must not exceed 'multibody simulation time'")
    samples = t_end / interval
    params.check("multibody simulation time", abs(samples - round(samples)) <= 1e-9 * samples,
                 "'multibody simulation time' must be a whole multiple of 'multibody output "
                 "interval'")
    dt = params.positive("multibody time step", allow_zero=True)
    return {"t_end": t_end, "dt": dt if dt > 0 else None, "output_interval": interval,
            "rtol": params.positive("multibody relative tolerance"),
            "atol": params.positive("multibody absolute tolerance")}


def check_work(params, runs, settings):
    """The runs asked for stay within the limits (before anything is computed): stored
    samples (runs x samples) and, with a fixed step, run-steps (runs x steps)."""
    samples = runs * (round(settings["t_end"] / settings["output_interval"]) + 1)
    params.check("multibody output interval", samples <= MAX_MULTIBODY_SAMPLES,
                 f"too much work: {runs} runs of {settings['t_end']:g} s sampled at this "
                 f"interval store {samples:,} samples, more than the "
                 f"{MAX_MULTIBODY_SAMPLES:,} allowed (limits of slingloads)")
    from slingloads.analyses.multibody.simulate import DRIVE_BUDGET, SAMPLE_BYTES

    need = DRIVE_BUDGET + samples * SAMPLE_BYTES
    params.check("multibody output interval", need <= MEMORY_BUDGET,
                 f"too much memory: {runs} runs of {settings['t_end']:g} s sampled at this "
                 f"interval need about {need / 2**20:,.0f} MB, more than the "
                 f"{MEMORY_BUDGET / 2**20:,.0f} MB budget of a computation (limits of "
                 "slingloads; docs/inputs-and-outputs.md, Memory)")
    if settings["dt"] is not None:
        # counted as the integrator steps: a whole number a run (0.0024 s over 3,600 s is
        # 1,500,000, not the 1,500,000.0000000002 of the division)
        steps = runs * math.ceil(settings["t_end"] / settings["dt"] * (1 - 1e-12))
        params.check("multibody time step", steps <= MAX_MULTIBODY_RUN_STEPS,
                     f"too much work: {runs} runs of {settings['t_end']:g} s at this step are "
                     f"{steps:,.0f} steps, more than the {MAX_MULTIBODY_RUN_STEPS:,} allowed "
                     "(limits of slingloads); use the adaptive step (0) or a longer one")


# --------------------------------------------------------------------------- the system
def read_system(reader, params, study):
    """The towed system of the workbook, and the Study's choices.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
    study : Study
        With the airframe and its hardpoints by kind (``study.source.points``).

    Returns
    -------
    system : SlingSystem
    choices : dict
        ``configuration``, ``tail``, ``carrier``, ``parachute_model``, ``canopy_table``
        (spelt as in the schema) and ``margin`` [-].
    """
    file = reader.file
    configuration = params.choice("multibody configuration", CHOICES)
    tail_choice = params.choice("multibody tail", CHOICES)
    parachute_model = params.choice("multibody parachute model", CHOICES)
    canopy_table = params.choice("multibody canopy CD", CHOICES)
    carrier_choice = params.choice("multibody carrier", CHOICES)
    margin = params.positive("multibody cable margin", allow_zero=True)
    airspeed = params.positive("multibody airspeed EAS", allow_zero=True)
    altitude = params("multibody density altitude")
    body = _body(reader, study)
    refs = study.source.points
    fuselage = read_fuselage_aero(reader, params, refs)
    if fuselage is None:
        raise reader.error("the multibody model needs the FuselageAero sheet (the carried "
                           "helicopter's aerodynamics)", sheet="FuselageAero")
    surfaces = _surfaces(reader, params, refs, tail_choice)
    hardpoints = study.airframe.hardpoints
    parachute = None
    if configuration == "with parachute":
        parachute = _parachute(reader, params, hardpoints, parachute_model, canopy_table)
    cable = _cable(params)
    if parachute is not None:
        _check_reach(reader, params, refs, hardpoints, parachute, cable)
    carrier = _carrier(params, carrier_choice)
    with located(params, default="multibody density altitude"):
        isa_density(altitude)
    with located(Place(file, STUDY_SHEET)):
        system = SlingSystem(body, hardpoints, cable, fuselage, surfaces, parachute, carrier,
                             airspeed, altitude, name=str(params("study name")))
    return system, {"configuration": configuration, "tail": tail_choice,
                    "carrier": carrier_choice, "parachute_model": parachute_model,
                    "canopy_table": canopy_table, "margin": margin}


def _body(reader, study):
    """The carried helicopter's mass, CG and inertia tensor from MassItems."""
    with located(Place(reader.file, "MassItems")):
        return RigidBody.from_mass_items(study.airframe.mass_items)


def _surfaces(reader, params, refs, tail_choice):
    """The fin (cut down, or intact with the full tail) and the horizontal tail."""
    fin = read_fin_aero(reader, params, refs)
    if fin is not None:
        with located(params, default="fin axes"):
            LiftingSurface.from_fin(fin)  # a normal-force table: body axes
    if tail_choice == "cut-down fin":
        return (LiftingSurface.from_fin(fin),) if fin is not None else ()
    if fin is None:
        raise reader.error("'multibody tail' = full tail needs the FinAero sheet (the intact "
                           "fin)", "full tail", STUDY_SHEET, params.where("multibody tail"))
    if not reader.has_sheet("HTailAero"):
        raise reader.error("'multibody tail' = full tail needs the HTailAero sheet (the "
                           "horizontal tail)", "full tail", STUDY_SHEET,
                           params.where("multibody tail"))
    if refs.get("htail_cp") is None:
        raise reader.error("'multibody tail' = full tail needs a Hardpoints row of kind "
                           "'htail_cp' (horizontal-tail centre of pressure)",
                           sheet="Hardpoints", cell="B1")
    area = params.positive("multibody horizontal tail area")
    t = reader.table(_SPEC["HTailAero"])
    with located(t):
        table = Table1D(t["alpha"], {"CN": t["CN"]}, angle_name="alpha",
                        what="horizontal tail")
    with located(params, default="multibody horizontal tail area"):
        tail = LiftingSurface(table, area, refs["htail_cp"], "z", 1.0, "horizontal tail")
    return LiftingSurface.from_fin(fin, efficiency=1.0), tail


def _parachute(reader, params, hardpoints, model, canopy_table):
    """The hinged or quasi-static canopy of the 'with parachute' configuration."""
    if hardpoints.chute is None:
        raise reader.error("'multibody configuration' = with parachute needs a Hardpoints row "
                           "of kind 'chute' (the parachute attachment)", sheet="Hardpoints",
                           cell="B1")
    area = params.positive("multibody parachute area", allow_zero=True)
    if area == 0:
        area = params.positive("parachute area", allow_zero=True)
        if area == 0:
            raise params.error("multibody parachute area", "the parachute needs an area: "
                               "'multibody parachute area' > 0, or the Study's 'parachute "
                               "area' > 0 when it is 0")
    chute = read_parachute(reader, params, area)
    if canopy_table == "extended":
        chute = replace(chute, cd=extended_cd_table(), axes="wind")
    elif chute.axes != "wind":
        raise params.error("parachute table axes", "the multibody canopy pulls along its "
                           "relative wind: its table must be in wind axes (CD), or set "
                           "'multibody canopy CD' to extended")
    if model == "quasi-static":
        return QuasiStaticParachute(chute)
    mass = params.positive("multibody canopy mass")
    with located(params, default="multibody canopy mass"):
        return HingedParachute(chute, mass)


def _cable(params):
    length = params.positive("multibody cable length")
    ea = params.positive("multibody cable EA")
    damping = params.positive("multibody cable damping ratio", allow_zero=True)
    return Cable(length, ea, damping)


def _check_reach(reader, params, refs, hardpoints, parachute, cable):
    """The canopy must not be able to reach the carrier: line plus hub-to-attachment distance
    shorter than the cable (stated in the cable's unit, at its cell)."""
    name = "multibody cable length"
    rule = parachute_reach_rule(reader, params, refs, hardpoints, parachute.line_length,
                                cable.length, params.unit(name))
    if rule is not None:
        raise params.error(name, rule)


def _carrier(params, choice):
    mass = params.positive("multibody carrier mass")
    drag = params.positive("multibody carrier drag area", allow_zero=True)
    gain = params.positive("multibody carrier speed gain")
    return FreeCarrier(mass, drag, gain) if choice == "free" else FrozenCarrier()


# --------------------------------------------------------------------------- manoeuvres
def read_manoeuvres(reader, params, system, t_end):
    """The runs of the MultibodyManoeuvres sheet, or the paper's list without it.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
    system : SlingSystem
        Its density altitude turns the forward accelerations' indicated airspeeds into true
        airspeeds.
    t_end : float
        Length of the runs (inputs must start before it). [s]

    Returns
    -------
    manoeuvres : tuple of Manoeuvre
    source : str
    """
    if not reader.has_sheet("MultibodyManoeuvres"):
        return tuple(paper_manoeuvres(system.density_altitude)), "the paper's list"
    t = reader.table(_SPEC["MultibodyManoeuvres"])
    rows = _Rows(reader, t)
    out = []
    for i in range(len(t)):
        name = str(t["name"][i]).strip()
        kind = rows.choice("kind", i, MANOEUVRE_KINDS, required=True)
        builder = {"free response": _free_response, "gust": _gust,
                   "forward acceleration": _acceleration, "wind ramp": _wind_ramp,
                   "hook trajectory": _hook_trajectory}[kind]
        with located(t, default="kind", index=i):
            out.append(builder(rows, i, name, system, t_end))
    return tuple(out), "MultibodyManoeuvres sheet"


class _Rows:
    """Cells of the MultibodyManoeuvres sheet, checked with the value as written."""

    def __init__(self, reader, table):
        self.reader, self.t = reader, table

    def error(self, column, i, rule):
        """An InputError at the cell, echoing the value as written with its header's unit
        (at the sheet's first cell for a missing column)."""
        if self.t.has(column):
            return self.t.error(column, i, rule)
        return self.reader.error(rule, None, self.t.sheet, "A1")

    def given(self, column, i):
        if not self.t.has(column):
            return False
        value = self.t[column][i]
        return bool(str(value).strip()) if isinstance(value, str) else np.isfinite(value)

    def number(self, column, i, default, rule, ok):
        """The SI value of a numeric cell (``default`` when empty), checked by ``ok``."""
        if not self.given(column, i):
            if default is None:
                raise self.error(column, i, f"{self.t['kind'][i]!r} needs {column!r}: {rule}")
            return default
        value = float(self.t[column][i])
        if not ok(value):
            raise self.error(column, i, f"{column!r} must be {rule}")
        return value

    def choice(self, column, i, valid, required=False, default=""):
        if not self.given(column, i):
            if required:
                raise self.error(column, i, f"{column!r} needs one of {list(valid)}")
            return default
        text = " ".join(str(self.t[column][i]).strip().lower().replace("_", " ").split())
        for v in valid:
            if text == v.lower():
                return v
        raise self.error(column, i, f"unknown {column}; valid values are {list(valid)}")

    def unused(self, columns, i, kind):
        for column in columns:
            if self.given(column, i):
                raise self.error(column, i, f"a {kind} does not use {column!r}; leave it "
                                            "empty")

    def disturbance(self, i, default):
        given = {key: float(self.t[column][i]) for column, key in DISTURBANCE_COLUMNS.items()
                 if self.given(column, i)}
        return given if given else dict(default)

    def onset(self, i, t_end):
        return self.number("onset", i, ONSET, f">= 0 and before the end of the run "
                           f"({t_end:g} s)", lambda v: 0 <= v < t_end)


def _free_response(rows, i, name, system, t_end):
    rows.unused(("shape", "direction", "amplitude", "onset", "duration", "target", "rate"), i,
                "free response")
    return Manoeuvre(name, disturbance=rows.disturbance(i, DEFAULT_DISTURBANCE))


def _gust(rows, i, name, system, t_end):
    rows.unused(("target", "rate"), i, "gust")
    shape = rows.choice("shape", i, tuple(GUST_KINDS), default="finite")
    direction = rows.choice("direction", i, DIRECTIONS, default="lateral")
    amplitude = rows.number("amplitude", i, GUST_VELOCITY, "finite and not 0",
                            lambda v: v != 0)
    onset = rows.onset(i, t_end)
    duration = rows.number("duration", i, DURATION, "> 0", lambda v: v > 0)
    if shape in ("finite", "1-cosine") and onset + duration >= t_end:
        raise rows.error("duration", i, f"a {shape} gust must end (onset + duration) before "
                                        f"the end of the run ({t_end:g} s)")
    gust = make_gust(shape, amplitude, onset, duration)
    return Manoeuvre(name, wind=Wind(gust=gust, direction=direction),
                     disturbance=rows.disturbance(i, {}))


def _acceleration(rows, i, name, system, t_end):
    rows.unused(("shape", "direction", "amplitude", "duration"), i, "forward acceleration")
    target = rows.number("target", i, None, "> 0 [kt]", lambda v: v > 0)
    rate = rows.number("rate", i, ACCELERATION, "> 0", lambda v: v > 0)
    onset = rows.onset(i, t_end)
    tas = float(true_airspeed(target, system.density_altitude))
    return Manoeuvre(name, trajectory=ForwardAcceleration(tas, rate, onset),
                     disturbance=rows.disturbance(i, HOVER_SEED))


def _hook_trajectory(rows, i, name, system, t_end):
    """A run along a hook trajectory read from the CSV file of column ``file``, from the
    trim at the system airspeed."""
    rows.unused(("shape", "direction", "amplitude", "onset", "duration", "target", "rate"), i,
                "hook trajectory")
    if not rows.given("file", i):
        raise rows.error("file", i, "a hook trajectory needs its CSV 'file' (time_s and "
                                    "ax_mps2, ay_mps2, az_mps2, or vx_mps..., or x_m...)")
    t = rows.t
    text = str(t["file"][i]).strip()
    path = referenced_file(rows.reader, text, t.sheet, t.cell("file", i))
    trajectory = read_trajectory_csv(path)
    late = [b for b in trajectory.breakpoints if b >= t_end]
    if late:
        raise rows.error("file", i, f"the trajectory's breakpoints must lie before the end "
                                    f"of the run ({t_end:g} s); {late[0]:g} s does not")
    return Manoeuvre(name, trajectory=trajectory, disturbance=rows.disturbance(i, {}))


def _wind_ramp(rows, i, name, system, t_end):
    rows.unused(("shape", "direction", "amplitude", "duration"), i, "wind ramp")
    target = rows.number("target", i, None, "> 0 [kt]", lambda v: v > 0)
    rate = rows.number("rate", i, RAMP_RATE, "> 0", lambda v: v > 0)
    onset = rows.onset(i, t_end)
    return Manoeuvre(name, wind=Wind(ramp=WindRamp(target, rate, onset)),
                     disturbance=rows.disturbance(i, HOVER_SEED))



"""Build the structural loads study from an input workbook (``run loads = yes``).

Called through the registry (:mod:`slingloads.io.analyses`) as ``read(reader, params, study)``
once the airframe is read. It reads the Study parameters of :mod:`slingloads.io.loads.schema`,
the aerodynamic tables and the parachute of the airframe sheets
(:mod:`slingloads.io.airframe.reader`), and the optional sheets ``AeroEnvelope``,
``LoadCases`` and ``PreviousEnvelope``. Every value is SI after reading; every bad value raises
:class:`~slingloads.errors.InputError` naming the file, sheet, cell, value and rule.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from slingloads.analyses.fe_loads import ModelAxes
from slingloads.analyses.hook_loads import (
    NO_HOOK,
    TOWED,
    HookLoadOptions,
    hook_directions,
    horizontal_basis,
)
from slingloads.analyses.loads import (
    NO_AERO,
    TRIM_AERO,
    AeroEnvelope,
    ListedCase,
    LoadsStudy,
)
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.io.airframe.reader import (
    PARACHUTE_PARAMETERS,
    read_fin_aero,
    read_fuselage_aero,
    read_parachute,
)
from slingloads.io.airframe.schema import SHEETS as _AIRFRAME
from slingloads.io.common.locate import Place, column_quantity, located, place_error
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.loads.nastran import MAX_ID
from slingloads.io.loads.rows import CHOICES
from slingloads.io.loads.schema import SHEETS
from slingloads.limits import MAX_CASE_POINTS, MAX_LOAD_CASES, MAX_SFBM_ROWS
from slingloads.models.attitude import Attitude, resolve_attitude
from slingloads.models.flight import FlightCondition
from slingloads.runs.loads import HANDOFF
from slingloads.runs.study import ReportOptions

_SPEC = {s.name: s for s in SHEETS}
AIRFRAME_SHEETS = {s.name: s for s in _AIRFRAME}


def read(reader, params, study):
    """Build the :class:`~slingloads.analyses.loads.LoadsStudy` of the workbook.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
        Study-sheet parameters (SI, with defaults).
    study : Study
        The airframe and the hardpoints by kind already read.

    Returns
    -------
    LoadsStudy

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule; also when the cases asked for exceed the
        limits of :mod:`slingloads.limits` (checked before anything is computed).
    """
    airframe, refs = study.airframe, study.source.points
    parachute = envelope = None
    fuselage = read_fuselage_aero(reader, params, refs)
    fin = read_fin_aero(reader, params, refs)
    chute_area = params.positive("parachute area", allow_zero=True)
    if chute_area > 0:
        if refs["chute"] is None:
            raise params.error("parachute area", "a parachute area is given but the "
                               "Hardpoints sheet has no row of kind 'chute'")
        parachute = read_parachute(reader, params, chute_area, _PARACHUTE_PARAMETERS)
    if reader.has_sheet("AeroEnvelope"):
        t = reader.table(_SPEC["AeroEnvelope"])
        for i, point in enumerate(t["id"]):
            if point.casefold() == NO_AERO.casefold():
                raise t.error("id", i, f"{NO_AERO!r} is reserved: in LoadCases, aero "
                                       f"{NO_AERO} means no aerodynamic load; choose another id")
            if point.casefold() == TRIM_AERO.casefold():
                raise t.error("id", i, f"{TRIM_AERO!r} is reserved: in LoadCases, aero "
                                       f"{TRIM_AERO} means the trimmed attitude of a towed "
                                       "case; choose another id")
        envelope = AeroEnvelope(tuple(t["id"]), t["alpha"], t["beta"])
        _check_envelope_in_tables(reader, t, fuselage, fin)
    elif fuselage is not None or fin is not None:
        raise reader.error("missing sheet 'AeroEnvelope': aerodynamic tables are given "
                           "(FuselageAero or FinAero) and the loads need the envelope's angle-"
                           "of-attack / sideslip points", sheet="AeroEnvelope")
    hook = _hook_options(reader, params)
    with located(params, {"eas": "airspeed EAS", "density_altitude": "density altitude"}):
        flight = FlightCondition(params("airspeed EAS"), params("density altitude"))
    attitude = _attitude(reader, params, airframe, refs)
    line = params.choice("parachute line direction", CHOICES)
    generate = params("generate case matrix")
    listed = _listed_cases(reader, params, hook, envelope, parachute, generate)
    _check_case_count(reader, params, hook, airframe, envelope, parachute, generate, listed)
    previous = _previous(reader) if reader.has_sheet("PreviousEnvelope") else None
    with located(Place(reader.file, "LoadCases" if listed else STUDY_SHEET)):
        return LoadsStudy(airframe, flight, hook, envelope, fuselage, fin, parachute,
                          chute_line=line, attitude=attitude, generate=generate,
                          listed=listed, previous_envelope=previous,
                          ultimate_factor=params("ultimate factor"),
                          name=str(params("study name")))


def _hook_options(reader, params):
    """HookLoadOptions from the Study rows, each bad value located at its own cell."""
    names = {"nz": "hook load factor Nz", "angle": "hook angle from vertical",
             "lateral_angle": "hook lateral angle", "n_azimuth": "hook azimuths",
             "include_vertical": "hook vertical case", "towed": "towed equilibrium cases"}
    kwargs = {arg: params(name) for arg, name in names.items()}
    _nz_warning(reader, params, kwargs["nz"])
    if kwargs["lateral_angle"] == 0:
        kwargs["lateral_angle"] = None  # 0: the same as 'hook angle from vertical'
    kwargs["cone"] = params.choice("hook cone shape", CHOICES)
    for arg, name in names.items():
        with located(params, default=name):
            HookLoadOptions(**{arg: kwargs[arg]})
    with located(params, default="hook azimuths"):
        return HookLoadOptions(**kwargs)


#: The hook load factor of CS 29.865(a) for non-human external cargo.
REGULATORY_NZ = 2.5


def _nz_warning(reader, params, nz):
    """Flag a hook load factor below the 2.5 of CS 29.865(a): a lower factor is allowed only
    when approved under CS 29.337 to 29.341 (the Study sheet refuses one below 1)."""
    if nz < REGULATORY_NZ:
        text = (f"hook load factor Nz = {nz:g} (Study {params.where('hook load factor Nz')}) "
                f"is below the {REGULATORY_NZ:g} of CS 29.865(a): a lower factor must be "
                "approved under CS 29.337 to 29.341 (CS 29.337 allows no positive limit "
                "manoeuvring factor below +2.0)")
        if text not in reader.warnings:
            reader.warnings.append(text)


def _attitude(reader, params, airframe, refs):
    """'hanging', 'mast vertical' or the Attitude given by 'attitude pitch' and 'roll'."""
    source = params.choice("attitude", CHOICES)
    angles = {name: params(name) for name in ("attitude pitch", "attitude roll")}
    if source != "given":
        for name, value in angles.items():
            params.check(name, value == 0, f"{name!r} is used only with 'attitude' = given; "
                         f"leave it 0 with {source!r}")
        if source == "hanging":
            _check_hanging(reader, params, airframe, refs)
        with located(params, default="attitude"):
            return resolve_attitude(source, airframe)
    for name, value in angles.items():
        with located(params, default=name):
            Attitude(**{name.split()[1]: value})
    with located(params, default="attitude"):
        attitude = Attitude(angles["attitude pitch"], angles["attitude roll"])
        horizontal_basis(attitude.vertical)
    return attitude


def _check_hanging(reader, params, airframe, refs):
    """The hanging attitude needs the hub above the CG of the mass items (the rule of
    :meth:`~slingloads.models.attitude.Attitude.hanging`): else an error at the hub's z cell,
    with the CG's z in that cell's unit."""
    hub, cg = airframe.hardpoints.hub, airframe.mass_items.cg
    if hub[2] - cg[2] > 0 and np.linalg.norm(hub - cg) >= 1e-9:
        return
    hp_t = reader.table(AIRFRAME_SHEETS["Hardpoints"])
    cell = params.cell("attitude")
    source = (f"'attitude' = hanging, {STUDY_SHEET} {cell}" if cell
              else "the default 'attitude' = hanging")
    raise hp_t.error("z", refs["rows"]["hub"][0], (
        f"the rotor hub must lie above the CG of the mass items (CG z = "
        f"{column_quantity(hp_t, 'z', cg[2], 'length')}, from the MassItems) for the airframe "
        f"to hang upright from it ({source}); check the hub's z and the headers' units, or "
        "give 'attitude' = given with 'attitude pitch' and 'attitude roll'"))


def _listed_cases(reader, params, hook, envelope, parachute, generate):
    """The LoadCases sheet, each case checked at its cells (hook direction, aerodynamic point,
    parachute, id) with the rules the analysis applies."""
    if not reader.has_sheet("LoadCases"):
        if not generate:
            raise params.error("generate case matrix", "no load case: 'generate case "
                               "matrix' is no and there is no LoadCases sheet")
        return ()
    t = reader.table(_SPEC["LoadCases"])
    with located(params, default="hook azimuths"):
        directions = list(hook_directions(hook)["hook"])
    valid_hooks = [*directions, TOWED, NO_HOOK]
    valid_aero = [*(envelope.ids if envelope is not None else ()), NO_AERO, TRIM_AERO]
    n_generated = _generated_count(hook, envelope, parachute) if generate else 0
    generated = {f"LC{i + 1:04d}" for i in range(n_generated)}
    cases = []
    for i in range(len(t)):
        case = ListedCase(t["id"][i], t["hook"][i], t["aero"][i], t["chute"][i],
                          t["description"][i] if t.has("description") else "")
        if case.id in generated:
            raise t.error("id", i, f"load case id is also the id of a generated case "
                          f"(LC0001 to LC{n_generated:04d}): choose another")
        if case.hook not in valid_hooks:
            raise t.error("hook", i, f"unknown hook direction; valid ids are {valid_hooks} "
                          "(from 'hook azimuths' and 'hook vertical case')")
        if (case.hook == TOWED) != (case.aero == TRIM_AERO):
            raise t.error("aero", i, f"a towed case (hook {TOWED}) flies at the trimmed "
                          f"attitude, aero {TRIM_AERO}, and only a towed case does")
        if case.aero not in valid_aero:
            raise t.error("aero", i, f"unknown aerodynamic point; valid ids are {valid_aero} "
                          "(the AeroEnvelope ids)")
        if case.chute and parachute is None:
            raise t.error("chute", i, "the case asks for the parachute but none is defined "
                          "('parachute area' is 0)")
        cases.append(case)
    return tuple(cases)


def _generated_count(hook, envelope, parachute):
    """Number of generated cases: directions x aerodynamic points x parachute states, and the
    towed cases (as :meth:`LoadsStudy.case_matrix` builds them)."""
    directions = hook.n_azimuth + (1 if hook.include_vertical else 0)
    points = len(envelope.ids) if envelope is not None else 1
    states = 2 if parachute is not None else 1
    towed = states if hook.towed else 0  # at most one trim per parachute state
    return directions * points * states + towed


def _check_case_count(reader, params, hook, airframe, envelope, parachute, generate, listed):
    """The load cases asked for stay within the limits (before anything is computed)."""
    generated = _generated_count(hook, envelope, parachute) if generate else 0
    cases = generated + len(listed)
    stations = len(airframe.stations)
    points = (len(airframe.mass_items.mass) + len(airframe.hardpoints.mast_feet)
              + len(airframe.aero_points) + 3)
    for count, limit, what in (
            (cases, MAX_LOAD_CASES, "load cases"),
            (cases * stations, MAX_SFBM_ROWS, "SFBM rows (load cases x cut stations)"),
            (cases * points, MAX_CASE_POINTS, "load cases x load points (mass items, mast "
                                              "feet, aerodynamic points)")):
        if count > limit:
            rule = (f"too much work: {generated:,} generated + {len(listed):,} listed load "
                    f"cases give {count:,} {what}, more than the {limit:,} allowed (limits of "
                    "slingloads); reduce 'hook azimuths', the AeroEnvelope points, the listed "
                    "cases or the cut stations")
            if generate and generated >= len(listed):
                raise params.error("hook azimuths", rule)
            raise reader.error(rule, None, "LoadCases", "A1")


_PARACHUTE_PARAMETERS = {**PARACHUTE_PARAMETERS, "parachute opening factor": "opening_factor"}


def _check_envelope_in_tables(reader, t, fuselage, fin):
    """Each envelope point must lie inside the aerodynamic tables (no extrapolation)."""
    for i in range(len(t)):
        if fuselage is not None:  # the angle outside the table names its cell
            with located(t, {"alpha": "alpha", "beta": "beta"}, default="alpha", index=i):
                fuselage.airframe_coefficients(t["alpha"][i], t["beta"][i])
        if fin is not None:
            with located(t, default="beta", index=i):
                fin.force(t["beta"][i], 0.0)


def _previous(reader):
    t = reader.table(_SPEC["PreviousEnvelope"])
    x = t["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            raise t.error("x", i, "previous envelope stations must be sorted by increasing x "
                          "without repeats")
    rows = []
    for name in COMPONENTS:
        lo, hi = t[f"{name} min"], t[f"{name} max"]
        for i in range(len(x)):
            if lo[i] > hi[i]:
                top, unit = t.shown(f"{name} max", i)
                top = f"{top} {unit}" if unit else top
                raise t.error(f"{name} min", i, f"previous envelope: {name} min must not "
                              f"exceed {name} max ({top} at {t.cell(f'{name} max', i)})")
        rows.append(pd.DataFrame({"x [m]": x, "component": name, "min": lo, "max": hi}))
    return pd.concat(rows, ignore_index=True)


def report_options(params, study):
    """The report options of the loads, checked for every workbook: the stations and
    component pairs of the 2-D envelopes ('hull stations', 'hull pairs'), the texts the
    Summary quotes ('hook angle justification', 'previous envelope source') and the Nastran
    file ('nastran ...' rows).

    Returns
    -------
    ReportOptions
    """
    airframe = study.airframe
    ids = list(airframe.station_ids)
    text = str(params("hull stations") or "").strip()
    if text:
        stations = [s.strip() for s in text.split(",") if s.strip()]
        for s in stations:
            if s not in ids:
                raise params.error("hull stations", f"unknown station id in 'hull stations'; "
                                   f"valid ids are {ids}", s)
    else:
        hub_x = airframe.hardpoints.hub[0]
        nearest = int(np.argmin(np.abs(airframe.stations - hub_x)))
        picks = sorted({max(nearest - 3, 0), nearest, min(nearest + 3, len(ids) - 1)})
        stations = [ids[i] for i in picks]
    pairs = []
    for item in str(params("hull pairs") or "").split(","):
        if not item.strip():
            continue
        parts = [p.strip() for p in item.split("-")]
        if len(parts) != 2 or not all(p in COMPONENTS for p in parts):
            raise params.error("hull pairs", f"each hull pair is two of {list(COMPONENTS)} "
                               "joined by '-', e.g. 'Vy-Mz'", item.strip())
        pairs.append(tuple(parts))
    if not pairs and params("hull pairs"):
        raise params.error("hull pairs", "no hull pair given (e.g. 'Vy-Mz, Vz-My', or leave "
                           "the cell empty for none)")
    return ReportOptions(
        hull_stations=stations, hull_pairs=pairs,
        hook_angle_justification=str(params("hook angle justification") or "").strip(),
        previous_envelope_source=str(params("previous envelope source") or "").strip(),
        sfbm_workbook=bool(params("SFBM workbook")), **_nastran_options(params, study))


_NASTRAN_IDS = {"first_grid_id": "nastran first grid id",
                "first_element_id": "nastran first element id",
                "load_id_base": "nastran load id base", "first_subcase": "nastran first subcase"}


def _nastran_options(params, study):
    """The Study rows 'nastran ...', checked at their cells: ``nastran`` (write the file),
    ``nastran_settings`` (options of :func:`~slingloads.io.loads.nastran.prepare_nastran`)
    and ``nastran_locations`` (the cell of each option and of each listed case id, for the
    errors found when the file is laid out)."""
    settings = {"inertia_relief": params.choice("nastran inertia relief", CHOICES),
                "hook_at": params.choice("nastran hook load at", CHOICES),
                "axes": str(params("nastran model axes") or "").strip(),
                "offset": tuple(float(params(f"nastran offset {a}")) for a in "xyz")}
    with located(params, default="nastran model axes"):
        ModelAxes(settings["axes"])
    for arg, name in _NASTRAN_IDS.items():
        value = params(name)
        smallest = 0 if arg == "load_id_base" else 1
        params.check(name, smallest <= value <= MAX_ID,
                     f"{name!r} must be a whole number from {smallest} to {MAX_ID:,}")
        settings[arg] = int(value)
    names = {"axes": "nastran model axes", "offset": "nastran offset x",
             "inertia_relief": "nastran inertia relief", "hook_at": "nastran hook load at",
             **_NASTRAN_IDS}
    locations = {arg: {"sheet": STUDY_SHEET, "cell": params.where(name), "name": name,
                       "value": params.raw(name), "unit": params.unit(name)}
                 for arg, name in names.items()}
    reader = params.reader
    if study.inputs.loads is not None and reader.has_sheet("LoadCases"):
        t = reader.table(_SPEC["LoadCases"])
        locations.update({("case", str(t["id"][i])): {"sheet": t.sheet,
                                                      "cell": t.cell("id", i)}
                          for i in range(len(t))})
    return {"nastran": bool(params("nastran bulk data")), "nastran_settings": settings,
            "nastran_locations": locations}


def locate(err, study, context=None):
    """``err``, raised while the loads of ``study`` ran: an error of the campaign's hand-off
    (``context`` :data:`~slingloads.runs.loads.HANDOFF`) on the Study sheet (the 'campaign
    ...' rows); any other error unchanged."""
    return place_error(err, Place(study.path, STUDY_SHEET)) if context == HANDOFF else err

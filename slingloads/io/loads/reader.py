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

from slingloads.analyses.hook_loads import CONE_SHAPES, HookLoadOptions, horizontal_basis
from slingloads.analyses.loads import AeroEnvelope, FlightCondition, ListedCase, LoadsStudy
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.errors import InputError
from slingloads.io.airframe.reader import (
    PARACHUTE_PARAMETERS,
    read_fin_aero,
    read_fuselage_aero,
    read_parachute,
)
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.io.common.workbook import check_unique, located
from slingloads.io.loads.schema import SHEETS
from slingloads.models.attitude import ATTITUDE_SOURCES, Attitude, resolve_attitude

_SPEC = {s.name: s for s in SHEETS}


def read(reader, params, study):
    """Build the :class:`~slingloads.analyses.loads.LoadsStudy` of the workbook.

    Parameters
    ----------
    reader : WorkbookReader
    params : StudyParameters
        Study-sheet parameters (SI, with defaults).
    study : WorkbookStudy
        The airframe and the hardpoints by kind already read.

    Returns
    -------
    LoadsStudy

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule.
    """
    airframe, refs = study.airframe, study.points
    parachute = envelope = None
    fuselage = read_fuselage_aero(reader, params, refs)
    fin = read_fin_aero(reader, params, refs)
    chute_area = params.positive("parachute area", allow_zero=True)
    if chute_area > 0:
        if refs["chute"] is None:
            raise params.error("parachute area", "a parachute area is given but the "
                               "Hardpoints sheet has no row of kind 'chute'", chute_area)
        parachute = read_parachute(reader, params, chute_area, _PARACHUTE_PARAMETERS)
    if reader.has_sheet("AeroEnvelope"):
        t = reader.table(_SPEC["AeroEnvelope"])
        check_unique(reader, t, "id")
        envelope = AeroEnvelope(tuple(t["id"]), t["alpha"], t["beta"])
        _check_envelope_in_tables(reader, t, fuselage, fin)
    listed = ()
    if reader.has_sheet("LoadCases"):
        t = reader.table(_SPEC["LoadCases"])
        check_unique(reader, t, "id")
        listed = tuple(ListedCase(t["id"][i], t["hook"][i].upper(), t["aero"][i],
                                  t["chute"][i], t["description"][i] if t.has("description")
                                  else "") for i in range(len(t)))
    previous = _previous(reader) if reader.has_sheet("PreviousEnvelope") else None
    hook = _hook_options(reader, params)
    with located(reader.file, STUDY_SHEET):
        flight = FlightCondition(params("airspeed EAS"), params("density altitude"))
    attitude = _attitude(reader, params, airframe)
    line = str(params("parachute line direction")).strip().lower()
    with located(reader.file, "LoadCases" if listed else STUDY_SHEET):
        return LoadsStudy(airframe, flight, hook, envelope, fuselage, fin, parachute,
                          chute_line=line, attitude=attitude,
                          generate=params("generate case matrix"),
                          listed=listed, previous_envelope=previous,
                          ultimate_factor=params("ultimate factor"),
                          name=str(params("study name")))


def _hook_options(reader, params):
    """HookLoadOptions from the Study rows, each bad value located at its own cell."""
    names = {"nz": "hook load factor Nz", "angle": "hook angle from vertical",
             "lateral_angle": "hook lateral angle", "n_azimuth": "hook azimuths",
             "include_vertical": "hook vertical case", "towed": "towed equilibrium cases"}
    kwargs = {arg: params(name) for arg, name in names.items()}
    if kwargs["lateral_angle"] == 0:
        kwargs["lateral_angle"] = None  # 0: the same as 'hook angle from vertical'
    kwargs["cone"] = params.choice("hook cone shape", CONE_SHAPES)
    for arg, name in names.items():
        with located(reader.file, STUDY_SHEET, params.where(name)):
            HookLoadOptions(**{arg: kwargs[arg]})
    with located(reader.file, STUDY_SHEET, params.where("hook azimuths")):
        return HookLoadOptions(**kwargs)


def _attitude(reader, params, airframe):
    """'hanging', 'mast vertical' or the Attitude given by 'attitude pitch' and 'roll'."""
    source = params.choice("attitude", (*ATTITUDE_SOURCES, "given"))
    angles = {name: params(name) for name in ("attitude pitch", "attitude roll")}
    if source != "given":
        for name, value in angles.items():
            params.check(name, value == 0, f"{name!r} is used only with 'attitude' = given; "
                         f"leave it 0 with {source!r}")
        with located(reader.file, STUDY_SHEET, params.where("attitude")):
            return resolve_attitude(source, airframe)
    for name, value in angles.items():
        with located(reader.file, STUDY_SHEET, params.where(name)):
            Attitude(**{name.split()[1]: value})
    with located(reader.file, STUDY_SHEET, params.where("attitude")):
        attitude = Attitude(angles["attitude pitch"], angles["attitude roll"])
        horizontal_basis(attitude.vertical)
    return attitude


_PARACHUTE_PARAMETERS = {**PARACHUTE_PARAMETERS, "parachute opening factor": "opening_factor"}


def _check_envelope_in_tables(reader, t, fuselage, fin):
    """Each envelope point must lie inside the aerodynamic tables (no extrapolation)."""
    for i in range(len(t)):
        if fuselage is not None:
            with located(reader.file, t.sheet, t.cell("alpha", i)):
                fuselage.airframe_coefficients(t["alpha"][i], t["beta"][i])
        if fin is not None:
            with located(reader.file, t.sheet, t.cell("beta", i)):
                fin.force(t["beta"][i], 0.0)


def _previous(reader):
    t = reader.table(_SPEC["PreviousEnvelope"])
    x = t["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            raise reader.error("previous envelope stations must be sorted by increasing x "
                               "without repeats", t.written("x", i), t.sheet, t.cell("x", i))
    rows = []
    for name in COMPONENTS:
        lo, hi = t[f"{name} min"], t[f"{name} max"]
        for i in range(len(x)):
            if lo[i] > hi[i]:
                raise reader.error(f"previous envelope: {name} min must not exceed {name} max "
                                   f"({t.written(f'{name} max', i)})",
                                   t.written(f"{name} min", i), t.sheet,
                                   t.cell(f"{name} min", i))
        rows.append(pd.DataFrame({"x [m]": x, "component": name, "min": lo, "max": hi}))
    return pd.concat(rows, ignore_index=True)


def report_options(params, study):
    """The report options of the loads, checked for every workbook: the stations and
    component pairs of the 2-D envelopes ('hull stations', 'hull pairs'), and the texts the
    Summary quotes ('hook angle justification', 'previous envelope source').

    Returns
    -------
    dict
        ``{"hull stations": [station id, ...], "hull pairs": [(component, component), ...],
        "hook angle justification": str, "previous envelope source": str,
        "sfbm workbook": bool}``
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
        raise InputError("no hull pair given")
    return {"hull stations": stations, "hull pairs": pairs,
            "hook angle justification": str(params("hook angle justification") or "").strip(),
            "previous envelope source": str(params("previous envelope source") or "").strip(),
            "sfbm workbook": bool(params("SFBM workbook"))}

"""Build the analyses' inputs from an input workbook (see :mod:`slingloads.io.common.schema`)."""

from __future__ import annotations

import hashlib
import importlib
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import AeroEnvelope, FlightCondition, ListedCase, LoadsStudy
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.errors import InputError
from slingloads.io.common.schema import STUDY_SHEET, all_parameters, all_sheets
from slingloads.io.common.units import si_factor
from slingloads.io.common.workbook import WorkbookReader, located
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import Fin, FuselageAero
from slingloads.models.airframe import Airframe, Hardpoints, MassItems, check_inside
from slingloads.models.parachute import Parachute

HARDPOINT_KINDS = ("hub", "mast_foot", "chute", "fin_cp", "aero_reference")


@dataclass
class WorkbookStudy:
    """Everything read from one input workbook.

    Attributes
    ----------
    name : str
    path : str
    sha256 : str
        Digest of the input file, printed on the reports.
    run : dict
        Which analyses the workbook asks for (``loads``, ``lateral``, ``chute sizing``).
    loads : LoadsStudy or None
    airframe : Airframe
    options : dict
        Report options (hull stations and pairs).
    extra : dict
        Inputs of the other analyses, by analysis name.
    points : dict
        Hardpoints by kind that the Airframe does not keep (``fin_cp``, ``aero_reference``:
        position or None). [m]
    """

    name: str
    path: str
    sha256: str
    run: dict
    loads: LoadsStudy | None
    airframe: Airframe
    parameters: dict
    options: dict = field(default_factory=dict)
    extra: dict = field(default_factory=dict)

    def digest(self):
        """What a report is computed from: input file, SHA-256, study, analyses, version."""
        from pathlib import Path

        from slingloads import __version__

        return {"input workbook": Path(self.path).name, "SHA-256": self.sha256,
                "study": self.name,
                "analyses": ", ".join(k for k, v in self.run.items() if v),
                "slingloads version": __version__}
    points: dict = field(default_factory=dict)


class _Params:
    """Study-sheet parameters with defaults, in SI, and their cells."""

    def __init__(self, reader):
        self.reader = reader
        self.given = reader.parameters()
        self.specs = all_parameters()

    def __call__(self, name):
        key = name.lower()
        if key in self.given:
            return self.given[key][0]
        spec = self.specs[key]
        if spec.kind in ("text", "flag", "integer"):
            value = spec.default
            if spec.kind == "flag":
                return str(value).lower() in ("yes", "true", "1")
            return value
        return spec.default * si_factor(spec.unit, spec.kind)

    def cell(self, name):
        got = self.given.get(name.lower())
        return got[1] if got else None

    def error(self, name, rule, value):
        return self.reader.error(rule, value, STUDY_SHEET, self.cell(name) or "(default)")

    def positive(self, name, allow_zero=False):
        value = self(name)
        if not np.isfinite(value) or value < 0 or (value == 0 and not allow_zero):
            raise self.error(name, f"{name!r} must be {'>= 0' if allow_zero else '> 0'}",
                             value)
        return value


def file_digest(path):
    """SHA-256 of a file, hex."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_study(path, only=None):
    """Read an input workbook and build every analysis it asks for.

    Parameters
    ----------
    path : str or Path
    only : iterable of str, optional
        Build these analyses (``"loads"``, ``"lateral"``, ``"chute sizing"``) whatever the
        workbook's ``run ...`` parameters say.

    Returns
    -------
    WorkbookStudy

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule, for any bad input.
    """
    reader = WorkbookReader(path)
    params = _Params(reader)
    sheets = all_sheets()
    run = {"loads": params("run loads"), "lateral": params("run lateral"),
           "chute sizing": params("run chute sizing")}
    if only is not None:
        run = {name: name in set(only) for name in run}
    airframe, refs = _airframe(reader, params, sheets)
    loads = _loads_study(reader, params, sheets, airframe, refs) if run["loads"] else None
    study = WorkbookStudy(name=str(params("study name")), path=str(path),
                          sha256=file_digest(path), run=run, loads=loads, airframe=airframe,
                          parameters={k: v[0] for k, v in params.given.items()},
                          options=_report_options(params, airframe), points=refs)
    for name, module in EXTRA_READERS.items():
        if run.get(name):
            study.extra[name] = importlib.import_module(module).read(reader, params, study)
    return study


#: Modules that build the other analyses' inputs, by analysis name; each has a function
#: ``read(reader, params, study) -> inputs`` (``params(name)`` gives a Study-sheet parameter
#: in SI with its default; ``params.cell(name)`` its cell; ``reader.table(spec)`` a table).
EXTRA_READERS = {"lateral": "slingloads.io.lateral.reader",
                 "chute sizing": "slingloads.io.chute.reader"}


def _airframe(reader, params, sheets):
    items_t = reader.table(sheets["MassItems"])
    _unique(reader, items_t, "id")
    masses = items_t["mass"]
    for i, m in enumerate(masses):
        if m <= 0:
            raise reader.error("mass must be > 0",
                               float(m / si_factor(items_t.units["mass"], "mass")),
                               items_t.sheet, items_t.cell("mass", i))
    inertia = np.zeros((len(masses), 3, 3))
    for (a, b), name in {(0, 0): "Ixx", (1, 1): "Iyy", (2, 2): "Izz", (0, 1): "Ixy",
                         (0, 2): "Ixz", (1, 2): "Iyz"}.items():
        if items_t.has(name):
            inertia[:, a, b] = inertia[:, b, a] = items_t[name]
    position = np.column_stack([items_t["x"], items_t["y"], items_t["z"]])
    with located(reader.file, items_t.sheet):
        items = MassItems(tuple(items_t["id"]), masses, position, inertia,
                          tuple(items_t["description"]) if items_t.has("description") else ())
    st = reader.table(sheets["Stations"])
    _unique(reader, st, "id")
    x = st["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            rule = ("cut stations must not repeat" if x[i] == x[i - 1]
                    else "cut stations must be sorted by increasing x")
            raise reader.error(rule, float(x[i] / si_factor(st.units["x"], "length")),
                               st.sheet, st.cell("x", i))
    axis = (params("reference axis y"), params("reference axis z"))
    hp_t = reader.table(sheets["Hardpoints"])
    _unique(reader, hp_t, "id")
    points = {k: [] for k in HARDPOINT_KINDS}
    for i, kind in enumerate(hp_t["kind"]):
        k = kind.strip().lower()
        if k not in HARDPOINT_KINDS:
            raise reader.error(f"unknown hardpoint kind; valid kinds are "
                               f"{list(HARDPOINT_KINDS)}", kind, hp_t.sheet,
                               hp_t.cell("kind", i))
        p = np.array([hp_t["x"][i], hp_t["y"][i], hp_t["z"][i]])
        if k != "aero_reference":
            with located(reader.file, hp_t.sheet, hp_t.cell("x", i)):
                check_inside(items, axis, f"{hp_t['id'][i]!r}", p)
        w = hp_t["weight"][i] if hp_t.has("weight") else 1.0
        if not w > 0:
            raise reader.error("hardpoint weight must be > 0", float(w), hp_t.sheet,
                               hp_t.cell("weight", i))
        points[k].append((hp_t["id"][i], p, w, i))
    for kind, lo, hi in (("hub", 1, 1), ("mast_foot", 1, None), ("chute", 0, 1),
                         ("fin_cp", 0, 1), ("aero_reference", 0, 1)):
        n = len(points[kind])
        if n < lo or (hi is not None and n > hi):
            want = f"exactly {lo}" if lo == hi else (f"at least {lo}" if hi is None
                                                    else f"at most {hi}")
            raise reader.error(f"the Hardpoints sheet needs {want} row(s) of kind {kind!r}",
                               n, hp_t.sheet, "B1")
    mast = np.array([params("mast axis x"), params("mast axis y"), params("mast axis z")])
    aero_points = aero_weights = None
    if reader.has_sheet("AeroPoints"):
        ap = reader.table(sheets["AeroPoints"])
        aero_points, aero_weights = ap["x"], ap["weight"]
        for i, (xa, wa) in enumerate(zip(aero_points, aero_weights, strict=True)):
            if not wa > 0:
                raise reader.error("aerodynamic share weight must be > 0", float(wa), ap.sheet,
                                   ap.cell("weight", i))
            with located(reader.file, ap.sheet, ap.cell("x", i)):
                check_inside(items, axis, f"aerodynamic point {i + 1}",
                             np.array([xa, axis[0], axis[1]]))
    with located(reader.file, hp_t.sheet):
        hardpoints = Hardpoints(
            hub=points["hub"][0][1],
            mast_feet=np.array([p[1] for p in points["mast_foot"]]),
            mast_weights=np.array([p[2] for p in points["mast_foot"]]),
            mast_axis=mast,
            chute=points["chute"][0][1] if points["chute"] else None,
            mast_feet_ids=tuple(p[0] for p in points["mast_foot"]),
        )
    with located(reader.file, st.sheet):
        airframe = Airframe(items, x, hardpoints, axis, tuple(st["id"]), aero_points,
                            aero_weights, name=str(params("study name")))
    refs = {k: (v[0][1] if v else None) for k, v in points.items()}
    refs["chute_row"] = points["chute"][0][3] if points["chute"] else None
    return airframe, refs


def _unique(reader, table, column):
    seen = {}
    for i, value in enumerate(table[column]):
        if value in seen:
            raise reader.error(f"duplicate {column} (first at {table.cell(column, seen[value])})",
                               value, table.sheet, table.cell(column, i))
        seen[value] = i


def read_fuselage_aero(reader, params, refs, sheets=None):
    """The FuselageAero sheet with its reference area, length and point, or None if absent.

    Parameters
    ----------
    reader : WorkbookReader
    params : _Params
        Study-sheet parameters ('fuselage reference area', 'fuselage reference length').
    refs : dict
        Hardpoints by kind (``refs["aero_reference"]``: moment reference point [m]).

    Returns
    -------
    FuselageAero or None
    """
    sheets = all_sheets() if sheets is None else sheets
    if not reader.has_sheet("FuselageAero"):
        return None
    t = reader.table(sheets["FuselageAero"])
    if refs["aero_reference"] is None:
        raise reader.error("the FuselageAero sheet needs a Hardpoints row of kind "
                           "'aero_reference' (moment reference point)", sheet="Hardpoints")
    area = params.positive("fuselage reference area")
    length = params.positive("fuselage reference length")
    with located(reader.file, t.sheet):
        table = Table2D.from_long(t["alpha"], t["beta"],
                                  {c: t[c] for c in ("CD", "CY", "CL", "Cl", "Cm", "Cn")})
        return FuselageAero(table, area, length, refs["aero_reference"])


def read_fin_aero(reader, params, refs, sheets=None):
    """The FinAero sheet with 'fin area', 'fin efficiency' and the fin_cp hardpoint, or None.

    Returns
    -------
    Fin or None
    """
    sheets = all_sheets() if sheets is None else sheets
    if not reader.has_sheet("FinAero"):
        return None
    t = reader.table(sheets["FinAero"])
    if refs["fin_cp"] is None:
        raise reader.error("the FinAero sheet needs a Hardpoints row of kind 'fin_cp'",
                           sheet="Hardpoints")
    area = params.positive("fin area")
    eff = params("fin efficiency")
    with located(reader.file, t.sheet):
        table = Table1D(t["beta"], {"CY": t["CY"]}, angle_name="beta", what="fin")
    with located(reader.file, STUDY_SHEET, params.cell("fin efficiency")):
        return Fin(table, area, refs["fin_cp"], eff)


def read_parachute_cd(reader, sheets=None):
    """The optional ParachuteCD sheet as a table, or None (the paper's CD is then used).

    Returns
    -------
    Table1D or None
    """
    sheets = all_sheets() if sheets is None else sheets
    if not reader.has_sheet("ParachuteCD"):
        return None
    t = reader.table(sheets["ParachuteCD"])
    with located(reader.file, t.sheet):
        return Table1D(t["alpha"], {"CD": t["CD"]}, angle_name="alpha", what="parachute")


def _loads_study(reader, params, sheets, airframe, refs):
    parachute = envelope = None
    fuselage = read_fuselage_aero(reader, params, refs, sheets)
    fin = read_fin_aero(reader, params, refs, sheets)
    chute_area = params.positive("parachute area", allow_zero=True)
    if chute_area > 0:
        if refs["chute"] is None:
            raise params.error("parachute area", "a parachute area is given but the "
                               "Hardpoints sheet has no row of kind 'chute'", chute_area)
        cd = read_parachute_cd(reader, sheets)
        for name in ("parachute wake ratio", "parachute line length",
                     "parachute opening factor"):
            with located(reader.file, STUDY_SHEET, params.cell(name)):
                Parachute(chute_area, cd, **{_PARA_ARGS[name]: params(name)})
        with located(reader.file, "ParachuteCD" if cd is not None else STUDY_SHEET):
            parachute = Parachute(chute_area, cd, params("parachute wake ratio"),
                                  params("parachute line length"),
                                  params("parachute opening factor"))
    if reader.has_sheet("AeroEnvelope"):
        t = reader.table(sheets["AeroEnvelope"])
        _unique(reader, t, "id")
        envelope = AeroEnvelope(tuple(t["id"]), t["alpha"], t["beta"])
        _check_envelope_in_tables(reader, t, fuselage, fin)
    listed = ()
    if reader.has_sheet("LoadCases"):
        t = reader.table(sheets["LoadCases"])
        _unique(reader, t, "id")
        listed = tuple(ListedCase(t["id"][i], t["hook"][i].upper(), t["aero"][i],
                                  t["chute"][i], t["description"][i] if t.has("description")
                                  else "") for i in range(len(t)))
    previous = _previous(reader, sheets) if reader.has_sheet("PreviousEnvelope") else None
    with located(reader.file, STUDY_SHEET):
        hook = HookLoadOptions(params("hook load factor Nz"), params("hook angle from mast"),
                               params("hook azimuths"), params("hook along mast axis"))
        flight = FlightCondition(params("airspeed EAS"), params("density altitude"))
    line = str(params("parachute line direction")).strip().lower()
    with located(reader.file, "LoadCases" if listed else STUDY_SHEET):
        return LoadsStudy(airframe, flight, hook, envelope, fuselage, fin, parachute,
                          chute_line=line, generate=params("generate case matrix"),
                          listed=listed, previous_envelope=previous,
                          ultimate_factor=params("ultimate factor"),
                          name=str(params("study name")))


_PARA_ARGS = {"parachute wake ratio": "wake_ratio", "parachute line length": "line_length",
              "parachute opening factor": "opening_factor"}


def _check_envelope_in_tables(reader, t, fuselage, fin):
    """Each envelope point must lie inside the aerodynamic tables (no extrapolation)."""
    for i in range(len(t)):
        if fuselage is not None:
            with located(reader.file, t.sheet, t.cell("alpha", i)):
                fuselage.table("CD", t["alpha"][i], t["beta"][i])
        if fin is not None:
            with located(reader.file, t.sheet, t.cell("beta", i)):
                fin.table("CY", t["beta"][i])


def _previous(reader, sheets):
    t = reader.table(sheets["PreviousEnvelope"])
    x = t["x"]
    for i in range(1, len(x)):
        if x[i] <= x[i - 1]:
            raise reader.error("previous envelope stations must be sorted by increasing x "
                               "without repeats", float(x[i]), t.sheet, t.cell("x", i))
    rows = []
    for name in COMPONENTS:
        lo, hi = t[f"{name} min"], t[f"{name} max"]
        for i in range(len(x)):
            if lo[i] > hi[i]:
                raise reader.error(f"previous envelope: {name} min must not exceed {name} max",
                                   float(lo[i]), t.sheet, t.cell(f"{name} min", i))
        rows.append(pd.DataFrame({"x [m]": x, "component": name, "min": lo, "max": hi}))
    return pd.concat(rows, ignore_index=True)


def _report_options(params, airframe):
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
    return {"hull stations": stations, "hull pairs": pairs}

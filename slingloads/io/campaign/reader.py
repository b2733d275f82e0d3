"""Build the campaign from an input workbook (``run campaign = yes``).

Called through the registry (:mod:`slingloads.io.analyses`) as ``read(reader, params, study)``.
The towed system is built from the airframe: the mass items' mass, CG and inertia
(:meth:`RigidBody.from_mass_items`), the hardpoints (hub, parachute attachment, mast axis), the
``FuselageAero`` and ``FinAero`` tables with their reference values, and the parachute (wake
ratio, line length, ``ParachuteCD``: without that sheet the GENERIC extended CD table of
:func:`~slingloads.models.parachute.extended_cd_table` is used, since runs from hover meet the
canopy at any angle). The cable, canopy mass and free carrier come from the ``campaign ...``
Study rows; the matrix from the list rows, the ``CampaignMasses`` sheet, or the
``CampaignRuns`` sheet. Every value is SI after reading; every bad value raises
:class:`~slingloads.errors.InputError` naming the file, sheet, cell, value and rule.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from slingloads.io.airframe.reader import (
    parachute_reach_rule,
    read_fin_aero,
    read_fuselage_aero,
    read_parachute,
)
from slingloads.io.campaign.rows import (
    CHOICES,
    check_helicopters,
    check_scheduler,
    gust_ramps,
    list_parameter,
)
from slingloads.io.campaign.schema import SHEETS
from slingloads.io.common.locate import Place, located, place_error
from slingloads.io.common.schema import STUDY_SHEET
from slingloads.limits import (
    MAX_CAMPAIGN_RUN_STEPS,
    MAX_CAMPAIGN_RUNS,
    MAX_CAMPAIGN_SAMPLES,
    MAX_MAP_POINTS,
    MEMORY_BUDGET,
)
from slingloads.models.yaw_dynamics import YAW_AXES
from slingloads.runs.campaign import SCHEDULER, CampaignInputs

ANALYSIS = "campaign"
_SPEC = {s.name: s for s in SHEETS}


def _sizing_fit_range(params):
    """The parachute sizing's linearisation range (its Study row, checked by its reader), so
    that the campaign's neutral area is the sizing's. [rad]"""
    half = float(params("chute sizing linearisation range"))
    return (-half, half)


def read_system(reader, params, study):
    """The towed system of the workbook (module notes), with the parachute area the study flies
    (:func:`base_parachute_area`; each run replaces it) and the first listed cable length.

    Returns
    -------
    SlingSystem
    """
    from slingloads.models.multibody import Cable, HingedParachute, LiftingSurface, RigidBody
    from slingloads.models.multibody.system import SlingSystem
    from slingloads.models.parachute import extended_cd_table

    file = reader.file
    airframe = study.airframe
    if airframe.hardpoints.chute is None:
        raise reader.error("the campaign needs a Hardpoints row of kind 'chute' (the parachute "
                           "attachment)", sheet="Hardpoints", cell="B1")
    fuselage = read_fuselage_aero(reader, params, study.source.points)
    fin = read_fin_aero(reader, params, study.source.points)
    if fuselage is None and fin is None:
        raise reader.error("the campaign needs a FuselageAero or a FinAero sheet",
                           sheet="FuselageAero")
    chute = read_parachute(reader, params, base_parachute_area(params))
    if not reader.has_sheet("ParachuteCD"):
        chute = replace(chute, cd=extended_cd_table())
    with located(params, default="campaign canopy mass"):
        holder = HingedParachute(chute, params("campaign canopy mass"))
    with located(Place(file, "MassItems")):
        body = RigidBody.from_mass_items(airframe.mass_items)
    lengths = list_parameter(params, "campaign cable lengths")
    for length in lengths:  # each checked at the list's cell, in the list's unit
        rule = parachute_reach_rule(reader, params, study.source.points, airframe.hardpoints,
                                    chute.line_length, length,
                                    params.unit("campaign cable lengths"))
        if rule is not None:
            raise params.error("campaign cable lengths", rule)
    length = lengths[0]
    with located(params, default="campaign cable EA"):
        cable = Cable(length if length > 0 else 1.0, params("campaign cable EA"),
                      params("campaign cable damping ratio"))
    surfaces = () if fin is None else (LiftingSurface.from_fin(fin),)
    with located(params, default="campaign cable lengths"):
        return SlingSystem(body, airframe.hardpoints, cable, fuselage, surfaces, holder,
                           name=str(params("study name")))


def base_parachute_area(params):
    """The parachute area of the campaign's base system: the one its towed trim (the attitude
    of the campaign's 1-DOF yaw model and neutral area) is flown with. The multibody model's
    ('multibody parachute area', else the Study's 'parachute area'), as the parachute sizing's
    trim flies it, so that both analyses read the neutral area at one attitude; 1 m^2 when
    neither is given (the campaign's Summary states the area beside the neutral area). [m^2]"""
    for name in ("multibody parachute area", "parachute area"):
        area = params.positive(name, allow_zero=True)
        if area > 0:
            return float(area)
    return 1.0


def _masses(reader):
    from slingloads.analyses.campaign import MassCase

    if not reader.has_sheet("CampaignMasses"):
        return ()
    t = reader.table(_SPEC["CampaignMasses"])
    out = []
    for i in range(len(t)):
        with located(t, default="mass", index=i):
            out.append(MassCase(t["mass case"][i], t["mass"][i]))
    return tuple(out)


def _rows(reader, params, study, system, masses):
    """The CampaignRuns sheet as listed rows, each bad value located at its cell."""
    from slingloads.analyses.campaign import CARRIERS, MANOEUVRES

    t = reader.table(_SPEC["CampaignRuns"])
    names = [m.name for m in masses] or ["nominal"]
    for i in range(len(t)):
        for column in ("area factor", "airspeed EAS", "cable length"):
            if not t[column][i] > 0:
                raise t.error(column, i, f"{column} must be > 0")
        rule = parachute_reach_rule(reader, params, study.source.points, study.airframe.hardpoints,
                                    system.parachute.parachute.line_length,
                                    t["cable length"][i], t.units.get("cable length"))
        if rule is not None:
            raise t.error("cable length", i, rule)
        checks = (("carrier", list(CARRIERS), str.lower), ("manoeuvre", list(MANOEUVRES), str))
        for column, valid, norm in checks:
            if norm(t[column][i]) not in valid:
                raise t.error(column, i, f"unknown {column}; valid values are {valid}")
        if t.has("mass case"):
            case = t["mass case"][i] or (names[0] if len(names) == 1 else "")
            if case not in names:
                raise reader.error(f"unknown mass case; valid mass cases (CampaignMasses) are "
                                   f"{names}", t["mass case"][i], t.sheet,
                                   t.cell("mass case", i))
    frame = pd.DataFrame({
        "area factor [-]": t["area factor"], "airspeed EAS [m/s]": t["airspeed EAS"],
        "mass case": ([c or names[0] for c in t["mass case"]] if t.has("mass case")
                      else names[0]),
        "density altitude [m]": t["density altitude"], "cable length [m]": t["cable length"],
        "carrier": [c.lower() for c in t["carrier"]], "manoeuvre": t["manoeuvre"]})
    return frame, t


def read(reader, params, study):
    """Build :class:`CampaignInputs` from the workbook.

    Raises
    ------
    InputError
        With the file, sheet, cell, value and rule.
    """
    from slingloads.analyses.campaign import (
        Campaign,
        CampaignSetup,
        Factors,
        NoParachuteStudy,
        RunSettings,
        SelectionCriteria,
        sample_full_tail_system,
    )
    from slingloads.models.multibody.carrier import FreeCarrier

    file = reader.file


    system = read_system(reader, params, study)
    with located(params, default="campaign carrier mass"):
        carrier = FreeCarrier(params("campaign carrier mass"),
                              params("campaign carrier drag area"))
    setup = CampaignSetup(system, carrier)
    masses = _masses(reader)
    lists = {}
    for name, field in (("campaign area factors", "area_factors"),
                        ("campaign airspeeds EAS", "airspeeds"),
                        ("campaign density altitudes", "density_altitudes"),
                        ("campaign cable lengths", "cable_lengths"),
                        ("campaign carriers", "carriers"),
                        ("campaign manoeuvres", "manoeuvres")):
        values = list_parameter(params, name)
        if field == "carriers":
            values = [v.lower() for v in values]
        with located(params, default=name):
            Factors(**{field: tuple(values)})  # each list checked at its own cell
        lists[field] = tuple(values)
    factors = Factors(masses=masses, **lists)
    kind = params.choice("campaign matrix", CHOICES)
    no_chute_runs = _no_parachute_runs(params)
    if kind == "full factorial":
        _check_matrix_size(params, factors, len(masses), no_chute_runs)
    with located(params, default="campaign cable lengths"):
        for length in factors.cable_lengths:
            system.with_(cable=replace(system.cable, length=length))
    rows, sheet = None, STUDY_SHEET
    if kind == "listed rows":
        if not reader.has_sheet("CampaignRuns"):
            raise params.error("campaign matrix", "'campaign matrix' = listed rows needs the "
                               "CampaignRuns sheet", "listed rows")
        rows, table = _rows(reader, params, study, system, masses)
        sheet = table.sheet
        lengths = rows["cable length [m]"].to_numpy()
        for length in np.unique(lengths):  # each at the first row that gives it
            first = int(np.flatnonzero(lengths == length)[0])
            with located(table, default="cable length", index=first):
                system.with_(cable=replace(system.cable, length=float(length)))
    with located(params, default="campaign run length"):
        step = params("campaign time step")
        params.check("campaign time step", step >= 0, "'campaign time step' must be >= 0 "
                     "(0: adaptive)")
        settings = RunSettings(params("campaign run length"), step if step > 0 else None,
                               params("campaign output interval"))
    with located(params, default="campaign minimum yaw damping"):
        criteria = SelectionCriteria(params("campaign minimum yaw damping"),
                                     params("campaign maximum yaw half time"))
    runs = (len(rows) if rows is not None else factors.size) + no_chute_runs
    _check_work(params, runs, settings)
    n_areas = params("campaign stability map areas")
    params.check("campaign stability map areas", n_areas >= 2,
                 "'campaign stability map areas' must be >= 2")
    n_speeds = params("campaign stability map airspeeds")
    params.check("campaign stability map airspeeds", n_speeds >= 1,
                 "'campaign stability map airspeeds' must be >= 1")
    altitudes = (len(set(rows["density altitude [m]"])) if rows is not None
                 else len(factors.density_altitudes))
    points = altitudes * n_areas * n_speeds
    params.check("campaign stability map areas", points <= MAX_MAP_POINTS,
                 f"too much work: the stability map asks for {points:,} points (density "
                 f"altitudes {altitudes} x areas {n_areas} x airspeeds {n_speeds}), more than "
                 f"the {MAX_MAP_POINTS:,} allowed (limits of slingloads)")
    chosen = params.positive("campaign chosen area factor", allow_zero=True)
    margin = params("campaign loads margin")
    params.check("campaign loads margin", np.isfinite(margin) and margin >= 1,
                 "'campaign loads margin' must be >= 1")
    no_chute = _no_parachute(params, system, NoParachuteStudy, sample_full_tail_system)
    _check_needs_parachute(params, system, rows, factors)
    with located(Place(file, sheet)):
        campaign = Campaign(setup, factors, rows, settings, criteria, margin,
                            _map(factors, rows, n_areas, n_speeds), no_chute,
                            chosen or None, name=str(params("study name")),
                            neutral_fit_range=_sizing_fit_range(params),
                            yaw_axis=params.choice("chute sizing yaw axis", YAW_AXES))
    listed = sorted(float(f) for f in campaign.matrix.frame["area factor [-]"].unique())
    if chosen and not np.any(np.isclose(listed, chosen)):
        raise params.error("campaign chosen area factor", "the chosen area factor must be one "
                           f"of the matrix's area factors {listed}")
    workers = params("campaign workers")
    params.check("campaign workers", workers >= 0, "'campaign workers' must be >= 0")
    scheduler = check_scheduler(params)
    return CampaignInputs(
        campaign, scheduler, workers or None,
        params.positive("campaign scheduler time-out"), params("campaign loads from dynamics"),
        params.choice("campaign loads hook angle", CHOICES),
        params.where("campaign scheduler"))


def _check_needs_parachute(params, system, rows, factors):
    """The campaign sizes a parachute: fuselage and fin must not be statically stable in yaw
    on their own (a positive neutral area), blamed on the fin area, the value to change."""
    from slingloads.analyses.campaign import neutral_area_of

    speeds = rows["airspeed EAS [m/s]"] if rows is not None else factors.airspeeds
    with located(params, default="fin area"):
        neutral = neutral_area_of(system, float(np.max(np.asarray(speeds, float))),
                                  axis=params.choice("chute sizing yaw axis", YAW_AXES))
    if neutral.already_stable:
        raise params.error("fin area", "fuselage and fin are already statically stable in yaw "
                           f"(neutral parachute area {neutral.area:.4g} m^2, not positive): "
                           "there is no parachute to size; check 'fin area', FinAero and "
                           "FuselageAero")


def _no_parachute_runs(params):
    """Runs of the study without parachute (helicopters x (ramps + ramps with a gust)), from
    the list cells."""
    helicopters = list_parameter(params, "campaign no-parachute helicopters")
    if [h.upper() for h in helicopters] == ["NONE"]:
        return 0
    return len(set(h.upper() for h in helicopters)) * (
        len(list_parameter(params, "campaign no-parachute ramps"))
        + len(gust_ramps(params)))


def _check_matrix_size(params, factors, masses, no_chute_runs):
    """The full factorial stays within MAX_CAMPAIGN_RUNS (before any run is built)."""
    lists = {"campaign area factors": len(factors.area_factors),
             "campaign airspeeds EAS": len(factors.airspeeds),
             "campaign density altitudes": len(factors.density_altitudes),
             "campaign cable lengths": len(factors.cable_lengths),
             "campaign carriers": len(factors.carriers),
             "campaign manoeuvres": len(factors.manoeuvres)}
    runs = factors.size + no_chute_runs
    if runs <= MAX_CAMPAIGN_RUNS:
        return
    longest = max(lists, key=lists.get)
    sizes = " x ".join(f"{n} {name.removeprefix('campaign ')}" for name, n in lists.items())
    raise params.error(longest, f"too much work: the campaign's matrix has {factors.size:,} "
                       f"runs ({sizes} x {max(masses, 1)} mass cases) and {no_chute_runs} "
                       f"without parachute, more than the {MAX_CAMPAIGN_RUNS:,} allowed "
                       "(limits of slingloads); shorten the longest list")


def _check_work(params, runs, settings):
    """Run-steps and stored samples of the campaign stay within the limits."""
    samples = runs * (round(settings.t_end / settings.output_interval) + 1)
    if settings.dt is not None:  # a fixed step; the adaptive one is not counted ahead
        steps = runs * round(settings.t_end / settings.dt)
        params.check("campaign time step", steps <= MAX_CAMPAIGN_RUN_STEPS,
                     f"too much work: {runs:,} runs of {settings.t_end:g} s at this step are "
                     f"{steps:,} steps, more than the {MAX_CAMPAIGN_RUN_STEPS:,} allowed "
                     "(limits of slingloads); use the adaptive step (0) or a longer one")
    params.check("campaign output interval", samples <= MAX_CAMPAIGN_SAMPLES,
                 f"too much work: {runs:,} runs of {settings.t_end:g} s sampled at this "
                 f"interval store {samples:,} samples, more than the {MAX_CAMPAIGN_SAMPLES:,} "
                 "allowed (limits of slingloads)")
    from slingloads.analyses.multibody.simulate import run_bytes

    one = run_bytes(settings.t_end, settings.output_interval)
    params.check("campaign output interval", one <= MEMORY_BUDGET,
                 f"too much memory: one run of {settings.t_end:g} s sampled at this interval "
                 f"needs about {one / 2**20:,.0f} MB, more than the "
                 f"{MEMORY_BUDGET / 2**20:,.0f} MB budget of a computation (limits of "
                 "slingloads; docs/inputs-and-outputs.md, Memory); use a longer interval")


def _no_parachute(params, system, study_type, sample):
    """The study without parachute of the Study rows, or None ('none')."""
    helicopters = check_helicopters(params)
    if helicopters == ["NONE"]:
        return None
    ramps = list_parameter(params, "campaign no-parachute ramps")
    with_gust = gust_ramps(params)
    with located(params, default="campaign no-parachute gust"):
        gust = params("campaign no-parachute gust")
    with located(params, default="campaign no-parachute ramps"):
        return study_type({h: sample(h, system.cable.length, system.cable.ea)
                           for h in dict.fromkeys(helicopters)}, ramps,
                          gust_targets=tuple(with_gust), gust_speed=gust)


def _in(params, name):
    return tuple(list_parameter(params, name))


def _map(factors, rows, n_areas, n_speeds):
    from slingloads.analyses.campaign import MapSettings

    if rows is not None:
        areas = rows["area factor [-]"].astype(float)
        speeds = rows["airspeed EAS [m/s]"].astype(float)
    else:
        areas, speeds = pd.Series(factors.area_factors), pd.Series(factors.airspeeds)
    a = np.linspace(0.5 * areas.min(), areas.max(), n_areas)  # below the matrix too
    v = np.linspace(speeds.min(), speeds.max(), n_speeds) if speeds.max() > speeds.min() else [
        speeds.min()]
    return MapSettings(tuple(a), tuple(v))


def locate(err, study, context=None):
    """``err``, raised while the campaign of ``study`` ran, put at its cell: an error
    reaching the workbook's own scheduler (``context`` :data:`~slingloads.runs.campaign.
    SCHEDULER`) at the 'campaign scheduler' cell, with the address as written; any other
    error unchanged."""
    if context != SCHEDULER:
        return err
    inputs = study.inputs.campaign
    written = study.source.written.get("campaign scheduler", (inputs.scheduler, None))[0]
    return place_error(err, Place(study.path, STUDY_SHEET, inputs.scheduler_cell, written))

"""The campaign: definition, execution and results (paper sections 4.4, 4.5, 5 and 6).

:class:`Campaign` gathers the base towed system and its free carrier
(:class:`~.setup.CampaignSetup`), the matrix (full factorial of :class:`~.matrix.Factors`, or
listed rows), the run settings, the selection criteria, the margin of the loads hand-off, the
stability-map grid and the study without parachute. :func:`run_campaign` executes it
(:mod:`.execution`: local processes or a Dask cluster, a store of finished runs) and returns a
:class:`CampaignResult`: the tidy metrics table (one row per run), the selection, the
sensitivity tables, the stability map, the 1.0 x neutral-area verdicts (1-DOF and multibody),
the speed limits without parachute and the envelope handed to the loads.

Method and choices: ``docs/campaign.md``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from slingloads.analyses.chute_sizing import FIT_RANGE, run_yaw
from slingloads.analyses.multibody import linearise, trim
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.gusts import standard_gusts
from slingloads.models.integration import SolverSettings
from slingloads.models.multibody.integrator import ATOL, RTOL

from .execution import MemoryStore, execute, make_executor
from .keys import KeyMaker
from .loads_envelope import MARGIN, dynamics_envelope
from .matrix import CONDITION_COLUMNS, MANOEUVRES, CampaignMatrix, Factors
from .metrics import HISTORY_LABELS, ordered
from .no_parachute import NoParachuteResult, NoParachuteStudy, ramp_verdict, speed_limits
from .selection import SelectionCriteria, condition_text, select_parachute
from .sensitivity import carrier_comparison, sensitivity_tables
from .setup import CampaignSetup, neutral_area_of, towed_trim_of, trim_text, yaw_model_of
from .stability_map import MapSettings, stability_map

#: Run length and step of the 1-DOF check of the neutral area (the sizing's defaults). [s]
ONE_DOF_TIME, ONE_DOF_STEP = 120.0, 0.1


@dataclass(frozen=True)
class RunSettings:
    """Length, step and sampling interval of every run of the matrix.

    Parameters
    ----------
    t_end : float
        (paper: 60 s) [s]
    dt : float or None
        Fixed step of the Dormand-Prince 5(4) integration; None (default): the adaptive step
        of the multibody model, each run's local error within ``rtol`` and ``atol``. [s]
    output_interval : float
        A whole multiple of ``dt`` when it is given. [s]
    rtol, atol : float
        Tolerances of the adaptive step, used when ``dt`` is None (the multibody defaults).
        [-], [SI]
    """

    t_end: float = 60.0
    dt: float | None = None
    output_interval: float = 0.1
    rtol: float = RTOL
    atol: float = ATOL

    def __post_init__(self):
        from slingloads.analyses.multibody.simulate import check_settings

        dt = None if self.dt is None else float(self.dt)
        check_settings(float(self.t_end), dt, float(self.output_interval), float(self.rtol),
                        float(self.atol))
        for name in ("t_end", "output_interval", "rtol", "atol"):
            object.__setattr__(self, name, float(getattr(self, name)))
        object.__setattr__(self, "dt", dt)

    def as_dict(self, t_end=None):
        """The settings as the keyword arguments of the runs.

        Parameters
        ----------
        t_end : float, optional
            Run length instead of the settings' own. [s]

        Returns
        -------
        dict
            ``t_end``, ``dt``, ``output_interval`` [s], ``rtol`` [-] and ``atol`` [SI], the keyword
            arguments of the multibody runs.
        """
        return {"t_end": self.t_end if t_end is None else float(t_end), "dt": self.dt,
                "output_interval": self.output_interval, "rtol": self.rtol,
                "atol": self.atol}


@dataclass(frozen=True, eq=False)
class Campaign:
    """Everything a campaign needs (module notes), SI.

    Parameters
    ----------
    setup : CampaignSetup
    factors : Factors
        The full-factorial matrix (ignored when ``rows`` is given).
    rows : pandas.DataFrame, optional
        Listed rows instead (columns of :data:`~.matrix.ROW_FACTORS`).
    settings : RunSettings
    criteria : SelectionCriteria
    margin : float
        Margin of the loads hand-off, >= 1. [-]
    stability : MapSettings or None
        Grid of the stability map (None: no map).
    no_parachute : NoParachuteStudy or None
    chosen_area_factor : float, optional
        The parachute handed to the loads (default: the recommended, else the smallest
        stable). [-]
    neutral_airspeed : float, optional
        Airspeed of the neutral-area sizing (default: the matrix's highest), at the system's
        density altitude; the yaw model flies the towed trim's angle of attack there
        (:func:`~.setup.yaw_model_of`). [m/s]
    name : str
    neutral_fit_range : tuple of float, optional
        Sideslip range of the least-squares linearisation of the neutral-area sizing (default
        the parachute sizing's :data:`~slingloads.analyses.chute_sizing.FIT_RANGE`; a workbook
        passes its 'chute sizing linearisation range', so that both analyses size the same
        neutral area). [rad]
    yaw_axis : {"suspension", "airframe z"}
        The axis of the 1-DOF yaw model of the neutral area and the 1-DOF checks (default the
        suspension axis; a workbook passes its 'chute sizing yaw axis', so that both analyses
        take the same axis, :func:`~slingloads.analyses.towed_attitude.yaw_model_about`).

    Attributes
    ----------
    neutral : NeutralAreaResult
        The neutral static area sizing the area factors multiply (computed on construction).
    neutral_trim : TowedAttitude
        The towed trim it is read at (alpha 0 when not converged: :attr:`neutral_condition`).
    matrix : CampaignMatrix
        The runs.
    """

    setup: CampaignSetup
    factors: Factors = field(default_factory=Factors)
    rows: pd.DataFrame | None = None
    settings: RunSettings = field(default_factory=RunSettings)
    criteria: SelectionCriteria = field(default_factory=SelectionCriteria)
    margin: float = MARGIN
    stability: MapSettings | None = field(default_factory=MapSettings)
    no_parachute: NoParachuteStudy | None = None
    chosen_area_factor: float | None = None
    neutral_airspeed: float | None = None
    name: str = "campaign"
    neutral_fit_range: tuple | None = None
    yaw_axis: str = "suspension"

    def __post_init__(self):
        if not isinstance(self.setup, CampaignSetup):
            raise InputError("a campaign needs a CampaignSetup", type(self.setup).__name__)
        if self.rows is None and not isinstance(self.factors, Factors):
            raise InputError("a campaign needs Factors or listed rows",
                             type(self.factors).__name__)
        for name, kind in (("settings", RunSettings), ("criteria", SelectionCriteria)):
            if not isinstance(getattr(self, name), kind):
                raise InputError(f"the campaign's {name} must be a {kind.__name__}",
                                 type(getattr(self, name)).__name__)
        if self.stability is not None and not isinstance(self.stability, MapSettings):
            raise InputError("the stability map settings must be MapSettings",
                             type(self.stability).__name__)
        if self.no_parachute is not None and not isinstance(self.no_parachute,
                                                            NoParachuteStudy):
            raise InputError("the study without parachute must be a NoParachuteStudy",
                             type(self.no_parachute).__name__)
        margin = float(self.margin)
        if not np.isfinite(margin) or margin < 1:
            raise InputError("the margin on the dynamics' extremes must be >= 1", self.margin)
        object.__setattr__(self, "margin", margin)
        speeds = (self.rows["airspeed EAS [m/s]"] if self.rows is not None
                  else self.factors.airspeeds)
        speed = self.neutral_airspeed or float(np.max(np.asarray(speeds, float)))
        fit = FIT_RANGE if self.neutral_fit_range is None else tuple(
            float(b) for b in self.neutral_fit_range)
        towed = towed_trim_of(self.setup.system, speed)
        object.__setattr__(self, "neutral_trim", towed)
        neutral = neutral_area_of(self.setup.system, speed, fit, towed=towed,
                                  axis=self.yaw_axis)
        if neutral.already_stable:
            raise InputError("fuselage and fin are already statically stable in yaw (neutral "
                             "parachute area not positive): there is no parachute to size",
                             neutral.area)
        object.__setattr__(self, "neutral", neutral)
        if self.rows is not None:
            matrix = CampaignMatrix.from_rows(self.rows, neutral.area, self.factors.masses,
                                              self.setup.base_mass)
        else:
            matrix = CampaignMatrix.from_factors(self.factors, neutral.area,
                                                 self.setup.base_mass)
        object.__setattr__(self, "matrix", matrix)
        self._check_geometry()

    def _check_geometry(self):
        """Every cable length must clear the parachute (the system refuses the others)."""
        first = self.matrix.frame.iloc[0]
        for length in self.matrix.frame["cable length [m]"].unique():
            row = first.copy()
            row["cable length [m]"] = length
            self.setup.system_for(row)

    @property
    def neutral_condition(self):
        """Where the neutral area is read, in words: the towed trim's angle of attack, or
        alpha 0 and why (no trim found)."""
        return trim_text(self.neutral_trim, self.setup.system.density_altitude)

    @property
    def size(self):
        """Runs of the matrix."""
        return len(self.matrix)

    def run_jobs(self, keys):
        """(run ids, jobs) of the matrix: jobs (key, system, manoeuvre), one system object per
        distinct area and condition, in matrix order.

        Parameters
        ----------
        keys : KeyMaker
            Keys of the runs (:class:`~.keys.KeyMaker`).

        Returns
        -------
        ids : list of str
            Run ids, in matrix order.
        jobs : list of (str, SlingSystem, Manoeuvre)
            Key, system and manoeuvre of each run.
        """
        systems, manoeuvres, jobs, ids = {}, {}, [], []
        for _, row in self.matrix.frame.iterrows():
            cond = tuple(row[c] for c in ("area factor [-]", "airspeed EAS [m/s]", "mass case",
                                          "density altitude [m]", "cable length [m]",
                                          "carrier"))
            if cond not in systems:
                systems[cond] = self.setup.system_for(row)
            system = systems[cond]
            mkey = (row["manoeuvre"], row["airspeed EAS [m/s]"], row["density altitude [m]"])
            if mkey not in manoeuvres:
                manoeuvres[mkey] = MANOEUVRES[row["manoeuvre"]].build(
                    row["airspeed EAS [m/s]"], row["density altitude [m]"])
            manoeuvre = manoeuvres[mkey]
            jobs.append((keys.key(system, manoeuvre), system, manoeuvre))
            ids.append(row["run"])
        return ids, jobs


@dataclass(frozen=True, eq=False)
class CampaignResult:
    """Results of a campaign (module notes).

    Attributes
    ----------
    campaign : Campaign
    metrics : pandas.DataFrame
        One row per run: the matrix's columns, then the metrics (:mod:`.metrics`), then
        ``stable`` and ``meets damping criterion``.
    keys : dict
        Run id -> key in the store.
    store : MemoryStore or compatible
        Where the histories are.
    execution : ExecutionReport
    selection : Selection
    envelope : DynamicsEnvelope or None
        None when no area is stable everywhere and none was chosen.
    sensitivity : dict
        Factor -> table.
    carrier : pandas.DataFrame or None
        Carrier free against frozen, paired runs.
    stability : StabilityMap or None
    neutral_check : pandas.DataFrame
        The 1.0 x neutral area: 1-DOF verdicts and the multibody verdict per condition.
    no_parachute : NoParachuteResult or None
    decision : ParachuteDecision or None
        The parachute decision of the campaign alone
        (:func:`~slingloads.analyses.parachute_decision.decide`, without the 1-DOF sweep).
    """

    campaign: Campaign
    metrics: pd.DataFrame
    keys: dict
    store: object
    execution: object
    selection: object
    envelope: object
    sensitivity: dict
    carrier: pd.DataFrame | None
    stability: object
    neutral_check: pd.DataFrame
    no_parachute: NoParachuteResult | None
    decision: object = None

    @property
    def neutral(self):
        """The neutral static area sizing (NeutralAreaResult)."""
        return self.campaign.neutral

    @property
    def chosen_area_factor(self):
        """The area factor handed to the loads (NaN when none). [-]"""
        return np.nan if self.envelope is None else self.envelope.area_factor

    def history(self, run):
        """Time histories of one run (a matrix run id, or (helicopter, target [m/s]) of the
        study without parachute, or (helicopter, target [m/s], "gust") of its ramps with a
        gust), unit-labelled columns (angles in degrees).

        Parameters
        ----------
        run : str or (str, float) or (str, float, "gust")
            A matrix run id, or (helicopter, target airspeed [m/s]) of a ramp of the study
            without parachute, or (helicopter, target airspeed [m/s], "gust") of its ramps
            with a gust.

        Returns
        -------
        pandas.DataFrame
            One row per sample, units in the column labels (s, m, m/s, N, deg).
        """
        key = self.keys.get(run)
        if key is None and self.no_parachute is not None:
            if isinstance(run, tuple) and len(run) == 3 and run[2] == "gust":
                key = self.no_parachute.gust_keys.get(run[:2])
            else:
                key = self.no_parachute.keys.get(run)
        if key is None:
            raise InputError("unknown run", run)
        record = self.store.get(key)
        if record is None or record[1] is None:
            raise InputError("the histories of this run were not kept", run)
        return pd.DataFrame(record[1], columns=list(HISTORY_LABELS))


def _metrics_frame(matrix, keys, store, criteria):
    from .selection import damped_runs, stable_runs

    records = [ordered(store.get(keys[run])[0]) for run in matrix.frame["run"]]
    frame = pd.concat([matrix.frame.reset_index(drop=True), pd.DataFrame(records)], axis=1)
    frame["stable"] = stable_runs(frame)
    frame["meets damping criterion"] = damped_runs(frame, criteria)
    return frame


def neutral_check(campaign, metrics):
    """The 1.0 x neutral area in the 1-DOF model and in the multibody model (module notes).

    The 1-DOF verdicts come from :func:`~slingloads.analyses.chute_sizing.run_yaw` at the
    sizing airspeed (the matrix's highest) and first density altitude under the standard
    30 ft/s lateral gusts (120 s, step 0.1 s); the multibody verdict of every condition of the
    matrix from its eigenvalues at exactly the neutral area, and from its runs when the matrix
    has factor 1.

    Parameters
    ----------
    campaign : Campaign
    metrics : pandas.DataFrame
        The campaign's metrics, one row per run (units in the column labels).

    Returns
    -------
    pandas.DataFrame
        One row per model, condition and test: verdict, peak sideslip [deg] and damping
        ratio [-].
    """
    m = campaign.matrix
    speed = float(m.frame["airspeed EAS [m/s]"].max())
    altitude = float(m.frame["density altitude [m]"].iloc[0])
    model = yaw_model_of(campaign.setup.system, speed, altitude, axis=campaign.yaw_axis)
    fit = (FIT_RANGE if campaign.neutral_fit_range is None
           else tuple(float(b) for b in campaign.neutral_fit_range))
    runs = run_yaw(model, campaign.neutral.area, standard_gusts(),
                   SolverSettings(ONE_DOF_TIME, ONE_DOF_STEP), fit_range=fit).to_frame()
    one_dof = f"{speed / KNOT:.0f} KEAS, density altitude {altitude:.0f} m"
    rows = [{"model": "1-DOF yaw", "condition": one_dof,
             "test": f"lateral gust {g}", "verdict": v,
             "peak beta [deg]": b, "damping ratio [-]": z}
            for g, v, b, z in zip(runs["gust"], runs["verdict"], runs["peak beta [deg]"],
                                  runs["damping ratio linear [-]"], strict=True)]
    at_one = metrics[np.isclose(metrics["area factor [-]"], 1.0)]
    for _, cond in m.conditions().iterrows():
        row = {**cond.to_dict(), "run": "neutral", "area factor [-]": 1.0,
               "area [m^2]": campaign.neutral.area}
        point = trim(campaign.setup.system_for(row))
        verdict = linearise(point).verdict() if point.converged else "no trim"
        text = condition_text(cond)
        rows.append({"model": "multibody", "condition": text, "test": "eigenvalues",
                     "verdict": verdict})
        same = at_one
        for column in CONDITION_COLUMNS:
            same = same[same[column] == cond[column]]
        for _, r in same.iterrows():
            rows.append({"model": "multibody", "condition": text, "test": r["manoeuvre"],
                         "verdict": (r["response verdict"] if r["linear verdict"] == "stable"
                                     else f"{r['response verdict']} (eigenvalues "
                                          f"{r['linear verdict']})"),
                         "peak beta [deg]": r["beta peak [deg]"],
                         "damping ratio [-]": r["yaw mode damping ratio [-]"]})
    return pd.DataFrame(rows)


def _map_row(campaign):
    frame = campaign.matrix.frame
    carriers = list(dict.fromkeys(frame["carrier"]))
    return {"run": "map", "mass case": frame["mass case"].iloc[0],
            "mass [kg]": float(frame["mass [kg]"].iloc[0]),
            "cable length [m]": float(frame["cable length [m]"].iloc[0]),
            "carrier": "frozen" if "frozen" in carriers else carriers[0]}


def _map_settings(campaign):
    s = campaign.stability
    frame = campaign.matrix.frame
    factors = s.area_factors or tuple(np.linspace(0.5 * frame["area factor [-]"].min(),
                                                  frame["area factor [-]"].max(), 11))
    lo, hi = frame["airspeed EAS [m/s]"].min(), frame["airspeed EAS [m/s]"].max()
    speeds = s.airspeeds or (tuple(np.linspace(lo, hi, 7)) if hi > lo else (lo,))
    altitudes = s.density_altitudes or tuple(frame["density altitude [m]"].unique())
    return MapSettings(factors, speeds, altitudes, s.refine)


def run_campaign(campaign, *, executor=None, store=None, progress=None, batch_size=None):
    """Execute a campaign (module notes).

    Parameters
    ----------
    campaign : Campaign
    executor : InProcess, LocalProcesses or DaskCluster, optional
        (default :func:`~.execution.make_executor` for the campaign's size). Closed at the end.
    store : MemoryStore or compatible, optional
        Finished runs (default: a new :class:`~.execution.MemoryStore`). Runs already in it are
        not run again.
    progress : callable, optional
        ``progress(done, total)``.
    batch_size : int, optional
        Runs per batch (default :func:`~.execution.batch_size`). [count]

    Returns
    -------
    CampaignResult
    """
    if not isinstance(campaign, Campaign):
        raise InputError("run_campaign needs a Campaign", type(campaign).__name__)
    store = MemoryStore() if store is None else store
    keys = KeyMaker(campaign.settings.as_dict())
    ids, jobs = campaign.run_jobs(keys)
    groups = [(campaign.settings.as_dict(), jobs)]
    chute_jobs = []
    if campaign.no_parachute is not None:
        # each ramp runs for its own length (its verdict must not depend on the others)
        study = campaign.no_parachute
        by_length = {}
        for gust, listed, length in ((False, study.jobs(), study.run_length_of),
                                     (True, study.gust_jobs(), study.gust_run_length_of)):
            for name, target, system, m in listed:
                ramp = campaign.settings.as_dict(length(target))
                key = KeyMaker(ramp).key(system, m)
                chute_jobs.append((name, target, key, system, m, gust))
                by_length.setdefault(ramp["t_end"], (ramp, []))[1].append((key, system, m))
        groups += list(by_length.values())
    if executor is None:
        executor = make_executor(runs=len(jobs) + len(chute_jobs),
                                 settings=campaign.settings.as_dict())
    with executor:
        report = execute(groups, store, executor, size=batch_size, progress=progress)
    run_keys = dict(zip(ids, (j[0] for j in jobs), strict=True))
    metrics = _metrics_frame(campaign.matrix, run_keys, store, campaign.criteria)
    selection = select_parachute(metrics, campaign.criteria, campaign.neutral.area,
                                 campaign.neutral_condition)
    chosen = campaign.chosen_area_factor
    if chosen is None:
        chosen = (selection.recommended if np.isfinite(selection.recommended)
                  else selection.smallest_stable)
    envelope = (dynamics_envelope(metrics, chosen, campaign.margin)
                if chosen is not None and np.isfinite(chosen) else None)
    no_chute = None
    if chute_jobs:
        rows = {False: [], True: []}
        for name, target, key, _, manoeuvre, gust in chute_jobs:
            record = ordered(store.get(key)[0])
            rows[gust].append({"helicopter": name, "ramp target [m/s]": target,
                               "manoeuvre": manoeuvre.name,
                               "verdict": ramp_verdict(record["response verdict"],
                                                       record["linear verdict"]), **record})
        runs = pd.DataFrame(rows[False])
        no_chute = NoParachuteResult(
            runs, speed_limits(runs), {(n, t): k for n, t, k, *_, g in chute_jobs if not g},
            pd.DataFrame(rows[True]), {(n, t): k for n, t, k, *_, g in chute_jobs if g})
    stability = (stability_map(campaign.setup, campaign.neutral.area, _map_settings(campaign),
                               _map_row(campaign)) if campaign.stability is not None else None)
    return CampaignResult(
        campaign, metrics, run_keys, store, report, selection, envelope,
        sensitivity_tables(metrics, chosen if chosen is not None else np.nan),
        carrier_comparison(metrics), stability, neutral_check(campaign, metrics), no_chute,
        campaign_decision(campaign, metrics, selection))


def campaign_decision(campaign, metrics, selection, sweep=None, static=None, one_dof=None,
                      study_area=None, yaw_axis=None, airspeed=None):
    """The parachute decision of a campaign (:func:`~slingloads.analyses.parachute_decision.
    decide`), with a 1-DOF sizing sweep if given; the 1-DOF verdicts at the chosen area from
    the campaign's yaw model at its highest airspeed (as :func:`neutral_check`) unless
    ``one_dof`` is given.

    Parameters
    ----------
    campaign : Campaign
    metrics : pandas.DataFrame
        The campaign's metrics, one row per run (units in the column labels).
    selection : Selection
        The campaign's parachute selection.
    sweep : SweepResult, optional
        The 1-DOF sizing sweep.
    static : NeutralAreaResult, optional
        The neutral area (default the campaign's).
    one_dof : callable, optional
        ``one_dof(area)`` -> DataFrame of the 1-DOF runs at an area [m^2].
    study_area : float, optional
        The study's parachute area (default that of the campaign's system). [m^2]
    yaw_axis : str, optional
        The 1-DOF model's axis in words (default: the campaign's, :attr:`Campaign.yaw_axis`).
    airspeed : float, optional
        The 1-DOF model's airspeed (default the matrix's highest). [m/s]

    Returns
    -------
    ParachuteDecision
    """
    from slingloads.analyses.parachute_decision import decide

    from .selection import stable_runs

    if airspeed is None:
        airspeed = float(campaign.matrix.frame["airspeed EAS [m/s]"].max())
    if yaw_axis is None:
        yaw_axis = f"'{campaign.yaw_axis}' ({campaign.neutral_condition})"
    if one_dof is None:
        m = campaign.matrix
        speed = float(m.frame["airspeed EAS [m/s]"].max())
        altitude = float(m.frame["density altitude [m]"].iloc[0])
        model = yaw_model_of(campaign.setup.system, speed, altitude, axis=campaign.yaw_axis)
        fit = (FIT_RANGE if campaign.neutral_fit_range is None
               else tuple(float(b) for b in campaign.neutral_fit_range))

        def one_dof(area):
            return run_yaw(model, area, standard_gusts(),
                           SolverSettings(ONE_DOF_TIME, ONE_DOF_STEP), fit_range=fit).to_frame()

    line = campaign.setup.system.parachute
    area = (float(line.parachute.area) if line is not None else float("nan")
            ) if study_area is None else study_area
    return decide(campaign.neutral if static is None else static, sweep, selection, metrics,
                  stable_runs(metrics).to_numpy(), one_dof, area, yaw_axis, airspeed)

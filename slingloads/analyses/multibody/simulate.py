"""Runs of the towed system: many manoeuvres (and systems) integrated together, histories and
metrics.

Every run starts from a trim (:func:`~.trim.trim`) at the manoeuvre's start condition, plus its
disturbance, and is integrated by the compiled Dormand-Prince 5(4) kernel over all runs at once
(:func:`slingloads.models.multibody.integrator.integrate`, blocks of runs on every processor),
each run with its own adaptive step (or a given fixed step), segment by segment between the
times at which its inputs jump. Runs whose systems share their aerodynamic tables go into one
batch. A fixed step is checked against the fastest mode of each trim's linear model (the step
must give |lambda| dt <= 1).

A run that leaves a table stops there: the verdict says which table and when, the history is NaN
after it (no extrapolation), and the rest of the batch goes on.

Each run's metrics are measured by the kernel as soon as the run is integrated (compiled, from
the quantities the equations report at its samples: no run's reported quantities are stored).
A run's reported quantities and histories are computed when asked for, from its sampled
states, which the batch keeps, or integrates again, the same to the last bit, when it was told
to keep only the metrics (``keep_histories=False``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import pandas as pd

from slingloads.analyses import verdicts as vd
from slingloads.analyses.response_modes import identify_mode
from slingloads.analyses.verdicts import EnvelopeTest
from slingloads.errors import InputError
from slingloads.limits import MAX_MULTIBODY_RUN_STEPS
from slingloads.models.multibody.equations import INFO, N_INFO, N_STATES
from slingloads.models.multibody.integrator import (
    ATOL,
    DRIVE_STEP,
    RTOL,
    evaluate_many,
    integrate,
    stack_drives,
    tabulate_drive,
)
from slingloads.models.multibody.response import (
    HISTORY,
    MEASURES,
    N_HISTORY,
    PEAKS,
    damping_from_peaks,
    derive,
    scratch,
)
from slingloads.models.multibody.rigid_body import (
    euler_angles,
    quaternion_from_euler,
    rotation_matrix,
)

from .manoeuvres import Manoeuvre
from .trim import fastest_rates, flag_text, linearise, trim_many

#: Default run length [s], fixed step (None: adaptive) [s] and sampling interval of the
#: histories [s].
T_END, DT, OUTPUT_INTERVAL = 60.0, None, 0.1
#: Largest |lambda| dt accepted for the fastest linear mode with a fixed step. [-]
STEP_LIMIT = 1.0
#: |lambda| dt at the edge of the stability region of the Dormand-Prince 5(4) pair on the
#: negative real axis (Hairer and Wanner, Solving ODEs II, section IV.2). [-]
ADAPTIVE_STABILITY = 3.3
#: Least half-width of the band a settled yaw stays in. [rad]
BAND_FLOOR = float(np.radians(1.0))
#: The envelope test of a run's response (:mod:`slingloads.analyses.verdicts`).
ENVELOPE = EnvelopeTest(band=BAND_FLOOR, offset=BAND_FLOOR)
#: Share of the peak excursion of the sideslip from trim that bounds the settling band (at
#: least :data:`BAND_FLOOR`). [-]
SETTLE_FRACTION = 0.1
#: The rule of a run's response verdict.
VERDICT_RULE = (
    "outside domain: left a table or the cable went slack (with the time); otherwise the worst "
    "of the " + ENVELOPE.rule("the sideslip (offset from its trim) and the lateral and "
    "longitudinal swing angles") + "; convergent also needs every eigenvalue of the trim's "
    "linear model to have a real part below -1e-6 1/s (else inconclusive)")
#: Names of the peaks in the metrics, where they differ from the histories'.
METRIC_LABELS = {"hub load angle": "hub load from mast"}

_INFO = {name: i for i, name in enumerate(INFO)}


def check_settings(t_end, dt, output_interval, rtol, atol):
    """Check a simulation's settings and count its stored samples.

    Parameters
    ----------
    t_end : float
        Simulated time, > 0 and a whole multiple of ``output_interval``. [s]
    dt : float or None
        Fixed step, > 0 (None: the adaptive Dormand-Prince integrator). [s]
    output_interval : float
        Interval of the stored samples, > 0. [s]
    rtol, atol : float
        Tolerances of the adaptive integrator, > 0. [-], [state units]

    Returns
    -------
    int
        Stored samples, t_end / output_interval + 1. [-]

    Raises
    ------
    InputError
        For a setting that is not finite and > 0, or a run length that is not a whole
        number of output intervals, naming the setting and its value.
    """
    for name, value in (("t_end", t_end), ("output_interval", output_interval)):
        if not np.isfinite(value) or value <= 0:
            raise InputError(f"simulation {name} must be > 0 [s]", value)
    if dt is not None and (not np.isfinite(dt) or dt <= 0):
        raise InputError("simulation dt must be > 0 [s] (or None: adaptive)", dt)
    for name, value in (("rtol", rtol), ("atol", atol)):
        if not np.isfinite(value) or value <= 0:
            raise InputError(f"simulation {name} must be > 0", value)
    samples = t_end / output_interval
    if abs(samples - round(samples)) > 1e-9 * samples:
        raise InputError("simulation t_end must be a whole multiple of output_interval [s]",
                         t_end)
    return int(round(samples)) + 1


def disturbed(state, disturbance, chute_kind="none"):
    """A state with a manoeuvre's initial disturbance added to it (nothing is overwritten).

    Parameters
    ----------
    state : array_like, shape (20,)
        The trim's state, or a start state (:func:`~.start.start_state`). [m, m/s, -, rad/s, rad]
    disturbance : dict
        Keys of :data:`~.manoeuvres.DISTURBANCES`: yaw, pitch, roll [rad] added to the
        attitude's angles; yaw_rate [rad/s] added to the body rates, about the earth vertical
        (nose right positive); longitudinal, lateral, vertical [m] added to the CG position
        (earth X, Y, Z); theta, psi [rad] added to the line angles of a hinged canopy.
    chute_kind : str
        The system's parachute kind (``"hinged"``: the line angles apply).

    Returns
    -------
    numpy.ndarray, shape (20,)
        The disturbed state. [m, m/s, -, rad/s, rad]
    """
    x = np.array(state, dtype=float)
    d = disturbance
    if any(k in d for k in ("yaw", "pitch", "roll")):
        yaw, pitch, roll = euler_angles(x[9:13])
        x[9:13] = quaternion_from_euler(yaw + d.get("yaw", 0.0), pitch + d.get("pitch", 0.0),
                                        roll + d.get("roll", 0.0))
    if "yaw_rate" in d:
        x[13:16] += rotation_matrix(x[9:13]).T @ np.array([0.0, 0.0, -d["yaw_rate"]])
    x[3] += d.get("longitudinal", 0.0)
    x[4] += d.get("lateral", 0.0)
    x[5] += d.get("vertical", 0.0)
    if chute_kind == "hinged":
        x[16] += d.get("theta", 0.0)
        x[17] += d.get("psi", 0.0)
    return x


def _drive(manoeuvre, base_velocity):
    """The manoeuvre's drive d(t) (n, 9): wind, commanded acceleration and velocity."""
    def drive(t):
        acc, vel = manoeuvre.trajectory.command(t, base_velocity)
        return np.concatenate([manoeuvre.wind.velocity(t), acc, vel], axis=1)
    return drive


def _damping_from_peaks(t, y, start=0.0):
    """Period [s] and damping ratio [-] from the successive positive peaks of ``y`` after
    ``start`` (log decrement), or NaN when there are fewer than three peaks above 2 % of the
    largest (:func:`~slingloads.models.multibody.response.damping_from_peaks`)."""
    t, y = np.ascontiguousarray(t, dtype=float), np.ascontiguousarray(y, dtype=float)
    return damping_from_peaks(t, y, float(start), scratch(t.size))


#: Columns of :meth:`RunResult.to_frame`: (key of :meth:`RunResult.histories`, label,
#: 1 if shown in SI as is or 0 if an angle shown in degrees).
HISTORY_COLUMNS = (("time", "time [s]", 1), ("x", "x from hook [m]", 1),
                   ("y", "y from hook [m]", 1), ("z", "z from hook [m]", 1),
                   ("yaw", "yaw (heading from flight path) [deg]", 0),
                   ("pitch", "pitch [deg]", 0), ("roll", "roll [deg]", 0),
                   ("yaw rate", "yaw rate [deg/s]", 0), ("alpha", "alpha [deg]", 0),
                   ("beta", "beta [deg]", 0), ("airspeed", "airspeed [m/s]", 1),
                   ("swing longitudinal", "swing longitudinal [deg]", 0),
                   ("swing lateral", "swing lateral [deg]", 0),
                   ("swing", "swing from vertical [deg]", 0), ("tension", "cable tension [N]", 1),
                   ("tension ratio", "tension / weight [-]", 1), ("hub Fx", "hub Fx [N]", 1),
                   ("hub Fy", "hub Fy [N]", 1), ("hub Fz", "hub Fz [N]", 1),
                   ("hub load angle", "hub load from mast [deg]", 0),
                   ("line theta", "line theta [deg]", 0), ("line psi", "line psi [deg]", 0),
                   ("line tension", "line tension [N]", 1),
                   ("chute alpha", "canopy alpha [deg]", 0),
                   ("carrier speed", "carrier speed [m/s]", 1),
                   ("thrust tilt", "carrier thrust tilt [deg]", 0))


@dataclass(frozen=True, eq=False)
class RunResult:
    """One run: its inputs, trim, sampled histories and verdict.

    Attributes
    ----------
    system : SlingSystem
    manoeuvre : Manoeuvre
    trim : Trim
    time : ndarray, shape (n,)
        [s]
    flag : int
        Table or limit left (0: none); see :func:`~.trim.flag_text`. [-]
    stop_time : float
        Time the run stopped (NaN if it ran to the end). [s]
    batch : object, optional
        The runs integrated with this one (their states, parameters, drives and measures),
        from which :attr:`states` and :attr:`info` come.
    index : int
        This run's place in ``batch``. [-]
    """

    system: object
    manoeuvre: Manoeuvre
    trim: object
    time: np.ndarray
    flag: int
    stop_time: float
    batch: object = field(default=None, repr=False)
    index: int = 0

    @cached_property
    def states(self):
        """States of the equations at the samples, ndarray (n, 20) (NaN after a stop or
        without trim); integrated again, the same to the last bit, when the batch did not
        keep them."""
        if self.batch is None:
            return np.full((self.time.size, N_STATES), np.nan)
        return self.batch.states_of(self.index)

    @cached_property
    def info(self):
        """Reported quantities of the equations at the samples, ndarray (n, N_INFO) (NaN
        after a stop or without trim), evaluated on first use."""
        if self.batch is None:
            return np.full((self.time.size, N_INFO), np.nan)
        return self.batch.info(self.index, self.states)

    @property
    def name(self):
        """The name of the manoeuvre this run flew."""
        return self.manoeuvre.name

    @property
    def stopped(self):
        """True when the run left a table (or had no trim)."""
        return bool(self.flag) or not self.trim.converged

    def stop_reason(self):
        """Why the run stopped ('' if it did not).

        Returns
        -------
        str
            "no trim: ..." or "left the <tables> at t = <time> s", or ''.
        """
        if not self.trim.converged:
            return f"no trim: {self.trim.message}"
        if self.flag:
            return f"left the {flag_text(self.flag)} at t = {self.stop_time:.3f} s"
        return ""

    def history_table(self):
        """Derived histories (n, len(HISTORY)) in the order of
        :data:`~slingloads.models.multibody.response.HISTORY` (SI, angles in rad).

        Returns
        -------
        ndarray, shape (n, N_HISTORY)
            SI, angles in rad. [SI, rad]
        """
        system = self.system
        table = np.empty((self.time.size, N_HISTORY))
        derive(self.time, self.states, self.info, float(system.weight),
               np.asarray(system.hardpoints.mast_axis, float), system.parachute is not None,
               table)
        return table

    def histories(self):
        """Derived histories in SI (angles in rad) as a dict of arrays.

        Returns
        -------
        dict of str to ndarray, shape (n,)
            The columns of :meth:`history_table` by the names of
            :data:`~slingloads.models.multibody.response.HISTORY`. [SI, rad]
        """
        table = self.history_table()
        return {name: table[:, k] for k, name in enumerate(HISTORY)}

    def to_frame(self):
        """Time histories with unit-labelled columns (angles in degrees; body-axis hub load;
        positions of the HC CG relative to the hook in earth axes).

        Returns
        -------
        pandas.DataFrame
            One row per sample, the columns of
            :data:`HISTORY_COLUMNS` with their units in the
            labels (s, m, m/s, N, deg).
        """
        h = self.histories()
        data = {}
        for key, label, si in HISTORY_COLUMNS:
            data[label] = h[key] if si else np.degrees(h[key])
        frame = pd.DataFrame(data)
        if self.system.carrier.kind == "frozen":
            frame = frame.drop(columns="carrier thrust tilt [deg]")
        return frame

    # ------------------------------------------------------------------------- metrics
    def measures(self):
        """The run's measures (:data:`~slingloads.models.multibody.response.MEASURES`; SI,
        angles in rad), computed as soon as it was integrated.

        Returns
        -------
        ndarray, shape (N_MEASURES,)
            SI, angles in rad. [SI, rad]
        """
        return self.batch.measures[self.index]

    def metrics(self):
        """Per-run metrics (SI, angles in degrees), see ``docs/multibody.md``.

        Returns
        -------
        dict
            Name, manoeuvre, trim and verdict, and the peaks, settling and damping measures,
            their units in their labels (a new dict each call: computed once per run, as
            the run does not change).
        """
        return dict(self._metrics)

    @cached_property
    def _metrics(self):
        row = {"run": self.name, "manoeuvre": self.manoeuvre.describe(),
               "trim converged": self.trim.converged}
        if not self.trim.converged:
            row.update({"verdict": "no trim", "stopped": self.stop_reason()})
            return row
        m = dict(zip(MEASURES, self.measures(), strict=True))
        for key, relative in PEAKS:
            label = METRIC_LABELS.get(key, key)
            row[f"{label} {'change' if relative else 'peak'} [deg]"] = np.degrees(
                m[f"{key} peak"])
            row[f"{label} at [s]"] = float(m[f"{key} at"])
        row["yaw rms [deg]"] = float(np.degrees(m["yaw rms"]))
        row["beta rms [deg]"] = float(np.degrees(m["beta rms"]))
        row["tension / weight max [-]"] = float(m["tension ratio max"])
        row["tension / weight min [-]"] = float(m["tension ratio min"])
        row["cable slack"] = bool(m["cable slack"])
        row["cable slack first at [s]"] = float(m["cable slack first at"])
        row["cable slack time [s]"] = float(m["cable slack time"])
        if self.system.parachute is not None:
            row["line tension min [N]"] = float(m["line tension min"])
            row["line slack"] = bool(m["line tension min"] < 0)
            row["canopy alpha max [deg]"] = float(np.degrees(m["chute alpha max"]))
        verdict, reason, settling, band = self._response()
        linear = self.linear_at_condition
        (row["yaw period from response [s]"], row["yaw damping ratio from response [-]"],
         row["response damping measured on mode"],
         row["response damping check"]) = self.response_damping(
            linear.modes_frame() if linear is not None else None)
        row["settling time [s]"] = settling
        row["settling band [deg]"] = float(np.degrees(band))
        row["verdict"] = verdict
        row["verdict reason"] = reason
        row["verdict rule"] = VERDICT_RULE
        row["stopped"] = self.stop_reason()
        row["carrier speed end [m/s]"] = float(m["carrier speed end"])
        return row

    def response_damping(self, modes=None, whose=""):
        """Period and damping ratio of the yaw mode measured on the heading history after the
        input, the mode they were measured on and their check against its eigenvalue.

        The components of the heading are identified by the matrix pencil method
        (:func:`~slingloads.analyses.response_modes.identify_mode`) and the one within
        :data:`~slingloads.analyses.verdicts.PERIOD_TOLERANCE` of the linear model's yaw mode
        (:func:`~slingloads.analyses.verdicts.yaw_mode`) is read; without a linear model, the
        heading's largest oscillatory component (named "no linear mode to compare with").

        Parameters
        ----------
        modes : pandas.DataFrame or None, optional
            The linear model's :meth:`LinearModel.modes_frame` to measure against.
        whose : str, optional
            Which trim the modes are of, appended to the mode's name.

        Returns
        -------
        tuple of (float, float, str, str)
            Period [s], damping ratio [-], the mode measured on, the check against it.
        """
        target = vd.yaw_mode(modes)
        nan = float("nan")
        if modes is not None and len(target) == 0:
            return (nan, nan, "", f"no yaw mode in the linear model{whose} (no mode with a yaw "
                    f"amplitude of {vd.YAW_SHARE:.0%} of its largest)")
        period = float(target["period [s]"].iloc[0]) if target is not None else None
        if period is not None and not math.isfinite(period):
            name, real = str(target["mode"].iloc[0]), float(target["real [1/s]"].iloc[0])
            return (nan, nan, f"{name}{whose} (aperiodic, real part {real:+.3g} 1/s)",
                    f"not measured: the {name} mode{whose} is aperiodic (a real root, "
                    f"{'unstable' if real > vd.EIGENVALUE_TOLERANCE else 'stable'}): it has "
                    "no period or damping ratio to read on the response")
        ident = identify_mode(self.time, self.histories()["yaw"], self.manoeuvre.input_end
                              if self.manoeuvre.input_end is not None else self.time[-1],
                              period, vd.PERIOD_TOLERANCE)
        reason = (ident.reason if self.manoeuvre.input_end is not None
                  else "the input lasts the whole run")
        on, check = vd.response_mode(ident.period, ident.damping_ratio, target, whose, reason)
        return ident.period, ident.damping_ratio, on, check

    @cached_property
    def linear(self):
        """Linear model of the run's trim (None without trim)."""
        return linearise(self.trim) if self.trim.converged else None

    @property
    def linear_at_condition(self):
        """Linear model of the run's trim when the run starts and ends at its system's
        condition (free responses, gusts), else None: the modes a ramp or an acceleration
        ends in are those of another trim (the campaign checks them there)."""
        same = (self.manoeuvre.input_end is not None
                and abs(self.trim.airspeed - self.system.airspeed) <= 1e-9
                * max(1.0, self.system.airspeed))
        return self.linear if same else None

    def _response(self):
        """(verdict, reason, settling time [s], settling band [rad]) of :data:`VERDICT_RULE`
        (:mod:`slingloads.analyses.verdicts`)."""
        m = dict(zip(MEASURES, self.measures(), strict=True))
        nan = float("nan")
        if self.flag:
            return (vd.OUTSIDE_DOMAIN, f"left the {flag_text(self.flag)} at t = "
                    f"{self.stop_time:.3f} s", nan, nan)
        if m["cable slack"]:
            return (vd.OUTSIDE_DOMAIN, f"cable slack from t = {m['cable slack first at']:.3f} s"
                    f" ({m['cable slack time']:.3g} s in all): the taut-cable results do not "
                    "hold", nan, nan)
        start, _, window = _measure_times(self.manoeuvre)
        sustained = self.manoeuvre.input_end is None
        h = self.histories()
        trim_beta = self.trim.quantity("beta")
        signals = np.vstack([h["beta"], h["swing lateral"], h["swing longitudinal"]])
        linear = self.linear_at_condition
        modes = linear.modes_frame() if linear is not None else None
        periods = [vd.slowest_period(modes, group)
                   for group in ("yaw", "lateral", "longitudinal")]
        env = vd.envelope(self.time, signals, window, [trim_beta, np.nan, np.nan], sustained,
                          ENVELOPE, periods)
        verdict, reason = str(env.verdict[0]), env.reason(0, "sideslip")
        # the swing pendulum modes are lightly damped whatever the parachute: a swing counts
        # only when its envelope grows (the sideslip decides the rest), and is named
        for k, what in ((1, "lateral swing"), (2, "longitudinal swing")):
            if env.verdict[k] == vd.DIVERGENT:
                verdict = vd.worst([verdict, vd.DIVERGENT])
                reason += "; " + env.reason(k, what)
            elif env.verdict[k] in (vd.LIMIT_CYCLE, vd.BOUNDED):
                reason += (f"; {what} not decaying ({math.degrees(env.first[k]):.3g} -> "
                           f"{math.degrees(env.second[k]):.3g} deg: a lightly damped pendulum "
                           "mode)")
        if verdict == vd.CONVERGENT and linear is not None and not linear.stable:
            verdict = vd.INCONCLUSIVE
            reason += (f"; the response decays but the trim's linear model is not stable "
                       f"(largest real part {float(np.max(linear.eigenvalues.real)):.3g} 1/s)")
        excursion = float(np.nanmax(np.abs(h["beta"][self.time >= start] - trim_beta)))
        band = max(SETTLE_FRACTION * excursion, BAND_FLOOR)
        settling = nan
        if verdict in vd.ACCEPTED and not sustained:
            settling = float(vd.settling_time(self.time, h["beta"], start, trim_beta,
                                              band)[0])
        return verdict, reason, settling, band


@dataclass(frozen=True, eq=False)
class Simulation:
    """Results of a set of runs, with their trims and linear models.

    Attributes
    ----------
    runs : list of RunResult
    linear : dict
        Linear model per distinct trim (keyed by (system name, start airspeed [m/s])), when
        a fixed step was checked against the modes.
    dt : float or None
        Fixed step the runs were integrated with (None: adaptive). [s]
    rtol, atol : float
        Tolerances of the adaptive step. [-], [SI]
    """

    runs: list
    linear: dict
    dt: float | None = None
    rtol: float = RTOL
    atol: float = ATOL

    def describe_integration(self):
        """How the runs were integrated, in words.

        Returns
        -------
        str
        """
        if self.dt is None:
            return (f"Dormand-Prince 5(4), adaptive step per run (rtol {self.rtol:g}, atol "
                    f"{self.atol:g}), split at the inputs' jumps")
        return f"Dormand-Prince 5(4), fixed step {self.dt:g} s, split at the inputs' jumps"

    def __getitem__(self, name):
        for run in self.runs:
            if run.name == name:
                return run
        raise KeyError(f"no run named {name!r}; runs are {[r.name for r in self.runs]}")

    def metrics_frame(self):
        """One row of metrics per run.

        Returns
        -------
        pandas.DataFrame
            The rows of :meth:`RunResult.metrics`, units in the column labels.
        """
        return pd.DataFrame([run.metrics() for run in self.runs])

    def to_frame(self):
        """Metrics per run (see :meth:`metrics_frame`).

        Returns
        -------
        pandas.DataFrame
            :meth:`metrics_frame`.
        """
        return self.metrics_frame()

    def histories_frame(self):
        """All histories in long format, a ``run`` column first.

        Returns
        -------
        pandas.DataFrame
            The rows of every :meth:`RunResult.to_frame` after a ``run`` column.
        """
        frames = []
        for run in self.runs:
            frame = run.to_frame()
            frame.insert(0, "run", run.name)
            frames.append(frame)
        return pd.concat(frames, ignore_index=True)


#: What :func:`simulate` does with a run whose start has no trim.
NO_TRIM_ACTIONS = ("raise", "report")


def simulate(system, manoeuvres, *, t_end=T_END, dt=DT, output_interval=OUTPUT_INTERVAL,
             rtol=RTOL, atol=ATOL, no_trim="raise"):
    """Fly ``system`` through ``manoeuvres`` (all integrated together).

    Parameters
    ----------
    system : SlingSystem
    manoeuvres : Manoeuvre or sequence of Manoeuvre
    t_end, dt, output_interval : float
        Run length, fixed integration step (None: adaptive) and sampling interval of the
        histories. [s]
    rtol, atol : float
        Tolerances of the adaptive step: local error below atol + rtol |x| (root mean square
        over the states, SI units). [-], [SI]
    no_trim : {"raise", "report"}
        A run whose start has no trim (every run starts from one: the carrier's steady
        velocity and the cable's pull are the trim's, also with a ``start_state``): raise
        :class:`~slingloads.errors.InputError` with the reason (default), or return it
        unflown, its verdict ``no trim`` and the reason in ``stopped`` (the workbook's
        reports list such runs).

    Returns
    -------
    Simulation

    Raises
    ------
    InputError
        For bad settings, and for a run without trim when ``no_trim="raise"``.
    """
    if no_trim not in NO_TRIM_ACTIONS:
        raise InputError(f"no_trim must be one of {list(NO_TRIM_ACTIONS)}", no_trim)
    if isinstance(manoeuvres, Manoeuvre):
        manoeuvres = [manoeuvres]
    names = [m.name for m in manoeuvres]
    if len(set(names)) != len(names):
        dup = next(n for n in names if names.count(n) > 1)
        raise InputError("manoeuvre names must be unique", dup)
    sim = simulate_runs([(system, m) for m in manoeuvres], t_end=t_end, dt=dt,
                        output_interval=output_interval, rtol=rtol, atol=atol,
                        untrimmed=no_trim == "raise")
    return sim


def simulate_runs(pairs, *, t_end=T_END, dt=DT, output_interval=OUTPUT_INTERVAL, rtol=RTOL,
                  atol=ATOL, check_step=True, workers=None, keep_histories=True,
                  untrimmed=False):
    """Integrate runs given as (system, manoeuvre) pairs, together (module notes).

    Parameters
    ----------
    pairs : sequence of (SlingSystem, Manoeuvre)
    t_end, dt, output_interval : float
        Run length, fixed integration step (None: adaptive) and sampling interval of the
        histories. [s]
    rtol, atol : float
        Tolerances of the adaptive step. [-], [SI]
    check_step : bool
        Check a fixed step against the fastest mode of every trim (and keep the linear
        models).
    workers : int, optional
        Threads integrating the runs (default: every processor this process may use). [count]
    keep_histories : bool
        Keep every run's sampled states (default). False keeps only what the metrics need
        (each run's measures, computed as soon as it is integrated): a run's states and
        histories are then integrated again when asked for (the same to the last bit, about
        a millisecond a run), and a large batch needs no memory for histories.
    untrimmed : bool
        Raise :class:`~slingloads.errors.InputError` for a run whose start has no trim
        (True), or return it unflown with the reason (False: a campaign maps where trims
        exist).

    Returns
    -------
    Simulation
    """
    t_end, output_interval = float(t_end), float(output_interval)
    dt = None if dt is None else float(dt)
    n_out = check_settings(t_end, dt, output_interval, float(rtol), float(atol))
    pairs = list(pairs)
    requests, keys = {}, []
    for system, manoeuvre in pairs:
        if not isinstance(manoeuvre, Manoeuvre):
            raise InputError("runs need Manoeuvre objects", type(manoeuvre).__name__)
        speed = 0.0 if manoeuvre.from_hover else system.airspeed
        key = (id(system), speed, manoeuvre.wind.steady)
        requests.setdefault(key, (system, speed, manoeuvre.wind.steady))
        keys.append(key)
    trims = dict(zip(requests, trim_many(list(requests.values())), strict=True))
    if untrimmed:
        for (system, manoeuvre), key in zip(pairs, keys, strict=True):
            point = trims[key]
            if not point.converged:
                start = "in hover" if manoeuvre.from_hover else (
                    f"at {point.airspeed:.4g} m/s EAS")
                raise InputError(
                    f"run {manoeuvre.name!r} of {system.name!r} cannot start: no trim "
                    f"{start}: {point.message} (every run starts from a trim, also with a "
                    "start_state; no_trim='report' returns such runs unflown)")
    linear = {}
    if check_step and dt is not None:
        for point in trims.values():
            if point.converged:
                _check_step(point, dt, linear)
    elif check_step:
        _check_adaptive_work(trims, keys, t_end)
    prepared = [(system, manoeuvre, trims[key])
                for (system, manoeuvre), key in zip(pairs, keys, strict=True)]
    time = np.arange(n_out) * output_interval
    results = [None] * len(prepared)
    groups = {}
    for k, (system, _, tr) in enumerate(prepared):
        if tr.converged:
            groups.setdefault(system.table_key(), []).append(k)
        else:
            results[k] = RunResult(system, prepared[k][1], tr, time, 0, 0.0)
    settings = {"step": dt, "rtol": float(rtol), "atol": float(atol), "workers": workers,
                "keep_states": bool(keep_histories)}
    for members in groups.values():
        # the drive tables of a few runs at a time (DRIVE_BUDGET): each chunk's are freed
        # before the next is tabulated, whatever the number of runs
        for chunk in _chunks(members, [drive_bytes(t_end, prepared[k][1].breakpoints)
                                       for k in members], drive_budget(workers)):
            _integrate_group(prepared, chunk, results, _DriveTables(t_end, output_interval),
                             time, settings)
    return Simulation(results, linear, dt, float(rtol), float(atol))


#: Bytes of drive tables tabulated at once (a chunk of runs; a run of 3,600 s takes about
#: 26 MB, held twice while its chunk is stacked: two such runs per chunk, so that two cores
#: integrate side by side). [bytes]
DRIVE_BUDGET = 128 * 2**20
def drive_budget(workers=None):
    """Bytes of drive tables tabulated at once for ``workers`` integrating threads (default
    every processor this process may use): :data:`DRIVE_BUDGET` for two threads or more,
    half of it for one (a chunk holds the runs integrated side by side: one run of 3,600 s
    for one thread, two for two). [bytes]

    Parameters
    ----------
    workers : int, optional
        Threads integrating the runs. [count]

    Returns
    -------
    int
        [bytes]
    """
    from slingloads.models.multibody.integrator import worker_count

    threads = worker_count() if workers is None else int(workers)
    return DRIVE_BUDGET if threads >= 2 else DRIVE_BUDGET // 2


#: Bytes a run keeps per stored sample: its states, the drive at the sample, and the reported
#: quantities and histories evaluated from them when asked for. [bytes]
SAMPLE_BYTES = 8 * (N_STATES + 9 + N_INFO + N_HISTORY)


def drive_bytes(t_end, breakpoints=()):
    """Bytes of the drive tables of one run of ``t_end`` [s] (sampled every DRIVE_STEP, and
    at both ends of each segment between ``breakpoints``), counted twice: the run's table and
    its copy in the chunk's stacked array.

    Parameters
    ----------
    t_end : float
        Run length. [s]
    breakpoints : sequence of float
        Times at which the run's inputs jump or kink. [s]

    Returns
    -------
    int
        Bytes. [B]
    """
    segments = 1 + len(tuple(breakpoints))
    rows = float(t_end) / DRIVE_STEP + 2 * segments + 1
    return int(2 * rows * 9 * 8)


def run_bytes(t_end, output_interval, breakpoints=()):
    """Memory one run needs while it is integrated and kept: its drive tables
    (:func:`drive_bytes`) and its samples (:data:`SAMPLE_BYTES` each). [bytes]

    Parameters
    ----------
    t_end : float
        Run length. [s]
    output_interval : float
        Sampling interval. [s]
    breakpoints : sequence of float
        Times at which the run's inputs jump or kink. [s]

    Returns
    -------
    int
        Bytes. [B]
    """
    samples = int(round(float(t_end) / float(output_interval))) + 1
    return drive_bytes(t_end, breakpoints) + samples * SAMPLE_BYTES


def _chunks(members, sizes, budget):
    """``members`` cut in order into chunks whose ``sizes`` add up to at most ``budget`` (at
    least one member each)."""
    chunk, used = [], 0
    for member, size in zip(members, sizes, strict=True):
        if chunk and used + size > budget:
            yield chunk
            chunk, used = [], 0
        chunk.append(member)
        used += size
    if chunk:
        yield chunk


def _check_step(point, dt, linear):
    """Refuse a fixed step too long for the fastest mode of the trim ``point``."""
    model = linearise(point)
    system, speed = point.system, point.airspeed
    linear[(system.name, speed)] = model
    fastest = float(np.max(np.abs(model.eigenvalues)))
    if fastest * dt > STEP_LIMIT:
        raise InputError(
            f"the integration step {dt:.4g} s is too long for the fastest mode of "
            f"{system.name!r} at {speed:.4g} m/s (|lambda| = {fastest:.4g} 1/s): "
            f"use dt <= {STEP_LIMIT / fastest:.3g} s", dt)


def _check_adaptive_work(trims, keys, t_end):
    """Refuse runs whose fastest linear mode would force more adaptive steps in all than
    :data:`~slingloads.limits.MAX_MULTIBODY_RUN_STEPS` (an explicit step is stable only
    within |lambda| dt <= ADAPTIVE_STABILITY): a very stiff cable or a very light canopy
    would otherwise keep the integrator busy for hours."""
    rates = fastest_rates(list(trims.values()))
    fastest = {key: float(rate) for key, rate in zip(trims, rates, strict=True)
               if np.isfinite(rate)}
    steps = sum(t_end * fastest.get(key, 0.0) / ADAPTIVE_STABILITY for key in keys)
    if steps > MAX_MULTIBODY_RUN_STEPS:
        worst = max(fastest.values())
        raise InputError(
            f"too much work: the fastest mode of the system (|lambda| = {worst:.4g} 1/s) "
            f"forces about {steps:,.0f} adaptive steps over the {len(keys)} runs, more than "
            f"the {MAX_MULTIBODY_RUN_STEPS:,} allowed (limits of slingloads); check the "
            "cable stiffness EA, the canopy mass and the mass items, or shorten the runs",
            t_end, field="t_end")


class _DriveTables:
    """The drive of each distinct (manoeuvre, steady carrier velocity), tabulated once."""

    def __init__(self, t_end, interval):
        self.t_end, self.interval = t_end, interval
        self._tables = {}

    def get(self, manoeuvre, velocity):
        key = (id(manoeuvre), tuple(np.round(velocity, 12)))
        if key not in self._tables:
            self._tables[key] = tabulate_drive(_drive(manoeuvre, velocity),
                                               manoeuvre.breakpoints, self.t_end,
                                               self.interval)
        return key, self._tables[key]


def _integrate_group(prepared, members, results, drives, time, settings):
    system0 = prepared[members[0]][0]
    runs = len(members)
    x0 = np.empty((runs, N_STATES))
    params = np.empty((runs, system0.parameters().size))
    profiles, index = [], np.empty(runs, dtype=np.int64)
    seen = {}
    for j, k in enumerate(members):
        system, manoeuvre, tr = prepared[k]
        x0[j] = disturbed(tr.state if manoeuvre.start_state is None
                          else manoeuvre.start_state, manoeuvre.disturbance,
                          system.chute_kind)
        pull = tr.info[_INFO["d_X"]:_INFO["d_Z"] + 1]
        pull = tr.quantity("tension") * pull / np.linalg.norm(pull)
        params[j] = system.parameters(pull=pull, locks=system.locks)
        key, table = drives.get(manoeuvre, tr.state[0:3])
        if key not in seen:
            seen[key] = len(profiles)
            profiles.append(table)
        index[j] = seen[key]
    recipes = [None] * len(profiles)
    for j, k in enumerate(members):
        recipes[index[j]] = (prepared[k][1], prepared[k][2].state[0:3])
    drive = stack_drives(profiles)
    measured = np.array([_measured(system, manoeuvre) for system, manoeuvre, _ in
                         (prepared[k] for k in members)])
    done = integrate(x0, params, drive, index, drives.interval, time.size, system0.tables(),
                     measured=measured, **settings)
    batch = _Batch(done, x0, params, drive, index, drives, recipes, system0.tables(),
                   settings)
    for j, k in enumerate(members):
        system, manoeuvre, tr = prepared[k]
        results[k] = RunResult(system, manoeuvre, tr, time, int(done.flags[j]),
                               float(done.stop_time[j]), batch, j)


def _measure_times(manoeuvre):
    """(start, end, verdict start) [s] of a run's measures: its input's start (peaks and RMS
    from then on), its end (damping and settling from then on; the first sample, 0, for a
    sustained input) and the start of the time whose halves the verdict compares (the
    input's start for a sustained input)."""
    start = min(manoeuvre.breakpoints or (0.0,))
    end = manoeuvre.input_end
    if end is None:
        return start, 0.0, start
    return start, end, end


def _measured(system, manoeuvre):
    """What the kernel needs to measure a run (see the integrator's ``dopri_runs``)."""
    return [system.weight, *system.hardpoints.mast_axis, float(system.parachute is not None),
            *_measure_times(manoeuvre), BAND_FLOOR]


class _Batch:
    """What the runs integrated together share: their initial states, parameters, drives and
    tables, their sampled states if kept and their measures. A run's states, when not kept,
    are integrated again (alone: each run is integrated on its own whatever its batch, so
    they are the same to the last bit), and its reported quantities are evaluated on
    request (the same compiled equations at the same states and drive as during the
    integration). Of the drive only the samples are kept: the tables (the larger part, a
    row every DRIVE_STEP) are tabulated again, the same to the last bit, for a run
    integrated again."""

    def __init__(self, done, x0, params, drive, profile, drives, recipes, tables, settings):
        self.states, self.measures = done.states, done.measures
        self.x0, self.params, self.profile = x0, params, profile
        self.nodes = drive["nodes"]
        self.t_end, self.interval, self.recipes = drives.t_end, drives.interval, recipes
        self.tables, self.settings = tables, settings
        self.samples = drive["nodes"].shape[1]

    @property
    def drive(self):
        """The stacked drive tables of the batch (as the integration had them), tabulated
        again on each access (module notes of the class)."""
        tables = _DriveTables(self.t_end, self.interval)
        return stack_drives([tables.get(*recipe)[1] for recipe in self.recipes])

    def states_of(self, j):
        """Sampled states of run ``j``."""
        if self.states is not None:
            return self.states[j]
        one = slice(j, j + 1)
        settings = {**self.settings, "keep_states": True, "workers": 1}
        _, table = _DriveTables(self.t_end, self.interval).get(*self.recipes[self.profile[j]])
        return integrate(self.x0[one], self.params[one], stack_drives([table]),
                         np.zeros(1, dtype=np.int64), self.interval, self.samples,
                         self.tables, **settings).states[0]

    def info(self, j, states):
        """Reported quantities of run ``j`` at its samples ``states`` (NaN where it had
        stopped)."""
        reached = np.isfinite(states[:, 0])
        info = np.full((states.shape[0], N_INFO), np.nan)
        if reached.any():
            nodes = self.nodes[self.profile[j]]
            _, info[reached], _ = evaluate_many(states[reached], self.params[j],
                                                nodes[reached], self.tables)
        return info

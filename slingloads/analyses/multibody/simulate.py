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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.limits import MAX_MULTIBODY_RUN_STEPS
from slingloads.models.multibody.equations import INFO, N_INFO, N_STATES
from slingloads.models.multibody.integrator import (
    ATOL,
    RTOL,
    integrate,
    stack_drives,
    tabulate_drive,
)
from slingloads.models.multibody.parachute_line import line_angles
from slingloads.models.multibody.rigid_body import (
    euler_angles,
    quaternion_from_euler,
    rotation_matrix,
)

from .manoeuvres import Manoeuvre
from .trim import flag_text, linearise, trim_many

#: Default run length [s], fixed step (None: adaptive) [s] and sampling interval of the
#: histories [s].
T_END, DT, OUTPUT_INTERVAL = 60.0, None, 0.1
#: Largest |lambda| dt accepted for the fastest linear mode with a fixed step. [-]
STEP_LIMIT = 1.0
#: |lambda| dt at the edge of the stability region of the Dormand-Prince 5(4) pair on the
#: negative real axis (Hairer and Wanner, Solving ODEs II, section IV.2). [-]
ADAPTIVE_STABILITY = 3.3
#: Activity (yaw rate, swing rates) below which a response counts as settled. [deg/s]
QUIET = 0.5

_INFO = {name: i for i, name in enumerate(INFO)}


def _check_settings(t_end, dt, output_interval, rtol, atol):
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


def _disturbed(trim_point, disturbance):
    """Trim state with a manoeuvre's initial disturbance applied."""
    x = trim_point.state.copy()
    d = disturbance
    if any(k in d for k in ("yaw", "pitch", "roll")):
        yaw, pitch, roll = euler_angles(x[9:13])
        x[9:13] = quaternion_from_euler(yaw + d.get("yaw", 0.0), pitch + d.get("pitch", 0.0),
                                        roll + d.get("roll", 0.0))
    if "yaw_rate" in d:
        x[13:16] = rotation_matrix(x[9:13]).T @ np.array([0.0, 0.0, -d["yaw_rate"]])
    x[3] += d.get("longitudinal", 0.0)
    x[4] += d.get("lateral", 0.0)
    x[5] += d.get("vertical", 0.0)
    if trim_point.system.chute_kind == "hinged":
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
    largest."""
    keep = (t >= start) & np.isfinite(y)
    t, y = t[keep], y[keep]
    if y.size < 5:
        return np.nan, np.nan
    inner = (y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:]) & (y[1:-1] > 0)
    idx = np.nonzero(inner)[0] + 1
    if idx.size == 0:
        return np.nan, np.nan
    idx = idx[y[idx] > 0.02 * y[idx].max()]
    if idx.size < 3:
        return np.nan, np.nan
    # parabolic refinement of each peak
    y0, y1, y2 = y[idx - 1], y[idx], y[idx + 1]
    den = y0 - 2 * y1 + y2
    shift = np.where(den != 0, 0.5 * (y0 - y2) / np.where(den != 0, den, 1.0), 0.0)
    h = t[1] - t[0]
    times = t[idx] + shift * h
    peaks = y1 - 0.25 * (y0 - y2) * shift
    period = float(np.mean(np.diff(times)))
    delta = float(np.mean(np.log(peaks[:-1] / peaks[1:])))
    return period, delta / np.sqrt(4 * np.pi**2 + delta**2)


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
    states : ndarray, shape (n, 20)
        States of the equations (NaN after a stop or without trim).
    info : ndarray, shape (n, N_INFO)
        Reported quantities of the equations.
    flag : int
        Table or limit left (0: none); see :func:`~.trim.flag_text`.
    stop_time : float
        Time the run stopped (NaN if it ran to the end). [s]
    """

    system: object
    manoeuvre: Manoeuvre
    trim: object
    time: np.ndarray
    states: np.ndarray
    info: np.ndarray
    flag: int
    stop_time: float

    @property
    def name(self):
        return self.manoeuvre.name

    @property
    def stopped(self):
        """True when the run left a table (or had no trim)."""
        return bool(self.flag) or not self.trim.converged

    def stop_reason(self):
        """Why the run stopped ('' if it did not)."""
        if not self.trim.converged:
            return f"no trim: {self.trim.message}"
        if self.flag:
            return f"left the {flag_text(self.flag)} at t = {self.stop_time:.3f} s"
        return ""

    def _q(self, name):
        return self.info[:, _INFO[name]]

    def histories(self):
        """Derived histories in SI (angles in rad) as a dict of arrays."""
        yaw, pitch, roll = euler_angles(self.states[:, 9:13])
        yaw = np.unwrap(np.where(np.isfinite(yaw), yaw, 0.0))
        yaw[~np.isfinite(self.states[:, 9])] = np.nan
        d = self.info[:, _INFO["d_X"]:_INFO["d_Z"] + 1]
        span = np.linalg.norm(d, axis=1)
        hub = self.info[:, _INFO["hub_x"]:_INFO["hub_z"] + 1]
        mast = self.system.hardpoints.mast_axis
        hub_norm = np.linalg.norm(hub, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            hub_angle = np.where(hub_norm > 0, np.arccos(np.clip(
                hub @ mast / np.where(hub_norm > 0, hub_norm, 1.0), -1, 1)), np.nan)
        theta, psi = line_angles(self.info[:, _INFO["line_x"]:_INFO["line_z"] + 1])
        r = rotation_matrix(np.where(np.isfinite(self.states[:, 9:13]), self.states[:, 9:13],
                                     [1.0, 0, 0, 0]))
        omega_earth = np.einsum("nij,nj->ni", r, self.states[:, 13:16])
        thrust = self.info[:, _INFO["thrust_X"]:_INFO["thrust_Z"] + 1]
        out = {
            "time": self.time, "x": self.states[:, 3], "y": self.states[:, 4],
            "z": self.states[:, 5], "yaw": yaw, "pitch": pitch, "roll": roll,
            "yaw rate": -omega_earth[:, 2], "alpha": self._q("alpha"),
            "beta": self._q("beta"), "airspeed": self._q("airspeed"),
            "swing longitudinal": np.arctan2(d[:, 0], -d[:, 2]),
            "swing lateral": np.arctan2(d[:, 1], -d[:, 2]),
            "swing": np.arccos(np.clip(-d[:, 2] / span, -1, 1)),
            "tension": self._q("tension"),
            "tension ratio": self._q("tension") / self.system.weight,
            "hub Fx": hub[:, 0], "hub Fy": hub[:, 1], "hub Fz": hub[:, 2],
            "hub load angle": hub_angle,
            "line theta": theta, "line psi": psi,
            "line tension": self._q("line_tension"), "chute alpha": self._q("chute_alpha"),
            "carrier speed": np.linalg.norm(self.states[:, 0:3], axis=1),
            "thrust tilt": np.arctan2(-thrust[:, 0], thrust[:, 2]),
        }
        if self.system.parachute is None:
            for key in ("line theta", "line psi", "line tension", "chute alpha"):
                out[key] = np.full(self.time.shape, np.nan)
        return out

    def to_frame(self):
        """Time histories with unit-labelled columns (angles in degrees; body-axis hub load;
        positions of the HC CG relative to the hook in earth axes)."""
        h = self.histories()
        data = {}
        for key, label, si in HISTORY_COLUMNS:
            data[label] = h[key] if si else np.degrees(h[key])
        frame = pd.DataFrame(data)
        if self.system.carrier.kind == "frozen":
            frame = frame.drop(columns="carrier thrust tilt [deg]")
        return frame

    # ------------------------------------------------------------------------- metrics
    def metrics(self):
        """Per-run metrics (SI, angles in degrees), see ``docs/multibody.md``."""
        h = self.histories()
        t = self.time
        row = {"run": self.name, "manoeuvre": self.manoeuvre.describe(),
               "trim converged": self.trim.converged}
        if not self.trim.converged:
            row.update({"verdict": "no trim", "stopped": self.stop_reason()})
            return row
        start = min(self.manoeuvre.breakpoints or (0.0,))
        after = (t >= start) & np.isfinite(h["yaw"])
        x0 = {k: h[k][0] for k in h}

        def peak(key, relative=True):
            y = h[key] - (x0[key] if relative else 0.0)
            y = np.where(after, y, np.nan)
            if not np.any(np.isfinite(y)):
                return np.nan, np.nan
            k = int(np.nanargmax(np.abs(y)))
            return float(y[k]), float(t[k])

        for key, label, rel in (("yaw", "yaw", True), ("beta", "beta", False),
                                ("swing lateral", "swing lateral", False),
                                ("swing longitudinal", "swing longitudinal", True),
                                ("pitch", "pitch", True), ("roll", "roll", False),
                                ("hub load angle", "hub load from mast", False),
                                ("line psi", "line psi", False),
                                ("line theta", "line theta", True)):
            value, when = peak(key, rel)
            what = "change" if rel else "peak"
            row[f"{label} {what} [deg]"] = np.degrees(value)
            row[f"{label} at [s]"] = when
        y = h["yaw"] - x0["yaw"]
        row["yaw rms [deg]"] = float(np.degrees(np.sqrt(np.nanmean(y[after] ** 2))))
        b = h["beta"]
        row["beta rms [deg]"] = float(np.degrees(np.sqrt(np.nanmean(b[after] ** 2))))
        tr = h["tension ratio"]
        row["tension / weight max [-]"] = float(np.nanmax(tr))
        row["tension / weight min [-]"] = float(np.nanmin(tr))
        slack = tr <= 0
        row["cable slack"] = bool(np.any(slack))
        row["cable slack first at [s]"] = float(t[np.argmax(slack)]) if slack.any() else np.nan
        row["cable slack time [s]"] = float(np.count_nonzero(slack) * (t[1] - t[0]))
        if self.system.parachute is not None:
            row["line tension min [N]"] = float(np.nanmin(h["line tension"]))
            row["line slack"] = bool(np.nanmin(h["line tension"]) < 0)
            row["canopy alpha max [deg]"] = float(np.degrees(np.nanmax(h["chute alpha"])))
        end = self.manoeuvre.input_end
        end = t[0] if end is None else end
        period, zeta = _damping_from_peaks(t, h["yaw rate"], end)
        row["yaw period from response [s]"] = period
        row["yaw damping ratio from response [-]"] = zeta
        row["settling time [s]"] = self._settling(t, y, end)
        verdict, rule = self._verdict(h)
        row["verdict"] = verdict
        row["verdict rule"] = rule
        row["stopped"] = self.stop_reason()
        row["carrier speed end [m/s]"] = float(h["carrier speed"][np.isfinite(
            h["carrier speed"])][-1])
        return row

    @staticmethod
    def _settling(t, y, start):
        """Time after ``start`` after which |y - y_end| stays within max(10 % of its peak,
        1 deg); NaN when it never does."""
        ok = np.isfinite(y)
        if not ok[-1]:
            return np.nan
        dev = np.abs(y - y[-1])
        band = max(0.1 * np.nanmax(dev), np.radians(1.0))
        outside = np.nonzero((dev > band) & ok)[0]
        if outside.size == 0:
            return 0.0
        last = outside[-1]
        if last >= t.size - 2:
            return np.nan
        return max(0.0, float(t[last + 1] - start))

    def _verdict(self, h):
        rule = ("divergent: left a table, or the envelope of the motion (largest |rate| of "
                "yaw, lateral and longitudinal swing) grows by > 10 % from the first to the "
                "second half of the time after the input ends (after its onset for a sustained "
                f"input); convergent: it shrinks by > 10 % or stays below {QUIET} deg/s; "
                "otherwise undamped (bounded under a sustained input); inconclusive when less "
                "than 10 s are left after the input")
        if self.flag:
            return "divergent", rule
        t = self.time
        dt = t[1] - t[0]
        sustained = self.manoeuvre.input_end is None
        start = (min(self.manoeuvre.breakpoints or (0.0,)) if sustained
                 else self.manoeuvre.input_end)
        if t[-1] - start < 10.0:
            return "inconclusive", rule
        rates = np.vstack([np.abs(h["yaw rate"]),
                           np.abs(np.gradient(h["swing lateral"], dt)),
                           np.abs(np.gradient(h["swing longitudinal"], dt))])
        activity = np.degrees(rates.max(axis=0))
        middle = 0.5 * (start + t[-1])
        first = activity[(t >= start) & (t < middle)].max()
        second = activity[t >= middle].max()
        if second > 1.1 * first and second > QUIET:
            return "divergent", rule
        if second < 0.9 * first or second <= QUIET:
            return "convergent", rule
        return ("bounded" if sustained else "undamped"), rule


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
        """How the runs were integrated, in words."""
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
        """One row of metrics per run."""
        return pd.DataFrame([run.metrics() for run in self.runs])

    def to_frame(self):
        """Metrics per run (see :meth:`metrics_frame`)."""
        return self.metrics_frame()

    def histories_frame(self):
        """All histories in long format, a ``run`` column first."""
        frames = []
        for run in self.runs:
            frame = run.to_frame()
            frame.insert(0, "run", run.name)
            frames.append(frame)
        return pd.concat(frames, ignore_index=True)


def simulate(system, manoeuvres, *, t_end=T_END, dt=DT, output_interval=OUTPUT_INTERVAL,
             rtol=RTOL, atol=ATOL):
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

    Returns
    -------
    Simulation
    """
    if isinstance(manoeuvres, Manoeuvre):
        manoeuvres = [manoeuvres]
    names = [m.name for m in manoeuvres]
    if len(set(names)) != len(names):
        dup = next(n for n in names if names.count(n) > 1)
        raise InputError("manoeuvre names must be unique", dup)
    return simulate_runs([(system, m) for m in manoeuvres], t_end=t_end, dt=dt,
                         output_interval=output_interval, rtol=rtol, atol=atol)


def simulate_runs(pairs, *, t_end=T_END, dt=DT, output_interval=OUTPUT_INTERVAL, rtol=RTOL,
                  atol=ATOL, check_step=True, workers=None):
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
        Threads integrating the runs (default: every processor this process may use).

    Returns
    -------
    Simulation
    """
    t_end, output_interval = float(t_end), float(output_interval)
    dt = None if dt is None else float(dt)
    n_out = _check_settings(t_end, dt, output_interval, float(rtol), float(atol))
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
            results[k] = RunResult(system, prepared[k][1], tr, time,
                                   np.full((n_out, N_STATES), np.nan),
                                   np.full((n_out, N_INFO), np.nan), 0, 0.0)
    drives = _DriveTables(t_end, output_interval)
    settings = {"step": dt, "rtol": float(rtol), "atol": float(atol), "workers": workers}
    for members in groups.values():
        _integrate_group(prepared, members, results, drives, time, settings)
    return Simulation(results, linear, dt, float(rtol), float(atol))


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
    fastest = {}
    for key, point in trims.items():
        if point.converged:
            fastest[key] = float(np.max(np.abs(linearise(point).eigenvalues)))
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
        x0[j] = (_disturbed(tr, manoeuvre.disturbance) if manoeuvre.start_state is None
                 else manoeuvre.start_state)
        pull = tr.info[_INFO["d_X"]:_INFO["d_Z"] + 1]
        pull = tr.quantity("tension") * pull / np.linalg.norm(pull)
        params[j] = system.parameters(pull=pull, locks=system.locks)
        key, table = drives.get(manoeuvre, tr.state[0:3])
        if key not in seen:
            seen[key] = len(profiles)
            profiles.append(table)
        index[j] = seen[key]
    out, _, info, flags, stops = integrate(
        x0, params, stack_drives(profiles), index, drives.interval, time.size,
        system0.tables(), **settings)
    for j, k in enumerate(members):
        system, manoeuvre, tr = prepared[k]
        results[k] = RunResult(system, manoeuvre, tr, time, out[j], info[j], int(flags[j]),
                               float(stops[j]))

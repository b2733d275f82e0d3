"""Metrics of one campaign run (paper section 4.5), from its trim, linear model and histories.

Every run is measured three ways:

* **its condition's trim** (steady towed flight at the run's airspeed): the swing angle of the
  cable from the vertical, the paper's drag proxy, with the tension and the parachute drag;
* **its condition's linear model** (:func:`~slingloads.analyses.multibody.linearise`): the
  verdict from the eigenvalues, the largest real part, the least damping ratio of all modes,
  and the **yaw-mode damping ratio**: the least damping ratio among the modes in which the yaw
  takes part (yaw amplitude at least :data:`YAW_SHARE` of the mode's largest angular
  amplitude, the threshold at which a mode's name lists a second motion), and the longest
  time to half amplitude among those modes (a slow aperiodic root has a damping ratio of 1
  but hardly decays). The pendulum modes of cable and airframe are lightly damped whatever the
  parachute; the yaw modes are those the parachute sizes;
* **its response** (:meth:`RunResult.metrics <slingloads.analyses.multibody.RunResult.metrics>`):
  peak and RMS yaw and sideslip, damping ratio and period of the yaw mode identified on the
  heading history (:meth:`RunResult.response_damping
  <slingloads.analyses.multibody.RunResult.response_damping>`), settling
  time, tension extremes, slack, response verdict; and the extremes the structural loads take:
  angle of attack and sideslip, parachute line angles and tension, hub-load angle from the
  mast, and from the hanging vertical (hub above CG, the vertical of the loads' hanging
  attitude and CS-29.865 cone) in total, sideways and fore-and-aft (azimuths 90/270 and 0/180
  about that vertical, :func:`~slingloads.analyses.hook_loads.horizontal_basis`).

Angles are in degrees in the metric names' units; everything else SI. The per-run record
holds no name (run id, manoeuvre name): the campaign adds those, so that a stored record is
identified by its inputs alone (:mod:`.keys`).
"""

from __future__ import annotations

import numpy as np

from slingloads.analyses.hook_loads import horizontal_basis
from slingloads.analyses.multibody.simulate import HISTORY_COLUMNS
from slingloads.analyses.verdicts import YAW_SHARE, yaw_mode

#: Labels of the stored histories, in order (SI; angles in degrees).
HISTORY_LABELS = tuple(label for _, label, _ in HISTORY_COLUMNS)

#: The keys of a record's metrics, in the order of the tables.
METRIC_ORDER = (
    "trim converged", "trim message", "swing angle trim [deg]", "tension / weight trim [-]",
    "parachute drag trim [N]", "linear verdict", "largest real part [1/s]",
    "least damping ratio [-]", "least damped mode", "yaw mode", "yaw mode damping ratio [-]",
    "yaw mode real part [1/s]", "yaw mode period [s]", "yaw mode time to half amplitude [s]",
    "response verdict", "verdict reason",
    "yaw change [deg]", "yaw rms [deg]", "beta peak [deg]", "beta rms [deg]",
    "yaw damping ratio from response [-]", "yaw period from response [s]",
    "response damping measured on mode", "response damping check",
    "settling time [s]", "settling band [deg]", "tension / weight max [-]",
    "tension / weight min [-]",
    "cable slack", "hub load from mast max [deg]",
    "hub load from hanging vertical max [deg]", "hub load lateral max [deg]",
    "hub load longitudinal min [deg]", "hub load longitudinal max [deg]", "alpha min [deg]",
    "alpha max [deg]", "beta min [deg]", "beta max [deg]", "line theta min [deg]",
    "line theta max [deg]", "line psi min [deg]", "line psi max [deg]",
    "line tension max [N]", "canopy alpha max [deg]", "stopped")

#: Response metrics of :meth:`RunResult.metrics` not kept (names, or kept under another name).
_DROPPED = ("run", "manoeuvre", "trim converged", "verdict rule", "verdict")


def _extreme(values, how):
    finite = values[np.isfinite(values)]
    if finite.size == 0:
        return np.nan
    return float(how(finite))


def linear_metrics(trim_point, model):
    """Metrics of a condition's trim and linear model (module notes).

    Parameters
    ----------
    trim_point : Trim
        Trim at the condition's airspeed.
    model : LinearModel or None
        Its linear model (None when the trim did not converge).

    Returns
    -------
    dict
    """
    out = {"trim converged": bool(trim_point.converged), "trim message": trim_point.message}
    if not trim_point.converged or model is None:
        out["linear verdict"] = "no trim"
        return out
    out["swing angle trim [deg]"] = float(np.degrees(trim_point.swing_angle))
    out["tension / weight trim [-]"] = (trim_point.quantity("tension")
                                        / trim_point.system.weight)
    out["parachute drag trim [N]"] = trim_point.quantity("chute_drag")
    modes = model.modes_frame()
    out["linear verdict"] = model.verdict()
    out["largest real part [1/s]"] = float(np.max(model.eigenvalues.real))
    modes = modes[np.isfinite(modes["damping ratio [-]"])]  # a zero eigenvalue has none
    if len(modes) == 0:
        return out
    least = modes["damping ratio [-]"].idxmin()
    out["least damping ratio [-]"] = float(modes.loc[least, "damping ratio [-]"])
    out["least damped mode"] = str(modes.loc[least, "mode"])
    yaw = modes[modes["yaw amplitude [-]"] >= YAW_SHARE]
    if len(yaw):
        k = yaw_mode(modes).index[0]
        out["yaw mode"] = str(yaw.loc[k, "mode"])
        out["yaw mode damping ratio [-]"] = float(yaw.loc[k, "damping ratio [-]"])
        out["yaw mode real part [1/s]"] = float(yaw.loc[k, "real [1/s]"])
        out["yaw mode period [s]"] = float(yaw.loc[k, "period [s]"])
        slowest = float(yaw["real [1/s]"].max())
        out["yaw mode time to half amplitude [s]"] = (float(np.log(2.0) / -slowest)
                                                      if slowest < 0 else np.inf)
    return out


def response_metrics(run, model=None):
    """Metrics of a run's response (module notes), and its histories.

    Parameters
    ----------
    run : RunResult
    model : LinearModel or None, optional
        The linear model of the run's condition (its system's trim). A wind ramp starts in
        hover and ends at its system's airspeed: its response damping is then compared with
        this model's modes (the ones the campaign's tables list beside it), not left
        unchecked.

    Returns
    -------
    metrics : dict
    histories : ndarray, shape (samples, len(HISTORY_LABELS))
        SI, angles in degrees; NaN where the run had stopped or has no such quantity.
        [SI, angles in deg]
    """
    base = run.metrics()
    out = {k: v for k, v in base.items() if k not in _DROPPED}
    out["response verdict"] = base["verdict"]
    ramp = getattr(getattr(run.manoeuvre, "wind", None), "ramp", None)
    if (model is not None and run.linear_at_condition is None and ramp is not None
            and abs(ramp.target - run.system.airspeed) <= 1e-9 * max(1.0, ramp.target)):
        (out["yaw period from response [s]"], out["yaw damping ratio from response [-]"],
         out["response damping measured on mode"],
         out["response damping check"]) = run.response_damping(
            model.modes_frame(), " of the trim at the ramp's final airspeed")
    h = run.histories()
    table = np.column_stack([h[key] if si else np.degrees(h[key])
                             for key, _, si in HISTORY_COLUMNS])
    if not run.trim.converged:
        return out, table
    deg = np.degrees
    for key, name in (("alpha", "alpha"), ("beta", "beta"), ("line theta", "line theta"),
                      ("line psi", "line psi")):
        out[f"{name} min [deg]"] = _extreme(deg(h[key]), np.min)
        out[f"{name} max [deg]"] = _extreme(deg(h[key]), np.max)
    out["line tension max [N]"] = _extreme(h["line tension"], np.max)
    out["hub load from mast max [deg]"] = _extreme(deg(h["hub load angle"]), np.max)
    system = run.system
    a0, a90, k = horizontal_basis(system.hardpoints.hub - system.body.cg)
    hub = np.column_stack([h["hub Fx"], h["hub Fy"], h["hub Fz"]])
    along = hub @ k
    norm = np.linalg.norm(hub, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        total = deg(np.arccos(np.clip(along / norm, -1.0, 1.0)))
    out["hub load from hanging vertical max [deg]"] = _extreme(total, np.max)
    lateral = deg(np.arctan2(hub @ a90, along))
    longitudinal = deg(np.arctan2(hub @ a0, along))
    out["hub load lateral max [deg]"] = _extreme(np.abs(lateral), np.max)
    out["hub load longitudinal min [deg]"] = _extreme(longitudinal, np.min)
    out["hub load longitudinal max [deg]"] = _extreme(longitudinal, np.max)
    return out, table


def ordered(record):
    """A metrics dict with the keys of :data:`METRIC_ORDER` first (missing ones NaN).

    Parameters
    ----------
    record : dict
        Metrics of a run (units in the keys).

    Returns
    -------
    dict
    """
    out = {k: record.get(k, np.nan) for k in METRIC_ORDER}
    out.update({k: v for k, v in record.items() if k not in out})
    return out

"""Run the multibody model of a study: its inputs, its result and :func:`run`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.analyses.multibody import linearise, simulate
from slingloads.analyses.towed_attitude import towed_attitude
from slingloads.constants import KNOT
from slingloads.models.multibody.system import SlingSystem

ANALYSIS = "multibody"


@dataclass(frozen=True)
class MultibodyInputs:
    """Everything the multibody analysis needs, in SI.

    Attributes
    ----------
    system : SlingSystem
    manoeuvres : tuple of Manoeuvre
    settings : dict
        Keywords of :func:`~slingloads.analyses.multibody.simulate`: ``t_end``, ``dt`` (None:
        adaptive), ``output_interval`` [s], ``rtol`` [-], ``atol`` [SI].
    configuration, tail, carrier, parachute_model, canopy_table : str
        The Study's choices, as spelt in :mod:`slingloads.io.multibody.schema`.
    margin : float
        Required excess of the cable over the parachute line. [-]
    warnings : tuple of str
        Rules broken that do not prevent the runs (shown in the report).
    manoeuvre_source : str
        "MultibodyManoeuvres sheet" or "the paper's list".
    """

    system: SlingSystem
    manoeuvres: tuple
    settings: dict
    configuration: str
    tail: str
    carrier: str
    parachute_model: str
    canopy_table: str
    margin: float
    warnings: tuple
    manoeuvre_source: str


@dataclass(frozen=True, eq=False)
class MultibodyReport:
    """Results of the multibody analysis of one workbook.

    Attributes
    ----------
    inputs : MultibodyInputs
    trim : Trim
        Steady towed flight at the system airspeed (or why there is none).
    linear : LinearModel or None
        Linear model about that trim (None without trim).
    simulation : Simulation
        Every manoeuvre.
    outline : dict
        Airframe polylines for the views, airframe axes. [m]
    """

    inputs: MultibodyInputs
    trim: object
    linear: object
    simulation: object
    outline: dict

    def to_frame(self):
        """Every manoeuvre, one row each: its verdict and metrics (units in the headers;
        :meth:`~slingloads.analyses.multibody.Simulation.metrics_frame`).

        Returns
        -------
        pandas.DataFrame
            One row per manoeuvre, units in the column labels.
        """
        return self.simulation.metrics_frame()

    def largest_excursion(self):
        """(run, sample index, departure [rad]) of the largest angular departure from its
        start (yaw, lateral or longitudinal cable swing) over all runs; None without runs.

        Returns
        -------
        tuple or None
            ``(run, sample index, departure)``: the run, the index of its sample [-] and the
            departure [rad].
        """
        best = None
        for run in self.simulation.runs:
            h = run.histories()
            depart = np.zeros(run.time.size)
            for key in ("yaw", "swing lateral", "swing longitudinal"):
                values = h[key] - h[key][0]
                depart = np.fmax(depart, np.abs(np.where(np.isfinite(values), values, 0.0)))
            k = int(np.argmax(depart))
            if best is None or depart[k] > best[2]:
                best = (run, k, float(depart[k]))
        return best


def run(study):
    """Run the multibody analysis of a study.

    Parameters
    ----------
    study : Study
        With ``study.inputs.multibody`` (:class:`MultibodyInputs`).

    Returns
    -------
    MultibodyReport

    Raises
    ------
    InputError
        If the study does not ask for the multibody model, or the analysis refuses its
        inputs (located where they came from: :meth:`Study.located`).
    """
    inputs = study.require(ANALYSIS)
    with study.located(ANALYSIS):
        point = towed_attitude(inputs.system).trim  # the attitude the loads and sizing fly
        linear = linearise(point) if point.converged else None
        sim = simulate(inputs.system, inputs.manoeuvres, no_trim="report",
                       **inputs.settings)
    return MultibodyReport(inputs, point, linear, sim, airframe_outline(study.airframe))


def shortfalls(result):
    """What the multibody model was asked for and could not compute, one line each: no trim
    at the system airspeed (then no linear model, no eigenvalue figure, no stability
    verdict), and the runs that could not start because their own trim failed. A run that
    stops because it left a table is a result (its verdict says so), not a shortfall.

    Parameters
    ----------
    result : MultibodyReport
        The multibody model's result.

    Returns
    -------
    list of str
        One line per shortfall; empty when none.
    """
    out = []
    airspeed = result.inputs.system.airspeed / KNOT
    if not result.trim.converged:
        out.append(f"multibody: no trim at {airspeed:.4g} kt EAS ({result.trim.message}): no "
                   "linear modes, no eigenvalue figure and no stability verdict")
    runs = result.simulation.runs
    failed = [run.name for run in runs if not run.trim.converged]
    if failed:
        shown = ", ".join(repr(name) for name in failed[:5])
        more = f" and {len(failed) - 5} more" if len(failed) > 5 else ""
        out.append(f"multibody: {len(failed)} of {len(runs)} runs not flown for want of a "
                   f"trim: {shown}{more}")
    return out


def airframe_outline(airframe):
    """Polylines of the airframe for the views: fuselage (foremost mass item, CG, aftmost
    mass item) and mast (CG to hub), airframe axes. [m]

    Parameters
    ----------
    airframe : Airframe
        The airframe (:class:`~slingloads.models.airframe.Airframe`).

    Returns
    -------
    dict of str to ndarray
        Each polyline's points, shape (k, 3), airframe axes. [m]
    """
    items = airframe.mass_items
    x = items.position[:, 0]
    nose, tail = items.position[int(np.argmin(x))], items.position[int(np.argmax(x))]
    cg = items.cg
    nose = np.array([nose[0], cg[1], nose[2]])
    tail = np.array([tail[0], cg[1], tail[2]])
    return {"fuselage": np.vstack([nose, cg, tail]),
            "mast": np.vstack([cg, airframe.hardpoints.hub])}

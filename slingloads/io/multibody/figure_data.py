"""The data of the multibody report's figures, taken from the model's objects where they are
computed (:mod:`slingloads.io.multibody.plots` draws them): names, arrays and tables only, so
that the process that draws the figures needs neither the model's compiled code nor scipy.

Earth axes of the simulation: X aft along the flight path, Y right, Z up
(``docs/multibody.md``).
"""

from __future__ import annotations

import numpy as np

#: Panels of the histories plot: (history key, axis label).
HISTORY_PANELS = (("yaw", "yaw, heading from\nthe flight path [deg]"),
                  ("beta", "sideslip beta [deg]"),
                  ("swing longitudinal", "cable swing\nlongitudinal [deg]"),
                  ("swing lateral", "cable swing\nlateral [deg]"),
                  ("tension ratio", "cable tension /\nweight [-]"))


def history_panels(simulation):
    """The data of :func:`~slingloads.io.multibody.plots.plot_history_panels`:
    ``[(run name, {history: array})]`` with the time and the histories of
    :data:`HISTORY_PANELS` of every run (SI, angles in rad)."""
    keys = ("time", *(key for key, _ in HISTORY_PANELS))
    out = []
    for run in simulation.runs:
        h = run.histories()
        out.append((run.name, {key: h[key] for key in keys}))
    return out


def system_points(system, state, info, outline):
    """Earth-axis points of the system at a state: hook, hub, CG, outline, attachment, canopy.

    Parameters
    ----------
    system : SlingSystem
    state : array_like, shape (20,)
        State of the equations.
    info : array_like
        Reported quantities at that state (:data:`~slingloads.models.multibody.equations.INFO`).
    outline : dict of str to array_like, shape (n, 3)
        Polylines of the airframe in airframe axes (e.g. nose - CG - tail, CG - hub). [m]

    Returns
    -------
    dict of str to ndarray, shape (n, 3)
        Relative to the hook. [m]
    """
    # the model's compiled code, loaded where the points are computed (not by the plots)
    from slingloads.models.multibody.equations import INFO
    from slingloads.models.multibody.parachute_line import line_direction
    from slingloads.models.multibody.rigid_body import rotation_matrix

    x = np.asarray(state, float)
    r = rotation_matrix(x[9:13] / np.linalg.norm(x[9:13]))
    cg = system.body.cg
    where = x[3:6]

    def earth(points):
        return where + (np.atleast_2d(np.asarray(points, float)) - cg) @ r.T

    hub = earth(system.hardpoints.hub)
    out = {"hook": np.zeros((1, 3)), "cable": np.vstack([np.zeros(3), hub]), "CG": earth(cg)}
    for name, line in outline.items():
        out[name] = earth(line)
    if system.parachute is not None:
        attach = system.hardpoints.chute
        if system.parachute.kind == "hinged":
            e, _, _ = line_direction(x[16], x[17])
            e = np.array(e)
        else:
            at = INFO.index("line_x")
            e = np.asarray(info, float)[at:at + 3]
            e = e / np.linalg.norm(e) if np.all(np.isfinite(e)) and np.any(e) else \
                np.array([1.0, 0.0, 0.0])
        canopy = attach + system.parachute.line_length * e
        out["parachute line"] = earth(np.vstack([attach, canopy]))
        out["canopy"] = earth(canopy)
    return out


def view_points(system, states, outline):
    """The data of :func:`~slingloads.io.multibody.plots.plot_view_points`:
    ``[(label, points)]``, the points of :func:`system_points` at each of ``states``. [m]"""
    return [(name, system_points(system, state, info, outline))
            for name, state, info in states]

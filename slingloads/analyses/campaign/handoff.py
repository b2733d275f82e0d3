"""The dynamics handed to the structural loads (paper section 6): a loads study whose cases
include those the multibody campaign reached, compared with the hand-entered ones.

From a :class:`~.loads_envelope.DynamicsEnvelope` (the chosen parachute's runs, with the
margin), :func:`loads_from_dynamics` returns a copy of the loads study with

* **aerodynamic envelope**: the hand-entered points kept, and the dynamics' corners and centre
  added (ids ``DYN-CENTRE``, ``DYN-A+B+``...). The sideslip range is mirrored about zero (a
  gust set from one side says nothing of the other; the aircraft is taken as symmetric), and
  the comparison says so. A bound that the margin takes beyond the fuselage or fin table is
  set at the table's edge and flagged (tables are never extrapolated; the runs themselves
  stay inside them);
* **parachute**: the Study's parachute kept in the parachute model (``parachute="study"``,
  the default) or the chosen one (``"chosen"``), the comparison giving both areas; line cases
  (``LINE-AFT``, ``LINE-T+P+``...): the line load scaled to the loads' dynamic pressure and
  parachute area (the largest line tension over q x area of the runs, x margin, x the loads'
  q x area: never the campaign's load at a lower airspeed), along the trailing direction and
  the corners of the line-angle range (psi mirrored), combined with every hook direction and
  each dynamics point (:class:`~slingloads.analyses.loads.DynamicsCases`);
* **hook cone** (``hook_source``): ``"CS-29.865"`` keeps the Study's angles (30 deg unless a
  smaller one is justified) and raises each to the dynamics' x margin where they reach
  further (CS 29.865: the maximum angle achievable in service, not less than 30 deg);
  ``"dynamics"`` uses the dynamics' angles x margin (fore-and-aft and sideways about the
  hanging vertical, an elliptical cone): the justified smaller angle;
* **load factor**: the Study's Nz, raised to the largest tension factor x margin if the
  dynamics exceed it.

Every change is a row of :attr:`Handoff.comparison`: the hand-entered value, what the
dynamics reached, with the margin, what the loads use, and ``lowered``: True, with the note
starting "LOWER", where the loads use less than the hand-entered value.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from slingloads.analyses.hook_loads import angle_words
from slingloads.analyses.loads import AeroEnvelope, DynamicsCases, LoadsStudy
from slingloads.errors import InputError

#: Sources of the loads' hook cone.
HOOK_SOURCES = ("CS-29.865", "dynamics")
#: Parachutes of the loads after the hand-off: the Study's, or the campaign's chosen one.
PARACHUTE_SOURCES = ("study", "chosen")


@dataclass(frozen=True, eq=False)
class Handoff:
    """A loads study with the dynamics' cases, and the comparison with the hand-entered one.

    Attributes
    ----------
    study : LoadsStudy
    comparison : pandas.DataFrame
        quantity, unit, hand-entered, dynamics reached, with margin, used in the loads, note.
    envelope : DynamicsEnvelope
    """

    study: LoadsStudy
    comparison: pd.DataFrame
    envelope: object


def _range(values):
    values = np.degrees(np.asarray(values, float))
    return f"{values.min():.4g} to {values.max():.4g}"


def _limit(bounds, grid, what):
    """Bounds [deg] limited to a table's range [rad], with a note when limited."""
    lo, hi = np.degrees(grid[0]), np.degrees(grid[-1])
    out = (max(bounds[0], lo), min(bounds[1], hi))
    note = (f"limited to the {what} table's range [{lo:.4g}, {hi:.4g}] deg (the margin goes "
            "beyond it; tables are never extrapolated)" if out != tuple(bounds) else "")
    return out, note


def _aero(study, env):
    """The envelope with the dynamics' points, and the comparison rows."""
    bounds = {"alpha": env.bounds("alpha"), "beta": env.mirrored("beta")}
    notes = {"alpha": [], "beta": []}
    if not np.allclose(env.mirrored("beta"), env.bounds("beta")):
        b0, b1 = env.bounds("beta")
        notes["beta"].append(f"mirrored about zero (with margin {b0:.4g} to {b1:.4g}: the "
                             "gusts came from one side)")
    tables = []
    if study.fuselage is not None:
        tables += [("alpha", study.fuselage.table.alpha, "fuselage alpha"),
                   ("beta", study.fuselage.table.beta, "fuselage beta")]
    if study.fin is not None:
        tables.append(("beta", study.fin.table.angle, "fin beta"))
    for name, grid, what in tables:
        bounds[name], note = _limit(bounds[name], grid, what)
        if note:
            notes[name].append(note)
    ids = ("DYN-CENTRE", "DYN-A+B+", "DYN-A+B-", "DYN-A-B+", "DYN-A-B-")
    (a0, a1), (b0, b1) = np.radians(bounds["alpha"]), np.radians(bounds["beta"])
    alpha = np.array([0.0, a1, a1, a0, a0])
    beta = np.array([0.0, b1, b0, b1, b0])
    hand = study.envelope
    clash = [i for i in ids if hand is not None and i in hand.ids]
    if clash:
        raise InputError("the hand-entered envelope already has a point named like a "
                         "dynamics point", clash[0])
    envelope = (AeroEnvelope(ids, alpha, beta) if hand is None else
                AeroEnvelope(hand.ids + ids, np.concatenate([hand.alpha, alpha]),
                             np.concatenate([hand.beta, beta])))
    rows = []
    for name in ("alpha", "beta"):
        reached, margin, used = env.reached[name], bounds[name], bounds[name]
        hand_values = None if hand is None else getattr(hand, name)
        rows.append({"quantity": f"{name} range", "unit": "deg",
                     "hand-entered": "none" if hand_values is None else _range(hand_values),
                     "dynamics reached": f"{reached[0]:.4g} to {reached[1]:.4g}",
                     "with margin": f"{margin[0]:.4g} to {margin[1]:.4g}",
                     "used in the loads": f"hand points, and {used[0]:.4g} to {used[1]:.4g} "
                                          "(DYN-* points)",
                     "note": "; ".join(notes[name])})
    return envelope, ids, rows


def _hook(study, env, source):
    hook = study.hook
    k = env.margin
    lon = max(abs(v) for v in env.reached["hub load longitudinal"])
    lat = env.reached["hub load lateral"][1]
    lon_k, lat_k = k * lon, k * lat
    study_lat = np.degrees(hook.lateral)
    study_lon = np.degrees(hook.angle)
    if source == "dynamics":
        angle, lateral, cone = lon_k, lat_k, "elliptical"
        note = "the dynamics' angles x margin (the justified smaller angle), elliptical cone"
    else:
        angle, lateral, cone = max(study_lon, lon_k), max(study_lat, lat_k), hook.cone
        raised = [w for w, a, b in (("fore-and-aft", study_lon, lon_k),
                                    ("lateral", study_lat, lat_k)) if b > a]
        note = ("CS-29.865: the Study's angles kept" if not raised else
                f"CS-29.865: {' and '.join(raised)} angle raised to the dynamics' x margin "
                "(the maximum angle achievable in service)")
    if not (angle < 90 and lateral < 90):
        raise InputError("the dynamics' hub-load angle x margin reaches 90 deg: no hook cone",
                         max(angle, lateral))
    nz = max(hook.nz, env.tension_factor)
    new = replace(hook, angle=np.radians(angle), lateral_angle=(
        np.radians(lateral) if not np.isclose(lateral, angle) else None), cone=cone, nz=nz)
    rows = [
        {"quantity": "hook cone, fore-and-aft angle from the vertical", "unit": "deg",
         "hand-entered": study_lon, "dynamics reached": lon, "with margin": lon_k,
         "used in the loads": angle, "note": note},
        {"quantity": "hook cone, lateral angle from the vertical", "unit": "deg",
         "hand-entered": study_lat, "dynamics reached": lat, "with margin": lat_k,
         "used in the loads": lateral, "note": ""},
        {"quantity": "hub load from the hanging vertical (total)", "unit": "deg",
         "hand-entered": np.nan, "dynamics reached": env.reached["hub load from vertical"][1],
         "with margin": np.degrees(env.hook_angle), "used in the loads": np.nan,
         "note": "for information: the cone is taken fore-and-aft and sideways"},
        {"quantity": "hook load factor Nz", "unit": "-", "hand-entered": hook.nz,
         "dynamics reached": env.reached["tension / weight"][1],
         "with margin": env.tension_factor, "used in the loads": nz,
         "note": "the Study's Nz kept" if nz == hook.nz
                 else "raised to the dynamics' peak tension factor x margin"},
    ]
    return new, rows


def _parachute(study, env, chosen_area, source="study"):
    if study.parachute is None:
        return None, None, [{"quantity": "parachute", "unit": "", "hand-entered": "none",
                             "dynamics reached": f"{env.area:.6g} m^2",
                             "with margin": np.nan, "used in the loads": "none",
                             "note": "the loads study has no parachute ('parachute area' 0): "
                                     "no parachute case added"}]
    chosen = env.area if chosen_area is None else chosen_area
    area = study.parachute.area if source == "study" else chosen
    chute = replace(study.parachute, area=area)
    q = study.flight.dynamic_pressure

    def drag(parachute):
        return float(np.asarray(parachute.drag(q, 0.0, opening=True)).reshape(-1)[0])

    line = env.chute_drag_at(q, area)
    if not np.isfinite(line):
        line = env.chute_drag
    ids, theta, psi = env.line_directions()
    p0, p1 = env.mirrored("line psi")
    psi = np.radians(np.array([0.0, p1, p0, p1, p0]))
    cases = DynamicsCases(line_ids=ids, line_theta=theta, line_psi=psi, line_force=line)
    t0, t1 = env.bounds("line theta")
    rows = [
        {"quantity": "parachute area", "unit": "m^2", "hand-entered": study.parachute.area,
         "dynamics reached": env.area, "with margin": np.nan, "used in the loads": area,
         "note": (f"the Study's parachute kept (the campaign's chosen: {chosen:.6g} m^2, "
                  f"{env.area_factor:g} x neutral area)" if source == "study" else
                  f"the campaign's chosen parachute, {env.area_factor:g} x neutral area, in "
                  f"place of the Study's {study.parachute.area:.6g} m^2")},
        {"quantity": "parachute load", "unit": "N", "hand-entered": drag(study.parachute),
         "dynamics reached": env.reached["line tension"][1], "with margin": env.chute_drag,
         "used in the loads": line,
         "note": f"on the LINE-* cases: the runs' largest line tension over q x area x "
                 f"margin, at the loads' q {q:.4g} Pa and area {area:.6g} m^2 (the "
                 f"campaign's own peak x margin: {env.chute_drag:.4g} N); hand-entered: the "
                 f"parachute model's drag at the loads' airspeed, on the 'parachute on' "
                 f"cases"},
        {"quantity": "parachute line direction", "unit": "deg",
         "hand-entered": study.chute_line,
         "dynamics reached": (f"theta {env.reached['line theta'][0]:.4g} to "
                              f"{env.reached['line theta'][1]:.4g}, psi "
                              f"{env.reached['line psi'][0]:.4g} to "
                              f"{env.reached['line psi'][1]:.4g}"),
         "with margin": f"theta {t0:.4g} to {t1:.4g}, psi {p0:.4g} to {p1:.4g}",
         "used in the loads": ", ".join(ids),
         "note": "trailing direction and the corners of the range (psi mirrored about zero)"},
    ]
    return chute, cases, rows


def _flag_lowered(rows):
    """Mark the rows whose value used in the loads is below the hand-entered one."""
    for row in rows:
        hand, used = row.get("hand-entered"), row.get("used in the loads")
        lowered = (isinstance(hand, (int, float)) and isinstance(used, (int, float))
                   and np.isfinite(hand) and np.isfinite(used) and used < hand * (1 - 1e-9))
        row["lowered"] = bool(lowered)
        if lowered:
            row["note"] = (f"LOWER than the hand-entered value ({used:.4g} < {hand:.4g}); "
                           + row["note"])
    return rows


def loads_from_dynamics(study, envelope, hook_source="CS-29.865", chosen_area=None,
                        parachute="study"):
    """The loads study with the dynamics' cases (module notes).

    Parameters
    ----------
    study : LoadsStudy
        The hand-entered study.
    envelope : DynamicsEnvelope
    hook_source : {"CS-29.865", "dynamics"}
    chosen_area : float, optional
        The chosen parachute's area (default: the envelope's). [m^2]
    parachute : {"study", "chosen"}
        The parachute of the loads: the Study's (default) or the chosen one.

    Returns
    -------
    Handoff
    """
    if hook_source not in HOOK_SOURCES:
        raise InputError(f"{hook_source=!r} is not a valid hook-cone source; valid sources "
                         f"are {list(HOOK_SOURCES)}", hook_source)
    if not isinstance(study, LoadsStudy):
        raise InputError("the hand-off needs a LoadsStudy", type(study).__name__)
    if parachute not in PARACHUTE_SOURCES:
        raise InputError(f"{parachute=!r} is not a valid parachute source; valid sources are "
                         f"{list(PARACHUTE_SOURCES)}", parachute)
    rows = []
    aero_ids = ()
    new = {}
    if study.fuselage is not None or study.fin is not None:
        new["envelope"], aero_ids, aero_rows = _aero(study, envelope)
        rows += aero_rows
    new["hook"], hook_rows = _hook(study, envelope, hook_source)
    rows += hook_rows
    chute, cases, chute_rows = _parachute(study, envelope, chosen_area, parachute)
    rows += chute_rows
    if chute is not None:
        new["parachute"] = chute
    new["dynamics"] = DynamicsCases(
        aero_ids=aero_ids, line_ids=() if cases is None else cases.line_ids,
        line_theta=() if cases is None else cases.line_theta,
        line_psi=() if cases is None else cases.line_psi,
        line_force=0.0 if cases is None else cases.line_force,
        note=f"campaign runs at {envelope.area_factor:g} x neutral area, margin "
             f"{envelope.margin:g}")
    return Handoff(replace(study, **new), pd.DataFrame(_flag_lowered(rows)), envelope)


#: The comparison's hook-cone rows and the :class:`HookCone` angle (rad) each reports.
_HOOK_ROWS = {"hook cone, fore-and-aft angle from the vertical": "angle",
              "hook cone, lateral angle from the vertical": "lateral"}


def comparison_as_run(comparison, hook):
    """The hand-off's comparison with its hook-cone rows' "used in the loads" taken from the
    hook cone the loads were finally run with (``hook``): a later hand-off (the lateral
    study's recommended design angle, :mod:`slingloads.analyses.hook_angle`) may raise an
    angle after the campaign's, and the table must state the angle the loads used, not the
    campaign's.

    Parameters
    ----------
    comparison : pandas.DataFrame
        :attr:`Handoff.comparison`.
    hook : HookCone
        The hook cone of the loads study that was run.

    Returns
    -------
    pandas.DataFrame
        A copy; a row whose angle was raised says so in its note.
    """
    table = comparison.copy()
    for quantity, attribute in _HOOK_ROWS.items():
        rows = np.nonzero((table["quantity"] == quantity).to_numpy())[0]
        for i in rows:
            used = float(np.degrees(getattr(hook, attribute)))
            before = pd.to_numeric(pd.Series([table["used in the loads"].iloc[i]]),
                                   errors="coerce").iloc[0]
            if np.isfinite(before) and used > before * (1 + 1e-12):
                note = str(table["note"].iloc[i] or "")
                table.iloc[i, table.columns.get_loc("used in the loads")] = used
                table.iloc[i, table.columns.get_loc("note")] = "; ".join(
                    t for t in (note, f"raised from {angle_words(before)} deg by the lateral "
                                      "study's recommended design angle") if t)
    return table


def loads_comparison(result):
    """Largest |limit load| of each component over the fuselage: the hand-entered cases
    against the cases from the dynamics (the ``source`` column of the case matrix).

    Parameters
    ----------
    result : LoadsResult
        Internal loads of the hand-entered and the dynamics cases.

    Returns
    -------
    pandas.DataFrame or None
        None when no case comes from the dynamics.
    """
    from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS

    source = result.cases["source"].to_numpy() if "source" in result.cases else None
    if source is None or not np.any(source == "dynamics"):
        return None
    rows = []
    for j, name in enumerate(COMPONENTS):
        hand = np.abs(result.loads[source == "hand", :, j]).max(initial=0.0)
        dyn = np.abs(result.loads[source == "dynamics", :, j]).max(initial=0.0)
        rows.append({"component": name, "kind": COMPONENT_KINDS[j],
                     "hand-entered cases": hand, "dynamics cases": dyn,
                     "dynamics / hand [-]": dyn / hand if hand > 0 else np.nan})
    return pd.DataFrame(rows)

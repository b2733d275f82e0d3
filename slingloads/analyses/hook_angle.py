"""The CS-29.865 hook cases with the lateral directions at another angle: the link from the
lateral study's recommended design angle to the structural loads.

:func:`hook_angle_comparison` runs the hook cases of a loads study (the vertical and the cone's
azimuths, Nz x weight, inertia relief, without the aerodynamic and parachute loads, which do
not depend on the cone angle) at the 30 deg of CS-29.865, and again with the **lateral
directions only** at another angle (the lateral-step study justifies lateral directions, not
fore-and-aft ones: :class:`~slingloads.analyses.hook_loads.HookLoadOptions` ``lateral_angle``
and ``cone``), and compares the envelopes max |load| per station and component.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from slingloads.analyses.hook_loads import VERTICAL, angle_words
from slingloads.analyses.lateral import REGULATORY_ANGLE
from slingloads.analyses.sfbm import COMPONENT_KINDS, COMPONENTS

#: Order of the load components in the comparison: Y shear first (the paper's point).
COMPARISON_ORDER = ("Vy", "Mz", "Mx", "Vx", "Vz", "My")
#: SI unit labels of the load components' kinds.
SI_LABELS = {"force": "N", "moment": "N m"}


@dataclass(frozen=True, eq=False)
class HookAngleComparison:
    """Envelopes max |load| of the CS-29.865 hook cases at two cone angles.

    Attributes
    ----------
    reference_angle : float
        The CS-29.865 angle (30 deg). [rad]
    angle : float
        The compared angle (the recommended design angle). [rad]
    station_ids : tuple of str
    stations : ndarray, shape (s,)
        [m]
    reference : ndarray, shape (s, 6)
        max over the hook cases of |load| at ``reference_angle``. [N, N m]
    at_angle : ndarray, shape (s, 6)
        The same with the lateral directions at ``angle``. [N, N m]
    cases : tuple of str
        Hook directions run (VERTICAL, AZ000...).
    reduced : tuple of str
        Directions whose inclination ``angle`` replaced the reference (the lateral ones);
        the others keep ``reference_angle``.
    cone : str
        Where the lateral angle applies (``HookLoadOptions.cone``).
    """

    reference_angle: float
    angle: float
    station_ids: tuple
    stations: np.ndarray
    reference: np.ndarray
    at_angle: np.ndarray
    cases: tuple
    reduced: tuple = ()
    cone: str = "lateral directions"

    def reduced_note(self):
        """Which directions were taken at the compared angle, and which kept the reference.

        Returns
        -------
        str
        """
        ref = angle_words(np.degrees(self.reference_angle))
        at = angle_words(np.degrees(self.angle))
        if not self.reduced:
            return (f"No hook direction is lateral: every direction kept {ref} deg (the "
                    "lateral study justifies lateral directions only).")
        kept = [c for c in self.cases if c not in self.reduced and c != VERTICAL]
        how = ("pure lateral directions only" if self.cone == "lateral directions"
               else "elliptical cone between the fore-and-aft and the lateral angle")
        return (f"Directions at {at} deg ({how}): {', '.join(self.reduced)}. Kept at "
                f"{ref} deg (the lateral study gives no evidence for them): "
                f"{', '.join(kept) or 'none'}.")

    @property
    def reduction(self):
        """100 (1 - at_angle / reference) per station and component; 0 where both are
        zero. [%]"""
        scale = np.abs(self.reference).max(axis=0, keepdims=True)
        tiny = 1e-12 * np.maximum(scale, 1.0)
        ok = self.reference > tiny
        out = np.zeros_like(self.reference)
        np.divide(self.at_angle, self.reference, out=out, where=ok)
        return np.where(ok, 100.0 * (1.0 - out), np.where(self.at_angle > tiny, -np.inf, 0.0))

    def labels(self):
        """The two cones as column-label fragments: ``("at 30 deg", "lateral at 21.3 deg")``.

        Returns
        -------
        tuple of str
        """
        return (f"at {angle_words(np.degrees(self.reference_angle))} deg",
                f"lateral at {angle_words(np.degrees(self.angle))} deg")

    def station_frame(self):
        """Per station: each component's envelope at both angles and the reduction, Y shear
        first (SI, unit-labelled columns: ``x [m]``, ``max |Vy| at 30 deg [N]``...).

        Returns
        -------
        pandas.DataFrame
            A row per station.
        """
        ref, at = self.labels()
        frame = {"station": list(self.station_ids), "x [m]": self.stations}
        red = self.reduction
        for name in COMPARISON_ORDER:
            j = COMPONENTS.index(name)
            unit = SI_LABELS[COMPONENT_KINDS[j]]
            frame[f"max |{name}| {ref} [{unit}]"] = self.reference[:, j]
            frame[f"max |{name}| {at} [{unit}]"] = self.at_angle[:, j]
            frame[f"{name} reduction [%]"] = red[:, j]
        return pd.DataFrame(frame)

    def summary_frame(self):
        """Per component: the largest envelope value along the airframe at both angles, where
        it occurs, and the reduction, Y shear first (SI; the ``unit`` column gives each
        row's unit).

        Returns
        -------
        pandas.DataFrame
            A row per component.
        """
        ref, at = self.labels()
        rows = []
        for name in COMPARISON_ORDER:
            j = COMPONENTS.index(name)
            i_ref = int(np.argmax(self.reference[:, j]))
            i_at = int(np.argmax(self.at_angle[:, j]))
            big_ref, big_at = self.reference[i_ref, j], self.at_angle[i_at, j]
            rows.append({
                "component": name,
                f"largest {ref}": float(big_ref),
                f"station {ref}": self.station_ids[i_ref],
                f"largest {at}": float(big_at),
                f"station {at}": self.station_ids[i_at],
                "unit": SI_LABELS[COMPONENT_KINDS[j]],
                "reduction [%]": 100.0 * (1.0 - big_at / big_ref) if big_ref > 0 else 0.0,
            })
        return pd.DataFrame(rows)


def hook_angle_comparison(loads_study, angle, reference_angle=REGULATORY_ANGLE):
    """Envelopes of the CS-29.865 hook cases alone, at 30 deg and with the lateral directions
    at a smaller (or larger) angle.

    The hook cases are the loads study's hook directions (the vertical and the azimuths of the
    cone) with gravity and inertia relief, without the aerodynamic and parachute loads, which
    do not depend on the cone angle. The lateral-step study justifies lateral directions only,
    so ``angle`` replaces ``reference_angle`` only where the study's cone shape puts the
    lateral angle (``HookLoadOptions.cone``: the pure lateral azimuths 90 and 270 deg by
    default); the other directions keep ``reference_angle``. Each cone is one run of
    :meth:`LoadsStudy.run <slingloads.analyses.loads.LoadsStudy.run>`.

    Parameters
    ----------
    loads_study : LoadsStudy
    angle : float
        Lateral angle to compare, in [0, 90) deg (e.g. the recommended design angle). [rad]
    reference_angle : float
        The CS-29.865 angle. [rad]

    Returns
    -------
    HookAngleComparison

    Raises
    ------
    InputError
        For an angle outside [0, 90) deg.
    """
    hooks = replace(loads_study, envelope=None, fuselage=None, fin=None, parachute=None,
                    listed=(), generate=True, previous_envelope=None)
    studies = [replace(hooks, hook=replace(hooks.hook, angle=float(reference_angle),
                                           lateral_angle=lateral))
               for lateral in (None, float(angle))]
    runs = [s.run() for s in studies]
    ref, at = (np.abs(r.loads).max(axis=0) for r in runs)
    table = studies[1].hook_table()
    return HookAngleComparison(float(reference_angle), float(angle),
                               tuple(runs[0].station_ids), np.asarray(runs[0].stations),
                               ref, at, tuple(runs[0].cases["hook"]),
                               tuple(table.loc[table["reduced"], "hook"]),
                               studies[1].hook.cone)


#: Who sets the loads' lateral hook angle (:class:`HookAngleHandoff` ``governs``).
GOVERNS_LATERAL = "lateral study"
GOVERNS_STUDY = "Study"


@dataclass(frozen=True, eq=False)
class HookAngleHandoff:
    """The lateral study's recommended design angle handed to the loads: the lateral hook
    cases take the larger of the loads' own lateral angle and the recommended one, never
    less than the loads' own.

    Attributes
    ----------
    study : LoadsStudy
        The loads study with that lateral angle.
    loads_angle : float
        The lateral angle the loads had before (the Study's, or the campaign's hand-off's when
        it raised it). [rad]
    recommended : float
        The lateral study's recommended design angle; NaN when it gives none (no case
        inside its domain, or 90 deg or more with the margin). [rad]
    used : float
        ``max(loads_angle, recommended)``; ``loads_angle`` when ``recommended`` is NaN.
        [rad]
    governs : str
        :data:`GOVERNS_LATERAL` when the recommended angle is larger, else
        ``loads_source``.
    reason : str
        Why, in words.
    loads_source : str
        Where ``loads_angle`` comes from (``"Study"``, or the campaign's hand-off).
    """

    study: object
    loads_angle: float
    recommended: float
    used: float
    governs: str
    reason: str
    loads_source: str = GOVERNS_STUDY

    def to_frame(self):
        """The three angles and which one governs, one row each (deg).

        Returns
        -------
        pandas.DataFrame
            Columns item, value, unit, note.
        """
        rec = np.degrees(self.recommended)
        return pd.DataFrame([
            ("lateral hook angle of the loads' own inputs", float(np.degrees(self.loads_angle)),
             "deg", f"from the {self.loads_source}"),
            ("lateral study's recommended design angle", float(rec), "deg",
             "margin x largest load angle inside the lateral model's domain"
             if np.isfinite(rec) else "none: " + self.reason),
            ("lateral hook angle used by the loads", float(np.degrees(self.used)), "deg",
             f"governed by the {self.governs}"),
        ], columns=["item", "value", "unit", "note"])

    def describe(self):
        """One sentence: the angle used, both angles and which governs, and why.

        Returns
        -------
        str
        """
        used, own = np.degrees(self.used), np.degrees(self.loads_angle)
        rec = np.degrees(self.recommended)
        rec_text = f"{rec:.1f} deg" if np.isfinite(rec) else "none"
        return (f"Lateral hook cases at {used:.1f} deg = max({self.loads_source} {own:.1f} deg, "
                f"lateral study's recommended {rec_text}): the {self.governs} governs; "
                f"{self.reason}.")


def lateral_hook_handoff(loads_study, recommended, why_none="", loads_source=GOVERNS_STUDY):
    """The loads study with its lateral hook directions at the lateral study's recommended
    design angle where that is larger (CS 29.865: the maximum angle achievable in service;
    the conservative value wins, the loads' own angle is never lowered).

    Parameters
    ----------
    loads_study : LoadsStudy
    recommended : float
        The lateral study's recommended design angle; NaN when it gives none. [rad]
    why_none : str
        Why it gives none (quoted when ``recommended`` is NaN).
    loads_source : str
        Where the loads' own lateral angle comes from (printed).

    Returns
    -------
    HookAngleHandoff
    """
    hook = loads_study.hook
    own = float(hook.lateral)
    rec = float(recommended)
    if not np.isfinite(rec):
        reason = ("the lateral study gives no design angle"
                  + (f" ({why_none.rstrip('.')})" if why_none else "")
                  + f": the {loads_source}'s angle is kept")
        return HookAngleHandoff(loads_study, own, np.nan, own, loads_source, reason,
                                loads_source)
    if rec > own:
        new = replace(loads_study, hook=replace(hook, lateral_angle=rec))
        reason = (f"its recommended angle exceeds the loads' {np.degrees(own):.1f} deg, so the "
                  "larger (conservative) angle is used")
        return HookAngleHandoff(new, own, rec, rec, GOVERNS_LATERAL, reason, loads_source)
    reason = ("the loads' angle already covers the lateral study's recommended angle and is "
              "never lowered to it")
    return HookAngleHandoff(loads_study, own, rec, own, loads_source, reason, loads_source)

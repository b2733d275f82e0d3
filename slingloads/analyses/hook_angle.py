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

from slingloads.analyses.hook_loads import VERTICAL
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
        ref, at = np.degrees(self.reference_angle), np.degrees(self.angle)
        if not self.reduced:
            return (f"No hook direction is lateral: every direction kept {ref:.4g} deg (the "
                    "lateral study justifies lateral directions only).")
        kept = [c for c in self.cases if c not in self.reduced and c != VERTICAL]
        how = ("pure lateral directions only" if self.cone == "lateral directions"
               else "elliptical cone between the fore-and-aft and the lateral angle")
        return (f"Directions at {at:.4g} deg ({how}): {', '.join(self.reduced)}. Kept at "
                f"{ref:.4g} deg (the lateral study gives no evidence for them): "
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
        return (f"at {np.degrees(self.reference_angle):.4g} deg",
                f"lateral at {np.degrees(self.angle):.4g} deg")

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

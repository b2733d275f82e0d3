"""The CS-29.865 hook cases at two cone angles: the link from the lateral study's recommended
design angle to the structural loads.

:func:`hook_angle_comparison` runs the hook cases of a loads study (mast axis and the cone's
azimuths, Nz x weight, inertia relief, without the aerodynamic and parachute loads, which do
not depend on the cone angle) at the 30 deg of CS-29.865 and at another angle, and compares
the envelopes max |load| per station and component.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

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
        The same at ``angle``. [N, N m]
    cases : tuple of str
        Hook directions run (AXIAL, AZ000...).
    """

    reference_angle: float
    angle: float
    station_ids: tuple
    stations: np.ndarray
    reference: np.ndarray
    at_angle: np.ndarray
    cases: tuple

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
        """The two angles as column-label fragments: ``("at 30 deg", "at 21.3 deg")``."""
        return (f"at {np.degrees(self.reference_angle):.4g} deg",
                f"at {np.degrees(self.angle):.4g} deg")

    def station_frame(self):
        """Per station: each component's envelope at both angles and the reduction, Y shear
        first (SI, unit-labelled columns: ``x [m]``, ``max |Vy| at 30 deg [N]``...)."""
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
        row's unit)."""
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
    """Envelopes of the CS-29.865 hook cases alone at two cone angles.

    The hook cases are the loads study's hook directions (mast axis and the azimuths of the
    cone) with gravity and inertia relief, without the aerodynamic and parachute loads, which
    do not depend on the cone angle. Each angle is one run of
    :meth:`LoadsStudy.run <slingloads.analyses.loads.LoadsStudy.run>`.

    Parameters
    ----------
    loads_study : LoadsStudy
    angle : float
        Cone angle to compare, in [0, 90) deg (e.g. the recommended design angle). [rad]
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
    runs = [hooks.with_hook(angle=float(a)).run() for a in (reference_angle, angle)]
    ref, at = (np.abs(r.loads).max(axis=0) for r in runs)
    return HookAngleComparison(float(reference_angle), float(angle),
                               tuple(runs[0].station_ids), np.asarray(runs[0].stations),
                               ref, at, tuple(runs[0].cases["hook"]))

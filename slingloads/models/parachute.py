"""Drogue parachute modelled as a flat-plate area (paper, section 3.3).

Drag magnitude :math:`D = k_{open}\\, q\\, \\eta_{wake}\\, C_D(\\alpha_p)\\, A`, where
:math:`\\eta_{wake}` is the ratio of the dynamic pressure at the canopy (in the fuselage wake)
to the free-stream one and :math:`\\alpha_p` the canopy's angle of attack. The paper takes
:math:`C_D = 0.95` over +-8 deg, lift and moment zero.

Note: the paper explains its 0.95 drag coefficient by the 5 % wake loss. If a tabulated
``CD`` already contains the wake loss, set ``wake_ratio`` to 1 so the loss is not counted twice.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D

#: The paper's drag coefficient and its angle-of-attack validity range [rad].
PAPER_CD = 0.95
PAPER_CD_RANGE = np.radians(8.0)


def paper_cd_table():
    """The paper's parachute drag table: CD = 0.95 for alpha in [-8, 8] deg."""
    return Table1D(np.array([-PAPER_CD_RANGE, PAPER_CD_RANGE]),
                   {"CD": np.array([PAPER_CD, PAPER_CD])}, angle_name="alpha",
                   what="parachute")


#: Canopy drag coefficient the extended table keeps broadside and in reverse flow. [-]
COLLAPSED_CD = 0.4


def extended_cd_table(cd=PAPER_CD, valid=PAPER_CD_RANGE, collapsed=COLLAPSED_CD):
    """GENERIC canopy drag table over the whole circle of canopy angle of attack.

    The paper's CD (0.95) over +-8 deg, then a cosine-squared fall to ``collapsed`` at 90 deg,
    held beyond (flow from the side or from behind: a partly collapsed canopy). Only the
    +-8 deg part comes from the paper; the rest is an assumption of this generic set, there so
    that a hinged parachute can be flown from hover, where it hangs below its attachment and
    meets the flow at up to 90 deg as the airspeed builds.

    Returns
    -------
    Table1D
        ``CD`` against alpha, -180 to 180 deg every 2 deg (and at +-``valid``).
    """
    grid = np.union1d(np.radians(np.arange(-180.0, 180.0 + 1e-9, 2.0)), [-valid, valid])
    a = np.abs(grid)
    fall = np.clip((a - valid) / (0.5 * np.pi - valid), 0.0, 1.0)
    values = collapsed + (cd - collapsed) * np.cos(0.5 * np.pi * fall) ** 2
    return Table1D(grid, {"CD": values}, angle_name="alpha", what="parachute")


@dataclass(frozen=True)
class Parachute:
    """Stabilising drogue parachute.

    Parameters
    ----------
    area : float
        Flat-plate area A. [m^2]
    cd : Table1D
        Drag coefficient ``CD`` against the canopy angle of attack (default: the paper's).
    wake_ratio : float
        Dynamic pressure at the canopy over free-stream dynamic pressure, 0 < eta <= 1. [-]
    line_length : float
        Length of the line from the fin attachment to the canopy. [m]
    opening_factor : float
        Opening-load factor applied to the drag in the loads cases, >= 1. [-]
    """

    area: float
    cd: Table1D | None = None
    wake_ratio: float = 0.95
    line_length: float = 10.0
    opening_factor: float = 1.0

    def __post_init__(self):
        area = float(self.area)
        if not np.isfinite(area) or area <= 0:
            raise InputError("parachute flat-plate area must be > 0 [m^2]", area)
        eta = float(self.wake_ratio)
        if not (0 < eta <= 1):
            raise InputError("parachute wake dynamic-pressure ratio must lie in (0, 1]", eta)
        line = float(self.line_length)
        if not np.isfinite(line) or line <= 0:
            raise InputError("parachute line length must be > 0 [m]", line)
        k = float(self.opening_factor)
        if not np.isfinite(k) or k < 1:
            raise InputError("parachute opening-load factor must be >= 1", k)
        cd = paper_cd_table() if self.cd is None else self.cd
        if "CD" not in cd.coefficients:
            raise InputError("parachute table needs a CD column")
        values = cd.coefficients["CD"]
        if np.any((values <= 0) | (values > 2.0)):
            raise InputError("parachute CD must lie in (0, 2] (a flat plate normal to the "
                             "flow has 1.17)", float(values[(values <= 0) | (values > 2)][0]))
        if not (cd.angle[0] <= 0 <= cd.angle[-1]):
            raise InputError("parachute CD table must include alpha = 0 deg",
                             np.degrees(cd.angle).tolist())
        object.__setattr__(self, "area", area)
        object.__setattr__(self, "wake_ratio", eta)
        object.__setattr__(self, "line_length", line)
        object.__setattr__(self, "opening_factor", k)
        object.__setattr__(self, "cd", cd)

    def drag_area(self, alpha=0.0):
        """Effective drag area eta_wake * CD(alpha) * A [m^2] (no opening factor)."""
        return self.wake_ratio * self.cd("CD", alpha) * self.area

    def drag(self, q, alpha=0.0, opening=False):
        """Drag magnitude [N] at free-stream dynamic pressure ``q`` [Pa].

        Parameters
        ----------
        q : array_like
            [Pa]
        alpha : array_like
            Canopy angle of attack. [rad]
        opening : bool
            Multiply by the opening-load factor.
        """
        factor = self.opening_factor if opening else 1.0
        return factor * np.asarray(q, float) * self.drag_area(alpha)

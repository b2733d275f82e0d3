"""Drogue parachute modelled as a flat-plate area (paper, section 3.3).

Drag magnitude :math:`D = k_{open}\\, q\\, \\eta_{wake}\\, C_D(\\alpha_p)\\, A`, where
:math:`\\eta_{wake}` is the ratio of the dynamic pressure at the canopy (in the fuselage wake)
to the free-stream one and :math:`\\alpha_p` the canopy's angle of attack.

**The wake loss is counted once, in the wake ratio.** The paper's drag coefficient of 0.95
over +-8 deg (lift and moment zero) is a canopy coefficient of one reduced by the 5 %
dynamic-pressure loss in the fuselage wake (its sections 3.2 and 3.3). Here the default
canopy table is the free-stream coefficient, **CD = 1.0** within +-8 deg, and the default
**wake ratio is 0.95**, so the product is the paper's 0.95. The wake ratio carries the loss
because it belongs to the installation, not to the canopy: it is what the wake sizing gives
at the chosen line length (:mod:`slingloads.models.wake`, the 'target q ratio'), and a longer
line changes it while the canopy's coefficient stays. A user whose tabulated coefficient
already contains the wake loss (as the paper's 0.95 does) sets the wake ratio to 1.

The table's axes are declared (``docs/conventions.md``, section 5):

* ``"wind"`` (default): column ``CD``, the force along the canopy's relative wind (lift and
  side force zero, the paper's flat-plate model);
* ``"canopy"``: column ``CT``, the tangential force along the canopy's symmetry axis, which
  lies along the line (normal force zero).

With the line along the relative wind (canopy angle of attack 0) both give the same force.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D

#: The paper's effective drag coefficient (canopy coefficient x wake ratio) and its
#: angle-of-attack validity range [rad].
PAPER_CD = 0.95
PAPER_CD_RANGE = np.radians(8.0)
#: Free-stream drag coefficient of the canopy (the paper: "equal to one or almost one"). [-]
CANOPY_CD = 1.0
#: Dynamic-pressure ratio at the canopy in the fuselage wake (the paper's q_loss = 0.95). [-]
WAKE_RATIO = 0.95
#: Largest force coefficient of a parachute table (a flat plate normal to the flow has 1.17). [-]
PARACHUTE_CD_MAX = 2.0
#: Axes a parachute table may be given in, with the name of its coefficient column.
PARACHUTE_AXES = {"wind": "CD", "canopy": "CT"}


def canopy_cd_table():
    """Default canopy drag table: free-stream CD = 1.0 for alpha in [-8, 8] deg, wind axes.

    Times the default wake ratio 0.95 it gives the paper's effective 0.95 (section 3.3).

    Returns
    -------
    Table1D
        Column ``CD`` [-] against alpha [rad].
    """
    return Table1D(np.array([-PAPER_CD_RANGE, PAPER_CD_RANGE]),
                   {"CD": np.array([CANOPY_CD, CANOPY_CD])}, angle_name="alpha",
                   what="parachute")


#: Canopy drag coefficient the extended table keeps broadside and in reverse flow. [-]
COLLAPSED_CD = 0.4


def extended_cd_table(cd=CANOPY_CD, valid=PAPER_CD_RANGE, collapsed=COLLAPSED_CD):
    """GENERIC canopy drag table over the whole circle of canopy angle of attack, free stream.

    The canopy's free-stream CD (1.0; with the default wake ratio 0.95 the paper's 0.95) over
    +-8 deg, then a cosine-squared fall to ``collapsed`` at 90 deg, held beyond (flow from the
    side or from behind: a partly collapsed canopy). Only the +-8 deg part comes from the
    paper; the rest is an assumption of this generic set, there so that a hinged parachute can
    be flown from hover, where it hangs below its attachment and meets the flow at up to 90 deg
    as the airspeed builds. Like every canopy table here it carries no wake loss: the
    parachute's wake ratio does.

    Parameters
    ----------
    cd : float
        Free-stream CD over the valid range. [-]
    valid : float
        Half-width of the range of constant CD. [rad]
    collapsed : float
        CD broadside and in reverse flow. [-]

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
        Force coefficient against the canopy angle of attack, free stream (default:
        :func:`canopy_cd_table`, CD 1.0 within +-8 deg): column ``CD`` in wind axes, ``CT``
        in canopy axes.
    wake_ratio : float
        Dynamic pressure at the canopy over free-stream dynamic pressure, 0 < eta <= 1
        (default 0.95, the paper's wake loss; 1 if ``cd`` already contains it). [-]
    line_length : float
        Length of the line from the fin attachment to the canopy. [m]
    opening_factor : float
        Opening-load factor applied to the drag in the loads cases, >= 1. [-]
    axes : str
        Axes of ``cd``: ``"wind"`` (drag along the relative wind) or ``"canopy"``
        (tangential force along the canopy axis).
    """

    area: float
    cd: Table1D | None = None
    wake_ratio: float = WAKE_RATIO
    line_length: float = 10.0
    opening_factor: float = 1.0
    axes: str = "wind"

    def __post_init__(self):
        area = float(self.area)
        if not np.isfinite(area) or area <= 0:
            raise InputError("parachute flat-plate area must be > 0 [m^2]", area,
                             field="area")
        eta = float(self.wake_ratio)
        if not (0 < eta <= 1):
            raise InputError("parachute wake dynamic-pressure ratio must lie in (0, 1]", eta,
                             field="wake_ratio")
        line = float(self.line_length)
        if not np.isfinite(line) or line <= 0:
            raise InputError("parachute line length must be > 0 [m]", line,
                             field="line_length")
        k = float(self.opening_factor)
        if not np.isfinite(k) or k < 1:
            raise InputError("parachute opening-load factor must be >= 1", k,
                             field="opening_factor")
        if self.axes not in PARACHUTE_AXES:
            raise InputError(f"parachute table axes must be one of {list(PARACHUTE_AXES)}",
                             self.axes)
        column = PARACHUTE_AXES[self.axes]
        cd = canopy_cd_table() if self.cd is None else self.cd
        if self.cd is None and self.axes == "canopy":
            cd = Table1D(cd.angle, {"CT": cd.coefficients["CD"]}, "alpha", "parachute")
        if column not in cd.coefficients:
            raise InputError(f"a parachute table in {self.axes} axes needs a {column} column",
                             sorted(cd.coefficients))
        values = cd.coefficients[column]
        bad = (values <= 0) | (values > PARACHUTE_CD_MAX)
        if np.any(bad):
            i = int(np.argmax(bad))
            raise InputError(f"parachute {column} must lie in (0, {PARACHUTE_CD_MAX:g}] (a flat "
                             "plate normal to the flow has 1.17)", float(values[i]),
                             field=column, index=i)
        if not (cd.angle[0] <= 0 <= cd.angle[-1]):
            raise InputError("parachute CD table must include alpha = 0 deg",
                             np.degrees(cd.angle).tolist())
        object.__setattr__(self, "area", area)
        object.__setattr__(self, "wake_ratio", eta)
        object.__setattr__(self, "line_length", line)
        object.__setattr__(self, "opening_factor", k)
        object.__setattr__(self, "cd", cd)

    @property
    def column(self):
        """Name of the coefficient column of :attr:`cd` (``CD`` or ``CT``)."""
        return PARACHUTE_AXES[self.axes]

    def coefficient(self, alpha=0.0):
        """Free-stream force coefficient CD (wind axes) or CT (canopy axes); no wake ratio.

        Parameters
        ----------
        alpha : array_like
            Canopy angle of attack. [rad]

        Returns
        -------
        ndarray
            [-]
        """
        return self.cd(self.column, alpha)

    def effective_coefficient(self, alpha=0.0):
        """Coefficient times the wake ratio: the one factor the drag uses.

        Parameters
        ----------
        alpha : array_like
            Canopy angle of attack. [rad]

        Returns
        -------
        ndarray
            [-]
        """
        return self.wake_ratio * self.coefficient(alpha)

    def drag_area(self, alpha=0.0):
        """Effective drag area eta_wake CD(alpha) A (no opening factor).

        Parameters
        ----------
        alpha : array_like
            Canopy angle of attack. [rad]

        Returns
        -------
        ndarray
            [m^2]
        """
        return self.effective_coefficient(alpha) * self.area

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

        Returns
        -------
        ndarray
            Drag. [N]
        """
        factor = self.opening_factor if opening else 1.0
        return factor * np.asarray(q, float) * self.drag_area(alpha)

    def force_direction(self, wind, canopy_axis):
        """Unit direction of the drag on the airframe, airframe axes, shape (n, 3).

        Parameters
        ----------
        wind : ndarray, shape (n, 3)
            Direction of the relative wind at the canopy (downstream). [-]
        canopy_axis : ndarray, shape (n, 3)
            Direction of the line from the attachment to the canopy. [-]

        Returns
        -------
        ndarray, shape (n, 3)
            Unit vector, airframe axes. [-]
        """
        return np.asarray(wind if self.axes == "wind" else canopy_axis, float)

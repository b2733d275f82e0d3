"""Dynamic-pressure ratio in the wake behind the fuselage, and the parachute line length.

The drogue rides in the carried helicopter's wake, where the dynamic pressure is lower than in
the free stream. The ratio eta(x) = q_wake / q at a distance x behind the fuselage comes either
from a table the user supplies (CFD, as in the paper's section 3.2) or from an empirical
bluff-body wake model driven by the fuselage drag area.

Empirical model (:class:`BluffBodyWake`)
----------------------------------------
Far from a three-dimensional bluff body the turbulent wake becomes self-similar: its width grows
as x^(1/3) and its centreline velocity defect decays as x^(-2/3) [1]_ [2]_ [3]_. Momentum
conservation fixes the defect by the drag, D = rho U int(u_d dA) (small defect), i.e.
int(u_d / U dA) = C_D S / 2. With a Gaussian defect profile of half-width (half defect) b,

.. math::

    \\frac{u_d}{U}(x, r) = K \\frac{(C_D S)^{1/3}}{(x - x_0)^{2/3}}
        \\exp\\left(-\\ln 2\\, \\frac{r^2}{b^2}\\right), \\qquad
    b = \\sqrt{\\frac{\\ln 2}{2 \\pi K}}\\,(C_D S)^{1/3} (x - x_0)^{1/3}

which satisfies the momentum integral exactly for any K. The dynamic-pressure ratio is
``(1 - u_d/U)^2``, on the wake axis (the conservative default) or averaged over a canopy disc of
area A centred on the axis (closed form for the Gaussian profile).

Assumptions: far wake (several body lengths; the near wake just behind the body is not
similar and its defect is larger, so the model is not used closer than ``min_distance``);
small defect; a single axisymmetric wake of the whole drag area C_D S (fuselage plus hub);
the canopy on the wake axis; no carrier downwash. K is an empirical order-one constant; the
default 1.0 is a round value of the order of the classical similarity solutions. It is **not
calibrated on helicopter fuselages**: the distance for a given ratio scales as K^(3/2), so
prefer a CFD or test table (:class:`TabulatedWake`) whenever one exists.

References
----------
.. [1] S. F. Hoerner, "Fluid-Dynamic Drag", Hoerner Fluid Dynamics, 1965, chapter 3 (wake
   behind bodies and the drag-area scaling of the wake).
.. [2] H. Schlichting, "Boundary-Layer Theory", 7th ed., McGraw-Hill, 1979, chapter XXIV
   (free turbulent flows; the rotationally symmetric wake).
.. [3] S. B. Pope, "Turbulent Flows", Cambridge University Press, 2000, section 5.4
   (self-similar axisymmetric wake: width ~ x^(1/3), defect ~ x^(-2/3)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import positive
from slingloads.errors import InputError

#: Default target dynamic-pressure ratio at the canopy (the paper's 0.95).
TARGET_RATIO = 0.95
#: Default margin by which the carrier's cable must exceed the parachute line (paper: 20 %).
CABLE_MARGIN = 0.20


def _positive(value, name, unit):
    return positive(value, f"{name} must be > 0 [{unit}]")


@dataclass(frozen=True)
class TabulatedWake:
    """Dynamic-pressure ratio against distance behind the fuselage, from CFD or test.

    Parameters
    ----------
    distance : array_like, shape (n,)
        Strictly increasing distances behind the fuselage (measured from the parachute
        attachment), >= 0. [m]
    ratio : array_like, shape (n,)
        q_wake / q at those distances, in (0, 1.2], not decreasing: the wake recovers
        downstream (its velocity deficit decays with distance). [-]
    source : str
        Where the table comes from, for reports.
    """

    distance: np.ndarray
    ratio: np.ndarray
    source: str = "user table"

    def __post_init__(self):
        x = np.asarray(self.distance, dtype=float)
        r = np.asarray(self.ratio, dtype=float)
        if x.ndim != 1 or x.size < 2 or r.shape != x.shape:
            raise InputError("a wake table needs at least two (distance, ratio) pairs, "
                             "one ratio per distance")
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(r))):
            raise InputError("wake table distances and ratios must be finite numbers")
        if x[0] < 0:
            raise InputError("wake table distances must be >= 0 [m]", x[0].item())
        steps = np.diff(x)
        if np.any(steps <= 0):
            i = int(np.argmax(steps <= 0)) + 1
            raise InputError("wake table distances must be strictly increasing [m]",
                             x[i].item())
        bad = (r <= 0) | (r > 1.2)
        if np.any(bad):
            raise InputError("wake dynamic-pressure ratios must lie in (0, 1.2]",
                             r[bad][0].item())
        falls = np.diff(r) < 0
        if np.any(falls):
            i = int(np.argmax(falls)) + 1
            raise InputError("wake dynamic-pressure ratios must not decrease downstream (a "
                             "wake recovers with distance)", r[i].item(), field="ratio",
                             index=i)
        object.__setattr__(self, "distance", x)
        object.__setattr__(self, "ratio", r)

    @property
    def range(self):
        """(first, last) tabulated distance. [m]"""
        return float(self.distance[0]), float(self.distance[-1])

    def __call__(self, distance):
        """Ratio [-] at ``distance`` [m]; error outside the table (no extrapolation)."""
        x = np.asarray(distance, dtype=float)
        lo, hi = self.range
        out = ~np.isfinite(x) | (x < lo) | (x > hi)
        if np.any(out):
            raise InputError(f"distance is outside the wake table's range [{lo:.6g}, "
                             f"{hi:.6g}] m; no extrapolation is done",
                             np.atleast_1d(x)[np.atleast_1d(out)][0].item())
        return np.interp(x, self.distance, self.ratio)

    def line_length(self, target=TARGET_RATIO):
        """Shortest distance at which the ratio reaches ``target`` (linear between points).

        Parameters
        ----------
        target : float
            Dynamic-pressure ratio q_wake / q to reach, in (0, 1]. [-]

        Returns
        -------
        float
            Distance behind the body. [m]

        Raises
        ------
        InputError
            If the table never reaches the target.
        """
        target = _check_target(target)
        reached = self.ratio >= target
        if not np.any(reached):
            raise InputError(
                f"the wake table never reaches the target dynamic-pressure ratio {target:.4g} "
                f"(largest {self.ratio.max():.4g} at {self.distance[np.argmax(self.ratio)]:.4g} "
                f"m); extend the table downstream", float(self.ratio.max()))
        i = int(np.argmax(reached))
        if i == 0:
            return float(self.distance[0])
        x0, x1 = self.distance[i - 1], self.distance[i]
        r0, r1 = self.ratio[i - 1], self.ratio[i]
        return float(x0 + (target - r0) * (x1 - x0) / (r1 - r0))


@dataclass(frozen=True)
class BluffBodyWake:
    """Empirical axisymmetric far-wake model driven by the fuselage drag area (module notes).

    Parameters
    ----------
    drag_area : float
        Fuselage (plus hub) drag area C_D S. [m^2]
    coefficient : float
        Empirical constant K of the centreline defect law. [-]
    virtual_origin : float
        Virtual origin x0 of the similarity law, measured from the attachment. [m]
    canopy_area : float, optional
        If given, the ratio is averaged over a disc of this area on the wake axis; otherwise
        the centreline value is used. [m^2]
    min_distance : float, optional
        Closest distance where the far-wake law is used (default: 2 equivalent diameters
        sqrt(4 C_D S / pi) beyond the virtual origin). [m]
    """

    drag_area: float
    coefficient: float = 1.0
    virtual_origin: float = 0.0
    canopy_area: float | None = None
    min_distance: float | None = None

    source = "bluff-body far-wake model (Hoerner; Schlichting)"

    def __post_init__(self):
        object.__setattr__(self, "drag_area", _positive(self.drag_area,
                                                        "fuselage drag area", "m^2"))
        object.__setattr__(self, "coefficient", _positive(self.coefficient,
                                                          "wake coefficient K", "-"))
        x0 = float(self.virtual_origin)
        if not np.isfinite(x0):
            raise InputError("wake virtual origin must be finite [m]", x0)
        object.__setattr__(self, "virtual_origin", x0)
        if self.canopy_area is not None:
            object.__setattr__(self, "canopy_area", _positive(self.canopy_area,
                                                              "canopy area", "m^2"))
        xmin = (x0 + 2.0 * np.sqrt(4.0 * self.drag_area / np.pi)
                if self.min_distance is None else float(self.min_distance))
        if not np.isfinite(xmin) or xmin <= x0:
            raise InputError("wake model min_distance must lie beyond the virtual origin [m]",
                             xmin)
        object.__setattr__(self, "min_distance", xmin)

    def centreline_defect(self, distance):
        """Centreline velocity defect of the wake.

        Parameters
        ----------
        distance : numeric
            Distance behind the body, at least ``min_distance``. [m]

        Returns
        -------
        numeric
            u_d / U. [-]
        """
        x = self._check(distance)
        return self.coefficient * self.drag_area ** (1 / 3) / (x - self.virtual_origin) ** (2 / 3)

    def half_width(self, distance):
        """Wake half-width b (radius of half defect).

        Parameters
        ----------
        distance : numeric
            Distance behind the body, at least ``min_distance``. [m]

        Returns
        -------
        numeric
            Half-width. [m]
        """
        x = self._check(distance)
        return (np.sqrt(np.log(2.0) / (2 * np.pi * self.coefficient))
                * (self.drag_area * (x - self.virtual_origin)) ** (1 / 3))

    def __call__(self, distance):
        """Dynamic-pressure ratio q_wake / q [-] at ``distance`` [m]."""
        u = np.minimum(self.centreline_defect(distance), 1.0)
        if self.canopy_area is None:
            return (1.0 - u) ** 2
        b = self.half_width(distance)
        s = np.log(2.0) * self.canopy_area / (np.pi * b**2)  # ln2 R^2 / b^2
        mean_u = u * (1.0 - np.exp(-s)) / s
        mean_u2 = u**2 * (1.0 - np.exp(-2 * s)) / (2 * s)
        return 1.0 - 2.0 * mean_u + mean_u2

    def line_length(self, target=TARGET_RATIO):
        """Shortest distance at which the ratio reaches ``target`` (it rises with x).

        Parameters
        ----------
        target : float
            Dynamic-pressure ratio q_wake / q to reach, in (0, 1]. [-]

        Returns
        -------
        float
            Distance behind the body, at least ``min_distance``. [m]
        """
        target = _check_target(target)
        if self(self.min_distance) >= target:
            return float(self.min_distance)
        if self.canopy_area is None:
            u = 1.0 - np.sqrt(target)
            return float(self.virtual_origin
                         + (self.coefficient * self.drag_area ** (1 / 3) / u) ** 1.5)
        hi = 2.0 * self.min_distance
        while self(hi) < target:
            hi *= 2.0
        from scipy.optimize import brentq  # scipy loads where it is used

        return float(brentq(lambda x: self(x) - target, self.min_distance, hi, xtol=1e-9))

    def _check(self, distance):
        x = np.asarray(distance, dtype=float)
        bad = ~np.isfinite(x) | (x < self.min_distance * (1 - 1e-12))
        if np.any(bad):
            raise InputError(
                f"the far-wake model is valid from {self.min_distance:.4g} m behind the "
                f"fuselage (about two equivalent diameters); nearer, use a CFD table",
                np.atleast_1d(x)[np.atleast_1d(bad)][0].item())
        return x


def _check_target(target):
    target = float(target)
    if not (0 < target <= 1):
        raise InputError("target dynamic-pressure ratio must lie in (0, 1]", target)
    return target


@dataclass(frozen=True)
class CableCheck:
    """Outcome of the carrier-cable versus parachute-line check.

    Attributes
    ----------
    ok : bool
    cable_length, line_length, required : float
        Carrier cable, parachute line, and the shortest acceptable cable. [m]
    margin : float
        Required excess of the cable over the line. [-]
    message : str
    """

    ok: bool
    cable_length: float
    line_length: float
    required: float
    margin: float
    message: str


def check_cable_length(cable_length, line_length, margin=CABLE_MARGIN):
    """Check that the carrier's cable is at least ``margin`` longer than the parachute line.

    The paper keeps the HC-to-carrier cable at least 20 % longer than the HC-to-parachute line,
    so that the canopy cannot reach the carrier's rotor.

    Parameters
    ----------
    cable_length : float
        Carrier-to-hub cable. [m]
    line_length : float
        Fin-to-canopy line. [m]
    margin : float
        Required excess, >= 0 (0.20 = 20 %). [-]

    Returns
    -------
    CableCheck
        ``ok`` is False, with a message saying by how much to lengthen the cable or shorten the
        line, when the check fails. Invalid lengths raise :class:`InputError`.
    """
    cable = _positive(cable_length, "carrier cable length", "m")
    line = _positive(line_length, "parachute line length", "m")
    margin = float(margin)
    if not np.isfinite(margin) or margin < 0:
        raise InputError("cable margin must be >= 0", margin)
    required = (1.0 + margin) * line
    ok = cable >= required * (1 - 1e-12)
    # lengths to 6 digits: a report quotes each at a length cell's precision
    if ok:
        message = (f"carrier cable {cable:.6g} m is at least {margin:.0%} longer than the "
                   f"parachute line {line:.6g} m (needs >= {required:.6g} m)")
    else:
        message = (f"carrier cable {cable:.6g} m is too short: it must be at least "
                   f"{margin:.0%} longer than the parachute line {line:.6g} m, i.e. >= "
                   f"{required:.6g} m; lengthen the cable by {required - cable:.6g} m or "
                   f"shorten the line to <= {cable / (1 + margin):.6g} m")
    return CableCheck(bool(ok), cable, line, required, margin, message)

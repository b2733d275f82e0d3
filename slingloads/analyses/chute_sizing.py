"""Drogue-parachute sizing for yaw: linearisation, neutral static stability, line length,
1-DOF gust runs and the sizing sweep (paper sections 3.2-4.2).

Method (``docs/parachute-sizing.md``):

1. Linearise the yawing-moment coefficients of the fuselage and of the cut-down fin against
   sideslip over a chosen range (paper figures 4 and 5): :func:`yaw_linearisation`.
2. Neutral yaw static stability: the parachute flat-plate area for which the total yawing-moment
   derivative about the suspension axis is zero, the parachute's drag acting at the fin
   attachment with the wake's dynamic-pressure ratio: :func:`neutral_area`.
3. Parachute line length from the wake ratio and the carrier-cable check: :func:`line_length`.
4. 1-DOF yaw runs with the full nonlinear tables and lateral gusts: :func:`run_yaw`; the sizing
   sweep from 1x to 2x the static area: :func:`sizing_sweep`.

Sign conventions are those of :mod:`slingloads.models.yaw_dynamics`: psi, N nose right
positive; beta positive wind from the right; stable means dN/dbeta > 0.
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from slingloads.analyses import verdicts as _verdicts
from slingloads.errors import InputError
from slingloads.models.aero_tables import linear_fit
from slingloads.models.gusts import standard_gusts
from slingloads.models.integration import SolverSettings
from slingloads.models.wake import CABLE_MARGIN, TARGET_RATIO, check_cable_length
from slingloads.models.yaw_dynamics import (
    YawModel,
    integrate_dopri,
    integrate_reference,
    integrate_rk4,
    relative_wind,
    yaw_solver_settings,
)

#: Default sideslip range of the local linearisation. [rad]
FIT_RANGE = (np.radians(-10.0), np.radians(10.0))
#: Default sideslip past which no run is called stable (see :class:`MetricSettings`). [rad]
SIDESLIP_LIMIT = np.radians(20.0)

#: Integrators of the yaw runs: compiled adaptive Dormand-Prince 5(4) (``settings.rtol``,
#: ``atol``), compiled fixed-step RK4 (``settings.step``), one solve_ivp call per run.
INTEGRATORS = {"dopri5": integrate_dopri, "rk4": integrate_rk4,
               "solve_ivp": integrate_reference}

#: Verdicts of a run (:mod:`slingloads.analyses.verdicts`).
VERDICTS = _verdicts.VERDICTS


def _deg(x):
    return np.degrees(x)


# --------------------------------------------------------------------------- linearisation
@dataclass(frozen=True)
class LinearisationResult:
    """Table and straight-line fit of the fuselage and fin yawing-moment coefficients.

    The fuselage coefficient is the table's Cn about the suspension axis (side-force transfer
    included), on the fuselage's S and L; the fin's is Cn_fin = N_fin / (q S_fin l_fin) =
    -eta CY on the fin area and its arm l_fin from the axis (dimensionless either way).

    Attributes
    ----------
    beta : ndarray
        Sideslip of the curves. [rad]
    fuselage_cn, fin_cn : ndarray or None
        Tabulated coefficients at ``beta``. [-]
    fuselage_slope, fin_slope : float or None
        Least-squares dCn/dbeta over ``fit_range``. [1/rad]
    fuselage_intercept, fin_intercept : float or None
        Cn of the least-squares lines at zero sideslip. [-]
    fit_range : tuple of float
        [rad]
    """

    beta: np.ndarray
    fuselage_cn: np.ndarray | None
    fin_cn: np.ndarray | None
    fuselage_slope: float | None
    fuselage_intercept: float | None
    fin_slope: float | None
    fin_intercept: float | None
    fit_range: tuple
    fuselage_local_slope: float | None = None
    fin_local_slope: float | None = None

    def slopes(self, basis="fit"):
        """(fuselage, fin) dCn/dbeta of ``basis``: "fit" (least squares over
        ``fit_range``) or "local" (at zero sideslip, :func:`local_slope`). [1/rad]

        Parameters
        ----------
        basis : str
            "fit" or "local".

        Returns
        -------
        fuselage, fin : float or None
            dCn/dbeta (None without the component). [1/rad]
        """
        if basis == "local":
            return self.fuselage_local_slope, self.fin_local_slope
        if basis == "fit":
            return self.fuselage_slope, self.fin_slope
        raise InputError(f"{basis=!r} is not a valid slope basis. Valid options are: "
                         "'fit', 'local'", basis)

    def to_frame(self):
        """Slopes and intercepts, one row per component.

        Returns
        -------
        pandas.DataFrame
            One row per component: fitted slope [1/rad and 1/deg], local slope at zero sideslip
            [1/deg], Cn at zero sideslip [-] and the fit range [deg].
        """
        rows = []
        for name, slope, icpt in (("fuselage", self.fuselage_slope, self.fuselage_intercept),
                                  ("fin", self.fin_slope, self.fin_intercept)):
            if slope is not None:
                local = (self.fuselage_local_slope if name == "fuselage"
                         else self.fin_local_slope)
                rows.append({"component": name, "dCn/dbeta [1/rad]": slope,
                             "dCn/dbeta [1/deg]": slope * np.pi / 180,
                             "local dCn/dbeta at beta 0 [1/deg]": (
                                 np.nan if local is None else local * np.pi / 180),
                             "Cn at beta 0 [-]": icpt,
                             "fit from [deg]": _deg(self.fit_range[0]),
                             "fit to [deg]": _deg(self.fit_range[1])})
        return pd.DataFrame(rows)

    def curves_frame(self):
        """Table against fit along sideslip (the paper's figures 4 and 5).

        Returns
        -------
        pandas.DataFrame
            Sideslip [deg] and the tabulated and fitted Cn of the fuselage and the fin [-].
        """
        frame = pd.DataFrame({"beta [deg]": _deg(self.beta)})
        if self.fuselage_cn is not None:
            frame["fuselage Cn table [-]"] = self.fuselage_cn
            frame["fuselage Cn fit [-]"] = self.fuselage_intercept + self.fuselage_slope * self.beta
        if self.fin_cn is not None:
            frame["fin Cn table [-]"] = self.fin_cn
            frame["fin Cn fit [-]"] = self.fin_intercept + self.fin_slope * self.beta
        return frame

    def frames(self):
        """The tables of the result, by sheet name.

        Returns
        -------
        dict of str to pandas.DataFrame
            The slopes and the curves, by sheet name.
        """
        return {"yaw linearisation": self.to_frame(), "yaw Cn curves": self.curves_frame()}


def yaw_linearisation(model, fit_range=FIT_RANGE):
    """Local linearisation of the yawing-moment coefficients against sideslip.

    Parameters
    ----------
    model : YawModel
    fit_range : (float, float)
        Sideslip range of the least-squares fit. [rad]

    Returns
    -------
    LinearisationResult
    """
    lo, hi = _check_range(fit_range)
    fus_cn = fin_cn = fus = fin = fus_local = fin_local = None
    grids = []
    if model.fuselage is not None:
        grid, n_per_q = model.fuselage_moment_table
        fus_cn = n_per_q / (model.fuselage.area * model.fuselage.length)
        fus = linear_fit(grid, fus_cn, lo, hi, "fuselage")
        fus_local = local_slope(grid, fus_cn, "fuselage")
        grids.append((grid, fus_cn))
    if model.fin is not None:
        (grid, k), dx = model.fin_side_force_table, model.fin_arm[0]
        if dx == 0:
            raise InputError("the fin's centre of pressure lies on the suspension axis", dx)
        fin_cn = -k / model.fin.area  # -eta CY: N_fin / (q S_fin dx)
        fin = linear_fit(grid, fin_cn, lo, hi, "fin")
        fin_local = local_slope(grid, fin_cn, "fin")
        grids.append((grid, fin_cn))
    if not grids:
        raise InputError("the yaw model has neither fuselage nor fin to linearise")
    beta = np.unique(np.concatenate([g for g, _ in grids]))
    blo, bhi = model.beta_range()
    beta = beta[(beta >= blo) & (beta <= bhi)]
    fus_vals = None if fus is None else np.interp(beta, model.fuselage_moment_table[0],
                                                  fus_cn)
    fin_vals = None if fin is None else np.interp(beta, model.fin_side_force_table[0], fin_cn)
    return LinearisationResult(
        beta, fus_vals, fin_vals, None if fus is None else fus[0],
        None if fus is None else fus[1], None if fin is None else fin[0],
        None if fin is None else fin[1], (lo, hi), fus_local, fin_local)


def local_slope(angle, values, what="aerodynamic"):
    """Slope of a table at zero sideslip: the least-squares line through the breakpoints
    within +-h of 0, h the larger distance from 0 to its nearest breakpoint on either side
    (the central difference of the interpolated table when the breakpoints are symmetric
    about 0). This is the derivative a small disturbance about beta = 0 sees, where the fit
    over ``fit_range`` is a finite-amplitude average. [1/rad]

    Parameters
    ----------
    angle : array_like, shape (n,)
        Sideslip breakpoints. [rad]
    values : array_like, shape (n,)
        Table values. [unit of the table]
    what : str
        Name of the table, for the message.

    Returns
    -------
    float
        Slope. [unit of the table / rad]
    """
    angle = np.asarray(angle, dtype=float)
    below, above = angle[angle < -1e-12], angle[angle > 1e-12]
    if below.size == 0 or above.size == 0:
        raise InputError(f"the {what} table does not bracket zero sideslip: no local slope",
                         field="fit_range")
    h = max(-below.max(), above.min())
    return linear_fit(angle, values, -h, h, what)[0]


def _check_range(fit_range):
    lo, hi = (float(v) for v in fit_range)
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise InputError("fit range must be two finite sideslips, low < high [rad]",
                         (lo, hi))
    return lo, hi


# --------------------------------------------------------------------- linear yaw model
@dataclass(frozen=True)
class LinearYaw:
    """Linearised 1-DOF yaw: I psi'' + c psi' + k psi = k gamma(t) about the trim.

    Attributes
    ----------
    inertia : float
        [kg m^2]
    stiffness : float
        k = dN/dbeta, fuselage + fin + parachute. [N m/rad]
    damping : float
        c = -dN/dr, fin + parachute. [N m s/rad]
    parts : dict
        Stiffness and damping of each component. [N m/rad], [N m s/rad]
    tas : float
        True airspeed, for the gust angle. [m/s]
    """

    inertia: float
    stiffness: float
    damping: float
    parts: dict
    tas: float
    beta_trim: float = 0.0
    weight_stiffness: float = 0.0

    @property
    def natural_frequency(self):
        """Undamped natural frequency sqrt(k/I), NaN when k <= 0. [rad/s]"""
        return float(np.sqrt(self.stiffness / self.inertia)) if self.stiffness > 0 else np.nan

    @property
    def damping_ratio(self):
        """c / (2 sqrt(k I)), NaN when k <= 0. [-]"""
        if self.stiffness <= 0:
            return np.nan
        return float(self.damping / (2.0 * np.sqrt(self.stiffness * self.inertia)))

    @property
    def eigenvalues(self):
        """Roots of I s^2 + c s + k = 0. [1/s]"""
        return np.roots([self.inertia, self.damping, self.stiffness])

    @property
    def stable(self):
        """True when both roots have negative real parts (k > 0 and c > 0)."""
        return bool(self.stiffness > 0 and self.damping > 0)

    # The same interface as YawModel, so the same integrators run it.
    condition = property(lambda self: _Tas(self.tas))

    def beta_range(self):
        """Sideslip range of the linear model (a linear moment has no table to leave).

        Returns
        -------
        (float, float)
            (-pi/2, pi/2). [rad]
        """
        return -np.pi / 2, np.pi / 2

    def relative_wind(self, gust):
        """Wind angle and relative speed for a lateral gust.

        Parameters
        ----------
        gust : array_like
            Lateral gust velocity. [m/s]

        Returns
        -------
        gamma : ndarray
            Wind angle atan2(v, V). [rad]
        v_rel : ndarray
            Relative speed sqrt(V^2 + v^2). [m/s]
        """
        return relative_wind(self.tas, gust)

    def derivatives(self, psi, rate, gamma, v_rel, area):
        """State derivatives of the linear model (the protocol of :class:`YawModel`).

        Parameters
        ----------
        psi, rate : array_like
            Yaw [rad] and yaw rate [rad/s].
        gamma, v_rel : array_like
            Wind angle [rad] and relative speed [m/s] (:meth:`relative_wind`).
        area : array_like
            Parachute flat-plate area (its effect is in the stiffness and damping). [m^2]

        Returns
        -------
        dpsi : ndarray
            [rad/s]
        drate : ndarray
            ((k - k_w) (gamma - psi - beta_trim) - k_w (psi + beta_trim) - c r) / I, k_w
            the weight's part of the stiffness (it turns with psi, not with the gust).
            [rad/s^2]
        outside : ndarray of bool
            All False (no table to leave).
        """
        aero, weight = self.stiffness - self.weight_stiffness, self.weight_stiffness
        acc = (aero * (gamma - psi - self.beta_trim) - weight * (psi + self.beta_trim)
               - self.damping * rate) / self.inertia
        return rate, acc, np.zeros(np.shape(acc), dtype=bool)


@dataclass(frozen=True)
class _Tas:
    tas: float


def linear_yaw(model, area, fit_range=FIT_RANGE, basis="fit"):
    """Linearise the yaw model about beta = 0, r = 0 with parachute ``area`` [m^2].

    The fuselage and fin stiffnesses come from the slopes of :func:`yaw_linearisation` of
    ``basis``: "fit" (least squares over ``fit_range``) or "local" (at zero sideslip); the
    parachute's from its drag at the attachment,
    ``q eta_w CD A dx_c``. Damping: fin ``-1/2 rho V S_f eta CY_beta dx_f^2`` and parachute
    ``1/2 rho V eta_w CD A dx_c^2`` (attachment-point velocity, Apollo legacy model).

    Parameters
    ----------
    model : YawModel
    area : float
        Parachute flat-plate area, >= 0. [m^2]
    fit_range : (float, float)
        Sideslip range of the fits. [rad]
    basis : str
        "fit" or "local".

    Returns
    -------
    LinearYaw
    """
    area = float(area)
    if not np.isfinite(area) or area < 0:
        raise InputError("parachute area must be >= 0 [m^2]", area)
    lin = yaw_linearisation(model, fit_range)
    fus_slope, fin_slope = lin.slopes(basis)
    q, rho, v = model.condition.dynamic_pressure, model.condition.density, model.condition.tas
    parts = {}
    if fus_slope is not None:
        f = model.fuselage
        parts["fuselage"] = (q * f.area * f.length * fus_slope, 0.0)
    if fin_slope is not None:
        dx = model.fin_arm[0]
        k = q * model.fin.area * dx * fin_slope
        c = (0.5 * rho * v * model.fin.area * dx**2 * fin_slope
             if model.fin_rate_damping else 0.0)
        parts["fin"] = (k, c)
    if model.parachute is not None:
        cd, dx = model.chute_drag_coefficient, model.chute_arm[0]
        parts["parachute"] = (q * cd * area * dx, 0.5 * rho * v * cd * area * dx**2)
    elif area > 0:
        raise InputError("a parachute area was given but the model has no parachute", area)
    weight = -model.weight_terms[1]  # N_w ~ W_c + W_s psi, psi = -beta at rest
    if weight != 0.0:
        parts["weight"] = (weight, 0.0)
    stiffness = sum(p[0] for p in parts.values())
    damping = sum(p[1] for p in parts.values())
    return LinearYaw(model.yaw_inertia, stiffness, damping, parts, v,
                     weight_stiffness=weight)


# ---------------------------------------------------------------------- neutral area
@dataclass(frozen=True)
class NeutralAreaResult:
    """Parachute area for neutral yaw static stability, with its breakdown.

    Attributes
    ----------
    area : float
        Flat-plate area that makes the total dN/dbeta zero (negative: already stable), on the
        slope basis ``basis``. [m^2]
    derivatives : dict
        dN/dbeta of the fuselage, the fin and the parachute at ``area`` (slopes of
        ``basis``). [N m/rad]
    per_area : float
        Parachute dN/dbeta per unit area, q eta_w CD dx_c. [N m/rad/m^2]
    q : float
        Dynamic pressure. [Pa]
    beta : ndarray
        Sideslip of the moment curves. [rad]
    moments : dict of ndarray
        Nonlinear static yawing moments at ``area`` against ``beta``, per component. [N m]
    linearisation : LinearisationResult
    """

    area: float
    derivatives: dict
    per_area: float
    q: float
    chute_arm: float
    beta: np.ndarray
    moments: dict
    linearisation: LinearisationResult
    area_fit: float = np.nan
    area_local: float = np.nan
    basis: str = "fit"

    @property
    def basis_text(self):
        """Which neutral area is used, in words."""
        lo, hi = (float(np.degrees(v)) for v in self.linearisation.fit_range)
        which = {"fit": f"least-squares slopes over [{lo:.3g}, {hi:.3g}] deg",
                 "local": "local slopes at zero sideslip"}[self.basis]
        return f"{which} (fit {self.area_fit:.6g} m^2, local {self.area_local:.6g} m^2)"

    @property
    def already_stable(self):
        """True when fuselage and fin alone are statically stable (no parachute needed)."""
        return self.area <= 0

    def to_frame(self):
        """Breakdown: one row per contribution and their sum.

        Returns
        -------
        pandas.DataFrame
            dN/dbeta of each contribution and their total [N m/rad and N m/deg].
        """
        rows = [{"component": k, "dN/dbeta [N m/rad]": v,
                 "dN/dbeta [N m/deg]": v * np.pi / 180} for k, v in self.derivatives.items()]
        total = sum(self.derivatives.values())
        rows.append({"component": "total", "dN/dbeta [N m/rad]": total,
                     "dN/dbeta [N m/deg]": total * np.pi / 180})
        frame = pd.DataFrame(rows)
        frame["area [m^2]"] = [np.nan] * (len(rows) - 2) + [self.area, np.nan]
        return frame

    def summary_frame(self):
        """The neutral area as one row.

        Returns
        -------
        pandas.DataFrame
            One row: neutral areas [m^2], basis, q [Pa], parachute arm [m], parachute dN/dbeta
            per unit area [N m/rad/m^2], already stable.
        """
        return pd.DataFrame([{"neutral area [m^2]": self.area,
                              "neutral area, fit slopes [m^2]": self.area_fit,
                              "neutral area, local slopes [m^2]": self.area_local,
                              "neutral area basis": self.basis, "q [Pa]": self.q,
                              "chute arm [m]": self.chute_arm,
                              "chute dN/dbeta per area [N m/rad/m^2]": self.per_area,
                              "already stable": self.already_stable}])

    def curves_frame(self):
        """The static yaw moments against sideslip.

        Returns
        -------
        pandas.DataFrame
            Sideslip [deg] and the yaw moment of each contribution [N m].
        """
        frame = pd.DataFrame({"beta [deg]": _deg(self.beta)})
        for k, v in self.moments.items():
            frame[f"N {k} [N m]"] = v
        return frame

    def frames(self):
        """The tables of the result, by sheet name.

        Returns
        -------
        dict of str to pandas.DataFrame
            Summary, breakdown, moments and linearisation, by sheet name.
        """
        return {"chute neutral area": self.summary_frame(),
                "chute breakdown": self.to_frame(),
                "chute static moments": self.curves_frame(),
                **self.linearisation.frames()}


#: Slope bases of the neutral area: the larger of the two areas (default), the least-squares
#: slopes over the fit range (the paper's linearisation, figures 4 and 5) or the local slopes
#: at zero sideslip.
NEUTRAL_BASES = ("larger", "fit", "local")


def neutral_area(model, fit_range=FIT_RANGE, beta_plot=None, basis="larger"):
    """Parachute flat-plate area for neutral yaw static stability (paper section 4.1).

    .. math:: \\frac{dN_{fus}}{d\\beta} + \\frac{dN_{fin}}{d\\beta}
              + q\\,\\eta_w C_D A\\, l_c = 0

    with the fuselage and fin derivatives from the linearised tables and l_c the parachute
    attachment's distance aft of the suspension axis.

    Parameters
    ----------
    model : YawModel
        Must have a parachute (its CD and wake ratio are used; its area is not).
    fit_range : (float, float)
        [rad]
    beta_plot : array_like, optional
        Sideslip of the moment curves (default: -45..45 deg within the tables). [rad]
    basis : {"larger", "fit", "local"}
        Slopes of the fuselage and fin: both areas are computed, from the least-squares
        slopes over ``fit_range`` and from the local slopes at zero sideslip
        (:func:`local_slope`); the one used is the larger (default: a small disturbance about
        the trim must be restored as well as a finite one), or the one named.

    Returns
    -------
    NeutralAreaResult
    """
    if basis not in NEUTRAL_BASES:
        raise InputError(f"{basis=!r} is not a valid neutral-area basis. Valid options are: "
                         f"{', '.join(map(repr, NEUTRAL_BASES))}", basis)
    if model.parachute is None:
        raise InputError("neutral-area sizing needs a parachute (its CD and wake ratio)")
    dx = model.chute_arm[0]
    if dx <= 0:
        raise InputError("the parachute attachment must lie aft of the suspension axis "
                         "(dx > 0 [m]) to stabilise", float(dx))
    per_area = model.condition.dynamic_pressure * model.chute_drag_coefficient * dx
    areas, bases = {}, {}
    for which in ("fit", "local"):
        bases[which] = linear_yaw(model, 0.0, fit_range, which)
        others = sum(k for name, (k, _) in bases[which].parts.items() if name != "parachute")
        areas[which] = -others / per_area
    used = (basis if basis != "larger"
            else ("local" if areas["local"] > areas["fit"] else "fit"))
    base, area = bases[used], areas[used]
    derivs = {name: k for name, (k, _) in base.parts.items() if name != "parachute"}
    derivs["parachute"] = per_area * area
    lo, hi = model.beta_range()
    if beta_plot is None:
        beta_plot = np.radians(np.arange(-45.0, 45.0 + 1e-9, 0.5))
        beta_plot = beta_plot[(beta_plot >= lo) & (beta_plot <= hi)]
    beta_plot = np.asarray(beta_plot, dtype=float)
    n_fus, n_fin, n_chute = model.static_moments(beta_plot, max(area, 0.0))
    moments = {}
    if model.fuselage is not None:
        moments["fuselage"] = n_fus
    if model.fin is not None:
        moments["fin"] = n_fin
    moments["parachute"] = n_chute
    n_weight = model.weight_moment(-beta_plot)  # at rest psi = -beta
    if model.weight_terms != (0.0, 0.0):
        moments["weight"] = n_weight
    moments["total"] = n_fus + n_fin + n_chute + n_weight
    return NeutralAreaResult(float(area), derivs, float(per_area),
                             model.condition.dynamic_pressure, float(dx), beta_plot, moments,
                             yaw_linearisation(model, fit_range), float(areas["fit"]),
                             float(areas["local"]), used)


# ------------------------------------------------------------------------ line length
@dataclass(frozen=True)
class LineLengthResult:
    """Parachute line length from the wake, and the carrier-cable check.

    Parameters
    ----------
    line_length : float
        Shortest line at which the wake ratio reaches ``target``. [m]
    target : float
        Dynamic-pressure ratio to reach. [-]
    wake_source : str
        Where the wake data come from.
    distance : ndarray, shape (n,)
        Distances behind the fuselage of the ratio curve. [m]
    ratio : ndarray, shape (n,)
        Wake dynamic-pressure ratio at ``distance``. [-]
    cable : CableCheck or None
        The carrier-cable check (None: no cable given).
    """

    line_length: float
    target: float
    wake_source: str
    distance: np.ndarray
    ratio: np.ndarray
    cable: object | None

    def to_frame(self):
        """The line length and the cable check as one row.

        Returns
        -------
        pandas.DataFrame
            One row: line length [m], target q ratio [-], wake source and, with a cable, its
            length and the required length [m] and the check.
        """
        row = {"line length [m]": self.line_length, "target q ratio [-]": self.target,
               "wake source": self.wake_source}
        if self.cable is not None:
            row.update({"cable length [m]": self.cable.cable_length,
                        "required cable [m]": self.cable.required,
                        "cable check": "ok" if self.cable.ok else "FAIL",
                        "message": self.cable.message})
        return pd.DataFrame([row])

    def curve_frame(self):
        """The wake's dynamic-pressure ratio against distance.

        Returns
        -------
        pandas.DataFrame
            Distance [m] and q ratio [-].
        """
        return pd.DataFrame({"distance [m]": self.distance, "q ratio [-]": self.ratio})

    def frames(self):
        """The tables of the result, by sheet name.

        Returns
        -------
        dict of str to pandas.DataFrame
            The line length and the wake's ratio curve, by sheet name.
        """
        return {"chute line": self.to_frame(), "wake q ratio": self.curve_frame()}


def line_length(wake, target=TARGET_RATIO, cable_length=None, margin=CABLE_MARGIN,
                distance=None, flown_line=None):
    """Shortest parachute line at which the wake ratio reaches ``target``, and the cable check.

    The cable is checked against the longer of that line and the line flown (the Study's,
    which the loads and the multibody model use), so that this check and the multibody
    system's state one required cable length for one parachute line.

    Parameters
    ----------
    wake : TabulatedWake or BluffBodyWake
    target : float
        Dynamic-pressure ratio to reach (paper: 0.95). [-]
    cable_length : float, optional
        Carrier cable; if given it is checked against the line with ``margin``. [m]
    margin : float
        [-]
    distance : array_like, optional
        Distances for the ratio curve (default: the table, or up to 1.5 x the line). [m]
    flown_line : float, optional
        The parachute line flown (the Study's 'parachute line length'). [m]

    Returns
    -------
    LineLengthResult
    """
    length = wake.line_length(target)
    if distance is None:
        if hasattr(wake, "distance"):
            distance = wake.distance
        else:
            distance = np.linspace(wake.min_distance, max(1.5 * length, 2 * wake.min_distance),
                                   200)
    distance = np.asarray(distance, dtype=float)
    checked = length if flown_line is None else max(float(length), float(flown_line))
    cable = None if cable_length is None else check_cable_length(cable_length, checked, margin)
    return LineLengthResult(float(length), float(target), wake.source, distance,
                            np.asarray(wake(distance)), cable)


def wake_ratio_at(wake, distance):
    """The wake's q ratio at ``distance`` [m], NaN outside its data (table range, or nearer
    than the far-wake model's validity). [-]

    The parachute's wake ratio carries the wake loss once (:mod:`slingloads.models.parachute`);
    this is the value the wake data give for it at the chosen line length.

    Parameters
    ----------
    wake : TabulatedWake or BluffBodyWake
    distance : float
        Distance behind the fuselage. [m]

    Returns
    -------
    float
        q ratio, or NaN outside the wake data. [-]
    """
    lo, hi = wake.range if hasattr(wake, "range") else (wake.min_distance, np.inf)
    if not (np.isfinite(distance) and lo <= distance <= hi):
        return float("nan")
    return float(wake(distance))


# ----------------------------------------------------------------------------- runs
@dataclass(frozen=True)
class MetricSettings:
    """How the run metrics are taken.

    Parameters
    ----------
    settle_fraction : float
        Settling band as a share of the peak sideslip excursion from trim. [-]
    final_tolerance : float
        Band and offset of the envelope test (:class:`~slingloads.analyses.verdicts.
        EnvelopeTest`): a sideslip whose second-half half amplitude is within it has
        settled, and one that settles farther than this from the trim is a static departure.
        [rad]
    peak_threshold : float
        Yaw-rate peaks smaller than this are ignored by the logarithmic decrement. [rad/s]
    sideslip_limit : float
        A run whose |beta| passes this is never called stable, > 0. Default 20 deg: past it
        the yawing-moment curves of helicopter-class fuselages turn over (|Cn| peaks near 20
        deg and falls back to zero near 45 deg) and a cut-down fin approaches its stall, so
        the stiffness the sizing counts on is no longer there; set it to the sideslip
        envelope of the loads analysis to keep the two consistent. [rad]

    A run whose sideslip also leaves the range over which the tables were linearised (the
    ``fit_range`` of the runs) is outside the model's domain as well: the linear stiffness
    and damping behind the mode check no longer describe it.
    """

    settle_fraction: float = 0.05
    final_tolerance: float = np.radians(1.0)
    peak_threshold: float = 1e-5
    sideslip_limit: float = SIDESLIP_LIMIT

    def __post_init__(self):
        for name in ("settle_fraction", "final_tolerance", "peak_threshold",
                     "sideslip_limit"):
            value = float(getattr(self, name))
            if not np.isfinite(value) or value <= 0:
                raise InputError(f"metric setting {name} must be > 0", value)
            object.__setattr__(self, name, value)

    @property
    def envelope_test(self):
        """The envelope test of the runs' sideslip."""
        return _verdicts.EnvelopeTest(band=self.final_tolerance, offset=self.final_tolerance)


@dataclass(frozen=True)
class YawRuns:
    """Histories and metrics of a batch of 1-DOF yaw runs.

    Attributes
    ----------
    areas : ndarray, shape (runs,)
        [m^2]
    gusts : tuple
    histories : Histories
    metrics : pandas.DataFrame
        One row per run: peak |beta| and |psi|; final beta and psi (the last sample); the
        trim the run is judged about ("beta trim": the static equilibrium at rest, or under
        the gust still acting at the end of the run, which moves it when the weight has a
        moment about the yaw axis); the sideslip's offset from that trim (the mean over the
        second half of the envelope test's window, less the trim) and its half amplitudes
        over the two halves (so that a final beta lies within twice the second half's
        amplitude of trim + offset); linear damping ratio
        c / (2 sqrt(k I)) and natural frequency on the local slopes at zero sideslip (the
        yaw mode's eigenvalue); damping ratio from the logarithmic decrement of the first two
        positive yaw-rate peaks after the gust ends (NaN for continuous gusts or no
        oscillation) and whether it agrees with the linear one ("damping check",
        :func:`~slingloads.analyses.verdicts.damping_check`); settling time from the gust
        onset until |beta - beta_trim| stays within the "settling band" (``settle_fraction``
        of its peak excursion; NaN if never, for a gust that never ends, or for a run that
        is not convergent); verdict (:mod:`slingloads.analyses.verdicts`): "outside domain"
        (left the tables, passed ``sideslip_limit`` or left the linearisation range, with
        the time), else the envelope test's on the sideslip ("divergent", "limit cycle",
        "bounded", "static departure" with its size, "convergent"), "convergent" only if the
        linear yaw mode is stable too ("inconclusive" otherwise); "verdict reason" says why,
        with the numbers.
    """

    areas: np.ndarray
    gusts: tuple
    histories: object
    metrics: pd.DataFrame
    beta_trim: float
    settings: SolverSettings

    def to_frame(self):
        """Metrics per run, unit-labelled columns.

        Returns
        -------
        pandas.DataFrame
            :attr:`metrics` (a copy).
        """
        return self.metrics.copy()

    def history_frame(self, runs=None):
        """Wide table of sideslip and yaw [deg] against time for the chosen run indices.

        Parameters
        ----------
        runs : sequence of int, optional
            Run indices (default all). [-]

        Returns
        -------
        pandas.DataFrame
            Time [s], then sideslip and yaw [deg] of each run.
        """
        runs = range(len(self.areas)) if runs is None else runs
        h = self.histories
        frame = pd.DataFrame({"time [s]": h.time})
        for j in runs:
            tag = f"A={self.areas[j]:.3f} m^2 {self.gusts[j].kind}"
            frame[f"beta [deg] {tag}"] = _deg(h.beta[j])
            frame[f"psi [deg] {tag}"] = _deg(h.psi[j])
        return frame

    def frames(self):
        """The tables of the result, by sheet name.

        Returns
        -------
        dict of str to pandas.DataFrame
            Runs and histories, by sheet name.
        """
        return {"yaw runs": self.to_frame(), "yaw histories": self.history_frame()}


def _run_metrics(model, areas, gusts, hist, beta_trim, fit_range, metric):
    """Metrics of every run, vectorised over runs (no per-run loop on the histories)."""
    from slingloads.analyses import verdicts as vd
    from slingloads.analyses.chute_metrics import history_metrics

    t = hist.time
    runs = hist.beta.shape[0]
    trim = np.broadcast_to(np.asarray(beta_trim, dtype=float).reshape(-1), (runs,)).copy()
    onset = np.array([g.breakpoints[0] for g in gusts], dtype=float)
    free = np.array([np.nan if g.end is None else g.end for g in gusts], dtype=float)
    out = np.empty((runs, 8))
    history_metrics(t, np.ascontiguousarray(hist.beta), np.ascontiguousarray(hist.psi),
                    np.ascontiguousarray(hist.rate), trim, onset, free,
                    metric.settle_fraction, metric.peak_threshold, out)
    peak_beta, peak_psi, beta_min, beta_max, settling, p1, p2 = out[:, :7].T
    with np.errstate(divide="ignore", invalid="ignore"):
        delta = np.where((p1 > 0) & (p2 > 0), np.log(p1 / p2), np.nan)
    zeta_log = delta / np.sqrt(4 * np.pi**2 + delta**2)
    zeta_lin, omega, lin_stable, stiffness, damping = _linear_metrics(model, areas, fit_range)
    # domain of the 1-DOF model: inside the tables, |beta| within the sideslip limit and
    # within the range the linearisation (and so the mode check) holds
    lo, hi = fit_range
    over_at = _first_time(t, np.abs(hist.beta) > metric.sideslip_limit)
    unlinear_at = _first_time(t, (hist.beta < lo) | (hist.beta > hi))
    outside = hist.left_table | np.isfinite(over_at) | np.isfinite(unlinear_at)
    sustained = ~np.isfinite(free)
    test = metric.envelope_test
    period_lin = np.where(np.isfinite(omega) & (zeta_lin < 1),
                          2 * np.pi / (omega * np.sqrt(np.abs(1 - zeta_lin**2))), np.nan)
    env = vd.envelope(t, hist.beta, np.where(sustained, onset, free), trim, sustained, test,
                      period_lin)
    response = env.verdict
    verdict = np.where(outside, vd.OUTSIDE_DOMAIN,
                       np.where((response == vd.CONVERGENT) & ~lin_stable, vd.INCONCLUSIVE,
                                response)).astype(object)
    excursion = np.nanmax(np.abs(hist.beta - trim[:, None]), axis=1)
    band = metric.settle_fraction * excursion
    settling = np.where(np.isin(verdict, vd.ACCEPTED) & ~sustained, settling, np.nan)
    checks = [vd.damping_check(zl, pl if np.isfinite(zl) else np.nan, z, pl, "yaw (1-DOF)")
              for zl, z, pl in zip(zeta_log.tolist(), zeta_lin.tolist(), period_lin.tolist(),
                                   strict=True)]
    reasons = []
    k_round_off = 1e-9 * float(np.nanmax(np.abs(stiffness), initial=0.0))
    for j in range(runs):
        why = []
        if hist.left_table[j]:
            why.append(f"left the aerodynamic tables at t = {hist.exit_time[j]:.4g} s")
        if np.isfinite(over_at[j]):
            why.append(f"|beta| passed the sideslip limit "
                       f"{math.degrees(metric.sideslip_limit):.3g} deg at t = {over_at[j]:.4g} s"
                       f" (peak {math.degrees(peak_beta[j]):.3g} deg)")
        if np.isfinite(unlinear_at[j]):
            why.append(f"sideslip left the linearisation range [{math.degrees(lo):.3g}, "
                       f"{math.degrees(hi):.3g}] deg at t = {unlinear_at[j]:.4g} s")
        if not why:
            why.append(env.reason(j))
            if not lin_stable[j]:
                # at the neutral area k cancels to round-off of the sweep's stiffnesses: 0
                k = stiffness[j] if abs(stiffness[j]) > k_round_off else 0.0
                why.append(f"linear yaw mode (local slopes) not stable: k = "
                           f"{k:.4g} N m/rad, c = {damping[j]:.4g} N m s/rad")
        reasons.append("; ".join(why))
    labels = {id(g): (g.kind, g.label) for g in gusts}  # once per distinct gust
    return pd.DataFrame({
        "area [m^2]": areas,
        "gust": [labels[id(g)][0] for g in gusts],
        "gust label": [labels[id(g)][1] for g in gusts],
        "peak beta [deg]": _deg(peak_beta),
        "peak psi [deg]": _deg(peak_psi),
        "final beta [deg]": _deg(hist.beta[:, -1]),
        "final psi [deg]": _deg(hist.psi[:, -1]),
        "beta trim [deg]": _deg(trim),
        "beta offset from trim [deg]": _deg(env.offset),
        "beta amplitude first half [deg]": _deg(env.first),
        "beta amplitude second half [deg]": _deg(env.second),
        "damping ratio linear [-]": zeta_lin,
        "damping ratio log decrement [-]": zeta_log,
        "damping check": checks,
        "natural frequency [rad/s]": omega,
        "settling time [s]": settling,
        "settling band [deg]": _deg(band),
        "left table": hist.left_table,
        "verdict": verdict,
        "verdict reason": reasons,
    })


def _first_time(t, flags):
    """First time at which each row of ``flags`` (runs, n) is True (NaN if never). [s]"""
    hit = flags.any(axis=1)
    return np.where(hit, t[np.argmax(flags, axis=1)], np.nan)


def _linear_metrics(model, areas, fit_range):
    """Linear damping ratio [-], natural frequency [rad/s], linear stability (both roots'
    real parts below -:data:`~slingloads.analyses.verdicts.EIGENVALUE_TOLERANCE`), stiffness
    [N m/rad] and damping [N m s/rad] of every run, as :func:`linear_yaw` gives them on the
    local slopes at zero sideslip (the eigenvalue of a small disturbance about the trim), on
    arrays: fuselage and fin linearised once, the parachute's stiffness and damping
    proportional to its area."""
    base = linear_yaw(model, 0.0, fit_range, "local")
    if model.parachute is None and np.any(areas > 0):
        linear_yaw(model, float(areas.max()), fit_range)  # refuses the area
    k_rest = sum(k for name, (k, _) in base.parts.items() if name != "parachute")
    c_rest = sum(c for name, (_, c) in base.parts.items() if name != "parachute")
    k_chute = c_chute = np.zeros(areas.shape)
    if model.parachute is not None:  # the products in the order of linear_yaw
        cd, dx = model.chute_drag_coefficient, model.chute_arm[0]
        q, rho, v = model.condition.dynamic_pressure, model.condition.density, model.condition.tas
        k_chute = q * cd * areas * dx
        c_chute = 0.5 * rho * v * cd * areas * dx**2
    stiffness = k_rest + k_chute
    damping = c_rest + c_chute
    inertia = model.yaw_inertia
    positive = stiffness > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        omega = np.where(positive, np.sqrt(stiffness / inertia), np.nan)
        zeta = np.where(positive, damping / (2.0 * np.sqrt(stiffness * inertia)), np.nan)
        # real part of the slower root of I s^2 + c s + k = 0 (the stable-root form
        # -2k / (c + sqrt(c^2 - 4 k I)) when both roots are real)
        disc = damping**2 - 4.0 * stiffness * inertia
        slowest = np.where(disc >= 0, -2.0 * stiffness / (damping + np.sqrt(np.abs(disc))),
                           -damping / (2.0 * inertia))
    stable = positive & (damping > 0) & (slowest < -_verdicts.EIGENVALUE_TOLERANCE)
    return zeta, omega, stable, stiffness, damping


def run_yaw(model, areas, gusts, settings=None, fit_range=FIT_RANGE, metrics=None,
            integrator="dopri5"):
    """Run the nonlinear 1-DOF yaw model from trim for each (area, gust) pair.

    Parameters
    ----------
    model : YawModel
    areas : array_like
        Parachute flat-plate areas, one per run or one for all. [m^2]
    gusts : gust or sequence of gusts
        One per run or one for all (:mod:`slingloads.models.gusts`).
    settings : SolverSettings, optional
    fit_range : (float, float)
        Range of the linearisation behind the linear damping ratio. [rad]
    metrics : MetricSettings, optional
    integrator : {"dopri5", "rk4", "solve_ivp"}
        Compiled adaptive Dormand-Prince 5(4), each run with its own step within
        ``settings.rtol`` and ``atol`` (:func:`~slingloads.models.yaw_dynamics.integrate_dopri`,
        the default); compiled fixed-step RK4 at ``settings.step``
        (:func:`~slingloads.models.yaw_dynamics.integrate_rk4`); or one solve_ivp call per run
        (``settings.method``, the reference).

    Returns
    -------
    YawRuns
    """
    if integrator not in INTEGRATORS:
        raise InputError(f"{integrator=!r} is not a valid option. Valid options are: "
                         f"{', '.join(map(repr, INTEGRATORS))}", integrator)
    settings = yaw_solver_settings(settings)
    metrics = MetricSettings() if metrics is None else metrics
    areas = np.atleast_1d(np.asarray(areas, dtype=float))
    gust_list = tuple(gusts) if isinstance(gusts, (list, tuple)) else (gusts,)
    runs = max(areas.size, len(gust_list))
    areas = np.broadcast_to(areas, (runs,)).copy() if areas.size == 1 else areas
    gust_list = gust_list * runs if len(gust_list) == 1 else gust_list
    # Trim: the static equilibrium nearest beta = 0 (per distinct area); each run is judged
    # about the equilibrium under the gust it ends in (a held gust moves it when the weight
    # has a moment about the axis; the same as at rest otherwise).
    distinct, back = np.unique(areas, return_inverse=True)
    untrimmed = {}  # area -> why it has no static equilibrium (judged about beta 0)
    try:
        beta_trim = model.trim_betas(distinct)[back]
    except InputError as err:
        if err.field != "trim":
            raise
        found = np.zeros(distinct.size)
        for i, a in enumerate(distinct):
            try:
                found[i] = model.trim_betas([a])[0]
            except InputError as one:
                # without a restoring stiffness (at or below the neutral area) there need be
                # no equilibrium: a finding, run from beta 0; with one, the moment's offset
                # is the input's (e.g. a hub off the plane of symmetry): refused
                lin = linear_yaw(model, float(a), fit_range, "local")
                scale = sum(abs(k) for k, _ in lin.parts.values())
                if lin.stiffness > 1e-6 * scale:
                    raise
                untrimmed[float(a)] = str(one.args[0] if one.args else one)
        beta_trim = found[back]
    reference = beta_trim.copy()
    if hasattr(model, "weight_terms") and model.weight_terms != (0.0, 0.0):
        for j, g in enumerate(gust_list):
            held = float(g.velocity(np.array([settings.t_end]))[0]) if g.end is not None else 0.0
            if held != 0.0 and float(areas[j]) not in untrimmed:
                with contextlib.suppress(InputError):  # none under the gust: judged at rest
                    reference[j] = model.trim_betas([areas[j]], gust=held)[0]
    run = INTEGRATORS[integrator]
    hist = run(model, areas, gust_list, psi0=-beta_trim, rate0=0.0, settings=settings)
    frame = _run_metrics(model, areas, gust_list, hist, reference[:, None], fit_range, metrics)
    for j, a in enumerate(areas):
        if float(a) in untrimmed:
            frame.loc[j, "verdict reason"] = (f"{untrimmed[float(a)]}: started and judged about "
                                              f"beta 0; {frame.loc[j, 'verdict reason']}")
    return YawRuns(areas, gust_list, hist, frame, float(np.max(np.abs(beta_trim))), settings)


def gust_frame(gusts, tas):
    """The gust shapes as a table: shape, description, largest velocity [m/s], the sideslip
    angle atan(v/V) it makes at true airspeed ``tas`` [m/s], onset [s] and the time after
    which it no longer changes [s] (NaN: never, as the harmonic gust).

    Parameters
    ----------
    gusts : sequence of gusts
        Gust shapes (:mod:`slingloads.models.gusts`).
    tas : float
        True airspeed. [m/s]

    Returns
    -------
    pandas.DataFrame
    """
    return pd.DataFrame({
        "shape": [g.kind for g in gusts],
        "description": [g.label for g in gusts],
        "peak gust [m/s]": [g.peak for g in gusts],
        "gust angle [deg]": [_deg(np.arctan(g.peak / tas)) for g in gusts],
        "onset [s]": [g.breakpoints[0] for g in gusts],
        "steady from [s]": [np.nan if g.end is None else g.end for g in gusts],
    })


@dataclass(frozen=True)
class SweepResult:
    """Sizing sweep: metrics against parachute area for each gust shape.

    Parameters
    ----------
    static : NeutralAreaResult
        The neutral area the sweep is scaled on.
    factors : ndarray, shape (k,)
        Swept areas over the neutral area. [-]
    runs : YawRuns
        The runs, every gust at every area.
    gusts : tuple
        The gust shapes (:mod:`slingloads.models.gusts`).
    tas : float
        True airspeed of the condition. [m/s]
    """

    static: NeutralAreaResult
    factors: np.ndarray
    runs: YawRuns
    gusts: tuple = field(default_factory=tuple)
    tas: float = np.nan

    def to_frame(self):
        """Metrics per run, with the area over the neutral area.

        Returns
        -------
        pandas.DataFrame
            :meth:`YawRuns.to_frame` with the area ratio [-].
        """
        frame = self.runs.to_frame()
        frame.insert(1, "area / neutral area [-]", frame["area [m^2]"] / self.static.area)
        return frame

    def by_area(self):
        """One row per swept area: every gust meets the criterion (verdict in
        :data:`~slingloads.analyses.verdicts.ACCEPTED`)?, the worst verdict, peak sideslip
        and yaw over the gusts.

        Returns
        -------
        pandas.DataFrame
            One row per area [m^2]: area ratio [-], all gusts stable, worst verdict, peak sideslip
            and yaw [deg].
        """
        frame = self.to_frame()
        grouped = frame.groupby("area [m^2]", sort=True)
        return pd.DataFrame({
            "area / neutral area [-]": grouped["area / neutral area [-]"].first(),
            "all gusts stable": grouped["verdict"].agg(
                lambda v: bool(v.isin(_verdicts.ACCEPTED).all())),
            "worst verdict": grouped["verdict"].agg(lambda v: _verdicts.worst(list(v))),
            "worst peak beta [deg]": grouped["peak beta [deg]"].max(),
            "worst peak psi [deg]": grouped["peak psi [deg]"].max(),
        }).reset_index()

    @property
    def smallest_stable_area(self):
        """Smallest swept area at which every gust run meets the criterion (convergent,
        or bounded under a sustained gust); NaN if none does. This, not a factor on the
        neutral area, is the sizing's recommendation: an area the sweep shows failing is
        never recommended. [m^2]"""
        table = self.by_area()
        ok = table[table["all gusts stable"]]
        return float(ok["area [m^2]"].min()) if len(ok) else float("nan")

    def history_frame(self, factors=(1.0, 1.5, 2.0)):
        """Histories of the runs whose area ratio is nearest each of ``factors``.

        Parameters
        ----------
        factors : sequence of float
            Area ratios. [-]

        Returns
        -------
        pandas.DataFrame
            :meth:`YawRuns.history_frame` of those runs.
        """
        ratio = self.runs.areas / self.static.area
        chosen = []
        for f in factors:
            nearest = ratio[np.argmin(np.abs(ratio - f))]
            chosen += list(np.nonzero(np.isclose(ratio, nearest))[0])
        return self.runs.history_frame(sorted(set(chosen)))

    def gust_frame(self):
        """One row per gust shape: what it is, its largest velocity and the sideslip that
        makes at the condition's true airspeed, when it starts and when it stops changing.

        Returns
        -------
        pandas.DataFrame
            :func:`gust_frame` of the sweep's gusts.
        """
        return gust_frame(self.gusts, self.tas)

    def frames(self):
        """The tables of the result, by sheet name.

        Returns
        -------
        dict of str to pandas.DataFrame
            Neutral area, gusts, sweep and histories, by sheet name.
        """
        return {**self.static.frames(), "chute gusts": self.gust_frame(),
                "chute sweep": self.to_frame(), "chute histories": self.history_frame()}


def sizing_sweep(model, factors=None, gusts=None, settings=None, fit_range=FIT_RANGE,
                 metrics=None, static=None, integrator="dopri5"):
    """Sweep the parachute area from 1x to 2x the neutral static area over several gusts.

    Parameters
    ----------
    model : YawModel
    factors : array_like, optional
        Area over neutral area (default 100 values from 1 to 2). [-]
    gusts : sequence, optional
        Gust shapes (default: step, 10 s finite, 10 s 1-cosine and 10 s-period continuous, 30
        ft/s, at t = 30 s).
    settings : SolverSettings, optional
    static : NeutralAreaResult, optional
        Reuse a neutral-area result.

    Returns
    -------
    SweepResult
        All runs are integrated at once (vectorised over area x gust).
    """
    static = neutral_area(model, fit_range) if static is None else static
    if static.already_stable:
        raise InputError("fuselage and fin are already statically stable: the neutral "
                         "parachute area is not positive; sweep explicit areas with run_yaw",
                         static.area)
    factors = np.linspace(1.0, 2.0, 100) if factors is None else np.asarray(factors, float)
    if factors.ndim != 1 or factors.size == 0 or np.any(~np.isfinite(factors) | (factors < 0)):
        raise InputError("area factors must be a non-empty list of numbers >= 0",
                         np.atleast_1d(factors).tolist())
    gusts = standard_gusts() if gusts is None else tuple(gusts)
    areas = np.repeat(factors * static.area, len(gusts))
    gust_runs = tuple(gusts) * factors.size
    runs = run_yaw(model, areas, gust_runs, settings, fit_range, metrics, integrator)
    return SweepResult(static, factors, runs, gusts, model.condition.tas)


def with_area(model, area):
    """A copy of ``model`` whose parachute template has ``area`` (convenience for reports).

    Parameters
    ----------
    model : YawModel
    area : float
        Parachute flat-plate area. [m^2]

    Returns
    -------
    YawModel
    """
    return replace(model, parachute=replace(model.parachute, area=area))


__all__ = [
    "FIT_RANGE", "NEUTRAL_BASES", "SIDESLIP_LIMIT", "VERDICTS", "LineLengthResult", "LinearYaw",
    "LinearisationResult", "MetricSettings", "NeutralAreaResult", "SweepResult", "YawModel",
    "YawRuns", "gust_frame", "line_length", "local_slope", "linear_yaw", "neutral_area", "run_yaw",
    "sizing_sweep", "with_area", "yaw_linearisation",
]

"""One-degree-of-freedom yaw model of the carried helicopter about its suspension axis.

The helicopter hangs from its rotor hub; the suspension axis is the line through the hub
(:attr:`Hardpoints.hub`) along :attr:`YawModel.axis`: the line from the hook through the hub
(at rest the hub-CG line; in towed flight the trimmed cable's line,
:attr:`slingloads.analyses.towed_attitude.TowedAttitude.axis`), airframe z when not given. The
only freedom is the yaw angle psi about that axis (the hub does not move, the airframe stays at
the trim angle of attack). Moments and inertia are both taken about it: a point r from the hub
has the arms ``dx = (a x r)_y``, ``dy = -(a x r)_x`` (a the unit axis; ``dx = r_x, dy = r_y``
for a = z), and a moment vector M contributes ``-a . M`` (nose right positive): the fuselage's
``-a . M = q S L (a_x Cl + a_z Cn)`` in body-axes coefficients, plus its force's transfer. The
sideslip is taken to change one for one with psi: yawing by psi turns the airflow d about a,
so that exactly ``dbeta/dpsi = -(a x d)_y``, the sine of the angle between the axis and the
airflow (cos(alpha) for a = z; 0.997 at the example's towed trim, whose cable line is nearly
normal to the flow); the factor scales every aerodynamic stiffness alike and leaves the neutral
area, where the total is zero, unchanged.
Conventions, as in :mod:`slingloads.models.aerodynamics`: airframe axes x aft, y right, z
up; psi and the yawing moment N positive **nose right** (a negative rotation about +a, so
N = -M_z for a = z); sideslip beta positive with the wind from the right; directionally
stable means dN/dbeta > 0.

Kinematics. With a lateral gust v (air moving from right to left) at true airspeed V, the
relative wind comes from gamma = atan2(v, V) to the right of the flight path at speed
V_r = sqrt(V^2 + v^2); yawing the nose right by psi turns the nose towards it, so

.. math:: \\beta = \\gamma - \\psi, \\qquad q = \\tfrac12 \\rho V_r^2 .

A point at (dx, dy) from the axis moves at (r dy, -r dx) with r = dpsi/dt (nose right moves
the tail left); the air passes it at ``u = (V_r cos(beta) - r dy, -V_r sin(beta) + r dx)``.

Moments about the suspension axis:

* fuselage, from the full nonlinear table at the trim alpha:
  ``N_fus = q S L Cn(alpha, beta) - [dx_ref F_y - dy_ref F_x]`` where ``(dx_ref, dy_ref)`` is
  the moment reference point from the axis and F the table's force (side-force transfer);
* fin, side force at its centre of pressure from the full table at the *local* sideslip
  ``beta_f = atan2(-u_y, u_x)`` and local dynamic pressure: ``N_fin = -dx_f q_f S_f eta CY``;
* parachute, Apollo legacy drogue model [1]_: the drag acts at the attachment along the
  relative air velocity ``u`` of the attachment point,
  ``F = 1/2 rho eta_w CD A |u| u``, ``N_chute = -(dx_c F_y - dy_c F_x)``. Its dependence on r
  through u gives the drogue's damping as well as its stiffness.

* weight (when given, :attr:`YawModel.weight`): yawing the body by psi turns the weight W,
  fixed in the earth, about the axis in airframe axes, ``W(psi) = W_par + W_perp cos(psi) +
  (a x W) sin(psi)``, so that with r_g the CG from the hub
  ``-a . (r_g x W(psi)) = W_c cos(psi) + W_s sin(psi)``, ``W_c = -(a x r_g) . W``,
  ``W_s = -(a x r_g) . (a x W)``. The moment at psi = 0, ``W_c``, belongs to the trim (the
  towed trim balances it with the aerodynamic and parachute moments at its own sideslip; zero
  for a symmetric body), so the model takes its change, ``N_w = W_c (cos(psi) - 1) +
  W_s sin(psi)``: zero about the vertical through the hub (the hanging body at rest), a
  stiffness ``-W_s = (r_g)_perp . W_perp`` about a tilted axis (the towed trim's cable line,
  a few degrees from the vertical).

Equation of motion ``I psi'' = N_fus + N_fin + N_chute + N_w``, state ``(psi, r)``.

Linearised about beta = 0, r = 0 (symmetric tables, dy = 0) the parachute contributes the
stiffness ``dN/dbeta = q eta_w CD A dx_c`` and the damping ``-dN/dr = 1/2 rho V eta_w CD A
dx_c^2``; the fin ``-q S_f eta CY_beta dx_f`` and ``-1/2 rho V S_f eta CY_beta dx_f^2``.

Airspeed: the condition is given as indicated airspeed, taken equal to equivalent airspeed
(position and compressibility errors are neglected at 80 kt); q = 1/2 rho0 V_EAS^2.

Three integrators of the same moments: :func:`integrate_rk4`, fixed-step Runge-Kutta 4, and
:func:`integrate_dopri`, the adaptive Dormand-Prince 5(4) pair, both compiled over all runs at
once (:mod:`slingloads.models.yaw_batch`, the sizing sweep); and
:func:`integrate_reference`, one :func:`scipy.integrate.solve_ivp` call per run on
:meth:`YawModel.derivatives` (the reference they are checked against).

References
----------
.. [1] K. Currin, J. Gamble, D. Matz, D. Bretz, "Evaluation of Drogue Parachute Damping Effects
   Utilizing the Apollo Legacy Parachute Model", 30th AIAA Applied Aerodynamics Conference,
   2012.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from slingloads.errors import InputError
from slingloads.limits import (
    MAX_CHUTE_RUN_STEPS,
    MAX_CHUTE_STEPS,
    MAX_ODE_EVALUATIONS,
    evaluation_budget,
)
from slingloads.models.aerodynamics import Fin, FuselageAero
from slingloads.models.airframe import Hardpoints
from slingloads.models.flight import SIZING_SPEED, FlightCondition
from slingloads.models.gusts import (
    DrydenTurbulence,
    FiniteGust,
    HarmonicGust,
    OneMinusCosineGust,
    StepGust,
    SustainedGust,
    TabulatedGust,
)
from slingloads.models.integration import solver_settings
from slingloads.models.parachute import Parachute
from slingloads.models.yaw_moments import (  # noqa: F401 (the model row, re-exported)
    CHUTE_CD,
    CHUTE_DX,
    CHUTE_DY,
    FIN_DX,
    FIN_DY,
    FIN_HI,
    FIN_LO,
    FIN_LOCAL,
    FUS_HI,
    FUS_LO,
    HALF_RHO,
    HAS_CHUTE,
    HAS_FIN,
    HAS_FUS,
    INERTIA,
    LAYOUT,
    N_MODEL,
    TAS,
    WEIGHT_C,
    WEIGHT_S,
    make_yaw_moments,
    numpy_moments,
    weight_moment,
)

#: Axes of the 1-DOF yaw model about the hub
#: (:func:`slingloads.analyses.towed_attitude.yaw_model_about`): the suspension axis (default),
#: or airframe z through the hub (the paper's balance of Mz, section 4.1).
YAW_AXES = ("suspension", "airframe z")

#: Defaults of the yaw runs: 120 s at a 0.05 s RK4 step, stored every 0.1 s. [s]
YAW_SOLVER_DEFAULTS = {"t_end": 120.0, "step": 0.05, "output_interval": 0.1}
#: Half-width of the sideslip interval searched for the yaw trim. [rad]
TRIM_SEARCH = np.radians(20.0)


def _unit_axis(axis):
    """The suspension axis as a unit vector (airframe z for None), or an error."""
    if axis is None:
        return np.array([0.0, 0.0, 1.0])
    a = np.asarray(axis, dtype=float).reshape(-1)
    norm = float(np.linalg.norm(a)) if a.size == 3 and np.all(np.isfinite(a)) else 0.0
    if not norm > 0 or not a[2] > 0:
        raise InputError("the suspension axis must be a finite 3-vector pointing up from the "
                         "hub towards the hook (z component > 0) [-]",
                         a.tolist() if a.size <= 3 else a.size)
    return a / norm


def _arms(axis, r):
    """Arms (dx, dy) about the suspension axis of a point r from the hub: a side force F_y
    gives the moment a . (r x F) = dx F_y - dy F_x (module notes). [m]"""
    c = np.cross(axis, np.asarray(r, float))
    return float(c[1]), float(-c[0])

def _weight_terms(axis, weight, cg, hub):
    """(W_c, W_s) of the weight's moment about the suspension axis (module notes). [N m]"""
    if weight is None and cg is None:
        return 0.0, 0.0
    if weight is None or cg is None:
        raise InputError("the yaw model's weight needs both the weight vector and the CG")
    w = np.asarray(weight, dtype=float).reshape(-1)
    r = np.asarray(cg, dtype=float).reshape(-1) - hub
    if w.size != 3 or r.size != 3 or not (np.all(np.isfinite(w)) and np.all(np.isfinite(r))):
        raise InputError("the yaw model's weight and CG must be finite 3-vectors [N], [m]")
    c = np.cross(axis, r)
    return float(-c @ w), float(-c @ np.cross(axis, w))


def relative_wind(tas, gust):
    """Wind angle and relative speed of a lateral gust on a flight at true airspeed ``tas``:
    the one definition for the yaw models (:class:`YawModel` and the linear model of
    :mod:`slingloads.analyses.chute_sizing`).

    Parameters
    ----------
    tas : float
        True airspeed. [m/s]
    gust : array_like
        Lateral gust velocity. [m/s]

    Returns
    -------
    gamma : ndarray
        Wind angle atan2(v, V). [rad]
    v_rel : ndarray
        Relative speed sqrt(V^2 + v^2). [m/s]
    """
    v = np.asarray(gust, dtype=float)
    return np.arctan2(v, tas), np.hypot(tas, v)


@dataclass(frozen=True)
class YawModel:
    """The carried helicopter's yaw about its suspension axis (module notes).

    Parameters
    ----------
    fuselage : FuselageAero or None
        Fuselage alone; ``None`` leaves it out.
    fin : Fin or None
        The cut-down fin; ``None`` leaves it out.
    hardpoints : Hardpoints
        ``hub`` fixes the suspension axis; ``chute`` the parachute attachment.
    yaw_inertia : float
        Yaw inertia about the suspension axis (Izz about the CG plus m d^2 for a hub offset
        horizontally from the CG by d), > 0. [kg m^2]
    condition : FlightCondition
        Airspeed > 0 (default the paper's 80 KIAS at ISA sea level) and trim angle of attack.
    parachute : Parachute or None
        Drag coefficient (at canopy alpha 0: the canopy trails along the flow) times the wake
        ratio, the one factor that carries the wake loss (:mod:`slingloads.models.parachute`);
        the area comes with each run. ``None`` with area 0 runs models no parachute.
    fin_rate_damping : bool
        Evaluate the fin at its local sideslip (yaw-rate damping); False uses the axis sideslip.
    axis : array_like, shape (3,), optional
        The suspension axis: direction from the hub towards the hook, airframe axes, pointing
        up (z component > 0); normalised. None is airframe z. ``yaw_inertia`` must be about
        the same line (:func:`slingloads.models.airframe.hanging_yaw_inertia` with ``axis``).
        [-]
    weight : array_like, shape (3,), optional
        The weight vector at psi = 0 in airframe axes (m g times the earth's downward vertical
        at the trim); with ``cg``. None leaves the weight out (the paper's balance of the
        aerodynamic moments alone; exact when the axis is vertical). [N]
    cg : array_like, shape (3,), optional
        Centre of gravity, airframe axes (with ``weight``). [m]
    """

    fuselage: FuselageAero | None
    fin: Fin | None
    hardpoints: Hardpoints
    yaw_inertia: float
    condition: FlightCondition = field(
        default_factory=lambda: FlightCondition(SIZING_SPEED))
    parachute: Parachute | None = None
    fin_rate_damping: bool = True
    axis: np.ndarray | None = None
    weight: np.ndarray | None = None
    cg: np.ndarray | None = None

    def __post_init__(self):
        inertia = float(self.yaw_inertia)
        if not np.isfinite(inertia) or inertia <= 0:
            raise InputError("yaw inertia must be > 0 [kg m^2]", inertia)
        object.__setattr__(self, "yaw_inertia", inertia)
        if not isinstance(self.condition, FlightCondition):
            raise InputError("the yaw model's condition must be a FlightCondition",
                             type(self.condition).__name__)
        if self.condition.hover:
            raise InputError("the yaw model needs an airspeed > 0 [m/s] (its stiffness and "
                             "damping come from the free stream)", self.condition.eas,
                             field="airspeed")
        object.__setattr__(self, "_half_rho", 0.5 * self.condition.density)
        object.__setattr__(self, "_tas", self.condition.tas)
        axis = _unit_axis(self.axis)
        object.__setattr__(self, "axis", axis)
        hub = self.hardpoints.hub
        alpha = self.condition.alpha
        if self.fuselage is not None:
            grid = self.fuselage.table.beta
            force, moment = self.fuselage.loads(np.full(grid.shape, alpha), grid, 1.0)
            arm = self.fuselage.moment_reference - hub
            # N per unit q about the suspension axis: -a . (M + r x F). [m^3]
            n_per_q = -(moment + np.cross(arm, force)) @ axis
            object.__setattr__(self, "_fus", (grid, n_per_q, grid[0], grid[-1]))
        if self.fin is not None:
            dx, dy = _arms(axis, self.fin.centre_of_pressure - hub)
            grid, cfy = self.fin.side_force_coefficients  # airframe y, whatever the axes
            k = self.fin.area * self.fin.efficiency * cfy
            object.__setattr__(self, "_fin", (grid, k, dx, dy, grid[0], grid[-1]))
        if self.parachute is not None:
            if self.hardpoints.chute is None:
                raise InputError("a parachute needs the attachment point Hardpoints.chute")
            dx, dy = _arms(axis, self.hardpoints.chute - hub)
            cd = float(self.parachute.effective_coefficient(0.0))
            object.__setattr__(self, "_chute", (cd, dx, dy))
        object.__setattr__(self, "_weight", _weight_terms(axis, self.weight, self.cg, hub))

    # ----------------------------------------------------------------------------- helpers
    @property
    def axis_tilt(self):
        """Angle between the suspension axis and airframe z. [rad]"""
        return float(np.arccos(np.clip(self.axis[2], -1.0, 1.0)))

    @property
    def weight_terms(self):
        """(W_c, W_s) of the weight's yawing moment about the suspension axis,
        ``W_c cos(psi) + W_s sin(psi)``; the model takes its change from psi = 0,
        :meth:`weight_moment` (module notes; (0, 0) without a weight). [N m]"""
        return self._weight

    def weight_moment(self, psi):
        """The change of the weight's yawing moment about the suspension axis from psi = 0,
        nose right positive (module notes).

        Parameters
        ----------
        psi : array_like
            Yaw, nose right positive. [rad]

        Returns
        -------
        ndarray
            [N m]
        """
        return weight_moment(np.asarray(psi, dtype=float), self._arrays[0])

    @property
    def chute_arm(self):
        """(dx, dy) of the parachute attachment from the suspension axis, in the plane
        normal to it (module notes). [m]"""
        return None if self.parachute is None else self._chute[1:]

    @property
    def fin_arm(self):
        """(dx, dy) of the fin centre of pressure from the suspension axis. [m]"""
        return None if self.fin is None else self._fin[2:4]

    @property
    def fuselage_moment_table(self):
        """(beta grid [rad], yawing moment about the suspension axis per unit q [m^3]) of the
        fuselage at the trim angle of attack, or None."""
        return None if self.fuselage is None else self._fus[:2]

    @property
    def fin_side_force_table(self):
        """(beta grid [rad], S_fin eta CY [m^2]) of the fin, or None."""
        return None if self.fin is None else self._fin[:2]

    @property
    def chute_drag_coefficient(self):
        """Wake ratio times the canopy's free-stream CD at alpha 0 (the paper's 0.95 with the
        defaults 0.95 x 1.0). [-]"""
        return 0.0 if self.parachute is None else self._chute[0]

    def beta_range(self):
        """Sideslip range covered by every table in the model (fuselage and fin).

        Returns
        -------
        lo, hi : float
            [rad]
        """
        lo, hi = -np.pi, np.pi
        if self.fuselage is not None:
            lo, hi = max(lo, self._fus[2]), min(hi, self._fus[3])
        if self.fin is not None:
            lo, hi = max(lo, self._fin[4]), min(hi, self._fin[5])
        return lo, hi

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
        return relative_wind(self._tas, gust)

    # ----------------------------------------------------------------------------- moments
    def moments(self, beta, rate, v_rel, area):
        """Yawing moments about the suspension axis, nose right positive.

        Parameters
        ----------
        beta : array_like
            Sideslip at the axis. [rad]
        rate : array_like
            Yaw rate, nose right positive. [rad/s]
        v_rel : array_like
            Relative airspeed V_r. [m/s]
        area : array_like
            Parachute flat-plate area (0 for none). [m^2]

        Returns
        -------
        fuselage, fin, chute : ndarray
            [N m]
        outside : ndarray of bool
            True where a table was queried outside its range (the value is then not valid).
        """
        beta = np.asarray(beta, dtype=float)
        rate = np.asarray(rate, dtype=float)
        v_rel = np.asarray(v_rel, dtype=float)
        area = np.asarray(area, dtype=float)
        if self.parachute is None and np.any(area != 0):
            raise InputError("a parachute area was given but the model has no parachute",
                             float(np.max(np.abs(area))))
        shape = np.broadcast_shapes(beta.shape, rate.shape, v_rel.shape)
        n_fus, n_fin, n_chute, inside = numpy_moments(beta, rate, v_rel, area, *self.arrays(),
                                                       None)
        zero = np.zeros(shape)
        n_fus, n_fin = zero + n_fus, zero + n_fin
        n_chute = n_chute if self.parachute is not None else zero
        return n_fus, n_fin, n_chute, ~np.broadcast_to(inside, shape)

    def arrays(self):
        """The model row and tables of :func:`make_yaw_moments` and of the compiled batches
        (:mod:`slingloads.models.yaw_batch`).

        Returns
        -------
        tuple of ndarray
            ``M`` (:data:`LAYOUT`), ``fus_x`` [rad], ``fus_n`` [m^3], ``fus_s`` [m^3/rad],
            ``fin_x`` [rad], ``fin_k`` [m^2], ``fin_s`` [m^2/rad] (the tables with the slopes
            of their segments).
        """
        return self._arrays

    @cached_property
    def _arrays(self):
        row = np.zeros(N_MODEL)
        row[HALF_RHO], row[INERTIA] = self._half_rho, self.yaw_inertia
        row[TAS] = self._tas
        row[WEIGHT_C], row[WEIGHT_S] = self._weight
        none = np.zeros(2)
        fus_x = fus_n = fin_x = fin_k = none
        if self.fuselage is not None:
            fus_x, fus_n, row[FUS_LO], row[FUS_HI] = self._fus
            row[HAS_FUS] = 1.0
        if self.fin is not None:
            fin_x, fin_k, row[FIN_DX], row[FIN_DY], row[FIN_LO], row[FIN_HI] = self._fin
            row[HAS_FIN], row[FIN_LOCAL] = 1.0, float(self.fin_rate_damping)
        if self.parachute is not None:
            row[CHUTE_CD], row[CHUTE_DX], row[CHUTE_DY] = self._chute
            row[HAS_CHUTE] = 1.0
        tables = []
        for x, f in ((fus_x, fus_n), (fin_x, fin_k)):
            slope = np.zeros(1) if x is none else np.diff(f) / np.diff(x)  # none: never read
            tables += [np.ascontiguousarray(a, dtype=float) for a in (x, f, slope)]
        return (row, *tables)

    def derivatives(self, psi, rate, gamma, v_rel, area):
        """State derivatives and the out-of-table flag.

        Parameters
        ----------
        psi, rate : array_like
            Yaw [rad] and yaw rate [rad/s].
        gamma, v_rel : array_like
            Wind angle [rad] and relative speed [m/s] (:meth:`relative_wind`).
        area : array_like
            Parachute flat-plate area. [m^2]

        Returns
        -------
        dpsi : ndarray
            [rad/s]
        drate : ndarray
            [rad/s^2]
        outside : ndarray of bool
            Where a table was read outside its range.
        """
        n_fus, n_fin, n_chute, outside = self.moments(gamma - psi, rate, v_rel, area)
        n_weight = self.weight_moment(psi)
        return rate, (n_fus + n_fin + n_chute + n_weight) / self.yaw_inertia, outside

    def static_moments(self, beta, area=0.0):
        """Moments at rest (r = 0, no gust) against sideslip.

        Parameters
        ----------
        beta : array_like
            Sideslip. [rad]
        area : array_like
            Parachute flat-plate area. [m^2]

        Returns
        -------
        n_fus, n_fin, n_chute : ndarray
            Fuselage, fin and parachute yawing moments, nose right positive. [N m]

        Raises
        ------
        InputError
            For a sideslip outside the tables (no extrapolation).
        """
        beta = np.asarray(beta, dtype=float)
        n_fus, n_fin, n_chute, outside = self.moments(beta, 0.0, self.condition.tas, area)
        if np.any(outside):
            bad = np.atleast_1d(beta)[np.atleast_1d(outside)][0]
            lo, hi = self.beta_range()
            raise InputError(f"beta = {np.degrees(bad):.6g} deg is outside the tables' range "
                             f"[{np.degrees(lo):.6g}, {np.degrees(hi):.6g}] deg; no "
                             f"extrapolation is done", float(np.degrees(bad)))
        return n_fus, n_fin, n_chute

    def trim_beta(self, area=0.0, search=TRIM_SEARCH):
        """Sideslip of the static equilibrium nearest to beta = 0 (0 for symmetric tables).

        Parameters
        ----------
        area : float
            Parachute flat-plate area. [m^2]
        search : float
            Half-width of the sideslip interval searched. [rad]

        Returns
        -------
        float
            [rad]

        Raises
        ------
        InputError
            When no equilibrium lies within +-``search``.
        """
        return float(self.trim_betas([area], search)[0])

    def trim_betas(self, areas, search=TRIM_SEARCH, gust=0.0):
        """:meth:`trim_beta` of several parachute areas at once (the moments on one
        sideslip grid, the parachute's scaled by each area), at rest or under a held gust.

        Parameters
        ----------
        areas : array_like, shape (n,)
            Parachute flat-plate areas. [m^2]
        search : float
            Half-width of the sideslip interval searched. [rad]
        gust : float
            A held lateral gust (0: at rest). Under it the aerodynamic moments scale with the
            relative speed squared and keep their zeros; the weight's moment, which turns with
            the heading psi = gamma - beta and not with the wind, moves the equilibrium
            (none without a weight). [m/s]

        Returns
        -------
        ndarray, shape (n,)
            [rad]
        """
        areas = np.atleast_1d(np.asarray(areas, dtype=float))
        lo, hi = self.beta_range()
        grid = np.linspace(max(lo, -search), min(hi, search), 801)
        gamma, v_rel = (float(x) for x in self.relative_wind(float(gust)))
        n_fus, n_fin, _, _ = self.moments(grid, 0.0, v_rel, 0.0)
        unit = (self.moments(grid, 0.0, v_rel, 1.0)[2] if self.parachute is not None
                else 0.0)
        if self.parachute is None and np.any(areas != 0):
            self.static_moments(grid, areas[areas != 0][0])  # refuses the area
        total = (0 + n_fus + n_fin + self.weight_moment(gamma - grid)) + areas[:, None] * unit
        total = np.broadcast_to(total, (areas.size, grid.size))
        b0, b1, n0, n1 = grid[:-1], grid[1:], total[:, :-1], total[:, 1:]
        change = np.sign(n0) != np.sign(n1)
        with np.errstate(divide="ignore", invalid="ignore"):
            roots = np.where(change, b0 - n0 * (b1 - b0) / (n1 - n0), np.nan)
        exact = total == 0
        roots = np.where(exact.any(axis=1)[:, None],
                         np.where(exact, grid, np.nan), np.pad(roots, ((0, 0), (0, 1)),
                                                               constant_values=np.nan))
        found = np.isfinite(roots).any(axis=1)
        if not found.all():
            i, j = int(np.argmin(found)), int(np.argmin(np.abs(grid)))
            area = f", parachute area {areas[i]:.6g} m^2" if areas[i] else ", no parachute"
            raise InputError(f"no yaw trim within +-{np.degrees(search):.3g} deg of sideslip: "
                             f"the yawing moment about the hub does not change sign "
                             f"({total[i, j]:.4g} N m at beta = {np.degrees(grid[j]):.3g} deg"
                             f"{area})", field="trim")
        nearest = np.nanargmin(np.abs(roots), axis=1)
        return roots[np.arange(areas.size), nearest]


@dataclass(frozen=True)
class Histories:
    """Sampled time histories of a batch of runs.

    Attributes
    ----------
    time : ndarray, shape (n,)
        [s]
    psi, rate, beta, gust : ndarray, shape (runs, n)
        Yaw [rad], yaw rate [rad/s], sideslip [rad], lateral gust [m/s].
    left_table : ndarray of bool, shape (runs,)
        The run reached a sideslip outside the tables; its state is frozen from ``exit_time``.
    exit_time : ndarray, shape (runs,)
        Time the run left the tables (NaN if it did not). [s]
    """

    time: np.ndarray
    psi: np.ndarray
    rate: np.ndarray
    beta: np.ndarray
    gust: np.ndarray
    left_table: np.ndarray
    exit_time: np.ndarray


def yaw_solver_settings(settings=None):
    """``settings`` with the yaw runs' defaults filled in (:data:`YAW_SOLVER_DEFAULTS`) and
    its fixed grid checked: ``t_end`` and ``output_interval`` must be whole multiples of
    ``step``.

    Parameters
    ----------
    settings : SolverSettings, optional
        Default :class:`SolverSettings`.

    Returns
    -------
    SolverSettings

    Raises
    ------
    InputError
        For something other than a SolverSettings, or a grid that does not fit.
    """
    settings = solver_settings(settings).with_defaults(**YAW_SOLVER_DEFAULTS)
    settings.fixed_grid()
    return settings


def _distinct(gusts):
    """Distinct gust objects (by identity) and each run's index into them."""
    seen, unique, index = {}, [], []
    for g in gusts:
        if id(g) not in seen:
            seen[id(g)] = len(unique)
            unique.append(g)
        index.append(seen[id(g)])
    return unique, np.array(index, dtype=int)


def _check_runs(model, areas, gusts, psi0, rate0):
    areas = np.atleast_1d(np.asarray(areas, dtype=float))
    gusts = tuple(gusts) if isinstance(gusts, (list, tuple)) else (gusts,)
    runs = max(areas.size, len(gusts))
    if areas.size == 1:
        areas = np.full(runs, areas[0])
    if len(gusts) == 1:
        gusts = gusts * runs
    if areas.size != runs or len(gusts) != runs:
        raise InputError("give one parachute area and one gust per run (or a single one)",
                         (int(areas.size), len(gusts)))
    bad = ~np.isfinite(areas) | (areas < 0)
    if np.any(bad):
        raise InputError("parachute area must be >= 0 [m^2]", float(areas[bad][0]))
    lo, hi = model.beta_range()
    for g in _distinct(gusts)[0]:
        gamma = np.arctan(g.peak / model.condition.tas)
        if gamma > min(-lo, hi):
            raise InputError(
                f"gust of {g.peak:.4g} m/s at {model.condition.tas:.4g} m/s true airspeed makes "
                f"a sideslip of {np.degrees(gamma):.4g} deg, outside the tables' range "
                f"[{np.degrees(lo):.4g}, {np.degrees(hi):.4g}] deg", g.peak)
    psi0 = np.broadcast_to(np.asarray(psi0, dtype=float), (runs,)).copy()
    rate0 = np.broadcast_to(np.asarray(rate0, dtype=float), (runs,)).copy()
    return areas, gusts, psi0, rate0


def integrate_rk4(model, areas, gusts, psi0=0.0, rate0=0.0, settings=None):
    """Integrate many runs with fixed-step RK4, compiled, the runs spread over the cores.

    Parameters
    ----------
    model : YawModel
    areas : array_like, shape (runs,) or scalar
        Parachute flat-plate areas. [m^2]
    gusts : gust or sequence of gusts, one per run (see :mod:`slingloads.models.gusts`)
    psi0, rate0 : array_like
        Initial yaw [rad] and yaw rate [rad/s] (trim: psi0 = -beta_trim).
    settings : SolverSettings, optional

    Returns
    -------
    Histories

    Raises
    ------
    InputError
        For a model that is not a :class:`YawModel`, or runs, gusts or settings out of
        range.

    Notes
    -----
    The step grid is uniform with every gust breakpoint (jump or kink: onsets, ends, the end
    of a rise) inserted, so that no step straddles one; histories are stored on the uniform
    output grid. Each run is integrated on its own by the RK4 step of
    :mod:`slingloads.models.runge_kutta` (:func:`slingloads.models.yaw_batch.rk4_batch`).
    Gust velocities are tabulated once per distinct gust (at the start, middle
    and end of each step, the end value taken just before the step end so that a jump on a
    step boundary is seen on the correct side); a turbulence realisation is a function of
    time, so every stage sees the same gust. Table lookups are ``np.interp`` on the tables'
    breakpoints; a run that leaves a table is flagged and frozen, never clamped silently.
    """
    from slingloads.models import yaw_batch

    if not isinstance(model, YawModel):
        raise InputError("the compiled yaw integrators run a YawModel",
                         type(model).__name__)
    settings = yaw_solver_settings(settings)
    areas, gusts, psi, rate = _check_runs(model, areas, gusts, psi0, rate0)
    runs = areas.size
    unique, index = _distinct(gusts)
    times = settings.output_times()
    nodes, stored = _time_nodes(settings, unique)
    start, step = nodes[:-1], np.diff(nodes)
    # the relative wind (channels yaw_batch.WIND) of each distinct gust at the start (after a
    # jump there), middle and end (just before a jump) of each step: (gusts, steps, 3, N_WIND)
    wind = np.empty((len(unique), step.size, 3, yaw_batch.N_WIND))
    for stage, when in enumerate((start, start + 0.5 * step, nodes[1:] - 1e-9 * step)):
        v = np.stack([g.velocity(when) for g in unique])  # (unique, steps)
        gamma, v_rel = model.relative_wind(v)
        wind[:, :, stage, yaw_batch.W_GAMMA] = gamma
        wind[:, :, stage, yaw_batch.W_V_REL] = v_rel
    out_psi, out_rate = np.empty((runs, times.size)), np.empty((runs, times.size))
    left = np.zeros(runs, dtype=bool)
    exit_step = np.zeros(runs, dtype=np.int64)
    yaw_batch.rk4_batch(psi, rate, areas, index, wind, step, stored, *model.arrays(),
                        out_psi, out_rate, left, exit_step)
    exit_time = np.where(left, start[exit_step], np.nan)
    gust_out = np.stack([g.velocity(times) for g in unique])
    gamma_out = model.relative_wind(gust_out)[0]
    beta = gamma_out[index] - out_psi
    return Histories(times, out_psi, out_rate, beta, gust_out[index], left, exit_time)


#: First trial step of the adaptive runs (the step then grows tenfold a step at most). [s]
FIRST_STEP = 1e-3


def integrate_dopri(model, areas, gusts, psi0=0.0, rate0=0.0, settings=None):
    """Integrate many runs with the compiled adaptive Dormand-Prince 5(4) pair.

    The same runs as :func:`integrate_rk4`, each with its own step, controlled so that the
    local error estimate stays within ``settings.atol + settings.rtol |y|`` (the norm and the
    step control of :func:`scipy.integrate.solve_ivp`'s ``RK45``), at most
    ``settings.max_step``; ``settings.step`` is not used. Runs are integrated in parallel
    over the cores (:func:`slingloads.models.yaw_batch.dopri_batch`), segment by segment
    between their gust's breakpoints, and sampled on the output times from the method's
    fourth-order dense output. The gust is evaluated in the kernel from its exact formula
    (:func:`_gust_pieces`). A stage outside a table halves the step; a run that still leaves
    below 1e-6 s is flagged and frozen from then, never clamped silently. The work is
    bounded: each run may try :data:`~slingloads.limits.MAX_CHUTE_STEPS` steps (accepted or
    rejected), and :data:`~slingloads.limits.MAX_CHUTE_RUN_STEPS` / runs when that is fewer;
    a run that needs more stops every run and the call raises an :class:`InputError`
    (``field="rtol"``) instead of keeping the cores busy for hours (a very stiff model, a
    tolerance near round-off).

    Parameters
    ----------
    model : YawModel
    areas : array_like, shape (runs,) or scalar
        Parachute flat-plate areas. [m^2]
    gusts : gust or sequence of gusts (step, finite, 1-cosine, continuous, harmonic,
        turbulence or tabulated; :mod:`slingloads.models.gusts`)
    psi0, rate0 : array_like
        Initial yaw [rad] and yaw rate [rad/s].
    settings : SolverSettings, optional

    Returns
    -------
    Histories
    """
    from slingloads.models import yaw_batch

    if not isinstance(model, YawModel):
        raise InputError("the adaptive compiled integrator runs a YawModel; use the 'rk4' "
                         "integrator for other models", type(model).__name__)
    settings = yaw_solver_settings(settings)
    areas, gusts, psi, rate = _check_runs(model, areas, gusts, psi0, rate0)
    runs = areas.size
    unique, index = _distinct(gusts)
    times = settings.output_times()
    t_end = float(times[-1])
    pieces = [_gust_pieces(g, t_end) for g in unique]
    segments = [_segments(g, p, t_end) for g, p in zip(unique, pieces, strict=True)]
    seg_end = _padded([e for e, _ in segments], np.inf)
    seg_piece = _padded([k for _, k in segments], 0).astype(np.int64)
    n_seg = np.array([len(e) for e, _ in segments], dtype=np.int64)
    width = max(len(p) for p in pieces)
    p_start = np.full((len(unique), width), np.inf)
    p_coef = np.zeros((len(unique), width, len(yaw_batch.PIECE)))
    h_off = np.zeros((len(unique), width), dtype=np.int64)
    h_count = np.zeros((len(unique), width), dtype=np.int64)
    # the columns of the tables by their names (yaw_batch.PIECE, yaw_batch.HARMONIC)
    piece_columns = [yaw_batch.P_C0, yaw_batch.P_C1, yaw_batch.P_REF]
    term_columns = [yaw_batch.H_AMPLITUDE, yaw_batch.H_OMEGA, yaw_batch.H_PHASE]
    harm = [np.zeros((0, len(yaw_batch.HARMONIC)))]
    rows = 0
    for g, gust_pieces in enumerate(pieces):
        for k, (start, c0, c1, ref, terms) in enumerate(gust_pieces):
            p_start[g, k] = start
            p_coef[g, k, piece_columns] = c0, c1, ref
            h_off[g, k], h_count[g, k] = rows, len(terms)
            block = np.empty((len(terms), len(yaw_batch.HARMONIC)))
            block[:, term_columns] = np.asarray(terms, dtype=float).reshape(-1, 3)
            harm.append(block)
            rows += len(terms)
    harm = np.ascontiguousarray(np.concatenate(harm))
    out_psi, out_rate = np.empty((runs, times.size)), np.empty((runs, times.size))
    left = np.zeros(runs, dtype=bool)
    exit_time = np.full(runs, np.nan)
    steps = np.zeros(runs, dtype=np.int64)
    budget = max(min(MAX_CHUTE_STEPS, MAX_CHUTE_RUN_STEPS // runs), 1)
    stop = np.zeros(1, dtype=np.int64)
    yaw_batch.dopri_batch(psi, rate, areas, index.astype(np.int64), seg_end, seg_piece, n_seg,
                          p_start, p_coef, h_off, h_count, harm, float(settings.output_interval),
                          float(settings.rtol), float(settings.atol), float(settings.max_step),
                          FIRST_STEP, budget, stop, *model.arrays(), out_psi, out_rate,
                          left, exit_time, steps)
    if stop[0]:
        raise InputError(f"too much work: a yaw run needs more than {budget:,} adaptive steps "
                         f"(limits of slingloads: at most {MAX_CHUTE_STEPS:,} a run and "
                         f"{MAX_CHUTE_RUN_STEPS:,} over the runs); loosen the tolerance, shorten "
                         "the runs or check the yaw inertia and the tables for a very stiff "
                         "case", float(settings.rtol), field="rtol")
    gust_out = np.stack([g.velocity(times) for g in unique])
    gamma_out = model.relative_wind(gust_out)[0]
    beta = gamma_out[index] - out_psi
    return Histories(times, out_psi, out_rate, beta, gust_out[index], left, exit_time)


def _segments(gust, pieces, t_end):
    """(ends [s], pieces) of the smooth segments of ``gust`` over (0, ``t_end``]: they end at
    its breakpoints and at the starts of its ``pieces`` (:func:`_gust_pieces`), then at
    ``t_end``; each lies on one piece, the last that starts at or before the segment's
    start."""
    starts = np.array([p[0] for p in pieces], dtype=float)
    inner = [b for b in (*gust.breakpoints, *starts) if b is not None and 0.0 < b < t_end]
    ends = np.unique([*inner, t_end])
    begins = np.concatenate([[0.0], ends[:-1]])
    return ends, np.searchsorted(starts, begins, side="right") - 1


def _padded(rows, fill):
    out = np.full((len(rows), max(len(r) for r in rows)), fill, dtype=float)
    for i, r in enumerate(rows):
        out[i, :len(r)] = r
    return out


def _gust_pieces(gust, t_end):
    """The gust as formulas between its breakpoints, for the compiled adaptive integrator:
    ``[(start [s], c0 [m/s], c1 [m/s^2], ref [s], [(a [m/s], omega [rad/s], phase [rad])])]``,
    the gust from ``start`` on (until the next piece) being
    ``c0 + c1 (t - start) + sum a cos(omega (t - ref) + phase)``; the same formulas as the
    gusts' ``velocity``."""
    if isinstance(gust, TabulatedGust):
        gust.velocity(t_end)  # refuses an end time past the table
        t, v = gust.time, gust.velocity_table
        slope = np.diff(v) / np.diff(t)
        return ([(0.0, 0.0, 0.0, 0.0, [])]
                + [(t[i], v[i], slope[i], 0.0, []) for i in range(t.size - 1)]
                + [(t[-1], v[-1], 0.0, 0.0, [])])
    if isinstance(gust, DrydenTurbulence):
        terms = np.column_stack([gust.amplitudes, gust.omega, gust.phases])
        return [(0.0, 0.0, 0.0, 0.0, []), (gust.onset, 0.0, 0.0, gust.onset, terms),
                (gust.end, 0.0, 0.0, 0.0, [])]
    if not isinstance(gust, StepGust):
        raise InputError(f"the adaptive compiled integrator knows the gusts of "
                         f"slingloads.models.gusts, not a {type(gust).__name__}; use the "
                         f"'rk4' integrator", type(gust).__name__)
    amp, t0 = gust.amplitude, gust.onset
    rest = (0.0, 0.0, 0.0, 0.0, [])
    if isinstance(gust, HarmonicGust):
        return [rest, (t0, 0.0, 0.0, t0, [(amp, 2 * np.pi / gust.period, -0.5 * np.pi)])]
    if isinstance(gust, SustainedGust):
        tr = gust.rise_time
        if tr == 0:
            return [rest, (t0, amp, 0.0, 0.0, [])]
        return [rest, (t0, 0.5 * amp, 0.0, t0, [(-0.5 * amp, np.pi / tr, 0.0)]),
                (t0 + tr, amp, 0.0, 0.0, [])]
    if isinstance(gust, OneMinusCosineGust):
        d = gust.duration
        return [rest, (t0, 0.5 * amp, 0.0, t0, [(-0.5 * amp, 2 * np.pi / d, 0.0)]),
                (t0 + d, 0.0, 0.0, 0.0, [])]
    if isinstance(gust, FiniteGust):
        return [rest, (t0, amp, 0.0, 0.0, []), (t0 + gust.duration, 0.0, 0.0, 0.0, [])]
    return [rest, (t0, amp, 0.0, 0.0, [])]


def _time_nodes(settings, gusts):
    """The uniform RK4 grid with every gust breakpoint (jump or kink) inserted, so that no
    step straddles one; and a flag per node: True at the stored (uniform output) times.

    A breakpoint closer than 1e-6 of a step to a grid node is taken as that node.
    """
    n, every = settings.fixed_grid()
    grid = np.arange(n + 1) * settings.step
    stored = np.zeros(n + 1, dtype=bool)
    stored[::every] = True
    breaks = np.unique([b for g in gusts for b in g.breakpoints
                        if b is not None and 0.0 < b < settings.t_end])
    if breaks.size:
        near = np.abs(breaks[:, None] - grid[None, :]).min(axis=1) < 1e-6 * settings.step
        extra = breaks[~near]
        if extra.size:
            order = np.argsort(np.concatenate([grid, extra]), kind="stable")
            grid = np.concatenate([grid, extra])[order]
            stored = np.concatenate([stored, np.zeros(extra.size, dtype=bool)])[order]
    return grid, stored


def integrate_reference(model, areas, gusts, psi0=0.0, rate0=0.0, settings=None):
    """The same runs as :func:`integrate_rk4`, one :func:`scipy.integrate.solve_ivp` per run.

    Adaptive (``settings.method``, ``rtol``, ``atol``, ``max_step``), sampled at the same output
    times, integrated piecewise between the gust's breakpoints (so that no step straddles a
    jump). It is the reference for runs that stay inside their tables: a run found outside
    them at an output time is flagged (``left_table``) but not frozen.

    Parameters
    ----------
    model : YawModel
    areas : array_like, shape (runs,) or scalar
        Parachute flat-plate areas. [m^2]
    gusts : gust or sequence of gusts, one per run (:mod:`slingloads.models.gusts`)
    psi0, rate0 : array_like
        Initial yaw [rad] and yaw rate [rad/s].
    settings : SolverSettings, optional
        ``method``, ``rtol``, ``atol``, ``max_step``, ``t_end`` and ``output_interval``.

    Returns
    -------
    Histories
    """
    from scipy.integrate import solve_ivp  # scipy loads where it is used

    settings = yaw_solver_settings(settings)
    areas, gusts, psi0, rate0 = _check_runs(model, areas, gusts, psi0, rate0)
    times = settings.output_times()
    runs = areas.size
    # From a trimmed rest the adaptive step grows without bound and could jump over a finite
    # gust entirely; the step is therefore capped at the output interval.
    max_step = min(settings.max_step, settings.output_interval)
    out_psi, out_rate = np.empty((runs, times.size)), np.empty((runs, times.size))
    for j in range(runs):
        gust, area = gusts[j], areas[j]

        def rhs(t, y, gust=gust, area=area):
            gamma, v_rel = model.relative_wind(gust.velocity(t))
            dpsi, drate, _ = model.derivatives(y[0], y[1], gamma, v_rel, area)
            return [float(dpsi), float(drate)]

        budget = evaluation_budget(rhs, "the solve_ivp reference runs", field="rtol",
                                   limit=MAX_ODE_EVALUATIONS // runs)
        cuts = np.unique([0.0, *(b for b in gust.breakpoints
                                 if b is not None and 0.0 < b < times[-1]), times[-1]])
        which = np.clip(np.searchsorted(cuts, times, side="right") - 1, 0, cuts.size - 2)
        y = [psi0[j], rate0[j]]
        for k in range(cuts.size - 1):
            sol = solve_ivp(budget, (cuts[k], cuts[k + 1]), y, method=settings.method,
                            rtol=settings.rtol, atol=settings.atol, max_step=max_step,
                            dense_output=True)
            if not sol.success:
                raise InputError(f"solve_ivp failed: {sol.message}", j)
            inside = which == k
            out_psi[j, inside], out_rate[j, inside] = sol.sol(times[inside])
            y = sol.y[:, -1]
    gust_out = np.stack([g.velocity(times) for g in gusts])
    gamma, v_rel = model.relative_wind(gust_out)
    beta = gamma - out_psi
    *_, outside = model.moments(beta, out_rate, v_rel, areas[:, None])
    left = outside.any(axis=1)
    first = np.where(left, times[np.argmax(outside, axis=1)], np.nan)
    return Histories(times, out_psi, out_rate, beta, gust_out, left, first)


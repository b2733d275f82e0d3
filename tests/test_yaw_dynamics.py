"""1-DOF yaw model (paper section 4.2): closed-form checks, signs, drogue damping, integrators.

Closed-form reference: the damped single-degree-of-freedom oscillator I x'' + c x' + k x = f(t)
(e.g. W. T. Thomson, "Theory of Vibration with Applications", ch. 2 and 4): free response
x0 e^(-zeta w t) (cos wd t + zeta / sqrt(1 - zeta^2) sin wd t) and step response
x_s (1 - e^(-zeta w t) (cos wd t + zeta / sqrt(1 - zeta^2) sin wd t)).
"""

from dataclasses import replace

import numpy as np
import pytest
from numpy.testing import assert_allclose
from rk4_references import yaw_rk4_numpy

from slingloads.analyses.chute_sizing import LinearYaw, MetricSettings, neutral_area, run_yaw
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import FUSELAGE_COEFFICIENTS, Fin, FuselageAero
from slingloads.models.airframe import Hardpoints
from slingloads.models.flight import FlightCondition
from slingloads.models.gusts import (
    DrydenTurbulence,
    FiniteGust,
    HarmonicGust,
    OneMinusCosineGust,
    StepGust,
    SustainedGust,
    TabulatedGust,
    standard_gusts,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)
from slingloads.models.yaw_dynamics import (
    YawModel,
    integrate_dopri,
    integrate_reference,
    integrate_rk4,
)

SPAN = np.radians(60.0)

INERTIA, K, C, V = 9000.0, 5000.0, 1500.0, 41.0


def oscillator(t, k=K, c=C, inertia=INERTIA):
    """Unit step response of I x'' + c x' + k x = k u(t), and the free-response shape."""
    w = np.sqrt(k / inertia)
    z = c / (2 * np.sqrt(k * inertia))
    wd = w * np.sqrt(1 - z * z)
    shape = np.exp(-z * w * t) * (np.cos(wd * t) + z / np.sqrt(1 - z * z) * np.sin(wd * t))
    return 1.0 - shape, shape


def linear_model(cn_beta=-0.4, cy_fin=-3.0, span=SPAN, fin=True, chute=True):
    """Fuselage Cn = cn_beta * beta exactly, fin CY linear, reference point on the hub axis."""
    beta = np.linspace(-span, span, 25)
    alpha = np.radians([-5.0, 0.0, 5.0])
    coeffs = {k: np.zeros((3, beta.size)) for k in FUSELAGE_COEFFICIENTS}
    coeffs["Cn"] = np.tile(cn_beta * beta, (3, 1))
    fus = FuselageAero(Table2D(alpha, beta, coeffs), 3.0, 11.0, np.array([0.0, 0.0, 0.0]))
    f = Fin(Table1D(beta, {"CY": cy_fin * beta}), 1.0, np.array([5.0, 0.0, 1.0]), 0.5)
    hp = Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]], chute=[6.0, 0.0, 1.5])
    return YawModel(fus, f if fin else None, hp, 9000.0, FlightCondition(80 * KNOT),
                    Parachute(1.0) if chute else None)


def test_linear_free_response_matches_closed_form():
    """Free response of the linearised model (the RK4 scheme, as the numpy reference of the
    compiled batch steps it; ``test_compiled_rk4_equals_the_numpy_rk4`` shows the compiled
    batch gives the same to round-off) against the closed form."""
    lin = LinearYaw(INERTIA, K, C, {}, V)
    s = SolverSettings(t_end=30.0, step=0.01, output_interval=0.1)
    h = yaw_rk4_numpy(lin, 0.0, StepGust(0.0), psi0=0.02, settings=s)
    _, shape = oscillator(h.time)
    assert_allclose(h.psi[0], 0.02 * shape, atol=1e-9)


def test_linear_step_and_finite_gust_match_closed_form():
    """Step gust: psi -> gamma0 = atan(v/V) as a step response from the onset; finite gust: the
    superposition of a step at the onset and a negative step at its end (the RK4 scheme of the
    numpy reference, as above)."""
    lin = LinearYaw(INERTIA, K, C, {}, V)
    s = SolverSettings(t_end=60.0, step=0.02, output_interval=0.1)
    gusts = [StepGust(3.0, 10.0), FiniteGust(3.0, 10.0, 10.0)]
    h = yaw_rk4_numpy(lin, [0.0, 0.0], gusts, settings=s)
    g0 = np.arctan2(3.0, V)
    t = h.time
    step_on = np.where(t >= 10, oscillator(np.maximum(t - 10, 0))[0], 0.0)
    step_off = np.where(t >= 20, oscillator(np.maximum(t - 20, 0))[0], 0.0)
    assert_allclose(h.psi[0], g0 * step_on, atol=1e-8)
    assert_allclose(h.psi[1], g0 * (step_on - step_off), atol=1e-8)


@pytest.mark.parametrize("integrate", [integrate_rk4, integrate_dopri])
def test_nonlinear_model_small_gust_matches_hand_linearisation(integrate):
    """Full model with exactly linear tables and a tiny gust against the closed-form response
    with stiffness and damping derived by hand from the geometry:
    k = q (S L n_b - S_f eta y_b l_f + eta_w CD A l_c),
    c = 1/2 rho V (-S_f eta y_b l_f^2 + eta_w CD A l_c^2), by the fixed-step RK4 and by the
    adaptive Dormand-Prince 5(4) (rtol 1e-8) alike."""
    model = linear_model()
    cond = model.condition
    area = 2.0
    k = cond.dynamic_pressure * (3 * 11 * -0.4 - 1 * 0.5 * -3.0 * 5 + 0.95 * 1.0 * area * 6)
    c = 0.5 * cond.density * cond.tas * (-1 * 0.5 * -3.0 * 25 + 0.95 * 1.0 * area * 36)
    s = SolverSettings(t_end=40.0, step=0.02, output_interval=0.1)
    h = integrate(model, area, StepGust(0.02, 5.0), settings=s)
    g0 = np.arctan2(0.02, cond.tas)
    expected = g0 * np.where(h.time >= 5, oscillator(np.maximum(h.time - 5, 0), k, c)[0], 0.0)
    assert_allclose(h.psi[0], expected, atol=2e-3 * g0)


def test_drogue_damping_equals_hand_derivation():
    """Apollo legacy model (Currin et al. 2012): drag along the attachment point's relative
    velocity u = (V cos b, -V sin b + r l_c). At b = 0, N = -l_c F_y with
    F_y = 1/2 rho eta CD A |u| u_y, so dN/dr = -1/2 rho V eta CD A l_c^2 and
    dN/dbeta = q eta CD A l_c (hand derivation)."""
    model = linear_model()
    rho, v, area, l_c = model.condition.density, model.condition.tas, 1.7, 6.0
    r = 1e-6
    _, _, plus, _ = model.moments(0.0, r, v, area)
    _, _, minus, _ = model.moments(0.0, -r, v, area)
    assert float(plus - minus) / (2 * r) == pytest.approx(
        -0.5 * rho * v * 0.95 * 1.0 * area * l_c**2, rel=1e-6)
    b = 1e-6
    _, _, plus, _ = model.moments(b, 0.0, v, area)
    _, _, minus, _ = model.moments(-b, 0.0, v, area)
    assert float(plus - minus) / (2 * b) == pytest.approx(
        0.5 * rho * v * v * 0.95 * 1.0 * area * l_c, rel=1e-6)


def test_signs_fuselage_diverges_fin_and_chute_converge():
    """Facts s.3: the fuselage alone is directionally unstable, so a small yaw grows; with the
    fin and a parachute of twice the neutral area it decays (paper s.4.2)."""
    ref = sample_reference("HC1")
    s = SolverSettings(t_end=60.0, step=0.05, output_interval=0.5)
    alone = YawModel(sample_fuselage("HC1"), None, sample_hardpoints("HC1"), ref.yaw_inertia)
    h = integrate_rk4(alone, 0.0, StepGust(0.0), psi0=np.radians(0.5), settings=s)
    assert np.degrees(h.psi[0]).max() > 10.0
    full = YawModel(sample_fuselage("HC1"), sample_fin("HC1"), sample_hardpoints("HC1"),
                    ref.yaw_inertia, parachute=Parachute(1.0))
    area = 2 * neutral_area(full).area
    h = integrate_rk4(full, area, StepGust(0.0), psi0=np.radians(0.5), settings=s)
    assert abs(h.psi[0, -1]) < 0.01 * np.radians(0.5)


def test_log_decrement_matches_linear_damping_ratio():
    """Logarithmic decrement delta = 2 pi zeta / sqrt(1 - zeta^2) of the free decay after a
    small finite gust equals the hand-derived linear damping ratio (linear tables)."""
    model = linear_model()
    cond = model.condition
    area = 2.0
    k = cond.dynamic_pressure * (3 * 11 * -0.4 + 7.5 + 0.95 * area * 6)
    c = 0.5 * cond.density * cond.tas * (37.5 + 0.95 * area * 36)
    zeta = c / (2 * np.sqrt(k * 9000.0))
    runs = run_yaw(model, area, FiniteGust(0.05, 5.0, 5.0),
                   SolverSettings(t_end=80.0, step=0.02, output_interval=0.02))
    row = runs.to_frame().iloc[0]
    assert row["damping ratio log decrement [-]"] == pytest.approx(zeta, rel=5e-3)
    assert row["damping ratio linear [-]"] == pytest.approx(zeta, rel=1e-9)
    assert row["verdict"] == "stable"


def test_vectorised_rk4_agrees_with_solve_ivp():
    """The vectorised fixed-step RK4 against scipy's adaptive RK45 (rtol 1e-9), one call per
    run, on the four gust shapes (HC2, 1.5 x neutral area)."""
    ref = sample_reference("HC2")
    model = YawModel(sample_fuselage("HC2"), sample_fin("HC2"), sample_hardpoints("HC2"),
                     ref.yaw_inertia, parachute=Parachute(1.0))
    area = 1.5 * neutral_area(model).area
    s = SolverSettings(t_end=60.0, step=0.05, output_interval=0.5, rtol=1e-9, atol=1e-11)
    gusts = standard_gusts()
    fast = integrate_rk4(model, area, gusts, settings=s)
    slow = integrate_reference(model, area, gusts, settings=s)
    assert np.degrees(np.abs(fast.psi - slow.psi)).max() < 2e-3
    assert np.degrees(np.abs(fast.beta - slow.beta)).max() < 2e-3


def test_adaptive_compiled_runs_match_the_tight_dop853_reference():
    """The compiled adaptive Dormand-Prince 5(4) (rtol 1e-8, atol 1e-10) against the
    reference: scipy's DOP853 at rtol 1e-11, atol 1e-13, one solve_ivp call per run and per
    piece between the gust's breakpoints (:func:`integrate_reference`), on every gust shape:
    sustained crosswind, finite, 1-cosine (breakpoints off any grid), harmonic, Dryden
    turbulence and a tabulated gust (each of its kinks a segment of the adaptive runs, not of
    the reference's), at 1x and 1.6x the neutral area of HC2 from trim. The yaw histories agree
    within 1e-3 deg, the accuracy the sizing sweep asks (about 2e-4 deg here); the fixed-step
    RK4 at 0.05 s on the same runs is held to the same bound as the former reference path."""
    ref = sample_reference("HC2")
    model = YawModel(sample_fuselage("HC2"), sample_fin("HC2"), sample_hardpoints("HC2"),
                     ref.yaw_inertia, parachute=Parachute(1.0))
    neutral = neutral_area(model).area
    gusts = [SustainedGust(6.0, 5.03, 3.33), FiniteGust(6.0, 5.03, 7.31),
             OneMinusCosineGust(6.0, 5.03, 7.31), HarmonicGust(4.0, 5.0, 9.0),
             DrydenTurbulence(2.0, 250.0, model.condition.tas, onset=5.0, duration=15.0,
                              seed=1),
             TabulatedGust([5.0, 6.0, 8.0, 9.5, 12.0, 14.0, 30.0],
                           [0.0, 4.0, -2.0, 5.0, 1.0, 0.0, 0.0])]
    tight = SolverSettings(t_end=30.0, step=0.05, output_interval=0.1, method="DOP853",
                           rtol=1e-11, atol=1e-13)
    s = SolverSettings(t_end=30.0, step=0.05, output_interval=0.1, rtol=1e-8, atol=1e-10)
    for factor in (1.0, 1.6):
        for gust in gusts:
            fast = integrate_dopri(model, factor * neutral, gust, settings=s)
            rk4 = integrate_rk4(model, factor * neutral, gust, settings=s)
            slow = integrate_reference(model, factor * neutral, gust, settings=tight)
            assert not fast.left_table.any() and not slow.left_table.any()
            assert np.degrees(np.abs(fast.psi - slow.psi)).max() < 1e-3, gust.kind
            assert np.degrees(np.abs(rk4.psi - slow.psi)).max() < 2e-3, gust.kind
            assert np.degrees(np.abs(slow.psi)).max() > 0.5  # the gust did move it


def test_adaptive_runs_of_a_very_stiff_model_are_refused_quickly():
    """A yaw inertia of 0.01 kg m^2 instead of 8,500 (HC2, 2 m^2 parachute): the yaw mode's
    fastest root, c / I with c = 1/2 rho V eta_w CD A l_c^2 + fin, is about 2.6e5 1/s, so
    the explicit pair needs steps below 3.3 / |lambda| = 1.3e-5 s, some 10 million of them
    for a 120 s run. The compiled runs stop at the 200,000 steps a run allowed (all runs at
    once) and the call is refused with the setting to change, instead of computing for
    minutes."""
    ref = sample_reference("HC2")
    model = YawModel(sample_fuselage("HC2"), sample_fin("HC2"), sample_hardpoints("HC2"), 0.01,
                     parachute=Parachute(1.0))
    with pytest.raises(InputError, match="more than 200,000 adaptive steps") as err:
        integrate_dopri(model, 2.0, standard_gusts(), settings=SolverSettings(t_end=120.0))
    assert err.value.field == "rtol"
    sane = replace(model, yaw_inertia=ref.yaw_inertia)
    assert not integrate_dopri(sane, 2.0, standard_gusts()[:1]).left_table.any()


def test_rk4_steps_on_gust_breakpoints_off_the_grid():
    """Gust breakpoints off the step grid (a finite gust from 10.03 s for 7.31 s, a sustained
    crosswind rising from 10.03 s over 3.33 s) and a Dryden turbulence realisation: the RK4
    integrator inserts the breakpoints into its grid, so it keeps its fourth-order agreement
    with solve_ivp (rtol 1e-10, integrated piecewise between the same breakpoints): within
    2e-4 deg here, where the uniform grid alone (a step straddling the 10.03 s jump) errs by
    0.05 deg."""
    ref = sample_reference("HC2")
    model = YawModel(sample_fuselage("HC2"), sample_fin("HC2"), sample_hardpoints("HC2"),
                     ref.yaw_inertia, parachute=Parachute(1.0))
    area = 1.5 * neutral_area(model).area
    s = SolverSettings(t_end=30.0, step=0.05, output_interval=0.5, rtol=1e-10, atol=1e-12)
    gusts = [FiniteGust(6.0, 10.03, 7.31), SustainedGust(6.0, 10.03, 3.33),
             DrydenTurbulence(2.0, 250.0, model.condition.tas, onset=10.0, duration=15.0,
                              seed=1)]
    fast = integrate_rk4(model, area, gusts, settings=s)
    slow = integrate_reference(model, area, gusts, settings=s)
    assert np.degrees(np.abs(fast.beta - slow.beta)).max() < 2e-4
    assert np.degrees(np.abs(fast.psi).max()) > 1.0      # the gusts did move the aircraft


def test_run_beyond_the_linearised_range_or_the_limit_is_never_stable():
    """A stable aircraft (linear tables, a 2 m^2 parachute) under a sharp-edged crosswind of
    tan(beta) = v/V: the run returns to trim, but a gust angle of 12.6 deg leaves a +-10 deg
    linearisation range, and 7.0 deg passes a 5 deg sideslip limit: neither is called
    stable, and the reason says which rule; the same 7.0 deg run with the +-10 deg range and
    the default 20 deg limit is stable (the rules, not the dynamics, decide)."""
    model = linear_model()
    tas = model.condition.tas
    s = SolverSettings(t_end=60.0)
    big = SustainedGust(tas * np.tan(np.radians(12.6)), 5.0, 0.0)
    small = SustainedGust(tas * np.tan(np.radians(7.0)), 5.0, 0.0)
    ten = (np.radians(-10.0), np.radians(10.0))
    runs = run_yaw(model, 2.0, [big, small], s, fit_range=ten).to_frame()
    assert list(runs["verdict"]) == ["beyond limits", "stable"]
    assert "leaves the linearisation range [-10, 10] deg" in runs["verdict reason"][0]
    assert runs["peak beta [deg]"][0] == pytest.approx(12.6, rel=1e-3)
    tight = run_yaw(model, 2.0, small, s, fit_range=ten,
                    metrics=MetricSettings(sideslip_limit=np.radians(5.0))).to_frame()
    assert tight["verdict"][0] == "beyond limits"
    assert "passes the sideslip limit 5 deg" in tight["verdict reason"][0]


def test_run_leaving_the_table_is_flagged_divergent():
    """No silent clamping: an unstable fuselage driven out of a +-60 deg table is flagged and
    judged divergent."""
    model = linear_model(fin=False, chute=False)
    runs = run_yaw(model, 0.0, StepGust(2.0, 1.0), SolverSettings(t_end=60.0))
    row = runs.to_frame().iloc[0]
    assert bool(row["left table"]) and row["verdict"] == "divergent"


def test_bad_dynamic_input():
    """Zero or negative speed, inertia, area; a gust beyond the tables; bad solver settings and
    a non-monotonic table: each an InputError echoing the value."""
    m = linear_model()
    with pytest.raises(InputError, match=r"airspeed > 0 \[m/s\].*value 0.0"):
        YawModel(m.fuselage, m.fin, m.hardpoints, 9000.0, FlightCondition(eas=0.0))
    with pytest.raises(InputError, match=r"airspeed must be >= 0.*-5"):
        FlightCondition(eas=-5.0)
    with pytest.raises(InputError, match=r"yaw inertia must be > 0.*0.0"):
        YawModel(m.fuselage, m.fin, m.hardpoints, 0.0)
    with pytest.raises(InputError, match=r"parachute area must be >= 0.*-1"):
        run_yaw(m, -1.0, StepGust())
    with pytest.raises(InputError, match=r"gust of 100 m/s .* outside the tables' range"):
        run_yaw(m, 1.0, StepGust(100.0))
    with pytest.raises(InputError, match="t_end must be a whole multiple of the step.*100.01"):
        run_yaw(m, 1.0, StepGust(), SolverSettings(t_end=100.01, step=0.05))
    with pytest.raises(InputError, match=r"step must be > 0.*-0.05"):
        SolverSettings(step=-0.05)
    with pytest.raises(InputError, match="strictly increasing"):
        Table1D(np.radians([0.0, 10.0, 10.0]), {"CY": [0.0, -0.5, -0.5]})
    with pytest.raises(InputError, match=r"flat-plate area must be > 0.*0.0"):
        Parachute(0.0)


@pytest.mark.parametrize("fin_rate_damping", [True, False])
def test_compiled_rk4_equals_the_numpy_rk4(fin_rate_damping):
    """The compiled batch against its reference, the numpy RK4 batch of
    ``rk4_references.yaw_rk4_numpy`` (the scheme written out in numpy): the same
    scheme on the same grid (gust breakpoints off the step grid included), so the histories
    agree to round-off: HC2 with the four gust shapes at 1.5x its neutral area, and the
    exactly linear tables of ``linear_model`` (+-60 deg) with and without a parachute,
    started 0.3 rad off: without one that airframe diverges and leaves its tables, and both
    batches stop that run at the same step."""
    ref = sample_reference("HC2")
    hc2 = YawModel(sample_fuselage("HC2"), sample_fin("HC2"), sample_hardpoints("HC2"),
                   ref.yaw_inertia, parachute=Parachute(1.0), fin_rate_damping=fin_rate_damping)
    gusts = [*standard_gusts(), FiniteGust(6.0, 10.03, 7.31)]
    linear = replace(linear_model(), fin_rate_damping=fin_rate_damping)
    s = SolverSettings(t_end=60.0, step=0.05, output_interval=0.5)
    for model, areas, psi0 in ((hc2, 1.5 * neutral_area(hc2).area, 0.0),
                               (linear, np.repeat([0.0, 2.0], len(gusts)), 0.3)):
        runs = gusts * (np.size(areas) // len(gusts) or 1)
        fast = integrate_rk4(model, areas, runs, psi0=psi0, settings=s)
        slow = yaw_rk4_numpy(model, areas, runs, psi0=psi0, settings=s)
        assert_allclose(fast.psi, slow.psi, rtol=0, atol=1e-12)
        assert_allclose(fast.rate, slow.rate, rtol=0, atol=1e-12)
        np.testing.assert_array_equal(fast.left_table, slow.left_table)
        np.testing.assert_array_equal(fast.exit_time, slow.exit_time)
    assert slow.left_table.any() and not slow.left_table.all()

"""Lateral-step study: vectorised sweep against solve_ivp, the study table against closed
forms, the outputs' layout, bad input, and the plots."""

import numpy as np
import pandas as pd
import pytest
from matplotlib.figure import Figure
from numpy.testing import assert_allclose
from scipy.special import ellipk

from slingloads.analyses.lateral import (
    REGULATORY_ANGLE,
    ParameterRanges,
    acceleration_sweep,
    lateral_study,
    simulate,
    simulation,
    sweep,
)
from slingloads.constants import FOOT, G0
from slingloads.errors import InputError
from slingloads.io.lateral.plots import plot_max_angle_vs_acceleration, plot_time_histories
from slingloads.models.carrier_motion import (
    ConstantAcceleration,
    CycloidalStep,
    QuinticStep,
    TimeHistory,
    VelocityStep,
)
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import LateralPendulum, SlungBody

UH60 = SlungBody(7439.0, 7632.0, 1.722, "UH-60A")   # NASA TM 85890
BO105 = SlungBody(2096.0, 1803.0, 0.95, "BO-105C")  # NASA CR-3144
POINT = SlungBody(1000.0, 1.0, 0.0, "point mass")   # CG at the hub
ROPES = [18.0 * FOOT, 60.0 * FOOT, 100.0 * FOOT]


def test_vectorised_sweep_agrees_with_solve_ivp():
    """The vectorised RK4 sweep gives the same peak load angle, rope angle and tension as
    per-run solve_ivp (DOP853, rtol 1e-10) within 0.1 %, for rigid and elastic cables and every
    kind of carrier motion (the accuracy the benchmark's 10x claim is made at)."""
    t = np.linspace(0.0, 4.0, 41)
    history = TimeHistory(t, QuinticStep(3.0, 4.0).displacement(t), name="sampled step")
    cases = [
        (LateralPendulum(UH60, ROPES[0]), QuinticStep.from_peak_acceleration(0.3 * G0, 2.0)),
        (LateralPendulum(BO105, ROPES[1]), ConstantAcceleration(0.5 * G0, 1.0, "stop")),
        (LateralPendulum(UH60, ROPES[0], cable_ea=2e7), ConstantAcceleration(2.0, 3.0)),
        (LateralPendulum(BO105, ROPES[0], cable_ea=2e7), VelocityStep(2.0)),
        (LateralPendulum(UH60, ROPES[1]), history),
    ]
    pendulums, motions = zip(*cases, strict=True)
    metrics, _ = sweep(pendulums, motions, solver=SolverSettings(t_end=12.0))
    solver = SolverSettings(t_end=12.0, output_interval=0.002, method="DOP853", rtol=1e-10,
                            atol=1e-12)
    for i, (p, m) in enumerate(cases):
        ref = simulate(p, m, solver=solver).metrics
        assert metrics.max_load_angle[i] == pytest.approx(ref.max_load_angle, rel=1e-3)
        assert metrics.max_rope_angle[i] == pytest.approx(ref.max_rope_angle, rel=1e-3)
        assert metrics.max_tension_ratio[i] == pytest.approx(ref.max_tension_ratio, rel=1e-3)
        assert metrics.t_max_load_angle[i] == pytest.approx(ref.t_max_load_angle, abs=0.01)


@pytest.fixture(scope="module")
def point_mass_study():
    accelerations = [0.1 * G0, 0.3 * G0, 0.5 * G0]
    motions = [ConstantAcceleration(a, 100.0) for a in accelerations]  # held throughout
    return lateral_study([POINT], ROPES, motions, margin=1.25,
                         ranges=ParameterRanges.nominal(), solver=SolverSettings(t_end=12.0))


def test_point_mass_study_against_closed_form(point_mass_study):
    """Point mass, support accelerated at a and held: every row's peak load angle is
    2 atan(a/g) (FACTS 5), so the largest is 2 atan(0.5) = 53.13 deg and the recommended
    angle is margin x 2 atan(0.5). The peak recurs every period of the pendulum swinging
    +-atan(a/g) about the tilted equilibrium in the field g_eff = sqrt(g^2 + a^2): at odd
    multiples of the half period 2 sqrt(l/g_eff) K(sin^2(atan(a/g)/2)) (exact large-amplitude
    pendulum, complete elliptic integral K)."""
    table = point_mass_study.to_frame()
    a = table["peak S'' [m/s^2]"].to_numpy()
    length = table["rope length [m]"].to_numpy()
    assert_allclose(table["max |theta1 - theta2| [deg]"], np.degrees(2 * np.arctan(a / G0)),
                    rtol=1e-5)
    amplitude = np.arctan(a / G0)
    half_period = 2 * np.sqrt(length / np.hypot(G0, a)) * ellipk(np.sin(amplitude / 2) ** 2)
    cycles = table["t at max |theta1 - theta2| [s]"].to_numpy() / half_period
    assert_allclose(cycles, 2 * np.round((cycles - 1) / 2) + 1, atol=1e-4)
    assert point_mass_study.max_load_angle == pytest.approx(2 * np.arctan(0.5), rel=1e-5)
    assert point_mass_study.recommended_angle == pytest.approx(1.25 * 2 * np.arctan(0.5),
                                                               rel=1e-5)
    assert point_mass_study.critical_case["peak S'' [g]"] == pytest.approx(0.5)
    assert point_mass_study.exceeds_regulatory_angle  # 66 deg > 30 deg: no reduction


def test_study_outputs_layout(point_mass_study):
    """The study's frames: one row per case (1 body x 3 ropes x 3 motions), unit-labelled
    columns, a summary with the recommended angle beside the 30 deg, an envelope per rope."""
    frames = point_mass_study.frames()
    assert set(frames) == {"lateral summary", "lateral runs", "lateral cases", "lateral envelope",
                           "lateral sensitivity", "lateral tension", "lateral ranges",
                           "lateral damping"}
    runs = frames["lateral runs"]
    assert len(runs) == 9
    for column in ("rope length [m]", "mass [kg]", "max |theta1 - theta2| [deg]",
                   "max |theta1| [deg]", "max T/(m g) [-]", "t at max T/(m g) [s]"):
        assert column in runs
    summary = frames["lateral summary"].set_index("quantity")
    assert summary.loc["CS-29.865 angle", "value"] == pytest.approx(30.0)
    assert summary.loc["recommended design angle", "unit"] == "deg"
    assert len(frames["lateral envelope"]) == 9
    assert all(len(name) <= 31 for name in frames)  # Excel sheet-name limit


def test_envelope_over_the_ranges_is_the_maximum_of_the_separate_studies():
    """Bookkeeping of the ranges: the study over +-20 % of roll inertia, CG below hub and
    rope length (factors 0.8, 1, 1.2 each) gives, for every combination, the same peaks as
    the scaled bodies and ropes built here by hand and swept; its envelope is their maximum,
    its 'others nominal' sensitivity rows are the one-at-a-time studies, and its nominal
    maximum is the nominal study's."""
    motion = QuinticStep.from_peak_acceleration(0.3 * G0, 1.5)
    solver = SolverSettings(t_end=6.0, step=0.01)
    ranges = ParameterRanges(points=3)
    study = lateral_study([BO105], [ROPES[0]], [motion], margin=1.0, ranges=ranges,
                          solver=solver)
    assert len(study.pendulums) == 27
    keys = [(fi, fe, fl) for fi in (0.8, 1.0, 1.2) for fe in (0.8, 1.0, 1.2)
            for fl in (0.8, 1.0, 1.2)]
    pendulums = [LateralPendulum(SlungBody(BO105.mass, BO105.roll_inertia * fi,
                                           BO105.cg_below_hub * fe), ROPES[0] * fl)
                 for fi, fe, fl in keys]
    one_by_one, _ = sweep(pendulums, [motion] * len(keys), solver=solver)
    separate = dict(zip(keys, one_by_one.max_load_angle, strict=True))
    found = {tuple(np.round(f, 12)): a for f, a in zip(study.factors,
                                                      study.metrics.max_load_angle,
                                                      strict=True)}
    for key, angle in separate.items():
        assert found[key] == pytest.approx(angle, rel=1e-12)
    assert study.max_load_angle == pytest.approx(max(separate.values()), rel=1e-12)
    assert study.nominal_max_load_angle == pytest.approx(separate[1.0, 1.0, 1.0], rel=1e-12)
    sens = study.sensitivity_frame()
    row = sens[(sens["parameter"] == "roll inertia") & (sens["factor [-]"] == 0.8)].iloc[0]
    assert row["max load angle, others nominal [deg]"] == pytest.approx(
        np.degrees(separate[0.8, 1.0, 1.0]), rel=1e-12)
    assert row["max load angle, others over their ranges [deg]"] == pytest.approx(
        np.degrees(max(a for k, a in separate.items() if k[0] == 0.8)), rel=1e-12)


def test_tension_factor_against_the_hook_load_factor():
    """Point mass, hook speed step dV: the tension at the bottom of the swing is
    m (g + dV^2/L) (FACTS 5), so T/(m g) = 1 + dV^2/(g L): 2.0 for dV = sqrt(g L), 3.0 for
    dV = sqrt(2 g L). Against Nz = 2.5 the second exceeds and is flagged, the first not; a
    load angle over 30 deg makes the study say the 30 deg rule is not conservative."""
    length = ROPES[0]
    motions = [VelocityStep(np.sqrt(G0 * length)), VelocityStep(np.sqrt(2 * G0 * length))]
    study = lateral_study([POINT], [length], motions, margin=1.0, hook_load_factor=2.5,
                          ranges=ParameterRanges.nominal(), solver=SolverSettings(t_end=4.0))
    assert_allclose(study.metrics.max_tension_ratio, [2.0, 3.0], rtol=1e-3)
    assert list(study.exceeds_hook_load_factor) == [False, True]
    table = study.tension_frame()
    assert list(table["T/(m g) above Nz [-]"]) == [False, True]
    summary = study.summary_frame().set_index("quantity")["value"]
    assert summary["cases with T/(m g) above Nz"] == 1
    assert study.regulatory_angle_not_conservative   # the swings reach 60 and 90 deg
    assert "NOT conservative" in study.verdict()


def test_run_case_time_histories(point_mass_study):
    """Re-running the critical case gives the documented time-history columns, and a static
    hub load m g along the mast at t = 0 (hanging at rest: statics)."""
    run = point_mass_study.run_case()
    frame = run.to_frame()
    for column in ("t [s]", "theta1 [deg]", "roll [deg]", "theta1 - theta2 [deg]",
                   "T [N]", "T/(m g) [-]", "hub Fy [N]", "hub Fz [N]"):
        assert column in frame
    assert frame["hub Fz [N]"].iloc[0] == pytest.approx(POINT.mass * G0)
    assert frame["hub Fy [N]"].iloc[0] == pytest.approx(0.0, abs=1e-9)


def test_acceleration_sweep_peaks():
    """Every generated motion has the requested peak acceleration (quintic step: from
    A = a T^2 sqrt(3)/10) and duration, for each kind x acceleration x duration."""
    motions = acceleration_sweep([1.0, 4.9], [2.0, 5.0])
    assert len(motions) == 8
    assert_allclose([m.peak_acceleration for m in motions], [1.0, 1.0, 4.9, 4.9] * 2,
                    rtol=1e-12)
    assert_allclose([m.duration for m in motions], [2.0, 5.0] * 4)


@pytest.mark.parametrize("kwargs, match", [
    ({"margin": 0.9}, r"margin must be >= 1: value 0.9"),
    ({"margin": 1.5, "rope_lengths": [18.0, 0.0]}, r"rope length must be > 0 \[m\]: value 0.0"),
    ({"margin": 1.5, "motions": []}, r"at least one motion"),
    ({"margin": 1.5, "bodies": [1000.0]}, r"SlungBody.*'float'"),
    ({"margin": 1.5, "solver": 12.0}, r"must be a SolverSettings: value 'float'"),
])
def test_bad_study_input(kwargs, match):
    """Bad study input raises InputError naming the rule and echoing the value."""
    args = {"bodies": [UH60], "rope_lengths": [18.0], "motions": [VelocityStep(1.0)]}
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        lateral_study(**args)


def test_plots_draw_the_results(point_mass_study):
    """The plots draw the data they are given: the load-angle curve is the run's
    theta1 - theta2 in degrees, the 30 deg line is drawn, and the envelope plot has one line
    per rope length at the closed-form 2 atan(a/g)."""
    run = simulate(LateralPendulum(UH60, ROPES[0]), QuinticStep(5.0, 2.0),
                   solver=SolverSettings(t_end=8.0))
    fig = plot_time_histories(run)
    assert isinstance(fig, Figure)
    lines = fig.axes[0].get_lines()
    load = [ln for ln in lines if ln.get_label().startswith("load angle")][0]
    assert_allclose(load.get_ydata(), np.degrees(run.load_angle))
    assert any(np.allclose(ln.get_ydata(), 30.0) for ln in lines)

    fig = plot_max_angle_vs_acceleration(point_mass_study)
    ropes = [ln for ln in fig.axes[0].get_lines() if ln.get_label().startswith("rope")]
    assert len(ropes) == 3
    for ln in ropes:
        assert_allclose(ln.get_ydata(), np.degrees(2 * np.arctan(ln.get_xdata())), rtol=1e-5)
    assert any(np.allclose(ln.get_ydata(), np.degrees(REGULATORY_ANGLE))
               for ln in fig.axes[0].get_lines())


def test_models_and_analyses_do_not_import_io():
    """Layering rule: the physics never imports the io layer, openpyxl or matplotlib."""
    import pathlib

    import slingloads

    root = pathlib.Path(slingloads.__file__).parent
    lateral_files = [str(p.relative_to(root)) for p in (root / "analyses/lateral").glob("*.py")]
    assert len(lateral_files) > 1
    for name in ("models/carrier_motion.py", "models/pendulum.py", *lateral_files):
        text = (root / name).read_text()
        for banned in ("slingloads.io", "openpyxl", "matplotlib"):
            assert banned not in text, (name, banned)
    assert isinstance(pd.DataFrame(), pd.DataFrame)


def _numpy_right_hand_side(pendulum, motion):
    """simulate's right-hand side before the compiled fast path: the numpy equations at the
    motion's array kinematics."""
    def derivatives(t, x):
        _, v, a = motion.kinematics(t)
        return pendulum.derivatives(x, v, a)[0]

    return derivatives


_T = np.linspace(0.0, 4.0, 41)
_HISTORY = TimeHistory(_T + 0.5, 2.0 * _T + 0.3 * np.sin(2.0 * _T), name="ramp")
_DAMPED = {"lateral_damping": 2000.0, "roll_damping": 5000.0, "damping_height": 0.4}
_FAST_PATH_CASES = [
    (LateralPendulum(UH60, ROPES[0]), QuinticStep.from_peak_acceleration(0.3 * G0, 2.0)),
    (LateralPendulum(BO105, ROPES[1], **_DAMPED), CycloidalStep(-2.0, 1.5)),
    (LateralPendulum(UH60, ROPES[0], cable_ea=2e7), ConstantAcceleration(2.0, 1.0, "stop")),
    (LateralPendulum(BO105, ROPES[0], cable_ea=2e7, **_DAMPED), _HISTORY),
    (LateralPendulum(POINT, ROPES[2]), VelocityStep(2.0)),
]


@pytest.mark.parametrize("pendulum, motion", _FAST_PATH_CASES)
def test_right_hand_side_is_the_numpy_one(pendulum, motion):
    """simulate's right-hand side (compiled equations at kinematics_at) against the numpy
    equations at the motion's array kinematics, the right-hand side it replaces: the same
    doubles at random states and times (before, inside and after the motion, and at its
    breakpoints), a new array each call (solve_ivp keeps them), several states at once (the
    implicit methods' Jacobians) as numpy gives them, and numpy's nan (not an exception)
    where the elastic cable's hub is exactly at the hook."""
    fast = simulation._right_hand_side(pendulum, motion)
    numpy_rhs = _numpy_right_hand_side(pendulum, motion)
    rng = np.random.default_rng(3)
    n = len(pendulum.state_names)
    times = np.concatenate([rng.uniform(-1.0, 8.0, 300), motion.breakpoints])
    for t in times:
        x = pendulum.initial_state(1.0) + rng.normal(0.0, 0.5, n)
        got = fast(t, x[:, None])
        assert got.shape == (n,)
        np.testing.assert_array_equal(got, numpy_rhs(t, x[:, None])[:, 0])
    assert fast(1.0, x[:, None]) is not fast(1.0, x[:, None])
    columns = pendulum.initial_state(0.5)[:, None] + rng.normal(0.0, 0.5, (n, 3))
    np.testing.assert_array_equal(fast(0.7, columns), numpy_rhs(0.7, columns))
    if not pendulum.rigid:
        with np.errstate(invalid="ignore"):
            at_hook = fast(0.7, np.zeros((n, 1)))
        assert np.isnan(at_hook[3:5]).all()


@pytest.mark.parametrize("pendulum, motion", _FAST_PATH_CASES)
def test_simulate_histories_are_those_of_the_numpy_equations(pendulum, motion, monkeypatch):
    """End to end: simulate with its compiled right-hand side against simulate with the numpy
    one (monkeypatched in): the same number of evaluations and the same states, tension and
    carrier histories to the last bit, so solve_ivp took the same steps."""
    counts = []
    budget = simulation.evaluation_budget

    def counted_budget(function, *args, **kwargs):
        counts.append(0)
        inner = budget(function, *args, **kwargs)

        def f(*a):
            counts[-1] += 1
            return inner(*a)

        return f

    monkeypatch.setattr(simulation, "evaluation_budget", counted_budget)
    solver = SolverSettings(t_end=4.0, method="DOP853", rtol=1e-8)
    fast = simulate(pendulum, motion, solver=solver)
    monkeypatch.setattr(simulation, "_right_hand_side", _numpy_right_hand_side)
    reference = simulate(pendulum, motion, solver=solver)
    assert counts[0] == counts[1] > 50
    for name in ("t", "states", "tension", "carrier"):
        np.testing.assert_array_equal(getattr(fast, name), getattr(reference, name))


def test_simulate_counts_every_evaluation(monkeypatch):
    """The evaluation budget still counts every call of the fast right-hand side: with the
    limit set to 200, a run needing more is refused with the located budget error (field
    rtol) instead of finishing."""
    import slingloads.limits

    monkeypatch.setattr(slingloads.limits, "MAX_ODE_EVALUATIONS", 200)
    with pytest.raises(InputError, match="needs more than 200 evaluations") as error:
        simulate(*_FAST_PATH_CASES[0], solver=SolverSettings(t_end=4.0))
    assert error.value.field == "rtol"


def test_a_case_leaving_the_domain_yields_no_design_angle():
    """Point mass, hook speed step dV (FACTS 5): cos(theta_max) = 1 - dV^2/(2 g L). For
    dV^2 = 0.5 g L the swing peaks at acos(0.75) = 41.41 deg, inside the domain. For
    dV^2 = 3 g L the rope passes the horizontal (cos would be -0.5) and the rigid rope goes
    slack at cos(theta) = (2 - dV^2/(g L)) / 3 = -1/3 (109.5 deg): that case is outside the
    model's domain, with its reason, and the design angle (margin 1) is the 41.41 deg of the
    other case alone; the verdict says no reduction is supported while the case is in the set.
    Alone, the violent step leaves no design angle at all (NaN, never a value past 90 deg)."""
    length = ROPES[0]
    motions = [VelocityStep(np.sqrt(0.5 * G0 * length)), VelocityStep(np.sqrt(3 * G0 * length))]
    study = lateral_study([POINT], [length], motions, margin=1.0,
                          ranges=ParameterRanges.nominal(), solver=SolverSettings(t_end=6.0))
    assert list(study.in_domain) == [True, False]
    note = study.domain_notes()[1]
    assert "cable slack" in note and "over the top" in note
    assert np.degrees(study.recommended_angle) == pytest.approx(
        np.degrees(np.arccos(0.75)), rel=2e-3)
    assert "1 of 2 cases leave the model's domain" in study.verdict()
    alone = lateral_study([POINT], [length], motions[1:], margin=1.0,
                          ranges=ParameterRanges.nominal(), solver=SolverSettings(t_end=6.0))
    assert np.isnan(alone.recommended_angle) and "no design angle" in alone.verdict()


def test_carrier_limits_and_flyable_motions():
    """A coordinated carrier banked phi accelerates sideways at g tan(phi): at 20 deg,
    0.364 g; its rate at roll rate p is g sec^2(phi) p (1.94 m/s^3 at 10 deg/s). A quintic
    step's jerk is 60 A / T^3, checked against the finite difference of its acceleration; the
    example's quickest 0.36 g step (19 s) is flyable, a 0.5 g step in 2 s is not (both limits
    named), nor is any motion whose acceleration jumps (infinite jerk)."""
    from slingloads.analyses.lateral import CarrierLimits, flyable, peak_jerk

    limits = CarrierLimits()
    assert limits.acceleration == pytest.approx(G0 * np.tan(np.radians(20.0)), rel=1e-12)
    assert limits.jerk == pytest.approx(
        G0 * np.radians(10.0) / np.cos(np.radians(20.0)) ** 2, rel=1e-12)
    step = QuinticStep.from_peak_acceleration(0.36 * G0, 19.0)
    h = 1e-4
    numeric = (step.acceleration(h) - step.acceleration(0.0)) / h
    assert peak_jerk(step) == pytest.approx(numeric, rel=1e-3)
    assert flyable(step, limits) == ""
    fast = flyable(QuinticStep.from_peak_acceleration(0.5 * G0, 2.0), limits)
    assert "peak acceleration" in fast and "peak jerk" in fast
    assert np.isinf(peak_jerk(VelocityStep(1.0)))
    assert "peak jerk inf" in flyable(VelocityStep(1.0), limits)

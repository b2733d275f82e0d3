"""Hook trajectories as data (slingloads.models.hook_trajectory) in both dynamic models.

References: the exact integrals of a piecewise-linear acceleration (hand-worked below); the
constant-acceleration motion of slingloads.models.carrier_motion (another implementation of
the same law); the frozen carrier's integrated velocity, which must equal the commanded
velocity's closed form; the lateral pendulum under the same motion given two ways.
"""

from pathlib import Path

import numpy as np
import pytest

from slingloads.analyses.lateral import simulate as lateral_simulate
from slingloads.analyses.lateral import sweep
from slingloads.analyses.multibody import Manoeuvre, simulate
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.io.multibody.trajectory import read_trajectory_csv
from slingloads.models.airframe import Hardpoints
from slingloads.models.carrier_motion import ConstantAcceleration, QuinticStep
from slingloads.models.hook_trajectory import HookTrajectory, PiecewiseAcceleration
from slingloads.models.integration import SolverSettings
from slingloads.models.multibody import (
    Cable,
    ForwardAcceleration,
    LateralHookMotion,
    RigidBody,
    SlingSystem,
)
from slingloads.models.pendulum import LateralPendulum, SlungBody


def test_piecewise_acceleration_exact_integrals():
    """Trapezoid 0 -> 2 m/s^2 over 1 s, 2 held for 2 s, 2 -> 0 over 1 s: v(1) = 1,
    s(1) = 1/3; v(3) = 5, s(3) = 1/3 + 1*2 + 2*2^2/2 = 6.3333; v(4) = 6,
    s(4) = 6.3333 + 5 + 2/2 - 2/6 = 12; then the speed is held: s(6) = 12 + 12."""
    m = PiecewiseAcceleration([0.0, 1.0, 3.0, 4.0], [0.0, 2.0, 2.0, 0.0])
    s, v, a = m.kinematics(np.array([1.0, 3.0, 4.0, 6.0, -1.0]))
    np.testing.assert_allclose(s, [1 / 3, 19 / 3, 12.0, 24.0, 0.0], rtol=1e-14)
    np.testing.assert_allclose(v, [1.0, 5.0, 6.0, 6.0, 0.0], rtol=1e-14)
    np.testing.assert_allclose(a, [2.0, 2.0, 0.0, 0.0, 0.0], atol=1e-15)
    for t in (0.3, 1.0, 2.5, 3.7, 5.0):
        assert m.kinematics_at(t) == pytest.approx(tuple(float(x) for x in m.kinematics(t)),
                                                   rel=1e-14, abs=1e-15)


def test_held_acceleration_is_the_constant_acceleration_motion():
    """Held steps +4.9, -4.9, 0 m/s^2 at 0, 2, 4 s are ConstantAcceleration(4.9, 2, 'stop')
    of carrier_motion, at every time."""
    t = np.linspace(-1.0, 6.0, 141)
    mine = PiecewiseAcceleration([0.0, 2.0, 4.0], [4.9, -4.9, 0.0], "previous")
    ref = ConstantAcceleration(4.9, 2.0, "stop")
    for got, want in zip(mine.kinematics(t), ref.kinematics(t), strict=True):
        np.testing.assert_allclose(got, want, rtol=1e-13, atol=1e-12)


def test_forward_acceleration_closed_form():
    """From hover to 10 m/s at 1 m/s^2, jerk time 2 s, onset 5 s: the acceleration ramps
    over 5-7 s, holds to 15 s, falls to 0 at 17 s; speeds 1, 9, 10 m/s at 7, 15, 17 s along
    -X (the flight path), and the commanded velocity adds v0. Too small a target (1 m/s)
    gives the triangle of peak target / jerk time = 0.5 m/s^2."""
    old = ForwardAcceleration(10.0, 1.0, 5.0, 2.0)
    assert old.breakpoints == (5.0, 7.0, 15.0, 17.0)
    acc, vel = old.command(np.array([6.0, 7.0, 15.0, 17.0, 30.0]), np.array([-3.0, 0, 0]))
    np.testing.assert_allclose(vel[:, 0], [-3.25, -4.0, -12.0, -13.0, -13.0], rtol=1e-14)
    np.testing.assert_allclose(acc[:, 0], [-0.5, -1.0, -1.0, 0.0, 0.0], atol=1e-15)
    assert np.all(acc[:, 1:] == 0) and np.all(vel[:, 1:] == 0)
    small = HookTrajectory.forward_acceleration(1.0, 1.0, 0.0, 2.0)
    _, v, a = small.kinematics(np.array([2.0, 4.0]))
    np.testing.assert_allclose([a[0, 0], v[1, 0]], [-0.5, -1.0], rtol=1e-14)
    assert small.from_hover


def test_velocity_and_displacement_histories():
    """A velocity history is met at its samples, and one whose first sample is not at rest
    (the hook's speed would jump) is refused; a displacement history passes through its
    samples (relative to the first) and leaves the first at rest."""
    t = [0.0, 1.0, 2.0, 4.0]
    v = [[0, 0, 0], [1.0, -0.5, 0.2], [1.0, -0.5, 0.0], [0.0, 0.0, -1.0]]
    traj = HookTrajectory.from_velocity(t, v)
    np.testing.assert_allclose(traj.kinematics(np.array(t))[1], v, atol=1e-14)
    with pytest.raises(InputError, match="start from 0"):
        HookTrajectory.from_velocity(t, np.array(v) + 1.0)
    x = np.array([[0.0, 0.0, 5.0], [0.2, 0.0, 5.0], [0.8, -0.3, 4.0], [1.0, -0.3, 3.0]])
    traj = HookTrajectory.from_displacement([1.0, 2.0, 3.0, 4.0], x)
    s, v, _ = traj.kinematics(np.array([0.5, 1.0, 2.0, 3.0, 4.0]))
    np.testing.assert_allclose(s[1:], x - x[0], atol=1e-14)
    assert np.all(s[0] == 0) and np.all(v[:2] == 0)  # at rest until the first sample


def test_multibody_carrier_follows_a_3d_trajectory(tmp_path):
    """A pull down and to the right read from a CSV file (acceleration linear between 0, 1,
    3, 4 s: 0 -> (0, 0.5, -1) m/s^2, held, -> 0): the frozen carrier's integrated velocity
    equals the closed form, (0, 1.5, -3) m/s at 4 s on top of the steady flight."""
    path = tmp_path / "pull.csv"
    path.write_text("time_s,ax_mps2,ay_mps2,az_mps2\n0,0,0,0\n1,0,0.5,-1\n3,0,0.5,-1\n"
                    "4,0,0,0\n")
    traj = read_trajectory_csv(path)
    body = RigidBody(2900.0, np.zeros(3), np.diag([2500.0, 7000.0, 9000.0]))
    system = SlingSystem(body, Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]]),
                         Cable(18.3, 5e6, 0.1))
    sim = simulate(system, Manoeuvre("pull", trajectory=traj, from_hover=True), t_end=5.0,
                   output_interval=0.5)
    states = sim.runs[0].states
    _, v, _ = traj.kinematics(np.arange(11) * 0.5)
    np.testing.assert_allclose(states[:, 0:3], v, atol=1e-9)
    np.testing.assert_allclose(states[-1, 0:3], [0.0, 1.5, -3.0], atol=1e-9)


def test_lateral_study_takes_the_same_trajectories():
    """The lateral pendulum under a quintic step given as a 1-D motion and as the Y motion
    of a HookTrajectory: the same run; and a sweep with a held-acceleration trajectory
    matches the constant-acceleration motion it equals."""
    pendulum = LateralPendulum(SlungBody(2096.0, 1803.0, 0.95, "BO-105C"), 20.0)
    step = QuinticStep.from_peak_acceleration(0.3 * G0, 2.0)
    solver = SolverSettings(t_end=8.0)
    direct = lateral_simulate(pendulum, step, solver=solver)
    traj = LateralHookMotion(step).trajectory
    projected = lateral_simulate(pendulum, traj.lateral_motion(), solver=solver)
    np.testing.assert_allclose(projected.load_angle, direct.load_angle, atol=1e-9)
    held = HookTrajectory.along(PiecewiseAcceleration([0.0, 1.0, 2.0], [4.9, -4.9, 0.0],
                                                      "previous"), "Y").lateral_motion()
    metrics, _ = sweep([pendulum, pendulum], [held, ConstantAcceleration(4.9, 1.0, "stop")],
                       solver=SolverSettings(t_end=8.0, step=0.01))
    assert metrics.max_load_angle[0] == pytest.approx(metrics.max_load_angle[1], rel=1e-9)


class _NoShape:
    breakpoints = ()

    def command(self, t, v0):
        return np.zeros(3), np.zeros(3)

    def describe(self):
        return "bad"


def test_manoeuvre_checks_the_trajectory_protocol():
    """A trajectory without breakpoints, or whose command has the wrong shape, is refused
    when the manoeuvre is made, with the rule stated (it failed deep in a run before)."""
    with pytest.raises(InputError, match=r"shape \(len\(t\), 3\)"):
        Manoeuvre("x", trajectory=_NoShape())
    with pytest.raises(InputError, match="needs a method command"):
        Manoeuvre("x", trajectory=object())


def test_workbook_manoeuvre_reads_a_trajectory_file(tmp_path):
    """MultibodyManoeuvres kind 'hook trajectory' with a CSV 'file' (relative to the
    workbook): the run flies that trajectory (its velocity at 4 s is the closed form
    (0, 1.5, -3) m/s of the pull above); a file whose breakpoints pass the end of the run is
    refused at its cell."""
    import openpyxl

    from slingloads.io.study import load_workbook_system

    example = Path(__file__).resolve().parents[1] / "loadcases" / "example-light-twin.xlsx"
    book = openpyxl.load_workbook(example)
    ws = book["FuselageAero"]
    keep = [r for r in ws.iter_rows(min_row=2, values_only=True)
            if r[0] is not None and r[0] % 20 == 0 and r[1] % 20 == 0]
    ws.delete_rows(2, ws.max_row)
    for r in keep:
        ws.append(r)
    ws = book["MultibodyManoeuvres"]
    heads = [c.value for c in ws[1]]
    column = heads.index(None) + 1 if None in heads else len(heads) + 1
    ws.cell(1, column, "file")
    ws.delete_rows(2, ws.max_row)
    ws.cell(2, 1, "pull")
    ws.cell(2, 2, "hook trajectory")
    ws.cell(2, column, "pull.csv")
    (tmp_path / "pull.csv").write_text("time_s,ax_mps2,ay_mps2,az_mps2\n0,0,0,0\n1,0,0.5,-1\n"
                                       "3,0,0.5,-1\n4,0,0,0\n")
    book.save(tmp_path / "traj.xlsx")
    inputs = load_workbook_system(tmp_path / "traj.xlsx")
    (run,) = inputs.manoeuvres
    _, v, _ = run.trajectory.kinematics(np.array([4.0]))
    np.testing.assert_allclose(v[0], [0.0, 1.5, -3.0], atol=1e-12)
    (tmp_path / "pull.csv").write_text("time_s,vx_mps,vy_mps,vz_mps\n0,0,0,0\n9999,1,0,0\n")
    with pytest.raises(InputError, match=r"before the end of the run"):
        load_workbook_system(tmp_path / "traj.xlsx")

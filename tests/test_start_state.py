"""Starting states by name (slingloads.analyses.multibody.start) and additive disturbances.

References: the trim's own state rebuilt from its named quantities (a different route to
the same 20 values); rope-angle geometry (tan of each angle = offset over depth); free fall
of a body on a slack cable, p(t) = p0 + v t - g t^2 / 2 with no rotation (Newton, no force
but gravity while the cable is slack and without aerodynamics); vector addition of rates.
"""

import numpy as np
import pytest

from slingloads.analyses.multibody import (
    Manoeuvre,
    disturbed,
    simulate,
    start_state,
    state_table,
    trim,
)
from slingloads.constants import G0, KNOT
from slingloads.errors import InputError
from slingloads.models.airframe import Hardpoints
from slingloads.models.multibody import Cable, HingedParachute, RigidBody, SlingSystem
from slingloads.models.multibody.rigid_body import rotation_matrix
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
    sample_surfaces,
)


def hc1():
    ref = sample_reference("HC1")
    return SlingSystem(RigidBody(ref.mass, np.zeros(3), np.diag([2500.0, 7000.0,
                                                                 ref.yaw_inertia])),
                       sample_hardpoints("HC1"), Cable(18.3, 5e6), sample_fuselage("HC1"),
                       sample_surfaces("HC1"),
                       HingedParachute(Parachute(1.1, extended_cd_table())),
                       airspeed=80 * KNOT)


def bare():
    """No aerodynamics, no parachute: only gravity and the cable act."""
    body = RigidBody(2900.0, np.zeros(3), np.diag([2500.0, 7000.0, 9000.0]))
    return SlingSystem(body, Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]]),
                       Cable(18.3, 5e6))


def test_trim_state_rebuilt_by_name():
    """The trim at 80 KEAS rebuilt from its hub position, velocities, attitude and line
    angles equals the trim's own state to round-off."""
    system = hc1()
    point = trim(system)
    hub = [point.quantity(f"d_{axis}") for axis in "XYZ"]
    x = start_state(system, hub=hub, velocity=point.state[6:9],
                    carrier_velocity=point.state[0:3], attitude=point.attitude,
                    line_angles=point.state[16:18])
    np.testing.assert_allclose(x, point.state, rtol=0, atol=1e-12)
    named = state_table(x)
    assert named["pitch"] == pytest.approx(point.attitude[1], abs=1e-14)
    assert named["v_X"] == point.state[6]


def test_rope_angles_geometry():
    """Rope angles (10 deg aft, -5 deg left) at a span of 20 m: the hub's offsets over its
    depth are tan 10 deg and tan -5 deg, and it lies 20 m from the hook."""
    system = bare()
    x = start_state(system, rope_angles=np.radians([10.0, -5.0]), span=20.0)
    hub = x[3:6] + rotation_matrix(x[9:13]) @ (system.hardpoints.hub - system.body.cg)
    assert np.linalg.norm(hub) == pytest.approx(20.0, rel=1e-14)
    assert hub[0] / -hub[2] == pytest.approx(np.tan(np.radians(10.0)), rel=1e-13)
    assert hub[1] / -hub[2] == pytest.approx(np.tan(np.radians(-5.0)), rel=1e-13)
    with pytest.raises(InputError, match="one of them"):
        start_state(system)
    with pytest.raises(InputError, match="hinged parachute"):
        start_state(system, hub=(0, 0, -18), line_angles=(0.0, 0.0))


def test_free_fall_on_a_slack_cable_from_a_named_state():
    """A slack start (hub 15 m below the hook, cable 18.3 m) moving at (-20, 3, -1) m/s under
    a hook at (-20, 0, 0) m/s, no aerodynamics: the CG relative to the hook follows
    p0 + (0, 3, -1) t - g t^2 / 2 (z) for 0.5 s, the attitude stays level; the initial
    velocity is the one given to the last bit (no equivalent airspeed in between)."""
    system = bare()
    x0 = start_state(system, hub=(0.5, 0.0, -15.0), velocity=(-20.0, 3.0, -1.0),
                     carrier_velocity=(-20.0, 0.0, 0.0))
    run = Manoeuvre("drop", start_state=x0, from_hover=True)
    sim = simulate(system, run, t_end=0.5, output_interval=0.1)
    states = sim.runs[0].states
    t = np.arange(6) * 0.1
    expected = x0[3:6] + np.outer(t, [0.0, 3.0, -1.0]) - np.outer(0.5 * G0 * t**2, [0, 0, 1])
    np.testing.assert_allclose(states[:, 3:6], expected, atol=1e-6)
    assert states[0, 6:9].tolist() == [-20.0, 3.0, -1.0]
    np.testing.assert_allclose(states[:, 9:13], np.tile([1.0, 0, 0, 0], (6, 1)), atol=1e-9)


def test_disturbances_add_to_the_state():
    """yaw_rate adds its body-axis rates to those already there (it overwrote them before);
    positions add; a disturbance also applies on top of a start state."""
    system = bare()
    x = start_state(system, hub=(0.0, 0.0, -18.4), attitude=(0.2, 0.1, -0.05),
                    body_rates=(0.1, -0.02, 0.03))
    out = disturbed(x, {"yaw_rate": 0.05, "lateral": 0.3})
    extra = rotation_matrix(x[9:13]).T @ np.array([0.0, 0.0, -0.05])
    np.testing.assert_allclose(out[13:16], x[13:16] + extra, rtol=0, atol=1e-15)
    assert out[4] == x[4] + 0.3
    assert np.array_equal(out[9:13], x[9:13])


def test_right_handed_conversion_is_the_same_rotation():
    """docs/conventions.md section 8: R = Rz(-yaw) Ry(pitch) Rx(-roll) equals the textbook
    right-handed product Rz(rz) Ry(ry) Rx(rx) of the converted angles; the inverse returns
    the angles."""
    from slingloads.models.attitude import from_right_handed, to_right_handed
    from slingloads.models.multibody.rigid_body import quaternion_from_euler

    def rx(a):
        return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])

    def ry(a):
        return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])

    def rz(a):
        return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])

    angles = (0.4, -0.25, 0.15)
    a, b, c = to_right_handed(*angles)
    np.testing.assert_allclose(rz(c) @ ry(b) @ rx(a),
                               rotation_matrix(quaternion_from_euler(*angles)), atol=1e-15)
    np.testing.assert_allclose(from_right_handed(a, b, c), angles, atol=0)


def test_warm_up_compiles_the_loads_kernel():
    """slingloads compile (slingloads.runs.warmup) reaches the kernels a run calls: after the
    loads warm-up numba records a compiled signature of the free-free kernel (numba's own
    record is the reference)."""
    from slingloads.analyses import sfbm_kernel
    from slingloads.runs.warmup import STEPS, _timed

    assert set(STEPS) == {"loads", "lateral", "chute sizing", "multibody"}
    seconds = _timed(["loads"])["loads"]
    assert seconds >= 0 and sfbm_kernel.free_free_rows.signatures

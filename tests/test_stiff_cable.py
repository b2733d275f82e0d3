"""The multibody trim from the hanging attitude, stiff cables, cable damping by coefficient,
and runs that cannot start.

References: statics of a body hung at one point (at rest its CG lies under the hub, so the
pitch is atan(dx / dz) of the hub seen from the CG, and the cable carries the hung weight,
stretched by W L / EA); the inextensible limit (a cable 100 and 10 000 times stiffer than
1e7 N changes a response by nothing visible);
the damped-oscillator relation c = 2 zeta sqrt(k m).
"""

import numpy as np
import pytest

from slingloads.analyses.multibody import free_response, simulate, trim
from slingloads.analyses.multibody.trim import hanging_attitude, trim_many
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table2D
from slingloads.models.aerodynamics import FUSELAGE_COEFFICIENTS, FuselageAero
from slingloads.models.multibody import Cable, HingedParachute, RigidBody, SlingSystem
from slingloads.models.multibody.rigid_body import quaternion_from_euler, rotation_matrix
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
    sample_surfaces,
)

OFFSET = 0.17  # CG ahead of the hub [m] (the case that broke the former first guess)


def system(ea, airspeed=0.0, fuselage=None, chute=True):
    ref = sample_reference("HC1")
    hp = sample_hardpoints("HC1")
    cg = np.array([hp.hub[0] - OFFSET, 0.0, 0.0])
    return SlingSystem(RigidBody(ref.mass, cg, np.diag([2500.0, 7000.0, ref.yaw_inertia])),
                       hp, Cable(18.3, ea), fuselage or sample_fuselage("HC1"),
                       sample_surfaces("HC1"),
                       HingedParachute(Parachute(1.1, extended_cd_table())) if chute else None,
                       airspeed=airspeed)


@pytest.mark.parametrize("ea", [1e8, 2e8, 1e10, 1e11])
def test_hover_trim_hangs_the_cg_under_the_hub(ea):
    """Hover, CG 0.17 m ahead of the hub, no parachute (whose canopy would move the hung
    CG): trim() and trim_many() converge (they failed from EA 1e8 and 2e8 N) to the hanging
    pitch atan2(-dx, dz) of the hub seen from the CG, a tension equal to the weight and the
    stretch W L / EA."""
    s = system(ea, chute=False)
    hub = s.hardpoints.hub - s.body.cg
    expected = -np.arctan2(hub[0], hub[2])  # Ry(pitch) turns the hub vertical
    for point in (trim(s), trim_many([(s, None, (0.0, 0.0, 0.0))])[0]):
        assert point.converged, point.message
        assert point.attitude[1] == pytest.approx(expected, abs=1e-6)
        assert point.quantity("tension") == pytest.approx(s.weight, rel=1e-9)
        span = np.linalg.norm([point.quantity(f"d_{a}") for a in "XYZ"])
        assert span - 18.3 == pytest.approx(s.weight * 18.3 / ea, rel=1e-4, abs=1e-12)


@pytest.mark.parametrize("ea", [1e9, 1e11])
def test_stiff_cable_trims_at_speed(ea):
    """At 80 KEAS the trim converges for stiff cables too, to the attitude of the 5e6 N
    cable within the cable's compliance (the stretch is millimetres: same equilibrium)."""
    soft = trim(system(5e6, 80 * KNOT))
    stiff = trim(system(ea, 80 * KNOT))
    assert soft.converged and stiff.converged, stiff.message
    assert np.degrees(stiff.attitude[1]) == pytest.approx(np.degrees(soft.attitude[1]),
                                                          abs=0.05)


def test_stiff_cable_response_converges_to_the_rigid_limit():
    """A free response flown with EA 1e7, 1e9 and 1e11 N: the stiffer cables change the
    15 deg yaw change of the response by less than 1e-3 deg (the inextensible limit,
    reached within the integrator's tolerance), and the EA 1e11 N run is flown to the end
    (an explicit integrator following a 1350 rad/s bounce)."""
    runs = {}
    for ea in (1e7, 1e9, 1e11):
        sim = simulate(system(ea, 80 * KNOT), free_response(), t_end=10.0)
        assert not sim.runs[0].stopped
        runs[ea] = sim.metrics_frame()["yaw change [deg]"].iloc[0]
    assert abs(runs[1e11]) > 10.0
    assert runs[1e9] == pytest.approx(runs[1e7], abs=1e-3)
    assert runs[1e11] == pytest.approx(runs[1e9], abs=1e-3)


def test_hanging_attitude_closed_form():
    """The rotation found puts the hub exactly on the given line (any yaw), and a hub
    straight above the CG needs no rotation."""
    hub = np.array([0.3, -0.2, 1.4])
    up = np.array([-0.25, 0.1, 1.0])
    for yaw in (0.0, 0.4):
        pitch, roll = hanging_attitude(hub, up, yaw)
        turned = rotation_matrix(quaternion_from_euler(yaw, pitch, roll)) @ hub
        assert np.cross(turned, up) == pytest.approx(np.zeros(3), abs=1e-12)
        assert turned @ up > 0
    assert hanging_attitude([0.0, 0.0, 1.0], [0.0, 0.0, 1.0]) == pytest.approx((0.0, 0.0))


def test_damping_coefficient_or_ratio():
    """c = 2 zeta sqrt(k m): a ratio and the coefficient it stands for give the same c and
    back the same ratio; giving both is refused; a negative coefficient is refused."""
    m, ratio = 3000.0, 0.05
    by_ratio = Cable(18.3, 5e6, damping_ratio=ratio)
    c = 2 * ratio * np.sqrt(5e6 / 18.3 * m)
    assert by_ratio.damping(m) == pytest.approx(c, rel=1e-14)
    by_c = Cable(18.3, 5e6, damping_coefficient=c)
    assert by_c.damping(m) == c
    assert by_c.damping_ratio_for(m) == pytest.approx(ratio, rel=1e-14)
    assert Cable(18.3, 5e6).damping_ratio == 0.05
    with pytest.raises(InputError, match="not both"):
        Cable(18.3, 5e6, damping_ratio=0.05, damping_coefficient=c)
    with pytest.raises(InputError, match=r"coefficient must be >= 0 \[N s/m\]: value -1"):
        Cable(18.3, 5e6, damping_coefficient=-1.0)


def test_run_without_trim_raises_in_the_api():
    """A fuselage table covering only alpha +-1 deg cannot hold the nose-down trim at 80 kt:
    simulate() raises with the run's name and the reason (it returned all-NaN histories
    before), also with a start state; no_trim='report' returns the run unflown with its
    reason (the workbook's route)."""
    full = sample_fuselage("HC1")
    alpha = np.radians([-1.0, 1.0])
    coeffs = {k: np.vstack([full.table.beta_slice(k, a) for a in alpha])
              for k in FUSELAGE_COEFFICIENTS}
    narrow = FuselageAero(Table2D(alpha, full.table.beta, coeffs), full.area, full.length,
                          full.moment_reference)
    s = system(5e6, 80 * KNOT, fuselage=narrow)
    with pytest.raises(InputError, match=r"run 'free response' .* no trim at 41\.16 m/s EAS"
                                         r".*alpha"):
        simulate(s, free_response(), t_end=5.0)
    sim = simulate(s, free_response(), t_end=5.0, no_trim="report")
    row = sim.metrics_frame().iloc[0]
    assert row["verdict"] == "no trim" and "alpha" in row["stopped"]

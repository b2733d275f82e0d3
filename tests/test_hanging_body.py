"""The hanging airframe's pendulum properties against closed forms.

Reference: a rigid body hung at one point rests with its CG under that point, so the vertical
is the unit vector from the CG to the hub. For two point masses m at (+-L, 0, 0) about their
CG and a hub at (a, 0, h) the hanging vertical is k = (a, 0, h)/r, r = sqrt(a^2 + h^2), and by
the definition of a moment of inertia about an axis through the CG,
sum m (|p|^2 - (p . u)^2):

* about the vertical k (yaw):           I = 2 m L^2 (1 - a^2/r^2) = 2 m L^2 h^2 / r^2;
* about the horizontal fore-aft axis (h, 0, -a)/r (roll): I = 2 m L^2 a^2 / r^2;
* the CG lies r below the hub.

Before, the yaw inertia added the parallel-axis term m a^2 of a hub off the body z axis
through the CG, and the lateral pendulum took the CG distance along the mast and Ixx, i.e.
the airframe hanging level, which it does not.
"""

import numpy as np
import pytest

from slingloads.analyses.lateral import airframe_body
from slingloads.models.airframe import (
    Airframe,
    Hardpoints,
    MassItems,
    hanging_roll_axis,
    hanging_vertical,
    yaw_inertia_about_hub,
)

M, L = 400.0, 3.0


def dumbbell(a, h, own=None):
    """Two masses M at x = +-L (CG at the origin), hub at (a, 0, h)."""
    inertia = None if own is None else np.stack([own, own])
    items = MassItems(("fwd", "aft"), [M, M], [[-L, 0.0, 0.0], [L, 0.0, 0.0]], inertia)
    hardpoints = Hardpoints(hub=[a, 0.0, h], mast_feet=[[a, 0.0, h - 0.5]])
    return Airframe(items, [-1.0, 1.0], hardpoints)


@pytest.mark.parametrize("a, h", [(0.17, 1.072), (-0.4, 0.9), (0.5, 0.5)])
def test_point_masses_against_closed_form(a, h):
    airframe = dumbbell(a, h)
    r = np.hypot(a, h)
    np.testing.assert_allclose(hanging_vertical(airframe), [a / r, 0.0, h / r], atol=1e-15)
    np.testing.assert_allclose(hanging_roll_axis(airframe), [h / r, 0.0, -a / r], atol=1e-15)
    assert yaw_inertia_about_hub(airframe) == pytest.approx(2 * M * L**2 * h**2 / r**2,
                                                            rel=1e-12, abs=1e-9)
    body = airframe_body(airframe)
    assert body.cg_below_hub == pytest.approx(r, rel=1e-14)
    assert body.roll_inertia == pytest.approx(2 * M * L**2 * a**2 / r**2, rel=1e-12, abs=1e-9)


def test_hub_on_the_body_z_axis_gives_the_level_values():
    """Limit case: a hub straight above the CG leaves the airframe level, so the pendulum
    takes Ixx and the distance along the mast, the yaw inertia Izz (own inertias included)."""
    own = np.diag([50.0, 80.0, 120.0])
    airframe = dumbbell(0.0, 1.3, own)
    tensor = airframe.mass_items.inertia_about_cg
    body = airframe_body(airframe)
    assert body.roll_inertia == pytest.approx(tensor[0, 0], rel=1e-14)
    assert body.cg_below_hub == pytest.approx(1.3, rel=1e-14)
    assert yaw_inertia_about_hub(airframe) == pytest.approx(tensor[2, 2], rel=1e-14)


def test_rotating_the_airframe_level_gives_the_same_pendulum():
    """Invariance: rotate every item (position and own inertia) by the hanging pitch so that
    the hub sits straight above the CG; the level formulas on the rotated airframe (Ixx,
    Izz, distance along z) must equal the hanging values of the original."""
    own = np.array([[60.0, 0.0, 7.0], [0.0, 90.0, 0.0], [7.0, 0.0, 110.0]])
    a, h = 0.35, 1.1
    original = dumbbell(a, h, own)
    theta = np.arctan2(a, h)  # rotation about y taking (a, 0, h) onto +z
    c, s = np.cos(theta), np.sin(theta)
    rot = np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])
    np.testing.assert_allclose(rot @ [a, 0.0, h], [0.0, 0.0, np.hypot(a, h)], atol=1e-15)
    items = original.mass_items
    level = MassItems(items.ids, items.mass, items.position @ rot.T,
                      np.einsum("ij,njk,lk->nil", rot, items.inertia, rot))
    tensor = level.inertia_about_cg
    body = airframe_body(original)
    assert body.roll_inertia == pytest.approx(tensor[0, 0], rel=1e-12)
    assert yaw_inertia_about_hub(original) == pytest.approx(tensor[2, 2], rel=1e-12)

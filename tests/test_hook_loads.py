"""Verification of the CS-29.865 hook-load directions (slingloads.analyses.hook_loads) and of
the hub force that LoadsStudy applies at the mast feet.

References: CS 29.865(a) / 14 CFR 29.865(a) (limit load Nz x weight, vertically and in a cone
of at least 30 deg from the vertical), FACTS section 1, and docs/conventions.md section 4:

    e_k = cos(theta_k) k + sin(theta_k) (cos(psi_k) a0 + sin(psi_k) a90),  psi_k = k 360 deg / N,

with k the earth's upward vertical in airframe axes (the attitude's), psi = 0 aft (+x),
psi = 90 deg right (+y); for a tilted vertical a0 is +x projected normal to k (normalised) and
a90 = k x a0. The expected vectors below are worked by hand from these definitions, never from
the code.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.hook_loads import HookLoadOptions, hook_directions
from slingloads.analyses.loads import LoadsStudy
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.airframe import Airframe, Hardpoints, MassItems

TILTED = np.array([0.2, -0.1, 1.0]) / np.linalg.norm([0.2, -0.1, 1.0])


def vectors(frame):
    return frame[["ux", "uy", "uz"]].to_numpy()


@pytest.mark.parametrize("up", [np.array([0.0, 0.0, 1.0]), TILTED])
@pytest.mark.parametrize(("angle_deg", "n"), [(30.0, 8), (20.0, 12), (45.0, 3), (10.0, 5)])
def test_directions_are_unit_and_at_the_set_angle(up, angle_deg, n):
    """|e| = 1 for every direction; VERTICAL is the vertical k; every off-vertical direction
    makes exactly theta with it: arccos(e . k) = theta."""
    frame = hook_directions(HookLoadOptions(angle=np.radians(angle_deg), n_azimuth=n), up)
    u = vectors(frame)
    assert len(frame) == n + 1
    assert_allclose(np.linalg.norm(u, axis=1), 1.0, rtol=1e-14)
    axial = frame["hook"] == "VERTICAL"
    assert_allclose(u[axial][0], up, atol=1e-15)
    angles = np.degrees(np.arccos(np.clip(u[~axial] @ up, -1.0, 1.0)))
    assert_allclose(angles, angle_deg, atol=1e-6)
    assert_allclose(frame.loc[~axial, "inclination [deg]"], angle_deg, rtol=1e-14)


@pytest.mark.parametrize("up", [np.array([0.0, 0.0, 1.0]), TILTED])
@pytest.mark.parametrize("n", [2, 3, 8, 12])
def test_azimuths_are_evenly_spread(up, n):
    """Project the off-vertical directions on the horizontal plane (normal to k): consecutive
    projections are 360/N deg apart (arccos of their normalised dot product, and turning
    positively about k), and they sum to zero (N >= 2 vectors evenly spread on a circle)."""
    frame = hook_directions(HookLoadOptions(n_azimuth=n), up)
    u = vectors(frame)[frame["hook"] != "VERTICAL"]
    proj = u - (u @ up)[:, None] * up
    proj /= np.linalg.norm(proj, axis=1)[:, None]
    nxt = np.roll(proj, -1, axis=0)
    step = np.degrees(np.arccos(np.clip(np.sum(proj * nxt, axis=1), -1.0, 1.0)))
    assert_allclose(step, 360.0 / n, atol=1e-6)
    turn = np.cross(proj, nxt) @ up  # > 0: each next azimuth turns positively about k
    assert np.all(turn > 0) or n == 2
    assert_allclose(proj.sum(axis=0), 0.0, atol=1e-14 * n)
    assert_allclose(frame.loc[frame["hook"] != "VERTICAL", "azimuth [deg]"],
                    np.arange(n) * 360.0 / n, atol=1e-12)


def test_level_attitude_azimuth_0_is_aft_and_90_is_right():
    """docs/conventions.md section 4 for k = +z, theta = 30 deg, N = 8, by hand:
    AZ000 = (sin 30, 0, cos 30) = (0.5, 0, 0.866025) leans aft (+x);
    AZ090 = (0, 0.5, 0.866025) leans right (+y); AZ180 = (-0.5, 0, 0.866025) forward;
    AZ045 = (0.5 cos 45, 0.5 sin 45, 0.866025) = (0.353553, 0.353553, 0.866025)."""
    frame = hook_directions(HookLoadOptions()).set_index("hook")
    c30 = np.sqrt(3.0) / 2
    assert_allclose(frame.loc["AZ000", ["ux", "uy", "uz"]], [0.5, 0.0, c30], atol=1e-15)
    assert_allclose(frame.loc["AZ090", ["ux", "uy", "uz"]], [0.0, 0.5, c30], atol=1e-15)
    assert_allclose(frame.loc["AZ180", ["ux", "uy", "uz"]], [-0.5, 0.0, c30], atol=1e-15)
    h = 0.5 / np.sqrt(2.0)
    assert_allclose(frame.loc["AZ045", ["ux", "uy", "uz"]], [h, h, c30], atol=1e-15)
    assert list(frame.index) == ["VERTICAL", "AZ000", "AZ045", "AZ090", "AZ135", "AZ180",
                                 "AZ225", "AZ270", "AZ315"]


def test_tilted_vertical_basis_by_hand():
    """Airframe pitched 10 deg nose up, so the earth vertical leans forward in airframe axes:
    k = (-sin 10, 0, cos 10). a0 = +x projected normal to k, normalised:
    x - (x.k) k = (1 - s^2, 0, s c) = c (c, 0, s), so a0 = (cos 10, 0, sin 10) (horizontal,
    aft); a90 = k x a0 = (0, 1, 0) (still right).
    AZ000 = cos 30 k + sin 30 a0, AZ090 = cos 30 k + sin 30 (0, 1, 0)."""
    s, c = np.sin(np.radians(10.0)), np.cos(np.radians(10.0))
    m = np.array([-s, 0.0, c])
    frame = hook_directions(HookLoadOptions(n_azimuth=4), m).set_index("hook")
    c30, s30 = np.sqrt(3.0) / 2, 0.5
    assert_allclose(frame.loc["AZ000", ["ux", "uy", "uz"]],
                    c30 * m + s30 * np.array([c, 0.0, s]), atol=1e-15)
    assert_allclose(frame.loc["AZ090", ["ux", "uy", "uz"]],
                    c30 * m + s30 * np.array([0.0, 1.0, 0.0]), atol=1e-15)
    assert_allclose(frame.loc["AZ270", ["ux", "uy", "uz"]],
                    c30 * m - s30 * np.array([0.0, 1.0, 0.0]), atol=1e-15)


def test_tilted_vertical_azimuth_zero_leans_aft_in_the_x_k_plane():
    """For any tilted vertical k: AZ000 lies in the plane of k and +x (no component along
    k x x) and leans towards +x relative to k (its projection has a positive x component);
    AZ090 leans along a90 = k x a0, which has a positive y component for a near-level
    attitude ("right")."""
    frame = hook_directions(HookLoadOptions(), TILTED).set_index("hook")
    az0 = frame.loc["AZ000", ["ux", "uy", "uz"]].to_numpy(float)
    az90 = frame.loc["AZ090", ["ux", "uy", "uz"]].to_numpy(float)
    normal = np.cross(TILTED, [1.0, 0.0, 0.0])
    assert az0 @ normal == pytest.approx(0.0, abs=1e-15)
    assert (az0 - (az0 @ TILTED) * TILTED)[0] > 0
    assert (az90 - (az90 @ TILTED) * TILTED)[1] > 0


def test_include_vertical_false_and_vertical_only():
    """Cone options: without the vertical case only the N azimuths; N = 0 the vertical alone."""
    only_cone = hook_directions(HookLoadOptions(n_azimuth=4, include_vertical=False))
    assert list(only_cone["hook"]) == ["AZ000", "AZ090", "AZ180", "AZ270"]
    axis_only = hook_directions(HookLoadOptions(n_azimuth=0))
    assert list(axis_only["hook"]) == ["VERTICAL"]
    assert_allclose(vectors(axis_only)[0], [0.0, 0.0, 1.0], atol=0)


def small_airframe(mast_axis=(0.0, 0.0, 1.0)):
    """A 4-mass airframe (total 2000 kg) with the HC1-like four mast feet 0.4 m below a hub."""
    items = MassItems(("nose", "cabin", "engine", "tail"),
                      [300.0, 900.0, 500.0, 300.0],
                      [[-3.0, 0.0, -0.5], [0.0, 0.2, -0.3], [0.5, -0.2, 0.4], [5.0, 0.0, 0.5]],
                      np.broadcast_to(np.diag([50.0, 80.0, 80.0]), (4, 3, 3)).copy())
    hub = np.array([0.0, 0.0, 1.0])
    feet = hub + np.array([[-0.4, -0.4, -0.4], [-0.4, 0.4, -0.4],
                           [0.4, -0.4, -0.4], [0.4, 0.4, -0.4]])
    hp = Hardpoints(hub=hub, mast_feet=feet, mast_axis=mast_axis)
    return Airframe(items, np.linspace(-3.0, 5.0, 9), hp)


@pytest.mark.parametrize("attitude", ["hanging", "mast vertical"])
@pytest.mark.parametrize("mast", [(0.0, 0.0, 1.0), tuple(TILTED)])
@pytest.mark.parametrize("nz", [2.5, 1.7])
def test_hub_force_is_nz_times_weight(attitude, mast, nz):
    """CS 29.865(a): the limit hook load is Nz x the carried weight. Sum the mast-feet forces
    that LoadsStudy.applied_loads puts on the airframe: for every direction the sum is
    Nz m g0 e, with m = 2000 kg by hand (300 + 900 + 500 + 300), e.g. Nz = 2.5:
    2.5 * 2000 * 9.80665 = 49033.25 N; and their moment about the hub is zero (the cable
    applies a pure force at the hub)."""
    study = LoadsStudy(small_airframe(mast), hook=HookLoadOptions(nz=nz), attitude=attitude)
    cases = study.case_matrix()
    positions, forces, moments = study.applied_loads(cases)
    feet = slice(4, 8)
    f_feet = forces[:, feet].sum(axis=1)
    weight = 2000.0 * G0
    assert_allclose(np.linalg.norm(f_feet, axis=1), nz * weight, rtol=1e-12)
    e = vectors(study.hook_table().set_index("hook").loc[cases["hook"]])
    assert_allclose(f_feet, nz * weight * e, rtol=1e-12, atol=1e-9 * weight)
    hub = study.airframe.hardpoints.hub
    m_hub = (np.cross(positions[feet] - hub, forces[:, feet]) + moments[:, feet]).sum(axis=1)
    assert_allclose(m_hub, 0.0, atol=1e-10 * weight)


def test_vertical_hook_case_feet_share_equally():
    """Hand check of the sharing rule for the vertical case: four equal feet symmetric about
    the line of the hub force carry 2.5 * 2000 * 9.80665 / 4 = 12258.3125 N each, along +z
    (mast vertical attitude: the vertical is +z)."""
    study = LoadsStudy(small_airframe(), hook=HookLoadOptions(n_azimuth=0),
                       attitude="mast vertical")
    _, forces, moments = study.applied_loads(study.case_matrix())
    assert_allclose(forces[0, 4:8], np.tile([0.0, 0.0, 12258.3125], (4, 1)), atol=1e-9)
    assert_allclose(moments[0, 4:8], 0.0, atol=1e-9)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"nz": 0.0}, r"Nz must be > 0: value 0\.0"),
    ({"nz": -2.5}, r"Nz must be > 0: value -2\.5"),
    ({"nz": np.nan}, r"Nz must be > 0"),
    ({"angle": np.radians(90.0)}, r"\[0, 90\) deg.* rad = 90 deg: value 1\.57\d* \[rad\]"),
    ({"angle": np.radians(120.0)}, r"\[0, 90\) deg.*given 2\.0944 rad = 120 deg"),
    ({"angle": np.radians(-5.0)}, r"\[0, 90\) deg.* = -5 deg: value -0\.087"),
    ({"angle": 20.0}, r"in radians.*given 20 rad = 1145\.92 deg: value 20\.0 \[rad\]"),
    ({"n_azimuth": -1}, r"whole number >= 0: value -1"),
    ({"n_azimuth": 2.5}, r"whole number >= 0: value 2\.5"),
    ({"n_azimuth": 0, "include_vertical": False}, r"no direction at all"),
    ({"lateral_angle": np.radians(90.0)}, r"lateral hook-load angle .* = 90 deg"),
    ({"cone": "round"}, r"cone shape must be one of \['lateral directions', 'elliptical'\]"),
])
def test_bad_options_raise_input_error(kwargs, message):
    """Invalid hook options are refused with InputError naming the rule and the value
    (STYLE.md): Nz <= 0, angle outside [0, 90) deg, azimuth count not a whole number >= 0."""
    with pytest.raises(InputError, match=message):
        HookLoadOptions(**kwargs)


def test_vertical_parallel_to_x_is_refused():
    """A vertical along the fuselage axis leaves azimuth 0 (+x projected normal to k)
    undefined."""
    with pytest.raises(InputError, match="parallel to the fuselage x axis"):
        hook_directions(HookLoadOptions(), (1.0, 0.0, 0.0))

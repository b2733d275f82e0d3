"""Hanging attitude, towed-flight equilibrium cases and the per-direction hook cone.

References:

* Statics of a body hung from one point: at rest under its weight and the cable pull only,
  the two forces balance only on one vertical line, so the CG lies under the hub
  (docs/conventions.md, section 4). The attitude angles are the aerospace Euler angles:
  earth vertical in airframe axes k = (-sin theta, -sin phi cos theta, cos phi cos theta).
* Towed-flight equilibrium (docs/loads-method.md): hook force = Nz W k - P_h (F_aero +
  F_chute), P_h the projection on the horizontal plane; so the resultant horizontal force is
  zero and the vertical one (Nz - 1) W + k . F_aero; steady trail angle atan(D / W) at 1 g
  (FACTS section 5).
* CS 29.865(a): 30 deg cone, reducible where a smaller angle is shown; the elliptical cone's
  horizontal section at unit height is the ellipse (x / tan a)^2 + (y / tan b)^2 = 1.
* Free-free beam (docs/conventions.md, sections 2 and 6): V(x) = -(sum of the forces on the
  part forward of x), gravity and inertia included.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.hook_loads import HookLoadOptions, cable_geometry, hook_directions
from slingloads.analyses.loads import AeroEnvelope, ListedCase, LoadsStudy
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table2D
from slingloads.models.aerodynamics import FuselageAero
from slingloads.models.airframe import Airframe, Hardpoints, MassItems
from slingloads.models.attitude import Attitude
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage

Q = 0.5 * 1.225 * (100 * 1852.0 / 3600.0) ** 2  # 1621.000 Pa at 100 KEAS


# ------------------------------------------------------------------------ hanging attitude
def offset_airframe(dx=0.17, dy=0.0, dz=1.05):
    """Four masses (total 1000 kg) with the CG at (1.3, 0, 0.05) by hand:
    x: (200*0 + 300*1 + 300*1.5 + 200*2.75)/1000 = (0 + 300 + 450 + 550)/1000 = 1.3;
    y: (-80 + 150 - 150 + 80)/1000 = 0; z: (200*0.1 + 200*0.15)/1000 = 0.05.
    The hub is put at CG + (dx, dy, dz)."""
    items = MassItems(("a", "b", "c", "d"), [200.0, 300.0, 300.0, 200.0],
                      [[0.0, -0.4, 0.1], [1.0, 0.5, 0.0], [1.5, -0.5, 0.0], [2.75, 0.4, 0.15]],
                      np.broadcast_to(np.diag([30.0, 40.0, 40.0]), (4, 3, 3)).copy())
    hub = items.cg + np.array([dx, dy, dz])
    feet = hub + np.array([[-0.3, -0.3, -0.5], [-0.3, 0.3, -0.5], [0.3, -0.3, -0.5],
                           [0.3, 0.3, -0.5]])
    return Airframe(items, np.linspace(0.0, 2.75, 12), Hardpoints(hub, feet))


def test_hanging_attitude_by_hand():
    """Hub 0.17 m aft of and 1.05 m above the CG: the airframe pitches nose down by
    atan(0.17 / 1.05) = 9.197 deg; a hub also 0.10 m to the right rolls it left side down
    by atan(0.10 / 1.05) = 5.440 deg (k = offset / |offset|, pitch = -asin(k_x),
    roll = atan2(-k_y, k_z))."""
    af = offset_airframe()
    assert_allclose(af.mass_items.cg, [1.3, 0.0, 0.05], atol=1e-12)
    hanging = Attitude.hanging(af.mass_items, af.hardpoints.hub)
    assert np.degrees(hanging.pitch) == pytest.approx(-9.1967, abs=1e-4)
    assert hanging.roll == pytest.approx(0.0, abs=1e-15)
    assert_allclose(hanging.vertical, np.array([0.17, 0.0, 1.05]) / np.hypot(0.17, 1.05),
                    atol=1e-15)
    rolled = offset_airframe(dy=0.10)
    att = Attitude.hanging(rolled.mass_items, rolled.hardpoints.hub)
    assert np.degrees(att.roll) == pytest.approx(-5.4403, abs=1e-4)
    assert_allclose(att.vertical, np.array([0.17, 0.10, 1.05]) / np.linalg.norm([0.17, 0.1, 1.05]),
                    atol=1e-15)
    assert "nose down" in att.describe() and "left side down" in att.describe()


def test_given_attitude_round_trips_and_bad_ones_are_refused():
    """An explicit pitch/roll gives k; from_vertical(k) gives them back. A hub below the CG,
    or at it, leaves no upright hanging attitude: refused with the rule."""
    att = Attitude(np.radians(-7.0), np.radians(3.0))
    back = Attitude.from_vertical(att.vertical)
    assert back.pitch == pytest.approx(att.pitch) and back.roll == pytest.approx(att.roll)
    below = offset_airframe(dz=-0.5)
    with pytest.raises(InputError, match="must lie above the CG"):
        Attitude.hanging(below.mass_items, below.hardpoints.hub)
    with pytest.raises(InputError, match="coincides with the CG"):
        Attitude.hanging(below.mass_items, below.mass_items.cg)
    with pytest.raises(InputError, match=r"within \(-90, 90\) deg"):
        Attitude(np.radians(95.0))


def vertical_only(airframe, nz, attitude="hanging"):
    hook = HookLoadOptions(nz=nz, n_azimuth=0, towed=False)
    return LoadsStudy(airframe, hook=hook, attitude=attitude).run()


def test_one_g_hanging_case_is_at_rest_and_closes():
    """Nz = 1 along the earth vertical through hub and CG: weight and hook force balance on
    one line, so the linear and angular accelerations are zero, the vertical load factor is
    1 and the free-free closure holds."""
    result = vertical_only(offset_airframe(dy=0.1), 1.0)
    assert_allclose(result.linear_acceleration, 0.0, atol=1e-12)
    assert_allclose(result.angular_acceleration, 0.0, atol=1e-12)
    assert result.vertical_load_factor[0] == pytest.approx(1.0, rel=1e-12)
    assert np.abs(result.residual).max() < 1e-8 * result.residual_scale


def test_vertical_nz_case_has_no_pitch_acceleration_and_vz_by_hand():
    """Nz = 2.5 vertical case in the hanging attitude: a = 1.5 g0 k, no angular acceleration;
    every item carries -Nz m g0 k (gravity plus inertia), so forward of the mast feet
    V(x) = Nz g0 k sum_{x_i <= x} m_i. At the cut x = 0.5 (item a, 200 kg):
    Vz = 2.5 * 9.80665 * 200 * cos(9.197 deg) = 4840.2 N, Vx = 2.5 * 9.80665 * 200 *
    sin(9.197 deg) = 783.6 N. The mast-vertical attitude (the former behaviour) instead has
    the moment -dx Nz W about y at the CG (hub 0.17 m aft of the CG), so I_cg alpha =
    (0, -0.17 Nz W, 0)."""
    af = offset_airframe()
    k = np.array([0.17, 0.0, 1.05]) / np.hypot(0.17, 1.05)
    result = vertical_only(af, 2.5)
    assert_allclose(result.angular_acceleration, 0.0, atol=1e-12)
    assert_allclose(result.linear_acceleration[0], 1.5 * G0 * k, rtol=1e-12)
    assert result.vertical_load_factor[0] == pytest.approx(2.5, rel=1e-12)
    station = int(np.argmin(np.abs(af.stations - 0.5)))
    assert af.stations[station] == pytest.approx(0.5)
    assert result.loads[0, station, 2] == pytest.approx(2.5 * G0 * 200.0 * k[2], rel=1e-12)
    assert result.loads[0, station, 0] == pytest.approx(2.5 * G0 * 200.0 * k[0], rel=1e-12)
    assert result.loads[0, station, 2] == pytest.approx(4840.2, abs=0.1)
    mast = vertical_only(af, 2.5, "mast vertical")
    weight = af.mass_items.weight
    moment = np.array([0.0, -0.17 * 2.5 * weight, 0.0])
    assert_allclose(af.mass_items.inertia_about_cg @ mast.angular_acceleration[0], moment,
                    rtol=1e-9, atol=1e-9 * weight)
    assert abs(mast.angular_acceleration[0, 1]) > 1.0  # [rad/s^2], not balanced


def test_legacy_axial_id_is_read_as_vertical():
    """Workbooks written before the hanging attitude name the vertical case AXIAL."""
    assert ListedCase("X", "axial", "NONE", False).hook == "VERTICAL"


# ------------------------------------------------------------------------- towed cases
def towing_airframe():
    """Ten masses in symmetric pairs on the x axis (z = 0), 100 kg each, pairs at x = 1, 3,
    5, 7, 9 and y = +-0.3: CG (5, 0, 0), under the hub (5, 0, 1), so the hanging attitude is
    level. Stations 0.5, 1.5, ... 9.5; the aerodynamic points are their mid-points inside the
    airframe, x = 1, 2, ..., 9 (nine equal shares) on the reference axis y = z = 0; mast feet at
    x = 4.7 and 5.3, z = 0.5; parachute attachment (9, 0, 0)."""
    x = np.repeat([1.0, 3.0, 5.0, 7.0, 9.0], 2)
    y = np.tile([-0.3, 0.3], 5)
    items = MassItems(tuple(f"m{i}" for i in range(10)), np.full(10, 100.0),
                      np.column_stack([x, y, np.zeros(10)]))
    feet = np.array([[4.7, -0.3, 0.5], [4.7, 0.3, 0.5], [5.3, -0.3, 0.5], [5.3, 0.3, 0.5]])
    hp = Hardpoints([5.0, 0.0, 1.0], feet, chute=[9.0, 0.0, 0.0])
    return Airframe(items, np.arange(0.5, 10.0, 1.0), hp)


def drag_only_fuselage(cx=-0.2, area=2.0):
    """Body-axes table with CX = -0.2 (axial force rearwards) everywhere, nothing else:
    force q S 0.2 along +x (aft), no moment about its reference on the x axis."""
    alpha = np.radians([-10.0, 10.0])
    beta = np.radians([-10.0, 10.0])
    zeros = np.zeros((2, 2))
    coeffs = {"CX": np.full((2, 2), cx), "CY": zeros, "CZ": zeros, "Cl": zeros, "Cm": zeros,
              "Cn": zeros}
    return FuselageAero(Table2D(alpha, beta, coeffs), area, 10.0, np.array([5.0, 0.0, 0.0]),
                        force_axes="body")


def towing_study(**hook):
    env = AeroEnvelope(("CENTRE",), [0.0], [0.0])
    return LoadsStudy(towing_airframe(), hook=HookLoadOptions(n_azimuth=0, **hook),
                      envelope=env, fuselage=drag_only_fuselage(), parachute=Parachute(1.0))


def trimmed_pitch_by_hand(fa, d, w):
    """Pitch of the towing airframe at which the moments about the hub balance, by hand.

    Body to earth R = Ry(theta) = [[c, 0, s], [0, 1, 0], [-s, 0, c]]; from the hub (5, 0, 1):
    the CG and the fuselage reference at r = (0, 0, -1), the parachute at (4, 0, -1). In body
    axes the weight is R^T (0, 0, -W) = (W s, 0, -W c), the fuselage drag (Fa, 0, 0), the
    parachute drag along the earth's aft flow R^T (D, 0, 0) = (D c, 0, D s). Pitching moments
    (M_y = r_z F_x - r_x F_z): -W s, -Fa, -D c - 4 D s; their sum is zero where
    (W + 4 D) sin(theta) + D cos(theta) = -Fa, i.e.
    theta = asin(-Fa / hypot(W + 4 D, D)) - atan2(D, W + 4 D)."""
    a, b = w + 4.0 * d, d
    return np.arcsin(-fa / np.hypot(a, b)) - np.arctan2(b, a)


def test_towed_trim_against_a_hand_moment_balance():
    """The towed case with parachute flies at the pitch of the hand moment balance
    (:func:`trimmed_pitch_by_hand`: Fa = q S 0.2 = 648.40 N, D = q 0.95 A = 1539.95 N,
    W = 9806.65 N: theta = -7.826 deg). Without parachute the table has no yawing moment at
    all: the yaw is indeterminate, so there is no trim, no towed case, and a finding says so.
    The loads' own applied loads at that attitude (gravity along its vertical, fuselage,
    parachute; another code than the multibody trim) have no moment about the hub, and the
    trimmed case has no horizontal acceleration."""
    study = towing_study()
    fa, d, w = Q * 2.0 * 0.2, Q * 0.95, 1000.0 * G0
    assert fa == pytest.approx(648.40, abs=0.01) and d == pytest.approx(1539.95, abs=0.01)
    trims = study.towed_trims
    assert np.degrees(trimmed_pitch_by_hand(fa, d, w)) == pytest.approx(-7.826, abs=1e-3)
    assert trims[True].pitch == pytest.approx(trimmed_pitch_by_hand(fa, d, w), abs=1e-8)
    assert not trims[False].converged and trims[True].trim.neutral == ""
    assert "nothing fixes the yaw" in trims[False].message
    assert any("without parachute" in line and "no trim" in line
               for line in study.run().towed_findings())
    assert trims[True].roll == pytest.approx(0.0, abs=1e-10)
    cases = study.case_matrix()
    tow = (cases["hook"] == "TOW").to_numpy()
    positions, forces, moments = study.applied_loads(cases[tow])
    n, feet = len(study.airframe.mass_items.mass), 4
    others = np.r_[0:n, n + feet:positions.shape[0]]
    r = positions[others] - study.airframe.hardpoints.hub
    about_hub = (np.cross(r[None], forces[:, others]) + moments[:, others]).sum(axis=1)
    assert_allclose(about_hub, 0.0, atol=1e-7 * w)
    result = study.run()
    k = study.case_verticals(cases)[tow]
    a = result.linear_acceleration[tow]
    assert_allclose(a - np.einsum("ij,ij->i", a, k)[:, None] * k, 0.0, atol=1e-12 * G0)


def test_vertical_case_x_shear_by_hand():
    """Fuselage drag Fa = q S 0.2 = 648.40 N shared over nine points, parachute drag
    D = q 0.95 A = 1539.95 N at x = 9. The vertical hook case reacts the drag by an aft
    acceleration (Fa + D)/m, which adds m_fwd (Fa + D)/m to V_x = -(applied x forces forward):
    at x = 3.5 (points 1, 2, 3 forward; 400 kg forward of 1000 kg), -3/9 Fa + 0.4 (Fa + D) =
    659.21 N; at x = 6.5 (the hub forward too), D + 3/9 Fa - 0.4 (Fa + D) = 880.74 N."""
    study = towing_study()
    result = study.run()
    cases = result.cases
    fa, d = Q * 2.0 * 0.2, Q * 0.95
    x = result.stations
    at = {v: int(np.argmin(np.abs(x - v))) for v in (3.5, 6.5)}
    vert = int(np.flatnonzero((cases["hook"] == "VERTICAL") & cases["chute"])[0])
    assert result.loads[vert, at[3.5], 0] == pytest.approx(-3 / 9 * fa + 0.4 * (fa + d),
                                                           rel=1e-9)
    assert result.loads[vert, at[6.5], 0] == pytest.approx(d + 3 / 9 * fa - 0.4 * (fa + d),
                                                           rel=1e-9)
    assert np.abs(result.residual).max() < 1e-8 * result.residual_scale


def test_towed_cable_angle_and_cone_flag_by_hand():
    """Trimmed cable at the trimmed pitch theta (:func:`trimmed_pitch_by_hand`): vertical
    component Nz W = 2.5 * 1000 * 9.80665 = 24516.63 N, horizontal the earth-horizontal part
    of the drags, H = D + Fa cos(theta) (the fuselage's body-axis drag tilted by theta),
    forward: angle atan(H / (Nz W)) at azimuth 180 deg (towards forward); at 1 g
    atan(H / W). Inside a 30 deg cone; with a 10 deg cone the 1 g angle lies OUTSIDE and is
    flagged."""
    table = towing_study().run().towed_table()
    on = table[table["chute"]].iloc[0]
    fa, d, w = Q * 2.0 * 0.2, Q * 0.95, 1000.0 * G0
    h = d + fa * np.cos(trimmed_pitch_by_hand(fa, d, w))
    assert on["cable angle from vertical [deg]"] == pytest.approx(
        np.degrees(np.arctan(h / (2.5 * w))), abs=1e-6)
    assert on["cable angle at 1 g [deg]"] == pytest.approx(np.degrees(np.arctan(h / w)),
                                                           abs=1e-6)
    assert on["cable azimuth [deg]"] == pytest.approx(180.0, abs=1e-9)
    assert on["inside hook cone"] == "yes"
    narrow = towing_study(angle=np.radians(10.0)).run().towed_table()
    assert narrow.loc[narrow["chute"], "inside hook cone"].iloc[0] == "OUTSIDE"
    assert not (~narrow["chute"]).any()  # no trim without parachute (yaw indeterminate)


def hc1_towing_study(attitude):
    """The small airframe under the generic HC1 fuselage, fin and a 1 m^2 parachute, four
    envelope points off the breakpoints."""
    af = offset_airframe()
    hp = af.hardpoints
    fuselage = sample_fuselage("HC1")
    fuselage = FuselageAero(fuselage.table, fuselage.area, fuselage.length, af.mass_items.cg)
    fin = sample_fin("HC1")
    fin = type(fin)(fin.table, fin.area, [2.7, 0.0, 0.6], fin.efficiency)
    airframe = Airframe(af.mass_items, af.stations,
                        Hardpoints(hp.hub, hp.mast_feet, chute=[2.75, 0.0, 0.3]))
    env = AeroEnvelope(("P1", "P2", "P3", "P4"), np.radians([0.0, 7.0, -9.0, 3.0]),
                       np.radians([0.0, 13.0, -11.0, -5.0]))
    return LoadsStudy(airframe, hook=HookLoadOptions(n_azimuth=4), envelope=env,
                      fuselage=fuselage, fin=fin, parachute=Parachute(1.0), attitude=attitude)


@pytest.mark.parametrize("attitude", ["hanging", Attitude(np.radians(4.0), np.radians(-2.0))])
def test_towed_cases_have_no_horizontal_resultant(attitude):
    """Every towed case: resultant force horizontal part zero (no fore-and-aft or lateral
    acceleration), vertical part m a . k = (Nz - 1) W + k . (aerodynamic + parachute
    forces); the hook's vertical component is Nz W; closure holds."""
    study = hc1_towing_study(attitude)
    cases = study.case_matrix()
    positions, forces, _ = study.applied_loads(cases)
    result = study.run()
    tow = (cases["hook"] == "TOW").to_numpy()
    assert tow.sum() == 2  # the trim with and without parachute
    k = study.case_verticals(cases)[tow]
    n, feet = len(study.airframe.mass_items.mass), 4
    hook = forces[:, n:n + feet].sum(axis=1)
    external = forces[:, n + feet:].sum(axis=1)
    weight = study.airframe.mass_items.weight
    m = study.airframe.mass_items.total_mass
    a = result.linear_acceleration[tow]
    along = np.einsum("ij,ij->i", a, k)
    assert_allclose(a - along[:, None] * k, 0.0, atol=1e-12 * G0)
    assert_allclose(m * along, 1.5 * weight + np.einsum("ij,ij->i", external[tow], k),
                    rtol=1e-12)
    assert_allclose(np.einsum("ij,ij->i", hook[tow], k), 2.5 * weight, rtol=1e-12)
    assert np.abs(result.residual).max() < 1e-8 * result.residual_scale
    angle = np.array([cable_geometry(hook[tow][j:j + 1], k[j])[0][0] for j in range(2)])
    assert_allclose(np.degrees(angle), result.cases.loc[tow, "cable angle from vertical [deg]"],
                    rtol=1e-12)


# -------------------------------------------------------------- per-direction inclination
def test_lateral_angle_applies_to_the_pure_lateral_directions_only():
    """angle 30 deg, lateral 10 deg, 8 azimuths, level attitude: AZ090 and AZ270 at 10 deg,
    all others at 30. By hand AZ090 = (0, sin 10, cos 10) = (0, 0.173648, 0.984808),
    AZ045 = (sin 30 cos 45, sin 30 sin 45, cos 30) = (0.353553, 0.353553, 0.866025),
    AZ000 = (0.5, 0, 0.866025)."""
    options = HookLoadOptions(lateral_angle=np.radians(10.0))
    frame = hook_directions(options).set_index("hook")
    assert_allclose(frame["inclination [deg]"].to_numpy(),
                    [0, 30, 30, 10, 30, 30, 30, 10, 30], atol=1e-12)
    assert list(frame.index[frame["reduced"]]) == ["AZ090", "AZ270"]
    assert_allclose(frame.loc["AZ090", ["ux", "uy", "uz"]], [0.0, 0.173648, 0.984808],
                    atol=1e-6)
    assert_allclose(frame.loc["AZ270", ["ux", "uy", "uz"]], [0.0, -0.173648, 0.984808],
                    atol=1e-6)
    assert_allclose(frame.loc["AZ045", ["ux", "uy", "uz"]], [0.353553, 0.353553, 0.866025],
                    atol=1e-6)
    assert_allclose(frame.loc["AZ000", ["ux", "uy", "uz"]], [0.5, 0.0, 0.866025], atol=1e-6)
    u = frame[["ux", "uy", "uz"]].to_numpy()
    assert_allclose(np.linalg.norm(u, axis=1), 1.0, rtol=1e-14)
    five = hook_directions(HookLoadOptions(lateral_angle=0.1, n_azimuth=5))
    assert not five["reduced"].any()  # no azimuth of five is pure lateral


def test_elliptical_cone_by_hand():
    """Elliptical cone, fore-and-aft 30 deg, lateral 10 deg: at 45 deg azimuth
    tan(theta) = tan30 tan10 / sqrt((tan10 cos45)^2 + (tan30 sin45)^2)
    = 0.101803 / sqrt(0.015546 + 0.166667) = 0.101803 / 0.426865 = 0.238490,
    theta = 13.414 deg; 30 deg at 0 and 180, 10 deg at 90 and 270. Every direction's
    horizontal offset at unit height (tan theta cos psi, tan theta sin psi) lies on the
    ellipse (x / tan 30)^2 + (y / tan 10)^2 = 1."""
    options = HookLoadOptions(lateral_angle=np.radians(10.0), cone="elliptical", n_azimuth=8)
    frame = hook_directions(options)
    inc = frame["inclination [deg]"].to_numpy()[1:]
    assert inc[1] == pytest.approx(13.414, abs=1e-3)
    assert_allclose(inc[[0, 2, 4, 6]], [30.0, 10.0, 30.0, 10.0], atol=1e-12)
    u = frame[["ux", "uy", "uz"]].to_numpy()[1:]
    x, y = u[:, 0] / u[:, 2], u[:, 1] / u[:, 2]
    assert_allclose((x / np.tan(np.radians(30))) ** 2 + (y / np.tan(np.radians(10))) ** 2,
                    1.0, rtol=1e-12)
    assert list(frame.loc[frame["reduced"], "hook"]) == ["AZ045", "AZ090", "AZ135", "AZ225",
                                                       "AZ270", "AZ315"]

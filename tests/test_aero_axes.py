"""Declared coefficient axes, converted once on input to airframe axes.

References:

* B. L. Stevens, F. L. Lewis, E. N. Johnson, "Aircraft Control and Simulation", 3rd ed.,
  Wiley 2016, section 2.3: wind-to-body transformation of the aerodynamic force
  (flight-mechanics body axes x forward, y right, z down):
  X = -D cos a cos b - C cos a sin b + L sin a, Y = -D sin b + C cos b,
  Z = -D sin a cos b - C sin a sin b - L cos a (D drag, C side force along y_W, L lift), and the
  stability-to-body rotation by alpha about y (the same with b = 0 for the forces; for the
  moments l_B = l_S cos a - n_S sin a, n_B = l_S sin a + n_S cos a).
* docs/conventions.md section 3: airframe axes are x aft, y right, z up, so a body-axes vector
  (X, Y, Z) is (-X, Y, -Z) in airframe axes.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import AeroEnvelope, LoadsStudy
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import (
    Fin,
    FuselageAero,
    force_from_airframe,
    force_to_airframe,
    moment_to_airframe,
)
from slingloads.models.airframe import Airframe, MassItems
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fuselage, sample_hardpoints

ANGLES = [(0.0, 0.0), (10.0, 15.0), (-8.0, -25.0), (20.0, 60.0)]


def stevens_body_force(cd, cc, cl, a, b):
    """Body-axes (x fwd, y right, z down) force coefficients from wind axes (Stevens & Lewis)."""
    ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    return np.array([-cd * ca * cb - cc * ca * sb + cl * sa,
                     -cd * sb + cc * cb,
                     -cd * sa * cb - cc * sa * sb - cl * ca])


def to_airframe(body):
    """Flight-mechanics body axes to airframe axes (x aft, z up): (-X, Y, -Z)."""
    return np.array([-body[0], body[1], -body[2]])


@pytest.mark.parametrize("alpha_deg, beta_deg", ANGLES)
def test_wind_force_conversion_against_stevens_lewis(alpha_deg, beta_deg):
    """Wind axes (CD, CY, CL) = (0.3, -0.5, 0.2) against the textbook rotation, at four
    (alpha, beta). Worked for alpha 10, beta 15 deg: ca cb = 0.951251, ca sb = 0.254887,
    sa = 0.173648, sa cb = 0.167731, sa sb = 0.044943, ca = 0.984808, cb = 0.965926,
    sb = 0.258819: X = -0.285375 + 0.127444 + 0.034730 = -0.123202, Y = -0.077646 - 0.482963
    = -0.560609, Z = -0.050319 + 0.022472 - 0.196962 = -0.224810; airframe (0.123202,
    -0.560609, 0.224810)."""
    a, b = np.radians(alpha_deg), np.radians(beta_deg)
    expected = to_airframe(stevens_body_force(0.3, -0.5, 0.2, a, b))
    assert_allclose(force_to_airframe([0.3, -0.5, 0.2], a, b, "wind"), expected, atol=1e-12)
    if (alpha_deg, beta_deg) == (10.0, 15.0):
        assert_allclose(expected, [0.123202, -0.560609, 0.224810], atol=2e-6)


@pytest.mark.parametrize("alpha_deg, beta_deg", ANGLES)
def test_stability_force_conversion_is_the_rotation_by_alpha(alpha_deg, beta_deg):
    """Stability axes: Stevens & Lewis with beta = 0 whatever the sideslip (the drag lies in
    the plane of symmetry, the side force along body y): X = -CD cos a + CL sin a, Y = CY,
    Z = -CD sin a - CL cos a."""
    a, b = np.radians(alpha_deg), np.radians(beta_deg)
    expected = to_airframe(stevens_body_force(0.3, -0.5, 0.2, a, 0.0))
    assert_allclose(force_to_airframe([0.3, -0.5, 0.2], a, b, "stability"), expected,
                    atol=1e-12)


def test_body_force_conversion_signs():
    """Body axes: CX forward, CY right, CZ down; airframe (x aft, z up) = (-CX, CY, -CZ)."""
    assert_allclose(force_to_airframe([0.3, -0.5, 0.2], 0.3, -0.4, "body"),
                    [-0.3, -0.5, -0.2], atol=0)


def test_all_frames_coincide_at_zero_angles():
    """Limit case alpha = beta = 0: drag CD = 1 pulls aft (+x), lift CL = 1 up (+z), in wind
    and stability axes alike; body CX = -1 (axial force rearwards) is the same drag."""
    for axes in ("wind", "stability"):
        assert_allclose(force_to_airframe([1.0, 0.0, 0.0], 0.0, 0.0, axes), [1, 0, 0],
                        atol=1e-15)
        assert_allclose(force_to_airframe([0.0, 0.0, 1.0], 0.0, 0.0, axes), [0, 0, 1],
                        atol=1e-15)
    assert_allclose(force_to_airframe([-1.0, 0.0, 0.0], 0.0, 0.0, "body"), [1, 0, 0])


@pytest.mark.parametrize("alpha_deg, beta_deg", ANGLES)
def test_moment_conversions_by_hand(alpha_deg, beta_deg):
    """Moments (Cl, Cm, Cn) = (0.02, -0.05, 0.08) about the declared axes:
    body -> airframe (-Cl, Cm, -Cn); stability -> body l_B = l cos a - n sin a, m_B = m,
    n_B = l sin a + n cos a; wind -> body = l x_W + m y_W + n z_W with x_W = (ca cb, sb, sa cb),
    y_W = (-ca sb, cb, -sa sb), z_W = (-sa, 0, ca) in body axes (Stevens & Lewis 2.3)."""
    a, b = np.radians(alpha_deg), np.radians(beta_deg)
    ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    cl, cm, cn = 0.02, -0.05, 0.08
    assert_allclose(moment_to_airframe([cl, cm, cn], a, b, "body"), [-cl, cm, -cn], atol=0)
    stab = np.array([cl * ca - cn * sa, cm, cl * sa + cn * ca])
    assert_allclose(moment_to_airframe([cl, cm, cn], a, b, "stability"), to_airframe(stab),
                    atol=1e-15)
    wind = (cl * np.array([ca * cb, sb, sa * cb]) + cm * np.array([-ca * sb, cb, -sa * sb])
            + cn * np.array([-sa, 0.0, ca]))
    assert_allclose(moment_to_airframe([cl, cm, cn], a, b, "wind"), to_airframe(wind),
                    atol=1e-15)


def test_inverse_conversion_round_trips():
    """The frames are orthonormal: converting to airframe axes and back is the identity."""
    c = np.array([[0.3, -0.5, 0.2], [1.2, 0.1, -0.4]])
    a, b = np.radians([5.0, -12.0]), np.radians([33.0, -7.0])
    for axes in ("wind", "stability", "body"):
        assert_allclose(force_from_airframe(force_to_airframe(c, a, b, axes), a, b, axes), c,
                        atol=1e-14)


def body_equivalent(fuselage):
    """The sample's wind-axes force table re-tabulated in body axes (CX, CY, CZ) with the
    textbook formulas, grid point by grid point; moments copied (body axes both)."""
    t = fuselage.table
    a, b = np.meshgrid(t.alpha, t.beta, indexing="ij")
    cd, cy, cl = (t.coefficients[c] for c in ("CD", "CY", "CL"))
    x, y, z = stevens_body_force(cd, cy, cl, a, b)
    coeffs = {"CX": x, "CY": y, "CZ": z, **{c: t.coefficients[c] for c in ("Cl", "Cm", "Cn")}}
    return FuselageAero(Table2D(t.alpha, t.beta, coeffs), fuselage.area, fuselage.length,
                        fuselage.moment_reference, force_axes="body")


def small_airframe():
    """Four masses of 500 kg at x = -4, -1, 2, 6.5 m, off the x axis so that every inertia is
    positive, with the HC1 sample's hub, mast feet and parachute attachment (x = 6.4 m)."""
    position = [[-4.0, 0.3, -0.4], [-1.0, -0.3, 0.2], [2.0, 0.3, 0.5], [6.5, -0.3, 0.9]]
    items = MassItems(("a", "b", "c", "d"), np.full(4, 500.0), position)
    return Airframe(items, np.linspace(-4.0, 6.5, 8), sample_hardpoints("HC1"))


def test_body_table_and_its_wind_equivalent_give_the_same_loads():
    """The same fuselage given in wind axes (the HC1 sample) and in body axes (re-tabulated by
    the textbook formulas at every breakpoint) gives the same SFBM at envelope points on the
    breakpoints (alpha 10 / -5 / 5 deg, beta 16 / -4 / 0 deg). Between breakpoints each table
    is linear in its own frame, so the two differ there at second order in the 2-deg step:
    within 0.1 % of the largest load at beta 15 deg."""
    wind = sample_fuselage("HC1")
    body = body_equivalent(wind)
    on = AeroEnvelope(("P1", "P2", "P3"), np.radians([10.0, -5.0, 5.0]),
                      np.radians([16.0, -4.0, 0.0]))
    off = AeroEnvelope(("Q",), [np.radians(10.0)], [np.radians(15.0)])
    for env, tol in ((on, 1e-10), (off, 1e-3)):
        runs = [LoadsStudy(small_airframe(), hook=HookLoadOptions(n_azimuth=4), envelope=env,
                           fuselage=f).run() for f in (wind, body)]
        scale = np.abs(runs[0].loads).max()
        assert_allclose(runs[1].loads, runs[0].loads, rtol=0, atol=tol * scale)
    assert_allclose(body.drag_coefficient(np.radians(10.0), np.radians(16.0)),
                    wind.table("CD", np.radians(10.0), np.radians(16.0)), rtol=1e-12)


def test_conversion_is_exact_between_coarse_breakpoints():
    """Regression: interpolating airframe-axes values converted on the breakpoints turns the
    frame's rotation into a chord. A constant wind-axes CD = 1 tabulated only at beta = -180
    and 180 deg must still be a pure drag along the airflow d(alpha, beta) at any angle (at
    beta = 0 the chord would have pointed forward)."""
    alpha, beta = np.radians([-40.0, 40.0]), np.radians([-180.0, 180.0])
    coeffs = {c: np.zeros((2, 2)) for c in ("CD", "CY", "CL", "Cl", "Cm", "Cn")}
    coeffs["CD"] = np.ones((2, 2))
    fus = FuselageAero(Table2D(alpha, beta, coeffs), 1.0, 1.0, np.zeros(3))
    a, b = np.radians([0.0, 17.0, -33.0]), np.radians([0.0, 95.0, -140.0])
    d = np.stack([np.cos(a) * np.cos(b), -np.sin(b), np.sin(a) * np.cos(b)], axis=-1)
    assert_allclose(fus.airframe_coefficients(a, b)[:, :3], d, atol=1e-15)


@pytest.mark.parametrize("force_axes", ["wind", "stability", "body"])
@pytest.mark.parametrize("moment_axes", ["body", "stability", "wind"])
def test_multibody_kernel_converts_as_the_loads_do(force_axes, moment_axes):
    """The compiled fuselage kernel of the multibody model (air velocity in airframe axes)
    gives the force and moment of FuselageAero.loads at the same alpha and beta, for every
    pair of declared frames (one conversion, two implementations)."""
    from slingloads.models.aerodynamics import FRAME_CODES
    from slingloads.models.multibody.local_flow import fuselage_loads

    rng = np.random.default_rng(3)
    alpha, beta = np.radians([-20.0, 0.0, 25.0]), np.radians([-150.0, 0.0, 40.0, 170.0])
    names = (("CX", "CY", "CZ") if force_axes == "body" else ("CD", "CY", "CL"))
    coeffs = {c: rng.normal(size=(3, 4)) for c in names + ("Cl", "Cm", "Cn")}
    fus = FuselageAero(Table2D(alpha, beta, coeffs), 2.0, 3.0, np.zeros(3), force_axes,
                       moment_axes)
    grid = np.stack([fus.table.coefficients[c] for c in fus.columns])
    for a_deg, b_deg in ((7.0, -100.0), (-12.0, 33.0), (18.0, 160.0)):
        a, b = np.radians(a_deg), np.radians(b_deg)
        u = 30.0 * np.array([np.cos(a) * np.cos(b), -np.sin(b), np.sin(a) * np.cos(b)])
        out = fuselage_loads(*u, 0.5, 2.0, 3.0, alpha, beta, grid, 0.1,
                             FRAME_CODES[force_axes], FRAME_CODES[moment_axes])
        force, moment = fus.loads(np.array([a]), np.array([b]), 0.5 * 900.0)
        assert_allclose(out[:3], force[0], rtol=1e-12, atol=1e-12)
        assert_allclose(out[3:6], moment[0], rtol=1e-12, atol=1e-12)
        assert_allclose(out[6:8], [a, b], atol=1e-12)


def test_fin_in_wind_axes_by_hand():
    """A fin table in wind axes: CY along y_W = (sin b, cos b, 0) at zero angle of attack.
    CY = -1 at beta = 30 deg, q S eta = 1000 N: force (-500, -866.025, 0) N; the same table in
    body axes gives (0, -1000, 0) N."""
    beta = np.radians([-30.0, 0.0, 30.0])
    table = Table1D(beta, {"CY": [1.0, 0.0, -1.0]})
    wind = Fin(table, 2.0, np.zeros(3), 0.5, axes="wind")
    body = Fin(table, 2.0, np.zeros(3), 0.5)
    assert_allclose(wind.force(np.radians(30.0), 1000.0), [-500.0, -866.0254, 0.0], rtol=1e-6)
    assert_allclose(body.force(np.radians(30.0), 1000.0), [0.0, -1000.0, 0.0], atol=1e-12)


def test_parachute_canopy_axes_along_the_line():
    """Parachute line held along +x at alpha 0, beta 15 deg (canopy angle of attack 15 deg):
    a canopy-axes CT acts along +x, a wind-axes CD along the wind d = (cos 15, -sin 15, 0),
    each with magnitude q eta C A = 1621.000 x 0.95 x 1.0 x 2 = 3079.90 N (flat tables to
    20 deg)."""
    twenty = np.radians(20.0)
    airframe = small_airframe()
    env = AeroEnvelope(("P",), [0.0], [np.radians(15.0)])
    drags = []
    for column, axes in (("CT", "canopy"), ("CD", "wind")):
        chute = Parachute(2.0, Table1D([-twenty, twenty], {column: [1.0, 1.0]}, "alpha",
                                       "parachute"), axes=axes)
        study = LoadsStudy(airframe, hook=HookLoadOptions(n_azimuth=0), envelope=env,
                           parachute=chute, chute_line="fuselage axis")
        cases = study.case_matrix()
        _, forces, _ = study.applied_loads(cases)
        drags.append(forces[cases["chute"].to_numpy(bool)][0, -1])
    b = np.radians(15.0)
    assert_allclose(drags[0], [3079.90, 0.0, 0.0], rtol=1e-5)
    assert_allclose(drags[1], 3079.90 * np.array([np.cos(b), -np.sin(b), 0.0]), rtol=1e-5)


def test_axes_and_columns_are_checked():
    """A body-axes table needs CX, CY, CZ; an unknown frame is refused with the valid ones."""
    t = sample_fuselage("HC1").table
    with pytest.raises(InputError, match=r"body axes it needs \['CX', 'CY', 'CZ'"):
        FuselageAero(t, 3.0, 11.0, np.zeros(3), force_axes="body")
    with pytest.raises(InputError, match="must be one of"):
        FuselageAero(t, 3.0, 11.0, np.zeros(3), moment_axes="earth")
    with pytest.raises(InputError, match="must be one of"):
        Fin(Table1D([-1.0, 1.0], {"CY": [1.0, -1.0]}), 1.0, np.zeros(3), axes="stability")

"""Verification of the aerodynamic and parachute loads that LoadsStudy puts on the airframe.

References:

* docs/conventions.md section 3 (flight-mechanics coefficients into airframe axes; the sample
  tables give forces in wind axes and moments in body axes):
  d = (cos a cos b, -sin b, sin a cos b), y_W = (cos a sin b, cos b, sin a sin b),
  l = (-sin a, 0, cos a), F = q S (CD d + CY y_W + CL l), M = q S L (-Cl, Cm, -Cn) about the
  moment reference;
  fin side force q S_fin eta CY(beta) along +y at the fin centre of pressure.
* docs/conventions.md section 5: parachute drag D = k_open q eta_wake CD A along the relative
  wind d(alpha, beta); the paper's effective CD of 0.95 (FACTS section 3) is the default
  canopy CD 1.0 times the default wake ratio eta_wake 0.95 (the wake loss counted once).
* Statics: the fuselage load shared to the aerodynamic points must keep its resultant force and
  its moment about the table's moment reference point.

Coefficients are read from the CSV files with pandas, not through slingloads, and the dynamic
pressure is q = 0.5 rho0 V^2 at 100 KEAS = 0.5 * 1.225 * 51.4444^2 = 1621.000 Pa.
"""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from numpy.testing import assert_allclose

import slingloads
from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import AeroEnvelope, ListedCase, LoadsStudy
from slingloads.errors import InputError
from slingloads.models.airframe import Airframe, MassItems
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import sample_fin, sample_fuselage, sample_hardpoints

DATA = Path(slingloads.__file__).parent / "data"
Q = 0.5 * 1.225 * (100 * 1852.0 / 3600.0) ** 2  # 1621.000 Pa at 100 KEAS
S, LREF, MREF = 3.0, 11.5, np.array([0.25, 0.0, -0.3])  # HC1, SAMPLE_DATA.md
S_FIN, ETA_FIN, FIN_CP = 0.9, 0.5, np.array([5.9, 0.0, 1.1])
CHUTE_AREA = 10.0


def fuselage_row(alpha_deg, beta_deg):
    frame = pd.read_csv(DATA / "hc1_fuselage.csv")
    row = frame[(frame["alpha [deg]"] == alpha_deg) & (frame["beta [deg]"] == beta_deg)]
    assert len(row) == 1, "pick a grid point of the table"
    return row.iloc[0]


def fin_cy(beta_deg):
    frame = pd.read_csv(DATA / "hc1_fin.csv")
    row = frame[frame["beta [deg]"] == beta_deg]
    assert len(row) == 1
    return float(row["CY"].iloc[0])


def hc1_airframe():
    """Six masses from x = -5 to 7 m (covering the fin and the parachute attachment)."""
    x = np.array([-5.0, -2.0, 0.0, 1.5, 4.0, 7.0])
    position = np.column_stack([x, [0.0, 0.1, -0.2, 0.3, 0.0, 0.5],
                                [-0.5, -0.3, 0.2, 0.4, 0.3, 1.2]])
    mass = np.array([200.0, 700.0, 800.0, 600.0, 350.0, 250.0])
    inertia = np.broadcast_to(np.diag([40.0, 60.0, 60.0]), (6, 3, 3)).copy()
    items = MassItems(tuple(f"m{i}" for i in range(6)), mass, position, inertia)
    return Airframe(items, np.linspace(-5.0, 7.0, 13), sample_hardpoints("HC1"))


def study_at(alpha_deg, beta_deg, fuselage=True, fin=True, chute=True, **kwargs):
    env = AeroEnvelope(("P",), [np.radians(alpha_deg)], [np.radians(beta_deg)])
    return LoadsStudy(hc1_airframe(), hook=HookLoadOptions(n_azimuth=0, towed=False), envelope=env,
                      fuselage=sample_fuselage("HC1") if fuselage else None,
                      fin=sample_fin("HC1") if fin else None,
                      parachute=Parachute(area=CHUTE_AREA) if chute else None, **kwargs)


def blocks(study):
    """Index ranges of the load points: mass items, mast feet, aero points, fin, chute."""
    af = study.airframe
    n, k, a = len(af.mass_items.mass), len(af.hardpoints.mast_feet), af.aero_points.size
    aero = slice(n + k, n + k + a)
    fin = n + k + a if study.fin is not None else None
    chute = n + k + a + (study.fin is not None) if study.parachute is not None else None
    return aero, fin, chute


def test_fuselage_resultants_equal_the_table_at_a_grid_point():
    """HC1 fuselage table (wind-axes forces, body-axes moments, SAMPLE_DATA.md) at alpha = 10
    deg, beta = 16 deg (CSV row): CD = 0.607253, CY = -0.562787, CL = 0.188417, Cl = -0.013248,
    Cm = 0.077793, Cn = -0.088524. q S = 1621.000 * 3.0 = 4863.00 N; airflow
    d = (cos a cos b, -sin b, sin a cos b) = (0.946658, -0.275637, 0.166921), wind y axis
    y_W = (cos a sin b, cos b, sin a sin b) = (0.271450, 0.961262, 0.047864), lift
    l = (-0.173648, 0, 0.984808); by hand
    F = 4863.00 (CD d + CY y_W + CL l) = (1893.53, -3444.79, 1264.29) N,
    M = 4863.00 * 11.5 (-Cl, Cm, -Cn) = (740.888, 4350.54, 4950.66) N m about (0.25, 0, -0.3).
    The forces LoadsStudy puts on the aerodynamic points sum to F, and their moment about the
    moment reference (plus any point moments) is M."""
    row = fuselage_row(10.0, 16.0)
    a, b = np.radians(10.0), np.radians(16.0)
    d = np.array([np.cos(a) * np.cos(b), -np.sin(b), np.sin(a) * np.cos(b)])
    y_w = np.array([np.cos(a) * np.sin(b), np.cos(b), np.sin(a) * np.sin(b)])
    lift = np.array([-np.sin(a), 0.0, np.cos(a)])
    f_hand = Q * S * (row["CD"] * d + row["CY"] * y_w + row["CL"] * lift)
    m_hand = Q * S * LREF * np.array([-row["Cl"], row["Cm"], -row["Cn"]])
    assert_allclose(f_hand, [1893.53, -3444.79, 1264.29], rtol=1e-5)  # the worked numbers
    assert_allclose(m_hand, [740.888, 4350.54, 4950.66], rtol=1e-5)

    study = study_at(10.0, 16.0, fin=False, chute=False)
    positions, forces, moments = study.applied_loads(study.case_matrix())
    aero, _, _ = blocks(study)
    f_sum = forces[:, aero].sum(axis=1)
    m_sum = (np.cross(positions[aero] - MREF, forces[:, aero]) + moments[:, aero]).sum(axis=1)
    assert_allclose(f_sum, np.tile(f_hand, (len(f_sum), 1)), rtol=1e-10)
    assert_allclose(m_sum, np.tile(m_hand, (len(m_sum), 1)), rtol=1e-9)
    # the aero points lie on the loads reference axis (y0, z0) = (0, 0)
    assert_allclose(positions[aero][:, 1:], 0.0, atol=0)


def test_fin_side_force_by_hand_and_its_sign():
    """Fin side force q S_fin eta CY(beta) along +y at the fin centre of pressure (5.9, 0, 1.1).
    HC1 fin CSV at beta = +16 deg: CY = -0.75547; by hand
    1621.000 * 0.9 * 0.5 * (-0.75547) = -551.078 N: positive beta (wind from the right)
    pushes the fin to the left (-y), so the fin, aft of the CG, turns the nose right
    (stabilising, docs/conventions.md section 3). At beta = -16 deg the force is +551.078 N."""
    for beta, expected in ((16.0, -551.078), (-16.0, 551.078)):
        cy = fin_cy(beta)
        hand = Q * S_FIN * ETA_FIN * cy
        assert hand == pytest.approx(expected, rel=1e-5)
        study = study_at(10.0, beta, fuselage=False, chute=False)
        positions, forces, _ = study.applied_loads(study.case_matrix())
        _, fin, _ = blocks(study)
        assert_allclose(positions[fin], FIN_CP, atol=0)
        assert_allclose(forces[:, fin], np.tile([0.0, hand, 0.0], (len(forces), 1)), rtol=1e-12)
    assert fin_cy(16.0) < 0 < fin_cy(-16.0)


def test_fin_yawing_moment_about_cg_is_nose_right_for_positive_beta():
    """Sign chain of docs/conventions.md section 3: fin force -y at x aft of the CG gives
    Mz = (x_fin - x_cg) * Fy < 0 about +z, i.e. nose right (positive Cn is a negative
    rotation about +z); so the inertia relief turns the airframe with alpha_dot_z < 0."""
    study = study_at(0.0, 16.0, fuselage=False, chute=False)
    result = study.run()
    assert np.all(result.angular_acceleration[:, 2] < 0)


def test_parachute_drag_magnitude_and_direction_by_hand():
    """Parachute drag D = q eta_wake CD A = 1621.000 * 0.95 * 1.0 * 10 = 15399.50 N along the
    relative wind at alpha = 10 deg, beta = 15 deg:
    d = (cos 10 cos 15, -sin 15, sin 10 cos 15) = (0.951251, -0.258819, 0.167731):
    aft (+x), to the left (-y, the wind comes from the right) and up (+z, the wind comes from
    below at positive alpha). The case with the parachute off carries no drag."""
    study = study_at(10.0, 15.0, fuselage=False, fin=False)
    cases = study.case_matrix()
    positions, forces, _ = study.applied_loads(cases)
    _, _, chute = blocks(study)
    assert_allclose(positions[chute], [6.4, 0.0, 1.6], atol=0)
    on = cases["chute"].to_numpy(bool)
    assert on.sum() == 1 and (~on).sum() == 1
    drag = forces[on, chute][0]
    assert np.linalg.norm(drag) == pytest.approx(15399.50, rel=1e-6)
    assert_allclose(drag / np.linalg.norm(drag), [0.951251, -0.258819, 0.167731], atol=1e-6)
    assert_allclose(forces[~on, chute], 0.0, atol=0)


def test_parachute_drag_at_zero_incidence_pulls_aft():
    """Limit case: alpha = beta = 0 gives d = (1, 0, 0): the drag pulls straight aft with
    1621.000 * 0.95 * 1.0 * 10 = 15399.50 N."""
    study = study_at(0.0, 0.0, fuselage=False, fin=False)
    cases = study.case_matrix()
    _, forces, _ = study.applied_loads(cases)
    _, _, chute = blocks(study)
    on = cases["chute"].to_numpy(bool)
    assert_allclose(forces[on, chute][0], [15399.50, 0.0, 0.0], rtol=1e-6, atol=1e-9)


def test_aero_off_case_has_no_aerodynamic_load():
    """A listed case with aero point NONE and parachute off: no fuselage, fin or parachute
    load at all (only gravity and the hook act)."""
    study = study_at(10.0, 16.0, generate=False,
                     listed=(ListedCase("QUIET", "AXIAL", "NONE", False),))
    positions, forces, moments = study.applied_loads(study.case_matrix())
    aero, fin, chute = blocks(study)
    assert_allclose(forces[:, aero.start:], 0.0, atol=0)
    assert_allclose(moments[:, aero.start:], 0.0, atol=0)


@pytest.mark.parametrize(("alpha", "beta", "message"), [
    (45.0, 0.0, r"alpha = 45 deg is outside the HC1 fuselage table's range \[-40, 40\]"),
    (-41.0, 10.0, r"alpha = -41 deg is outside"),
    (0.0, 185.0, r"beta = 185 deg is outside the HC1 fuselage table's range \[-180, 180\]"),
])
def test_envelope_point_outside_the_table_is_refused(alpha, beta, message):
    """No extrapolation (aero_tables module contract): an envelope point outside the HC1
    fuselage table (alpha -40..40 deg, beta -180..180 deg) raises InputError naming the angle
    and the range when the study is built."""
    with pytest.raises(InputError, match=message):
        study_at(alpha, beta, fin=False, chute=False)


def test_fin_beta_outside_its_table_is_refused():
    """The fin table (beta -180..180 deg) does not extrapolate either."""
    with pytest.raises(InputError, match=r"beta = 185 deg is outside the HC1 fin table"):
        study_at(0.0, 185.0, fuselage=False, chute=False)


def test_parachute_along_fuselage_axis_outside_its_cd_range_is_refused():
    """With the line along the fuselage axis the canopy meets the wind at
    arccos(cos 10 cos 15) = arccos(0.951251) = 17.96 deg, outside the paper's +-8 deg CD
    range (FACTS section 3): InputError naming the angle, not an extrapolated CD."""
    with pytest.raises(InputError, match=r"alpha = 17\.9\d* deg is outside the parachute"):
        study_at(10.0, 15.0, fuselage=False, fin=False, chute_line="fuselage axis")

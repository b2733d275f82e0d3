"""The 1-DOF yaw model about one axis through the hub: the airframe-z limit, the tilted
suspension axis against a hand calculation from the tables, and the weight's moment against a
rotation computed independently (scipy)."""

from __future__ import annotations

import numpy as np
import pytest
from hostile import EXAMPLE
from scipy.spatial.transform import Rotation

from slingloads.analyses.chute_sizing import neutral_area, run_yaw
from slingloads.analyses.towed_attitude import yaw_model_about
from slingloads.constants import G0
from slingloads.io.study import read_study
from slingloads.models.gusts import standard_gusts
from slingloads.models.integration import SolverSettings
from slingloads.runs.chute_sizing import _towed_system

HALF = np.radians(15.0)  # the example's linearisation range


@pytest.fixture(scope="module")
def example():
    """The example's sizing model (airframe z, alpha 0 as read), its towed system and the
    towed trim at the sizing airspeed."""
    from slingloads.analyses.towed_attitude import towed_attitude

    study = read_study(EXAMPLE, only=["chute sizing", "multibody"])
    model = study.inputs.chute_sizing.model
    system = _towed_system(study)
    return model, system, towed_attitude(system, model.condition.eas)


def test_airframe_z_reproduces_the_paper_balance_exactly(example):
    """Limit case: the axis along airframe z without a weight is the model as it was (axis
    None): the same model row, tables and neutral areas, bit for bit, at the trim alpha."""
    from dataclasses import replace

    model, system, towed = example
    old = replace(model, condition=replace(model.condition, alpha=towed.alpha))
    new, text = yaw_model_about(model, "airframe z", towed, None)
    assert "airframe z" in text and new.weight_terms == (0.0, 0.0)
    for a, b in zip(old.arrays(), new.arrays(), strict=True):
        np.testing.assert_array_equal(a, b)
    r_old, r_new = neutral_area(old, (-HALF, HALF)), neutral_area(new, (-HALF, HALF))
    assert (r_new.area_fit, r_new.area_local) == (r_old.area_fit, r_old.area_local)


def _hand_neutral_area(model, towed, body, weight=True):
    """Neutral area about the towed trim's cable line a, by hand from the table values:
    N = -a . M with M = q S L (-Cl, Cm, -Cn) + r x F (docs/conventions.md: body-axes moment
    coefficients, wind-axes forces; F_y = q S (CY cos b - CD sin b)), the fin's side force
    q S_f eta CY_f along y at its centre of pressure, the parachute's drag q eta CD A along the
    airflow at the attachment, and the weight turning about a with the heading; the arm of a
    point r from the hub is its component along e1 = y x a, a_z r_x - a_x r_z. Slopes at zero
    sideslip by central differences over the 2 deg breakpoints."""
    fus, fin = model.fuselage, model.fin
    hub = model.hardpoints.hub
    a = np.asarray(towed.axis, float)
    alpha = towed.alpha
    table = fus.table

    def coefficient(name, beta):
        column = [np.interp(alpha, table.alpha, table.coefficients[name][:, j])
                  for j in range(table.beta.size)]
        return np.interp(beta, table.beta, column)

    h = np.radians(2.0)

    def slope(name):
        return (coefficient(name, h) - coefficient(name, -h)) / (2 * h)

    def arm(r):
        return a[2] * r[0] - a[0] * r[2]

    q = model.condition.dynamic_pressure
    S, L = fus.area, fus.length
    d_fus = (q * S * L * (a[0] * slope("Cl") + a[2] * slope("Cn"))
             - q * S * (slope("CY") - coefficient("CD", 0.0)) * arm(fus.moment_reference - hub))
    cy = fin.table.coefficients["CY"]
    fin_slope = (np.interp(h, fin.table.angle, cy) - np.interp(-h, fin.table.angle, cy)) / (2 * h)
    d_fin = -q * fin.area * fin.efficiency * fin_slope * arm(fin.centre_of_pressure - hub)
    d_weight = 0.0
    if weight:
        # dN_w/dpsi = -(r_perp . W_perp); the model takes beta = gamma - psi one for one
        w = -body.mass * G0 * np.asarray(towed.vertical, float)
        r = body.cg - hub
        w_perp, r_perp = w - (w @ a) * a, r - (r @ a) * a
        d_weight = r_perp @ w_perp  # dN_w/dbeta = -dN_w/dpsi
    cd = float(model.parachute.effective_coefficient(0.0))
    per_area = q * cd * arm(model.hardpoints.chute - hub)
    return -(d_fus + d_fin + d_weight) / per_area


def test_tilted_axis_neutral_area_against_a_hand_calculation(example):
    """About the towed trim's cable line (18 deg from airframe z on the example), the model's
    local-slope neutral area, with and without the weight, equals the hand calculation of
    :func:`_hand_neutral_area` within 0.5 % (the central difference of F_y = CY cos b - CD
    sin b against the table's own lines: second order in the 2 deg step)."""
    from dataclasses import replace

    model, system, towed = example
    tilted, text = yaw_model_about(model, "suspension", towed, system.body)
    assert "18.1 deg" in text and "weight included" in text
    assert tilted.axis_tilt == pytest.approx(np.radians(18.07), abs=np.radians(0.01))
    with_weight = neutral_area(tilted, (-HALF, HALF), basis="local").area
    hand = _hand_neutral_area(model, towed, system.body)
    assert with_weight == pytest.approx(hand, rel=5e-3)
    bare = neutral_area(replace(tilted, weight=None, cg=None), (-HALF, HALF),
                        basis="local").area
    assert bare == pytest.approx(_hand_neutral_area(model, towed, system.body, False),
                                 rel=5e-3)
    # the weight is destabilising about the forward-tilted cable line on the example
    assert with_weight > bare


def test_weight_moment_against_an_independent_rotation(example):
    """N_w(psi) = W_c (cos(psi) - 1) + W_s sin(psi) against -a . (r x W_body(psi)) less its
    value at psi = 0 (the trim's), with the earth's weight turned into airframe axes by
    scipy's rotation about a by +psi (nose right is a negative rotation of the body about +a);
    zero about the vertical through the hub."""
    from dataclasses import replace

    model, system, towed = example
    tilted, _ = yaw_model_about(model, "suspension", towed, system.body)
    a = tilted.axis
    w0 = -system.body.mass * G0 * np.asarray(towed.vertical, float)
    r = system.body.cg - model.hardpoints.hub
    for psi in np.radians([-60.0, -7.0, 0.0, 3.0, 45.0, 170.0]):
        w = Rotation.from_rotvec(psi * a).apply(w0)
        direct = -a @ np.cross(r, w) + a @ np.cross(r, w0)
        assert tilted.weight_moment(psi) == pytest.approx(direct,
                                                          abs=1e-9 * np.linalg.norm(w0))
    vertical = replace(tilted, axis=np.asarray(towed.vertical, float))
    assert np.allclose(vertical.weight_terms, 0.0, atol=1e-9 * np.linalg.norm(w0))


def test_held_gust_is_judged_about_its_own_equilibrium(example):
    """With the weight's moment about the tilted axis, a held 30 ft/s gust moves the
    equilibrium off zero sideslip (the weight turns with the heading, not with the wind): the
    linear estimate beta = k_w gamma / k (from (k - k_w)(gamma - psi) - k_w psi = 0, k the
    total stiffness, k_w the weight's, negative here) within 10 %; a run that settles there
    is convergent, not a static departure."""
    model, system, towed = example
    tilted, _ = yaw_model_about(model, "suspension", towed, system.body)
    area = 3.0 * neutral_area(tilted, (-HALF, HALF)).area
    gust = 30 * 0.3048
    beta = tilted.trim_betas([area], gust=gust)[0]
    from slingloads.analyses.chute_sizing import linear_yaw

    lin = linear_yaw(tilted, area, (-HALF, HALF), "local")
    gamma = np.arctan2(gust, tilted.condition.tas)
    assert beta == pytest.approx(lin.weight_stiffness * gamma / lin.stiffness, rel=0.1)
    assert abs(np.degrees(beta)) > 1.0  # beyond the 1 deg static-departure offset
    runs = run_yaw(tilted, area, [g for g in standard_gusts() if g.kind == "step"],
                   SolverSettings(120.0, 0.1), (-HALF, HALF)).to_frame()
    assert runs["verdict"].iloc[0] == "convergent"
    assert runs["final beta [deg]"].iloc[0] == pytest.approx(np.degrees(beta), abs=0.05)


def test_the_campaign_runs_the_sizings_proposed_area(tmp_path):
    """With the sizing in the same run, a campaign whose factors lack the 1-DOF proposal (the
    example's with factors 1.0 and 3.0) also runs it: the matrix gains the factor
    proposal / neutral (2.2 on the example), the Summary says it was added, and the decision
    gives the multibody verdict at that area from those runs (was 'not run at this area')."""
    import openpyxl
    import pandas as pd
    from hostile import study_row

    from slingloads.analyses.campaign.selection import stable_runs
    from slingloads.analyses.parachute_decision import multibody_verdict_at

    book = openpyxl.load_workbook(EXAMPLE)
    for name, value in (("run campaign", "yes"), ("campaign area factors", "1.0, 3.0"),
                        ("run lateral", "no"), ("run loads", "no")):
        book["Study"][f"B{study_row(book, name)}"] = value
    path = tmp_path / "added.xlsx"
    book.save(path)
    study = read_study(path)
    results = study.run()
    sizing, campaign = results.chute_sizing, results.campaign
    proposal = sizing.sweep.smallest_stable_area
    factor = proposal / campaign.result.campaign.neutral.area
    assert factor == pytest.approx(2.2, rel=1e-9)
    assert campaign.sizing_factor == pytest.approx(factor, rel=1e-12)
    metrics = campaign.result.metrics
    at = np.isclose(metrics["area [m^2]"], proposal, rtol=1e-6)
    assert at.sum() == 4  # 2 airspeeds x 2 manoeuvres
    decision = results.parachute_decision
    assert decision.multibody_at_one_dof == multibody_verdict_at(
        metrics, proposal, stable_runs(metrics).to_numpy())
    assert decision.multibody_at_one_dof != "not run at this area"
    from slingloads.io.reports import write_reports

    write_reports(results, tmp_path / "out")
    summary = pd.read_excel(next((tmp_path / "out").glob("*-campaign.xlsx")), "Summary",
                            header=None)
    row = summary[summary[0] == "area factors"].iloc[0]
    assert "added: the parachute sizing's proposed area" in str(row[3])

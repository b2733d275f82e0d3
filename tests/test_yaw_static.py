"""Neutral yaw static stability (paper section 4.1) and the local linearisation."""

import numpy as np
import pandas as pd
import pytest

from slingloads.analyses.chute_sizing import linear_yaw, neutral_area, sizing_sweep
from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import FUSELAGE_COEFFICIENTS, Fin, FuselageAero
from slingloads.models.airframe import Hardpoints
from slingloads.models.flight import FlightCondition
from slingloads.models.parachute import Parachute
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)
from slingloads.models.yaw_dynamics import YawModel

SPAN = np.radians(60.0)

ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]


def linear_model(cn_beta=-0.4, cy_fin=-3.0, span=SPAN, ref=(0.0, 0.0, 0.0)):
    """Fuselage with Cn = cn_beta * beta exactly (other coefficients zero), fin CY linear."""
    beta = np.linspace(-span, span, 25)
    alpha = np.radians([-5.0, 0.0, 5.0])
    coeffs = {k: np.zeros((3, beta.size)) for k in FUSELAGE_COEFFICIENTS}
    coeffs["Cn"] = np.tile(cn_beta * beta, (3, 1))
    fus = FuselageAero(Table2D(alpha, beta, coeffs), 3.0, 11.0, np.array(ref))
    fin = Fin(Table1D(beta, {"CY": cy_fin * beta}), 1.0, np.array([5.0, 0.0, 1.0]), 0.5)
    hp = Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]], chute=[6.0, 0.0, 1.5])
    return YawModel(fus, fin, hp, 9000.0, FlightCondition(80 * KNOT), Parachute(1.0))


def test_neutral_area_by_hand():
    """Paper s.4.1, sum of yaw moments zero: q S L Cn_b - q S_f eta CY_b l_f + q eta_w CD A l_c = 0
    worked by hand with the paper's effective parachute coefficient eta_w CD = 0.95 x 1.0 = 0.95
    (section 3.3: the wake loss counted once): A = -(3 * 11 * (-0.4) - 1 * 0.5 * (-3) * 5) /
    (0.95 * 6) = (13.2 - 7.5) / 5.7 = 1.0 m^2 (q cancels)."""
    result = neutral_area(linear_model())
    assert result.area == pytest.approx(5.7 / 5.7, rel=1e-9)
    assert result.derivatives["fuselage"] == pytest.approx(
        FlightCondition(80 * KNOT).dynamic_pressure * 3 * 11 * -0.4, rel=1e-9)
    assert sum(result.derivatives.values()) == pytest.approx(0.0, abs=1e-8)


def test_neutral_area_gives_zero_stiffness():
    """At the neutral area the linearised model's yaw stiffness is zero, and so is the slope at
    beta = 0 of the full nonlinear static moment (central difference, independent of the fit;
    the parachute moment there is l_c q eta_w CD A sin(beta), whose slope at 0 is exact)."""
    model = linear_model()
    area = neutral_area(model).area
    assert linear_yaw(model, area).stiffness == pytest.approx(0.0, abs=1e-8)
    h = np.radians(0.01)
    plus = sum(model.static_moments(h, area))
    minus = sum(model.static_moments(-h, area))
    scale = model.condition.dynamic_pressure * 3 * 11 * 0.4
    assert (plus - minus) / (2 * h) == pytest.approx(0.0, abs=1e-6 * scale)


def test_side_force_transfer_to_suspension_axis():
    """Moment transfer M_axis = M_ref + (r_ref - r_hub) x F: a pure side force CY at a moment
    reference 1 m aft of the hub adds N = -dx * q S CY (nose right positive), by hand. The
    table is in body axes (CX, CY, CZ), so CY is exactly the force along +y."""
    beta = np.linspace(-0.5, 0.5, 11)
    alpha = np.array([-0.1, 0.1])
    coeffs = {k: np.zeros((2, beta.size)) for k in ("CX", "CY", "CZ", "Cl", "Cm", "Cn")}
    coeffs["CY"] = np.tile(-2.0 * beta, (2, 1))
    fus = FuselageAero(Table2D(alpha, beta, coeffs), 3.0, 11.0, np.array([1.0, 0.0, 0.0]),
                       force_axes="body")
    hp = Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]])
    model = YawModel(fus, None, hp, 9000.0)
    n_fus, _, _ = model.static_moments(np.array([0.2]))
    q = model.condition.dynamic_pressure
    assert float(n_fus[0]) == pytest.approx(-1.0 * q * 3.0 * (-2.0 * 0.2))


def test_sample_neutral_area_from_raw_csv():
    """Independent recomputation for HC1 from the CSV file with pandas and np.polyfit: fuselage
    Cn about the hub axis is Cn - dx_ref F_y / L at alpha 0 with the body-axis side force
    F_y = CY cos beta - CD sin beta of the wind-axes table (SAMPLE_DATA.md), fin Cn = -eta CY;
    least squares over +-10 deg; area = -(q S L n_b + q S_f l_f (-eta) y_b) / (q eta_w CD l_c).
    The local area: the same with the central differences of the raw tables over their
    breakpoints at +-2 deg (the slope at zero sideslip); the area used is the larger."""
    ref = sample_reference("HC1")
    raw = pd.read_csv(ROOT / "slingloads" / "data" / "hc1_fuselage.csv")
    raw = raw[(raw["alpha [deg]"] == 0) & (raw["beta [deg]"].abs() <= 10)]
    b = np.radians(raw["beta [deg]"].to_numpy())
    dx_ref = ref.moment_reference[0] - ref.hub[0]
    side = raw["CY"] * np.cos(b) - raw["CD"] * np.sin(b)
    cn = raw["Cn"] - dx_ref * side / ref.fuselage_length
    n_b = np.polyfit(b, cn, 1)[0]
    fin = pd.read_csv(ROOT / "slingloads" / "data" / "hc1_fin.csv")
    fin = fin[fin["beta [deg]"].abs() <= 10]
    y_b = np.polyfit(np.radians(fin["beta [deg]"]), fin["CY"], 1)[0]
    l_f = ref.fin_centre_of_pressure[0] - ref.hub[0]
    l_c = ref.chute[0] - ref.hub[0]
    expected = -(ref.fuselage_area * ref.fuselage_length * n_b
                 - ref.fin_area * 0.5 * y_b * l_f) / (0.95 * l_c)
    model = YawModel(sample_fuselage("HC1"), sample_fin("HC1"), sample_hardpoints("HC1"),
                     ref.yaw_inertia, parachute=Parachute(1.0))
    result = neutral_area(model)
    assert result.area_fit == pytest.approx(expected, rel=1e-9)
    # local slopes: central differences over the breakpoints -2, 0, +2 deg
    at = {round(float(np.degrees(x))): v for x, v in zip(b, cn, strict=True)}
    n_b0 = (at[2] - at[-2]) / np.radians(4.0)
    fin_at = dict(zip(fin["beta [deg]"].round().astype(int), fin["CY"], strict=True))
    y_b0 = (fin_at[2] - fin_at[-2]) / np.radians(4.0)
    local = -(ref.fuselage_area * ref.fuselage_length * n_b0
              - ref.fin_area * 0.5 * y_b0 * l_f) / (0.95 * l_c)
    assert result.area_local == pytest.approx(local, rel=1e-9)
    assert result.area == max(result.area_fit, result.area_local) and result.area > 0
    assert result.basis == ("local" if local > expected else "fit")
    assert neutral_area(model, basis="fit").area == pytest.approx(expected, rel=1e-9)
    frame = result.to_frame()
    assert list(frame["component"]) == ["fuselage", "fin", "parachute", "total"]
    curves = result.curves_frame()
    parts = curves["N fuselage [N m]"] + curves["N fin [N m]"] + curves["N parachute [N m]"]
    assert np.allclose(parts, curves["N total [N m]"])


def test_already_stable_configuration():
    """A stabilising fuselage (dCn/dbeta > 0) needs no parachute: the neutral area is negative
    and the sweep refuses to run from it."""
    model = linear_model(cn_beta=+0.2)
    result = neutral_area(model)
    assert result.already_stable and result.area < 0
    with pytest.raises(InputError, match="already statically stable"):
        sizing_sweep(model)


def test_bad_static_input():
    """A parachute attached ahead of the axis cannot stabilise; a reversed fit range is
    refused; beta outside the tables is refused with the angle echoed."""
    m = linear_model()
    hp = Hardpoints(hub=[0.0, 0.0, 1.0], mast_feet=[[0.0, 0.0, 0.5]], chute=[-2.0, 0.0, 1.0])
    ahead = YawModel(m.fuselage, m.fin, hp, 9000.0, parachute=Parachute(1.0))
    with pytest.raises(InputError, match=r"aft of the suspension axis.*-2"):
        neutral_area(ahead)
    with pytest.raises(InputError, match="fit range"):
        neutral_area(m, fit_range=(0.2, -0.2))
    with pytest.raises(InputError, match="beta = 70 deg is outside"):
        m.static_moments(np.radians(70.0))


def test_neutral_area_about_a_tilted_axis_by_hand():
    """Moments about the suspension axis a = (sin t, 0, cos t), t = 20 deg, through the hub
    (0, 0, 1), worked by hand: the fuselage's airframe moment q S L (-Cl, Cm, -Cn) gives
    N = -a . M = q S L (a_x Cl_b + a_z Cn_b) beta; the fin (cp 5 m aft of the hub, level with
    it) and the parachute (6 m aft, 0.5 m above) have the arms dx = a_z r_x - a_x r_z, so
    A = -(S L (sin t Cl_b + cos t Cn_b) - S_f eta CY_b 5 cos t) / (eta_w CD (6 cos t
    - 0.5 sin t)) = 8.7422 / 5.1938 = 1.6832 m^2 with Cl_b = -0.3, Cn_b = -0.4, S L = 33,
    S_f eta CY_b = -1.5; and about airframe z (t = 0) the Cl term drops out (A = 1.0 m^2,
    test_neutral_area_by_hand)."""
    t = np.radians(20.0)
    base = linear_model()
    table = base.fuselage.table
    coeffs = dict(table.coefficients)
    coeffs["Cl"] = -0.3 * np.tile(table.beta, (table.alpha.size, 1))
    fus = FuselageAero(Table2D(table.alpha, table.beta, coeffs), 3.0, 11.0, np.zeros(3))
    axis = np.array([np.sin(t), 0.0, np.cos(t)])
    model = YawModel(fus, base.fin, base.hardpoints, 9000.0, base.condition, base.parachute,
                     axis=axis)
    expected = -(33 * (np.sin(t) * -0.3 + np.cos(t) * -0.4) - (-1.5) * 5 * np.cos(t)) / (
        0.95 * (6 * np.cos(t) - 0.5 * np.sin(t)))
    assert expected == pytest.approx(1.6832, abs=1e-4)
    assert neutral_area(model).area == pytest.approx(expected, rel=1e-9)
    assert model.chute_arm[0] == pytest.approx(6 * np.cos(t) - 0.5 * np.sin(t), rel=1e-12)
    assert np.degrees(model.axis_tilt) == pytest.approx(20.0, rel=1e-12)
    level = YawModel(fus, base.fin, base.hardpoints, 9000.0, base.condition, base.parachute)
    assert neutral_area(level).area == pytest.approx(1.0, rel=1e-9)


def test_a_suspension_axis_must_point_up():
    """An axis without an upward component (or not a finite 3-vector) is refused, echoing it."""
    base = linear_model()
    for bad in ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [np.nan, 0.0, 1.0], [0.0, 1.0]):
        with pytest.raises(InputError, match="suspension axis"):
            YawModel(base.fuselage, None, base.hardpoints, 9000.0, axis=bad)


def test_yaw_inertia_about_a_tilted_line_is_the_sum_over_point_masses():
    """hanging_yaw_inertia about a line through the hub that misses the CG equals the direct
    sum m_i |r_i - (r_i . a) a|^2 over a cloud of point masses (r_i from the hub): the
    parallel-axis term is counted; about the hub-CG line no mass is needed."""
    from slingloads.models.airframe import hanging_yaw_inertia

    rng = np.random.default_rng(7)
    masses = rng.uniform(10.0, 100.0, 12)
    points = rng.normal(0.0, 1.5, (12, 3))
    cg = masses @ points / masses.sum()
    d = points - cg
    inertia_cg = np.einsum("i,ijk->jk", masses, np.einsum("ij,ij->i", d, d)[:, None, None]
                           * np.eye(3) - np.einsum("ij,ik->ijk", d, d))
    hub = cg + np.array([0.4, 0.1, 1.2])
    axis = np.array([0.3, -0.05, 0.95])
    a = axis / np.linalg.norm(axis)
    rel = points - hub
    direct = float(masses @ np.sum((rel - np.outer(rel @ a, a)) ** 2, axis=1))
    got = hanging_yaw_inertia(inertia_cg, cg, hub, axis, masses.sum())
    assert got == pytest.approx(direct, rel=1e-12)
    with pytest.raises(InputError, match="give the mass"):
        hanging_yaw_inertia(inertia_cg, cg, hub, axis)
    k = (hub - cg) / np.linalg.norm(hub - cg)
    on_line = float(masses @ np.sum((rel - np.outer(rel @ k, k)) ** 2, axis=1))
    assert hanging_yaw_inertia(inertia_cg, cg, hub) == pytest.approx(on_line, rel=1e-12)

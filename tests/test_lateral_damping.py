"""Aerodynamic damping of the lateral swing and roll from the fuselage and fin tables.

References: the quasi-steady side-force derivative (Etkin and Reid, Dynamics of Flight,
ch. 5): a lateral speed v at true airspeed V is a sideslip v/V, so a side force
q dY/dbeta v/V = -1/2 rho V |dY/dbeta| v; hand calculations below.
"""

import numpy as np
import pytest

from slingloads.analyses.lateral import ParameterRanges, lateral_study
from slingloads.analyses.lateral_damping import (
    LateralDamping,
    aerodynamic_damping,
    combine_dampers,
)
from slingloads.constants import FOOT, G0, KNOT
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D, Table2D
from slingloads.models.aerodynamics import Fin, FuselageAero, fuselage_columns
from slingloads.models.carrier_motion import QuinticStep
from slingloads.models.flight import FlightCondition
from slingloads.models.integration import SolverSettings
from slingloads.models.pendulum import SlungBody

HUB = np.array([0.0, 0.0, 1.0])
MAST = np.array([0.0, 0.0, 1.0])


def linear_aircraft():
    """Fuselage with body-axes CY = -0.4 beta and Cl = -0.05 beta only (S = 3 m^2,
    L = 10 m, reference 0.5 m below the hub); fin CY = -3 beta (1 m^2, eta 0.5, centre of
    pressure 1 m above the hub)."""
    beta = np.radians(np.linspace(-30.0, 30.0, 13))
    alpha = np.radians([-5.0, 0.0, 5.0])
    coeffs = {k: np.zeros((3, beta.size)) for k in fuselage_columns("body")}
    coeffs["CY"] = np.tile(-0.4 * beta, (3, 1))
    coeffs["Cl"] = np.tile(-0.05 * beta, (3, 1))
    fuselage = FuselageAero(Table2D(alpha, beta, coeffs), 3.0, 10.0, [0.0, 0.0, 0.5],
                            force_axes="body")
    fin = Fin(Table1D(beta, {"CY": -3.0 * beta}), 1.0, [5.0, 0.0, 2.0], 0.5)
    return fuselage, fin


def test_damping_from_linear_tables_by_hand():
    """80 KEAS at sea level: 1/2 rho V = 0.5 x 1.225 x 41.1556 = 25.208 kg/m^2/s.
    Fuselage: dY/dbeta per q = S CY_beta = -1.2 m^2, so c = 30.250 N s/m; its rolling moment
    M_x = -q S L Cl puts the side force z = -dMx/dY = L Cl_beta / CY_beta = 1.25 m above the
    reference, i.e. 0.75 m above the hub (d = -0.75 m). Fin: S eta CY_beta = -1.5 m^2, so
    c = 37.812 N s/m at its centre of pressure, d = -1 m. One damper c = 68.062 N s/m at
    d = (30.25 x -0.75 + 37.81 x -1)/68.06 = -0.8889 m, and the roll damping of two dampers
    about their common point, c_r = c1 c2/(c1 + c2) (d1 - d2)^2 = 1.0502 N m s/rad."""
    fuselage, fin = linear_aircraft()
    damping = aerodynamic_damping(FlightCondition(80 * KNOT), HUB, MAST, fuselage, fin)
    k = 0.5 * 1.225 * 80 * KNOT
    c_fus, c_fin = 1.2 * k, 1.5 * k
    assert dict((n, c) for n, c, _ in damping.parts) == pytest.approx(
        {"fuselage": c_fus, "fin": c_fin}, rel=1e-6)   # ISA sea-level density to 1e-6
    assert dict((n, d) for n, _, d in damping.parts) == pytest.approx(
        {"fuselage": -0.75, "fin": -1.0}, rel=1e-9)
    assert damping.lateral == pytest.approx(c_fus + c_fin, rel=1e-6)
    assert damping.below_hub == pytest.approx((-0.75 * c_fus - c_fin) / (c_fus + c_fin),
                                              rel=1e-9)
    assert damping.roll == pytest.approx(c_fus * c_fin / (c_fus + c_fin) * 0.25**2, rel=1e-6)
    assert damping.height_above_cg(1.2) == pytest.approx(1.2 - damping.below_hub)


def test_no_linear_damping_in_hover():
    """Hover: no free stream, so the derivatives' damping 1/2 rho V |dY/dbeta| is zero."""
    fuselage, fin = linear_aircraft()
    damping = aerodynamic_damping(FlightCondition(0.0), HUB, MAST, fuselage, fin)
    assert damping.off and damping.below_hub is None and "hover" in damping.note


def test_combining_dampers_keeps_the_roll_damping_independent_of_the_origin():
    """c_r = sum c_i d_i^2 - c d^2 is the same whatever point the distances are measured
    from (shift all d_i by 3 m: c and c_r unchanged, d shifted by 3 m)."""
    parts = [("a", 10.0, 0.5), ("b", 30.0, -1.5), ("c", 5.0, 2.0)]
    c, d, roll = combine_dampers(parts)
    c2, d2, roll2 = combine_dampers([(n, ci, di + 3.0) for n, ci, di in parts])
    assert (c2, d2, roll2) == (pytest.approx(c), pytest.approx(d + 3.0), pytest.approx(roll))


def test_study_applies_the_damping_to_every_variant():
    """The damped point is fixed on the airframe (d below the hub): each body variant of the
    study's ranges gets the damping at h = e - d above its own CG, with the same c and c_r;
    at hover the aerodynamic damping is zero and the study equals the undamped one."""
    fuselage, fin = linear_aircraft()
    body = SlungBody(2900.0, 1800.0, 1.0)
    motion = [QuinticStep.from_peak_acceleration(0.3 * G0, 2.0)]
    solver = SolverSettings(t_end=6.0, step=0.01)
    forward = aerodynamic_damping(FlightCondition(60 * KNOT), HUB, MAST, fuselage, fin)
    study = lateral_study([body], [18 * FOOT], motion, margin=1.0, damping=forward,
                          ranges=ParameterRanges(points=3), solver=solver)
    for p in study.pendulums:
        assert p.lateral_damping == forward.lateral and p.roll_damping == forward.roll
        assert p.damping_height == pytest.approx(p.body.cg_below_hub - forward.below_hub)
    hover = aerodynamic_damping(FlightCondition(0.0), HUB, MAST, fuselage, fin)
    nominal = ParameterRanges.nominal()
    assert (lateral_study([body], [18 * FOOT], motion, margin=1.0, damping=hover,
                          ranges=nominal, solver=solver).max_load_angle
            == lateral_study([body], [18 * FOOT], motion, margin=1.0, ranges=nominal,
                             solver=solver).max_load_angle)


def test_bad_damping_input():
    """Negative damping and a condition that is not a FlightCondition are refused."""
    with pytest.raises(InputError, match=r"lateral damping must be >= 0.*-1"):
        LateralDamping(-1.0)
    with pytest.raises(InputError, match="FlightCondition"):
        aerodynamic_damping(80.0, HUB, MAST)

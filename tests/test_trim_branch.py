"""The towed trim's branch (``slingloads.analyses.multibody.trim``, module notes "Branch").

On the GENERIC sample HC1 with its drogue, at 100 KEAS and the campaign's minimum mass
(2,300 kg) and 0.91 m^2 of drogue, the equations also hold with the helicopter upside down and
tail first (Euler yaw 180, roll 180 deg), and the batched Newton iterations of the campaign's
runs reached that equilibrium from the hanging guess: its runs left the fuselage table within
2 s ("outside domain") while the neighbouring areas flew. Checked against: continuation (the
trim reached step by step from a neighbouring converged trim in area and in airspeed, from
40 KEAS where the body hangs nearly level), the equations' own residual, and a moment balance
about the hub written here by hand from the loads the trim reports.
"""

import numpy as np
import pytest
from scipy.optimize import root

from slingloads.analyses.campaign.setup import scaled_body
from slingloads.analyses.multibody import trim
from slingloads.analyses.multibody.trim import TRIM_TOLERANCE, _TrimProblem, trim_many
from slingloads.constants import FOOT, KNOT
from slingloads.models.multibody import Cable, HingedParachute, SlingSystem
from slingloads.models.multibody.rigid_body import rotation_matrix
from slingloads.models.parachute import Parachute, extended_cd_table
from slingloads.models.sample_aircraft import (
    sample_body,
    sample_fuselage,
    sample_hardpoints,
    sample_surfaces,
)

AREA = 0.91          # the drogue at which the batched trim found the other branch [m^2]
MASS = 2300.0        # the campaign's minimum mass case [kg]


def system(area=AREA, airspeed=100 * KNOT, mass=MASS):
    chute = HingedParachute(Parachute(area, extended_cd_table(), line_length=10.1))
    return SlingSystem(scaled_body(sample_body("HC1"), mass), sample_hardpoints("HC1"),
                       Cable(60 * FOOT, 5e6), sample_fuselage("HC1"), sample_surfaces("HC1"),
                       chute, airspeed=airspeed, name="HC1")


def unknowns(point):
    """(yaw, pitch, roll, line theta, line psi) of a trim. [rad]"""
    return np.array([*point.attitude, *point.state[16:18]])


def test_batched_and_single_trims_agree_on_the_upright_branch():
    """trim_many (the campaign's runs) and trim (its linear verdicts) give one equilibrium:
    mast up, heading on the flight path, the line trailing aft (theta within 90 deg)."""
    areas = (0.82, AREA, 1.0)
    batched = trim_many([(system(a), None, (0.0, 0.0, 0.0)) for a in areas])
    for area, b in zip(areas, batched, strict=True):
        single = trim(system(area))
        assert b.converged and single.converged, (b.message, single.message)
        assert unknowns(b) == pytest.approx(unknowns(single), abs=1e-7)
        assert rotation_matrix(b.state[9:13])[2, 2] > 0.8          # mast within 37 deg
        assert abs(b.quantity("beta")) < 1e-6
        assert abs(b.line_angles[0]) < np.radians(90.0)


def test_continuation_over_area_and_airspeed_lands_on_the_default_trim():
    """The trim continued from its neighbours (1.8 and 2.2 x 0.455 m^2 at 100 KEAS; 40 to
    100 KEAS in 10 kt steps, each started from the last, at 0.91 m^2) is the default one."""
    default = trim(system())
    assert default.converged
    for neighbour in (system(0.82), system(1.0)):
        continued = trim(system(), start=trim(neighbour))
        assert continued.converged
        assert unknowns(continued) == pytest.approx(unknowns(default), abs=1e-7)
    point = trim(system(airspeed=40 * KNOT))
    assert abs(point.attitude[1]) < np.radians(5.0)          # nearly level at 40 KEAS
    for v in range(50, 101, 10):
        point = trim(system(airspeed=v * KNOT), start=point)
        assert point.converged, (v, point.message)
    assert unknowns(point) == pytest.approx(unknowns(default), abs=1e-7)
    assert default.residual <= TRIM_TOLERANCE


def test_moment_balance_about_the_hub_by_hand():
    """At trim the moments about the hub (where the cable acts) of the weight, the fuselage's
    loads, the fin's normal force and the parachute line's pull sum to zero
    (hand statics in body axes: r x F about the hub), within 1e-6 of the weight times the
    hub's height above the CG."""
    s = system()
    point = trim(s)
    info = {name: point.quantity(name) for name in (
        "fus_fx", "fus_fy", "fus_fz", "fus_mx", "fus_my", "fus_mz", "fin_force",
        "tail_force", "line_tension", "line_x", "line_y", "line_z")}
    cg = s.body.cg
    hub = s.hardpoints.hub - cg
    fin = s.fin.centre_of_pressure - cg
    assert s.tail is None and info["tail_force"] == 0.0   # the transport has no tailplane
    chute = s.hardpoints.chute - cg
    r = rotation_matrix(point.state[9:13])           # body to earth, earth z up
    weight = r.T @ np.array([0.0, 0.0, -s.body.mass * s.gravity])
    fuselage = np.array([info["fus_fx"], info["fus_fy"], info["fus_fz"]])
    line = info["line_tension"] * np.array([info["line_x"], info["line_y"], info["line_z"]])
    moment = (np.array([info["fus_mx"], info["fus_my"], info["fus_mz"]])  # about the CG
              - np.cross(hub, fuselage)
              + np.cross(fin - hub, [0.0, info["fin_force"], 0.0])
              + np.cross(-hub, weight)
              + np.cross(chute - hub, line))
    scale = s.body.mass * s.gravity * np.linalg.norm(hub)
    assert np.all(np.abs(moment) < 1e-6 * scale), moment / scale
    # the two large terms the pitch balance is made of are not zero themselves
    assert abs(info["fus_my"]) > 1e-3 * scale


def test_the_inverted_tail_first_equilibrium_exists_and_is_refused():
    """The other branch is an equilibrium of the equations (residual ~ 0 from the inverted,
    tail-first attitude) with the mast pointing down; the trim refuses it with its reason."""
    problem = _TrimProblem(system(), None, (0.0, 0.0, 0.0), 0.0)
    guess = problem.hanging.copy()
    guess[3], guess[5] = np.pi, np.pi              # yaw 180, roll 180 deg
    guess[6] = np.pi                               # the line along the flow (forward)
    found = root(lambda u: problem.scaled(
        _rates(problem, u))[0], guess, method="hybr", options={"xtol": 1e-13})
    x = problem.state(found.x)
    assert np.max(np.abs(problem.scaled(_rates(problem, found.x)))) < 1e-8
    assert rotation_matrix(x[9:13])[2, 2] < -0.9
    refused = problem.result(found.x)
    assert not refused.converged
    assert "another branch" in refused.message and "upside down" in refused.message


def _rates(problem, u):
    from slingloads.analyses.multibody.trim import evaluate_state

    dx, _, _ = evaluate_state(problem.system, problem.state(u), problem.drive, problem.params,
                              problem.tables)
    return dx

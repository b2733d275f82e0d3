"""Verification of the loads chain on the closed-form free-free beam (FACTS section 5 and
docs/conventions.md section 2, "Worked sign example").

A uniform beam of weight W and length L (x = 0 nose to x = L tail, on the loads reference
axis) is hung at mid-length by a vertical hook load n W. Inertia relief gives a_z = (n - 1) g0,
so gravity plus inertia is a downward line load n W / L and

    0 <= x < L/2 :  Vz = +n W x / L,          My = +n W x^2 / (2 L)
    L/2 <= x <= L:  Vz = -n W (1 - x / L),     My = +n W (L - x)^2 / (2 L)

peak |Vz| = n W / 2 either side of the hook, peak My = n W L / 8 at the hook, and every load is
zero beyond both ends (free-free closure).

The beam is modelled as N equal point masses m = W / (N g0) at the segment centres
x_i = (i + 1/2) L / N, N even, so the hook station L/2 falls between two masses. At the segment
boundaries x = k L / N the lumped model reproduces the continuous formulas *exactly*:
k masses lie forward, so Vz = k n W / N = n W x / L, and
My = (n W / N) sum_{i<k} (x - x_i) = (n W / N) (k x - (L/N) k^2 / 2) = n W x^2 / (2 L).
The tests therefore check the lumped model at those stations to round-off.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.hook_loads import HookLoadOptions
from slingloads.analyses.loads import LoadsStudy
from slingloads.constants import G0
from slingloads.models.airframe import Airframe, Hardpoints, MassItems


def beam_study(weight, length, n, n_masses, extra_stations=()):
    """Uniform lumped beam hung at mid-length by one mast foot under the hub."""
    x = (np.arange(n_masses) + 0.5) * length / n_masses
    position = np.column_stack([x, np.zeros(n_masses), np.zeros(n_masses)])
    mass = np.full(n_masses, weight / G0 / n_masses)
    # small own inertias so the inertia tensor is regular about x as well
    inertia = np.broadcast_to(1e-3 * np.eye(3), (n_masses, 3, 3)).copy()
    items = MassItems(tuple(f"m{i}" for i in range(n_masses)), mass, position, inertia)
    boundaries = np.arange(n_masses + 1) * length / n_masses
    stations = np.unique(np.concatenate([[-1.0, length + 1.0], boundaries,
                                         np.asarray(extra_stations, float)]))
    hardpoints = Hardpoints(hub=[length / 2, 0.0, 1.0], mast_feet=[[length / 2, 0.0, 0.0]])
    airframe = Airframe(items, stations, hardpoints, name="uniform beam")
    study = LoadsStudy(airframe, hook=HookLoadOptions(nz=n, n_azimuth=0))
    return study, stations


def continuous_beam(weight, length, n, x):
    """The closed form of docs/conventions.md section 2 (Vz, My) on 0 <= x <= L."""
    x = np.asarray(x, float)
    fwd = x < length / 2
    vz = np.where(fwd, n * weight * x / length, -n * weight * (1 - x / length))
    my = np.where(fwd, n * weight * x**2 / (2 * length),
                  n * weight * (length - x) ** 2 / (2 * length))
    return vz, my


def test_worked_sign_example_numbers():
    """docs/conventions.md worked example: W = 1000 N, L = 10 m, n = 2.5.

    By hand: Vz = +n W / 2 = +1250 N just forward of the hook (x = 4.9 m), -1250 N at the
    hook station (x = 5 m, the foot belongs to the forward part) and just aft (5.1 m);
    My = n W L / 8 = 2.5 * 1000 * 10 / 8 = 3125 N m at the hook;
    My = n W x^2 / (2 L) = 2500 * 6.25 / 20 = 781.25 N m at x = 2.5 m and at x = 7.5 m.
    """
    study, stations = beam_study(1000.0, 10.0, 2.5, 20, extra_stations=(4.9, 5.1))
    loads = study.run().loads[0]
    at = {round(float(s), 6): loads[i] for i, s in enumerate(stations)}
    assert at[4.9][2] == pytest.approx(1250.0, rel=1e-12)
    assert at[5.0][2] == pytest.approx(-1250.0, rel=1e-12)
    assert at[5.1][2] == pytest.approx(-1250.0, rel=1e-12)
    assert at[5.0][4] == pytest.approx(3125.0, rel=1e-12)
    assert at[2.5][4] == pytest.approx(781.25, rel=1e-12)
    assert at[7.5][4] == pytest.approx(781.25, rel=1e-12)


@pytest.mark.parametrize(("weight", "length", "n", "n_masses"), [
    (1000.0, 10.0, 2.5, 20),
    (28_000.0, 11.5, 1.0, 8),      # hanging at rest in 1 g
    (5000.0, 4.0, 3.5, 50),
    (1.0, 1.0, 0.3, 2),            # the coarsest even model
])
def test_uniform_beam_matches_closed_form(weight, length, n, n_masses):
    """Lumped beam vs. the continuous closed form at the segment boundaries (exact there,
    see the module docstring), and the FACTS section 5 peaks:
    max Vz = +n W / 2 just forward of the hook (a cut between the last forward mass and the
    hook has N/2 masses of n W / N each forward of it), min Vz = -n W / 2 (at and aft of it),
    max My = n W L / 8 at the hook station L/2; Vx = Vy = Mx = Mz = 0."""
    just_forward = length / 2 - length / (4 * n_masses)  # between last forward mass and hook
    study, stations = beam_study(weight, length, n, n_masses, extra_stations=(just_forward,))
    loads = study.run().loads[0]
    inside = (stations >= 0) & (stations <= length) & (stations != just_forward)
    vz, my = continuous_beam(weight, length, n, stations[inside])
    scale = n * weight * max(length, 1.0)
    assert_allclose(loads[inside, 2], vz, rtol=1e-12, atol=1e-12 * scale)
    assert_allclose(loads[inside, 4], my, rtol=1e-12, atol=1e-12 * scale)
    assert loads[:, 2].max() == pytest.approx(n * weight / 2, rel=1e-12)
    assert loads[:, 2].min() == pytest.approx(-n * weight / 2, rel=1e-12)
    assert loads[:, 4].max() == pytest.approx(n * weight * length / 8, rel=1e-12)
    assert stations[np.argmax(loads[:, 4])] == pytest.approx(length / 2, abs=1e-12)
    assert_allclose(loads[:, [0, 1, 3, 5]], 0.0, atol=1e-12 * scale)


def test_vz_sign_convention_either_side_of_the_hook():
    """docs/conventions.md section 2: forward of the hook Vz > 0 (the aft part holds the
    forward part up), at and aft of the hook Vz < 0; My >= 0 everywhere (hogging)."""
    study, stations = beam_study(1000.0, 10.0, 2.5, 20)
    loads = study.run().loads[0]
    fwd = (stations > 0) & (stations < 5.0)
    aft = (stations >= 5.0) & (stations < 10.0)
    assert np.all(loads[fwd, 2] > 0)
    assert np.all(loads[aft, 2] < 0)
    assert np.all(loads[(stations > 0) & (stations < 10.0), 4] > 0)


@pytest.mark.parametrize("n", [1.0, 2.5])
def test_load_factor_at_cg_equals_hook_factor(n):
    """Inertia relief, docs/conventions.md section 6: with the hook force n W the only
    external load besides gravity, a_z = (n W - W) / m = (n - 1) g0 and
    n_z = (a_z + g0) / g0 = n (hanging at rest, n = 1, gives a = 0 and n_z = +1)."""
    result = beam_study(1000.0, 10.0, n, 20)[0].run()
    assert_allclose(result.load_factor[0], [0.0, 0.0, n], atol=1e-12)
    assert_allclose(result.linear_acceleration[0], [0.0, 0.0, (n - 1) * G0], atol=1e-12)
    assert_allclose(result.angular_acceleration[0], 0.0, atol=1e-12)


def test_zero_internal_loads_beyond_both_ends():
    """Free-free closure (FACTS section 5): a cut forward of the nose has nothing forward of
    it, and a cut aft of the tail has everything forward of it, which is in equilibrium.
    Both give six zero loads; the reported closure residual is round-off too."""
    weight, length, n = 1000.0, 10.0, 2.5
    study, stations = beam_study(weight, length, n, 20)
    result = study.run()
    loads = result.loads[0]
    tol = 1e-12 * n * weight * length
    assert stations[0] < 0 and stations[-1] > length
    assert_allclose(loads[0], 0.0, atol=tol)
    assert_allclose(loads[-1], 0.0, atol=tol)
    assert_allclose(loads[stations == length][0], 0.0, atol=tol)
    assert_allclose(result.residual[0], 0.0, atol=tol)


def test_shear_is_the_slope_of_the_bending_moment():
    """Differential relation of docs/conventions.md section 2: dMy/dx = Vz between point
    loads. On the lumped beam My is piecewise linear, so the difference quotient of My
    between two cuts with no load between them equals Vz there exactly."""
    study, stations = beam_study(1000.0, 10.0, 2.5, 20, extra_stations=(1.1, 1.2, 6.6, 6.7))
    loads = study.run().loads[0]
    for a, b in ((1.1, 1.2), (6.6, 6.7)):
        i, j = int(np.argmin(abs(stations - a))), int(np.argmin(abs(stations - b)))
        slope = (loads[j, 4] - loads[i, 4]) / (stations[j] - stations[i])
        assert slope == pytest.approx(loads[i, 2], rel=1e-9)

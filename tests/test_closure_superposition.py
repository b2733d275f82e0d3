"""Property-based verification of inertia relief, the internal-load definition, superposition
and the RBE3-like load sharing (hypothesis).

References (each test names its own):

* Free-free closure, docs/conventions.md sections 2 and 6, FACTS section 5: applied loads plus
  the inertia loads of the rigid-body acceleration a = sum F / m, I_cg alpha = M_cg are in
  equilibrium, so the internal loads aft of the last point are zero.
* Definition of the internal load, docs/conventions.md section 2:
  V(x_c) = -sum_{x_i <= x_c} F_i, M(x_c) = -sum_{x_i <= x_c} [(r_i - p_c) x F_i + M_i],
  evaluated here by brute force (a Python loop), independently of the vectorised cumsum.
* Free-free internal loads (the compiled pipeline and its numpy twin for small studies:
  gravity and unit inertia responses superposed, accelerations from the applied loads'
  totals) against that definition applied to every load, gravity and inertia loads at the
  mass items included; and the two twins against each other, bit for bit.
* Linearity: every step (resultants, the inertia solve, the inertia loads, the cut sums) is
  linear in the applied loads, so loads(a L1 + b L2) = a loads(L1) + b loads(L2).
* Statics of load transfer, docs/conventions.md section 4: the shared point loads have the
  same resultant force and the same moment about any point as the load they replace.
"""

from unittest import mock

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from slingloads.analyses import sfbm
from slingloads.analyses.inertia_relief import (
    gravity_forces,
    inertia_loads,
    rigid_body_acceleration,
)
from slingloads.analyses.sfbm import closure_residual, free_free_internal_loads, internal_loads
from slingloads.models.airframe import MassItems
from slingloads.models.load_sharing import rigid_share

SETTINGS = settings(max_examples=60, deadline=None)
# Relative round-off allowed against the load scale (largest force x lever arm).
ROUNDOFF = 1e-9


def vec(*shape, bound=1.0):
    """Bounded finite float arrays (no NaN, no subnormals)."""
    return arrays(np.float64, shape, elements=st.floats(-bound, bound, allow_nan=False,
                                                         allow_subnormal=False))


def pos(*shape, lo, hi):
    return arrays(np.float64, shape, elements=st.floats(lo, hi, allow_nan=False,
                                                        allow_subnormal=False))


@st.composite
def mass_items(draw):
    """Random lumped masses in 3-D with physical own inertias.

    Each own inertia is that of a small rigid cloud of 4 sub-masses about its own centre,
    sum mu_j (|q_j|^2 I - q_j q_j^T), plus an isotropic part k I (a solid sphere): a sum of
    physical tensors, so it is symmetric, positive semi-definite and meets the triangle
    inequality of principal moments.
    """
    n = draw(st.integers(1, 7))
    mass = draw(pos(n, lo=1.0, hi=1000.0))
    position = draw(vec(n, 3, bound=5.0))
    offsets = draw(vec(n, 4, 3, bound=0.5))
    weights = draw(pos(n, 4, lo=0.0, hi=1.0))
    gyration = draw(pos(n, lo=0.2, hi=0.8))
    cloud = (np.einsum("nk,nkc,nkc->n", weights, offsets, offsets)[:, None, None] * np.eye(3)
             - np.einsum("nk,nki,nkj->nij", weights, offsets, offsets))
    inertia = cloud * mass[:, None, None] / 4 + (
        0.4 * mass * gyration**2)[:, None, None] * np.eye(3)
    return MassItems(tuple(f"m{i}" for i in range(n)), mass, position, inertia)


@st.composite
def applied_loads(draw, n_points=None, n_cases=None):
    """Random point forces and moments at random points, several cases."""
    p = draw(st.integers(1, 5)) if n_points is None else n_points
    c = draw(st.integers(1, 3)) if n_cases is None else n_cases
    position = draw(vec(p, 3, bound=6.0))
    forces = draw(vec(c, p, 3, bound=1e4))
    moments = draw(vec(c, p, 3, bound=1e4))
    return position, forces, moments


def relieve(items, positions, forces, moments):
    """Applied loads at ``positions`` plus gravity, balanced by inertia relief.

    Returns all points (mass items first) with the total forces and moments, per case.
    """
    c = forces.shape[0]
    n = len(items.mass)
    all_pos = np.concatenate([items.position, positions])
    f = np.concatenate([np.broadcast_to(gravity_forces(items), (c, n, 3)), forces], axis=1)
    m = np.concatenate([np.zeros((c, n, 3)), moments], axis=1)
    accel = rigid_body_acceleration(items, all_pos, f, m)
    f_in, m_in = inertia_loads(items, accel)
    f[:, :n] += f_in
    m[:, :n] += m_in
    return all_pos, f, m


def load_scale(positions, forces, moments, reference):
    """Largest force x largest lever arm about ``reference`` plus largest moment."""
    lever = max(np.abs(positions - reference).max(), 1.0)
    return max(np.abs(forces).max() * lever + np.abs(moments).max(), 1.0)


def brute_force_internal(positions, forces, moments, station_points):
    """docs/conventions.md section 2, literally: loop over cuts and over points."""
    c, s = forces.shape[0], len(station_points)
    out = np.zeros((c, s, 6))
    for k in range(c):
        for j, p_c in enumerate(station_points):
            v = np.zeros(3)
            mom = np.zeros(3)
            for i, r in enumerate(positions):
                if r[0] <= p_c[0]:
                    v -= forces[k, i]
                    mom -= np.cross(r - p_c, forces[k, i]) + moments[k, i]
            out[k, j, :3] = v
            out[k, j, 3:] = mom
    return out


@SETTINGS
@given(mass_items(), applied_loads(), vec(2, bound=1.0))
def test_inertia_relief_closes_free_free(items, loads, axis):
    """Free-free closure (docs/conventions.md sections 2 and 6): with gravity, the applied
    loads and the inertia loads -m_i (a + alpha x (r_i - r_cg)), -I_i alpha, the sum of all
    forces and of all moments about the CG vanishes, and the internal loads at a cut aft of
    every point (and forward of every point) are zero, to round-off of the load scale."""
    positions, forces, moments = loads
    all_pos, f, m = relieve(items, positions, forces, moments)
    scale = load_scale(all_pos, f, m, items.cg)
    residual = closure_residual(all_pos, f, m, items.cg)
    np.testing.assert_allclose(residual, 0.0, atol=ROUNDOFF * scale)
    y0, z0 = axis
    ends = np.array([[all_pos[:, 0].min() - 1.0, y0, z0], [all_pos[:, 0].max() + 1.0, y0, z0]])
    ends_loads = internal_loads(all_pos, f, m, ends)
    np.testing.assert_allclose(ends_loads, 0.0, atol=ROUNDOFF * scale)


@SETTINGS
@given(mass_items(), applied_loads())
def test_load_factor_is_resultant_over_weight(items, loads):
    """docs/conventions.md section 6: n = (a - g) / g0 = sum F_ext / (m g0); the applied
    loads without gravity, summed by hand, give the same load factor."""
    positions, forces, moments = loads
    n = len(items.mass)
    all_pos = np.concatenate([items.position, positions])
    c = forces.shape[0]
    f = np.concatenate([np.broadcast_to(gravity_forces(items), (c, n, 3)), forces], axis=1)
    m = np.concatenate([np.zeros((c, n, 3)), moments], axis=1)
    accel = rigid_body_acceleration(items, all_pos, f, m)
    expected = forces.sum(axis=1) / (items.total_mass * 9.80665)
    np.testing.assert_allclose(accel.load_factor, expected,
                               atol=1e-12 * max(np.abs(expected).max(), 1.0))


@SETTINGS
@given(applied_loads(), st.data())
def test_internal_loads_equal_brute_force_definition(loads, data):
    """The vectorised cumulative sum equals the definition of docs/conventions.md section 2
    evaluated by a loop, including cuts placed exactly at load points (those loads belong to
    the forward part, x_i <= x_c) and cuts forward of / aft of every point."""
    positions, forces, moments = loads
    extra = data.draw(pos(data.draw(st.integers(0, 4)), lo=-7.0, hi=7.0))
    xs = np.unique(np.concatenate([positions[:, 0], extra, [-8.0, 8.0]]))
    y0, z0 = data.draw(vec(2, bound=1.0))
    stations = np.column_stack([xs, np.full(xs.shape, y0), np.full(xs.shape, z0)])
    expected = brute_force_internal(positions, forces, moments, stations)
    got = internal_loads(positions, forces, moments, stations)
    scale = load_scale(positions, forces, moments, stations.mean(axis=0))
    np.testing.assert_allclose(got, expected, atol=1e-12 * scale * len(positions))


def test_internal_loads_point_at_cut_belongs_to_forward_part():
    """Hand example of docs/conventions.md section 2: a single force F = (0, 0, 100) N at
    x = 2 m. Cut at x = 1.999: nothing forward, all zero. Cut at x = 2: the load is forward,
    Vz = -100 N, My = 0 (no lever). Cut at x = 5: (r - p) x F = (-3, 0, 0) x (0, 0, 100)
    = (0, 300, 0), so My = -300 N m."""
    positions = np.array([[2.0, 0.0, 0.0]])
    forces = np.array([[[0.0, 0.0, 100.0]]])
    stations = np.array([[1.999, 0.0, 0.0], [2.0, 0.0, 0.0], [5.0, 0.0, 0.0]])
    out = internal_loads(positions, forces, None, stations)[0]
    np.testing.assert_allclose(out[:, 2], [0.0, -100.0, -100.0], atol=1e-12)
    np.testing.assert_allclose(out[:, 4], [0.0, 0.0, -300.0], atol=1e-12)


def _worked_by(compiled):
    """Force the compiled kernel (``True``) or its numpy twin (``False``) whatever the size."""
    return mock.patch.object(sfbm, "NUMPY_CUTS", -1 if compiled else 10**12)


@SETTINGS
@given(mass_items(), applied_loads(), st.booleans(), vec(3, bound=1.0), st.booleans(),
       st.data())
def test_free_free_internal_loads_equal_definition(items, loads, with_moments, vertical,
                                                   compiled, data):
    """The free-free pipeline (compiled kernel or numpy twin) against docs/conventions.md
    section 2 applied to every load by the brute-force loop: gravity along -vertical and the
    inertia loads -m_j (a + alpha x rho_j), -I_j alpha at each mass item (inertia_loads of
    rigid_body_acceleration, section 6) plus the applied loads, with cuts at load points and
    mass items, forward and aft of everything. Also: the accelerations equal
    rigid_body_acceleration's, the closing residual is zero (free-free closure), the loads are
    written into ``out``, and strided input arrays give the same loads."""
    assume(np.linalg.norm(vertical) > 0.1)
    positions, forces, moments = loads
    moments = moments if with_moments else np.zeros_like(forces)
    n, c = len(items.mass), len(forces)
    extra = data.draw(pos(data.draw(st.integers(0, 4)), lo=-7.0, hi=7.0))
    xs = np.unique(np.concatenate([positions[:, 0], items.position[:, 0], extra, [-8.0, 8.0]]))
    y0, z0 = data.draw(vec(2, bound=1.0))
    stations = np.column_stack([xs, np.full(xs.shape, y0), np.full(xs.shape, z0)])
    all_pos = np.concatenate([items.position, positions])
    f = np.concatenate([np.broadcast_to(gravity_forces(items, vertical), (c, n, 3)), forces],
                       axis=1)
    m = np.concatenate([np.zeros((c, n, 3)), moments], axis=1)
    accel = rigid_body_acceleration(items, all_pos, f, m)
    f_in, m_in = inertia_loads(items, accel)
    f[:, :n] += f_in
    m[:, :n] += m_in
    expected = brute_force_internal(all_pos, f, m, stations)

    strided = np.repeat(forces, 2, axis=1)[:, ::2]     # same values, not contiguous
    out = np.full(expected.shape, np.nan)
    with _worked_by(compiled):
        got, got_accel, residual = free_free_internal_loads(
            items, positions, strided, moments if with_moments else None, stations, vertical,
            out=out)
    scale = load_scale(all_pos, f, m, stations[0])
    assert got is out
    np.testing.assert_allclose(got, expected, atol=ROUNDOFF * scale)
    np.testing.assert_allclose(residual, 0.0, atol=ROUNDOFF * scale)
    a_scale = ROUNDOFF * max(np.abs(accel.linear).max(), np.abs(accel.angular).max(), 1.0)
    np.testing.assert_allclose(got_accel.linear, accel.linear, atol=a_scale)
    np.testing.assert_allclose(got_accel.angular, accel.angular, atol=a_scale)
    np.testing.assert_allclose(got_accel.gravity,
                               -9.80665 * np.asarray(vertical) / np.linalg.norm(vertical),
                               rtol=1e-15, atol=1e-15)


@SETTINGS
@given(mass_items(), applied_loads(), st.booleans(), vec(3, bound=1.0), st.data())
def test_numpy_twin_equals_compiled_kernel_bit_for_bit(items, loads, with_moments, vertical,
                                                       data):
    """The numpy twin of small studies against the compiled kernel: the same operations in the
    same order, so the same loads, accelerations and residuals to the last bit (a study
    changes path with its size only, never its numbers)."""
    assume(np.linalg.norm(vertical) > 0.1)
    positions, forces, moments = loads
    xs = np.unique(np.concatenate([positions[:, 0], items.position[:, 0], [-8.0, 8.0]]))
    y0, z0 = data.draw(vec(2, bound=1.0))
    stations = np.column_stack([xs, np.full(xs.shape, y0), np.full(xs.shape, z0)])
    moments = moments if with_moments else None
    results = []
    for compiled in (True, False):
        with _worked_by(compiled):
            results.append(free_free_internal_loads(items, positions, forces, moments,
                                                    stations, vertical))
    (l1, a1, r1), (l2, a2, r2) = results
    np.testing.assert_array_equal(l1, l2)
    np.testing.assert_array_equal(r1, r2)
    np.testing.assert_array_equal(a1.linear, a2.linear)
    np.testing.assert_array_equal(a1.angular, a2.angular)


def test_small_studies_are_worked_by_numpy_large_ones_compiled():
    """The size rule of free_free_internal_loads: cases x cuts up to NUMPY_CUTS by numpy, above
    it by the compiled kernel (told apart by which of the two is called)."""
    items = MassItems(("a", "b"), np.array([1.0, 2.0]), np.array([[0.0, 0, 0], [1.0, 0, 0]]),
                      np.broadcast_to(np.eye(3), (2, 3, 3)).copy())
    stations = np.array([[0.5, 0.0, 0.0], [2.0, 0.0, 0.0]])
    cuts = len(stations) + 1
    for cases, numpy_expected in ((sfbm.NUMPY_CUTS // cuts, True),
                                  (sfbm.NUMPY_CUTS // cuts + 1, False)):
        forces = np.ones((cases, 1, 3))
        numpy_rows, compiled_rows = mock.Mock(), mock.Mock()
        with mock.patch.object(sfbm, "free_free_rows_numpy", numpy_rows), \
                mock.patch.object(sfbm, "_compiled_rows", return_value=compiled_rows):
            free_free_internal_loads(items, np.zeros((1, 3)), forces, None, stations)
        assert (numpy_rows.called, compiled_rows.called) == (numpy_expected,
                                                             not numpy_expected), cases


def test_free_free_internal_loads_of_no_case():
    """No load case: empty loads, accelerations and residuals of the right shapes."""
    items = MassItems(("a", "b"), np.array([1.0, 2.0]), np.array([[0.0, 0, 0], [1.0, 0, 0]]),
                      np.broadcast_to(np.eye(3), (2, 3, 3)).copy())
    stations = np.array([[0.5, 0.0, 0.0], [2.0, 0.0, 0.0]])
    loads, accel, residual = free_free_internal_loads(
        items, np.zeros((1, 3)), np.zeros((0, 1, 3)), None, stations)
    assert loads.shape == (0, 2, 6) and residual.shape == (0, 6)
    assert accel.linear.shape == accel.angular.shape == (0, 3)


@pytest.mark.parametrize(("forces", "moments"), [
    (np.zeros((2, 1, 3)), None),                      # fewer points than positions
    (np.zeros((2, 2, 3)), np.zeros((1, 2, 3))),       # moments of another case count
])
def test_free_free_internal_loads_refuses_mismatched_shapes(forces, moments):
    """The compiled kernel reads forces and moments by the positions' indices without bounds
    checks: arrays of the wrong shape are refused, the shapes echoed."""
    items = MassItems(("a", "b"), np.array([1.0, 2.0]), np.array([[0.0, 0, 0], [1.0, 0, 0]]),
                      np.broadcast_to(np.eye(3), (2, 3, 3)).copy())
    stations = np.array([[0.5, 0.0, 0.0], [2.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match=r"must have the shape \(cases, points, 3\)"):
        free_free_internal_loads(items, np.zeros((2, 3)), forces, moments, stations)


@SETTINGS
@given(mass_items(), st.integers(1, 4), st.data())
def test_superposition_of_relieved_loads(items, p, data):
    """Linearity of the whole chain (resultants -> inertia relief -> cut sums), here with
    the applied loads only (gravity is an affine term and is left out):
    loads(a L1 + b L2) = a loads(L1) + b loads(L2)."""
    pos1, f1, m1 = data.draw(applied_loads(n_points=p, n_cases=2))
    f2, m2 = data.draw(vec(2, p, 3, bound=1e4)), data.draw(vec(2, p, 3, bound=1e4))
    a, b = data.draw(st.floats(-3, 3)), data.draw(st.floats(-3, 3))
    all_pos = np.concatenate([items.position, pos1])
    n = len(items.mass)
    xs = np.linspace(all_pos[:, 0].min() - 0.5, all_pos[:, 0].max() + 0.5, 9)
    stations = np.column_stack([xs, np.zeros(9), np.zeros(9)])

    def chain(f, m):
        ff = np.concatenate([np.zeros((2, n, 3)), f], axis=1)
        mm = np.concatenate([np.zeros((2, n, 3)), m], axis=1)
        accel = rigid_body_acceleration(items, all_pos, ff, mm)
        fi, mi = inertia_loads(items, accel)
        ff[:, :n] += fi
        mm[:, :n] += mi
        return internal_loads(all_pos, ff, mm, stations)

    combined = chain(a * f1 + b * f2, a * m1 + b * m2)
    separate = a * chain(f1, m1) + b * chain(f2, m2)
    scale = 4 * load_scale(all_pos, np.concatenate([f1, f2]), np.concatenate([m1, m2]),
                           items.cg)
    np.testing.assert_allclose(combined, separate, atol=ROUNDOFF * scale)


def check_resultants(points, weights, force, moment, reference):
    """Share the load and check the statics: same resultant force, same moment about the
    reference point (docs/conventions.md section 4: "Resultants are exact")."""
    pf, pm = rigid_share(points, weights, force, moment, reference)
    lever = points - reference
    total_f = pf.sum(axis=-2)
    total_m = np.cross(lever, pf).sum(axis=-2) + pm.sum(axis=-2)
    f_scale = np.abs(force).max() + np.abs(pf).sum()
    m_scale = (np.abs(moment).max() + np.abs(pm).sum()
               + (np.linalg.norm(lever, axis=-1) * np.linalg.norm(pf, axis=-1)).sum())
    np.testing.assert_allclose(total_f, force, atol=1e-12 * f_scale + 1e-12)
    np.testing.assert_allclose(total_m, moment, atol=1e-10 * m_scale + 1e-12)
    return pf, pm


@SETTINGS
@given(st.integers(3, 6), st.data())
def test_rigid_share_non_collinear_preserves_resultants(k, data):
    """RBE3 statics for points not on one line: resultant force and moment preserved, and
    no point moments (J is regular, every moment is carried by point forces)."""
    points = data.draw(vec(k, 3, bound=3.0))
    centred = points - points.mean(axis=0)
    sv = np.linalg.svd(centred, compute_uv=False)
    assume(sv[1] > 1e-2 * max(sv[0], 1e-300) and sv[0] > 1e-3)
    weights = data.draw(pos(k, lo=0.1, hi=10.0))
    force, moment = data.draw(vec(3, 3, bound=1e4)), data.draw(vec(3, 3, bound=1e4))
    reference = data.draw(vec(3, bound=5.0))
    pf, pm = check_resultants(points, weights, force, moment, reference)
    np.testing.assert_allclose(pm, 0.0, atol=1e-9 * (np.abs(moment).max() + 1.0)
                               * (1.0 + np.abs(force).max()))


@SETTINGS
@given(st.integers(2, 6), st.data())
def test_rigid_share_collinear_preserves_resultants(k, data):
    """Points on one line cannot carry torsion about it by forces; that component goes into
    point moments, and the resultants are still exact. The point moments are along the line
    (the rest of the moment is carried by forces)."""
    p0 = data.draw(vec(3, bound=3.0))
    u = data.draw(vec(3, bound=1.0))
    assume(np.linalg.norm(u) > 0.1)
    u = u / np.linalg.norm(u)
    t = data.draw(pos(k, lo=-3.0, hi=3.0))
    assume(np.ptp(t) > 0.1)
    points = p0 + t[:, None] * u
    weights = data.draw(pos(k, lo=0.1, hi=10.0))
    force, moment = data.draw(vec(2, 3, bound=1e4)), data.draw(vec(2, 3, bound=1e4))
    reference = data.draw(vec(3, bound=5.0))
    pf, pm = check_resultants(points, weights, force, moment, reference)
    across = pm - (pm @ u)[..., None] * u
    np.testing.assert_allclose(across, 0.0, atol=1e-9 * (np.abs(pm).max() + 1.0))


@SETTINGS
@given(vec(1, 3, bound=3.0), pos(1, lo=0.1, hi=10.0), vec(2, 3, bound=1e4),
       vec(2, 3, bound=1e4), vec(3, bound=5.0))
def test_rigid_share_single_point_is_load_transfer(point, weight, force, moment, reference):
    """Single point: the rule reduces to moving a load to a new point (statics by hand):
    F_1 = F and M_1 = M + (r_ref - p_1) x F."""
    pf, pm = check_resultants(point, weight, force, moment, reference)
    np.testing.assert_allclose(pf[:, 0], force, rtol=1e-14, atol=1e-10)
    expected = moment + np.cross(reference - point[0], force)
    np.testing.assert_allclose(pm[:, 0], expected, atol=1e-10 * (np.abs(expected).max() + 1))


def test_rigid_share_four_feet_hand_example():
    """Hand example: four equal feet at (+-1, +-1, 0), a vertical force 100 N at the centre
    (reference (0, 0, 1)) and a pitching moment My = 40 N m. Equal shares give 25 N up each;
    J = sum (|d|^2 I - d d^T) = diag(4, 4, 8); mu = J^-1 M = (0, 10, 0);
    mu x d_i = (0, 10, 0) x (x_i, y_i, 0) = (0, 0, -10 x_i):
    feet at x = +1 get 25 - 10 = 15 N, feet at x = -1 get 35 N.
    Check: moment about y of the feet forces = -sum x_i F_zi = -(2*15 - 2*35) = +40 N m."""
    feet = np.array([[1.0, 1.0, 0.0], [1.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]])
    pf, pm = rigid_share(feet, np.ones(4), np.array([0.0, 0.0, 100.0]),
                         np.array([0.0, 40.0, 0.0]), np.array([0.0, 0.0, 1.0]))
    np.testing.assert_allclose(pf[:, 2], [15.0, 15.0, 35.0, 35.0], atol=1e-12)
    np.testing.assert_allclose(pf[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(pm, 0.0, atol=1e-12)


def test_rigid_share_single_point_with_non_unit_weight_regression():
    """Regression: one point with weight w != 1 has a centroid w p / w that differs from p by
    round-off (here 2.8e-17 m); the J built from that offset was tiny but non-zero and its
    pseudo-inverse gave a vertical foot force of -7.2e19 N for a 2000 N hook load. The
    single-point rule is load transfer (statics by hand): F_1 = F = (1000, 0, 2000) N and
    M_1 = (r_hub - p) x F = (0, 0, 1) x (1000, 0, 2000) = (0, 1000, 0) N m."""
    x, w = -0.12007245715300696, 2.400491904429108
    assert (w * x) / w != x  # the round-off that triggered the bug
    pf, pm = rigid_share([[x, 0.3, 0.0]], [w], [[1000.0, 0.0, 2000.0]], [[0.0, 0.0, 0.0]],
                         [x, 0.3, 1.0])
    np.testing.assert_allclose(pf[0, 0], [1000.0, 0.0, 2000.0], rtol=1e-12)
    np.testing.assert_allclose(pm[0, 0], [0.0, 1000.0, 0.0], rtol=1e-12, atol=1e-9)

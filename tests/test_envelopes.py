"""Verification of load envelopes, convex hulls and the comparison with a previous envelope
(slingloads.analyses.envelopes), on small hand-made arrays whose answers are worked by hand
or computed independently with numpy max/argmax and plane geometry.
"""

import numpy as np
import pandas as pd
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.envelopes import compare_with_previous, convex_hull, envelope_table
from slingloads.analyses.sfbm import COMPONENTS, LOAD_COLUMNS
from slingloads.errors import InputError

CASES = ["LC1", "LC2", "LC3", "LC4"]
STATIONS = np.array([1.0, 2.5])
STATION_IDS = ["FS1", "FS2.5"]


def hand_loads():
    """Four cases x two stations x six components, no ties within a (station, component)."""
    loads = np.empty((4, 2, 6))
    loads[:, 0, :] = [[10.0, -3.0, 7.0, 0.5, -40.0, 12.0],
                      [-2.0, 8.0, -9.0, 1.5, 35.0, -11.0],
                      [4.0, 1.0, 3.0, -2.5, 5.0, 20.0],
                      [6.0, -6.0, -1.0, 0.1, -45.0, 2.0]]
    loads[:, 1, :] = [[1.0, 2.0, 3.0, 4.0, 5.0, 6.0],
                      [-1.0, -2.0, -3.0, -4.0, -5.0, -6.0],
                      [0.5, 9.0, -8.0, 7.5, 0.0, -0.5],
                      [2.0, -7.0, 2.5, -3.5, 11.0, 1.0]]
    return loads


def test_envelope_table_max_min_and_critical_case():
    """For every station and component the envelope's max/min equal numpy max/min over the
    cases and the critical case is the numpy argmax/argmin case; e.g. at FS1, My: values
    (-40, 35, 5, -45) -> max 35 (LC2), min -45 (LC4)."""
    loads = hand_loads()
    table = envelope_table(loads, CASES, STATIONS, STATION_IDS)
    assert len(table) == 2 * 6 * 2
    for s, sid in enumerate(STATION_IDS):
        for k, name in enumerate(COMPONENTS):
            rows = table[(table["station"] == sid) & (table["component"] == name)]
            top = rows[rows["bound"] == "max"].iloc[0]
            low = rows[rows["bound"] == "min"].iloc[0]
            column = "value_Nm" if name.startswith("M") else "value_N"
            assert top[column] == loads[:, s, k].max()
            assert low[column] == loads[:, s, k].min()
            assert top["case"] == CASES[int(np.argmax(loads[:, s, k]))]
            assert low["case"] == CASES[int(np.argmin(loads[:, s, k]))]
            assert top["x_m"] == STATIONS[s]
    my = table[(table["station"] == "FS1") & (table["component"] == "My")].set_index("bound")
    assert (my.loc["max", "value_Nm"], my.loc["max", "case"]) == (35.0, "LC2")
    assert (my.loc["min", "value_Nm"], my.loc["min", "case"]) == (-45.0, "LC4")
    assert np.isnan(my.loc["max", "value_N"])


def test_envelope_correlated_loads_are_the_critical_case_row():
    """Correlated loads are the other five components of the same case at the same station:
    FS1 My max is LC2, so the correlated row is LC2's (-2, 8, -9, 1.5, 35, -11)."""
    loads = hand_loads()
    table = envelope_table(loads, CASES, STATIONS, STATION_IDS)
    row = table[(table["station"] == "FS1") & (table["component"] == "My")
                & (table["bound"] == "max")].iloc[0]
    assert_allclose(row[list(LOAD_COLUMNS)].to_numpy(float),
                    [-2.0, 8.0, -9.0, 1.5, 35.0, -11.0], atol=0)
    for _, r in table.iterrows():
        s = STATION_IDS.index(r["station"])
        c = CASES.index(r["case"])
        assert_allclose(r[list(LOAD_COLUMNS)].to_numpy(float), loads[c, s], atol=0)
        k = COMPONENTS.index(r["component"])
        assert r[LOAD_COLUMNS[k]] == r["value_Nm" if k >= 3 else "value_N"]


def counter_clockwise_area(xy):
    """Shoelace formula: positive for counter-clockwise vertex order."""
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def cloud(points, pair=("Vy", "Mz")):
    """Loads array (c, 1, 6) holding the given 2-D points in the two named components."""
    points = np.asarray(points, float)
    loads = np.zeros((len(points), 1, 6))
    loads[:, 0, COMPONENTS.index(pair[0])] = points[:, 0]
    loads[:, 0, COMPONENTS.index(pair[1])] = points[:, 1]
    return loads


def test_convex_hull_of_square_with_interior_points():
    """Plane geometry: the hull of the square corners (+-2000 N, +-5e4 N m) plus interior
    points (and a point on an edge) is exactly the four corners, with their case ids, in
    counter-clockwise order (shoelace area = +4000 * 1e5 = 4e8)."""
    corners = {"C1": (-2000.0, -5e4), "C2": (2000.0, -5e4), "C3": (2000.0, 5e4),
               "C4": (-2000.0, 5e4)}
    inside = {"I1": (0.0, 0.0), "I2": (1500.0, -4e4), "I3": (-1999.0, 4.9e4),
              "E1": (2000.0, 0.0)}
    ids = ["I1", "C3", "I2", "C1", "E1", "C4", "I3", "C2"]
    pts = {**corners, **inside}
    loads = cloud([pts[i] for i in ids])
    hull = convex_hull(loads, ids, 0, ("Vy", "Mz"))
    assert sorted(hull["case"]) == ["C1", "C2", "C3", "C4"]
    for _, row in hull.iterrows():
        assert (row["Vy_N"], row["Mz_Nm"]) == corners[row["case"]]
    area = counter_clockwise_area(hull[["Vy_N", "Mz_Nm"]].to_numpy(float))
    assert area == pytest.approx(4000.0 * 1e5, rel=1e-12)


def test_convex_hull_of_collinear_cloud_returns_the_two_extremes():
    """Degenerate cloud: points on the line Mz = 3 Vy + 10 at Vy = -4, -1, 0, 2, 7. The hull
    degenerates to the segment between the extreme cases (Vy = -4 and Vy = 7)."""
    vy = np.array([0.0, 7.0, -1.0, -4.0, 2.0])
    ids = ["A", "B", "C", "D", "E"]
    loads = cloud(np.column_stack([vy, 3 * vy + 10]))
    hull = convex_hull(loads, ids, 0, ("Vy", "Mz"))
    assert sorted(hull["case"]) == ["B", "D"]
    got = dict(zip(hull["case"], hull["Vy_N"], strict=True))
    assert got == {"B": 7.0, "D": -4.0}


def test_convex_hull_of_vertical_line_and_single_point():
    """Degenerate clouds along one axis (Vy constant) and a single repeated point: the two
    extremes of the line, and the one point."""
    loads = cloud([[1.0, 5.0], [1.0, -2.0], [1.0, 9.0]])
    hull = convex_hull(loads, ["a", "b", "c"], 0, ("Vy", "Mz"))
    assert sorted(hull["case"]) == ["b", "c"]
    same = cloud([[3.0, 4.0], [3.0, 4.0]])
    hull = convex_hull(same, ["p", "q"], 0, ("Vy", "Mz"))
    assert len(hull) == 1 and (hull["Vy_N"].iloc[0], hull["Mz_Nm"].iloc[0]) == (3.0, 4.0)


def test_convex_hull_rejects_unknown_component():
    """Rule: hull components are among Vx, Vy, Vz, Mx, My, Mz; an unknown one is refused."""
    with pytest.raises(InputError, match="'Vq'"):
        convex_hull(cloud([[0, 0], [1, 0], [0, 1]]), ["a", "b", "c"], 0, ("Vq", "Mz"))


def previous_envelope():
    """Previous design envelope at x = 0 and x = 10 m: +-100 for every component, except Mx
    whose max grows linearly from 100 at x = 0 to 200 at x = 10 (150 at x = 5 by hand)."""
    rows = []
    for name in COMPONENTS:
        for x in (0.0, 10.0):
            top = 100.0 + 10.0 * x if name == "Mx" else 100.0
            rows.append({"x [m]": x, "component": name, "min": -100.0, "max": top})
    return pd.DataFrame(rows)


def test_compare_with_previous_hand_numbers():
    """Exceedance ratio max(new_max+ / prev_max+, |new_min-| / |prev_min-|) by hand at x = 5:
    Vx 120 / 100 = 1.2 flagged; Vy 80 / 100 = 0.8 within; Vz |-120| / 100 = 1.2 flagged
    (negative side); Mx 120 / 150 = 0.8 within (previous max interpolated);
    My, Mz 0 -> ratio 0 within. At x = 12 m, outside the previous range [0, 10] m, every
    component is 'not covered', never flagged, even with loads of 1000."""
    stations = np.array([5.0, 12.0])
    loads = np.zeros((2, 2, 6))
    loads[0, 0, :4] = [120.0, 80.0, 30.0, 120.0]
    loads[1, 0, :4] = [-10.0, -50.0, -120.0, 0.0]
    loads[:, 1, :] = 1000.0
    out = compare_with_previous(loads, stations, ["S5", "S12"], previous_envelope())
    s5 = out[out["station"] == "S5"].set_index("component")
    expected_ratio = {"Vx": 1.2, "Vy": 0.8, "Vz": 1.2, "Mx": 0.8, "My": 0.0, "Mz": 0.0}
    for name, ratio in expected_ratio.items():
        assert s5.loc[name, "exceedance ratio"] == pytest.approx(ratio, rel=1e-12)
        assert bool(s5.loc[name, "exceeds"]) == (ratio > 1)
        assert s5.loc[name, "status"] == ("EXCEEDS previous envelope" if ratio > 1
                                          else "within")
    assert s5.loc["Mx", "previous max"] == pytest.approx(150.0, rel=1e-12)
    assert s5.loc["Vz", "new min"] == -120.0
    s12 = out[out["station"] == "S12"]
    assert len(s12) == 6
    assert (s12["status"] == "not covered by previous envelope").all()
    assert not s12["exceeds"].any()
    assert s12["exceedance ratio"].isna().all()


def test_compare_with_previous_exactly_equal_is_not_an_exceedance():
    """Boundary: new max equal to the previous one gives ratio 1.0, which is not > 1."""
    loads = np.zeros((1, 1, 6))
    loads[0, 0, 2] = 100.0
    out = compare_with_previous(loads, np.array([5.0]), ["S5"], previous_envelope())
    vz = out.set_index("component").loc["Vz"]
    assert vz["exceedance ratio"] == pytest.approx(1.0, rel=1e-15)
    assert not vz["exceeds"]


@pytest.mark.parametrize("shape", ["gaussian", "disc", "circle", "square grid", "thin"])
def test_convex_hull_matches_qhull(shape):
    """Reference: scipy.spatial.ConvexHull (Qhull) on clouds of 2000 cases of loads of very
    different magnitudes (N against N m): the same vertex cases, counter-clockwise (positive
    shoelace area equal to Qhull's hull area), starting from the case of smallest Vy."""
    from scipy.spatial import ConvexHull

    rng = np.random.default_rng(len(shape))
    n = 2000
    if shape == "gaussian":
        pts = rng.normal(size=(n, 2))
    elif shape == "disc":
        r, a = np.sqrt(rng.uniform(size=n)), rng.uniform(0, 2 * np.pi, n)
        pts = np.column_stack([r * np.cos(a), r * np.sin(a)])
    elif shape == "circle":  # every case a vertex (hook-load directions on a cone)
        a = np.sort(rng.uniform(0, 2 * np.pi, 500))
        pts = np.column_stack([np.cos(a), np.sin(a)])
    elif shape == "square grid":  # many cases on the edges, which are not vertices
        g = np.arange(-10.0, 11.0)
        pts = np.array([(x, y) for x in g for y in g])
    else:
        pts = np.column_stack([rng.uniform(-1, 1, n), 1e-3 * rng.normal(size=n)])
    pts = pts * [3000.0, 8.0e4] + [500.0, -2.0e4]
    ids = [f"LC{k:04d}" for k in range(len(pts))]
    hull = convex_hull(cloud(pts), ids, 0, ("Vy", "Mz"))
    qhull = ConvexHull(pts)
    assert sorted(hull["case"]) == sorted(ids[k] for k in qhull.vertices)
    xy = hull[["Vy_N", "Mz_Nm"]].to_numpy(float)
    assert counter_clockwise_area(xy) == pytest.approx(qhull.volume, rel=1e-12)
    assert xy[0, 0] == pts[:, 0].min()

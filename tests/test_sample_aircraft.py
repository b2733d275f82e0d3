"""GENERIC sample aircraft HC1 and HC2: physical shape of the tables and their provenance.

References: the project's reference facts, section 3 (helicopter fuselages directionally
unstable alone, fin stabilising; UH-60-class magnitudes), and slingloads/data/SAMPLE_DATA.md.
"""

import runpy
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from numpy.testing import assert_allclose

from slingloads.errors import InputError
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)

ROOT = Path(__file__).resolve().parents[1]
NAMES = ["HC1", "HC2"]


@pytest.mark.parametrize("name", NAMES)
def test_symmetry_of_fuselage_table(name):
    """A left-right symmetric fuselage: CY, Cl, Cn odd in beta; CD, CL, Cm even in beta."""
    t = sample_fuselage(name).table
    c = t.coefficients
    assert_allclose(t.beta, -t.beta[::-1], atol=1e-12)
    for key in ("CY", "Cl", "Cn"):
        assert_allclose(c[key], -c[key][:, ::-1], atol=1e-6)
    for key in ("CD", "CL", "Cm"):
        assert_allclose(c[key], c[key][:, ::-1], atol=1e-6)


@pytest.mark.parametrize("name", NAMES)
def test_fuselage_is_directionally_unstable_and_recovers_at_45(name):
    """Facts s.3: fuselage alone unstable (dCn/dbeta < 0 at beta 0), Cn back to ~0 near 45 deg;
    the drag (wind axes) rises with |beta| up to 60 deg and is larger broadside than head-on;
    CL and Cm mainly functions of alpha."""
    f = sample_fuselage(name)
    for alpha in np.radians([-10.0, 0.0, 10.0]):
        slope, _ = f.table.slope("Cn", alpha, -np.radians(4), np.radians(4))
        assert slope < 0
    assert abs(float(f.table("Cn", 0.0, np.radians(45.0)))) < 1e-6
    cd = f.table.beta_slice("CD", 0.0)
    rising = (f.table.beta >= 0) & (f.table.beta <= np.radians(60.0))
    assert np.all(np.diff(cd[rising]) > 0)
    assert cd[np.isclose(f.table.beta, np.pi / 2)][0] > 5 * cd[f.table.beta == 0][0]
    cl_alpha = f.table("CL", np.radians(10.0), 0.0) - f.table("CL", np.radians(-10.0), 0.0)
    cl_beta = f.table("CL", 0.0, np.radians(10.0)) - f.table("CL", 0.0, 0.0)
    assert abs(cl_alpha) > 5 * abs(cl_beta)


@pytest.mark.parametrize("name", NAMES)
def test_magnitudes_of_order_of_uh60_class(name):
    """Facts s.3: |lateral force| about 0.2 / 0.4 / 0.85 and |Cn| about 0.03 / 0.06 / 0.08 at
    beta 5 / 10 / 20 deg; accepted within a factor 1.6 (generic data, scaled). The tables are
    in wind axes (SAMPLE_DATA.md), so the body-axis lateral force is CY cos(beta) - CD sin(beta)
    (y_W = (sin b, cos b, 0) and the airflow d = (cos b, -sin b, 0) at alpha 0)."""
    f = sample_fuselage(name)
    beta = np.radians([5.0, 10.0, 20.0])
    fy = (f.table("CY", 0.0, beta) * np.cos(beta)
          - f.table("CD", 0.0, beta) * np.sin(beta))  # body-axis force
    for value, ref in zip(np.abs(fy), [0.2, 0.4, 0.85], strict=True):
        assert ref / 1.6 < value < ref * 1.6
    cn = np.abs(f.table("Cn", 0.0, beta))
    for value, ref in zip(cn, [0.03, 0.06, 0.08], strict=True):
        assert ref / 1.6 < value < ref * 1.6


@pytest.mark.parametrize("name", NAMES)
def test_fin_stabilises_and_stalls(name):
    """Fin CY negative for positive beta (side force to the left, aft of the CG: stabilising),
    with a stall peak between 20 and 30 deg (facts s.3: |CY| 1.0 at 25 deg then stall)."""
    fin = sample_fin(name)
    beta = fin.table.angle
    cy = fin.table.coefficients["CY"]
    forward = np.abs(beta) < np.pi - 1e-9  # +-180 deg: the flow runs along the fin, CY = 0
    assert np.all(cy[forward & (beta > 0)] < 0) and np.all(cy[forward & (beta < 0)] > 0)
    window = (beta > 0) & (beta <= np.radians(45))
    peak = np.degrees(beta[window][np.argmin(cy[window])])
    assert 20.0 <= peak <= 30.0
    assert fin.efficiency == 0.5
    assert fin.centre_of_pressure[0] > 0


def test_hc2_less_stable_than_hc1():
    """SAMPLE_DATA.md: HC2 is the less stable in yaw (more unstable fuselage moment, less fin)."""
    def stability(name):
        f, fin, ref = sample_fuselage(name), sample_fin(name), sample_reference(name)
        cn, _ = f.table.slope("Cn", 0.0, -np.radians(10), np.radians(10))
        cy, _ = fin.table.slope("CY", -np.radians(10), np.radians(10))
        arm = ref.fin_centre_of_pressure[0]
        return f.area * f.length * cn - fin.area * fin.efficiency * cy * arm
    assert stability("HC2") < stability("HC1") < 0


def test_generator_reproduces_committed_csv():
    """Regression guard: the documented generator rewrites exactly the packaged CSV files."""
    gen = runpy.run_path(str(ROOT / "docs" / "sample-data" / "generate_sample_tables.py"))
    for name in NAMES:
        p = gen["SHAPES"][name]
        for kind, build in (("fuselage", gen["fuselage_table"]), ("fin", gen["fin_table"])):
            committed = pd.read_csv(ROOT / "slingloads" / "data" / f"{name.lower()}_{kind}.csv")
            assert list(committed.columns) == list(build(p).columns)
            assert_allclose(committed.to_numpy(), build(p).to_numpy(), atol=1e-6)


def test_columns_and_unknown_name():
    """The CSV header is exactly the one the workbook expects; unknown names are refused."""
    head = (ROOT / "slingloads" / "data" / "hc1_fuselage.csv").read_text().splitlines()[0]
    assert head == "alpha [deg],beta [deg],CD,CY,CL,Cl,Cm,Cn"
    assert sample_hardpoints("HC1").chute[0] > sample_hardpoints("HC1").hub[0]
    with pytest.raises(InputError, match="unknown sample aircraft.*'HC3'"):
        sample_fuselage("HC3")

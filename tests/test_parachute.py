"""The parachute's wake loss is counted once (paper, sections 3.2 and 3.3).

The paper's drag coefficient of 0.95 over +-8 deg is a canopy coefficient of one reduced by
the 5 % dynamic-pressure loss in the fuselage wake: its product "canopy CD x wake ratio" is
0.95, not 0.95 x 0.95 = 0.9025. The defaults carry the loss in the wake ratio (0.95) and give
the canopy its free-stream CD (1.0).
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from slingloads.analyses.chute_sizing import neutral_area
from slingloads.errors import InputError
from slingloads.models.aero_tables import Table1D
from slingloads.models.parachute import PAPER_CD, Parachute
from slingloads.models.sample_aircraft import (
    sample_fin,
    sample_fuselage,
    sample_hardpoints,
    sample_reference,
)
from slingloads.models.yaw_dynamics import YawModel

EIGHT = np.radians(8.0)


def test_default_product_is_the_papers_095():
    """Paper 3.3: effective CD 0.95 within +-8 deg = canopy 1.0 x wake ratio 0.95 (one 5 %
    loss); drag of 1 m^2 at q = 1000 Pa is 950 N, not 902.5 N."""
    chute = Parachute(1.0)
    assert chute.wake_ratio == 0.95
    assert float(chute.coefficient(0.0)) == 1.0
    assert float(chute.effective_coefficient(0.0)) == pytest.approx(PAPER_CD, rel=1e-12)
    assert float(chute.effective_coefficient(EIGHT)) == pytest.approx(0.95, rel=1e-12)
    assert float(chute.drag(1000.0)) == pytest.approx(950.0, rel=1e-12)


def test_table_containing_the_wake_with_ratio_one_gives_the_same_drag():
    """The alternative bookkeeping of the same physics: the paper's CD 0.95 tabulated (wake
    already in it) with wake ratio 1 gives the same drag as the defaults."""
    paper = Table1D([-EIGHT, EIGHT], {"CD": [0.95, 0.95]}, "alpha", "parachute")
    assert_allclose(Parachute(2.0, paper, wake_ratio=1.0).drag([500.0, 1621.0]),
                    Parachute(2.0).drag([500.0, 1621.0]), rtol=1e-14)


def test_sizing_uses_the_same_single_factor():
    """The neutral area (paper 4.1) A = -(dN_fus + dN_fin)/dbeta / (q eta_w CD l_c) uses the
    one effective factor 0.95: the yaw model's chute coefficient is 0.95, and the area with
    the defaults equals the area with the paper's 0.95 table at wake ratio 1 (HC1 sample)."""
    ref = sample_reference("HC1")
    paper = Table1D([-EIGHT, EIGHT], {"CD": [0.95, 0.95]}, "alpha", "parachute")

    def model(chute):
        return YawModel(sample_fuselage("HC1"), sample_fin("HC1"), sample_hardpoints("HC1"),
                        ref.yaw_inertia, parachute=chute)

    default = model(Parachute(1.0))
    assert default.chute_drag_coefficient == pytest.approx(0.95, rel=1e-12)
    assert neutral_area(default).area == pytest.approx(
        neutral_area(model(Parachute(1.0, paper, wake_ratio=1.0))).area, rel=1e-12)


def test_canopy_axes_table_needs_ct():
    """Declared axes: a canopy-axes table carries the tangential coefficient CT; a table
    without it is refused with the valid column named."""
    table = Table1D([-EIGHT, EIGHT], {"CD": [1.0, 1.0]}, "alpha", "parachute")
    with pytest.raises(InputError, match="canopy axes needs a CT column"):
        Parachute(1.0, table, axes="canopy")
    with pytest.raises(InputError, match="must be one of"):
        Parachute(1.0, axes="body")
    ct = Parachute(1.0, axes="canopy")
    assert float(ct.effective_coefficient(0.0)) == pytest.approx(0.95)

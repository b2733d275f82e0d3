"""The loads pipeline worked in chunks of cases gives the loads of the whole case matrix at
once.

Reference: the same study run as a single chunk (every case's applied loads, accelerations and
internal loads built together, the former path); the cases are independent, so chunking can
change nothing but round-off.
"""


import numpy as np
from hostile import EXAMPLE
from numpy.testing import assert_allclose

from slingloads.analyses import loads as loads_module
from slingloads.io.study import read_study


def test_chunked_run_equals_one_chunk(monkeypatch):
    """The example's cases in chunks of 7 against one chunk:
    internal loads, residuals, accelerations and the cable columns agree to round-off."""
    study = read_study(EXAMPLE, only=["loads"]).inputs.loads
    monkeypatch.setattr(loads_module, "RUN_CHUNK", 10**9)
    whole = study.run()
    monkeypatch.setattr(loads_module, "RUN_CHUNK", 7)
    parts = study.run()
    assert len(whole.cases) > 7
    scale = np.abs(whole.loads).max()
    assert_allclose(parts.loads, whole.loads, rtol=0, atol=1e-12 * scale)
    assert_allclose(parts.residual, whole.residual, rtol=0, atol=1e-12 * scale)
    assert_allclose(parts.linear_acceleration, whole.linear_acceleration, rtol=1e-12)
    assert parts.cases.equals(whole.cases)

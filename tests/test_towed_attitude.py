"""One towed attitude per flight condition, used by the loads, the sizing and the multibody.

References:

* Limit case: in hover (no air load) a body hung by its hub hangs with its CG under the hub
  (statics of a body hung from one point; :meth:`Attitude.hanging`, checked by hand in
  tests/test_attitude_towed.py).
* The trim itself is checked against a hand moment balance about the hub in
  tests/test_attitude_towed.py::test_towed_trim_against_a_hand_moment_balance.
* Agreement: the loads' towed cases, the one-degree sizing and the multibody model ask one
  function (:func:`slingloads.analyses.towed_attitude.towed_attitude`) for the attitude, so
  at one airspeed they must agree to the trim's tolerance (1e-9 rad stated here).
"""

import re
from dataclasses import replace

import numpy as np
import pytest

from slingloads.analyses.towed_attitude import towed_attitude, towed_system
from slingloads.constants import KNOT
from slingloads.models.attitude import Attitude
from slingloads.runs.chute_sizing import run as run_sizing
from slingloads.runs.loads import with_towed_system
from slingloads.runs.multibody import run as run_multibody

TOLERANCE = 1e-9  # rad


def test_hover_trim_is_the_hanging_attitude(example_study):
    """At zero airspeed the trim of the system assembled from the loads' parts (massless
    quasi-static canopy) is the hanging attitude (CG under the hub), to 1e-9 rad. (The
    multibody model's hinged canopy has a mass, which tilts its hang.)"""
    loads = example_study.inputs.loads
    system, _ = towed_system(loads.airframe, loads.fuselage, loads.fin, loads.parachute)
    hover = towed_attitude(system, 0.0)
    hanging = Attitude.hanging(example_study.airframe.mass_items,
                               example_study.airframe.hardpoints.hub)
    assert hover.pitch == pytest.approx(hanging.pitch, abs=TOLERANCE)
    assert hover.roll == pytest.approx(hanging.roll, abs=TOLERANCE)


def test_loads_sizing_and_multibody_fly_one_attitude_at_80_keas(example_study):
    """At 80 KEAS the multibody trim's pitch, the sizing's angle of attack and the loads'
    towed case with parachute (its airspeed set to 80 KEAS) agree within 1e-9 rad; and the
    trim lies outside the example's +-10 deg envelope, which the loads flag."""
    multibody = run_multibody(example_study).trim
    sizing = run_sizing(example_study)
    loads = with_towed_system(example_study, example_study.inputs.loads)
    loads = replace(loads, flight=replace(loads.flight, eas=80.0 * KNOT))
    towed = loads.towed_trims[True]
    pitch = multibody.attitude[1]
    assert sizing.inputs.model.condition.eas == pytest.approx(80.0 * KNOT, rel=1e-12)
    assert sizing.inputs.model.condition.alpha == pytest.approx(pitch, abs=TOLERANCE)
    assert towed.pitch == pytest.approx(pitch, abs=TOLERANCE)
    assert towed.alpha == pytest.approx(sizing.inputs.model.condition.alpha, abs=TOLERANCE)
    assert np.degrees(pitch) < -10.0
    assert any("OUTSIDE the aerodynamic envelope" in line
               for line in loads.run().towed_findings())


def test_towed_case_descriptions_give_the_trim_at_the_reports_precision(example_study):
    """A towed case's description states the trimmed angle of attack and sideslip at the
    reports' 0.1 deg (checked against the trim itself, rounded by hand), a round-off zero as
    0.0: no ``1.48e-16`` in a description a checker reads."""
    loads = with_towed_system(example_study, example_study.inputs.loads)
    cases = loads.run().cases
    towed = cases[cases["hook"] == "TOW"]
    assert len(towed)
    trim = loads.towed_trims[True]
    with_chute = towed[towed["chute"].astype(bool)]
    for text in towed["description"]:
        assert not re.search(r"\de[-+]?\d", text), text
    alpha = f"{round(float(np.degrees(trim.alpha)), 1) + 0.0:+.1f}"
    assert any(f"alpha {alpha} deg" in text for text in with_chute["description"]), \
        (alpha, list(with_chute["description"]))

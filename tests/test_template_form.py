"""The blank template is a form that works: filled with a small airframe of its own and run
as it comes (optional sheets left empty, the template's own columns and defaults kept).

References: conservation (the study's mass is the sum of the three items typed in: 2200 kg)
and the CS-29.865 vertical case (the hook force is Nz W = 2.5 x 2200 x 9.80665 N along the
vertical, so the shear just aft of the hub balances the items forward of it under 2.5 g).
"""

import itertools

import numpy as np
import pytest
from openpyxl import load_workbook

from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.io.study import read_study
from slingloads.io.template import write_input_workbook


def _fill(path, aero=True, study=None):
    write_input_workbook(path)
    book = load_workbook(path)

    def rows(name, data):
        for r in data:
            book[name].append(list(r))

    rows("MassItems", [("NOSE", "nose", 300, 1.0, 0, 0.5, 0, 0, 0, 0, 0, 0),
                       ("CAB", "cabin", 1500, 3.0, 0, 0.8, 0, 0, 0, 0, 0, 0),
                       ("TAIL", "tail", 400, 7.0, 0, 1.0, 0, 0, 0, 0, 0, 0)])
    rows("Stations", [("S1", 2.0), ("S2", 4.0), ("S3", 6.0)])
    hardpoints = [("HUB", "hub", 3.2, 0, 2.0, None), ("F1", "mast_foot", 3.0, -0.3, 1.2, 1),
                  ("F2", "mast_foot", 3.0, 0.3, 1.2, 1)]
    values = dict(study or {})
    if aero:
        hardpoints += [("REF", "aero_reference", 3.5, 0, 1.0, None),
                       ("FIN", "fin_cp", 7.0, 0, 1.5, None)]
        rows("FuselageAero", [(a, b, 0.5, -0.02 * b, 0.03 * a, None, None, 0.0, -0.01 * a,
                               0.005 * b)
                              for a, b in itertools.product([-10, 0, 10], [-15, 0, 15])])
        rows("FinAero", [(-15, 0.3), (0, 0), (15, -0.3)])
        rows("AeroEnvelope", [("C", 0, 0), ("A+B+", 10, 15)])
        values = {"fuselage reference area": 4.0, "fuselage reference length": 8.0,
                  "fin area": 1.0, **values}
    rows("Hardpoints", hardpoints)
    for row in book["Study"].iter_rows(min_row=2):
        if row[0].value in values:
            row[1].value = values[row[0].value]
    book.save(path)
    return path


def test_template_filled_runs_first_time(tmp_path):
    """Three items, three stations, the hub and two mast feet typed into the blank template,
    with fuselage and fin tables in the template's own columns (CX and CZ left empty under
    the default wind frame) and every other sheet left empty: the workbook reads and runs."""
    study = read_study(_fill(tmp_path / "small.xlsx"), only=["loads"])
    loads = study.inputs.loads
    assert loads.airframe.mass_items.total_mass == pytest.approx(2200.0, rel=1e-12)
    result = loads.run()
    vertical = result.case_ids[list(result.cases["hook"]).index("VERTICAL")]
    i = result.case_ids.index(vertical)
    hub = result.study.hook_forces(result.cases.iloc[[i]], np.zeros((1, 3)))[0]
    assert np.linalg.norm(hub) == pytest.approx(2.5 * 2200.0 * G0, rel=1e-12)
    assert len(result.study.envelope.ids) == 2 and result.study.fin is not None


def test_template_without_aero_runs_and_an_empty_sheet_is_absent(tmp_path):
    """Without any aerodynamic data the same form runs (the empty FuselageAero, FinAero and
    AeroEnvelope sheets count as deleted), and a cross-sheet rule still names its cell."""
    study = read_study(_fill(tmp_path / "bare.xlsx", aero=False), only=["loads"])
    assert study.inputs.loads.fuselage is None and study.inputs.loads.envelope is None
    with pytest.raises(InputError, match=r"cell B\d+: a parachute area is given but the "
                                         r"Hardpoints sheet has no row of kind 'chute'"):
        read_study(_fill(tmp_path / "chute.xlsx", aero=False,
                         study={"parachute area": 2.0}), only=["loads"])


def test_multibody_refuses_a_wind_axes_fin_saying_who_refuses(tmp_path):
    """A FinAero table in wind axes is fine for the loads; the multibody model's refusal
    says that the multibody model is what needs body axes, at the 'fin axes' row."""
    path = _fill(tmp_path / "wind.xlsx", study={"run multibody": "yes", "fin axes": "wind"})
    with pytest.raises(InputError, match=r"cell B\d+: the multibody model .*'fin axes' = body"):
        read_study(path)

"""The stress engineer's script of docs/api.md, run as written, and the helpers it uses.

The references are independent of the code under test: conservation of mass (the changed
item adds exactly its mass change to the total), the closed-form hook direction (the
lateral cone directions lie ``lateral_angle`` from the vertical), the numpy maximum over the
cases of the internal loads, and the Nastran file's own CONM2 cards read back as text.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import slingloads as sl
from slingloads.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "loadcases" / "example-light-twin.xlsx"


def _script():
    """The first python block after the heading "A stress engineer's script"."""
    text = (ROOT / "docs" / "api.md").read_text(encoding="utf-8")
    part = text.split("## A stress engineer's script", 1)[1]
    return re.search(r"```python\n(.*?)```", part, re.S).group(1)


@pytest.fixture(scope="module")
def base():
    return sl.read_study(EXAMPLE, only=["loads"]).inputs.loads


def test_script_is_ten_lines():
    """The issue's promise: the whole script in at most ten lines of code."""
    lines = [line for line in _script().splitlines() if line.strip()]
    assert len(lines) <= 10, lines


def test_stress_script_runs_and_gives_the_changed_loads(base, tmp_path, monkeypatch):
    """Run the script from docs/api.md, then check its numbers against references of its
    own: total mass = original - m(ENG1) + 160 kg (conservation); the lateral hook
    directions (azimuth 90 and 270 deg) at 20 deg from the vertical; the envelope rows equal
    the numpy max/min over the cases at that station; the Nastran file holds a CONM2 of
    160 kg in lbf s^2/in (160 / 175.1268 = 0.913624)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "loadcases").symlink_to(ROOT / "loadcases")
    namespace = {}
    exec(compile(_script(), "docs/api.md", "exec"), namespace)  # noqa: S102 - our own doc
    result, critical = namespace["result"], namespace["critical"]
    items0 = base.airframe.mass_items
    items = result.study.airframe.mass_items
    assert items.total_mass == pytest.approx(
        items0.total_mass - items0.mass[items0.index("ENG1")] + 160.0, rel=1e-12)
    hooks = result.study.hook_table().set_index("hook")
    assert hooks.loc[["AZ090", "AZ270"], "inclination [deg]"].tolist() == pytest.approx(
        [20.0, 20.0], abs=1e-12)
    assert hooks.loc["AZ000", "inclination [deg]"] == pytest.approx(30.0, abs=1e-12)
    i = result.station_ids.index("FS0215")
    mx = result.loads[:, i, 3]
    row = critical.set_index("bound")
    assert row.loc["max", "value_Nm"] == mx.max()
    assert row.loc["min", "value_Nm"] == mx.min()
    assert row.loc["max", "case"] == result.case_ids[int(np.argmax(mx))]
    assert list(critical["station"]) == ["FS0215", "FS0215"]
    text = (tmp_path / "nastran" / "light-twin.bdf").read_text()
    conm2 = [line for line in text.splitlines() if line.startswith("CONM2")]
    assert len(conm2) == len(items.ids)
    # large-field CONM2: the mass in columns 57-72, Nastran's exponent without the "E"
    masses = [float(re.sub(r"(\d)([+-]\d+)$", r"\1e\2", line[56:72].strip()))
              for line in conm2]
    assert any(abs(m - 160.0 / 175.126835) < 1e-5 for m in masses), masses


def test_model_arrays_are_read_only(base):
    """A change that bypasses the constructor's checks is impossible (a past defect:
    ``items.mass[0] = -5`` then ``run()`` ran silently)."""
    items = base.airframe.mass_items
    for array in (items.mass, items.position, items.inertia, base.airframe.stations,
                  base.airframe.hardpoints.hub, base.airframe.hardpoints.mast_feet):
        with pytest.raises(ValueError, match="read-only"):
            array[0] = -5.0
    given = np.array([10.0, 20.0])
    sl.MassItems(["A", "B"], given, np.zeros((2, 3)))
    given[0] = 1.0  # the caller's own array stays writable (it was copied, not frozen)


def test_helpers_check_what_they_change(base):
    """The helpers go through the constructors' rules: a negative mass names the item, an
    unknown id lists the valid ones, a hook angle out of [0, 90) deg echoes it in degrees,
    and an unknown keyword is refused (no **changes hiding the valid ones)."""
    with pytest.raises(InputError, match=r"mass of item 'ENG1' must be > 0: value -5\.0"):
        base.with_mass_item("ENG1", mass=-5.0)
    with pytest.raises(InputError, match=r"unknown mass item; valid ids are \['NOSE'"):
        base.with_mass_item("ENGINE", mass=100.0)
    with pytest.raises(InputError, match=r"\[0, 90\) deg: value 95\.0 \[deg\]"):
        base.with_hook(lateral_angle_deg=95)
    with pytest.raises(TypeError, match="lateral_angle"):
        base.with_hook(lateral_angle=0.3)
    with pytest.raises(InputError, match=r"radians.*given 20 rad = 1145\.92 deg"):
        sl.HookLoadOptions(lateral_angle=20)


def test_station_and_hardpoint_helpers(base):
    """Moving a cut station moves where the loads are reported and nothing else (the
    stations stay sorted; a station moved past its neighbour is refused); moving the hub
    1 cm aft changes the hanging vertical by the closed-form angle atan(dx / dz)."""
    af = base.airframe
    i = af.station_index("FS0215")
    moved = base.with_station("FS0215", af.stations[i] + 0.01)
    assert moved.airframe.stations[i] == pytest.approx(af.stations[i] + 0.01)
    assert np.delete(moved.airframe.stations, i) == pytest.approx(np.delete(af.stations, i))
    with pytest.raises(InputError, match="sorted by increasing x"):
        base.with_station("FS0215", af.stations[i + 2])
    hub = af.hardpoints.hub + [0.01, 0.0, 0.0]
    study = base.with_hardpoints(hub=hub)
    d = hub - af.mass_items.cg
    k = study.airframe.hardpoints.hub - af.mass_items.cg
    assert k == pytest.approx(d)
    assert study.airframe.hardpoints.mast_feet.tolist() == af.hardpoints.mast_feet.tolist()


def test_envelope_filters(base):
    """envelope(station=, component=, bound=) keeps exactly the matching rows of the full
    table; an unknown component is refused with the valid list."""
    result = base.run()
    full = result.envelope()
    part = result.envelope(station=[0, "FS0052"], component=("Vy", "Mz"), bound="max")
    expected = full[full["station"].isin(["FS0034", "FS0052"])
                    & full["component"].isin(["Vy", "Mz"]) & (full["bound"] == "max")]
    pd.testing.assert_frame_equal(part, expected.reset_index(drop=True))
    assert list(full.columns[:7]) == ["station", "x_m", "component", "bound", "case",
                                      "value_N", "value_Nm"]
    assert set(result.to_frame().columns) >= set(full.columns[7:])
    with pytest.raises(InputError, match="valid components"):
        result.envelope(component="Fy")

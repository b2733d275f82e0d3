"""Packed parameter vectors of the compiled kernels: laid out from one table, addressed by name.

References: the physical inputs themselves (a field of the packed vector must hold the value
of the input it is named after, whatever the field's position), and the rule that a kernel
never reads a packed vector at a literal index (a source scan of the kernels).
"""

import re
from pathlib import Path

import numpy as np
import pytest

import slingloads
from slingloads.models import packed
from slingloads.models.multibody import equations as eq
from slingloads.models.packed import BODY, Field, Layout

#: Modules with kernels, and the names of the packed vectors they read.
KERNELS = {"models/multibody/equations.py": ("P",), "models/multibody/integrator.py": ("P", "pj"),
           "models/pendulum_batch.py": ("P", "p"), "models/yaw_batch.py": ("M",),
           "models/yaw_dynamics.py": ("M",), "analyses/sfbm_kernel.py": ("rigid",),
           "analyses/sfbm.py": ("rigid",)}


@pytest.mark.parametrize("path", sorted(KERNELS))
def test_no_kernel_reads_a_packed_vector_at_a_literal_index(path):
    """Every index into a packed vector is a name generated from its layout table: a
    literal such as ``P[52]`` silently reads the wrong field when the table changes."""
    source = (Path(slingloads.__file__).parent / path).read_text()
    literal = re.compile(rf"\b({'|'.join(KERNELS[path])})\[\s*\d")
    assert not literal.findall(source), path


def test_layout_offsets_follow_the_table():
    """Offsets are the running sum of the sizes (hand count: 1 + 3 = 4), element names are
    ``<name>_<component>``, and a name given twice is refused."""
    layout = Layout((Field("a", "kg", "a"), Field("r", "m", "r", BODY), Field("b", "-", "b")))
    assert (layout["a"], layout["r"], layout["b"], len(layout)) == (0, 1, 4, 5)
    assert layout.names == ("a", "r_x", "r_y", "r_z", "b")
    assert layout.slice("r") == slice(1, 4)
    with pytest.raises(ValueError, match="'a' appears twice"):
        Layout((Field("a", "kg", "a"), Field("a", "m", "again")))
    with pytest.raises(KeyError, match="no field 'c'"):
        layout["c"]


def test_multibody_vector_holds_each_input_at_its_named_field():
    """The parameter vector of a system, read at the kernel's named offsets, gives back the
    inputs it was built from: mass, hub position from the CG, cable, air density."""
    from test_multibody import hc1_system

    system = hc1_system("hinged")
    p = system.parameters()
    body = system.body
    assert p[eq.MASS] == body.mass
    np.testing.assert_array_equal(p[eq.HUB:eq.HUB + 3], system.hardpoints.hub - body.cg)
    np.testing.assert_array_equal(p[eq.INERTIA:eq.INERTIA + 9], body.inertia.ravel())
    assert p[eq.CABLE_LENGTH] == system.cable.length
    assert p[eq.CABLE_STIFFNESS] == system.cable.stiffness
    assert p[eq.DENSITY] == system.density
    assert p[eq.CHUTE_MODE] == eq.CHUTE_HINGED
    assert len(p) == eq.N_PARAMETERS == len(eq.LAYOUT)
    assert all(isinstance(f, packed.Field) and f.unit for f in eq.LAYOUT.fields)

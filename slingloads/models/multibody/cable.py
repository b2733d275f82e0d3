"""The cable from the carrier's hook to the carried helicopter's rotor hub.

One massless, elastic, tension-only segment (paper section 4.3: the helicopter is far heavier
than the cable, so the tension is taken uniform along it). With ``d`` the vector from the hook
to the hub, its length ``|d|`` and stretch rate ``s' = d . d' / |d|``:

.. math::

    T = \\max\\left(0,\\; \\frac{EA}{L_0} (|d| - L_0) + c\\, s'\\right) \\quad (|d| > L_0),
    \\qquad T = 0 \\quad (|d| \\le L_0)

The cable is slack when it is no longer than its unstretched length (it then transmits
nothing, and the run reports it). Structural damping is viscous on the stretch rate, never
pushing: ``c = 2 zeta sqrt((EA/L_0) m)`` with ``zeta`` the damping ratio of the load's bounce
on the cable and ``m`` the mass hung on it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import non_negative, positive
from slingloads.models.multibody._jit import jit


@dataclass(frozen=True)
class Cable:
    """Carrier cable, hook to hub.

    Parameters
    ----------
    length : float
        Unstretched length L0, > 0. [m]
    ea : float
        Axial stiffness EA, > 0. [N]
    damping_ratio : float
        Structural damping as the damping ratio of the bounce mode of the hung mass, >= 0. [-]
    """

    length: float
    ea: float
    damping_ratio: float = 0.05

    def __post_init__(self):
        object.__setattr__(self, "length", positive(
            self.length, "cable length must be > 0 [m]"))
        object.__setattr__(self, "ea", positive(
            self.ea, "cable axial stiffness EA must be > 0 [N]"))
        object.__setattr__(self, "damping_ratio", non_negative(
            self.damping_ratio, "cable damping ratio must be >= 0 [-]"))

    @property
    def stiffness(self):
        """Spring rate EA / L0. [N/m]"""
        return self.ea / self.length

    def damping(self, hung_mass):
        """Viscous coefficient c = 2 zeta sqrt(k m) for the hung mass ``hung_mass`` [kg]. [N s/m]"""
        return 2.0 * self.damping_ratio * np.sqrt(self.stiffness * hung_mass)

    def static_stretch(self, weight):
        """Stretch under a steady pull ``weight`` [N]: W L0 / EA. [m]"""
        return weight / self.stiffness


@jit
def cable_tension(length, rate, unstretched, stiffness, damping):
    """Tension [N] of the tension-only cable of current ``length`` [m], stretch ``rate`` [m/s]."""
    if length <= unstretched:
        return 0.0
    tension = stiffness * (length - unstretched) + damping * rate
    return tension if tension > 0.0 else 0.0

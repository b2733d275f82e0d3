"""The cable from the carrier's hook to the carried helicopter's rotor hub.

One massless, elastic, tension-only segment (paper section 4.3: the helicopter is far heavier
than the cable, so the tension is taken uniform along it). With ``d`` the vector from the hook
to the hub, its length ``|d|`` and stretch rate ``s' = d . d' / |d|``:

.. math::

    T = \\max\\left(0,\\; \\frac{EA}{L_0} (|d| - L_0) + c\\, s'\\right) \\quad (|d| > L_0),
    \\qquad T = 0 \\quad (|d| \\le L_0)

The cable is slack when it is no longer than its unstretched length (it then transmits
nothing, and the run reports it). Structural damping is viscous on the stretch rate, never
pushing, given either as the coefficient ``c`` [N s/m] itself or as the damping ratio ``zeta``
of the load's bounce on the cable: ``c = 2 zeta sqrt((EA/L_0) m)`` with ``m`` the mass hung on
it.

**A stiff cable is the rigid one.** The trim solves for the tension, not the stretch, and the
adaptive integrator follows the bounce mode however fast (about sqrt(EA / (L_0 m)) rad/s):
EA up to 1e11 N trims and flies (an 18 m cable under 3 t: 1350 rad/s, a few tens of thousands
of steps a minute), and the responses are the inextensible cable's (the yaw change of a free
response at 80 KEAS is the same to 1e-3 deg for EA 1e7, 1e9 and 1e11 N). There is therefore
no separate rigid-cable model: give a large EA.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slingloads.checks import non_negative, positive
from slingloads.errors import InputError
from slingloads.models.multibody._jit import jit

#: Damping ratio of the bounce mode when neither a ratio nor a coefficient is given. [-]
DEFAULT_DAMPING_RATIO = 0.05


@dataclass(frozen=True)
class Cable:
    """Carrier cable, hook to hub.

    Parameters
    ----------
    length : float
        Unstretched length L0, > 0. [m]
    ea : float
        Axial stiffness EA, > 0 (1e11 N for a practically rigid cable: module notes). [N]
    damping_ratio : float, optional
        Structural damping as the damping ratio of the bounce mode of the hung mass, >= 0
        (default :data:`DEFAULT_DAMPING_RATIO` unless ``damping_coefficient`` is given). [-]
    damping_coefficient : float, optional
        Structural damping as the viscous coefficient on the stretch rate, >= 0; give this
        or ``damping_ratio``, not both. [N s/m]

    Examples
    --------
    >>> Cable(18.3, 5e6, damping_coefficient=2000.0).damping(3000.0)
    2000.0
    >>> # 2 zeta sqrt(EA / L0 m) = 0.1 sqrt(5e6 / 18.3 x 3000)
    >>> round(float(Cable(18.3, 5e6, damping_ratio=0.05).damping(3000.0)), 1)
    2863.0
    """

    length: float
    ea: float
    damping_ratio: float | None = None
    damping_coefficient: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "length", positive(
            self.length, "cable length must be > 0 [m]"))
        object.__setattr__(self, "ea", positive(
            self.ea, "cable axial stiffness EA must be > 0 [N]"))
        if self.damping_coefficient is not None:
            if self.damping_ratio is not None:
                raise InputError("give the cable damping as a ratio or as a coefficient, not "
                                 "both", (self.damping_ratio, self.damping_coefficient))
            object.__setattr__(self, "damping_coefficient", non_negative(
                self.damping_coefficient, "cable damping coefficient must be >= 0 [N s/m]"))
            return
        ratio = DEFAULT_DAMPING_RATIO if self.damping_ratio is None else self.damping_ratio
        object.__setattr__(self, "damping_ratio", non_negative(
            ratio, "cable damping ratio must be >= 0 [-]"))

    @property
    def stiffness(self):
        """Spring rate EA / L0. [N/m]"""
        return self.ea / self.length

    def damping(self, hung_mass):
        """Viscous coefficient: the one given, else c = 2 zeta sqrt(k m) for the hung mass.

        Parameters
        ----------
        hung_mass : float
            Mass hung on the cable. [kg]

        Returns
        -------
        float
            Damping coefficient on the stretch rate. [N s/m]
        """
        if self.damping_coefficient is not None:
            return self.damping_coefficient
        return 2.0 * self.damping_ratio * np.sqrt(self.stiffness * hung_mass)

    def damping_ratio_for(self, hung_mass):
        """Damping ratio of the bounce of the hung mass: the one given, else c / (2 sqrt(k m)).

        Parameters
        ----------
        hung_mass : float
            Mass hung on the cable. [kg]

        Returns
        -------
        float
            Damping ratio of the bounce mode. [-]
        """
        if self.damping_coefficient is None:
            return self.damping_ratio
        return self.damping_coefficient / (2.0 * np.sqrt(self.stiffness * hung_mass))

    def static_stretch(self, weight):
        """Stretch under a steady pull: W L0 / EA.

        Parameters
        ----------
        weight : float
            Steady pull on the cable. [N]

        Returns
        -------
        float
            Stretch. [m]
        """
        return weight / self.stiffness


@jit
def cable_tension(length, rate, unstretched, stiffness, damping):
    """Tension of the tension-only cable (module notes; zero when slack, never pushing).

    Parameters
    ----------
    length : float
        Current hook-to-hub distance |d|. [m]
    rate : float
        Stretch rate d . d' / |d|. [m/s]
    unstretched : float
        Unstretched length L0. [m]
    stiffness : float
        Spring rate EA / L0. [N/m]
    damping : float
        Viscous coefficient on the stretch rate. [N s/m]

    Returns
    -------
    float
        Tension, >= 0. [N]
    """
    if length <= unstretched:
        return 0.0
    tension = stiffness * (length - unstretched) + damping * rate
    return tension if tension > 0.0 else 0.0

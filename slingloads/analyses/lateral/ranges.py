"""The slung body of an airframe, and the stated uncertainty of its mass properties and rope.

:func:`airframe_body` turns an airframe's mass items and hub into the lateral pendulum's body
(mass, roll inertia about the hanging fore-and-aft axis, CG distance below the hub);
:class:`ParameterRanges` states how far the roll inertia, the CG distance and the rope length
may differ from their nominal values, as factors the study runs over.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.models.airframe import hanging_roll_axis
from slingloads.models.pendulum import SlungBody


def airframe_body(airframe, name="airframe (MassItems)"):
    """The lateral-pendulum body of an airframe, hanging: mass, roll inertia, CG below hub.

    At rest the airframe hangs with its CG under the hub
    (:func:`~slingloads.models.airframe.hanging_vertical`), so the CG distance below the hub
    is :math:`e = |\\mathbf{r}_{hub} - \\mathbf{r}_{CG}|` and the roll inertia is taken about
    the horizontal fore-and-aft axis :math:`\\hat a` of that attitude
    (:func:`~slingloads.models.airframe.hanging_roll_axis`),
    :math:`I = \\hat a^T I_{CG} \\hat a`. With the hub on the body z axis through the CG these
    are the distance along the mast and :math:`I_{xx}`.

    Parameters
    ----------
    airframe : Airframe
    name : str

    Returns
    -------
    SlungBody

    Raises
    ------
    InputError
        If the CG does not lie below the hub or the roll inertia is not positive.
    """
    items = airframe.mass_items
    d = np.asarray(airframe.hardpoints.hub, float) - items.cg
    mast = np.asarray(airframe.hardpoints.mast_axis, float)
    along_mast = float(d @ mast / np.linalg.norm(mast))
    if not along_mast > 0:
        raise InputError("the CG of the mass items lies above the rotor hub along the mast; "
                         "the lateral pendulum needs it below [m]", along_mast,
                         field="cg_below_hub")
    e = float(np.linalg.norm(d))
    axis = hanging_roll_axis(airframe)
    inertia = float(axis @ items.inertia_about_cg @ axis)
    if not inertia > 0:
        raise InputError("the mass items' roll inertia about the CG must be > 0 [kg m^2]",
                         inertia, field="roll_inertia")
    return SlungBody(items.total_mass, inertia, e, name)


@dataclass(frozen=True)
class ParameterRanges:
    """Stated uncertainty of the mass properties and the rope, as factors on nominal values.

    The study runs every combination of ``points`` factors evenly spaced over each range
    (plus the nominal 1 if it is not among them): the recommended angle is taken over that
    envelope, so that it survives the uncertainty of the inputs.

    Parameters
    ----------
    roll_inertia, cg_below_hub, rope_length : (float, float)
        (lowest, highest) factor on the roll inertia, the CG distance below the hub and the
        rope length, each 0 < low <= 1 <= high (default +-20 %). [-]
    points : int
        Factors per range, >= 1 (1: the nominal value alone). [-]
    """

    roll_inertia: tuple = (0.8, 1.2)
    cg_below_hub: tuple = (0.8, 1.2)
    rope_length: tuple = (0.8, 1.2)
    points: int = 5

    NAMES = ("roll inertia", "CG below hub", "rope length")

    def __post_init__(self):
        for name in ("roll_inertia", "cg_below_hub", "rope_length"):
            value = getattr(self, name)
            try:
                lo, hi = (float(v) for v in value)
            except (TypeError, ValueError):
                raise InputError(f"the {name.replace('_', ' ')} range must be two factors "
                                 f"(low, high)", value) from None
            if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo <= 1 <= hi):
                raise InputError(f"the {name.replace('_', ' ')} range must satisfy 0 < low "
                                 f"<= 1 <= high [-]", (lo, hi))
            object.__setattr__(self, name, (lo, hi))
        if int(self.points) != self.points or self.points < 1:
            raise InputError("points per range must be a whole number >= 1", self.points)
        object.__setattr__(self, "points", int(self.points))

    @classmethod
    def nominal(cls):
        """No variation: the nominal values alone.

        Returns
        -------
        ParameterRanges
        """
        return cls((1.0, 1.0), (1.0, 1.0), (1.0, 1.0), 1)

    @classmethod
    def spread(cls, roll_inertia=0.2, cg_below_hub=0.2, rope_length=0.2, points=5):
        """Symmetric ranges 1 -+ the given fractions (each in [0, 1)).

        Parameters
        ----------
        roll_inertia, cg_below_hub, rope_length : float
            Fractions of the nominal values, each in [0, 1). [-]
        points : int
            Factors per range. [count]

        Returns
        -------
        ParameterRanges
        """
        ranges = []
        for name, f in (("roll inertia", roll_inertia), ("CG below hub", cg_below_hub),
                        ("rope length", rope_length)):
            f = float(f)
            if not (np.isfinite(f) and 0 <= f < 1):
                raise InputError(f"the {name} spread must lie in [0, 1) [-]", f)
            ranges.append((1.0 - f, 1.0 + f))
        return cls(*ranges, points)

    def factors(self):
        """The factors of each range: three 1-D arrays, each with 1 among them. [-]

        Returns
        -------
        tuple of three ndarray
            Roll-inertia, CG and rope-length factors. [-]
        """
        out = []
        for lo, hi in (self.roll_inertia, self.cg_below_hub, self.rope_length):
            grid = np.linspace(lo, hi, self.points) if self.points > 1 else np.array([1.0])
            out.append(np.unique(np.append(np.round(grid, 12), 1.0)))
        return tuple(out)

    def to_frame(self):
        """The ranges, one row per parameter.

        Returns
        -------
        pandas.DataFrame
            Parameter, lowest and highest factor [-] and points.
        """
        return pd.DataFrame({
            "parameter": list(self.NAMES),
            "lowest factor [-]": [r[0] for r in (self.roll_inertia, self.cg_below_hub,
                                                 self.rope_length)],
            "highest factor [-]": [r[1] for r in (self.roll_inertia, self.cg_below_hub,
                                                  self.rope_length)],
            "values [-]": [len(f) for f in self.factors()],
        })

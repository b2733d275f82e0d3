"""Own inertias of the example's mass items (imported by ``build_example.py``).

A mass item that stands for structure spread over the fuselage's section (cabin and cockpit
shells, floors, decks, boom) is not a point: its own inertia about its CG adds to the
parallel-axis terms of its position. Without it the example's roll inertia came from the
items' heights alone (905 kg m^2 for 2.9 t, k = 0.56 m), well below what helicopters of the
class have. Each distributed item is given here a simple shape of the size of the section it
stands for, and its own inertia from the shape's closed form:

* ``shell``: thin-walled rectangular tube along x (length L, section width w x height h),
  four plates of uniform areal mass;
* ``solid``: uniform box L x w x h;
* ``rod_x``, ``rod_y``: slender rod along x or y of length L;
* ``tube_x``: thin circular tube along x (length L, radius r).

Check of the magnitude (FACTS.md section 4): a BO-105C of 2096 kg has Ixx = 1803 kg m^2
(NASA CR-3144), radius of gyration k^2 = 0.86 m^2; a UH-60A 7632 kg m^2 for 7439 kg,
k^2 = 1.03 m^2. Both include the main-rotor blades, removed here (for a BO-105 four blades of
about 25 kg over 4.9 m carry roughly 2 m R^2/3 = 400 kg m^2 of roll inertia at rest, an
estimate); the BO-105's k^2 less that share, 0.67 m^2, times 2.9 t gives about 1,900 kg m^2,
the order the items below reach (1,680 kg m^2, k = 0.76 m). These are GENERIC
estimates for an illustrative aircraft, not the inertias of any real helicopter.
"""

from __future__ import annotations

import numpy as np

#: id -> (shape, dimensions [m]) of the items that are not points.
SHAPES = {
    "NOSE": ("shell", (1.0, 1.0, 1.0)),
    "CKPT": ("shell", (1.0, 1.4, 1.3)),
    "CREW": ("solid", (0.8, 1.2, 0.6)),
    "CABF": ("shell", (1.0, 1.5, 1.4)),
    "CABI": ("solid", (1.2, 1.4, 1.0)),
    "RECV": ("solid", (1.0, 1.3, 0.8)),
    "CABA": ("shell", (1.0, 1.5, 1.4)),
    "ELEC": ("solid", (1.0, 1.2, 0.6)),
    "FUEL": ("solid", (1.2, 1.2, 0.5)),
    "DECK": ("solid", (1.6, 1.4, 0.1)),
    "MGB": ("solid", (0.7, 0.6, 0.6)),
    "ENG1": ("solid", (1.0, 0.5, 0.5)),
    "ENG2": ("solid", (1.0, 0.5, 0.5)),
    "COWL": ("shell", (1.5, 1.0, 0.6)),
    "RFUS": ("shell", (1.2, 1.2, 1.1)),
    "SKXF": ("rod_y", (2.0,)),
    "SKXA": ("rod_y", (2.0,)),
    "SKTL": ("rod_x", (2.6,)),
    "SKTR": ("rod_x", (2.6,)),
    "BOOMF": ("tube_x", (1.8, 0.3)),
    "BOOMA": ("tube_x", (1.8, 0.25)),
    "TRDS": ("rod_x", (4.0,)),
    "FIN": ("solid", (0.8, 0.05, 1.0)),
}

NOTE = (
    "Own inertias (MassItems Ixx, Iyy, Izz about each item's CG): the structure, cabin, boom "
    "and skid items are given simple shapes of the size of the section they stand for "
    "(thin-walled boxes, solid boxes, rods, tubes; loadcases/example_inertia.py), so that the "
    "roll inertia of the 2.9 t example, 1,680 kg m^2, is of the order a BO-105C's "
    "(2096 kg, Ixx 1803 kg m^2, NASA CR-3144) scales to without its blades (FACTS.md 4); "
    "the items' heights alone gave 905 kg m^2. GENERIC estimates, not a real aircraft's.")


def _shell(m, length, width, height):
    """Thin-walled rectangular tube along x: two side walls and top/bottom plates."""
    perimeter = 2.0 * (width + height)
    ms, mt = m * height / perimeter, m * width / perimeter  # one side wall, one top plate
    ixx = 2 * ms * (height**2 / 12 + width**2 / 4) + 2 * mt * (width**2 / 12 + height**2 / 4)
    iyy = 2 * ms * (length**2 + height**2) / 12 + 2 * mt * (length**2 / 12 + height**2 / 4)
    izz = 2 * ms * (length**2 / 12 + width**2 / 4) + 2 * mt * (length**2 + width**2) / 12
    return ixx, iyy, izz


def _solid(m, length, width, height):
    return (m * (width**2 + height**2) / 12, m * (length**2 + height**2) / 12,
            m * (length**2 + width**2) / 12)


def _rod_x(m, length):
    return 0.0, m * length**2 / 12, m * length**2 / 12


def _rod_y(m, length):
    return m * length**2 / 12, 0.0, m * length**2 / 12


def _tube_x(m, length, radius):
    return m * radius**2, m * (radius**2 / 2 + length**2 / 12), m * (radius**2 / 2 +
                                                                     length**2 / 12)


_LAWS = {"shell": _shell, "solid": _solid, "rod_x": _rod_x, "rod_y": _rod_y,
         "tube_x": _tube_x}


def own_inertias(ids, masses):
    """Own inertia tensors about each item's CG (diagonal; zero for point items).

    Parameters
    ----------
    ids : sequence of str
    masses : array_like, shape (n,)
        [kg]

    Returns
    -------
    ndarray, shape (n, 3, 3)
        [kg m^2]
    """
    out = np.zeros((len(ids), 3, 3))
    for i, (item, m) in enumerate(zip(ids, masses, strict=True)):
        if item in SHAPES:
            law, dims = SHAPES[item]
            out[i] = np.diag(_LAWS[law](float(m), *dims))
    return out

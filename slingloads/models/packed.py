"""Packed parameter vectors of the compiled kernels, laid out from one table.

A compiled kernel (numba) reads its parameters from one float64 vector per run. The vector's
layout is written once, as a table of :class:`Field` (name, size, unit, meaning); a
:class:`Layout` made from it gives the offset of every field and the names of the vector's
elements. The module that owns a kernel binds each offset to a module-level integer
(``DENSITY = LAYOUT["density"]``); numba reads module-level integers as compile-time
constants, so a kernel indexes ``P[DENSITY]`` at no cost, and the packer (which fills the
vector) and the kernel (which reads it) cannot disagree on an index.

Components of a field of several elements are named ``<name>_<component>``: ``x``, ``y``,
``z`` for a vector in body axes (:data:`BODY`), ``X``, ``Y``, ``Z`` in earth axes
(:data:`EARTH`), ``xx`` to ``zz`` for a row-major 3 x 3 tensor (:data:`TENSOR`).
"""

from __future__ import annotations

from dataclasses import dataclass

#: Components of a vector in body (airframe) axes.
BODY = ("x", "y", "z")
#: Components of a vector in earth axes.
EARTH = ("X", "Y", "Z")
#: Components of a row-major 3 x 3 tensor in body axes.
TENSOR = ("xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz")


@dataclass(frozen=True)
class Field:
    """One field of a packed parameter vector.

    Parameters
    ----------
    name : str
        Name of the field (a Python identifier).
    unit : str
        Unit of its elements, e.g. ``"kg"``, ``"m"``, ``"-"`` for a number or a flag.
    doc : str
        What it is.
    components : tuple of str
        Names of its elements when it has more than one (:data:`BODY`, :data:`EARTH`,
        :data:`TENSOR`); empty for a scalar.
    """

    name: str
    unit: str
    doc: str
    components: tuple[str, ...] = ()

    @property
    def size(self):
        """Number of elements. [-]"""
        return max(1, len(self.components))

    @property
    def element_names(self):
        """Names of the elements: the field's name, or ``<name>_<component>``."""
        if not self.components:
            return (self.name,)
        return tuple(f"{self.name}_{c}" for c in self.components)


class Layout:
    """The layout of a packed vector: fields one after the other, in the table's order.

    Parameters
    ----------
    fields : sequence of Field
        The table. Names must be unique.

    Raises
    ------
    ValueError
        If a name (of a field or of an element) appears twice.
    """

    def __init__(self, fields):
        self.fields = tuple(fields)
        offsets, names = {}, []
        for f in self.fields:
            if f.name in offsets:
                raise ValueError(f"packed layout: field {f.name!r} appears twice")
            offsets[f.name] = len(names)
            names.extend(f.element_names)
        if len(set(names)) != len(names):
            raise ValueError(f"packed layout: an element name appears twice in {names}")
        self._offsets = offsets
        #: Names of the vector's elements, in order.
        self.names = tuple(names)

    def __getitem__(self, name):
        """Offset of field ``name`` (its first element). [-]"""
        try:
            return self._offsets[name]
        except KeyError:
            raise KeyError(f"packed layout: no field {name!r}; fields are "
                           f"{list(self._offsets)}") from None

    def __len__(self):
        """Length of the vector (elements). [-]"""
        return len(self.names)

    def slice(self, name):
        """The elements of a field, as a slice of the vector.

        Parameters
        ----------
        name : str
            Field name.

        Returns
        -------
        slice
        """
        start = self[name]
        return slice(start, start + next(f.size for f in self.fields if f.name == name))

    def table(self):
        """The table as rows (name, offset, size, unit, doc), e.g. for documentation.

        Returns
        -------
        list of tuple
        """
        return [(f.name, self[f.name], f.size, f.unit, f.doc) for f in self.fields]

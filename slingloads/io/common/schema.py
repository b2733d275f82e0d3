"""The types that describe an input workbook: table sheets, their columns, Study parameters.

Each analysis declares its Study-sheet parameters and sheets with these types in its own
``schema`` module (``slingloads.io.airframe.schema``, ``slingloads.io.loads.schema``...), and
:mod:`slingloads.io.analyses` lists them all. The reader (:mod:`slingloads.io.common.workbook`),
the study builder (:mod:`slingloads.io.study`) and the blank template
(:mod:`slingloads.io.template`) all follow these definitions, so the template's explanations
are always those the reader enforces: the allowed range of each number (:class:`Bounds`), the
longest text, the most rows of a sheet (:mod:`slingloads.limits`).

Column headers carry their unit in square brackets, ``x [in]``, ``mass [lb]``; any unit of the
right kind is accepted (SI or US customary). Parameters on the ``Study`` sheet carry theirs in
the ``unit`` column.
"""

from __future__ import annotations

from dataclasses import dataclass

from slingloads.limits import MAX_ID_CHARS, MAX_TABLE_ROWS, MAX_TEXT_CHARS

#: Kinds that are not physical quantities.
TEXT, FLAG, INTEGER = "text", "flag", "integer"


@dataclass(frozen=True)
class Bounds:
    """Allowed range of a number, checked at its cell when the workbook is read.

    Parameters
    ----------
    lo, hi : float, optional
        Lower and upper bound (None: unbounded), in ``unit``.
    lo_open, hi_open : bool
        The bound itself is excluded (``> lo`` rather than ``>= lo``).
    unit : str, optional
        Unit of the bounds (pint spelling); default: the unit of the column or parameter in
        the template.
    nonzero : bool
        Zero is not allowed (a nonzero acceleration of either sign).
    """

    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    unit: str | None = None
    nonzero: bool = False

    def contains(self, value):
        """True if ``value`` (in the bounds' unit) lies in the range."""
        if self.nonzero and value == 0:
            return False
        if self.lo is not None and (value < self.lo or (self.lo_open and value == self.lo)):
            return False
        return not (self.hi is not None
                    and (value > self.hi or (self.hi_open and value == self.hi)))

    def text(self, scale=1.0, unit=""):
        """The allowed range in words, bounds divided by ``scale`` and followed by ``unit``:
        ``"> 0 kg"``, ``"in [0, 90) deg"``, ``"not 0"``."""
        suffix = f" {unit}" if unit else ""
        if self.lo is not None and self.hi is not None:
            text = (f"in {'(' if self.lo_open else '['}{self.lo / scale:.6g}, "
                    f"{self.hi / scale:.6g}{')' if self.hi_open else ']'}{suffix}")
        elif self.lo is not None:
            text = f"{'>' if self.lo_open else '>='} {self.lo / scale:.6g}{suffix}"
        elif self.hi is not None:
            text = f"{'<' if self.hi_open else '<='} {self.hi / scale:.6g}{suffix}"
        else:
            text = ""
        if self.nonzero:
            text = f"{text}, not 0" if text else "not 0"
        return text

    def rule(self, value, scale=1.0, unit=""):
        """The rule ``value`` (in the bounds' unit) breaks: ``"must be > 0 kg"``, followed by
        the allowed range when it has two ends."""
        suffix = f" {unit}" if unit else ""
        if self.nonzero and value == 0:
            side = "must not be 0"
        elif self.lo is not None and (value < self.lo or (self.lo_open and value == self.lo)):
            side = f"must be {'>' if self.lo_open else '>='} {self.lo / scale:.6g}{suffix}"
        else:
            side = f"must be {'<' if self.hi_open else '<='} {self.hi / scale:.6g}{suffix}"
        if self.lo is not None and self.hi is not None:
            side += f" (allowed: {self.text(scale, unit)})"
        return side


#: Bounds of a relative tolerance of solve_ivp (below 1e-13 it is under the round-off).
RELATIVE_TOLERANCE = Bounds(1e-13, 0.1)
#: Bounds of an absolute tolerance of an adaptive step, SI units of the states.
ABSOLUTE_TOLERANCE = Bounds(1e-13, 1.0)
#: ISA density altitude: the troposphere model's range.
ISA_ALTITUDE = Bounds(-610, 11000, unit="m")
#: Simulated time of a run of the multibody model or the campaign (an hour: the paper's runs
#: last 60 s; the work limits bound runs x steps as well).
RUN_LENGTH = Bounds(0, 3600, lo_open=True, unit="s")
#: Sampling interval of stored histories.
OUTPUT_INTERVAL = Bounds(0, 60, lo_open=True, unit="s")
#: Equivalent airspeed of every analysis (loads, lateral damping, parachute sizing, multibody
#: model, campaign): 200 kt is above the never-exceed speed of the heavy-lift helicopters
#: that carry slung loads, and far above the speeds flown with one (field practice in
#: damaged-helicopter recovery: 30-40 KIAS; the paper: 80-100 KEAS). A higher value is a unit
#: or typing mistake (1900 kt is Mach 2.9 at sea level).
AIRSPEED = Bounds(0, 200, unit="kt")
#: Carrier cable, hook to hub (paper: 18 to 100 ft; the longest long lines about 200 ft).
CABLE_LENGTH = Bounds(0, 500, lo_open=True, unit="m")
#: Axial stiffness EA of a cable (a 25 mm steel rope is about 5e7 N; below 1e4 N a
#: helicopter would stretch its cable several times its length).
CABLE_EA = Bounds(1e4, 1e9, unit="N")
#: Mass of a parachute canopy and its line (a drogue of a few m^2 weighs a few kg; a lighter
#: one makes its swing a very fast mode).
CANOPY_MASS = Bounds(0.1, 1000, unit="kg")
#: Mass of a carrier helicopter (the heaviest, Mi-26 class, about 56 t).
CARRIER_MASS = Bounds(0, 1e5, lo_open=True, unit="kg")
#: Flat-plate drag area of a carrier (CH-47 class: 4 m^2).
DRAG_AREA = Bounds(0, 1000, unit="m^2")


def above(lo, **kw):
    """Bounds ``> lo`` (and ``hi``/``unit`` as keywords)."""
    return Bounds(lo=lo, lo_open=True, **kw)


def at_least(lo, **kw):
    """Bounds ``>= lo``."""
    return Bounds(lo=lo, **kw)


def at_most(hi, **kw):
    """Bounds ``<= hi``."""
    return Bounds(hi=hi, **kw)


@dataclass(frozen=True)
class Column:
    """One column of a table sheet.

    Parameters
    ----------
    name : str
        Header text without the unit (matched case-insensitively).
    kind : str
        A quantity kind of :data:`slingloads.io.common.units.SI_UNITS`, or ``text``,
        ``flag``, ``integer``.
    unit : str
        Unit written in the template header (the user may change it to any unit of the kind).
    required : bool
        The column must be present and each row must fill it.
    default : object
        Value used when an optional cell is empty (SI).
    help : str
    bounds : Bounds, optional
        Allowed range of the column's numbers (every number is also bounded in magnitude by
        :data:`slingloads.limits.MAX_MAGNITUDE` of its kind).
    max_chars : int, optional
        Longest text of a text column (default :data:`slingloads.limits.MAX_ID_CHARS`, or
        :data:`~slingloads.limits.MAX_TEXT_CHARS` for a ``description``).
    """

    name: str
    kind: str
    unit: str = ""
    required: bool = True
    default: object = None
    help: str = ""
    bounds: Bounds | None = None
    max_chars: int | None = None

    @property
    def header(self):
        return f"{self.name} [{self.unit}]" if self.unit else self.name

    @property
    def char_limit(self):
        """Longest text accepted in a cell of this column. [characters]"""
        if self.max_chars is not None:
            return self.max_chars
        return MAX_TEXT_CHARS if self.name.lower() == "description" else MAX_ID_CHARS


@dataclass(frozen=True)
class TableSheet:
    """A sheet holding a table: header in row 1, one record per row below.

    ``max_rows`` bounds the data rows (:data:`slingloads.limits.MAX_TABLE_ROWS` by default).
    ``ids`` names its id columns: each value unique, case and surrounding spaces ignored
    (:mod:`slingloads.ids`), checked by the workbook reader as the sheet reads, for every
    sheet alike.
    """

    name: str
    columns: tuple
    required: bool = False
    help: str = ""
    max_rows: int = MAX_TABLE_ROWS
    ids: tuple = ()


@dataclass(frozen=True)
class Parameter:
    """One row of the ``Study`` sheet: ``parameter | value | unit | description``.

    ``default`` is in the unit ``unit`` (converted on reading); ``None`` means required.
    ``bounds`` (in ``unit`` unless stated) is checked at the value's cell; every number is
    also bounded in magnitude by :data:`slingloads.limits.MAX_MAGNITUDE` of its kind.
    ``former`` lists names the parameter had before (a workbook using one is told the new
    name, since the meaning may have changed with it).
    """

    name: str
    kind: str
    unit: str = ""
    default: object = None
    help: str = ""
    section: str = "general"
    bounds: Bounds | None = None
    former: tuple = ()


@dataclass(frozen=True)
class Section:
    """Parameters and sheets that belong to one analysis."""

    name: str
    parameters: tuple = ()
    sheets: tuple = ()


STUDY_SHEET = "Study"
NOTE_COLUMNS = ("note", "notes", "comment", "comments", "source")

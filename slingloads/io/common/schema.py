"""The types that describe an input workbook: table sheets, their columns, Study parameters.

Each analysis declares its Study-sheet parameters and sheets with these types in its own
``schema`` module (``slingloads.io.airframe.schema``, ``slingloads.io.loads.schema``...), and
:mod:`slingloads.io.analyses` lists them all. The reader (:mod:`slingloads.io.common.workbook`),
the study builder (:mod:`slingloads.io.study`) and the blank template
(:mod:`slingloads.io.template`) all follow these definitions, so the template's explanations
are always those the reader enforces.

Column headers carry their unit in square brackets, ``x [in]``, ``mass [lb]``; any unit of the
right kind is accepted (SI or US customary). Parameters on the ``Study`` sheet carry theirs in
the ``unit`` column.
"""

from __future__ import annotations

from dataclasses import dataclass

#: Kinds that are not physical quantities.
TEXT, FLAG, INTEGER = "text", "flag", "integer"


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
    """

    name: str
    kind: str
    unit: str = ""
    required: bool = True
    default: object = None
    help: str = ""

    @property
    def header(self):
        return f"{self.name} [{self.unit}]" if self.unit else self.name


@dataclass(frozen=True)
class TableSheet:
    """A sheet holding a table: header in row 1, one record per row below."""

    name: str
    columns: tuple
    required: bool = False
    help: str = ""


@dataclass(frozen=True)
class Parameter:
    """One row of the ``Study`` sheet: ``parameter | value | unit | description``.

    ``default`` is in the unit ``unit`` (converted on reading); ``None`` means required.
    ``former`` lists names the parameter had before (a workbook using one is told the new
    name, since the meaning may have changed with it).
    """

    name: str
    kind: str
    unit: str = ""
    default: object = None
    help: str = ""
    section: str = "general"
    former: tuple = ()


@dataclass(frozen=True)
class Section:
    """Parameters and sheets that belong to one analysis."""

    name: str
    parameters: tuple = ()
    sheets: tuple = ()


STUDY_SHEET = "Study"
NOTE_COLUMNS = ("note", "notes", "comment", "comments", "source")

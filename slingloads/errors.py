"""Exception hierarchy of slingloads.

Every error raised on bad input is an :class:`InputError` (a ``ValueError``). When the
input came from a workbook the error carries the file, sheet and cell, the offending value
and the rule it broke, so that the message can be acted on without a debugger.
"""

from __future__ import annotations


class SlingloadsError(Exception):
    """Base class of every error raised by slingloads."""


class InputError(SlingloadsError, ValueError):
    """Input data that break a stated rule.

    Parameters
    ----------
    rule : str
        The rule that was broken, phrased as the rule ("mass must be > 0").
    value : object, optional
        The offending value, echoed with ``repr``.
    file, sheet, cell : str, optional
        Where the value was read from, when it came from a workbook or CSV file.
    """

    def __init__(self, rule, value=None, *, file=None, sheet=None, cell=None):
        self.rule = rule
        self.value = value
        self.file = file
        self.sheet = sheet
        self.cell = cell
        super().__init__(self._message())

    def located(self, *, file=None, sheet=None, cell=None):
        """Return a copy of this error with its location filled in where still unknown."""
        return type(self)(
            self.rule,
            self.value,
            file=self.file or file,
            sheet=self.sheet or sheet,
            cell=self.cell or cell,
        )

    def _message(self):
        where = []
        if self.file:
            where.append(f"file {self.file!s}")
        if self.sheet:
            where.append(f"sheet {self.sheet!r}")
        if self.cell:
            where.append(f"cell {self.cell}")
        prefix = ", ".join(where)
        value = "" if self.value is None else f": value {self.value!r}"
        text = f"{self.rule}{value}"
        return f"{prefix}: {text}" if prefix else text


class UnitError(InputError):
    """A unit that is unknown, or of the wrong kind for the quantity it is attached to."""


class ClosureError(SlingloadsError):
    """A load case whose free-free internal loads do not close to zero within tolerance."""

"""Exception hierarchy of slingloads.

Every error raised on bad input is an :class:`InputError` (a ``ValueError``). When the
input came from a workbook the error carries the file, sheet and cell, the offending value
as the user wrote it (with the unit of its header or unit cell) and the rule it broke, so that
the message can be acted on without a debugger. An :class:`OutputError` is a failure of the
environment (an output folder that cannot be written, a full disk, a name too long for the
file system); the command line exits with code 2 for the first and 1 for the second.
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
        The offending value, echoed with ``repr`` (numpy scalars and arrays as plain Python
        numbers and lists, never as ``np.float64(...)``).
    file, sheet, cell : str, optional
        Where the value was read from, when it came from a workbook or CSV file.
    unit : str, optional
        Unit in which ``value`` is given (the user's unit for a value read from a workbook).
    field : str, optional
        Name of the model argument that holds the value (``"mass"``, ``"angle"``), so that the
        io layer can locate an error a model raised at the cell the value came from
        (:func:`slingloads.io.common.locate.located`).
    index : int, optional
        Index of the record (row) of ``field`` that holds the value.
    """

    def __init__(self, rule, value=None, *, file=None, sheet=None, cell=None, unit=None,
                 field=None, index=None):
        self.rule = rule
        self.value = plain(value)
        self.file = file
        self.sheet = sheet
        self.cell = cell
        self.unit = unit
        self.field = field
        self.index = index
        super().__init__(self._message())

    @property
    def location(self):
        """``(file, sheet, cell)``."""
        return self.file, self.sheet, self.cell

    def _message(self, with_file=True):
        where = []
        if self.file and with_file:
            where.append(f"file {self.file!s}")
        if self.sheet:
            where.append(f"sheet {self.sheet!r}")
        if self.cell:
            where.append(f"cell {self.cell}")
        prefix = ", ".join(where)
        value = ""
        if self.value is not None:
            unit = f" [{self.unit}]" if self.unit else ""
            value = f": value {self.value!r}{unit}"
        text = f"{self.rule}{value}"
        return f"{prefix}: {text}" if prefix else text


def plain(value):
    """``value`` with numpy scalars and arrays (also inside tuples and lists) turned into
    Python numbers and lists, so that a message shows ``5.0``, not ``np.float64(5.0)``."""
    if isinstance(value, (list, tuple)):
        items = [plain(v) for v in value]
        return items if isinstance(value, list) else tuple(items)
    tolist = getattr(value, "tolist", None)  # numpy scalars and arrays (no numpy import here)
    if tolist is not None and type(value).__module__ == "numpy":
        return tolist()
    return value


#: At most this many errors of one input are gathered and reported together; reading stops at
#: the next one (the message says so).
MAX_REPORTED_ERRORS = 25
#: The message of several errors lists them up to about this length, then says how many more.
MAX_MESSAGE_CHARS = 2400


class InputErrors(InputError):
    """Several input errors of one input, reported together.

    Its location, rule and value are those of the first error (in reading order: the Study
    sheet, then the airframe sheets, then each analysis's sheets, row by row and cell by cell),
    so that code reading ``err.cell`` sees the first error; ``str(err)`` lists every one.

    Parameters
    ----------
    errors : list of InputError
        At least two, in reading order.
    complete : bool, optional
        False when reading stopped at :data:`MAX_REPORTED_ERRORS` or when some sheets could not
        be checked because an earlier error prevents it (``note`` says which).
    note : str, optional
        What was not checked, and why.
    """

    def __init__(self, errors, *, complete=True, note=""):
        self.errors = list(errors)
        self.complete = complete
        self.note = note
        first = self.errors[0]
        super().__init__(first.rule, first.value, file=first.file, sheet=first.sheet,
                         cell=first.cell, unit=first.unit, field=first.field,
                         index=first.index)

    def _message(self):
        n = len(self.errors)
        files = {err.file for err in self.errors}
        one_file = len(files) == 1 and None not in files
        where = f" file {self.errors[0].file!s}" if one_file else ""
        head = (f"{n} errors in the input{where}" if self.complete
                else f"{n} errors in the input{where} (reading stopped there)")
        lines = [f"{head}:"]
        size = len(head)
        for i, err in enumerate(self.errors, start=1):
            line = f"  {i}. {err._message(with_file=not one_file)}"
            if size + len(line) > MAX_MESSAGE_CHARS and i > 1:
                lines.append(f"  ... and {n - i + 1} more (fix these first)")
                break
            lines.append(line)
            size += len(line) + 1
        if self.note:
            lines.append(f"  {self.note}")
        return "\n".join(lines)


class ErrorCollector:
    """Gathers the input errors of independent steps of a reading, to report them at once.

    A step whose result others need stops the reading when it fails (:meth:`stop`); a step
    that others do not need is attempted (:meth:`call`) and the reading goes on. At most
    ``limit`` errors are gathered: the next one stops the reading.

    Parameters
    ----------
    limit : int, optional
        Default :data:`MAX_REPORTED_ERRORS`.
    """

    def __init__(self, limit=MAX_REPORTED_ERRORS):
        self.errors = []
        self.limit = limit
        self._seen = set()
        self._stop = None  # the error that stopped the reading, passed on through call()

    def __bool__(self):
        return bool(self.errors)

    def add(self, err):
        """Gather ``err`` (an :class:`InputError`, or an :class:`InputErrors` whose errors are
        gathered one by one); an error already gathered (same message) is not repeated.

        Raises
        ------
        InputErrors
            When the gathered errors pass ``limit``.
        """
        for one in getattr(err, "errors", None) or [err]:
            text = str(one)
            if text in self._seen:
                continue
            self._seen.add(text)
            self.errors.append(one)
            if len(self.errors) > self.limit:
                self._stop = InputErrors(self.errors[:self.limit], complete=False)
                raise self._stop

    def call(self, step, *args, **kwargs):
        """``step(*args, **kwargs)``, or None after gathering the :class:`InputError` it
        raised."""
        try:
            return step(*args, **kwargs)
        except InputError as err:
            if err is self._stop:  # the limit reached within the step (a nested call)
                raise
            self.add(err)
            return None

    def error(self, note=""):
        """The gathered errors as one exception: the error itself when there is one (and no
        ``note``), else an :class:`InputErrors`; None when there is none."""
        if not self.errors:
            return None
        if len(self.errors) == 1 and not note:
            return self.errors[0]
        if len(self.errors) == 1:
            return _with_note(self.errors[0], note)
        return InputErrors(self.errors, complete=not note, note=note)

    def raise_if_any(self, note=""):
        """Raise :meth:`error` if any error was gathered."""
        err = self.error(note)
        if err is not None:
            raise err


def _with_note(err, note):
    """``err`` with ``note`` added to its message (one error, some sheets not checked)."""
    err.args = (f"{err} ({note})",)
    return err


class UnitError(InputError):
    """A unit that is unknown, or of the wrong kind for the quantity it is attached to."""


class ClosureError(SlingloadsError):
    """A load case whose free-free internal loads do not close to zero within tolerance."""


class OutputError(SlingloadsError, OSError):
    """The outputs cannot be written: a failure of the environment, not of the input.

    Parameters
    ----------
    rule : str
        What went wrong and what to do about it.
    path : str, optional
        The path concerned.
    """

    def __init__(self, rule, path=None):
        self.rule = rule
        self.path = None if path is None else str(path)
        super().__init__(f"{rule}: {self.path}" if self.path else rule)

    def __str__(self):
        return f"{self.rule}: {self.path}" if self.path else self.rule

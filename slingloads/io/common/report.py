"""What every report and plot shares: the report unit system and the inputs digest.

Values are SI inside slingloads; a report converts them to its unit system (``"SI"`` or
``"US"``, :data:`slingloads.io.common.units.REPORT_UNITS`) when it writes them, and labels
every header and axis with the unit (``x [in]``, ``Vy [lbf]``, ``Mz [lbf in]``).

What this module guarantees: a report value is converted from SI in one place, to a unit
system the reports know (any other is refused, naming the valid ones); every converted
column's header carries the unit it is now in; and an infinite value in the columns a
report names is written as what it means (:func:`explain_infinite`), not as a bare ``inf``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.io.common.formats import format_decimals, unit_format
from slingloads.io.common.units import REPORT_UNITS, from_si, unit_label


def check_units(units):
    """Return ``units`` if it is a report unit system, else raise :class:`InputError`."""
    if units not in REPORT_UNITS:
        raise InputError(f"{units=!r} is not a report unit system; valid are "
                         f"{sorted(REPORT_UNITS)}", units)
    return units


def report_unit(kind, units):
    """Unit string (pint spelling) of a quantity ``kind`` in the report system ``units``."""
    return REPORT_UNITS[check_units(units)][kind]


def in_report_units(values, kind, units):
    """Convert SI ``values`` of quantity ``kind`` to the report unit system.

    Parameters
    ----------
    values : array_like
        SI values. [m, N, N m...]
    kind : str
        Quantity kind (``"length"``, ``"force"``, ``"moment"``...).
    units : str
        ``"SI"`` or ``"US"``.

    Returns
    -------
    ndarray
        Values in the report unit of ``kind`` (in, lbf, lbf in for ``"US"``).
    """
    return from_si(values, report_unit(kind, units), kind)


#: Quantities written to the whole unit, as integers (an altitude: 0 m, 24000 ft).
WHOLE_UNIT_KINDS = frozenset({"altitude"})


def report_value(value, kind, units):
    """One SI value in report units: a float, or an int for a quantity of
    :data:`WHOLE_UNIT_KINDS` (so that it is written without decimals).

    Examples
    --------
    >>> report_value(7315.2, "altitude", "US"), report_value(0.0, "altitude", "SI")
    (24000, 0)
    """
    shown = float(in_report_units(value, kind, units))
    return int(round(shown)) if kind in WHOLE_UNIT_KINDS else shown


#: Kinds a sentence quotes at the precision of their cells (formats.py), trailing zeros
#: dropped, so that a title or a note reads the number of the cell beside it: a cable of
#: 18.288 m is "18.288 m" in both, never "18.29 m".
CELL_PRECISION_KINDS = frozenset({"length"})


def quantity_text(value, kind, units, digits=4):
    """One SI value of quantity ``kind`` written with its report unit, for a sentence or a
    title: the one spelling of each quantity in both unit systems (an altitude to the whole
    unit, in m or ft; a length in m or in, at its cells' precision; an airspeed in kt; other
    kinds to ``digits`` significant digits).

    Examples
    --------
    >>> quantity_text(1524.0, "altitude", "US"), quantity_text(1524.0, "altitude", "SI")
    ('5,000 ft', '1,524 m')
    >>> quantity_text(18.288, "length", "US"), quantity_text(18.288, "length", "SI")
    ('720 in', '18.288 m')
    >>> quantity_text(10.0584, "length", "SI"), quantity_text(10.0584, "length", "US")
    ('10.058 m', '396 in')
    """
    shown = report_value(value, kind, units)
    unit = unit_label(report_unit(kind, units))
    if isinstance(shown, int):
        number = f"{shown:,d}"
    elif kind in CELL_PRECISION_KINDS:
        number = f"{shown:,.{format_decimals(unit_format(unit))}f}"
        number = number.rstrip("0").rstrip(".") if "." in number else number
    else:
        number = f"{shown:.{digits}g}"
    return f"{number} {unit}"


def plural(count, one, many):
    """``"1 body"``, ``"3 bodies"``: a count with its noun in the right number."""
    return f"{count} {one if count == 1 else many}"


def labelled(name, kind, units):
    """Header or axis label with the report unit: ``labelled("Vy", "force", "US")`` is
    ``"Vy [lbf]"``."""
    return f"{name} [{unit_label(report_unit(kind, units))}]"


#: Quantity kind of an SI column by the unit in its header (``name [unit]``).
_SI_KINDS = {"m/s": "speed", "m": "length", "kg": "mass", "N": "force", "m^2": "area"}
_SI_HEADER = re.compile(r"^(?P<name>.*) \[(?P<unit>[^\]]+)\]$")


def _is_airspeed(name):
    """Whether a speed column ``name`` is an airspeed (the carrier's flight speed is one)."""
    return "airspeed" in name or "carrier speed" in name


def si_columns_in_units(frame, units, airspeed=_is_airspeed):
    """A copy of ``frame`` with its SI columns (``[m/s]``, ``[m]``, ``[kg]``, ``[N]``,
    ``[m^2]`` in the header) in the report units and relabelled, as every report writes each
    quantity (:data:`~slingloads.io.common.units.REPORT_UNITS`).

    Parameters
    ----------
    frame : pandas.DataFrame
        Table with SI columns named ``name [unit]``; other columns are left as they are.
    units : str
        ``"SI"`` or ``"US"``.
    airspeed : callable
        ``name -> bool``: which speed columns are airspeeds, in kt in both unit systems
        (default: a name with ``airspeed`` or ``carrier speed``); other speeds in m/s or
        ft/s. A length named ``... altitude ...`` is a density altitude (m or ft).

    Returns
    -------
    pandas.DataFrame
    """
    spec = {}
    for column in frame.columns:
        match = _SI_HEADER.match(str(column))
        if not match or match.group("unit") not in _SI_KINDS:
            continue
        name, kind = match.group("name"), _SI_KINDS[match.group("unit")]
        if kind == "speed" and airspeed(name):
            kind = "airspeed"
        elif kind == "length" and "altitude" in name:
            kind = "altitude"
        spec[column] = (name, kind)
    return convert_columns(frame, spec, units)


def convert_columns(frame, spec, units):
    """Convert SI columns of a DataFrame to report units and label them with the unit.

    Parameters
    ----------
    frame : pandas.DataFrame
        Table with SI columns.
    spec : mapping of str to (str, str)
        SI column name -> (new base name, quantity kind); ``{"x [m]": ("x", "length")}``
        gives ``x [in]`` in US units. Other columns are left as they are.
    units : str
        ``"SI"`` or ``"US"``.

    Returns
    -------
    pandas.DataFrame
        A converted copy.
    """
    check_units(units)
    out = frame.copy()
    renames = {}
    for column, (name, kind) in spec.items():
        if kind == "speed" and "airspeed" in name:  # an airspeed: in kt in both systems
            kind = "airspeed"
        if column not in out.columns:
            raise InputError(f"column to convert is missing; columns are {list(out.columns)}",
                             column)
        out[column] = in_report_units(out[column].to_numpy(float), kind, units)
        renames[column] = labelled(name, kind, units)
    return out.rename(columns=renames)


def explain_infinite(frame, columns, text, negative=None):
    """A copy of ``frame`` whose infinite numbers in ``columns`` are written as what they
    mean: ``text`` for +inf, ``negative`` for -inf (default ``"-" + text``).

    Excel has no infinity, and a bare ``inf`` in a column of numbers reads as a fault; a
    report says instead why the value has no finite size (``"unbounded (velocity step)"``:
    the acceleration of an impulse; ``"unbounded (previous 0)"``: a ratio over zero). The
    other cells keep their numbers (and their number format); absent columns are skipped.
    """
    out = frame.copy()
    for column in columns:
        if column not in out.columns:
            continue
        values = pd.to_numeric(out[column], errors="coerce").to_numpy(float)
        infinite = np.isinf(values)
        if not infinite.any():
            continue
        cells = out[column].astype(object).to_numpy(copy=True)
        cells[infinite & (values > 0)] = text
        cells[infinite & (values < 0)] = negative if negative is not None else f"-{text}"
        out[column] = cells
    return out


def digest_frame(inputs_digest):
    """What a report was computed from, as a two-column table ``input | entry``.

    Parameters
    ----------
    inputs_digest : dict or pandas.DataFrame or None
        ``{item: entry}`` (e.g. :func:`slingloads.io.common.cover.input_digest`), or a ready
        table.

    Returns
    -------
    pandas.DataFrame or None
    """
    if inputs_digest is None:
        return None
    if isinstance(inputs_digest, pd.DataFrame):
        return inputs_digest
    if isinstance(inputs_digest, Mapping):
        return pd.DataFrame({"input": [str(k) for k in inputs_digest],
                             "entry": list(inputs_digest.values())})
    raise InputError("inputs_digest must be a dict or a DataFrame",
                     type(inputs_digest).__name__)


def warning_sections(warnings):
    """The Summary block of the warnings on the inputs (implausible but possible values, each
    naming its cells), or nothing when there are none.

    Parameters
    ----------
    warnings : sequence of str
        :attr:`Source.warnings <slingloads.runs.study.Source.warnings>`.

    Returns
    -------
    list of slingloads.io.common.excel.Section
    """
    from slingloads.io.common.excel import Section

    warnings = list(warnings or ())
    if not warnings:
        return []
    table = pd.DataFrame({"warning": [f"WARNING {k}" for k in range(1, len(warnings) + 1)],
                          "on the inputs": warnings})
    return [Section("Warnings on the inputs (accepted, but check them)", table)]


def csv_name(header):
    """The CSV spelling of a unit-labelled header: ``name_unit``, as the SFBM file's columns.

    The name keeps letters and digits (other runs become ``_``; a prime ``'`` is ``dot``);
    the unit loses its spaces, ``*`` and ``^``, and ``/`` becomes ``p``; a dimensionless
    ``[-]`` adds nothing.

    Examples
    --------
    >>> [csv_name(h) for h in ("x [m]", "Mx [N m]", "S'' [m/s^2]", "T/(m g) [-]", "case")]
    ['x_m', 'Mx_Nm', 'Sddot_mps2', 'T_m_g', 'case']
    """
    text = str(header)
    unit = None
    if text.endswith("]") and "[" in text:
        text, unit = text[:text.rindex("[")], text[text.rindex("[") + 1:-1]
    name = text.strip().replace("''", "ddot").replace("'", "dot")
    name = re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_") or "value"
    if unit is None or unit.strip() in ("", "-"):
        return name
    unit = unit.replace(" ", "").replace("*", "").replace("^", "").replace("/", "p")
    return f"{name}_{re.sub(r'[^A-Za-z0-9]+', '', unit)}"


def csv_frame(frame):
    """A copy of ``frame`` with :func:`csv_name` headers (for the CSV files)."""
    names = [csv_name(c) for c in frame.columns]
    if len(set(names)) != len(names):
        raise InputError("two columns have the same CSV name", names)
    out = frame.copy()
    out.columns = names
    return out


def sample_rows(frame, column, max_rows, steps=(0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0,
                                                2.0, 2.5, 5.0, 10.0, 20.0, 30.0, 60.0)):
    """Rows of a table at a round interval of ``column`` (time, angle), for print.

    Parameters
    ----------
    frame : pandas.DataFrame
    column : str
        Increasing column sampled (e.g. ``"t [s]"``).
    max_rows : int
        Most rows kept.
    steps : sequence of float
        Round intervals tried in order; the first that keeps at most ``max_rows`` rows (and
        is no finer than the table's own spacing) is used.

    Returns
    -------
    (pandas.DataFrame, float)
        The rows nearest each whole multiple of the interval, and the interval; the whole
        table and its spacing when it already fits.
    """
    values = frame[column].to_numpy(float)
    if len(frame) <= max_rows or len(values) < 2:
        spacing = float(np.median(np.diff(values))) if len(values) > 1 else 0.0
        return frame, spacing
    spacing = float(np.median(np.diff(values)))
    span = float(values[-1] - values[0])
    for step in steps:
        if step >= spacing * (1 - 1e-9) and span / step + 1 <= max_rows:
            break
    else:
        step = span / (max_rows - 1)
    targets = np.arange(np.ceil(values[0] / step - 1e-9) * step, values[-1] + 1e-9 * step,
                        step)
    pos = np.searchsorted(values, targets).clip(1, len(values) - 1)
    left = np.abs(values[pos - 1] - targets) <= np.abs(values[pos] - targets)
    index = np.unique(np.where(left, pos - 1, pos))
    return frame.iloc[index], step


def split_unit(header):
    """``("name", "unit")`` of a unit-labelled header ``"name [unit]"``; ``(header, "")``
    when it has no unit."""
    text = str(header)
    if text.endswith("]") and " [" in text:
        return text[:text.rindex(" [")], text[text.rindex(" [") + 2:-1]
    return text, ""

"""What every report and plot shares: the report unit system and the inputs digest.

Values are SI inside slingloads; a report converts them to its unit system (``"SI"`` or
``"US"``, :data:`slingloads.io.common.units.REPORT_UNITS`) when it writes them, and labels
every header and axis with the unit (``x [in]``, ``Vy [lbf]``, ``Mz [lbf in]``).
"""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from slingloads.errors import InputError
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


def labelled(name, kind, units):
    """Header or axis label with the report unit: ``labelled("Vy", "force", "US")`` is
    ``"Vy [lbf]"``."""
    return f"{name} [{unit_label(report_unit(kind, units))}]"


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
        if column not in out.columns:
            raise InputError(f"column to convert is missing; columns are {list(out.columns)}",
                             column)
        out[column] = in_report_units(out[column].to_numpy(float), kind, units)
        renames[column] = labelled(name, kind, units)
    return out.rename(columns=renames)


def digest_frame(inputs_digest):
    """What a report was computed from, as a two-column table ``input | entry``.

    Parameters
    ----------
    inputs_digest : dict or pandas.DataFrame or None
        ``{item: entry}`` (e.g. :meth:`WorkbookStudy.digest
        <slingloads.io.study.WorkbookStudy.digest>`), or a ready table.

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

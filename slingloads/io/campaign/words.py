"""Quantities of the campaign as its report and its figures write them in a sentence."""

from __future__ import annotations

from slingloads.constants import POUND
from slingloads.io.common.report import quantity_text


def mass_text(value, units):
    """A mass in a title or a sentence, to the unit: in kg (SI) or lb (US).

    Parameters
    ----------
    value : float
        Mass. [kg]
    units : str
        ``"SI"`` or ``"US"``.

    Returns
    -------
    str

    Examples
    --------
    >>> mass_text(4900.1, "US"), mass_text(2900.0, "SI")
    ('10803 lb', '2900 kg')
    """
    return quantity_text(round(value) if units == "SI" else round(value / POUND) * POUND,
                         "mass", units, digits=12)

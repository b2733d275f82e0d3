"""Engineering precision of report numbers: one Excel number format per unit.

Every report writes a number with the precision an engineer would write it by hand, chosen
from the unit beside it, never from the report: a force in N or lbf to the unit
(``12,345``), a length in m to the millimetre (``4.087``), an angle to a tenth of a degree.
The unit is read from the column header (the last ``[...]``, ``"Vy [lbf]"``) or, for a
table whose value column holds several kinds, from the row's ``unit`` column.

==========================================  =====================  ===================
quantity                                    units                  format (example)
==========================================  =====================  ===================
force, moment, stiffness, pressure (SI)     N, N m, N m/rad, Pa    ``#,##0`` (12,345)
force, moment (US)                          lbf, lbf in, lbf ft    ``#,##0`` (2,775)
force, moment (plots)                       kN, kN m, 1000 lbf ft  ``#,##0.00``
length                                      m                      ``0.000`` (4.087)
length                                      in, ft                 ``0.00`` (160.91)
altitude (a header naming one)              m, ft                  ``#,##0`` (1,524)
mass, inertia                               kg, lb, kg m^2, ...    ``#,##0.0``
angle                                       deg                    ``0.0`` (30.0)
angle                                       rad                    ``0.0000``
angular rate and acceleration               rad/s, rad/s^2         ``0.000``
angular rate                                deg/s                  ``0.00``
growth rate (real part of an eigenvalue)    1/s                    ``0.0000``
speed                                       m/s, kt, ft/s          ``0.0``
acceleration                                m/s^2, ft/s^2          ``0.00``
acceleration                                g                      ``0.000``
time                                        s                      ``0.00``
area                                        m^2                    ``0.000``
area                                        ft^2                   ``0.00``
density                                     kg/m^3                 ``0.0000``
density                                     slug/ft^3              ``0.000000``
ratio, factor, coefficient                  -                      ``0.000``
percentage                                  %                      ``0.0``
==========================================  =====================  ===================

Rules beside the table: a whole number (a Python or numpy integer: counts, case numbers) is
written without decimals; a non-zero ratio (unit ``-``) smaller than the format can show (a
relative difference of 3e-6) is written in scientific notation rather than as ``0.000``,
while a ratio below 1e-12, or a length or force too small for its format, is round-off and
shows as zero; a number whose unit is not
in the table keeps Excel's General format. The report can override any
column by name (closure residuals are scientific, ``0.00E+00``).
"""

from __future__ import annotations

import re

#: Excel number format by report unit label (as written between brackets in headers).
UNIT_FORMATS = {
    # forces, moments, stiffnesses, pressures: to the unit
    "N": "#,##0", "lbf": "#,##0", "N m": "#,##0", "lbf in": "#,##0", "lbf ft": "#,##0",
    "N m/rad": "#,##0", "N m/deg": "#,##0", "lbf in/rad": "#,##0", "lbf in/deg": "#,##0",
    "lbf ft/rad": "#,##0", "lbf ft/deg": "#,##0", "N/m": "#,##0", "lbf/in": "#,##0",
    "Pa": "#,##0", "kN": "#,##0.00", "kN m": "#,##0.00", "1000 lbf ft": "#,##0.00",
    "psf": "0.00",
    # lengths
    "m": "0.000", "in": "0.00", "ft": "0.00",
    # masses and inertias
    "kg": "#,##0.0", "lb": "#,##0.0", "kg m^2": "#,##0.0", "slug ft^2": "#,##0.0",
    "lb in^2": "#,##0",
    # angles, rates
    "deg": "0.0", "rad": "0.0000", "rad/s": "0.000", "rad/s^2": "0.000", "Hz": "0.000",
    "deg/s": "0.00", "1/s": "0.0000",
    # speeds, accelerations, time
    "m/s": "0.0", "kt": "0.0", "ft/s": "0.0", "m/s^2": "0.00", "ft/s^2": "0.00",
    "g": "0.000", "s": "0.00",
    # areas, densities
    "m^2": "0.000", "ft^2": "0.00", "kg/m^3": "0.0000", "slug/ft^3": "0.000000",
    # damping
    "N s/m": "#,##0.0", "lbf s/ft": "#,##0.0", "N m s/rad": "#,##0.0",
    "lbf ft s/rad": "#,##0.0", "lbf in s/rad": "#,##0",
    # dimensionless
    "-": "0.000", "%": "0.0", "1/deg": "0.0000", "1/rad": "0.0000",
}
#: Format of whole numbers (counts, case numbers).
INTEGER_FORMAT = "0"
#: Format of ratios too small for ``0.000``, and of residuals.
SCIENTIFIC_FORMAT = "0.00E+00"
#: Ratios smaller than this are round-off (a load factor of 1.5e-16) and show as zero. [-]
ROUND_OFF = 1e-12

_UNIT = re.compile(r"\[([^\[\]]*)\]")


def header_unit(header):
    """The unit label of a column header: the text of its last ``[...]``, or None.

    Examples
    --------
    >>> header_unit("Vy [lbf]"), header_unit("beta [deg] A=1.07 m^2 step"), header_unit("id")
    ('lbf', 'deg', None)
    """
    found = _UNIT.findall(str(header))
    return found[-1].strip() if found else None


def unit_format(unit):
    """Excel number format of a value in ``unit`` (a report unit label), or None (General)."""
    if unit is None:
        return None
    return UNIT_FORMATS.get(str(unit).strip())


#: Format of an altitude: to the whole metre or foot, as every sentence of a report quotes it
#: (``report.quantity_text``), never to the millimetre of a length.
ALTITUDE_FORMAT = "#,##0"


def header_format(header):
    """Excel number format of a column from its header: the unit's (:func:`unit_format`),
    but an altitude (a header naming one, in m or ft) to the whole unit.

    Parameters
    ----------
    header : str
        A column header, ``name [unit]``.

    Returns
    -------
    str or None
        The format (None: Excel's General).

    Examples
    --------
    >>> header_format("density altitude [m]"), header_format("cable length [m]")
    ('#,##0', '0.000')
    """
    unit = header_unit(header)
    if unit in ("m", "ft") and "altitude" in str(header).lower():
        return ALTITUDE_FORMAT
    return unit_format(unit)


def format_decimals(number_format):
    """Decimals shown by a fixed-point format (``"0.000"`` -> 3)."""
    if "E" in number_format or "." not in number_format:
        return 0
    return len(number_format.split(".")[1].rstrip("#")) if number_format else 0


def value_format(value, number_format, dimensionless=False):
    """The format of one number: ``number_format`` adapted to what the value is.

    Parameters
    ----------
    value : int or float
    number_format : str or None
        The column's (or row's) format.
    dimensionless : bool
        The value is a ratio (unit ``-``): a non-zero ratio too small for the fixed format is
        written in scientific notation. (A length or a force that small is round-off, and is
        written as zero.)

    Returns
    -------
    str or None
        :data:`INTEGER_FORMAT` style for whole numbers stored as integers, scientific for a
        small non-zero ratio, else ``number_format``.
    """
    if isinstance(value, bool) or number_format is None:
        return number_format
    if isinstance(value, int):
        return "#,##0" if number_format.startswith("#,##") else INTEGER_FORMAT
    if dimensionless and abs(value) >= ROUND_OFF and "E" not in number_format:
        if abs(value) < 0.5 * 10.0 ** -format_decimals(number_format):
            return SCIENTIFIC_FORMAT
    return number_format

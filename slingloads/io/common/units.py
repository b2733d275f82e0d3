"""Units at the boundary: unit strings from workbook headers to SI, and SI to report units.

Inside slingloads every quantity is SI (m, kg, s, N, rad). Units appear only where data
enter (workbook headers such as ``x [in]``) and where they leave (reports). Unit strings are
parsed by `pint <https://pint.readthedocs.io>`_, so any spelling pint knows is accepted
(``in``, ``inch``, ``ft``, ``lb``, ``lbf*in``, ``slug*ft^2``, ``kt``...), and each column
checks the dimension of its unit (a length column refuses ``kg``). The physical constants
and exact unit factors the physics uses (``G0``, ``KNOT``, ``FOOT``...) are in
:mod:`slingloads.constants`, which needs no unit library.
"""

from __future__ import annotations

import math
import re
from functools import lru_cache

import numpy as np

from slingloads.constants import FOOT, G0, INCH, KNOT, POUND, POUND_FORCE
from slingloads.errors import UnitError
from slingloads.io.common.formats import format_decimals, unit_format
from slingloads.limits import MAX_UNIT_CHARS

#: Quantity kinds and their SI unit, as pint strings.
SI_UNITS = {
    "length": "m",
    "mass": "kg",
    "force": "N",
    "moment": "N*m",
    "inertia": "kg*m^2",
    "angle": "rad",
    "speed": "m/s",
    "airspeed": "m/s",
    "altitude": "m",
    "acceleration": "m/s^2",
    "area": "m^2",
    "density": "kg/m^3",
    "time": "s",
    "frequency": "rad/s",
    "stiffness": "N/m",
    "linear damping": "N*s/m",
    "rotational damping": "N*m*s/rad",
    "dimensionless": "",
}

#: Report unit systems: the unit in which each kind is written.
REPORT_UNITS = {
    "SI": {
        "length": "m", "mass": "kg", "force": "N", "moment": "N*m", "inertia": "kg*m^2",
        "angle": "deg", "speed": "m/s", "airspeed": "kt", "altitude": "m",
        "acceleration": "m/s^2", "area": "m^2",
        "density": "kg/m^3", "time": "s", "frequency": "rad/s", "stiffness": "N/m",
        "linear damping": "N*s/m", "rotational damping": "N*m*s/rad", "dimensionless": "",
    },
    "US": {
        "length": "in", "mass": "lb", "force": "lbf", "moment": "lbf*in",
        "inertia": "lb*in^2", "angle": "deg", "speed": "ft/s", "airspeed": "kt",
        "altitude": "ft", "acceleration": "ft/s^2",
        "area": "ft^2", "density": "slug/ft^3", "time": "s", "frequency": "rad/s",
        "stiffness": "lbf/in", "linear damping": "lbf*s/ft",
        # the moments' family (lbf in), as the parachute sizing's yaw damping
        "rotational damping": "lbf*in*s/rad", "dimensionless": "",
    },
}

#: How report headers spell each unit (pint strings are not pretty).
UNIT_LABELS = {
    "N*m": "N m", "kg*m^2": "kg m^2", "lbf*in": "lbf in", "slug*ft^2": "slug ft^2",
    "lb*in^2": "lb in^2",
    "m/s^2": "m/s^2", "ft/s^2": "ft/s^2", "slug/ft^3": "slug/ft^3", "": "-",
    "N*s/m": "N s/m", "N*m*s/rad": "N m s/rad", "lbf*s/ft": "lbf s/ft",
    "lbf*ft*s/rad": "lbf ft s/rad", "lbf*in*s/rad": "lbf in s/rad",
}


_SLUG = POUND_FORCE / FOOT  # [kg]

#: Exact factors to SI of the units the template, the example and the reports spell, by
#: (unit as written, kind): read without building pint's registry (half a second or more
#: with the libraries pint probes on import). Any other spelling goes to pint;
#: tests/test_units.py checks that pint gives the same factors (to the last bits of a double:
#: the factors here are the exact definitions, pint's carry its rounding).
EXACT_FACTORS = {
    **{(kind, u): 1.0 for kind, u in (("length", "m"), ("mass", "kg"), ("force", "N"),
                                       ("moment", "N*m"), ("moment", "N m"),
                                       ("inertia", "kg*m^2"), ("inertia", "kg m^2"),
                                       ("angle", "rad"), ("speed", "m/s"),
                                       ("acceleration", "m/s^2"), ("area", "m^2"),
                                       ("density", "kg/m^3"), ("time", "s"),
                                       ("frequency", "rad/s"), ("stiffness", "N/m"),
                                       ("linear damping", "N*s/m"),
                                       ("linear damping", "N s/m"),
                                       ("rotational damping", "N*m*s/rad"),
                                       ("rotational damping", "N m s/rad"))},
    ("length", "ft"): FOOT, ("length", "in"): INCH, ("mass", "lb"): POUND,
    ("mass", "slug"): _SLUG, ("force", "lbf"): POUND_FORCE,
    ("moment", "lbf*in"): POUND_FORCE * INCH, ("moment", "lbf in"): POUND_FORCE * INCH,
    ("moment", "lbf*ft"): POUND_FORCE * FOOT, ("moment", "lbf ft"): POUND_FORCE * FOOT,
    # the parachute sizing plots' moment units
    ("moment", "kN*m"): 1000.0, ("moment", "kilolbf*ft"): 1000.0 * POUND_FORCE * FOOT,
    ("inertia", "slug*ft^2"): _SLUG * FOOT**2, ("inertia", "slug ft^2"): _SLUG * FOOT**2,
    ("inertia", "lb*in^2"): POUND * INCH**2, ("inertia", "lb in^2"): POUND * INCH**2,
    ("airspeed", "m/s"): 1.0, ("airspeed", "kt"): KNOT, ("altitude", "m"): 1.0,
    ("altitude", "ft"): FOOT,
    ("angle", "deg"): math.pi / 180.0, ("speed", "kt"): KNOT, ("speed", "ft/s"): FOOT,
    ("frequency", "1/s"): 1.0, ("frequency", "deg/s"): math.pi / 180.0,
    ("acceleration", "ft/s^2"): FOOT, ("acceleration", "g0"): G0,
    ("area", "ft^2"): FOOT**2, ("area", "in^2"): INCH**2,
    ("density", "slug/ft^3"): _SLUG / FOOT**3, ("stiffness", "lbf/in"): POUND_FORCE / INCH,
    ("linear damping", "lbf*s/ft"): POUND_FORCE / FOOT,
    ("rotational damping", "lbf*ft*s/rad"): POUND_FORCE * FOOT,
    ("rotational damping", "lbf*in*s/rad"): POUND_FORCE * INCH,
}


#: SI units a sentence of a report may quote after a number, longest spelling first, and
#: their quantity kind.
_TEXT_UNITS = {"N m s/rad": "rotational damping", "N m/rad": "rotational stiffness",
               "kg m^2": "inertia", "kg/m^3": "density", "m/s^3": "jerk",
               "m/s^2": "acceleration", "m/s": "speed", "m^2": "area", "kN m": None,
               "N m": "moment", "kN": None, "kg": "mass", "m": "length", "N": "force"}
#: A quoted number: with thousands separators (``443,995``) or without, whole, as the
#: sentence wrote it (never its last group alone).
_QUOTED = re.compile(r"(?<![\w.^/,])(-?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[+-]?\d+)?) ?("
                     + "|".join(re.escape(u) for u in _TEXT_UNITS) + r")(?![\w^/])")


#: The words that make a quoted length an altitude (``density altitude 1524 m``).
_ALTITUDE = re.compile(r"altitude (?:of )?$")


def _quoted_number(value):
    """A converted number in a sentence: 4 significant digits, whole above 1,000."""
    return f"{value:,.0f}" if abs(value) >= 1000 else f"{value:.4g}"


def cell_number(value, unit):
    """A number in ``unit`` (a report unit label) for a sentence, at the precision of that
    unit's cells (formats.py), trailing zeros dropped: the one spelling of a length in a
    sentence, so that it reads as the cell beside it.

    Examples
    --------
    >>> cell_number(18.288, "m"), cell_number(80.9063, "m"), cell_number(3185.04, "in")
    ('18.288', '80.906', '3,185.04')
    >>> cell_number(720.0, "in"), cell_number(1.0, "m")
    ('720', '1')
    """
    number = f"{float(value):,.{format_decimals(unit_format(unit) or '0.000')}f}"
    return number.rstrip("0").rstrip(".") if "." in number else number


def _length_text(match, number, unit, text):
    """A length quoted in ``text`` (``number`` in ``unit``) at its cells' precision; an
    altitude (``density altitude 0 m``) and a length too small for that precision as
    written."""
    if _ALTITUDE.search(text, 0, match.start()):
        return None
    decimals = format_decimals(unit_format(unit) or "0.000")
    if number != 0.0 and abs(number) < 0.5 * 10.0 ** -decimals:
        return None
    return f"{cell_number(number, unit)} {unit}"


#: Decimals of an area in a report, in a sentence as in its cells (formats.py: ``0.000``
#: m^2, ``0.00`` ft^2), so that an area quoted in a note reads as the cell beside it.
_AREA_DECIMALS = {"SI": 3, "US": 2}


def _area_number(value, units):
    return f"{value:,.{_AREA_DECIMALS[units]}f}"


def report_text(text, units):
    """A sentence of a report with its quoted SI quantities (``"step 9.14 m/s"``) in the
    report unit system (``"step 30 ft/s"`` in US units); unchanged in SI but for the areas
    and the lengths (not altitudes), which a sentence quotes at the precision of their cells
    in both systems (the analyses quote them with 6 significant digits so that the
    conversion does not round twice; :func:`cell_number`).

    Examples
    --------
    >>> report_text("quintic step 0.04246 m over 0.5 s (peak 0.9807 m/s^2)", "US")
    'quintic step 1.67 in over 0.5 s (peak 3.218 ft/s^2)'
    >>> report_text("cycloidal step 80.9063 m over 12 s", "SI")
    'cycloidal step 80.906 m over 12 s'
    >>> report_text("load scale 443,995 N m; peak jerk <= 1.94 m/s^3", "US")
    'load scale 3,929,687 lbf in; peak jerk <= 6.365 ft/s^3'
    >>> report_text("k = -15.2 N m/rad, c = 2,000 N m s/rad", "US")
    'k = -134.5 lbf in/rad, c = 17,701 lbf in s/rad'
    >>> report_text("chosen 2.52453 m^2 (fit 0.148632 m^2)", "SI")
    'chosen 2.525 m^2 (fit 0.149 m^2)'
    >>> report_text("chosen 2.52453 m^2", "US")
    'chosen 27.17 ft^2'
    >>> report_text("density altitude 1524 m, cable 18.29 m", "US")
    'density altitude 5,000 ft, cable 720.08 in'
    """
    if not isinstance(text, str) or not any(c.isdigit() for c in text):
        return text
    if units != "US":
        def keep(m):
            number = float(m.group(1).replace(",", ""))
            if m.group(2) == "m^2":
                return f"{_area_number(number, 'SI')} m^2"
            if m.group(2) == "m":
                return _length_text(m, number, "m", text) or m.group(0)
            return m.group(0)

        return _QUOTED.sub(keep, text)

    def convert(match):
        kind = _TEXT_UNITS[match.group(2)]
        if kind is None:
            return match.group(0)
        number = float(match.group(1).replace(",", ""))
        if kind == "length" and _ALTITUDE.search(text, 0, match.start()):
            # an altitude is its own quantity (ft in US units, to the foot), never inches
            return f"{number / FOOT:,.0f} ft"
        if kind == "length":  # at the precision of a length's cell (0.00 in)
            inches = number / INCH
            return _length_text(match, inches, "in", text) or f"{_quoted_number(inches)} in"
        if kind == "jerk":  # a rate of acceleration, in the acceleration's family
            return f"{_quoted_number(number / FOOT)} ft/s^3"
        if kind == "area":  # at the precision of an area's cell (0.00 ft^2)
            return f"{_area_number(number / FOOT ** 2, 'US')} ft^2"
        if kind == "rotational stiffness":  # a moment per radian, in the moments' unit
            return f"{_quoted_number(number / (POUND_FORCE * INCH))} lbf in/rad"
        unit = REPORT_UNITS["US"][kind]
        value = number * si_factor(match.group(2).replace(" ", "*"), kind)
        return f"{_quoted_number(value / si_factor(unit, kind))} {unit_label(unit)}"

    return _QUOTED.sub(convert, text)


@lru_cache(maxsize=1)
def _registry():
    """pint's unit registry, built on first use (it parses pint's definitions file)."""
    import pint

    return pint.UnitRegistry()


def unit_label(unit):
    """Human spelling of a pint unit string, for report headers."""
    return UNIT_LABELS.get(unit, unit)


@lru_cache(maxsize=512)
def si_factor(unit, kind):
    """Factor that converts a value in ``unit`` to the SI unit of ``kind``.

    Parameters
    ----------
    unit : str
        Unit string as written by a user (``"in"``, ``"lbf*in"``, ``"-"`` for none), at most
        :data:`slingloads.limits.MAX_UNIT_CHARS` characters.
    kind : str
        One of the keys of :data:`SI_UNITS`.

    Returns
    -------
    float
        Multiply a value in ``unit`` by this to get SI: finite and > 0.

    Raises
    ------
    UnitError
        If the unit is unknown, malformed (``kg/0``, ``kg**0``, unbalanced brackets), too
        long, an offset unit (``degC``), its dimension does not fit ``kind``, or its factor is
        not a finite positive number (``percent**1000``).
    """
    if kind not in SI_UNITS:
        raise UnitError(f"unknown quantity kind; valid kinds are {sorted(SI_UNITS)}", kind)
    if not isinstance(unit, str):
        raise UnitError("a unit must be text", unit)
    text = unit.strip()
    if len(text) > MAX_UNIT_CHARS:
        raise UnitError(f"a unit must have at most {MAX_UNIT_CHARS} characters",
                        unit[:MAX_UNIT_CHARS] + "...")
    if text in ("", "-", "1"):
        text = ""
    if kind == "dimensionless" and text == "":
        return 1.0
    if text == "":
        raise UnitError(f"a {kind} needs a unit, such as {SI_UNITS[kind]!r}", unit)
    factor = EXACT_FACTORS.get((kind, text))
    if factor is None:
        factor = _pint_factor(engineering_spelling(text, kind), kind, unit)
    if not (math.isfinite(factor) and factor > 0):
        raise UnitError(f"unit has no usable factor to {SI_UNITS[kind] or 'a pure number'} "
                        f"(it converts with {factor!r}; a unit must scale by a finite "
                        "positive factor)", unit)
    return factor


#: Kinds whose dimension holds a force: there US engineers write ``lb`` for pound-force.
_FORCE_KINDS = ("force", "moment", "stiffness", "linear damping", "rotational damping")
_HYPHEN = re.compile(r"(?<=[A-Za-z])-(?=[A-Za-z])")
_BARE_POWER = re.compile(r"(?<=[A-Za-z])([23])\b")
_POUND = re.compile(r"\blbs?\b")
_POUND_MASS = re.compile(r"\blbm\b")
_HERTZ = re.compile(r"\b(k|M)?Hz\b")


def engineering_spelling(text, kind):
    """Unit spellings of engineering practice rewritten for pint.

    ``in-lb``, ``lb-in``, ``ft-lbf`` (a hyphen between two unit names is a product);
    ``ft2``, ``in3`` (a bare power 2 or 3 after a unit name); ``lbm`` (pound-mass); and
    ``lb`` / ``lbs`` in a quantity that holds a force (force, moment, stiffness, damping),
    where it means pound-force as on US drawings (pint's ``lb`` is the pound-mass); ``Hz``
    in an angular rate is a cycle per second, 2 pi rad/s (pint would read it as 1/s = 1
    rad/s).
    """
    text = _HYPHEN.sub("*", text)
    text = _BARE_POWER.sub(r"^\1", text)
    text = _POUND_MASS.sub("lb", text)
    if kind in _FORCE_KINDS:
        text = _POUND.sub("lbf", text)
    if kind == "frequency":  # an angular rate: one hertz is one cycle, 2 pi rad, per second
        text = _HERTZ.sub(lambda m: f"({m.group(1) or ''}revolution/s)", text)
    return text


def _pint_factor(text, kind, unit):
    """pint's conversion factor of ``text`` to the SI unit of ``kind``, or a UnitError."""
    import pint

    try:
        quantity = _registry().Quantity(1.0, text)
        if not quantity.unitless and not quantity._is_multiplicative:
            raise UnitError("offset units (degC, degF) are not accepted", unit)
        return float(quantity.to(SI_UNITS[kind] or "dimensionless").magnitude)
    except UnitError:
        raise
    except pint.errors.DimensionalityError:
        raise UnitError(
            f"unit is not a {kind} (expected something convertible to {SI_UNITS[kind]!r})",
            unit,
        ) from None
    except Exception:  # noqa: BLE001 - pint parses arbitrary text: any failure is a bad unit
        # (seen: ZeroDivisionError for kg/0, KeyError for kg**0, RecursionError for deep
        # brackets, OverflowError for percent**-200, OffsetUnitCalculusError)
        hint = ("; a unit is written with unit names and powers only, never a numeric "
                "factor (write 'in', not '0.0254*m')" if _FACTOR.search(unit) else "")
        raise UnitError(f"unknown unit (or a malformed unit expression){hint}", unit) from None


#: A number standing as a factor in a unit expression (``0.0254*m``, ``2 m``, ``1e999 kg``),
#: not a power (``m^2``, ``m**2``).
_FACTOR = re.compile(r"(?:^|[\s*/(])[0-9.]")


def to_si(values, unit, kind):
    """Convert ``values`` given in ``unit`` to SI for a quantity of ``kind``.

    Angles in degrees become radians; temperatures are not supported (no offset units).
    """
    return np.asarray(values, dtype=float) * si_factor(unit, kind)


def from_si(values, unit, kind):
    """Convert SI ``values`` of ``kind`` to ``unit`` (the inverse of :func:`to_si`)."""
    return np.asarray(values, dtype=float) / si_factor(unit, kind)

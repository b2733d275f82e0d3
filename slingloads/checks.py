"""Small validators shared by the models: each returns the value as a float or raises
:class:`~slingloads.errors.InputError` that states the rule and echoes the value."""

from __future__ import annotations

import math

from slingloads.errors import InputError


def finite(value, rule):
    """``value`` as a finite float, else ``InputError(rule, value)``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(rule, value) from None
    if not math.isfinite(number):
        raise InputError(rule, number)
    return number


def positive(value, rule):
    """``value`` as a float > 0, else ``InputError(rule, value)``."""
    number = finite(value, rule)
    if number <= 0:
        raise InputError(rule, number)
    return number


def non_negative(value, rule):
    """``value`` as a float >= 0, else ``InputError(rule, value)``."""
    number = finite(value, rule)
    if number < 0:
        raise InputError(rule, number)
    return number

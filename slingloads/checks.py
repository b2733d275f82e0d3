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


def frozen(values, dtype=float):
    """A read-only copy of ``values`` as a numpy array.

    The arrays of the model objects are frozen so that a change goes through the object's
    constructor (``dataclasses.replace`` or a ``with_...`` helper), which checks it:
    ``items.mass[0] = -5`` raises ``ValueError: assignment destination is read-only``.
    """
    import numpy as np

    out = np.array(values, dtype=dtype)
    out.flags.writeable = False
    return out

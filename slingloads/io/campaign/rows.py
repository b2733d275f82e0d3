"""The campaign's Study rows checked for every workbook whether it runs or not
(:meth:`slingloads.io.analyses.Analysis.check_rows`): its choice rows, the form of each list row
(its numbers within their bounds), the helicopters without parachute and the scheduler's address
(also checked by the command line's ``--scheduler``). A light module: it imports no analysis
and no numerical library beyond numpy, so that the check costs nothing to a study that does not
run the campaign (its reader, imported when it runs, takes them from here)."""

from __future__ import annotations

import re

import numpy as np

from slingloads.io.campaign.schema import (
    HOOK_ANGLE_SOURCES,
    LIST_BOUNDS,
    LISTS,
    MATRIX_KINDS,
    SAMPLE_HELICOPTERS,
)
from slingloads.io.common.locate import Place, located
from slingloads.io.common.schema import STUDY_SHEET, TEXT
from slingloads.io.common.table import cell_name
from slingloads.io.common.units import si_factor
from slingloads.io.common.values import check_quantity, number_from_text
from slingloads.limits import MAX_LIST_ITEMS

#: Valid values of each choice row of this analysis's Study rows (case ignored), checked
#: for every workbook, whether the analysis runs or not
#: (:meth:`~slingloads.io.analyses.Analysis.check_rows`).
CHOICES = {
    "campaign matrix": MATRIX_KINDS,
    "campaign loads hook angle": HOOK_ANGLE_SOURCES,
}

#: A Dask scheduler address: ``[protocol://]host[:port]``.
_ADDRESS = re.compile(r"^(?:(?:tcp|tls)://)?(?:[A-Za-z0-9](?:[A-Za-z0-9.-]{0,252})"
                      r"|\[[0-9A-Fa-f:.]{2,45}\])(?::(?P<port>[0-9]{1,5}))?$")


def address_rule(address):
    """The rule a scheduler address breaks, or None if it is well formed."""
    match = _ADDRESS.match(address)
    if match is None:
        if re.match(r"^(?:ws|wss|ucx|inproc)://", address, re.I):
            return ("a scheduler on the ws, wss, ucx or inproc protocol is not supported: "
                    "slingloads reads the scheduler's first answer itself, in bounded time "
                    "and memory, over tcp:// or tls:// only (start the scheduler with "
                    "--protocol tcp)")
        return ("not a scheduler address; write [protocol://]host[:port], e.g. "
                "tcp://10.0.0.5:8786 (protocols tcp, tls)")
    port = match.group("port")
    if port is not None and not 1 <= int(port) <= 65535:
        return "the scheduler's port must be in [1, 65535]"
    return None


def list_parameter(params, name):
    """A comma-separated Study list: names (text lists) or SI numbers (unit column).

    At most :data:`~slingloads.limits.MAX_LIST_ITEMS` values; each number is checked at the
    list's cell against its kind's magnitude and the list's :data:`LIST_BOUNDS`, the value
    shown as written with the unit of the row.

    Returns
    -------
    list
    """
    kind = LISTS[name]
    raw = params(name)
    text = "" if raw is None else str(raw)
    items = [s.strip() for s in text.split(",") if s.strip()]
    if not items:
        raise params.error(name, f"{name!r} needs at least one value (comma-separated)", text)
    if len(items) > MAX_LIST_ITEMS:
        raise params.error(name, f"{name!r} lists {len(items):,} values; at most "
                           f"{MAX_LIST_ITEMS} are allowed (limits of slingloads)")
    if kind == TEXT:
        return items
    spec = params.specs[name.lower()]
    cell = params.cell(name)
    if cell is None:
        unit = spec.unit
        where = "(default)"
    else:
        row = int("".join(ch for ch in cell if ch.isdigit()))
        unit = params.unit(name) or ""
        where = cell_name(row, 3)
        if kind != "dimensionless" and not unit.strip():
            raise params.reader.error(f"{name!r} needs a unit in its unit column, e.g. "
                                      f"{spec.unit!r}", None, STUDY_SHEET, where)
    with located(Place(params.reader.file, STUDY_SHEET, where, unit)):  # the unit cell
        factor = si_factor(unit, kind)
    values = []
    for item in items:
        value = number_from_text(item)
        if value is None:
            raise params.error(name, f"{name!r}: every value must be a number", item)
        if not np.isfinite(value):
            raise params.error(name, f"{name!r}: every value must be a finite number", item)
        values.append(check_quantity(value, item, kind, factor, unit.strip(),
                                     LIST_BOUNDS.get(name), spec.unit,
                                     f"every value of {name!r}", params.reader.error,
                                     STUDY_SHEET, params.where(name)))
    return values


def gust_ramps(params):
    """Targets of the ramps with a gust [m/s]: the list, or none ('none')."""
    name = "campaign no-parachute gust ramps"
    raw = params(name)
    if str("" if raw is None else raw).strip().lower() == "none":
        return []
    return list_parameter(params, name)


def check_scheduler(params):
    """'campaign scheduler' is empty or a well-formed address."""
    scheduler = str(params("campaign scheduler") or "").strip()
    if scheduler:
        rule = address_rule(scheduler)
        params.check("campaign scheduler", rule is None, f"'campaign scheduler': {rule}")
    return scheduler


def check_helicopters(params):
    """'campaign no-parachute helicopters' is 'none' or a list of known sample helicopters."""
    name = "campaign no-parachute helicopters"
    helicopters = [h.upper() for h in list_parameter(params, name)]
    if helicopters != ["NONE"]:
        for h in helicopters:
            if h not in SAMPLE_HELICOPTERS:
                raise params.error(name, "unknown helicopter; valid are "
                                   f"{list(SAMPLE_HELICOPTERS)} or 'none'", h)
    return helicopters


#: The campaign's Study rows whose rules need no sheet, checked for every workbook whether
#: the campaign runs or not (:meth:`slingloads.io.analyses.Analysis.check_rows`), besides
#: its CHOICES: the form of each list (its numbers within their bounds), the helicopters,
#: the scheduler's address.
ROW_CHECKS = {
    **{name: (lambda params, name=name: list_parameter(params, name))
       for name in LISTS if name not in ("campaign no-parachute gust ramps",
                                         "campaign no-parachute helicopters")},
    "campaign no-parachute gust ramps": lambda params: gust_ramps(params),
    "campaign no-parachute helicopters": check_helicopters,
    "campaign scheduler": check_scheduler,
}

"""The choice rows of the multibody model's Study rows, checked for every workbook whether it runs
or not (:meth:`slingloads.io.analyses.Analysis.check_rows`). A light module: it imports no
analysis and no numerical library beyond numpy and pandas, so that the check costs nothing to a
study that does not run the multibody model (its reader, imported when it runs, takes them from
here)."""

from __future__ import annotations

from slingloads.io.multibody.schema import (
    CANOPY_TABLES,
    CARRIERS,
    CONFIGURATIONS,
    PARACHUTE_MODELS,
    TAILS,
)

#: Valid values of each choice row of this analysis's Study rows (case ignored), checked
#: for every workbook, whether the analysis runs or not
#: (:meth:`~slingloads.io.analyses.Analysis.check_rows`).
CHOICES = {
    "multibody configuration": CONFIGURATIONS,
    "multibody tail": TAILS,
    "multibody parachute model": PARACHUTE_MODELS,
    "multibody canopy CD": CANOPY_TABLES,
    "multibody carrier": CARRIERS,
}

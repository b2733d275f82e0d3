"""The choice rows of the lateral study's Study rows, checked for every workbook whether it runs
or not (:meth:`slingloads.io.analyses.Analysis.check_rows`). A light module: it imports no
analysis and no numerical library beyond numpy and pandas, so that the check costs nothing to a
study that does not run the lateral study (its reader, imported when it runs, takes them from
here)."""

from __future__ import annotations

from slingloads.analyses.lateral_damping import DAMPING_SOURCES
from slingloads.io.lateral.schema import CABLE_MODELS, SOLVER_METHODS

#: Valid values of each choice row of this analysis's Study rows (case ignored), checked
#: for every workbook, whether the analysis runs or not
#: (:meth:`~slingloads.io.analyses.Analysis.check_rows`).
CHOICES = {
    "lateral cable model": CABLE_MODELS,
    "lateral history method": SOLVER_METHODS,
    "lateral damping source": DAMPING_SOURCES,
}

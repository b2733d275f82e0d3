"""The choice rows of the structural loads' Study rows, checked for every workbook whether it runs
or not (:meth:`slingloads.io.analyses.Analysis.check_rows`). A light module: it imports no
analysis and no numerical library beyond numpy and pandas, so that the check costs nothing to a
study that does not run the structural loads (its reader, imported when it runs, takes them from
here)."""

from __future__ import annotations

from slingloads.analyses.fe_loads import HOOK_POINTS
from slingloads.analyses.hook_loads import CONE_SHAPES
from slingloads.analyses.loads import CHUTE_LINE_DIRECTIONS
from slingloads.io.loads.nastran import INERTIA_RELIEF
from slingloads.models.attitude import ATTITUDE_SOURCES

#: Valid values of each choice row of this analysis's Study rows (case ignored), checked
#: for every workbook, whether the analysis runs or not
#: (:meth:`~slingloads.io.analyses.Analysis.check_rows`).
CHOICES = {
    "parachute line direction": CHUTE_LINE_DIRECTIONS,
    "hook cone shape": CONE_SHAPES,
    "attitude": (*ATTITUDE_SOURCES, "given"),
    "nastran inertia relief": INERTIA_RELIEF,
    "nastran hook load at": HOOK_POINTS,
}

"""The choice rows of the parachute sizing's Study rows, checked for every workbook whether it runs
or not (:meth:`slingloads.io.analyses.Analysis.check_rows`). A light module: it imports no
analysis and no numerical library beyond numpy and pandas, so that the check costs nothing to a
study that does not run the parachute sizing (its reader, imported when it runs, takes them from
here)."""

from __future__ import annotations

from slingloads.io.chute.schema import INERTIA_SOURCES, INTEGRATORS, SEVERITIES, WAKE_SOURCES
from slingloads.models.integration import SOLVE_IVP_METHODS
from slingloads.models.yaw_dynamics import YAW_AXES

#: Valid values of each choice row of this analysis's Study rows (case ignored), checked
#: for every workbook, whether the analysis runs or not
#: (:meth:`~slingloads.io.analyses.Analysis.check_rows`).
CHOICES = {
    "chute sizing yaw axis": YAW_AXES,
    "chute sizing yaw inertia source": INERTIA_SOURCES,
    "chute sizing wake source": WAKE_SOURCES,
    "chute sizing integrator": INTEGRATORS,
    "chute sizing reference method": SOLVE_IVP_METHODS,
    "chute sizing turbulence severity": SEVERITIES,
}

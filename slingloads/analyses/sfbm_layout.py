"""The rigid-body vector of the free-free internal loads: one table, read by the numpy pipeline
(:mod:`slingloads.analyses.sfbm`) and the compiled kernel
(:mod:`slingloads.analyses.sfbm_kernel`) by name (:mod:`slingloads.models.packed`)."""

from __future__ import annotations

from slingloads.models.packed import BODY, TENSOR, Field, Layout

#: The rigid-body vector ``rigid`` of :func:`slingloads.analyses.sfbm.free_free_rows_numpy`
#: and of the compiled kernel.
RIGID = Layout((
    Field("cg", "m", "CG relative to the axis point (0, y0, z0)", BODY),
    Field("gravity_force", "N", "resultant force of gravity", BODY),
    Field("gravity_moment", "N m", "moment of gravity about the CG", BODY),
    Field("inv_mass", "1/kg", "1 / total mass"),
    Field("inv_inertia", "1/(kg m^2)", "inverse inertia tensor about the CG", TENSOR),
))
R_CG, R_FORCE, R_MOMENT = RIGID["cg"], RIGID["gravity_force"], RIGID["gravity_moment"]
R_INV_MASS, R_INV_INERTIA = RIGID["inv_mass"], RIGID["inv_inertia"]

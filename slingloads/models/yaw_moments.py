"""The yawing moments of the 1-DOF yaw model (fuselage, fin, parachute) and the model row
that carries its parameters, written once for numpy
(:meth:`slingloads.models.yaw_dynamics.YawModel.moments`) and for the compiled batches
(:mod:`slingloads.models.yaw_batch`), so that neither imports the other."""

from __future__ import annotations

import numpy as np

from slingloads.models.packed import Field, Layout

#: The model row ``M`` of :func:`make_yaw_moments` (:mod:`slingloads.models.packed`).
LAYOUT = Layout((
    Field("half_rho", "kg/m^3", "half the air density"),
    Field("inertia", "kg m^2", "yaw inertia about the suspension axis"),
    Field("has_fus", "-", "1: the fuselage is modelled"),
    Field("has_fin", "-", "1: the fin is modelled"),
    Field("fin_local", "-", "1: the fin at its local sideslip (yaw-rate damping)"),
    Field("has_chute", "-", "1: the parachute is modelled"),
    Field("fin_dx", "m", "fin arm from the suspension axis, x"),
    Field("fin_dy", "m", "fin arm from the suspension axis, y"),
    Field("fin_lo", "rad", "lower end of the fin table"),
    Field("fin_hi", "rad", "upper end of the fin table"),
    Field("chute_cd", "-", "parachute drag coefficient times wake ratio"),
    Field("chute_dx", "m", "parachute arm from the suspension axis, x"),
    Field("chute_dy", "m", "parachute arm from the suspension axis, y"),
    Field("fus_lo", "rad", "lower end of the fuselage table"),
    Field("fus_hi", "rad", "upper end of the fuselage table"),
    Field("tas", "m/s", "true airspeed"),
    Field("weight_c", "N m", "weight's moment about the suspension axis at psi = 0 (the trim's)"),
    Field("weight_s", "N m", "weight's moment about the suspension axis, sin(psi) term"),
))
HALF_RHO, INERTIA = LAYOUT["half_rho"], LAYOUT["inertia"]
HAS_FUS, HAS_FIN, FIN_LOCAL = LAYOUT["has_fus"], LAYOUT["has_fin"], LAYOUT["fin_local"]
HAS_CHUTE = LAYOUT["has_chute"]
FIN_DX, FIN_DY, FIN_LO, FIN_HI = (LAYOUT["fin_dx"], LAYOUT["fin_dy"], LAYOUT["fin_lo"],
                                  LAYOUT["fin_hi"])
CHUTE_CD, CHUTE_DX, CHUTE_DY = LAYOUT["chute_cd"], LAYOUT["chute_dx"], LAYOUT["chute_dy"]
FUS_LO, FUS_HI, TAS = LAYOUT["fus_lo"], LAYOUT["fus_hi"], LAYOUT["tas"]
WEIGHT_C, WEIGHT_S = LAYOUT["weight_c"], LAYOUT["weight_s"]
#: Length of a model row.
N_MODEL = len(LAYOUT)


def make_yaw_moments(lookup):
    """The yawing moments of the model, written once for numpy and for the compiled batches.

    The returned function uses elementwise operations only, so that it runs on arrays (numpy,
    :meth:`slingloads.models.yaw_dynamics.YawModel.moments`) and, compiled by numba, on floats
    (:func:`slingloads.models.yaw_batch.yaw_acceleration`); only the table lookup differs
    (``numpy.interp``, or the compiled search from the interval found last: the same
    numbers).

    Parameters
    ----------
    lookup : callable
        ``lookup(x, xp, fp, slope, lo, k)``: ``fp`` interpolated linearly on ``xp`` at ``x``
        (end values outside), ``slope`` the slopes of the segments, ``lo[k]`` the interval
        found last by lookup ``k`` (0 fuselage, 1 fin).

    Returns
    -------
    callable
        ``moments(beta, rate, v_rel, area, M, fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, lo)``
        of the sideslip at the axis [rad], the yaw rate [rad/s], the relative airspeed
        [m/s], the parachute area [m^2], the model row ``M`` (:data:`LAYOUT`) and the tables
        (:meth:`slingloads.models.yaw_dynamics.YawModel.arrays`), returning the fuselage,
        fin and parachute moments [N m] and whether every table was read inside its range.
    """

    def moments(beta, rate, v_rel, area, M, fus_x, fus_n, fus_s, fin_x, fin_k, fin_s, lo):
        half_rho = M[HALF_RHO]
        q = half_rho * (v_rel * v_rel)
        inside = True
        n_fus = 0.0
        n_fin = 0.0
        n_chute = 0.0
        if M[HAS_FUS] != 0.0:
            n_fus = q * lookup(beta, fus_x, fus_n, fus_s, lo, 0)
            inside = inside & (beta >= M[FUS_LO]) & (beta <= M[FUS_HI])  # False for NaN
        ux0 = v_rel * np.cos(beta)
        uy0 = -v_rel * np.sin(beta)
        if M[HAS_FIN] != 0.0:
            dx, dy = M[FIN_DX], M[FIN_DY]
            beta_f, q_f = beta, q
            if M[FIN_LOCAL] != 0.0:
                ux = ux0 - rate * dy
                uy = uy0 + rate * dx
                beta_f = np.arctan2(-uy, ux)
                q_f = half_rho * (ux * ux + uy * uy)
            n_fin = (-dx * q_f) * lookup(beta_f, fin_x, fin_k, fin_s, lo, 1)
            inside = inside & (beta_f >= M[FIN_LO]) & (beta_f <= M[FIN_HI])
        if M[HAS_CHUTE] != 0.0:
            dx, dy = M[CHUTE_DX], M[CHUTE_DY]
            ux = ux0 - rate * dy
            uy = uy0 + rate * dx
            scale = (half_rho * M[CHUTE_CD]) * area * np.sqrt(ux * ux + uy * uy)
            n_chute = scale * (dy * ux - dx * uy)
        return n_fus, n_fin, n_chute, inside

    return moments


def weight_moment(psi, M):
    """The change of the weight's yawing moment about the suspension axis from psi = 0 (nose
    right positive), ``W_c (cos(psi) - 1) + W_s sin(psi)`` with the model row's ``weight_c``
    and ``weight_s`` (:class:`slingloads.models.yaw_dynamics.YawModel`): the moment at psi = 0
    belongs to the trim. Elementwise, for numpy and compiled code.

    Parameters
    ----------
    psi : float or ndarray
        Yaw, nose right positive. [rad]
    M : ndarray, shape (N_MODEL,)
        The model row (:data:`LAYOUT`). [SI]

    Returns
    -------
    float or ndarray
        [N m]
    """
    return M[WEIGHT_C] * (np.cos(psi) - 1.0) + M[WEIGHT_S] * np.sin(psi)


def _numpy_lookup(x, xp, fp, slope, lo, k):
    """The lookup of :func:`make_yaw_moments` in numpy."""
    return np.interp(x, xp, fp)


#: :func:`make_yaw_moments` with numpy's interpolation: the moments of arrays of states, from
#: the same source as the compiled batches' (used by
#: :meth:`slingloads.models.yaw_dynamics.YawModel.moments`).
numpy_moments = make_yaw_moments(_numpy_lookup)

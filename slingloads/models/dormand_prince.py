"""The Dormand-Prince 5(4) Runge-Kutta pair of every adaptive compiled integrator.

The tableau is the one of scipy's ``RK45``: J. R. Dormand and P. J. Prince, "A family of
embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26; the dense-output
matrix ``P`` is the one of ``scipy.integrate.RK45`` (L. F. Shampine, "Some practical
Runge-Kutta formulas", Math. Comp. 46 (1986)). The arithmetic of the pair is written here once,
as compiled functions on a state of n elements and the stage derivatives ``K`` (7, n):

* :func:`stage`: the argument of stage i, ``x + h sum_j a_ij K_j``;
* :func:`error_norm`: the root mean square over the states of the local error estimate
  ``h sum_i e_i K_i`` scaled by ``atol + rtol max(|x|, |x_new|)``, the norm of scipy's
  ``RK45``;
* :func:`shrink` and :func:`grow`: the step-size factors after a rejected and an accepted
  step (safety factor 0.9, exponent -1/5, at most tenfold growth, no growth right after a
  rejection, at least a fifth);
* :func:`dense`: the fourth-order dense output at a fraction theta of the step.

The integrators of the multibody model (:mod:`slingloads.models.multibody.integrator`) and of
the yaw sweep (:mod:`slingloads.models.yaw_batch`) are built on them; what differs between
them is what their models need around a step (the segments between the inputs' jumps, the
samples, what a run that leaves its tables does). The tableau is read by the compiled
functions as constants, and the functions are inlined into the integrators at numba's level
(``inline="always"``: no call, no reference counting of the arrays handed on).
"""

import math

import numba
import numpy as np

_jit = numba.njit(cache=True, fastmath=False, nogil=True, inline="always")

#: Nodes c_i of the seven stages (the seventh is the first of the next step). [-]
C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0])
#: Stage coefficients a_ij. [-]
A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 5, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3 / 40, 9 / 40, 0.0, 0.0, 0.0, 0.0],
    [44 / 45, -56 / 15, 32 / 9, 0.0, 0.0, 0.0],
    [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0, 0.0],
    [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0.0],
    [35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]])
#: Error weights: fifth-order minus fourth-order weights. [-]
E = np.array([-71 / 57600, 0.0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40])
#: Dense output: stage weights as cubic polynomials of the step fraction. [-]
P = np.array([
    [1.0, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
    [0.0, 0.0, 0.0, 0.0],
    [0.0, 131558114200 / 32700410799, -68118460800 / 10900136933,
     87487479700 / 32700410799],
    [0.0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
    [0.0, 127303824393 / 49829197408, -318862633887 / 49829197408,
     701980252875 / 199316789632],
    [0.0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
    [0.0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423]])

#: Safety factor of the step-size control. [-]
SAFETY = 0.9
#: Largest and smallest step-size factors. [-]
MAX_FACTOR, MIN_FACTOR = 10.0, 0.2


@_jit
def stage(x, h, K, i, acc, out):
    """Argument of stage ``i`` (1 to 6) into ``out`` (n,): ``x + h sum_{j<i} a_ij K_j``.

    Parameters
    ----------
    x : ndarray, shape (n,)
        State at the step's start.
    h : float
        Step. [s]
    K : ndarray, shape (7, n)
        Stage derivatives, rows 0 to i - 1 filled.
    i : int
        Stage, 1 to 6 (6: the fifth-order solution).
    acc, out : ndarray, shape (n,)
        Work array; receives the argument.
    """
    n = x.size
    for m in range(n):
        acc[m] = 0.0
    for j in range(i):
        a = A[i, j]
        for m in range(n):
            acc[m] += a * K[j, m]
    for m in range(n):
        out[m] = x[m] + h * acc[m]


@_jit
def error_norm(x, x_new, K, h, rtol, atol, acc):
    """Root mean square of the scaled local error estimate of a step.

    Parameters
    ----------
    x, x_new : ndarray, shape (n,)
        States at the step's start and end (fifth order).
    K : ndarray, shape (7, n)
        The seven stage derivatives.
    h : float
        Step. [s]
    rtol, atol : float
        Relative [-] and absolute (units of the states) tolerances.
    acc : ndarray, shape (n,)
        Work array.

    Returns
    -------
    float
        The norm; the step is accepted at 1 or below. [-]
    """
    n = x.size
    for m in range(n):
        acc[m] = 0.0
    for i in range(7):
        e = E[i]
        for m in range(n):
            acc[m] += e * K[i, m]
    err = 0.0
    for m in range(n):
        scale = atol + rtol * max(abs(x[m]), abs(x_new[m]))
        err += (h * acc[m] / scale) ** 2
    return math.sqrt(err / n)


@_jit
def shrink(err):
    """Factor of the step after a step rejected with error norm ``err`` > 1.

    Parameters
    ----------
    err : float
        Error norm of the rejected step (:func:`error_norm`). [-]

    Returns
    -------
    float
        max(1/5, 0.9 err^(-1/5)). [-]
    """
    return max(MIN_FACTOR, SAFETY * err ** -0.2)


@_jit
def grow(err, rejected):
    """Factor of the next step after a step accepted with error norm ``err`` <= 1.

    Parameters
    ----------
    err : float
        Error norm of the accepted step (:func:`error_norm`). [-]
    rejected : bool
        The step had been rejected before (the factor is then at most 1).

    Returns
    -------
    float
        min(10, 0.9 err^(-1/5)), 10 for a zero error. [-]
    """
    factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * err ** -0.2)
    if rejected:
        factor = min(1.0, factor)
    return factor


@_jit
def dense(x, K, h, theta, weights, acc, out):
    """Fourth-order dense output at ``t + theta h`` into ``out`` (n,).

    Parameters
    ----------
    x : ndarray, shape (n,)
        State at the step's start.
    K : ndarray, shape (7, n)
        The seven stage derivatives of the step.
    h : float
        Step. [s]
    theta : float
        Fraction of the step, 0 to 1. [-]
    weights : ndarray, shape (7,)
        Work array.
    acc, out : ndarray, shape (n,)
        Work array; receives the state.
    """
    n = x.size
    for i in range(7):
        weights[i] = P[i, 0] + theta * (P[i, 1] + theta * (P[i, 2] + theta * P[i, 3]))
    for m in range(n):
        acc[m] = 0.0
    for i in range(7):
        w = weights[i]
        for m in range(n):
            acc[m] += K[i, m] * w
    for m in range(n):
        out[m] = x[m] + h * theta * acc[m]

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

The step loop around them is written once too: :func:`integrator` takes a model's compiled
right-hand side and returns the compiled loop that integrates one run with it (step-size
control, accept or reject, the segments between the inputs' jumps, the samples from the dense
output, a run that leaves its tables, a work budget). The multibody model
(:mod:`slingloads.models.multibody.integrator`) and the yaw sweep
(:mod:`slingloads.models.yaw_batch`) are built on it; what differs between them is their
right-hand side and what they keep at the samples. The tableau is read by the compiled
functions as constants, and the functions are inlined into the integrators at numba's level
(``inline="always"``: no call, no reference counting of the arrays handed on); the machine code
of each pairing is cached on disk (``cache=True``).

The loop is the one of :func:`scipy.integrate.solve_ivp`'s ``RK45`` stepped segment by segment,
each segment from the step the previous one ended with (``tests/test_dormand_prince.py``
checks it against scipy's ``RK45`` class): the trial step is ``min(h, max_step)``; a step that
reaches the segment's end ``b``, or ends within :data:`END_SNAP` output intervals before it,
ends exactly at ``b`` (its last stages see the input just before ``b``); a step is rejected
when its error norm exceeds 1 (the step then shrinks, :func:`shrink`) and the next one grows by
:func:`grow`. Two rules are the models': a stage outside the model's tables (the right-hand
side returns a nonzero flag) halves the step, and below :data:`SMALLEST_STEP` the run stops
there; a derivative outside the tables at a segment's start (after an input's jump) stops the
run at once.
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
        State at the step's start. [units of the state]
    h : float
        Step. [s]
    K : ndarray, shape (7, n)
        Stage derivatives, rows 0 to i - 1 filled. [units of the state / s]
    i : int
        Stage, 1 to 6 (6: the fifth-order solution). [-]
    acc, out : ndarray, shape (n,)
        Work array; receives the argument. [units of the state]
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
        States at the step's start and end (fifth order). [units of the state]
    K : ndarray, shape (7, n)
        The seven stage derivatives. [units of the state / s]
    h : float
        Step. [s]
    rtol, atol : float
        Relative [-] and absolute (units of the states) tolerances.
    acc : ndarray, shape (n,)
        Work array. [units of the state]

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
        State at the step's start. [units of the state]
    K : ndarray, shape (7, n)
        The seven stage derivatives of the step. [units of the state / s]
    h : float
        Step. [s]
    theta : float
        Fraction of the step, 0 to 1. [-]
    weights : ndarray, shape (7,)
        Work array. [s]
    acc, out : ndarray, shape (n,)
        Work array; receives the state. [units of the state]
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


#: Smallest adaptive step of a run whose stages leave the model's tables, before it stops. [s]
SMALLEST_STEP = 1e-6
#: A step that ends within this fraction of the output interval before a segment's end is
#: stretched to end at it; a sample within it of a step's end is taken from that step. [-]
END_SNAP = 1e-9
#: Phase of a right-hand side call at a sample (:func:`integrator`); 0 to 6 are the stages.
SAMPLE = 7
#: How a run ended (:func:`integrator`): at its end, outside the model's tables, over the
#: budget of steps.
DONE, LEFT, OVER_BUDGET = 0, 1, 2


def integrator(rhs, project):
    """The compiled Dormand-Prince step loop of one run, for the right-hand side ``rhs``.

    Parameters
    ----------
    rhs : numba dispatcher
        Compiled ``rhs(phase, t, s, k, y, args, dx) -> int``, best compiled with
        ``inline="always"``. With ``phase`` 0 to 6 it writes into ``dx`` (n,) the derivative
        at stage ``phase`` of a step in segment ``s``, state ``y`` (n,) at time ``t`` [s]
        (phase 0: at the segment's start, once per segment; 6: at the fifth-order solution,
        the next step's first derivative) and returns a flag, nonzero when ``y`` is outside
        the model's tables. With ``phase`` :data:`SAMPLE` it is handed ``y``, the state at
        sample ``k`` (time ``k interval``; sample 0 is the initial state, the others the dense
        output), to keep what it needs; it returns a flag too (returned for a run of no
        segment). ``args`` is the model's tuple, passed through untouched. The loop calls it
        at one place only, so that the model's equations are compiled into it once.
    project : numba dispatcher
        Compiled ``project(x)``: what the model does to the state after every accepted step,
        in place (a quaternion renormalised), or nothing.

    Returns
    -------
    run : numba dispatcher
        Compiled ``run(x, ends, segments, interval, n_out, fixed, rtol, atol, max_step,
        first_step, max_steps, stop, args) -> (status, flag, t, accepted, sampled)``,
        inlined into its caller. It integrates state ``x`` (n,; updated in place to the last
        accepted state) from t = 0 over ``segments`` segments ending at ``ends`` [s] (each
        from the previous one's end), sampling ``n_out`` samples every ``interval`` [s].
        ``fixed`` > 0: that fixed step [s], without error control (a stage outside the
        tables then stops the run at once); else adaptive: the local error estimate within
        ``atol + rtol max(|x|, |x_new|)`` (root mean square over the states, tolerances
        [-] and units of the states), steps at most ``max_step`` [s], the first
        ``first_step`` [s]. A run that would try more than ``max_steps`` steps (accepted or
        rejected), or finds ``stop[0]`` (int64 array shared by the runs) nonzero, sets
        ``stop[0] = 1`` and ends. ``status`` is :data:`DONE`, :data:`LEFT` or
        :data:`OVER_BUDGET`; ``flag`` the right-hand side's flag that stopped it (or that of
        sample 0 for no segment); ``t`` the time reached [s] (where it stopped); ``accepted``
        the steps accepted; ``sampled`` the samples handed to ``rhs`` (the rest are the
        caller's to fill).
    """

    @_jit
    def run(x, ends, segments, interval, n_out, fixed, rtol, atol, max_step, first_step,
            max_steps, stop, args):
        n = x.size
        K = np.empty((7, n))
        y = np.empty(n)
        x_new = np.empty(n)
        dx = np.empty(n)
        acc = np.empty(n)
        weights = np.empty(7)
        snap = END_SNAP * interval
        t = 0.0
        t_new = 0.0
        h = first_step
        h_next = first_step
        b = 0.0
        s = 0
        sample = 0
        accepted = 0
        tried = 0
        rejected = False
        last = False
        stage_flag = 0
        status = DONE
        flag = 0
        new_step = False
        phase = SAMPLE
        while True:
            if new_step:  # --------------------------------------------- a trial step
                new_step = False
                if tried == max_steps or stop[0] != 0:  # over budget: the run ends
                    stop[0] = 1
                    status = OVER_BUDGET
                    break
                tried += 1
                h = min(h, max_step)
                last = t + h >= b - snap
                if last:
                    h = b - t
                stage_flag = 0
                phase = 1
            # ------------------------------------------------------------- one evaluation
            # (the one call of the right-hand side, on y: its equations are compiled in once)
            if phase == SAMPLE:
                when = sample * interval
                if sample == 0:
                    for m in range(n):
                        y[m] = x[m]
                else:
                    dense(x, K, h, (when - t) / h, weights, acc, y)
            elif phase == 0:
                for m in range(n):
                    y[m] = x[m]
                when = t
            else:
                stage(x, h, K, phase, acc, y)
                when = b if (last and C[phase] == 1.0) else t + C[phase] * h
            f = rhs(phase, when, s, sample, y, args, dx)
            if phase != SAMPLE:
                for m in range(n):
                    K[phase, m] = dx[m]
            # ------------------------------------------------------------- what next
            if phase == SAMPLE:
                sample += 1
                if sample == 1:  # the initial state
                    if segments == 0:
                        flag = f
                        break
                    b = ends[0]
                    phase = 0
                    continue
                if sample < n_out and sample * interval <= t_new + snap:
                    continue
            elif phase == 0:
                if f != 0:  # outside the tables at the segment's start: stop there
                    status = LEFT
                    flag = f
                    break
                new_step = True
                continue
            else:
                stage_flag |= f
                if phase < 6:
                    phase += 1
                    continue
                # y, the last stage's argument, is the fifth-order solution
                for m in range(n):
                    x_new[m] = y[m]
                if stage_flag != 0:  # a stage left the tables: a shorter step, or stop
                    if fixed > 0.0 or h < 2.0 * SMALLEST_STEP:
                        status = LEFT
                        flag = stage_flag
                        break
                    h *= 0.5
                    rejected = True
                    new_step = True
                    continue
                if fixed > 0.0:
                    h_next = fixed
                else:
                    err = error_norm(x, x_new, K, h, rtol, atol, acc)
                    if err > 1.0:
                        h *= shrink(err)
                        rejected = True
                        new_step = True
                        continue
                    h_next = h * grow(err, rejected)
                    rejected = False
                t_new = b if last else t + h
                if sample < n_out and sample * interval <= t_new + snap:
                    phase = SAMPLE
                    continue
            # ----------------------------------------------------------- step accepted
            accepted += 1
            t = t_new
            for m in range(n):
                x[m] = x_new[m]
                K[0, m] = K[6, m]
            project(x)
            h = h_next
            if last:
                s += 1
                if s == segments:
                    break
                b = ends[s]
                phase = 0
            else:
                new_step = True
        return status, flag, t, accepted, sample

    return run

"""Time-integration settings shared by the time-domain analyses (lateral pendulum, yaw).

Each analysis has two integrators over the same right-hand side:

* a compiled batch integrator over all runs of a sweep at once: the **fixed-step classical
  Runge-Kutta (RK4)** step of :mod:`slingloads.models.runge_kutta`
  (:func:`slingloads.analyses.lateral.sweep`,
  :func:`slingloads.models.yaw_dynamics.integrate_rk4`): it uses ``t_end``, ``step`` and
  ``output_interval``; or the adaptive **Dormand-Prince 5(4)** pair of
  :mod:`slingloads.models.dormand_prince` (:func:`slingloads.models.yaw_dynamics.integrate_dopri`,
  and the multibody model's :mod:`slingloads.models.multibody.integrator`): it uses ``rtol``,
  ``atol``, ``max_step``, ``t_end`` and ``output_interval``;
* :func:`scipy.integrate.solve_ivp`, one run at a time (time histories of a chosen run, and
  the reference the batch integrators are tested against): it uses ``method``, ``rtol``,
  ``atol``, ``max_step``, ``t_end`` and ``output_interval``.

A field left at ``None`` takes the analysis's own default, chosen for what it integrates
(:meth:`SolverSettings.with_defaults`): the lateral pendulum picks its run length from the
motions and its slowest swing mode and its step from its fastest mode; the yaw analyses run
120 s at 0.05 s.

When to tighten (after python-control's advice on :func:`solve_ivp`):

* RK4: halve ``step`` and compare; its error falls about 16-fold. Put input discontinuities
  (gust onsets and ends) on multiples of the step where the analysis does not insert them.
* solve_ivp: tighten ``rtol`` (and use ``"DOP853"``) when comparing with closed forms below
  1e-6; set ``max_step`` below the shortest feature of an input between breakpoints; use
  ``"Radau"`` or ``"LSODA"`` for a stiff system (a very stiff elastic cable).

References
----------
.. [1] E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary Differential Equations I",
   2nd ed., Springer, 1993 (RK4, section II.1).
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from slingloads.errors import InputError

#: The :func:`scipy.integrate.solve_ivp` methods.
SOLVE_IVP_METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

_OPTIONAL = ("t_end", "step", "output_interval")


@dataclass(frozen=True)
class SolverSettings:
    """Settings of the fixed-step RK4 and of the solve_ivp integrators.

    Parameters
    ----------
    t_end : float or None
        Simulated time of every run, > 0; ``None``: the analysis's default. [s]
    step : float or None
        Fixed step of the vectorised RK4 integrator, > 0; ``None``: the analysis's
        default. [s]
    output_interval : float or None
        Interval of the stored time histories, > 0; ``None``: the analysis's default. [s]
    method : str
        solve_ivp method: "RK45", "RK23", "DOP853", "Radau", "BDF" or "LSODA".
    rtol : float
        solve_ivp relative tolerance, > 0. [-]
    atol : float
        solve_ivp absolute tolerance, > 0 (in the units of the states: rad, m, rad/s, m/s).
        [rad, m, rad/s, m/s]
    max_step : float
        Largest solve_ivp step, > 0 (inf: no limit). [s]

    Raises
    ------
    InputError
        For an unknown method or a setting that is not > 0.
    """

    t_end: float | None = None
    step: float | None = None
    output_interval: float | None = None
    method: str = "RK45"
    rtol: float = 1e-8
    atol: float = 1e-10
    max_step: float = np.inf

    def __post_init__(self):
        if self.method not in SOLVE_IVP_METHODS:
            raise InputError(f"solver {self.method=!r} is not a valid option; valid options "
                             f"are {list(SOLVE_IVP_METHODS)}", self.method)
        for f in fields(self):
            if f.name == "method" or (f.name in _OPTIONAL and getattr(self, f.name) is None):
                continue
            value = float(getattr(self, f.name))
            if np.isnan(value) or value <= 0:
                raise InputError(f"solver setting {f.name} must be > 0", value)
            object.__setattr__(self, f.name, value)

    def with_defaults(self, **defaults):
        """A copy whose ``None`` fields take the analysis's defaults; fields already set are
        kept.

        Parameters
        ----------
        **defaults : float
            ``t_end`` [s], ``step`` [s], ``output_interval`` [s].

        Returns
        -------
        SolverSettings

        Raises
        ------
        InputError
            For a name other than those three.
        """
        unknown = sorted(set(defaults) - set(_OPTIONAL))
        if unknown:
            raise InputError(f"only {list(_OPTIONAL)} take analysis defaults", unknown[0])
        missing = {k: v for k, v in defaults.items() if getattr(self, k) is None}
        return replace(self, **missing) if missing else self

    def fixed_grid(self):
        """Steps and output decimation of a fixed grid that lands exactly on ``t_end`` and
        on every output time.

        Returns
        -------
        n_steps : int
            t_end / step. [count]
        output_every : int
            output_interval / step. [count]

        Raises
        ------
        InputError
            If a field is unset, ``t_end`` is not a whole multiple of ``step``, or
            ``output_interval`` is not.
        """
        for name in _OPTIONAL:
            if getattr(self, name) is None:
                raise InputError(f"solver setting {name} is not set (None)")
        ratio = self.output_interval / self.step
        if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
            raise InputError("solver output_interval must be a whole multiple of the step [s]",
                             self.output_interval)
        steps = self.t_end / self.step
        if abs(steps - round(steps)) > 1e-9 * steps:
            raise InputError("solver t_end must be a whole multiple of the step [s]",
                             self.t_end)
        return int(round(steps)), int(round(ratio))

    def output_times(self):
        """Stored sample times of a fixed grid, 0 to ``t_end``.

        Returns
        -------
        ndarray
            [s]
        """
        n_steps, every = self.fixed_grid()
        return np.arange(n_steps // every + 1) * self.output_interval


def solver_settings(solver):
    """``solver`` checked, or the default :class:`SolverSettings` when it is None.

    Parameters
    ----------
    solver : SolverSettings or None
        The settings an analysis was given.

    Returns
    -------
    SolverSettings
        ``solver``, or ``SolverSettings()`` (every field at its default) for None.

    Raises
    ------
    InputError
        For anything other than a SolverSettings or None, naming its type.
    """
    if solver is None:
        return SolverSettings()
    if not isinstance(solver, SolverSettings):
        raise InputError("solver settings must be a SolverSettings", type(solver).__name__)
    return solver

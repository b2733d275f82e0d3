"""Compile the compiled kernels ahead of the first run (``slingloads compile``).

The kernels of the loads (free-free internal loads), the lateral sweep, the parachute sizing's
yaw runs and the multibody model are compiled by `numba <https://numba.pydata.org>`_ on their
first call and cached beside the package (``cache=True``). A fresh installation therefore
spends its first run compiling them. :func:`compile_kernels` runs one tiny problem of each
analysis through the same public functions a run calls, with the same argument types, so that
every kernel a run needs is compiled and cached; the multibody kernels (the largest) compile in
a second process while this one compiles the others.
"""

from __future__ import annotations

import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np


def _loads():
    from slingloads.analyses.loads import LoadsStudy
    from slingloads.analyses.sfbm import NUMPY_CUTS
    from slingloads.models.airframe import Airframe, Hardpoints, MassItems

    items = MassItems(["A", "B", "C"], [300.0, 1500.0, 400.0],
                      [[1.0, 0.0, 0.5], [3.0, 0.0, 0.8], [7.0, 0.0, 1.0]])
    hardpoints = Hardpoints([3.2, 0.0, 2.0], [[3.0, -0.3, 1.2], [3.0, 0.3, 1.2]])
    cases = len(LoadsStudy(Airframe(items, [2.0], hardpoints)).case_matrix())
    cuts = NUMPY_CUTS // cases + 2  # enough for the compiled kernel
    LoadsStudy(Airframe(items, np.linspace(1.5, 6.5, cuts), hardpoints,
                        station_ids=[f"S{i}" for i in range(cuts)])).run()


def _lateral():
    from slingloads.analyses.lateral import sweep
    from slingloads.models.carrier_motion import QuinticStep
    from slingloads.models.integration import SolverSettings
    from slingloads.models.pendulum import LateralPendulum, SlungBody

    body = SlungBody(2096.0, 1803.0, 0.95, "warm-up")
    for ea in (None, 5e6):  # the rigid rope and the elastic cable
        sweep([LateralPendulum(body, 20.0, ea)], [QuinticStep(1.0, 2.0)],
              solver=SolverSettings(t_end=1.0, step=0.01))


def _chute():
    from slingloads.analyses.chute_sizing import run_yaw
    from slingloads.models.gusts import StepGust
    from slingloads.models.integration import SolverSettings
    from slingloads.models.parachute import Parachute
    from slingloads.models.sample_aircraft import (
        sample_fin,
        sample_fuselage,
        sample_hardpoints,
        sample_reference,
    )
    from slingloads.models.yaw_dynamics import YawModel

    ref = sample_reference("HC1")
    model = YawModel(sample_fuselage("HC1"), sample_fin("HC1"), sample_hardpoints("HC1"),
                     ref.yaw_inertia, parachute=Parachute(1.0))
    settings = SolverSettings(t_end=1.0, step=0.05, output_interval=0.5)
    for integrator in ("dopri5", "rk4"):
        run_yaw(model, [1.0], [StepGust(5.0)], settings, integrator=integrator)


def _sample_system():
    from slingloads.models.multibody import Cable, HingedParachute, RigidBody, SlingSystem
    from slingloads.models.parachute import Parachute, extended_cd_table
    from slingloads.models.sample_aircraft import (
        sample_fuselage,
        sample_hardpoints,
        sample_reference,
        sample_surfaces,
    )

    ref = sample_reference("HC1")
    return SlingSystem(RigidBody(ref.mass, np.zeros(3), np.diag([2500.0, 7000.0,
                                                                 ref.yaw_inertia])),
                       sample_hardpoints("HC1"), Cable(18.3, 5e6), sample_fuselage("HC1"),
                       sample_surfaces("HC1"),
                       HingedParachute(Parachute(1.1, extended_cd_table())), airspeed=40.0)


def _equations():
    """The multibody equations alone: what a trim and a linearisation (the loads' towed
    cases too) compile."""
    from slingloads.analyses.multibody import trim
    from slingloads.analyses.multibody.trim import linearise

    linearise(trim(_sample_system()))


def _integration():
    """The multibody integration loop and the measures of its runs (the equations too)."""
    from slingloads.analyses.multibody import free_response, simulate

    system = _sample_system()
    simulate(system, free_response(), t_end=1.0)
    simulate(system, free_response(), t_end=1.0, dt=0.01)


def _multibody():
    _equations()
    _integration()


def _cached(dispatcher):
    """True if numba's on-disk cache holds a compiled version of ``dispatcher`` for its
    current source (numba's cache index; False where it cannot be read)."""
    try:
        return bool(dispatcher._cache._cache_file._load_index())
    except Exception:  # noqa: BLE001 - no readable cache: compile
        return False


def _kernels(part):
    if part == "equations":
        from slingloads.models.multibody.integrator import evaluate_states
        return [evaluate_states]
    from slingloads.models.multibody.integrator import dopri_runs
    return [dopri_runs]


#: The parts of the multibody warm-up a run compiles in the background, in order.
BACKGROUND = {"equations": _equations, "integration": _integration}


def compile_part(part):
    """Compile and cache one part of :data:`BACKGROUND` unless it is cached already (the
    command line runs it in a second process while the first analyses compute, so that the
    multibody kernels of a fresh installation compile on the machine's other core).

    Parameters
    ----------
    part : str
        ``"equations"`` or ``"integration"``.

    Returns
    -------
    bool
        True if it compiled anything.
    """
    if all(_cached(k) for k in _kernels(part)):
        return False
    BACKGROUND[part]()
    return True


#: The warm-up of each analysis, by name.
STEPS = {"loads": _loads, "lateral": _lateral, "chute sizing": _chute,
         "multibody": _multibody}


def _timed(names):
    out = {}
    for name in names:
        start = time.perf_counter()
        STEPS[name]()
        out[name] = time.perf_counter() - start
    return out


def compile_kernels(workers=2):
    """Compile and cache every kernel a run may need (module notes).

    Parameters
    ----------
    workers : int
        1: all in this process; 2 (default): the multibody kernels in a second process. [count]

    Returns
    -------
    dict
        Seconds spent per analysis. [s]
    """
    if workers < 2:
        return _timed(STEPS)
    with ProcessPoolExecutor(1) as pool:
        other = pool.submit(_timed, ["multibody"])
        done = _timed([name for name in STEPS if name != "multibody"])
        done.update(other.result())
    return done

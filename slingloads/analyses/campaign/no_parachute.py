"""Transport without the parachute (paper section 5): frontal wind ramps on the helicopters in
their full-tail configuration.

Each helicopter hangs without parachute, with its intact fin and horizontal tail (paper
section 5.1), under a hovering carrier, and meets a head wind rising from 0 at ``rate`` to each
target speed (paper figure 15: 20, 30, 40, 60 and 80 kt here; the paper shows 20, 30 and 40 kIAS
in figures 16 to 18). Each ramp runs for its own length, :data:`OBSERVE` s after its ramp ends
(:func:`ramp_length`), so that its verdict does not depend on which other ramps were run.
Its **verdict** is the multibody response verdict (``docs/multibody.md``,
:mod:`slingloads.analyses.verdicts`): "convergent" when the response decays back to its trim
and the towed equilibrium at the ramp's final airspeed is stable (eigenvalues of its linear
model); "static departure" when it settles off its trim heading (the helicopter weathervanes
away from the flight path, a static divergence; the size in the reason); "limit cycle";
"divergent"; "outside domain" (left a table, slack cable); "inconclusive".

**Ramps with a gust.** A ramp alone shows whether the helicopter holds its heading, but not
how well damped it is: a stable case rides the ramp with hardly a swing. Each target of
``gust_targets`` (default 20 and 30 kt, the paper's limit) is flown again with a lateral gust
of ``gust_speed`` (default 10 ft/s, a "finite" gust of :data:`GUST_DURATION` s) starting
:data:`GUST_DELAY` s after its ramp ends, the run lasting :data:`OBSERVE` s after the gust
ends: the response after the gust shows the damping (or its absence). 10 ft/s rather than the
30 ft/s of the parachuted runs: at 20 kt a 30 ft/s side gust alone turns the relative wind by
41 deg (10 ft/s: 16 deg), beyond the small-disturbance response these runs are to show. Their
verdicts (the same rule, read after the gust) stand beside the ramps' and do not enter the
speed limit, which is the paper's (ramps alone).

**Speed limit** of a helicopter: the largest ramp target whose run, and the run of every lower
target, is convergent (NaN when even the lowest is not). It is stated as the bracket the ramps
tried give: ``">= X kt and < Y kt"`` between the largest convergent target and the first that
is not (with that one's verdict); ``">= X kt"`` when every ramp tried converges (the limit is
only known to be at least the highest target); ``"< Y kt"`` when even the lowest does not.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError
from slingloads.models.multibody.cable import Cable
from slingloads.models.multibody.system import SlingSystem

#: Default ramp targets (paper sections 5.2-5.3). [m/s]
RAMP_TARGETS = tuple(v * KNOT for v in (20.0, 30.0, 40.0, 60.0, 80.0))
#: Default ramp: rate [m/s^2] and onset [s] (the multibody model's wind ramp).
RAMP_RATE, RAMP_ONSET = 0.5, 5.0
#: Seconds of response seen after each ramp ends. [s]
OBSERVE = 60.0
#: Default carrier cable of the sample systems. [m]
SAMPLE_CABLE = 60 * FOOT
#: Default cable stiffness EA of the sample systems. [N]
SAMPLE_EA = 5e6
#: Default targets of the ramps flown again with a gust after the ramp (module notes). [m/s]
GUST_TARGETS = tuple(v * KNOT for v in (20.0, 30.0))
#: Default lateral gust of those runs (module notes: 10 ft/s). [m/s]
GUST_SPEED = 10 * FOOT
#: Duration of that gust (a "finite" gust, :func:`slingloads.models.gusts.make_gust`). [s]
GUST_DURATION = 10.0
#: Time from the ramp's end to the gust's start. [s]
GUST_DELAY = 10.0


def sample_full_tail_system(name, cable_length=SAMPLE_CABLE, ea=SAMPLE_EA):
    """A GENERIC sample helicopter (``slingloads.models.sample_aircraft``) without parachute,
    in its full-tail configuration, under a frozen carrier.

    Parameters
    ----------
    name : str
        "HC1" or "HC2".
    cable_length : float
        [m]
    ea : float
        [N]

    Returns
    -------
    SlingSystem
    """
    from slingloads.models.sample_aircraft import (
        sample_body,
        sample_fuselage,
        sample_hardpoints,
        sample_surfaces,
    )

    return SlingSystem(sample_body(name), sample_hardpoints(name), Cable(cable_length, ea),
                       sample_fuselage(name), sample_surfaces(name, "full tail"), None,
                       name=str(name).upper())


def ramp_length(target, rate=RAMP_RATE, onset=RAMP_ONSET):
    """Run length that shows :data:`OBSERVE` s after a ramp to ``target`` [m/s] ends, rounded
    up to a whole 10 s. [s]

    Parameters
    ----------
    target : float
        Ramp target. [m/s]
    rate : float
        Rate of rise of the wind. [m/s^2]
    onset : float
        Start of the ramp. [s]

    Returns
    -------
    float
        [s]
    """
    return float(10.0 * np.ceil((onset + target / rate + OBSERVE) / 10.0))


@dataclass(frozen=True, eq=False)
class NoParachuteStudy:
    """Wind ramps on helicopters without parachute (module notes).

    Parameters
    ----------
    systems : dict
        Name -> SlingSystem without parachute (full-tail configuration).
    targets : sequence of float
        Ramp target speeds, > 0. [m/s]
    rate : float
        Ramp rate, > 0. [m/s^2]
    onset : float
        [s]
    gust_targets : sequence of float
        Ramp targets flown again with a lateral gust after the ramp, each > 0, or empty
        (module notes; default :data:`GUST_TARGETS`, 20 and 30 kt). [m/s]
    gust_speed : float
        Speed of that gust, > 0 (default :data:`GUST_SPEED`, 10 ft/s). [m/s]
    """

    systems: dict = field(default_factory=dict)
    targets: tuple = RAMP_TARGETS
    rate: float = RAMP_RATE
    onset: float = RAMP_ONSET
    gust_targets: tuple = GUST_TARGETS
    gust_speed: float = GUST_SPEED

    def __post_init__(self):
        if not self.systems:
            raise InputError("the study without parachute needs at least one helicopter")
        for name, system in self.systems.items():
            if not isinstance(system, SlingSystem):
                raise InputError(f"helicopter {name!r} of the study without parachute must be "
                                 "a SlingSystem", type(system).__name__)
            if system.parachute is not None:
                raise InputError(f"helicopter {name!r} of the study without parachute has a "
                                 "parachute", name)
        targets = np.atleast_1d(np.asarray(self.targets, float))
        if targets.size == 0 or np.any(~np.isfinite(targets) | (targets <= 0)):
            raise InputError("wind-ramp targets must be > 0 [m/s]", targets.tolist())
        object.__setattr__(self, "targets", tuple(np.unique(targets)))
        gusts = np.atleast_1d(np.asarray(self.gust_targets, float))
        if np.any(~np.isfinite(gusts) | (gusts <= 0)):
            raise InputError("targets of the ramps with a gust must be > 0 [m/s]",
                             gusts.tolist())
        object.__setattr__(self, "gust_targets", tuple(np.unique(gusts)))
        speed = float(self.gust_speed)
        if not np.isfinite(speed) or speed <= 0:
            raise InputError("the gust after the ramps must be > 0 [m/s]", speed)
        object.__setattr__(self, "gust_speed", speed)
        for name, value in (("rate", self.rate), ("onset", self.onset)):
            value = float(value)
            if not np.isfinite(value) or value < 0 or (name == "rate" and value == 0):
                raise InputError(f"wind-ramp {name} must be {'> 0' if name == 'rate' else '>= 0'}",
                                 value)
        object.__setattr__(self, "systems", dict(self.systems))

    @property
    def size(self):
        """Runs of the study: the ramps and the ramps with a gust, of every helicopter."""
        return len(self.systems) * (len(self.targets) + len(self.gust_targets))

    @property
    def run_length(self):
        """Length of the longest ramp run: :data:`OBSERVE` s after the highest ramp ends. [s]"""
        return ramp_length(max(self.targets), self.rate, self.onset)

    def run_length_of(self, target):
        """Length of the run of the ramp to ``target`` [m/s]: :data:`OBSERVE` s after it
        ends, whatever the other ramps. [s]

        Parameters
        ----------
        target : float
            Ramp target. [m/s]

        Returns
        -------
        float
            [s]
        """
        return ramp_length(target, self.rate, self.onset)

    def ramp_end(self, target):
        """Time the ramp to ``target`` [m/s] ends. [s]

        Parameters
        ----------
        target : float
            Ramp target. [m/s]

        Returns
        -------
        float
            [s]
        """
        return self.onset + float(target) / self.rate

    def gust_window(self, target):
        """(start, end) of the gust after the ramp to ``target`` [m/s] (module notes). [s]

        Parameters
        ----------
        target : float
            Ramp target. [m/s]

        Returns
        -------
        (float, float)
            [s]
        """
        start = self.ramp_end(target) + GUST_DELAY
        return start, start + GUST_DURATION

    def gust_run_length_of(self, target):
        """Length of the run of the ramp to ``target`` [m/s] with its gust: :data:`OBSERVE` s
        after the gust ends, rounded up to a whole 10 s. [s]

        Parameters
        ----------
        target : float
            Ramp target. [m/s]

        Returns
        -------
        float
            [s]
        """
        return float(10.0 * np.ceil((self.gust_window(target)[1] + OBSERVE) / 10.0))

    def gust_jobs(self):
        """(name, target, system, manoeuvre) of every ramp with a gust (module notes).

        Returns
        -------
        list of (str, float, SlingSystem, Manoeuvre)
            Helicopter name, ramp target [m/s], system and manoeuvre.
        """
        from slingloads.models.gusts import make_gust

        def gust(target):
            start, _ = self.gust_window(target)
            return (make_gust("finite", self.gust_speed, start, GUST_DURATION),
                    f", lateral gust of {GUST_DURATION:g} s at {start:.0f} s")

        return self._ramp_jobs(self.gust_targets, gust)

    def jobs(self):
        """(name, target, system, manoeuvre) of every ramp.

        Returns
        -------
        list of (str, float, SlingSystem, Manoeuvre)
            Helicopter name, ramp target [m/s], system and manoeuvre.
        """
        return self._ramp_jobs(self.targets, lambda target: (None, ""))

    def _ramp_jobs(self, targets, gust):
        """The ramps to ``targets`` [m/s] of every helicopter, each with ``gust(target)``'s
        (gust or None, suffix of its name). The run starts in hover (the ramp's choice); the
        system's airspeed is the ramp's final one, where its linear model is taken (sea-level
        samples: EAS equals the wind's true speed)."""
        from slingloads.analyses.multibody.manoeuvres import wind_ramp

        out = []
        for name, system in self.systems.items():
            for target in targets:
                shape, suffix = gust(target)
                manoeuvre = wind_ramp(target, self.rate, self.onset, gust=shape,
                                      name=f"wind ramp to {target / KNOT:.0f} kt{suffix}")
                out.append((name, target, system.with_(airspeed=target), manoeuvre))
        return out


@dataclass(frozen=True, eq=False)
class NoParachuteResult:
    """Verdicts and speed limits of the study without parachute.

    Attributes
    ----------
    runs : pandas.DataFrame
        One row per (helicopter, target): verdict and response metrics.
    limits : pandas.DataFrame
        One row per helicopter: largest convergent target speed.
    keys : dict
        (helicopter, target) -> run key (histories in the store).
    gust_runs : pandas.DataFrame
        One row per (helicopter, target) of the ramps with a gust: verdict and response
        metrics (empty without them).
    gust_keys : dict
        (helicopter, target) -> run key of the ramps with a gust.
    """

    runs: pd.DataFrame
    limits: pd.DataFrame
    keys: dict
    gust_runs: pd.DataFrame = field(default_factory=pd.DataFrame)
    gust_keys: dict = field(default_factory=dict)


def ramp_verdict(response, linear):
    """Verdict of a ramp (module notes) from its response and linear verdicts: the response
    verdict, "convergent" only with a stable linear verdict ("inconclusive" otherwise).

    Parameters
    ----------
    response : str
        Verdict of the response (convergent, divergent, ...).
    linear : str
        Verdict of the eigenvalues at trim (stable, neutral, unstable, no trim).

    Returns
    -------
    str
    """
    if response == "convergent" and linear != "stable":
        return "inconclusive"
    return response


def speed_limits(runs):
    """Largest target of each helicopter whose run and every lower one converge (module
    notes); ``runs`` has the columns helicopter, ramp target [m/s] and verdict.

    Parameters
    ----------
    runs : pandas.DataFrame
        The ramps: helicopter, ramp target [m/s], verdict.

    Returns
    -------
    pandas.DataFrame
        One row per helicopter: the speed limit in words and the largest convergent ramp.
    """
    rows = []
    for name, group in runs.groupby("helicopter", sort=False):
        group = group.sort_values("ramp target [m/s]")
        ok = (group["verdict"] == "convergent").to_numpy()
        targets = group["ramp target [m/s]"].to_numpy()
        first_bad = np.argmin(ok) if not ok.all() else ok.size
        limit = targets[first_bad - 1] if first_bad > 0 else np.nan
        beyond = group.iloc[first_bad] if first_bad < ok.size else None
        if beyond is None:
            text = f">= {limit / KNOT:.0f} kt (every ramp tried converges)"
        else:
            bad = beyond["ramp target [m/s]"] / KNOT
            if np.isfinite(limit):
                text = (f">= {limit / KNOT:.0f} kt and < {bad:.0f} kt (the ramp to {bad:.0f} "
                        f"kt: {beyond['verdict']})")
            else:
                text = (f"< {bad:.0f} kt (the lowest ramp tried, to {bad:.0f} kt: "
                        f"{beyond['verdict']})")
        rows.append({
            "helicopter": name, "speed limit": text,
            "largest convergent ramp [m/s]": limit,
            "largest convergent ramp [kt]": limit / KNOT,
            "first non-convergent ramp [kt]": (beyond["ramp target [m/s]"] / KNOT
                                               if beyond is not None else np.nan),
            "its verdict": beyond["verdict"] if beyond is not None else "",
        })
    return pd.DataFrame(rows)

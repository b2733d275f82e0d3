"""The result of the design-angle study: its cases, the model's domain, the verdict and tables.

:class:`LateralStudy` holds every case's pendulum, motion and peaks, and reads from them the
largest load angle over the cases that count (inside the model's domain, :data:`DOMAIN_ANGLE`,
and with a flyable carrier motion), the recommended design angle (that maximum times the
margin) against the CS-29.865 angle (:data:`REGULATORY_ANGLE`), the verdict in words with its
caveats, and the report's tables.

References
----------
.. [1] EASA CS-29, CS 29.865 "External loads"; 14 CFR 29.865(a).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import pandas as pd

from slingloads.analyses.lateral.carrier_limits import (
    CARRIER_FORCE_LIMIT,
    CarrierLimits,
    flyable,
)
from slingloads.analyses.lateral.metrics import RunMetrics
from slingloads.analyses.lateral.ranges import ParameterRanges
from slingloads.analyses.lateral.simulation import simulate
from slingloads.analyses.lateral_damping import LateralDamping
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.integration import SolverSettings, solver_settings

#: CS-29.865 minimum angle of the hook load from the mast. [rad]
REGULATORY_ANGLE = np.radians(30.0)
#: Domain of the lateral pendulum: the cable stays taut (T > 0 throughout), the rope angle
#: from the vertical stays below this (past it the hub is above the hook's horizontal: the
#: body goes over the top, a motion no carrier flies and a cable that only pulls cannot
#: hold), and the hub load's angle from the mast stays below it (past 90 deg the cable pulls
#: the hub from below its own horizontal plane: no hook load case). [rad]
DOMAIN_ANGLE = np.radians(90.0)


def _max(values):
    return float(np.nanmax(values)) if np.size(values) and np.any(np.isfinite(values)) \
        else np.nan


def _motion_row(motion):
    duration = getattr(motion, "duration", getattr(motion, "end_time", np.nan))
    peak = motion.peak_acceleration
    return {
        "motion": motion.kind, "motion description": motion.describe(),
        "peak S'' [m/s^2]": peak, "peak S'' [g]": peak / G0,
        "motion duration [s]": float(duration), "velocity jump [m/s]": motion.velocity_jump,
    }


@dataclass(frozen=True, eq=False)
class LateralStudy:
    """Result of :func:`lateral_study`.

    Attributes
    ----------
    pendulums, motions : tuple, one per case
    metrics : RunMetrics, arrays of shape (cases,)
    margin : float [-]
    t_end : float, common run length [s]
    step : float, RK4 step used [s]
    regulatory_angle : float [rad]
    solver : SolverSettings, the settings of :meth:`run_case` (its ``t_end`` is the sweep's)
    factors : ndarray, shape (cases, 3), factors on roll inertia, CG below hub, rope [-]
    nominal_rope : ndarray, shape (cases,), the rope length before its factor [m]
    ranges : ParameterRanges
    damping : LateralDamping
    hook_load_factor : float or None, Nz of the hook cases [-]
    limits : CarrierLimits or None, what the carrier can fly (None: not checked)
    """

    pendulums: tuple
    motions: tuple
    metrics: RunMetrics
    margin: float
    t_end: float
    step: float
    regulatory_angle: float = REGULATORY_ANGLE
    solver: SolverSettings = SolverSettings()
    factors: np.ndarray | None = None
    nominal_rope: np.ndarray | None = None
    ranges: ParameterRanges | None = None
    damping: LateralDamping | None = None
    hook_load_factor: float | None = None
    limits: CarrierLimits | None = None

    def __post_init__(self):
        n = len(self.pendulums)
        if self.factors is None:
            object.__setattr__(self, "factors", np.ones((n, 3)))
        if self.nominal_rope is None:
            object.__setattr__(self, "nominal_rope",
                               np.array([p.rope_length for p in self.pendulums]))
        if self.ranges is None:
            object.__setattr__(self, "ranges", ParameterRanges.nominal())
        if self.damping is None:
            object.__setattr__(self, "damping", LateralDamping())

    @property
    def nominal(self):
        """True for the cases at the nominal roll inertia, CG and rope length."""
        return np.all(self.factors == 1.0, axis=1)

    @property
    def in_domain(self):
        """True for the cases that stay inside the model's domain (:data:`DOMAIN_ANGLE`):
        taut cable throughout, rope angle and load angle below 90 deg. The others yield no
        design angle."""
        m = self.metrics
        with np.errstate(invalid="ignore"):
            return (~np.asarray(m.slack, bool)
                    & (np.asarray(m.max_rope_angle) < DOMAIN_ANGLE)
                    & (np.asarray(m.max_load_angle) < DOMAIN_ANGLE))

    def domain_notes(self):
        """Why each case is outside the domain, with the time ('' inside). [str]

        Returns
        -------
        list of str
            One note per case.
        """
        m, d = self.metrics, np.degrees
        notes = []
        for k in range(len(self.pendulums)):
            why = []
            if bool(np.asarray(m.slack)[k]):
                why.append(f"cable slack (min T/(m g) {float(m.min_tension_ratio[k]):.3g})")
            if not np.asarray(m.max_rope_angle)[k] < DOMAIN_ANGLE:
                why.append(f"rope angle {float(d(m.max_rope_angle[k])):.4g} deg at t = "
                           f"{float(m.t_max_rope_angle[k]):.4g} s passes "
                           f"{float(d(DOMAIN_ANGLE)):.3g} deg (over the top)")
            if not np.asarray(m.max_load_angle)[k] < DOMAIN_ANGLE:
                why.append(f"load angle {float(d(m.max_load_angle[k])):.4g} deg at t = "
                           f"{float(m.t_max_load_angle[k]):.4g} s passes "
                           f"{float(d(DOMAIN_ANGLE)):.3g} deg")
            notes.append("; ".join(why))
        return notes

    @property
    def outside_domain(self):
        """Number of cases outside the domain."""
        return int(np.count_nonzero(~self.in_domain))

    def flyable_notes(self):
        """Why each case's carrier motion is beyond :attr:`limits` ('' if flyable or not
        checked). [str]

        Returns
        -------
        list of str
            One note per case (:func:`flyable`).
        """
        return list(self._flyable_notes)

    @cached_property
    def _flyable_notes(self):
        """The notes of :meth:`flyable_notes`, judged once per study (each motion once)."""
        if self.limits is None:
            return ("",) * len(self.motions)
        seen = {}
        return tuple(seen.setdefault(id(m), flyable(m, self.limits)) for m in self.motions)

    @property
    def flyable(self):
        """True for the cases whose carrier motion the carrier can fly (all without
        limits)."""
        return np.array([not note for note in self.flyable_notes()], dtype=bool)

    @property
    def carrier_force_ratio(self):
        """Each case's largest lateral cable force on the carrier over the carrier's weight,
        max over the run of T(t) |sin theta1(t)| / (m_carrier g) (NaN without a carrier
        mass). [-]"""
        mass = np.nan if self.limits is None else self.limits.carrier_mass
        loads = np.array([p.body.mass for p in self.pendulums])
        return np.asarray(self.metrics.max_side_force_ratio) * loads / mass

    @property
    def counted(self):
        """The cases the design angle is taken over: inside the domain, motion flyable."""
        return self.in_domain & self.flyable

    def _inside(self, values):
        return np.where(self.counted, values, np.nan)

    @property
    def critical_index(self):
        """Index of the case with the largest load angle among those inside the domain (of
        all cases when none is)."""
        inside = self._inside(self.metrics.max_load_angle)
        if np.any(np.isfinite(inside)):
            return int(np.nanargmax(inside))
        return int(np.nanargmax(self.metrics.max_load_angle))

    @property
    def max_load_angle(self):
        """Largest |theta1 - theta2| over the cases inside the domain, the envelope over the
        ranges (NaN when no case is inside). [rad]"""
        value = float(self._inside(self.metrics.max_load_angle)[self.critical_index])
        return value

    @property
    def nominal_max_load_angle(self):
        """Largest |theta1 - theta2| over the nominal cases inside the domain (NaN if
        none). [rad]"""
        values = self._inside(self.metrics.max_load_angle)[self.nominal]
        return float(np.nanmax(values)) if np.any(np.isfinite(values)) else np.nan

    @property
    def critical_case(self):
        """The row of :meth:`to_frame` of the case with the largest load angle (a Series)."""
        return self.to_frame().iloc[self.critical_index]

    @property
    def max_load_angle_taut(self):
        """Largest |theta1 - theta2| over the cases whose cable never went slack (NaN if
        none). [rad]"""
        values = np.where(self.metrics.slack, np.nan, self.metrics.max_load_angle)
        return float(np.nanmax(values)) if np.any(np.isfinite(values)) else np.nan

    @property
    def recommended_angle(self):
        """Recommended design angle of the hook load from the mast = margin x the largest
        load angle over the envelope of the ranges, the cases inside the domain only; NaN
        when no case is inside or when it would reach 90 deg (no hook cone). [rad]"""
        value = self.margin * self.max_load_angle
        return value if value < DOMAIN_ANGLE else np.nan

    @property
    def exceeds_regulatory_angle(self):
        """True if the recommended angle is above the regulatory angle (no reduction)."""
        return self.recommended_angle > self.regulatory_angle

    @property
    def regulatory_angle_not_conservative(self):
        """True if a load angle found exceeds the regulatory angle itself: for this motion
        set the 30 deg rule is not conservative."""
        return self.max_load_angle > self.regulatory_angle

    @property
    def max_tension_ratio(self):
        """Largest T/(m g) over all cases. [-]"""
        return float(np.nanmax(self.metrics.max_tension_ratio))

    @property
    def exceeds_hook_load_factor(self):
        """Cases whose largest T/(m g) exceeds the hook load factor Nz (all False without
        Nz)."""
        if self.hook_load_factor is None:
            return np.zeros(len(self.pendulums), dtype=bool)
        return self.metrics.max_tension_ratio > self.hook_load_factor

    def caveats(self):
        """What limits the conclusion, in words ('' when nothing): cases outside the domain,
        carrier motions beyond the carrier's limits, cases loading the carrier sideways
        beyond :data:`CARRIER_FORCE_LIMIT` of its weight.

        Returns
        -------
        str
        """
        reg = np.degrees(self.regulatory_angle)
        n = len(self.pendulums)
        text = ""
        out = self.outside_domain
        if out:
            text += (f" {out} of {n} cases leave the model's domain (sheet Runs, 'domain'): "
                     f"their motions bound no angle, so no reduction below {reg:.3g} deg is "
                     "supported while they are in the motion set.")
        unflyable = int(np.count_nonzero(~self.flyable))
        if unflyable:
            text += (f" {unflyable} of {n} cases have carrier motions beyond what the carrier "
                     f"can fly ({self.limits.describe()}; sheet Runs, 'flyable'): they bound "
                     "no angle.")
        heavy = int(np.count_nonzero(self.carrier_force_ratio > CARRIER_FORCE_LIMIT))
        if heavy:
            text += (f" {heavy} cases load the carrier sideways above "
                     f"{CARRIER_FORCE_LIMIT:g} x its weight (largest T |sin theta1| over the "
                     "run): the prescribed (frozen-carrier) path is not assured for them.")
        return text

    def verdict(self):
        """The study's conclusion on the 30 deg rule, in words.

        Returns
        -------
        str
            The largest load angle and the recommended design angle against the regulatory one
            [deg], with the caveats.
        """
        found, rec = np.degrees(self.max_load_angle), np.degrees(self.recommended_angle)
        reg = np.degrees(self.regulatory_angle)
        caveats = self.caveats()
        if self.outside_domain == len(self.pendulums):
            return (f"Every case leaves the lateral pendulum's domain (slack cable, or rope or "
                    f"load angle past {np.degrees(DOMAIN_ANGLE):.3g} deg): no design angle; "
                    f"for this motion set the {reg:.3g} deg rule can be neither reduced nor "
                    "confirmed. Use flyable carrier motions.")
        if not np.any(self.counted):
            return ("No case has a flyable carrier motion inside the model's domain: no design "
                    f"angle.{caveats}")
        if not np.isfinite(rec):
            return (f"The largest load angle inside the domain is {found:.3g} deg; with the "
                    f"margin {self.margin:g} it reaches 90 deg: no hook cone can be built, no "
                    f"design angle. Restrict the operation (motions, masses, rope lengths) or "
                    f"show more damping.{caveats}")
        return self._verdict_inside(found, rec, reg) + caveats

    def _verdict_inside(self, found, rec, reg):
        if self.regulatory_angle_not_conservative:
            need = (f"the hook cases need at least {rec:.3g} deg ({self.margin:g} x "
                    f"{found:.3g} deg)." if rec < 90.0 else
                    f"with the margin ({rec:.3g} deg) no hook cone can be built: restrict the "
                    f"operation (motions, masses, rope lengths) or show more damping.")
            return (f"For this motion set the {reg:.3g} deg rule is NOT conservative: the "
                    f"largest load angle over the stated ranges is {found:.3g} deg, above "
                    f"{reg:.3g} deg; {need}")
        if self.exceeds_regulatory_angle:
            return (f"The recommended angle {rec:.3g} deg ({self.margin:g} x the largest load "
                    f"angle {found:.3g} deg) exceeds {reg:.3g} deg: no reduction is supported.")
        return (f"The recommended angle {rec:.3g} deg ({self.margin:g} x the largest load angle "
                f"{found:.3g} deg over the stated ranges) is below {reg:.3g} deg for this "
                f"motion set.")

    def to_frame(self):
        """One row per case: inputs and metrics, unit-labelled columns.

        Returns
        -------
        pandas.DataFrame
            One row per case, units in the column labels (kg, kg m^2, m, s, deg, -).
        """
        rows = []
        for p, m in zip(self.pendulums, self.motions, strict=True):
            rows.append({
                "body": p.body.name, "mass [kg]": p.body.mass,
                "roll inertia [kg m^2]": p.body.roll_inertia,
                "CG below hub [m]": p.body.cg_below_hub,
                "rope length [m]": p.rope_length,
                "cable EA [N]": np.inf if p.rigid else p.cable_ea,
                **_motion_row(m),
            })
        frame = pd.DataFrame(rows)
        frame.insert(0, "case", np.arange(1, len(rows) + 1))
        for j, name in enumerate(("roll inertia factor [-]", "CG below hub factor [-]",
                                  "rope length factor [-]")):
            frame.insert(6 + j, name, self.factors[:, j])
        frame.insert(9, "nominal rope length [m]", self.nominal_rope)
        frame.insert(10, "nominal [-]", self.nominal)
        for key, values in self.metrics.to_dict().items():
            frame[key] = values
        if self.hook_load_factor is not None:
            frame["T/(m g) > Nz [-]"] = self.exceeds_hook_load_factor
        frame["inside domain [-]"] = self.in_domain
        frame["domain"] = self.domain_notes()
        frame["flyable [-]"] = self.flyable
        frame["flyable note"] = self.flyable_notes()
        frame["max lateral cable force / carrier weight [-]"] = self.carrier_force_ratio
        return frame

    def nominal_case(self, index):
        """The case number (1-based, as :meth:`case_frame` lists it) of the nominal case of
        which run ``index`` (0-based, of :attr:`pendulums`) is a variant over the stated
        ranges: the same body, nominal rope length and carrier motion.

        Parameters
        ----------
        index : int
            A run of the sweep, 0-based. [-]

        Returns
        -------
        int
            Its nominal case, 1-based (the ``case`` of :meth:`case_frame`). [-]

        Examples
        --------
        A nominal run is its own case: ``study.nominal_case(j) == j + 1`` where
        ``study.nominal[j]``.
        """
        per_pendulum = len(self.pendulums) // len({id(p) for p in self.pendulums})

        def key(j):
            return (self.pendulums[j].body.name, float(self.nominal_rope[j]),
                    j % per_pendulum)

        target = key(int(index))
        return next(int(j) + 1 for j in np.flatnonzero(self.nominal) if key(j) == target)

    def case_frame(self):
        """One row per nominal case (body x rope length x motion): its inputs and metrics
        with the nominal roll inertia, CG and rope, and beside them the largest load angle
        over the stated ranges among the cases inside the model's domain (NaN: none), the
        factors that gave it, the largest tension factor and the number of cases of the
        ranges outside the domain.

        Returns
        -------
        pandas.DataFrame
            One row per nominal case, units in the column labels.
        """
        frame = self.to_frame()
        per_pendulum = len(self.pendulums) // len({id(p) for p in self.pendulums})
        frame["motion number"] = np.arange(len(frame)) % per_pendulum
        key = ["body", "nominal rope length [m]", "motion number"]
        inside = frame["inside domain [-]"].astype(bool) & frame["flyable [-]"].astype(bool)
        angle = frame["max |theta1 - theta2| [deg]"].where(inside).fillna(-np.inf)
        worst = frame.loc[angle.groupby([frame[k] for k in key], sort=False).idxmax()]
        worst = worst.set_index(key)
        worst.loc[~worst["inside domain [-]"].astype(bool), "max |theta1 - theta2| [deg]"] = (
            np.nan)
        factors = ["roll inertia factor [-]", "CG below hub factor [-]",
                   "rope length factor [-]"]
        out = frame[frame["nominal [-]"]].set_index(key)
        out["max |theta1 - theta2| over the ranges [deg]"] = \
            worst["max |theta1 - theta2| [deg]"]
        for name in factors:
            out[name.replace(" [-]", " at that maximum [-]")] = worst[name]
        out["max T/(m g) over the ranges [-]"] = frame.groupby(key)["max T/(m g) [-]"].max()
        out["cases outside the domain over the ranges [-]"] = (~inside).groupby(
            [frame[k] for k in key]).sum()
        out = out.reset_index().drop(columns=[*factors, "nominal [-]", "motion number"])
        return out[["case", *[c for c in out.columns if c != "case"]]]

    def summary_frame(self):
        """The largest load angle, its case, the margin and the recommended angle.

        Returns
        -------
        pandas.DataFrame
            Item, value and unit (deg, m, -).
        """
        case = self.critical_case
        items = [
            ("cases run", len(self.pendulums), "-"),
            ("largest load angle |theta1 - theta2|, nominal inputs",
             np.degrees(self.nominal_max_load_angle), "deg"),
            ("largest load angle |theta1 - theta2| over the stated ranges",
             np.degrees(self.max_load_angle), "deg"),
            ("case producing it", int(case["case"]), "-"),
            ("  body", case["body"], "-"),
            ("  roll inertia", case["roll inertia [kg m^2]"], "kg m^2"),
            ("  CG below hub", case["CG below hub [m]"], "m"),
            ("  rope length", case["rope length [m]"], "m"),
            ("  carrier motion", case["motion description"], "-"),
            ("  time of the maximum", case["t at max |theta1 - theta2| [s]"], "s"),
            ("  cable slack in that case", bool(case["slack [-]"]), "-"),
            ("cases whose cable went slack", int(np.sum(self.metrics.slack)), "-"),
            ("cases outside the model's domain (no design value)", self.outside_domain, "-"),
            ("cases with a carrier motion beyond the carrier's limits",
             int(np.count_nonzero(~self.flyable)), "-"),
            ("largest load angle, cases that stayed taut",
             np.degrees(self.max_load_angle_taut), "deg"),
            ("margin", self.margin, "-"),
            ("recommended design angle", np.degrees(self.recommended_angle), "deg"),
            ("CS-29.865 angle", np.degrees(self.regulatory_angle), "deg"),
            ("recommended angle exceeds CS-29.865 angle", self.exceeds_regulatory_angle, "-"),
            ("CS-29.865 angle not conservative for this motion set",
             self.regulatory_angle_not_conservative, "-"),
            ("largest cable tension factor T/(m g)", self.max_tension_ratio, "-"),
        ]
        if self.hook_load_factor is not None:
            items += [("hook load factor Nz", self.hook_load_factor, "-"),
                      ("cases with T/(m g) above Nz",
                       int(np.sum(self.exceeds_hook_load_factor)), "-")]
        items += [("damping", self.damping.source if not self.damping.off else "none", "-"),
                  ("run length", self.t_end, "s"),
                  ("RK4 step", self.step, "s")]
        return pd.DataFrame(items, columns=["quantity", "value", "unit"])

    def sensitivity_frame(self):
        """Largest load angle and tension factor against each parameter's factor.

        For each of roll inertia, CG below hub and rope length, and each of its factors:
        the maxima over bodies, ropes and motions with the two other parameters nominal
        ("one at a time") and over their whole ranges ("envelope").

        Returns
        -------
        pandas.DataFrame
            Parameter, factor [-], largest load angle [deg] and tension factor [-], one at a time
            and over the envelope.
        """
        angle = np.degrees(self.metrics.max_load_angle)
        ratio = self.metrics.max_tension_ratio
        rows = []
        for j, name in enumerate(ParameterRanges.NAMES):
            others = np.delete(self.factors, j, axis=1)
            alone = np.all(others == 1.0, axis=1)
            for f in np.unique(self.factors[:, j]):
                at = self.factors[:, j] == f
                rows.append({
                    "parameter": name, "factor [-]": f,
                    "max load angle, others nominal [deg]": _max(angle[at & alone]),
                    "max load angle, others over their ranges [deg]": _max(angle[at]),
                    "max T/(m g), others nominal [-]": _max(ratio[at & alone]),
                    "max T/(m g), others over their ranges [-]": _max(ratio[at]),
                })
        return pd.DataFrame(rows)

    def tension_frame(self):
        """Largest cable tension factor per carrier motion (over bodies, ropes and ranges)
        against the hook load factor Nz, with the exceedance flagged.

        Returns
        -------
        pandas.DataFrame
            One row per carrier motion: largest and smallest T/(m g) [-], largest load angle [deg],
            against the hook load factor [-].
        """
        frame = self.to_frame()
        grouped = frame.groupby("motion description", sort=False)
        out = grouped.agg(**{
            "max T/(m g) [-]": ("max T/(m g) [-]", "max"),
            "min T/(m g) [-]": ("min T/(m g) [-]", "min"),
            "max |theta1 - theta2| [deg]": ("max |theta1 - theta2| [deg]", "max"),
        }).reset_index()
        if self.hook_load_factor is not None:
            out["Nz [-]"] = self.hook_load_factor
            out["T/(m g) above Nz [-]"] = out["max T/(m g) [-]"] > self.hook_load_factor
        return out

    def envelope_frame(self):
        """Largest load angle per nominal rope length and peak carrier acceleration, over
        the stated ranges. Velocity steps (no finite acceleration) are left out.

        Returns
        -------
        pandas.DataFrame
            Nominal rope length [m], peak S'' [g] and largest load angle [deg].
        """
        frame = self.to_frame()
        frame = frame[np.isfinite(frame["peak S'' [m/s^2]"])]
        return (frame.groupby(["nominal rope length [m]", "peak S'' [g]"], as_index=False)
                ["max |theta1 - theta2| [deg]"].max())

    def frames(self):
        """Sheet name -> DataFrame, for the Excel report.

        Returns
        -------
        dict of str to pandas.DataFrame
        """
        return {"lateral summary": self.summary_frame(), "lateral runs": self.to_frame(),
                "lateral cases": self.case_frame(), "lateral envelope": self.envelope_frame(),
                "lateral sensitivity": self.sensitivity_frame(),
                "lateral tension": self.tension_frame(),
                "lateral ranges": self.ranges.to_frame(),
                "lateral damping": self.damping.to_frame()}

    def run_case(self, index=None, solver=None):
        """Re-run one case (default the critical one) with solve_ivp for its time histories.

        Parameters
        ----------
        index : int, optional
            0-based case index (the ``case`` column minus 1). [-]
        solver : SolverSettings, optional
            solve_ivp settings (default the study's); the run length is the study's.

        Returns
        -------
        LateralRun
        """
        index = self.critical_index if index is None else int(index)
        if not 0 <= index < len(self.pendulums):
            raise InputError(f"case index must lie in [0, {len(self.pendulums) - 1}]", index)
        solver = self.solver if solver is None else solver_settings(solver)
        return simulate(self.pendulums[index], self.motions[index],
                        solver=replace(solver, t_end=self.t_end))

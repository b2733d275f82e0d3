"""The campaign matrix: which runs the multibody model is flown through (paper section 4.4).

A run is one parachute area in one operating condition under one manoeuvre. The factors are

* the parachute area, as a factor of the neutral static area (paper: 1.0 to 2.0);
* the equivalent airspeed (paper: up to 100 KEAS);
* the mass case of the carried helicopter (paper: maximum, medium, minimum);
* the ISA density altitude (paper: sea level, 5,000 and 10,000 ft);
* the carrier-to-hub cable length (paper: 18, 60 and 100 ft);
* the carrier, ``"frozen"`` (the hook follows its path) or ``"free"`` (paper, figure 13);
* the manoeuvre (:data:`MANOEUVRES`).

The matrix is the full factorial of the factors (:meth:`CampaignMatrix.from_factors`) or a
list of rows (:meth:`CampaignMatrix.from_rows`). A *condition* is everything but the area and
the manoeuvre (:data:`CONDITION_COLUMNS`): "stable in every condition" means every run of
every condition, under every manoeuvre.

A mass case scales the helicopter's inertia tensor with its mass (same radii of gyration) and
keeps its centre of gravity.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.constants import FOOT, KNOT
from slingloads.errors import InputError
from slingloads.ids import first_duplicate
from slingloads.models.atmosphere import isa_density, true_airspeed
from slingloads.models.gusts import GUST_VELOCITY, make_gust
from slingloads.models.multibody.carrier import ForwardAcceleration
from slingloads.models.multibody.environment import Wind

#: Carrier models a run may use.
CARRIERS = ("frozen", "free")

#: Columns of the matrix, in order (SI).
COLUMNS = ("run", "area factor [-]", "area [m^2]", "airspeed EAS [m/s]", "mass case",
           "mass [kg]", "density altitude [m]", "cable length [m]", "carrier", "manoeuvre")
#: The columns that make up an operating condition.
CONDITION_COLUMNS = ("airspeed EAS [m/s]", "mass case", "density altitude [m]",
                     "cable length [m]", "carrier")
#: The factors of a listed row (columns of :meth:`CampaignMatrix.from_rows`).
ROW_FACTORS = ("area factor [-]", "airspeed EAS [m/s]", "mass case", "density altitude [m]",
               "cable length [m]", "carrier", "manoeuvre")

#: Initial yaw of the free response. [rad]
FREE_RESPONSE_YAW = np.radians(10.0)
#: Lateral gust of the campaign: 10 s finite ("impulsive") gust starting at 5 s. [s]
GUST_ONSET, GUST_DURATION = 5.0, 10.0
#: Forward acceleration from hover to the run's airspeed: peak [m/s^2], jerk time [s], onset [s].
ACCELERATION, JERK_TIME, ACCELERATION_ONSET = 1.5, 2.0, 5.0
#: Yaw seed of the starts from hover (a perfectly symmetric start stays symmetric). [rad]
HOVER_SEED = np.radians(2.0)


@dataclass(frozen=True)
class ManoeuvreKind:
    """A manoeuvre of the campaign, built for each run's condition.

    Attributes
    ----------
    name : str
    description : str
    """

    name: str
    description: str

    def build(self, airspeed, density_altitude):
        """The :class:`~slingloads.analyses.multibody.Manoeuvre` at a condition.

        Parameters
        ----------
        airspeed : float
            Equivalent airspeed of the run. [m/s]
        density_altitude : float
            [m]

        Returns
        -------
        Manoeuvre
        """
        from slingloads.analyses.multibody.manoeuvres import Manoeuvre

        name = self.name
        if name == "free response":
            return Manoeuvre(name, disturbance={"yaw": FREE_RESPONSE_YAW})
        if name.startswith("gust "):
            sign = 1.0 if name[5] == "+" else -1.0
            gust = make_gust("finite", sign * GUST_VELOCITY, GUST_ONSET, GUST_DURATION)
            return Manoeuvre(name, wind=Wind(gust=gust, direction="lateral"))
        if name == "acceleration":
            if airspeed <= 0:
                raise InputError("the acceleration manoeuvre needs an airspeed > 0 [m/s]",
                                 airspeed)
            tas = float(true_airspeed(airspeed, density_altitude))
            return Manoeuvre(name, trajectory=ForwardAcceleration(
                tas, ACCELERATION, ACCELERATION_ONSET, JERK_TIME),
                disturbance={"yaw": HOVER_SEED})
        raise InputError(f"unknown manoeuvre; valid manoeuvres are {list(MANOEUVRES)}", name)


#: The manoeuvres of the campaign (paper section 4.4), by name.
MANOEUVRES = {m.name: m for m in (
    ManoeuvreKind("free response", "free response from 10 deg of yaw at trim"),
    # descriptions in SI (a US report quotes the gust in ft/s: 9.144 m/s = 30 ft/s exactly)
    ManoeuvreKind("gust +30 ft/s", "lateral 10 s gust of +9.144 m/s (from the right) at 5 s"),
    ManoeuvreKind("gust -30 ft/s", "lateral 10 s gust of -9.144 m/s (from the left) at 5 s"),
    ManoeuvreKind("acceleration", "forward acceleration from hover to the run's airspeed, "
                                  "1.5 m/s^2 peak, 2 s jerk, from 5 s (2 deg yaw seed)"),
)}


@dataclass(frozen=True)
class MassCase:
    """A mass case of the carried helicopter.

    Parameters
    ----------
    name : str
        e.g. "maximum", "medium", "minimum".
    mass : float
        > 0. [kg]
    """

    name: str
    mass: float

    def __post_init__(self):
        name = str(self.name).strip()
        if not name:
            raise InputError("a mass case needs a name", self.name)
        mass = float(self.mass)
        if not np.isfinite(mass) or mass <= 0:
            raise InputError(f"mass of the mass case {name!r} must be > 0 [kg]", self.mass)
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "mass", mass)


def _positive_list(values, what, unit, allow_zero=False):
    out = np.atleast_1d(np.asarray(values, dtype=float)).ravel()
    if out.size == 0:
        raise InputError(f"the campaign needs at least one {what}", list(out))
    for v in out:
        if not np.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
            rule = ">= 0" if allow_zero else "> 0"
            raise InputError(f"every {what} must be {rule} [{unit}]", float(v))
    if len(set(out.tolist())) != out.size:
        dup = next(v for v in out if np.count_nonzero(out == v) > 1)
        raise InputError(f"{what} listed twice", float(dup))
    return tuple(float(v) for v in out)


def _names(values, valid, what):
    values = (values,) if isinstance(values, str) else tuple(values)
    if not values:
        raise InputError(f"the campaign needs at least one {what}")
    for v in values:
        if v not in valid:
            raise InputError(f"unknown {what}; valid values are {list(valid)}", v)
        if values.count(v) > 1:
            raise InputError(f"{what} listed twice", v)
    return values


@dataclass(frozen=True)
class Factors:
    """The factors of a full-factorial campaign (module notes), SI.

    Parameters
    ----------
    area_factors : sequence of float
        Parachute areas over the neutral static area, > 0 (paper: 1.0 to 2.0). [-]
    airspeeds : sequence of float
        Equivalent airspeeds, > 0 (paper: up to 100 KEAS). [m/s]
    masses : sequence of MassCase
        (default: one case, the helicopter's own mass, named "nominal").
    density_altitudes : sequence of float
        ISA density altitudes. [m]
    cable_lengths : sequence of float
        Carrier-to-hub cable lengths, > 0. [m]
    carriers : sequence of str
        Of :data:`CARRIERS`.
    manoeuvres : sequence of str
        Of :data:`MANOEUVRES`.
    """

    area_factors: tuple = (1.0, 1.2, 1.4, 1.6, 1.8, 2.0)
    airspeeds: tuple = tuple(v * KNOT for v in (40.0, 60.0, 80.0, 100.0))
    masses: tuple = ()
    density_altitudes: tuple = (0.0, 5000 * FOOT, 10000 * FOOT)
    cable_lengths: tuple = tuple(v * FOOT for v in (60.0, 100.0))
    carriers: tuple = ("frozen",)
    manoeuvres: tuple = ("free response", "gust +30 ft/s", "gust -30 ft/s")

    def __post_init__(self):
        object.__setattr__(self, "area_factors", _positive_list(
            self.area_factors, "parachute area factor", "-"))
        object.__setattr__(self, "airspeeds", _positive_list(
            self.airspeeds, "airspeed", "m/s"))
        altitudes = np.atleast_1d(np.asarray(self.density_altitudes, float))
        if altitudes.size == 0:
            raise InputError("the campaign needs at least one density altitude")
        for h in altitudes:
            isa_density(h)  # validates the altitude
        if len(set(altitudes.tolist())) != altitudes.size:
            raise InputError("density altitude listed twice", altitudes.tolist())
        object.__setattr__(self, "density_altitudes", tuple(float(h) for h in altitudes))
        object.__setattr__(self, "cable_lengths", _positive_list(
            self.cable_lengths, "cable length", "m"))
        object.__setattr__(self, "carriers", _names(self.carriers, CARRIERS, "carrier"))
        object.__setattr__(self, "manoeuvres", _names(self.manoeuvres, MANOEUVRES,
                                                      "manoeuvre"))
        masses = tuple(self.masses)
        for m in masses:
            if not isinstance(m, MassCase):
                raise InputError("mass cases must be MassCase objects", type(m).__name__)
        names = [m.name for m in masses]
        twice = first_duplicate(names)
        if twice is not None:
            raise InputError("mass case named twice (names are compared with case ignored)",
                             names[twice[1]])
        object.__setattr__(self, "masses", masses)

    @property
    def size(self):
        """Number of runs of the full factorial."""
        return (len(self.area_factors) * len(self.airspeeds) * max(len(self.masses), 1)
                * len(self.density_altitudes) * len(self.cable_lengths) * len(self.carriers)
                * len(self.manoeuvres))


@dataclass(frozen=True, eq=False)
class CampaignMatrix:
    """The runs of a campaign, one row each (columns :data:`COLUMNS`, SI).

    Build with :meth:`from_factors` or :meth:`from_rows`.

    Attributes
    ----------
    frame : pandas.DataFrame
    neutral_area : float
        Neutral static area the area factors multiply. [m^2]
    masses : dict
        Mass of each mass case. [kg]
    """

    frame: pd.DataFrame
    neutral_area: float
    masses: dict

    def __len__(self):
        return len(self.frame)

    @staticmethod
    def _mass_cases(masses, base_mass):
        masses = tuple(masses) or (MassCase("nominal", base_mass),)
        return {m.name: m.mass for m in masses}

    @classmethod
    def from_factors(cls, factors, neutral_area, base_mass):
        """Full factorial of ``factors``.

        Parameters
        ----------
        factors : Factors
        neutral_area : float
            [m^2]
        base_mass : float
            Mass of the default mass case (when ``factors.masses`` is empty). [kg]

        Returns
        -------
        CampaignMatrix
        """
        if not isinstance(factors, Factors):
            raise InputError("from_factors needs a Factors object", type(factors).__name__)
        area = _neutral(neutral_area)
        masses = cls._mass_cases(factors.masses, base_mass)
        rows = itertools.product(factors.area_factors, factors.airspeeds, masses,
                                 factors.density_altitudes, factors.cable_lengths,
                                 factors.carriers, factors.manoeuvres)
        frame = pd.DataFrame(list(rows), columns=list(ROW_FACTORS))
        return cls(_finish(frame, area, masses), area, masses)

    @classmethod
    def from_rows(cls, rows, neutral_area, masses=(), base_mass=None):
        """Listed rows instead of the full factorial.

        Parameters
        ----------
        rows : pandas.DataFrame or sequence of dict
            Columns :data:`ROW_FACTORS` (SI); "mass case" may be omitted when there is a
            single mass case.
        neutral_area : float
            [m^2]
        masses : sequence of MassCase
            The mass cases the rows name (default: one, "nominal", of ``base_mass``).
        base_mass : float, optional
            [kg]

        Returns
        -------
        CampaignMatrix
        """
        area = _neutral(neutral_area)
        if not masses and base_mass is None:
            raise InputError("listed rows need their mass cases (or the base mass)")
        cases = cls._mass_cases(masses, base_mass)
        frame = pd.DataFrame(rows).copy()
        if len(frame) == 0:
            raise InputError("the campaign matrix is empty: no run is listed")
        if "mass case" not in frame and len(cases) == 1:
            frame["mass case"] = next(iter(cases))
        missing = [c for c in ROW_FACTORS if c not in frame]
        if missing:
            raise InputError(f"listed campaign rows need the columns {list(ROW_FACTORS)}",
                             missing)
        frame = frame[list(ROW_FACTORS)]
        for i, row in frame.iterrows():
            _check_row(row, i, cases)
        return cls(_finish(frame, area, cases), area, cases)

    def conditions(self):
        """The distinct operating conditions (columns :data:`CONDITION_COLUMNS` and the mass
        of the mass case).

        Returns
        -------
        pandas.DataFrame
            One row per condition, units in the column labels.
        """
        return self.frame[[*CONDITION_COLUMNS, "mass [kg]"]].drop_duplicates().reset_index(
            drop=True)


def _neutral(area):
    area = float(area)
    if not np.isfinite(area) or area <= 0:
        raise InputError("the neutral static parachute area must be > 0 [m^2] (fuselage and "
                         "fin already stable need no parachute campaign)", area)
    return area


def _check_row(row, i, cases):
    where = f"listed campaign row {i + 1}"
    for column, unit in (("area factor [-]", "-"), ("airspeed EAS [m/s]", "m/s"),
                         ("cable length [m]", "m")):
        value = float(row[column])
        if not np.isfinite(value) or value <= 0:
            raise InputError(f"{where}: {column.split(' [')[0]} must be > 0 [{unit}]",
                             row[column])
    isa_density(float(row["density altitude [m]"]))
    checks = (("mass case", list(cases)), ("carrier", list(CARRIERS)),
              ("manoeuvre", list(MANOEUVRES)))
    for column, valid in checks:
        if row[column] not in valid:
            raise InputError(f"{where}: unknown {column}; valid values are {valid}",
                             row[column])


def _finish(frame, neutral_area, masses):
    if len(frame) == 0:
        raise InputError("the campaign matrix is empty")
    frame = frame.reset_index(drop=True)
    frame["area factor [-]"] = frame["area factor [-]"].astype(float)
    frame["area [m^2]"] = frame["area factor [-]"] * neutral_area
    frame["mass [kg]"] = frame["mass case"].map(masses).astype(float)
    dup = frame.duplicated(list(ROW_FACTORS))
    if dup.any():
        raise InputError("the same run is listed twice",
                         frame.loc[dup, list(ROW_FACTORS)].iloc[0].tolist())
    width = max(4, len(str(len(frame))))
    frame.insert(0, "run", [f"R{i + 1:0{width}d}" for i in range(len(frame))])
    return frame[list(COLUMNS)]

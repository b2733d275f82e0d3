"""The load cases as Nastran bulk data: ``<stem>-loads.bdf``.

:func:`write_nastran` (``LoadsResult.to_nastran``, ``slingloads loads --nastran``) writes one
Nastran input file (method, card choices and how to include it in a model: ``docs/nastran.md``):

* executive and case control: ``SOL 101``, one ``SUBCASE`` per load case with
  ``LABEL = <case id> <description>`` and ``LOAD = <set>``;
* a ``GRID`` per mass item and per load point (rotor hub, mast feet, aerodynamic points, fin
  centre of pressure, parachute attachment), in the model's basic system (the project's
  airframe axes through an optional offset and axis map, :class:`ModelAxes`);
* a ``CONM2`` per mass item at its own grid (its own inertia, no offset);
* per case a ``LOAD`` combination of ``FORCE`` and ``MOMENT`` cards (the applied loads;
  scale 1.0 and the vector's components), the shared ``GRAV`` of gravity along the
  attitude's downward vertical (a towed case, which flies its own trimmed attitude, has its
  own gravity ``GRAV`` in its place), and, with ``inertia_relief="accelerations"``, the rigid-body
  accelerations of the inertia relief as a ``GRAV`` (linear) and an ``RFORCE`` (angular,
  about the basic origin) with ``MOMENT`` cards for the items' own rotary inertia (which
  RFORCE does not load); with ``"inrel"``, ``PARAM,INREL,-2`` and no inertia cards: Nastran
  finds the accelerations from the CONM2s.

Cards are written by hand in **large-field fixed format**: 16-character fields, every real
with eleven significant digits in Nastran's exponent form without ``E`` (``-2.3853270124+04``),
which 8-character small fields could not hold; every line at most 72 characters. The writing
is vectorised (one ``%`` formatting per card type over a block of cases); the test suite reads
every card back with pyNastran. Loads below :data:`ROUND_OFF` of their case's scale are not
written. Units are one consistent set: SI (m, N, kg, s) or US (in, lbf, s, mass in
lbf s^2/in); ``PARAM,WTMASS`` must stay 1.0.
"""

from __future__ import annotations

import unicodedata
import zlib
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np
import pandas as pd

import slingloads
from slingloads.analyses.fe_loads import HOOK_POINTS, ModelAxes, PointLoadCases
from slingloads.constants import G0, INCH, POUND_FORCE
from slingloads.errors import InputError
from slingloads.io.common.atomic import atomic_outputs, check_outputs
from slingloads.io.common.locate import Place, located
from slingloads.io.common.report import digest_frame

#: Inertia-relief set-ups of the deck.
INERTIA_RELIEF = ("accelerations", "inrel")
#: Largest Nastran identification number (eight digits).
MAX_ID = 99_999_999
#: Most case x point pairs (cases x (load points + mass items)) written in one file: about
#: 120 MB of cards at the limit (the example's airframe: 120 bytes per case and point).
MAX_CASE_POINTS = 1_000_000
#: Longest case id kept whole in a LABEL; longer or non-ASCII ids are shortened with a hash.
LABEL_ID_LENGTH = 40
#: Characters of a case-control line (Nastran reads 72 columns).
LINE_LENGTH = 72
#: Defaults of the identification numbers.
DEFAULT_IDS = {"first_grid_id": 900_001, "first_element_id": 900_001,
               "load_id_base": 100_000, "first_subcase": 1}
#: Load-set numbering: subcase s uses base + 10 s + offset; base + 1 is the gravity GRAV
#: shared by the cases at the study's attitude; "gravity" is a case's own gravity GRAV (a towed
#: case at its trimmed attitude), which its LOAD takes in place of the shared one.
SET_OFFSETS = {"LOAD": 0, "applied": 1, "linear inertia": 2, "angular inertia": 3,
               "rotary inertia": 4, "gravity": 5}
GRAVITY_SET = 1
#: Loads below this fraction of their case's load scale (largest force, and that force times
#: the size of the model for moments) are round-off, far below the ten digits of a field,
#: and are not written; so are direction components below it.
ROUND_OFF = 1e-12

#: A real as ``%17.10E`` without its ``E`` (Nastran's ``-2.3853270120+04``): 16 characters,
#: eleven significant digits.
_REAL = "%17.10E"
_INT = "%16d"
_BLANK = " " * 16
_CONT = "\n*       "
#: Largest magnitude a 16-character real holds with its sign; smaller than 1e-99 is written 0.
_REAL_LIMIT = 1e99
_TINY = 1e-99


@dataclass(frozen=True)
class NastranUnits:
    """A consistent Nastran unit set: factors from SI and the labels written in the file.

    Attributes
    ----------
    name : str
        ``"SI"`` or ``"US"``.
    factors : dict
        Multiply an SI value of each kind by its factor.
    labels : dict
        Unit of each kind as written in the comments and report headers.
    """

    name: str
    factors: dict
    labels: dict

    def __call__(self, values, kind):
        """SI ``values`` of quantity ``kind`` in this unit set."""
        return np.asarray(values, float) * self.factors[kind]

    def describe(self):
        lab = self.labels
        return (f"{self.name}: length {lab['length']}, force {lab['force']}, mass "
                f"{lab['mass']}, time s; moment {lab['moment']}, inertia {lab['inertia']}, "
                f"acceleration {lab['acceleration']}, angular acceleration rad/s^2")


#: The unit sets of ``--units``. US: lbf, in, s and the mass that goes with them,
#: 1 lbf s^2/in = POUND_FORCE / INCH kg (about 175.1 kg), so that F = m a holds in the file.
UNIT_SYSTEMS = {
    "SI": NastranUnits("SI", {
        "length": 1.0, "force": 1.0, "mass": 1.0, "moment": 1.0, "inertia": 1.0,
        "acceleration": 1.0, "angular acceleration": 1.0,
    }, {"length": "m", "force": "N", "mass": "kg", "moment": "N m", "inertia": "kg m^2",
        "acceleration": "m/s^2"}),
    "US": NastranUnits("US", {
        "length": 1 / INCH, "force": 1 / POUND_FORCE, "mass": INCH / POUND_FORCE,
        "moment": 1 / (POUND_FORCE * INCH), "inertia": 1 / (POUND_FORCE * INCH),
        "acceleration": 1 / INCH, "angular acceleration": 1.0,
    }, {"length": "in", "force": "lbf", "mass": "lbf s^2/in", "moment": "lbf in",
        "inertia": "lbf in s^2", "acceleration": "in/s^2"}),
}


def write_nastran(result, path, **options):
    """Write the load cases of a loads result as a Nastran input file, atomically.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    path : path-like
        The ``.bdf`` file to write (its directory is created if needed).
    **options
        Those of :func:`prepare_nastran`.

    Returns
    -------
    NastranDeck
        What was written, with :meth:`NastranDeck.subcase_table` (subcase -> case id).

    Raises
    ------
    InputError
        On a bad option (see :func:`prepare_nastran`), or if ``path`` is a file slingloads
        did not write (:func:`slingloads.io.common.atomic.check_outputs`); nothing is
        written then.
    """
    path = Path(path)
    check_outputs(path.parent, [path.name], ())
    deck = prepare_nastran(result, **options)
    with atomic_outputs(path.parent) as out:
        deck.write(out.path(path.name))
    return deck


def prepare_nastran(result, *, units="SI", axes="x, y, z", offset=(0.0, 0.0, 0.0),
                    inertia_relief="accelerations", hook_at="mast feet",
                    first_grid_id=DEFAULT_IDS["first_grid_id"],
                    first_element_id=DEFAULT_IDS["first_element_id"],
                    load_id_base=DEFAULT_IDS["load_id_base"],
                    first_subcase=DEFAULT_IDS["first_subcase"], title=None,
                    inputs_digest=None, max_case_points=MAX_CASE_POINTS, locations=None):
    """Check the options and lay out the deck (ids, labels, units); nothing is written.

    Parameters
    ----------
    result : slingloads.analyses.loads.LoadsResult
    units : str
        ``"SI"`` (m, N, kg, s) or ``"US"`` (in, lbf, s, lbf s^2/in).
    axes : str or array_like, shape (3, 3)
        The model's axes (:class:`~slingloads.analyses.fe_loads.ModelAxes`): three signed
        project axes for its X, Y, Z (``"-x, y, -z"``) or the rotation R.
    offset : array_like, shape (3,)
        Position of the project's origin in model axes. [m]
    inertia_relief : str
        ``"accelerations"`` (inertia loads in every subcase: self-balanced, constrain the
        model statically determinate) or ``"inrel"`` (``PARAM,INREL,-2``).
    hook_at : str
        ``"mast feet"`` or ``"hub"`` (:data:`~slingloads.analyses.fe_loads.HOOK_POINTS`).
    first_grid_id, first_element_id : int
        Ids of the first GRID and CONM2 (the others follow). [-]
    load_id_base : int
        Load sets are ``load_id_base + 1`` (gravity) and ``load_id_base + 10 s + 0..4`` for
        subcase s (LOAD, applied, linear, angular and rotary inertia). [-]
    first_subcase : int
        Number of the first subcase (the others follow in case order). [-]
    title : str, optional
        TITLE of the deck (default: the study name).
    inputs_digest : dict or pandas.DataFrame, optional
        What the analysis was run from (input file, SHA-256...), stated in the comments.
    max_case_points : int
        Refuse more than this many cases x (load points + mass items).
    locations : dict, optional
        Where each option was read from, for error messages: option name or
        ``("case", case id)`` -> ``{"sheet": ..., "cell": ..., "name": ...}`` (``name``: how
        the message calls the option, e.g. its Study row).

    Returns
    -------
    NastranDeck

    Raises
    ------
    InputError
        On an unknown unit system, inertia-relief set-up or hook point; an axis map that is
        not a rotation or an offset that is not finite; an id that is not a positive integer
        or a range past 99,999,999; case ids that cannot be made distinct Nastran labels;
        more than ``max_case_points``.
    """
    where = _Locator(locations)
    _choice(units, UNIT_SYSTEMS, "units", where)
    _choice(inertia_relief, INERTIA_RELIEF, "inertia_relief", where)
    _choice(hook_at, HOOK_POINTS, "hook_at", where)
    with where.of("axes"):
        axes = ModelAxes(axes, (0.0, 0.0, 0.0))
    with where.of("offset"):
        model_axes = ModelAxes(axes.rotation, offset)
    ids = {name: _whole(value, name, 0 if name == "load_id_base" else 1, where)
           for name, value in (("first_grid_id", first_grid_id),
                               ("first_element_id", first_element_id),
                               ("load_id_base", load_id_base),
                               ("first_subcase", first_subcase))}
    loads = PointLoadCases.from_result(result, hook_at=hook_at).in_model_axes(model_axes)
    _check_size(loads, max_case_points)
    _check_id_ranges(loads, ids, where)
    labels = case_labels(loads.case_ids, where)
    return NastranDeck(loads=loads, units=UNIT_SYSTEMS[units], inertia_relief=inertia_relief,
                       ids=ids, labels=labels,
                       title=str(result.study.name if title is None else title),
                       digest=_digest(inputs_digest), attitude=result.attitude)


def _digest(inputs_digest):
    """``{item: entry}`` from a dict or a two-column table (:func:`digest_frame`)."""
    frame = digest_frame(inputs_digest)
    if frame is None:
        return {}
    return {str(row[0]): row[1] for row in frame.itertuples(index=False)}


class _Locator:
    """Fills the sheet and cell of an option into the errors raised about it."""

    def __init__(self, locations):
        self.locations = dict(locations or {})

    def get(self, key):
        """``sheet`` and ``cell`` of option ``key`` (empty if unknown)."""
        where = dict(self.locations.get(key) or {})
        for extra in ("name", "value", "unit"):
            where.pop(extra, None)
        return where

    def name(self, key):
        """How the messages call option ``key`` (its Study row, or the keyword)."""
        return (self.locations.get(key) or {}).get("name", key)

    def error(self, key, rule, value):
        return InputError(rule, value, **self.get(key))

    def of(self, key):
        """Locate the errors of a model built from option ``key`` at its cell, echoing its
        value as written (when the locations give it) in place of the model's."""
        where = self.locations.get(key) or {}
        if where.get("cell") is not None:
            return located(Place(None, where.get("sheet"), where["cell"], where.get("value"),
                                 where.get("unit")))
        return located(Place(**self.get(key)))


def _choice(value, valid, key, where):
    if value not in valid:
        raise where.error(key, f"{where.name(key)}={value!r} is not valid; valid values are "
                               f"{list(valid)}", value)


def _whole(value, key, smallest, where):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not (
            smallest <= int(value) <= MAX_ID):
        raise where.error(key, f"{where.name(key)} must be a whole number from {smallest} to "
                               f"{MAX_ID:,}", value)
    return int(value)


def _check_size(loads, limit):
    size = loads.n_cases * (len(loads.point_ids) + len(loads.masses))
    if size > limit:
        raise InputError(f"too many load cases for one Nastran file: {loads.n_cases} cases x "
                         f"{len(loads.point_ids) + len(loads.masses)} points (load points and "
                         f"mass items) = {size:,} is above the limit of {limit:,}; split the "
                         "cases into several studies", size)


def _check_id_ranges(loads, ids, where):
    """Every id range must end at or below :data:`MAX_ID`."""
    n_grids = len(loads.masses) + len(loads.point_ids)
    last = {
        "first_grid_id": (ids["first_grid_id"] + n_grids - 1, f"{n_grids} grids"),
        "first_element_id": (ids["first_element_id"] + len(loads.masses) - 1,
                             f"{len(loads.masses)} CONM2 elements"),
        "first_subcase": (ids["first_subcase"] + loads.n_cases - 1,
                          f"{loads.n_cases} subcases"),
        "load_id_base": (ids["load_id_base"] + 10 * (ids["first_subcase"] + loads.n_cases - 1)
                         + max(SET_OFFSETS.values()),
                         f"10 load-set ids per subcase up to subcase "
                         f"{ids['first_subcase'] + loads.n_cases - 1}"),
    }
    for key, (end, what) in last.items():
        if end > MAX_ID:
            name = where.name(key)
            raise where.error(key, f"{name}: the ids of {what} would run to {end:,}, past the "
                                   f"largest Nastran id {MAX_ID:,}; choose a smaller {name}",
                              ids[key])


def case_labels(case_ids, where=None):
    """The text of each case id as it appears in a Nastran LABEL.

    An id of printable ASCII characters without ``$`` and at most :data:`LABEL_ID_LENGTH`
    characters is kept as it is. Any other is written in ASCII (accents dropped, other
    characters as ``_``), cut to fit and followed by ``~`` and eight hexadecimal digits of a
    checksum of the whole id, so that distinct ids stay distinct; the subcase table keeps the
    link to the id itself.

    Raises
    ------
    InputError
        If two case ids still give the same label (located at the second).
    """
    where = where or _Locator(None)
    labels, seen = [], {}
    for case_id in case_ids:
        label = _label(case_id)
        if label in seen:
            raise where.error(("case", case_id),
                              f"case ids {seen[label]!r} and {case_id!r} give the same Nastran "
                              f"label {label!r} (labels are printable ASCII without '$', at "
                              f"most {LABEL_ID_LENGTH} characters, a longer or non-ASCII id "
                              "ends in '~' and a checksum); rename one of them", case_id)
        seen[label] = case_id
        labels.append(label)
    return tuple(labels)


def _label(case_id):
    text = str(case_id)
    if _printable(text) and 0 < len(text) <= LABEL_ID_LENGTH and text == text.strip():
        return text
    ascii_text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode()
    ascii_text = "".join(c if _printable(c) else "_" for c in ascii_text).strip()
    checksum = f"{zlib.crc32(text.encode('utf-8')):08x}"
    return f"{ascii_text[:LABEL_ID_LENGTH - 9]}~{checksum}"


def _without_accents(text):
    """``text`` with accents dropped (``é`` -> ``e``); other characters kept."""
    text = str(text)
    if text.isascii():
        return text
    return "".join(c for c in unicodedata.normalize("NFKD", text)
                   if not unicodedata.combining(c))


def _printable(text):
    return all(" " <= c <= "~" and c != "$" for c in text)


def _ascii(text):
    """Text for a comment: non-ASCII characters escaped (``\\u00e9``), control characters as
    spaces."""
    text = str(text)
    if text.isascii() and text.isprintable():
        return text
    text = text.encode("ascii", "backslashreplace").decode("ascii")
    return "".join(c if " " <= c <= "~" else " " for c in text)


def _comment(text, indent=""):
    """``$`` comment lines of at most :data:`LINE_LENGTH` characters, cut at spaces."""
    width = LINE_LENGTH - 2 - len(indent)
    text = _ascii(text).rstrip()
    lines = []
    while len(text) > width:
        cut = text.rfind(" ", 0, width + 1)
        cut = cut if cut > 0 else width
        lines.append(text[:cut])
        text = text[cut:].lstrip()
    lines.append(text)
    return "".join(f"$ {indent}{line}".rstrip() + "\n" for line in lines)


@dataclass(frozen=True)
class NastranDeck:
    """A Nastran input file laid out and checked, ready to write (:func:`prepare_nastran`).

    Attributes
    ----------
    loads : PointLoadCases
        The cases in model axes (SI).
    units : NastranUnits
    inertia_relief : str
    ids : dict
        ``first_grid_id``, ``first_element_id``, ``load_id_base``, ``first_subcase``.
    labels : tuple of str
        Case id as written in each LABEL.
    title : str
    digest : dict
    attitude : Attitude
    """

    loads: PointLoadCases
    units: NastranUnits
    inertia_relief: str
    ids: dict
    labels: tuple
    title: str
    digest: dict
    attitude: object

    # --- numbering -------------------------------------------------------------------------

    @cached_property
    def subcases(self):
        """Subcase number of each case, shape (c,)."""
        return self.ids["first_subcase"] + np.arange(self.loads.n_cases)

    def set_id(self, kind, subcases=None):
        """Load-set id of ``kind`` (a key of :data:`SET_OFFSETS`) for the subcases."""
        s = self.subcases if subcases is None else np.asarray(subcases)
        return self.ids["load_id_base"] + 10 * s + SET_OFFSETS[kind]

    @property
    def gravity_set(self):
        return self.ids["load_id_base"] + GRAVITY_SET

    @property
    def mass_grids(self):
        return self.ids["first_grid_id"] + np.arange(len(self.loads.masses))

    @property
    def point_grids(self):
        return self.ids["first_grid_id"] + len(self.loads.masses) + np.arange(
            len(self.loads.point_ids))

    @property
    def elements(self):
        return self.ids["first_element_id"] + np.arange(len(self.loads.masses))

    # --- tables for the report ---------------------------------------------------------------

    def subcase_table(self):
        """Subcase number -> LOAD set, case id, its Nastran label and description."""
        return pd.DataFrame({
            "subcase": self.subcases, "LOAD set": self.set_id("LOAD"),
            "case": list(self.loads.case_ids), "Nastran label": list(self.labels),
            "description": list(self.loads.descriptions),
        })

    def grid_table(self):
        """Every GRID (and CONM2) with what it stands for, position in model axes."""
        u = self.units
        loads = self.loads
        length = u.labels["length"]
        xyz = u(np.vstack([loads.mass_positions, loads.point_positions]), "length")
        n = len(loads.masses)
        frame = pd.DataFrame({
            "grid": np.concatenate([self.mass_grids, self.point_grids]),
            "CONM2": [*self.elements.tolist(), *([None] * len(loads.point_ids))],
            "kind": ["mass item"] * n + list(loads.point_kinds),
            "name": list(loads.mass_ids) + list(loads.point_ids),
            f"X [{length}]": xyz[:, 0], f"Y [{length}]": xyz[:, 1],
            f"Z [{length}]": xyz[:, 2],
            f"mass [{u.labels['mass']}]": np.concatenate(
                [u(loads.masses, "mass"), np.full(len(loads.point_ids), np.nan)]),
        })
        return frame

    def settings_table(self):
        """Units, axes, gravity, inertia relief and id ranges, as stated in the file."""
        return pd.DataFrame([(k, v) for k, v in self._settings()], columns=["item", "setting"])

    def _settings(self):
        u, loads = self.units, self.loads
        axes = loads.axes
        g = u(loads.gravity, "acceleration")
        last_grid = int(self.point_grids[-1])
        return [
            ("units", u.describe() + "; PARAM,WTMASS must be 1.0 (the default)"),
            ("project axes", "x aft, y right, z up, origin at the airframe datum "
                             "(FS 0, BL 0, WL 0)"),
            ("model axes (Nastran basic system)", axes.describe()),
            (f"offset: project origin in model axes [{u.labels['length']}]",
             _vector(u(axes.offset, "length"))),
            ("attitude", self.attitude.describe()),
            (f"gravity in model axes [{u.labels['acceleration']}]", _vector(g)),
            ("gravity of its own", self._own_gravity_text()),
            ("inertia relief", _RELIEF_TEXT[self.inertia_relief]),
            ("hook load applied at", loads.hook_at),
            ("grids", f"{self.ids['first_grid_id']} to {last_grid}: mass items, then rotor "
                      "hub, mast feet, aerodynamic points, fin centre of pressure, parachute "
                      "attachment"),
            ("CONM2 elements", f"{self.elements[0]} to {self.elements[-1]} (one per mass "
                               "item, at its grid)"),
            ("load sets", _SETS_TEXT.format(gravity=self.gravity_set,
                                            base=self.ids["load_id_base"])),
            ("subcases", f"{self.subcases[0]} to {self.subcases[-1]}, in case order"),
        ]

    @cached_property
    def own_gravity(self):
        """True for each case whose gravity is not the shared one (a towed case at its
        trimmed attitude), shape (c,)."""
        loads = self.loads
        return _norm(loads.case_gravity - loads.gravity) > ROUND_OFF * _norm(loads.gravity)

    def _own_gravity_text(self):
        own = np.flatnonzero(self.own_gravity)
        if own.size == 0:
            return "none: every subcase takes the shared gravity GRAV"
        subcases = ", ".join(str(s) for s in self.subcases[own])
        return (f"subcases {subcases} (towed cases at their trimmed attitude) take their own "
                f"gravity GRAV (set base + 10 s + {SET_OFFSETS['gravity']}) in place of the "
                "shared one")

    # --- the file ------------------------------------------------------------------------------

    def write(self, path, chunk=500):
        """Write the deck to ``path`` (ASCII, ``\\n`` line ends), ``chunk`` cases at a time."""
        with open(path, "w", encoding="ascii", newline="\n") as handle:
            handle.write(self._header())
            handle.write(self._case_control())
            handle.write(self._bulk_model())
            for start in range(0, self.loads.n_cases, chunk):
                handle.write(self._case_cards(start, min(start + chunk, self.loads.n_cases)))
            handle.write("ENDDATA\n")

    def _header(self):
        loads = self.loads
        text = [f"slingloads {slingloads.__version__}: the load cases of study "
                f"{self.title!r} as Nastran bulk data (limit loads)."]
        text += [f"{k}: {v}." for k, v in self.digest.items()]
        out = "".join(_comment(t) for t in text) + "$\n"
        for item, setting in self._settings():
            out += _comment(f"{item}: {setting}.")
        out += _comment("Each subcase's LOAD combines its applied FORCE and MOMENT cards "
                        f"(hook, aerodynamics, fin, parachute), the gravity GRAV "
                        f"{self.gravity_set} acting on the CONM2 masses (or the case's own "
                        "gravity GRAV when it flies another attitude: a towed case) and, with "
                        "inertia relief 'accelerations', its inertia cards.")
        out += "$\n" + _comment("SUBCASE TABLE: subcase, LOAD set, case id as in the LABEL, "
                                "case id in full (non-ASCII escaped).")
        for s, load, label, case in zip(self.subcases, self.set_id("LOAD"), self.labels,
                                        loads.case_ids, strict=True):
            full = "" if label == case else f"  = {case}"
            out += _comment(f"{s:>8d} {load:>10d}  {label}{full}", indent="  ")
        return out + "$\n"

    def _case_control(self):
        lines = ["SOL 101", "CEND", _cc("TITLE", self.title, ""), "ECHO = NONE",
                 "OLOAD = ALL", "SPCFORCES = ALL", "DISPLACEMENT = ALL"]
        for s, load, label, text in zip(self.subcases, self.set_id("LOAD"), self.labels,
                                        self.loads.descriptions, strict=True):
            lines += [f"SUBCASE {s}", _cc("LABEL", f"{label} {text}", "    "),
                      f"    LOAD = {load}"]
        return "\n".join(lines) + "\nBEGIN BULK\n"

    def _bulk_model(self):
        u, loads = self.units, self.loads
        out = _comment("Connect the grids below to your model (INCLUDE it here or include "
                       "this file's bulk data in it): docs/nastran.md.")
        out += "$ INCLUDE 'your-model.bdf'\n"
        if self.inertia_relief == "inrel":
            out += _comment("Inertia relief by Nastran from the CONM2 masses:") + \
                "PARAM   INREL   -2\n"
        out += _comment("GRIDs of the mass items (with their CONM2) and of the load points; "
                        f"{u.labels['length']}, model basic system:")
        n = len(loads.masses)
        names = [f"mass item {i} ({d})" if d else f"mass item {i}"
                 for i, d in zip(loads.mass_ids, loads.mass_descriptions, strict=True)]
        names += [name if name.startswith(kind) else f"{kind}: {name}"
                  for kind, name in zip(loads.point_kinds, loads.point_ids, strict=True)]
        grids = np.concatenate([self.mass_grids, self.point_grids])
        for grid, name in zip(grids, names, strict=True):
            out += _comment(f"{grid:>10d}  {name}", indent="  ")
        xyz = u(np.vstack([loads.mass_positions, loads.point_positions]), "length")
        out += _cards(_GRID, np.column_stack([grids, xyz]))
        out += _comment(f"CONM2 per mass item: mass [{u.labels['mass']}], own inertia about "
                        f"its CG [{u.labels['inertia']}] in the basic system "
                        "(I21 = -Ixy: Nastran's products of inertia).")
        inertia = u(loads.inertias, "inertia")
        rows = np.column_stack([
            self.elements, self.mass_grids, u(loads.masses, "mass"), np.zeros((n, 3)),
            inertia[:, 0, 0], -inertia[:, 1, 0], inertia[:, 1, 1], -inertia[:, 2, 0],
            -inertia[:, 2, 1], inertia[:, 2, 2]])
        point_mass = ~loads.inertias.reshape(n, 9).any(axis=1)
        out += "".join(_cards(_CONM2_POINT if bare else _CONM2, row[:3] if bare else row)
                       for row, bare in zip(rows, point_mass, strict=True))
        g = u(loads.gravity, "acceleration")
        out += _comment(f"Gravity, shared by every subcase at the study's attitude: g0 = "
                        f"{u(G0, 'acceleration'):.10g} {u.labels['acceleration']} along the "
                        "attitude's downward vertical.")
        out += _cards(_GRAV, _magnitude_direction(np.array([self.gravity_set]), g[None, :]))
        return out

    def _case_cards(self, start, stop):
        """Comments, LOAD and load cards of cases ``start`` to ``stop - 1``."""
        blocks = self._card_blocks(start, stop)
        accelerations = self._acceleration_comments(start, stop)
        out = []
        for i in range(start, stop):
            out.append(self._case_comment(i))
            out.append(accelerations[i - start])
            out.append(self._load_card(i, blocks))
            out.extend(block.text(i) for block in blocks.values())
        return "".join(out)

    def _card_blocks(self, start, stop):
        """Every load card of the cases, formatted at once per card type and set."""
        u, loads = self.units, self.loads
        cases = slice(start, stop)
        s = self.subcases[cases]
        force, size = self._scales(cases)
        forces, moments = loads.forces[cases], loads.moments[cases]
        blocks = {
            "applied forces": _PointCards(
                _FORCE, self.set_id("applied", s), self.point_grids, u(forces, "force"),
                _norm(forces) > ROUND_OFF * force[:, None], start),
            "applied moments": _PointCards(
                _MOMENT, self.set_id("applied", s), self.point_grids, u(moments, "moment"),
                _norm(moments) > ROUND_OFF * (force * size)[:, None], start),
        }
        own = self.own_gravity[cases]
        blocks["gravity"] = _CaseCards(_GRAV, self.set_id("gravity", s),
                                       u(loads.case_gravity[cases], "acceleration"), own, start)
        if self.inertia_relief == "accelerations":
            mass = loads.masses.sum()
            alpha = loads.angular_acceleration[cases]
            field = np.cross(alpha, loads.cg) - loads.linear_acceleration[cases]
            rotary = -np.einsum("nij,cj->cni", loads.inertias, alpha)
            blocks["linear inertia"] = _CaseCards(
                _GRAV, self.set_id("linear inertia", s), u(field, "acceleration"),
                mass * _norm(field) > ROUND_OFF * force, start)
            blocks["angular inertia"] = _CaseCards(
                _RFORCE, self.set_id("angular inertia", s), alpha,
                mass * _norm(alpha) * size > ROUND_OFF * force, start)
            blocks["rotary inertia"] = _PointCards(
                _MOMENT, self.set_id("rotary inertia", s), self.mass_grids,
                u(rotary, "moment"), _norm(rotary) > ROUND_OFF * (force * size)[:, None],
                start)
        return blocks

    def _scales(self, cases):
        """Load scale of each case: its largest applied force or the weight [N]; and the
        size of the model (its points' extent, at least 1 m) [m]."""
        loads = self.loads
        weight = loads.masses.sum() * np.linalg.norm(loads.gravity)
        force = np.maximum(_norm(loads.forces[cases]).max(axis=1), weight)
        points = np.vstack([loads.point_positions, loads.mass_positions])
        return force, max(float(np.ptp(points, axis=0).max()), 1.0)

    def _case_comment(self, i):
        loads = self.loads
        text = _comment(f"---- SUBCASE {self.subcases[i]}: case {loads.case_ids[i]}: "
                        f"{loads.descriptions[i]}")
        if self.own_gravity[i]:
            g = _clean(self.units(loads.case_gravity[i], "acceleration"))
            text += _comment(f"own gravity (its trimmed attitude), model axes: ({g[0]:.6g}, "
                             f"{g[1]:.6g}, {g[2]:.6g}) {self.units.labels['acceleration']}")
        return text

    def _acceleration_comments(self, start, stop):
        """Per case: the inertia relief's CG and angular accelerations, two comment lines."""
        u, loads = self.units, self.loads
        a = _clean(u(loads.linear_acceleration[start:stop], "acceleration")).tolist()
        alpha = _clean(loads.angular_acceleration[start:stop]).tolist()
        unit = u.labels["acceleration"]
        return [_comment(f"inertia relief (model axes): CG acceleration ({x:.6g}, {y:.6g}, "
                         f"{z:.6g}) {unit}, angular acceleration ({p:.6g}, {q:.6g}, {r:.6g}) "
                         "rad/s^2") for (x, y, z), (p, q, r) in zip(a, alpha, strict=True)]

    def _load_card(self, i, blocks):
        """The LOAD combination of case i: every set that has cards, and gravity."""
        s = int(self.subcases[i])
        parts = []
        if blocks["applied forces"].count(i) + blocks["applied moments"].count(i):
            parts.append(self.set_id("applied", s))
        parts.append(self.set_id("gravity", s) if blocks["gravity"].count(i)
                     else self.gravity_set)
        for kind in ("linear inertia", "angular inertia", "rotary inertia"):
            if kind in blocks and blocks[kind].count(i):
                parts.append(self.set_id(kind, s))
        return _load(self.set_id("LOAD", s), parts)


_RELIEF_TEXT = {
    "accelerations": "applied accelerations: each subcase carries the inertia loads of the "
                     "loads analysis's rigid-body accelerations (GRAV of the linear part, "
                     "RFORCE of the angular acceleration about the basic origin, MOMENT "
                     "-I alpha for the CONM2s' own inertia), so applied, gravity and inertia "
                     "loads balance: constrain the model statically determinate (3-2-1 SPC "
                     "or SUPORT); the reactions are round-off",
    "inrel": "PARAM,INREL,-2: Nastran computes the rigid-body accelerations from the model's "
             "mass (the CONM2s here) and no constraint is needed; no inertia cards",
}
_SETS_TEXT = ("{gravity} = gravity GRAV; subcase s: LOAD {base} + 10 s, applied FORCE and "
              "MOMENT {base} + 10 s + 1, linear inertia GRAV + 2, angular inertia RFORCE + 3, "
              "rotary inertia MOMENT + 4, own gravity GRAV + 5 (a case at another attitude)")


def _vector(v):
    """``(x, y, z)`` to six digits, components below :data:`ROUND_OFF` of the largest as 0."""
    return "(" + ", ".join(f"{x:.6g}" for x in _clean(v)) + ")"


def _clean(vectors):
    """Vectors (..., 3) with the components below :data:`ROUND_OFF` of their largest as 0."""
    v = np.asarray(vectors, float)
    largest = np.abs(v).max(axis=-1, keepdims=True, initial=0.0)
    return np.where(np.abs(v) < ROUND_OFF * largest, 0.0, v)


def _cc(keyword, text, indent):
    """A case-control line ``KEYWORD = text`` cut to :data:`LINE_LENGTH` characters (``$``,
    which could start a comment, written as ``_``)."""
    head = f"{indent}{keyword} = "
    text = _ascii(_without_accents(text)).replace("$", "_").strip()
    room = LINE_LENGTH - len(head)
    if len(text) > room:
        text = text[:room - 3].rstrip() + "..."
    return head + text


#: Large-field card templates: the field values in order, (i)nteger or (r)eal.
_GRID = ("GRID*   " + _INT + _BLANK + _REAL + _REAL + _CONT + _REAL + "\n", "irrr")
_CONM2_POINT = ("CONM2*  " + _INT + _INT + _BLANK + _REAL + "\n", "iir")
_CONM2 = ("CONM2*  " + _INT + _INT + _BLANK + _REAL + _CONT + _REAL * 3 + _CONT + _REAL * 4
          + _CONT + _REAL * 2 + "\n", "iirrrrrrrrrr")
#: FORCE and MOMENT: scale F = 1.0 and the vector's components in N1, N2, N3.
_FORCE = ("FORCE*  " + _INT + _INT + _BLANK + _REAL % 1.0 + _CONT + _REAL * 3 + "\n", "iirrr")
_MOMENT = ("MOMENT* " + _INT + _INT + _BLANK + _REAL % 1.0 + _CONT + _REAL * 3 + "\n",
           "iirrr")
_GRAV = ("GRAV*   " + _INT + _BLANK + _REAL + _REAL + _CONT + _REAL * 2 + "\n", "irrrr")
#: RFORCE: no angular velocity (A = 0), the rotation vector through the basic origin (G = 0),
#: METHOD 1, RACC in revolutions per unit time squared.
_RFORCE = ("RFORCE* " + _INT + f"{0:16d}" + _BLANK + _REAL % 0.0 + _CONT + _REAL * 3
           + f"{1:16d}" + _CONT + _REAL + "\n", "irrrr")


def _cards(template, rows):
    """All cards of one template at once: ``rows`` (k, fields) of numbers, ints exact."""
    fmt, kinds = template
    rows = np.asarray(rows, dtype=float).reshape(-1, len(kinds))
    if rows.size == 0:
        return ""
    reals = np.array([k == "r" for k in kinds])
    values = rows[:, reals]
    if not np.all(np.isfinite(values)) or np.abs(values).max() >= _REAL_LIMIT:
        raise InputError(f"a value does not fit a 16-character Nastran field (finite, "
                         f"magnitude below {_REAL_LIMIT:g})", float(np.abs(values).max()))
    values[np.abs(values) < _TINY] = 0.0
    rows[:, reals] = values
    return _without_e((fmt * len(rows)) % tuple(rows.ravel().tolist()))


def _without_e(text):
    """Card text with every real's ``E`` dropped (``1.0E+05`` -> ``1.0+05``); card names
    hold no ``E+`` or ``E-``."""
    return text.replace("E+", "+").replace("E-", "-")


def _magnitude_direction(sids, vectors):
    """GRAV rows ``sid, A, N1, N2, N3`` with A = |v| and N the unit vector of v."""
    magnitude = _norm(vectors)
    return np.column_stack([sids, magnitude, _direction(vectors, magnitude)])


class _PointCards:
    """FORCE or MOMENT cards (F = 1.0, the components in N) of the vectors of a
    (cases, points, 3) array where ``keep``, one set id per case, formatted at once; the text
    of case i is a slice, every card having the same width."""

    def __init__(self, template, sids, grids, vectors, keep, start):
        case, point = np.nonzero(keep)
        self._set(template, np.column_stack([sids[case], grids[point],
                                             _clean(vectors[case, point])]),
                  np.bincount(case, minlength=len(sids)), start)

    def _set(self, template, rows, counts, start):
        self.text_all = _cards(template, rows)
        self.width = len(_cards(template, np.ones((1, len(template[1])))))
        self.offsets = np.concatenate([[0], np.cumsum(counts)])
        self.start = start

    def count(self, i):
        j = i - self.start
        return int(self.offsets[j + 1] - self.offsets[j])

    def text(self, i):
        j = i - self.start
        return self.text_all[self.offsets[j] * self.width:self.offsets[j + 1] * self.width]


class _CaseCards(_PointCards):
    """One GRAV (A = |v|, N its direction) or RFORCE (R the direction of alpha, RACC =
    |alpha| / 2 pi revolutions per unit time squared) per case where ``keep``."""

    def __init__(self, template, sids, vectors, keep, start):
        v = vectors[keep]
        magnitude = _norm(v)
        direction = _direction(v, magnitude)
        if template is _RFORCE:
            rows = np.column_stack([sids[keep], direction, magnitude / (2 * np.pi)])
        else:
            rows = np.column_stack([sids[keep], magnitude, direction])
        self._set(template, rows, keep.astype(int), start)


def _norm(vectors):
    return np.sqrt((np.asarray(vectors) ** 2).sum(axis=-1))


def _direction(vectors, magnitude):
    """Unit vectors, components below :data:`ROUND_OFF` written as 0."""
    unit = vectors / magnitude[..., None]
    unit[np.abs(unit) < ROUND_OFF] = 0.0
    return unit


def _load(sid, parts):
    """A LOAD card combining ``parts`` with scale 1.0 (overall scale 1.0)."""
    fields = [_INT % sid, _REAL % 1.0]
    for part in parts:
        fields += [_REAL % 1.0, _INT % part]
    lines = ["LOAD*   " + "".join(fields[:4])]
    for k in range(4, len(fields), 4):
        lines.append("*       " + "".join(fields[k:k + 4]))
    return _without_e("\n".join(lines) + "\n")

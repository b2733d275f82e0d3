"""The load cases as Nastran bulk data, verified by reading the file back with pyNastran.

References:

* the card definitions of the MSC Nastran Quick Reference Guide, as the independent sums
  below read them: FORCE and MOMENT ``F = mag N`` at their grid; GRAV loads every mass m
  with ``m A N``; RFORCE with angular acceleration ``alpha = 2 pi RACC R / |R|`` about the
  line through grid G (0: the basic origin) loads every translational mass with
  ``-m alpha x (r - r_G)`` (remark 1: the translational mass matrix only); CONM2's inertia
  matrix is ``[[I11, -I21, -I31], [-I21, I22, -I32], [-I31, -I32, I33]]`` (remark on the
  form of the inertia matrix); LOAD scales each set by ``S Si``;
* the rigid body in equilibrium (docs/conventions.md, section 6): applied loads, gravity and
  the inertia loads of the rigid-body accelerations sum to zero, and the applied resultant is
  ``m g0 n`` (n the load factor of the inertia relief) with moment ``I_cg alpha`` about the
  CG;
* the uniform beam hung at mid-length (FACTS.md section 5, docs/conventions.md section 2):
  shear ``n W / 2`` either side of the hook, bending moment ``n W L / 8`` at it;
* unit factors from pint, independent of the writer's constants.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import openpyxl
import pint
import pytest
from hostile import EXAMPLE
from numpy.testing import assert_allclose
from pyNastran.bdf.bdf import read_bdf
from test_sfbm_beam import beam_study

from slingloads.analyses.fe_loads import ModelAxes, PointLoadCases, axis_map_from_text
from slingloads.analyses.loads import ListedCase
from slingloads.cli import main
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.io.loads.nastran import MAX_ID, case_labels, prepare_nastran, write_nastran
from slingloads.io.study import read_study
from slingloads.models.airframe import MassItems

TOLERANCE = 1e-9
_UREG = pint.UnitRegistry()
#: File units of each kind per unit system, from pint.
PINT_UNITS = {"SI": {"length": "m", "force": "N", "mass": "kg", "moment": "N*m",
                     "inertia": "kg*m^2", "acceleration": "m/s^2"},
              "US": {"length": "in", "force": "lbf", "mass": "lbf*s^2/in",
                     "moment": "lbf*in", "inertia": "lbf*in*s^2", "acceleration": "in/s^2"}}
SI_OF = {"length": "m", "force": "N", "mass": "kg", "moment": "N*m", "inertia": "kg*m^2",
         "acceleration": "m/s^2"}


def factor(kind, units):
    """SI -> file units, by pint."""
    return _UREG.Quantity(1.0, SI_OF[kind]).to(PINT_UNITS[units][kind]).magnitude


@pytest.fixture(scope="module")
def example():
    """The example's loads, with own inertias given to its mass items (the example has
    none) and three listed cases whose ids need shortening for a Nastran label."""
    study = read_study(EXAMPLE, only=["loads"]).inputs.loads
    items = study.airframe.mass_items
    rng = np.random.default_rng(3)
    root = rng.normal(0.0, 1.0, (len(items.mass), 3, 3))
    second = np.einsum("nij,nkj->nik", root, root) + np.eye(3)  # integral(r r^T dm) > 0
    trace = np.trace(second, axis1=1, axis2=2)[:, None, None]
    inertia = trace * np.eye(3) - second  # a body's tensor: the triangle inequality holds
    items = MassItems(items.ids, items.mass, items.position, inertia, items.description)
    listed = (ListedCase("vérification-1", "AZ090", "NONE", False, "accented id"),
              ListedCase("L" * 60, "TOW", "TRIM", True, "a sixty-character id"),
              ListedCase("cost $5", "VERTICAL", "CENTRE", True, "an id with a dollar"))
    study = replace(study, airframe=replace(study.airframe, mass_items=items), listed=listed)
    return study.run()


# --- reading the deck back ---------------------------------------------------------------

def read_back(path):
    """pyNastran's reading of the file. Its card validation is off: pyNastran 1.3.4's
    CONM2.validate tests the inertia fields without the minus signs that the QRG (CONM2,
    remark on the form of the inertia matrix) and its own CONM2.Inertia() put on the products
    of inertia; :func:`test_conm2_inertias_are_the_items_own` checks that matrix instead."""
    return read_bdf(str(path), validate=False, debug=None)


def inertia_matrix(conm2):
    """CONM2 inertia as the QRG defines it from the fields I11, I21, I22, I31, I32, I33."""
    i11, i21, i22, i31, i32, i33 = conm2.I
    return np.array([[i11, -i21, -i31], [-i21, i22, -i32], [-i31, -i32, i33]])


class Deck:
    """A read-back deck: grids, masses and each subcase's point loads by role."""

    def __init__(self, path, load_id_base=100_000):
        self.model = read_back(path)
        self.xyz = {n: np.asarray(g.get_position(), float) for n, g in self.model.nodes.items()}
        self.base = load_id_base
        masses = list(self.model.masses.values())
        self.mass = np.array([c.mass for c in masses])
        self.mass_xyz = np.array([self.xyz[c.nid] for c in masses])
        self.own_inertia = np.array([inertia_matrix(c) for c in masses])
        self.mass_grids = [c.nid for c in masses]
        self.cg = self.mass @ self.mass_xyz / self.mass.sum()
        points = np.array(list(self.xyz.values()))
        self.size = max(float(np.ptp(points, axis=0).max()), 1.0)

    @property
    def subcases(self):
        return sorted(k for k in self.model.case_control_deck.subcases if k > 0)

    def loads(self, subcase):
        """``{role: (positions, forces, moments)}``, role ``applied``, ``gravity`` (the shared
        set, or the case's own) or ``inertia`` (by the documented set numbering), summed over
        the LOAD combination."""
        sc = self.model.case_control_deck.subcases[subcase]
        combination = self.model.load_combinations[sc.get_parameter("LOAD")[0]][0]
        out = {role: ([], [], []) for role in ("applied", "gravity", "inertia")}
        for scale, sid in zip(combination.scale_factors, combination.load_ids, strict=True):
            role = ("gravity" if sid in (self.base + 1, self.base + 10 * subcase + 5) else
                    "applied" if sid == self.base + 10 * subcase + 1 else "inertia")
            for card in self.model.loads[sid]:
                self._card(card, combination.scale * scale, out[role])
        return {role: tuple(np.array(v, float).reshape(-1, 3) for v in lists)
                for role, lists in out.items()}

    def _card(self, card, scale, into):
        positions, forces, moments = into
        zero = np.zeros(3)
        if card.type in ("FORCE", "MOMENT"):
            assert card.Cid() == 0
            vector = scale * card.mag * np.asarray(card.xyz, float)
            positions.append(self.xyz[card.node])
            forces.append(vector if card.type == "FORCE" else zero)
            moments.append(vector if card.type == "MOMENT" else zero)
        elif card.type == "GRAV":
            assert card.Cid() == 0
            field = scale * card.scale * np.asarray(card.N, float)
            for m, r in zip(self.mass, self.mass_xyz, strict=True):
                positions.append(r)
                forces.append(m * field)
                moments.append(zero)
        elif card.type == "RFORCE":
            assert card.Cid() == 0 and card.scale == 0.0 and card.method == 1
            axis = np.asarray(card.r123, float)
            origin = self.xyz[card.nid] if card.nid else zero
            alpha = scale * 2 * np.pi * card.racc * axis / np.linalg.norm(axis)
            for m, r in zip(self.mass, self.mass_xyz, strict=True):
                positions.append(r)
                forces.append(-m * np.cross(alpha, r - origin))
                moments.append(zero)
        else:  # pragma: no cover - the writer uses no other card
            raise AssertionError(card.type)

    def resultant(self, loads, about):
        """Sum of forces and of moments about ``about``."""
        positions, forces, moments = loads
        return (forces.sum(axis=0),
                np.cross(positions - about, forces).sum(axis=0) + moments.sum(axis=0))

    def rigid_body_accelerations(self, subcase):
        """What PARAM,INREL,-2 solves for: a and alpha of the CONM2 masses under the applied
        loads and gravity (I_cg from the own inertias plus the parallel-axis terms)."""
        loads = self.loads(subcase)
        force, moment = np.zeros(3), np.zeros(3)
        for role in ("applied", "gravity"):
            f, m = self.resultant(loads[role], self.cg)
            force, moment = force + f, moment + m
        d = self.mass_xyz - self.cg
        inertia = self.own_inertia.sum(axis=0) + sum(
            m * (r @ r * np.eye(3) - np.outer(r, r)) for m, r in zip(self.mass, d, strict=True))
        return force / self.mass.sum(), np.linalg.solve(inertia, moment), inertia


def project_axes(axes_text, offset, units):
    """The model axes as the tests build them: R from the signed axes, offset in file units."""
    rotation = axis_map_from_text(axes_text)
    return rotation, np.asarray(offset, float) * factor("length", units)


CONFIGS = [
    pytest.param("SI", "x, y, z", (0.0, 0.0, 0.0), "mast feet", id="SI-project-axes-feet"),
    pytest.param("US", "-x, y, -z", (3.0, -0.5, 1.2), "mast feet", id="US-mapped-feet"),
    pytest.param("SI", "y, -x, z", (-1.0, 2.0, 0.5), "hub", id="SI-yawed-hub"),
]


@pytest.fixture(scope="module")
def decks(example, tmp_path_factory):
    """The example written in each configuration (accelerations), read back."""
    out = {}
    folder = tmp_path_factory.mktemp("nastran")
    for param in CONFIGS:
        units, axes, offset, hook_at = param.values
        path = folder / f"{param.id}.bdf"
        example.to_nastran(path, units=units, axes=axes, offset=offset, hook_at=hook_at)
        out[param.id] = (path, Deck(path))
    return out


# --- item 3: applied resultants, balance, inertia relief -------------------------------------

@pytest.mark.parametrize(("units", "axes", "offset", "hook_at"), CONFIGS)
def test_applied_resultant_per_subcase(example, decks, request, units, axes, offset, hook_at):
    """Per subcase, the read-back FORCE and MOMENT cards sum to the project's applied
    resultant, to 1e-9 of the load scale (largest applied force; times the model size for
    moments). Two references: the sum of the analysis's applied loads (hook, aerodynamics,
    fin, parachute), and the rigid-body oracle m g0 n (n the load factor of the inertia
    relief) with moment I_cg alpha about the CG, both mapped by R and the offset and
    converted by pint. Covers SI and US, a mapped and a yawed axis system, and the hook load
    at the feet or at the hub (same resultant)."""
    _, deck = decks[request.node.callspec.id]
    rotation, shift = project_axes(axes, offset, units)
    study = example.study
    items = study.airframe.mass_items
    positions, forces, moments = study.applied_loads(example.cases)
    n = len(items.mass)
    lever = positions[n:] - items.cg
    applied_force = forces[:, n:].sum(axis=1)
    applied_moment = (np.cross(lever, forces[:, n:]) + moments[:, n:]).sum(axis=1)
    oracle_force = items.total_mass * G0 * example.load_factor
    oracle_moment = example.angular_acceleration @ items.inertia_about_cg.T
    assert_allclose(applied_force, oracle_force, rtol=0, atol=1e-9 * np.abs(oracle_force).max())
    f_unit, m_unit = factor("force", units), factor("moment", units)
    cg_model = shift + rotation @ items.cg * factor("length", units)
    assert deck.subcases == list(range(1, len(example.cases) + 1))
    for i, s in enumerate(deck.subcases):
        force, moment = deck.resultant(deck.loads(s)["applied"], cg_model)
        scale = np.abs(forces[i, n:]).max() * f_unit
        size = deck.size
        for expected_f, expected_m in ((applied_force[i], applied_moment[i]),
                                       (oracle_force[i], oracle_moment[i])):
            assert_allclose(force, rotation @ expected_f * f_unit, rtol=0,
                            atol=TOLERANCE * scale)
            assert_allclose(moment, rotation @ expected_m * m_unit, rtol=0,
                            atol=TOLERANCE * scale * size)


@pytest.mark.parametrize(("units", "axes", "offset", "hook_at"), CONFIGS)
def test_applied_gravity_and_inertia_balance(decks, request, units, axes, offset, hook_at):
    """With inertia relief by applied accelerations, every subcase's cards (FORCE and MOMENT,
    gravity GRAV on the CONM2 masses, the linear-acceleration GRAV, the RFORCE of the angular
    acceleration, the own-inertia MOMENTs) are in equilibrium: the resultant force and the
    moment about the CG are zero to 1e-9 of the load scale (largest of the applied forces and
    the weight; times the model size for moments). Read back from the file alone."""
    _, deck = decks[request.node.callspec.id]
    weight = deck.mass.sum() * G0 * factor("acceleration", units)
    for s in deck.subcases:
        loads = deck.loads(s)
        assert len(loads["inertia"][0]) > 0
        scale = max(np.abs(loads["applied"][1]).max(), weight)
        total_f, total_m = np.zeros(3), np.zeros(3)
        for role in loads.values():
            f, m = deck.resultant(role, deck.cg)
            total_f, total_m = total_f + f, total_m + m
        assert np.abs(total_f).max() <= TOLERANCE * scale, (s, total_f, scale)
        assert np.abs(total_m).max() <= TOLERANCE * scale * deck.size, (s, total_m)


def upward_vertical(pitch, roll):
    """Earth's upward vertical in airframe axes (x aft, y right, z up) of a body pitched nose
    up by ``pitch`` and rolled right side down by ``roll`` [rad], by hand: the aft axis dips
    by the pitch, the right axis by the roll (docs/conventions.md)."""
    return np.array([-np.sin(pitch), -np.sin(roll) * np.cos(pitch),
                     np.cos(roll) * np.cos(pitch)])


@pytest.mark.parametrize(("units", "axes", "offset", "hook_at"), CONFIGS)
def test_each_subcase_weighs_at_its_own_attitude(example, decks, request, units, axes, offset,
                                                 hook_at):
    """The read-back gravity of every subcase (GRAV on the CONM2 masses) is the weight
    ``-M g0 k`` along that case's vertical, mapped by R and converted by pint, to 1e-9: the
    study's attitude for every case but the towed one, whose k is rebuilt by hand from its
    trimmed pitch and roll on the report's towed table; that one differs from the shared
    gravity (a deck with one gravity for all would fail here)."""
    _, deck = decks[request.node.callspec.id]
    rotation, _ = project_axes(axes, offset, units)
    study = example.study
    weight = study.airframe.mass_items.total_mass * G0 * factor("force", units)
    towed = example.towed_table().set_index("case")
    assert len(towed) >= 1
    shared = -weight * upward_vertical(study.attitude_used.pitch, study.attitude_used.roll)
    for i, s in enumerate(deck.subcases):
        case = example.cases["case"].iloc[i]
        if case in towed.index:
            row = towed.loc[case]
            expected = -weight * upward_vertical(np.radians(row["trim pitch [deg]"]),
                                                 np.radians(row["trim roll [deg]"]))
            assert np.abs(expected - shared).max() > 0.01 * weight
        else:
            expected = shared
        force, _ = deck.resultant(deck.loads(s)["gravity"], deck.cg)
        assert_allclose(force, rotation @ expected, rtol=0, atol=TOLERANCE * weight)


def test_inrel_deck_gives_the_analysis_accelerations(example, tmp_path):
    """With PARAM,INREL,-2 the deck holds no inertia card, and the rigid-body accelerations
    Nastran would solve for from the read-back CONM2 masses (own inertias plus parallel-axis
    terms), applied cards and gravity are the analysis's inertia relief (linear and angular,
    mapped to model axes, US units) to 1e-9."""
    path = tmp_path / "inrel.bdf"
    example.to_nastran(path, units="US", axes="-x, y, -z", offset=(2.0, 0.0, 1.0),
                       inertia_relief="inrel")
    deck = Deck(path)
    assert deck.model.params["INREL"].values == [-2]
    assert not any(card.type == "RFORCE" for cards in deck.model.loads.values()
                   for card in cards)
    rotation, _ = project_axes("-x, y, -z", (0, 0, 0), "US")
    to_file = factor("acceleration", "US")
    for i, s in enumerate(deck.subcases):
        assert len(deck.loads(s)["inertia"][0]) == 0
        a, alpha, _ = deck.rigid_body_accelerations(s)
        expected_a = rotation @ example.linear_acceleration[i] * to_file
        expected_alpha = rotation @ example.angular_acceleration[i]
        assert_allclose(a, expected_a, rtol=0, atol=TOLERANCE * max(np.abs(expected_a).max(),
                                                                     G0 * to_file))
        assert_allclose(alpha, expected_alpha, rtol=0,
                        atol=TOLERANCE * max(np.abs(expected_alpha).max(), 1.0))


@pytest.mark.parametrize("units", ["SI", "US"])
@pytest.mark.parametrize("inertia_relief", ["accelerations", "inrel"])
def test_beam_sfbm_from_the_cards(tmp_path, units, inertia_relief):
    """Uniform beam, W = 1000 N, L = 10 m, 20 equal masses, hung at mid-length by a vertical
    hook load n W, n = 2.5 (FACTS.md section 5; docs/conventions.md section 2): the internal
    loads computed from the read-back cards by direct sums over the loads forward of each cut
    (V = -sum F, M = -sum (r - p) x F + M) give Vz = +n W / 2 = +1250 N just forward of the
    hook, -1250 N just aft, My = n W L / 8 = 3125 N m at the hook, and zero beyond both ends
    (free-free closure); in US units 281.0 lbf and 27 658.6 lbf in (pint). With 'inrel' the
    inertia loads are those of the accelerations solved from the cards, as Nastran does."""
    weight, length, n = 1000.0, 10.0, 2.5
    study, _ = beam_study(weight, length, n, 20)
    path = tmp_path / "beam.bdf"
    study.run().to_nastran(path, units=units, inertia_relief=inertia_relief)
    deck = Deck(path)
    loads = deck.loads(1)
    parts = [loads["applied"], loads["gravity"]]
    if inertia_relief == "accelerations":
        parts.append(loads["inertia"])
    else:
        a, alpha, _ = deck.rigid_body_accelerations(1)
        rho = deck.mass_xyz - deck.cg
        parts.append((deck.mass_xyz, -deck.mass[:, None] * (a + np.cross(alpha, rho)),
                      -deck.own_inertia @ alpha))
    positions, forces, moments = (np.vstack(p) for p in zip(*parts, strict=True))
    to_len = factor("length", units)

    def internal(x):
        forward = positions[:, 0] <= x * to_len
        point = np.array([x * to_len, 0.0, 0.0])
        v = -forces[forward].sum(axis=0)
        m = -(np.cross(positions[forward] - point, forces[forward]).sum(axis=0)
              + moments[forward].sum(axis=0))
        return v, m

    f_unit, m_unit = factor("force", units), factor("moment", units)
    scale = n * weight * f_unit
    delta = length / 80                       # between the hook and the nearest masses
    assert internal(length / 2 - delta)[0][2] == pytest.approx(n * weight / 2 * f_unit,
                                                               rel=TOLERANCE)
    assert internal(length / 2 + delta)[0][2] == pytest.approx(-n * weight / 2 * f_unit,
                                                               rel=TOLERANCE)
    assert internal(length / 2)[1][1] == pytest.approx(n * weight * length / 8 * m_unit,
                                                       rel=TOLERANCE)
    if units == "US":
        assert n * weight / 2 * f_unit == pytest.approx(281.0, abs=0.05)
        assert n * weight * length / 8 * m_unit == pytest.approx(27_658.6, abs=0.05)
    for x in (-1.0, length + 1.0):
        v, m = internal(x)
        assert np.abs(v).max() <= TOLERANCE * scale
        assert np.abs(m).max() <= TOLERANCE * scale * length * to_len


# --- the file itself: fields, ids, labels, units -----------------------------------------------

_REAL_TEXT = re.compile(r"^\s*([-+]?\d\.\d+)([-+]\d+)\s*$")


def field_value(text):
    """A 16-character field as a number: an integer, or a real in the E-less form."""
    match = _REAL_TEXT.match(text)
    if match:
        return float(f"{match.group(1)}E{match.group(2)}")
    return int(text) if text.strip() else None


def card_fields(lines):
    """The fields of the large-field cards of a file, card by card (name, [fields])."""
    cards = []
    for line in lines:
        if line.startswith("$") or not line.strip():
            continue
        if line.startswith("*"):
            cards[-1][1].extend(line[8 + 16 * k: 24 + 16 * k] for k in range(4))
        elif "*" in line[:8]:
            cards.append((line[:8].rstrip("* "), [line[8 + 16 * k: 24 + 16 * k]
                                                    for k in range(4)]))
    return cards


def test_every_field_reads_back_exactly(decks):
    """Every line is ASCII and at most 72 characters; every large-field card that pyNastran
    reads carries exactly the numbers written in its 16-character fields (the test's own
    reading of the text, the E-less exponent form included), so nothing is shifted, cut or
    rounded on the way in: GRID positions, CONM2 masses and inertias, FORCE, MOMENT, GRAV."""
    path, deck = decks["US-mapped-feet"]
    text = path.read_text(encoding="ascii")
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= 72
    cards = card_fields(lines)
    model = deck.model
    checked = {"GRID": 0, "CONM2": 0, "FORCE": 0, "MOMENT": 0, "GRAV": 0}
    loads = {(c.type, c.sid, c.node): c for cs in model.loads.values() for c in cs
             if c.type in ("FORCE", "MOMENT")}
    gravs = {c.sid: c for cs in model.loads.values() for c in cs if c.type == "GRAV"}
    for name, fields in cards:
        v = [field_value(f) for f in fields]
        if name == "GRID":
            assert model.nodes[v[0]].xyz.tolist() == [v[2], v[3], v[4]]
        elif name == "CONM2":
            card = model.masses[v[0]]
            assert (card.nid, card.mass) == (v[1], v[3])
            if len(v) > 4:
                assert card.I.tolist() == v[8:14]
        elif name in ("FORCE", "MOMENT"):
            card = loads[(name, v[0], v[1])]
            assert (card.mag, *card.xyz) == (v[3], v[4], v[5], v[6])
        elif name == "GRAV":
            card = gravs[v[0]]
            assert (card.scale, *card.N) == (v[2], v[3], v[4], v[5])
        checked[name] = checked.get(name, 0) + 1
    assert checked["GRID"] == len(model.nodes) and checked["CONM2"] == len(model.masses)
    assert checked["FORCE"] + checked["MOMENT"] == len(loads)


def test_ids_labels_and_subcase_table(example, decks, tmp_path):
    """Ids follow the documented numbering (grids and CONM2 from their first ids, mass items
    first; LOAD of subcase s = base + 10 s); each SUBCASE's LABEL starts with its case id as
    a Nastran label; ids that are not printable ASCII or longer than 40 characters are
    shortened with '~' and a checksum, distinct, and the subcase table (and the file's
    comments, escaped) keep the whole id."""
    path, deck = decks["SI-project-axes-feet"]
    n_items = len(example.study.airframe.mass_items.mass)
    grids = sorted(deck.model.nodes)
    assert grids == list(range(900_001, 900_001 + len(grids)))
    assert sorted(deck.model.masses) == list(range(900_001, 900_001 + n_items))
    assert [deck.model.masses[e].nid for e in sorted(deck.model.masses)] == grids[:n_items]
    table = prepare_nastran(example).subcase_table()
    assert list(table["case"]) == example.case_ids
    text = path.read_text(encoding="ascii")
    for s, load, label, case in table[["subcase", "LOAD set", "Nastran label",
                                       "case"]].itertuples(index=False):
        sc = deck.model.case_control_deck.subcases[s]
        assert sc.get_parameter("LOAD")[0] == load == 100_000 + 10 * s
        assert sc.get_parameter("LABEL")[0].startswith(label + " ")
        escaped = case.encode("ascii", "backslashreplace").decode()
        assert f"  {label}" in text and escaped[:30] in text.replace("\n$   ", "")
    labels = dict(zip(table["case"], table["Nastran label"], strict=True))
    assert labels["LC0001"] == "LC0001"
    for odd in ("vérification-1", "L" * 60, "cost $5"):
        assert re.fullmatch(r"[ -#%-~]{1,31}~[0-9a-f]{8}", labels[odd]), labels[odd]
    assert labels["vérification-1"].startswith("verification-1~")
    assert len(set(labels.values())) == len(labels)


def test_conm2_inertias_are_the_items_own(example, decks):
    """Each CONM2's inertia matrix in the QRG form [[I11, -I21, -I31], ...] is the item's own
    inertia tensor mapped to model axes (R I R^T) and converted by pint, and is positive
    definite; its mass is the item's."""
    _, deck = decks["US-mapped-feet"]
    items = example.study.airframe.mass_items
    rotation, _ = project_axes("-x, y, -z", (0, 0, 0), "US")
    expected = rotation @ items.inertia @ rotation.T * factor("inertia", "US")
    assert_allclose(deck.own_inertia, expected, rtol=1e-10, atol=0)
    assert np.all(np.linalg.eigvalsh(deck.own_inertia) > 0)
    assert_allclose(deck.mass, items.mass * factor("mass", "US"), rtol=1e-10)


def test_units_are_pint_consistent(example):
    """The US set (in, lbf, s, lbf s^2/in) equals pint's conversions, and is consistent:
    1 lbf = 1 (lbf s^2/in) x 1 in/s^2."""
    from slingloads.io.loads.nastran import UNIT_SYSTEMS

    us = UNIT_SYSTEMS["US"]
    for kind in ("length", "force", "mass", "moment", "inertia", "acceleration"):
        assert us.factors[kind] == pytest.approx(factor(kind, "US"), rel=1e-14), kind
    assert us.factors["force"] == pytest.approx(us.factors["mass"] * us.factors["acceleration"],
                                                rel=1e-14)


# --- model axes ------------------------------------------------------------------------------

def test_model_axes_map_points_vectors_and_inertias():
    """'-x, y, -z' (X forward, Y right, Z down) is the rotation diag(-1, 1, -1); points go
    through offset + R r, vectors through R v, inertias through R I R^T (a moment of inertia
    about x stays about X; the product Ixz keeps its sign under two reversed axes)."""
    axes = ModelAxes("-x, y, -z", offset=(1.0, 2.0, 3.0))
    assert_allclose(axes.rotation, np.diag([-1.0, 1.0, -1.0]))
    assert_allclose(axes.points([[2.0, 0.5, 1.0]]), [[-1.0, 2.5, 2.0]])
    assert_allclose(axes.vectors([0.0, 0.0, -9.8]), [0.0, 0.0, 9.8])
    tensor = np.array([[10.0, 0.0, -2.0], [0.0, 20.0, 0.0], [-2.0, 0.0, 30.0]])
    assert_allclose(axes.tensors(tensor), tensor)
    yawed = ModelAxes("y, -x, z")
    assert_allclose(yawed.vectors([1.0, 0.0, 0.0]), [0.0, -1.0, 0.0])
    assert yawed.describe() == "model X = y; model Y = -x; model Z = z"


@pytest.mark.parametrize(("rotation", "offset", "fragment"), [
    ("x, x, z", (0, 0, 0), "must be a rotation"),
    ("-x, y, z", (0, 0, 0), "mirror"),
    (np.diag([1.0, 1.0, 1.001]), (0, 0, 0), "not orthonormal"),
    ("x, y", (0, 0, 0), "three signed project axes"),
    ("x, y, w", (0, 0, 0), "three signed project axes"),
    ("x, y, z", (0.0, np.inf, 0.0), "offset must be finite"),
    ("x, y, z", (0.0, 1.0), "offset must be three numbers"),
])
def test_bad_model_axes_are_refused(example, tmp_path, rotation, offset, fragment):
    """An axis map that is not a proper rotation, or an offset that is not three finite
    numbers, is an InputError that echoes the value, and no file is written."""
    path = tmp_path / "bad.bdf"
    with pytest.raises(InputError, match=re.escape(fragment)):
        write_nastran(example, path, axes=rotation, offset=offset)
    assert not path.exists() and list(tmp_path.iterdir()) == []


def test_bad_options_are_refused(example, tmp_path):
    """Unknown units, inertia relief or hook point; ids that are not whole numbers; id ranges
    past 99,999,999; more case-points than the limit; case ids that give the same label."""
    path = tmp_path / "bad.bdf"
    cases = [({"units": "cgs"}, "units='cgs' is not valid"),
             ({"inertia_relief": "auto"}, "inertia_relief='auto' is not valid"),
             ({"hook_at": "rotor"}, "hook_at='rotor' is not valid"),
             ({"first_grid_id": 0}, "first_grid_id must be a whole number"),
             ({"first_grid_id": 2.5}, "first_grid_id must be a whole number"),
             ({"first_grid_id": 99_999_990}, "first_grid_id: the ids of"),
             ({"load_id_base": MAX_ID - 10 * len(example.cases)}, "load_id_base: the ids of"),
             ({"first_subcase": 99_999_950}, "first_subcase: the ids of"),
             ({"max_case_points": 1000}, "too many load cases")]
    for options, fragment in cases:
        with pytest.raises(InputError, match=re.escape(fragment)):
            write_nastran(example, path, **options)
    with pytest.raises(InputError, match="give the same Nastran label"):
        case_labels(["A" * 50, "A" * 31 + "~" + case_labels(["A" * 50])[0][-8:]])
    assert list(tmp_path.iterdir()) == []


def test_point_loads_are_mapped_once(example):
    """Mapping loads that are already in model axes would compose the maps: refused."""
    mapped = PointLoadCases.from_result(example).in_model_axes(ModelAxes("-x, y, -z"))
    with pytest.raises(InputError, match="already in model axes"):
        mapped.in_model_axes({"rotation": "x, y, z"})


# --- the command line and the workbook ---------------------------------------------------------

def with_rows(tmp_path, rows, edit=None, name="nastran.xlsx"):
    """A copy of the example with Study rows (parameter, value, unit) set, or added where the
    example does not list them."""
    book = openpyxl.load_workbook(EXAMPLE)
    ws = book["Study"]
    listed = {row[0].value: row[0].row for row in ws.iter_rows(min_row=2)}
    cells = {}
    for parameter, value, unit in rows:
        if parameter in listed:
            r = listed[parameter]
            ws[f"B{r}"], ws[f"C{r}"] = value, unit
        else:
            ws.append([parameter, value, unit])
            r = ws.max_row
        cells[parameter] = f"B{r}"
    if edit is not None:
        edit(book)
    path = tmp_path / name
    book.save(path)
    return path, cells


def test_study_rows_write_the_deck_with_the_report(tmp_path):
    """'nastran bulk data = yes' with --units US, a model axis map and offset on the Study
    sheet: the run publishes <stem>-loads.bdf with the report, whose Nastran sheet links each
    subcase to its case id (the subcase table, longer than a page, on a sheet of its own);
    the file balances (1e-9) in the mapped axes."""
    path, _ = with_rows(tmp_path, [("nastran bulk data", "yes", None),
                                   ("nastran model axes", "-x, y, -z", None),
                                   ("nastran offset x", 120.0, "in"),
                                   ("nastran first grid id", 5001, None)])
    out = tmp_path / "out"
    assert main(["loads", str(path), "--out", str(out), "--units", "US", "--quiet"]) == 0
    bdf = out / "nastran-loads.bdf"
    deck = Deck(bdf)
    assert min(deck.model.nodes) == 5001
    sheet = openpyxl.load_workbook(out / "nastran-loads.xlsx",
                                   read_only=True)["Nastran-Subcases"]
    rows = [r for r in sheet.iter_rows(values_only=True) if r and r[0] == 1]
    assert rows and rows[0][1:3] == (100_010, "LC0001")
    rotation, shift = project_axes("-x, y, -z", (120 * 0.0254, 0, 0), "US")
    hub = deck.xyz[5001 + 26]
    study = read_study(EXAMPLE, only=["loads"]).inputs.loads
    assert_allclose(hub, shift + rotation @ study.airframe.hardpoints.hub / 0.0254, rtol=1e-10)
    weight = deck.mass.sum() * G0 / 0.0254
    for s in deck.subcases[::9]:
        total = [deck.resultant(role, deck.cg) for role in deck.loads(s).values()]
        assert np.abs(sum(f for f, _ in total)).max() <= TOLERANCE * 3 * weight
    assert "GRAV" in bdf.read_text(encoding="ascii")


@pytest.mark.parametrize(("row", "value", "fragment"), [
    ("nastran model axes", "-x, y, z", "mirror"),
    ("nastran offset y", "inf", "must be a finite number"),
    ("nastran first grid id", 99_999_999, "nastran first grid id: the ids of"),
])
def test_bad_study_rows_are_located_and_nothing_is_written(tmp_path, capsys, row, value,
                                                            fragment):
    """A bad 'nastran ...' row: exit 2, the message names the file, the Study sheet, the
    row's value cell, the value and the rule; the output directory stays empty."""
    path, cells = with_rows(tmp_path, [(row, value, "m" if "offset" in row else None)])
    out = tmp_path / "out"
    assert main(["loads", str(path), "--out", str(out), "--nastran", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert fragment in err and "sheet 'Study'" in err and f"cell {cells[row]}" in err, err
    assert str(path) in err and "nothing was written" in err
    assert not out.exists() or list(out.iterdir()) == []


def test_case_ids_that_clash_are_located(tmp_path, capsys):
    """Two LoadCases ids that give the same Nastran label: exit 2 at the second id's cell."""
    long_id = "A" * 50
    clash = "A" * 31 + "~" + case_labels([long_id])[0][-8:]

    def edit(book):
        ws = book.create_sheet("LoadCases") if "LoadCases" not in book else book["LoadCases"]
        ws.delete_rows(1, ws.max_row)
        ws.append(["id", "hook", "aero", "chute", "description"])
        ws.append([long_id, "VERTICAL", "NONE", "no", "first"])
        ws.append([clash, "VERTICAL", "NONE", "no", "second"])

    path, _ = with_rows(tmp_path, [], edit=edit)
    out = tmp_path / "out"
    assert main(["loads", str(path), "--out", str(out), "--nastran", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "give the same Nastran label" in err and "sheet 'LoadCases'" in err
    assert "cell A3" in err and clash in err
    assert not out.exists() or list(out.iterdir()) == []


def test_nastran_needs_the_loads_analysis(tmp_path, capsys):
    """`run --nastran` on a workbook that does not run the loads: exit 2, nothing written."""
    def edit(book):
        for row in book["Study"].iter_rows(min_row=2):
            if row[0].value == "run loads":
                row[1].value = "no"
    path, _ = with_rows(tmp_path, [], edit=edit)
    out = tmp_path / "out"
    code = main(["run", str(path), "--out", str(out), "--nastran", "--quiet"])
    assert code == 2
    assert "--nastran" in capsys.readouterr().err
    assert not out.exists() or list(out.iterdir()) == []


def test_help_does_not_load_the_writer():
    """`slingloads --help` and `slingloads loads --help` import neither the Nastran writer nor
    pyNastran (the writer is loaded on first use, and never needs pyNastran)."""
    import subprocess
    import sys

    code = ("import sys\nfrom slingloads import cli\nfor argv in (['--help'], ['loads', "
            "'--help']):\n    try:\n        cli.main(argv)\n    except SystemExit:\n"
            "        pass\nprint([m for m in sys.modules if 'nastran' in m.lower()])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"
    assert "--nastran" in out

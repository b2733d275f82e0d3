"""Every public function and class of the physics modules and of the Python API (the run
layer, reading a study and writing its reports) documents its inputs and outputs.

Reference: the numpydoc standard (https://numpydoc.readthedocs.io/en/latest/format.html), as the
style guide asks: a function that takes arguments has a ``Parameters`` section, one that returns
a value a ``Returns`` (or ``Yields``) section, a class that takes arguments a ``Parameters``
(or ``Attributes``) section; the units go in [brackets] in the entries. The modules are read
with :mod:`ast` (no import, so the compiled kernels are read too). The modules still to be
documented (their functions are being reshaped elsewhere) are listed in ``PENDING``; the list
only shrinks.

Every numeric entry of those sections and of a class's ``Attributes`` (its type names a
float, an int, an ndarray, an array or a number) states its unit in brackets, pvlib style
(``pressure : numeric ... [Pa]``). What is not a quantity says so in the same brackets, from a
short list a reader can learn: ``[-]`` for a dimensionless number, an index, a flag or a seed,
``[count]`` for a number of things (runs, samples, workers). A mixed vector names its units in
order (``[m, m/s, -, rad/s, rad]``) or the table that lays it out (``[SI]`` with the layout
named in the text).
"""

import ast
import re
from pathlib import Path

import pytest

import slingloads

ROOT = Path(slingloads.__file__).parent
#: Modules whose docstring pass is still to come (relative to the package).
PENDING: set[str] = set()
#: The Python API beside the physics: the run layer (the typed Study, each analysis's
#: ``run`` and result) and the calls that read a workbook into a Study and write its reports.
API = ("io/study.py", "io/reports.py")
MODULES = sorted([str(p.relative_to(ROOT)) for folder in ("models", "analyses", "runs")
                  for p in (ROOT / folder).rglob("*.py")] + list(API))


def _has(doc, *names):
    lines = [line.strip() for line in doc.splitlines()]
    return any(a == name and set(b) == {"-"} for name in names
               for a, b in zip(lines, lines[1:], strict=False))


def _own_nodes(function):
    """The nodes of ``function``'s body, not those of functions or classes inside it."""
    stack = list(ast.iter_child_nodes(function))
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            continue
        yield node
        stack.extend(ast.iter_child_nodes(node))


def _returns(function):
    for node in _own_nodes(function):
        if isinstance(node, (ast.Yield, ast.YieldFrom)):
            return True
        if (isinstance(node, ast.Return) and node.value is not None
                and not (isinstance(node.value, ast.Constant) and node.value.value is None)):
            return True
    return False


def _arguments(function, method):
    a = function.args
    names = [x.arg for x in (*a.posonlyargs, *a.args, *a.kwonlyargs)]
    if method and names and names[0] in ("self", "cls"):
        names = names[1:]
    return names + [x.arg for x in (a.vararg, a.kwarg) if x is not None]


def _is_property(function):
    return any(getattr(d, "id", getattr(d, "attr", None)) in ("property", "cached_property",
                                                              "setter")
               for d in function.decorator_list)


def _missing(path):
    tree = ast.parse((ROOT / path).read_text())
    out = []

    def check(function, name, method=False):
        doc = ast.get_docstring(function) or ""
        if _arguments(function, method) and not _has(doc, "Parameters"):
            out.append(f"{path}: {name} has no Parameters section")
        if _returns(function) and not _has(doc, "Returns", "Yields"):
            out.append(f"{path}: {name} has no Returns section")

    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            check(node, node.name)
        elif isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            init = [b for b in node.body if isinstance(b, ast.FunctionDef)
                    and b.name == "__init__"]
            takes = (any(isinstance(b, ast.AnnAssign) for b in node.body)
                     or (init and _arguments(init[0], True)))
            if takes and not _has(ast.get_docstring(node) or "", "Parameters", "Attributes"):
                out.append(f"{path}: class {node.name} has no Parameters section")
            for b in node.body:
                if (isinstance(b, ast.FunctionDef) and not b.name.startswith("_")
                        and not _is_property(b)):
                    check(b, f"{node.name}.{b.name}", method=True)
    return out


#: A type that holds a number: float, int, complex, numeric, number, an array or an ndarray
#: (``bool`` and ``ndarray of bool`` are flags and ``ndarray of str`` text, not numbers).
_NUMERIC = re.compile(r"\b(float|float64|int|int64|complex|numeric|number|ndarray|array|"
                      r"array_like)\b")
#: A unit in brackets: ``[m/s]``, ``[-]``, ``[count]``; not an index (``x[0]``, ``[1]_``).
_UNIT = re.compile(r"(?<![\w`\]\[])\[[^\]\s][^\]]*\](?!_)")


def _sections(doc):
    """The lines of each numpydoc section of ``doc`` (a cleaned docstring), by heading."""
    lines = doc.splitlines()
    out, current = {}, None
    for line, below in zip(lines, [*lines[1:], ""], strict=True):
        if line.strip() and not line.startswith(" ") and below.strip() and set(
                below.strip()) == {"-"}:
            current = out.setdefault(line.strip(), [])
        elif current is not None and not (line.strip() and set(line.strip()) == {"-"}):
            current.append(line)
    return out


def _entries(lines):
    """(heading line, description lines) of each entry of a section."""
    entries = []
    for line in lines:
        if line.strip() and not line.startswith(" "):
            entries.append((line.strip(), []))
        elif entries:
            entries[-1][1].append(line.strip())
    return entries


def _is_numeric(kind):
    if re.search(r"\bbool\b|array of str", kind) and not re.search(r"float|numeric", kind):
        return False
    return bool(_NUMERIC.search(kind))


def _without_units(doc):
    """The numeric Parameters, Attributes, Returns and Yields entries of ``doc`` that state no
    unit."""
    sections = _sections(doc)
    out = []
    for section in ("Parameters", "Attributes", "Returns", "Yields"):
        for head, text in _entries(sections.get(section, [])):
            name, colon, kind = head.partition(" : ")
            if not colon:  # a Returns entry may give the type alone
                kind = head
            if _is_numeric(kind) and not _UNIT.search(" ".join([head, *text])):
                out.append(f"{section}: {head}")
    return out


def _public_docstrings(path):
    """(name, docstring) of each public function, class and method of module ``path``."""
    tree = ast.parse((ROOT / path).read_text())
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and not node.name.startswith("_"):
            yield node.name, ast.get_docstring(node) or ""
            if isinstance(node, ast.ClassDef):
                for b in node.body:
                    if isinstance(b, ast.FunctionDef) and not b.name.startswith("_"):
                        yield f"{node.name}.{b.name}", ast.get_docstring(b) or ""


@pytest.mark.parametrize("path", MODULES)
def test_numeric_entries_state_their_units(path):
    """Each number, array or numeric value a public function, method or class of the module
    takes or returns states its unit in brackets (``[m/s]``; ``[-]`` for a dimensionless
    number, an index, a flag or a seed; ``[count]`` for a number of things)."""
    missing = [f"{name}: {entry}" for name, doc in _public_docstrings(path)
               for entry in _without_units(doc)]
    assert missing == []


def test_the_unit_check_finds_a_missing_unit():
    """The check above can fail: a doctored docstring whose float, int and array entries lack a
    unit is caught entry by entry; a bracketed unit, ``[-]``, ``[count]``, a flag, a string and
    an index in code (``x[0]``) or a reference (``[1]_``) are told apart."""
    doc = ("Doctored.\n\nParameters\n----------\nspeed : float\n    Airspeed.\n"
           "mass : float\n    Mass. [kg]\nx : ndarray, shape (4,)\n    State ``x[0]`` [1]_.\n"
           "runs : int\n    Runs. [count]\nk : int\n    Index. [-]\nn : int\n    Samples.\n"
           "left : ndarray of bool\n    Flags.\nname : str\n    A name.\n"
           "labels : ndarray of str\n    Names.\n\nAttributes\n----------\n"
           "area : float\n    Area.\n\n"
           "Returns\n-------\nfloat\n    Tension.\ndx : ndarray\n    Rates. [m/s, rad/s]\n")
    assert _without_units(doc) == ["Parameters: speed : float",
                                   "Parameters: x : ndarray, shape (4,)",
                                   "Parameters: n : int", "Attributes: area : float",
                                   "Returns: float"]
    assert _without_units(doc.replace("Airspeed.", "Airspeed. [m/s]")
                          .replace("Samples.", "Samples. [count]")
                          .replace("[1]_.", "[1]_. [m, m/s]")
                          .replace("Tension.", "Tension. [N]")
                          .replace("Area.", "Area. [``unit``]")) == []


@pytest.mark.parametrize("path", [m for m in MODULES if m not in PENDING])
def test_public_functions_have_parameters_and_returns(path):
    """Each public function, method and class of the module documents its arguments
    (Parameters) and what it returns (Returns), numpydoc style."""
    assert _missing(path) == []


def test_pending_modules_exist():
    """The list of modules still to do names real modules (a renamed one must leave it)."""
    assert PENDING <= set(MODULES)

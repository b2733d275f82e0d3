"""Layering: the physical models and the analyses never import the input/output layer, the
unit library nor the file and plotting libraries (the reference is the architecture stated in
README.md: slingloads/models and slingloads/analyses are SI-only physics with no file access);
inside the io layer the shared machinery (io/common) and the airframe sheets (io/airframe)
know no particular analysis, and no io modules import each other in a circle."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from slingloads.io.analyses import ANALYSES

PACKAGE = Path(__file__).resolve().parents[1] / "slingloads"
FORBIDDEN = ("slingloads.io", "slingloads.cli", "openpyxl", "matplotlib", "pint")
PHYSICS = sorted((PACKAGE / "models").rglob("*.py")) + sorted((PACKAGE / "analyses").rglob("*.py"))
SHARED_IO = sorted((PACKAGE / "io" / "common").rglob("*.py")) + sorted(
    (PACKAGE / "io" / "airframe").rglob("*.py"))
#: What the shared io must not import: each analysis's folder, the registry and what follows it.
ABOVE_SHARED_IO = (*(f"slingloads.io.{a.folder}" for a in ANALYSES), "slingloads.io.analyses",
                   "slingloads.io.study", "slingloads.io.template")


#: The only imports of io from the physics: a result's ``to_<format>`` method hands the result
#: to the io writer of that format (the pandas ``DataFrame.to_excel`` pattern), by an import
#: inside that method, so that importing or running the physics never loads the io layer.
DELEGATIONS = {("analyses/loads.py", "to_nastran"): {"slingloads.io.loads.nastran"}}


def imported_modules(path, skip=()):
    """Every module ``path`` imports, at top level or inside a function (except inside the
    functions named in ``skip``); ``from X import Y`` gives ``X.Y`` when that is a module of
    the package, else ``X``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skipped = {id(n) for f in ast.walk(tree)
               if isinstance(f, ast.FunctionDef) and f.name in skip for n in ast.walk(f)}
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            yield node.module
            for alias in node.names:
                if _module_path(f"{node.module}.{alias.name}") is not None:
                    yield f"{node.module}.{alias.name}"


def _module_name(path):
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _module_path(name):
    """The file of module ``name`` of this package, or None."""
    if not name.startswith("slingloads"):
        return None
    base = PACKAGE.parent.joinpath(*name.split("."))
    for path in (base.with_suffix(".py"), base / "__init__.py"):
        if path.is_file():
            return path
    return None


def _within(name, prefixes):
    return any(name == p or name.startswith(p + ".") for p in prefixes)


@pytest.mark.parametrize("path", PHYSICS, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_physics_never_imports_io(path):
    """No module of models/ or analyses/ (sub-packages included) imports io, cli, pint,
    openpyxl or matplotlib, except the listed ``to_<format>`` delegations, each inside its
    own method and only to its writer."""
    name = str(path.relative_to(PACKAGE))
    delegations = {f: allowed for (file, f), allowed in DELEGATIONS.items() if file == name}
    bad = [m for m in imported_modules(path, skip=delegations) if _within(m, FORBIDDEN)]
    assert not bad, f"{path.name} imports {bad}"
    for function, allowed in delegations.items():
        inside = set(imported_modules(path)) - set(imported_modules(path, skip=(function,)))
        assert inside == allowed, f"{name}: {function} imports {sorted(inside)}"


def test_the_physics_walk_sees_every_module():
    """The walk above covers sub-packages: each physics module is listed once."""
    assert PHYSICS and len(set(PHYSICS)) == len(PHYSICS)
    assert (PACKAGE / "analyses" / "hook_angle.py") in PHYSICS


@pytest.mark.parametrize("path", SHARED_IO, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_shared_io_knows_no_analysis(path):
    """No module of io/common or io/airframe imports an analysis's io folder (io/loads,
    io/lateral, io/chute...), the registry of analyses, the study reader or the template."""
    bad = [m for m in imported_modules(path) if _within(m, ABOVE_SHARED_IO)]
    assert not bad, f"{path.relative_to(PACKAGE)} imports {bad}"


def _io_graph():
    graph = {}
    for path in sorted((PACKAGE / "io").rglob("*.py")):
        targets = {_module_name(_module_path(m)) for m in imported_modules(path)
                   if m.startswith("slingloads.io") and _module_path(m) is not None}
        graph[_module_name(path)] = targets - {_module_name(path)}
    return graph


def _cycle(graph):
    """One import circle of ``graph`` as a list of modules, or None."""
    state, stack = {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == "open":
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        state[node] = "done"
        stack.pop()
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def test_io_has_no_import_cycle():
    """The modules of slingloads.io import each other without a circle (function-level
    imports included)."""
    graph = _io_graph()
    assert "slingloads.io.study" in graph and graph["slingloads.io.lateral.reader"]
    cycle = _cycle(graph)
    assert cycle is None, " -> ".join(cycle)


def test_the_cycle_check_finds_a_circle():
    """The check above can fail: a made-up graph with a circle is caught."""
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": set()}) is None


def _python_lines(code):
    """The lines ``code`` prints when run by a fresh Python (nothing imported before it)."""
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True).stdout.strip().splitlines()


def test_help_imports_no_heavy_library():
    """`slingloads --help` lists the analyses from the registry without importing numpy,
    pandas, pint, openpyxl, matplotlib, scipy, numba or tqdm (the analyses' modules load on
    first use)."""
    code = ("import sys\nfrom slingloads import cli\ntry:\n    cli.main(['--help'])\n"
            "except SystemExit:\n    pass\n"
            "heavy = ('numpy', 'pandas', 'pint', 'openpyxl', 'matplotlib', 'scipy', 'numba',"
            " 'tqdm')\n"
            "print('loaded:' + ','.join(m for m in heavy if m in sys.modules))")
    out = _python_lines(code)
    assert out[-1] == "loaded:", f"--help imported {out[-1]}"


@pytest.mark.parametrize("module, absent", [
    ("slingloads.io.loads.report", ("matplotlib", "scipy.spatial", "numba")),
    ("slingloads.io.lateral.report", ("matplotlib", "numba")),
    ("slingloads.io.chute.report", ("matplotlib", "numba")),
    ("slingloads.cli", ("tqdm", "matplotlib", "scipy.spatial", "numba")),
    ("slingloads.analyses.lateral", ("scipy", "numba")),
    ("slingloads.analyses.chute_sizing", ("scipy", "numba")),
    ("slingloads.io.lateral.plots", ("scipy", "numba")),
    ("slingloads.io.chute.plots", ("scipy", "numba")),
    ("slingloads.io.multibody.plots", ("scipy", "numba")),
])
def test_libraries_load_only_where_used(module, absent):
    """Importing a report module (or the CLI) loads neither matplotlib (only the plots
    modules use it, when figures are drawn), nor scipy.spatial (only the convex hull), nor
    numba (only the compiled batch integrators), nor tqdm (only a running analysis); the
    lateral and sizing analyses and their plots, and the multibody plots (drawn from plain
    data), load neither scipy nor numba: the process that draws the figures needs neither
    (about 1 s)."""
    code = (f"import sys\nimport {module}\n"
            f"print('loaded:' + ','.join(m for m in {absent!r} if m in sys.modules))")
    out = _python_lines(code)
    assert out[-1] == "loaded:", f"importing {module} loaded {out[-1]}"


def test_a_hull_and_a_measured_motion_need_no_scipy():
    """The helper that draws the figures receives the results pickled: a measured carrier
    motion (its spline) and the 2-D hulls of the loads plots are numpy alone, so making
    them, pickling and unpickling them, and evaluating them loads no scipy (scipy's
    interpolation and spatial packages cost the helper about a third of a second)."""
    code = ("import pickle, sys\nimport numpy as np\n"
            "from slingloads.models.carrier_motion import TimeHistory\n"
            "from slingloads.analyses.envelopes import convex_hull\n"
            "h = pickle.loads(pickle.dumps(TimeHistory([0, 1, 2, 4], [0, 1, 3, 4])))\n"
            "h.kinematics(np.linspace(0, 5, 9))\n"
            "loads = np.random.default_rng(0).normal(size=(50, 1, 6))\n"
            "convex_hull(loads, [str(k) for k in range(50)], 0, ('Vy', 'Mz'))\n"
            "print('loaded:' + ('scipy' if 'scipy' in sys.modules else ''))")
    out = _python_lines(code)
    assert out[-1] == "loaded:", f"loaded {out[-1]}"


def test_a_quiet_run_loads_no_progress_bar():
    """`--quiet` shows no progress bar, so the run's stand-in loads no tqdm (which imports
    importlib.metadata and more, a tenth of a second); a shown bar is tqdm's."""
    code = ("import sys\nfrom slingloads import cli\n"
            "with cli._progress(False) as bar:\n"
            "    bar.total = 4\n    bar.update(1)\n    bar.set_description('x')\n"
            "print('loaded:' + ('tqdm' if 'tqdm' in sys.modules else ''))\n"
            "with cli._progress(True) as bar:\n    print(type(bar).__module__.split('.')[0])")
    out = _python_lines(code)
    assert out == ["loaded:", "tqdm"]

"""Layering: the physical models and the analyses never import the input/output layer, the
unit library nor the file and plotting libraries (the reference is the architecture stated in
README.md, "Layout": ``models`` < ``analyses`` < ``runs`` < ``io`` < ``cli``, each importing
only those before it); inside the io layer the shared machinery (io/common) and the airframe
sheets (io/airframe) know no particular analysis; and no modules of the package import each
other in a circle. Every import is seen: at top level, inside functions and under
``TYPE_CHECKING``, by parsing each module; the only import by name is the package root's
lazy export table, which is read as imports too."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "slingloads"
FORBIDDEN = ("slingloads.io", "slingloads.cli", "slingloads.runs", "openpyxl", "matplotlib",
             "pint")
PHYSICS = sorted((PACKAGE / "models").rglob("*.py")) + sorted((PACKAGE / "analyses").rglob("*.py"))
SHARED_IO = sorted((PACKAGE / "io" / "common").rglob("*.py")) + sorted(
    (PACKAGE / "io" / "airframe").rglob("*.py"))
#: Each analysis's io folder.
ANALYSIS_IO = tuple(f"slingloads.io.{p.name}" for p in sorted((PACKAGE / "io").iterdir())
                    if p.is_dir() and p.name not in ("common", "airframe", "__pycache__"))
#: What the shared io must not import: each analysis's folder, the registry and what follows it.
ABOVE_SHARED_IO = (*ANALYSIS_IO, "slingloads.io.analyses", "slingloads.io.study",
                   "slingloads.io.template", "slingloads.io.reports")
#: The layers, lowest first: a module imports only from its own layer and those before it.
#: ``base``: the package's shared modules (errors, constants, limits, checks), below all.
LAYERS = ("base", "models", "analyses", "runs", "io", "cli")


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
        if isinstance(node, ast.Assign) and _is_export_table(node):
            yield from (v.value.partition(":")[0] for v in node.value.values)
        elif (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "plot_function"
              and node.args and isinstance(node.args[0], ast.Constant)):
            yield node.args[0].value  # a plot drawn by a helper process, imported there
        elif isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            yield node.module
            for alias in node.names:
                if _module_path(f"{node.module}.{alias.name}") is not None:
                    yield f"{node.module}.{alias.name}"


def _is_export_table(node):
    """The package root's ``_EXPORTS = {name: "module[:attribute]"}``: imports by name."""
    return (any(isinstance(t, ast.Name) and t.id == "_EXPORTS" for t in node.targets)
            and isinstance(node.value, ast.Dict))


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


MODULES = sorted(PACKAGE.rglob("*.py"))


def _graph():
    """Module -> the modules of the package it imports (every import, see the module
    notes)."""
    graph = {}
    for path in MODULES:
        targets = {_module_name(_module_path(m)) for m in imported_modules(path)
                   if _module_path(m) is not None}
        graph[_module_name(path)] = targets - {_module_name(path), ROOT}
    return graph


#: The package root: every module may import it for ``__version__`` (its other names are
#: exports loaded on first use, so importing it loads no layer).
ROOT = "slingloads"


def _layer(name):
    """The layer of module ``name`` (:data:`LAYERS`); None for the package root."""
    parts = name.split(".")
    if len(parts) == 1:
        return None
    return parts[1] if parts[1] in LAYERS else "base"


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


def test_no_import_cycle():
    """The modules of the package import each other without a circle (function-level and
    TYPE_CHECKING imports included), so none depends on the order in which they load."""
    graph = _graph()
    assert graph["slingloads.io.study"] and graph["slingloads.io.lateral.reader"]
    assert "slingloads.io.loads.report" in graph["slingloads.io.analyses"]
    cycle = _cycle(graph)
    assert cycle is None, " -> ".join(cycle)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_layers(path):
    """Each module imports only from its own layer and the layers below it
    (``models`` < ``analyses`` < ``runs`` < ``io`` < ``cli``; the shared modules below all;
    the package root, whose exports are loaded on first use, above all), except the listed
    ``to_<format>`` delegations of the physics."""
    name = _module_name(path)
    layer = _layer(name)
    if layer is None:
        return
    file = str(path.relative_to(PACKAGE))
    skip = [f for (f_file, f) in DELEGATIONS if f_file == file]
    rank = LAYERS.index(layer)
    targets = {_module_name(_module_path(m)) for m in imported_modules(path, skip=skip)
               if _module_path(m) is not None} - {ROOT}
    above = sorted(m for m in targets if LAYERS.index(_layer(m)) > rank)
    assert not above, f"{file} ({layer}) imports {above} from a layer above it"


def test_the_layer_check_sees_function_level_imports():
    """The walk sees an import inside a function and under TYPE_CHECKING, and the root's
    export table: what hides an import from a check made at import time."""
    found = set(imported_modules(PACKAGE / "cli.py"))
    assert "slingloads.io.study" in found  # imported inside _run_analyses
    assert "slingloads.runs.campaign" in set(imported_modules(PACKAGE / "runs" / "study.py"))
    assert "slingloads.io.study" in set(imported_modules(PACKAGE / "__init__.py"))


#: The modules that import by name: the root's export table, and the helper process's
#: loaders of the plots named in ``plot_function("module", name)`` calls (which the walk reads
#: as imports of the caller) and of the modules it warms up.
LOADERS = ("__init__.py", "io/common/figures.py", "io/common/helper.py")


def test_no_import_by_name():
    """No module imports another by a string (``import_module``, ``__import__``) except the
    :data:`LOADERS`, whose names the walk reads: the graph above is complete."""
    calls = []
    for path in MODULES:
        if str(path.relative_to(PACKAGE)) in LOADERS:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Call):
                func = node.func
                called = getattr(func, "id", None) or getattr(func, "attr", None)
                if called in ("import_module", "__import__"):
                    calls.append(f"{path.relative_to(PACKAGE)}:{node.lineno}")
    assert not calls, calls


def test_each_analysis_runs_from_one_table_of_modules():
    """``run_one`` takes each analysis's runs module from one table
    (:data:`slingloads.runs.registry.RUNS`, no string, no if/elif chain), each entry a
    function that imports its module by a plain import: the table names every analysis of
    ``ANALYSES`` in its order, each entry gives the module ``slingloads.runs.<name>`` with a
    ``run`` function, and the walk sees the study's import of the registry and the
    registry's of each module, so the cycle check above covers them."""
    from slingloads.runs.registry import RUNS
    from slingloads.runs.study import ANALYSES

    assert tuple(RUNS) == ANALYSES
    modules = {name: load() for name, load in RUNS.items()}
    for name, module in modules.items():
        assert module.__name__ == f"slingloads.runs.{name.replace(' ', '_')}"
        assert callable(module.run)
    graph = _graph()
    assert "slingloads.runs.registry" in graph["slingloads.runs.study"]
    assert {m.__name__ for m in modules.values()} <= graph["slingloads.runs.registry"]


def _private(name):
    return name.startswith("_") and not name.startswith("__")


def _private_imports(path):
    """``(line, module, name)`` of each ``from module import _name`` of ``path`` whose module
    is another module of the package (relative imports resolved), and of each ``module._name``
    read through a module of the package that ``path`` imports."""
    me = _module_name(path)
    package = me.split(".") if path.name == "__init__.py" else me.split(".")[:-1]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    modules = {}  # local name -> module of the package it is bound to
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            modules.update({a.asname or a.name.partition(".")[0]: a.name for a in node.names
                            if a.name.startswith("slingloads")})
        if not isinstance(node, ast.ImportFrom):
            continue
        if node.level:
            base = package[:len(package) - node.level + 1]
            module = ".".join(base + ([node.module] if node.module else []))
        else:
            module = node.module
        if not module.startswith("slingloads") or module == me:
            continue
        for alias in node.names:
            if _private(alias.name):
                yield node.lineno, module, alias.name
            elif _module_path(f"{module}.{alias.name}") is not None:
                modules[alias.asname or alias.name] = f"{module}.{alias.name}"
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                and node.value.id in modules and _private(node.attr)
                and modules[node.value.id] != me):
            yield node.lineno, modules[node.value.id], node.attr


def test_no_module_imports_a_private_name_of_another():
    """No module of the package imports an underscore name from another module (``from .x
    import _helper``, or ``x._helper`` through an imported module): a name another module
    needs is public (documented, no underscore) or lives in the one module that owns the
    idea. No exception: the packages' ``__init__`` modules import public names only too.
    (Third-party private names, such as openpyxl's, are not the package's to fix and are not
    counted.)"""
    found = [f"{path.relative_to(PACKAGE)}:{line}: from {module} import {name}"
             for path in MODULES for line, module, name in _private_imports(path)]
    assert not found, "\n".join(found)


def test_the_private_import_check_finds_one(tmp_path, monkeypatch):
    """The check above can fail: a made-up module of the package importing ``_helper`` from
    a sibling, relatively and absolutely, is caught, and its own names are not."""
    folder = tmp_path / "slingloads" / "sub"
    folder.mkdir(parents=True)
    path = folder / "a.py"
    (folder / "b.py").write_text("")
    path.write_text("from .b import _helper, public\nfrom slingloads.sub.b import _other\n"
                    "from . import _shared\nfrom os import _exit\nfrom . import b\n"
                    "b._hidden()\nb.public()\n")
    monkeypatch.setattr(f"{__name__}.PACKAGE", tmp_path / "slingloads")
    assert sorted(_private_imports(path)) == [(1, "slingloads.sub.b", "_helper"),
                                              (2, "slingloads.sub.b", "_other"),
                                              (3, "slingloads.sub", "_shared"),
                                              (6, "slingloads.sub.b", "_hidden")]


#: Compiled kernels whose packed vectors are read by names generated from their tables
#: (``STATES``, ``DRIVE``, ``INFO`` and the parameter ``LAYOUT`` of
#: :mod:`slingloads.models.multibody.equations`; ``RIGID_STATES`` and ``ELASTIC_STATES`` of
#: :mod:`slingloads.models.pendulum`; ``DRIVE`` and ``SIGNALS`` of
#: :mod:`slingloads.models.pendulum_batch`; ``STATES``, ``WIND``, ``PIECE`` and ``HARMONIC``
#: of :mod:`slingloads.models.yaw_batch`): (module, function, the vectors' names).
NAMED_INDEX_KERNELS = (
    ("models/multibody/equations.py", "evaluate", ("x", "dx", "info", "drive", "P")),
    ("models/multibody/integrator.py", "_renormalise", ("x",)),
    ("models/pendulum.py", "rope_angle", ("x",)),
    ("models/pendulum.py", "airframe_angle", ("x",)),
    ("models/pendulum_batch.py", "rigid_rope", ("x", "dx", "p")),
    ("models/pendulum_batch.py", "elastic_cable", ("x", "dx", "p")),
    ("models/pendulum_batch.py", "_rhs", ("x", "dx", "drive")),
    ("models/pendulum_batch.py", "_signals", ("x", "y")),
    ("models/pendulum_batch.py", "rk4_peaks", ("x", "x0", "bj", "tj", "y0", "y1", "y2")),
    ("models/yaw_batch.py", "_rhs", ("x", "dx", "wind")),
    ("models/yaw_batch.py", "rk4_batch", ("x", "new")),
    ("models/yaw_batch.py", "gust_value", ("harm",)),
    ("models/yaw_batch.py", "_dopri_rhs", ("y", "dx", "wind", "p_coef")),
    ("models/yaw_batch.py", "_dopri_run", ("x",)),
)


def _literal_indices(tree, function, vectors):
    """``name[line]`` of each subscript of one of ``vectors`` by an integer literal inside
    ``function`` of ``tree``: the whole index (``x[9]``) or its last axis, the packed one
    (``drive[i, stage, 0]``)."""
    found = []
    for f in ast.walk(tree):
        if isinstance(f, ast.FunctionDef) and f.name == function:
            for node in ast.walk(f):
                if not (isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name)
                        and node.value.id in vectors):
                    continue
                last = node.slice.elts[-1] if isinstance(node.slice, ast.Tuple) else node.slice
                if isinstance(last, ast.Constant) and isinstance(last.value, int):
                    index = ast.unparse(node.slice).strip("()")
                    found.append(f"{node.value.id}[{index}]@{node.lineno}")
    return found


@pytest.mark.parametrize("file, function, vectors", NAMED_INDEX_KERNELS,
                         ids=[f"{f}:{name}" for f, name, _ in NAMED_INDEX_KERNELS])
def test_kernels_index_packed_vectors_by_name(file, function, vectors):
    """The compiled kernels (multibody, lateral pendulum, yaw) read and write their states,
    drives, reported quantities, signals and parameters at offsets named from one table each
    (``x[X_QUAT + 1]``, ``P[PULL]``, ``drive[i, stage, D_VEL]``), never at a literal index
    (``x[10]``), so that a table and the kernel cannot disagree."""
    tree = ast.parse((PACKAGE / file).read_text(encoding="utf-8"))
    assert any(isinstance(f, ast.FunctionDef) and f.name == function for f in ast.walk(tree))
    found = _literal_indices(tree, function, vectors)
    assert not found, f"{file}:{function} indexes by literals: {found}"


def test_the_literal_index_check_finds_one():
    """The check above can fail: a literal index of a named vector is caught, a named offset
    and another array's literal are not."""
    tree = ast.parse("def f(x, e, d):\n    return x[9] + x[Q + 1] + e[0] + d[i, 1] + d[1, K]\n")
    assert sorted(_literal_indices(tree, "f", ("x", "d"))) == ["d[i, 1]@2", "x[9]@2"]


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

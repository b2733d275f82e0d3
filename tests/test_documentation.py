"""The code shown to users runs: the README's Python API example and docs/api.md, executed
as written (the reference is the documentation itself: an example that fails is a defect)."""

from __future__ import annotations

import os
import re
from pathlib import Path

import matplotlib
import pytest
from hostile import EXAMPLE

ROOT = Path(__file__).resolve().parents[1]


def python_blocks(path):
    return re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), re.S)


@pytest.mark.parametrize("doc", ["README.md", "docs/api.md"])
def test_python_examples_run(doc, tmp_path, monkeypatch):
    """Every ```python block of the page runs in order in one namespace, from the repository
    root (so relative paths such as loadcases/... resolve) with outputs in a temp folder."""
    matplotlib.use("Agg")
    blocks = python_blocks(ROOT / doc)
    assert blocks, f"{doc} has no python example"
    monkeypatch.chdir(tmp_path)
    (tmp_path / "loadcases").symlink_to(ROOT / "loadcases")
    namespace = {}
    for block in blocks:
        exec(compile(block, doc, "exec"), namespace)  # noqa: S102 - our own documentation
    assert os.listdir(tmp_path)


def test_readme_api_example_is_short():
    """The README's API example stays short: at most 15 lines."""
    blocks = python_blocks(ROOT / "README.md")
    assert len(blocks[0].strip().splitlines()) <= 15


def test_every_limit_is_documented():
    """Every limit of slingloads/limits.py is named, with its reason, on the inputs and
    outputs page (the reference: the page promises to state them all)."""
    import slingloads.limits as limits

    page = (ROOT / "docs" / "inputs-and-outputs.md").read_text(encoding="utf-8")
    names = [n for n in vars(limits) if n.startswith(("MAX_", "MIN_"))]
    assert names
    missing = [n for n in names if f"`{n}`" not in page]
    assert not missing, missing


def _modules_with_examples():
    """The modules of slingloads whose source holds a ``>>>`` example, by dotted name."""
    package = ROOT / "slingloads"
    names = []
    for path in sorted(package.rglob("*.py")):
        if ">>>" in path.read_text(encoding="utf-8"):
            parts = path.relative_to(ROOT).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


MODULES_WITH_EXAMPLES = _modules_with_examples()


def test_the_docstring_examples_are_found():
    """The search below finds the modules that show examples (at least the ones known to:
    a search that found none would make the doctest test pass without running anything)."""
    assert {"slingloads.models.flight", "slingloads.io.common.atomic"} <= set(
        MODULES_WITH_EXAMPLES)


@pytest.mark.parametrize("name", MODULES_WITH_EXAMPLES)
def test_docstring_examples_run(name, tmp_path, monkeypatch):
    """Every ``>>>`` example in the module's docstrings gives the output written under it
    (the reference is the documentation itself, run by the standard library's doctest);
    an example marked to be skipped counts as not run."""
    import doctest
    import importlib
    import shutil

    # files an example writes land in a temp folder, which holds the example workbook at the
    # path the examples name (relative to the repository, as a user runs them)
    (tmp_path / "loadcases").mkdir()
    shutil.copy(EXAMPLE, tmp_path / "loadcases" / EXAMPLE.name)
    monkeypatch.chdir(tmp_path)
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    examples = skipped = 0
    report = []
    for test in finder.find(module, name):
        examples += len(test.examples)
        skipped += sum(bool(e.options.get(doctest.SKIP)) for e in test.examples)
        runner.run(test, out=report.append)
    assert examples and not skipped, f"{name}: {examples} examples, {skipped} skipped"
    assert runner.failures == 0, "".join(report)

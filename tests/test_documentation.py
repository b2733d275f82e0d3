"""The code shown to users runs: the README's Python API example and docs/api.md, executed
as written (the reference is the documentation itself: an example that fails is a defect)."""

from __future__ import annotations

import os
import re
from pathlib import Path

import matplotlib
import pytest

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

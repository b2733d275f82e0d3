"""Layering: the physical models and the analyses never import the input/output layer nor
the file and plotting libraries (the reference is the architecture stated in README.md:
slingloads/models and slingloads/analyses are SI-only physics with no file access)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "slingloads"
FORBIDDEN = ("slingloads.io", "openpyxl", "matplotlib", "slingloads.cli")


def imported_modules(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            yield node.module


@pytest.mark.parametrize("path", sorted((PACKAGE / "models").glob("*.py"))
                         + sorted((PACKAGE / "analyses").glob("*.py")),
                         ids=lambda p: f"{p.parent.name}/{p.name}")
def test_physics_never_imports_io(path):
    """No module of models/ or analyses/ imports io, cli, openpyxl or matplotlib."""
    bad = [m for m in imported_modules(path) if m.startswith(FORBIDDEN)]
    assert not bad, f"{path.name} imports {bad}"

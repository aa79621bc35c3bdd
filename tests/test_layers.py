"""The layering rules: drivers import no Qt and no app; widgets import no drivers."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _imports(package: str) -> set[tuple[str, str]]:
    found = set()
    for path in (ROOT / package).rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                found.update((str(path.relative_to(ROOT)), a.name) for a in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module:
                found.add((str(path.relative_to(ROOT)), node.module))
    return found


@pytest.mark.parametrize(
    ("package", "forbidden"),
    [
        ("drivers", ("PySide6", "pyqtgraph", "app", "widgets", "OpenGL")),
        ("widgets", ("drivers", "app", "serial")),
    ],
)
def test_layer_imports(package: str, forbidden: tuple[str, ...]) -> None:
    bad = {(path, name) for path, name in _imports(package) if name.split(".")[0] in forbidden}
    assert not bad, f"{package} must not import {forbidden}: {sorted(bad)}"
    assert _imports(package), f"no imports found under {package}: the check would prove nothing"

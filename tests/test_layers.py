"""The layering rules: drivers import no Qt and no app; widgets import no drivers."""

from __future__ import annotations

import ast
from collections.abc import Callable
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


def _module_name(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _load_time_imports(body: list[ast.stmt]) -> list[ast.Import | ast.ImportFrom]:
    """The imports a module runs as it loads: top-level, in classes and in if/try/with blocks,
    not in functions (called later) nor under `if TYPE_CHECKING:`."""
    found: list[ast.Import | ast.ImportFrom] = []
    for node in body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            found.append(node)
        elif isinstance(node, ast.If):
            if not _is_type_checking(node.test):
                found += _load_time_imports(node.body)
            found += _load_time_imports(node.orelse)
        elif isinstance(node, ast.Try):
            for block in (node.body, node.orelse, node.finalbody):
                found += _load_time_imports(block)
            for handler in node.handlers:
                found += _load_time_imports(handler.body)
        elif isinstance(node, ast.With | ast.ClassDef):
            found += _load_time_imports(node.body)
    return found


def _import_graph(
    package: str,
    imports: Callable[[list[ast.stmt]], list[ast.Import | ast.ImportFrom]] | None = None,
) -> dict[str, set[str]]:
    """Each module of `package` and the modules of `package` it imports as it loads (or, with
    `imports`, the imports that function finds in the module's body)."""
    find = imports or _load_time_imports
    paths = {_module_name(path): path for path in (ROOT / package).rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for module, path in paths.items():
        is_package = path.name == "__init__.py"
        tree = ast.parse(path.read_text(encoding="utf-8"))
        targets: set[str] = set()
        for node in find(tree.body):
            if isinstance(node, ast.Import):
                targets.update(alias.name for alias in node.names)
                continue
            base = node.module or ""
            if node.level:  # relative: from the module's own package upwards
                parts = module.split(".")[: len(module.split(".")) - node.level + is_package]
                base = ".".join([*parts, *([base] if base else [])])
            targets.add(base)
            targets.update(f"{base}.{alias.name}" for alias in node.names)  # submodules
        graph[module] = {target for target in targets if target in paths and target != module}
    return graph


def _find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One import cycle of `graph` (its modules, the first repeated at the end), or None."""
    done: set[str] = set()
    path: list[str] = []

    def visit(module: str) -> list[str] | None:
        if module in path:
            return [*path[path.index(module) :], module]
        if module in done:
            return None
        path.append(module)
        for target in sorted(graph.get(module, ())):
            cycle = visit(target)
            if cycle is not None:
                return cycle
        path.pop()
        done.add(module)
        return None

    for module in sorted(graph):
        cycle = visit(module)
        if cycle is not None:
            return cycle
    return None


def test_the_cycle_finder_finds_a_cycle() -> None:
    assert _find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == ["a", "b", "c", "a"]
    assert _find_cycle({"a": {"b", "c"}, "b": {"c"}, "c": set()}) is None


def test_drivers_have_no_import_cycle() -> None:
    graph = _import_graph("drivers")
    assert graph["drivers.traffic.spy_log"] >= {"drivers.traffic.log_records", "drivers.messages"}
    assert "drivers.traffic.spy_log" in graph["drivers.traffic.log_reader"]
    assert "drivers.framers.base" in graph["drivers.framers"]  # the package's own import
    cycle = _find_cycle(graph)
    assert cycle is None, "drivers/ modules import each other as they load: " + " -> ".join(cycle)


def _every_import(body: list[ast.stmt]) -> list[ast.Import | ast.ImportFrom]:
    """Every import of a module: at load time, in functions (run later) and under
    `if TYPE_CHECKING:` alike (a cycle through any of them is still a circle of modules)."""
    return [
        node
        for node in ast.walk(ast.Module(body, []))
        if isinstance(node, ast.Import | ast.ImportFrom)
    ]


@pytest.mark.parametrize("package", ["app", "widgets"])
def test_app_and_widgets_have_no_import_cycle(package: str) -> None:
    graph = _import_graph(package, _every_import)
    cycle = _find_cycle(graph)
    assert cycle is None, f"{package}/ modules import each other: " + " -> ".join(cycle)


def test_drivers_have_no_import_cycle_through_function_imports_either() -> None:
    graph = _import_graph("drivers", _every_import)
    # The package's own public names (`drivers.open_device`...), imported on first use (its
    # __getattr__), are the scripting API's facade: every submodule's `from drivers import x`
    # would close a circle through it that no module loading goes round. It imports only the
    # public names' modules (for type checkers) and the finder of moved module paths.
    import drivers

    homes = {f"drivers.{m}" for m in ("_moved", "session.device_session")}
    homes |= {drivers._HOMES[name] for name in drivers.__all__}
    assert graph.pop("drivers") == homes
    cycle = _find_cycle(graph)
    assert cycle is None, "drivers/ modules import each other: " + " -> ".join(cycle)


def test_the_full_import_graph_sees_function_and_type_checking_imports() -> None:
    graph = _import_graph("app", _every_import)
    assert (
        "app.window.device.worker_thread" in graph["app.window.device.worker_link"]
    )  # in a function
    assert "app.window.services" in graph["app.window.docks.device_docks"]  # under TYPE_CHECKING
    assert "app.window.services" not in _import_graph("app")["app.window.docks.device_docks"]


def test_only_app_main_imports_the_main_window() -> None:
    importers = sorted(
        module
        for module, targets in _import_graph("app", _every_import).items()
        if "app.window.main_window" in targets
    )
    assert importers == ["app.main"]

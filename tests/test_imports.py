"""Imports flow one way: no cycle between the package's modules and folders; the outer layers stay outside."""

from __future__ import annotations

import ast
from pathlib import Path

from tests.conftest import REPO_ROOT

PACKAGE = REPO_ROOT / "src" / "trajadapt"
OUTER = {"cli": set(), "web": {"cli"}, "bench": {"cli"}}  # unit -> the only units that may import it
FOUNDATION = {"errors", "safe_text", "model", "code_parse"}
MAX_TOP_LEVEL_MODULES = 12


def unit_of(module: str) -> str:
    """'trajadapt.skills.core' -> 'skills'; 'trajadapt' -> 'trajadapt'."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "trajadapt"


def imported(path: Path) -> set[str]:
    """The trajadapt modules ``path`` imports at run time (TYPE_CHECKING blocks left out)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    typing_only = {
        id(sub)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
        for sub in ast.walk(node)
    }
    found = set()
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("trajadapt"):
            found.add(node.module)
        elif isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names if alias.name.startswith("trajadapt")}
    return found


def unit_graph() -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        source = unit_of(".".join(p for p in parts if p != "__init__"))
        graph.setdefault(source, set())
        graph[source] |= {unit_of(m) for m in imported(path)} - {source, "trajadapt"}
    return graph


def test_no_cycle_between_the_packages_parts() -> None:
    graph = unit_graph()

    def reachable(start: str) -> set[str]:
        seen, stack = set(), [start]
        while stack:
            for nxt in graph.get(stack.pop(), set()) - seen:
                seen.add(nxt)
                stack.append(nxt)
        return seen

    cycles = sorted(unit for unit in graph if unit in reachable(unit))
    assert cycles == [], f"these parts import each other in a circle: {cycles}"


def test_the_outer_layers_are_imported_only_from_outside() -> None:
    graph = unit_graph()
    for outer, allowed in OUTER.items():
        importers = {unit for unit, deps in graph.items() if outer in deps}
        assert importers <= allowed, f"{outer} is imported by {sorted(importers - allowed)}"


def test_the_foundation_imports_only_the_foundation() -> None:
    graph = unit_graph()
    for unit in FOUNDATION:
        assert graph[unit] <= FOUNDATION, f"{unit} imports {sorted(graph[unit] - FOUNDATION)}"


def test_the_top_level_holds_few_modules_and_the_rest_are_packages() -> None:
    modules = sorted(path.name for path in PACKAGE.glob("*.py"))
    assert len(modules) <= MAX_TOP_LEVEL_MODULES, modules


def test_no_reader_imports_another_reader() -> None:
    from trajadapt.readers import READERS

    helpers = {
        "trajadapt.readers.words",
        "trajadapt.readers.direction_words",
        "trajadapt.readers.height_words",
        "trajadapt.readers.least_distances",
        "trajadapt.readers.end_words",
        "trajadapt.readers.end_place_words",
        "trajadapt.readers.stop_words",
        "trajadapt.readers.part_words",
        "trajadapt.readers.object_words",
        "trajadapt.readers.clause_split",
        "trajadapt.readers.request_words",
        "trajadapt.readers.plain_words",
        "trajadapt.readers.object_kinds",
        "trajadapt.readers.pointed_objects",
        "trajadapt.readers.object_mentions",
        "trajadapt.readers.paces",
        "trajadapt.readers.clause_amounts",
        "trajadapt.readers",
    }
    reader_modules = {reader.read.__module__ for reader in READERS} - {"trajadapt.readers"}
    folder = PACKAGE / "readers"
    modules = {f"trajadapt.readers.{path.stem}" for path in folder.glob("*.py") if path.stem != "__init__"}
    assert len(modules - helpers) == len({id(reader.read) for reader in READERS})  # one may run twice
    for module in modules - helpers:
        found = imported(folder / f"{module.rsplit('.', 1)[1]}.py")
        assert not {m for m in found if m.startswith("trajadapt.readers")} - helpers, module
    assert reader_modules <= modules


def test_only_the_readers_package_lists_the_readers() -> None:
    for path in PACKAGE.rglob("*.py"):
        if path.parent.name == "readers":
            continue
        text = path.read_text(encoding="utf-8")
        assert "replace_unstated_amounts" not in text and "readers.unasked_steps import" not in text, path


def test_no_module_is_longer_than_a_reader_can_hold() -> None:
    long = {
        str(p.relative_to(PACKAGE)): n
        for p in PACKAGE.rglob("*.py")
        if (n := len(p.read_text().splitlines())) > 400
    }
    assert long == {}


def test_no_session_result_travels_through_an_attribute() -> None:
    for path in (PACKAGE / "session").glob("*.py"):
        assert "self._last_" not in path.read_text(), path

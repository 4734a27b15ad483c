"""The package's imports point down its layers, form no cycle and keep private modules private.

The layer order is written once, in docs/architecture.md (the block after ``<!-- layers -->``),
and read from there. Imports under ``if TYPE_CHECKING:`` are type hints only and do not count;
imports inside functions (lazy imports) do.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import networkx as nx
import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "realistic_indoor"
TOP = "realistic_indoor"


def read_layers(text: str) -> list[list[str]]:
    """The layers, lowest first, from the numbered list after the ``<!-- layers -->`` marker."""
    block = text.split("<!-- layers -->", 1)[1].split("```", 2)[1]
    layers = [
        re.sub(r"^\s*\d+\.\s*", "", line) for line in block.splitlines() if re.match(r"^\s*\d+\.", line)
    ]
    return [[name.strip().strip("`") for name in line.split("#")[0].split(",")] for line in layers]


LAYERS = read_layers((ROOT / "docs" / "architecture.md").read_text())
RANK = {name: i for i, names in enumerate(LAYERS) for name in names}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _resolve(importer: str, is_package: bool, node: ast.ImportFrom) -> str:
    if not node.level:
        return node.module or ""
    base = importer.split(".") if is_package else importer.split(".")[:-1]
    base = base[: len(base) - node.level + 1]
    return ".".join(base + ([node.module] if node.module else []))


def _target(module: str, name: str, known: set[str]) -> str:
    """``from module import name``: the submodule if ``name`` is one, else the module."""
    return f"{module}.{name}" if f"{module}.{name}" in known else module


def imports_of(path: Path, known: set[str]) -> list[tuple[str, str, int]]:
    """``(imported module, imported name or "", line)`` of every runtime import in the file."""
    return imports_in(path.read_text(), module_name(path), path.name == "__init__.py", known)


def imports_in(source: str, importer: str, is_package: bool, known: set[str]) -> list[tuple[str, str, int]]:
    """The runtime imports of the project's own modules in ``source``, the text of ``importer``."""
    out: list[tuple[str, str, int]] = []

    def visit(node: ast.AST) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _is_type_checking(child):
                for stmt in child.orelse:
                    visit_one(stmt)
                continue
            visit_one(child)

    def visit_one(child: ast.AST) -> None:
        if isinstance(child, ast.Import):
            out.extend((alias.name, "", child.lineno) for alias in child.names)
        elif isinstance(child, ast.ImportFrom):
            module = _resolve(importer, is_package, child)
            out.extend((_target(module, a.name, known), a.name, child.lineno) for a in child.names)
        else:
            visit(child)

    visit(ast.parse(source, importer))
    return [(m, n, line) for m, n, line in out if m == TOP or m.startswith(TOP + ".")]


FILES = sorted(PACKAGE.rglob("*.py"))
KNOWN = {module_name(p) for p in FILES}
EDGES = {module_name(p): imports_of(p, KNOWN) for p in FILES}


def layer_of(module: str) -> str:
    """The layer entry of a module: its top-level package or module under ``realistic_indoor``."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "realistic_indoor"


def upward(importer: str, edges: list[tuple[str, str, int]]) -> list[str]:
    """The imports of ``importer`` that point up the layers."""
    return [dst for dst, _, _ in edges if RANK[layer_of(dst)] > RANK[layer_of(importer)]]


def test_checker__flags_what_the_rules_forbid():
    """The checks can fail: an upward, a type-hint-only, a private and a lazy import, judged."""
    source = (
        "from typing import TYPE_CHECKING\n"
        "from realistic_indoor.validator.connectivity import set_connectivity\n"
        "if TYPE_CHECKING:\n"
        "    from realistic_indoor.envs.config import EnvConfig\n"
        "def f():\n"
        "    from realistic_indoor.sim import _edt\n"
        "    from ..agents import explorer\n"
    )
    edges = imports_in(source, "realistic_indoor.generator.functions", False, KNOWN)
    # validator is beside generator (allowed); envs is a type hint only; agents is above
    assert upward("realistic_indoor.generator.functions", edges) == ["realistic_indoor.agents.explorer"]
    assert "realistic_indoor.envs.config" not in [dst for dst, _, _ in edges]
    assert ("realistic_indoor.sim._edt", "_edt", 6) in edges
    assert _owner("realistic_indoor.sim._edt", "") == "realistic_indoor.sim"
    assert _owner("realistic_indoor.sim.lidar", "_readings") == "realistic_indoor.sim"
    assert _owner("realistic_indoor.sim.lidar", "Lidar") is None


def test_layer_list__names_every_package_once():
    names = [n for layer in LAYERS for n in layer]
    assert len(names) == len(set(names))
    assert {layer_of(m) for m in KNOWN} <= set(names), "docs/architecture.md's layer list misses a package"


def test_imports__never_point_up_the_layers():
    found = [f"{src} imports {dst}" for src, edges in EDGES.items() for dst in upward(src, edges)]
    assert found == []


def test_packages_of_one_layer__do_not_import_each_other_in_a_circle():
    graph = nx.DiGraph()
    for src, edges in EDGES.items():
        for dst, _, _ in edges:
            a, b = layer_of(src), layer_of(dst)
            if a != b and RANK[a] == RANK[b]:
                graph.add_edge(a, b)
    assert list(nx.simple_cycles(graph)) == []


def test_modules__import_each_other_in_no_cycle():
    """A cycle of module-level imports (lazy imports inside functions are not part of loading)."""
    graph = nx.DiGraph()
    for path in FILES:
        src = module_name(path)
        tree = ast.parse(path.read_text())
        for node in tree.body:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                for dst, _, _ in imports_of_node(path, node):
                    if dst != src and not src.startswith(dst + "."):
                        graph.add_edge(src, dst)
    cycles = [c for c in nx.simple_cycles(graph) if len(c) > 1]
    assert cycles == []


def _module_graph(edges: dict[str, list[tuple[str, str, int]]]) -> nx.DiGraph:
    """Module -> imported module, for every runtime import (lazy ones inside functions too).

    A package's ``__init__`` importing its own submodules, and a submodule importing its
    package, are left out: a package is the sum of its modules, not a module beside them.
    """
    graph = nx.DiGraph()
    for src, found in edges.items():
        for dst, _, _ in found:
            if dst != src and not src.startswith(dst + ".") and not dst.startswith(src + "."):
                graph.add_edge(src, dst)
    return graph


def test_modules__import_each_other_in_no_cycle_even_lazily():
    """No two modules need each other, not even through an import inside a function: a lazy
    import that closes a circle hides a dependency that goes both ways."""
    cycles = sorted(sorted(c) for c in nx.simple_cycles(_module_graph(EDGES)) if len(c) > 1)
    assert cycles == []


def test_cycle_check__sees_a_cycle_closed_by_a_lazy_import():
    a = imports_in("from realistic_indoor.sim import lidar\n", "realistic_indoor.sim.raster", False, KNOWN)
    b = imports_in(
        "def f():\n    from realistic_indoor.sim import raster\n", "realistic_indoor.sim.lidar", False, KNOWN
    )
    graph = _module_graph({"realistic_indoor.sim.raster": a, "realistic_indoor.sim.lidar": b})
    assert [sorted(c) for c in nx.simple_cycles(graph)] == [
        ["realistic_indoor.sim.lidar", "realistic_indoor.sim.raster"]
    ]


def imports_of_node(path: Path, node: ast.Import | ast.ImportFrom) -> list[tuple[str, str, int]]:
    importer, is_package = module_name(path), path.name == "__init__.py"
    if isinstance(node, ast.Import):
        return [(a.name, "", node.lineno) for a in node.names if a.name.startswith(TOP)]
    module = _resolve(importer, is_package, node)
    if not module.startswith(TOP):
        return []
    return [(_target(module, a.name, KNOWN), a.name, node.lineno) for a in node.names]


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _owner(module: str, name: str) -> str | None:
    """The package whose private module or name ``from module import name`` reaches, if any.

    A private module (``sim._edt``) belongs to the package it sits in; a private name of a
    public module (``sim.lidar._readings``) to that module's package.
    """
    parts = module.split(".")
    first = next((i for i, p in enumerate(parts) if _private(p)), None)
    if first is not None:
        return ".".join(parts[:first])
    return module.rsplit(".", 1)[0] if _private(name) else None


def test_private_modules_and_names__are_imported_only_inside_their_package():
    leaks = []
    for src, edges in EDGES.items():
        for dst, name, line in edges:
            owner = _owner(dst, name)
            if owner is not None and not (src + ".").startswith(owner + "."):
                leaks.append(f"{src}:{line} imports {dst} {name}")
    assert leaks == []


@pytest.mark.parametrize("folder", ["benchmarks", "experiments", "scripts"])
def test_scripts__use_only_public_modules_and_names(folder):
    leaks = []
    for path in sorted((ROOT / folder).rglob("*.py")):
        for dst, name, line in imports_of(path, KNOWN):
            if _owner(dst, name) is not None:
                leaks.append(f"{path.relative_to(ROOT)}:{line} imports {dst} {name}")
    assert leaks == []

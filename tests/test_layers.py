"""The package's imports point down its layers, form no cycle and keep private modules private.

The layer order is written once, in docs/architecture.md (the block after ``<!-- layers -->``),
and read from there. Every import statement counts, wherever it stands: at the top of a file, in
a class body, or inside a function (a lazy import runs later, but the dependency is as real; a
circle closed by one is a circle). A package's ``__init__`` is a module like the others: when
it imports a submodule and that submodule imports a name the ``__init__`` defines, the two
need each other.

Imports under ``if TYPE_CHECKING:`` are left out. They never run (``TYPE_CHECKING`` is false at
run time, and with ``from __future__ import annotations`` the hints they serve are strings), so
they cannot make one module's loading wait on another's; and a hint is how a lower module names
the type of an object a higher one hands it without depending on that module's code. Counting
them would force such hints down to ``Any``.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import NamedTuple

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


class Import(NamedTuple):
    """One imported name of the project, as an import statement of ``importer`` reaches it.

    Attributes:
        module: The module reached: the submodule when the name is one, else the module named.
        name: The name imported from ``module`` (``""`` for ``import module``).
        line: The statement's line in the importer.
        lazy: Whether the statement stands inside a function (it runs when that is called).
    """

    module: str
    name: str
    line: int
    lazy: bool

    def where(self, importer: str) -> str:
        """``importer:line``, marked when the import is inside a function."""
        return f"{importer}:{self.line}" + (" (inside a function)" if self.lazy else "")


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


def imports_of(path: Path, known: set[str]) -> list[Import]:
    """Every runtime import of the project's own modules in the file."""
    return imports_in(path.read_text(), module_name(path), path.name == "__init__.py", known)


def imports_in(source: str, importer: str, is_package: bool, known: set[str]) -> list[Import]:
    """The runtime imports of the project's own modules in ``source``, the text of ``importer``.

    Every import statement counts, nested at any depth, except those under ``if TYPE_CHECKING:``
    (their ``else:`` branch runs, so it counts).
    """
    out: list[Import] = []

    def visit(node: ast.AST, lazy: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _is_type_checking(child):
                for stmt in child.orelse:
                    visit_one(stmt, lazy)
            else:
                visit_one(child, lazy)

    def visit_one(child: ast.AST, lazy: bool) -> None:
        if isinstance(child, ast.Import):
            out.extend(Import(alias.name, "", child.lineno, lazy) for alias in child.names)
        elif isinstance(child, ast.ImportFrom):
            module = _resolve(importer, is_package, child)
            out.extend(
                Import(_target(module, a.name, known), a.name, child.lineno, lazy) for a in child.names
            )
        else:
            visit(child, lazy or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)))

    visit(ast.parse(source, importer), False)
    return [i for i in out if i.module == TOP or i.module.startswith(TOP + ".")]


FILES = sorted(PACKAGE.rglob("*.py"))
KNOWN = {module_name(p) for p in FILES}
EDGES = {module_name(p): imports_of(p, KNOWN) for p in FILES}


def layer_of(module: str) -> str:
    """The layer entry of a module: its top-level package or module under ``realistic_indoor``."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "realistic_indoor"


def upward(importer: str, edges: list[Import]) -> list[Import]:
    """The imports of ``importer`` that point up the layers."""
    return [i for i in edges if RANK[layer_of(i.module)] > RANK[layer_of(importer)]]


def module_graph(edges: dict[str, list[Import]]) -> nx.DiGraph:
    """Module -> imported module, for every runtime import; each edge keeps its imports.

    A package's ``__init__`` is the node of the package's own name. A module importing itself
    is no edge.
    """
    graph = nx.DiGraph()
    for src, found in edges.items():
        for i in found:
            if i.module != src:
                if not graph.has_edge(src, i.module):
                    graph.add_edge(src, i.module, imports=[])
                graph.edges[src, i.module]["imports"].append(i)
    return graph


def cycles(graph: nx.DiGraph) -> list[list[str]]:
    """The groups of nodes that reach each other (strongly connected components of two or
    more), each sorted, in sorted order. A graph with none has no cycle between nodes.

    Linear in nodes and edges, unlike listing every simple cycle.
    """
    return sorted(sorted(c) for c in nx.strongly_connected_components(graph) if len(c) > 1)


def describe(graph: nx.DiGraph, members: list[str]) -> str:
    """A cycle's members and the imports that join them, one per line, to find what to move."""
    links = [
        f"  {i.where(src)} imports {dst}{' ' + i.name if i.name else ''}"
        for src, dst, data in graph.subgraph(members).edges(data=True)
        for i in data.get("imports", [])
    ]
    return "cycle: " + ", ".join(members) + "\n" + "\n".join(sorted(links))


KNOWN_CYCLES: dict[tuple[str, ...], str] = {}
"""Cycles left to the change that owns their folder, each with where it closes. The test fails
once one is gone, so the entry leaves with it."""


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
    # validator is beside generator (allowed); envs is a type hint only; agents is above, lazily
    assert upward("realistic_indoor.generator.functions", edges) == [
        Import("realistic_indoor.agents.explorer", "explorer", 7, True)
    ]
    assert "realistic_indoor.envs.config" not in [i.module for i in edges]
    assert Import("realistic_indoor.validator.connectivity", "set_connectivity", 2, False) in edges
    assert Import("realistic_indoor.sim._edt", "_edt", 6, True) in edges
    assert _owner("realistic_indoor.sim._edt", "") == "realistic_indoor.sim"
    assert _owner("realistic_indoor.sim.lidar", "_readings") == "realistic_indoor.sim"
    assert _owner("realistic_indoor.sim.lidar", "Lidar") is None


def test_layer_list__names_every_package_once():
    names = [n for layer in LAYERS for n in layer]
    assert len(names) == len(set(names))
    assert {layer_of(m) for m in KNOWN} <= set(names), "docs/architecture.md's layer list misses a package"


def test_imports__never_point_up_the_layers():
    """No import points up, at the top of a file or inside a function (those are counted apart)."""
    found = [(src, i) for src, edges in EDGES.items() for i in upward(src, edges)]
    lazy = sum(i.lazy for _, i in found)
    assert found == [], f"{len(found)} upward imports, {lazy} of them inside functions:\n" + "\n".join(
        f"{i.where(src)} imports {i.module}" for src, i in found
    )


def test_packages_of_one_layer__do_not_import_each_other_in_a_circle():
    graph = nx.DiGraph()
    for src, edges in EDGES.items():
        for i in edges:
            a, b = layer_of(src), layer_of(i.module)
            if a != b and RANK[a] == RANK[b]:
                graph.add_edge(a, b)
    assert cycles(graph) == []


def test_modules__import_each_other_in_no_cycle():
    """No two modules need each other, through any chain of imports, lazy ones included."""
    graph = module_graph(EDGES)
    found = [c for c in cycles(graph) if tuple(c) not in KNOWN_CYCLES]
    assert found == [], "\n\n".join(describe(graph, c) for c in found)


def test_known_cycles__still_stand():
    """An entry of KNOWN_CYCLES leaves once its cycle is broken."""
    found = {tuple(c) for c in cycles(module_graph(EDGES))}
    assert [c for c in KNOWN_CYCLES if c not in found] == [], "no longer a cycle: remove it from KNOWN_CYCLES"


def test_cycle_finder__finds_the_cycles_of_a_known_graph():
    graph = nx.DiGraph([("a", "b"), ("b", "c"), ("c", "a"), ("c", "d"), ("d", "e"), ("e", "d"), ("e", "f")])
    assert cycles(graph) == [["a", "b", "c"], ["d", "e"]]
    assert cycles(nx.DiGraph([("a", "b"), ("b", "c"), ("a", "c")])) == []


def test_cycle_check__sees_a_cycle_closed_by_a_lazy_import():
    a = imports_in("from realistic_indoor.sim import lidar\n", "realistic_indoor.sim.raster", False, KNOWN)
    b = imports_in(
        "def f():\n    from realistic_indoor.sim import raster\n", "realistic_indoor.sim.lidar", False, KNOWN
    )
    graph = module_graph({"realistic_indoor.sim.raster": a, "realistic_indoor.sim.lidar": b})
    assert cycles(graph) == [["realistic_indoor.sim.lidar", "realistic_indoor.sim.raster"]]
    assert "realistic_indoor.sim.lidar:2 (inside a function) imports realistic_indoor.sim.raster" in describe(
        graph, cycles(graph)[0]
    )


def test_cycle_check__sees_a_package_init_and_its_submodule_need_each_other():
    """A submodule importing a name its package's ``__init__`` defines, which imports the submodule."""
    init = imports_in("from realistic_indoor.sim import raster\n", "realistic_indoor.sim", True, KNOWN)
    sub = imports_in(
        "def f():\n    from realistic_indoor.sim import lidar, run_all\n",
        "realistic_indoor.sim.raster",
        False,
        KNOWN,
    )
    graph = module_graph({"realistic_indoor.sim": init, "realistic_indoor.sim.raster": sub})
    assert cycles(graph) == [["realistic_indoor.sim", "realistic_indoor.sim.raster"]]
    assert graph.has_edge("realistic_indoor.sim.raster", "realistic_indoor.sim.lidar")


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
    leaks = [
        f"{i.where(src)} imports {i.module} {i.name}"
        for src, edges in EDGES.items()
        for i in edges
        if (owner := _owner(i.module, i.name)) is not None and not (src + ".").startswith(owner + ".")
    ]
    assert leaks == []


@pytest.mark.parametrize("folder", ["benchmarks", "experiments", "scripts"])
def test_scripts__use_only_public_modules_and_names(folder):
    leaks = []
    for path in sorted((ROOT / folder).rglob("*.py")):
        for i in imports_of(path, KNOWN):
            if _owner(i.module, i.name) is not None:
                leaks.append(f"{path.relative_to(ROOT)}:{i.line} imports {i.module} {i.name}")
    assert leaks == []

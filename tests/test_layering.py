"""The package is layered: its module import graph has no cycle.

The graph is read from the source with ``ast`` (nothing is imported), over every module of
``infmob_usd.*`` (the five folders mapped in ``pyproject.toml``). An edge ``a -> b`` means
module ``a`` imports module ``b``; ``from pkg import name`` counts as importing ``pkg.name``
when that is a module, else ``pkg``. Imports at module level and imports inside functions
(lazy imports) are both edges: a lazy import that closes a loop hides a cycle, it does not
break one. Imports under ``if TYPE_CHECKING:`` are not edges (they never run). A module's
parent packages, which Python runs before it, are not edges either (``infmob_usd/__init__``
re-exports the API, so every module would otherwise sit on a cycle through it).

Run as a script to print the graph and any cycles::

    .venv/bin/python tests/test_layering.py          # exit 1 if there is a cycle
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = {  # package -> folder, as [tool.setuptools.package-dir] maps them
    "infmob_usd": "infmob_usd",
    "infmob_usd.categories": "categories",
    "infmob_usd.materials": "materials",
    "infmob_usd.layers": "layers",
    "infmob_usd.validate": "validate",
}


def modules() -> dict[str, Path]:
    """Dotted module name -> source file, for every module of the distribution."""
    out = {}
    for package, folder in FOLDERS.items():
        base = ROOT / folder
        for path in sorted(base.rglob("*.py")):
            rel = path.relative_to(base).with_suffix("")
            parts = [p for p in rel.parts if p != "__init__"]
            if any(p.startswith(".") or p == "__pycache__" for p in rel.parts):
                continue
            out[".".join([package, *parts])] = path
    return out


def _is_type_checking(node: ast.If) -> bool:
    t = node.test
    return (isinstance(t, ast.Name) and t.id == "TYPE_CHECKING") or (
        isinstance(t, ast.Attribute) and t.attr == "TYPE_CHECKING")


def imports(name: str, path: Path, known: set[str]) -> dict[str, set[str]]:
    """``{"module": {...}, "function": {...}}``: the package modules ``name`` imports at module
    level and inside functions (or classes' methods)."""
    is_package = path.name == "__init__.py"
    here = name if is_package else name.rpartition(".")[0]
    found: dict[str, set[str]] = {"module": set(), "function": set()}

    def resolve(level: int, module: str | None) -> str:
        if level == 0:
            return module or ""
        base = here.split(".")
        base = base[: len(base) - (level - 1)]
        return ".".join(base + ([module] if module else []))

    def add(target: str, where: str) -> None:
        while target and target not in known:  # "a.b.c" where c is a name in module a.b
            target = target.rpartition(".")[0]
        if target and target != name:
            found[where].add(target)

    def visit(node: ast.AST, where: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _is_type_checking(child):
                for sub in child.orelse:
                    visit_stmt(sub, where)
                continue
            visit_stmt(child, where)

    def visit_stmt(child: ast.AST, where: str) -> None:
        if isinstance(child, ast.Import):
            for alias in child.names:
                add(alias.name, where)
        elif isinstance(child, ast.ImportFrom):
            base = resolve(child.level, child.module)
            for alias in child.names:
                full = f"{base}.{alias.name}"
                add(full if full in known else base, where)
        elif isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            visit(child, "function")
        else:
            visit(child, where)

    visit(ast.parse(path.read_text(), str(path)), "module")
    return found


def graph() -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    """``(module-level edges, function-level edges)`` of every package module."""
    mods = modules()
    known = set(mods)
    top, lazy = {}, {}
    for name, path in mods.items():
        found = imports(name, path, known)
        top[name], lazy[name] = found["module"], found["function"]
    return top, lazy


def cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def strong(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(max(10000, sys.getrecursionlimit()))
    for v in sorted(edges):
        if v not in index:
            strong(v)
    return sorted(out)


def _merged(top, lazy):
    return {k: top.get(k, set()) | lazy.get(k, set()) for k in set(top) | set(lazy)}


def test_graph_sees_the_package():
    top, lazy = graph()
    assert "infmob_usd.geometry" in top and "infmob_usd.layers.usd" in top
    assert "infmob_usd.validate.files" in top and "infmob_usd.categories.lamp" in top
    # edges are resolved through relative imports and `from pkg import module`
    assert "infmob_usd.piece" in top["infmob_usd.mass"]
    assert "infmob_usd.categories" in lazy["infmob_usd.api"]


def test_cycle_finder_finds_cycles():
    edges = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"e"}}
    assert cycles(edges) == [["a", "b", "c"]]


def test_no_import_cycle():
    """No cycle among module-level and function-level imports together."""
    top, lazy = graph()
    found = cycles(_merged(top, lazy))
    assert not found, "import cycles (python tests/test_layering.py prints them): " + "; ".join(
        " <-> ".join(c) for c in found)


TOP = {"infmob_usd", "infmob_usd.__main__", "infmob_usd.api", "infmob_usd.cli", "infmob_usd.batch",
       "infmob_usd.fuzz", "infmob_usd.parts_tools", "infmob_usd.maniskill"}
"""The entry points: they wire the rooms together (generate, save, the command line, the fuzzer, the
part-library tools that export and measure the categories' own parts, the ManiSkill tasks that generate
objects and load them with the simulator checks' loaders); so does the scene composer's
package (``infmob_usd.scenes``: it makes objects, writes and checks scenes; its modules are core)."""


def room(module: str) -> str:
    """The room of a module (ARCHITECTURE.md): top, core, categories, materials, layers, validate."""
    if module in TOP or module == "infmob_usd.scenes" or module.split(".")[:2] == ["infmob_usd", "export"]:
        return "top"  # the dataset exporter reads object folders, runs a pool and writes: an entry point
    for name in ("categories", "materials", "layers", "validate"):
        if module == f"infmob_usd.{name}" or module.startswith(f"infmob_usd.{name}."):
            return name
    return "core"


FORBIDDEN = {  # room -> rooms it must not import (directly, at any level)
    "core": {"top", "categories", "layers", "validate"},
    "materials": {"top", "core", "categories", "layers", "validate"},
    "categories": {"top", "layers", "validate"},
    "layers": {"top", "categories", "validate"},
    "validate": {"categories", "layers"},
}


def test_rooms_import_only_downwards():
    """The core knows no category, writer or validator; writers and validators know no category;
    validate/ reads files, not the writers (its benchmark may call the top-level API)."""
    top, lazy = graph()
    bad = [f"{a} -> {b}" for a, targets in _merged(top, lazy).items() for b in sorted(targets)
           if room(b) in FORBIDDEN.get(room(a), ())]
    assert not bad, "imports against the room order: " + "; ".join(sorted(bad))


def main() -> int:
    top, lazy = graph()
    for name in sorted(top):
        t, f = sorted(top[name]), sorted(lazy[name] - top[name])
        print(f"{name}: {', '.join(t) or '-'}" + (f"  | in functions: {', '.join(f)}" if f else ""))
    found = cycles(_merged(top, lazy))
    only_top = cycles(top)
    print(f"\n{len(found)} cycle(s) among all imports, {len(only_top)} among module-level imports")
    bad = [f"{a} -> {b}" for a, targets in _merged(top, lazy).items() for b in sorted(targets)
           if room(b) in FORBIDDEN.get(room(a), ())]
    print(f"{len(bad)} import(s) against the room order" + "".join(f"\n  {b}" for b in sorted(bad)))
    for c in found:
        print("  cycle:", " <-> ".join(c))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

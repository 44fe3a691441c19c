"""The package's shape: one-way imports, a light ``import pentanb``, and the mesh's
private members read only inside :mod:`pentanb.mesh`."""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import pentanb
from pentanb.mesh import Mesh

ROOT = Path(pentanb.__file__).parent


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports(path: Path) -> set[str]:
    """Every pentanb module ``path`` imports, at load time or inside a function."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("pentanb"))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("pentanb"):
                continue
            found.add(target)
            for alias in node.names:  # "from . import x" may name a submodule
                found.add(f"{target}.{alias.name}")
    return found


def import_graph() -> dict[str, set[str]]:
    """Module -> the pentanb modules it imports (a package's own __init__ left out)."""
    modules = {_module_name(p): p for p in ROOT.rglob("*.py")}
    graph = {}
    for name, path in modules.items():
        targets = {t for t in _imports(path) if t in modules}
        # importing a.b.c runs a/__init__ and a/b/__init__ first: those count,
        # except the packages that contain the importer itself
        graph[name] = {t for t in targets if t != name and not name.startswith(t + ".")}
    return graph


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """A cycle of the graph as a list of nodes, or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt) :] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def test_imports_go_one_way():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_the_cycle_finder_finds_a_cycle():
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": set()}) is None


def test_import_pentanb_loads_no_heavy_module():
    code = (
        "import sys, pentanb\n"
        "heavy = ('scipy', 'matplotlib', 'ipywidgets', 'pythreejs', 'numba', 'pentanb.analysis',"
        " 'pentanb.viz', 'pentanb.figures')\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] in heavy or m.startswith(heavy)))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def _private_members() -> set[str]:
    names = set(Mesh.__slots__) | {n for n in dir(Mesh) if n.startswith("_")}
    return {n for n in names if n.startswith("_") and not n.startswith("__")}


def test_no_module_outside_the_mesh_package_reads_a_private_member_of_a_mesh():
    private = _private_members()
    assert {"_new", "_shared", "_faces_only", "_extent"} <= private
    pattern = re.compile(r"\.(" + "|".join(sorted(private, key=len, reverse=True)) + r")\b")
    offenders = []
    for path in ROOT.rglob("*.py"):
        if path.is_relative_to(ROOT / "mesh"):
            continue
        for lineno, line in enumerate(path.read_text().splitlines(), 1):
            if pattern.search(line.split("#", 1)[0]):
                offenders.append(f"{path.relative_to(ROOT)}:{lineno}: {line.strip()}")
    assert not offenders, "\n".join(offenders)

"""The architecture of ../shared/DESIGN.md, read off the code with ``ast``.

* imports go only downward in the layer order (function-level imports count too);
* no import cycles between modules;
* no private name (``_x``) imported from another module;
* no module sets process state on import (``os.environ`` assignments at module level).

The layer order is DESIGN.md's, lowest first. A package not in it fails the test: add it
where it belongs (and to DESIGN.md) rather than to an exception list here.
"""

from __future__ import annotations

import ast
from pathlib import Path

import networkx as nx
import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "assistant"

#: lowest first; modules of one layer may import each other
LAYERS: tuple[tuple[str, ...], ...] = (
    ("errors", "fileio", "progress", "rdt", "runtime"),
    ("geometry",),
    ("world",),
    ("robot",),
    ("sim",),
    ("perception",),
    ("language",),
    ("grounding",),
    ("spatial",),
    ("policy",),
    ("executor",),
    ("generation",),
    ("viz",),
    ("app",),
    ("dialogue",),
    ("eval",),
    ("cli",),
)
#: the package's own entry points sit above everything
TOP = ("__init__", "__main__")
LAYER_OF = {name: rank for rank, names in enumerate(LAYERS) for name in names}


def module_name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def layer(module: str) -> int | None:
    parts = module.split(".")
    if len(parts) == 1:  # the package itself
        return len(LAYERS)
    return LAYER_OF.get(parts[1], len(LAYERS) if parts[1] in TOP else None)


def imports_of(path: Path) -> list[tuple[str, list[str], int]]:
    """(imported module, names imported from it, line) for every import in a file."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    me = module_name(path)
    package = me if path.name == "__init__.py" else me.rpartition(".")[0]
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out.extend((alias.name, [], node.lineno) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            out.append((target, [a.name for a in node.names], node.lineno))
    return out


def source_files() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py") if "data" not in p.relative_to(PACKAGE).parts)


def own_imports():
    for path in source_files():
        for target, names, line in imports_of(path):
            if target == "assistant" or target.startswith("assistant."):
                yield path, module_name(path), target, names, line


def test_every_package_has_a_layer():
    unknown = sorted({module.split(".")[1] for _, module, *_ in own_imports()
                      if "." in module and layer(module) is None})
    assert not unknown, f"packages missing from the layer order: {unknown}"


def test_imports_only_go_downward():
    upward = []
    for path, module, target, _, line in own_imports():
        mine, theirs = layer(module), layer(target)
        if mine is not None and theirs is not None and theirs > mine:
            upward.append(f"{path.relative_to(PACKAGE.parent)}:{line} {module} → {target}")
    assert not upward, "upward imports:\n" + "\n".join(upward)


def test_no_private_names_across_modules():
    private = []
    for path, module, target, names, line in own_imports():
        if target == module:
            continue
        bad = [n for n in names if n.startswith("_") and not n.startswith("__")]
        if bad:
            private.append(f"{path.relative_to(PACKAGE.parent)}:{line} {target}: {', '.join(bad)}")
    assert not private, "private names imported from another module:\n" + "\n".join(private)


def _resolve(target: str, names: list[str], modules: set[str]) -> list[str]:
    """The modules an import statement loads: ``from assistant.x import y`` is the module
    ``assistant.x.y`` when that is a module, else ``assistant.x``."""
    out = []
    for name in names or [""]:
        candidate = f"{target}.{name}" if name else target
        if candidate in modules:
            out.append(candidate)
        elif target in modules:
            out.append(target)
    return out


def test_no_import_cycles_between_modules():
    modules = {module_name(p) for p in source_files()}
    graph = nx.DiGraph()
    for path, module, target, names, _ in own_imports():
        for dep in _resolve(target, names, modules):
            is_package_init = path.name == "__init__.py"
            # a package's __init__ re-exporting its own modules is not a cycle of logic
            if dep != module and not (is_package_init and dep.startswith(module + ".")):
                if not dep.startswith(module + ".") and not module.startswith(dep + "."):
                    graph.add_edge(module, dep)
    cycles = [sorted(c) for c in nx.strongly_connected_components(graph) if len(c) > 1]
    assert not cycles, "import cycles:\n" + "\n".join(" ↔ ".join(c) for c in cycles)


@pytest.mark.parametrize("path", source_files(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_process_state_set_on_import(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in tree.body:  # module level only
        for sub in ast.walk(node) if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef,
                                                             ast.ClassDef)) else ():
            text = ast.unparse(sub) if isinstance(sub, (ast.Assign, ast.Call)) else ""
            assert "os.environ[" not in text.split("=")[0] and "environ.setdefault" not in text, (
                f"{path.name}:{sub.lineno} sets the environment at import; do it at start-up "
                "(assistant.runtime)")

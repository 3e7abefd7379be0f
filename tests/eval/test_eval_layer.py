"""The evaluations' place in the layers: ``assistant.eval`` is called only by the command line,
and no domain package reaches up into the command line (read from the syntax trees)."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "assistant"


def _imports(path: Path) -> set[str]:
    """Every module a file imports, at any depth (function-level imports included)."""
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module)
            out.update(f"{node.module}.{alias.name}" for alias in node.names)
    return out


def _modules(*exclude: str):
    for path in sorted(PACKAGE.rglob("*.py")):
        part = path.relative_to(PACKAGE).parts[0]
        if part not in exclude and path.name != "__main__.py":
            yield path


def _reaching(target: str, *exclude: str) -> list[str]:
    return sorted(f"{p.relative_to(PACKAGE)} imports {name}" for p in _modules(*exclude)
                  for name in _imports(p) if name == target or name.startswith(target + "."))


def test_no_domain_package_imports_the_command_line():
    assert _reaching("assistant.cli", "cli") == []


def test_only_the_command_line_imports_the_evaluations():
    assert _reaching("assistant.eval", "cli", "eval") == []


def test_the_finder_sees_a_function_level_import(tmp_path):
    module = tmp_path / "m.py"
    module.write_text("def f():\n    from assistant.cli.common import emit_json\n", encoding="utf-8")
    assert "assistant.cli.common" in _imports(module)

"""The perception front half as it was before the speed work, read from the git history.

``benchmarks/bench_perception.py`` times it against the current code in the same run, and
``tests/perception/test_frame_reference.py`` checks that the current code gives the same floor,
samples and features on fixed frames. Nothing in ``assistant`` imports it.

:func:`load` writes the modules ``cloud``, ``samples``, ``features`` and ``frame`` of
``assistant/perception`` at :data:`REFERENCE_COMMIT` (``git show``) into a temporary package,
with their imports of each other made relative, and imports them. A checkout without that
commit (a shallow clone, an exported tree) raises :class:`ReferenceUnavailable`, which says so.
"""

from __future__ import annotations

import importlib
import subprocess
import sys
import tempfile
import types
from pathlib import Path

#: the last commit before the perception speed work
REFERENCE_COMMIT = "83aed71"
#: the code when issue 20 was filed (18 ms median, 23 ms p90 on the real frames, quiet machine)
FILED_COMMIT = "9b840b7"
MODULES = ("cloud", "samples", "features", "frame")
PACKAGE = "perception_at_reference_commit"
REPO = Path(__file__).resolve().parents[1]

_loaded: dict[str, types.SimpleNamespace] = {}


class ReferenceUnavailable(RuntimeError):
    """The reference commit cannot be read from this checkout."""


def _source(module: str, commit: str) -> str:
    path = f"assistant/perception/{module}.py"
    try:
        out = subprocess.run(["git", "show", f"{commit}:{path}"], cwd=REPO, check=True,
                             capture_output=True, text=True)
    except (OSError, subprocess.CalledProcessError) as exc:
        raise ReferenceUnavailable(
            f"cannot read {path} at commit {commit} (a shallow clone or no git?): "
            f"fetch the full history with `git fetch --unshallow` to compare with it") from exc
    text = out.stdout
    for other in MODULES:  # the reference modules import each other, not the current code
        text = text.replace(f"from assistant.perception.{other} import", f"from .{other} import")
    return text


def load(commit: str = REFERENCE_COMMIT) -> types.SimpleNamespace:
    """The modules (``.cloud``, ``.samples``, ``.features``, ``.frame``) at ``commit``, imported
    once per commit."""
    if commit in _loaded:
        return _loaded[commit]
    root = Path(tempfile.mkdtemp(prefix="perception-reference-"))
    name = f"{PACKAGE}_{commit}"
    package = root / name
    package.mkdir()
    (package / "__init__.py").write_text(f'"""assistant/perception at {commit}."""\n')
    for module in MODULES:
        (package / f"{module}.py").write_text(_source(module, commit))
    sys.path.insert(0, str(root))
    try:
        _loaded[commit] = types.SimpleNamespace(**{m: importlib.import_module(f"{name}.{m}") for m in MODULES})
    finally:
        sys.path.remove(str(root))
    return _loaded[commit]

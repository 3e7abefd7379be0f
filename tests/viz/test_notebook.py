"""The example notebook is valid nbformat and its code runs from top to bottom."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

NOTEBOOK = Path(__file__).resolve().parents[2] / "notebooks" / "explore_world.ipynb"


def test_explore_world_notebook_runs(tmp_path, monkeypatch):
    nbformat = pytest.importorskip("nbformat")
    import matplotlib

    matplotlib.use("Agg")
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(notebook)
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    namespace: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # plt.show() on the Agg backend
        for index, cell in enumerate(notebook.cells):
            if cell.cell_type == "code":
                exec(compile(cell.source, f"{NOTEBOOK.name}[{index}]", "exec"), namespace)
    view = namespace["view"]
    assert view.server_process.poll() is not None, "the notebook closes its server"
    assert (tmp_path / "apartment_scan.html").stat().st_size > 100_000
    assert len(namespace["points"]) > 10_000
    assert view.has("/meshcat/points/kinect") and view.has("/meshcat/arrows/move-to")

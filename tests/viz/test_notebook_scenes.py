"""Every notebook runs top to bottom in a real Jupyter kernel (fast mode), none is committed with
outputs, and the 3D scenes of explore_world, follow_a_command and ``assistant world --html``
render in headless Chromium with the furniture colours and the robot visible."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from screenshots import (BROWSER, colour_pixels, drawn_share, furniture_colours_seen,  # noqa: E402
                         robot_drawn, screenshot)

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
needs_browser = pytest.mark.skipif(BROWSER is None, reason="no headless Chromium (apt-get install chromium)")


@pytest.fixture(scope="module")
def warm_cache():
    """Train (or load) the models the notebooks use into this test session's cache, here in the
    test process, as `make notebook` does with `assistant warm-up`, through the application layer: a kernel inherits
    ASSISTANT_CACHE and then only loads them (training inside a kernel outlasts a cell's
    timeout on a loaded machine)."""
    from assistant.app import Fetcher, Finder
    from assistant.world import load_world

    world, fetcher = load_world("apartment"), Fetcher()
    fetcher.parser(world)
    assert fetcher.policies.models and fetcher.detector is not None
    assert Finder().describer is not None


def execute(name: str, tmp_path: Path):
    """Run notebook ``name`` in a fresh kernel from notebooks/ with ASSISTANT_NOTEBOOK_FAST=1;
    files the notebook writes to the temporary folder land in ``tmp_path``."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    notebook = nbformat.read(ROOT / "notebooks" / name, as_version=4)
    env = {"ASSISTANT_NOTEBOOK_FAST": "1", "TMPDIR": str(tmp_path), "MPLBACKEND": "Agg",
           "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)  # the kernel inherits this process's environment
    try:
        nbclient.NotebookClient(notebook, timeout=240, kernel_name="python3",
                                resources={"metadata": {"path": str(ROOT / "notebooks")}}).execute()
    finally:
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
    return notebook


def stdout_of(notebook) -> str:
    return "".join(o.get("text", "") for c in notebook.cells if c.cell_type == "code"
                   for o in c.get("outputs", []) if o.get("name") == "stdout")


def test_notebooks_are_committed_without_outputs():
    assert NOTEBOOKS, "no notebooks found"
    nbformat = pytest.importorskip("nbformat")
    for path in NOTEBOOKS:
        notebook = nbformat.read(path, as_version=4)
        nbformat.validate(notebook)
        for cell in notebook.cells:
            if cell.cell_type == "code":
                assert not cell.outputs and cell.execution_count is None, f"{path.name} has outputs: clear them"


@pytest.mark.slow
@pytest.mark.parametrize("name", [p.name for p in NOTEBOOKS if p.name not in
                                  ("explore_world.ipynb", "follow_a_command.ipynb", "explore_scans.ipynb")])
@pytest.mark.timeout(900)
def test_notebook_runs(name, tmp_path, warm_cache):
    out = stdout_of(execute(name, tmp_path))
    assert "Traceback" not in out
    for words in SAYS.get(name, ()):
        assert words in out, f"{name} does not print {words!r}"


#: what a notebook must print (its parts ran to the end)
SAYS = {"where_is.ipynb": ("the listener ", "followed:"),
        "results.ipynb": ("sensed ", "oracle ", "median ", "Table 3-6 all:", "mean d ")}


@pytest.mark.slow
@needs_browser
@pytest.mark.timeout(900)
def test_follow_a_command_runs_and_its_scene_renders(tmp_path, warm_cache):
    from assistant.world import load_world

    out = stdout_of(execute("follow_a_command.ipynb", tmp_path))
    assert "plan:" in out and "move-to nodes" in out
    image = screenshot(tmp_path / "follow_a_command.html", tmp_path / "shot.png", tmp_path / "profile")
    assert drawn_share(image) > 0.15, "the scene covers a good part of the view"
    assert len(furniture_colours_seen(image, load_world("apartment"))) >= 2, "furniture colours visible"
    assert robot_drawn(image), "the robot is drawn"


@pytest.mark.slow
@needs_browser
@pytest.mark.timeout(900)
def test_explore_world_runs_and_its_scene_renders(tmp_path, warm_cache):
    from assistant.world import load_world

    execute("explore_world.ipynb", tmp_path)
    image = screenshot(tmp_path / "apartment_scan.html", tmp_path / "shot.png", tmp_path / "profile")
    assert drawn_share(image) > 0.15
    assert len(furniture_colours_seen(image, load_world("apartment"))) >= 2
    assert robot_drawn(image)


@pytest.mark.slow
@needs_browser
@pytest.mark.timeout(900)
def test_explore_scans_opens_a_real_frame_and_draws_the_floor_and_furniture(tmp_path, warm_cache, shared_dir):
    """The scan explorer, choosing a real frame from ../shared/realdata as a person would, prints
    the floor and what was found, and its 3D page shows the floor plane and the furniture boxes
    in their category colours."""
    from assistant.viz import CATEGORY_COLOURS
    from assistant.viz.detections import FLOOR_COLOUR
    from tests.viz.conftest import page_commands

    out = stdout_of(execute("explore_scans.ipynb", tmp_path))
    assert "real sunrgbd_kv2_mmdet3d/000001_depth.png" in out and "floor: camera" in out
    found = [line.split()[0] + (" table" if line.split()[1] == "table" else "")
             for line in out.splitlines() if line.startswith("  ") and " at (" in line and "unknown" not in line]
    page = tmp_path / "explore_scans.html"
    drawn = {c.get("path", "") for c in page_commands(page.read_text())}
    assert "/meshcat/scan/scan/floor/box" in drawn
    assert sum(p.startswith("/meshcat/scan/scan/furniture/") and p.endswith("/box") for p in drawn) == len(found)
    image = screenshot(page, tmp_path / "shot.png", tmp_path / "profile")
    assert drawn_share(image) > 0.15
    assert colour_pixels(image, FLOOR_COLOUR) > 300, "the floor plane is seen"
    for category in found:
        assert colour_pixels(image, CATEGORY_COLOURS[category]) > 100, f"the {category}'s box is seen"


@needs_browser
def test_world_html_renders_with_furniture_and_robot(tmp_path):
    from assistant.cli import main
    from assistant.world import load_world

    page = tmp_path / "apartment.html"
    assert main(["world", "apartment", "--html", str(page)]) == 0
    image = screenshot(page, tmp_path / "shot.png", tmp_path / "profile")
    assert drawn_share(image) > 0.15
    assert len(furniture_colours_seen(image, load_world("apartment"))) >= 2
    assert robot_drawn(image)


@needs_browser
def test_the_checks_fail_on_a_scene_without_furniture_or_robot(tmp_path):
    """The same home with its furniture and robot removed fails the colour checks: they see
    what was drawn, not the floors or the sky."""
    from assistant.viz import SceneView
    from assistant.world import load_world

    world = load_world("apartment")
    view = SceneView(open_server=False)
    view.draw_world(world, "original")
    view.visualizer["world"]["furniture"].delete()
    view.clear("robot")
    image = screenshot(view.save_html(tmp_path / "bare.html"), tmp_path / "shot.png", tmp_path / "profile")
    assert drawn_share(image) > 0.15, "the floors and walls are still drawn"
    assert furniture_colours_seen(image, world) == []
    assert not robot_drawn(image)

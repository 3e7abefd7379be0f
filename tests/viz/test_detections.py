"""draw_detection_result: the floor plane, the furniture boxes and their labels drawn where the
detector's result says, in the detections' frame."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.perception.detector import Detection, DetectionResult, UnknownItem
from assistant.perception.frame import analyse_frame
from assistant.viz import SceneView, draw_detection_result
from assistant.viz.detections import detection_box, drawing_matrix, floor_polygon

from tests.viz.conftest import page_commands


def _cells(cx, cy, length, width, angle):
    """0.05 m cell centres covering a length × width rectangle turned by ``angle``."""
    u, v = np.meshgrid(np.arange(-length / 2 + 0.025, length / 2, 0.05), np.arange(-width / 2 + 0.025, width / 2, 0.05))
    local = np.column_stack([u.ravel(), v.ravel()])
    c, s = math.cos(angle), math.sin(angle)
    return local @ np.array([[c, s], [-s, c]]) + [cx, cy]


def _detection(category="couch", x=2.0, y=0.5, facing=0.5, length=2.0, width=0.9, height=0.8):
    cells = _cells(x, y, length, width, facing if facing is not None else 0.0)
    return Detection(category, category, x, y, facing, 0.83, cells, height, False, "world")


def test_a_box_is_the_footprint_turned_to_the_heading():
    box = detection_box(_detection(facing=0.5))
    sides = sorted(np.linalg.norm(box - np.roll(box, 1, axis=0), axis=1))
    assert sides == pytest.approx([0.9, 0.9, 2.0, 2.0], abs=0.06)
    edge = box[0] - box[1]  # rectangle(): the first edge runs along the heading
    assert abs(math.sin(math.atan2(edge[1], edge[0]) - 0.5)) < 0.02
    assert np.mean(box, axis=0) == pytest.approx([2.0, 0.5], abs=0.03)


def test_a_table_without_heading_gets_its_longer_axis():
    d = Detection("large table", "desk", 1.0, 1.0, None, 0.9, _cells(1.0, 1.0, 1.6, 0.8, 1.2), 0.75, False, "world")
    box = detection_box(d)
    long_edge = max((box[i] - box[i - 1] for i in range(4)), key=np.linalg.norm)
    assert abs(math.sin(math.atan2(long_edge[1], long_edge[0]) - 1.2)) < 0.05


def test_floor_polygon_covers_the_points_on_the_floor_only():
    rng = np.random.default_rng(0)
    floor = np.column_stack([rng.uniform(0, 3, 500), rng.uniform(-1, 1, 500), rng.normal(0, 0.005, 500)])
    wall = np.column_stack([np.full(300, 4.0), rng.uniform(-2, 2, 300), rng.uniform(0.1, 2, 300)])
    polygon = floor_polygon(np.vstack([floor, wall]))
    assert polygon[:, 0].min() >= 0 and polygon[:, 0].max() <= 3.0 and polygon[:, 0].max() > 2.8
    assert floor_polygon(wall) is None


@pytest.fixture(scope="module")
def sim_frame(apartment):
    from assistant.sim.renderer import DepthRenderer

    return DepthRenderer(apartment).render(Pose2D(apartment.start.x, apartment.start.y, apartment.start.theta))


def test_drawn_in_the_detections_frame_with_floor_boxes_and_labels(sim_frame):
    analysis = analyse_frame(sim_frame)
    assert analysis.floor is not None
    pose = sim_frame.robot_pose
    x, y = pose.transform_points(np.array([[2.0, 0.3]]))[0]
    couch = _detection(x=float(x), y=float(y), facing=pose.theta)
    thing = UnknownItem("other", 0.5, float(x) + 0.5, float(y), 1.5, 40, "other")
    result = DetectionResult([couch], analysis, None, {}, [thing])
    view = SceneView(open_server=False)
    drawn = draw_detection_result(view, sim_frame, result)
    # the cloud is in the world frame: the floor points lie at z ≈ 0 around the robot
    matrix = drawing_matrix(sim_frame, analysis.floor)
    assert matrix[:2, 3] == pytest.approx(pose.transform_points(analysis.floor.camera_to_floor[:2, 3][None])[0])
    assert np.median(np.abs(drawn["points"][drawn["points"][:, 2] < 0.05, 2])) < 0.02
    polygon = drawn["floor_polygon"]
    assert polygon is not None and np.linalg.norm(polygon.mean(axis=0) - [pose.x, pose.y]) < 5.0
    assert len(drawn["boxes"]) == 1 and np.mean(drawn["boxes"][0], axis=0) == pytest.approx([x, y], abs=0.05)
    paths = view.object_paths()
    for part in ("floor/box", "floor/label", "furniture/0/box", "furniture/0/heading", "furniture/0/label",
                 "unknown/0/body", "camera"):
        assert f"/meshcat/scan/scan/{part}" in paths, part
    commands = page_commands(view.static_html())
    labels = [c for c in commands if c.get("path", "").endswith("furniture/0/label") and c["type"] == "set_transform"]
    assert labels and labels[-1]["matrix"][14] == pytest.approx(0.8 + 0.05, abs=1e-3)  # on the box's top


def test_a_frame_without_floor_is_a_plain_cloud(sim_frame):
    analysis = analyse_frame(sim_frame)
    analysis.floor = None
    view = SceneView(open_server=False)
    drawn = draw_detection_result(view, sim_frame, DetectionResult([], analysis, "no floor visible"))
    assert drawn["floor_polygon"] is None and len(drawn["points"]) > 1000
    assert not any(p.startswith("/meshcat/scan/scan/floor") for p in view.object_paths())


@pytest.mark.skipif(__import__("shutil").which("chromium") is None, reason="no headless Chromium")
def test_the_floor_and_a_box_are_seen_in_the_browser(sim_frame, tmp_path):
    """The page with the floor plane and a bed's box shows their colours; the same page with
    the scan's drawings deleted (the cloud kept) does not."""
    from assistant.viz import CATEGORY_COLOURS
    from assistant.viz.detections import FLOOR_COLOUR
    from tests.viz.screenshots import colour_pixels, screenshot

    analysis = analyse_frame(sim_frame)
    pose = sim_frame.robot_pose
    x, y = pose.transform_points(np.array([[2.2, 0.0]]))[0]
    bed = _detection("bed", float(x), float(y), pose.theta, 2.0, 1.4, 0.6)
    view = SceneView(open_server=False)
    draw_detection_result(view, sim_frame, DetectionResult([bed], analysis, None), stride=4)
    shot = screenshot(view.save_html(tmp_path / "scan.html"), tmp_path / "a.png", tmp_path / "profile")
    view.visualizer["scan"].delete()
    bare = screenshot(view.save_html(tmp_path / "bare.html"), tmp_path / "b.png", tmp_path / "profile")
    for colour in (FLOOR_COLOUR, CATEGORY_COLOURS["bed"]):
        assert colour_pixels(shot, colour) > 300, colour
        assert colour_pixels(bare, colour) < 0.2 * colour_pixels(shot, colour), colour

"""SceneView drawing and HTML export, without a server (the recorded scene is the same)."""

from __future__ import annotations

import numpy as np
import pytest

from assistant.errors import AssistantError, UnknownNameError
from assistant.geometry import Pose2D
from assistant.viz import SceneView, external_urls, path_name
from tests.viz.conftest import page_commands


def test_drawing_the_apartment_creates_every_entity(drawn_apartment, apartment):
    paths = set(drawn_apartment.object_paths())
    scene = apartment.scene("original")
    expected = (
        {f"/meshcat/world/floors/{path_name(r.name)}" for r in apartment.floorplan.rooms}
        | {f"/meshcat/world/labels/{path_name(r.name)}" for r in apartment.floorplan.rooms}
        | {f"/meshcat/world/walls/wall_{i}" for i in range(len(apartment.floorplan.walls))}
        | {f"/meshcat/world/furniture/{f.id}" for f in scene.furniture}
        | {f"/meshcat/world/objects/{path_name(o.name)}" for o in scene.objects}
        | {f"/meshcat/robots/robot/{part}" for part in ("body", "heading", "mast", "camera")}
        | {"/meshcat/world/ground", "/meshcat/world/origin"}
    )
    assert paths == expected
    assert "/meshcat/world/floors/living_room" in paths
    assert "/meshcat/world/objects/glasses_case" in paths


def test_room_floors_have_distinct_colours(drawn_apartment, apartment):
    page = drawn_apartment.static_html()
    colours = {c["path"]: c["object"]["materials"][0]["color"] for c in page_commands(page)
               if c["type"] == "set_object" and c["path"].startswith("/meshcat/world/floors/")}
    assert len(colours) == len(apartment.floorplan.rooms)
    assert len(set(colours.values())) == len(colours)


def test_robot_sits_at_the_start_pose_facing_its_heading(drawn_apartment, apartment):
    page = drawn_apartment.static_html()
    transforms = {c["path"]: np.array(c["matrix"]).reshape(4, 4).T for c in page_commands(page)
                  if c["type"] == "set_transform"}
    robot = transforms["/meshcat/robots/robot"]
    assert robot[:2, 3] == pytest.approx([apartment.start.x, apartment.start.y])
    heading = np.arctan2(robot[1, 0], robot[0, 0])
    assert np.cos(heading - apartment.start.theta) == pytest.approx(1.0)


def test_html_is_self_contained_and_holds_the_whole_scene(drawn_apartment, tmp_path):
    written = drawn_apartment.save_html(tmp_path / "out" / "apartment.html")
    page = written.read_text(encoding="utf-8")
    assert external_urls(page) == []
    assert "<script src" not in page and "<link" not in page
    assert "MeshCat.Viewer" in page and "<title>apartment (original scene)</title>" in page
    drawn = {c["path"] for c in page_commands(page) if c["type"] == "set_object"}
    assert drawn == set(drawn_apartment.object_paths())
    assert not list(tmp_path.joinpath("out").glob(".*.tmp")), "atomic write leaves no temp file"


def test_external_urls_finds_a_cdn_reference():
    assert external_urls('<script src="https://cdn.example.org/three.js"></script>') == [
        "https://cdn.example.org/three.js"]
    assert external_urls('createElementNS("http://www.w3.org/1999/xhtml", "canvas")') == []


def test_drawing_again_replaces_the_world(apartment):
    view = SceneView(open_server=False)
    view.draw_world(apartment, "original")
    view.draw_world(apartment, "modified")
    modified = apartment.scene("modified")
    furniture = {p.rsplit("/", 1)[1] for p in view.object_paths() if "/world/furniture/" in p}
    assert furniture == {f.id for f in modified.furniture}
    assert view.title == "apartment (modified scene)"


def test_world_drawn_from_stand_in_meshes(apartment):
    """draw_world takes any list of world-frame meshes (here two boxes) instead of the sim's."""
    o3d = pytest.importorskip("open3d")
    from types import SimpleNamespace

    box = o3d.geometry.TriangleMesh.create_box(1.0, 1.0, 1.0)
    meshes = [SimpleNamespace(id="table_9", kind="furniture", name="box", mesh=box),
              SimpleNamespace(id="wall_0", kind="wall", name="wall", mesh=box)]
    view = SceneView(open_server=False)
    view.draw_world(apartment, "original", meshes=meshes, robot_pose=False)
    assert {p for p in view.object_paths() if "floors" not in p and "labels" not in p} == {
        "/meshcat/world/furniture/table_9", "/meshcat/world/walls/wall_0", "/meshcat/world/origin"}
    view.highlight("table_9", "red")
    assert view.has("/meshcat/highlights/table_9/box")
    bad = [SimpleNamespace(id="x", kind="ceiling", name="x", mesh=box)]
    with pytest.raises(AssistantError, match="ceiling"):
        view.draw_world(apartment, "original", meshes=bad)


def test_points_paths_arrows_and_clear(apartment):
    view = SceneView(open_server=False)
    rng = np.random.default_rng(0)
    cloud = rng.uniform(-1, 1, size=(500, 3))
    cloud[3] = np.nan
    view.draw_points("scan", cloud, colors=(rng.uniform(size=(500, 3)) * 255).astype(np.uint8))
    view.draw_points("few", cloud[:10], colors="red", max_points=4)
    view.draw_path("route", [(0, 0), (1, 0), (1, 2)], color="#00aa00")
    view.draw_arrows("move-to", [(0, 0, 0), (1, 0, 1.0), (2, 0, 2.0)], [0.0, 2.0, 4.0])
    paths = set(view.object_paths())
    assert {"/meshcat/points/scan", "/meshcat/points/few", "/meshcat/paths/route/line",
            "/meshcat/paths/route/ribbon", "/meshcat/arrows/move-to"} <= paths

    objects = {c["path"]: c["object"] for c in page_commands(view.static_html())
               if c["type"] == "set_object"}
    scan = objects["/meshcat/points/scan"]["geometries"][0]["data"]["attributes"]
    assert scan["position"]["itemSize"] == 3
    assert len(scan["position"]["array"].data) == 499 * 3 * 4  # the NaN point is dropped (float32)
    few = objects["/meshcat/points/few"]["geometries"][0]["data"]["attributes"]
    assert len(few["position"]["array"].data) == 4 * 3 * 4

    colours = np.frombuffer(objects["/meshcat/arrows/move-to"]["geometries"][0]["data"]
                            ["attributes"]["color"]["array"].data, dtype=np.float32).reshape(-1, 3)
    vertices = np.frombuffer(objects["/meshcat/arrows/move-to"]["geometries"][0]["data"]
                             ["attributes"]["position"]["array"].data, dtype=np.float32).reshape(-1, 3)
    tips = vertices[5::7]
    lengths = np.linalg.norm(tips[:, :2] - np.array([[0, 0], [1, 0], [2, 0]]), axis=1)
    assert lengths[0] < lengths[1] < lengths[2]  # longer with the score
    assert colours[0, 0] > colours[0, 1] and colours[14, 1] > colours[14, 0]  # red → green

    view.clear("scan")
    assert not view.has("/meshcat/points/scan") and view.has("/meshcat/points/few")
    with pytest.raises(UnknownNameError, match="scan"):
        view.clear("scan")
    view.clear()
    assert view.object_paths() == []


def test_bad_drawing_input_gets_a_clear_error():
    view = SceneView(open_server=False)
    with pytest.raises(AssistantError, match=r"\(N, 3\)"):
        view.draw_points("p", np.zeros((4, 2)))
    with pytest.raises(AssistantError, match="one .* per point"):
        view.draw_points("p", np.zeros((4, 3)), colors=np.zeros((3, 3)))
    with pytest.raises(AssistantError, match="0–1"):
        view.draw_points("p", np.zeros((2, 3)), colors=np.full((2, 3), 7.5))
    with pytest.raises(AssistantError, match="N ≥ 2"):
        view.draw_path("p", [(0, 0)])
    with pytest.raises(AssistantError, match="one score per pose"):
        view.draw_arrows("a", [(0, 0, 0)], [1.0, 2.0])


def test_highlights_of_furniture_objects_rooms_and_entities(apartment):
    from assistant.world import floorplan_entities, world_grid

    view = SceneView(open_server=False)
    view.draw_world(apartment, "original")
    view.highlight("couch_1")
    view.highlight("mug", "red")
    view.highlight("bedroom", "blue")
    grid = world_grid(apartment, 0.1)
    entity = next(e for e in floorplan_entities(apartment, grid) if e.name == "room")
    view.highlight(entity, "magenta", name="room entity")
    for key in ("couch_1", "mug", "bedroom"):
        assert view.has(f"/meshcat/highlights/{key}/box")
        assert view.has(f"/meshcat/highlights/{key}/outline")
    assert view.has("/meshcat/highlights/room_entity/footprint")
    with pytest.raises(UnknownNameError, match="couch_1"):  # the error lists what is known
        view.highlight("sofa_7")


def test_moving_the_robot_sends_only_a_transform():
    view = SceneView(open_server=False)
    view.draw_robot((0.0, 0.0, 0.0))
    before = len(page_commands(view.static_html()))
    view.draw_robot((1.0, 2.0, 1.5))
    after = page_commands(view.static_html())
    assert len(after) == before
    robot = [c for c in after if c["type"] == "set_transform" and c["path"] == "/meshcat/robots/robot"]
    assert np.array(robot[0]["matrix"])[12:14] == pytest.approx([1.0, 2.0])


def test_a_view_without_server_has_no_url():
    view = SceneView(open_server=False)
    assert view.url is None and view.server_process is None
    with pytest.raises(AssistantError, match="no server"):
        view.jupyter_cell()
    view.wait(timeout_s=0.01)
    view.close()
    view.close()


def test_depth_frame_points_land_in_the_world_where_the_camera_looks():
    """A level camera 2 m from a wall: every point is 2 m ahead of the robot, around 1.05 m
    high; with hit ids the points take the colour of what was hit."""
    from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame

    intr = CameraIntrinsics(64, 48, 50.0, 50.0, 31.5, 23.5)
    depth = np.full((48, 64), 2.0, dtype=np.float32)
    depth[:, :8] = 0.0  # missing readings are skipped
    hits = np.zeros((48, 64), dtype=np.int32)
    hits[:, 32:] = 1
    frame = DepthFrame(depth, intr, CameraMount(height_m=1.05, tilt_rad=0.0),
                       robot_pose=Pose2D(1.0, 2.0, np.pi / 2), hit_ids=hits,
                       hit_names=("wall_0", "couch_1"))
    view = SceneView(open_server=False)
    points = view.draw_depth_frame("kinect", frame, stride=1, colour_by="hit")
    assert len(points) == 48 * 56
    assert np.allclose(points[:, 1], 4.0)  # facing +y: 2 m ahead of y = 2
    assert points[:, 2].min() > 0.05 and points[:, 2].max() < 2.05
    assert abs(points[:, 2].mean() - 1.05) < 0.05
    cloud = next(c["object"] for c in page_commands(view.static_html())
                 if c["type"] == "set_object" and c["path"] == "/meshcat/points/kinect")
    colours = np.frombuffer(cloud["geometries"][0]["data"]["attributes"]["color"]["array"].data,
                            dtype=np.float32).reshape(-1, 3)
    assert len(np.unique(colours.round(3), axis=0)) == 2  # wall colour and furniture colour
    with pytest.raises(AssistantError, match="colour_by"):
        view.draw_depth_frame("kinect", frame, colour_by="temperature")
    recorded = DepthFrame(depth, intr, robot_pose=None)  # e.g. a PNG from disk: no hits, no pose
    with pytest.raises(AssistantError, match="simulated frame"):
        view.draw_depth_frame("disk", recorded, colour_by="hit")
    floor_frame = view.draw_depth_frame("disk", recorded, stride=4)
    tilt = CameraMount().tilt_rad  # 15° down, 1.05 m up, base under the camera at the origin
    assert floor_frame[:, 0].mean() == pytest.approx(2.0 * np.cos(tilt), abs=0.05)
    assert floor_frame[:, 2].mean() == pytest.approx(1.05 - 2.0 * np.sin(tilt), abs=0.1)


def test_labels_carry_their_text_as_an_embedded_image():
    view = SceneView(open_server=False)
    view.draw_label("note", "start here", (1.0, 2.0), height_m=0.5, max_width_m=1.0)
    command = next(c for c in page_commands(view.static_html()) if c["type"] == "set_object")
    assert command["path"] == "/meshcat/labels/note"
    box = command["object"]["geometries"][0]
    assert box["width"] <= 1.0 + 1e-9 and box["height"] < 0.5  # shrunk to the width limit
    image_url = command["object"]["images"][0]["url"]
    assert image_url.startswith("data:image/png;base64,")
    view.clear("note")
    assert view.object_paths() == []

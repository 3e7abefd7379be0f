"""The training home (dissertation Fig. 5.14a): sound, ours, and with an instance of every RDT
node of Table 5-1 in both its original and its modified (changed-from-training) layout."""

import math

import numpy as np
import pytest

from assistant.executor import build_occupancy, room_entry_waypoints
from assistant.world import check_world, furniture_entities, load_world, world_grid, world_names

SCENES = ["original", "modified"]


@pytest.fixture(scope="module")
def home():
    return load_world("training-home")


def local(item_or_pose, point, facing=None):
    """``point`` in the frame of something facing ``facing`` (x ahead, y to its left)."""
    theta = facing if facing is not None else item_or_pose.facing_rad
    dx, dy = point[0] - item_or_pose.x, point[1] - item_or_pose.y
    c, s = math.cos(theta), math.sin(theta)
    return c * dx + s * dy, -s * dx + c * dy


def test_the_training_home_is_sound_and_not_a_study_home(home, all_worlds):
    assert "training-home" in world_names()
    assert check_world(home) == []
    assert set(home.scenes) == set(SCENES)
    assert set(home.floorplan.room_names) == {"living room", "hallway", "bedroom"}
    for room in ("living room", "bedroom"):
        xs, ys = home.floorplan.room(room).polygon_array.T
        assert 4.0 <= xs.max() - xs.min() <= 6.0 and 4.0 <= ys.max() - ys.min() <= 6.0
    for name, other in all_worlds.items():
        if name != "training-home":
            assert other.floorplan != home.floorplan
    assert home.floorplan.room("hallway").contains(home.start.x, home.start.y)


def test_every_furniture_category_and_several_table_models(home):
    for scene in SCENES:
        furniture = home.scene(scene).furniture
        assert {f.category for f in furniture} >= {"couch", "bed", "chair", "small table", "large table"}
        assert len({f.model for f in furniture if "table" in f.category}) >= 4
        assert {o.on for o in home.scene(scene).objects} <= {f.id for f in furniture}


@pytest.mark.parametrize("scene", SCENES)
def test_couch_and_bed_relations(home, scene):
    sc = home.scene(scene)
    couch, bed = sc.item("couch_1"), sc.item("bed_1")
    ahead, left = local(couch, (sc.item("coffeetable_1").x, sc.item("coffeetable_1").y))
    assert 0.6 < ahead < 1.6 and abs(left) < 0.5  # couch-front-table
    ahead, left = local(couch, (sc.item("roundtable_1").x, sc.item("roundtable_1").y))
    assert left > 1.0 and abs(ahead) < 0.5  # couch-left-table
    ahead, left = local(couch, (sc.item("roundtable_2").x, sc.item("roundtable_2").y))
    assert left < -1.0 and abs(ahead) < 0.5  # couch-right-table
    for table, side in (("roundtable_3", 1), ("coffeetable_2", -1)):  # bed-left / bed-right
        ahead, left = local(bed, (sc.item(table).x, sc.item(table).y))
        assert side * left > 0.8 and ahead < -0.3  # beside the head of the bed


@pytest.mark.parametrize("scene", SCENES)
def test_chairs_beside_tables(home, scene):
    sc = home.scene(scene)
    for chair, table in (("bluechair_1", "dinnertable_1"), ("bluechair_2", "dinnertable_1"),
                         ("woodchair_1", "desk_1")):
        c, t = sc.item(chair), sc.item(table)
        assert math.dist((c.x, c.y), (t.x, t.y)) < 1.1
        ahead, _ = local(c, (t.x, t.y))
        assert ahead > 0.3  # the chair faces its table


@pytest.mark.parametrize("scene", SCENES)
def test_tables_on_the_robots_left_and_right_entering_the_living_room(home, scene):
    sc = home.scene(scene)
    entry = room_entry_waypoints(home, "hallway", "living room")[-1]
    ahead, left = local(entry, (sc.item("hexagontable_1").x, sc.item("hexagontable_1").y), entry.theta)
    assert ahead > 0 and left > 1.5  # robot-left-table
    ahead, left = local(entry, (sc.item("roundtable_1").x, sc.item("roundtable_1").y), entry.theta)
    assert ahead > 0 and left < -0.5  # robot-right-table


@pytest.mark.parametrize("scene", SCENES)
def test_room_centres_and_walls_can_be_reached(home, scene):
    entities = furniture_entities(home, scene, world_grid(home, 0.1))
    occ = build_occupancy(home, entities)
    for room in ("living room", "bedroom"):
        cx, cy = home.floorplan.room(room).centre
        assert occ.is_free(cx, cy), f"room-center-non: the {room}'s centre is not free in {scene}"
    # wall-front-non: entering the living room, the wall ahead can be approached
    entry = room_entry_waypoints(home, "hallway", "living room")[-1]
    assert occ.is_free(0.45, entry.y)


def test_the_modified_scene_moves_furniture(home):
    original = {f.id: f for f in home.scene("original").furniture}
    moved = [f for f in home.scene("modified").furniture
             if (f.x, f.y, f.yaw_rad) != (original[f.id].x, original[f.id].y, original[f.id].yaw_rad)]
    assert len(moved) >= 8
    assert {f.id for f in home.scene("modified").furniture} == set(original)
    assert np.mean([math.dist((f.x, f.y), (original[f.id].x, original[f.id].y)) for f in moved]) < 0.5

"""World state features: entities, pairs, absences, ordering, and the cached builder."""

import math

import numpy as np
import pytest

from assistant.geometry import GridMap, Pose2D, rectangle
from assistant.spatial import WSF, WSFBuilder, dir_srv, dist_srv, srv_slots, world_state_feature
from assistant.world import Entity, EntityKind

GRID = GridMap(0.1, -5.0, -5.0, 100, 100)


def thing(name, x, y, length, width, yaw=0.0, facing=None):
    return Entity.from_polygon(name, name, EntityKind.SHORT_TERM,
                               rectangle(Pose2D(x, y, yaw), length, width), GRID, facing)


COUCH = thing("couch", 0.03, 0.02, 0.8, 2.0, yaw=math.pi / 2, facing=math.pi / 2)
TABLE = thing("table", 0.03, 1.33, 0.7, 0.7)
START = Pose2D(0.05, -2.45, math.pi / 2)  # south of the couch, looking north


def test_all_slots_present_with_a_viewer():
    wsf = world_state_feature(Pose2D(1.55, 1.35, 0.0), START, COUCH, TABLE)
    assert isinstance(wsf, WSF)
    assert not wsf.absent
    assert len(wsf) == len(srv_slots()) == 12 + 12 + 1
    keys = wsf.keys()
    assert len(keys) == len(wsf.as_vector()) == 12 * 8 + 12 * 4 + 1
    assert keys[0] == "dir:CR->OR:front" and keys[-1] == "rot:OR->CR:rotation"
    assert wsf["rot:OR->CR"]["rotation"] == pytest.approx(-math.pi / 2)


def test_front_less_reference_without_viewer_is_absent_not_zero():
    wsf = world_state_feature(Pose2D(1.55, 1.35, 0.0), START, COUCH, TABLE, viewer_heading_rad=None)
    assert set(wsf.absent) == {"dir:tar->CR", "dir:tar->OR", "dir:tar->ref"}
    assert wsf.get("dir", "tar", "CR") is None
    with pytest.raises(KeyError, match="absent"):
        wsf["dir:tar->CR"]
    assert wsf.get("dist", "tar", "CR") is not None
    assert len(wsf.as_vector()) == 9 * 8 + 12 * 4 + 1


def test_missing_target_drops_its_pairs():
    wsf = world_state_feature(Pose2D(1.0, 0.0, 0.0), START, COUCH, None)
    assert all("tar" in name for name in wsf.absent) and len(wsf.absent) == 12
    assert len(wsf) == 6 + 6 + 1


def test_srvs_match_the_pairwise_functions():
    cr = Entity.robot(Pose2D(1.55, 1.35, 0.3), GRID)
    orr = Entity.robot(START, GRID, kind=EntityKind.ORIGINAL_ROBOT)
    wsf = world_state_feature(cr, orr, COUCH, TABLE)
    np.testing.assert_allclose(wsf["dir:ref->tar"].values, dir_srv(COUCH, TABLE).values, atol=1e-12)
    np.testing.assert_allclose(wsf["dir:tar->CR"].values,
                               dir_srv(TABLE, cr, viewer_heading_rad=START.theta).values, atol=1e-12)
    np.testing.assert_allclose(wsf["dir:CR->tar"].values, dir_srv(cr, TABLE).values, atol=1e-12)
    np.testing.assert_allclose(wsf["dir:OR->CR"].values, dir_srv(orr, cr).values, atol=1e-12)
    np.testing.assert_allclose(wsf["dist:CR->ref"].values, dist_srv(cr, COUCH).values, atol=1e-12)
    # the table is in front of the couch
    assert wsf["dir:ref->tar"].strongest()[0] == "front"


def test_robot_overlapping_the_table_fills_the_inner_half():
    wsf = world_state_feature(Pose2D(0.05, 1.35, 0.0), START, COUCH, TABLE)
    d = wsf["dir:tar->CR"]
    assert sum(d.values[4:]) > 0.5
    assert wsf["dist:tar->CR"].strongest()[0] == "superposition"


def test_builder_matches_one_shot_and_pose_entities_match():
    builder = WSFBuilder(START, COUCH, TABLE)
    for pose in (Pose2D(1.55, 1.35, 0.0), Pose2D(-1.45, 2.25, 2.0), Pose2D(0.05, -1.05, -1.0)):
        a = builder.feature(pose)
        b = world_state_feature(pose, START, COUCH, TABLE)
        assert a.allclose(b)
        c = world_state_feature(Entity.robot(pose, GRID), Entity.robot(START, GRID), COUCH, TABLE)
        assert a.keys() == c.keys()
        # cell-centre poses rasterize the same disc as Entity.robot
        assert a.allclose(c, atol=1e-9)


def test_robot_in_front_of_the_couch_scores_front():
    builder = WSFBuilder(START, COUCH, TABLE)
    in_front = builder(Pose2D(0.05, 1.25, 0.0))["dir:ref->CR"]
    behind = builder(Pose2D(0.05, -1.25, 0.0))["dir:ref->CR"]
    assert in_front.strongest()[0] in ("front", "inner-front") and in_front["front"] > 0.5
    assert behind.strongest()[0] == "back"


def test_two_features_compare():
    builder = WSFBuilder(START, COUCH, TABLE)
    a = builder(Pose2D(1.55, 1.35, 0.0))
    assert a.allclose(builder(Pose2D(1.55, 1.35, 0.0)))
    assert not a.allclose(builder(Pose2D(1.55, 1.35, 1.0)))  # rotation and the robot's frame differ
    assert not a.allclose(builder(Pose2D(-1.45, 1.35, 0.0)))


def test_pose_only_robots_need_a_grid():
    with pytest.raises(ValueError, match="grid"):
        WSFBuilder(START, None, None)
    wsf = WSFBuilder(START, None, None, grid=GRID)(Pose2D(1.0, 0.0, 0.0))
    assert [s.name for s in wsf] == ["dir:CR->OR", "dir:OR->CR", "dist:CR->OR", "dist:OR->CR", "rot:OR->CR"]

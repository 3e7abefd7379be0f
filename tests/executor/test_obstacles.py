import math

import numpy as np
import pytest

from assistant.executor import DepthObstacles, FloorplanLocalizer, Navigator, build_occupancy
from assistant.geometry import Pose2D
from assistant.world import load_world

sim = pytest.importorskip("assistant.sim")


def test_a_frame_marks_the_furniture_in_view_and_not_the_floor(apartment):
    pose = Pose2D(6.5, 3.0, math.pi)  # in the living room, looking west at the couch's end
    with sim.SimRobot(apartment, start=pose) as robot:
        frame = robot.depth_frame()
    obstacles = DepthObstacles(apartment)
    added = obstacles.add_frame(frame, pose)
    mask = obstacles.mask()
    assert added == mask.sum() > 20
    # ground truth, for the test only: the couch's footprint holds obstacle cells
    couch = apartment.scene("original").item("couch_1")
    footprint = obstacles.grid.rasterize_polygon(couch.footprint_polygon())
    assert (mask & footprint).sum() >= 5
    # the free floor between the robot and the couch stays free
    between = obstacles.grid.world_to_cell(np.array([[6.0, 3.0], [5.9, 2.9], [5.8, 3.1]]))
    assert not mask[between[:, 0], between[:, 1]].any()
    assert obstacles.entity().name == "obstacle"
    occ = obstacles.occupancy()
    assert occ is obstacles.occupancy()  # cached until something new is seen
    assert not occ.is_free(couch.x + 0.9, couch.y)


def test_depth_obstacles_keep_the_robot_off_unknown_furniture():
    world = load_world("training-home")
    start, goal = Pose2D(1.0, 3.2, 0.0), (9.5, 1.2)  # the coffee table stands 0.8 m ahead
    plain = build_occupancy(world, [])  # the floor plan alone: furniture unknown
    with sim.SimRobot(world, start=start) as robot:
        result = Navigator(world, lambda: plain, localizer=FloorplanLocalizer(world)).go_to(robot, goal)
    assert result.status.value == "collision" and result.details.get("bumped")
    with sim.SimRobot(world, start=start) as robot:
        obstacles = DepthObstacles(world)
        localizer = FloorplanLocalizer(world, listeners=[obstacles.add_frame])
        result = Navigator(world, obstacles.occupancy, localizer=localizer, max_replans=10).go_to(robot, goal)
        assert result.success, result.message
        assert not robot.bumped
        assert robot.ground_truth_pose.distance_to(Pose2D(*goal)) < 0.1
    assert result.details["attempts"] >= 2  # replanned as furniture came into view


def test_occupancy_follows_the_perceived_entities(apartment):
    from assistant.world import furniture_entities, world_grid

    perceived = []
    obstacles = DepthObstacles(apartment, entities=lambda: list(perceived))
    empty = obstacles.occupancy()
    assert obstacles.occupancy() is empty
    couch = (4.5, 3.0)
    assert empty.is_free(*couch)
    perceived.extend(furniture_entities(apartment, "original", world_grid(apartment, 0.1)))
    seen = obstacles.occupancy()
    assert seen is not empty and not seen.is_free(*couch)
    # equal content handed out as new objects does not rebuild the map
    perceived[:] = furniture_entities(apartment, "original", world_grid(apartment, 0.1))
    assert obstacles.occupancy() is seen

import math

from assistant.executor import ExecutionStatus, Navigator, build_occupancy
from assistant.geometry import Pose2D, angle_difference, box_polygon
from assistant.world import Entity, EntityKind, furniture_entities, load_world, world_grid


def perceived(world, scene="original"):
    return furniture_entities(world, scene, world_grid(world, 0.1))


def test_enter_the_living_room_of_the_apartment(apartment, any_robot):
    robot = any_robot(apartment)
    occ = build_occupancy(apartment, perceived(apartment))
    result = Navigator(apartment, lambda: occ).enter_room(robot, "living room")
    assert result.success, result.message
    pose = result.final_pose
    assert apartment.floorplan.room("living room").contains(pose.x, pose.y)
    assert abs(angle_difference(pose.theta, math.pi / 2)) < 0.1  # headed into the room
    assert result.details["rooms"] == ["hallway", "living room"]


def test_enter_the_bedroom_of_the_training_home_from_the_living_room(kinematic_robot):
    world = load_world("training-home")
    robot = kinematic_robot(world, pose=Pose2D(2.5, 2.5, math.pi))
    occ = build_occupancy(world, perceived(world))
    result = Navigator(world, lambda: occ).enter_room(robot, "bedroom")
    assert result.success, result.message
    assert world.floorplan.room("bedroom").contains(result.final_pose.x, result.final_pose.y)
    assert result.details["rooms"] == ["living room", "hallway", "bedroom"]
    assert result.distance_m > 4.0


def test_an_unknown_room_is_a_no_room_outcome(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)
    result = Navigator(apartment, lambda: build_occupancy(apartment, [])).enter_room(robot, "kitchen")
    assert result.status is ExecutionStatus.NO_ROOM
    assert "living room" in result.message
    assert robot.odometry().pose == apartment.start


def test_replans_around_an_obstacle_seen_on_the_way(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)  # (5, 0) heading west in the hallway
    grid = world_grid(apartment, 0.05)
    # a box in the middle of the hallway, leaving room to pass south of it
    box = Entity.from_polygon("box", "box", EntityKind.SHORT_TERM, box_polygon(0.5, -0.3, 1.0, 1.26), grid)
    empty, with_box = build_occupancy(apartment, []), build_occupancy(apartment, [box])
    calls = {"n": 0}

    def latest():
        calls["n"] += 1
        return empty if calls["n"] < 30 else with_box

    result = Navigator(apartment, latest).go_to(robot, (-3.0, 0.0))
    assert result.success, result.message
    assert result.details["attempts"] == 2
    assert math.dist(result.final_pose.xy, (-3.0, 0.0)) < 0.15
    assert not robot.bumped


def test_a_blocked_bedroom_is_a_no_path_outcome(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)
    grid = world_grid(apartment, 0.05)
    cx, cy = 2.633, -1.41
    box = Entity.from_polygon("box", "box", EntityKind.SHORT_TERM,
                              box_polygon(cx - 0.7, cy - 0.3, cx + 0.7, cy + 0.3), grid)
    occ = build_occupancy(apartment, [box])
    result = Navigator(apartment, lambda: occ).enter_room(robot, "bedroom")
    assert result.status is ExecutionStatus.NO_PATH
    assert result.details["reason"] == "unreachable"


def test_look_around_turns_and_hands_frames_to_perception(apartment):
    import pytest

    sim = pytest.importorskip("assistant.sim")
    with sim.SimRobot(apartment) as robot:
        nav = Navigator(apartment, lambda: build_occupancy(apartment, []))
        headings = []
        result = nav.look_around(robot, lambda frame, pose: headings.append(pose.theta) and False)
        assert result.success and result.details == {"frames": 8, "found": False}
        turns = [angle_difference(b, a) for a, b in zip(headings[:-1], headings[1:])]
        assert all(abs(t - math.pi / 4) < 0.06 for t in turns)
        assert math.dist(robot.odometry().pose.xy, apartment.start.xy) < 0.02  # on the spot
        # stops as soon as perception reports a find
        seen = []
        result = nav.look_around(robot, lambda frame, pose: seen.append(frame) or len(seen) == 3)
        assert result.details == {"frames": 3, "found": True}
        assert seen[0].depth_m.shape == (480, 640)

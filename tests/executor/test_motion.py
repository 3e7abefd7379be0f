import math

import numpy as np

from assistant.executor import (
    ExecutionStatus,
    PathFollower,
    build_occupancy,
    plan_path,
    room_entry_waypoints,
)
from assistant.geometry import Pose2D, angle_difference, box_polygon
from assistant.world import Entity, EntityKind, furniture_entities, load_world, world_grid


def perceived(world, scene="original"):
    return furniture_entities(world, scene, world_grid(world, 0.1))


def test_follower_drives_from_the_apartment_start_into_the_living_room(apartment, any_robot):
    robot = any_robot(apartment)
    occ = build_occupancy(apartment, perceived(apartment))
    goal = (5.5, 5.5)
    path = plan_path(occ, robot.odometry().pose, goal)
    result = PathFollower().follow(robot, path, final_heading_rad=math.pi / 2, occupancy=occ)
    assert result.status is ExecutionStatus.SUCCESS, result.message
    pose = result.final_pose
    assert math.dist((pose.x, pose.y), goal) < 0.15
    assert abs(angle_difference(pose.theta, math.pi / 2)) < 0.1
    assert apartment.floorplan.room("living room").contains(pose.x, pose.y)
    assert not getattr(robot, "bumped", False)
    # driven about the path's length, in about the time a 0.4 m/s base needs
    assert path.length_m * 0.9 < result.distance_m < path.length_m * 1.3
    assert path.length_m / 0.4 < result.sim_seconds < 3 * path.length_m / 0.4 + 20



def test_driving_into_a_wall_ends_with_a_collision_not_a_hang(apartment, any_robot):
    robot = any_robot(apartment)  # at (5, 0) heading west, the hallway's north wall at y = 1.258
    into_wall = np.array([[5.0, 0.0], [5.0, 3.0]])
    follower = PathFollower()
    result = follower.follow(robot, into_wall)  # no occupancy: only the bump can stop it
    assert result.status is ExecutionStatus.COLLISION
    assert result.details.get("bumped") or result.details.get("stalled")
    assert result.final_pose.y < 1.258
    assert result.sim_seconds < 60


def test_the_follower_stops_before_a_wall_it_knows_about(apartment, any_robot):
    robot = any_robot(apartment)
    occ = build_occupancy(apartment, [])
    result = PathFollower().follow(robot, np.array([[5.0, 0.0], [5.0, 3.0]]), occupancy=occ)
    assert result.status is ExecutionStatus.COLLISION
    assert "blocked" in result.message
    assert not getattr(robot, "bumped", False)
    assert result.final_pose.y < 1.258 - 0.25  # the robot's disc stays off the wall


def test_an_obstacle_that_appears_stops_the_robot(apartment, kinematic_robot):
    robot = kinematic_robot(apartment, pose=Pose2D(5.0, 0.0, math.pi))
    empty = build_occupancy(apartment, [])
    grid = world_grid(apartment, 0.05)
    box = Entity.from_polygon("box", "box", EntityKind.SHORT_TERM, box_polygon(0.8, -0.6, 1.4, 0.6), grid)
    with_box = build_occupancy(apartment, [box])
    calls = {"n": 0}

    def latest():
        calls["n"] += 1
        return empty if calls["n"] < 20 else with_box  # the box is seen after 2 s

    path = np.array([[5.0, 0.0], [-2.0, 0.0]])
    result = PathFollower().follow(robot, path, occupancy=latest)
    assert result.status is ExecutionStatus.COLLISION
    assert result.details["blocked_at"][0] > 1.0
    assert result.final_pose.x > 1.4 + 0.25
    assert not robot.bumped


def test_a_robot_that_does_not_move_stalls_out(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)
    robot.advance = lambda seconds: setattr(robot, "time_s", robot.time_s + seconds)  # wheels spin freely
    result = PathFollower().follow(robot, np.array([[5.0, 0.0], [3.0, 0.0]]))
    assert result.status is ExecutionStatus.COLLISION and result.details["stalled"]
    assert robot.commands_sent < 200


def test_a_robot_whose_clock_stands_still_still_returns(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)
    robot.advance = lambda seconds: None
    result = PathFollower(time_slack_s=2.0).follow(robot, np.array([[5.0, 0.0], [3.0, 0.0]]))
    assert result.status is ExecutionStatus.TIMEOUT


def test_turn_to_and_face_point(apartment, any_robot):
    robot = any_robot(apartment)
    follower = PathFollower()
    result = follower.turn_to(robot, 0.3)
    assert result.success
    assert abs(angle_difference(robot.odometry().pose.theta, 0.3)) <= follower.heading_tolerance_rad
    result = follower.face_point(robot, 5.0, -1.0)  # straight south of the robot
    assert result.success
    assert abs(angle_difference(robot.odometry().pose.theta, -math.pi / 2)) <= follower.heading_tolerance_rad
    start = robot.odometry().pose
    assert math.dist(start.xy, (5.0, 0.0)) < 0.02  # turning on the spot


def test_velocity_limits_are_respected(apartment, kinematic_robot):
    robot = kinematic_robot(apartment)
    sent = []
    original = robot.send_velocity

    def record(v, w):
        sent.append((v, w))
        original(v, w)

    robot.send_velocity = record
    follower = PathFollower()
    result = follower.follow(robot, np.array([[5.0, 0.0], [3.0, 0.3], [1.0, -0.4]]))
    assert result.success
    v = np.array(sent)
    assert np.all(np.abs(v[:, 0]) <= follower.limits.max_linear_m_s + 1e-9)
    assert np.all(np.abs(v[:, 1]) <= follower.limits.max_angular_rad_s + 1e-9)
    assert np.all(np.diff(v[:, 0]) <= follower.limits.max_linear_accel_m_s2 * follower.control_period_s + 1e-9)


def test_room_entry_on_the_training_home(any_robot):
    world = load_world("training-home")
    robot = any_robot(world)
    occ = build_occupancy(world, perceived(world))
    follower = PathFollower()
    for waypoint in room_entry_waypoints(world, "hallway", "bedroom"):
        path = plan_path(occ, robot.odometry().pose, (waypoint.x, waypoint.y))
        result = follower.follow(robot, path, final_heading_rad=waypoint.theta, occupancy=occ)
        assert result.success, result.message
    pose = robot.odometry().pose
    assert world.floorplan.room("bedroom").contains(pose.x, pose.y)


def test_backing_off_after_a_bump_frees_the_robot(apartment, any_robot):
    robot = any_robot(apartment)
    follower = PathFollower()
    bumped = follower.follow(robot, np.array([[5.0, 0.0], [5.0, 3.0]]))  # into the hallway's north wall
    assert bumped.status is ExecutionStatus.COLLISION
    at_wall = robot.odometry().pose
    backed = follower.back_off(robot, distance_m=0.25)
    assert backed.status is ExecutionStatus.SUCCESS, backed.message
    pose = robot.odometry().pose
    assert 0.2 < math.dist(pose.xy, at_wall.xy) < 0.35  # reversed about the distance asked
    assert pose.y < at_wall.y  # away from the wall, heading unchanged
    assert abs(angle_difference(pose.theta, at_wall.theta)) < 0.05
    # and it can drive again: a path away from the wall is followed
    away = follower.follow(robot, np.array([pose.xy, [pose.x, pose.y - 0.5]]))
    assert away.status is ExecutionStatus.SUCCESS, away.message


def test_back_off_rejects_a_distance_that_is_not_positive(apartment, any_robot):
    import pytest

    with pytest.raises(ValueError, match="positive"):
        PathFollower().back_off(any_robot(apartment), distance_m=0.0)

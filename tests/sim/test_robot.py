"""SimRobot specifics (the shared contract is in tests/robot/test_contract.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.errors import UnknownNameError
from assistant.geometry import Pose2D
from assistant.robot import DeviceNotConnectedError, Robot
from assistant.sim import OdometryNoise, SimRobot, StartPoseError


def test_unknown_world_lists_the_known_ones():
    with pytest.raises(UnknownNameError, match="apartment"):
        SimRobot("apartmnt")


def test_start_pose_outside_the_map(apartment):
    with pytest.raises(StartPoseError, match="outside the map"):
        SimRobot(apartment, start=Pose2D(100.0, 100.0, 0.0))


def test_commands_after_close_raise(apartment):
    robot = SimRobot(apartment)
    with robot:
        robot.send_velocity(0.2, 0.0)
        robot.advance(0.5)
    assert isinstance(robot, Robot)
    with pytest.raises(DeviceNotConnectedError, match="simulated robot in apartment"):
        robot.send_velocity(0.2, 0.0)
    with pytest.raises(DeviceNotConnectedError):
        robot.depth_frame()


def test_drive_into_a_wall_through_the_interface(apartment):
    # from the start (5, 0) heading east, the hallway's east wall is at x = 7.18
    with SimRobot(apartment, start=Pose2D(5.0, 0.0, 0.0)) as robot:
        robot.send_velocity(0.75, 0.0)
        robot.advance(10.0)
        assert robot.bumped and robot.bumped_into == "wall_4"
        assert robot.ground_truth_pose.x == pytest.approx(7.18 - 0.25, abs=1e-3)
        assert robot.odometry().linear_m_s == 0.0
        robot.send_velocity(-0.2, 0.0)
        assert not robot.bumped


def test_frame_carries_the_odometry_pose_and_is_rendered_from_the_truth(apartment):
    with SimRobot(apartment, odometry_noise=OdometryNoise(0.2, 0.2, 0.2), seed=4) as robot:
        robot.send_velocity(0.5, 0.3)
        robot.advance(3.0)
        frame = robot.depth_frame()
        assert frame.robot_pose == robot.odometry().pose
        assert frame.robot_pose != robot.ground_truth_pose
        assert frame.timestamp_s == pytest.approx(robot.time_s)
        exact, _ = robot.renderer.cast(robot.ground_truth_pose)
        valid = frame.valid
        assert np.median(np.abs(frame.depth_m[valid] - exact[valid])) < 0.02
        assert robot.depth_frame() is frame  # no time passed: the same frame
        robot.advance(0.1)
        assert robot.depth_frame() is not frame


def test_same_seed_same_run(apartment):
    def run(seed):
        with SimRobot(apartment, seed=seed, odometry_noise=OdometryNoise()) as robot:
            robot.send_velocity(0.4, -0.2)
            robot.advance(2.0)
            return robot.odometry().pose, robot.depth_frame().depth_m

    (p1, d1), (p2, d2), (p3, d3) = run(5), run(5), run(6)
    assert p1 == p2 and np.array_equal(d1, d2)
    assert p1 != p3 and not np.array_equal(d1, d3)


def test_tilt_is_applied(apartment):
    robot = SimRobot(apartment, tilt_deg=25.0)
    assert robot.mount.tilt_rad == pytest.approx(math.radians(25.0))
    with robot:
        assert robot.depth_frame().mount.tilt_rad == pytest.approx(math.radians(25.0))

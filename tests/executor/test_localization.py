import math

import numpy as np
import pytest

from assistant.executor import FloorplanLocalizer, PathFollower, build_occupancy, plan_path, wall_faces
from assistant.geometry import Pose2D
from assistant.robot.frames import CameraIntrinsics, DepthFrame
from assistant.world import furniture_entities, load_world, world_grid

sim = pytest.importorskip("assistant.sim")


@pytest.fixture(scope="module")
def training_home():
    return load_world("training-home")


def test_wall_faces_are_the_faces_inside_the_home(apartment):
    faces = wall_faces(apartment)
    # every face point lies on a wall outline, and a room is right beside it
    assert len(faces) > 1000
    outer_east = faces[np.isclose(faces[:, 0], 7.23)]
    assert len(outer_east) == 0  # the outside face of the east wall is not seen from inside
    assert np.isclose(faces[:, 0], 7.18).sum() > 100  # its inside face is


@pytest.mark.parametrize("offset", [Pose2D(0.2, -0.15, 0.0), Pose2D(0.0, 0.0, 0.08), Pose2D(-0.12, 0.1, -0.05)])
def test_one_frame_pulls_a_wrong_estimate_back(apartment, offset):
    truth = Pose2D(5.5, 5.5, 2.4)  # in the living room, looking at two walls
    with sim.SimRobot(apartment, start=truth) as robot:
        frame = robot.depth_frame()
    localizer = FloorplanLocalizer(apartment, max_search_m=0.4)
    localizer.correction = offset  # as if odometry had drifted by `offset`
    localizer._since_m = 3.0  # …over 3 m, so the search window is wide enough
    before = localizer.pose(truth)
    update = localizer.update(frame)
    assert update.accepted, update.reason
    after = localizer.pose(truth)
    assert after.distance_to(truth) < 0.06
    assert abs(math.remainder(after.theta - truth.theta, 2 * math.pi)) < 0.02
    assert after.distance_to(truth) < before.distance_to(truth) or before.distance_to(truth) < 0.06


def test_a_frame_without_walls_changes_nothing(apartment):
    intrinsics = CameraIntrinsics.kinect_v1()
    empty = DepthFrame(np.zeros((480, 640), np.float32), intrinsics, robot_pose=Pose2D(5.0, 0.0, 3.0))
    localizer = FloorplanLocalizer(apartment)
    update = localizer.update(empty)
    assert not update.accepted and "wall points" in update.reason
    assert localizer.pose(Pose2D(5.0, 0.0, 3.0)) == Pose2D(5.0, 0.0, 3.0)
    with pytest.raises(ValueError):
        localizer.update(DepthFrame(np.zeros((480, 640), np.float32), intrinsics))


def test_drifting_odometry_still_arrives_with_the_localizer(training_home):
    from assistant.sim.kinematics import OdometryNoise

    occ = build_occupancy(training_home, furniture_entities(training_home, "original", world_grid(training_home, 0.1)))
    start = Pose2D(1.0, 3.2, 0.0)
    goal = (9.5, 1.2)
    path = plan_path(occ, start, goal)
    strong = OdometryNoise(translation_m_per_sqrt_m=0.04, heading_rad_per_sqrt_m=0.05, heading_rad_per_sqrt_rad=0.05)
    with sim.SimRobot(training_home, start=start, seed=3, odometry_noise=strong) as robot:
        localizer = FloorplanLocalizer(training_home)
        result = PathFollower().follow(robot, path, occupancy=occ, localizer=localizer)
        truth = robot.ground_truth_pose
        drift = robot.odometry().pose.distance_to(truth)
    assert result.success, result.message
    assert truth.distance_to(Pose2D(*goal)) < 0.15
    assert result.final_pose.distance_to(truth) < 0.1
    assert sum(u.accepted for u in localizer.updates) >= 10
    assert drift > 0.1  # the odometry alone is off: without the localizer this run ends in a collision

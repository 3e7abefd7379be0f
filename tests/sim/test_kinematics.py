"""The differential-drive base: limits, stopping at contact (no tunnelling), odometry noise."""

from __future__ import annotations

import math

import pytest

from assistant.geometry import Pose2D
from assistant.sim import DiffDriveBase, DiffDriveLimits, OdometryNoise, StartPoseError


def test_drives_into_a_thin_wall_at_full_speed_and_stops_at_contact(empty_room):
    base = DiffDriveBase(empty_room, start=Pose2D(3.0, 2.0, 0.0))
    base.set_command(10.0, 0.0)  # clamped to the P3-DX's 0.75 m/s
    assert base.command == (0.75, 0.0)
    bumped = base.step(30.0)  # one long call: substeps inside
    assert bumped and base.bumped and base.bumped_into == "wall_3"
    assert base.pose.x == pytest.approx(6.0 - 0.25, abs=1e-3)  # wall face at x = 6, radius 0.25
    assert base.pose.x <= 6.0 - 0.25
    assert base.velocity == (0.0, 0.0) and base.command == (0.0, 0.0)
    base.step(5.0)
    assert base.pose.x <= 6.0 - 0.25


@pytest.mark.parametrize("substep_s", [0.01, 0.5, 2.0])
def test_no_tunnelling_whatever_the_substep(make_box_world, substep_s):
    # a 5 cm wall across the middle of the room
    world = make_box_world(size=(6.0, 4.0), wall=0.05)
    from assistant.world import Wall
    walls = world.floorplan.walls + (Wall(3.0, 0.0, 3.05, 4.0),)
    world = type(world)(world.name, type(world.floorplan)(world.floorplan.rooms, walls, ()),
                        world.start, world.start_heading_rad, world.scenes)
    fast = DiffDriveLimits(max_linear_m_s=3.0, linear_accel_m_s2=100.0)
    base = DiffDriveBase(world, start=Pose2D(1.0, 2.0, 0.0), limits=fast, substep_s=substep_s)
    base.set_command(3.0, 0.0)
    base.step(10.0)
    assert base.bumped_into == "wall_4"
    assert base.pose.x == pytest.approx(3.0 - 0.25, abs=1e-3)


def test_stops_at_furniture_and_can_back_away(room_with_table):
    base = DiffDriveBase(room_with_table, start=Pose2D(1.0, 2.0, 0.0))
    base.set_command(0.5, 0.0)
    base.step(20.0)
    assert base.bumped_into == "table_1"
    assert base.pose.x == pytest.approx(3.0 - 0.3555 - 0.25, abs=2e-3)
    base.set_command(-0.3, 0.0)
    assert not base.bumped
    base.step(2.0)
    assert base.pose.x == pytest.approx(2.3945 - 0.45, abs=2e-3) and not base.bumped  # 1 s ramp + 1 s at 0.3 m/s


def test_turning_in_place_beside_a_wall_is_allowed(empty_room):
    base = DiffDriveBase(empty_room, start=Pose2D(0.26, 2.0, 0.0))
    base.set_command(0.0, 1.0)
    base.step(3.0)
    assert not base.bumped
    assert base.pose.theta == pytest.approx(3.0 - _ramp_loss(1.0), abs=0.01)


def _ramp_loss(w: float) -> float:
    """Angle lost accelerating to ``w`` rad/s at the P3-DX's 100°/s²."""
    a = math.radians(100.0)
    return w * w / (2 * a)


def test_acceleration_and_speed_limits(empty_room):
    base = DiffDriveBase(empty_room, start=Pose2D(1.0, 2.0, 0.0))
    base.set_command(0.75, 5.0)
    assert base.command[1] == pytest.approx(math.radians(100))
    base.step(1.0)
    linear, angular = base.velocity
    assert linear == pytest.approx(0.3, abs=1e-6)  # 0.3 m/s² for one second
    assert angular == pytest.approx(math.radians(100), abs=1e-6)  # reached after 1 s at 100°/s²
    with pytest.raises(ValueError):
        base.set_command(math.nan, 0.0)
    with pytest.raises(ValueError):
        base.step(-1.0)


def test_exact_odometry_without_noise(empty_room):
    base = DiffDriveBase(empty_room, start=Pose2D(1.0, 1.0, 0.3))
    base.set_command(0.4, 0.3)
    base.step(4.0)
    assert base.odometry_pose == base.pose
    assert base.distance_m > 1.0


def test_odometry_noise_is_seeded_and_grows(empty_room):
    def run(seed):
        base = DiffDriveBase(empty_room, start=Pose2D(1.0, 1.0, 0.3), odometry_noise=OdometryNoise(), seed=seed)
        base.set_command(0.4, 0.3)
        base.step(4.0)
        return base

    a, b, c = run(1), run(1), run(2)
    assert a.odometry_pose == b.odometry_pose and a.pose == b.pose
    assert a.odometry_pose != c.odometry_pose
    assert a.pose == c.pose  # noise is in the encoders, not in the motion
    assert a.odometry_pose.distance_to(a.pose) > 1e-4


def test_start_pose_checks(empty_room, room_with_table):
    with pytest.raises(StartPoseError, match="outside the map"):
        DiffDriveBase(empty_room, start=Pose2D(20.0, 2.0, 0.0))
    with pytest.raises(StartPoseError, match="table_1"):
        DiffDriveBase(room_with_table, start=Pose2D(3.0, 2.0, 0.0))
    with pytest.raises(StartPoseError, match="wall"):
        DiffDriveBase(empty_room, start=Pose2D(0.1, 2.0, 0.0))


def test_cannot_leave_through_an_open_end(apartment):
    # the apartment's hallway is open at its west end (x = -5): the map edge stops the robot
    base = DiffDriveBase(apartment, start=Pose2D(-3.0, 0.0, math.pi))
    base.set_command(0.75, 0.0)
    base.step(20.0)
    assert base.bumped_into == "map edge"
    assert base.pose.x >= apartment.floorplan.bounds()[0] + 0.25 - 1e-6


def test_a_start_against_furniture_is_backed_off_until_clear():
    from assistant.geometry import Pose2D
    from assistant.sim.collision import Obstacles
    from assistant.sim.kinematics import clear_start
    from assistant.world import ROBOT_RADIUS_M, load_world

    world = load_world("apartment")
    obstacles = Obstacles.from_world(world, "original")
    touching = Pose2D(5.647, 3.556, -0.6836)  # where a search left the robot, against couch_1
    assert obstacles.disc_collides(touching.x, touching.y, ROBOT_RADIUS_M) is not None
    clear = clear_start(world, "original", touching)
    assert clear is not None and clear.theta == touching.theta
    assert obstacles.disc_collides(clear.x, clear.y, ROBOT_RADIUS_M + 0.04) is None
    assert clear_start(world, "original", world.start) == world.start  # free: as it was
    assert clear_start(world, "original", Pose2D(4.5, 3.0, 0.0), max_back_m=0.1) is None  # inside the couch

"""Fixtures of the executor tests: a tiny kinematic robot (a test stand-in with the robot
interface: odometry, send_velocity, stop, advance, bumped) and the SimRobot when it exists."""

from __future__ import annotations

import math

import pytest

from assistant.geometry import Pose2D
from assistant.robot.frames import Odometry


class KinematicRobot:
    """Unicycle kinematics integrated in simulated time; stops with ``bumped`` set when its
    disc would move into an obstacle of a boolean occupancy (True = blocked). Like the
    simulator's base, a new velocity command clears ``bumped``, and moving away from what it
    touched is allowed."""

    def __init__(self, pose: Pose2D, grid=None, occupied=None, radius_m: float = 0.25):
        self.pose = pose
        self.grid, self.occupied, self.radius_m = grid, occupied, radius_m
        self.time_s = 0.0
        self.command = (0.0, 0.0)
        self.bumped = False
        self.commands_sent = 0
        if occupied is not None:
            from scipy import ndimage

            res = grid.resolution_m
            self._clearance = ndimage.distance_transform_edt(~occupied, sampling=res) - res / 2

    def odometry(self) -> Odometry:
        return Odometry(self.pose, self.command[0], self.command[1], self.time_s)

    def send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        self.commands_sent += 1
        self.command = (float(linear_m_s), float(angular_rad_s))
        self.bumped = False

    def stop(self) -> None:
        self.command = (0.0, 0.0)

    def advance(self, seconds: float) -> None:
        steps = max(1, int(math.ceil(seconds / 0.02)))
        dt = seconds / steps
        for _ in range(steps):
            v, w = self.command
            if self.bumped:
                v = 0.0
            p = self.pose
            nxt = Pose2D(p.x + v * math.cos(p.theta) * dt, p.y + v * math.sin(p.theta) * dt, p.theta + w * dt)
            if self._collides(nxt) and self._clearance_at(nxt) <= self._clearance_at(p):
                self.bumped = True
                self.command = (0.0, 0.0)
            else:
                self.pose = nxt
            self.time_s += dt

    def _clearance_at(self, pose: Pose2D) -> float:
        if self.occupied is None:
            return math.inf
        iy, ix = self.grid.world_to_cell(pose.xy)[0]
        if not (0 <= iy < self.grid.height_cells and 0 <= ix < self.grid.width_cells):
            return -math.inf
        return float(self._clearance[iy, ix])

    def _collides(self, pose: Pose2D) -> bool:
        if self.occupied is None:
            return False
        iy, ix = self.grid.world_to_cell(pose.xy)[0]
        if not (0 <= iy < self.grid.height_cells and 0 <= ix < self.grid.width_cells):
            return True
        return bool(self._clearance[iy, ix] < self.radius_m)


@pytest.fixture
def kinematic_robot():
    """Factory: ``kinematic_robot(world, scene, pose=None)`` → a KinematicRobot in that world."""

    def make(world, scene: str = "original", pose: Pose2D | None = None) -> KinematicRobot:
        from assistant.world import occupancy

        grid, occupied = occupancy(world, scene, resolution_m=0.05)
        return KinematicRobot(pose or world.start, grid, occupied)

    return make


def _sim_robot_factory():
    try:
        from assistant.sim import SimRobot  # noqa: F401
    except ImportError:
        return None
    return SimRobot


@pytest.fixture(params=["kinematic", "sim"])
def any_robot(request, kinematic_robot):
    """The same motion tests on the stand-in and on the simulator's SimRobot (skipped until
    ``assistant.sim.SimRobot`` exists)."""

    def make(world, scene: str = "original", pose: Pose2D | None = None):
        if request.param == "kinematic":
            return kinematic_robot(world, scene, pose)
        sim_robot = _sim_robot_factory()
        if sim_robot is None:
            pytest.skip("assistant.sim.SimRobot is not built yet")
        robot = sim_robot(world, scene=scene, start=pose).connect()
        request.addfinalizer(robot.close)
        return robot

    return make


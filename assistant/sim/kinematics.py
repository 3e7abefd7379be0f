"""A differential-drive base with the Pioneer P3-DX's limits, collisions and odometry.

The base integrates a commanded (linear, angular) velocity in small substeps, with the
acceleration and speed limits of the P3-DX's controller (ARCOS defaults: 0.75 m/s, 100°/s,
0.3 m/s², 100°/s²). Its footprint is a disc of 0.25 m radius; a substep that would make the
disc overlap a wall, a furniture footprint or the map's edge is cut back to the point of
contact (by bisection), the base stops there, the command is cleared and ``bumped`` is set.
Substeps never move the base by more than ``max_substep_m`` (2 cm), so it cannot pass through
a 5 cm wall at any speed.

Odometry integrates the same motion with optional noise whose variance grows with the distance
travelled and the angle turned (so its size does not depend on the substep length), drawn from
a seeded generator: the same seed and commands give the same run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.sim.collision import Obstacles
from assistant.world import ROBOT_RADIUS_M, World

__all__ = ["DiffDriveBase", "DiffDriveLimits", "OdometryNoise", "StartPoseError"]


class StartPoseError(AssistantError, ValueError):
    """A start pose off the map or overlapping a wall or furniture."""


@dataclass(frozen=True)
class DiffDriveLimits:
    """Speed and acceleration limits (m/s, rad/s, m/s², rad/s²) of the base controller."""

    max_linear_m_s: float = 0.75
    max_angular_rad_s: float = math.radians(100.0)
    linear_accel_m_s2: float = 0.3
    angular_accel_rad_s2: float = math.radians(100.0)

    @classmethod
    def p3dx(cls) -> "DiffDriveLimits":
        """The P3-DX's ARCOS defaults (TransVelMax 750 mm/s, RotVelMax 100°/s, accelerations
        300 mm/s² and 100°/s²)."""
        return cls()


@dataclass(frozen=True)
class OdometryNoise:
    """Odometry error growth: standard deviations after 1 m driven / 1 rad turned.

    Over a motion of ``d`` metres and ``a`` radians, the distance error has standard deviation
    ``translation_m_per_sqrt_m · √d``, the heading error
    ``√(heading_rad_per_sqrt_m² · d + heading_rad_per_sqrt_rad² · a)``.
    """

    translation_m_per_sqrt_m: float = 0.02
    heading_rad_per_sqrt_m: float = 0.02
    heading_rad_per_sqrt_rad: float = 0.03


@dataclass
class _State:
    pose: Pose2D
    odometry: Pose2D
    linear: float = 0.0
    angular: float = 0.0
    command: tuple[float, float] = (0.0, 0.0)
    bumped: bool = False
    bumped_into: str | None = None
    time_s: float = 0.0
    distance_m: float = 0.0


class DiffDriveBase:
    """A simulated P3-DX base in one scene of a world (poses in the world frame).

    Raises :class:`StartPoseError` when ``start`` is off the map or the disc overlaps an
    obstacle there.
    """

    def __init__(self, world: World, scene: str = "original", start: Pose2D | None = None, *,
                 limits: DiffDriveLimits | None = None, radius_m: float = ROBOT_RADIUS_M,
                 odometry_noise: OdometryNoise | None = None, seed: int | None = 0,
                 substep_s: float = 0.01, max_substep_m: float = 0.02):
        self.world = world
        self.scene = world.scene(scene).name
        self.limits = limits or DiffDriveLimits.p3dx()
        self.radius_m = float(radius_m)
        self.odometry_noise = odometry_noise
        # no substep may move the disc by more than max_substep_m (nor half its radius)
        self.max_substep_m = min(float(max_substep_m), self.radius_m / 2.0)
        self.substep_s = min(float(substep_s), self.max_substep_m / self.limits.max_linear_m_s)
        self.rng = np.random.default_rng(seed)
        self.obstacles = Obstacles.from_world(world, self.scene)
        start = world.start if start is None else start
        self._check_start(start)
        self._state = _State(pose=start, odometry=start)

    def _check_start(self, pose: Pose2D) -> None:
        xmin, ymin, xmax, ymax = self.obstacles.bounds
        if not (xmin <= pose.x <= xmax and ymin <= pose.y <= ymax):
            raise StartPoseError(
                f"start pose ({pose.x:.2f}, {pose.y:.2f}) is outside the map of {self.world.name} "
                f"(x from {xmin:.2f} to {xmax:.2f} m, y from {ymin:.2f} to {ymax:.2f} m)")
        hit = self.obstacles.disc_collides(pose.x, pose.y, self.radius_m)
        if hit is not None:
            raise StartPoseError(
                f"start pose ({pose.x:.2f}, {pose.y:.2f}) puts the robot (radius {self.radius_m} m) "
                f"into {hit} in {self.world.name}; choose a free spot")

    # ---------------------------------------------------------------- state
    @property
    def pose(self) -> Pose2D:
        """True pose (ground truth, world frame): for evaluation only."""
        return self._state.pose

    @property
    def odometry_pose(self) -> Pose2D:
        """What the wheel encoders say (world frame, starts at the start pose)."""
        return self._state.odometry

    @property
    def velocity(self) -> tuple[float, float]:
        """Current (linear m/s, angular rad/s)."""
        return self._state.linear, self._state.angular

    @property
    def command(self) -> tuple[float, float]:
        return self._state.command

    @property
    def bumped(self) -> bool:
        """True after the base stopped against an obstacle, until the next command."""
        return self._state.bumped

    @property
    def bumped_into(self) -> str | None:
        """Name of what the base bumped into (``wall_<k>``, a furniture id, ``map edge``)."""
        return self._state.bumped_into

    @property
    def time_s(self) -> float:
        """Simulated time (seconds) since the base was created."""
        return self._state.time_s

    @property
    def distance_m(self) -> float:
        """Distance driven so far (metres)."""
        return self._state.distance_m

    # ---------------------------------------------------------------- commands
    def set_command(self, linear_m_s: float, angular_rad_s: float) -> tuple[float, float]:
        """Command a velocity (clamped to the limits); returns the command as applied."""
        linear, angular = float(linear_m_s), float(angular_rad_s)
        if not (math.isfinite(linear) and math.isfinite(angular)):
            raise ValueError(f"velocity must be finite numbers, got ({linear_m_s}, {angular_rad_s})")
        lim = self.limits
        linear = max(-lim.max_linear_m_s, min(lim.max_linear_m_s, linear))
        angular = max(-lim.max_angular_rad_s, min(lim.max_angular_rad_s, angular))
        self._state.command = (linear, angular)
        self._state.bumped = False
        self._state.bumped_into = None
        return self._state.command

    def stop(self) -> None:
        """Command zero velocity (the base decelerates within its limits)."""
        self.set_command(0.0, 0.0)

    def halt(self) -> None:
        """Zero command and velocity at once (an emergency stop)."""
        self._state.command = (0.0, 0.0)
        self._state.linear = self._state.angular = 0.0

    # ---------------------------------------------------------------- integration
    def step(self, dt_s: float) -> bool:
        """Advance simulated time by ``dt_s`` seconds; return True when the base bumped."""
        if not (dt_s >= 0 and math.isfinite(dt_s)):
            raise ValueError(f"time step must be a non-negative number of seconds, got {dt_s}")
        remaining = float(dt_s)
        while remaining > 1e-12:
            dt = min(self.substep_s, remaining)
            self._accelerate(dt)
            if self._move(dt):
                remaining = 0.0
            else:
                remaining -= dt
            self._state.time_s += dt
        return self._state.bumped

    def _accelerate(self, dt: float) -> None:
        target_v, target_w = self._state.command
        lim = self.limits
        dv = lim.linear_accel_m_s2 * dt
        dw = lim.angular_accel_rad_s2 * dt
        self._state.linear += max(-dv, min(dv, target_v - self._state.linear))
        self._state.angular += max(-dw, min(dw, target_w - self._state.angular))

    @staticmethod
    def _arc(pose: Pose2D, ds: float, dtheta: float) -> Pose2D:
        """``pose`` moved along a circular arc of length ``ds`` turning by ``dtheta``."""
        if abs(dtheta) < 1e-9:
            dx, dy = ds, 0.0
        else:
            radius = ds / dtheta
            dx = radius * math.sin(dtheta)
            dy = radius * (1.0 - math.cos(dtheta))
        return pose.compose(Pose2D(dx, dy, dtheta))

    @classmethod
    def _advance_pose(cls, pose: Pose2D, linear: float, angular: float, dt: float) -> Pose2D:
        """Exact integration of a constant (linear, angular) velocity for ``dt`` seconds."""
        return cls._arc(pose, linear * dt, angular * dt)

    def _move(self, dt: float) -> bool:
        """One substep with collision handling; True when it ended in a bump."""
        state = self._state
        linear, angular = state.linear, state.angular
        if linear == 0.0 and angular == 0.0:
            return False
        start = state.pose
        candidate = self._advance_pose(start, linear, angular, dt)
        hit = None
        if linear != 0.0:
            hit = self.obstacles.disc_collides(candidate.x, candidate.y, self.radius_m, edges_only=True)
        fraction = 1.0
        if hit is not None:
            lo, hi = 0.0, 1.0  # lo is free, hi collides
            for _ in range(20):
                mid = (lo + hi) / 2.0
                trial = self._advance_pose(start, linear, angular, dt * mid)
                if self.obstacles.disc_collides(trial.x, trial.y, self.radius_m, edges_only=True) is None:
                    lo = mid
                else:
                    hi = mid
            fraction = lo
            candidate = self._advance_pose(start, linear, angular, dt * fraction)
        self._update_odometry(linear * dt * fraction, angular * dt * fraction)
        state.distance_m += abs(linear) * dt * fraction
        state.pose = candidate
        if hit is not None:
            state.bumped = True
            state.bumped_into = hit
            state.command = (0.0, 0.0)
            state.linear = state.angular = 0.0
            return True
        return False

    def _update_odometry(self, ds: float, dtheta: float) -> None:
        noise = self.odometry_noise
        if noise is not None and (ds != 0.0 or dtheta != 0.0):
            d, a = abs(ds), abs(dtheta)
            sigma_s = noise.translation_m_per_sqrt_m * math.sqrt(d)
            sigma_t = math.sqrt(noise.heading_rad_per_sqrt_m ** 2 * d + noise.heading_rad_per_sqrt_rad ** 2 * a)
            e_s, e_t = self.rng.standard_normal(2)
            ds = ds + sigma_s * e_s
            dtheta = dtheta + sigma_t * e_t
        self._state.odometry = self._arc(self._state.odometry, ds, dtheta)


def clear_start(world: World, scene: str, pose: Pose2D, radius_m: float = ROBOT_RADIUS_M,
                margin_m: float = 0.05, max_back_m: float = 0.6, step_m: float = 0.05) -> Pose2D | None:
    """``pose``, or the nearest pose straight behind it (same heading, ``step_m`` at a time, up to
    ``max_back_m``), where the robot's disc keeps ``margin_m`` from every obstacle; None when
    there is none. A task that ended against a piece of furniture (a bump stops the disc
    touching it) leaves the robot where a new simulated robot cannot start, or bumps at its
    first move: the next task starts backed off, as a real robot backs off a bumper hit."""
    obstacles = Obstacles.from_world(world, world.scene(scene).name)
    back = np.array([-np.cos(pose.theta), -np.sin(pose.theta)])
    for k in range(int(round(max_back_m / step_m)) + 1):
        x, y = pose.x + back[0] * k * step_m, pose.y + back[1] * k * step_m
        if obstacles.disc_collides(x, y, radius_m + margin_m) is None:
            return Pose2D(float(x), float(y), pose.theta)
    return None

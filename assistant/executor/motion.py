"""Driving a differential-drive robot along a path: pure pursuit with velocity limits.

The controller uses only the robot interface every adapter shares — ``odometry()``,
``send_velocity(linear_m_s, angular_rad_s)``, ``stop()`` — and lets time pass with the
robot's ``advance(seconds)`` when it has one (the simulator: simulated time) or by sleeping
(a real robot). It never reads the world's ground truth.

Safety: before every command the follower checks the next stretch of the path against the
latest :class:`~assistant.executor.planning.OccupancyMap` (when given one, or a function that
returns the current one) and stops short of anything in the way; after every step it reads the
robot's ``bumped`` flag. Every call is bounded in robot time and in steps, and returns an
:class:`~assistant.executor.outcome.ExecutionResult` (``success``, ``collision``, ``timeout``).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Protocol, Union, runtime_checkable

import numpy as np

from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.planning import OccupancyMap, PlannedPath
from assistant.geometry import Pose2D, angle_difference
from assistant.robot.frames import Odometry


@runtime_checkable
class DrivableRobot(Protocol):
    """What the motion controller needs of a robot (every adapter has it)."""

    def odometry(self) -> Odometry: ...

    def send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None: ...

    def stop(self) -> None: ...


OccupancySource = Union[OccupancyMap, Callable[[], OccupancyMap], None]


@runtime_checkable
class Localizer(Protocol):
    """Turns odometry into a better world pose (e.g. by matching walls in depth frames)."""

    def observe(self, robot, odometry_pose: Pose2D): ...

    def pose(self, odometry_pose: Pose2D) -> Pose2D: ...


@dataclass(frozen=True)
class MotionLimits:
    """Velocity and acceleration limits: a P3-DX indoors, below its controller's maxima
    (0.75 m/s, 100°/s) and at its default acceleration (0.3 m/s²)."""

    max_linear_m_s: float = 0.4
    max_angular_rad_s: float = 1.0
    max_linear_accel_m_s2: float = 0.3
    min_linear_m_s: float = 0.05  # below this near the goal the base barely moves
    min_angular_rad_s: float = 0.15


@dataclass(frozen=True)
class PathFollower:
    """Pure-pursuit path following for a differential-drive base.

    The robot steers toward the point ``lookahead_m`` further along the path; when that point
    is more than ``rotate_in_place_rad`` off its heading it turns on the spot first. It slows
    down within ``slow_down_m`` of the goal and stops within ``goal_tolerance_m``. Each control
    step lasts ``control_period_s`` of robot time.
    """

    limits: MotionLimits = MotionLimits()
    lookahead_m: float = 0.35
    goal_tolerance_m: float = 0.05
    heading_tolerance_rad: float = 0.05
    control_period_s: float = 0.1
    rotate_in_place_rad: float = 0.9
    slow_down_m: float = 0.5
    turn_gain: float = 2.0
    safety_lookahead_m: float = 0.6  # how far ahead on the path to look for obstacles
    stall_seconds: float = 5.0  # no progress for this long → stop (pushing against something)
    time_factor: float = 3.0  # time budget: this many times the nominal drive time, plus slack
    time_slack_s: float = 20.0

    # --- public ----------------------------------------------------------------------------

    def follow(self, robot: DrivableRobot, path: PlannedPath | np.ndarray | Sequence[Sequence[float]], *,
               final_heading_rad: float | None = None, occupancy: OccupancySource = None,
               max_seconds: float | None = None, localizer: Localizer | None = None) -> ExecutionResult:
        """Drive ``robot`` along ``path`` (waypoints in metres, world frame), then turn to
        ``final_heading_rad`` if given. Returns ``success``, ``collision`` (bumped, or stopped
        because the path ahead is blocked) or ``timeout``.

        Poses come from odometry, corrected by ``localizer`` when given (e.g. a
        :class:`~assistant.executor.localization.FloorplanLocalizer`)."""
        points = _as_points(path)
        dense = _resample(points, step_m=0.05)
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
        total = float(arc[-1])
        budget = max_seconds if max_seconds is not None else self._budget(total)
        clock = _Clock(robot, self.control_period_s)
        odo = robot.odometry()
        start_time = odo.timestamp_s
        travelled = 0.0
        last_xy = _world_pose(robot, odo, localizer).xy
        index = 0
        v_prev = 0.0
        best_remaining, last_progress_time = math.inf, start_time
        max_steps = int(math.ceil(budget / self.control_period_s)) * 2 + 10

        for _ in range(max_steps):
            odo = robot.odometry()
            pose = _world_pose(robot, odo, localizer)
            travelled += float(np.linalg.norm(pose.xy - last_xy))
            last_xy = pose.xy
            elapsed = odo.timestamp_s - start_time
            if _bumped(robot):
                robot.stop()
                return self._result(ExecutionStatus.COLLISION, "the robot bumped into something and stopped",
                                    robot, start_time, travelled, localizer, bumped=True)
            index = _project(dense, pose.xy, index, window=int(1.0 / 0.05))
            remaining = float(np.linalg.norm(dense[-1] - pose.xy))
            overshot = pose.to_local(dense[-1])[0, 0] < 0 and total - arc[index] < self.lookahead_m
            if remaining <= self.goal_tolerance_m or (overshot and remaining <= 2 * self.goal_tolerance_m):
                robot.stop()
                break
            if elapsed > budget:
                robot.stop()
                return self._result(ExecutionStatus.TIMEOUT, f"did not reach the goal within {budget:.0f} s "
                                    f"({remaining:.2f} m short)", robot, start_time, travelled, localizer)
            progress = total - arc[index] + remaining
            if progress < best_remaining - 0.05:
                best_remaining, last_progress_time = progress, odo.timestamp_s
            elif odo.timestamp_s - last_progress_time > self.stall_seconds:
                robot.stop()
                return self._result(ExecutionStatus.COLLISION, f"no progress for {self.stall_seconds:.0f} s "
                                    f"({remaining:.2f} m short): something is in the way", robot, start_time,
                                    travelled, localizer, stalled=True)
            current = _current(occupancy)
            if current is not None:
                blocked_at = self._blocked_ahead(current, dense, arc, index, pose)
                if blocked_at is not None:
                    robot.stop()
                    return self._result(ExecutionStatus.COLLISION,
                                        f"stopped: the way ahead is blocked at ({blocked_at[0]:.2f}, "
                                        f"{blocked_at[1]:.2f})", robot, start_time, travelled, localizer,
                                        blocked_at=[float(blocked_at[0]), float(blocked_at[1])])
            v, w = self._command(pose, dense, arc, index, remaining, v_prev)
            robot.send_velocity(v, w)
            v_prev = v
            clock.tick()
        else:
            robot.stop()
            return self._result(ExecutionStatus.TIMEOUT, f"gave up after {max_steps} control steps", robot,
                                start_time, travelled, localizer)

        if final_heading_rad is not None:
            turned = self.turn_to(robot, final_heading_rad, localizer=localizer)
            if not turned.success:
                return self._result(turned.status, turned.message, robot, start_time, travelled, localizer,
                                    **turned.details)
        return self._result(ExecutionStatus.SUCCESS, f"arrived ({total:.2f} m path)", robot, start_time,
                            travelled, localizer)

    def turn_to(self, robot: DrivableRobot, heading_rad: float, max_seconds: float | None = None,
                localizer: Localizer | None = None) -> ExecutionResult:
        """Turn on the spot to ``heading_rad`` (radians, world frame)."""
        limits = self.limits
        clock = _Clock(robot, self.control_period_s)
        odo = robot.odometry()
        start_time = odo.timestamp_s
        budget = max_seconds if max_seconds is not None else (
            math.pi / limits.min_angular_rad_s + self.time_slack_s)
        for _ in range(int(math.ceil(budget / self.control_period_s)) * 2 + 10):
            odo = robot.odometry()
            if _bumped(robot):
                robot.stop()
                return self._result(ExecutionStatus.COLLISION, "the robot bumped into something while turning",
                                    robot, start_time, 0.0, localizer, bumped=True)
            error = angle_difference(heading_rad, _world_pose(robot, odo, localizer).theta)
            if abs(error) <= self.heading_tolerance_rad:
                robot.stop()
                return self._result(ExecutionStatus.SUCCESS, "turned", robot, start_time, 0.0, localizer)
            if odo.timestamp_s - start_time > budget:
                break
            # slow down so that one control step cannot overshoot the tolerance band
            speed = min(limits.max_angular_rad_s, self.turn_gain * abs(error),
                        abs(error) / self.control_period_s)
            speed = max(speed, min(limits.min_angular_rad_s, abs(error) / self.control_period_s))
            robot.send_velocity(0.0, math.copysign(speed, error))
            clock.tick()
        robot.stop()
        return self._result(ExecutionStatus.TIMEOUT, f"could not turn to {heading_rad:.2f} rad", robot,
                            start_time, 0.0, localizer)

    def back_off(self, robot: DrivableRobot, distance_m: float = 0.25, speed_m_s: float = 0.15,
                 localizer: Localizer | None = None) -> ExecutionResult:
        """Reverse straight for ``distance_m`` (metres) at ``speed_m_s``: what a robot does after
        its bumper touched something, before it tries another way. Stops early on a second
        bump (something behind) and reports it as ``collision``."""
        if distance_m <= 0 or speed_m_s <= 0:
            raise ValueError(f"distance and speed must be positive, got {distance_m} m at {speed_m_s} m/s")
        clock = _Clock(robot, self.control_period_s)
        odo = robot.odometry()
        start_time, start_xy = odo.timestamp_s, odo.pose.xy
        budget = distance_m / speed_m_s + self.time_slack_s
        for _ in range(int(math.ceil(budget / self.control_period_s)) * 2 + 10):
            odo = robot.odometry()
            if float(np.linalg.norm(odo.pose.xy - start_xy)) >= distance_m:
                break
            if odo.timestamp_s - start_time > budget:
                break
            robot.send_velocity(-speed_m_s, 0.0)
            clock.tick()
            if _bumped(robot):
                robot.stop()
                return self._result(ExecutionStatus.COLLISION, "bumped into something while backing off",
                                    robot, start_time, 0.0, localizer, bumped=True)
        robot.stop()
        travelled = float(np.linalg.norm(robot.odometry().pose.xy - start_xy))
        return self._result(ExecutionStatus.SUCCESS, f"backed off {travelled:.2f} m", robot, start_time,
                            travelled, localizer)

    def face_point(self, robot: DrivableRobot, x: float, y: float,
                   localizer: Localizer | None = None) -> ExecutionResult:
        """Turn on the spot to face the point ``(x, y)`` (metres)."""
        pose = _world_pose(robot, robot.odometry(), localizer)
        if math.hypot(x - pose.x, y - pose.y) < 1e-6:
            return ExecutionResult.ok("already there", final_pose=pose)
        return self.turn_to(robot, math.atan2(y - pose.y, x - pose.x), localizer=localizer)

    # --- internals -------------------------------------------------------------------------

    def _budget(self, length_m: float) -> float:
        return self.time_factor * length_m / self.limits.max_linear_m_s + self.time_slack_s

    def _command(self, pose: Pose2D, dense: np.ndarray, arc: np.ndarray, index: int, remaining: float,
                 v_prev: float) -> tuple[float, float]:
        limits = self.limits
        target_s = arc[index] + self.lookahead_m
        k = int(min(np.searchsorted(arc, target_s), len(dense) - 1))
        target = dense[k]
        local = pose.to_local(target)[0]
        distance = float(np.hypot(*local))
        alpha = math.atan2(local[1], local[0])
        if abs(alpha) > self.rotate_in_place_rad or distance < 1e-6:
            w = math.copysign(min(limits.max_angular_rad_s, max(self.turn_gain * abs(alpha),
                                                                 limits.min_angular_rad_s)), alpha)
            return 0.0, w if distance >= 1e-6 else 0.0
        curvature = 2.0 * local[1] / max(distance ** 2, 1e-9)
        v = limits.max_linear_m_s * min(1.0, remaining / self.slow_down_m)
        v = max(v, limits.min_linear_m_s)
        v = min(v, v_prev + limits.max_linear_accel_m_s2 * self.control_period_s)
        if abs(curvature) * v > limits.max_angular_rad_s:
            v = limits.max_angular_rad_s / abs(curvature)
        return v, curvature * v

    def _blocked_ahead(self, occupancy: OccupancyMap, dense: np.ndarray, arc: np.ndarray, index: int,
                       pose: Pose2D) -> np.ndarray | None:
        end = int(np.searchsorted(arc, arc[index] + self.safety_lookahead_m))
        ahead = np.vstack([pose.xy[None], dense[index:end + 1]])
        clearance = occupancy.clearance_at(ahead)
        hit = np.nonzero(clearance < occupancy.robot_radius_m)[0]
        if len(hit) == 0:
            return None
        # already overlapping where the robot stands (e.g. a snapped start): only stop when it gets worse
        if hit[0] == 0 and clearance[min(len(clearance) - 1, 1):].min() >= clearance[0]:
            return None
        return ahead[hit[0]]

    def _result(self, status: ExecutionStatus, message: str, robot: DrivableRobot, start_time: float,
                travelled: float, localizer: Localizer | None = None, **details) -> ExecutionResult:
        odo = robot.odometry()
        pose = odo.pose if localizer is None else localizer.pose(odo.pose)
        return ExecutionResult(status, message, final_pose=pose, sim_seconds=odo.timestamp_s - start_time,
                               distance_m=travelled, details=details)


def follow_path(robot: DrivableRobot, path: PlannedPath | np.ndarray, **kwargs) -> ExecutionResult:
    """:meth:`PathFollower.follow` with the default controller."""
    return PathFollower().follow(robot, path, **kwargs)


def turn_to(robot: DrivableRobot, heading_rad: float) -> ExecutionResult:
    """:meth:`PathFollower.turn_to` with the default controller."""
    return PathFollower().turn_to(robot, heading_rad)


def face_point(robot: DrivableRobot, x: float, y: float) -> ExecutionResult:
    """:meth:`PathFollower.face_point` with the default controller."""
    return PathFollower().face_point(robot, x, y)


class _Clock:
    """Lets one control period pass: simulated (``robot.advance``) or real (sleep)."""

    def __init__(self, robot, period_s: float):
        self.period_s = period_s
        self._advance = getattr(robot, "advance", None)

    def tick(self) -> None:
        if callable(self._advance):
            self._advance(self.period_s)
        else:
            time.sleep(self.period_s)


def _world_pose(robot, odo: Odometry, localizer: Localizer | None) -> Pose2D:
    """The pose to steer by: odometry, corrected by the localizer when there is one."""
    if localizer is None:
        return odo.pose
    localizer.observe(robot, odo.pose)
    return localizer.pose(odo.pose)


def _bumped(robot) -> bool:
    return bool(getattr(robot, "bumped", False))


def _current(source: OccupancySource) -> OccupancyMap | None:
    if source is None or isinstance(source, OccupancyMap):
        return source
    return source()


def _as_points(path) -> np.ndarray:
    points = path.waypoints if isinstance(path, PlannedPath) else np.asarray(path, dtype=float)
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(points) == 0:
        raise ValueError("a path needs at least one waypoint")
    return points


def _resample(points: np.ndarray, step_m: float) -> np.ndarray:
    """Points every ``step_m`` along a polyline (keeping its ends)."""
    out = [points[0]]
    for a, b in zip(points[:-1], points[1:]):
        length = float(np.linalg.norm(b - a))
        n = max(1, int(math.ceil(length / step_m)))
        t = np.arange(1, n + 1) / n
        out.extend(a + t[:, None] * (b - a))
    return np.asarray(out)


def _project(dense: np.ndarray, xy: np.ndarray, index: int, window: int) -> int:
    """Index of the path point nearest ``xy`` among the next ``window`` points (never backwards)."""
    stop = min(len(dense), index + window + 1)
    d = np.linalg.norm(dense[index:stop] - xy, axis=1)
    return index + int(np.argmin(d))

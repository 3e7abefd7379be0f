"""Plan-and-drive: going to a point or into a room, replanning when the way ahead is blocked.

:class:`Navigator` ties planning and motion together for the fetch task's low level
(dissertation 5.5: "path planning and robot moving control", the same for every RDT node):
it plans on the latest occupancy the robot knows (the floor plan plus whatever perception has
reported so far, supplied by a function), follows the path, and when the follower stops
because something new blocks the way, plans again from where the robot stands — a bounded
number of times. Everything ends in an :class:`~assistant.executor.outcome.ExecutionResult`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

from assistant.errors import UnknownNameError
from assistant.executor.motion import DrivableRobot, Localizer, PathFollower
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.planning import NoPathError, OccupancyMap, plan_path
from assistant.executor.rooms import ENTRY_DEPTH_M, RoomGraph, door_crossing, room_of
from assistant.geometry import Pose2D
from assistant.robot.frames import DepthFrame
from assistant.world import World


@dataclass
class Navigator:
    """Goes places in ``world`` with ``robot``.

    ``occupancy`` is called for the current :class:`OccupancyMap` before every plan and every
    control step (so new perception is used at once); ``max_replans`` bounds the replanning
    after the way gets blocked. ``localizer`` (e.g. a
    :class:`~assistant.executor.localization.FloorplanLocalizer`) corrects odometry drift.
    """

    world: World
    occupancy: Callable[[], OccupancyMap]
    follower: PathFollower = field(default_factory=PathFollower)
    max_replans: int = 3
    localizer: Localizer | None = None

    def pose(self, robot: DrivableRobot) -> Pose2D:
        """The robot's best world pose: odometry, corrected by the localizer if there is one."""
        odometry = robot.odometry().pose
        return odometry if self.localizer is None else self.localizer.pose(odometry)

    def go_to(self, robot: DrivableRobot, goal_xy: Sequence[float], heading_rad: float | None = None,
              snap_goal: bool = True) -> ExecutionResult:
        """Drive to ``goal_xy`` (metres, world frame), then turn to ``heading_rad`` if given."""
        sim_seconds = distance = 0.0
        last: ExecutionResult | None = None
        for attempt in range(self.max_replans + 1):
            pose = self.pose(robot)
            try:
                path = plan_path(self.occupancy(), pose, goal_xy, snap_goal=snap_goal)
            except NoPathError as error:
                result = error.to_result(final_pose=pose)
                return _accumulate(result, sim_seconds, distance, replace_totals=True, attempts=attempt + 1)
            result = self.follower.follow(robot, path, final_heading_rad=heading_rad, occupancy=self.occupancy,
                                          localizer=self.localizer)
            sim_seconds += result.sim_seconds
            distance += result.distance_m
            last = result.with_details(goal=list(path.goal), goal_snapped=path.goal_snapped,
                                       path_length_m=path.length_m)
            blocked = result.status is ExecutionStatus.COLLISION and "blocked_at" in result.details
            if not blocked:  # arrived, bumped, stalled or out of time: nothing a new plan fixes
                break
        return _accumulate(last, sim_seconds, distance, attempts=attempt + 1, replace_totals=True)

    def enter_room(self, robot: DrivableRobot, room: str, depth_m: float = ENTRY_DEPTH_M) -> ExecutionResult:
        """Drive through the doors on the way into ``room`` and stop ``depth_m`` inside the
        last one, headed into the room (the first sub-task of a fetch)."""
        graph = RoomGraph(self.world)
        if room not in graph.graph:
            return ExecutionResult.failed(ExecutionStatus.NO_ROOM, str(UnknownNameError("room", room, graph.rooms)),
                                          final_pose=self.pose(robot), details={"room": room})
        pose = self.pose(robot)
        here = room_of(self.world, pose)
        if here is None:
            return ExecutionResult.failed(ExecutionStatus.NO_PATH, f"the robot at ({pose.x:.2f}, {pose.y:.2f}) "
                                          "is in no room of the floor plan", final_pose=pose)
        if here == room:
            return ExecutionResult.ok(f"already in the {room}", final_pose=pose, details={"room": room})
        route = graph.room_route(here, room)
        if route is None:
            return ExecutionResult.failed(ExecutionStatus.NO_PATH, f"no door leads from the {here} to the {room}",
                                          final_pose=pose, details={"room": room})
        sim_seconds = distance = 0.0
        result = None
        for a, b in zip(route[:-1], route[1:]):
            crossing = door_crossing(self.world, graph.graph[a][b]["door"], a, b, depth_m)
            final = b == room
            # through the door's centre only on the last door; on the way, aim just inside the next room
            result = self.go_to(robot, (crossing.inside.x, crossing.inside.y),
                                crossing.inside.theta if final else None)
            sim_seconds += result.sim_seconds
            distance += result.distance_m
            if not result.success:
                break
        return _accumulate(result, sim_seconds, distance, replace_totals=True, room=room, rooms=route)

    def look_around(self, robot: DrivableRobot, on_frame: Callable[[DepthFrame, Pose2D], bool | None], *,
                    step_rad: float = math.pi / 4, full_turn: bool = True) -> ExecutionResult:
        """Turn on the spot in steps of ``step_rad``, handing each stop's depth frame and world
        pose to ``on_frame`` (perception); stop early when it returns True (found what it
        looks for). ``details.frames`` counts the frames taken, ``details.found`` says whether
        ``on_frame`` said so. Searching for a reference the robot cannot see yet (4.3 II.D)."""
        if step_rad <= 0:
            raise ValueError(f"step_rad must be a positive angle in radians, got {step_rad}")
        steps = int(math.ceil(2 * math.pi / step_rad)) if full_turn else 1
        start = self.pose(robot)
        sim_seconds, frames = 0.0, 0
        for k in range(steps):
            if k > 0:
                turned = self.follower.turn_to(robot, start.theta + k * step_rad, localizer=self.localizer)
                sim_seconds += turned.sim_seconds
                if not turned.success:
                    return _accumulate(turned, sim_seconds, 0.0, replace_totals=True, frames=frames, found=False)
            frames += 1
            if on_frame(robot.depth_frame(), self.pose(robot)):
                return ExecutionResult.ok("found while looking around", final_pose=self.pose(robot),
                                          sim_seconds=sim_seconds, details={"frames": frames, "found": True})
        return ExecutionResult.ok("looked all around", final_pose=self.pose(robot), sim_seconds=sim_seconds,
                                  details={"frames": frames, "found": False})


def _accumulate(result: ExecutionResult, sim_seconds: float, distance: float, replace_totals: bool = False,
                **details) -> ExecutionResult:
    if replace_totals:
        result = replace(result, sim_seconds=sim_seconds, distance_m=distance)
    return result.with_details(**details)


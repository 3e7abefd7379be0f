"""The one context every robot task (a fetch, a search) runs in, passed in explicitly.

A :class:`TaskContext` holds what a task drives and senses with — the robot, the furniture
perception (the environment model being built), the depth-obstacle map, the localizer and the
navigator built over them — and what it is held to: the robot-time budget and the event
callback. It also keeps the running totals every task reports the same way (metres driven,
robot seconds used, the latest sighting of each object). :class:`BudgetSpent` is raised by
:meth:`TaskContext.step` once the budget is used up; the task catches it and returns a
``timeout`` result.

Tasks receive a context instead of building their own localizer, navigator and map, so the
application layer (or a test) decides how a task is set up, and two tasks can share one.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from assistant.executor.localization import FloorplanLocalizer
from assistant.executor.navigation import Navigator
from assistant.executor.obstacles import DepthObstacles
from assistant.executor.outcome import ExecutionResult
from assistant.executor.sensing import FurnitureSource
from assistant.executor.sightings import place_sightings
from assistant.geometry import Pose2D, wrap_angle
from assistant.perception.objects import Sighting
from assistant.robot.frames import DepthFrame
from assistant.world import World

__all__ = ["BudgetSpent", "FrameListener", "TaskContext", "moved_enough"]

#: called with each depth frame and the robot's world pose when it was taken
FrameListener = Callable[[DepthFrame, Pose2D], object]


class BudgetSpent(Exception):
    """Raised inside a task when its robot-time budget is spent (the task returns ``timeout``)."""


@dataclass
class TaskContext:
    """What a task drives and senses with, and what it is held to (module docstring).

    ``max_sim_seconds``: the robot-time budget of the task; ``on_event(name, data)``: progress
    events (``entered``, ``node``, ``move_to``, ``objects_seen``…), or None. ``start_s`` is the
    robot clock when the context was made; ``distance_m`` the metres driven since;
    ``seen`` maps each object name to its latest placed :class:`Sighting`.
    """

    world: World
    robot: object
    perception: FurnitureSource
    obstacles: DepthObstacles
    navigator: Navigator
    localizer: FloorplanLocalizer | None
    max_sim_seconds: float
    on_event: Callable[[str, dict], None] | None = None
    start_s: float = 0.0
    distance_m: float = 0.0
    seen: dict[str, Sighting] = field(default_factory=dict)

    @classmethod
    def start(cls, world: World, robot, perception: FurnitureSource, *, max_sim_seconds: float,
              on_event: Callable[[str, dict], None] | None = None, localize: bool = True,
              max_replans: int = 10, look_first: bool = False) -> "TaskContext":
        """A context for ``robot`` (connected) in ``world``: a depth-obstacle map over the
        floor plan and ``perception``'s furniture, a floor-plan localizer (unless not
        ``localize``) that hands every frame it reads to the map and to the listeners added
        with :meth:`add_frame_listener`, and a navigator over both. ``look_first``: the robot
        turns once on the spot before anything else, its depth frames going to the obstacle map
        — a robot that starts where an earlier task left it, between a couch and a table,
        otherwise plans its first path through them (it knows rooms, not furniture) and bumps
        into one (the disc turns on the spot without touching anything); it ends facing the way
        it started, so "turn around" after it turns from where the last task left it."""
        obstacles = DepthObstacles(world, entities=perception.furniture)
        localizer = FloorplanLocalizer(world, listeners=[obstacles.add_frame]) if localize else None
        navigator = Navigator(world, obstacles.occupancy, localizer=localizer, max_replans=max_replans)
        if look_first:
            heading = navigator.pose(robot).theta
            def mark(frame, pose) -> bool:
                obstacles.add_frame(frame, pose)
                return False  # look all the way round

            navigator.look_around(robot, mark)
            navigator.follower.turn_to(robot, heading, localizer=localizer)
        return cls(world, robot, perception, obstacles, navigator, localizer, float(max_sim_seconds),
                   on_event, robot.odometry().timestamp_s)

    # ------------------------------------------------------------------ sensing
    def add_frame_listener(self, listener: FrameListener) -> None:
        """Also hand ``listener`` the frames the localizer reads while the robot drives."""
        if self.localizer is not None:
            self.localizer.listeners.append(listener)

    def pose(self) -> Pose2D:
        """The robot's best world pose now (odometry corrected by the localizer)."""
        return self.navigator.pose(self.robot)

    def report_sightings(self, sightings: Sequence[Sighting], pose: Pose2D) -> list[Sighting]:
        """Place the object detector's ``sightings`` (room from the floor plan, support among
        the perceived furniture), keep the latest of each object and send them as one
        ``objects_seen`` event ``{"seen": [...], "pose": pose}``; returns them placed."""
        placed = place_sightings(self.world, self.perception.furniture(), sightings)
        for item in placed:
            self.seen[item.name] = item
        self.event("objects_seen", seen=placed, pose=pose)
        return placed

    # ------------------------------------------------------------------ time and events
    def event(self, name: str, **data) -> None:
        if self.on_event is not None:
            self.on_event(name, data)

    def spent(self) -> float:
        """Robot seconds since the context was made."""
        return self.robot.odometry().timestamp_s - self.start_s

    def step(self, result: ExecutionResult) -> ExecutionResult:
        """Count what a motion result drove; raise :class:`BudgetSpent` past the budget."""
        self.distance_m += result.distance_m
        if self.spent() > self.max_sim_seconds:
            raise BudgetSpent()
        return result

    # ------------------------------------------------------------------ driving (budgeted)
    def go_to(self, goal_xy, heading_rad: float | None = None, snap_goal: bool = True) -> ExecutionResult:
        return self.step(self.navigator.go_to(self.robot, goal_xy, heading_rad, snap_goal=snap_goal))

    def turn_to(self, heading_rad: float) -> ExecutionResult:
        return self.step(self.navigator.follower.turn_to(self.robot, heading_rad, localizer=self.localizer))

    def face_point(self, x_m: float, y_m: float) -> ExecutionResult:
        return self.step(self.navigator.follower.face_point(self.robot, x_m, y_m, localizer=self.localizer))

    def back_off(self, distance_m: float = 0.25) -> ExecutionResult:
        """Reverse straight ``distance_m`` (metres)."""
        return self.step(self.navigator.follower.back_off(self.robot, distance_m, localizer=self.localizer))

    def look_around(self, on_frame: Callable[[DepthFrame, Pose2D], bool | None]) -> ExecutionResult:
        """A full turn on the spot, handing each stop's frame to ``on_frame`` (see
        :meth:`Navigator.look_around`)."""
        return self.step(self.navigator.look_around(self.robot, on_frame))


def moved_enough(last: Pose2D | None, pose: Pose2D, every_m: float, every_rad: float) -> bool:
    """Whether the robot has driven ``every_m`` metres or turned ``every_rad`` radians since
    ``last`` (always, when there was none): how tasks throttle perception while driving."""
    return last is None or math.hypot(pose.x - last.x, pose.y - last.y) >= every_m \
        or abs(wrap_angle(pose.theta - last.theta)) >= every_rad

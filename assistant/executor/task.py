"""What every robot task (a fetch, a search) keeps track of the same way: its events, the
robot's pose, the robot time it has used, and when perception is due while driving.

:class:`TaskSteps` is a mixin for task dataclasses that have ``on_event`` (a callable or None),
``max_sim_seconds``, ``world``, ``perception`` and, once set up, ``navigator``, ``_robot``,
``_t0`` (the robot clock at the start), ``_dist`` (metres driven) and ``_seen`` (object name →
latest sighting). :class:`BudgetSpent` is raised inside the task when
the robot time is used up; the task catches it and returns a ``timeout`` result.
"""

from __future__ import annotations

import math

from assistant.geometry import Pose2D, wrap_angle

__all__ = ["BudgetSpent", "TaskSteps"]


class BudgetSpent(Exception):
    """Raised inside a task when its simulated-time budget is spent."""


class TaskSteps:
    """Events, pose, robot time and the step budget of a task (see the module docstring)."""

    def _event(self, name: str, **data) -> None:
        if self.on_event is not None:
            self.on_event(name, data)

    def _pose(self) -> Pose2D:
        return self.navigator.pose(self._robot)

    def _spent(self) -> float:
        """Robot seconds since the task began."""
        return self._robot.odometry().timestamp_s - self._t0

    def _step(self, result):
        """Count what a motion result drove; raise :class:`BudgetSpent` past the budget."""
        self._dist += result.distance_m
        if self._spent() > self.max_sim_seconds:
            raise BudgetSpent()
        return result

    def _moved_enough(self, last: Pose2D | None, pose: Pose2D) -> bool:
        """Whether the robot has driven ``perceive_every_m`` metres or turned
        ``perceive_every_rad`` since ``last`` (always, when there was none)."""
        return last is None or math.hypot(pose.x - last.x, pose.y - last.y) >= self.perceive_every_m \
            or abs(wrap_angle(pose.theta - last.theta)) >= self.perceive_every_rad

    def _report_sightings(self, sightings, pose: Pose2D) -> list:
        """Place the object detector's ``sightings`` (room from the floor plan, support among
        the perceived furniture), keep the latest of each object and send them as one
        ``objects_seen`` event; returns the placed sightings."""
        from assistant.executor.sightings import place_sightings

        placed = place_sightings(self.world, self.perception.furniture(), sightings)
        for item in placed:
            self._seen[item.name] = item
        self._event("objects_seen", seen=placed, pose=pose)
        return placed

"""Stopping a task that is under way: "stop" said while the robot drives.

:class:`StoppableRobot` wraps a robot so that every call first checks a stop flag and raises
:class:`Stopped` once it is set — a task talks to its robot many times a second, so the stop
takes effect at once. The use cases catch :class:`Stopped` and end in a ``stopped``
:class:`~assistant.app.result.Result` that keeps what the robot saw before it stopped.
"""

from __future__ import annotations

__all__ = ["StoppableRobot", "Stopped"]


class Stopped(Exception):
    """Raised inside a task when the person asked it to stop (not an error)."""


class StoppableRobot:
    """Wraps ``robot``: each call raises :class:`Stopped` once ``stop`` (a
    :class:`threading.Event`, or None) is set; every ``every`` calls ``on_pose(pose)`` gets the
    robot's true pose when it has one (the simulator's, for the 3D view)."""

    def __init__(self, robot, stop, on_pose=None, every: int = 20):
        self._robot = robot
        self._stop = stop
        self._on_pose = on_pose
        self._every = every
        self._calls = 0

    def __getattr__(self, name):
        value = getattr(self._robot, name)
        if not callable(value):
            return value

        def call(*args, **kwargs):
            if self._stop is not None and self._stop.is_set():
                raise Stopped()
            out = value(*args, **kwargs)
            self._calls += 1
            if self._calls % self._every == 0:
                self.report_pose()
            return out

        return call

    def report_pose(self) -> None:
        """Give ``on_pose`` the robot's true pose now (also at a task's end, stopped or not: a
        conversation starts its next task where this one left the robot)."""
        pose = getattr(self._robot, "ground_truth_pose", None)
        if self._on_pose is not None and pose is not None:
            try:
                self._on_pose(pose)
            except Exception:  # drawing is a courtesy: a viewer's problem must not stop the task
                pass

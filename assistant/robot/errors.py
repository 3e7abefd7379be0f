"""Typed errors of robot adapters: a lost or missing connection, a bad command.

All are :class:`~assistant.errors.AssistantError` s, so the command line prints them as one
line and the dialogue turns them into a sentence; the connection errors are also
:class:`ConnectionError` s, so code that handles I/O failures generically still catches them.
"""

from __future__ import annotations

from assistant.errors import AssistantError

__all__ = [
    "DeviceAlreadyConnectedError",
    "DeviceNotConnectedError",
    "RobotConnectionError",
    "RobotError",
]


class RobotError(AssistantError):
    """Something a robot adapter cannot do; the message says what to do about it."""


class RobotConnectionError(RobotError, ConnectionError):
    """The connection to the robot (serial port, camera, recording, simulator) failed or was lost."""


class DeviceNotConnectedError(RobotConnectionError):
    """A command or a read on a robot that is not connected (never connected, or closed)."""

    def __init__(self, robot: str, action: str):
        self.robot = robot
        self.action = action
        super().__init__(f"{robot} is not connected: cannot {action}; call connect() first "
                         "(or use the robot in a `with` block)")


class DeviceAlreadyConnectedError(RobotError):
    """``connect()`` on a robot that is already connected."""

    def __init__(self, robot: str):
        self.robot = robot
        super().__init__(f"{robot} is already connected; close() it before connecting again")

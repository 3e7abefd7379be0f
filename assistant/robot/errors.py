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
    "HandshakeError",
    "LinkLostError",
    "MotorsDisabledError",
    "NoCameraError",
    "RobotConnectionError",
    "RobotError",
    "SerialPortError",
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


class SerialPortError(RobotConnectionError):
    """The serial port cannot be opened: missing, busy, or not permitted."""

    def __init__(self, port: str, problem: str, fix: str):
        self.port = port
        self.problem = problem
        super().__init__(f"cannot open serial port {port}: {problem}; {fix}")


class HandshakeError(RobotConnectionError):
    """The robot controller did not answer the connection handshake (SYNC0/1/2)."""

    def __init__(self, port: str, detail: str):
        self.port = port
        super().__init__(f"no robot controller answered on {port} ({detail}); check that the robot "
                         "is switched on, the serial cable sits in the controller's HOST port, and "
                         "no other program holds the port (then run `assistant doctor`)")


class LinkLostError(RobotConnectionError):
    """The link to a connected base failed mid-session; the motors were commanded to stop.

    ``reason`` is one of :data:`LINK_LOST_REASONS`: ``"port vanished"`` (the adapter was
    unplugged or the port closed), ``"silent controller"`` (no bytes for longer than the
    watchdog period), ``"garbled data"`` (bytes, but no valid status packet for that long).
    """

    def __init__(self, robot: str, reason: str, detail: str = ""):
        self.robot = robot
        self.reason = reason
        self.detail = detail
        extra = f" ({detail})" if detail else ""
        super().__init__(f"{robot}: link lost, {reason}{extra}; the motors were commanded to stop. "
                         "Check the cable and the robot's power, then connect again")


#: The reasons a :class:`LinkLostError` gives.
LINK_LOST_REASONS = ("port vanished", "silent controller", "garbled data")


class NoCameraError(RobotError):
    """A depth frame asked of a base that has no camera attached."""

    def __init__(self, robot: str):
        self.robot = robot
        super().__init__(f"{robot} has no depth camera attached; plug in the Kinect and connect it "
                         "(or build the robot with a camera), or use `--robot sim` to try the "
                         "assistant without one")


class MotorsDisabledError(RobotError):
    """A drive command while the base reports its motors disabled (motor switch or e-stop)."""

    def __init__(self, robot: str):
        self.robot = robot
        super().__init__(f"{robot}: the motors are disabled; release the emergency stop and press "
                         "the MOTORS button on the robot's panel (or reconnect), then try again")

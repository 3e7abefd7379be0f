"""The one robot interface every adapter implements (simulator, replay, P3-DX + Kinect).

A :class:`Robot` is connected before use and closed after, or used as a context manager::

    with SimRobot(load_world("apartment")) as robot:
        robot.send_velocity(0.3, 0.0)
        robot.advance(2.0)            # let 2 s of robot time pass
        frame = robot.depth_frame()   # DepthFrame: depth, intrinsics, mount, pose at capture
        print(robot.odometry().pose)

Every read or command on a robot that is not connected raises
:class:`~assistant.robot.errors.DeviceNotConnectedError`; a connection lost mid-session raises
:class:`~assistant.robot.errors.RobotConnectionError`. ``close()`` stops the base first and may be
called any number of times. The contract is checked for every adapter by
:mod:`assistant.robot.contract`.
"""

from __future__ import annotations

import abc

from assistant.robot.errors import DeviceAlreadyConnectedError, DeviceNotConnectedError
from assistant.robot.frames import DepthFrame, Odometry

__all__ = ["Robot"]


class Robot(abc.ABC):
    """A mobile base with a depth camera: odometry, depth frames, velocity commands.

    Units: metres, radians, seconds; poses in the world frame. Subclasses implement the
    ``_``-prefixed hooks; the public methods check the connection first.
    """

    #: A short name for messages ("simulated robot", "P3-DX on /dev/ttyUSB0"…).
    name: str = "robot"
    #: False for an adapter whose motion does not follow velocity commands (a replay).
    follows_commands: bool = True

    def __init__(self) -> None:
        self._connected = False

    # ---------------------------------------------------------------- connection
    @property
    def is_connected(self) -> bool:
        return self._connected

    def connect(self) -> "Robot":
        """Open the connection (serial port, camera, file, simulator); returns ``self``.

        Raises :class:`DeviceAlreadyConnectedError` when already connected and
        :class:`~assistant.robot.errors.RobotConnectionError` when the device cannot be reached
        (after releasing anything half-opened).
        """
        if self._connected:
            raise DeviceAlreadyConnectedError(self.name)
        self._connect()
        self._connected = True
        return self

    def close(self) -> None:
        """Stop the base and release the connection; safe to call more than once."""
        if not self._connected:
            return
        try:
            self._stop()
        finally:
            self._connected = False
            self._close()

    def __enter__(self) -> "Robot":
        if not self._connected:
            self.connect()
        return self

    def __exit__(self, *exc_info) -> None:
        self.close()

    def _require(self, action: str) -> None:
        if not self._connected:
            raise DeviceNotConnectedError(self.name, action)

    # ---------------------------------------------------------------- public API
    def odometry(self) -> Odometry:
        """The latest odometry: pose estimate (world frame), velocity, timestamp."""
        self._require("read odometry")
        return self._odometry()

    def depth_frame(self) -> DepthFrame:
        """The latest depth frame, with its intrinsics, camera mount and the pose at capture."""
        self._require("read a depth frame")
        return self._depth_frame()

    def send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        """Command a forward speed (m/s) and a turn rate (rad/s, counter-clockwise positive).

        The adapter clamps to the base's limits; non-finite values raise :class:`ValueError`.
        """
        self._require("send a velocity command")
        self._send_velocity(float(linear_m_s), float(angular_rad_s))

    def stop(self) -> None:
        """Command zero velocity."""
        self._require("stop")
        self._stop()

    def advance(self, seconds: float) -> None:
        """Let ``seconds`` of robot time pass while the last command runs.

        A simulator integrates its motion (simulated time); hardware waits in real time; a
        replay moves through its recording.
        """
        self._require("advance time")
        if not (seconds >= 0):
            raise ValueError(f"seconds must be a non-negative number, got {seconds}")
        self._advance(float(seconds))

    @property
    def time_s(self) -> float:
        """Robot time in seconds (simulated, recorded or wall-clock since connect)."""
        self._require("read the clock")
        return self._time_s()

    @property
    def bumped(self) -> bool:
        """True when the base has stopped against an obstacle since the last command."""
        self._require("read the bumpers")
        return self._bumped()

    # ---------------------------------------------------------------- hooks
    @abc.abstractmethod
    def _connect(self) -> None: ...

    @abc.abstractmethod
    def _close(self) -> None: ...

    @abc.abstractmethod
    def _odometry(self) -> Odometry: ...

    @abc.abstractmethod
    def _depth_frame(self) -> DepthFrame: ...

    @abc.abstractmethod
    def _send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None: ...

    @abc.abstractmethod
    def _stop(self) -> None: ...

    @abc.abstractmethod
    def _advance(self, seconds: float) -> None: ...

    @abc.abstractmethod
    def _time_s(self) -> float: ...

    def _bumped(self) -> bool:
        return False

    def __repr__(self) -> str:
        state = "connected" if self._connected else "not connected"
        return f"<{type(self).__name__} {self.name} ({state})>"

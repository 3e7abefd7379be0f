"""``P3DX``: a Pioneer P3-DX base with a depth camera behind the one Robot interface.

The base speaks ARCOS over a serial port (:class:`~assistant.robot.p3dx.link.ArcosLink`); the
camera is any object with ``depth_frame()`` and ``close()`` (and optionally ``connect()``) —
the Kinect adapter, a recorded stream, or a test stand-in. Without a camera
(``camera=None``) the base still drives and ``depth_frame()`` raises
:class:`~assistant.robot.errors.NoCameraError`. Each frame gets the base's odometry pose and
robot time at the moment it is read.

The motors are commanded to stop on every way out: ``close()`` (and so a ``with`` block left by
an exception), Ctrl-C or any exception inside ``advance()``, the interpreter exiting with the
robot still open, a lost link (see :mod:`~assistant.robot.p3dx.link`), and a bump or stall.
:attr:`P3DX.stop_reason` says which stopped it last.
"""

from __future__ import annotations

import atexit
import dataclasses
import logging
import math
import time
from typing import Protocol, runtime_checkable

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.robot.errors import LinkLostError, MotorsDisabledError, NoCameraError
from assistant.robot.frames import DepthFrame, Odometry
from assistant.robot.interface import Robot
from assistant.robot.p3dx.link import ArcosLink, ControllerInfo
from assistant.robot.p3dx.params import P3DXParams, load_p3dx_params

__all__ = ["DepthCamera", "P3DX", "p3dx_robot_from_spec"]

log = logging.getLogger(__name__)

#: every connected P3DX (strong references: a robot dropped without close() is still stopped at exit)
_OPEN_ROBOTS: "set[P3DX]" = set()
_POLL_S = 0.02


@runtime_checkable
class DepthCamera(Protocol):
    """What :class:`P3DX` needs of a camera."""

    def depth_frame(self) -> DepthFrame: ...

    def close(self) -> None: ...


class P3DX(Robot):
    """A P3-DX on serial ``port`` with ``camera`` (or none); see the module docstring.

    ``params`` defaults to ``hardware/p3dx.yaml``; ``max_linear_m_s`` / ``max_angular_rad_s``
    lower its speed limits (a first drive); ``start`` is the world pose at connect.
    """

    def __init__(self, port: str, camera: DepthCamera | None = None, *, params: P3DXParams | None = None,
                 start: Pose2D | None = None, max_linear_m_s: float | None = None,
                 max_angular_rad_s: float | None = None):
        super().__init__()
        if not port:
            raise ValueError("a P3-DX needs a serial port, e.g. /dev/ttyUSB0")
        if camera is not None and not isinstance(camera, DepthCamera):
            raise TypeError(f"camera must have depth_frame() and close(), got {type(camera).__name__}")
        self.port = port
        self.camera = camera
        base = params or load_p3dx_params()
        self.params = base.limited(max_linear_m_s, max_angular_rad_s)
        self.start = start or Pose2D(0.0, 0.0, 0.0)
        self.name = f"P3-DX on {port}"
        self._link: ArcosLink | None = None
        self._closing = False
        self._stop_reason: str | None = None

    # ---------------------------------------------------------------- extras
    @property
    def stop_reason(self) -> str | None:
        """Why the base was last commanded to stop: ``"stop()"``, ``"close()"``, ``"bump"``,
        ``"stall"``, ``"interrupted (Ctrl-C)"``, ``"error: …"``, ``"link lost: …"``,
        ``"interpreter exit"``; None before any stop."""
        link = self._link
        return link.stop_reason if link is not None else self._stop_reason

    @property
    def controller(self) -> ControllerInfo:
        """The controller's name, class and subclass from the handshake."""
        self._require("read the controller's name")
        return self._live_link().info

    @property
    def battery_v(self) -> float | None:
        self._require("read the battery")
        sip = self._live_link().last_sip
        return None if sip is None else sip.battery_v

    @property
    def line_stats(self):
        """The serial line's health: packets decoded, bad checksums, bytes skipped (DecoderStats)."""
        self._require("read the line statistics")
        return self._live_link().line_stats

    def sonar_m(self) -> dict[int, float]:
        """The latest sonar ranges (metres) by sonar number."""
        self._require("read the sonar")
        return self._live_link().sonar_m()

    # ---------------------------------------------------------------- hooks
    def _connect(self) -> None:
        link = ArcosLink(self.port, self.params, start=self.start, name=self.name)
        link.open()
        self._link = link
        try:
            opener = getattr(self.camera, "connect", None) or getattr(self.camera, "open", None)
            if callable(opener) and not getattr(self.camera, "is_connected", False):
                opener()
        except BaseException as error:
            self._link = None
            link.close()
            log.error("%s: the camera did not start (%s); the base is closed again. To drive without "
                      "it, use the robot spec p3dx:%s:nocamera", self.name, error, self.port)
            raise
        self._stop_reason = None
        _OPEN_ROBOTS.add(self)

    def _close(self) -> None:
        _OPEN_ROBOTS.discard(self)
        link, self._link = self._link, None
        if link is not None:
            self._stop_reason = link.stop_reason
        try:
            if self.camera is not None:
                self.camera.close()
        finally:
            if link is not None:
                link.close()

    def _live_link(self) -> ArcosLink:
        assert self._link is not None  # the public methods checked the connection
        self._link.touch()
        return self._link

    def _odometry(self) -> Odometry:
        return self._live_link().odometry()

    def _depth_frame(self) -> DepthFrame:
        if self.camera is None:
            raise NoCameraError(self.name)
        link = self._live_link()
        frame = self.camera.depth_frame()
        odometry = link.odometry()
        return dataclasses.replace(frame, robot_pose=odometry.pose, timestamp_s=link.time_s())

    def _send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        if not (math.isfinite(linear_m_s) and math.isfinite(angular_rad_s)):
            raise ValueError(f"velocities must be finite, got ({linear_m_s}, {angular_rad_s})")
        p = self.params
        linear = max(-p.max_linear_m_s, min(p.max_linear_m_s, linear_m_s))
        angular = max(-p.max_angular_rad_s, min(p.max_angular_rad_s, angular_rad_s))
        link = self._live_link()
        command = (int(round(linear * 1000)), int(round(math.degrees(angular))))
        if command != (0, 0) and link.motors_disabled:
            link.stop("motors disabled")
            raise MotorsDisabledError(self.name)
        link.drive(*command)

    def _stop(self, reason: str | None = None) -> None:
        reason = reason or ("close()" if self._closing else "stop()")
        link = self._link
        if link is not None:
            link.stop(reason)
        self._stop_reason = reason

    def _advance(self, seconds: float) -> None:
        link = self._live_link()
        deadline = time.monotonic() + seconds
        try:
            while True:
                link.touch()
                link.odometry()  # raises the link's fault, if any
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    return
                link.failed.wait(min(remaining, _POLL_S))
        except LinkLostError:
            raise  # the link has already commanded STOP and recorded why
        except KeyboardInterrupt:
            self._stop("interrupted (Ctrl-C)")
            log.warning("%s: interrupted: motors commanded to stop", self.name)
            raise
        except BaseException as error:
            self._stop(f"error: {type(error).__name__}")
            raise

    def _time_s(self) -> float:
        return self._live_link().time_s()

    def _bumped(self) -> bool:
        return self._live_link().bumped

    def close(self) -> None:
        self._closing = True
        try:
            super().close()
        finally:
            self._closing = False


def p3dx_robot_from_spec(argument: str = "", *, camera: DepthCamera | None | str = "kinect",
                         world=None, start: Pose2D | None = None, **options) -> P3DX:
    """The ``p3dx`` adapter of :func:`assistant.robot.factory.make_robot`.

    ``argument`` is the serial port (``/dev/ttyUSB0``), optionally followed by ``:nocamera``
    for a base without its camera. ``camera`` is a camera object, None for a base without one,
    or ``"kinect"`` (the default) for the Kinect adapter when it can be loaded — when it cannot,
    the base comes without a camera and says why in the log. ``start`` is where the base stands
    when it connects; by default the start pose of ``world`` (a :class:`~assistant.world.World`
    or a home's name) when one is given — the robot is placed there in the home — else the
    origin. Other options go to :class:`P3DX`.
    """
    port, _, flag = argument.partition(":")
    port = port or "/dev/ttyUSB0"
    if flag:
        if flag.strip().lower() != "nocamera":
            raise AssistantError(f"unknown p3dx option {flag!r}; use p3dx:PORT or p3dx:PORT:nocamera")
        camera = None
    if isinstance(camera, str):
        camera = _named_camera(camera)
    if start is None and world is not None:
        if isinstance(world, str):
            from assistant.world import load_world

            world = load_world(world)
        start = world.start
    return P3DX(port, camera, start=start, **options)


def _named_camera(name: str) -> DepthCamera | None:
    if name != "kinect":
        raise AssistantError(f"unknown camera {name!r}; use 'kinect', None or a camera object")
    try:
        from assistant.robot import kinect  # another adapter of this layer, optional
    except ImportError as error:
        log.warning("no Kinect adapter (%s): the P3-DX runs without a depth camera", error)
        return None
    maker = getattr(kinect, "Kinect", None)
    if maker is None:
        log.warning("the Kinect adapter has no Kinect class: the P3-DX runs without a depth camera")
        return None
    return maker()


@atexit.register
def _stop_open_robots() -> None:
    """At interpreter exit, stop and close every P3-DX still open (the last safety net in Python)."""
    for robot in list(_OPEN_ROBOTS):
        try:
            robot._stop("interpreter exit")
            robot.close()
        except Exception as error:  # noqa: BLE001 - exiting: report and go on to the next robot
            log.error("%s: could not close cleanly at exit: %s", robot.name, error)

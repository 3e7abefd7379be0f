"""``RecordingRobot``: any robot, with everything that passes through it written to an MCAP file.

Wrap a robot and use the wrapper in its place (the executor, the dialogue and the command line
do not know the difference)::

    with RecordingRobot(make_robot("sim:apartment"), "session.mcap", {"world": "apartment"}) as robot:
        run_task(robot)

Every depth frame and odometry reading the caller receives, every velocity command it sends and
every dialogue turn it reports (:meth:`RecordingRobot.record_turn`) is appended to the file as it
happens (:class:`~assistant.robot.recording.writer.SessionWriter`).

The caller receives each reading *as the recording holds it* — depth in whole millimetres, times
in whole nanoseconds, headings through a quaternion — so a replay of the file gives the caller
exactly what the live session gave it, and a deterministic task makes the same decisions on the
replay. (Depth is whole millimetres already from a real Kinect and from the simulator's noise
model; headings change in their last bits.) Evaluation-only data (the simulator's hit ids) is
passed through but not recorded.
"""

from __future__ import annotations

import functools
import os

from assistant.robot.frames import CameraMount, DepthFrame, Odometry
from assistant.robot.interface import Robot
from assistant.robot.recording import messages as msgs
from assistant.robot.recording.writer import SessionWriter

__all__ = ["RecordingRobot"]


class RecordingRobot(Robot):
    """``robot`` with its session written to ``path`` (see the module docstring).

    ``metadata`` describes the session (``world``, ``scene``… as strings). ``overwrite`` allows
    replacing an existing file; connecting again after ``close()`` starts the file anew only
    with ``overwrite`` (otherwise it raises, keeping the first recording).
    """

    def __init__(self, robot: Robot, path: str | os.PathLike[str], metadata: dict[str, str] | None = None, *,
                 overwrite: bool = False):
        super().__init__()
        self.inner = robot
        self.path = str(path)
        self.session_metadata = {"robot": robot.name, **(metadata or {})}
        self.overwrite = overwrite
        self.follows_commands = robot.follows_commands
        self.name = f"{robot.name}, recording to {os.path.basename(self.path)}"
        self.writer: SessionWriter | None = None
        self._last_inner_frame: DepthFrame | None = None
        self._last_frame: DepthFrame | None = None
        self._last_odometry_key: tuple | None = None

    def __getattr__(self, name: str):
        # the wrapped robot's own extras (a simulator's world, its ground truth for evaluation…)
        if name.startswith("_") or name == "inner":
            raise AttributeError(name)
        return getattr(self.inner, name)

    def record_turn(self, speaker: str, text: str) -> None:
        """Add a dialogue turn (``speaker`` "user" or "robot") at the robot's current time."""
        self._require("record a dialogue turn")
        self.writer.write_turn(speaker, text, self.inner.time_s)

    # ---------------------------------------------------------------- hooks
    def _connect(self) -> None:
        if not self.inner.is_connected:
            self.inner.connect()
        try:
            self.writer = SessionWriter(self.path, self.session_metadata, overwrite=self.overwrite)
        except BaseException:
            self.inner.close()
            raise
        self._last_inner_frame = self._last_frame = None
        self._last_odometry_key = None

    def _close(self) -> None:
        try:
            end_s = self.inner.time_s if self.inner.is_connected else None
            if self.writer is not None:
                self.writer.close(end_s=end_s)
        finally:
            self.inner.close()

    def _odometry(self) -> Odometry:
        live = self.inner.odometry()
        key = (live.timestamp_s, live.pose, live.linear_m_s, live.angular_rad_s)
        if key != self._last_odometry_key:
            self.writer.write_odometry(live)  # the live values: encoding twice would change headings
            self._last_odometry_key = key
        return _as_recorded_odometry(live)

    def _depth_frame(self) -> DepthFrame:
        live = self.inner.depth_frame()
        if live is self._last_inner_frame and self._last_frame is not None:
            return self._last_frame
        millimetres = live.to_millimetres()
        pose = None if live.robot_pose is None else msgs.round_trip_pose(live.robot_pose)
        frame = DepthFrame(msgs.depth_from_millimetres(millimetres), live.intrinsics, _as_recorded_mount(live.mount),
                           pose, msgs.from_ns(msgs.to_ns(live.timestamp_s)), live.hit_ids, live.hit_names)
        self.writer.write_frame(millimetres, live.intrinsics, live.mount, live.robot_pose, live.timestamp_s)
        self._last_inner_frame, self._last_frame = live, frame
        return frame

    def _send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        self.inner.send_velocity(linear_m_s, angular_rad_s)
        self.writer.write_command(linear_m_s, angular_rad_s, self.inner.time_s)

    def _stop(self) -> None:
        self.inner.stop()
        if self.writer is not None and not self.writer.closed:
            self.writer.write_command(0.0, 0.0, self.inner.time_s)

    def _advance(self, seconds: float) -> None:
        self.inner.advance(seconds)

    def _time_s(self) -> float:
        return msgs.from_ns(msgs.to_ns(self.inner.time_s))  # the clock as a replay of this file keeps it

    def _bumped(self) -> bool:
        return self.inner.bumped


def _as_recorded_odometry(odometry: Odometry) -> Odometry:
    return Odometry(msgs.round_trip_pose(odometry.pose), odometry.linear_m_s, odometry.angular_rad_s,
                    msgs.from_ns(msgs.to_ns(odometry.timestamp_s)))


@functools.lru_cache(maxsize=16)
def _as_recorded_mount(mount: CameraMount) -> CameraMount:
    return msgs.mount_from_tf(msgs.mount_message(mount, 0))

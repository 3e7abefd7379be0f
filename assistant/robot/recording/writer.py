"""``SessionWriter``: a robot session written to an MCAP file as it happens.

Each message goes to disk in its own zstd-compressed MCAP chunk the moment it is added (and the
file is synced to the disk at most every ``sync_every_s`` seconds of wall-clock time), so a
recording cut by a crash or a power loss reads back up to its last complete message
(:func:`~assistant.robot.recording.reader.read_session` stops at the cut). ``close()`` writes
MCAP's summary section, which lets viewers seek; a cut file has none and is read from the start.

The file is written under its final name from the first message on: a recording is a log, and
a half-written log is worth more than none. A file already at that path is refused unless
``overwrite`` is given.
"""

from __future__ import annotations

import datetime
import os
import time
from pathlib import Path

import numpy as np

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame, Odometry
from assistant.robot.recording import messages as msgs

__all__ = ["SESSION_END_METADATA", "SESSION_METADATA", "SessionWriter"]

#: name of the MCAP metadata record that describes a session (world, scene, robot, start time)
SESSION_METADATA = "assistant.session"
#: name of the metadata record written at a clean close: the robot time the session ended
SESSION_END_METADATA = "assistant.session_end"
PROFILE = "ros2"


class SessionWriter:
    """Append depth frames, odometry, velocity commands and dialogue turns to ``path``.

    Times are robot times in seconds (the robot's clock); they become the messages' log times
    and header stamps in nanoseconds. ``metadata`` (strings) describes the session: ``world``,
    ``scene``, ``robot``… Use as a context manager, or call :meth:`close`.
    """

    def __init__(self, path: str | os.PathLike[str], metadata: dict[str, str] | None = None, *,
                 overwrite: bool = False, sync_every_s: float = 1.0):
        from mcap.writer import CompressionType, Writer

        self.path = Path(path)
        if self.path.exists() and not overwrite:
            raise AssistantError(f"{self.path} exists; choose another file name or remove it first")
        if self.path.suffix.lower() != ".mcap":
            raise AssistantError(f"a recording is an .mcap file; got {self.path.name}")
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file = open(self.path, "wb")
        # chunk_size=1: every message closes its own chunk, so it is on disk once added
        self._writer = Writer(self._file, chunk_size=1, compression=CompressionType.ZSTD)
        self._writer.start(profile=PROFILE, library="assistant")
        info = {"format": "assistant-session/1", "started_utc": _utc_now()}
        info.update({str(k): str(v) for k, v in (metadata or {}).items()})
        self._writer.add_metadata(SESSION_METADATA, info)
        self._channels: dict[str, int] = {}
        self._sequence = 0
        self._last_ns = 0
        self._sync_every_s = sync_every_s
        self._last_sync = time.monotonic()
        self._last_mount: CameraMount | None = None
        self._last_intrinsics: CameraIntrinsics | None = None
        self.closed = False
        self._flush()

    # ---------------------------------------------------------------- public API
    def write_frame(self, millimetres: np.ndarray, intrinsics: CameraIntrinsics, mount: CameraMount,
                    robot_pose: Pose2D | None, t_s: float) -> None:
        """One depth frame: uint16 millimetres, its intrinsics, the camera mount and the base
        pose at capture; camera info and the mount are written again only when they change."""
        t_ns = msgs.to_ns(t_s)
        if mount != self._last_mount:
            self._write("/tf_static", msgs.mount_message(mount, t_ns), t_ns)
            self._last_mount = mount
        if intrinsics != self._last_intrinsics:
            self._write("/camera/depth/info", msgs.camera_info_message(intrinsics, t_ns), t_ns)
            self._last_intrinsics = intrinsics
        if robot_pose is not None:
            self._write("/camera/depth/pose", msgs.pose_stamped_message(robot_pose, t_ns), t_ns)
        self._write("/camera/depth/image", msgs.image_message(millimetres, t_ns), t_ns)

    def write_depth_frame(self, frame: DepthFrame) -> None:
        self.write_frame(frame.to_millimetres(), frame.intrinsics, frame.mount, frame.robot_pose, frame.timestamp_s)

    def write_odometry(self, odometry: Odometry) -> None:
        t_ns = msgs.to_ns(odometry.timestamp_s)
        self._write("/odom", msgs.odometry_message(odometry, t_ns), t_ns)

    def write_command(self, linear_m_s: float, angular_rad_s: float, t_s: float) -> None:
        t_ns = msgs.to_ns(t_s)
        self._write("/cmd_vel", msgs.twist_message(linear_m_s, angular_rad_s), t_ns)

    def write_turn(self, speaker: str, text: str, t_s: float) -> None:
        """One dialogue turn (``speaker`` "user" or "robot")."""
        t_ns = msgs.to_ns(t_s)
        self._write("/dialogue", msgs.string_message({"speaker": speaker, "text": text}), t_ns)

    def close(self, end_s: float | None = None) -> None:
        """Write the end time (robot seconds, when given), MCAP's summary, and close the file;
        safe to call more than once."""
        if self.closed:
            return
        self.closed = True
        try:
            if end_s is not None:
                end_ns = max(msgs.to_ns(end_s), self._last_ns)
                self._writer.add_metadata(SESSION_END_METADATA, {"end_ns": str(end_ns)})
            self._writer.finish()
            self._file.flush()
            os.fsync(self._file.fileno())
        finally:
            self._file.close()

    def __enter__(self) -> "SessionWriter":
        return self

    def __exit__(self, *exc_info) -> None:
        self.close()

    # ---------------------------------------------------------------- internals
    def _channel(self, topic: str) -> int:
        if topic not in self._channels:
            typename = msgs.TOPICS[topic]
            schema = self._writer.register_schema(typename, "ros2msg", msgs.message_definition(typename).encode())
            self._channels[topic] = self._writer.register_channel(topic, "cdr", schema)
        return self._channels[topic]

    def _write(self, topic: str, message, t_ns: int) -> None:
        if self.closed:
            raise AssistantError(f"the recording {self.path} is closed; start a new one")
        # log times never go back, so the file reads in time order without sorting
        t_ns = max(t_ns, self._last_ns)
        self._last_ns = t_ns
        data = msgs.serialize(message, msgs.TOPICS[topic])
        self._writer.add_message(self._channel(topic), log_time=t_ns, data=data, publish_time=t_ns,
                                 sequence=self._sequence)
        self._sequence += 1
        self._flush()

    def _flush(self) -> None:
        self._file.flush()
        now = time.monotonic()
        if now - self._last_sync >= self._sync_every_s:
            os.fsync(self._file.fileno())
            self._last_sync = now


def _utc_now() -> str:
    """Now in UTC, or ``$SOURCE_DATE_EPOCH`` when set (the reproducible-builds convention), so a
    recording regenerated from the same commands is the same file byte for byte."""
    fixed = os.environ.get("SOURCE_DATE_EPOCH")
    when = (datetime.datetime.fromtimestamp(int(fixed), datetime.timezone.utc) if fixed and fixed.isdigit()
            else datetime.datetime.now(datetime.timezone.utc))
    return when.isoformat(timespec="seconds")

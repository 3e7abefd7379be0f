"""Other people's recordings as event streams: ROS 1 / ROS 2 bags and TUM RGB-D folders.

* :class:`BagSource` reads a ROS 1 ``.bag`` or a ROS 2 bag folder (sqlite3 or MCAP storage)
  with ``rosbags``: the first depth image topic (``16UC1`` millimetres or ``32FC1`` metres),
  its camera info, ``nav_msgs/Odometry`` and ``geometry_msgs/Twist`` commands.
* :class:`TumSource` reads a TUM RGB-D style folder: ``depth.txt`` (``timestamp path`` per
  line), 16-bit depth PNGs (``depth_scale`` metres per unit, 1/5000 by default) and, when
  present, ``groundtruth.txt`` (``timestamp tx ty tz qx qy qz qw``), whose camera poses are
  projected onto the floor (x, y and the heading of the optical axis) as the robot's odometry.

Neither format says where the camera sits on the robot, so the mount comes from the caller
(``camera_height_m``, ``tilt_deg``; the product's defaults otherwise), and a bag without camera
info gets the Kinect's intrinsics scaled to its image size.
"""

from __future__ import annotations

import functools
import heapq
import math
import os
from collections.abc import Iterator
from pathlib import Path

import numpy as np

from assistant.geometry import Pose2D
from assistant.robot.frames import CameraIntrinsics, CameraMount, Odometry
from assistant.robot.recording import messages as msgs
from assistant.robot.recording.reader import (
    FRAME, INTRINSICS, MOUNT, ODOMETRY, Event, MessageDecoder, RecordingError,
)

__all__ = ["BagSource", "TumSource", "mount_from_options", "scaled_kinect_intrinsics"]

#: TUM RGB-D depth PNGs: 5000 units per metre
TUM_DEPTH_SCALE = 1.0 / 5000.0


def mount_from_options(camera_height_m: float | None = None, tilt_deg: float | None = None) -> CameraMount:
    default = CameraMount()
    return CameraMount(height_m=default.height_m if camera_height_m is None else float(camera_height_m),
                       tilt_rad=default.tilt_rad if tilt_deg is None else math.radians(float(tilt_deg)))


class BagSource:
    """A ROS 1 bag file or a ROS 2 bag folder as events (see the module docstring)."""

    def __init__(self, path: str | os.PathLike[str], depth_topic: str | None = None,
                 camera_height_m: float | None = None, tilt_deg: float | None = None):
        self.path = Path(path)
        self.depth_topic = depth_topic
        self.mount = mount_from_options(camera_height_m, tilt_deg)
        self.metadata = {"format": "ros-bag", "source": str(self.path)}
        self.truncated = False
        self._check()

    def _reader(self):
        from rosbags.highlevel import AnyReader

        return AnyReader([self.path], default_typestore=msgs.typestore())

    def _check(self) -> None:
        from rosbags.highlevel import AnyReaderError

        try:
            with self._reader() as reader:
                types = {msgs.ros2_type_name(c.msgtype) for c in reader.connections}
        except AnyReaderError as error:
            raise RecordingError(f"cannot read the bag {self.path}: {error}") from error
        if "sensor_msgs/msg/Image" not in types:
            raise RecordingError(f"{self.path} has no sensor_msgs/Image topic; a replay needs depth images")

    def events(self) -> Iterator[Event]:
        decoder = MessageDecoder(self.depth_topic)
        first = True
        with self._reader() as reader:
            wanted = [c for c in reader.connections if decoder.wants(c.topic, msgs.ros2_type_name(c.msgtype))]
            for connection, t_ns, raw in reader.messages(connections=wanted):
                if first:
                    yield Event(int(t_ns), MOUNT, self.mount)
                    first = False
                message = reader.deserialize(raw, connection.msgtype)
                event = decoder.decode(connection.topic, msgs.ros2_type_name(connection.msgtype), message, int(t_ns))
                if event is not None:
                    yield event


class TumSource:
    """A TUM RGB-D style folder as events (see the module docstring)."""

    def __init__(self, path: str | os.PathLike[str], depth_scale: float = TUM_DEPTH_SCALE,
                 intrinsics: CameraIntrinsics | None = None, camera_height_m: float | None = None,
                 tilt_deg: float | None = None):
        self.path = Path(path)
        self.depth_scale = float(depth_scale)
        self.mount = mount_from_options(camera_height_m, tilt_deg)
        self.metadata = {"format": "tum-rgbd", "source": str(self.path)}
        self.truncated = False
        self.frames = _read_table(self.path / "depth.txt", 1)
        if not self.frames:
            raise RecordingError(f"{self.path / 'depth.txt'} lists no depth images ('timestamp path' per line)")
        for _, (name,) in self.frames[:1]:
            if not (self.path / name).is_file():
                raise RecordingError(f"{self.path / 'depth.txt'} names {name}, which is not in {self.path}")
        truth = self.path / "groundtruth.txt"
        self.poses = _read_table(truth, 7) if truth.is_file() else []
        self.intrinsics = intrinsics

    def _depth_m(self, name: str) -> np.ndarray:
        from PIL import Image

        with Image.open(self.path / name) as image:
            units = np.asarray(image)
        if units.ndim != 2:
            raise RecordingError(f"{self.path / name} is not a single-channel depth image")
        return (units.astype(np.float64) * self.depth_scale).astype(np.float32)

    def events(self) -> Iterator[Event]:
        first_t = msgs.to_ns(self.frames[0][0])
        if self.poses:
            first_t = min(first_t, msgs.to_ns(self.poses[0][0]))
        yield Event(first_t, MOUNT, self.mount)
        yield Event(first_t, INTRINSICS, self.intrinsics or scaled_kinect_intrinsics(self._depth_m(self.frames[0][1][0]).shape))
        frames = (Event(msgs.to_ns(t), FRAME, functools.partial(self._depth_m, name)) for t, (name,) in self.frames)
        poses = (Event(msgs.to_ns(t), ODOMETRY, Odometry(_floor_pose(values), 0.0, 0.0, t)) for t, values in self.poses)
        yield from heapq.merge(poses, frames, key=lambda e: e.t_ns)


def _read_table(path: Path, columns: int) -> list[tuple[float, tuple]]:
    """Rows ``timestamp v1 … vN`` of a TUM text file (``#`` comments skipped), sorted by time."""
    rows = []
    with open(path, encoding="utf-8") as handle:
        for number, line in enumerate(handle, start=1):
            parts = line.split()
            if not parts or parts[0].startswith("#"):
                continue
            if len(parts) < columns + 1:
                raise RecordingError(f"{path}: line {number}: expected a timestamp and {columns} values")
            try:
                t = float(parts[0])
                values = tuple(parts[1:columns + 1]) if columns == 1 else tuple(float(v) for v in parts[1:columns + 1])
            except ValueError:
                raise RecordingError(f"{path}: line {number}: not a number: {line.strip()!r}") from None
            rows.append((t, values))
    rows.sort(key=lambda row: row[0])
    return rows


def _floor_pose(values: tuple) -> Pose2D:
    """A TUM camera pose (tx ty tz qx qy qz qw) projected onto the floor: position and the
    heading of the optical axis in the x-y plane."""
    from scipy.spatial.transform import Rotation

    tx, ty, _, qx, qy, qz, qw = values
    axis = Rotation.from_quat([qx, qy, qz, qw]).as_matrix()[:, 2]
    return Pose2D(tx, ty, math.atan2(axis[1], axis[0]))


def scaled_kinect_intrinsics(shape: tuple[int, int]) -> CameraIntrinsics:
    """The Kinect v1's intrinsics scaled to an image of ``shape`` (rows, columns)."""
    k = CameraIntrinsics.kinect_v1()
    sx, sy = shape[1] / k.width, shape[0] / k.height
    return CameraIntrinsics(shape[1], shape[0], k.fx * sx, k.fy * sy, (k.cx + 0.5) * sx - 0.5, (k.cy + 0.5) * sy - 0.5)

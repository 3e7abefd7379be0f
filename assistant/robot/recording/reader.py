"""Reading a recorded session back as a time-ordered stream of :class:`Event` s.

:class:`McapSource` reads MCAP files with ROS 2 (CDR) messages — the product's own recordings
and other robots' ROS 2 recordings in MCAP storage — from the start, without the summary
section, so a file cut by a crash reads up to its last complete message (``truncated`` then
says so). Other formats (ROS 1 bags, ROS 2 bag folders, TUM RGB-D folders) are in
:mod:`assistant.robot.recording.foreign`; :func:`~assistant.robot.recording.sources.open_source`
picks the reader for a path.

Messages are recognised by their ROS type, not their topic name, so another robot's
``/camera/depth/image_raw`` and ``/odom`` work as well as the product's own topics; a
recording with several depth topics uses the first one seen (or ``depth_topic``).
"""

from __future__ import annotations

import functools
import json
import os
import struct
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from assistant.errors import AssistantError
from assistant.robot.recording import messages as msgs
from assistant.robot.recording.writer import SESSION_END_METADATA, SESSION_METADATA

__all__ = ["Event", "McapSource", "MessageDecoder", "RecordingError"]

#: event kinds, in the order events of one instant are applied
FRAME, FRAME_POSE, INTRINSICS, MOUNT, ODOMETRY, COMMAND, TURN, END = (
    "frame", "frame_pose", "intrinsics", "mount", "odometry", "command", "turn", "end")


class RecordingError(AssistantError):
    """A recording that cannot be read (missing, not a recording, no depth or odometry in it)."""


@dataclass(frozen=True)
class Event:
    """One recorded message: ``t_ns`` (robot time, nanoseconds), ``kind`` and its ``value``.

    Values: ``frame`` → a zero-argument callable giving float32 depth in metres (decoded only
    when read); ``frame_pose`` → :class:`~assistant.geometry.Pose2D`; ``intrinsics`` →
    :class:`~assistant.robot.CameraIntrinsics`; ``mount`` → :class:`~assistant.robot.CameraMount`;
    ``odometry`` → :class:`~assistant.robot.Odometry`; ``command`` → (linear m/s, angular rad/s);
    ``turn`` → {speaker, text}; ``end`` → None (the recording's end time, written when it closed).
    """

    t_ns: int
    kind: str
    value: object = field(compare=False)


class MessageDecoder:
    """Turns (topic, ROS type, deserialised message, log time) into :class:`Event` s.

    It locks onto the first depth image topic and the first camera-info topic it sees (or the
    ``depth_topic`` given), so colour images and second cameras are skipped.
    """

    WANTED = frozenset({
        "sensor_msgs/msg/Image", "sensor_msgs/msg/CameraInfo", "geometry_msgs/msg/PoseStamped",
        "tf2_msgs/msg/TFMessage", "nav_msgs/msg/Odometry", "geometry_msgs/msg/Twist", "std_msgs/msg/String",
    })

    def __init__(self, depth_topic: str | None = None):
        self.depth_topic = depth_topic
        self.info_topic: str | None = None

    def wants(self, topic: str, typename: str) -> bool:
        typename = msgs.ros2_type_name(typename)
        if typename not in self.WANTED:
            return False
        if typename == "std_msgs/msg/String":
            return topic == "/dialogue"
        if typename == "geometry_msgs/msg/PoseStamped":
            return topic == "/camera/depth/pose"
        if typename == "sensor_msgs/msg/Image" and self.depth_topic is not None:
            return topic == self.depth_topic
        return True

    def decode(self, topic: str, typename: str, message, t_ns: int) -> Event | None:
        typename = msgs.ros2_type_name(typename)
        if typename == "sensor_msgs/msg/Image":
            if str(message.encoding).lower() not in ("16uc1", "32fc1", "mono16"):
                return None
            if self.depth_topic is None:
                self.depth_topic = topic
            if topic != self.depth_topic:
                return None
            return Event(t_ns, FRAME, functools.partial(msgs.image_depth_m, message))
        if typename == "sensor_msgs/msg/CameraInfo":
            if self.info_topic is None and (self.depth_topic is None or _namespace(topic) == _namespace(self.depth_topic)
                                            or "depth" in topic):
                self.info_topic = topic
            return Event(t_ns, INTRINSICS, msgs.intrinsics_from_info(message)) if topic == self.info_topic else None
        if typename == "geometry_msgs/msg/PoseStamped":
            return Event(t_ns, FRAME_POSE, msgs.pose_of(message.pose))
        if typename == "tf2_msgs/msg/TFMessage":
            mount = msgs.mount_from_tf(message)
            return None if mount is None else Event(t_ns, MOUNT, mount)
        if typename == "nav_msgs/msg/Odometry":
            odometry = msgs.odometry_of(message)
            return Event(t_ns, ODOMETRY, odometry)
        if typename == "geometry_msgs/msg/Twist":
            return Event(t_ns, COMMAND, (float(message.linear.x), float(message.angular.z)))
        if typename == "std_msgs/msg/String":
            try:
                turn = json.loads(message.data)
            except json.JSONDecodeError:
                turn = {"speaker": "?", "text": str(message.data)}
            return Event(t_ns, TURN, turn)
        return None


def _namespace(topic: str) -> str:
    return topic.rsplit("/", 1)[0]


class McapSource:
    """An MCAP file of ROS 2 messages as events, readable up to a cut.

    ``metadata`` holds the session's description (world, scene, robot, ``started_utc``…; empty
    for another robot's file); after :meth:`events` has run to its end, ``truncated`` is True
    when the file stopped mid-record (a crash or power loss while recording).
    """

    def __init__(self, path: str | os.PathLike[str], depth_topic: str | None = None):
        self.path = Path(path)
        self.depth_topic = depth_topic
        if not self.path.is_file():
            raise RecordingError(f"no recording at {self.path}; give the path of an .mcap file, a ROS bag "
                                 "or a TUM RGB-D folder")
        with open(self.path, "rb") as handle:
            if handle.read(8) != b"\x89MCAP0\r\n":
                raise RecordingError(f"{self.path} is not an MCAP file (it does not start with MCAP's magic bytes)")
        self.truncated = False
        self.metadata = self._read_metadata()

    def _read_metadata(self) -> dict[str, str]:
        from mcap.records import Metadata

        for record in self._records():
            if isinstance(record, Metadata) and record.name == SESSION_METADATA:
                return dict(record.metadata)
            if type(record).__name__ in ("Chunk", "Message"):
                break  # the session record comes before any message
        return {}

    def _records(self) -> Iterator:
        """MCAP records in file order (chunks opened), stopping quietly at a cut."""
        from mcap.exceptions import McapError
        from mcap.reader import breakup_chunk
        from mcap.records import Chunk
        from mcap.stream_reader import StreamReader

        self.truncated = False
        with open(self.path, "rb") as handle:
            reader = StreamReader(handle, skip_magic=False)
            try:
                for record in reader.records:
                    if isinstance(record, Chunk):
                        yield from breakup_chunk(record, validate_crc=True)
                    else:
                        yield record
            except (McapError, struct.error):  # a record cut short: the file ends mid-write
                self.truncated = True

    def events(self) -> Iterator[Event]:
        """Every wanted message, in file order (the product writes in time order)."""
        from mcap.records import Channel, Message, Metadata, Schema

        decoder = MessageDecoder(self.depth_topic)
        schemas: dict[int, str] = {}
        channels: dict[int, tuple[str, str]] = {}
        for record in self._records():
            if isinstance(record, Schema):
                schemas[record.id] = record.name
            elif isinstance(record, Channel):
                channels[record.id] = (record.topic, schemas.get(record.schema_id, ""))
            elif isinstance(record, Message):
                topic, typename = channels.get(record.channel_id, ("", ""))
                if not decoder.wants(topic, typename):
                    continue
                message = msgs.deserialize(record.data, msgs.ros2_type_name(typename))
                event = decoder.decode(topic, typename, message, int(record.log_time))
                if event is not None:
                    yield event
            elif isinstance(record, Metadata) and record.name == SESSION_END_METADATA:
                yield Event(int(record.metadata.get("end_ns", 0)), END, None)

"""Recording robot sessions to MCAP and reading recordings back.

* :class:`SessionWriter` writes depth frames, odometry, velocity commands and dialogue turns
  as ROS 2 messages in an MCAP file, each on disk as soon as it is added;
* :class:`RecordingRobot` wraps any robot and records everything that passes through it;
* :func:`open_source` reads a recording (the product's ``.mcap``, a ROS 1 / ROS 2 bag, a TUM
  RGB-D folder) as a time-ordered stream of events, which
  :class:`~assistant.robot.replay.ReplayRobot` plays back as a robot.
"""

from assistant.robot.recording.reader import Event, McapSource, RecordingError
from assistant.robot.recording.sources import open_source, read_events
from assistant.robot.recording.summary import recording_summary
from assistant.robot.recording.recorder import RecordingRobot
from assistant.robot.recording.writer import SessionWriter

__all__ = ["Event", "McapSource", "RecordingError", "RecordingRobot", "SessionWriter", "open_source", "read_events",
           "recording_summary"]

"""``ReplayRobot``: a recorded session played back behind the one :class:`Robot` interface.

The robot's clock is the recording's: ``advance(s)`` moves it on by ``s`` seconds and every
message recorded up to then takes effect, so ``depth_frame()`` and ``odometry()`` give what the
robot had at that time — as fast as the caller asks, or in real time with ``speed=1.0``. The
base does not follow commands (``follows_commands`` is False): each velocity command is logged
and compared with the one recorded at the same time (:meth:`ReplayRobot.command_report`), which
tells whether a replayed task made the decisions the live one made. Advancing past the end of
the recording raises :class:`RecordingEndedError` (``on_end="hold"`` keeps the last frame and
pose instead, for browsing).

Recordings: the product's own ``.mcap`` files (``assistant record``), other robots' ROS 1 / ROS 2
bags with depth and odometry, and TUM RGB-D folders (:func:`~assistant.robot.recording.reader.open_source`).
"""

from __future__ import annotations

import bisect
import os
import time
from collections import defaultdict
from collections.abc import Iterator

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.robot.errors import RobotConnectionError
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame, Odometry
from assistant.robot.interface import Robot
from assistant.robot.recording import messages as msgs
from assistant.robot.recording.foreign import scaled_kinect_intrinsics
from assistant.robot.recording.reader import COMMAND, END, FRAME, FRAME_POSE, INTRINSICS, MOUNT, ODOMETRY, TURN, Event
from assistant.robot.recording.sources import open_source

__all__ = ["RecordingEndedError", "ReplayRobot", "replay_robot_from_spec"]

ON_END = ("error", "hold")


class RecordingEndedError(RobotConnectionError):
    """The replay was asked to go on past the end of its recording."""


class ReplayRobot(Robot):
    """A recording as a robot (see the module docstring).

    ``speed``: 0 replays as fast as asked (default), 1.0 in real time, 2.0 twice as fast;
    ``on_end``: "error" (default) or "hold"; ``command_tolerance``: (m/s, rad/s) within which a
    command counts as the recorded one. Other options go to the reader (``depth_topic``,
    ``camera_height_m``, ``tilt_deg``, and for TUM folders ``depth_scale``, ``intrinsics``).
    """

    follows_commands = False

    def __init__(self, path: str | os.PathLike[str], *, speed: float = 0.0, on_end: str = "error",
                 command_tolerance: tuple[float, float] = (1e-6, 1e-6), **source_options):
        super().__init__()
        if on_end not in ON_END:
            raise AssistantError(f"on_end must be one of {', '.join(ON_END)}, got {on_end!r}")
        if not speed >= 0:
            raise AssistantError(f"speed must be 0 (as fast as asked) or a positive factor, got {speed}")
        self.path = str(path)
        self.speed = float(speed)
        self.on_end = on_end
        self.command_tolerance = command_tolerance
        self.source = open_source(path, **source_options)  # checks the path now, not at connect
        self._source_options = source_options
        self.name = f"replay of {os.path.basename(os.path.normpath(self.path))}"
        self._reset()

    @property
    def metadata(self) -> dict[str, str]:
        """The session's description (world, scene, robot, start time…) for the product's own
        recordings; the format and path for others."""
        return dict(self.source.metadata)

    @property
    def ended(self) -> bool:
        """True once the replay has reached the end of its recording."""
        return self._exhausted and self._now_ns >= self._end_ns

    @property
    def transcript(self) -> list[dict]:
        """The dialogue turns recorded up to now: {t, speaker, text}."""
        return list(self._turns)

    def frames(self) -> Iterator[DepthFrame]:
        """Every depth frame from the current one to the end, in order, moving the replay's clock
        to each (for browsing a recording; a task uses ``advance`` and ``depth_frame``)."""
        self._require("read frames")
        while True:
            yield self.depth_frame()
            current = self._frame_event
            while self._pending is not None and self._frame_event is current:
                self._now_ns = self._pending.t_ns
                self._apply_until(self._now_ns)
            if self._frame_event is current:
                return

    # ---------------------------------------------------------------- hooks
    def _reset(self) -> None:
        self._events: Iterator[Event] | None = None
        self._pending: Event | None = None
        self._exhausted = False
        self._now_ns = 0
        self._end_ns = 0
        self._intrinsics: CameraIntrinsics | None = None
        self._mount = CameraMount()
        self._odo: Odometry | None = None
        self._frame_event: Event | None = None
        self._frame_pose: tuple[int, Pose2D] | None = None
        self._frame_cache: tuple[Event, DepthFrame] | None = None
        self._recorded: dict[int, list[tuple[float, float]]] = defaultdict(list)
        self._issued: list[tuple[int, float, float]] = []
        self._turns: list[dict] = []
        self._wall_start = 0.0
        self._first_ns = 0

    def _connect(self) -> None:
        self._reset()
        self._events = iter(self.source.events())
        self._pull()
        if self._pending is None:
            raise RobotConnectionError(f"the recording {self.path} holds no depth frames or odometry")
        self._now_ns = self._pending.t_ns
        self._apply_until(self._now_ns)
        if self._frame_event is None:  # start at the first frame; what came before it applies
            self._apply_until_first_frame()
        if self._frame_event is None:
            raise RobotConnectionError(f"the recording {self.path} holds no depth frames; a replay needs them")
        self._first_ns = self._now_ns
        self._wall_start = time.monotonic()

    def _close(self) -> None:
        self._events = None
        self._pending = None
        self._frame_cache = None

    def _odometry(self) -> Odometry:
        if self._odo is None:
            return Odometry(Pose2D(0.0, 0.0, 0.0), 0.0, 0.0, msgs.from_ns(self._now_ns))
        return self._odo

    def _depth_frame(self) -> DepthFrame:
        event = self._frame_event
        if self._frame_cache is not None and self._frame_cache[0] is event:
            return self._frame_cache[1]
        depth = event.value()
        intrinsics = self._intrinsics
        if intrinsics is None or (intrinsics.height, intrinsics.width) != depth.shape:
            intrinsics = scaled_kinect_intrinsics(depth.shape)
        if self._frame_pose is not None and self._frame_pose[0] == event.t_ns:
            pose = self._frame_pose[1]
        else:
            pose = self._odometry().pose
        frame = DepthFrame(depth, intrinsics, self._mount, pose, msgs.from_ns(event.t_ns))
        self._frame_cache = (event, frame)
        return frame

    def _send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        if not (abs(linear_m_s) < float("inf") and abs(angular_rad_s) < float("inf")):
            raise ValueError(f"velocity must be finite numbers, got ({linear_m_s}, {angular_rad_s})")
        self._issued.append((self._now_ns, linear_m_s, angular_rad_s))

    def _stop(self) -> None:
        self._issued.append((self._now_ns, 0.0, 0.0))

    def _advance(self, seconds: float) -> None:
        target = self._now_ns + msgs.to_ns(seconds)
        if self.speed > 0:
            self._wait_until(target)
        self._apply_until(target)
        if self._exhausted and target > self._end_ns:
            if self.on_end == "error":
                self._now_ns = self._end_ns
                raise RecordingEndedError(
                    f"the recording {self.path} ends at {msgs.from_ns(self._end_ns):.2f} s; nothing more to "
                    "replay (replay it again, or use on_end='hold' to keep the last frame)")
        self._now_ns = target

    def _time_s(self) -> float:
        return msgs.from_ns(self._now_ns)

    # ---------------------------------------------------------------- commands
    def command_report(self) -> dict:
        """How the commands sent during the replay compare with the recorded ones.

        ``issued`` and ``recorded`` counts, the largest differences (m/s, rad/s), how many
        ``matched`` within ``command_tolerance``, and ``first_difference_s``: the robot time of the
        first command that did not (None when all matched).
        """
        seen_at: dict[int, int] = defaultdict(int)
        times = sorted(self._recorded)
        max_linear = max_angular = 0.0
        matched = 0
        first = None
        for t_ns, linear, angular in self._issued:
            same_time = self._recorded.get(t_ns, [])
            k = seen_at[t_ns]
            seen_at[t_ns] += 1
            if k < len(same_time):
                expected = same_time[k]
            else:
                i = bisect.bisect_right(times, t_ns)  # the command in force: the last one recorded before
                expected = self._recorded[times[i - 1]][-1] if i else (0.0, 0.0)
            d_linear, d_angular = abs(linear - expected[0]), abs(angular - expected[1])
            max_linear, max_angular = max(max_linear, d_linear), max(max_angular, d_angular)
            if d_linear <= self.command_tolerance[0] and d_angular <= self.command_tolerance[1]:
                matched += 1
            elif first is None:
                first = msgs.from_ns(t_ns)
        return {"issued": len(self._issued), "recorded": sum(len(v) for v in self._recorded.values()),
                "matched": matched, "max_linear_difference": max_linear,
                "max_angular_difference": max_angular, "first_difference_s": first}

    # ---------------------------------------------------------------- the event stream
    def _pull(self) -> None:
        try:
            self._pending = next(self._events)
        except StopIteration:
            self._pending = None
            self._exhausted = True

    def _apply_until(self, t_ns: int) -> None:
        while self._pending is not None and self._pending.t_ns <= t_ns:
            self._apply(self._pending)
            self._pull()

    def _apply_until_first_frame(self) -> None:
        while self._pending is not None and self._frame_event is None:
            self._now_ns = self._pending.t_ns
            self._apply_until(self._now_ns)

    def _apply(self, event: Event) -> None:
        self._end_ns = max(self._end_ns, event.t_ns)
        kind = event.kind
        if kind == FRAME:
            self._frame_event = event
        elif kind == ODOMETRY:
            self._odo = event.value
        elif kind == FRAME_POSE:
            self._frame_pose = (event.t_ns, event.value)
        elif kind == INTRINSICS:
            self._intrinsics = event.value
        elif kind == MOUNT:
            self._mount = event.value
        elif kind == COMMAND:
            self._recorded[event.t_ns].append(event.value)
        elif kind == TURN:
            self._turns.append({"t": msgs.from_ns(event.t_ns), **event.value})
        elif kind == END:
            pass  # only moves the end time

    def _wait_until(self, target_ns: int) -> None:
        due = self._wall_start + msgs.from_ns(target_ns - self._first_ns) / self.speed
        delay = due - time.monotonic()
        if delay > 0:
            time.sleep(delay)


def replay_robot_from_spec(argument: str = "", **options) -> ReplayRobot:
    """``replay:PATH`` → a :class:`ReplayRobot` of the recording at PATH.

    Options are :class:`ReplayRobot`'s (the factory passes it no home options: the recording has
    its own home).
    """
    if not argument:
        raise AssistantError("say which recording to replay: replay:PATH (an .mcap file, a ROS bag or a "
                             "TUM RGB-D folder); sample recordings are in sample_scans/")
    return ReplayRobot(argument, **options)

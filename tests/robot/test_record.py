"""Recording sessions to MCAP: what is written, how it reads back, and a file cut mid-write."""

from __future__ import annotations

import shutil
from collections import Counter

import numpy as np
import pytest

from assistant.errors import AssistantError
from assistant.robot.recording import McapSource, RecordingRobot, SessionWriter, read_events
from assistant.robot.recording import messages as msgs
from tests.robot.conftest import record_sim_session


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    path = tmp_path_factory.mktemp("rec") / "session.mcap"
    live = record_sim_session(path, steps=6)
    return path, live


def test_a_session_holds_every_kind_of_message(session):
    path, live = session
    kinds = Counter(e.kind for e in read_events(path))
    assert kinds["frame"] == len(live) and kinds["frame_pose"] == len(live)
    assert kinds["odometry"] == len(live)
    assert kinds["command"] == len(live) + 1  # and the stop when the robot closed
    assert kinds["mount"] == 1 and kinds["intrinsics"] == 1  # written again only on a change
    assert kinds["turn"] == 1 and kinds["end"] == 1


def test_metadata_and_ros2_schemas_are_in_the_file(session):
    from mcap.reader import make_reader

    path, _ = session
    source = McapSource(path)
    assert source.metadata["world"] == "apartment" and source.metadata["robot"].startswith("simulated robot")
    with open(path, "rb") as handle:
        summary = make_reader(handle).get_summary()  # a cleanly closed file has MCAP's summary for viewers
    topics = {c.topic: summary.schemas[c.schema_id].name for c in summary.channels.values()}
    assert topics["/camera/depth/image"] == "sensor_msgs/msg/Image"
    assert topics["/odom"] == "nav_msgs/msg/Odometry"
    assert topics["/cmd_vel"] == "geometry_msgs/msg/Twist"
    assert {s.encoding for s in summary.schemas.values()} == {"ros2msg"}


def test_depth_is_16uc1_millimetres(session):
    from mcap.reader import make_reader

    path, live = session
    with open(path, "rb") as handle:
        for _, channel, message in make_reader(handle).iter_messages(topics=["/camera/depth/image"]):
            image = msgs.deserialize(message.data, "sensor_msgs/msg/Image")
            break
    assert image.encoding == "16UC1" and image.step == image.width * 2 and not image.is_bigendian
    assert np.array_equal(msgs.image_millimetres(image), live[0][1].to_millimetres())


def test_the_caller_gets_what_the_file_holds(session):
    path, live = session
    frames = [e for e in read_events(path) if e.kind == "frame"]
    for (_, frame, _), event in zip(live, frames):
        assert np.array_equal(event.value(), frame.depth_m)  # bit for bit
        assert frame.depth_m.dtype == np.float32


def test_a_file_cut_mid_write_reads_up_to_the_cut(session, tmp_path):
    path, live = session
    data = path.read_bytes()
    full = read_events(path)
    for fraction in (0.3, 0.55, 0.8):
        cut = tmp_path / f"cut{fraction}.mcap"
        cut.write_bytes(data[: int(len(data) * fraction)])
        source = McapSource(cut)
        events = list(source.events())
        assert source.truncated
        assert 0 < len(events) < len(full)
        assert [(e.t_ns, e.kind) for e in events] == [(e.t_ns, e.kind) for e in full[: len(events)]]
        frames = [e for e in events if e.kind == "frame"]
        for (_, frame, _), event in zip(live, frames):
            assert np.array_equal(event.value(), frame.depth_m)


def test_the_writer_refuses_to_overwrite_and_other_suffixes(session, tmp_path):
    path, _ = session
    with pytest.raises(AssistantError, match="exists"):
        SessionWriter(path)
    with pytest.raises(AssistantError, match=r"\.mcap"):
        SessionWriter(tmp_path / "session.bag")


def test_recording_robot_passes_extras_through_and_keeps_the_first_file(tmp_path):
    from assistant.sim import SimRobot

    path = tmp_path / "extras.mcap"
    robot = RecordingRobot(SimRobot("apartment", seed=0), path)
    with robot:
        assert robot.ground_truth_pose == robot.inner.ground_truth_pose  # the simulator's own attribute
        frame = robot.depth_frame()
        assert frame.hit_ids is not None  # evaluation data passes through (it is not recorded)
        # the simulator's depth is whole millimetres already: recording it changes nothing
        assert np.array_equal(frame.depth_m, robot.inner.depth_frame().depth_m)
        assert robot.depth_frame() is frame  # an unchanged frame is not written twice
    with pytest.raises(AssistantError, match="exists"):
        robot.connect()
    assert not robot.inner.is_connected  # the half-opened robot was released


def test_a_session_killed_without_close_still_replays(tmp_path):
    """Simulate a crash: the writer is never closed (no summary, no end record)."""
    from assistant.robot.replay import ReplayRobot
    from assistant.sim import SimRobot

    path = tmp_path / "crash.mcap"
    robot = RecordingRobot(SimRobot("apartment", seed=0), path).connect()
    first = robot.depth_frame()
    robot.send_velocity(0.0, 0.5)
    robot.advance(0.5)
    robot.odometry()
    copy = tmp_path / "copy.mcap"
    shutil.copyfile(path, copy)  # the file as it is on disk while the process still runs
    robot.close()
    with ReplayRobot(copy) as replay:
        assert np.array_equal(replay.depth_frame().depth_m, first.depth_m)
        replay.advance(0.5)
        assert replay.odometry().timestamp_s == pytest.approx(0.5)

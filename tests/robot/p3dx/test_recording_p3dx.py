"""A P3-DX session recorded and replayed: the driver, the recorder and the replay compose."""

from __future__ import annotations

import numpy as np
import pytest

from assistant.robot.p3dx import P3DX
from assistant.robot.p3dx.fake import FloorCamera

recording = pytest.importorskip("assistant.robot.recording")
replay = pytest.importorskip("assistant.robot.replay")


def test_a_p3dx_session_records_and_replays_its_frames_and_poses(fake, params, tmp_path):
    path = tmp_path / "p3dx.mcap"
    live = []
    robot = recording.RecordingRobot(P3DX(fake.port, FloorCamera(), params=params), path,
                                     {"spec": f"p3dx:{fake.port}"})
    with robot:
        for _ in range(3):
            live.append((robot.odometry(), robot.depth_frame()))
            robot.send_velocity(0.0, 0.4)
            robot.advance(0.3)
        robot.stop()
    summary = recording.recording_summary(path)
    assert summary["frames"] == 3 and summary["commands"] >= 3
    with replay.ReplayRobot(path) as played:
        frame = played.depth_frame()
        assert np.array_equal(frame.to_millimetres(), live[0][1].to_millimetres())
        assert frame.robot_pose.x == pytest.approx(live[0][1].robot_pose.x, abs=1e-6)

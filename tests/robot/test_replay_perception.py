"""Perception on a replayed session gives what it gave live.

The geometric front half (floor, samples, features) is compared on every frame; the whole
detector (trained classifier) on the same frames in a slow test.
"""

from __future__ import annotations

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.robot.recording import RecordingRobot
from assistant.robot.replay import ReplayRobot

#: in the apartment's living room, facing the couch and the coffee table, then turning
START = Pose2D(2.8, 5.9, -1.17)


@pytest.fixture(scope="module")
def live_and_replayed(tmp_path_factory):
    from assistant.sim import SimRobot

    path = tmp_path_factory.mktemp("perceive") / "living_room.mcap"
    live = []
    with RecordingRobot(SimRobot("apartment", start=START, seed=0), path) as robot:
        for _ in range(3):
            live.append(robot.depth_frame())
            robot.send_velocity(0.0, 0.5)
            robot.advance(0.8)
    with ReplayRobot(path) as replay:
        replayed = list(replay.frames())
    return live, replayed


def test_the_front_half_finds_the_same_floor_samples_and_features(live_and_replayed):
    from assistant.perception.frame import analyse_frame

    live, replayed = live_and_replayed
    assert len(replayed) == len(live)
    found = 0
    for a, b in zip(live, replayed):
        x, y = analyse_frame(a), analyse_frame(b)
        assert (x.floor is None) == (y.floor is None)
        assert len(x.samples) == len(y.samples)
        assert np.array_equal(x.features, y.features)
        found += len(x.samples)
    assert found > 0, "the frames should show furniture"


@pytest.mark.slow
def test_the_detector_gives_the_same_detections(live_and_replayed):
    from assistant.perception import FurnitureDetector

    live, replayed = live_and_replayed
    detector = FurnitureDetector()
    live_detections = [detector.analyse(f).to_dict()["detections"] for f in live]
    assert any(live_detections)
    assert [detector.analyse(f).to_dict()["detections"] for f in replayed] == live_detections

"""Robot adapters under the contract suite: each entry makes a fresh, unconnected robot.

Add an adapter (replay, P3-DX on a test rig…) by adding a factory here; every check in
``assistant.robot.contract`` then runs on it.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest


def _sim_robot():
    from assistant.sim import SimRobot

    return SimRobot("apartment", seed=0)


def _noisy_sim_robot():
    from assistant.sim import OdometryNoise, SimRobot

    return SimRobot("hk-studio", scene="modified", seed=3, odometry_noise=OdometryNoise(), tilt_deg=5.0)


def _p3dx_over_fake_controller(request):
    """The real P3-DX driver over the fake ARCOS controller (a pty), with a stand-in floor camera."""
    from assistant.robot.p3dx import P3DX
    from assistant.robot.p3dx.fake import FakeArcosController, FloorCamera, patient_params

    params = patient_params()
    fake = FakeArcosController(params)
    request.addfinalizer(fake.close)
    return lambda: P3DX(fake.port, FloorCamera(), params=params)


def record_sim_session(path, steps: int = 6, world: str = "apartment", seed: int = 0):
    """Record a short simulated session (turn, drive a little, one frame per step) to ``path``;
    returns what the recording robot gave its caller: [(odometry, frame, (linear, angular))]."""
    from assistant.robot.recording import RecordingRobot
    from assistant.sim import SimRobot

    live = []
    with RecordingRobot(SimRobot(world, seed=seed), path, {"world": world, "scene": "original"}) as robot:
        for step in range(steps):
            odometry, frame = robot.odometry(), robot.depth_frame()
            command = (0.1 * (step % 2), 0.4)
            robot.send_velocity(*command)
            robot.advance(0.5)
            live.append((odometry, frame, command))
        robot.record_turn("user", "where is my mug?")
    return live


_RECORDINGS = tempfile.TemporaryDirectory(prefix="assistant-replay-")


def _replay_robot():
    from assistant.robot.replay import ReplayRobot

    path = Path(_RECORDINGS.name) / "contract.mcap"
    if not path.exists():
        record_sim_session(path, steps=4)
    return ReplayRobot(path)


def _recording_sim_robot():
    from assistant.robot.recording import RecordingRobot
    from assistant.sim import SimRobot

    return RecordingRobot(SimRobot("apartment", seed=0), Path(_RECORDINGS.name) / "wrapped.mcap", overwrite=True)


ADAPTERS = {
    "sim": _sim_robot,
    "sim-noisy-odometry": _noisy_sim_robot,
    "replay": _replay_robot,
    "recording-sim": _recording_sim_robot,
}

#: Adapters that need set-up and tear-down around each test: called with the pytest request,
#: they return the factory.
FIXTURE_ADAPTERS = {
    "p3dx-fake-controller": _p3dx_over_fake_controller,
}


@pytest.fixture(params=sorted(ADAPTERS) + sorted(FIXTURE_ADAPTERS))
def make_robot(request):
    """A factory of fresh, unconnected robots, once per adapter."""
    if request.param in FIXTURE_ADAPTERS:
        return FIXTURE_ADAPTERS[request.param](request)
    return ADAPTERS[request.param]

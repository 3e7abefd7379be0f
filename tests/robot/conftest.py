"""Robot adapters under the contract suite: each entry makes a fresh, unconnected robot.

Add an adapter (replay, P3-DX on a test rig…) by adding a factory here; every check in
``assistant.robot.contract`` then runs on it.
"""

from __future__ import annotations

import pytest


def _sim_robot():
    from assistant.sim import SimRobot

    return SimRobot("apartment", seed=0)


def _noisy_sim_robot():
    from assistant.sim import OdometryNoise, SimRobot

    return SimRobot("hk-studio", scene="modified", seed=3, odometry_noise=OdometryNoise(), tilt_deg=5.0)


ADAPTERS = {
    "sim": _sim_robot,
    "sim-noisy-odometry": _noisy_sim_robot,
}


@pytest.fixture(params=sorted(ADAPTERS))
def make_robot(request):
    """A factory of fresh, unconnected robots, once per adapter."""
    return ADAPTERS[request.param]

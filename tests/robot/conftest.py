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


def _p3dx_over_fake_controller(request):
    """The real P3-DX driver over the fake ARCOS controller (a pty), with a stand-in floor camera."""
    from assistant.robot.p3dx import P3DX
    from assistant.robot.p3dx.fake import FakeArcosController, FloorCamera, patient_params

    params = patient_params()
    fake = FakeArcosController(params)
    request.addfinalizer(fake.close)
    return lambda: P3DX(fake.port, FloorCamera(), params=params)


ADAPTERS = {
    "sim": _sim_robot,
    "sim-noisy-odometry": _noisy_sim_robot,
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

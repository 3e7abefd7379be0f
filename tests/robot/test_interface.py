"""The Robot base class and its errors, with a stand-in adapter that breaks the contract."""

from __future__ import annotations

import numpy as np
import pytest

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.robot import (
    CameraIntrinsics,
    DepthFrame,
    DeviceNotConnectedError,
    Odometry,
    Robot,
    RobotConnectionError,
)
from assistant.robot.contract import check_commands_after_close_raise, check_velocity_moves_and_stop_stops


class _Frozen(Robot):
    """Connects and answers, but ignores velocity commands (a broken adapter)."""

    name = "frozen test robot"

    def _connect(self): pass
    def _close(self): pass
    def _odometry(self): return Odometry(Pose2D(0, 0, 0))
    def _depth_frame(self):
        k = CameraIntrinsics(4, 3, 2.0, 2.0, 1.5, 1.0)
        return DepthFrame(np.ones((3, 4), np.float32), k)
    def _send_velocity(self, v, w): pass
    def _stop(self): pass
    def _advance(self, s): pass
    def _time_s(self): return 0.0


def test_errors_are_typed():
    error = DeviceNotConnectedError("robot", "read odometry")
    assert isinstance(error, RobotConnectionError)
    assert isinstance(error, ConnectionError)
    assert isinstance(error, AssistantError)
    assert "connect()" in str(error)


def test_contract_catches_a_robot_that_does_not_move():
    with pytest.raises(AssertionError, match="heading|second"):
        check_velocity_moves_and_stop_stops(_Frozen)


def test_contract_passes_the_connection_checks_for_the_base_class():
    check_commands_after_close_raise(_Frozen)


def test_cannot_instantiate_without_hooks():
    class Half(Robot):
        def _connect(self): pass

    with pytest.raises(TypeError):
        Half()

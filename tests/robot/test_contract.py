"""Every robot adapter passes every check of the robot contract."""

from __future__ import annotations

import pytest

from assistant.robot.contract import robot_checks


@pytest.mark.parametrize("check", list(robot_checks()), ids=lambda c: c.__name__)
def test_robot_contract(make_robot, check):
    check(make_robot)

"""The robot factory: specs, the simulator adapter, clear errors."""

import pytest

from assistant.errors import AssistantError, UnknownNameError
from assistant.robot import Robot, RobotSpec, make_robot, parse_robot_spec, robot_schemes


def test_parse_spec_splits_scheme_and_argument():
    assert parse_robot_spec("p3dx:/dev/ttyUSB0") == RobotSpec("p3dx", "/dev/ttyUSB0")
    assert parse_robot_spec(" SIM ") == RobotSpec("sim", "")
    assert str(RobotSpec("sim", "apartment")) == "sim:apartment"


def test_unknown_scheme_lists_the_known_ones():
    with pytest.raises(UnknownNameError) as error:
        parse_robot_spec("roomba:1")
    assert "sim" in str(error.value)
    assert "sim" in robot_schemes()


def test_empty_spec_is_a_clear_error():
    with pytest.raises(AssistantError, match="sim:apartment"):
        parse_robot_spec("  ")


def test_sim_spec_builds_an_unconnected_simulator_in_the_named_world_and_scene():
    robot = make_robot("sim:hk-studio:modified", seed=3)
    assert isinstance(robot, Robot) and not robot.is_connected
    assert robot.world.name == "hk-studio" and robot.scene == "modified"
    default = make_robot("sim", world="apartment")
    assert default.world.name == "apartment" and default.scene == "original"


def test_sim_noise_option_turns_on_odometry_noise():
    assert make_robot("sim:apartment", noise=True).base.odometry_noise is not None
    assert make_robot("sim:apartment").base.odometry_noise is None

"""The robot factory: specs, the simulator adapter, clear errors."""

import sys

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


def test_each_adapter_gets_the_home_options_it_takes(monkeypatch):
    """A use case passes the same home options to any robot; the factory gives each adapter the
    ones it registered for (a recording none, a real base its start) and the adapter's own."""
    from assistant.geometry import Pose2D
    from assistant.robot import factory
    from assistant.world import load_world

    seen = {}
    module = type(sys)("fake_adapters")
    module.build = lambda argument, **options: seen.setdefault(argument, options)
    monkeypatch.setitem(sys.modules, "fake_adapters", module)
    monkeypatch.setitem(factory._ADAPTERS, "fake", "fake_adapters:build")
    monkeypatch.setitem(factory._TAKES, "fake", frozenset({"start"}))
    home = {"world": "apartment", "scene": "original", "start": Pose2D(1, 2, 0), "seed": 3, "noise": True}
    make_robot("fake:one", **home, speed=0.2)
    assert seen["one"] == {"start": Pose2D(1, 2, 0), "speed": 0.2}
    with pytest.raises(ValueError, match="not home options"):
        factory.register_adapter("fake", "fake_adapters:build", takes=("port",))

    apartment = load_world("apartment")
    robot = make_robot("sim", world=apartment, scene="modified", start=None, seed=1, noise=True)
    assert robot.world is apartment and robot.scene == "modified" and robot.base.odometry_noise is not None


def test_a_real_base_starts_where_the_home_says_unless_told(monkeypatch):
    from assistant.geometry import Pose2D
    from assistant.robot.p3dx import robot as p3dx
    from assistant.world import load_world

    monkeypatch.setattr(p3dx, "P3DX", lambda port, camera, **options: options)
    apartment = load_world("apartment")
    assert make_robot("p3dx:/dev/null:nocamera", world=apartment, seed=0, noise=True) == {"start": apartment.start}
    assert make_robot("p3dx:/dev/null:nocamera", world="apartment")["start"] == apartment.start
    there = Pose2D(1.0, 2.0, 0.5)
    assert make_robot("p3dx:/dev/null:nocamera", world=apartment, start=there)["start"] == there
    assert make_robot("p3dx:/dev/null:nocamera") == {"start": None}

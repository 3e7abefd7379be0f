"""The P3-DX adapter over the fake controller: handshake, driving, limits, camera, bumps, stalls."""

from __future__ import annotations

import math

import pytest

from assistant.errors import AssistantError
from assistant.robot import make_robot
from assistant.robot.errors import MotorsDisabledError, NoCameraError, RobotConnectionError, SerialPortError
from assistant.robot.p3dx import P3DX
from assistant.robot.p3dx.commands import Command
from assistant.robot.p3dx.fake import FakeArcosController, Faults, FloorCamera, quick_params

from .conftest import reader_threads


def _advance_until(robot, predicate, timeout_s=2.0):
    """Let robot time pass in small steps until ``predicate()`` (a loaded machine is slow)."""
    waited = 0.0
    while not predicate() and waited < timeout_s:
        robot.advance(0.05)
        waited += 0.05
    return predicate()


def _commands(fake, number):
    return [arg for _, cmd, arg in fake.log.commands if cmd == number]


def test_connect_runs_the_handshake_and_sets_the_limits(fake, params):
    with P3DX(fake.port, params=params) as robot:
        assert robot.controller.robot_class == "Pioneer"
        assert robot.controller.name == "fake-p3dx"
        assert robot.battery_v == pytest.approx(12.6)
        assert robot.sonar_m()[1] == pytest.approx(1.6)
    assert fake.wait_until(lambda: fake.log.closed == 1)
    assert [c for _, c, _ in fake.log.commands[:3]] == [0, 1, 2]  # SYNC0, SYNC1, SYNC2
    assert _commands(fake, Command.SETV) == [750] and _commands(fake, Command.SETRV) == [100]
    assert _commands(fake, Command.SETA) == [300, -300]
    assert _commands(fake, Command.BUMPSTALL) == [3] and _commands(fake, Command.ENABLE) == [1]
    assert fake.log.opened == 1 and fake.log.closed == 1


def test_driving_forward_moves_the_odometry_along_the_heading(fake, params):
    with P3DX(fake.port, params=params) as robot:
        robot.send_velocity(0.4, 0.0)
        robot.advance(1.8)  # 1.33 s to reach 0.4 m/s at 0.3 m/s²
        odo = robot.odometry()
        assert 0.35 < odo.pose.x < 0.7 and abs(odo.pose.y) < 0.01
        assert odo.linear_m_s == pytest.approx(0.4, abs=0.02)
        assert fake.x_m == pytest.approx(odo.pose.x, abs=0.05)  # odometry follows the base


def test_commands_are_clamped_to_the_limits_of_the_hardware_file(fake, params):
    with P3DX(fake.port, params=params, max_linear_m_s=0.2) as robot:
        robot.send_velocity(5.0, -10.0)
        assert fake.wait_until(lambda: _commands(fake, Command.RVEL))
        assert _commands(fake, Command.VEL)[-1] == 200  # the lower limit asked for
        assert _commands(fake, Command.RVEL)[-1] == -100  # RotVelMax 100 °/s
        with pytest.raises(ValueError):
            robot.send_velocity(math.nan, 0.0)


@pytest.mark.parametrize("params", [quick_params()], ids=["quick-watchdogs"])
def test_keepalive_repeats_the_command_inside_the_controller_watchdog(fake, params):
    with P3DX(fake.port, params=params) as robot:
        robot.send_velocity(0.0, 0.3)
        robot.advance(2.0)  # longer than the controller's 1 s watchdog
        assert fake.log.watchdog_stops == []
        assert fake.commanded[1] == pytest.approx(math.radians(17))
        times = [t for t, c, _ in fake.log.commands if c == Command.RVEL]
        assert max(b - a for a, b in zip(times, times[1:])) < params.controller_watchdog_s / 2


def test_depth_frames_carry_the_pose_at_capture(fake, params):
    camera = FloorCamera()
    with P3DX(fake.port, camera, params=params) as robot:
        robot.send_velocity(0.0, 0.5)
        robot.advance(0.5)
        frame = robot.depth_frame()
        assert frame.robot_pose == robot.odometry().pose or frame.robot_pose.theta > 0.05
        assert frame.valid.any() and frame.timestamp_s > 0.4
    assert camera.closed == 1


def test_no_camera_is_a_typed_error_and_the_base_still_drives(fake, params):
    with P3DX(fake.port, None, params=params) as robot:
        with pytest.raises(NoCameraError, match="no depth camera"):
            robot.depth_frame()
        robot.send_velocity(0.1, 0.0)
        robot.advance(0.3)


def test_front_bump_stops_the_base_and_refuses_to_push_on(fake, params):
    with P3DX(fake.port, params=params) as robot:
        robot.send_velocity(0.3, 0.0)
        robot.advance(0.3)
        fake.faults.front_bump = True
        assert _advance_until(robot, lambda: robot.bumped)
        assert robot.stop_reason == "bump"
        assert fake.wait_until(lambda: fake.commanded == (0.0, 0.0))
        assert fake.log.stop_commands
        robot.send_velocity(0.2, 0.0)  # forward into the bumper: refused
        robot.advance(0.05)
        assert robot.bumped and fake.commanded == (0.0, 0.0)
        robot.send_velocity(-0.1, 0.0)  # backing away is allowed
        assert not robot.bumped
        robot.advance(0.15)
        assert fake.commanded[0] == pytest.approx(-0.1)


def test_wheel_stall_stops_the_base(fake, params):
    with P3DX(fake.port, params=params) as robot:
        robot.send_velocity(0.3, 0.0)
        robot.advance(0.2)
        fake.faults.stalled_left_wheel = True
        assert _advance_until(robot, lambda: robot.bumped)
        assert robot.stop_reason == "stall"
        assert fake.wait_until(lambda: fake.commanded == (0.0, 0.0))


def test_leaving_a_with_block_by_an_exception_stops_and_closes(fake, params):
    with pytest.raises(RuntimeError):
        with P3DX(fake.port, params=params) as robot:
            robot.send_velocity(0.3, 0.0)
            raise RuntimeError("boom")
    assert robot.stop_reason == "close()"
    assert fake.wait_until(lambda: fake.log.closed == 1)
    assert fake.commanded == (0.0, 0.0)


def test_missing_port_is_a_clear_error():
    robot = P3DX("/dev/ttyDOESNOTEXIST")
    with pytest.raises(SerialPortError, match="no such device"):
        robot.connect()
    assert not robot.is_connected


def test_the_port_is_exclusive(fake, params):
    with P3DX(fake.port, params=params):
        with pytest.raises(SerialPortError, match="in use"):
            P3DX(fake.port, params=params).connect()


def test_factory_builds_a_p3dx_from_its_spec(fake, params):
    robot = make_robot(f"p3dx:{fake.port}:nocamera", params=params)
    assert isinstance(robot, P3DX) and robot.camera is None and not robot.is_connected
    camera = FloorCamera()
    assert make_robot(f"p3dx:{fake.port}", camera=camera).camera is camera
    with pytest.raises(AssistantError, match="nocamera"):
        make_robot(f"p3dx:{fake.port}:fast")


def test_reconnect_after_close_starts_a_new_session(fake, params):
    robot = P3DX(fake.port, params=params)
    for _ in range(2):
        with robot:
            robot.send_velocity(0.0, 0.2)
            robot.advance(0.2)
    assert fake.wait_until(lambda: fake.log.closed == 2)
    assert fake.log.opened == 2


def test_disabled_motors_are_a_clear_error(params):
    with FakeArcosController(params, faults=Faults(motors_off=True)) as fake:
        with P3DX(fake.port, params=params) as robot:
            robot.advance(2.0)  # past the controller's second to act on ENABLE
            with pytest.raises(MotorsDisabledError, match="MOTORS button"):
                robot.send_velocity(0.2, 0.0)
            robot.stop()  # stopping is always allowed
            assert robot.stop_reason == "stop()"


def test_a_camera_that_does_not_start_closes_the_base_again(fake, params):
    class DeadCamera(FloorCamera):
        def connect(self):
            raise RobotConnectionError("no Kinect found")

    robot = P3DX(fake.port, DeadCamera(), params=params)
    with pytest.raises(RobotConnectionError, match="no Kinect"):
        robot.connect()
    assert not robot.is_connected
    assert fake.wait_until(lambda: fake.log.closed == 1)
    assert not [t for t in reader_threads() if t.name.startswith("arcos-reader")]


def test_the_default_camera_is_the_kinect_adapter(fake, params):
    kinect = pytest.importorskip("assistant.robot.kinect")
    robot = make_robot(f"p3dx:{fake.port}", params=params)
    assert isinstance(robot.camera, kinect.Kinect)

"""The robot contract: checks every :class:`~assistant.robot.Robot` adapter must pass.

Like scikit-learn's ``check_estimator``, each check takes a *factory* — a callable returning a
fresh, unconnected robot — and raises ``AssertionError`` on a breach. Run them all on an adapter
with::

    for check in robot_checks():
        check(make_robot)

or, in pytest, parametrise over ``robot_checks()`` (see ``tests/robot/test_contract.py``). The
checks need no hardware beyond what the factory opens, drive the base at most 0.2 m/s for a
second, and close every robot they open.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator

import numpy as np

from assistant.robot.errors import DeviceAlreadyConnectedError, DeviceNotConnectedError
from assistant.robot.frames import CameraIntrinsics, DepthFrame, Odometry
from assistant.robot.interface import Robot

__all__ = ["robot_checks", "check_robot"]

RobotFactory = Callable[[], Robot]


def check_is_robot(make: RobotFactory) -> None:
    robot = make()
    assert isinstance(robot, Robot), f"{type(robot).__name__} does not implement Robot"
    assert not robot.is_connected, "a new robot must not be connected before connect()"


def check_connect_returns_self_and_close_is_idempotent(make: RobotFactory) -> None:
    robot = make()
    assert robot.connect() is robot
    assert robot.is_connected
    robot.close()
    assert not robot.is_connected
    robot.close()  # a second close is harmless
    assert not robot.is_connected


def check_context_manager(make: RobotFactory) -> None:
    robot = make()
    with robot as entered:
        assert entered is robot
        assert robot.is_connected
        robot.odometry()
    assert not robot.is_connected


def check_context_manager_closes_on_error(make: RobotFactory) -> None:
    robot = make()
    try:
        with robot:
            raise KeyError("boom")
    except KeyError:
        pass
    assert not robot.is_connected, "leaving a with block by an exception must close the robot"


def check_double_connect_raises(make: RobotFactory) -> None:
    with make() as robot:
        try:
            robot.connect()
        except DeviceAlreadyConnectedError:
            pass
        else:
            raise AssertionError("connect() on a connected robot must raise DeviceAlreadyConnectedError")


def check_commands_before_connect_raise(make: RobotFactory) -> None:
    _check_all_calls_raise(make(), "before connect()")


def check_commands_after_close_raise(make: RobotFactory) -> None:
    robot = make()
    robot.connect()
    robot.close()
    _check_all_calls_raise(robot, "after close()")


def _check_all_calls_raise(robot: Robot, when: str) -> None:
    calls = {
        "odometry()": lambda: robot.odometry(),
        "depth_frame()": lambda: robot.depth_frame(),
        "send_velocity()": lambda: robot.send_velocity(0.1, 0.0),
        "stop()": lambda: robot.stop(),
        "advance()": lambda: robot.advance(0.1),
        "time_s": lambda: robot.time_s,
        "bumped": lambda: robot.bumped,
    }
    for label, call in calls.items():
        try:
            call()
        except DeviceNotConnectedError as error:
            assert isinstance(error, ConnectionError)
            assert "connect" in str(error), f"{label}: the message should say to connect: {error}"
        else:
            raise AssertionError(f"{label} {when} must raise DeviceNotConnectedError")


def check_odometry(make: RobotFactory) -> None:
    with make() as robot:
        odo = robot.odometry()
        assert isinstance(odo, Odometry)
        assert all(math.isfinite(v) for v in (odo.pose.x, odo.pose.y, odo.pose.theta))
        assert -math.pi <= odo.pose.theta < math.pi


def check_depth_frame(make: RobotFactory) -> None:
    with make() as robot:
        frame = robot.depth_frame()
        assert isinstance(frame, DepthFrame)
        assert isinstance(frame.intrinsics, CameraIntrinsics)
        k = frame.intrinsics
        assert frame.depth_m.shape == (k.height, k.width)
        assert frame.depth_m.dtype == np.float32
        depth = frame.depth_m
        assert np.all(np.isfinite(depth)) and np.all(depth >= 0), "depth must be finite, ≥ 0 (0 = missing)"
        assert frame.valid.any(), "a frame should have some readings"
        assert 0.0 < frame.mount.height_m < 3.0
        transform = frame.camera_to_world()
        assert transform.shape == (4, 4) and np.allclose(transform[3], [0, 0, 0, 1])
        if frame.hit_ids is not None:
            assert frame.hit_ids.shape == depth.shape
            assert frame.hit_ids.max() < len(frame.hit_names)


def check_velocity_moves_and_stop_stops(make: RobotFactory) -> None:
    with make() as robot:
        if not robot.follows_commands:
            robot.send_velocity(0.0, 0.5)
            robot.stop()
            return
        start = robot.odometry()
        t0 = robot.time_s
        robot.send_velocity(0.0, 0.5)  # turning in place never bumps
        robot.advance(1.0)
        turned = robot.odometry()
        assert robot.time_s >= t0 + 0.99, "advance(1.0) must let a second of robot time pass"
        assert abs(_angle(turned.pose.theta - start.pose.theta)) > 0.05, "turning did not change the heading"
        robot.stop()
        robot.advance(3.0)
        still = robot.odometry()
        robot.advance(0.5)
        later = robot.odometry()
        assert abs(later.linear_m_s) < 1e-6 and abs(later.angular_rad_s) < 1e-6, "stop() must stop the base"
        assert abs(_angle(later.pose.theta - still.pose.theta)) < 1e-6


def check_bad_velocity_raises(make: RobotFactory) -> None:
    with make() as robot:
        for bad in ((math.nan, 0.0), (0.0, math.inf)):
            try:
                robot.send_velocity(*bad)
            except ValueError:
                pass
            else:
                raise AssertionError(f"send_velocity{bad} must raise ValueError")


def check_negative_advance_raises(make: RobotFactory) -> None:
    with make() as robot:
        try:
            robot.advance(-1.0)
        except ValueError:
            pass
        else:
            raise AssertionError("advance(-1) must raise ValueError")


def check_reconnect_after_close(make: RobotFactory) -> None:
    robot = make()
    with robot:
        pass
    with robot:
        assert robot.is_connected
        robot.odometry()


_CHECKS = (
    check_is_robot,
    check_connect_returns_self_and_close_is_idempotent,
    check_context_manager,
    check_context_manager_closes_on_error,
    check_double_connect_raises,
    check_commands_before_connect_raise,
    check_commands_after_close_raise,
    check_odometry,
    check_depth_frame,
    check_velocity_moves_and_stop_stops,
    check_bad_velocity_raises,
    check_negative_advance_raises,
    check_reconnect_after_close,
)


def robot_checks() -> Iterator[Callable[[RobotFactory], None]]:
    """Every contract check, in a stable order."""
    yield from _CHECKS


def check_robot(make: RobotFactory) -> None:
    """Run every contract check on an adapter (raises AssertionError on the first breach)."""
    for check in robot_checks():
        check(make)


def _angle(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi

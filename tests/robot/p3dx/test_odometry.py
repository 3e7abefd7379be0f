"""SIPs → odometry: counter wrap-around, conversion factors, the product's world frame."""

import math

import pytest

from assistant.geometry import Pose2D
from assistant.robot.p3dx import P3DXParams
from assistant.robot.p3dx.odometry import OdometryTracker
from assistant.robot.p3dx.sip import Sip


def _sip(x, y, th, left=0, right=0):
    return Sip(moving=False, x_raw=x % 0x8000, y_raw=y % 0x8000, th_raw=th, left_vel_raw=left,
               right_vel_raw=right, battery_v=12.0, left_stall=False, right_stall=False,
               front_bumpers=0, rear_bumpers=0, motors_enabled=True)


def test_first_sip_is_the_start_pose_and_motion_is_relative_to_it():
    tracker = OdometryTracker(P3DXParams(), start=Pose2D(1.0, 2.0, math.pi / 2))
    first = tracker.update(_sip(5000, 7000, 1024), 0.0)  # the controller's frame is arbitrary
    assert first.pose.as_tuple() == pytest.approx((1.0, 2.0, math.pi / 2))
    # the controller heading is 90° (1024 units), so +y in its frame is the robot's forward
    moved = tracker.update(_sip(5000, 7500, 1024), 0.1)
    assert moved.pose.x == pytest.approx(1.0, abs=1e-9)
    assert moved.pose.y == pytest.approx(2.5)  # 0.5 m forward from a start facing +y


def test_counters_wrap_without_a_jump():
    tracker = OdometryTracker(P3DXParams())
    tracker.update(_sip(0x7FF0, 0, 0), 0.0)
    after = tracker.update(_sip(0x7FF0 + 40, 0, 0), 0.1)  # wraps past 0x7FFF
    assert after.pose.x == pytest.approx(0.040)
    back = tracker.update(_sip(0x7FF0 - 10, 0, 0), 0.2)
    assert back.pose.x == pytest.approx(-0.010)


def test_distance_factor_scales_positions():
    tracker = OdometryTracker(P3DXParams(distance_mm_per_unit=0.485))
    tracker.update(_sip(0, 0, 0), 0.0)
    assert tracker.update(_sip(2000, 0, 0), 0.1).pose.x == pytest.approx(0.970)


def test_velocities_from_wheel_speeds():
    params = P3DXParams()
    odo = OdometryTracker(params).update(_sip(0, 0, 0, left=100, right=300), 0.0)
    assert odo.linear_m_s == pytest.approx(0.2)
    assert odo.angular_rad_s == pytest.approx(200 * params.diff_conv_factor / 2)
    assert odo.angular_rad_s == pytest.approx(0.2 / params.wheel_base_m, rel=1e-3)


def test_heading_wraps_into_the_products_range():
    tracker = OdometryTracker(P3DXParams())
    tracker.update(_sip(0, 0, 4000), 0.0)
    turned = tracker.update(_sip(0, 0, 100), 0.1)  # +196 units across the 4096 wrap
    assert turned.pose.theta == pytest.approx(196 * P3DXParams().angle_rad_per_unit, abs=2e-3)
    assert -math.pi <= turned.pose.theta < math.pi

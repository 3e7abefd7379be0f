"""``hardware/``: the files load, agree with the simulator, and bad values get clear errors."""

import shutil

import pytest
import yaml

from assistant.errors import DataFileError
from assistant.robot.frames import CameraIntrinsics, CameraMount
from assistant.robot.hardware import hardware_dir, kinect_intrinsics, kinect_mount
from assistant.robot.p3dx import P3DXParams, load_p3dx_params
from assistant.sim.kinematics import DiffDriveLimits


def test_p3dx_file_loads_and_matches_the_drivers_defaults():
    params = load_p3dx_params()
    assert params.source.endswith("p3dx.yaml")
    defaults = P3DXParams()
    for field in ("angle_rad_per_unit", "distance_mm_per_unit", "diff_conv_factor", "max_linear_m_s",
                  "max_angular_rad_s", "linear_accel_m_s2", "angular_accel_rad_s2", "sip_period_s",
                  "link_watchdog_s", "controller_watchdog_s"):
        assert getattr(params, field) == pytest.approx(getattr(defaults, field), rel=1e-6), field


def test_p3dx_limits_are_the_simulators():
    params, sim = load_p3dx_params(), DiffDriveLimits.p3dx()
    assert params.max_linear_m_s == pytest.approx(sim.max_linear_m_s)
    assert params.max_angular_rad_s == pytest.approx(sim.max_angular_rad_s)
    assert params.linear_accel_m_s2 == pytest.approx(sim.linear_accel_m_s2)
    assert params.angular_accel_rad_s2 == pytest.approx(sim.angular_accel_rad_s2)


def test_kinect_file_is_the_simulators_camera():
    assert kinect_intrinsics() == CameraIntrinsics.kinect_v1()
    mount, sim_mount = kinect_mount(), CameraMount()
    assert mount.height_m == pytest.approx(sim_mount.height_m)
    assert mount.tilt_rad == pytest.approx(sim_mount.tilt_rad)
    assert mount.forward_m == pytest.approx(sim_mount.forward_m)


def test_keepalive_is_inside_the_controller_watchdog():
    params = load_p3dx_params()
    assert params.keepalive_s < params.controller_watchdog_s / 2
    assert params.link_watchdog_s < params.controller_watchdog_s


def _edited(tmp_path, section, key, value):
    shutil.copy(hardware_dir() / "p3dx.yaml", tmp_path / "p3dx.yaml")
    data = yaml.safe_load((tmp_path / "p3dx.yaml").read_text())
    data[section][key] = value
    (tmp_path / "p3dx.yaml").write_text(yaml.safe_dump(data))
    return tmp_path


@pytest.mark.parametrize("section,key,value,message", [
    ("limits", "max_linear_m_s", "fast", "limits.max_linear_m_s: expected a number"),
    ("limits", "max_linear_m_s", -1, "expected a positive number"),
    ("geometry", "wheel_base_m", 0.5, "disagrees with conversion.diff_conv_factor"),
    ("timing", "keepalive_s", 5.0, "shorter than controller_watchdog_s"),
    ("serial", "baud", 1234, "serial.baud"),
])
def test_bad_values_name_the_file_and_key(tmp_path, section, key, value, message):
    with pytest.raises(DataFileError, match=message) as error:
        load_p3dx_params(_edited(tmp_path, section, key, value))
    assert "p3dx.yaml" in str(error.value)


def test_missing_file_says_how_to_point_at_one(tmp_path, monkeypatch):
    monkeypatch.setenv("ASSISTANT_HARDWARE", str(tmp_path))
    with pytest.raises(DataFileError, match="ASSISTANT_HARDWARE"):
        load_p3dx_params()


def test_udev_rules_cover_the_serial_adapters_and_the_kinect():
    rules = (hardware_dir() / "udev" / "99-assistant-robot.rules").read_text()
    for ids in ('"0403", ATTRS{idProduct}=="6001"', '"067b"', '"10c4"', '"045e", ATTR{idProduct}=="02ae"',
                '"045e", ATTR{idProduct}=="02b0"'):
        assert ids in rules
    assert 'GROUP="dialout"' in rules

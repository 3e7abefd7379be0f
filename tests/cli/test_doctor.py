"""``assistant doctor``: every check reports a status and a fix; ports, permissions, the probe."""

from __future__ import annotations

import importlib.util
import json
import os
import re

import numpy as np

import pytest

from assistant.cli import main
from assistant.cli.doctor import check_kinect_usb, check_serial_ports, check_udev_rules, probe_kinect, run_checks
from assistant.robot.p3dx.fake import FakeArcosController, Faults, patient_params, quick_params


def _doctor_params(monkeypatch, params):
    """The doctor reads hardware/p3dx.yaml; give it these parameters instead."""
    monkeypatch.setattr("assistant.robot.p3dx.params.load_p3dx_params", lambda folder=None: params)
    monkeypatch.setattr("assistant.robot.p3dx.robot.load_p3dx_params", lambda folder=None: params)


@pytest.fixture(autouse=True)
def patient_watchdogs(monkeypatch):
    """Watchdogs a loaded test machine never trips."""
    _doctor_params(monkeypatch, patient_params())


def _by_name(checks):
    return {c.name: c for c in checks}


def test_json_output_lists_every_check_with_status_and_fix(capsys):
    status = main(["doctor", "--json"])
    out = json.loads(capsys.readouterr().out)
    names = {c["name"] for c in out["checks"]}
    assert {"pyserial", "hardware files", "udev rules", "libfreenect", "Kinect", "PortAudio", "espeak-ng"} <= names
    assert any(n.startswith("serial port") for n in names)
    assert all(c["status"] in ("ok", "warn", "fail") for c in out["checks"])
    assert all(c["fix"] for c in out["checks"] if c["status"] != "ok"), "every problem says what to fix"
    assert out["ok"] == (out["counts"]["fail"] == 0) and status == (0 if out["ok"] else 1)


def test_text_output_ends_with_a_summary(capsys):
    main(["doctor"])
    lines = capsys.readouterr().out.strip().splitlines()
    assert lines[-1].endswith("failures") and lines[0].startswith("[")


def test_no_adapter_is_a_warning_that_says_to_plug_it_in(tmp_path):
    (check,) = check_serial_ports(None, dev=str(tmp_path))
    assert check.status == "warn" and "plug" in check.fix


def test_a_port_this_user_may_not_open_names_the_group_to_join(tmp_path):
    master, slave = os.openpty()  # a real character device
    try:
        (check,) = check_serial_ports(os.ttyname(slave), access=lambda path, mode: False)
        assert check.status == "fail" and "usermod -aG" in check.fix
        (ok,) = check_serial_ports(os.ttyname(slave))
        assert ok.status == "ok"
    finally:
        os.close(master)
        os.close(slave)
    plain = tmp_path / "ttyUSB0"
    plain.write_text("")
    (bad,) = check_serial_ports(None, dev=str(tmp_path))
    assert bad.status == "fail" and "not a character device" in bad.detail
    (missing,) = check_serial_ports("/dev/ttyNOPE")
    assert missing.status == "fail" and "does not exist" in missing.detail


def test_kinect_is_found_in_sysfs(tmp_path):
    device = tmp_path / "sys" / "1-1"
    device.mkdir(parents=True)
    for name, value in {"idVendor": "045e", "idProduct": "02ae", "busnum": "1", "devnum": "7"}.items():
        (device / name).write_text(value + "\n")
    found = check_kinect_usb(str(tmp_path / "sys"), str(tmp_path / "dev"), os.access)
    assert found.status == "ok" and "045e:02ae" in found.detail
    node = tmp_path / "dev" / "bus" / "usb" / "001" / "007"
    node.parent.mkdir(parents=True)
    node.write_text("")
    denied = check_kinect_usb(str(tmp_path / "sys"), str(tmp_path / "dev"), lambda p, m: False)
    assert denied.status == "fail" and "plugdev" in denied.fix
    assert check_kinect_usb(str(tmp_path / "nothing"), str(tmp_path), os.access).status == "warn"


def test_udev_rules_check(tmp_path):
    assert check_udev_rules(str(tmp_path)).status == "warn"
    (tmp_path / "99-assistant-robot.rules").write_text("# installed\n")
    assert check_udev_rules(str(tmp_path)).status == "ok"


def test_probe_talks_to_the_controller_without_enabling_the_motors():
    with FakeArcosController(patient_params()) as fake:
        checks = _by_name(run_checks(port=fake.port, probe=True))
        assert checks["robot controller"].status == "ok"
        assert "fake-p3dx" in checks["robot controller"].detail and "12.6 V" in checks["robot controller"].detail
        assert fake.wait_until(lambda: fake.log.closed == 1)
        assert not any(cmd == 4 for _, cmd, _ in fake.log.commands), "ENABLE must not be sent"


def test_probe_of_a_silent_port_fails_with_the_reason(capsys, monkeypatch):
    _doctor_params(monkeypatch, quick_params())  # a shorter handshake timeout
    with FakeArcosController(quick_params(), faults=Faults(answer_sync=False)) as fake:
        status = main(["doctor", "--port", fake.port, "--probe", "--json"])
    out = json.loads(capsys.readouterr().out)
    probe = {c["name"]: c for c in out["checks"]}["robot controller"]
    assert probe["status"] == "fail" and "no robot controller answered" in probe["detail"]
    assert status == 1


def test_first_drive_moves_the_base_a_little_and_reports_the_odometry(capsys):
    with FakeArcosController(patient_params()) as fake:
        status = main(["doctor", "--port", fake.port, "--first-drive", "--json"])
        out = json.loads(capsys.readouterr().out)
        drive = {c["name"]: c for c in out["checks"]}["first drive"]
        assert drive["status"] == "ok", drive
        assert 0.19 <= fake.x_m <= 0.26 and fake.commanded == (0.0, 0.0)
        assert max(arg for _, cmd, arg in fake.log.commands if cmd == 11) == 100  # VEL ≤ 100 mm/s
    assert status == (1 if out["counts"]["fail"] else 0)


def test_kinect_probe_without_a_kinect_fails_with_the_adapters_reason():
    pytest.importorskip("assistant.robot.kinect")
    check = probe_kinect()
    assert check.status == "fail" and check.detail and "hardware/README.md" in check.fix


def test_kinect_probe_reads_a_frame_from_a_recording(tmp_path):
    kinect = pytest.importorskip("assistant.robot.kinect")
    recordings = pytest.importorskip("tests.robot.test_kinect")
    if importlib.util.find_spec("freenect") is None or not any(
            os.path.isdir(d) for d in kinect.FAKENECT_LIBRARY_DIRS):
        pytest.skip("needs the freenect binding and fakenect")
    wall = recordings.mm_to_raw_disparity(np.full((480, 640), 2000.0))
    recordings.write_fakenect_recording(tmp_path / "rec", [wall] * 4, [1.0, 1.5, 2.0, 2.5])
    check = probe_kinect(fakenect=tmp_path / "rec", depth_format="raw", timeout_s=3.0)
    assert check.status == "ok", check
    median = float(re.search(r"median ([0-9.]+) m", check.detail).group(1))
    assert abs(median - 2.0) < 0.05 and "1.05 m high" in check.detail

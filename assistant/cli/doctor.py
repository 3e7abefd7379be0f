"""``assistant doctor``: check this machine for the robot, the camera and audio, and say what to fix.

Each check gives ``ok``, ``warn`` (something only the hardware needs is missing) or ``fail``
(something is there but broken: a port you may not open, an invalid hardware file), a detail,
and the fix. ``--port PORT`` checks that serial port; ``--probe`` also opens an ARCOS session
on it (handshake, one status packet, close — the motors are not enabled) and reports the
controller's name and battery. ``--json`` prints one object: ``checks`` [{name, status, detail,
fix}], ``ok`` (no failures), ``counts``. The exit status is 1 when a check fails.
"""

from __future__ import annotations

import argparse
import ctypes.util
import glob
import grp
import importlib
import math
import os
import shutil
import stat
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from assistant.cli.common import add_json_flag, emit_json

UDEV_RULES = "99-assistant-robot.rules"
KINECT_VENDOR = "045e"
KINECT_CAMERA_PRODUCTS = ("02ae", "02bf")
SERIAL_GLOBS = ("ttyUSB*", "ttyACM*")
FIRST_DRIVE_M = 0.2
FIRST_DRIVE_SPEED_M_S = 0.1


@dataclass(frozen=True)
class Check:
    """The outcome of one check: ``status`` is ``ok``, ``warn`` or ``fail``."""

    name: str
    status: str
    detail: str
    fix: str = ""


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "doctor", help="check this machine for the robot (serial port), the Kinect and audio",
        description="Check serial ports and permissions, pyserial, the hardware files, libfreenect and "
                    "the Kinect, and audio (PortAudio, sounddevice, espeak-ng); say what to fix.")
    parser.add_argument("--port", help="the robot's serial port to check (default: every USB-serial port)")
    parser.add_argument("--probe", action="store_true",
                        help="with --port: talk to the controller (handshake, one status packet; no motion)")
    parser.add_argument("--kinect", action="store_true",
                        help="open the Kinect, read one depth frame, report what it sees, close it")
    parser.add_argument("--first-drive", action="store_true",
                        help=f"with --port: the bring-up drive — {FIRST_DRIVE_M:g} m straight ahead at "
                             f"{FIRST_DRIVE_SPEED_M_S:g} m/s, then stop; clear 1 m in front of the robot")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    checks = run_checks(port=args.port, probe=args.probe)
    if args.kinect:
        checks.append(probe_kinect())
    if args.first_drive:
        checks.append(first_drive(args.port))
    counts = {s: sum(c.status == s for c in checks) for s in ("ok", "warn", "fail")}
    if args.json:
        emit_json({"checks": [asdict(c) for c in checks], "ok": counts["fail"] == 0, "counts": counts})
    else:
        marks = {"ok": "ok  ", "warn": "WARN", "fail": "FAIL"}
        for check in checks:
            print(f"[{marks[check.status]}] {check.name}: {check.detail}")
            if check.fix and check.status != "ok":
                print(f"       fix: {check.fix}")
        print(f"{counts['ok']} ok, {counts['warn']} warnings, {counts['fail']} failures")
    return 1 if counts["fail"] else 0


def run_checks(port: str | None = None, probe: bool = False, *, dev: str = "/dev",
               sys_usb: str = "/sys/bus/usb/devices", udev_dir: str = "/etc/udev/rules.d",
               access: Callable[[str, int], bool] = os.access) -> list[Check]:
    """Every check, in the order they are printed (paths injectable for tests)."""
    checks = [check_pyserial(), check_hardware_files()]
    checks += check_serial_ports(port, dev=dev, access=access)
    if probe:
        checks.append(probe_controller(port))
    checks.append(check_udev_rules(udev_dir))
    checks += [check_freenect(), check_kinect_usb(sys_usb, dev, access)]
    checks += [check_portaudio(), check_module("sounddevice", "audio in/out (sounddevice)",
                                               "pip install sounddevice (needs PortAudio)"),
               check_espeak(), check_enrolment_tools()]
    return checks


# ---------------------------------------------------------------------------- robot base
def check_pyserial() -> Check:
    try:
        serial = importlib.import_module("serial")
    except ImportError:
        return Check("pyserial", "fail", "not installed (the P3-DX driver needs it)",
                     "pip install pyserial (or `make setup`)")
    return Check("pyserial", "ok", f"version {getattr(serial, '__version__', '?')}")


def check_hardware_files() -> Check:
    from assistant.errors import AssistantError
    from assistant.robot.hardware import hardware_dir, kinect_intrinsics, kinect_mount
    from assistant.robot.p3dx.params import load_p3dx_params

    try:
        params = load_p3dx_params()
        kinect_intrinsics()
        kinect_mount()
    except AssistantError as error:
        return Check("hardware files", "fail", str(error),
                     "fix the file named, or set $ASSISTANT_HARDWARE to a folder with p3dx.yaml and kinect.yaml")
    return Check("hardware files", "ok", f"{hardware_dir()}: p3dx.yaml (speed limit "
                                         f"{params.max_linear_m_s:g} m/s), kinect.yaml")


def check_serial_ports(port: str | None, *, dev: str = "/dev",
                       access: Callable[[str, int], bool] = os.access) -> list[Check]:
    """The given port, or every USB-serial port under ``dev``: present, readable and writable."""
    ports = [port] if port else sorted(p for pattern in SERIAL_GLOBS for p in glob.glob(os.path.join(dev, pattern)))
    if not ports:
        return [Check("serial port", "warn", f"no USB-serial adapter under {dev} (ttyUSB*, ttyACM*)",
                      "plug the USB-serial adapter into this computer and the robot's HOST serial port; "
                      "`dmesg | tail` shows whether the kernel saw it")]
    return [_check_port(p, access) for p in ports]


def _check_port(port: str, access: Callable[[str, int], bool]) -> Check:
    name = f"serial port {port}"
    try:
        info = os.stat(port)
    except FileNotFoundError:
        return Check(name, "fail", "does not exist", "check the name (`ls /dev/ttyUSB*`) and that the adapter is plugged in")
    if not stat.S_ISCHR(info.st_mode):
        return Check(name, "fail", "is not a character device (not a serial port)", "give the device, e.g. /dev/ttyUSB0")
    if access(port, os.R_OK | os.W_OK):
        return Check(name, "ok", "present, readable and writable")
    group = _group_name(info.st_gid)
    return Check(name, "fail", f"present, but this user may not open it (group {group}, mode {stat.filemode(info.st_mode)})",
                 f"sudo usermod -aG {group} $USER, then log out and in (or install hardware/udev/{UDEV_RULES})")


def probe_controller(port: str | None) -> Check:
    """Open an ARCOS session on ``port`` without enabling the motors; report the controller."""
    if not port:
        return Check("robot controller", "fail", "--probe needs --port", "add --port /dev/ttyUSB0")
    from assistant.errors import AssistantError
    from assistant.robot.p3dx.link import ArcosLink
    from assistant.robot.p3dx.params import load_p3dx_params

    link = ArcosLink(port, load_p3dx_params(), enable_motors=False)
    try:
        link.open()
        sip = link.last_sip
        battery = f", battery {sip.battery_v:.1f} V" if sip is not None else ""
        info = link.info
        return Check("robot controller", "ok",
                     f"{info.name or 'unnamed'} ({info.robot_class} {info.subclass}) answered on {port}{battery}")
    except AssistantError as error:
        return Check("robot controller", "fail", str(error), "see hardware/README.md, bring-up steps 1–4")
    finally:
        link.close()


def first_drive(port: str | None, camera=None) -> Check:
    """Drive :data:`FIRST_DRIVE_M` straight ahead at a walking-slow speed, stop, report the odometry.

    Compare the reported distance with a tape measure: a different figure means
    ``conversion.distance_mm_per_unit`` in ``hardware/p3dx.yaml`` is wrong for this robot.
    """
    if not port:
        return Check("first drive", "fail", "--first-drive needs --port", "add --port /dev/ttyUSB0")
    from assistant.errors import AssistantError
    from assistant.robot.p3dx.robot import P3DX

    robot = P3DX(port, camera, max_linear_m_s=FIRST_DRIVE_SPEED_M_S)
    try:
        with robot:
            start = robot.odometry().pose
            robot.send_velocity(FIRST_DRIVE_SPEED_M_S, 0.0)
            deadline = robot.time_s + 3 * FIRST_DRIVE_M / FIRST_DRIVE_SPEED_M_S
            while robot.odometry().pose.distance_to(start) < FIRST_DRIVE_M and robot.time_s < deadline:
                if robot.bumped:
                    return Check("first drive", "fail", "the base bumped or stalled", "clear the way, check the wheels")
                robot.advance(0.05)
            robot.stop()
            robot.advance(1.0)
            moved = robot.odometry().pose
    except AssistantError as error:
        return Check("first drive", "fail", str(error), "see hardware/README.md, bring-up steps 1–5")
    distance, turned = moved.distance_to(start), abs(moved.theta - start.theta)
    if distance < 0.5 * FIRST_DRIVE_M:
        return Check("first drive", "fail", f"odometry moved only {distance:.3f} m",
                     "are the motors enabled (MOTORS button) and the wheels on the floor?")
    return Check("first drive", "ok", f"odometry says {distance:.3f} m ahead, {turned:.3f} rad turned; "
                                      "measure the real distance with a tape",
                 "if the tape disagrees, scale conversion.distance_mm_per_unit in hardware/p3dx.yaml")


def check_udev_rules(udev_dir: str) -> Check:
    path = Path(udev_dir) / UDEV_RULES
    if path.exists():
        return Check("udev rules", "ok", f"{path} installed")
    return Check("udev rules", "warn", f"{path} not installed (the serial port and Kinect may need root)",
                 f"sudo cp hardware/udev/{UDEV_RULES} {udev_dir}/ && sudo udevadm control --reload-rules "
                 "&& sudo udevadm trigger")


# ---------------------------------------------------------------------------- camera
def check_freenect() -> Check:
    library = ctypes.util.find_library("freenect")
    try:
        importlib.import_module("freenect")
        binding = True
    except ImportError:
        binding = False
    if library and binding:
        return Check("libfreenect", "ok", f"library {library} and the Python binding `freenect`")
    missing = [what for what, there in (("the library", library), ("the Python binding", binding)) if not there]
    return Check("libfreenect", "warn", f"{' and '.join(missing)} missing (the Kinect needs both)",
                 "sudo apt-get install libfreenect0.5 libfreenect-dev, then pip install freenect "
                 "(`make setup` does both)")


def check_kinect_usb(sys_usb: str, dev: str, access: Callable[[str, int], bool]) -> Check:
    for device in sorted(glob.glob(os.path.join(sys_usb, "*"))):
        vendor, product = _read(device, "idVendor"), _read(device, "idProduct")
        if vendor != KINECT_VENDOR or product not in KINECT_CAMERA_PRODUCTS:
            continue
        bus, number = _read(device, "busnum"), _read(device, "devnum")
        node = os.path.join(dev, "bus", "usb", f"{int(bus or 0):03d}", f"{int(number or 0):03d}")
        if os.path.exists(node) and not access(node, os.R_OK | os.W_OK):
            return Check("Kinect", "fail", f"camera {vendor}:{product} at {node}, but this user may not open it",
                         f"install hardware/udev/{UDEV_RULES} and add yourself to plugdev")
        return Check("Kinect", "ok", f"camera {vendor}:{product} on USB bus {bus}, device {number}")
    return Check("Kinect", "warn", "no Kinect camera on USB",
                 "plug the Kinect into a USB 2 port and its own 12 V power supply (the USB plug alone "
                 "does not power it)")


def probe_kinect(**options) -> Check:
    """Open the Kinect adapter (``options`` go to it), read one frame, report it, close it."""
    from assistant.errors import AssistantError

    try:
        from assistant.robot.kinect import Kinect
    except ImportError as error:
        return Check("Kinect frame", "fail", f"the Kinect adapter cannot be loaded ({error})",
                     "run `make setup`")
    try:
        with Kinect(**options) as camera:
            frame = camera.depth_frame()
    except AssistantError as error:
        return Check("Kinect frame", "fail", str(error), "see hardware/README.md, bring-up steps 1–4 and 7")
    valid = frame.valid
    if not valid.any():
        return Check("Kinect frame", "fail", "a frame with no depth readings",
                     "take the lens cap off, aim the camera at the room (0.5–4.5 m), keep it out of sunlight")
    depths = frame.depth_m[valid]
    return Check("Kinect frame", "ok",
                 f"{frame.intrinsics.width}×{frame.intrinsics.height}, {valid.mean():.0%} of pixels with depth, "
                 f"median {float(np.median(depths)):.2f} m; mount {frame.mount.height_m:.2f} m high, tilted "
                 f"{math.degrees(frame.mount.tilt_rad):.1f}° down")


# ---------------------------------------------------------------------------- audio
def check_portaudio() -> Check:
    library = ctypes.util.find_library("portaudio")
    if library:
        return Check("PortAudio", "ok", f"library {library}")
    return Check("PortAudio", "warn", "not found (microphone and speaker access need it)",
                 "sudo apt-get install libportaudio2")


def check_module(module: str, label: str, fix: str) -> Check:
    try:
        loaded = importlib.import_module(module)
    except ImportError:
        return Check(label, "warn", f"`{module}` not installed", fix)
    except OSError as error:  # sounddevice raises this when PortAudio is missing
        return Check(label, "warn", f"`{module}` cannot load: {error}", fix)
    if module == "sounddevice":
        return _sound_devices(loaded, label)
    return Check(label, "ok", f"`{module}` available")


def _sound_devices(sounddevice, label: str) -> Check:
    try:
        devices = sounddevice.query_devices()
    except Exception as error:  # noqa: BLE001 - PortAudio reports its own errors; show them
        return Check(label, "warn", f"cannot list audio devices: {error}", "check that a sound card is present")
    inputs = sum(1 for d in devices if d.get("max_input_channels", 0) > 0)
    outputs = sum(1 for d in devices if d.get("max_output_channels", 0) > 0)
    if not inputs or not outputs:
        return Check(label, "warn", f"{inputs} input and {outputs} output devices",
                     "plug in a microphone and a speaker (or use typed chat)")
    return Check(label, "ok", f"{inputs} input and {outputs} output devices")


def check_espeak() -> Check:
    path = shutil.which("espeak-ng")
    if path:
        return Check("espeak-ng", "ok", f"{path} (spoken replies)")
    return Check("espeak-ng", "warn", "not installed (spoken replies need it)", "sudo apt-get install espeak-ng")


def check_enrolment_tools() -> Check:
    from assistant.dialogue.speech.enrol import INSTALL_HINT, tools

    missing = [name for name, path in tools().items() if path is None]
    if missing:
        return Check("speaker enrolment", "warn", f"{', '.join(missing)} not installed (assistant enrol needs them)",
                     INSTALL_HINT)
    return Check("speaker enrolment", "ok", "SphinxTrain's bw and map_adapt, sphinx_fe (assistant enrol)")


# ---------------------------------------------------------------------------- helpers
def _group_name(gid: int) -> str:
    try:
        return grp.getgrgid(gid).gr_name
    except KeyError:
        return str(gid)


def _read(folder: str, name: str) -> str:
    try:
        return Path(folder, name).read_text().strip()
    except OSError:
        return ""

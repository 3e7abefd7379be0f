"""A fake ARCOS controller on a pseudo-terminal, for tests and dry runs without a robot.

:class:`FakeArcosController` opens a pty pair (``pty.openpty``): the driver opens
:attr:`~FakeArcosController.port` as if it were ``/dev/ttyUSB0``, and a thread on the other end
answers like a P3-DX's controller — the SYNC handshake, OPEN/CLOSE, ENABLE, the speed and
acceleration settings, VEL/RVEL/STOP/PULSE — sends a standard SIP every ``sip_period_s`` (100 ms),
drives a differential-drive base with acceleration limits, and stops the motors by itself when no
client packet arrives for ``controller_watchdog_s``.

Faults to inject (attributes of :class:`Faults`, changeable while running): bad checksums,
dropped and truncated SIPs, garbage instead of SIPs, silence, a stalled wheel, a pressed front
bumper, a controller that never answers SYNC; and :meth:`~FakeArcosController.vanish` closes the
port mid-drive, as an unplugged USB adapter does.
"""

from __future__ import annotations

import math
import os
import random
import select
import threading
import time
import tty
from dataclasses import dataclass, field

import numpy as np

from assistant.robot.frames import (CameraIntrinsics, CameraMount, DepthFrame, camera_to_base_matrix,
                                    pixel_rays)
from assistant.robot.p3dx.commands import Command, decode_command
from assistant.robot.p3dx.odometry import heading_units
from assistant.robot.p3dx.packet import PacketDecoder, encode_packet
from assistant.robot.p3dx.params import P3DXParams
from assistant.robot.p3dx.sip import Sip, encode_sip

__all__ = ["Faults", "FakeArcosController", "FloorCamera", "MotionLog", "patient_params", "quick_params"]

_TICK_S = 0.01


def quick_params(params: P3DXParams | None = None) -> P3DXParams:
    """``params`` (default: built-in) with watchdogs short enough for tests that wait for them."""
    return (params or P3DXParams()).with_timing(link_watchdog_s=0.6, keepalive_s=0.1, command_timeout_s=1.0,
                                                controller_watchdog_s=1.0, handshake_timeout_s=2.0)


def patient_params(params: P3DXParams | None = None) -> P3DXParams:
    """``params`` with watchdogs long enough that a heavily loaded test machine never trips them
    (for tests of something else than the watchdogs)."""
    return (params or P3DXParams()).with_timing(link_watchdog_s=2.0, keepalive_s=0.25, command_timeout_s=4.0,
                                                controller_watchdog_s=4.0, handshake_timeout_s=4.0)


class FloorCamera:
    """A stand-in depth camera for the fake base: an empty flat floor seen from the mount."""

    def __init__(self, intrinsics: CameraIntrinsics | None = None, mount: CameraMount | None = None,
                 max_range_m: float = 4.5):
        self.intrinsics = intrinsics or CameraIntrinsics.kinect_v1()
        self.mount = mount or CameraMount()
        self.closed = 0
        down = pixel_rays(self.intrinsics) @ camera_to_base_matrix(self.mount)[:3, :3].T
        dz = down[..., 2]  # metres of height lost per metre of depth along each ray
        with np.errstate(divide="ignore", invalid="ignore"):
            depth = np.where(dz < -1e-6, -self.mount.height_m / dz, 0.0)
        self._depth = np.where(depth <= max_range_m, depth, 0.0).astype(np.float32)

    def depth_frame(self) -> DepthFrame:
        return DepthFrame(self._depth.copy(), self.intrinsics, self.mount)

    def close(self) -> None:
        self.closed += 1


@dataclass
class Faults:
    """What goes wrong on the fake controller (probabilities per SIP, or switches)."""

    bad_checksum: float = 0.0
    drop: float = 0.0
    truncate: float = 0.0
    garbage: bool = False  # random bytes instead of SIPs
    silent: bool = False  # no SIPs at all (commands still obeyed)
    answer_sync: bool = True
    stalled_left_wheel: bool = False
    front_bump: bool = False
    motors_off: bool = False  # the motor switch is off / the e-stop is pressed: ENABLE is ignored


@dataclass
class MotionLog:
    """What the fake saw: every command, and when the motors were last told to stop."""

    commands: list[tuple[float, int, int | None]] = field(default_factory=list)
    stop_commands: list[float] = field(default_factory=list)
    watchdog_stops: list[float] = field(default_factory=list)
    sips_sent: list[float] = field(default_factory=list)  # whole, valid SIPs written
    opened: int = 0
    closed: int = 0


class FakeArcosController:
    """An ARCOS controller simulated on a pty (see the module docstring). Use as a context manager."""

    def __init__(self, params: P3DXParams | None = None, *, faults: Faults | None = None,
                 seed: int = 0, name: str = "fake-p3dx"):
        self.params = params or P3DXParams()
        self.faults = faults or Faults()
        self.robot_name = name
        self.log = MotionLog()
        self._rng = random.Random(seed)
        self._lock = threading.RLock()
        self._stop = threading.Event()
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        os.set_blocking(self._master, False)
        self.port = os.ttyname(self._slave)
        self._vanished = False
        self._decoder = PacketDecoder()
        self._sync_step = 0
        self._open = False
        self._enabled = False
        # kinematics: metres, radians, seconds
        self.x_m = self.y_m = self.theta_rad = 0.0
        self.v_m_s = self.w_rad_s = 0.0
        self._cmd = (0.0, 0.0)
        self._max_v = self.params.max_linear_m_s
        self._max_w = self.params.max_angular_rad_s
        self._accel = (self.params.linear_accel_m_s2, self.params.angular_accel_rad_s2)
        self._last_packet_at = time.monotonic()
        self._thread = threading.Thread(target=self._run, name="fake-arcos", daemon=True)
        self._thread.start()

    # ------------------------------------------------------------------ control from tests
    def __enter__(self) -> "FakeArcosController":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        """Stop the controller thread (joined) and close both ends of the pty."""
        self._stop.set()
        self._thread.join(timeout=2.0)
        self._close_fds()

    def vanish(self) -> None:
        """Close the port as an unplugged adapter would; the base keeps running on its watchdog."""
        self._close_fds()

    def _close_fds(self) -> None:
        with self._lock:
            self._vanished = True
            for fd in (self._master, self._slave):
                if fd >= 0:
                    os.close(fd)
            self._master = self._slave = -1

    def wait_until(self, predicate, timeout_s: float = 3.0) -> bool:
        """Poll ``predicate()`` until true or ``timeout_s`` passes (the fake reads every 10 ms)."""
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            if predicate():
                return True
            time.sleep(_TICK_S)
        return bool(predicate())

    @property
    def commanded(self) -> tuple[float, float]:
        """The velocity the controller is driving towards (m/s, rad/s)."""
        with self._lock:
            return self._cmd

    @property
    def velocity(self) -> tuple[float, float]:
        """The base's actual velocity (m/s, rad/s)."""
        with self._lock:
            return self.v_m_s, self.w_rad_s

    @property
    def is_open(self) -> bool:
        return self._open

    # ------------------------------------------------------------------ the controller thread
    def _run(self) -> None:
        last = time.monotonic()
        next_sip = last + self.params.sip_period_s
        while not self._stop.is_set():
            self._receive()
            now = time.monotonic()
            with self._lock:
                self._watchdog(now)
                self._integrate(now - last)
            last = now
            if now >= next_sip:  # on time, or at once after a stall (no burst of late SIPs)
                next_sip = max(next_sip + self.params.sip_period_s, now)
                if self._open:
                    self._send_sip()
            time.sleep(_TICK_S)

    def _receive(self) -> None:
        with self._lock:
            if self._vanished:
                return
            try:
                ready, _, _ = select.select([self._master], [], [], 0)
                data = os.read(self._master, 4096) if ready else b""
            except OSError:  # no client has the port open
                return
        for payload in self._decoder.feed(data):
            self._last_packet_at = time.monotonic()
            try:
                command, argument = decode_command(payload)
            except ValueError:
                continue
            with self._lock:
                self.log.commands.append((self._last_packet_at, command, argument))
                self._handle(command, argument)

    def _handle(self, command: int, argument: int | None) -> None:
        if not self._open:
            self._handshake(command)
            return
        if command == Command.SYNC0:  # PULSE
            return
        if command == Command.SYNC2:  # CLOSE
            self._open = self._enabled = False
            self._sync_step = 0
            self._cmd = (0.0, 0.0)
            self.log.closed += 1
            return
        self._motion_command(command, argument)

    def _handshake(self, command: int) -> None:
        if command == Command.SYNC1 and self._sync_step == 3:  # OPEN
            self._open = True
            self.log.opened += 1
            return
        if not self.faults.answer_sync or command > 2:
            return
        if command != self._sync_step:
            self._sync_step = 0
            if command != 0:
                return
        reply = bytes([command])
        if command == 2:
            reply += b"\x00".join(s.encode() for s in (self.robot_name, "Pioneer", "p3dx-sh")) + b"\x00"
        self._write(encode_packet(reply))
        self._sync_step = command + 1

    def _motion_command(self, command: int, argument: int | None) -> None:
        arg = argument or 0
        if command == Command.ENABLE:
            self._enabled = arg == 1 and not self.faults.motors_off
            if not self._enabled:
                self._cmd = (0.0, 0.0)
        elif command == Command.VEL:
            self._cmd = (max(-self._max_v, min(self._max_v, arg / 1000.0)), self._cmd[1])
        elif command == Command.RVEL:
            self._cmd = (self._cmd[0], max(-self._max_w, min(self._max_w, math.radians(arg))))
        elif command in (Command.STOP, Command.ESTOP):
            self._cmd = (0.0, 0.0)
            self.log.stop_commands.append(time.monotonic())
        elif command == Command.SETV and arg > 0:
            self._max_v = arg / 1000.0
        elif command == Command.SETRV and arg > 0:
            self._max_w = math.radians(arg)
        elif command == Command.SETA and arg > 0:
            self._accel = (arg / 1000.0, self._accel[1])
        elif command == Command.SETRA and arg > 0:
            self._accel = (self._accel[0], math.radians(arg))

    def _watchdog(self, now: float) -> None:
        if self._cmd != (0.0, 0.0) and now - self._last_packet_at > self.params.controller_watchdog_s:
            self._cmd = (0.0, 0.0)
            self.log.watchdog_stops.append(now)

    def _integrate(self, dt: float) -> None:
        target_v, target_w = self._cmd if self._enabled else (0.0, 0.0)
        if self.faults.stalled_left_wheel or (self.faults.front_bump and target_v > 0):
            target_v = target_w = 0.0
            self.v_m_s = self.w_rad_s = 0.0
        self.v_m_s = _approach(self.v_m_s, target_v, self._accel[0] * dt)
        self.w_rad_s = _approach(self.w_rad_s, target_w, self._accel[1] * dt)
        self.theta_rad += self.w_rad_s * dt
        self.x_m += self.v_m_s * math.cos(self.theta_rad) * dt
        self.y_m += self.v_m_s * math.sin(self.theta_rad) * dt

    # ------------------------------------------------------------------ SIPs and faults
    def _sip(self) -> Sip:
        p = self.params
        with self._lock:
            half_track_mm = 1.0 / p.diff_conv_factor  # wheel base / 2, in mm
            v_mm, w = self.v_m_s * 1000.0, self.w_rad_s
            left = (v_mm - w * half_track_mm) / p.velocity_mm_s_per_unit
            right = (v_mm + w * half_track_mm) / p.velocity_mm_s_per_unit
            driving = self._cmd != (0.0, 0.0)
            x_units = int(round(self.x_m * 1000.0 / p.distance_mm_per_unit))
            y_units = int(round(self.y_m * 1000.0 / p.distance_mm_per_unit))
            return Sip(moving=abs(self.v_m_s) > 0 or abs(self.w_rad_s) > 0,
                       x_raw=x_units % 0x8000, y_raw=y_units % 0x8000,
                       th_raw=heading_units(self.theta_rad, p),
                       left_vel_raw=int(round(left)), right_vel_raw=int(round(right)), battery_v=12.6,
                       left_stall=self.faults.stalled_left_wheel and driving, right_stall=False,
                       front_bumpers=1 if self.faults.front_bump else 0, rear_bumpers=0,
                       motors_enabled=self._enabled,
                       sonar_raw={i: 1500 + 100 * i for i in range(4)})

    def _send_sip(self) -> None:
        f, rng = self.faults, self._rng
        if f.silent or (f.drop and rng.random() < f.drop):
            return
        if f.garbage:
            self._write(bytes(rng.randrange(256) for _ in range(rng.randrange(10, 40))))
            return
        packet = bytearray(encode_packet(encode_sip(self._sip())))
        intact = True
        if f.bad_checksum and rng.random() < f.bad_checksum:
            packet[-1] ^= 0x5A
            intact = False
        if f.truncate and rng.random() < f.truncate:
            packet = packet[:rng.randrange(3, len(packet) - 1)]
            intact = False
        self._write(bytes(packet))
        if intact:
            self.log.sips_sent.append(time.monotonic())

    def _write(self, data: bytes) -> None:
        with self._lock:
            if self._vanished:
                return
            try:
                os.write(self._master, data)
            except OSError:  # no reader, or the buffer is full: the line drops bytes
                pass


def _approach(value: float, target: float, step: float) -> float:
    if value < target:
        return min(target, value + step)
    return max(target, value - step)

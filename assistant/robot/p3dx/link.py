"""The serial link to an ARCOS controller: handshake, a reader thread, keep-alive and watchdog.

:class:`ArcosLink` opens the port (pyserial), runs the SYNC0/SYNC1/SYNC2 handshake, OPENs the
connection, sets the speed and acceleration limits, arms the controller's bump-stall stop and
enables the motors. A reader thread then parses every SIP into odometry and, every
``keepalive_s``, re-sends the current velocity command (or PULSE) so the controller's own
watchdog never fires while the client is alive — and only while it is: with no call from the
program (:meth:`ArcosLink.touch`) for ``command_timeout_s`` the thread commands STOP, so a hung
program cannot leave the robot driving.

Safety, in the thread: no valid SIP for ``link_watchdog_s`` (a silent controller, or garbled
bytes) or a read error (the port vanished) ends the link: STOP is written if the port still
takes it, and :attr:`fault` holds a :class:`~assistant.robot.errors.LinkLostError` saying which.
A bump or a wheel stall while driving writes STOP at once and latches :attr:`bumped`. If this
process dies, the controller's watchdog stops the motors (``controller_watchdog_s``).
"""

from __future__ import annotations

import errno
import logging
import math
import threading
import time
from dataclasses import dataclass

from assistant.geometry import Pose2D
from assistant.robot.errors import HandshakeError, LinkLostError, SerialPortError
from assistant.robot.frames import Odometry
from assistant.robot.p3dx.commands import CLOSE, OPEN, PULSE, Command, command_payload
from assistant.robot.p3dx.odometry import OdometryTracker
from assistant.robot.p3dx.packet import DecoderStats, PacketDecoder, encode_packet
from assistant.robot.p3dx.params import P3DXParams
from assistant.robot.p3dx.sip import Sip, SipError, is_sip, parse_sip

__all__ = ["ArcosLink", "ControllerInfo"]

log = logging.getLogger(__name__)

_READ_TIMEOUT_S = 0.02
#: how long after ENABLE a "motors off" flag in a SIP is still taken for the controller's delay
MOTORS_GRACE_S = 1.0


@dataclass(frozen=True)
class ControllerInfo:
    """What the controller said about itself in its SYNC2 reply."""

    name: str = ""
    robot_class: str = ""
    subclass: str = ""


def _open_serial(port: str, baud: int):
    try:
        import serial
    except ImportError as error:  # the driver's one optional dependency
        raise SerialPortError(port, "pyserial is not installed",
                              "install it with `pip install pyserial` (or `make setup`)") from error
    try:
        return serial.Serial(port, baudrate=baud, timeout=_READ_TIMEOUT_S, write_timeout=0.5,
                             exclusive=True)
    except serial.SerialException as error:
        code = getattr(error, "errno", None)
        if code == errno.ENOENT:
            raise SerialPortError(port, "no such device", "is the USB-serial adapter plugged in? "
                                  "`ls /dev/ttyUSB*` lists the ports; `assistant doctor` checks them") from error
        if code == errno.EACCES:
            raise SerialPortError(port, "permission denied", "add yourself to the dialout group "
                                  "(`sudo usermod -aG dialout $USER`, then log out and in) or install "
                                  "hardware/udev/99-assistant-robot.rules") from error
        if code in (errno.EBUSY, errno.EAGAIN, errno.EWOULDBLOCK) or "lock" in str(error).lower():
            raise SerialPortError(port, "in use by another program",
                                  "close the other program (another assistant, minicom, a ROS driver)") from error
        raise SerialPortError(port, str(error), "check the port name and the cable") from error


class ArcosLink:
    """One client connection to an ARCOS controller on a serial port (see the module docstring).

    ``enable_motors=False`` opens a read-only session (``assistant doctor --probe``): status
    packets flow, the motors stay as they are.
    """

    def __init__(self, port: str, params: P3DXParams, *, start: Pose2D | None = None,
                 name: str | None = None, enable_motors: bool = True):
        self.port_name = port
        self.enable_motors = enable_motors
        self.params = params
        self.name = name or f"P3-DX on {port}"
        self.info = ControllerInfo()
        self._tracker = OdometryTracker(params, start)
        self._serial = None
        self._decoder = PacketDecoder()
        self._write_lock = threading.Lock()
        self._state_lock = threading.Lock()
        self._stop_event = threading.Event()
        self._first_sip = threading.Event()
        self._motors_on = threading.Event()
        self.failed = threading.Event()
        self._thread: threading.Thread | None = None
        self._t0 = 0.0
        self._odometry: Odometry | None = None
        self._sip: Sip | None = None
        self._command = (0, 0)  # (mm/s, deg/s) being driven
        self._last_sent = 0.0
        self._last_call = 0.0  # the client's last call (touch)
        self._enabled_at = 0.0  # when ENABLE was sent
        self._last_sip_at = 0.0
        self._last_bytes_at = 0.0
        self._bad_sips = 0
        self._contact = False
        self._contact_sides = (False, False)  # (front, rear) bumpers pressed
        self.bumped = False
        self.fault: LinkLostError | None = None
        self.stop_reason: str | None = None

    # ------------------------------------------------------------------ opening
    def open(self) -> None:
        """Open the port and the connection; raises SerialPortError or HandshakeError."""
        self._serial = _open_serial(self.port_name, self.params.baud)
        try:
            try:
                self._serial.reset_input_buffer()
                self.info = self._handshake()
                self._configure()
            except (OSError, _serial_exception()) as error:
                if isinstance(error, HandshakeError):
                    raise
                raise SerialPortError(self.port_name, f"the port failed during the handshake ({error})",
                                      "check the cable and that the port is a serial port") from error
            self._t0 = time.monotonic()
            self._last_sip_at = self._last_bytes_at = self._last_sent = self._last_call = self._t0
            self._thread = threading.Thread(target=self._run, name=f"arcos-reader {self.port_name}",
                                            daemon=True)
            self._thread.start()
            if not self._first_sip.wait(self.params.handshake_timeout_s) or self.fault is not None:
                detail = self.fault.reason if self.fault else "no status packet after OPEN"
                raise HandshakeError(self.port_name, detail)
            if self.enable_motors and not self._motors_on.wait(3 * self.params.sip_period_s + 0.1):
                log.warning("%s: the motors did not enable (emergency stop pressed or MOTORS off?)", self.name)
        except BaseException:
            self.close()
            raise

    def _handshake(self) -> ControllerInfo:
        deadline = time.monotonic() + self.params.handshake_timeout_s
        step = 0
        while time.monotonic() < deadline:
            self._write(command_payload(step))
            reply = self._await_reply(min(deadline, time.monotonic() + 0.4))
            if reply is not None and is_sip(reply):  # still open from an earlier client: close it
                self._write(command_payload(CLOSE))
                time.sleep(0.2)
                reply = None
            if reply is None or reply[0] != step:  # start over from SYNC0 on a clean line
                self._flush_input()
                step = 0
                continue
            if step == 2:
                return _controller_info(reply[1:])
            step += 1
        raise HandshakeError(self.port_name, f"no answer to SYNC{step} within "
                                             f"{self.params.handshake_timeout_s:g} s")

    def _flush_input(self) -> None:
        time.sleep(0.05)  # let a late reply arrive, then drop it
        self._serial.reset_input_buffer()
        self._decoder = PacketDecoder()

    def _await_reply(self, until: float) -> bytes | None:
        while time.monotonic() < until:
            data = self._read()
            for payload in self._decoder.feed(data):
                return payload
        return None

    def _configure(self) -> None:
        p = self.params
        self._write(command_payload(OPEN))
        time.sleep(0.02)
        accel_mm = int(round(p.linear_accel_m_s2 * 1000))
        accel_deg = int(round(math.degrees(p.angular_accel_rad_s2)))
        for command, argument in (
                (Command.SETV, int(round(p.max_linear_m_s * 1000))),
                (Command.SETRV, int(round(math.degrees(p.max_angular_rad_s)))),
                (Command.SETA, accel_mm), (Command.SETA, -accel_mm),
                (Command.SETRA, accel_deg), (Command.SETRA, -accel_deg),
                (Command.BUMPSTALL, p.bump_stall)):
            self._write(command_payload(command, argument))
        if self.enable_motors:
            self._write(command_payload(Command.ENABLE, 1))
            self._enabled_at = time.monotonic()

    # ------------------------------------------------------------------ commands
    def touch(self) -> None:
        """Note that the client is alive (every call on the robot does this)."""
        self._last_call = time.monotonic()

    def drive(self, linear_mm_s: int, angular_deg_s: int) -> None:
        """Command a forward speed (mm/s) and a turn rate (deg/s); refuses to push into a contact."""
        self._raise_fault()
        self.touch()
        with self._state_lock:
            if self._contact and self._into_contact(linear_mm_s):
                self.bumped = True
                linear_mm_s = angular_deg_s = 0
            else:
                self.bumped = False
            self._command = (linear_mm_s, angular_deg_s)
        try:
            if linear_mm_s == 0 and angular_deg_s == 0:
                self._write(command_payload(Command.STOP))
            else:
                self._send_command()
        except (OSError, _serial_exception()) as error:
            self._fail("port vanished", f"writing failed: {error}")
            raise self.fault from error

    def stop(self, reason: str) -> None:
        """Command zero velocity (STOP); never raises, even on a failed link."""
        with self._state_lock:
            self._command = (0, 0)
            self.stop_reason = reason
        try:
            self._write(command_payload(Command.STOP))
        except (OSError, LinkLostError, _serial_exception()):
            pass

    def odometry(self) -> Odometry:
        self._raise_fault()
        with self._state_lock:
            assert self._odometry is not None  # open() waited for the first SIP
            return self._odometry

    @property
    def motors_disabled(self) -> bool:
        """True when the latest SIP, received a second or more after ENABLE, says the motors are off
        (the second lets the controller act on ENABLE before its flag is believed)."""
        sip = self._sip
        return (sip is not None and not sip.motors_enabled
                and self._last_sip_at - self._enabled_at > MOTORS_GRACE_S)

    @property
    def line_stats(self) -> DecoderStats:
        """Packets decoded, bad checksums and bytes skipped on this link so far."""
        return self._decoder.stats

    @property
    def last_sip(self) -> Sip | None:
        return self._sip

    def time_s(self) -> float:
        return time.monotonic() - self._t0

    def sonar_m(self) -> dict[int, float]:
        sip = self._sip
        return self._tracker.sonar_m(sip) if sip is not None else {}

    def _raise_fault(self) -> None:
        if self.fault is not None:
            raise self.fault

    # ------------------------------------------------------------------ closing
    def close(self) -> None:
        """Stop the reader thread (joined), command STOP and CLOSE, release the port."""
        self._stop_event.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
        self._thread = None
        if self._serial is not None:
            try:
                if self.fault is None or self.fault.reason != "port vanished":
                    self._write(command_payload(Command.STOP))
                    self._write(command_payload(CLOSE))
                    self._serial.flush()
            except (OSError, _serial_exception()):
                pass
            try:
                self._serial.close()
            except (OSError, _serial_exception()):
                pass
            self._serial = None

    # ------------------------------------------------------------------ the reader thread
    def _run(self) -> None:
        p = self.params
        while not self._stop_event.is_set():
            try:
                data = self._read()
            except (OSError, _serial_exception()) as error:
                self._fail("port vanished", str(error))
                return
            now = time.monotonic()
            if data:
                self._last_bytes_at = now
            for payload in self._decoder.feed(data):
                if is_sip(payload):
                    self._handle_sip(payload, now)
            silent_for = now - self._last_sip_at
            limit = p.link_watchdog_s if self._first_sip.is_set() else p.handshake_timeout_s
            # judge once the line is drained (a thread the machine held up reads what queued
            # meanwhile first), but never later than two watchdog periods
            if silent_for > limit and (silent_for > 2 * limit or not self._pending()):
                garbled = self._last_bytes_at > self._last_sip_at
                self._fail("garbled data" if garbled else "silent controller",
                           f"no valid status packet for {silent_for:.2f} s"
                           + (f"; {self._decoder.stats.bad_checksums} bad checksums, "
                              f"{self._bad_sips} unreadable SIPs" if garbled else ""))
                return
            if self._command != (0, 0) and now - self._last_call > p.command_timeout_s:
                log.warning("%s: no call from the program for %.1f s: stopping the base", self.name,
                            now - self._last_call)
                self.stop("command timeout")
            if now - self._last_sent >= p.keepalive_s:
                try:
                    self._send_command()
                except (OSError, _serial_exception()) as error:
                    self._fail("port vanished", str(error))
                    return

    def _handle_sip(self, payload: bytes, now: float) -> None:
        try:
            sip = parse_sip(payload)
        except SipError:
            self._bad_sips += 1
            return
        with self._state_lock:
            self._sip = sip
            self._odometry = self._tracker.update(sip, now - self._t0)
            self._last_sip_at = now
            contact = sip.bumped or sip.stalled
            rising = contact and not self._contact
            self._contact_sides = (sip.front_bumpers != 0, sip.rear_bumpers != 0)
            self._contact = contact
            driving = self._command != (0, 0)
        self._first_sip.set()
        if sip.motors_enabled:
            self._motors_on.set()
        if rising and driving:
            what = "stall" if sip.stalled else "bump"
            log.warning("%s: %s flag in the status packet: stopping the base", self.name, what)
            with self._state_lock:
                self.bumped = True
            self.stop(what)

    def _into_contact(self, linear_mm_s: int) -> bool:
        front, rear = self._contact_sides
        if not (front or rear):  # a stall: any drive pushes on
            return linear_mm_s != 0
        return (front and linear_mm_s > 0) or (rear and linear_mm_s < 0)

    def _fail(self, reason: str, detail: str) -> None:
        if self.fault is not None:
            return
        self.fault = LinkLostError(self.name, reason, detail)
        log.error("%s", self.fault)
        self.stop(f"link lost: {reason}")
        self.failed.set()

    # ------------------------------------------------------------------ I/O
    def _send_command(self) -> None:
        linear, angular = self._command
        if linear == 0 and angular == 0:
            self._write(command_payload(PULSE))
            return
        self._write(command_payload(Command.VEL, linear))
        self._write(command_payload(Command.RVEL, angular))

    def _write(self, payload: bytes) -> None:
        port = self._serial
        if port is None:
            raise LinkLostError(self.name, "port vanished", "the port is closed")
        with self._write_lock:
            port.write(encode_packet(payload))
            self._last_sent = time.monotonic()

    def _pending(self) -> int:
        """Bytes waiting in the port (0 when it cannot tell): a late thread reads them first."""
        port = self._serial
        try:
            return port.in_waiting if port is not None else 0
        except (OSError, _serial_exception()):
            return 0

    def _read(self) -> bytes:
        port = self._serial
        if port is None:
            return b""
        waiting = port.in_waiting
        return port.read(waiting or 1)


def _controller_info(data: bytes) -> ControllerInfo:
    parts = [p.decode("ascii", "replace") for p in data.split(b"\x00")]
    parts += [""] * 3
    return ControllerInfo(parts[0], parts[1], parts[2])


def _serial_exception() -> type[BaseException]:
    try:
        import serial
    except ImportError:  # pragma: no cover - open() already needed pyserial
        return OSError
    return serial.SerialException

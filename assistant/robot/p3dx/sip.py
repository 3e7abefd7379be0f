"""The standard Server Information Packet (SIP): what ARCOS reports every cycle.

Payload layout (little-endian), after ARIA's ``ArRobot::processMotorPacket`` and p2os's
``SIP::ParseStandard`` (see ``docs/robot.md``)::

    type      u8    0x32 motors stopped, 0x33 moving
    XPOS      u16   15 bits, wraps at 0x8000 (× distance factor → mm)
    YPOS      u16   15 bits, likewise
    THPOS     s16   heading (× angle factor → rad), 4096 units a turn
    L VEL     s16   left wheel (× velocity factor → mm/s)
    R VEL     s16   right wheel
    BATTERY   u8    tenths of a volt
    STALLBUMP u16   low byte: bit 0 left-wheel stall, bits 1–7 rear bumpers;
                    high byte: bit 0 right-wheel stall, bits 1–7 front bumpers
    CONTROL   s16   heading set-point
    FLAGS     u16   bit 0 motors enabled
    COMPASS   u8
    SONARS    u8    n readings, then n × (sonar number u8, range u16)
    … optional I/O fields (ignored here)

:func:`encode_sip` is the inverse, for the fake controller and the tests.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field

__all__ = ["SIP_MOVING", "SIP_STOPPED", "Sip", "SipError", "encode_sip", "is_sip", "parse_sip"]

SIP_STOPPED = 0x32
SIP_MOVING = 0x33
_FIXED = struct.Struct("<BHHhhhBHhHBB")  # type … sonar count: 20 bytes


class SipError(ValueError):
    """A status packet too short or malformed to read."""


@dataclass(frozen=True)
class Sip:
    """One standard SIP in the controller's raw units (see the module docstring)."""

    moving: bool
    x_raw: int
    y_raw: int
    th_raw: int
    left_vel_raw: int
    right_vel_raw: int
    battery_v: float
    left_stall: bool
    right_stall: bool
    front_bumpers: int  # bit mask, bit 0 = first bumper
    rear_bumpers: int
    motors_enabled: bool
    sonar_raw: dict[int, int] = field(default_factory=dict)  # sonar number → range units

    @property
    def stalled(self) -> bool:
        return self.left_stall or self.right_stall

    @property
    def bumped(self) -> bool:
        return bool(self.front_bumpers or self.rear_bumpers)


def is_sip(payload: bytes) -> bool:
    """True for a standard SIP payload (type byte 0x32 or 0x33)."""
    return bool(payload) and payload[0] in (SIP_STOPPED, SIP_MOVING)


def parse_sip(payload: bytes) -> Sip:
    """Read a standard SIP payload; raises :class:`SipError` when it is truncated or not a SIP."""
    if not is_sip(payload):
        raise SipError(f"not a standard SIP (type byte {payload[:1].hex() or 'missing'})")
    if len(payload) < _FIXED.size:
        raise SipError(f"SIP truncated: {len(payload)} bytes, the fixed part needs {_FIXED.size}")
    (kind, x, y, th, lvel, rvel, battery, stall_bump, _control, flags, _compass,
     n_sonar) = _FIXED.unpack_from(payload)
    needed = _FIXED.size + 3 * n_sonar
    if len(payload) < needed:
        raise SipError(f"SIP truncated: {len(payload)} bytes, {n_sonar} sonar readings need {needed}")
    sonar = {}
    for i in range(n_sonar):
        number, rng = struct.unpack_from("<BH", payload, _FIXED.size + 3 * i)
        sonar[number] = rng
    low, high = stall_bump & 0xFF, stall_bump >> 8
    return Sip(moving=kind == SIP_MOVING, x_raw=x & 0x7FFF, y_raw=y & 0x7FFF, th_raw=th,
               left_vel_raw=lvel, right_vel_raw=rvel, battery_v=battery / 10.0,
               left_stall=bool(low & 1), right_stall=bool(high & 1), front_bumpers=high >> 1,
               rear_bumpers=low >> 1, motors_enabled=bool(flags & 1), sonar_raw=sonar)


def encode_sip(sip: Sip) -> bytes:
    """The payload of ``sip`` (inverse of :func:`parse_sip`; control and compass are 0)."""
    stall_bump = ((sip.front_bumpers << 1 | int(sip.right_stall)) << 8) | (sip.rear_bumpers << 1 | int(sip.left_stall))
    head = _FIXED.pack(SIP_MOVING if sip.moving else SIP_STOPPED, sip.x_raw & 0x7FFF, sip.y_raw & 0x7FFF,
                       sip.th_raw, sip.left_vel_raw, sip.right_vel_raw,
                       max(0, min(255, round(sip.battery_v * 10))), stall_bump & 0xFFFF, 0,
                       int(sip.motors_enabled), 0, len(sip.sonar_raw))
    body = b"".join(struct.pack("<BH", n, r) for n, r in sorted(sip.sonar_raw.items()))
    return head + body

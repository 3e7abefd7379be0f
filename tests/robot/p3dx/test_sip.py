"""Standard SIP parsing: fields, flags, sonar, truncation."""

import pytest

from assistant.robot.p3dx.sip import Sip, SipError, encode_sip, is_sip, parse_sip


def _sip(**changes) -> Sip:
    base = dict(moving=True, x_raw=1234, y_raw=32000, th_raw=2048, left_vel_raw=-150, right_vel_raw=310,
                battery_v=12.4, left_stall=False, right_stall=True, front_bumpers=0b00101, rear_bumpers=0,
                motors_enabled=True, sonar_raw={0: 500, 7: 5000})
    base.update(changes)
    return Sip(**base)


def test_round_trip_keeps_every_field():
    sip = _sip()
    assert parse_sip(encode_sip(sip)) == sip
    assert is_sip(encode_sip(sip))


def test_stall_and_bumper_bits():
    parsed = parse_sip(encode_sip(_sip(left_stall=True, right_stall=False, front_bumpers=0, rear_bumpers=3)))
    assert parsed.left_stall and not parsed.right_stall and parsed.stalled
    assert parsed.rear_bumpers == 3 and parsed.bumped
    quiet = parse_sip(encode_sip(_sip(right_stall=False, front_bumpers=0)))
    assert not quiet.stalled and not quiet.bumped


def test_position_counters_are_15_bits():
    payload = bytearray(encode_sip(_sip(x_raw=0x7FFF)))
    payload[2] |= 0x80  # a set top bit (unused by ARCOS) is ignored
    assert parse_sip(bytes(payload)).x_raw == 0x7FFF


def test_truncated_sips_raise():
    payload = encode_sip(_sip())
    with pytest.raises(SipError, match="truncated"):
        parse_sip(payload[:15])
    with pytest.raises(SipError, match="sonar"):
        parse_sip(payload[:-2])
    with pytest.raises(SipError, match="not a standard SIP"):
        parse_sip(b"\x90" + payload[1:])

"""The ARCOS packet codec: checksum, framing, and a decoder that survives a noisy line."""

import pytest

from assistant.robot.p3dx.commands import Command, command_payload, decode_command
from assistant.robot.p3dx.packet import PacketDecoder, checksum, encode_packet


def test_sync0_and_enable_packets_have_the_documented_bytes():
    # SYNC0 is "FA FB 03 00 00 00"; ENABLE 1 is "FA FB 06 04 3B 01 00 05 3B" (words 0x043B + 0x0100).
    assert encode_packet(command_payload(Command.SYNC0)) == bytes.fromhex("fafb03000000")
    assert encode_packet(command_payload(Command.ENABLE, 1)) == bytes.fromhex("fafb06043b0100053b")


def test_odd_length_payload_xors_its_last_byte():
    assert checksum(bytes([0x12, 0x34, 0x56])) == 0x1234 ^ 0x56
    assert checksum(b"") == 0


def test_negative_arguments_use_the_negative_int_type():
    payload = command_payload(Command.SETA, -300)
    assert payload == bytes([5, 0x1B, 300 & 0xFF, 300 >> 8])
    assert decode_command(payload) == (5, -300)
    assert decode_command(command_payload(Command.VEL, 250)) == (11, 250)
    assert decode_command(command_payload(Command.STOP)) == (29, None)


def test_oversized_payloads_and_arguments_are_refused():
    with pytest.raises(ValueError):
        encode_packet(bytes(201))
    with pytest.raises(ValueError):
        command_payload(Command.VEL, 70000)


def test_decoder_finds_packets_split_across_reads_and_behind_garbage():
    a, b = encode_packet(b"\x32abc"), encode_packet(b"\x33" + bytes(30))
    stream = b"\x00\xfa\x17garbage\xfa" + a + b
    decoder = PacketDecoder()
    out = []
    for i in range(len(stream)):  # one byte at a time
        out += decoder.feed(stream[i:i + 1])
    assert out == [b"\x32abc", b"\x33" + bytes(30)]
    assert decoder.stats.packets == 2 and decoder.stats.skipped_bytes > 0
    assert decoder.pending() == 0


def test_decoder_drops_bad_checksums_and_recovers_a_header_inside_them():
    good = encode_packet(b"\x32hello")
    bad = bytearray(good)
    bad[-1] ^= 0xFF
    decoder = PacketDecoder()
    assert decoder.feed(bytes(bad) + good) == [b"\x32hello"]
    assert decoder.stats.bad_checksums == 1


def test_truncated_packet_then_a_good_one():
    good = encode_packet(b"\x32" + bytes(20))
    decoder = PacketDecoder()
    # a packet cut after 8 bytes: its count swallows part of the next one, whose checksum then fails,
    # and the decoder resynchronises on the next header
    out = decoder.feed(good[:8] + good + good)
    assert out[-1] == b"\x32" + bytes(20)
    assert len(out) >= 1

"""The ARCOS packet codec: framing, checksum, and a resynchronising stream decoder.

Every packet on the Pioneer's serial line, in both directions, is::

    0xFA 0xFB  COUNT  PAYLOAD…  CHECKSUM_HI CHECKSUM_LO

``COUNT`` is the number of bytes after it (the payload plus the two checksum bytes). The
checksum runs over the payload: the payload read as big-endian 16-bit words summed modulo
2¹⁶, and an odd last byte XOR-ed into the low byte. The first payload byte is the command
number (client → controller) or the packet type (controller → client). Sources: ARIA's
``ArRobotPacket::calcCheckSum`` / ``finalizePacket`` and p2os's ``P2OSPacket::Build`` (see
``docs/robot.md``).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["HEADER", "MAX_PAYLOAD", "PacketDecoder", "DecoderStats", "checksum", "encode_packet"]

HEADER = b"\xfa\xfb"
#: ARCOS packets carry at most 200 bytes of payload (p2os refuses larger ones).
MAX_PAYLOAD = 200


def checksum(payload: bytes) -> int:
    """The ARCOS checksum of ``payload`` (an int in 0…0xFFFF)."""
    total = 0
    even = len(payload) - len(payload) % 2
    for i in range(0, even, 2):
        total = (total + ((payload[i] << 8) | payload[i + 1])) & 0xFFFF
    if len(payload) % 2:
        total ^= payload[-1]
    return total


def encode_packet(payload: bytes) -> bytes:
    """Frame ``payload`` (command or type byte first) as one ARCOS packet."""
    if not payload:
        raise ValueError("an ARCOS packet needs at least one payload byte")
    if len(payload) > MAX_PAYLOAD:
        raise ValueError(f"ARCOS payloads hold at most {MAX_PAYLOAD} bytes, got {len(payload)}")
    total = checksum(payload)
    return HEADER + bytes([len(payload) + 2]) + bytes(payload) + bytes([total >> 8, total & 0xFF])


@dataclass
class DecoderStats:
    """What a :class:`PacketDecoder` has seen: good packets, bad checksums, skipped bytes."""

    packets: int = 0
    bad_checksums: int = 0
    skipped_bytes: int = 0


class PacketDecoder:
    """Turn a byte stream into packet payloads, resynchronising on garbage.

    Feed it whatever the port returned; it returns the payloads of the complete packets with a
    good checksum, in order, and keeps a partial packet for the next call. Bytes that do not
    start a header, impossible byte counts and packets with a bad checksum are skipped (one byte
    at a time, so a real header hidden inside garbage is still found) and counted in ``stats``.
    """

    def __init__(self) -> None:
        self._buffer = bytearray()
        self.stats = DecoderStats()

    def feed(self, data: bytes) -> list[bytes]:
        self._buffer.extend(data)
        payloads: list[bytes] = []
        while True:
            payload = self._next()
            if payload is None:
                return payloads
            payloads.append(payload)

    def _next(self) -> bytes | None:
        buf = self._buffer
        while True:
            start = buf.find(HEADER)
            if start < 0:
                keep = 1 if buf[-1:] == HEADER[:1] else 0  # a header split across reads
                self._skip(len(buf) - keep)
                return None
            self._skip(start)
            if len(buf) < 3:
                return None
            count = buf[2]
            if count < 3 or count > MAX_PAYLOAD + 2:
                self._skip(1)
                continue
            if len(buf) < 3 + count:
                return None
            payload = bytes(buf[3:1 + count])
            received = (buf[1 + count] << 8) | buf[2 + count]
            if received != checksum(payload):
                self.stats.bad_checksums += 1
                self._skip(1)
                continue
            del buf[:3 + count]
            self.stats.packets += 1
            return payload

    def _skip(self, n: int) -> None:
        if n > 0:
            del self._buffer[:n]
            self.stats.skipped_bytes += n

    def pending(self) -> int:
        """Bytes held back waiting for the rest of a packet."""
        return len(self._buffer)

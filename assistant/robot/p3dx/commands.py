"""ARCOS client commands: numbers and the payloads that carry them.

A command payload is the command number, then for an integer argument the argument-type byte
(``0x3B`` for a value ≥ 0, ``0x1B`` for a negative one) and the magnitude as an unsigned
little-endian 16-bit word. Numbers from ARIA's ``ArCommands.h`` (the same in p2os's
``robot_params.hpp``); see ``docs/robot.md``.
"""

from __future__ import annotations

import enum
import struct

__all__ = ["CLOSE", "Command", "INT_ARG", "NEG_INT_ARG", "OPEN", "PULSE", "command_payload", "decode_command"]

INT_ARG = 0x3B
NEG_INT_ARG = 0x1B
STRING_ARG = 0x2B


class Command(enum.IntEnum):
    """The ARCOS commands this driver sends (and the fake controller understands)."""

    SYNC0 = 0  # also PULSE once connected: the keep-alive that feeds the controller's watchdog
    SYNC1 = 1  # also OPEN once synchronised
    SYNC2 = 2  # also CLOSE once open
    ENABLE = 4  # int: 1 enables the motors, 0 disables them
    SETA = 5  # int: translational acceleration (+) or deceleration (−), mm/s²
    SETV = 6  # int: maximum translational velocity, mm/s
    SETRV = 10  # int: maximum rotational velocity, deg/s
    VEL = 11  # int: translational velocity, mm/s
    RVEL = 21  # int: rotational velocity, deg/s (counter-clockwise positive)
    SETRA = 23  # int: rotational acceleration (+) or deceleration (−), deg/s²
    SONAR = 28  # int: 1 enables, 0 disables the sonar
    STOP = 29  # none: stop both wheels (motors stay enabled)
    BUMPSTALL = 44  # int: the controller stops on a front (1), rear (2) or either (3) bump
    ESTOP = 55  # none: emergency stop, ignores the deceleration limit


#: After the handshake the three SYNC numbers mean PULSE (keep-alive), OPEN and CLOSE.
PULSE = Command.SYNC0
OPEN = Command.SYNC1
CLOSE = Command.SYNC2


def command_payload(command: int, argument: int | None = None) -> bytes:
    """The payload of ``command`` with an optional signed 16-bit integer ``argument``."""
    if not 0 <= int(command) <= 255:
        raise ValueError(f"command numbers are bytes, got {command}")
    if argument is None:
        return bytes([int(command)])
    value = int(argument)
    if not -0xFFFF <= value <= 0xFFFF:
        raise ValueError(f"command {int(command)}: argument {value} does not fit 16 bits")
    kind = INT_ARG if value >= 0 else NEG_INT_ARG
    return bytes([int(command), kind]) + struct.pack("<H", abs(value))


def decode_command(payload: bytes) -> tuple[int, int | None]:
    """``(command, argument or None)`` of a command payload (the fake controller's side).

    Raises :class:`ValueError` for an argument type it does not know or a short payload.
    """
    if not payload:
        raise ValueError("empty command payload")
    command = payload[0]
    if len(payload) == 1:
        return command, None
    kind = payload[1]
    if kind == STRING_ARG:
        return command, None
    if kind not in (INT_ARG, NEG_INT_ARG) or len(payload) < 4:
        raise ValueError(f"command {command}: bad argument bytes {payload[1:].hex()}")
    magnitude = struct.unpack_from("<H", payload, 2)[0]
    return command, magnitude if kind == INT_ARG else -magnitude


"""The Kinect's libfreenect session, in a process of its own (``python -m assistant.robot.kinect_worker``).

:class:`~assistant.robot.kinect.Kinect` starts this program and talks to it over its standard
input and output, so a USB call that never returns can hang only this process, which the adapter
then ends; the product itself never waits on libfreenect without a timeout.

Protocol. Requests, one text line each on stdin: ``frame ID`` (send the newest depth frame no
request has had yet, at once if there is one, else when it arrives), ``tilt DEGREES`` (move the tilt motor), ``state ID`` (report the tilt state), ``quit``.
Replies on stdout, each ``b"KNCT"``, one type byte, a 4-byte little-endian payload length and
the payload: ``R`` ready (JSON: devices), ``F`` frame (``<IIHH``: request id, device timestamp,
width, height; then width × height little-endian uint16), ``S`` state (JSON: id, tilt_deg,
accel_m_s2), ``E`` error (JSON: kind "not_found" or "lost", message; the worker exits after it).
"""

from __future__ import annotations

import json
import os
import select
import struct
import sys

MAGIC = b"KNCT"
HEADER = struct.Struct("<4scI")
FRAME_HEADER = struct.Struct("<IIHH")
#: depth modes by the names the adapter uses
FORMATS = ("registered", "mm", "raw")


def _send(out, kind: bytes, payload: bytes) -> None:
    out.write(HEADER.pack(MAGIC, kind, len(payload)))
    out.write(payload)
    out.flush()


def _fail(out, kind: str, message: str) -> int:
    """Report an error (``kind``: "not_found" before the camera ran, "lost" after) and exit."""
    _send(out, b"E", json.dumps({"kind": kind, "message": message}).encode("utf-8"))
    return 1


def main(argv: list[str] | None = None) -> int:
    import argparse

    parser = argparse.ArgumentParser(prog="kinect_worker")
    parser.add_argument("--index", type=int, default=0)
    parser.add_argument("--format", choices=FORMATS, default="registered")
    args = parser.parse_args(argv)
    # the protocol gets its own copy of stdout; the C library's printf (fakenect's warnings)
    # goes to stderr instead of garbling it
    out = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    os.dup2(sys.stderr.fileno(), sys.stdout.fileno())
    # fakenect's stand-in libfreenect lacks a symbol libfreenect_sync asks for (camera_to_world,
    # never called here): resolve symbols lazily so the binding loads under it too
    sys.setdlopenflags(os.RTLD_LAZY | os.RTLD_GLOBAL)
    try:
        import freenect
    except ImportError as error:
        return _fail(out, "not_found", f"the Python binding of libfreenect is missing ({error}); install libfreenect-dev "
                          "and then `pip install freenect` (make setup does both)")
    ctx = freenect.init()
    if not ctx:
        return _fail(out, "not_found", "libfreenect could not start (no USB access?); see `assistant doctor`")
    count = freenect.num_devices(ctx)
    if count <= args.index:
        return _fail(out, "not_found", f"no Kinect found: libfreenect sees {count} device(s); plug the Kinect into USB and "
                          "its power adapter, then check `assistant doctor`")
    dev = freenect.open_device(ctx, args.index)
    if not dev:
        return _fail(out, "not_found", "the Kinect is there but could not be opened (permissions? another program using "
                          "it?); see the udev rules in hardware/")
    mode = {"registered": freenect.DEPTH_REGISTERED, "mm": freenect.DEPTH_MM, "raw": freenect.DEPTH_11BIT}[args.format]
    freenect.set_depth_mode(dev, freenect.RESOLUTION_MEDIUM, mode)
    return _serve(freenect, ctx, dev, out)


def _serve(freenect, ctx, dev, out) -> int:
    wanted: list[int] = []  # request ids waiting for a frame
    unsent: list[tuple] = []  # the newest frame no request has had yet (at most one)

    def on_depth(_dev, depth, timestamp):
        frame = (depth.astype("<u2", copy=False).tobytes(), int(timestamp) & 0xFFFFFFFF, depth.shape)
        unsent[:] = [frame]
        if wanted:
            _answer(out, wanted, unsent)

    freenect.set_depth_callback(dev, on_depth)
    freenect.start_depth(dev)
    _send(out, b"R", json.dumps({"devices": 1}).encode())
    stdin = sys.stdin.buffer
    pending = b""
    try:
        while True:
            readable, _, _ = select.select([stdin], [], [], 0)
            if readable:
                chunk = os.read(stdin.fileno(), 4096)
                if not chunk:
                    return 0  # the adapter went away
                pending += chunk
                while b"\n" in pending:
                    line, pending = pending.split(b"\n", 1)
                    if _handle(freenect, dev, out, line.decode().split(), wanted) == "quit":
                        return 0
                if wanted and unsent:
                    _answer(out, wanted, unsent)
            if freenect.process_events(ctx) < 0:
                return _fail(out, "lost", "the Kinect stopped answering on USB (unplugged, or its power adapter off)")
    finally:
        freenect.stop_depth(dev)
        freenect.close_device(dev)
        freenect.shutdown(ctx)


def _answer(out, wanted: list[int], unsent: list[tuple]) -> None:
    """Send the unsent frame to every waiting request."""
    data, timestamp, (height, width) = unsent.pop()
    for request in wanted:
        _send(out, b"F", FRAME_HEADER.pack(request, timestamp, width, height) + data)
    wanted.clear()


def _handle(freenect, dev, out, words: list[str], wanted: list[int]) -> str | None:
    if not words:
        return None
    if words[0] == "quit":
        return "quit"
    if words[0] == "frame":
        wanted.append(int(words[1]))
    elif words[0] == "tilt":
        freenect.set_tilt_degs(dev, float(words[1]))
    elif words[0] == "state":
        freenect.update_tilt_state(dev)
        state = freenect.get_tilt_state(dev)
        accel = freenect.get_mks_accel(state)
        _send(out, b"S", json.dumps({"id": int(words[1]), "tilt_deg": freenect.get_tilt_degs(state),
                                      "accel_m_s2": list(accel)}).encode())
    return None


if __name__ == "__main__":
    sys.exit(main())

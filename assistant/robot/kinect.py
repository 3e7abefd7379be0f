"""``Kinect``: the Kinect (v1) depth camera through libfreenect, never able to hang the product.

libfreenect runs in a worker process (:mod:`assistant.robot.kinect_worker`) that this adapter
starts and talks to over pipes; every wait on it has a deadline. So:

* no libfreenect binding, no Kinect on USB, or a Kinect that cannot be opened →
  :class:`KinectNotFoundError` at ``connect()``, with what to do;
* no frame for ``timeout_s`` (2 s by default, ``hardware/kinect.yaml``'s ``frame_timeout_s``) →
  :class:`KinectTimeoutError`; the camera stays open and the next read may succeed;
* a camera unplugged mid-session (the worker reports it, or dies) →
  :class:`KinectDisconnectedError`.

All three are :class:`~assistant.robot.errors.RobotConnectionError` s. Depth is read registered
to the colour camera in millimetres (``depth_format="registered"``, libfreenect's
``FREENECT_DEPTH_REGISTERED``), or unregistered in millimetres (``"mm"``), or as raw 11-bit
disparity converted here (``"raw"``, the only mode libfreenect's recorded-stream player
*fakenect* supports). The intrinsics and the mount (height, tilt, forward offset) come from
``hardware/kinect.yaml`` when it is there, else the Kinect defaults of
:mod:`assistant.robot.frames`; moving the tilt motor (:meth:`Kinect.set_tilt`) changes the
mount's tilt by the same angle.

``fakenect=PATH`` plays a fakenect recording (a folder of ``INDEX.txt`` and dumps) through the
same code path instead of a device: that is how the adapter is tested without a Kinect.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import select
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from assistant.errors import DataFileError
from assistant.robot import hardware
from assistant.robot.errors import DeviceNotConnectedError, RobotConnectionError
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame
from assistant.robot.kinect_worker import FORMATS, FRAME_HEADER, HEADER, MAGIC

__all__ = ["FAKENECT_LIBRARY_DIRS", "Kinect", "KinectDisconnectedError", "KinectError", "KinectNotFoundError",
           "KinectTimeoutError", "raw_disparity_to_mm"]

#: where Debian's libfreenect-bin puts fakenect's stand-in libfreenect
FAKENECT_LIBRARY_DIRS = ("/usr/lib/x86_64-linux-gnu/fakenect", "/usr/lib/aarch64-linux-gnu/fakenect",
                         "/usr/lib/fakenect", "/usr/local/lib/fakenect")
#: the tilt motor's range (degrees, positive tilts the camera up) when hardware/kinect.yaml has none
TILT_RANGE_DEG = (-27.0, 27.0)
#: how long the worker may take to find and open the camera
OPEN_TIMEOUT_S = 10.0


class KinectError(RobotConnectionError):
    """Something went wrong with the Kinect; the message says what to do."""


class KinectNotFoundError(KinectError):
    """No Kinect (or no libfreenect) to open."""


class KinectTimeoutError(KinectError):
    """The Kinect sent no frame within its timeout."""


class KinectDisconnectedError(KinectError):
    """The Kinect went away mid-session (unplugged, power lost, its worker died)."""


def raw_disparity_to_mm(raw: np.ndarray) -> np.ndarray:
    """Kinect v1 raw 11-bit disparity → uint16 millimetres (0 where there is no reading).

    Uses the OpenKinect community's fit of depth to disparity, ``z = 0.1236 m · tan(raw / 2842.5
    + 1.1863)`` (OpenKinect wiki, "Imaging Information"); 2047 means no reading, and the fit is
    only trusted up to raw 1050 (≈ 9 m), beyond which 0 is returned.
    """
    raw = np.asarray(raw, dtype=np.float64)
    valid = (raw < 1050) & (raw > 0)
    depth_m = 0.1236 * np.tan(np.where(valid, raw, 0.0) / 2842.5 + 1.1863)
    return np.where(valid & (depth_m > 0), np.round(depth_m * 1000.0), 0).astype(np.uint16)


def _hardware_camera() -> tuple[CameraIntrinsics, CameraMount, float, tuple[float, float]]:
    """Intrinsics, mount, frame timeout (s) and tilt motor range (degrees) from
    ``hardware/kinect.yaml``, or the defaults when the hardware folder has no such file (an
    installed package without the repository)."""
    if not (hardware.hardware_dir() / "kinect.yaml").is_file():
        return CameraIntrinsics.kinect_v1(), CameraMount(), 2.0, TILT_RANGE_DEG
    data = hardware.load_hardware_file("kinect.yaml")
    timeout = data.get("frame_timeout_s", 2.0)
    if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) or not 0 < timeout < math.inf:
        raise DataFileError(data["__path__"], "frame_timeout_s", f"expected a positive number of seconds, got {timeout!r}")
    tilt = TILT_RANGE_DEG
    if "tilt_motor" in data:
        tilt = (hardware.number(data, "tilt_motor", "min_deg", positive=False),
                hardware.number(data, "tilt_motor", "max_deg", positive=False))
    return hardware.kinect_intrinsics(), hardware.kinect_mount(), float(timeout), tilt


class Kinect:
    """A Kinect v1 depth camera (see the module docstring).

    ``connect()`` (or ``open()``) starts it, ``depth_frame()`` reads the next frame,
    ``close()`` ends it; usable in a ``with`` block. ``robot_pose`` of a frame is None: the robot
    adapter that carries the camera sets it.
    """

    def __init__(self, device_index: int = 0, *, depth_format: str = "registered",
                 intrinsics: CameraIntrinsics | None = None, mount: CameraMount | None = None,
                 timeout_s: float | None = None, fakenect: str | os.PathLike[str] | None = None):
        if depth_format not in FORMATS:
            raise ValueError(f"depth_format must be one of {', '.join(FORMATS)}, got {depth_format!r}")
        if fakenect is not None and depth_format != "raw":
            raise ValueError("fakenect recordings replay raw 11-bit depth only: use depth_format='raw'")
        hw_intrinsics, hw_mount, hw_timeout, self.tilt_range_deg = _hardware_camera()
        self.device_index = device_index
        self.depth_format = depth_format
        self.intrinsics = intrinsics or hw_intrinsics
        self.base_mount = mount or hw_mount
        self.timeout_s = float(timeout_s if timeout_s is not None else hw_timeout)
        self.fakenect = None if fakenect is None else Path(fakenect)
        self.name = f"Kinect #{device_index}" if fakenect is None else f"Kinect (fakenect {self.fakenect.name})"
        self.tilt_motor_deg = 0.0
        self._process: subprocess.Popen | None = None
        self._buffer = b""
        self._request = 0
        self._t0 = 0.0

    # ---------------------------------------------------------------- lifecycle
    @property
    def is_connected(self) -> bool:
        return self._process is not None

    def connect(self) -> "Kinect":
        """Start the camera; raises :class:`KinectNotFoundError` when there is none to start."""
        if self._process is not None:
            return self
        self._process = subprocess.Popen(
            [sys.executable, "-m", "assistant.robot.kinect_worker", "--index", str(self.device_index),
             "--format", self.depth_format],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=self._environment())
        self._buffer = b""
        try:
            kind, payload = self._reply(OPEN_TIMEOUT_S, "start")
            if kind != b"R":
                raise KinectNotFoundError(f"{self.name}: unexpected first reply {kind!r} from the camera worker")
        except KinectError as error:
            self.close()
            if isinstance(error, KinectNotFoundError):
                raise
            raise KinectNotFoundError(str(error)) from error
        self._t0 = time.monotonic()
        return self

    open = connect

    def close(self) -> None:
        """Stop the camera and its worker (at once if it does not answer); safe to repeat."""
        process, self._process = self._process, None
        if process is None:
            return
        try:
            process.stdin.write(b"quit\n")
            process.stdin.flush()
        except OSError:
            pass  # the worker is already gone
        try:
            process.wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            process.kill()  # stuck in a USB call
            process.wait(timeout=5.0)
        for stream in (process.stdin, process.stdout):
            try:
                stream.close()
            except OSError:  # a request still buffered for a worker that is gone
                pass

    def __enter__(self) -> "Kinect":
        return self.connect()

    def __exit__(self, *exc_info) -> None:
        self.close()

    # ---------------------------------------------------------------- reading
    @property
    def mount(self) -> CameraMount:
        """The camera mount now: the configured one, tilted by the tilt motor's angle (the motor's
        positive angle looks up; the mount's positive tilt looks down)."""
        return dataclasses.replace(self.base_mount,
                                   tilt_rad=self.base_mount.tilt_rad - math.radians(self.tilt_motor_deg))

    def read_millimetres(self) -> tuple[np.ndarray, int]:
        """The next depth image as uint16 millimetres (0 = no reading) and the device's timestamp."""
        self._request += 1
        self._command(f"frame {self._request}")
        deadline = time.monotonic() + self.timeout_s
        while True:
            kind, payload = self._reply(deadline - time.monotonic(), "send a depth frame")
            if kind != b"F":
                continue
            request, timestamp, width, height = FRAME_HEADER.unpack_from(payload)
            if request != self._request:
                continue  # the late answer to a request that timed out
            depth = np.frombuffer(payload, dtype="<u2", offset=FRAME_HEADER.size).reshape(height, width)
            if self.depth_format == "raw":
                depth = raw_disparity_to_mm(depth)
            return depth.astype(np.uint16), int(timestamp)

    def depth_frame(self) -> DepthFrame:
        """The next depth frame (metres, the mount as it is now, time since connect)."""
        millimetres, _ = self.read_millimetres()
        depth_m = millimetres.astype(np.float32) / np.float32(1000.0)
        intrinsics = self.intrinsics
        if (intrinsics.height, intrinsics.width) != depth_m.shape:
            raise KinectError(f"{self.name} sent a {depth_m.shape[1]}×{depth_m.shape[0]} image but its intrinsics "
                              f"are for {intrinsics.width}×{intrinsics.height}; fix hardware/kinect.yaml")
        return DepthFrame(depth_m, intrinsics, self.mount, None, time.monotonic() - self._t0)

    def set_tilt(self, degrees: float) -> float:
        """Move the tilt motor to ``degrees`` (positive up, clamped to the motor's range, ±27°);
        returns the angle set."""
        if not math.isfinite(degrees):
            raise ValueError(f"tilt must be a finite angle in degrees, got {degrees}")
        angle = max(self.tilt_range_deg[0], min(self.tilt_range_deg[1], float(degrees)))
        self._command(f"tilt {angle}")
        self.tilt_motor_deg = angle
        return angle

    def tilt_state(self) -> dict:
        """The tilt motor's reported angle (degrees) and the accelerometer (m/s², x y z)."""
        self._request += 1
        self._command(f"state {self._request}")
        deadline = time.monotonic() + self.timeout_s
        while True:
            kind, payload = self._reply(deadline - time.monotonic(), "report its tilt")
            if kind == b"S":
                state = json.loads(payload)
                if state.get("id") == self._request:
                    return {"tilt_deg": state["tilt_deg"], "accel_m_s2": state["accel_m_s2"]}

    # ---------------------------------------------------------------- the worker
    def _environment(self) -> dict[str, str]:
        env = dict(os.environ)
        root = str(Path(__file__).resolve().parents[2])
        env["PYTHONPATH"] = os.pathsep.join(p for p in (root, env.get("PYTHONPATH", "")) if p)
        if self.fakenect is not None:
            library = next((d for d in FAKENECT_LIBRARY_DIRS if os.path.isdir(d)), None)
            if library is None:
                raise KinectNotFoundError("fakenect is not installed (Debian: apt-get install libfreenect-bin)")
            if not (self.fakenect / "INDEX.txt").is_file():
                raise KinectNotFoundError(f"{self.fakenect} is not a fakenect recording (no INDEX.txt)")
            env["LD_LIBRARY_PATH"] = os.pathsep.join(p for p in (library, env.get("LD_LIBRARY_PATH", "")) if p)
            env["FAKENECT_PATH"] = str(self.fakenect)  # fakenect loops it unless FAKENECT_LOOP=0
        return env

    def _command(self, line: str) -> None:
        if self._process is None:
            raise DeviceNotConnectedError(self.name, line.split()[0] if line else "talk to the camera")
        try:
            self._process.stdin.write(line.encode() + b"\n")
            self._process.stdin.flush()
        except OSError:
            raise self._gone() from None

    def _reply(self, timeout_s: float, doing: str) -> tuple[bytes, bytes]:
        """The next whole reply from the worker, waiting at most ``timeout_s``."""
        deadline = time.monotonic() + max(0.0, timeout_s)
        while True:
            if len(self._buffer) >= HEADER.size:
                magic, kind, length = HEADER.unpack_from(self._buffer)
                if magic != MAGIC:
                    raise self._gone("garbled data from the camera worker")
                if len(self._buffer) >= HEADER.size + length:
                    payload = self._buffer[HEADER.size:HEADER.size + length]
                    self._buffer = self._buffer[HEADER.size + length:]
                    if kind == b"E":
                        error = json.loads(payload)
                        raise self._gone(error["message"], not_found=error["kind"] == "not_found")
                    return kind, payload
            left = deadline - time.monotonic()
            if left <= 0:
                raise KinectTimeoutError(f"{self.name} did not {doing} within {self.timeout_s:g} s; check its USB "
                                         "cable and power adapter (the camera stays open: try again)")
            stdout = self._process.stdout
            readable, _, _ = select.select([stdout], [], [], left)
            if readable:
                chunk = os.read(stdout.fileno(), 1 << 20)
                if not chunk:
                    raise self._gone()
                self._buffer += chunk

    def _gone(self, reason: str | None = None, not_found: bool = False) -> KinectError:
        """Close after the worker reported an error or died; the error to raise."""
        process = self._process
        code = None if process is None else process.poll()
        self.close()
        if not_found:
            return KinectNotFoundError(reason)
        detail = reason or (f"its worker ended (exit status {code})" if code is not None else "its worker vanished")
        return KinectDisconnectedError(f"{self.name} was lost: {detail}; check the USB cable and power, then "
                                       "connect again")

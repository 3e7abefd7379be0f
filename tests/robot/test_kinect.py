"""The Kinect adapter, through libfreenect's recorded-stream player (fakenect) where it is installed.

What needs a real Kinect and is not tested here: registered and unregistered millimetre depth
(fakenect plays raw 11-bit disparity only), the tilt motor moving and its accelerometer (fakenect
answers every tilt command and reports 0°), and a camera unplugged from USB (here: a recording
that ends, and a worker killed). See docs/robot.md, section "Kinect".
"""

from __future__ import annotations

import math
import os
import time

import numpy as np
import pytest

from assistant.robot.frames import CameraIntrinsics
from assistant.robot.kinect import (
    FAKENECT_LIBRARY_DIRS, Kinect, KinectDisconnectedError, KinectNotFoundError, KinectTimeoutError,
    raw_disparity_to_mm,
)


def _binding_installed() -> bool:
    import importlib.util

    return importlib.util.find_spec("freenect") is not None


needs_fakenect = pytest.mark.skipif(
    not _binding_installed() or not any(os.path.isdir(d) for d in FAKENECT_LIBRARY_DIRS),
    reason="needs the freenect binding and fakenect (make setup: libfreenect-dev, libfreenect-bin, freenect)")


def mm_to_raw_disparity(depth_mm: np.ndarray) -> np.ndarray:
    """The inverse of the adapter's disparity fit, to make raw frames of known depth."""
    raw = (np.arctan(np.asarray(depth_mm, float) / 1000.0 / 0.1236) - 1.1863) * 2842.5
    return np.where(np.asarray(depth_mm) > 0, np.round(raw), 2047).astype(np.uint16)


def write_fakenect_recording(folder, frames: list[np.ndarray], times_s: list[float]) -> None:
    """A fakenect recording: ``INDEX.txt`` naming one dump per line, each dump named
    ``d-TIME-TIMESTAMP.pgm`` and holding a one-line PGM header, then the raw 11-bit depth as
    little-endian 16-bit words (fakenect copies the bytes after the header as they are)."""
    folder.mkdir(parents=True, exist_ok=True)
    names = []
    for i, (raw, t) in enumerate(zip(frames, times_s)):
        name = f"d-{t:f}-{i * 1000}.pgm"
        height, width = raw.shape
        (folder / name).write_bytes(f"P5 {width} {height} 65535\n".encode() + raw.astype("<u2").tobytes())
        names.append(name)
    (folder / "INDEX.txt").write_text("\n".join(names) + "\n")


def _wall(depth_m: float) -> np.ndarray:
    depth = np.full((480, 640), depth_m * 1000.0)
    depth[:20] = 0  # no reading at the top
    return mm_to_raw_disparity(depth)


def test_raw_disparity_conversion_agrees_with_an_independent_fit():
    raw = np.arange(450, 1000)
    ours = raw_disparity_to_mm(raw) / 1000.0
    other = 1.0 / (raw * -0.0030711016 + 3.3309495161)  # N. Burrus's fit, from another Kinect
    assert np.max(np.abs(ours - other) / other) < 0.07  # the two devices' fits differ by up to 6 %
    assert raw_disparity_to_mm(np.array([2047, 0, 1100])).tolist() == [0, 0, 0]


def test_no_kinect_is_a_typed_error_not_a_hang():
    start = time.monotonic()
    with pytest.raises(KinectNotFoundError, match="Kinect|libfreenect|freenect"):
        Kinect(timeout_s=1.0).connect()
    assert time.monotonic() - start < 15.0


def test_a_missing_binding_says_how_to_install_it(tmp_path, monkeypatch):
    (tmp_path / "freenect.py").write_text("raise ImportError('no libfreenect here')\n")
    monkeypatch.setenv("PYTHONPATH", str(tmp_path))
    with pytest.raises(KinectNotFoundError, match="pip install freenect"):
        Kinect().connect()


@needs_fakenect
def test_depth_frames_through_fakenect(tmp_path):
    # one frame a second (fakenect keeps the recorded pace), long enough for the whole test; the
    # wall at 2 m is shown for 3 s, so a worker that starts late on a busy machine (the tests
    # run on every core) still sees it first
    write_fakenect_recording(tmp_path / "rec", [_wall(2.0)] * 3 + [_wall(2.5)] * 6,
                             [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
    with Kinect(fakenect=tmp_path / "rec", depth_format="raw", timeout_s=2.0) as kinect:
        frame = kinect.depth_frame()
        assert frame.depth_m.shape == (480, 640) and frame.depth_m.dtype == np.float32
        assert frame.intrinsics == CameraIntrinsics.kinect_v1()
        assert np.all(frame.depth_m[:20] == 0)
        assert np.allclose(frame.depth_m[20:], 2.0, atol=0.01)
        later = [kinect.depth_frame().depth_m[20:] for _ in range(5)]  # the wall moves back to 2.5 m
        assert any(np.allclose(d, 2.5, atol=0.01) for d in later)
        before = frame.mount.tilt_rad
        assert kinect.set_tilt(40.0) == 27.0  # clamped to the motor's range
        assert kinect.mount.tilt_rad == pytest.approx(before - math.radians(27.0))
        assert set(kinect.tilt_state()) == {"tilt_deg", "accel_m_s2"}
    assert not kinect.is_connected


@needs_fakenect
def test_a_silent_camera_times_out_and_can_be_read_again(tmp_path):
    # Frames at 1, 5 and 9 s, then every half second. fakenect sleeps through a recorded gap inside
    # the worker's event loop, so a first request that reaches a busy worker a moment late waits
    # for the frame at 5 s instead of the one at 1 s: either way, 4 s of silence follow the first
    # frame read, and dense frames come after the second gap.
    write_fakenect_recording(tmp_path / "rec", [_wall(2.0)] + [_wall(3.0)] * 5, [1.0, 5.0, 9.0, 9.5, 10.0, 10.5])
    with Kinect(fakenect=tmp_path / "rec", depth_format="raw", timeout_s=15.0) as kinect:
        kinect.depth_frame()  # (a generous timeout for the first: the machine may be busy)
        kinect.timeout_s = 1.0
        start = time.monotonic()
        with pytest.raises(KinectTimeoutError, match="within 1 s"):
            kinect.depth_frame()
        assert time.monotonic() - start < 2.5  # gave up after its timeout, not at the next frame 4 s on
        kinect.timeout_s = 15.0
        frame = kinect.depth_frame()  # the camera is still open; a later frame arrives
        assert np.allclose(frame.depth_m[20:], 3.0, atol=0.02)


@needs_fakenect
def test_a_camera_that_goes_away_is_a_typed_error(tmp_path, monkeypatch):
    write_fakenect_recording(tmp_path / "rec", [_wall(2.0)] * 3, [1.0, 1.1, 1.2])
    monkeypatch.setenv("FAKENECT_LOOP", "0")  # at its end the recording reports the device gone
    # (Debian's fakenect 0.5 does so anyway; newer ones loop unless told not to)
    kinect = Kinect(fakenect=tmp_path / "rec", depth_format="raw", timeout_s=2.0).connect()
    with pytest.raises(KinectDisconnectedError, match="stopped answering"):
        for _ in range(5):
            kinect.depth_frame()
    assert not kinect.is_connected
    monkeypatch.delenv("FAKENECT_LOOP")
    write_fakenect_recording(tmp_path / "long", [_wall(2.0)] * 5, [1.0, 2.0, 3.0, 4.0, 5.0])
    kinect = Kinect(fakenect=tmp_path / "long", depth_format="raw", timeout_s=2.0).connect()
    kinect._process.kill()  # the worker dies (as when libusb crashes on an unplug)
    with pytest.raises(KinectDisconnectedError):
        kinect.depth_frame()
    kinect.close()

"""A depth PNG read without --intrinsics or --depth-scale: a Kinect's values stand in, said as
notes; a scale that makes no room is refused with the one that would."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from assistant.errors import AssistantError
from assistant.perception.depthfile import guess_depth_scale, load_depth_png, nominal_intrinsics


def write(tmp_path, units: np.ndarray):
    path = tmp_path / "depth.png"
    Image.fromarray(units.astype(np.uint16)).save(path)
    return path


def test_nominal_intrinsics_by_frame_size():
    assert nominal_intrinsics(640, 480) == (525.0, 525.0, 319.5, 239.5)
    assert nominal_intrinsics(512, 424) == (365.0, 365.0, 255.5, 211.5)
    fx, fy, cx, cy = nominal_intrinsics(320, 240)
    assert fx == fy == pytest.approx(262.5) and (cx, cy) == (159.5, 119.5)


@pytest.mark.parametrize("median, size, scale", [
    (2500, (640, 480), 1e-3),        # millimetres
    (25000, (512, 424), 1e-4),       # a Kinect v2's 0.1 mm
    (12500, (640, 480), 2e-4),       # TUM's 1/5000 m
])
def test_the_scale_is_guessed_from_the_readings(median, size, scale):
    assert guess_depth_scale(median, *size)[0] == scale


def test_defaults_stand_in_and_are_said(tmp_path):
    notes = []
    frame, mount = load_depth_png(write(tmp_path, np.full((480, 640), 2500)), None, None, notes=notes)
    assert frame.intrinsics.fx == 525.0 and float(np.median(frame.depth_m)) == pytest.approx(2.5)
    assert not mount and len(notes) == 2 and "--depth-scale 0.001" in notes[0] and "--intrinsics 525" in notes[1]


def test_a_scale_that_makes_no_room_is_refused_with_the_one_that_fits(tmp_path):
    path = write(tmp_path, np.full((480, 640), 2500))
    with pytest.raises(AssistantError, match=r"2,500.00 m, not a room.*try --depth-scale 0.001"):
        load_depth_png(path, (525, 525, 319.5, 239.5), 1.0)
    with pytest.raises(AssistantError, match=r"0.25 m, not a room"):
        load_depth_png(path, (525, 525, 319.5, 239.5), 1e-4)


def _room(shape=(480, 640)) -> np.ndarray:
    """Millimetre readings of a room: 1.2–4.8 m, every value (not all multiples of 8)."""
    return np.random.default_rng(0).integers(1200, 4800, size=shape)


@pytest.mark.parametrize("suffix", [".tif", ".npy"])
def test_float_depth_in_metres_from_a_tiff_or_npy(tmp_path, suffix):
    """A 32-bit float image in metres (the usual research format) is read with a scale of 1;
    one in millimetres as millimetres; NaN and inf are no reading."""
    metres = (_room() / 1000.0).astype(np.float32)
    metres[0, :10] = np.nan
    metres[1, :10] = np.inf
    path = tmp_path / f"depth{suffix}"
    np.save(path, metres) if suffix == ".npy" else Image.fromarray(metres).save(path)
    notes = []
    frame, _ = load_depth_png(path, None, None, notes=notes)
    assert "metres (a floating-point image)" in notes[0]
    assert float(np.median(frame.depth_m[frame.depth_m > 0])) == pytest.approx(np.median(_room()) / 1000, rel=1e-3)
    assert frame.depth_m[0, 0] == 0 and frame.depth_m[1, 0] == 0
    millimetres = tmp_path / f"mm{suffix}"
    data = _room().astype(np.float32)
    np.save(millimetres, data) if suffix == ".npy" else Image.fromarray(data).save(millimetres)
    frame, _ = load_depth_png(millimetres, None, None, notes=[])
    assert float(np.median(frame.depth_m)) == pytest.approx(np.median(_room()) / 1000, rel=1e-3)


def test_sun_rgbd_bit_rotated_millimetres_are_decoded(tmp_path):
    """SUN RGB-D's raw depth (millimetres rotated left by 3 bits) was read as TUM's 1/5000 m:
    it is recognised (nine in ten readings multiples of 8) and decoded; given millimetres,
    the refusal says to leave the scale out."""
    mm = _room()
    mm[:5] = 9000  # beyond 8.19 m: wraps round, not a multiple of 8
    rotated = ((mm << 3) | (mm >> 13)) & 0xFFFF
    path = write(tmp_path, rotated)
    notes = []
    frame, _ = load_depth_png(path, None, None, notes=notes)
    assert "SUN RGB-D" in notes[0]
    assert np.allclose(frame.depth_m, mm / 1000.0, atol=1e-6)
    with pytest.raises(AssistantError, match="bit-rotated millimetres: leave out --depth-scale"):
        load_depth_png(path, None, 1e-3)
    # a camera's own millimetres past 6 m median are not taken for it
    far, notes = write(tmp_path, _room() * 2 + 2001), []  # an 8 m median, odd readings
    load_depth_png(far, None, None, notes=notes)
    assert "SUN" not in notes[0] and "TUM" in notes[0]


def test_units_that_no_encoding_fits_say_so_and_do_not_repeat_the_scale(tmp_path):
    """Depth saved in whole decimetres: no common scale makes a room of it; the message says to
    check how the file was saved instead of offering the scale just refused."""
    with pytest.raises(AssistantError, match="no common depth encoding") as error:
        load_depth_png(write(tmp_path, _room() // 100), None, 1e-3)
    assert "try --depth-scale 0.001" not in str(error.value)


def test_a_height_without_a_tilt_and_intrinsics_no_camera_has_are_refused(tmp_path):
    path = write(tmp_path, _room())
    with pytest.raises(AssistantError, match="go together"):
        load_depth_png(path, None, 1e-3, camera_height_m=1.0)
    with pytest.raises(AssistantError, match="principal point"):
        load_depth_png(path, (518, 519, 3250, 2530), 1e-3)
    with pytest.raises(AssistantError, match="field of view"):
        load_depth_png(path, (5.18, 5.19, 325, 253), 1e-3)

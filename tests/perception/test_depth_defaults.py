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

"""The scans a person explores: listed, opened by path, read, and analysed the right way."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from assistant.app import analyse_scan, open_scan, scan_source, scan_sources
from assistant.errors import AssistantError

ROOT = Path(__file__).resolve().parents[2]
SCANS = ROOT / "sample_scans"


def test_recordings_are_listed_first_and_real_frames_after(shared_dir):
    sources = scan_sources(SCANS, shared_dir / "realdata")
    kinds = [s.kind for s in sources]
    assert kinds == sorted(kinds, key=lambda k: k != "recording")
    assert {s.path.name for s in sources if s.kind == "recording"} == {p.name for p in SCANS.glob("*.mcap")}
    real = {s.label: s for s in sources if s.kind == "depth"}
    sun = real["real sunrgbd_kv2_mmdet3d/000001_depth.png"]
    assert sun.intrinsics == (529.5, 529.5, 364.0, 264.0) and sun.depth_scale_m == 1e-3
    assert real["real kinect2_livingroom_esanet/sample_depth.png"].min_depth_m == 0.5
    assert all(s.path.exists() for s in sources)


def test_no_realdata_folder_lists_the_recordings_only(tmp_path):
    assert all(s.kind == "recording" for s in scan_sources(SCANS, tmp_path / "absent"))
    assert all(s.kind == "recording" for s in scan_sources(SCANS, None))


def test_a_named_png_is_read_as_its_folder_says_or_as_a_kinect_frame(shared_dir, tmp_path):
    from PIL import Image

    known = scan_source(shared_dir / "realdata" / "tum_office_open3d" / "TUM_depth.png")
    assert known.intrinsics == (525.0, 525.0, 319.5, 239.5) and known.depth_scale_m == 2e-4
    own = tmp_path / "mine.png"
    Image.fromarray(np.full((48, 64), 1500, dtype=np.uint16)).save(own)
    source = scan_source(own)
    assert source.kind == "depth" and not source.use_mount and source.depth_scale_m == 1e-3
    assert len(source.intrinsics) == 4  # the Kinect's, from hardware/kinect.yaml
    frame, = open_scan(scan_source(own, (50.0, 50.0, 32.0, 24.0), 2e-3))
    assert frame.depth_m.shape == (48, 64) and float(frame.depth_m[0, 0]) == pytest.approx(3.0)
    assert frame.robot_pose is None


@pytest.mark.parametrize("name, words", [("missing.png", "no such file"), ("notes.txt", "not a recording")])
def test_bad_paths_get_one_line_errors(tmp_path, name, words):
    (tmp_path / "notes.txt").write_text("hello")
    with pytest.raises(AssistantError) as error:
        scan_source(tmp_path / name)
    assert words in str(error.value) and "\n" not in str(error.value)


def test_a_recording_gives_frames_with_the_robot_pose():
    source = scan_source(SCANS / "apartment_look_around.mcap")
    frames = open_scan(source, limit=3)
    assert len(frames) == 3 and all(f.robot_pose is not None for f in frames)
    assert source.use_mount


def test_the_near_readings_of_a_kinect2_frame_are_dropped(shared_dir):
    source = scan_source(shared_dir / "realdata" / "kinect2_livingroom_esanet" / "sample_depth.png")
    frame, = open_scan(source)
    valid = frame.depth_m[frame.depth_m > 0]
    assert valid.min() >= 0.5


def test_analyse_searches_the_floor_of_an_image_and_predicts_a_recordings():
    calls = []

    class Spy:
        def analyse(self, frame, use_mount=True):
            calls.append(use_mount)
            return "result"

    recording = scan_source(SCANS / "apartment_look_around.mcap")
    image = recording.__class__("x", Path("x.png"), "depth", (1.0, 1.0, 0.0, 0.0))
    assert analyse_scan(Spy(), recording, None) == "result"
    analyse_scan(Spy(), image, None)
    assert calls == [True, False]

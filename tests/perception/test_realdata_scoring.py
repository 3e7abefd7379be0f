"""The real-frame scoring: which share of a labelled box the detector's range holds, the
summary of the issue's checks, and the range knob of ``assistant eval perception``."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from assistant.perception.realdata import _in_range_shares, summarise
from assistant.robot.frames import CameraIntrinsics, DepthFrame


class _Floor:
    """A floor frame that is the camera frame turned so that camera z (depth) is floor x."""

    camera_to_floor = np.array([[0.0, 0.0, 1.0, 0.0],
                                [-1.0, 0.0, 0.0, 0.0],
                                [0.0, -1.0, 0.0, 1.2],
                                [0.0, 0.0, 0.0, 1.0]])


def test_in_range_share_counts_the_mask_pixels_nearer_than_the_range(tmp_path):
    k = CameraIntrinsics(width=8, height=4, fx=4.0, fy=4.0, cx=4.0, cy=2.0)
    depth = np.full((4, 8), 3.0)
    depth[:, 4:] = 5.0  # the right half of box 1 lies beyond 4 m
    depth[0, 0] = 0.0   # an invalid pixel is not counted
    mask = np.zeros((4, 8), np.uint8)
    mask[:, :] = 1
    mask[3, :2] = 2     # box 2: near pixels only
    Image.fromarray(mask).save(tmp_path / "m.png")
    shares = _in_range_shares(tmp_path / "m.png", DepthFrame(depth_m=depth, intrinsics=k), _Floor(), 4.0)
    # box 1: 32 pixels, minus box 2's two, minus the invalid one = 29; 16 of them are at 5 m
    assert shares == {1: round(13 / 29, 3), 2: 1.0}
    assert _in_range_shares(tmp_path / "none.png", DepthFrame(depth_m=depth, intrinsics=k),
                            _Floor(), 4.0) == {}


def test_summary_counts_each_check_and_beds_or_couches_nobody_labelled():
    report = {"folders": {
        "sun": [{"floor": {"height": 1.2}, "detections": [{"category": "couch"}, {"category": "large table"}],
                 "matches": [{"object": "bed", "correct": False, "detection": 1, "in_range_share": 0.07},
                             {"object": "night_stand", "correct": False, "in_range_share": 1.0}]},
                {"floor": {"height": 1.2}, "detections": [{"category": "bed"}],
                 "matches": [{"object": "bed", "correct": True, "detection": 0, "in_range_share": 0.9}]}],
        "boxes": [{"floor": None, "detections": [{"category": "couch"}, {"category": "bed"}],
                   "boxes": [{"object": "couch", "detected": ["couch"], "detection_indices": [0],
                              "correct": True},
                             {"object": "large_table", "detected": ["bed"], "detection_indices": [1],
                              "correct": False}]}],
        "negative": [{"floor": {"height": 1.4}, "detections": [{"category": "bed"}],
                      "false_beds_or_couches": 1}]}}
    s = summarise(report)
    assert (s["frames"], s["floor_found"]) == (4, 3)
    assert s["labelled"]["bed"] == {"correct": 1, "labelled": 2, "in_range": 1, "in_range_correct": 1,
                                    "out_of_range_partial": 0}
    assert s["labelled"]["couch"]["correct"] == 1 and s["labelled"]["large_table"]["correct"] == 0
    # the SUN frame's couch and the desk read as a bed; the negatives are counted apart
    assert s["false_beds_or_couches_elsewhere"] == 2
    assert s["false_beds_or_couches_in_negatives"] == 1


def test_eval_perception_rejects_a_range_it_cannot_use(capsys):
    from assistant.cli import main

    assert main(["eval", "perception", "--skip", "classify,orientation,scenes,real", "--range-m", "0.5"]) == 2
    assert "--range-m must be 1 to 8 metres" in capsys.readouterr().err


def test_the_range_knob_sets_the_points_kept_and_the_grid():
    from assistant.eval.perception import frame_params
    from assistant.perception.samples import grid_size

    p = frame_params(5.5).samples
    assert (p.max_forward_m, p.x_range_m[1]) == (5.5, 5.5)
    assert grid_size(p)[0] == 110
    assert frame_params(None).samples.max_forward_m == 4.0
    with pytest.raises(Exception, match="1 to 8"):
        frame_params(9.0)


def test_most_of_sun_000001s_bed_lies_beyond_the_four_metres_the_detector_keeps(shared_dir):
    """The one real bed not read as a bed: its headboard stands 5.0–5.4 m away and its mattress
    is hidden behind its footboard, so under 10 % of its pixels are within range (the other
    three beds: over 80 %)."""
    from assistant.perception.frame import FrameParams, analyse_frame
    from assistant.perception.realdata import load_frames

    folder = shared_dir / "realdata" / "sunrgbd_kv2_mmdet3d"
    if not folder.is_dir():
        pytest.skip(f"{folder} not present")
    shares = {}
    for _, name, frame in load_frames(shared_dir / "realdata"):
        if name.endswith("_depth.png") and name[:6].isdigit():
            floor = analyse_frame(frame, FrameParams(), use_mount=False).floor
            shares[name[:6]] = _in_range_shares(folder / f"{name[:6]}_boxmask.png", frame, floor, 4.0)[1]
    assert shares["000001"] < 0.1
    assert min(shares[f] for f in ("000002", "000003", "000004")) > 0.8


def test_any_folder_with_a_frames_json_is_read_and_a_bad_one_says_what_is_missing(tmp_path):
    import json

    from assistant.errors import DataFileError
    from assistant.perception.realdata import load_frames, real_folders

    folder = tmp_path / "my_frames"
    folder.mkdir()
    depth = np.full((24, 32), 2000, np.uint16)
    depth[0, 0] = 100  # nearer than min_depth_m: dropped
    Image.fromarray(depth).save(folder / "a.png")
    (folder / "frames.json").write_text(json.dumps({
        "frames": ["a.png", "missing.png"], "intrinsics": [30.0, 30.0, 16.0, 12.0],
        "depth_scale_m": 0.001, "labels": "negative", "min_depth_m": 0.5}))
    (tmp_path / "not_frames").mkdir()  # neither known nor described: skipped
    assert list(real_folders(tmp_path)) == ["my_frames"]
    assert list(real_folders(folder)) == ["my_frames"]  # the folder itself
    frames = list(load_frames(tmp_path))
    assert [(f, n) for f, n, _ in frames] == [("my_frames", "a.png")]
    d = frames[0][2].depth_m
    assert d.shape == (24, 32) and d[0, 0] == 0.0 and d[5, 5] == 2.0
    (folder / "frames.json").write_text(json.dumps({"frames": ["a.png"], "labels": "negative"}))
    with pytest.raises(DataFileError, match="intrinsics"):
        real_folders(tmp_path)


def test_a_partial_bed_beyond_the_range_is_counted_apart_from_beds_seen_whole():
    """Issue 20: SUN 000001's bed, mostly beyond the range, reported as a partial bed: the
    summary says 3 of the 3 in range and the fourth as partial, not 4 of 4."""
    matches = [{"object": "bed", "correct": True, "in_range_share": 0.9, "partial": False, "detection": 0}] * 3
    matches = matches + [{"object": "bed", "correct": True, "in_range_share": 0.07, "partial": True, "detection": 1}]
    report = {"folders": {"sun": [{"floor": {"height": 1.2}, "detections": [{"category": "bed"}, {"category": "bed"}],
                                   "matches": matches}]}}
    s = summarise(report)
    assert s["labelled"]["bed"] == {"correct": 3, "labelled": 4, "in_range": 3, "in_range_correct": 3,
                                    "out_of_range_partial": 1}
    assert s["false_beds_or_couches_elsewhere"] == 0
    from assistant.cli.eval_perception import realdata_summary_line

    line = realdata_summary_line(s)
    assert "bed 3/4 (3/3 of those mostly within range; 1/1 mostly beyond it reported as a partial bed)" in line


def test_a_partial_view_matches_the_box_its_cells_lie_on_though_its_centre_is_far_from_the_boxs():
    from assistant.perception.realdata import _seen_part_on

    class _Det:
        def __init__(self, cells, partial):
            self.cells_xy, self.partial, self.beyond_range, self.frame = np.asarray(cells), False, partial, "camera-floor"

    box = {"corners_upright_m": [[0, 3, 0], [2, 3, 0], [2, 5.4, 0], [0, 5.4, 0]]}
    identity = lambda p: np.asarray(p)  # noqa: E731 - the floor frame is the upright frame here

    class _Same:
        camera_to_floor = np.eye(4)

    near_end = _Det([[1.0, 3.1], [1.2, 3.3], [0.8, 3.4]], True)
    outside = _Det([[3.0, 3.1], [3.2, 3.3]], True)
    whole = _Det([[1.0, 3.1], [1.2, 3.3]], False)  # not cut: matched by its centre only
    dets = [(outside, None, None, 0), (whole, None, None, 1), (near_end, None, None, 2)]
    assert _seen_part_on(box, dets, _Same(), identity)[3] == 2
    assert _seen_part_on(box, dets[:2], _Same(), identity) is None


@pytest.mark.timeout(900)  # trains the detector in the tests' private cache on first use
def test_the_real_frames_meet_issue_20s_bed_checks_with_the_trained_detector(shared_dir):
    """Issue 20 on the real frames (trained models, cached after the first run): no false bed or
    couch, the three beds in range found, SUN 000001's bed — mostly beyond the range — reported
    as a partial bed and counted apart from those seen whole."""
    from assistant.perception import FurnitureDetector
    from assistant.perception.realdata import evaluate_realdata

    root = shared_dir / "realdata"
    if not (root / "sunrgbd_kv2_mmdet3d").is_dir():
        pytest.skip(f"{root} not present")
    summary = evaluate_realdata(root, FurnitureDetector())["summary"]
    beds = summary["labelled"]["bed"]
    assert (beds["in_range_correct"], beds["in_range"], beds["out_of_range_partial"], beds["correct"]) == (3, 3, 1, 3)
    assert summary["false_beds_or_couches_in_negatives"] == summary["false_beds_or_couches_elsewhere"] == 0
    assert summary["labelled"]["couch"]["correct"] == 2 and summary["floor_found"] == 10

"""Simulated Kinect depth: geometry, noise model, hit ids, determinism and the adaptive caster."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.errors import AssistantError
from assistant.geometry import Pose2D
from assistant.robot import CameraMount, pixel_rays
from assistant.sim import DepthRenderer, KinectNoise, PoseOutsideMapError

LEVEL = CameraMount(height_m=1.05, tilt_rad=0.0)


def _points_world(frame, depth):
    """World points (H, W, 3) of a depth image taken with ``frame``'s camera."""
    pts_cam = pixel_rays(frame.intrinsics) * depth[..., None]
    t = frame.camera_to_world()
    return pts_cam @ t[:3, :3].T + t[:3, 3]


@pytest.mark.parametrize("distance", [0.8, 2.0, 3.5])
def test_wall_straight_ahead_reads_its_distance_within_the_noise(empty_room, distance):
    # the room's east wall has its inner face at x = 6
    renderer = DepthRenderer(empty_room, mount=LEVEL, seed=1)
    frame = renderer.render(Pose2D(6.0 - distance, 2.0, 0.0))
    centre = frame.depth_m[220:260, 300:340]
    assert np.all(centre > 0)
    noise = renderer.noise
    tolerance = 5 * noise.sigma_m(distance) + noise.step_m(distance) + 0.001
    assert np.all(np.abs(centre - distance) < tolerance)
    assert abs(float(centre.mean()) - distance) < noise.step_m(distance) / 2 + 0.003
    assert frame.hit_names[int(frame.hit_ids[240, 320])] == "wall_3"


def test_exact_depth_is_the_z_of_the_hit(empty_room):
    renderer = DepthRenderer(empty_room, mount=LEVEL, noise=KinectNoise.none())
    depth, _ = renderer.cast(Pose2D(3.5, 2.0, 0.0))
    # every pixel on the facing wall (x = 6) is 2.5 m deep along the optical axis
    wall_rows = depth[150:330]  # between floor and top of the wall
    on_wall = np.abs(wall_rows - 2.5) < 1e-4
    assert on_wall[:, 100:540].all()


def test_tilted_camera_sees_the_floor_where_the_tilt_says(empty_room):
    tilt = math.radians(15.0)
    renderer = DepthRenderer(empty_room, mount=CameraMount(1.05, tilt), noise=KinectNoise.none())
    depth, ids = renderer.cast(Pose2D(1.0, 2.0, 0.0))
    centre = float(depth[239:241, 319:321].mean())  # the optical axis is between these pixels
    assert centre == pytest.approx(1.05 / math.sin(tilt), abs=0.01)
    assert renderer.hit_names[ids[240, 320]] == "floor"
    assert renderer.hit_names[ids[100, 320]] == "wall_3"  # higher up: the far wall


def test_range_limits_give_zero(empty_room):
    renderer = DepthRenderer(empty_room, mount=LEVEL)
    far = renderer.render(Pose2D(1.0, 2.0, 0.0))  # far wall 5 m away
    assert np.all(far.depth_m[230:250, 310:330] == 0)
    assert far.hit_names[far.hit_ids[240, 320]] == "wall_3"  # the ray hit it; the sensor has no reading
    near = renderer.render(Pose2D(5.6, 2.0, 0.0))  # 0.4 m from the wall
    assert np.all(near.depth_m[230:250, 310:330] == 0)
    assert near.depth_m.min() == 0.0 and near.depth_m.dtype == np.float32


def test_table_from_two_metres_shows_top_and_legs(room_with_table):
    renderer = DepthRenderer(room_with_table, noise=KinectNoise.none())  # default 15° tilt
    frame = renderer.render(Pose2D(1.0, 2.0, 0.0))  # table centre 2 m ahead
    table = frame.hit_ids == frame.hit_names.index("table_1")
    pts = _points_world(frame, frame.depth_m)[table]
    assert len(pts) > 2000
    z = pts[:, 2]
    top = z > 0.47
    legs = z < 0.3
    assert top.sum() > 500 and legs.sum() > 100
    assert not np.any((z > 0.3) & (z < 0.45) & (np.abs(pts[:, 1] - 2.0) < 0.25)), \
        "nothing of the table between the legs' tops and the top near its middle"
    # the legs: two separate groups of image columns with floor between them
    rows, cols = np.nonzero(table & (_points_world(frame, frame.depth_m)[..., 2] < 0.3))
    columns = np.unique(cols)
    gaps = np.diff(columns)
    assert gaps.max() > 20, "the near legs should show as separate columns"
    between = slice(columns[np.argmax(gaps)] + 3, columns[np.argmax(gaps) + 1] - 3)
    low_row = int(np.median(rows))
    assert frame.hit_names[frame.hit_ids[low_row, between].min()] in ("floor", "wall_2")


def test_hit_ids_name_what_was_seen(apartment):
    renderer = DepthRenderer(apartment)
    frame = renderer.render(Pose2D(4.5, 5.5, -math.pi / 2))  # living room, looking at the couch
    seen = {frame.hit_names[i] for i in np.unique(frame.hit_ids[frame.valid])}
    assert {"couch_1", "coffeetable_1", "floor"} <= seen
    assert frame.hit_ids.dtype == np.int32 and frame.hit_ids.min() >= -1


def test_same_seed_same_frames_and_noise_changes_per_frame(apartment):
    pose = Pose2D(5.0, 0.0, math.pi)
    a = DepthRenderer(apartment, seed=7)
    b = DepthRenderer(apartment, seed=7)
    c = DepthRenderer(apartment, seed=8)
    fa, fb, fc = a.render(pose), b.render(pose), c.render(pose)
    assert np.array_equal(fa.depth_m, fb.depth_m)
    assert not np.array_equal(fa.depth_m, fc.depth_m)
    assert np.array_equal(a.render(pose).depth_m, b.render(pose).depth_m)
    assert not np.array_equal(a.render(pose).depth_m, fa.depth_m)


@pytest.mark.parametrize("pose", [(4.5, 5.5, -1.571), (3.0, 2.2, 0.3), (1.0, -4.0, 3.1), (5.0, 0.0, 3.14)])
def test_adaptive_casting_matches_casting_every_pixel(apartment, pose):
    p = Pose2D(*pose)
    full = DepthRenderer(apartment, noise=KinectNoise.none(), adaptive=False)
    d_full, id_full = full.cast(p)
    for step in (2, 3, 4):
        fast = DepthRenderer(apartment, noise=KinectNoise.none(), sample_step=step)
        d_fast, id_fast = fast.cast(p)
        assert fast.last_cast_fraction < 0.5
        assert _agreement(d_fast, id_fast, d_full, id_full) > 0.999, f"sample step {step}"


def _agreement(d_fast, id_fast, d_full, id_full) -> float:
    """Share of pixels where both casters hit the same thing at the same depth (±1 mm)."""
    same_hit = np.isfinite(d_fast) == np.isfinite(d_full)
    close = np.abs(np.nan_to_num(d_fast, posinf=0) - np.nan_to_num(d_full, posinf=0)) < 1e-3
    return float((same_hit & close & (id_fast == id_full)).mean())


def test_noise_grows_with_distance_and_is_quantised():
    noise = KinectNoise(edge_dropout=0.0)
    rng = np.random.default_rng(0)
    near = noise.apply(np.full((100, 100), 1.0, np.float32), rng)
    far = noise.apply(np.full((100, 100), 4.0, np.float32), rng)
    assert near.std() < far.std()
    assert far.std() == pytest.approx(math.hypot(noise.sigma_m(4.0), noise.step_m(4.0) / math.sqrt(12)), rel=0.3)
    assert len(np.unique(far)) < 15  # a handful of disparity steps, not a continuum
    assert np.allclose(far * 1000, np.round(far * 1000), atol=1e-3)  # whole millimetres


def test_edge_dropout_removes_pixels_only_at_depth_jumps():
    noise = KinectNoise(edge_dropout=1.0, sigma_base_m=0.0, sigma_quad_m=0.0, quantise=False)
    depth = np.full((50, 50), 2.0, np.float32)
    depth[:, 25:] = 3.0
    out = noise.apply(depth, np.random.default_rng(0))
    assert np.all(out[:, 24:26] == 0)
    assert np.all(out[:, :24] == 2.0) and np.all(out[:, 26:] == 3.0)


def test_pose_outside_the_map_is_refused(apartment):
    renderer = DepthRenderer(apartment)
    with pytest.raises(PoseOutsideMapError, match="outside the map of apartment"):
        renderer.render(Pose2D(50.0, 0.0, 0.0))
    assert issubclass(PoseOutsideMapError, AssistantError)


def test_unknown_scene_lists_the_known_ones(apartment):
    with pytest.raises(AssistantError, match="modified"):
        DepthRenderer(apartment, scene="modifed")


def test_parallel_bands_give_the_same_frame(apartment):
    pose = Pose2D(4.5, 5.5, -1.571)
    a = DepthRenderer(apartment, seed=2, parallel=True).render(pose)
    b = DepthRenderer(apartment, seed=2, parallel=False).render(pose)
    assert np.array_equal(a.depth_m, b.depth_m)


@pytest.mark.parametrize("size", [(100, 74), (101, 75), (33, 2), (3, 5)])
def test_adaptive_casting_handles_any_image_size(apartment, size):
    from assistant.robot import CameraIntrinsics

    width, height = size
    k = CameraIntrinsics(width, height, 60.0, 60.0, (width - 1) / 2, (height - 1) / 2)
    pose = Pose2D(4.5, 5.5, -1.571)
    fast = DepthRenderer(apartment, intrinsics=k, noise=KinectNoise.none())
    full = DepthRenderer(apartment, intrinsics=k, noise=KinectNoise.none(), adaptive=False)
    d_fast, id_fast = fast.cast(pose)
    d_full, id_full = full.cast(pose)
    assert d_fast.shape == (height, width)
    assert _agreement(d_fast, id_fast, d_full, id_full) > 0.99  # coarse pixels: thin parts may slip

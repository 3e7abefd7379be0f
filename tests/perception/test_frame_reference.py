"""The fast front half gives what the code before the speed work gave, and bad frames say why.

The old code is read from the git history by ``benchmarks/perception_reference.py`` (also timed
against the new one by ``benchmarks/bench_perception.py``); the comparisons skip, saying why, in
a checkout without that commit. Floors, samples and cells agree to float rounding.
Normals agree except at a handful of points: open3d picks the 12 nearest neighbours of a
voxel-grid point among neighbours at *exactly* equal distances, and a 1e-14 change of the
points (another summation order) can pick another one — the old code's BLAS calls had the same
sensitivity to the BLAS kernel and thread count.
"""

from __future__ import annotations

import sys
import types
from pathlib import Path

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.perception import cloud
from assistant.perception.features import shape_descriptor
from assistant.perception.frame import FrameParams, analyse_frame
from assistant.perception.samples import SampleParams, _is_wall_piece, extract_samples, sample_region
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
import perception_reference  # noqa: E402


@pytest.fixture(scope="module")
def ref():
    """The front half before the speed work (``cloud``, ``samples``, ``features``, ``frame``)."""
    try:
        return perception_reference.load()
    except perception_reference.ReferenceUnavailable as exc:
        pytest.skip(str(exc))


@pytest.fixture(scope="module")
def sim_frames():
    """Two simulated 640×480 views with furniture in view (scenes 1 and 3 of Table 3-9)."""
    from assistant.eval.perception_scenes import SCENES, viewpoints
    from assistant.sim.renderer import DepthRenderer
    from assistant.world import load_world

    world = load_world("apartment")
    renderer = DepthRenderer(world, "original", seed=0)
    frames = []
    for number in (1, 3):
        ids = SCENES[number - 1][1]
        items = [f for f in world.scene("original").furniture if f.id in ids]
        frames.append(renderer.render(viewpoints(world, "original", items)[0]))
    return frames


def assert_same_analysis(new, old, ref):
    assert new.reason == old.reason
    assert (new.floor is None) == (old.floor is None)
    if new.floor is not None:
        assert np.allclose(new.floor.camera_to_floor, old.floor.camera_to_floor, atol=1e-9)
        assert new.floor.inliers == old.floor.inliers
    assert new.stats == old.stats
    assert len(new.samples) == len(old.samples)
    normals_same = normals_all = 0
    for a, b in zip(new.samples, old.samples):
        assert a.points.shape == b.points.shape
        assert np.allclose(a.points, b.points, atol=1e-9)
        assert np.array_equal(a.cells_xy_m, b.cells_xy_m)
        assert a.height_m == pytest.approx(b.height_m, abs=1e-9)
        assert a.touches_border == b.touches_border and a.info == b.info
        err = np.minimum(np.abs(a.normals - b.normals).max(axis=1), np.abs(a.normals + b.normals).max(axis=1))
        normals_same += int((err < 1e-6).sum())
        normals_all += len(err)
        # the old code's 49 values (the side cues of issue 20 came later)
        assert np.allclose(shape_descriptor(a.points, a.normals)[:49],
                           ref.features.shape_descriptor(b.points, b.normals), atol=0.02)
    if normals_all:
        assert normals_same >= 0.98 * normals_all
        diff = np.abs(new.features - old.features)
        assert (diff < 1e-9).mean() >= 0.99 and diff.max() < 0.15


#: the old code had no clearing of a wall's remains beside its cleared columns, no wall trace
#: and no splitting of joined items (changes of what is computed, not of speed): compared
#: without them
AS_BEFORE = FrameParams(samples=SampleParams(wall_remains_top_m=None, wall_trace_band_m=None,
                                             split_min_area_m2=None))


def test_fast_front_half_matches_the_old_code_on_simulated_frames(sim_frames, ref):
    for frame in sim_frames:
        new, old = analyse_frame(frame, AS_BEFORE), ref.frame.analyse_frame(frame)
        assert len(new.samples) >= 2  # furniture in view: the comparison means something
        assert_same_analysis(new, old, ref)
        # without the mount the floor is searched for (the path of every real frame)
        assert_same_analysis(analyse_frame(frame, AS_BEFORE, use_mount=False),
                             ref.frame.analyse_frame(frame, use_mount=False), ref)


def test_fast_front_half_matches_the_old_code_on_a_real_frame(shared_dir, ref):
    from assistant.perception.depthfile import load_depth_png
    from assistant.perception.realdata import FOLDERS

    files, k, scale, invalid, _ = FOLDERS["sunrgbd_kv2_mmdet3d"]
    path = shared_dir / "realdata" / "sunrgbd_kv2_mmdet3d" / files[1]
    if not path.exists():
        pytest.skip(f"{path} not present")
    frame, _ = load_depth_png(path, k, scale, invalid_values=invalid)
    new = analyse_frame(frame, AS_BEFORE, use_mount=False)
    old = ref.frame.analyse_frame(frame, use_mount=False)
    assert new.floor is not None and new.samples
    assert_same_analysis(new, old, ref)


def test_plane_fit_transform_and_scores_match_the_straightforward_formulas():
    rng = np.random.default_rng(3)
    pts = np.column_stack([rng.uniform(-2, 2, 5000), 1.0 + rng.normal(0, 0.01, 5000), rng.uniform(1, 4, 5000)])
    plane = cloud._lsq_plane(pts, np.array([0.0, -1.0, 0.0]))
    centre = pts.mean(axis=0)
    _, _, vt = np.linalg.svd(pts - centre, full_matrices=False)
    normal = vt[2] if vt[2][1] < 0 else -vt[2]
    assert np.allclose(plane, np.append(normal, -normal @ centre), atol=1e-9)

    m = np.eye(4)
    m[:3, :3] = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    m[:3, 3] = [0.1, -0.2, 1.05]
    assert np.allclose(cloud.transform(pts, m), pts @ m[:3, :3].T + m[:3, 3], atol=1e-12)

    normals = rng.normal(size=(130, 3))
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    d = rng.uniform(0.5, 1.5, 130)
    h = pts @ normals.T + d
    expected = (np.abs(h) < 0.05).sum(axis=0) - 2 * (h < -0.12).sum(axis=0)
    assert np.array_equal(cloud._support_scores(pts, normals, d), expected)


def test_sample_region_is_the_old_keep_and_grid_test():
    rng = np.random.default_rng(5)
    pts = rng.uniform([-1, -4, -0.5], [5, 4, 1.5], size=(20000, 3))
    p = SampleParams()
    keep = (pts[:, 2] > p.min_z_m) & (pts[:, 2] < p.max_z_m) & (pts[:, 0] < p.max_forward_m)
    ix = np.floor((pts[:, 0] - p.x_range_m[0]) / p.grid_m).astype(int)
    iy = np.floor((pts[:, 1] - p.y_range_m[0]) / p.grid_m).astype(int)
    inside = keep & (ix >= 0) & (ix < 80) & (iy >= 0) & (iy < 120)
    assert np.array_equal(sample_region(pts[:, 0], pts[:, 1], pts[:, 2], p), inside)
    # extract_samples gives the same with or without the caller's pre-selection
    a, sa = extract_samples(pts, params=p)
    b, sb = extract_samples(pts[inside], params=p)
    assert len(a) >= 1
    sb["points"] = sa["points"]
    assert sa == sb and len(a) == len(b)
    assert all(np.array_equal(x.points, y.points) for x, y in zip(a, b))


@pytest.mark.parametrize("seed", range(4))
def test_wall_piece_test_matches_the_old_one(seed, ref):
    rng = np.random.default_rng(seed)
    p = SampleParams()
    sheet = np.column_stack([rng.uniform(0, rng.uniform(0.5, 2.0), 3000), rng.normal(0, rng.uniform(0.01, 0.2), 3000),
                             rng.uniform(0, rng.uniform(0.8, 1.8), 3000)])
    assert _is_wall_piece(sheet, p) == ref.samples._is_wall_piece(sheet, p)


K = CameraIntrinsics.kinect_v1()


def frame_of(depth) -> DepthFrame:
    return DepthFrame(np.asarray(depth, dtype=np.float32), K, CameraMount(), Pose2D(0, 0, 0))


def truncated(frame: DepthFrame, from_row: int) -> DepthFrame:
    depth = frame.depth_m.copy()
    depth[from_row:] = 0.0
    return frame_of(depth)


@pytest.mark.parametrize("what, make, says", [
    ("zeros", lambda f: frame_of(np.zeros((480, 640))), "empty frame"),
    ("NaN", lambda f: frame_of(np.full((480, 640), np.nan)), "all NaN"),
    ("inf and negative", lambda f: frame_of(np.where(np.eye(480, 640) > 0, -1.0, np.inf)), "empty frame"),
    ("a wall filling the view", lambda f: frame_of(np.full((480, 640), 0.9)), "no floor"),
    ("no floor: only the top rows", lambda f: truncated(f, 30), "truncated"),
    ("truncated: bottom half missing", lambda f: truncated(f, 240), "truncated"),
    ("every other row NaN (stride hits only NaN)",
     lambda f: frame_of(np.where(np.arange(480)[:, None] % 2 == 0, np.nan, f.depth_m)), "too few"),
    ("only the floor", lambda f: frame_of(np.where(np.arange(480)[:, None] > 400, f.depth_m, 0.0)),
     "nothing stands on the floor"),
])
def test_bad_frames_give_a_reason_and_no_samples(sim_frames, what, make, says):
    result = analyse_frame(make(sim_frames[0]))
    assert result.samples == [] and result.features.shape == (0, FrameParams().features.length)
    assert says in result.reason


def test_a_frame_whose_image_does_not_match_its_intrinsics_is_truncated():
    frame = types.SimpleNamespace(depth_m=np.ones((200, 640), dtype=np.float32), intrinsics=K,
                                  mount=CameraMount(), robot_pose=None)
    result = analyse_frame(frame)
    assert result.samples == [] and "truncated frame" in result.reason and "640×200" in result.reason


def test_the_real_frames_empty_border_rows_are_not_truncation(sim_frames):
    # NYU frames have 8 empty bottom rows (registration border): still read
    depth = sim_frames[0].depth_m.copy()
    depth[-8:] = 0.0
    result = analyse_frame(frame_of(depth))
    assert result.reason is None and len(result.samples) >= 2


def test_the_detector_reports_a_truncated_frame(tiny_models, sim_frames):
    from assistant.perception import FurnitureDetector

    result = FurnitureDetector(tiny_models).analyse(truncated(sim_frames[0], 200))
    assert result.detections == [] and "truncated frame" in result.reason
    assert result.to_dict()["reason"] == result.reason


def test_one_thread_while_a_frame_is_analysed_and_the_process_setting_back_after(sim_frames):
    from threadpoolctl import threadpool_info

    from assistant.perception import frame as frame_module

    seen = []
    inner = frame_module._analyse

    def spy(*args):
        seen.append({(i["internal_api"], i["filepath"]): i["num_threads"] for i in threadpool_info()})
        return inner(*args)

    before = {(i["internal_api"], i["filepath"]): i["num_threads"] for i in threadpool_info()}
    frame_module._analyse = spy
    try:
        analyse_frame(sim_frames[0])
        analyse_frame(sim_frames[0], FrameParams(threads=None))
    finally:
        frame_module._analyse = inner
    assert set(seen[0].values()) == {1}  # every OpenMP and BLAS pool
    assert seen[1] == before
    assert {(i["internal_api"], i["filepath"]): i["num_threads"] for i in threadpool_info()} == before


def test_the_thread_limit_sets_omp_num_threads_so_that_open3d_obeys_it(monkeypatch):
    """open3d 0.19 sizes its parallel loops by the OpenMP setting only when ``OMP_NUM_THREADS``
    is set (else by the core count), so a process without the variable (a notebook, the
    benchmark) had its limit ignored by open3d's normals: the limit sets the variable, to the
    OpenMP thread count the process has (nothing changes outside the limit), and leaves a set
    one alone."""
    import os

    from threadpoolctl import threadpool_info

    from assistant.perception import frame as frame_module

    openmp = max(i["num_threads"] for i in threadpool_info() if i["user_api"] == "openmp")
    monkeypatch.delenv("OMP_NUM_THREADS", raising=False)
    monkeypatch.setattr(frame_module, "_CONTROLLER", [])
    with frame_module.thread_limit(1):
        assert os.environ["OMP_NUM_THREADS"] == str(openmp)
    monkeypatch.setenv("OMP_NUM_THREADS", "3")
    monkeypatch.setattr(frame_module, "_CONTROLLER", [])
    with frame_module.thread_limit(1):
        assert os.environ["OMP_NUM_THREADS"] == "3"

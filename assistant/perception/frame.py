"""One depth frame → floor + furniture samples with features (3.6.1–3.6.2), never raising.

:func:`analyse_frame` is the front half of the detector, shared by the detector, the training
database and the evaluation. A bad frame (all zeros, all NaN, no floor in view, a wall filling
the view, a truncated frame) gives no samples and a ``reason`` instead of an exception.

Speed (the Kinect's 33 ms frame period is the budget): the floor-frame transform is three
matrix-vector products and only the points that can belong to a sample are gathered, rows are
selected with ``np.compress`` rather than boolean indexing, and no (N, 3) × (3, 3) BLAS product
is made (slow, and slower still with BLAS threads on a loaded machine). The results are those
of the straightforward code up to float rounding; ``tests/perception/test_frame_reference.py``
compares them with the code before these changes (``benchmarks/perception_reference.py``).
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass, field

import numpy as np

from assistant.perception.cloud import Floor, depth_to_points, find_floor
from assistant.perception.features import FeatureParams, normal_histogram, estimate_normals
from assistant.perception.samples import FurnitureSample, SampleParams, extract_samples, sample_region
from assistant.robot.frames import DepthFrame


@dataclass(frozen=True)
class FrameParams:
    """Front-half parameters: ``target_width`` sets the back-projection stride (a 640-pixel
    frame is read every second pixel), ``floor_band_m``/``floor_near_m`` the RANSAC subset;
    a frame whose bottom ``truncated_rows_share`` of rows (or more) holds no reading at all is
    a truncated frame (cut short in transfer: image rows arrive top first) and is not read —
    the real Kinect frames have at most 8 of 480 empty bottom rows (registration border).

    ``threads``: the OpenMP (open3d) and BLAS (numpy) threads while a frame is analysed (None:
    leave them as the process has them). The command line sets ``OMP_NUM_THREADS=1`` at start-up
    (:func:`assistant.runtime.limit_openmp_threads`), but when open3d is loaded first it used
    both cores: measured on the loaded 2-core machine, 56 ms of CPU per simulated frame instead
    of 18 ms; numpy's two BLAS threads doubled the real frames' CPU time (32 → 58 ms;
    ``bench_perception.py --threads``). Until 2 Dec evening the limit did not reach open3d at
    all in a process without the variable (a notebook, the benchmark): see :func:`thread_limit`."""

    target_width: int = 320
    max_range_m: float = 6.0
    floor_band_m: float = 0.1
    floor_near_m: float = 3.0
    truncated_rows_share: float = 0.2
    threads: int | None = 1
    samples: SampleParams = field(default_factory=SampleParams)
    features: FeatureParams = field(default_factory=FeatureParams)


@dataclass(eq=False)
class FrameAnalysis:
    """What the front half found: the floor (or None), the samples with their histograms
    (``features`` (S, L)), the camera's position in the floor frame, and why nothing was found.

    ``timings_ms`` holds the wall-clock milliseconds of each stage (cloud, floor, samples,
    features) and ``cpu_ms`` this process's CPU milliseconds (``time.process_time``) of the
    same stages: on a loaded machine the wall time includes waiting for a core."""

    floor: Floor | None
    samples: list[FurnitureSample]
    features: np.ndarray
    camera_xyz: np.ndarray
    reason: str | None = None
    stats: dict = field(default_factory=dict)
    timings_ms: dict = field(default_factory=dict)
    cpu_ms: dict = field(default_factory=dict)


def analyse_frame(frame: DepthFrame, params: FrameParams = FrameParams(), *,
                  use_mount: bool = True, previous_floor: Floor | None = None) -> FrameAnalysis:
    """Floor, samples and features of one frame.

    ``use_mount`` predicts the floor from the frame's mount (camera height and tilt); without
    it (a frame from disk with unknown height and tilt) the floor is searched for.
    ``previous_floor`` (the :class:`Floor` of an earlier frame from the same camera pose) is
    tried before either (``cloud.find_floor``). open3d and numpy run with ``params.threads``
    threads meanwhile (see :class:`FrameParams`).
    """
    if params.threads is None:
        return _analyse(frame, params, use_mount, previous_floor)
    with thread_limit(params.threads):
        return _analyse(frame, params, use_mount, previous_floor)


_CONTROLLER: list = []


def thread_limit(threads: int = 1):
    """Context limiting the process's OpenMP (open3d) and BLAS (numpy, scipy) thread pools to
    ``threads`` (threadpoolctl; about 20 µs to enter and leave). On the shared 2-core machine
    one thread is faster: a second one mostly waits for a core the other jobs hold.

    open3d (0.19) sizes each parallel loop with ``utility::EstimateMaxThreads()``, which reads
    the OpenMP setting (``omp_get_max_threads``, what threadpoolctl changes) only when the
    ``OMP_NUM_THREADS`` variable is set at the time of the call, and otherwise takes the
    machine's core count: without the variable the limit did not reach open3d's normal
    estimation (2 threads; measured 8 ms median CPU for a 1500-point sample instead of 2.7 ms
    on the loaded machine, ``docs/perception.md``). So when the variable is unset this sets it,
    to the OpenMP thread count the process has now: nothing changes outside the limit (open3d
    gets the OpenMP count instead of the core count, the same on this machine), and inside it
    open3d obeys. The first call also applies :func:`assistant.runtime.keep_freed_memory` (a
    frame's arrays then reuse freed memory instead of faulting fresh pages in)."""
    if not _CONTROLLER:
        import importlib

        from threadpoolctl import ThreadpoolController

        from assistant.runtime import keep_freed_memory

        keep_freed_memory()

        importlib.import_module("open3d")  # its OpenMP runtime must be loaded to be found

        controller = ThreadpoolController()
        if "OMP_NUM_THREADS" not in os.environ:
            counts = [info["num_threads"] for info in controller.info() if info["user_api"] == "openmp"]
            os.environ["OMP_NUM_THREADS"] = str(max(counts, default=os.cpu_count() or 1))
        _CONTROLLER.append(controller)
    return _CONTROLLER[0].limit(limits=threads)


def _analyse(frame: DepthFrame, params: FrameParams, use_mount: bool,
             previous_floor: Floor | None = None) -> FrameAnalysis:
    t0, c0 = time.perf_counter(), time.process_time()
    empty = np.zeros((0, params.features.length))
    nothing = np.zeros(3)
    depth = np.asarray(frame.depth_m)
    shape = (frame.intrinsics.height, frame.intrinsics.width)
    if depth.shape != shape:
        return FrameAnalysis(None, [], empty, nothing,
                             f"truncated frame (depth image {'×'.join(map(str, depth.shape[::-1]))}"
                             f" but the intrinsics say {shape[1]}×{shape[0]})")
    valid = np.isfinite(depth) & (depth > 0)
    if not valid.any():
        what = "all NaN" if np.isnan(depth).all() else "no valid depth"
        return FrameAnalysis(None, [], empty, nothing, f"empty frame ({what})")
    rows_with_depth = np.flatnonzero(valid.any(axis=1))
    missing_bottom = depth.shape[0] - 1 - int(rows_with_depth[-1])
    if missing_bottom >= params.truncated_rows_share * depth.shape[0]:
        return FrameAnalysis(None, [], empty, nothing,
                             f"truncated frame (the bottom {missing_bottom} of {depth.shape[0]} "
                             "rows have no depth)")
    stride = max(1, int(round(frame.intrinsics.width / params.target_width)))
    pts, rows = depth_to_points(depth, frame.intrinsics, stride, params.max_range_m)
    t1, c1 = time.perf_counter(), time.process_time()
    if len(pts) < 500:
        return FrameAnalysis(None, [], empty, nothing,
                             f"too few depth readings ({len(pts)} points within {params.max_range_m} m)")
    floor = find_floor(pts, frame.mount if use_mount else None, band_m=params.floor_band_m,
                       near_m=params.floor_near_m, previous=previous_floor)
    t2, c2 = time.perf_counter(), time.process_time()
    if floor is None:
        return FrameAnalysis(None, [], empty, nothing, "no floor visible",
                             timings_ms={"cloud": (t1 - t0) * 1e3, "floor": (t2 - t1) * 1e3},
                             cpu_ms={"cloud": (c1 - c0) * 1e3, "floor": (c2 - c1) * 1e3})
    pf, keep = _sample_points(pts, floor.camera_to_floor, params.samples)
    cols = frame.intrinsics.fx * pts[keep, 0] / pts[keep, 2] + frame.intrinsics.cx
    samples, stats = extract_samples(pf, rows[keep], frame.intrinsics.height, cols,
                                     frame.intrinsics.width, params.samples,
                                     camera_xy=floor.camera_to_floor[:2, 3], in_region=True)
    stats["points"] = int(len(pts))
    t3, c3 = time.perf_counter(), time.process_time()
    camera_xyz = floor.camera_to_floor[:3, 3].copy()
    feats = []
    for sample in samples:
        sample.normals = estimate_normals(sample.points, camera_xyz, params.features)
        feats.append(normal_histogram(sample.points, sample.normals, params.features))
    t4, c4 = time.perf_counter(), time.process_time()
    reason = None
    if not samples:
        reason = _why_no_samples(stats)
    return FrameAnalysis(floor, samples, np.array(feats) if feats else empty, camera_xyz, reason,
                         stats, {"cloud": (t1 - t0) * 1e3, "floor": (t2 - t1) * 1e3,
                                 "samples": (t3 - t2) * 1e3, "features": (t4 - t3) * 1e3},
                         {"cloud": (c1 - c0) * 1e3, "floor": (c2 - c1) * 1e3,
                          "samples": (c3 - c2) * 1e3, "features": (c4 - c3) * 1e3})


def _sample_points(points: np.ndarray, camera_to_floor: np.ndarray, params: SampleParams
                   ) -> tuple[np.ndarray, np.ndarray]:
    """The floor-frame points that can belong to a sample (``samples.sample_region``) and their
    indices in ``points``: each floor coordinate is one matrix-vector product over the cloud
    (the same values as ``cloud.transform``), and only the kept points — not the floor, most
    of the frame — are gathered into an (N, 3) array. The height is tested first, and the
    rest of the region only on the points at furniture height (the floor is most of a frame)."""
    x, y, z = (points @ camera_to_floor[k, :3] for k in range(3))
    z += camera_to_floor[2, 3]
    high = np.flatnonzero((z > params.min_z_m) & (z < params.max_z_m))
    x, y, z = x[high], y[high], z[high]
    x += camera_to_floor[0, 3]
    y += camera_to_floor[1, 3]
    inside = np.flatnonzero(sample_region(x, y, z, params))
    out = np.empty((len(inside), 3))
    out[:, 0], out[:, 1], out[:, 2] = x[inside], y[inside], z[inside]
    return out, high[inside]


def _why_no_samples(stats: dict) -> str:
    if stats.get("kept_points", 0) == 0:
        return "nothing stands on the floor within 4 m"
    parts = []
    if stats.get("cleared_cells") or stats.get("dropped_wall") or stats.get("dropped_tall"):
        parts.append("only walls or things taller than the view")
    if stats.get("dropped_small"):
        parts.append(f"{stats['dropped_small']} clutter piece(s) under 10 cells")
    return "no furniture-sized samples: " + ("; ".join(parts) if parts else "nothing found")

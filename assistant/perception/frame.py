"""One depth frame → floor + furniture samples with features (3.6.1–3.6.2), never raising.

:func:`analyse_frame` is the front half of the detector, shared by the detector, the training
database and the evaluation. A bad frame (all zeros, all NaN, no floor in view, a wall filling
the view) gives no samples and a ``reason`` instead of an exception.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from assistant.perception.cloud import Floor, depth_to_points, find_floor, transform
from assistant.perception.features import FeatureParams, normal_histogram, estimate_normals
from assistant.perception.samples import FurnitureSample, SampleParams, extract_samples
from assistant.robot.frames import DepthFrame


@dataclass(frozen=True)
class FrameParams:
    """Front-half parameters: ``target_width`` sets the back-projection stride (a 640-pixel
    frame is read every second pixel), ``floor_band_m``/``floor_near_m`` the RANSAC subset."""

    target_width: int = 320
    max_range_m: float = 6.0
    floor_band_m: float = 0.1
    floor_near_m: float = 3.0
    samples: SampleParams = field(default_factory=SampleParams)
    features: FeatureParams = field(default_factory=FeatureParams)


@dataclass(eq=False)
class FrameAnalysis:
    """What the front half found: the floor (or None), the samples with their histograms
    (``features`` (S, L)), the camera's position in the floor frame, and why nothing was found."""

    floor: Floor | None
    samples: list[FurnitureSample]
    features: np.ndarray
    camera_xyz: np.ndarray
    reason: str | None = None
    stats: dict = field(default_factory=dict)
    timings_ms: dict = field(default_factory=dict)


def analyse_frame(frame: DepthFrame, params: FrameParams = FrameParams(), *,
                  use_mount: bool = True) -> FrameAnalysis:
    """Floor, samples and features of one frame.

    ``use_mount`` predicts the floor from the frame's mount (camera height and tilt); without
    it (a frame from disk with unknown height and tilt) the floor is searched for.
    """
    t0 = time.perf_counter()
    empty = np.zeros((0, params.features.length))
    nothing = np.zeros(3)
    depth = np.asarray(frame.depth_m)
    valid = np.isfinite(depth) & (depth > 0)
    if not valid.any():
        what = "all NaN" if np.isnan(depth).all() else "no valid depth"
        return FrameAnalysis(None, [], empty, nothing, f"empty frame ({what})")
    stride = max(1, int(round(frame.intrinsics.width / params.target_width)))
    pts, rows = depth_to_points(depth, frame.intrinsics, stride, params.max_range_m)
    t1 = time.perf_counter()
    if len(pts) < 500:
        return FrameAnalysis(None, [], empty, nothing,
                             f"too few depth readings ({len(pts)} points within {params.max_range_m} m)")
    floor = find_floor(pts, frame.mount if use_mount else None, band_m=params.floor_band_m,
                       near_m=params.floor_near_m)
    t2 = time.perf_counter()
    if floor is None:
        return FrameAnalysis(None, [], empty, nothing, "no floor visible",
                             timings_ms={"cloud": (t1 - t0) * 1e3, "floor": (t2 - t1) * 1e3})
    pf = transform(pts, floor.camera_to_floor)
    cols = frame.intrinsics.fx * pts[:, 0] / pts[:, 2] + frame.intrinsics.cx
    samples, stats = extract_samples(pf, rows, frame.intrinsics.height, cols,
                                     frame.intrinsics.width, params.samples)
    t3 = time.perf_counter()
    camera_xyz = floor.camera_to_floor[:3, 3].copy()
    feats = []
    for sample in samples:
        sample.normals = estimate_normals(sample.points, camera_xyz, params.features)
        feats.append(normal_histogram(sample.points, sample.normals, params.features))
    t4 = time.perf_counter()
    reason = None
    if not samples:
        reason = _why_no_samples(stats)
    return FrameAnalysis(floor, samples, np.array(feats) if feats else empty, camera_xyz, reason,
                         stats, {"cloud": (t1 - t0) * 1e3, "floor": (t2 - t1) * 1e3,
                                 "samples": (t3 - t2) * 1e3, "features": (t4 - t3) * 1e3})


def _why_no_samples(stats: dict) -> str:
    if stats.get("kept_points", 0) == 0:
        return "nothing stands on the floor within 4 m"
    parts = []
    if stats.get("cleared_cells") or stats.get("dropped_wall") or stats.get("dropped_tall"):
        parts.append("only walls or things taller than the view")
    if stats.get("dropped_small"):
        parts.append(f"{stats['dropped_small']} clutter piece(s) under 10 cells")
    return "no furniture-sized samples: " + ("; ".join(parts) if parts else "nothing found")

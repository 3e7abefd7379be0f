"""Experiment (issue 20, 2 Dec evening, not adopted): sample normals from the depth image's own
pixel neighbours instead of open3d's KD-tree search (``features.estimate_normals``).

The frame's points come from a strided back-projection, so each point's image neighbours are
known. Here the points that can belong to a sample are laid out on their pixel grid once per
frame; a sample point's normal (its points are 5 cm voxel centroids, so each is projected back
into the image) is the cross product of the horizontal and vertical differences between the
grid points ``--radius`` metres (at its depth) either side of it — a neighbour missing or
farther than ``--jump`` × radius (a depth edge) replaced by the point (one-sided difference),
retried at half the distance and at one grid step where a direction has none.

Printed, per real frame and in total: the CPU milliseconds (best of ``--repeats``, one thread)
of open3d's normals and of the grid + image normals, and how far the image normals are from
open3d's (unoriented angle) and what that does to M_h (|difference| of the filled bins).
Result and the quality check of the retrained classifiers: ``docs/perception.md``,
"2 Dec evening (branch i20d)".

    OMP_NUM_THREADS=1 PYTHONPATH=. .venv/bin/python benchmarks/bench_image_normals.py \\
        [--realdata ../shared/realdata] [--radius 0.05] [--jump 8] [--repeats 7]
"""

from __future__ import annotations

import argparse
import sys
import timeit
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from assistant.perception.cloud import depth_to_points  # noqa: E402
from assistant.perception.features import estimate_normals, normal_histogram  # noqa: E402
from assistant.perception.frame import FrameParams, _sample_points, analyse_frame, thread_limit  # noqa: E402
from assistant.perception.realdata import load_frames  # noqa: E402


def point_grid(points, rows, cols, image_shape, stride) -> np.ndarray:
    """Camera-frame points on their (ceil(H / stride), ceil(W / stride)) pixel grid, NaN elsewhere."""
    h, w = -(-image_shape[0] // stride), -(-image_shape[1] // stride)
    gi = np.clip(np.rint(rows / stride).astype(np.intp), 0, h - 1)
    gj = np.clip(np.rint(cols / stride).astype(np.intp), 0, w - 1)
    grid = np.full((h * w, 3), np.nan)
    grid[gi * w + gj] = points
    return grid.reshape(h, w, 3)


def image_normals(grid, pts, k, stride, radius_m, jump) -> np.ndarray:
    """(N, 3) unit camera-frame normals at ``pts`` from their neighbours in ``grid``, facing the
    camera; the camera's −z axis where none can be made."""
    n = len(pts)
    out = np.tile([0.0, 0.0, -1.0], (n, 1))
    h, w, _ = grid.shape
    flat = grid.reshape(-1, 3)
    gi = (k.fy * pts[:, 1] / pts[:, 2] + k.cy) / stride
    gj = (k.fx * pts[:, 0] / pts[:, 2] + k.cx) / stride
    steps = radius_m * k.fx / (stride * pts[:, 2])
    di = np.array([0.0, 0.0, 1.0, -1.0])[:, None]  # right, left, down, up
    dj = np.array([1.0, -1.0, 0.0, 0.0])[:, None]
    todo = np.arange(n)
    for scale in (1.0, 0.5, 0.0):
        p = pts[todo]
        step = np.maximum(steps[todo] * scale, 1.0)
        ii = np.clip(np.rint(gi[todo] + di * step), 0, h - 1).astype(np.intp)
        jj = np.clip(np.rint(gj[todo] + dj * step), 0, w - 1).astype(np.intp)
        d = flat.take(ii * w + jj, axis=0) - p  # (4, M, 3)
        ok = np.einsum("kij,kij->ki", d, d) < (jump * radius_m) ** 2  # False where NaN
        d[~ok] = 0.0
        a, b = d[0] - d[1], d[2] - d[3]
        c = np.stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                      a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]], axis=1)
        length = np.sqrt(np.einsum("ij,ij->i", c, c))
        good = (ok[0] | ok[1]) & (ok[2] | ok[3]) & (length > 0)
        out[todo[good]] = c[good] / length[good, None]
        todo = todo[~good]
        if len(todo) == 0:
            break
    out[np.einsum("ij,ij->i", out, pts) > 0] *= -1.0
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--realdata", type=Path, default=HERE.parent.parent / "shared" / "realdata")
    ap.add_argument("--radius", type=float, default=0.05)
    ap.add_argument("--jump", type=float, default=8.0)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    params = FrameParams()
    best = lambda fn: min(timeit.repeat(fn, number=1, repeat=args.repeats)) * 1e3  # noqa: E731
    angles, diffs, totals = [], [], np.zeros(3)
    with thread_limit(1):
        for folder, name, frame in load_frames(args.realdata):
            a = analyse_frame(frame, params, use_mount=False)
            if a.floor is None or not a.samples:
                continue
            k = frame.intrinsics
            stride = max(1, int(round(k.width / params.target_width)))
            rot, t = a.floor.camera_to_floor[:3, :3], a.floor.camera_to_floor[:3, 3]
            pts, rows = depth_to_points(np.asarray(frame.depth_m), k, stride, params.max_range_m)
            _, keep = _sample_points(pts, a.floor.camera_to_floor, params.samples)
            kept = pts.take(keep, axis=0)
            cols = k.fx * kept[:, 0] / kept[:, 2] + k.cx
            cams = [(s.points - t) @ rot for s in a.samples]
            old = best(lambda: [estimate_normals(s.points, a.camera_xyz, params.features) for s in a.samples])
            grid_ms = best(lambda: point_grid(kept, rows.take(keep), cols, (k.height, k.width), stride))
            grid = point_grid(kept, rows.take(keep), cols, (k.height, k.width), stride)
            new = best(lambda: [image_normals(grid, c, k, stride, args.radius, args.jump) for c in cams])
            totals += [old, grid_ms, new]
            print(f"{folder}/{name}: {sum(len(s.points) for s in a.samples)} sample points; open3d "
                  f"{old:.2f} ms, grid {grid_ms:.2f} + image normals {new:.2f} ms (CPU)")
            for s, c in zip(a.samples, cams):
                o = estimate_normals(s.points, a.camera_xyz, params.features)
                n = image_normals(grid, c, k, stride, args.radius, args.jump) @ rot.T
                angles.append(np.degrees(np.arccos(np.clip(np.abs(np.einsum("ij,ij->i", o, n)), 0, 1))))
                ho, hn = (normal_histogram(s.points, x, params.features) for x in (o, n))
                diffs.append(np.abs(ho - hn)[ho >= 0])
    ang, dif = np.concatenate(angles), np.concatenate(diffs)
    print(f"total CPU ms over the frames: open3d {totals[0]:.1f}, grid {totals[1]:.1f} + image "
          f"normals {totals[2]:.1f} (radius {args.radius} m, jump {args.jump})")
    print(f"angle to open3d's normal (deg): median {np.median(ang):.1f}, p75 {np.percentile(ang, 75):.1f}, "
          f"p90 {np.percentile(ang, 90):.1f}, over 30° {100 * np.mean(ang > 30):.1f} % of {len(ang)} points")
    print(f"M_h filled bins |difference|: mean {dif.mean():.3f}, p90 {np.percentile(dif, 90):.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

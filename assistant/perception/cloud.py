"""Depth image → point cloud → the floor frame (dissertation 3.6.1, "Floor Detection").

Frames used here:

* **camera** (optical) frame: x right, y down, z forward, metres, origin at the lens;
* **floor** frame: z up and 0 on the floor, x forward (the camera's optical axis projected on
  the floor), y left. For a robot frame the origin is under the robot's base centre, so the
  floor frame *is* the robot frame, levelled by the measured floor; for a frame from disk it is
  under the camera ("camera-floor" frame).

The floor is found by RANSAC (open3d ``segment_plane``) on the points near the floor that the
camera height and tilt predict (within ``band_m``, nearer than ``near_m``), then refined on the
points near the fitted plane, so a camera rolled by a few degrees (hand-held SUN RGB-D frames)
still converges. Without a prediction (unknown height/tilt) the lowest large plane whose normal
points roughly up in the image is searched for instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.robot.frames import CameraIntrinsics, CameraMount, camera_to_base_matrix

#: RANSAC parameters of the floor fit (metres / iterations)
RANSAC_DISTANCE_M = 0.02
RANSAC_ITERATIONS = 60
RANSAC_MAX_POINTS = 2000
MIN_FLOOR_POINTS = 300
#: the floor search scores its plane hypotheses on about this many evenly taken points
SEARCH_POINTS = 5000


@dataclass(frozen=True)
class Floor:
    """The floor plane found in a frame.

    ``camera_to_floor`` (4×4) maps camera-frame points to the floor frame; ``height_m`` is the
    camera's height above the floor; ``normal_camera`` the floor's unit up-normal in the camera
    frame; ``inliers`` how many points supported it; ``tilt_rad``/``roll_rad`` the camera's
    measured pitch down and roll.
    """

    camera_to_floor: np.ndarray
    height_m: float
    normal_camera: np.ndarray
    inliers: int
    tilt_rad: float
    roll_rad: float

    @property
    def plane(self) -> np.ndarray:
        """``(nx, ny, nz, d)``: the floor as n·p + d = 0 in camera coordinates (n up)."""
        return np.append(self.normal_camera, self.height_m)

    def to_dict(self) -> dict:
        return {"height": round(float(self.height_m), 4),
                "normal": [round(float(v), 5) for v in self.normal_camera],
                "tilt_deg": round(math.degrees(self.tilt_rad), 2),
                "roll_deg": round(math.degrees(self.roll_rad), 2),
                "inliers": int(self.inliers)}


def sanitize_depth(depth_m: np.ndarray, max_range_m: float = 8.0) -> np.ndarray:
    """float32 depth with every non-finite, negative or too far reading set to 0 (missing)."""
    d = np.asarray(depth_m, dtype=np.float32)
    good = d > 0  # False for NaN; inf fails the range test
    good &= d <= max_range_m
    return np.where(good, d, np.float32(0.0))


def depth_to_points(depth_m: np.ndarray, intrinsics: CameraIntrinsics, stride: int = 2,
                    max_range_m: float = 6.0) -> tuple[np.ndarray, np.ndarray]:
    """Back-project a depth image (metres, 0 = missing): every ``stride``-th pixel of every
    ``stride``-th row with a reading in (0, ``max_range_m`` + 1 m], in image order.

    Returns ``(points, rows)``: (N, 3) float64 camera-frame points and the (N,) image row of
    each point (used to tell objects cut by the top of the view).

    The points are bit for bit open3d's ``PointCloud.create_from_depth_image`` of the
    :func:`sanitize_depth` image (which this was until 2 Dec; open3d applies no range cut to a
    float image, and computes ``x = (column − cx) · z / fx`` in double precision, as here):
    only the pixels read are sanitised, and no image or cloud is copied into and out of
    open3d — about 0.5 ms less per frame (``docs/perception.md``, 2 Dec night)."""
    d = np.asarray(depth_m, dtype=np.float32)[::stride, ::stride]
    good = d > 0  # False for NaN; inf fails the range test (as sanitize_depth)
    good &= d <= max_range_m + 1.0
    h, w = d.shape
    z = d[good].astype(float)
    if len(z) == 0:
        return np.zeros((0, 3)), np.zeros(0)
    columns = np.broadcast_to(np.arange(0, w * stride, stride) - intrinsics.cx, (h, w))[good]
    image_rows = np.broadcast_to((np.arange(0, h * stride, stride) - intrinsics.cy)[:, None], (h, w))[good]
    x = columns * z
    x /= intrinsics.fx
    y = image_rows * z
    y /= intrinsics.fy
    pts = np.column_stack([x, y, z])
    rows = intrinsics.fy * y / z + intrinsics.cy
    return pts, rows


def nominal_camera_to_floor(mount: CameraMount) -> np.ndarray:
    """4×4 camera → floor (robot base) transform predicted from the mount alone."""
    return camera_to_base_matrix(mount)


def transform(points: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """Apply a 4×4 rigid transform to (N, 3) points (off the per-frame path: the frame's own
    transform is ``frame._sample_points``)."""
    return np.asarray(points, dtype=float) @ matrix[:3, :3].T + matrix[:3, 3]


def _lsq_plane(points: np.ndarray, towards: np.ndarray) -> np.ndarray:
    """Least-squares plane ``(nx, ny, nz, d)`` of (N ≥ 3, 3) points, its unit normal on the side
    of ``towards``: the eigenvector of the smallest eigenvalue of the 3×3 scatter matrix (the
    same plane as the smallest singular vector of the centred points, without the N×3 SVD).

    Rows are selected with ``np.compress`` throughout this module: on an (N, 3) array it is
    about 5× faster than boolean indexing, with the same result."""
    n = len(points)
    centre = np.ones(n) @ points / n
    # scatter about the centre from the raw moments (no centred N×3 copy); with coordinates of
    # a few metres the cancellation costs ~1e-11 of the smallest eigenvalue's scale
    scatter = points.T @ points - n * np.outer(centre, centre)
    _, vecs = np.linalg.eigh(scatter)
    normal = vecs[:, 0]
    if normal @ towards <= 0:
        normal = -normal
    return np.append(normal, -normal @ centre)


def _fit_plane(points: np.ndarray, seed: int, max_points: int = RANSAC_MAX_POINTS
               ) -> tuple[np.ndarray, int] | None:
    """RANSAC plane (open3d ``segment_plane``) on at most ``max_points`` evenly taken points,
    then a least-squares refit on all points within the RANSAC distance.

    Returns ``(plane, inliers)``: plane ``(nx, ny, nz, d)`` with unit normal, n·p + d = 0.
    """
    import open3d as o3d

    if len(points) < 3:
        return None
    # a contiguous copy: open3d converts a strided array ~50× slower (1.2 ms for 2000 points)
    sub = np.ascontiguousarray(points[:: max(1, len(points) // max_points)])
    o3d.utility.random.seed(seed)
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(sub))
    model, _ = cloud.segment_plane(RANSAC_DISTANCE_M, 3, RANSAC_ITERATIONS)
    n = np.asarray(model[:3], dtype=float)
    norm = np.linalg.norm(n)
    if norm == 0:
        return None
    plane = np.append(n / norm, model[3] / norm)
    inl = np.abs(points @ plane[:3] + plane[3]) < RANSAC_DISTANCE_M
    count = int(np.count_nonzero(inl))
    if count >= 3:
        plane = _lsq_plane(np.compress(inl, points, axis=0), plane[:3])
    return plane, count


def _refine(points: np.ndarray, plane: np.ndarray, band_m: float, seed: int,
            max_turn_deg: float = 15.0, rounds: int = 3) -> tuple[np.ndarray, int] | None:
    """RANSAC (open3d) on the points within ``band_m`` of a plane, then least-squares refits on
    the points within the RANSAC distance of the latest plane.

    Returns None (no plane) when the RANSAC plane turns by more than ``max_turn_deg`` from the
    given one: the band then caught another surface (a bed side, a wall).
    """
    sel = np.abs(points @ plane[:3] + plane[3]) < band_m
    if np.count_nonzero(sel) < MIN_FLOOR_POINTS:
        return None
    fit = _fit_plane(np.compress(sel, points, axis=0), seed)
    if fit is None:
        return None
    new, inliers = fit
    if new[:3] @ plane[:3] < 0:
        new = -new
    if new[:3] @ plane[:3] < math.cos(math.radians(max_turn_deg)):
        return None
    for _ in range(rounds - 1):  # the band may have cut a rolled floor short: widen to it
        near = np.abs(points @ new[:3] + new[3]) < RANSAC_DISTANCE_M
        count = int(np.count_nonzero(near))
        if count < 3:
            break
        refit = _lsq_plane(np.compress(near, points, axis=0), new[:3])
        inliers = count
        # np.allclose(refit, new, atol=1e-3) for finite planes (its test, without its ~50 µs
        # of argument handling)
        if bool(np.all(np.abs(refit - new) <= 1e-3 + 1e-5 * np.abs(new))):
            break
        new = refit
    return new, inliers


def _search_floor(points: np.ndarray, seed: int = 0, hypotheses: int = 400,
                  max_tilt_deg: float = 50.0, heights_m: tuple[float, float] = (0.3, 2.5),
                  lowest: bool = False) -> np.ndarray | None:
    """Without a prediction: the plane with most support and (almost) nothing below it.

    Plane hypotheses (:func:`_floor_hypotheses`) are scored by their inliers (5 cm) minus twice
    the points more than 12 cm *below* them: a bed or table top has the floor under it, the
    floor has nothing. Returns a rough plane for :func:`_refine`. The cloud (image order) is
    read every ``len // SEARCH_POINTS``-th point. ``lowest``: the lowest plane holding half the
    best score instead (:func:`_lowest_supported`; tried when the best one gave no floor).
    """
    sub = points[:: max(1, len(points) // SEARCH_POINTS)]
    if len(sub) < MIN_FLOOR_POINTS // 3:
        return None
    normals, d = _floor_hypotheses(sub, seed, hypotheses, max_tilt_deg, heights_m)
    if len(normals) == 0:
        return None
    k, score = _best_supported(sub, normals, d)
    if score < max(20, 0.02 * len(sub)):
        return None
    if lowest:
        return np.append(*_lowest_supported(sub, normals, d, k, score))
    return np.append(normals[k], d[k])


def _lowest_supported(points: np.ndarray, normals: np.ndarray, d: np.ndarray, k: int, score: int,
                      share: float = 0.5, lower_m: float = 0.15) -> tuple[np.ndarray, float]:
    """The floor among the hypotheses: the lowest plane (farthest below the camera, at least
    ``lower_m`` below the best-supported one, ``k`` with ``score``) that holds ``share`` of that
    score with nothing 12 cm under it; else the best-supported one. The floor is the lowest
    large plane with nothing under it: a frame that shows little floor beside a bed (SUN RGB-D
    000002: 5 % of the points) has a plane grazing the bed's near side at the bottom of the view,
    with nothing under it either, that outscores the floor (measured, the frame mirrored or a
    tenth of its pixels lost: 316 against the floor's 258); the search took it and found no
    floor."""
    lower = np.flatnonzero(d >= d[k] + lower_m)
    if len(lower) == 0:
        return normals[k], float(d[k])
    scores = _support_scores(points, normals[lower], d[lower])
    good = scores >= share * score
    if not good.any():
        return normals[k], float(d[k])
    best = lower[good][int(np.argmax(d[lower][good]))]
    return normals[best], float(d[best])


def _floor_hypotheses(sub: np.ndarray, seed: int = 0, hypotheses: int = 400,
                      max_tilt_deg: float = 50.0, heights_m: tuple[float, float] = (0.3, 2.5)
                      ) -> tuple[np.ndarray, np.ndarray]:
    """(normals (M, 3), offsets (M,)) of the planes through random point triples of ``sub``
    whose normal is within ``max_tilt_deg`` of the image's up direction (−y) and which lie
    ``heights_m`` below the camera."""
    rng = np.random.default_rng(seed)
    # triples of nearby points (the cloud is in image order), so a floor seen in a small part
    # of the image still gets hypotheses; the refit in _refine makes the normal precise
    first = rng.integers(0, len(sub), size=hypotheses)
    offsets = rng.integers(3, 120, size=(hypotheses, 2))
    idx = np.clip(np.stack([first, first + offsets[:, 0], first + offsets[:, 0] + offsets[:, 1] // 2 + 2],
                           axis=1), 0, len(sub) - 1)
    tri = sub[idx]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    norms = np.linalg.norm(normals, axis=1)
    ok = norms > 1e-9
    normals = normals[ok] / norms[ok, None]
    normals *= np.where(normals[:, 1] > 0, -1.0, 1.0)[:, None]  # point up in the image (−y)
    d = -np.einsum("ij,ij->i", normals, tri[ok, 0])
    keep = (-normals[:, 1] > math.cos(math.radians(max_tilt_deg))) & (d > heights_m[0]) & (d < heights_m[1])
    return normals[keep], d[keep]


def _best_supported(points: np.ndarray, normals: np.ndarray, d: np.ndarray,
                    thin: int = 4, finalists: int = 16) -> tuple[int, int]:
    """(index, score) of the plane with the highest :func:`_support_scores` on ``points`` (the
    first of equals, as ``np.argmax``), scoring in two rounds: every plane on every ``thin``-th
    point, then the ``finalists`` best of them on all points. The planes are a few hundred
    hypotheses of which a handful lie near the floor; the winner on all points is among the
    best on a quarter of them unless two planes' supports differ by noise (measured on the real
    frames and a synthetic one: the same plane each time, ``tests/perception/test_cloud.py``), and
    scoring the rest on a quarter of the points cuts the scoring by about 2×."""
    if len(normals) <= finalists:
        score = _support_scores(points, normals, d)
        k = int(np.argmax(score))
        return k, int(score[k])
    rough = _support_scores(points[::thin], normals, d)
    best = np.sort(np.argsort(-rough, kind="stable")[:finalists])  # in hypothesis order
    score = _support_scores(points, normals[best], d[best])
    k = int(np.argmax(score))
    return int(best[k]), int(score[k])


def _support_scores(points: np.ndarray, normals: np.ndarray, d: np.ndarray,
                    chunk: int = 32) -> np.ndarray:
    """Per plane (M): points within 5 cm minus twice the points more than 12 cm below it.

    The (M, N) heights are built a few dozen planes at a time from the three coordinate rows
    (no BLAS matrix product: its threads competed on the loaded machine, and a chunk stays in
    the cache), in two buffers and one mask allocated once per call (a fresh megabyte array
    per step cost more than the arithmetic), rows counted one by one (:func:`_row_counts`);
    the counts are exact integers.
    """
    rows = np.ascontiguousarray(points.T)
    score = np.empty(len(normals), dtype=np.int64)
    shape = (min(chunk, len(normals)), rows.shape[1])
    heights, scratch, mask = np.empty(shape), np.empty(shape), np.empty(shape, dtype=bool)
    for a in range(0, len(normals), chunk):
        n = normals[a:a + chunk]
        h, t, m = heights[:len(n)], scratch[:len(n)], mask[:len(n)]
        np.multiply.outer(n[:, 0], rows[0], out=h)
        h += np.multiply.outer(n[:, 1], rows[1], out=t)
        h += np.multiply.outer(n[:, 2], rows[2], out=t)
        h += d[a:a + chunk, None]
        below = _row_counts(np.less(h, -0.12, out=m))
        score[a:a + len(n)] = _row_counts(np.less(np.abs(h, out=t), 0.05, out=m)) - 2 * below
    return score


def _row_counts(mask: np.ndarray) -> np.ndarray:
    """``np.count_nonzero(mask, axis=1)`` of a C-contiguous 2-D bool array: its bytes summed
    along the rows as 32-bit integers (exact) — 1–2× faster than counting the rows one by one
    (the way this was done before) and ~3× faster than the axis count for a few dozen rows of
    a few thousand."""
    return np.add.reduce(mask.view(np.uint8), axis=1, dtype=np.int32).astype(np.int64)


def find_floor(points_camera: np.ndarray, mount: CameraMount | None, *, band_m: float = 0.1,
               near_m: float = 3.0, seed: int = 0, strong_support: float = 0.2,
               previous: "Floor | None" = None) -> Floor | None:
    """The floor plane of a camera-frame cloud, or None when no floor is visible.

    With a ``mount`` (camera height and tilt), RANSAC runs on the points within ``band_m`` of
    the predicted floor and nearer than ``near_m`` (dissertation 3.6.1). If that plane holds
    fewer than ``strong_support`` of the near points, and always without a mount, the lowest
    large upward plane is also searched for (:func:`_search_floor`), and the lower of the two
    planes wins.

    ``previous`` (the floor found in an earlier frame from the same camera pose) is checked
    first (:func:`_reuse_floor`): if the points near its plane still hold it, it is refitted to
    them and nothing is searched; a camera that has moved finds no such support and the floor
    is found as without it.

    All points take part (fitting on a subset, tried for speed with a throw-away change, moved
    the floor of the real frames and changed what was detected; not kept, not reproducible by a
    command).
    """
    pts = points_camera
    if len(pts) < MIN_FLOOR_POINTS:
        return None
    range2 = _squared_ranges(pts)
    candidates = []
    wider = None  # the points within near_m + 2 m, gathered once and only when needed
    if previous is not None:
        wider = np.compress(range2 < (near_m + 2.0) ** 2, pts, axis=0)
        if (found := _reuse_floor(wider, previous)) is not None:
            return _floor_from_plane(*found, mount)
    near_count = 0
    if mount is not None:
        near = np.compress(range2 < near_m ** 2, pts, axis=0)
        near_count = len(near)
        nominal = nominal_camera_to_floor(mount)
        # predicted plane in camera coordinates: n = R^T z, d = the camera height
        n = nominal[:3, :3].T @ np.array([0.0, 0.0, 1.0])
        found = _refine(near, np.append(n, nominal[2, 3]), band_m, seed)
        if found is not None:
            candidates.append(found)
    if not candidates or candidates[0][1] < strong_support * near_count:
        # no prediction, or a weak one (an approximate height/tilt given by hand): search
        if wider is None:
            wider = np.compress(range2 < (near_m + 2.0) ** 2, pts, axis=0)
        guess = _search_floor(wider, seed)
        found = None if guess is None else _refine(wider, guess, max(band_m, 0.1), seed)
        if found is None and guess is not None and mount is None:
            # no floor on the best-supported plane: a frame from disk showing little floor
            lower = _search_floor(wider, seed, lowest=True)
            if lower is not None and not np.array_equal(lower, guess):
                found = _refine(wider, lower, max(band_m, 0.1), seed)
        if found is not None:
            candidates.append(found)
    if not candidates:
        return None
    # the floor is the lowest well-supported plane: a bed or table top filling the near view
    # can hold more points than the floor beside it
    supported = [c for c in candidates if c[1] >= MIN_FLOOR_POINTS]
    if not supported:
        return None
    plane, inliers = max(supported, key=lambda c: c[0][3])
    return _floor_from_plane(plane, inliers, mount)


def _squared_ranges(points: np.ndarray) -> np.ndarray:
    """Each point's squared distance from the origin, from the coordinate columns: ~2.5×
    faster than ``np.einsum("ij,ij->i", points, points)`` on a frame's ~80 000 points, and
    the same bits here — this machine's numpy (2.4, AVX2) adds the squares as ``(x² + z²) + y²``
    in its einsum (checked on 100 random clouds and the real frames); another build may round
    a last bit differently, which only matters to a point exactly at the 5 m range cut."""
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    out = x * x
    square = z * z
    out += square
    np.multiply(y, y, out=square)
    out += square
    return out


def _reuse_floor(points: np.ndarray, previous: Floor, keep_share: float = 0.7,
                 max_shift_m: float = 0.02, max_turn_deg: float = 1.0) -> tuple[np.ndarray, int] | None:
    """The previous frame's floor refitted (least squares, twice) to this frame's points within
    the RANSAC distance of it — if they are still at least ``keep_share`` of its inliers and
    the plane moved by under ``max_shift_m`` and ``max_turn_deg``; else None (search again).
    No RANSAC and no search: a few vector operations over the cloud."""
    plane = previous.plane
    count = 0
    for _ in range(2):
        near = np.abs(points @ plane[:3] + plane[3]) < RANSAC_DISTANCE_M
        count = int(np.count_nonzero(near))
        if count < max(MIN_FLOOR_POINTS, keep_share * previous.inliers):
            return None
        plane = _lsq_plane(np.compress(near, points, axis=0), previous.plane[:3])
    turn = math.degrees(math.acos(min(1.0, float(plane[:3] @ previous.plane[:3]))))
    if abs(plane[3] - previous.plane[3]) > max_shift_m or turn > max_turn_deg:
        return None
    return plane, count


def _floor_from_plane(plane: np.ndarray, inliers: int, mount: CameraMount | None) -> Floor:
    """Build the camera → floor transform from the plane n·p + d = 0 (n up, camera frame)."""
    up = plane[:3] / np.linalg.norm(plane[:3])
    height = float(plane[3])
    forward = np.array([0.0, 0.0, 1.0]) - up * up[2]  # optical axis projected on the floor
    if np.linalg.norm(forward) < 1e-6:  # looking straight down: use the image's up direction
        forward = np.array([0.0, -1.0, 0.0]) - up * (-up[1])
    forward /= np.linalg.norm(forward)
    left = np.cross(up, forward)
    rot = np.vstack([forward, left, up])  # rows: floor axes in camera coordinates
    m = np.eye(4)
    m[:3, :3] = rot
    m[:3, 3] = [mount.forward_m if mount else 0.0, 0.0, height]
    tilt = math.asin(max(-1.0, min(1.0, -float(up @ np.array([0.0, 0.0, 1.0])))))
    # roll: angle of the camera's x axis out of the floor plane
    roll = math.asin(max(-1.0, min(1.0, float(up @ np.array([1.0, 0.0, 0.0])))))
    return Floor(m, height, up, inliers, tilt, roll)

"""Samples regrouped where one item was cut in two or two items were joined (issue 20).

The floor grid's connected components are the detector's samples; two cases they get wrong on
real frames are put right here, each as a hypothesis the classifier confirms:

* **a bed cut by its footboard's shadow** (:func:`shadow_candidates`): seen from its foot end,
  the footboard hides the mattress behind it, and only a strip of mattress far beyond shows —
  two samples, neither a bed. A sample B lying behind a sample A (along the camera's rays), thin
  along them, whose near edge is no farther than where a ray grazing A's top comes down to B's
  top surface, is joined with A's part that rises to B's height (the footboard; a bench in
  front of it stays apart) — kept if the classifier reads the join as a bed, or the verifier
  (``info["checked"]``) the part before the board as ``other`` (a bench: the board and what
  lies in its shadow are one item).
* **a night stand beside a bed** (:func:`side_candidates`): a small box standing against a bed's
  long side is one component with it. Cells that stick out sideways beyond the bed's width
  (the median of its cross-section along its length) by more than a margin, in a piece of
  night-stand size, are split off — kept if the classifier reads that piece as a small table
  and the rest still as a bed.

Both need the classifier (a callable ``classify(samples) → (subclasses, confidences,
features)``) and touch only the samples involved; a frame without such a pair costs a few
array operations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.perception.features import percentiles
from assistant.perception.samples import FurnitureSample, centred_xy


@dataclass(frozen=True)
class RegroupParams:
    """Thresholds in metres (areas m²): how far B's near edge may lie past the shadow's end
    (``shadow_margin_m``), the least share of B's bearings A must cover, B's largest depth along
    the rays (a strip: more and it is an item of its own), how much lower than B's top surface
    A's board may be; the side margin, and the side piece's area and size."""

    shadow_margin_m: float = 0.2
    min_bearing_overlap: float = 0.5
    max_strip_depth_m: float = 0.7
    board_below_m: float = 0.1
    range_bin_m: float = 0.05
    side_margin_m: float = 0.1
    min_side_m2: float = 0.06
    max_side_m: float = 1.0
    min_part_m2: float = 0.1


def _ranges(points: np.ndarray, camera_xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    d, _ = centred_xy(points, np.asarray(camera_xy, dtype=float))
    return np.hypot(d[:, 0], d[:, 1]), np.arctan2(d[:, 1], d[:, 0])


def part(sample: FurnitureSample, keep_points: np.ndarray, keep_cells: np.ndarray) -> FurnitureSample:
    """A new sample of some of ``sample``'s points and cells, with their normals (each point's
    normal was estimated once, from its neighbours in the whole sample: a surface's, however
    the samples are then grouped; None if the sample had none yet)."""
    pts = sample.points[keep_points]
    normals = None if sample.normals is None else sample.normals[keep_points]
    return FurnitureSample(pts, sample.cells_xy_m[keep_cells], percentiles(pts[:, 2], 99),
                           sample.touches_border, normals)


def joined(a: FurnitureSample, b: FurnitureSample) -> FurnitureSample:
    """One sample of both samples' points, cells and normals (as in :func:`part`)."""
    pts = np.vstack([a.points, b.points])
    normals = None if a.normals is None or b.normals is None else np.vstack([a.normals, b.normals])
    return FurnitureSample(pts, np.vstack([a.cells_xy_m, b.cells_xy_m]),
                           percentiles(pts[:, 2], 99), a.touches_border or b.touches_border, normals)


def _board_split(a: FurnitureSample, camera_xy: np.ndarray, level_m: float, p: RegroupParams):
    """(far part, near part or None, the far part's top, its farthest range) of ``a``: the far
    run of depth bins (along the line from the camera to ``a``'s centre) whose top reaches
    ``level_m`` (the board), and what stands before it."""
    u = a.points[:, :2].mean(axis=0) - camera_xy
    u /= max(float(np.linalg.norm(u)), 1e-9)
    d = (a.points[:, :2] - camera_xy) @ u
    bins = ((d - d.min()) / p.range_bin_m).astype(int)
    top = np.full(bins.max() + 1, -np.inf)
    np.maximum.at(top, bins, a.points[:, 2])
    high = top >= level_m
    if len(high) < 2 or not high[-2:].any():
        return None
    k = len(top) - 1 if high[-1] else len(top) - 2
    while k > 0 and (high[k - 1] or not np.isfinite(top[k - 1])):
        k -= 1
    split = d.min() + k * p.range_bin_m
    far_pts = d >= split
    far_cells = (a.cells_xy_m - camera_xy) @ u >= split - p.range_bin_m / 2
    near_area = np.count_nonzero(~far_cells) * _cell_area(a)
    if near_area >= p.min_part_m2 and (~far_pts).sum() >= 10:
        far, near = part(a, far_pts, far_cells), part(a, ~far_pts, ~far_cells)
    else:
        far, near = a, None
    r, _ = _ranges(a.points, camera_xy)
    return far, near, percentiles(a.points[far_pts, 2], 95), float(r.max())


def _cell_area(s: FurnitureSample) -> float:
    if len(s.cells_xy_m) < 2:
        return 0.0025
    d = np.diff(np.unique(s.cells_xy_m[:, 0]))
    g = float(d[d > 1e-6].min()) if np.any(d > 1e-6) else 0.05
    return g * g


def shadow_candidates(samples: list[FurnitureSample], camera_xyz: np.ndarray, surfaces: list[float],
                      p: RegroupParams = RegroupParams()) -> list[tuple[int, int, FurnitureSample, FurnitureSample | None]]:
    """(index of A, index of B, the joined sample, A's part before its board or None) for each
    pair where B lies in A's shadow (module docstring); ``surfaces`` is each sample's top
    surface height (the shape descriptor's)."""
    cam = np.asarray(camera_xyz[:2], dtype=float)
    height = float(camera_xyz[2])
    out = []
    geo = [_ranges(s.points, cam) for s in samples]
    # each sample's range and bearing percentiles, once: (range 2nd, 98th; bearing 2nd, 98th)
    spans = [(*percentiles(r, (2, 98)), *percentiles(a, (2, 98))) for r, a in geo]
    for ib, b in enumerate(samples):
        rb, ab = geo[ib]
        hb = surfaces[ib] if surfaces[ib] > 0 else percentiles(b.points[:, 2], 95)
        near_b, far_b = spans[ib][:2]
        if far_b - near_b > p.max_strip_depth_m or hb >= height:
            continue
        b_lo, b_hi = percentiles(ab, (5, 95))
        for ia, a in enumerate(samples):
            if ia == ib:
                continue
            _, ra98, aa2, aa98 = spans[ia]
            if ra98 > near_b:
                continue
            overlap = np.mean((ab >= aa2) & (ab <= aa98))
            if overlap < p.min_bearing_overlap or b_hi - b_lo <= 0:
                continue
            split = _board_split(a, cam, hb - p.board_below_m, p)
            if split is None:
                continue
            far, near, ha, far_range = split
            if ha >= height - 0.05:
                continue
            shadow_end = far_range * (height - min(hb, ha)) / (height - ha)
            if near_b <= shadow_end + p.shadow_margin_m:
                out.append((ia, ib, joined(far, b), near))
    return out


def side_candidates(sample: FurnitureSample, p: RegroupParams = RegroupParams()
                    ) -> tuple[FurnitureSample, FurnitureSample] | None:
    """(the bed without the piece, the piece) when cells stick out sideways beyond the
    sample's width — along either side of its best rectangle (``geometry.rectangle_fill``) —
    in a night-stand-sized piece (module docstring), else None."""
    from assistant.geometry import rectangle_fill

    cells = sample.cells_xy_m
    if len(cells) < 40:
        return None
    grid = math.sqrt(_cell_area(sample))
    _, angle, _ = rectangle_fill(np.round(cells / grid))
    centre = cells.mean(axis=0)
    for a in (angle, angle + math.pi / 2):
        major = np.array([math.cos(a), math.sin(a)])
        minor = np.array([-major[1], major[0]])
        found = _side_piece(sample, centre, major, minor, p)
        if found is not None:
            return found
    return None


def _side_piece(sample: FurnitureSample, centre: np.ndarray, major: np.ndarray, minor: np.ndarray,
                p: RegroupParams) -> tuple[FurnitureSample, FurnitureSample] | None:
    """:func:`side_candidates` along one choice of the item's length axis ``major``: the
    largest connected piece (8-neighbour, on the sample's cells) of the cells outside the
    median width that has a night stand's size."""
    from scipy import ndimage

    cells = sample.cells_xy_m
    grid = math.sqrt(_cell_area(sample))
    along, across = (cells - centre) @ major, (cells - centre) @ minor
    # the cross-section's ends in each 0.1 m slice along the item (the slices that hold cells)
    k = np.floor((along - along.min()) / 0.1).astype(int)
    lo, hi = np.full(k.max() + 1, np.inf), np.full(k.max() + 1, -np.inf)
    np.minimum.at(lo, k, across)
    np.maximum.at(hi, k, across)
    held = np.bincount(k) > 0
    lo, hi = lo[held], hi[held]
    ij = np.round((cells - cells.min(axis=0)) / grid).astype(int)
    point_ij = np.floor((sample.points[:, :2] - cells.min(axis=0) + grid / 2) / grid + 1e-6).astype(int)
    for side, edge in ((1, float(np.median(hi))), (-1, float(np.median(lo)))):
        outside = (across - edge) * side > p.side_margin_m
        if np.count_nonzero(outside) * grid * grid < p.min_side_m2:
            continue
        image = np.zeros(ij.max(axis=0) + 1, dtype=bool)
        image[ij[outside, 0], ij[outside, 1]] = True
        labels, count = ndimage.label(image, structure=np.ones((3, 3)))
        cell_label = labels[ij[:, 0], ij[:, 1]]
        best = None
        for c in range(1, count + 1):
            piece = outside & (cell_label == c)
            if np.count_nonzero(piece) * grid * grid < p.min_side_m2:
                continue
            if max(np.ptp(along[piece]), np.ptp(across[piece])) > p.max_side_m:
                continue
            if best is None or piece.sum() > best.sum():
                best = piece
        if best is None:
            continue
        inside = np.zeros_like(image)
        inside[ij[best, 0], ij[best, 1]] = True
        ok = (point_ij >= 0).all(axis=1) & (point_ij < image.shape).all(axis=1)
        piece_pts = np.zeros(len(sample.points), dtype=bool)
        piece_pts[ok] = inside[point_ij[ok, 0], point_ij[ok, 1]]
        if piece_pts.sum() < 10 or (~piece_pts).sum() < 10:
            continue
        return part(sample, ~piece_pts, ~best), part(sample, piece_pts, best)
    return None


def regroup(samples: list[FurnitureSample], labels: list[tuple[str, float]], surfaces: list[float],
            camera_xyz: np.ndarray, classify, p: RegroupParams = RegroupParams()
            ) -> tuple[list[FurnitureSample], list[tuple[str, float]], list[str]]:
    """The samples after :func:`shadow_candidates` and :func:`side_candidates` confirmed by
    ``classify`` (a list of samples → list of (subclass, confidence)), their labels, and a note
    per change ("joined across a shadow", "split off a bed's side")."""
    from assistant.perception.classifiers import category_of

    samples, labels, notes = list(samples), list(labels), []
    used: set[int] = set()
    for ia, ib, join, near in shadow_candidates(samples, camera_xyz, surfaces, p):
        if ia in used or ib in used:
            continue
        (sub, conf), *rest = classify([join] + ([near] if near is not None else []))
        if category_of(sub) != "bed" and not (near is not None and near.info.get("checked") == "other"):
            continue
        used.update((ia, ib))
        join.info["joined"] = "shadow"
        samples[ia], labels[ia] = join, (sub, conf)
        samples[ib], labels[ib] = None, None
        if near is not None:
            samples.append(near)
            labels.append(rest[0])
        notes.append("joined across a shadow")
    for i in range(len(samples)):
        if samples[i] is None or category_of(labels[i][0]) != "bed":
            continue
        found = side_candidates(samples[i], p)
        if found is None:
            continue
        (bsub, bconf), (psub, pconf) = classify(list(found))
        if category_of(bsub) != "bed" or category_of(psub) != "small table":
            continue
        samples[i], labels[i] = found[0], (bsub, bconf)
        samples.append(found[1])
        labels.append((psub, pconf))
        notes.append("split off a bed's side")
    keep = [k for k, s in enumerate(samples) if s is not None]
    return [samples[k] for k in keep], [labels[k] for k in keep], notes


def range_cut(sample: FurnitureSample, max_forward_m: float, margin_m: float = 0.15) -> bool:
    """Whether the sample reaches the far end of the sample range (``max_forward_m`` ahead
    along the floor frame's x, before any robot pose is applied): the item may go on beyond."""
    return bool(len(sample.cells_xy_m) and sample.cells_xy_m[:, 0].max() >= max_forward_m - margin_m)

"""Floor-frame point cloud → furniture samples (dissertation 3.6.1, "Extract Furniture Sample").

Points between ``min_z_m`` and ``max_z_m`` above the floor and nearer than ``max_forward_m`` are
projected onto a floor grid (x forward in [0, 4] m, y left in [-3, 3] m — the dissertation's
x/y, turned to the robot frame); connected components of the occupied cells (scipy) are the
samples. The dissertation's grid is 0.1 m; this one is 0.05 m because, measured on the scenes
of Table 3-9, a chair or couch 0.15 m from a table merged with it on the 0.1 m grid (diagonal
neighbours touch) and was misread. Components taller than ``max_height_m`` or smaller than
``min_area_m2`` (the dissertation's 10 cells of 0.1 m) are dropped (walls, clutter). Before labelling, every cell a point seen in
the top rows of the image, or any point higher than ``max_height_m``, falls into is cleared:
such a column runs out of the view or above furniture height, so it is a wall or something too
tall to be furniture, and clearing it keeps a couch or bed standing against a wall apart from
the wall (the dissertation drops whole components taller than 2 m, which loses them); so is
every cell higher than ``wall_remains_top_m`` within two cells of a cleared one (a wall's remains
beside its cleared columns: noise spreads a wall over two cells, and its part under the top
rows of the image is not cleared otherwise). With the image rows and columns, the wall is also followed down
each image column from those points for as long as it stays a vertical surface
(:func:`wall_continuation`): a wall leaning a degree or two against the floor found (real
frames) or seen obliquely drops its lower part into the cells in front of the cleared ones,
below the remains height, where it stood on the couch or bed before it like a headboard.
Each sample is voxel-downsampled (open3d).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from assistant.geometry import rectangle_fill
from assistant.geometry.shapes import FILL_ANGLES


@dataclass(frozen=True)
class SampleParams:
    """Sample-extraction parameters (metres unless stated)."""

    min_z_m: float = 0.1
    max_z_m: float = 2.5
    max_forward_m: float = 4.0
    grid_m: float = 0.05
    x_range_m: tuple[float, float] = (0.0, 4.0)
    y_range_m: tuple[float, float] = (-3.0, 3.0)
    max_height_m: float = 2.0
    min_area_m2: float = 0.1  # 10 cells of 0.1 m
    voxel_m: float = 0.05
    top_rows_fraction: float = 0.015  # image rows counted as "the top of the view"
    wall_thickness_m: float = 0.08  # a thin, long, tall-ish component is a piece of wall
    wall_length_m: float = 1.2
    wall_remains_top_m: float | None = 1.2  # None: clear only the tall columns themselves
    wall_trace_band_m: float | None = 0.025  # None: do not follow walls down the image columns
    split_min_area_m2: float | None = 1.0  # None: never split a component into two items
    split_max_fill: float = 0.7  # split only components filling less of their best rectangle
    split_min_part_fill: float = 0.75  # each part must fill this much of its own rectangle …
    split_min_gain: float = 0.2  # … and this much more than the whole fills its rectangle
    split_min_part_m2: float = 0.25


@dataclass(eq=False)
class FurnitureSample:
    """One candidate piece of furniture: its points in the floor frame (metres).

    ``points`` (N, 3) are voxel-downsampled; ``cells`` (M, 2) the ``(ix, iy)`` indices of the
    occupied 0.1 m cells of the local grid (x forward from ``x_range_m[0]``, y from
    ``y_range_m[0]``); ``touches_border`` says the sample runs out of the left, right or bottom
    of the image (a partial view).
    """

    points: np.ndarray
    cells_xy_m: np.ndarray
    height_m: float
    touches_border: bool = False
    normals: np.ndarray | None = None
    info: dict = field(default_factory=dict)

    @property
    def centroid_xy(self) -> np.ndarray:
        return self.points[:, :2].mean(axis=0)

    @property
    def footprint_centre_xy(self) -> np.ndarray:
        """Centre (metres) of the occupied cells."""
        return self.cells_xy_m.mean(axis=0)


def grid_size(params: SampleParams = SampleParams()) -> tuple[int, int]:
    """(cells along x, cells along y) of the floor grid."""
    p = params
    return (int(round((p.x_range_m[1] - p.x_range_m[0]) / p.grid_m)),
            int(round((p.y_range_m[1] - p.y_range_m[0]) / p.grid_m)))


def sample_region(x: np.ndarray, y: np.ndarray, z: np.ndarray,
                  params: SampleParams = SampleParams()) -> np.ndarray:
    """Mask of the floor-frame points (coordinates in metres) that can belong to a sample:
    ``min_z_m``–``max_z_m`` above the floor, nearer than ``max_forward_m``, on the floor grid.

    :func:`extract_samples` applies it itself; a caller may apply it first to transform only
    these points (the floor, most of a frame, is not needed): the samples are the same.
    """
    p = params
    nx, ny = grid_size(p)
    gx = (x - p.x_range_m[0]) / p.grid_m  # the cell index is floor(gx): inside ⇔ 0 ≤ gx < nx
    gy = (y - p.y_range_m[0]) / p.grid_m
    return ((z > p.min_z_m) & (z < p.max_z_m) & (x < p.max_forward_m)
            & (gx >= 0) & (gx < nx) & (gy >= 0) & (gy < ny))


def extract_samples(points_floor: np.ndarray, rows: np.ndarray | None = None,
                    image_height: int | None = None, cols: np.ndarray | None = None,
                    image_width: int | None = None,
                    params: SampleParams = SampleParams(),
                    camera_xy=None, *, in_region: bool = False) -> tuple[list[FurnitureSample], dict]:
    """Split a floor-frame cloud into furniture samples.

    ``in_region``: the caller kept only the points of :func:`sample_region` (the frame does),
    so the test is not made again.

    ``rows``/``cols`` give each point's image row/column (or None) to clear columns that run
    out of the top of the view and to flag samples cut by the image sides; with them and
    ``camera_xy`` (the camera's floor-frame position) a wall is also followed down its image
    columns (:func:`wall_continuation`). Returns the samples and counts of what was dropped and
    why.
    """
    from scipy import ndimage

    p = params
    stats = {"points": int(len(points_floor)), "dropped_tall": 0, "dropped_small": 0,
             "dropped_wall": 0, "cleared_cells": 0}
    if len(points_floor) == 0:
        return [], stats
    pts, r, c = points_floor, rows, cols
    inside = None if in_region else sample_region(points_floor[:, 0], points_floor[:, 1],
                                                  points_floor[:, 2], p)
    if inside is not None and not inside.all():
        pts = np.compress(inside, points_floor, axis=0)  # = points_floor[inside], faster
        r = np.compress(inside, rows) if rows is not None else None
        c = np.compress(inside, cols) if cols is not None else None
    nx, ny = grid_size(p)
    ix = np.floor((pts[:, 0] - p.x_range_m[0]) / p.grid_m).astype(int)
    iy = np.floor((pts[:, 1] - p.y_range_m[0]) / p.grid_m).astype(int)
    stats["kept_points"] = int(len(pts))
    if len(pts) == 0:
        return [], stats
    flat = iy * nx + ix
    occupied = np.zeros(nx * ny, dtype=bool)
    occupied[flat] = True
    pts, r, c, flat, occupied = _clear_columns(pts, r, c, flat, occupied, image_height, camera_xy,
                                               (ny, nx), p, stats)
    grid = occupied.reshape(ny, nx)
    labels, count = ndimage.label(grid, structure=np.ones((3, 3), dtype=int))
    if p.split_min_area_m2 is not None and count:
        labels, count, stats["split"] = split_joined_items(labels, count, p)
    samples: list[FurnitureSample] = []
    if count == 0:
        return samples, stats
    cell_counts = np.bincount(labels.reshape(-1), minlength=count + 1)
    big = cell_counts * p.grid_m ** 2 >= p.min_area_m2 - 1e-9
    big[0] = False
    stats["dropped_small"] = int(count - np.count_nonzero(big))
    wanted = np.flatnonzero(big)
    if len(wanted) == 0:
        return samples, stats
    # only the points of furniture-sized components are grouped (the small ones are most of
    # the labels and need no points); a stable sort keeps each sample's points in cloud order
    point_label = labels.reshape(-1)[flat]
    mine = np.flatnonzero(big[point_label])
    order = mine[np.argsort(point_label[mine], kind="stable")]
    bounds = np.searchsorted(point_label[order], np.append(wanted, wanted[-1] + 1))
    for k, lab in enumerate(wanted):
        idx = order[bounds[k]:bounds[k + 1]]
        sp = pts.take(idx, axis=0)
        height = float(sp[:, 2].max())
        if height > p.max_height_m:
            stats["dropped_tall"] += 1
            continue
        if _is_wall_piece(sp, p):
            stats["dropped_wall"] += 1
            continue
        touches = _touches_border(None if r is None else r[idx], None if c is None else c[idx],
                                  image_height, image_width)
        samples.append(_sample(sp, np.argwhere(labels == lab), height, touches, p))
    return samples, stats


def _clear_columns(pts, r, c, flat, occupied, image_height, camera_xy, shape, p: SampleParams, stats: dict):
    """Clear the grid cells of columns that are not furniture: points above furniture height
    (walls, wardrobes), columns running out of the top of the view, and a wall followed down
    its image columns (:func:`wall_continuation`). Returns ``(points, rows, cols, flat cell
    index, occupied)`` without the wall's points; counts go to ``stats``."""
    ny, nx = shape
    clear = pts[:, 2] > p.max_height_m  # columns rising above furniture height: walls, wardrobes
    if r is not None and image_height:
        clear |= r < max(2.0, p.top_rows_fraction * image_height)  # columns leaving the view
    if clear.any():
        cleared = np.zeros(nx * ny, dtype=bool)
        cleared[flat[clear]] = True
        if p.wall_remains_top_m is not None:
            cleared = _with_wall_remains(cleared, occupied, flat, pts[:, 2], (ny, nx),
                                         p.wall_remains_top_m)
        if (p.wall_trace_band_m is not None and r is not None and c is not None
                and camera_xy is not None):
            # the wall: the clear points and, in cleared cells, what is above furniture height
            top = p.wall_remains_top_m if p.wall_remains_top_m is not None else p.max_height_m
            wall = wall_continuation(pts, r, c, clear | (cleared[flat] & (pts[:, 2] > top)),
                                     camera_xy, p.wall_trace_band_m)
            stats["wall_points"] = int(np.count_nonzero(wall))
            if stats["wall_points"]:
                keep = ~wall
                pts, r, c = np.compress(keep, pts, axis=0), r[keep], c[keep]
                flat = flat[keep]
                occupied = np.zeros(nx * ny, dtype=bool)
                occupied[flat] = True
        stats["cleared_cells"] = int(np.count_nonzero(cleared))
        occupied[cleared] = False
    return pts, r, c, flat, occupied


def _touches_border(rows, cols, image_height: int | None, image_width: int | None) -> bool:
    """Whether a sample's pixels reach the image's sides or bottom (it is cut by the view)."""
    touches = False
    if cols is not None and image_width:
        margin = max(3.0, 0.01 * image_width)
        touches = bool((cols.min() < margin) or (cols.max() > image_width - 1 - margin))
    if rows is not None and image_height:
        touches = touches or bool(rows.max() > image_height - 1 - max(3.0, 0.01 * image_height))
    return touches


def _sample(points: np.ndarray, cells: np.ndarray, height_m: float, touches: bool,
            p: SampleParams) -> FurnitureSample:
    """One furniture sample: its points voxel-downsampled, its floor cells (``(iy, ix)`` of the
    sample grid) as floor-frame centres in metres."""
    import open3d as o3d

    cells_xy = np.stack([p.x_range_m[0] + (cells[:, 1] + 0.5) * p.grid_m,
                         p.y_range_m[0] + (cells[:, 0] + 0.5) * p.grid_m], axis=1)
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    down = np.asarray(cloud.voxel_down_sample(p.voxel_m).points)
    return FurnitureSample(down, cells_xy, height_m, touches,
                           info={"raw_points": int(len(points)), "cells": int(len(cells))})


#: cell size (metres) on which :func:`split_joined_items` judges a component's shape
SHAPE_CELL_M = 0.1
#: directions of the cuts :func:`split_joined_items` tries (radians)
CUT_ANGLES = FILL_ANGLES


def _best_cut(cells: np.ndarray, min_cells: float, candidates: int = 12, min_aspect: float = 1.8,
              min_crossing: float = np.radians(45.0)) -> tuple[float, np.ndarray | None, float]:
    """(score, normal, offset): the straight cut of ``cells`` (K, 2, cell units) — a line
    ``x · normal = offset`` — after which both parts fill their own best rectangles best,
    ``score`` being the poorer part's fill; parts smaller than ``min_cells`` are not allowed. All cuts of one direction
    are scored at once, by the parts' rectangles aligned with the cut (running minima and
    maxima along the sorted cells); the ``candidates`` best are scored again with each part's
    own best rectangle (an arm of a V is not aligned with the cut along the other arm), and
    only cuts into two long parts (``min_aspect``) whose long sides cross at ``min_crossing`` or
    more count: two couches in an L, or a couch and a bench at its end, not a bed and its
    headboard or a desk and its chair."""
    n = len(cells)
    pool = []
    for angle in CUT_ANGLES:
        normal = np.array([-np.sin(angle), np.cos(angle)])
        tangent = np.array([np.cos(angle), np.sin(angle)])
        along, across = cells @ normal, cells @ tangent
        order = np.argsort(along, kind="stable")
        al, ac = along[order], across[order]
        # a cut after the i-th cell (only between distinct positions along the normal)
        i = np.flatnonzero(np.diff(al) > 0.5) + 1
        i = i[(i >= min_cells) & (n - i >= min_cells)]
        if len(i) == 0:
            continue
        lo_a, hi_a = np.minimum.accumulate(ac), np.maximum.accumulate(ac)
        lo_b, hi_b = np.minimum.accumulate(ac[::-1])[::-1], np.maximum.accumulate(ac[::-1])[::-1]
        fill_a = i / ((al[i - 1] - al[0] + 1.0) * (hi_a[i - 1] - lo_a[i - 1] + 1.0))
        fill_b = (n - i) / ((al[-1] - al[i] + 1.0) * (hi_b[i] - lo_b[i] + 1.0))
        score = np.minimum(fill_a, fill_b)
        for k in np.argsort(-score)[:3]:
            pool.append((float(score[k]), normal, float((al[i[k] - 1] + al[i[k]]) / 2)))
    best = (-1.0, None, 0.0)
    for _, normal, offset in sorted(pool, key=lambda c: -c[0])[:candidates]:
        side = cells @ normal > offset
        (fa, angle_a, aspect_a), (fb, angle_b, aspect_b) = rectangle_fill(cells[side]), rectangle_fill(cells[~side])
        crossing = abs(((angle_a - angle_b) + np.pi / 2) % np.pi - np.pi / 2)
        if min(aspect_a, aspect_b) < min_aspect or crossing < min_crossing:
            continue  # not two long items at an angle (a bed cut at its headboard, a desk and its chair)
        score = min(fa, fb)
        if score > best[0]:
            best = (score, normal, offset)
    return best


def split_joined_items(labels: np.ndarray, count: int, p: SampleParams = SampleParams()
                       ) -> tuple[np.ndarray, int, int]:
    """Split components that are two long items touching at an angle (an L of two couches, a
    bench across a bed's foot) into two.

    One piece of furniture covers a nearly rectangular patch of floor from any view; two
    long pieces at an angle cover an L, a V or a T, which fills its best rectangle poorly. For a
    component of at least ``split_min_area_m2`` that fills less than ``split_max_fill`` of
    its best rectangle, every straight cut (:data:`CUT_ANGLES`, every 0.1 m across) is scored
    by how well its two parts fill their own rectangles; the best is kept when both parts fill
    at least ``split_min_part_fill`` and ``split_min_gain`` more than the whole, and both cover
    ``split_min_part_m2``. Shapes are judged on 0.1 m cells (:data:`SHAPE_CELL_M`), the
    component closed over one cell with its holes filled: far surfaces are read every few
    cells (stripes), and the shape, not the sampling, decides. Returns the new labels, the new
    label count and how many components were split."""
    from scipy import ndimage

    cell_area = p.grid_m ** 2
    sizes = np.bincount(labels.reshape(-1), minlength=count + 1)
    min_cells = p.split_min_part_m2 / SHAPE_CELL_M ** 2
    split = 0
    out = labels
    for lab in np.flatnonzero(sizes * cell_area >= p.split_min_area_m2):
        if lab == 0:
            continue
        own = np.argwhere(labels == lab)  # (iy, ix)
        lo = own.min(axis=0)
        k = max(1, int(round(SHAPE_CELL_M / p.grid_m)))
        coarse = (own - lo) // k
        box = np.zeros(tuple(coarse.max(axis=0) + 3), dtype=bool)
        box[coarse[:, 0] + 1, coarse[:, 1] + 1] = True
        box = ndimage.binary_fill_holes(ndimage.binary_closing(box, np.ones((3, 3), dtype=bool)))
        cells = np.argwhere(box).astype(float)
        whole = rectangle_fill(cells)[0]
        if whole >= p.split_max_fill:
            continue  # one rectangle: no cut to look for (most components)
        score, normal, offset = _best_cut(cells, min_cells)
        if normal is None or score < max(p.split_min_part_fill, whole + p.split_min_gain):
            continue
        if out is labels:
            out = labels.copy()
        # the component's own cells on one side of the cut go to the new part
        far = own[((own - lo) / k + 1) @ normal > offset]
        mask = np.zeros(labels.shape, dtype=bool)
        mask[far[:, 0], far[:, 1]] = True
        # the cut-off part may fall apart along the cut: each of its pieces gets a label
        pieces, n = ndimage.label(mask, structure=np.ones((3, 3), dtype=int))
        for j in range(1, n + 1):
            count += 1
            out[pieces == j] = count
        split += 1
    return out, count, split


def wall_continuation(points: np.ndarray, rows: np.ndarray, cols: np.ndarray, wall: np.ndarray,
                      camera_xy, band_m: float = 0.025, steep: float = 0.5, reach: int = 3
                      ) -> np.ndarray:
    """Mask of the points that continue a wall (``wall``: points known to be on one) down its
    image columns; the ``wall`` points themselves are not in it.

    A wall is vertical, so at one image column its lower part stands at the same horizontal
    range from the camera as its upper part. Each column is read downwards over its readings;
    a step from a wall reading to one at most ``reach`` readings further down (so a noisy
    reading, a missing stretch or a picture on the wall is passed) stays on the wall when the
    lower reading is lower and either farther (back on the wall below something hanging on
    it) or nearer by less than ``band_m`` — half a floor cell, which the grid cannot tell from
    the wall — while dropping by more than ``steep`` times that (a surface steeper than ~63°).
    What stands in front of the wall (a backrest's, headboard's or table's top) is a step
    nearer than that, the floor and other horizontal surfaces a step that does not drop:
    there the wall ends.

    Measured on the Kinect v2 living-room frame (``docs/perception.md``): with the floor found
    from the frame, its walls lean ~2° and their lower parts (0.7–1.15 m) fell into the cells
    next to the cleared ones, below the 1.2 m of the remains rule, and stood like a headboard
    along the back of the L-shaped couch. Computed on the column-sorted readings as runs:
    a run is a stretch of readings with every gap between neighbours spanned by an accepted
    step; a reading is wall when it has an accepted step and its run holds a ``wall`` point.
    """
    out = np.zeros(len(points), dtype=bool)
    if len(points) < 2 or not wall.any():
        return out
    col = np.rint(cols).astype(np.int64)
    order, cs = _column_order(col, rows)
    n = len(order)
    z = points[:, 2].take(order)
    rng = np.hypot(points[:, 0] - camera_xy[0], points[:, 1] - camera_xy[1]).take(order)
    spanned = np.zeros(n, dtype=bool)  # spanned[g]: an accepted step crosses the gap g-1 | g
    linked = np.zeros(n, dtype=bool)
    for k in range(1, reach + 1):
        drop = z[:-k] - z[k:]
        move = rng[k:] - rng[:-k]  # > 0: the lower reading is farther
        # lower, not nearer by band_m or more, and dropping by more than steep × any nearing
        # (a step to a farther reading always does: then any drop will do)
        ok = (cs[:-k] == cs[k:]) & (move > -band_m) & (drop > 0) & (drop + steep * move > 0)
        linked[:-k] |= ok
        linked[k:] |= ok
        for j in range(1, k + 1):  # the step from a to a + k crosses the gaps a+1 … a+k
            spanned[j:n - k + j] |= ok
    run = np.cumsum(~spanned)
    known = wall.take(order)
    on_wall = np.zeros(int(run[-1]) + 1, dtype=bool)
    on_wall[run[known]] = True
    out[order] = on_wall[run] & linked & ~known
    return out


def _column_order(col: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.lexsort((rows, col))`` (readings by image column, then row, then index) and the
    sorted columns. A frame's cloud is in image order, so a stable sort by column alone gives
    that order unless some column's rows then decrease somewhere (its rows are computed back
    from the points, so they can be out of order by a rounding): checked, and only then the
    lexsort. Columns are sorted as 16-bit integers, for which numpy's stable sort is a radix
    sort (~2× faster)."""
    key = col.astype(np.int16) if len(col) and -32768 <= col.min() and col.max() < 32768 else col
    order = np.argsort(key, kind="stable")
    cs = col.take(order)
    r = rows.take(order)
    if np.any((cs[1:] == cs[:-1]) & (r[1:] < r[:-1])):
        order = np.lexsort((rows, col))
        cs = col.take(order)
    return order, cs


def _with_wall_remains(cleared: np.ndarray, occupied: np.ndarray, flat: np.ndarray,
                       z: np.ndarray, shape: tuple[int, int], top_m: float, rings: int = 2
                       ) -> np.ndarray:
    """``cleared`` (flat cell mask) grown over the occupied cells whose highest point is above
    ``top_m`` and that touch a cleared cell, directly or through other such cells, at most
    ``rings`` cells (8-neighbour) away from it.

    A wall's columns are cleared where they rise above furniture height or leave the top of the
    view, but sensor noise spreads a wall over two 0.05 m cells, and the wall under the top
    rows stays: these remains, up to 1.6 m high, joined a table or bed standing against the
    wall and made its sample look like a chair (Table 3-9 scene 13). Furniture is at most
    about 1.1 m high (the catalogue and the other-instance models). Growing without a limit
    ate the tall part of deep shelves next to a wall (NYU basement), and their low remains were
    read as beds; two rings (0.1 m) hold a wall's noise.
    """
    from scipy import ndimage

    # the cells whose highest point is above top_m: those holding any point above it
    above = np.zeros(len(cleared), dtype=bool)
    above[flat[z > top_m]] = True
    tall = occupied & ~cleared & above
    if not tall.any():
        return cleared
    grown = ndimage.binary_dilation(cleared.reshape(shape), structure=np.ones((3, 3), dtype=bool),
                                    iterations=rings, mask=(cleared | tall).reshape(shape))
    return grown.reshape(-1)


def centred_xy(points: np.ndarray, centre: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """``(points[:, :2] - centre, centre)``, ``centre`` by default ``points[:, :2].mean(axis=0)``
    — bit for bit, column by column. numpy reduces and broadcasts an (N, 2) array two values at
    a time, N times over (~10–20× slower than a column on this machine); its axis-0 mean adds
    the rows in order, which is a column's cumulative sum's last value (not the column's own
    pairwise sum). Returns a new C-ordered (N, 2) array, as the subtraction did."""
    x, y = points[:, 0], points[:, 1]
    if centre is None:
        centre = np.array([np.cumsum(x)[-1], np.cumsum(y)[-1]]) / len(x)
    xy = np.empty((len(x), 2))
    np.subtract(x, centre[0], out=xy[:, 0])
    np.subtract(y, centre[1], out=xy[:, 1])
    return xy, centre


def _is_wall_piece(points: np.ndarray, p: SampleParams) -> bool:
    """A thin, long vertical sheet reaching above 1.2 m: a piece of wall, not furniture.

    Cheapest first: a sample whose highest point is not above 1.2 m (its 98th percentile cannot
    be) or whose floor-plan bounding box has a diagonal no longer than ``wall_length_m`` (no
    extent along any axis can be longer) is not a wall piece — most furniture samples, decided
    without the principal axes; then the thickness across the principal axis, and the
    percentiles only for the thin samples that can still be walls.
    """
    if len(points) < 10:
        return False
    if not points[:, 2].max() > 1.2 - 1e-9:  # (margins: rounding in the tests below)
        return False
    x, y = points[:, 0], points[:, 1]  # column by column (see centred_xy)
    if not math.hypot(x.max() - x.min(), y.max() - y.min()) > p.wall_length_m - 1e-9:
        return False
    xy, _ = centred_xy(points)
    a, b = xy[:, 0], xy[:, 1]
    ab = a @ b
    cov = np.array([[a @ a, ab], [ab, b @ b]]) / (len(xy) - 1)  # np.cov of the centred points
    evals, evecs = np.linalg.eigh(cov)
    minor = np.sqrt(max(evals[0], 0.0))
    if not minor < p.wall_thickness_m:
        return False
    if not float(np.percentile(points[:, 2], 98)) > 1.2:
        return False
    along = xy @ evecs[:, 1]
    lo, hi = np.percentile(along, [1, 99])
    return float(hi - lo) > p.wall_length_m

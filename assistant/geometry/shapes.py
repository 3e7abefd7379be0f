"""Footprints of things on the floor as polygons (metres, world frame)."""

from __future__ import annotations

import math

import numpy as np

from assistant.geometry.pose import Pose2D


def rectangle(pose: Pose2D, length_m: float, width_m: float) -> np.ndarray:
    """Corners (4, 2) of a rectangle centred on ``pose``, ``length_m`` along its heading."""
    hl, hw = length_m / 2.0, width_m / 2.0
    local = np.array([[hl, hw], [-hl, hw], [-hl, -hw], [hl, -hw]])
    return pose.transform_points(local)


def regular_polygon(pose: Pose2D, circumradius_m: float, sides: int) -> np.ndarray:
    """Corners (sides, 2) of a regular polygon centred on ``pose`` (first vertex on its heading)."""
    angles = np.arange(sides) * 2.0 * math.pi / sides
    local = circumradius_m * np.stack([np.cos(angles), np.sin(angles)], axis=1)
    return pose.transform_points(local)


def ellipse(pose: Pose2D, length_m: float, width_m: float, segments: int = 32) -> np.ndarray:
    """A polygon (segments, 2) approximating the ellipse inscribed in ``length_m × width_m``."""
    angles = np.arange(segments) * 2.0 * math.pi / segments
    local = np.stack([length_m / 2 * np.cos(angles), width_m / 2 * np.sin(angles)], axis=1)
    return pose.transform_points(local)


def box_polygon(xmin: float, ymin: float, xmax: float, ymax: float) -> np.ndarray:
    """Corners (4, 2) of an axis-aligned box, counter-clockwise."""
    return np.array([[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]], dtype=float)


def point_in_polygon(points_xy: np.ndarray, polygon_xy: np.ndarray) -> np.ndarray:
    """Even-odd test of (N, 2) points against a simple polygon; returns a boolean array."""
    from matplotlib.path import Path as _Path  # noqa: PLC0415 - only when needed

    return _Path(np.asarray(polygon_xy, dtype=float)).contains_points(
        np.asarray(points_xy, dtype=float).reshape(-1, 2)
    )


def polygon_area(polygon_xy: np.ndarray) -> float:
    """Area (m²) of a simple polygon by the shoelace formula."""
    p = np.asarray(polygon_xy, dtype=float)
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


#: directions (radians) over which :func:`rectangle_fill` looks for the best rectangle
FILL_ANGLES = np.radians(np.arange(0.0, 180.0, 15.0))
_FILL_AXES = np.stack([np.cos(FILL_ANGLES), np.sin(FILL_ANGLES)])  # (2, angles)
_FILL_NORMALS = np.stack([-np.sin(FILL_ANGLES), np.cos(FILL_ANGLES)])


def rectangle_fill(cells: np.ndarray) -> tuple[float, float, float]:
    """(fill, long-axis angle, aspect) of the best-fitting rectangle of a set of grid cells
    (K, 2, in cell units) over :data:`FILL_ANGLES`: the share of the rectangle they cover, the
    direction (radians, mod π) of its longer side, and longer over shorter side. One piece of
    furniture covers most of its rectangle (0.8–1); two at an angle, an L, about half."""
    cells = np.asarray(cells, dtype=float).reshape(-1, 2)
    if len(cells) == 0:
        return 0.0, 0.0, 1.0
    u, v = cells @ _FILL_AXES, cells @ _FILL_NORMALS  # (K, angles): every direction at once
    # extents per direction from the transposed copies: numpy reduces an (K, 12) array's
    # columns 12 values at a time, K times over (3–5× slower for a few hundred cells)
    lu = np.ptp(np.ascontiguousarray(u.T), axis=1) + 1.0
    lv = np.ptp(np.ascontiguousarray(v.T), axis=1) + 1.0
    fills = len(cells) / (lu * lv)
    k = int(np.argmax(fills))
    angle = FILL_ANGLES[k] if lu[k] >= lv[k] else FILL_ANGLES[k] + np.pi / 2
    return float(fills[k]), float(angle % np.pi), float(max(lu[k], lv[k]) / min(lu[k], lv[k]))


def polygon_lattice(polygon_xy: np.ndarray, step_m: float, offset_m: float | None = None) -> np.ndarray:
    """Points (N, 2) of a square lattice of ``step_m`` inside a polygon (metres): x and y run
    from the polygon's bounding-box corner plus ``offset_m`` (default half a step) in steps up
    to its far side, and the points outside the polygon are left out."""
    poly = np.asarray(polygon_xy, dtype=float)
    lo, hi = poly.min(axis=0), poly.max(axis=0)
    offset = step_m / 2 if offset_m is None else offset_m
    xs, ys = np.meshgrid(np.arange(lo[0] + offset, hi[0], step_m), np.arange(lo[1] + offset, hi[1], step_m))
    pts = np.column_stack([xs.ravel(), ys.ravel()])
    return pts[point_in_polygon(pts, poly)]

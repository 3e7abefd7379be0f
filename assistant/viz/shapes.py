"""Triangle meshes the scene view draws, as plain arrays (metres, world frame, z up).

Every builder returns ``(vertices (N, 3) float, faces (M, 3) int)`` — or with per-vertex
colours ``(vertices, faces, colours (N, 3) in 0–1)`` — ready for
``meshcat.geometry.TriangularMeshGeometry``. Nothing here talks to meshcat, so these are
tested on their own.
"""

from __future__ import annotations

import numpy as np

from assistant.errors import AssistantError
from assistant.geometry import Pose2D

__all__ = [
    "arrows_mesh", "as_pose", "cells_mesh", "mesh_arrays", "polygon_area", "poses_array",
    "prism_outline", "ribbon_mesh", "slab_mesh", "triangulate_polygon",
]


def polygon_area(polygon_xy: np.ndarray) -> float:
    """Signed area (m²) of a polygon: positive when its corners run counter-clockwise."""
    p = np.asarray(polygon_xy, dtype=float)
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _clean_polygon(polygon_xy) -> np.ndarray:
    """Corners as a counter-clockwise (N, 2) array without a repeated closing corner or
    zero-length edges."""
    p = np.asarray(polygon_xy, dtype=float).reshape(-1, 2)
    keep = [0]
    for i in range(1, len(p)):
        if np.linalg.norm(p[i] - p[keep[-1]]) > 1e-9:
            keep.append(i)
    p = p[keep]
    if len(p) > 1 and np.linalg.norm(p[0] - p[-1]) <= 1e-9:
        p = p[:-1]
    if len(p) < 3 or abs(polygon_area(p)) < 1e-12:
        raise ValueError(f"a polygon needs at least 3 corners enclosing an area, got {p.tolist()}")
    return p if polygon_area(p) > 0 else p[::-1].copy()


def _cross(o: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def triangulate_polygon(polygon_xy) -> tuple[np.ndarray, np.ndarray]:
    """Split a simple polygon (convex or not, either winding) into triangles by ear clipping.

    Returns ``(corners (N, 2) counter-clockwise, triangles (N-2, 3) indices into corners)``.
    Raises ValueError for fewer than three corners or no area.
    """
    p = _clean_polygon(polygon_xy)
    remaining = list(range(len(p)))
    triangles: list[tuple[int, int, int]] = []
    guard = 0
    while len(remaining) > 3 and guard < 10 * len(p) ** 2:
        guard += 1
        n = len(remaining)
        for k in range(n):
            i, j, m = remaining[(k - 1) % n], remaining[k], remaining[(k + 1) % n]
            turn = _cross(p[i], p[j], p[m])
            if turn < -1e-12:
                continue  # reflex corner: not an ear
            if abs(turn) <= 1e-12:  # collinear corner: drop it without a triangle
                remaining.pop(k)
                break
            others = [q for q in remaining if q not in (i, j, m)]
            if any(_cross(p[i], p[j], p[q]) >= 0 and _cross(p[j], p[m], p[q]) >= 0
                   and _cross(p[m], p[i], p[q]) >= 0 for q in others):
                continue  # another corner lies inside: not an ear
            triangles.append((i, j, m))
            remaining.pop(k)
            break
        else:  # no ear found (self-intersecting input): fan the rest so something is drawn
            break
    for k in range(1, len(remaining) - 1):
        triangles.append((remaining[0], remaining[k], remaining[k + 1]))
    return p, np.asarray(triangles, dtype=np.int64).reshape(-1, 3)


def slab_mesh(polygon_xy, z_bottom: float, z_top: float) -> tuple[np.ndarray, np.ndarray]:
    """A vertical prism over a floor polygon, from ``z_bottom`` to ``z_top`` metres."""
    corners, tris = triangulate_polygon(polygon_xy)
    n = len(corners)
    bottom = np.column_stack([corners, np.full(n, z_bottom)])
    top = np.column_stack([corners, np.full(n, z_top)])
    vertices = np.vstack([bottom, top])
    faces = [tris[:, ::-1], tris + n]  # bottom faces down, top faces up
    sides = []
    for i in range(n):
        j = (i + 1) % n
        sides += [(i, j, n + j), (i, n + j, n + i)]
    faces.append(np.asarray(sides, dtype=np.int64))
    return vertices, np.vstack(faces)


def ribbon_mesh(points_xy, width_m: float, z: float) -> tuple[np.ndarray, np.ndarray]:
    """A flat band ``width_m`` wide along a polyline at height ``z`` (one quad per segment)."""
    p = np.asarray(points_xy, dtype=float).reshape(-1, 2)
    vertices, faces = [], []
    half = width_m / 2.0
    for a, b in zip(p[:-1], p[1:]):
        d = b - a
        length = float(np.hypot(*d))
        if length < 1e-9:
            continue
        nx, ny = -d[1] / length * half, d[0] / length * half
        base = len(vertices)
        vertices += [(a[0] + nx, a[1] + ny, z), (a[0] - nx, a[1] - ny, z),
                     (b[0] - nx, b[1] - ny, z), (b[0] + nx, b[1] + ny, z)]
        faces += [(base, base + 1, base + 2), (base, base + 2, base + 3)]
    return (np.asarray(vertices, dtype=float).reshape(-1, 3),
            np.asarray(faces, dtype=np.int64).reshape(-1, 3))


def arrows_mesh(poses_xyt, lengths_m, colours, width_m: float = 0.04, z: float = 0.05
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flat arrows lying at height ``z``, one per pose ``(x, y, heading)``.

    Each arrow starts at its pose and points along its heading; ``lengths_m`` (N,) sets how
    long, ``colours`` (N, 3) its colour. The shaft is ``width_m`` wide, the head 2.5 times that.
    """
    poses = np.asarray(poses_xyt, dtype=float).reshape(-1, 3)
    lengths = np.asarray(lengths_m, dtype=float).reshape(-1)
    cols = np.asarray(colours, dtype=float).reshape(-1, 3)
    if not len(poses) == len(lengths) == len(cols):
        raise ValueError(f"{len(poses)} poses, {len(lengths)} lengths and {len(cols)} colours: "
                         "give one of each per arrow")
    # Arrow outline in its own frame (x along the heading), as fractions of length / width.
    shaft, head = 0.62, 1.25  # shaft length fraction; half head width in shaft widths
    local = []
    for length in lengths:
        w = width_m / 2.0
        hw = head * width_m
        neck = shaft * length
        local.append([(0.0, -w), (neck, -w), (neck, w), (0.0, w),  # shaft quad
                      (neck, -hw), (length, 0.0), (neck, hw)])  # head triangle
    local_arr = np.asarray(local, dtype=float)  # (N, 7, 2)
    c, s = np.cos(poses[:, 2])[:, None], np.sin(poses[:, 2])[:, None]
    wx = poses[:, 0:1] + c * local_arr[:, :, 0] - s * local_arr[:, :, 1]
    wy = poses[:, 1:2] + s * local_arr[:, :, 0] + c * local_arr[:, :, 1]
    vertices = np.stack([wx, wy, np.full_like(wx, z)], axis=2).reshape(-1, 3)
    template = np.array([(0, 1, 2), (0, 2, 3), (4, 5, 6)], dtype=np.int64)
    faces = (template[None, :, :] + 7 * np.arange(len(poses))[:, None, None]).reshape(-1, 3)
    vertex_colours = np.repeat(cols, 7, axis=0)
    return vertices, faces, vertex_colours


def cells_mesh(points_xy, cell_m: float, z: float) -> tuple[np.ndarray, np.ndarray]:
    """One flat square of side ``cell_m`` per cell centre (an entity's footprint) at ``z``."""
    p = np.asarray(points_xy, dtype=float).reshape(-1, 2)
    h = cell_m / 2.0
    offsets = np.array([(-h, -h), (h, -h), (h, h), (-h, h)])
    corners = (p[:, None, :] + offsets[None, :, :]).reshape(-1, 2)
    vertices = np.column_stack([corners, np.full(len(corners), z)])
    base = 4 * np.arange(len(p))[:, None, None]
    faces = (np.array([(0, 1, 2), (0, 2, 3)])[None, :, :] + base).reshape(-1, 3)
    return vertices, faces.astype(np.int64)


def mesh_arrays(mesh) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """``(vertices, faces, vertex colours or None)`` of an open3d ``TriangleMesh``."""
    vertices = np.asarray(mesh.vertices, dtype=float)
    faces = np.asarray(mesh.triangles, dtype=np.int64)
    colours = np.asarray(mesh.vertex_colors, dtype=float) if mesh.has_vertex_colors() else None
    return vertices, faces, colours


def as_pose(pose) -> Pose2D:
    """A :class:`Pose2D` from a pose or any (x, y, heading) sequence."""
    if isinstance(pose, Pose2D):
        return pose
    values = tuple(float(v) for v in np.asarray(pose, dtype=float).reshape(-1))
    if len(values) != 3:
        raise AssistantError(f"a pose is (x, y, heading), got {values}")
    return Pose2D(*values)


def poses_array(poses) -> np.ndarray:
    """(N, 3) rows of x, y, heading from an array or a sequence of poses."""
    if isinstance(poses, np.ndarray):
        arr = np.asarray(poses, dtype=float)
    else:
        arr = np.array([as_pose(p).as_tuple() for p in poses], dtype=float)
    if arr.size == 0:
        return np.zeros((0, 3))
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise AssistantError(f"poses must be (N, 3) rows of x, y, heading; got shape {arr.shape}")
    return arr


def prism_outline(polygon_xy, z0: float, z1: float) -> np.ndarray:
    """(M, 3) float32 end points of the line segments outlining a vertical prism over
    ``polygon_xy`` from ``z0`` to ``z1`` (bottom, top and vertical edges)."""
    corners, _ = triangulate_polygon(polygon_xy)
    n = len(corners)
    edges = []
    for i in range(n):
        j = (i + 1) % n
        edges += [(*corners[i], z0), (*corners[j], z0), (*corners[i], z1), (*corners[j], z1),
                  (*corners[i], z0), (*corners[i], z1)]
    return np.asarray(edges, dtype=np.float32)

"""Depth frames as coloured world-frame point clouds, for the scene view."""

from __future__ import annotations

import numpy as np

from assistant.errors import AssistantError
from assistant.viz.colours import to_rgb

__all__ = ["HIT_COLOURS", "cloud_arrays", "depth_frame_points"]

#: Colours (0–1) of simulated hits by kind, for ``colour_by="hit"``.
HIT_COLOURS = {
    "floor": (0.6, 0.6, 0.6),
    "wall": (0.95, 0.95, 0.9),
    "furniture": (0.2, 0.6, 1.0),
    "object": (1.0, 0.3, 0.2),
}


def _hit_kind(hit_name: str) -> str:
    """The kind of a simulated hit id: ``floor``, ``wall_3`` → wall, an object name → object,
    anything else furniture."""
    if hit_name == "floor":
        return "floor"
    if hit_name.startswith("wall_"):
        return "wall"
    from assistant.world import load_catalogue

    return "object" if hit_name in load_catalogue().objects else "furniture"


def depth_frame_points(frame, stride: int = 2, max_range_m: float = 6.0,
                       colour_by: str = "height", camera_to_world: np.ndarray | None = None
                       ) -> tuple[np.ndarray, np.ndarray]:
    """``(points (N, 3), colours (N, 3) in 0–1)`` of a :class:`~assistant.robot.frames.DepthFrame`.

    The image is back-projected with its intrinsics (every ``stride``-th pixel, readings up
    to ``max_range_m``; :func:`assistant.perception.cloud.depth_to_points`) and placed by its
    camera mount and ``robot_pose`` in the world frame (a frame with no pose: the floor under
    the camera at the origin) — or by ``camera_to_world`` (4×4) when given, e.g. the floor a
    detector found in a frame of unknown mount. ``colour_by``: ``"height"`` (viridis over 0–2 m) or ``"hit"``
    (simulated frames only: the kind each ray hit, :data:`HIT_COLOURS` — ground truth, for
    looking at, never for perception).
    """
    from assistant.perception.cloud import depth_to_points
    from assistant.robot.frames import camera_to_base_matrix, camera_to_world_matrix

    if colour_by not in ("height", "hit"):
        raise AssistantError(f"colour_by {colour_by!r}: use 'height' or 'hit'")
    if colour_by == "hit" and frame.hit_ids is None:
        raise AssistantError("colour_by='hit' needs a simulated frame (with hit ids); use "
                             "colour_by='height' for recorded frames")
    points_cam, _rows = depth_to_points(frame.depth_m, frame.intrinsics, stride=stride,
                                        max_range_m=max_range_m)
    if camera_to_world is not None:
        matrix = np.asarray(camera_to_world, dtype=float)
    elif frame.robot_pose is None:
        matrix = camera_to_base_matrix(frame.mount)
    else:
        matrix = camera_to_world_matrix(frame.mount, frame.robot_pose)
    points = points_cam @ matrix[:3, :3].T + matrix[:3, 3]
    if colour_by == "hit":
        intr = frame.intrinsics
        u = np.clip(np.round(intr.fx * points_cam[:, 0] / points_cam[:, 2] + intr.cx),
                    0, intr.width - 1).astype(int)
        v = np.clip(np.round(intr.fy * points_cam[:, 1] / points_cam[:, 2] + intr.cy),
                    0, intr.height - 1).astype(int)
        lookup = np.array([(0.8, 0.0, 0.8)]  # index −1 + 1: no hit recorded (magenta)
                          + [HIT_COLOURS[_hit_kind(n)] for n in frame.hit_names])
        colours = lookup[frame.hit_ids[v, u] + 1]
    else:
        from matplotlib import colormaps

        colours = colormaps["viridis"](np.clip(points[:, 2] / 2.0, 0.0, 1.0))[:, :3]
    return points, colours.reshape(-1, 3)


def cloud_arrays(points_xyz, colors=None, max_points: int = 150_000) -> tuple[np.ndarray, np.ndarray]:
    """``(points (N, 3), colours (N, 3) floats in 0–1)`` ready to draw, from user input.

    ``colors``: None (one default colour), one colour (see :mod:`assistant.viz.colours`), or
    per point (N, 3) floats in 0–1 or uint8 0–255. Points that are not finite are dropped;
    beyond ``max_points`` an evenly spaced subset is kept. Bad shapes or ranges raise
    :class:`~assistant.errors.AssistantError` saying what to give instead.
    """
    pts = np.asarray(points_xyz, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise AssistantError(f"points must be an (N, 3) array of x, y, z; got shape {pts.shape}")
    keep = np.isfinite(pts).all(axis=1)
    per_point = colors is not None and np.ndim(colors) == 2
    if per_point:
        cols = np.asarray(colors)
        if cols.shape != pts.shape:
            raise AssistantError(f"{len(pts)} points but colours of shape {cols.shape}; give "
                                 "one (r, g, b) row per point")
        if np.issubdtype(cols.dtype, np.integer):
            cols = cols.astype(float) / 255.0  # 0–255 per channel
        cols = cols.astype(float)
        if len(cols) and not (np.nanmin(cols) >= 0.0 and np.nanmax(cols) <= 1.0):
            raise AssistantError("per-point colours must be floats in 0–1 or integers in "
                                 "0–255")
        cols = cols[keep]
    pts = pts[keep]
    if len(pts) > max_points:
        index = np.linspace(0, len(pts) - 1, max_points).round().astype(int)
        pts = pts[index]
        if per_point:
            cols = cols[index]
    if not per_point:
        cols = np.tile(to_rgb("cyan" if colors is None else colors), (len(pts), 1))
    return pts, cols

"""Depth frames as coloured world-frame point clouds, for the scene view."""

from __future__ import annotations

import numpy as np

from assistant.errors import AssistantError

__all__ = ["HIT_COLOURS", "depth_frame_points"]

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
                       colour_by: str = "height") -> tuple[np.ndarray, np.ndarray]:
    """``(points (N, 3), colours (N, 3) in 0–1)`` of a :class:`~assistant.robot.frames.DepthFrame`.

    The image is back-projected with its intrinsics (every ``stride``-th pixel, readings up
    to ``max_range_m``; :func:`assistant.perception.cloud.depth_to_points`) and placed by its
    camera mount and ``robot_pose`` in the world frame (a frame with no pose: the floor under
    the camera at the origin). ``colour_by``: ``"height"`` (viridis over 0–2 m) or ``"hit"``
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
    matrix = (camera_to_base_matrix(frame.mount) if frame.robot_pose is None
              else camera_to_world_matrix(frame.mount, frame.robot_pose))
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

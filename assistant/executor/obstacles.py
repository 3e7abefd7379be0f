"""Obstacles seen in depth frames: a floor grid of cells where something stands.

The dissertation's robot avoided obstacles by range sensing (4.3 II.D: "basic obstacle avoidance
by range sensing (e.g., sonar)") while its perception recognised furniture. This is that range
layer for a depth camera: every depth point between ``min_height_m`` and ``max_height_m`` above
the floor and within ``max_range_m`` counts for the floor cell under it; a cell with at least
``min_points`` points (over all frames so far) is an obstacle, so a lone noisy pixel is not. It knows nothing of categories — it only keeps the robot off
things — and it is what the executor can plan around before (or besides) furniture perception.

:meth:`DepthObstacles.occupancy` gives the planner's :class:`OccupancyMap` (floor plan +
perceived entities + seen obstacles), rebuilt only after new obstacle cells appear, so it can be
handed to :class:`~assistant.executor.navigation.Navigator` as its occupancy function. Frames
arrive through :meth:`add_frame` (e.g. as a listener of the
:class:`~assistant.executor.localization.FloorplanLocalizer`, which takes frames as the robot
drives, or from :meth:`~assistant.executor.navigation.Navigator.look_around`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from assistant.executor.planning import DEFAULT_RESOLUTION_M, OccupancyMap, build_occupancy
from assistant.geometry import Pose2D
from assistant.robot.frames import DepthFrame, camera_to_base_matrix, pixel_rays
from assistant.world import Entity, EntityKind, World, world_grid


@dataclass
class DepthObstacles:
    """Obstacle cells accumulated from depth frames (world frame, ``resolution_m`` cells).

    ``entities`` is a function returning the perceived entities to plan around as well (empty by
    default; e.g. ``EnvironmentModel.furniture``), so the occupancy always combines the latest
    perception with what depth has shown.
    """

    world: World
    resolution_m: float = DEFAULT_RESOLUTION_M
    min_height_m: float = 0.10  # above floor noise
    max_height_m: float = 1.9  # below a 2 m door frame's top
    max_range_m: float = 3.5
    stride: int = 4
    min_points: int = 3
    entities: Callable[[], Sequence[Entity]] = field(default=lambda: ())

    def __post_init__(self) -> None:
        self.grid = world_grid(self.world, self.resolution_m, margin_m=0.5)
        self.hits = np.zeros(self.grid.shape, dtype=np.int32)
        self._cached: OccupancyMap | None = None
        self._cached_key: tuple | None = None
        self._rays = None
        self.frames = 0

    def add_frame(self, frame: DepthFrame, pose: Pose2D | None = None) -> int:
        """Mark the cells under this frame's obstacle points; ``pose`` is the robot's world pose
        at capture (default: the frame's own, i.e. odometry). Returns how many cells became
        obstacles."""
        pose = pose if pose is not None else frame.robot_pose
        if pose is None:
            raise ValueError("a depth frame without the robot's pose cannot be placed on the map")
        if self._rays is None or self._rays[0] != frame.intrinsics:
            self._rays = (frame.intrinsics, pixel_rays(frame.intrinsics)[::self.stride, ::self.stride])
        depth = frame.depth_m[::self.stride, ::self.stride]
        valid = np.isfinite(depth) & (depth > 0)
        cam = self._rays[1][valid] * depth[valid][:, None]
        m = camera_to_base_matrix(frame.mount)
        base = cam @ m[:3, :3].T + m[:3, 3]
        keep = ((base[:, 2] >= self.min_height_m) & (base[:, 2] <= self.max_height_m)
                & (np.hypot(base[:, 0], base[:, 1]) <= self.max_range_m))
        cells = self.grid.world_to_cell(pose.transform_points(base[keep, :2]))
        cells = cells[self.grid.contains_cells(cells)]
        before = self.mask()
        np.add.at(self.hits, (cells[:, 0], cells[:, 1]), 1)
        self.frames += 1
        return int((self.mask() & ~before).sum())

    def mask(self) -> np.ndarray:
        """Boolean obstacle cells (at least ``min_points`` points seen over them)."""
        return self.hits >= self.min_points

    def entity(self) -> Entity:
        """The obstacle cells as one short-term entity named ``obstacle``."""
        return Entity.from_mask("depth_obstacles", "obstacle", EntityKind.SHORT_TERM, self.mask(), self.grid)

    def occupancy(self) -> OccupancyMap:
        """Floor plan + perceived entities + seen obstacles (rebuilt only when one changed)."""
        perceived = tuple(self.entities())
        mask = self.mask()
        # by content, not identity: an environment model may hand out new Entity objects each call
        key = (hash(mask.tobytes()),
               tuple((e.id, e.grid, hash(np.ascontiguousarray(e.cells).tobytes())) for e in perceived))
        if self._cached is None or key != self._cached_key:
            self._cached = build_occupancy(self.world, [*perceived, self.entity()], grid=self.grid)
            self._cached_key = key
        return self._cached

"""Where the robot's centre may stand, from an environment model (walls, furniture, rooms)."""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from assistant.geometry import GridMap
from assistant.policy.demonstration import EnvironmentEntity, environment_grid


class FreeSpace:
    """Clearance of every cell of a grid to the nearest wall or piece of furniture (metres);
    floor outside every room counts as an obstacle. ``is_free(x, y, inflate_m)``: the robot's
    centre at ``(x, y)`` keeps ``inflate_m`` from every obstacle (0.25 m = the robot's radius)."""

    def __init__(self, environment: tuple[EnvironmentEntity, ...] | list, resolution_m: float = 0.05,
                 grid: GridMap | None = None):
        self.environment = tuple(environment)
        self.grid = grid or environment_grid(self.environment, resolution_m)
        inside = np.zeros(self.grid.shape, dtype=bool)
        obstacles = np.zeros(self.grid.shape, dtype=bool)
        self.rooms: dict[str, np.ndarray] = {}
        for item in self.environment:
            poly = item.polygon_array()
            if item.id.startswith("room:"):
                inside |= self.grid.rasterize_polygon(poly)
                self.rooms[item.room or item.id[5:]] = poly
            elif item.kind == "short_term" or item.id.startswith("wall:"):
                obstacles |= self.grid.rasterize_polygon(poly)
        if inside.any():
            # door gaps lie between rooms: let a band of a few cells around the rooms count as floor
            inside = ndimage.binary_dilation(inside, iterations=max(1, int(round(0.1 / self.grid.resolution_m))))
            obstacles |= ~inside
        self.obstacles = obstacles
        if obstacles.any():
            d = ndimage.distance_transform_edt(~obstacles, sampling=self.grid.resolution_m)
            self.clearance_m = np.where(obstacles, 0.0, np.maximum(d - self.grid.resolution_m / 2, 0.0))
        else:
            self.clearance_m = np.full(self.grid.shape, np.inf)

        self._reachable: dict[float, np.ndarray] = {}

    def reachable(self, inflate_m: float) -> np.ndarray:
        """Cells with ``inflate_m`` clearance in the largest connected stretch of such floor
        (pockets the robot cannot drive into — behind a chair in a corner — are left out)."""
        key = round(float(inflate_m), 4)
        if key not in self._reachable:
            ok = self.clearance_m >= inflate_m
            labels, n = ndimage.label(ok, structure=np.ones((3, 3), bool))
            if n:
                sizes = np.bincount(labels.ravel())
                sizes[0] = 0
                ok = labels == int(sizes.argmax())
            self._reachable[key] = ok
        return self._reachable[key]

    def reachable_from(self, x: float, y: float, inflate_m: float) -> np.ndarray | None:
        """Cells with ``inflate_m`` clearance connected to ``(x, y)`` (None when that point
        itself lacks the clearance, e.g. a robot pressed against furniture)."""
        cell = self.grid.world_to_cell(np.array([[x, y]]))
        if not self.grid.contains_cells(cell)[0]:
            return None
        ok = self.clearance_m >= inflate_m
        if not ok[cell[0, 0], cell[0, 1]]:
            return None
        labels, _ = ndimage.label(ok, structure=np.ones((3, 3), bool))
        return labels == labels[cell[0, 0], cell[0, 1]]

    def is_reachable(self, x: float, y: float, inflate_m: float = 0.3) -> bool:
        cell = self.grid.world_to_cell(np.array([[x, y]]))
        if not self.grid.contains_cells(cell)[0]:
            return False
        return bool(self.reachable(inflate_m)[cell[0, 0], cell[0, 1]])

    def clearance(self, xy: np.ndarray) -> np.ndarray:
        """Clearance (metres) at (N, 2) world points; 0 off the grid."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        cells = self.grid.world_to_cell(xy)
        ok = self.grid.contains_cells(cells)
        out = np.zeros(len(xy))
        out[ok] = self.clearance_m[cells[ok, 0], cells[ok, 1]]
        return out

    def is_free(self, x: float, y: float, inflate_m: float = 0.25) -> bool:
        return bool(self.clearance(np.array([[x, y]]))[0] >= inflate_m)

    def segment_free(self, a, b, inflate_m: float = 0.25, step_m: float = 0.05) -> bool:
        a, b = np.asarray(a, float)[:2], np.asarray(b, float)[:2]
        n = max(2, int(np.ceil(np.linalg.norm(b - a) / step_m)) + 1)
        pts = a[None] + np.linspace(0, 1, n)[:, None] * (b - a)[None]
        return bool((self.clearance(pts) >= inflate_m).all())

    def room_at(self, x: float, y: float) -> str | None:
        from assistant.geometry import point_in_polygon

        for name, poly in self.rooms.items():
            if point_in_polygon(np.array([[x, y]]), poly)[0]:
                return name
        return None

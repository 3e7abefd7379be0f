"""What the simulated robot can bump into: walls, furniture footprints and the map's edge.

Obstacles are polygons on the floor (metres, world frame): every wall block, every furniture
item's footprint rectangle, and the map's bounding box (the robot may not drive off the map,
e.g. out of the apartment's open hallway end). The robot is a disc; it collides when its
centre is nearer than its radius to an obstacle's edge or inside an obstacle.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assistant.geometry import box_polygon, point_in_polygon
from assistant.world import World

__all__ = ["Obstacles"]


@dataclass(frozen=True, eq=False)
class Obstacles:
    """Obstacle polygons and their edges as segments, for fast disc-versus-world checks.

    ``segments`` is (M, 4) ``x0, y0, x1, y1``; ``owners[i]`` names the obstacle of segment i
    (``wall_<k>``, a furniture id, or ``map edge``).
    """

    polygons: tuple[np.ndarray, ...]
    names: tuple[str, ...]
    segments: np.ndarray
    owners: tuple[str, ...]
    bounds: tuple[float, float, float, float]

    @classmethod
    def from_world(cls, world: World, scene: str = "original") -> "Obstacles":
        polygons: list[np.ndarray] = []
        names: list[str] = []
        for index, wall in enumerate(world.floorplan.walls):
            polygons.append(wall.polygon_array)
            names.append(f"wall_{index}")
        for item in world.scene(scene).furniture:
            polygons.append(np.asarray(item.footprint_polygon(), dtype=float))
            names.append(item.id)
        bounds = tuple(float(b) for b in world.floorplan.bounds())
        segments, owners = [], []
        for name, poly in zip(names, polygons):
            nxt = np.roll(poly, -1, axis=0)
            segments.append(np.hstack([poly, nxt]))
            owners.extend([name] * len(poly))
        edge = box_polygon(*bounds)
        segments.append(np.hstack([edge, np.roll(edge, -1, axis=0)]))
        owners.extend(["map edge"] * 4)
        return cls(tuple(polygons), tuple(names), np.vstack(segments), tuple(owners), bounds)

    def distances(self, x: float, y: float) -> np.ndarray:
        """Distance (metres) from a point to every segment."""
        seg = self.segments
        p0 = seg[:, :2]
        d = seg[:, 2:] - p0
        length2 = np.einsum("ij,ij->i", d, d)
        rel = np.array([x, y]) - p0
        t = np.clip(np.einsum("ij,ij->i", rel, d) / np.maximum(length2, 1e-18), 0.0, 1.0)
        closest = p0 + t[:, None] * d
        return np.hypot(closest[:, 0] - x, closest[:, 1] - y)

    def inside(self, x: float, y: float) -> str | None:
        """The obstacle containing a point (or ``map edge`` when it is off the map), else None."""
        xmin, ymin, xmax, ymax = self.bounds
        if not (xmin <= x <= xmax and ymin <= y <= ymax):
            return "map edge"
        point = np.array([[x, y]])
        for name, poly in zip(self.names, self.polygons):
            if point_in_polygon(point, poly)[0]:
                return name
        return None

    def clearance(self, x: float, y: float) -> tuple[float, str]:
        """Distance (metres) from a point to the nearest obstacle edge and that obstacle's name;
        0 when the point is inside an obstacle or off the map."""
        hit = self.inside(x, y)
        if hit is not None:
            return 0.0, hit
        d = self.distances(x, y)
        i = int(np.argmin(d))
        return float(d[i]), self.owners[i]

    def disc_collides(self, x: float, y: float, radius_m: float, *, edges_only: bool = False) -> str | None:
        """Name of what a disc of ``radius_m`` at (x, y) overlaps, or None when it is free.

        Checks the edges first (cheap): a disc that overlaps no edge is either clear or wholly
        inside an obstacle, which the polygon test then catches. ``edges_only`` skips that test:
        enough for a disc that was free and has moved by less than its radius since.
        """
        d = self.distances(x, y)
        i = int(np.argmin(d))
        if d[i] < radius_m:
            return self.owners[i]
        return None if edges_only else self.inside(x, y)

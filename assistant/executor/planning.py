"""Path planning on an occupancy grid built from the known floor plan and perceived furniture.

The robot is *told* the floor plan (rooms, walls, doors) and *perceives* furniture; the
occupancy map is built from exactly those two: the walls of :class:`~assistant.world.World`'s
floor plan and a list of :class:`~assistant.world.Entity` that perception reported. It never
reads a world file's furniture.

* :func:`build_occupancy` → :class:`OccupancyMap`: obstacles, the clearance (metres from each
  cell to the nearest obstacle, a Euclidean distance transform), and from it the cells the
  robot's centre may not enter (clearance below robot radius + margin).
* :func:`plan_path` → :class:`PlannedPath`: a minimum-cost route with scikit-image's
  ``MCP_Geometric`` over a cost that rises near obstacles (so paths keep to the middle of
  doors and corridors), then shortened by line-of-sight shortcuts that never come closer to an
  obstacle than the grid route did. A goal inside an obstacle snaps to the nearest reachable
  free cell; an unreachable goal raises :class:`NoPathError`, whose :meth:`~NoPathError.to_result`
  is the ``no_path`` outcome.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy import ndimage

from assistant.errors import AssistantError
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.geometry import GridMap, Pose2D
from assistant.world import ROBOT_RADIUS_M, Entity, World, world_grid

DEFAULT_RESOLUTION_M = 0.05
DEFAULT_MARGIN_M = 0.05  # kept free beyond the robot's radius when planning
UNKNOWN_BEYOND_ROOMS_M = 0.15  # floor this far outside every room polygon counts as known (door gaps)


class NoPathError(AssistantError):
    """No collision-free path from ``start`` to ``goal`` (metres); ``reason`` says why.

    ``reason`` is one of ``start_blocked``, ``goal_blocked``, ``unreachable``, ``outside``.
    """

    def __init__(self, message: str, start: Sequence[float], goal: Sequence[float], reason: str):
        super().__init__(message)
        self.start = (float(start[0]), float(start[1]))
        self.goal = (float(goal[0]), float(goal[1]))
        self.reason = reason

    def to_result(self, final_pose: Pose2D | None = None) -> ExecutionResult:
        return ExecutionResult.failed(ExecutionStatus.NO_PATH, str(self), final_pose=final_pose,
                                      details={"reason": self.reason, "start": list(self.start),
                                               "goal": list(self.goal)})


@dataclass(frozen=True, eq=False)
class OccupancyMap:
    """What the robot may drive through.

    ``obstacles`` (bool, ``grid.shape``) marks walls, perceived furniture and unknown floor
    outside the rooms. ``clearance_m`` is, for every cell, the distance in metres from its
    centre to the nearest obstacle (0 on obstacles).
    """

    grid: GridMap
    obstacles: np.ndarray
    clearance_m: np.ndarray
    robot_radius_m: float = ROBOT_RADIUS_M
    margin_m: float = DEFAULT_MARGIN_M

    @classmethod
    def from_obstacles(cls, grid: GridMap, obstacles: np.ndarray, robot_radius_m: float = ROBOT_RADIUS_M,
                       margin_m: float = DEFAULT_MARGIN_M) -> "OccupancyMap":
        obstacles = np.asarray(obstacles, dtype=bool)
        if obstacles.shape != grid.shape:
            raise ValueError(f"obstacle mask {obstacles.shape} does not match grid {grid.shape}")
        if obstacles.any():
            centre_distance = ndimage.distance_transform_edt(~obstacles, sampling=grid.resolution_m)
            # an obstacle cell's edge is half a cell nearer than its centre
            clearance = np.where(obstacles, 0.0, np.maximum(centre_distance - grid.resolution_m / 2, 0.0))
        else:
            clearance = np.full(grid.shape, np.inf)
        return cls(grid, obstacles, clearance, robot_radius_m, margin_m)

    @cached_property
    def blocked(self) -> np.ndarray:
        """Cells the robot's centre must not enter when planning (radius + margin)."""
        return self.clearance_m < self.robot_radius_m + self.margin_m

    @cached_property
    def free_regions(self) -> np.ndarray:
        """Labels of the 8-connected regions of free (not blocked) cells; 0 on blocked cells."""
        labels, _ = ndimage.label(~self.blocked, structure=np.ones((3, 3), dtype=bool))
        return labels

    @property
    def colliding(self) -> np.ndarray:
        """Cells where the robot's disc would overlap an obstacle (radius only)."""
        return self.clearance_m < self.robot_radius_m

    def cells_of(self, points_xy: np.ndarray) -> np.ndarray:
        return self.grid.world_to_cell(np.asarray(points_xy, dtype=float).reshape(-1, 2))

    def reachable_from(self, pose, points_xy: np.ndarray) -> np.ndarray:
        """Which world points (N, 2) lie in the free region the robot at ``pose`` stands in
        (pockets behind furniture are left out). Off the grid: False; when the robot itself is
        off the grid or on a blocked cell (after a bump), every point on the grid counts."""
        pts = np.asarray(points_xy, dtype=float).reshape(-1, 2)
        if len(pts) == 0:
            return np.zeros(0, dtype=bool)
        labels = self.free_regions
        here = self.cells_of(np.array([[pose.x, pose.y]]))[0]
        cells = self.cells_of(pts)
        inside = self.grid.contains_cells(cells)
        if not self.grid.contains_cells(here[None])[0]:
            return inside
        mine = labels[here[0], here[1]]
        if mine == 0:
            return inside
        out = np.zeros(len(pts), dtype=bool)
        out[inside] = labels[cells[inside, 0], cells[inside, 1]] == mine
        return out

    def clearance_at(self, points_xy: np.ndarray) -> np.ndarray:
        """Clearance (metres) at world points; 0 outside the grid."""
        cells = self.cells_of(points_xy)
        inside = self.grid.contains_cells(cells)
        out = np.zeros(len(cells))
        out[inside] = self.clearance_m[cells[inside, 0], cells[inside, 1]]
        return out

    def is_free(self, x: float, y: float) -> bool:
        """Whether the robot's centre may be planned to ``(x, y)``."""
        return bool(self.clearance_at(np.array([[x, y]]))[0] >= self.robot_radius_m + self.margin_m)

    def segment_clearance(self, a_xy: Sequence[float], b_xy: Sequence[float]) -> float:
        """The least clearance (metres) of the cells a straight segment crosses."""
        return float(self.clearance_m[tuple(_line_cells(self.grid, a_xy, b_xy).T)].min())

    def cost(self, comfort_m: float = 0.5, weight: float = 4.0) -> np.ndarray:
        """Per-cell travel cost: 1 in open floor, up to ``1 + weight`` at the edge of the
        blocked zone (rising quadratically within ``comfort_m`` of it), inf where blocked.
        (Cached per map and parameters; do not modify the returned array.)"""
        key = (comfort_m, weight)
        cache = self.__dict__.setdefault("_cost_cache", {})
        if key not in cache:
            cache[key] = self._cost(comfort_m, weight)
        return cache[key]

    def _cost(self, comfort_m: float, weight: float) -> np.ndarray:
        lethal = self.robot_radius_m + self.margin_m
        closeness = np.clip((comfort_m - (self.clearance_m - lethal)) / comfort_m, 0.0, 1.0)
        cost = 1.0 + weight * closeness ** 2
        cost[self.blocked] = np.inf
        return cost


def build_occupancy(world: World, entities: Iterable[Entity] = (), *,
                    resolution_m: float = DEFAULT_RESOLUTION_M, robot_radius_m: float = ROBOT_RADIUS_M,
                    margin_m: float = DEFAULT_MARGIN_M, grid: GridMap | None = None) -> OccupancyMap:
    """The occupancy of a home as the robot knows it: the floor plan's walls, floor outside
    every room (unknown, so blocked; door gaps stay open), and the perceived ``entities``
    (furniture or anything else perception reports, on any grid)."""
    grid = grid or world_grid(world, resolution_m, margin_m=0.5)
    known = np.zeros(grid.shape, dtype=bool)
    for room in world.floorplan.rooms:
        known |= grid.rasterize_polygon(room.polygon_array)
    grow = int(math.ceil(UNKNOWN_BEYOND_ROOMS_M / grid.resolution_m))
    if grow > 0:
        known = ndimage.binary_dilation(known, iterations=grow)
    for door in world.floorplan.doors:  # the floor through a thick wall's door gap is known too
        cx, cy = door.centre
        half = door.width_m / 2
        known |= grid.rasterize_polygon(np.array([[cx - half, cy - half], [cx + half, cy - half],
                                                  [cx + half, cy + half], [cx - half, cy + half]]))
    obstacles = ~known
    for wall in world.floorplan.walls:
        obstacles |= grid.rasterize_polygon(wall.polygon_array)
    for entity in entities:
        obstacles |= entity_mask_on(entity, grid)
    return OccupancyMap.from_obstacles(grid, obstacles, robot_radius_m, margin_m)


def entity_mask_on(entity: Entity, grid: GridMap) -> np.ndarray:
    """The cells of ``grid`` an entity covers, whatever grid the entity was built on."""
    mask = np.zeros(grid.shape, dtype=bool)
    if len(entity.cells) == 0:
        return mask
    if entity.grid == grid:
        mask[entity.cells[:, 0], entity.cells[:, 1]] = True
        return mask
    # sample each of the entity's cells finely enough that no cell of ``grid`` under it is missed
    step = entity.grid.resolution_m
    n = max(1, int(math.ceil(step / grid.resolution_m)) * 2)
    offsets = (np.arange(n) + 0.5) / n * step - step / 2
    ox, oy = np.meshgrid(offsets, offsets)
    centres = entity.points_m()
    samples = (centres[:, None, :] + np.stack([ox.ravel(), oy.ravel()], axis=1)[None]).reshape(-1, 2)
    cells = grid.world_to_cell(samples)
    cells = cells[grid.contains_cells(cells)]
    mask[cells[:, 0], cells[:, 1]] = True
    return mask


@dataclass(frozen=True, eq=False)
class PlannedPath:
    """A path for the robot's centre: ``waypoints`` (N, 2) metres from the start position to
    the (possibly snapped) goal. ``min_clearance_m`` is the least distance from the path to an
    obstacle; ``goal_snapped`` says the requested goal was inside an obstacle and moved
    ``snap_distance_m`` to the nearest reachable free cell."""

    waypoints: np.ndarray
    requested_goal: tuple[float, float]
    goal_snapped: bool
    snap_distance_m: float
    min_clearance_m: float
    grid_cells: np.ndarray  # the unsimplified grid route (iy, ix)

    @property
    def goal(self) -> tuple[float, float]:
        return (float(self.waypoints[-1, 0]), float(self.waypoints[-1, 1]))

    @property
    def length_m(self) -> float:
        return float(np.linalg.norm(np.diff(self.waypoints, axis=0), axis=1).sum())

    def to_dict(self) -> dict:
        return {"waypoints": self.waypoints.round(3).tolist(), "length_m": round(self.length_m, 3),
                "goal_snapped": self.goal_snapped, "snap_distance_m": round(self.snap_distance_m, 3),
                "min_clearance_m": round(self.min_clearance_m, 3)}


def plan_path(occupancy: OccupancyMap, start: Pose2D | Sequence[float], goal: Sequence[float], *,
              snap_goal: bool = True, max_snap_m: float = 1.5, max_start_escape_m: float = 0.5,
              simplify: bool = True) -> PlannedPath:
    """A collision-free, obstacle-shy path from ``start`` to ``goal`` (metres).

    A goal inside an obstacle (or too close to one) moves to the nearest free cell reachable
    from the start, at most ``max_snap_m`` away. A start too close to an obstacle (e.g. after a
    bump) leaves by the nearest free cell within ``max_start_escape_m``. Raises
    :class:`NoPathError` when there is no way.
    """
    grid = occupancy.grid
    start_xy = np.array(start.xy if isinstance(start, Pose2D) else start[:2], dtype=float)
    goal_xy = np.array(goal[:2], dtype=float)
    blocked = occupancy.blocked
    start_cell = grid.world_to_cell(start_xy)[0]
    goal_cell = grid.world_to_cell(goal_xy)[0]
    for name, cell, xy in (("start", start_cell, start_xy), ("goal", goal_cell, goal_xy)):
        if not grid.contains_cells(cell[None])[0]:
            raise NoPathError(f"the {name} ({xy[0]:.2f}, {xy[1]:.2f}) is outside the map", start_xy,
                              goal_xy, "outside")

    # free floor reachable from the start (8-connected, as the planner moves)
    free = ~blocked
    labels = occupancy.free_regions
    if not free[tuple(start_cell)]:
        escape = _nearest_cell(free, start_cell, max_start_escape_m / grid.resolution_m)
        if escape is None:
            raise NoPathError(f"the robot at ({start_xy[0]:.2f}, {start_xy[1]:.2f}) is boxed in: no free "
                              f"floor within {max_start_escape_m:.2f} m", start_xy, goal_xy, "start_blocked")
        start_cell = escape
    reachable = labels == labels[tuple(start_cell)]

    snapped, snap_m = False, 0.0
    if not reachable[tuple(goal_cell)]:
        if free[tuple(goal_cell)]:
            raise NoPathError(f"no way from ({start_xy[0]:.2f}, {start_xy[1]:.2f}) to ({goal_xy[0]:.2f}, "
                              f"{goal_xy[1]:.2f}): the floor between them is blocked", start_xy, goal_xy,
                              "unreachable")
        near = _nearest_cell(reachable, goal_cell, max_snap_m / grid.resolution_m) if snap_goal else None
        if near is None:
            raise NoPathError(f"the goal ({goal_xy[0]:.2f}, {goal_xy[1]:.2f}) is inside or against an obstacle "
                              f"and no reachable free floor lies within {max_snap_m:.2f} m of it",
                              start_xy, goal_xy, "goal_blocked")
        snap_m = float(np.hypot(*(near - goal_cell)) * grid.resolution_m)
        goal_cell, snapped = near, True

    from skimage.graph import MCP_Geometric  # scikit-image's minimum-cost-path search

    mcp = MCP_Geometric(occupancy.cost(), fully_connected=True)
    mcp.find_costs([tuple(start_cell)], [tuple(goal_cell)])
    cells = np.asarray(mcp.traceback(tuple(goal_cell)), dtype=int)
    route = cells if not simplify else cells[_shortcut(occupancy, cells)]
    points = grid.cell_to_world(route)
    # the path starts where the robot is and ends at the requested goal when that was free
    points[0] = start_xy
    if not snapped:
        points[-1] = goal_xy
    points = _drop_repeats(points)
    clearance = min(occupancy.segment_clearance(a, b) for a, b in zip(points[:-1], points[1:])) \
        if len(points) > 1 else float(occupancy.clearance_at(points)[0])
    return PlannedPath(points, (float(goal_xy[0]), float(goal_xy[1])), snapped, snap_m, clearance, cells)


def _nearest_cell(mask: np.ndarray, cell: np.ndarray, max_cells: float) -> np.ndarray | None:
    """The True cell of ``mask`` nearest to ``cell`` within ``max_cells`` cells, or None."""
    r = int(math.ceil(max_cells))
    y0, x0 = max(cell[0] - r, 0), max(cell[1] - r, 0)
    window = mask[y0:cell[0] + r + 1, x0:cell[1] + r + 1]
    candidates = np.argwhere(window)
    if len(candidates) == 0:
        return None
    candidates += (y0, x0)
    d = np.hypot(*(candidates - cell).T)
    best = int(np.argmin(d))
    return candidates[best] if d[best] <= max_cells else None


def _line_cells(grid: GridMap, a_xy: Sequence[float], b_xy: Sequence[float]) -> np.ndarray:
    from skimage.draw import line

    (ay, ax), (by, bx) = grid.world_to_cell(np.array([a_xy[:2], b_xy[:2]], dtype=float))
    rows, cols = line(int(ay), int(ax), int(by), int(bx))
    keep = (rows >= 0) & (rows < grid.height_cells) & (cols >= 0) & (cols < grid.width_cells)
    return np.stack([rows[keep], cols[keep]], axis=1)


def _shortcut(occupancy: OccupancyMap, cells: np.ndarray) -> list[int]:
    """Indices of the grid route kept after greedy line-of-sight shortcuts.

    A shortcut from route cell i to j is taken when the straight segment's least clearance is
    at least the least clearance of the route between them (less half a cell), so smoothing
    never brings the path nearer an obstacle than the planner chose to go.
    """
    from skimage.draw import line

    clearance = occupancy.clearance_m
    route_clearance = clearance[cells[:, 0], cells[:, 1]]
    tolerance = occupancy.grid.resolution_m / 2
    keep = [0]
    i, n = 0, len(cells)
    while i < n - 1:
        best = i + 1
        lowest = route_clearance[i + 1]
        for j in range(i + 2, n):
            lowest = min(lowest, route_clearance[j])
            rows, cols = line(int(cells[i, 0]), int(cells[i, 1]), int(cells[j, 0]), int(cells[j, 1]))
            if clearance[rows, cols].min() >= lowest - tolerance:
                best = j
            elif j - best > 20:  # long after the last good shortcut: stop looking
                break
        keep.append(best)
        i = best
    return keep


def _drop_repeats(points: np.ndarray, tolerance_m: float = 1e-6) -> np.ndarray:
    keep = [0]
    for k in range(1, len(points)):
        if np.linalg.norm(points[k] - points[keep[-1]]) > tolerance_m:
            keep.append(k)
    if len(keep) == 1 and len(points) > 1:
        keep.append(len(points) - 1)
    return points[keep]

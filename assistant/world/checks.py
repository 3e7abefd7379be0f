"""Sanity checks of a world's content (beyond the file format): objects lie on their furniture,
furniture stands in its room, and the robot can reach every room from its start pose."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from assistant.geometry import point_in_polygon
from assistant.world.entities import world_grid
from assistant.world.entity import ROBOT_RADIUS_M
from assistant.world.model import World


@dataclass(frozen=True)
class Problem:
    scene: str
    what: str

    def __str__(self) -> str:
        return f"{self.scene}: {self.what}"


def occupancy(world: World, scene: str, resolution_m: float = 0.05, inflate_m: float = 0.0):
    """Boolean occupancy of walls and furniture (True = blocked), inflated by ``inflate_m``.

    Returns ``(grid, occupied)``.
    """
    grid = world_grid(world, resolution_m, margin_m=0.5)
    occupied = np.zeros(grid.shape, dtype=bool)
    for wall in world.floorplan.walls:
        occupied |= grid.rasterize_polygon(wall.polygon_array)
    for item in world.scene(scene).furniture:
        occupied |= grid.rasterize_polygon(item.footprint_polygon())
    if inflate_m > 0:
        radius = int(np.ceil(inflate_m / resolution_m))
        yy, xx = np.mgrid[-radius:radius + 1, -radius:radius + 1]
        disc = (xx ** 2 + yy ** 2) * resolution_m ** 2 <= inflate_m ** 2
        occupied = ndimage.binary_dilation(occupied, structure=disc)
    return grid, occupied


def check_world(world: World) -> list[Problem]:
    """Every problem found in every scene (empty when the world is sound)."""
    problems: list[Problem] = []
    for scene_name, scene in world.scenes.items():
        for obj in scene.objects:
            item = scene.item(obj.on)
            if not point_in_polygon(np.array([[obj.x, obj.y]]), item.footprint_polygon())[0]:
                problems.append(Problem(scene_name, f"{obj.name} at ({obj.x}, {obj.y}) is not on {item.id}"))
        for item in scene.furniture:
            room = world.floorplan.room(item.room)
            if not room.contains(item.x, item.y):
                problems.append(Problem(scene_name, f"{item.id} at ({item.x}, {item.y}) is not in the {item.room}"))
        problems.extend(_reachability(world, scene_name))
    return problems


def _reachability(world: World, scene: str) -> list[Problem]:
    grid, blocked = occupancy(world, scene, resolution_m=0.05, inflate_m=ROBOT_RADIUS_M)
    free_labels, _ = ndimage.label(~blocked)
    start_cell = grid.world_to_cell(world.start.xy)[0]
    if not grid.contains_cells(start_cell[None])[0] or blocked[start_cell[0], start_cell[1]]:
        return [Problem(scene, f"the robot's start pose ({world.start.x}, {world.start.y}) is blocked")]
    reachable = free_labels == free_labels[start_cell[0], start_cell[1]]
    out = []
    xs, ys = grid.cell_centres()
    points = np.stack([xs.ravel(), ys.ravel()], axis=1)
    for room in world.floorplan.rooms:
        inside = point_in_polygon(points, room.polygon_array).reshape(grid.shape)
        if not (inside & reachable).any():
            out.append(Problem(scene, f"the robot cannot reach the {room.name} from its start pose"))
    return out

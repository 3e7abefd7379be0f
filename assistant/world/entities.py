"""Entities of a world file: the floor plan's long-term entities and, for simulation and
evaluation only, the ground-truth furniture."""

from __future__ import annotations

import numpy as np

from assistant.geometry import GridMap, box_polygon
from assistant.world.entity import Entity, EntityKind
from assistant.world.model import World

DEFAULT_RESOLUTION_M = 0.1


def world_grid(world: World, resolution_m: float = DEFAULT_RESOLUTION_M, margin_m: float = 0.5) -> GridMap:
    """A grid covering the whole floor plan (plus a margin)."""
    return GridMap.covering(*world.floorplan.bounds(), resolution_m=resolution_m, margin_m=margin_m)


def floorplan_entities(world: World, grid: GridMap) -> list[Entity]:
    """Rooms, walls and doors as long-term entities."""
    out: list[Entity] = []
    for room in world.floorplan.rooms:
        out.append(Entity.from_polygon(f"room:{room.name}", "room", EntityKind.LONG_TERM,
                                       room.polygon_array, grid, room=room.name))
    for i, wall in enumerate(world.floorplan.walls):
        out.append(Entity.from_polygon(f"wall:{i}", "wall", EntityKind.LONG_TERM,
                                       wall.polygon_array, grid))
    for door in world.floorplan.doors:
        cx, cy = door.centre
        half = door.width_m / 2
        # a door is a thin box across the opening; its axis follows the wall it sits in
        horizontal = _door_is_horizontal(world, door.centre)
        poly = (box_polygon(cx - half, cy - 0.05, cx + half, cy + 0.05) if horizontal
                else box_polygon(cx - 0.05, cy - half, cx + 0.05, cy + half))
        out.append(Entity.from_polygon(f"door:{door.name}", "door", EntityKind.LONG_TERM, poly, grid))
    return out


def furniture_entities(world: World, scene: str, grid: GridMap) -> list[Entity]:
    """Ground-truth furniture of a scene as short-term entities (simulation/evaluation only)."""
    out = []
    for item in world.scene(scene).furniture:
        out.append(Entity.from_polygon(item.id, item.word, EntityKind.SHORT_TERM,
                                       item.footprint_polygon(), grid, item.facing_rad,
                                       category=item.category, room=item.room))
    return out


def _door_is_horizontal(world: World, centre: tuple[float, float]) -> bool:
    """Whether the wall a door sits in runs along x (True) or along y (False)."""
    cx, cy = centre
    best_h, best_v = np.inf, np.inf
    for w in world.floorplan.walls:
        if w.xmax - w.xmin >= w.ymax - w.ymin:  # wall along x
            if w.ymin - 0.1 <= cy <= w.ymax + 0.1:
                best_h = min(best_h, min(abs(cx - w.xmin), abs(cx - w.xmax)))
        elif w.xmin - 0.1 <= cx <= w.xmax + 0.1:
            best_v = min(best_v, min(abs(cy - w.ymin), abs(cy - w.ymax)))
    return best_h <= best_v

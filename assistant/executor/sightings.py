"""Where a seen object is: its room and the perceived furniture it lies on.

The object detector (:mod:`assistant.perception.objects`) reports a small object's position;
the robot places it with what it knows itself — the rooms of the floor plan and the furniture
its perception has found — never with the world file's furniture. Tasks that see objects
(fetch, search) report them as ``objects_seen`` events carrying these places, so that memory
(the dialogue) can record every object the robot sees during any task.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from assistant.executor.rooms import room_of
from assistant.perception.objects import ObjectSighting
from assistant.world import Entity, World

__all__ = ["PlacedSighting", "place_sightings", "SUPPORT_DISTANCE_M"]

#: largest gap (metres) between an object and a furniture footprint for it to count as lying on it
SUPPORT_DISTANCE_M = 0.3


@dataclass(frozen=True)
class PlacedSighting:
    """A sighting with its place: ``room`` (floor-plan room name or None) and the perceived
    furniture entity it lies on (``furniture_id`` / ``furniture_category``, None when it is on
    no furniture the robot has found)."""

    sighting: ObjectSighting
    room: str | None
    furniture_id: str | None = None
    furniture_category: str | None = None

    @property
    def name(self) -> str:
        return self.sighting.name

    def to_dict(self) -> dict:
        return {**self.sighting.to_dict(), "room": self.room, "furniture_id": self.furniture_id,
                "furniture": self.furniture_category}


def _distance_to_cells(entity: Entity, x_m: float, y_m: float) -> float:
    if len(entity.cells) == 0:
        return math.inf
    centres = entity.grid.cell_to_world(entity.cells)
    half = entity.grid.resolution_m / 2.0
    dx = np.maximum(np.abs(centres[:, 0] - x_m) - half, 0.0)
    dy = np.maximum(np.abs(centres[:, 1] - y_m) - half, 0.0)
    return float(np.sqrt(dx * dx + dy * dy).min())


def place_sightings(world: World, furniture: Sequence[Entity],
                    sightings: Sequence[ObjectSighting]) -> list[PlacedSighting]:
    """Each sighting with its room and the nearest perceived furniture within
    :data:`SUPPORT_DISTANCE_M` of it (its footprint cells)."""
    placed = []
    for sighting in sightings:
        best, best_d = None, SUPPORT_DISTANCE_M
        for entity in furniture:
            d = _distance_to_cells(entity, sighting.x_m, sighting.y_m)
            if d <= best_d:
                best, best_d = entity, d
        placed.append(PlacedSighting(
            sighting, room_of(world, (sighting.x_m, sighting.y_m)),
            None if best is None else best.id, None if best is None else best.category))
    return placed

"""Where a seen object is: its room and the perceived furniture it lies on.

The object detector (:mod:`assistant.perception.objects`) reports a small object's position;
the robot places it with what it knows itself — the rooms of the floor plan and the furniture
its perception has found — never with the world file's furniture. Tasks that see objects
(fetch, search) report them as ``objects_seen`` events carrying these placed
:class:`~assistant.perception.objects.Sighting` values, so that memory (the dialogue) can
record every object the robot sees during any task.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Sequence

import numpy as np

from assistant.executor.rooms import room_of
from assistant.perception.objects import Sighting
from assistant.world import Entity, World

__all__ = ["place_sightings", "SUPPORT_DISTANCE_M"]

#: largest gap (metres) between an object and a furniture footprint for it to count as lying on it
SUPPORT_DISTANCE_M = 0.3
#: the categories a chair gives way to (see :func:`place_sightings`)
TABLE_CATEGORIES = frozenset({"small table", "large table"})


def _distance_to_cells(entity: Entity, x_m: float, y_m: float) -> float:
    if len(entity.cells) == 0:
        return math.inf
    centres = entity.grid.cell_to_world(entity.cells)
    half = entity.grid.resolution_m / 2.0
    dx = np.maximum(np.abs(centres[:, 0] - x_m) - half, 0.0)
    dy = np.maximum(np.abs(centres[:, 1] - y_m) - half, 0.0)
    return float(np.sqrt(dx * dx + dy * dy).min())


def place_sightings(world: World, furniture: Sequence[Entity],
                    sightings: Sequence[Sighting]) -> list[Sighting]:
    """Each sighting with its room and the nearest perceived furniture within
    :data:`SUPPORT_DISTANCE_M` of it (its footprint cells) — but a table within that distance
    rather than a nearer chair: chairs stand pushed to tables, things are rarely left on them,
    and a small object seen from across the room is placed a few decimetres off (a mug on the
    bedroom's hexagon table was remembered "on the chair" beside it). No furniture there sets
    ``furniture_id``/``furniture_category`` to None."""
    placed = []
    for sighting in sightings:
        near = [(d, entity) for entity in furniture
                if (d := _distance_to_cells(entity, sighting.x_m, sighting.y_m)) <= SUPPORT_DISTANCE_M]
        tables = [(d, e) for d, e in near if e.category in TABLE_CATEGORIES]
        best = None
        if near:  # of equally near pieces, the last (as the scan always chose)
            nearest = min(reversed(near), key=lambda pair: pair[0])[1]
            best = min(reversed(tables), key=lambda pair: pair[0])[1] if tables and nearest.category == "chair" \
                else nearest
        placed.append(dataclasses.replace(
            sighting, room=room_of(world, (sighting.x_m, sighting.y_m)),
            furniture_id=None if best is None else best.id,
            furniture_category=None if best is None else best.category))
    return placed

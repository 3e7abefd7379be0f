"""Perception for the fetch task: what furniture the robot knows of, and how it learns more.

Two sources share one small interface (:class:`FurnitureSource`): ``observe(frame, pose)``
hands a depth frame and the robot's corrected world pose to perception, ``furniture()`` returns
the furniture entities known so far.

* :class:`SensedFurniture` — the product's perception: the
  :class:`~assistant.perception.FurnitureDetector` on each depth frame, fused into an
  :class:`~assistant.world.environment.EnvironmentModel`. It never reads the world file's
  furniture.
* :class:`OracleFurniture` — the environment model filled from the world file's ground-truth
  furniture (:func:`assistant.world.furniture_entities`). It exists only to separate language
  errors from perception errors (DESIGN.md, Principles) and is the ONLY place of the executor
  that touches ground truth.

:func:`environment_items` turns known entities plus the told floor plan into the
:class:`~assistant.policy.demonstration.EnvironmentEntity` polygons the policy models read.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Protocol

import numpy as np

from assistant.geometry import Pose2D
from assistant.robot.frames import DepthFrame
from assistant.world import Entity, World

PERCEPTION_MODES = ("sensed", "oracle")


class FurnitureSource(Protocol):
    """What the fetch task needs from perception."""

    def observe(self, frame: DepthFrame, pose: Pose2D) -> None: ...

    def furniture(self) -> list[Entity]: ...


class SensedFurniture:
    """Detector + environment model. ``detector`` is anything with ``detect(frame) ->
    list[Entity]`` (default: a :class:`~assistant.perception.FurnitureDetector` with its cached
    models). Frames are re-posed to the localizer's corrected pose before detection."""

    mode = "sensed"

    def __init__(self, world: World, detector=None, model=None):
        if detector is None:
            from assistant.perception import FurnitureDetector

            detector = FurnitureDetector()
        if model is None:
            from assistant.world.environment import EnvironmentModel

            model = EnvironmentModel(world)
        self.world = world
        self.detector = detector
        self.model = model
        self.frames = 0

    def observe(self, frame: DepthFrame, pose: Pose2D) -> None:
        if frame is None:
            return
        if pose is not None and frame.robot_pose != pose:
            frame = dataclasses.replace(frame, robot_pose=pose)
        detections = self.detector.detect(frame)
        self.model.update(detections, pose)
        self.frames += 1

    def furniture(self) -> list[Entity]:
        return self.model.furniture()


class OracleFurniture:
    """Ground-truth furniture of a scene (evaluation only: separates language from perception
    errors). ``observe`` only counts frames; every item is known from the start."""

    mode = "oracle"

    def __init__(self, world: World, scene: str, resolution_m: float = 0.05):
        from assistant.world import furniture_entities, world_grid

        self._items = furniture_entities(world, scene, world_grid(world, resolution_m))
        self.frames = 0

    def observe(self, frame: DepthFrame, pose: Pose2D) -> None:
        self.frames += 1

    def furniture(self) -> list[Entity]:
        return list(self._items)


def make_furniture_source(mode: str, world: World, scene: str, detector=None) -> FurnitureSource:
    """``sensed`` or ``oracle`` perception for a run in ``scene`` of ``world``."""
    if mode == "sensed":
        return SensedFurniture(world, detector=detector)
    if mode == "oracle":
        return OracleFurniture(world, scene)
    from assistant.errors import UnknownNameError

    raise UnknownNameError("perception mode", mode, PERCEPTION_MODES)


def entity_room(world: World, entity: Entity) -> str | None:
    """The room an entity stands in (its own ``room`` or the room of its centre)."""
    if entity.room:
        return entity.room
    x, y = entity_centre(entity)
    room = world.floorplan.room_at(x, y)
    return room.name if room else None


def entity_centre(entity: Entity) -> tuple[float, float]:
    """Best centre estimate (metres): :attr:`~assistant.world.Entity.centre_m`."""
    return entity.centre_m


def entity_polygon(entity: Entity) -> np.ndarray:
    """A floor polygon (K, 2) around an entity's cells: the convex hull of the cells' corners."""
    from scipy.spatial import ConvexHull, QhullError

    pts = entity.points_m()
    half = entity.grid.resolution_m / 2
    corners = np.concatenate([pts + [dx, dy] for dx in (-half, half) for dy in (-half, half)])
    try:
        hull = ConvexHull(corners)
        return corners[hull.vertices]
    except (QhullError, ValueError):
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        return np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])


def environment_items(world: World, furniture: Sequence[Entity]) -> tuple:
    """The policy models' environment: perceived furniture as polygons, plus the rooms and
    wall pieces of the floor plan (which the robot is told)."""
    from assistant.policy.demonstration import EnvironmentEntity, wall_pieces

    out = []
    for e in furniture:
        poly = entity_polygon(e)
        out.append(EnvironmentEntity(e.id, e.name, e.category, "short_term",
                                     tuple(map(tuple, poly.tolist())), e.orientation_rad,
                                     entity_room(world, e)))
    for room in world.floorplan.rooms:
        out.append(EnvironmentEntity(f"room:{room.name}", "room", "room", "long_term",
                                     tuple(map(tuple, room.polygon_array.tolist())), None, room.name))
    for i, wall in enumerate(world.floorplan.walls):
        out.extend(wall_pieces(i, wall.polygon_array, world.floorplan.rooms))
    return tuple(out)

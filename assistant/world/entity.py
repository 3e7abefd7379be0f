"""Entities: the things spatial relations are computed between (dissertation 3.5, 5.4.1).

An entity has an id, a name (a category or room word: ``couch``, ``table``, ``wall``, ``room``,
``robot``…), a kind, a footprint (the floor-grid cells it covers) and an orientation (radians of
its functional front, or None for symmetric items such as tables).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import lru_cache
from enum import Enum

import numpy as np

from assistant.geometry import GridMap, Pose2D, ellipse
from assistant.world.catalogue import load_catalogue


class EntityKind(str, Enum):
    LONG_TERM = "long_term"  # walls, doors, rooms: from the floor plan
    SHORT_TERM = "short_term"  # furniture and objects: perceived
    CURRENT_ROBOT = "current_robot"
    ORIGINAL_ROBOT = "original_robot"


ROBOT_RADIUS_M = 0.25  # P3-DX footprint radius used for the robot entity and collisions


@dataclass(frozen=True, eq=False)
class Entity:
    """A thing on the floor, as a set of cells of ``grid``.

    ``cells`` is an (N, 2) integer array of ``(iy, ix)`` indices into ``grid``;
    ``orientation_rad`` is the functional front (counter-clockwise from +x) or None.
    """

    id: str
    name: str
    kind: EntityKind
    grid: GridMap
    cells: np.ndarray
    orientation_rad: float | None = None
    category: str | None = None  # catalogue category for furniture ("small table"…)
    room: str | None = None
    confidence: float = 1.0
    attributes: dict = field(default_factory=dict)

    @classmethod
    def from_polygon(cls, id: str, name: str, kind: EntityKind, polygon_xy: np.ndarray,
                     grid: GridMap, orientation_rad: float | None = None, **extra) -> "Entity":
        mask = grid.rasterize_polygon(polygon_xy)
        return cls(id, name, kind, grid, np.argwhere(mask), orientation_rad, **extra)

    @classmethod
    def from_mask(cls, id: str, name: str, kind: EntityKind, mask: np.ndarray, grid: GridMap,
                  orientation_rad: float | None = None, **extra) -> "Entity":
        if mask.shape != grid.shape:
            raise ValueError(f"mask shape {mask.shape} does not match grid shape {grid.shape}")
        return cls(id, name, kind, grid, np.argwhere(mask), orientation_rad, **extra)

    @classmethod
    def robot(cls, pose: Pose2D, grid: GridMap, kind: EntityKind = EntityKind.CURRENT_ROBOT,
              radius_m: float = ROBOT_RADIUS_M) -> "Entity":
        """The robot as a disc of ``radius_m`` facing its heading."""
        polygon = ellipse(pose, 2 * radius_m, 2 * radius_m, segments=24)
        ident = "robot" if kind is EntityKind.CURRENT_ROBOT else "original_robot"
        return cls.from_polygon(ident, "robot", kind, polygon, grid, pose.theta)

    def mask(self) -> np.ndarray:
        """Boolean array of ``grid.shape``, True on the entity's cells."""
        m = np.zeros(self.grid.shape, dtype=bool)
        if len(self.cells):
            m[self.cells[:, 0], self.cells[:, 1]] = True
        return m

    def points_m(self) -> np.ndarray:
        """(N, 2) world coordinates (metres) of the centres of its cells."""
        return self.grid.cell_to_world(self.cells)

    @property
    def centroid_m(self) -> np.ndarray:
        pts = self.points_m()
        return pts.mean(axis=0) if len(pts) else np.array([math.nan, math.nan])

    @property
    def centre_m(self) -> tuple[float, float]:
        """The best centre estimate (metres): the detector's fused centre when it gave one
        (``attributes["x"]``, ``["y"]``), else the centroid of the cells."""
        attrs = self.attributes or {}
        if "x" in attrs and "y" in attrs:
            return float(attrs["x"]), float(attrs["y"])
        c = self.centroid_m
        return float(c[0]), float(c[1])

    @property
    def area_m2(self) -> float:
        return len(self.cells) * self.grid.resolution_m ** 2

    @property
    def has_front(self) -> bool:
        return self.orientation_rad is not None

    def to_dict(self) -> dict:
        cx, cy = self.centroid_m
        return {"id": self.id, "name": self.name, "kind": self.kind.value,
                "category": self.category, "room": self.room, "x": float(cx), "y": float(cy),
                "facing": self.orientation_rad, "cells": int(len(self.cells)),
                "confidence": self.confidence}


@lru_cache(maxsize=None)
def _largest_reach_m(category: str) -> float:
    """Metres from the centre to a corner of the largest catalogue model of ``category`` (0 when
    the catalogue has none)."""
    return max((math.hypot(m.length_m, m.width_m) / 2 for m in load_catalogue().models.values()
                if m.category == category), default=0.0)


def as_item(entity: Entity) -> Entity:
    """A perceived entity as the item it is: perception may fuse two items into one track (an
    L of two couches seen as one couch, a bed with the table at its side), whose cells then
    reach past anything of its category; the cells farther from the detector's centre
    (``attributes["x"]``, ``["y"]``) than the largest catalogue model of its category reaches
    are not part of that item. An entity without a detected centre or a known category is
    returned as it is. The spatial layer reads references so, and the executor's line of sight
    blockers."""
    attrs = entity.attributes or {}
    reach = _largest_reach_m(entity.category) if entity.category else 0.0
    if reach <= 0 or "x" not in attrs or "y" not in attrs or not len(entity.cells):
        return entity
    offsets = entity.points_m() - np.array(entity.centre_m)
    keep = np.hypot(offsets[:, 0], offsets[:, 1]) <= reach + entity.grid.resolution_m
    if keep.all() or not keep.any():
        return entity
    return dataclasses.replace(entity, cells=entity.cells[keep])

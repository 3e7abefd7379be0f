"""Getting from room to room through the doors of the floor plan.

The fetch task's first sub-task is to enter the target room (dissertation 4.3 II.D). A
:class:`RoomGraph` (networkx) has the floor plan's rooms as nodes and its doors as edges;
:func:`room_entry_waypoints` turns the doors on the way into poses: each door's centre and a
point a little inside the next room, headed into it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.errors import UnknownNameError
from assistant.geometry import Pose2D
from assistant.world import Door, World

ENTRY_DEPTH_M = 0.7  # how far past a door's centre the robot stops to be "in" the room
OUTSIDE = "outside"


@dataclass(frozen=True)
class DoorCrossing:
    """One door on a route: ``door``, the room left behind and the room entered, the unit
    vector pointing into ``to_room``, and the two poses to drive through."""

    door: Door
    from_room: str
    to_room: str
    inward: tuple[float, float]
    centre: Pose2D
    inside: Pose2D


class RoomGraph:
    """Routes between rooms over the floor plan's :meth:`~assistant.world.Floorplan.room_graph`
    (a networkx graph; edge attribute ``door`` is the :class:`Door`, ``weight`` the distance
    between the rooms' centres through it).

    The executor drives through doors only (``openings=False``): an open-plan room is entered
    by the fetch task's open-plan entry instead, which finds its own way in across the open side.
    """

    def __init__(self, world: World, openings: bool = False):
        self.world = world
        self.graph = world.floorplan.room_graph(openings=openings)

    @property
    def rooms(self) -> list[str]:
        return list(self.graph.nodes)

    def _check(self, room: str) -> None:
        if room not in self.graph:
            raise UnknownNameError("room", room, self.rooms)

    def room_route(self, from_room: str, to_room: str) -> list[str] | None:
        """Rooms on the shortest way, both ends included; None when no doors join them."""
        import networkx as nx

        self._check(from_room)
        self._check(to_room)
        try:
            return nx.shortest_path(self.graph, from_room, to_room, weight="weight")
        except nx.NetworkXNoPath:
            return None

    def doors_between(self, from_room: str, to_room: str) -> list[Door] | None:
        route = self.room_route(from_room, to_room)
        if route is None:
            return None
        return [self.graph[a][b]["door"] for a, b in zip(route[:-1], route[1:])]

    def crossings(self, from_room: str, to_room: str, depth_m: float = ENTRY_DEPTH_M) -> list[DoorCrossing] | None:
        route = self.room_route(from_room, to_room)
        if route is None:
            return None
        return [door_crossing(self.world, self.graph[a][b]["door"], a, b, depth_m)
                for a, b in zip(route[:-1], route[1:])]


def door_crossing(world: World, door: Door, from_room: str, to_room: str,
                  depth_m: float = ENTRY_DEPTH_M) -> DoorCrossing:
    """The poses to drive through ``door`` from ``from_room`` into ``to_room``."""
    c = np.asarray(door.centre, dtype=float)
    target = world.floorplan.room(to_room)
    best = None
    for direction in ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)):
        probe = c + depth_m * np.asarray(direction)
        if target.contains(*probe):
            # prefer the direction whose probe is deepest inside the room (farthest from its edge)
            depth = _inside_depth(target.polygon_array, probe)
            if best is None or depth > best[0]:
                best = (depth, direction)
    if best is None:  # an odd door: head from the door towards the room's centre
        v = target.centre - c
        norm = float(np.linalg.norm(v)) or 1.0
        direction = (float(v[0] / norm), float(v[1] / norm))
    else:
        direction = best[1]
    heading = math.atan2(direction[1], direction[0])
    inside = c + depth_m * np.asarray(direction)
    return DoorCrossing(door, from_room, to_room, direction, Pose2D(c[0], c[1], heading),
                        Pose2D(inside[0], inside[1], heading))


def room_entry_waypoints(world: World, from_room: str, to_room: str,
                         depth_m: float = ENTRY_DEPTH_M) -> list[Pose2D] | None:
    """Poses from ``from_room`` into ``to_room``: for each door on the way, its centre and a
    point ``depth_m`` inside the room beyond it, headed into that room. Empty when the rooms
    are the same; None when no doors join them. Unknown room names raise
    :class:`~assistant.errors.UnknownNameError`."""
    graph = RoomGraph(world)
    crossings = graph.crossings(from_room, to_room, depth_m)
    if crossings is None:
        return None
    poses: list[Pose2D] = []
    for crossing in crossings:
        poses.extend([crossing.centre, crossing.inside])
    return poses


def room_of(world: World, pose: Pose2D | tuple[float, float], max_distance_m: float = 0.3) -> str | None:
    """The room a position is in; in a doorway or wall gap, the nearest room within
    ``max_distance_m``; None when nowhere near a room."""
    x, y = (pose.x, pose.y) if isinstance(pose, Pose2D) else pose
    room = world.floorplan.room_at(x, y)
    if room is not None:
        return room.name
    best, best_d = None, max_distance_m
    for r in world.floorplan.rooms:
        d = _distance_to_polygon(r.polygon_array, np.array([x, y]))
        if d <= best_d:
            best, best_d = r.name, d
    return best


def _distance_to_polygon(polygon: np.ndarray, point: np.ndarray) -> float:
    a = polygon
    b = np.roll(polygon, -1, axis=0)
    ab = b - a
    t = np.clip(((point - a) * ab).sum(axis=1) / np.maximum((ab * ab).sum(axis=1), 1e-12), 0.0, 1.0)
    nearest = a + t[:, None] * ab
    return float(np.min(np.linalg.norm(nearest - point, axis=1)))


def _inside_depth(polygon: np.ndarray, point: np.ndarray) -> float:
    return _distance_to_polygon(polygon, point)

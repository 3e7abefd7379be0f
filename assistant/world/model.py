"""The world as the product knows it: floor plan (rooms, walls, doors), furniture, objects.

A :class:`World` is what a world file says: the floor plan, the robot's start pose, and one or
more :class:`Scene` s (``original``, ``modified``) that place furniture and objects. The robot
is *told* the floor plan; furniture and objects are ground truth the simulator renders and the
evaluation scores against, never read by the executor.
"""

from __future__ import annotations

from functools import cached_property
from typing import TYPE_CHECKING
from dataclasses import dataclass, field

import numpy as np

from assistant.errors import UnknownNameError
from assistant.geometry import Pose2D, box_polygon, point_in_polygon, rectangle
from assistant.world.catalogue import FurnitureModel, load_catalogue

if TYPE_CHECKING:
    import networkx as nx


@dataclass(frozen=True)
class Room:
    """A named area of the floor plan; ``open`` when no wall separates it from a neighbour."""

    name: str
    polygon: tuple[tuple[float, float], ...]  # metres, world frame, counter-clockwise
    open: bool = False

    @property
    def polygon_array(self) -> np.ndarray:
        return np.asarray(self.polygon, dtype=float)

    @property
    def centre(self) -> np.ndarray:
        return self.polygon_array.mean(axis=0)

    def contains(self, x: float, y: float) -> bool:
        return bool(point_in_polygon(np.array([[x, y]]), self.polygon_array)[0])


@dataclass(frozen=True)
class Wall:
    """An axis-aligned wall block (metres); walls are 2 m high."""

    xmin: float
    ymin: float
    xmax: float
    ymax: float

    HEIGHT_M = 2.0

    @property
    def polygon_array(self) -> np.ndarray:
        return box_polygon(self.xmin, self.ymin, self.xmax, self.ymax)

    def as_list(self) -> list[float]:
        return [self.xmin, self.ymin, self.xmax, self.ymax]


@dataclass(frozen=True)
class Door:
    """A doorway: its centre (metres), clear width (metres) and the two areas it connects."""

    name: str
    centre: tuple[float, float]
    width_m: float
    connects: tuple[str, str]


#: rooms whose bounding boxes lie this close (metres) share a side
SHARED_SIDE_GAP_M = 0.12
#: a free stretch of a shared side narrower than this (metres) is no passage
MIN_OPENING_M = 0.6


def _free_intervals(lo: float, hi: float, blocked: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """``[lo, hi]`` without the ``blocked`` intervals."""
    out, start = [], lo
    for b0, b1 in sorted(blocked):
        if b1 <= start:
            continue
        if b0 > start:
            out.append((start, min(b0, hi)))
        start = max(start, b1)
        if start >= hi:
            break
    if start < hi:
        out.append((start, hi))
    return [(u, v) for u, v in out if v > u]


def _shared_free_side(a: Room, b: Room, walls) -> tuple[tuple[float, float], float] | None:
    """(centre, width) of the longest stretch of the side rooms ``a`` and ``b`` share (their
    bounding boxes touch) that no wall block covers, or None."""
    pa, pb = a.polygon_array, b.polygon_array
    (ax0, ay0), (ax1, ay1) = pa.min(axis=0), pa.max(axis=0)
    (bx0, by0), (bx1, by1) = pb.min(axis=0), pb.max(axis=0)
    best = None
    for axis in (0, 1):  # 0: a side along y at some x; 1: a side along x at some y
        (a0, a1), (b0, b1) = ((ax0, ax1), (bx0, bx1)) if axis == 0 else ((ay0, ay1), (by0, by1))
        (c0, c1), (d0, d1) = ((ay0, ay1), (by0, by1)) if axis == 0 else ((ax0, ax1), (bx0, bx1))
        for edge_a, edge_b in ((a1, b0), (b1, a0)):
            if abs(edge_a - edge_b) > SHARED_SIDE_GAP_M:
                continue
            at = (edge_a + edge_b) / 2
            lo, hi = max(c0, d0), min(c1, d1)
            if hi - lo < MIN_OPENING_M:
                continue
            band = SHARED_SIDE_GAP_M
            blocked = []
            for w in walls:
                w_at0, w_at1 = (w.xmin, w.xmax) if axis == 0 else (w.ymin, w.ymax)
                if w_at1 < at - band or w_at0 > at + band:
                    continue
                blocked.append((w.ymin, w.ymax) if axis == 0 else (w.xmin, w.xmax))
            for u, v in _free_intervals(lo, hi, blocked):
                if v - u >= MIN_OPENING_M and (best is None or v - u > best[1]):
                    mid = (u + v) / 2
                    best = (((float(at), float(mid)) if axis == 0 else (float(mid), float(at))), float(v - u))
    return best


@dataclass(frozen=True)
class Floorplan:
    rooms: tuple[Room, ...]
    walls: tuple[Wall, ...]
    doors: tuple[Door, ...]

    @property
    def room_names(self) -> list[str]:
        return [room.name for room in self.rooms]

    def room(self, name: str) -> Room:
        for room in self.rooms:
            if room.name == name:
                return room
        raise UnknownNameError("room", name, self.room_names)

    def room_at(self, x: float, y: float) -> Room | None:
        """The room containing a point, or None outside every room."""
        for room in self.rooms:
            if room.contains(x, y):
                return room
        return None

    def doors_of(self, room_name: str) -> list[Door]:
        return [d for d in self.doors if room_name in d.connects]

    @cached_property
    def openings(self) -> tuple[Door, ...]:
        """Open-plan passages: where an ``open`` room meets a neighbour along a shared side
        that no wall covers (the living room that runs into the meeting room), one
        :class:`Door` per pair of rooms, named ``opening <a>/<b>``, at the middle of the
        longest free stretch of the shared side with that stretch's length as its width.
        Rooms a door joins get no opening (the free stretch there is the doorway).
        Doors are doorways with frames; openings are how people walk between open rooms."""
        out = []
        rooms = self.rooms
        by_door = {frozenset(d.connects) for d in self.doors}
        for i, a in enumerate(rooms):
            for b in rooms[i + 1:]:
                if not (a.open or b.open) or frozenset((a.name, b.name)) in by_door:
                    continue  # closed rooms, or rooms a doorway joins
                passage = _shared_free_side(a, b, self.walls)
                if passage is not None:
                    centre, width = passage
                    out.append(Door(f"opening {a.name}/{b.name}", centre, width, (a.name, b.name)))
        return tuple(out)

    def passages_of(self, room_name: str) -> list[Door]:
        """The ways into a room: its doors, then its open-plan :attr:`openings`."""
        return self.doors_of(room_name) + [d for d in self.openings if room_name in d.connects]

    def room_graph(self, openings: bool = True) -> "nx.Graph":
        """The rooms joined by the ways a person walks between them: the one room graph.

        A networkx graph with a node per room (attribute ``centre``) and an edge per pair of
        rooms joined by a door or, with ``openings``, an open-plan :attr:`openings` passage;
        edge attributes: ``door`` (the :class:`Door`), ``kind`` (``"door"`` or ``"opening"``)
        and ``weight`` (metres from one room's centre through the passage's centre to the
        other's). Doors to ``outside`` are left out (the robot never leaves the home); of two
        doors between the same rooms, the shorter way is kept. Built fresh on each call (a
        floor plan is immutable; callers that route often keep the graph).
        """
        import networkx as nx

        graph = nx.Graph()
        for room in self.rooms:
            graph.add_node(room.name, centre=tuple(room.centre))
        passages = [(d, "door") for d in self.doors]
        if openings:
            passages += [(d, "opening") for d in self.openings]
        for door, kind in passages:
            a, b = door.connects
            if a not in graph or b not in graph:
                continue
            ca, cb = (np.asarray(graph.nodes[n]["centre"]) for n in (a, b))
            c = np.asarray(door.centre)
            weight = float(np.linalg.norm(ca - c) + np.linalg.norm(cb - c))
            if graph.has_edge(a, b) and graph[a][b]["weight"] <= weight:
                continue
            graph.add_edge(a, b, door=door, kind=kind, weight=weight)
        return graph

    def room_faced(self, pose: Pose2D, side: str | None = None) -> str | None:
        """The room joined to the one at ``pose`` through the passage a person standing there
        would mean: on ``side`` (``"left"``/``"right"`` of the heading) when given, the one
        most nearly square to that side, else the most nearly ahead (nearer passages first
        among equals). None when ``pose`` is in no
        room or no passage leads on (on the side said)."""
        import math

        from assistant.geometry import wrap_angle

        here = self.room_at(pose.x, pose.y)
        if here is None:
            return None
        graph = self.room_graph()
        options = []
        for other in graph.neighbors(here.name):
            door = graph.edges[here.name, other]["door"]
            dx, dy = door.centre[0] - pose.x, door.centre[1] - pose.y
            bearing = wrap_angle(math.atan2(dy, dx) - pose.theta)
            if (side == "left" and bearing <= 0.0) or (side == "right" and bearing >= 0.0):
                continue
            want = {"left": math.pi / 2, "right": -math.pi / 2}.get(side, 0.0)
            options.append((abs(bearing - want) + 0.1 * math.hypot(dx, dy), other))
        return min(options)[1] if options else None

    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` of rooms and walls, metres."""
        pts = [r.polygon_array for r in self.rooms] + [w.polygon_array for w in self.walls]
        allpts = np.vstack(pts)
        return (*allpts.min(axis=0), *allpts.max(axis=0))


@dataclass(frozen=True)
class FurnitureItem:
    """A piece of furniture placed in a scene.

    ``yaw_rad`` is the model's placement angle; ``facing_rad`` its functional front (None for
    tables). ``length`` of the model runs along ``yaw_rad``.
    """

    id: str
    model: str
    x: float
    y: float
    yaw_rad: float
    facing_rad: float | None
    room: str

    @property
    def spec(self) -> FurnitureModel:
        return load_catalogue().model(self.model)

    @property
    def category(self) -> str:
        return self.spec.category

    @property
    def word(self) -> str:
        return self.spec.word

    @property
    def pose(self) -> Pose2D:
        return Pose2D(self.x, self.y, self.yaw_rad)

    @property
    def height_m(self) -> float:
        return self.spec.height_m

    def footprint_polygon(self) -> np.ndarray:
        """Corners (4, 2) of the model's bounding rectangle on the floor (metres)."""
        spec = self.spec
        return rectangle(self.pose, spec.length_m, spec.width_m)


@dataclass(frozen=True)
class PlacedObject:
    """A target object lying on a piece of furniture at ``(x, y)`` metres."""

    name: str
    on: str  # furniture id
    x: float
    y: float


@dataclass(frozen=True)
class Scene:
    name: str
    furniture: tuple[FurnitureItem, ...]
    objects: tuple[PlacedObject, ...] = ()

    def item(self, furniture_id: str) -> FurnitureItem:
        for item in self.furniture:
            if item.id == furniture_id:
                return item
        raise UnknownNameError("furniture", furniture_id, [f.id for f in self.furniture])

    def object(self, name: str) -> PlacedObject:
        for obj in self.objects:
            if obj.name == name:
                return obj
        raise UnknownNameError("object", name, [o.name for o in self.objects])

    def object_height_m(self, obj: PlacedObject) -> float:
        """Height (metres) of the surface the object lies on."""
        return self.item(obj.on).height_m


@dataclass(frozen=True)
class World:
    name: str
    floorplan: Floorplan
    start: Pose2D
    start_heading_rad: float  # as written in the file (``start.theta`` is wrapped)
    scenes: dict[str, Scene]
    title: str = ""
    source: str | None = field(default=None, compare=False)

    def scene(self, name: str = "original") -> Scene:
        try:
            return self.scenes[name]
        except KeyError:
            raise UnknownNameError("scene", name, self.scenes) from None

    def to_dict(self, scene: str = "original") -> dict:
        """The ``assistant world NAME --json`` object (see DESIGN.md's command-line contract)."""
        sc = self.scene(scene)
        return {
            "world": self.name,
            "scene": sc.name,
            "start": {"x": self.start.x, "y": self.start.y, "heading": self.start_heading_rad},
            "rooms": [
                {"name": r.name, "polygon": [list(p) for p in r.polygon], "open": r.open}
                for r in self.floorplan.rooms
            ],
            "doors": [
                {"name": d.name, "x": d.centre[0], "y": d.centre[1], "width": d.width_m,
                 "connects": list(d.connects)}
                for d in self.floorplan.doors
            ],
            "walls": [w.as_list() for w in self.floorplan.walls],
            "furniture": [
                {"id": f.id, "model": f.model, "category": f.category, "x": f.x, "y": f.y,
                 "yaw": f.yaw_rad, "facing": f.facing_rad, "room": f.room,
                 "length": f.spec.length_m, "width": f.spec.width_m, "height": f.spec.height_m}
                for f in sc.furniture
            ],
            "objects": [
                {"name": o.name, "on": o.on, "x": o.x, "y": o.y,
                 "z": sc.object_height_m(o), "room": sc.item(o.on).room}
                for o in sc.objects
            ],
        }

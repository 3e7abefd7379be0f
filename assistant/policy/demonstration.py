"""Demonstrations (dissertation 5.5.1–5.5.2): an RDT node, the robot's trajectory and the
environment model the teacher saw, as one JSON file.

File format (``*.json``, UTF-8, written atomically)::

    {"format": "assistant-demonstration/1",
     "rdt": "couch-front-table", "world": "training-home", "scene": "original",
     "reference_id": "couch_1", "target_id": "coffeetable_1",     # null when none
     "teacher": "scripted-keyboard",                              # or "keyboard" (a person)
     "goal": [x, y, theta] or null,                               # the teacher's intended pose
     "frames": [{"t": 0.0, "pose": [x, y, theta], "key": null}, ...],
     "environment": [{"id": "couch_1", "name": "couch", "category": "couch",
                      "kind": "short_term", "polygon": [[x, y], ...],
                      "orientation": -1.571 or null, "room": "living room"}, ...]}

Metres and radians (counter-clockwise from +x) in the world frame; ``t`` is simulated seconds
since the node began; ``key`` is the key pressed before that frame. The environment is stored
once because it is static during a demonstration (the furniture does not move while the robot
drives); it holds the furniture, the rooms (``room:<name>``) and the walls (``wall:<i>``) as
polygons, so a model can rebuild the entities on any grid.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from assistant.errors import DataFileError
from assistant.fileio import atomic_write_text
from assistant.geometry import GridMap, Pose2D
from assistant.policy.rdt import RDT

FORMAT = "assistant-demonstration/1"
ENTITY_KINDS = ("long_term", "short_term")


@dataclass(frozen=True)
class EnvironmentEntity:
    """One thing of the environment model as a floor polygon (metres)."""

    id: str
    name: str
    category: str | None
    kind: str  # "long_term" (rooms, walls) or "short_term" (furniture)
    polygon: tuple[tuple[float, float], ...]
    orientation: float | None = None  # functional front, radians, or None
    room: str | None = None

    def polygon_array(self) -> np.ndarray:
        return np.asarray(self.polygon, dtype=float)

    def to_entity(self, grid: GridMap):
        """The :class:`~assistant.world.Entity` on ``grid``."""
        from assistant.world import Entity, EntityKind

        kind = EntityKind.LONG_TERM if self.kind == "long_term" else EntityKind.SHORT_TERM
        return Entity.from_polygon(self.id, self.name, kind, self.polygon_array(), grid,
                                   self.orientation, category=self.category, room=self.room)

    def to_dict(self) -> dict:
        return {"id": self.id, "name": self.name, "category": self.category, "kind": self.kind,
                "polygon": [[round(x, 4), round(y, 4)] for x, y in self.polygon],
                "orientation": None if self.orientation is None else round(self.orientation, 6),
                "room": self.room}


@dataclass(frozen=True)
class Frame:
    """The robot at one moment: ``t`` seconds, ``pose`` (world frame), the key before it."""

    t: float
    pose: Pose2D
    key: str | None = None

    def to_dict(self) -> dict:
        return {"t": round(self.t, 4), "pose": _pose_list(self.pose), "key": self.key}


@dataclass(frozen=True, eq=False)
class Demonstration:
    """One demonstration of an RDT node."""

    rdt: str
    world: str
    scene: str
    reference_id: str | None
    target_id: str | None
    frames: tuple[Frame, ...]
    environment: tuple[EnvironmentEntity, ...]
    goal: Pose2D | None = None
    teacher: str = "keyboard"
    path: str | None = field(default=None, compare=False)

    @property
    def first_pose(self) -> Pose2D:
        return self.frames[0].pose

    @property
    def last_pose(self) -> Pose2D:
        return self.frames[-1].pose

    def entity(self, ident: str | None) -> EnvironmentEntity | None:
        if ident is None:
            return None
        for item in self.environment:
            if item.id == ident:
                return item
        raise KeyError(f"{ident!r} is not in the demonstration's environment")

    def to_dict(self) -> dict:
        return {"format": FORMAT, "rdt": self.rdt, "world": self.world, "scene": self.scene,
                "reference_id": self.reference_id, "target_id": self.target_id,
                "teacher": self.teacher, "goal": None if self.goal is None else _pose_list(self.goal),
                "frames": [f.to_dict() for f in self.frames],
                "environment": [e.to_dict() for e in self.environment]}

    def to_json(self) -> str:
        """JSON with one line per key, per frame and per entity (diff-friendly, compact)."""
        data = self.to_dict()
        lines = []
        for key, value in data.items():
            if key in ("frames", "environment"):
                items = ",\n  ".join(json.dumps(v, separators=(", ", ": ")) for v in value)
                lines.append(f'"{key}": [\n  {items}\n ]' if value else f'"{key}": []')
            else:
                lines.append(f'"{key}": {json.dumps(value)}')
        return "{" + ",\n ".join(lines) + "}\n"

    def save(self, path: str | Path) -> Path:
        """Write the demonstration atomically (JSON)."""
        return atomic_write_text(path, self.to_json())

    @classmethod
    def load(cls, path: str | Path) -> "Demonstration":
        """Read and validate a demonstration file; errors name the file and the key."""
        path = str(path)
        try:
            with open(path, encoding="utf-8") as handle:
                data = json.load(handle)
        except OSError as error:
            raise DataFileError(path, "", f"cannot read it ({error.strerror or error})") from error
        except json.JSONDecodeError as error:
            raise DataFileError(path, f"line {error.lineno}", f"not valid JSON: {error.msg}") from error
        return cls.from_dict(data, path)

    @classmethod
    def from_dict(cls, data, path: str = "<demonstration>") -> "Demonstration":
        if not isinstance(data, dict):
            raise DataFileError(path, "", "expected a JSON object at the top level")
        fmt = data.get("format", FORMAT)
        if fmt != FORMAT:
            raise DataFileError(path, "format", f"unsupported format {fmt!r}; expected {FORMAT!r}")
        rdt = _text(data, "rdt", path)
        try:
            RDT.parse(rdt)
        except Exception as error:
            raise DataFileError(path, "rdt", str(error)) from error
        world = _text(data, "world", path)
        scene = _text(data, "scene", path)
        reference_id = _text(data, "reference_id", path, optional=True)
        target_id = _text(data, "target_id", path, optional=True)
        teacher = _text(data, "teacher", path, optional=True) or "keyboard"
        goal = None if data.get("goal") is None else _pose(data["goal"], path, "goal")
        frames_raw = data.get("frames")
        if not isinstance(frames_raw, list) or not frames_raw:
            raise DataFileError(path, "frames", "expected a non-empty list of {t, pose} frames")
        frames = []
        last_t = -math.inf
        for i, item in enumerate(frames_raw):
            where = f"frames[{i}]"
            if not isinstance(item, dict):
                raise DataFileError(path, where, "expected an object with t and pose")
            t = _number(item, "t", path, where)
            if t < last_t:
                raise DataFileError(path, f"{where}.t", f"time goes back ({t} after {last_t})")
            last_t = t
            key = item.get("key")
            if key is not None and not isinstance(key, str):
                raise DataFileError(path, f"{where}.key", f"expected a string or null, got {key!r}")
            frames.append(Frame(t, _pose(item.get("pose"), path, f"{where}.pose"), key))
        env_raw = data.get("environment")
        if not isinstance(env_raw, list):
            raise DataFileError(path, "environment", "expected a list of entities")
        environment = []
        seen = set()
        for i, item in enumerate(env_raw):
            where = f"environment[{i}]"
            if not isinstance(item, dict):
                raise DataFileError(path, where, "expected an object")
            ident = _text(item, "id", path, where=where)
            if ident in seen:
                raise DataFileError(path, f"{where}.id", f"duplicate entity id {ident!r}")
            seen.add(ident)
            kind = item.get("kind", "short_term")
            if kind not in ENTITY_KINDS:
                raise DataFileError(path, f"{where}.kind", f"expected one of {ENTITY_KINDS}, got {kind!r}")
            poly = item.get("polygon")
            try:
                arr = np.asarray(poly, dtype=float)
                ok = arr.ndim == 2 and arr.shape[1] == 2 and len(arr) >= 3 and np.isfinite(arr).all()
            except (TypeError, ValueError):
                ok = False
            if not ok:
                raise DataFileError(path, f"{where}.polygon", "expected at least three [x, y] points (metres)")
            orientation = item.get("orientation")
            if orientation is not None:
                orientation = _number(item, "orientation", path, where)
            environment.append(EnvironmentEntity(
                ident, _text(item, "name", path, where=where) if "name" in item else ident,
                _text(item, "category", path, optional=True, where=where), kind,
                tuple((float(x), float(y)) for x, y in arr), orientation,
                _text(item, "room", path, optional=True, where=where)))
        for key, ident in (("reference_id", reference_id), ("target_id", target_id)):
            if ident is not None and ident not in seen:
                raise DataFileError(path, key, f"{ident!r} is not an entity of the environment")
        return cls(rdt, world, scene, reference_id, target_id, tuple(frames), tuple(environment),
                   goal, teacher, path)


def load_demonstrations(directory: str | Path, rdt: str | None = None) -> list[Demonstration]:
    """Every ``*.json`` demonstration under ``directory`` (sorted by path), optionally of one RDT."""
    out = []
    for path in sorted(Path(directory).rglob("*.json")):
        demo = Demonstration.load(path)
        if rdt is None or demo.rdt == rdt:
            out.append(demo)
    return out


def environment_from_world(world, scene: str) -> tuple[EnvironmentEntity, ...]:
    """The ground-truth environment model of a world's scene (oracle perception): its furniture
    footprints, rooms and walls."""
    sc = world.scene(scene)
    out = []
    for item in sc.furniture:
        out.append(EnvironmentEntity(item.id, item.word, item.category, "short_term",
                                     tuple(map(tuple, np.asarray(item.footprint_polygon(), float))),
                                     item.facing_rad, item.room))
    for room in world.floorplan.rooms:
        out.append(EnvironmentEntity(f"room:{room.name}", "room", "room", "long_term",
                                     tuple(map(tuple, room.polygon_array)), None, room.name))
    for i, wall in enumerate(world.floorplan.walls):
        out.extend(wall_pieces(i, wall.polygon_array, world.floorplan.rooms))
    return tuple(out)


def wall_pieces(index: int, polygon: np.ndarray, rooms) -> list[EnvironmentEntity]:
    """A wall cut into the pieces that bound each room (``wall:<i>:<room>``): "the front
    wall" is a wall of the room one is in, not the whole side of the house. The cut is by
    bounding boxes (the floor plans' walls are axis-aligned boxes)."""
    pieces = []
    wx0, wy0 = polygon.min(axis=0)
    wx1, wy1 = polygon.max(axis=0)
    for room in rooms:
        rx0, ry0 = room.polygon_array.min(axis=0) - 0.1
        rx1, ry1 = room.polygon_array.max(axis=0) + 0.1
        x0, y0, x1, y1 = max(wx0, rx0), max(wy0, ry0), min(wx1, rx1), min(wy1, ry1)
        if x1 - x0 <= 1e-6 or y1 - y0 <= 1e-6 or max(x1 - x0, y1 - y0) < 0.3:
            continue
        box = ((x0, y0), (x1, y0), (x1, y1), (x0, y1))
        pieces.append(EnvironmentEntity(f"wall:{index}:{room.name}", "wall", "wall", "long_term",
                                        box, None, room.name))
    return pieces


def environment_grid(environment, resolution_m: float = 0.1, margin_m: float = 0.5) -> GridMap:
    """A grid covering every polygon of an environment model."""
    pts = np.concatenate([e.polygon_array() for e in environment])
    return GridMap.covering(*pts.min(axis=0), *pts.max(axis=0), resolution_m=resolution_m,
                            margin_m=margin_m)


# --------------------------------------------------------------------------- helpers

def _pose_list(pose: Pose2D) -> list[float]:
    return [round(float(pose.x), 4), round(float(pose.y), 4), round(float(pose.theta), 6)]


def _pose(value, path: str, where: str) -> Pose2D:
    try:
        arr = [float(v) for v in value]
    except (TypeError, ValueError):
        arr = []
    if len(arr) != 3 or not all(math.isfinite(v) for v in arr):
        raise DataFileError(path, where, f"expected [x, y, theta] (metres, radians), got {value!r}")
    return Pose2D(*arr)


def _number(data: dict, key: str, path: str, where: str) -> float:
    value = data.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise DataFileError(path, f"{where}.{key}", f"expected a number, got {value!r}")
    return float(value)


def _text(data: dict, key: str, path: str, optional: bool = False, where: str = "") -> str | None:
    value = data.get(key)
    name = f"{where}.{key}" if where else key
    if value is None:
        if optional:
            return None
        raise DataFileError(path, name, "missing")
    if not isinstance(value, str) or not value:
        raise DataFileError(path, name, f"expected a non-empty string, got {value!r}")
    return value

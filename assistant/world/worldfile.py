"""World files (YAML): load in stages, validating each section before building; write back.

Format (metres, radians counter-clockwise from +x)::

    name: apartment
    title: A two-room apartment with a hallway
    start: {x: 5.0, y: 0.0, heading: 3.142}
    rooms:
      - {name: hallway, polygon: [[-5.0, -1.385], [7.18, -1.385], ...], open: true}
    walls:                      # axis-aligned blocks: [xmin, ymin, xmax, ymax]
      - [-5.0, 1.258, 2.023, 1.308]
    doors:
      - {name: living room door, centre: [2.633, 1.283], width: 1.219,
         connects: [hallway, living room]}
    scenes:
      original:
        furniture:
          - {id: couch_1, model: couch, x: 4.5, y: 3.0, yaw: 1.571, facing: 1.571,
             room: living room}
        objects:
          - {name: laptop, on: dinnertable_1, x: 4.5, y: 7.0}
      modified: {...}

Every problem is one :class:`WorldFileError` naming file, section, index and key, e.g.
``apartment.yaml: scenes.original.furniture[3].yaw: expected a number, got 'north'``.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable, Mapping
from importlib import resources
from pathlib import Path
from typing import Any

import yaml

from assistant.errors import DataFileError, UnknownNameError
from assistant.fileio import atomic_write_text, read_user_text, read_yaml
from assistant.geometry import Pose2D, angles_close
from assistant.world.catalogue import load_catalogue
from assistant.world.sanity import geometry_problems
from assistant.world.model import (
    Door,
    Floorplan,
    FurnitureItem,
    PlacedObject,
    Room,
    Scene,
    Wall,
    World,
)


class WorldFileError(DataFileError):
    """A world file that does not follow the format; names file, section, index and key."""


# --- schema --------------------------------------------------------------------------------

def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _text(value: Any) -> bool:
    return isinstance(value, str) and value.strip() != ""


def _point(value: Any) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(_number(v) for v in value)


def _polygon(value: Any) -> bool:
    return isinstance(value, list) and len(value) >= 3 and all(_point(p) for p in value)


def _box(value: Any) -> bool:
    return (isinstance(value, list) and len(value) == 4 and all(_number(v) for v in value)
            and value[0] < value[2] and value[1] < value[3])


def _pair_of_names(value: Any) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(_text(v) for v in value)


def _optional_number(value: Any) -> bool:
    return value is None or _number(value)


def _boolean(value: Any) -> bool:
    return isinstance(value, bool)


_EXPECT: dict[Callable[[Any], bool], str] = {
    _number: "a number",
    _text: "a non-empty text",
    _point: "a point [x, y] in metres",
    _polygon: "a polygon: a list of at least three [x, y] points",
    _box: "a wall block [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax",
    _pair_of_names: "two names",
    _optional_number: "a number or null",
    _boolean: "true or false",
}

# key → (check, required)
#: largest world file read (a home's plan is a few kilobytes; /dev/zero would fill the memory)
MAX_WORLD_FILE_BYTES = 10_000_000

ROOM_SCHEMA = {"name": (_text, True), "polygon": (_polygon, True), "open": (_boolean, False)}
DOOR_SCHEMA = {"name": (_text, True), "centre": (_point, True), "width": (_number, True),
               "connects": (_pair_of_names, True)}
FURNITURE_SCHEMA = {"id": (_text, True), "model": (_text, True), "x": (_number, True),
                    "y": (_number, True), "yaw": (_number, True),
                    "facing": (_optional_number, False), "room": (_text, True)}
OBJECT_SCHEMA = {"name": (_text, True), "on": (_text, True), "x": (_number, True),
                 "y": (_number, True)}
START_SCHEMA = {"x": (_number, True), "y": (_number, True), "heading": (_number, True)}
TOP_SCHEMA = {"name": (_text, True), "title": (_text, False), "start": (None, True),
              "rooms": (None, True), "walls": (None, True), "doors": (None, False),
              "scenes": (None, True)}
SCENE_SCHEMA = {"furniture": (None, True), "objects": (None, False)}


class _Checker:
    def __init__(self, path: str):
        self.path = path

    def fail(self, where: str, problem: str) -> None:
        raise WorldFileError(self.path, where, problem)

    def mapping(self, value: Any, where: str, schema: Mapping[str, tuple]) -> dict:
        if not isinstance(value, dict):
            self.fail(where, f"expected a mapping of keys, got {_show(value)}")
        for key in value:
            if key not in schema:
                hint = difflib.get_close_matches(str(key), list(schema), n=1)
                suggestion = f" (did you mean {hint[0]!r}?)" if hint else ""
                self.fail(f"{where}.{key}" if where else str(key),
                          f"unknown key{suggestion}; expected keys: {', '.join(schema)}")
        for key, (check, required) in schema.items():
            here = f"{where}.{key}" if where else key
            if key not in value:
                if required:
                    self.fail(here, "missing")
                continue
            if check is not None and not check(value[key]):
                self.fail(here, f"expected {_EXPECT[check]}, got {_show(value[key])}")
        return value

    def sequence(self, value: Any, where: str) -> list:
        if value is None:
            return []
        if not isinstance(value, list):
            self.fail(where, f"expected a list, got {_show(value)}")
        return value


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


# --- loading -------------------------------------------------------------------------------

def world_directory() -> Path:
    """Folder of the packaged world files."""
    return Path(str(resources.files("assistant.world") / "data" / "worlds"))


def world_names() -> list[str]:
    """Names of the packaged worlds (the four study homes and the training home)."""
    return sorted(p.stem for p in world_directory().glob("*.yaml"))


def resolve_world_path(name_or_path: str | Path) -> Path:
    """A packaged world's file by name, or a path to a world file."""
    candidate = Path(name_or_path)
    if candidate.suffix in (".yaml", ".yml") or candidate.exists():
        if not candidate.exists():
            raise WorldFileError(str(candidate), "", "no such file")
        return candidate
    path = world_directory() / f"{name_or_path}.yaml"
    if not path.exists():
        raise UnknownNameError("world", str(name_or_path), world_names())
    return path


def load_world(name_or_path: str | Path) -> World:
    """Load a packaged world by name (``apartment``) or a world file by path."""
    path = resolve_world_path(name_or_path)
    try:
        text = read_user_text(path, MAX_WORLD_FILE_BYTES, "world file")
    except (OSError, UnicodeDecodeError) as error:
        raise WorldFileError(str(path), "", f"cannot read: {error}") from error
    return parse_world(text, source=str(path))


def parse_world(text: str, source: str = "<world>") -> World:
    """Validate a world file's text section by section, then build the :class:`World`."""
    label = Path(source).name if source and not source.startswith("<") else source
    check = _Checker(label)
    try:
        data = read_yaml(text)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark is not None else ""
        raise WorldFileError(label, where, f"not valid YAML: {getattr(error, 'problem', error)}") from None
    check.mapping(data, "", TOP_SCHEMA)
    start = check.mapping(data["start"], "start", START_SCHEMA)  # stage 1: start pose
    floorplan = _parse_floorplan(data, check)  # stage 2: rooms, walls, doors
    # stage 3: scenes (furniture, then the objects on it)
    if not isinstance(data["scenes"], dict) or not data["scenes"]:
        check.fail("scenes", "expected a mapping of scene name → furniture and objects")
    room_names = set(floorplan.room_names)
    scenes = {str(name): _parse_scene(str(name), raw, room_names, check)
              for name, raw in data["scenes"].items()}
    world = World(
        name=data["name"],
        title=data.get("title", ""),
        floorplan=floorplan,
        start=Pose2D(start["x"], start["y"], start["heading"]),
        start_heading_rad=float(start["heading"]),
        scenes=scenes,
        source=source,
    )
    # stage 4: sizes and places (a house, not just valid YAML)
    problems = geometry_problems(world)
    if problems:
        where, problem = problems[0]
        more = f" (and {len(problems) - 1} more problem{'s' * (len(problems) > 2)})" if len(problems) > 1 else ""
        check.fail(where, problem + more)
    return world


def _parse_floorplan(data: dict, check: "_Checker") -> Floorplan:
    """The ``rooms``, ``walls`` and ``doors`` sections as a :class:`Floorplan`."""
    rooms: list[Room] = []
    for i, raw in enumerate(check.sequence(data["rooms"], "rooms")):
        r = check.mapping(raw, f"rooms[{i}]", ROOM_SCHEMA)
        if r["name"] in [room.name for room in rooms]:
            check.fail(f"rooms[{i}].name", f"room {r['name']!r} is listed twice")
        rooms.append(Room(r["name"], tuple(tuple(float(c) for c in p) for p in r["polygon"]),
                          bool(r.get("open", False))))
    if not rooms:
        check.fail("rooms", "a world needs at least one room")
    room_names = {room.name for room in rooms}
    walls: list[Wall] = []
    for i, raw in enumerate(check.sequence(data["walls"], "walls")):
        if not _box(raw):
            check.fail(f"walls[{i}]", f"expected {_EXPECT[_box]}, got {_show(raw)}")
        walls.append(Wall(*(float(v) for v in raw)))
    doors: list[Door] = []
    for i, raw in enumerate(check.sequence(data.get("doors"), "doors")):
        d = check.mapping(raw, f"doors[{i}]", DOOR_SCHEMA)
        for j, name in enumerate(d["connects"]):
            if name not in room_names and name != "outside":
                check.fail(f"doors[{i}].connects[{j}]",
                           f"unknown room {name!r}; rooms: {', '.join(sorted(room_names))} (or 'outside')")
        if d["width"] <= 0:
            check.fail(f"doors[{i}].width", "expected a positive width in metres")
        doors.append(Door(d["name"], (float(d["centre"][0]), float(d["centre"][1])),
                          float(d["width"]), (d["connects"][0], d["connects"][1])))
    return Floorplan(tuple(rooms), tuple(walls), tuple(doors))


def _parse_scene(scene_name: str, raw_scene, room_names: set[str], check: "_Checker") -> Scene:
    """One scene: its furniture (models, rooms, facings checked), then the objects on it."""
    base = f"scenes.{scene_name}"
    check.mapping(raw_scene, base, SCENE_SCHEMA)
    catalogue = load_catalogue()
    furniture: list[FurnitureItem] = []
    for i, raw in enumerate(check.sequence(raw_scene["furniture"], f"{base}.furniture")):
        furniture.append(_parse_furniture(raw, f"{base}.furniture[{i}]", furniture, room_names, check))
    ids = {item.id for item in furniture}
    objects: list[PlacedObject] = []
    for i, raw in enumerate(check.sequence(raw_scene.get("objects"), f"{base}.objects")):
        where = f"{base}.objects[{i}]"
        o = check.mapping(raw, where, OBJECT_SCHEMA)
        if o["on"] not in ids:
            check.fail(f"{where}.on", f"no furniture {o['on']!r} in scene {scene_name!r}")
        if o["name"] not in catalogue.objects:
            check.fail(f"{where}.name", f"unknown object {o['name']!r}; objects: {', '.join(sorted(catalogue.objects))}")
        objects.append(PlacedObject(o["name"], o["on"], float(o["x"]), float(o["y"])))
    return Scene(scene_name, tuple(furniture), tuple(objects))


def _parse_furniture(raw, where: str, earlier: list[FurnitureItem], room_names: set[str],
                     check: "_Checker") -> FurnitureItem:
    """One furniture entry: a known model, a known room, a unique id, a facing that agrees
    with the model's front (derived from the yaw when left out)."""
    catalogue = load_catalogue()
    f = check.mapping(raw, where, FURNITURE_SCHEMA)
    if f["model"] not in catalogue.models:
        hint = difflib.get_close_matches(f["model"], list(catalogue.models), n=1)
        check.fail(f"{where}.model", f"unknown model {f['model']!r}"
                   + (f" (did you mean {hint[0]!r}?)" if hint else "")
                   + f"; models: {', '.join(sorted(catalogue.models))}")
    if f["room"] not in room_names:
        check.fail(f"{where}.room", f"unknown room {f['room']!r}; rooms: {', '.join(sorted(room_names))}")
    if f["id"] in [item.id for item in earlier]:
        check.fail(f"{where}.id", f"furniture id {f['id']!r} is used twice")
    spec = catalogue.models[f["model"]]
    facing = f.get("facing")
    if spec.has_front:
        expected = f["yaw"] + spec.front_offset_rad
        if facing is None:
            facing = expected
        elif not angles_close(facing, expected, 0.02):
            check.fail(f"{where}.facing", f"a {f['model']} placed at yaw {f['yaw']} faces "
                       f"{math.remainder(expected, 2 * math.pi):.3f} rad, not {facing}")
    elif facing is not None:
        check.fail(f"{where}.facing", f"a {f['model']} has no front: write null or leave it out")
    return FurnitureItem(f["id"], f["model"], float(f["x"]), float(f["y"]), float(f["yaw"]),
                         None if facing is None else float(facing), f["room"])


# --- writing -------------------------------------------------------------------------------

def world_to_data(world: World) -> dict:
    """The plain data of a world file, in the order the format documents."""
    data: dict[str, Any] = {"name": world.name}
    if world.title:
        data["title"] = world.title
    data["start"] = {"x": world.start.x, "y": world.start.y, "heading": world.start_heading_rad}
    data["rooms"] = [{"name": r.name, "polygon": [list(p) for p in r.polygon], "open": r.open}
                     for r in world.floorplan.rooms]
    data["walls"] = [w.as_list() for w in world.floorplan.walls]
    data["doors"] = [{"name": d.name, "centre": list(d.centre), "width": d.width_m,
                      "connects": list(d.connects)} for d in world.floorplan.doors]
    data["scenes"] = {
        name: {
            "furniture": [{"id": f.id, "model": f.model, "x": f.x, "y": f.y, "yaw": f.yaw_rad,
                           "facing": f.facing_rad, "room": f.room} for f in scene.furniture],
            "objects": [{"name": o.name, "on": o.on, "x": o.x, "y": o.y} for o in scene.objects],
        }
        for name, scene in world.scenes.items()
    }
    return data


class _FlowListDumper(yaml.SafeDumper):
    """Short lists (points, wall blocks) and flat mappings in flow style, the rest in block style."""


def _represent_list(dumper: yaml.SafeDumper, value: list):
    flow = all(not isinstance(v, (dict, list)) for v in value)
    return dumper.represent_sequence("tag:yaml.org,2002:seq", value, flow_style=flow)


def _represent_dict(dumper: yaml.SafeDumper, value: dict):
    flat = all(not isinstance(v, dict) for v in value.values()) and not any(
        isinstance(v, list) and v and isinstance(v[0], dict) for v in value.values()
    )
    return dumper.represent_mapping("tag:yaml.org,2002:map", value.items(), flow_style=flat)


_FlowListDumper.add_representer(list, _represent_list)
_FlowListDumper.add_representer(dict, _represent_dict)


def dump_world(world: World) -> str:
    """The world as world-file text (loads back to an equal :class:`World`)."""
    return yaml.dump(world_to_data(world), Dumper=_FlowListDumper, sort_keys=False,
                     allow_unicode=True, width=100)


def write_world(world: World, path: str | Path) -> Path:
    """Write a world file atomically."""
    return atomic_write_text(path, dump_world(world))

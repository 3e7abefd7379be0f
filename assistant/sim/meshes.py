"""Procedural triangle meshes of the homes: furniture, target objects, walls and floor.

Every mesh is built from open3d primitives (boxes, cylinders, spheres) to the catalogue's
sizes, so that the simulated Kinect sees recognisable shapes: tables have a top and legs
(round, square or hexagonal top), chairs a seat, four legs and a back on the side opposite
their front, the couch a seat, a back and two arms, the bed a mattress with a headboard at its
head, the desk a top on two side panels with a modesty panel at its back.

Frames (metres):

* **model frame** (:func:`furniture_mesh`): x along the model's length (its placement yaw),
  y across it (its width), z up; origin on the floor at the centre of the footprint.
  The functional front is at angle ``front_offset_rad`` from +x (chairs −π/2: front towards
  −y, back rest on +y; couch 0: front towards +x, back rest on −x; bed π: the facing is the
  head→foot direction −x, so the head and headboard are at +x).
* **object frame** (:func:`object_mesh`): x along the object's length, y across, z up;
  origin at the centre of its base.
* **world frame** (:func:`wall_mesh`, :func:`scene_meshes`): the world file's x, y, z up,
  floor at z = 0.

Meshes carry vertex colours and normals (for the 3D view); the renderer ignores colours.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import open3d as o3d

from assistant.world import Wall, World, load_catalogue
from assistant.world.model import FurnitureItem, PlacedObject, Scene

__all__ = ["SceneMesh", "furniture_mesh", "object_mesh", "wall_mesh", "floor_mesh", "scene_meshes",
           "KIND_COLOURS"]

TriangleMesh = o3d.geometry.TriangleMesh

#: Default RGB colours (0–1) by kind, and a few per furniture shape, for the 3D view.
KIND_COLOURS = {
    "wall": (0.85, 0.85, 0.82),
    "floor": (0.62, 0.55, 0.45),
    "object": (0.90, 0.35, 0.20),
    "furniture": (0.55, 0.38, 0.22),
}
_SHAPE_COLOURS = {
    "round": (0.60, 0.42, 0.25),
    "square": (0.55, 0.38, 0.22),
    "hexagon": (0.50, 0.35, 0.20),
    "desk": (0.45, 0.33, 0.25),
    "chair": (0.25, 0.35, 0.65),
    "couch": (0.35, 0.45, 0.35),
    "bed": (0.75, 0.72, 0.60),
}

_TOP_THICKNESS_M = 0.035  # table and desk tops
_LEG_SIDE_M = 0.045  # square legs of tables and chairs
_LEG_INSET_M = 0.03  # from the edge of the top to the leg's outer face


@dataclass(frozen=True, eq=False)
class SceneMesh:
    """One thing of a scene as a world-frame mesh.

    ``id`` is unique in the scene (furniture id, object name, ``wall_<i>``, ``floor``);
    ``kind`` is "wall", "furniture", "object" or "floor"; ``name`` is the furniture model, the
    object name, "wall" or "floor".
    """

    id: str
    kind: str
    name: str
    mesh: TriangleMesh


# ---------------------------------------------------------------------------- primitives

def _box(cx: float, cy: float, z0: float, sx: float, sy: float, sz: float) -> TriangleMesh:
    """An axis-aligned box of size ``sx × sy × sz`` centred on (cx, cy), bottom at ``z0``."""
    box = TriangleMesh.create_box(width=sx, height=sy, depth=sz)
    box.translate((cx - sx / 2.0, cy - sy / 2.0, z0))
    return box


def _prism(cx: float, cy: float, z0: float, radius: float, height: float, sides: int) -> TriangleMesh:
    """A vertical cylinder (``sides`` ≥ 12) or regular prism, first vertex on +x, bottom at z0."""
    prism = TriangleMesh.create_cylinder(radius=radius, height=height, resolution=sides, split=1)
    prism.translate((cx, cy, z0 + height / 2.0))
    return prism


def _merge(parts: list[TriangleMesh]) -> TriangleMesh:
    mesh = TriangleMesh()
    for part in parts:
        mesh += part
    mesh.remove_duplicated_vertices()
    return mesh


def _finish(mesh: TriangleMesh, colour) -> TriangleMesh:
    mesh.compute_vertex_normals()
    mesh.paint_uniform_color(colour)
    return mesh


def _copy(mesh: TriangleMesh) -> TriangleMesh:
    return TriangleMesh(mesh)


# ---------------------------------------------------------------------------- furniture

def _legs(half_x: float, half_y: float, height: float, side: float = _LEG_SIDE_M) -> list[TriangleMesh]:
    """Four square legs whose outer faces sit at ±half_x, ±half_y (minus the inset)."""
    ox = half_x - _LEG_INSET_M - side / 2.0
    oy = half_y - _LEG_INSET_M - side / 2.0
    return [_box(sx * ox, sy * oy, 0.0, side, side, height) for sx in (-1, 1) for sy in (-1, 1)]


def _table(length: float, width: float, height: float, shape: str) -> list[TriangleMesh]:
    top_z = height - _TOP_THICKNESS_M
    if shape == "round":
        radius = min(length, width) / 2.0
        top = _prism(0.0, 0.0, top_z, radius, _TOP_THICKNESS_M, 40)
        reach = radius * math.cos(math.pi / 4) - _LEG_INSET_M  # legs under the rim, at 45°
        legs = _legs(reach + _LEG_INSET_M, reach + _LEG_INSET_M, top_z)
    elif shape == "hexagon":
        radius = length / 2.0  # corner to corner along x; flat to flat ≈ width
        top = _prism(0.0, 0.0, top_z, radius, _TOP_THICKNESS_M, 6)
        scale = width / (2.0 * radius * math.cos(math.pi / 6))
        vertices = np.asarray(top.vertices)
        vertices[:, 1] *= scale  # stretch to the catalogue's width
        top.vertices = o3d.utility.Vector3dVector(vertices)
        legs = _legs(radius * 0.55, width / 2.0 * 0.75, top_z)
    else:  # square / rectangular
        top = _box(0.0, 0.0, top_z, length, width, _TOP_THICKNESS_M)
        legs = _legs(length / 2.0, width / 2.0, top_z)
    return [top, *legs]


def _desk(length: float, width: float, height: float) -> list[TriangleMesh]:
    """A top on two full-depth side panels, with a modesty panel at the back (−y)."""
    top_z = height - _TOP_THICKNESS_M
    panel = 0.03
    sides = [_box(sx * (length / 2.0 - _LEG_INSET_M - panel / 2.0), 0.0, 0.0, panel,
                  width - 2 * _LEG_INSET_M, top_z) for sx in (-1, 1)]
    modesty = _box(0.0, -(width / 2.0 - _LEG_INSET_M - panel / 2.0), top_z * 0.35,
                   length - 2 * (_LEG_INSET_M + panel), panel, top_z * 0.65)
    top = _box(0.0, 0.0, top_z, length, width, _TOP_THICKNESS_M)
    return [top, *sides, modesty]


def _chair(length: float, width: float, height: float) -> list[TriangleMesh]:
    """Front towards −y (front_offset −π/2): the back rest stands on the +y edge."""
    seat_z, seat_t = 0.43, 0.04
    back_t = 0.04
    seat = _box(0.0, 0.0, seat_z, length, width, seat_t)
    legs = _legs(length / 2.0, width / 2.0, seat_z)
    back_y = width / 2.0 - back_t / 2.0
    back = _box(0.0, back_y, seat_z + seat_t, length, back_t, height - seat_z - seat_t)
    return [seat, *legs, back]


def _couch(length: float, width: float, height: float) -> list[TriangleMesh]:
    """Front towards +x (front_offset 0): back along the −x edge, arms at both ends (±y)."""
    seat_h = 0.42
    back_t = min(0.2, length * 0.3)
    arm_w, arm_h = 0.16, 0.62
    base = _box(back_t / 2.0, 0.0, 0.0, length - back_t, width - 2 * arm_w, seat_h)
    back = _box(-length / 2.0 + back_t / 2.0, 0.0, 0.0, back_t, width, height)
    arms = [_box(back_t / 2.0, sy * (width / 2.0 - arm_w / 2.0), 0.0, length - back_t, arm_w, arm_h)
            for sy in (-1, 1)]
    return [base, back, *arms]


def _bed(length: float, width: float, height: float) -> list[TriangleMesh]:
    """Facing (head → foot) is −x (front_offset π): the headboard stands at the +x end."""
    board_t = 0.06
    mattress_h = 0.52
    frame = _box(-board_t / 2.0, 0.0, 0.0, length - board_t, width, mattress_h)
    headboard = _box(length / 2.0 - board_t / 2.0, 0.0, 0.0, board_t, width, height)
    pillow = _box(length / 2.0 - board_t - 0.22, 0.0, mattress_h, 0.35, width * 0.7, 0.1)
    return [frame, headboard, pillow]


@lru_cache(maxsize=None)
def _furniture_mesh_cached(model_name: str) -> TriangleMesh:
    spec = load_catalogue().model(model_name)
    length, width, height = spec.length_m, spec.width_m, spec.height_m
    if spec.shape in ("round", "square", "hexagon"):
        parts = _table(length, width, height, spec.shape)
    elif spec.shape == "desk":
        parts = _desk(length, width, height)
    elif spec.shape == "chair":
        parts = _chair(length, width, height)
    elif spec.shape == "couch":
        parts = _couch(length, width, height)
    elif spec.shape == "bed":
        parts = _bed(length, width, height)
    else:  # a catalogue shape nobody has built yet: its bounding box
        parts = [_box(0.0, 0.0, 0.0, length, width, height)]
    return _finish(_merge(parts), _SHAPE_COLOURS.get(spec.shape, KIND_COLOURS["furniture"]))


def furniture_mesh(model_name: str) -> TriangleMesh:
    """The mesh of a catalogue furniture model in its model frame (see the module docstring).

    Raises :class:`~assistant.errors.UnknownNameError` (listing the models) for an unknown name.
    Returns a fresh copy the caller may transform.
    """
    return _copy(_furniture_mesh_cached(model_name))


# ---------------------------------------------------------------------------- objects

def _laptop(length: float, width: float, height: float) -> list[TriangleMesh]:
    base_t = 0.02
    screen_t = 0.012
    base = _box(0.0, 0.0, 0.0, length, width, base_t)
    screen = _box(0.0, -width / 2.0 + screen_t / 2.0, base_t, length, screen_t, height - base_t)
    screen.rotate(o3d.geometry.get_rotation_matrix_from_xyz((-0.25, 0.0, 0.0)),
                  center=(0.0, -width / 2.0, base_t))
    return [base, screen]


def _monitor(length: float, width: float, height: float) -> list[TriangleMesh]:
    foot = _box(0.0, 0.0, 0.0, length * 0.45, width, 0.015)
    neck = _box(0.0, 0.0, 0.015, 0.05, 0.03, height * 0.3)
    panel = _box(0.0, 0.0, height * 0.22, length, 0.03, height * 0.78)
    return [foot, neck, panel]


def _mug(length: float, width: float, height: float) -> list[TriangleMesh]:
    radius = min(length, width) / 2.0 * 0.8
    body = _prism(-(length / 2.0 - radius), 0.0, 0.0, radius, height, 24)
    handle = _box(radius * 0.6 + 0.01, 0.0, height * 0.25, length - 2 * radius + 0.01, 0.01, height * 0.5)
    return [body, handle]


def _statue(length: float, width: float, height: float) -> list[TriangleMesh]:
    plinth_h = 0.04
    plinth = _box(0.0, 0.0, 0.0, length, width, plinth_h)
    head_r = min(length, width) * 0.3
    body_h = height - plinth_h - 2 * head_r
    body = _prism(0.0, 0.0, plinth_h, min(length, width) * 0.28, body_h, 16)
    head = TriangleMesh.create_sphere(radius=head_r, resolution=10)
    head.translate((0.0, 0.0, plinth_h + body_h + head_r))
    return [plinth, body, head]


@lru_cache(maxsize=None)
def _object_mesh_cached(object_name: str) -> TriangleMesh:
    spec = load_catalogue().object(object_name)
    length, width, height = spec.length_m, spec.width_m, spec.height_m
    builders = {"laptop": _laptop, "monitor": _monitor, "mug": _mug, "statue": _statue}
    if object_name in builders:
        parts = builders[object_name](length, width, height)
    else:  # fork, glasses case: flat boxes of their size
        parts = [_box(0.0, 0.0, 0.0, length, width, height)]
    return _finish(_merge(parts), KIND_COLOURS["object"])


def object_mesh(object_name: str) -> TriangleMesh:
    """The mesh of a target object in its object frame (origin at the centre of its base).

    Raises :class:`~assistant.errors.UnknownNameError` for an object not in the catalogue.
    """
    return _copy(_object_mesh_cached(object_name))


# ---------------------------------------------------------------------------- walls, floor, scenes

def wall_mesh(wall: Wall) -> TriangleMesh:
    """A wall block as a box of ``Wall.HEIGHT_M`` (2 m) in the world frame."""
    mesh = _box((wall.xmin + wall.xmax) / 2.0, (wall.ymin + wall.ymax) / 2.0, 0.0,
                wall.xmax - wall.xmin, wall.ymax - wall.ymin, Wall.HEIGHT_M)
    return _finish(mesh, KIND_COLOURS["wall"])


def floor_mesh(world: World, margin_m: float = 0.5) -> TriangleMesh:
    """The floor (z = 0) as two triangles covering the floor plan's bounds plus ``margin_m``."""
    xmin, ymin, xmax, ymax = world.floorplan.bounds()
    xmin, ymin, xmax, ymax = xmin - margin_m, ymin - margin_m, xmax + margin_m, ymax + margin_m
    mesh = TriangleMesh(
        o3d.utility.Vector3dVector(np.array([[xmin, ymin, 0.0], [xmax, ymin, 0.0],
                                             [xmax, ymax, 0.0], [xmin, ymax, 0.0]])),
        o3d.utility.Vector3iVector(np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32)),
    )
    return _finish(mesh, KIND_COLOURS["floor"])


def placed_furniture_mesh(item: FurnitureItem) -> TriangleMesh:
    """A scene's furniture item in the world frame (model mesh moved to its pose)."""
    mesh = furniture_mesh(item.model)
    mesh.transform(item.pose.matrix4())
    return mesh


def placed_object_mesh(scene: Scene, obj: PlacedObject) -> TriangleMesh:
    """A target object in the world frame, standing on its furniture's top (aligned with it)."""
    support = scene.item(obj.on)
    mesh = object_mesh(obj.name)
    transform = np.eye(4)
    c, s = math.cos(support.yaw_rad), math.sin(support.yaw_rad)
    transform[:2, :2] = [[c, -s], [s, c]]
    transform[:3, 3] = [obj.x, obj.y, scene.object_height_m(obj)]
    mesh.transform(transform)
    return mesh


def scene_meshes(world: World, scene_name: str = "original", floor: bool = True) -> list[SceneMesh]:
    """Every wall, furniture item and object of a scene (and the floor) as world-frame meshes.

    Order: floor, walls (``wall_0``…), furniture (by id), objects (by name). Raises
    :class:`~assistant.errors.UnknownNameError` for an unknown scene.
    """
    scene = world.scene(scene_name)
    out: list[SceneMesh] = []
    if floor:
        out.append(SceneMesh("floor", "floor", "floor", floor_mesh(world)))
    for index, wall in enumerate(world.floorplan.walls):
        out.append(SceneMesh(f"wall_{index}", "wall", "wall", wall_mesh(wall)))
    for item in scene.furniture:
        out.append(SceneMesh(item.id, "furniture", item.model, placed_furniture_mesh(item)))
    for obj in scene.objects:
        out.append(SceneMesh(obj.name, "object", obj.name, placed_object_mesh(scene, obj)))
    return out

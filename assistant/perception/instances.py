"""Meshes of the *other* furniture instances (``data/instances.yaml``) for the cross-database
test, of the *training variants* (``data/training_variants.yaml``: furniture as homes and stores
have it beyond the study models — desks with monitors over open knee space, store-height beds
with footboards, night stands with lamps, and, as ``other``, benches and dressers, which are
none of the five categories), and size-jittered copies of the catalogue models for training.

The study homes' models come from the simulator (:func:`assistant.sim.meshes.furniture_mesh`);
the instances here are built the same way (open3d boxes and cylinders, model frame x along the
length, y across, z up, origin on the floor at the footprint centre) but differ in size and
build: slatted or framed backs, round legs, pedestal bases, arms, footboards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
import yaml

from assistant.errors import DataFileError, UnknownNameError
from assistant.world import CATEGORIES

#: catalogue convention: angle (radians) from the model's +x to its functional front
FRONT_OFFSET_RAD = {"chair": -math.pi / 2, "couch": 0.0, "bed": math.pi,
                    "small table": None, "large table": None, "other": None}
#: the instance files: the cross-database test's, and the training variants'
INSTANCE_FILES = ("instances.yaml", "training_variants.yaml")
#: what a training variant may be besides the five categories: something that is none of them
OTHER = "other"


@dataclass(frozen=True)
class Instance:
    """One furniture instance of the second database (sizes in metres)."""

    name: str
    category: str
    build: str
    length_m: float
    width_m: float
    height_m: float
    options: dict

    @property
    def front_offset_rad(self) -> float | None:
        return FRONT_OFFSET_RAD[self.category]


@lru_cache(maxsize=None)
def load_instances(file: str = "instances.yaml") -> dict[str, Instance]:
    """The instances of ``data/<file>`` (one of :data:`INSTANCE_FILES`) by name, validated;
    the training variants may also be :data:`OTHER`."""
    path = resources.files("assistant.perception") / "data" / file
    data = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
    allowed = (*CATEGORIES, OTHER) if file != "instances.yaml" else tuple(CATEGORIES)
    out: dict[str, Instance] = {}
    for name, spec in (data.get("instances") or {}).items():
        where = f"instances.{name}"
        if spec.get("category") not in allowed:
            raise DataFileError(file, f"{where}.category",
                                f"expected one of {', '.join(allowed)}, got {spec.get('category')!r}")
        if spec.get("build") not in _BUILDERS:
            raise DataFileError(file, f"{where}.build",
                                f"expected one of {', '.join(_BUILDERS)}, got {spec.get('build')!r}")
        try:
            dims = [float(spec[k]) for k in ("length", "width", "height")]
        except (KeyError, TypeError, ValueError):
            raise DataFileError(file, where, "length, width and height must be numbers") from None
        options = {k: v for k, v in spec.items() if k not in ("category", "build", "length", "width", "height")}
        out[name] = Instance(name, spec["category"], spec["build"], *dims, options)
    return out


def instance_mesh(name: str, file: str = "instances.yaml"):
    """The open3d mesh of an instance of ``data/<file>`` (model frame)."""
    import open3d as o3d

    instances = load_instances(file)
    if name not in instances:
        raise UnknownNameError("furniture instance", name, instances)
    inst = instances[name]
    parts = _BUILDERS[inst.build](inst.length_m, inst.width_m, inst.height_m, inst.options)
    mesh = o3d.geometry.TriangleMesh()
    for part in parts:
        mesh += part
    mesh.compute_vertex_normals()
    return mesh


def scaled_mesh(mesh, sx: float, sy: float, sz: float):
    """A copy of a model-frame mesh scaled along its axes (training-set jitter)."""
    import open3d as o3d

    out = o3d.geometry.TriangleMesh(mesh)
    v = np.asarray(out.vertices) * np.array([sx, sy, sz])
    out.vertices = o3d.utility.Vector3dVector(v)
    return out


# ------------------------------------------------------------------------------ builders

def _box(cx, cy, z0, sx, sy, sz):
    import open3d as o3d

    b = o3d.geometry.TriangleMesh.create_box(max(sx, 1e-3), max(sy, 1e-3), max(sz, 1e-3))
    b.translate((cx - sx / 2, cy - sy / 2, z0))
    return b


def _cyl(cx, cy, z0, radius, height, sides=16):
    import open3d as o3d

    c = o3d.geometry.TriangleMesh.create_cylinder(radius, height, sides, 1)
    c.translate((cx, cy, z0 + height / 2))
    return c


def _legs(half_x, half_y, height, style, side=0.045):
    ox, oy = half_x - 0.03 - side / 2, half_y - 0.03 - side / 2
    spots = [(sx * ox, sy * oy) for sx in (-1, 1) for sy in (-1, 1)]
    if style == "round":
        return [_cyl(x, y, 0.0, side / 2, height) for x, y in spots]
    if style == "pedestal":
        return [_cyl(0.0, 0.0, 0.0, 0.05, height), _cyl(0.0, 0.0, 0.0, min(half_x, half_y) * 0.8, 0.04, 24)]
    if style == "panel":  # two full-width end panels
        return [_box(sx * ox, 0.0, 0.0, 0.04, 2 * oy + side, height) for sx in (-1, 1)]
    return [_box(x, y, 0.0, side, side, height) for x, y in spots]


def _table(length, width, height, o):
    top_z = height - 0.035
    if o.get("top") == "round":
        top = _cyl(0.0, 0.0, top_z, 0.5, 0.035, 40)
        v = np.asarray(top.vertices) * np.array([length, width, 1.0])
        v[:, 2] = np.asarray(top.vertices)[:, 2]
        import open3d as o3d

        top.vertices = o3d.utility.Vector3dVector(v)
        reach = 0.5 * math.cos(math.pi / 4)
        legs = _legs(length * reach, width * reach, top_z, o.get("legs", "square"))
    else:
        top = _box(0.0, 0.0, top_z, length, width, 0.035)
        legs = _legs(length / 2, width / 2, top_z, o.get("legs", "square"))
    return [top, *legs]


def _chair(length, width, height, o):
    seat_z = float(o.get("seat", 0.45))
    seat_t, back_t = 0.05, 0.04
    parts = [_box(0.0, 0.0, seat_z, length, width, seat_t)]
    legs = o.get("legs", "square")
    if legs == "arms":  # upholstered: a solid base and two arms
        parts.append(_box(0.0, 0.0, 0.0, length, width, seat_z))
        parts += [_box(sx * (length / 2 - 0.06), 0.0, 0.0, 0.12, width, seat_z + 0.22) for sx in (-1, 1)]
    else:
        parts += _legs(length / 2, width / 2, seat_z, legs)
    by = width / 2 - back_t / 2
    top = height - seat_z - seat_t
    back = o.get("back", "solid")
    z0 = seat_z + seat_t
    if back == "slats":
        parts += [_box(x, by, z0, 0.06, back_t, top) for x in np.linspace(-length / 2 + 0.04, length / 2 - 0.04, 4)]
        parts.append(_box(0.0, by, height - 0.08, length, back_t, 0.08))
    elif back == "frame":
        parts += [_box(sx * (length / 2 - 0.025), by, z0, 0.05, back_t, top) for sx in (-1, 1)]
        parts.append(_box(0.0, by, height - 0.15, length, back_t, 0.15))
    elif back == "half":
        parts.append(_box(0.0, by, z0 + top * 0.35, length, back_t, top * 0.65))
        parts.append(_box(0.0, by, z0, 0.06, back_t, top * 0.35))
    else:
        parts.append(_box(0.0, by, z0, length, back_t, top))
    return parts


def _couch(length, width, height, o):
    seat = float(o.get("seat", 0.42))
    arm_h = float(o.get("arm", 0.6))
    back_t = min(0.22, length * 0.28)
    arm_w = 0.18 if arm_h > 0 else 0.0
    z0 = 0.12 if o.get("legs") else 0.0
    parts = [_box(back_t / 2, 0.0, z0, length - back_t, width - 2 * arm_w, seat - z0),
             _box(-length / 2 + back_t / 2, 0.0, z0, back_t, width, height - z0)]
    if arm_w:
        parts += [_box(back_t / 2, sy * (width / 2 - arm_w / 2), z0, length - back_t, arm_w, arm_h - z0)
                  for sy in (-1, 1)]
    if z0:
        parts += _legs(length / 2, width / 2, z0, "square", 0.05)
    return parts


def _bed(length, width, height, o):
    board_t = 0.07
    mattress = float(o.get("mattress", 0.5))
    foot = float(o.get("footboard", 0.0))
    parts = [_box(0.0, 0.0, 0.0, length - 2 * board_t, width, mattress),
             _box(length / 2 - board_t / 2, 0.0, 0.0, board_t, width, height),
             _box(length / 2 - board_t - 0.25, 0.0, mattress, 0.4, width * 0.75, 0.12)]
    parts.append(_box(-length / 2 + board_t / 2, 0.0, 0.0, board_t, width, foot if foot > 0 else mattress))
    return parts


def _lamp(cx, cy, z0, height):
    """A table lamp standing at z0: a round foot, a stem and a shade (its upper 45 %)."""
    shade = 0.45 * height
    return [_cyl(cx, cy, z0, 0.08, 0.03), _cyl(cx, cy, z0, 0.015, height - shade),
            _cyl(cx, cy, z0 + height - shade, 0.15 * height + 0.05, shade)]


def _desk(length, width, height, o):
    """A work desk, front (the sitter's side) towards −y: a top on legs or end panels with
    open knee space under it, an optional drawer pedestal at one end, a modesty panel at the
    back or a cubicle ``partition`` (its height) behind it, ``monitors`` screens (and a
    keyboard) along the back edge, and ``chairs`` office chairs pushed in at its front."""
    top_z = height - 0.03
    parts = [_box(0.0, 0.0, top_z, length, width, 0.03)]
    parts += _legs(length / 2, width / 2, top_z, o.get("legs", "square"))
    if o.get("pedestal"):
        parts.append(_box(length / 2 - 0.25, 0.0, 0.0, 0.42, width - 0.1, top_z))
    if o.get("partition"):  # a cubicle partition along the back, from the floor up
        parts.append(_box(0.0, width / 2 + 0.03, 0.05, length, 0.05, float(o["partition"]) - 0.05))
    elif o.get("modesty", True):
        parts.append(_box(0.0, width / 2 - 0.04, top_z * 0.45, length - 0.1, 0.02, top_z * 0.55))
    for x in np.linspace(-length / 4, length / 4, int(o.get("chairs", 0))):  # pushed in, facing +y
        parts += _swivel_chair(x, -width / 2 + 0.05)
    n = int(o.get("monitors", 0))
    screen_w = min(0.6, 0.9 * length / max(n, 1))
    for x in np.linspace(-(n - 1) * screen_w / 2, (n - 1) * screen_w / 2, n) if n else []:
        parts += [_box(x, width / 2 - 0.15, height, 0.22, 0.18, 0.02),
                  _box(x, width / 2 - 0.14, height, 0.05, 0.04, 0.15),
                  _box(x, width / 2 - 0.14, height + 0.1, screen_w, 0.03, float(o.get("screen", 0.38)))]
    if n:
        parts.append(_box(0.0, -width / 2 + 0.2, height, 0.45, 0.15, 0.03))
    return parts


def _swivel_chair(cx, cy):
    """An office chair at (cx, cy): a star base, a column, a seat at 0.48 m and a back on its
    −y side (the sitter faces +y, the desk)."""
    parts = [_box(cx, cy, 0.05, 0.6, 0.06, 0.05), _box(cx, cy, 0.05, 0.06, 0.6, 0.05),
             _cyl(cx, cy, 0.1, 0.03, 0.33), _box(cx, cy, 0.43, 0.48, 0.46, 0.07)]
    return parts + [_box(cx, cy - 0.24, 0.55, 0.44, 0.05, 0.5)]


def _cabinet(length, width, height, o):
    """A night stand or dresser: a closed box (on short legs, or with an open shelf under a
    drawer), a top overhanging it, a lamp on it and a mirror standing on its back edge."""
    legs = float(o.get("legs", 0.0))
    parts = [_box(0.0, 0.0, height - 0.03, length + 0.02, width + 0.02, 0.03)]
    if o.get("shelf"):  # a drawer under the top, an open shelf below on four legs
        parts += [_box(0.0, 0.0, height - 0.2, length, width, 0.17), _box(0.0, 0.0, 0.12, length, width, 0.02)]
        parts += _legs(length / 2, width / 2, height - 0.03, "square", 0.04)
    else:
        parts.append(_box(0.0, 0.0, legs, length, width, height - 0.03 - legs))
        if legs:
            parts += _legs(length / 2, width / 2, legs, "square", 0.04)
    if o.get("lamp"):
        parts += _lamp(0.0, 0.05, height, float(o["lamp"]))
    if o.get("mirror"):
        parts.append(_box(0.0, width / 2 - 0.02, height, length * 0.8, 0.03, float(o["mirror"])))
    return parts


def _bench(length, width, height, o):
    """A bench or ottoman: an upholstered block, or a padded top on four legs."""
    if o.get("legs"):
        return [_box(0.0, 0.0, height - 0.12, length, width, 0.12), *_legs(length / 2, width / 2, height - 0.12, "square")]
    return [_box(0.0, 0.0, 0.0, length, width, height)]


_BUILDERS = {"table": _table, "chair": _chair, "couch": _couch, "bed": _bed, "desk": _desk,
             "cabinet": _cabinet, "bench": _bench}

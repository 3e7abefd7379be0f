"""The furniture databases, rendered by the simulator's Kinect model (dissertation 3.7.1–3.7.2).

Each view puts ONE furniture mesh on an open floor in front of the robot (open3d
``RaycastingScene``), casts the Kinect's rays, adds the simulator's noise model
(:class:`assistant.sim.renderer.KinectNoise`), runs the detector's front half
(:func:`~assistant.perception.frame.analyse_frame`) and keeps the sample nearest the item, with
its labels (category, model, true facing and centre in the robot's floor frame).

* the **grid** views of 3.7.2: eight directions (the item's front turned 0°, 45° … 315° from
  facing the robot) × three distances (1.5, 2.5, 3.5 m to the item's centre; nearer than
  1.5 m the camera, 1.05 m up and pitched 15° down, no longer sees the floor in front of a bed);
* **random** views: distance 1.3–3.8 m, bearing within the field of view, any facing; the
  training views also scale the model along each axis (by up to ±12 %, ±20 % or ±30 %), put one
  of the target objects on half of the tables' tops (objects lie on tables in the homes), and
  in some plans stand a 2.6 m wall 2–30 cm behind the item, on the side away from the robot
  (furniture stands against walls; what the sample extraction leaves of a wall stays attached).

``study`` items are the catalogue models of the four homes (meshes from the simulator);
``other`` items are :mod:`assistant.perception.instances`. Databases are deterministic for
their seed and cached under ``cache_dir()/perception`` keyed by a hash of everything they are
made from (catalogue, instances, the syntax trees of the mesh, noise, camera and pipeline code —
:func:`code_digest` — and the parameters).
"""

from __future__ import annotations

import ast
import hashlib
import inspect
import io
import logging
import math
import textwrap
import zipfile
from dataclasses import dataclass, field, fields
from functools import lru_cache
from importlib import resources

import numpy as np

from assistant.fileio import atomic_write_bytes, cache_dir, cached
from assistant.geometry import Pose2D, wrap_angle
from assistant.perception.features import SHAPE_LENGTH, orientation_features, shape_descriptor
from assistant.perception.frame import FrameParams, analyse_frame
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame, camera_to_world_matrix, pixel_rays

DB_VERSION = "2"
GRID_DISTANCES_M = (1.5, 2.5, 3.5)
GRID_DIRECTIONS_DEG = tuple(range(0, 360, 45))


def training_intrinsics() -> CameraIntrinsics:
    """The Kinect at half resolution (320×240): the detector reads a 640×480 frame every second
    pixel anyway, so rendering only those rays gives the same clouds at a quarter of the cost."""
    k = CameraIntrinsics.kinect_v1()
    return CameraIntrinsics(k.width // 2, k.height // 2, k.fx / 2, k.fy / 2, k.cx / 2, k.cy / 2)


@dataclass(frozen=True)
class Item:
    """A furniture item of a database: name, category, front offset and how to get its mesh."""

    name: str
    category: str
    front_offset_rad: float | None
    source: str  # "study" (catalogue model), "other" (instances.yaml), "variant" (training_variants.yaml)

    def mesh(self):
        if self.source == "study":
            from assistant.sim.meshes import furniture_mesh

            return furniture_mesh(self.name)
        from assistant.perception.instances import instance_mesh

        return instance_mesh(self.name, "training_variants.yaml" if self.source == "variant" else "instances.yaml")


def study_items() -> list[Item]:
    from assistant.world import load_catalogue

    cat = load_catalogue()
    return [Item(m.name, m.category, m.front_offset_rad, "study") for m in cat.models.values()]


def other_items() -> list[Item]:
    from assistant.perception.instances import load_instances

    return [Item(i.name, i.category, i.front_offset_rad, "other") for i in load_instances().values()]


def variant_items() -> list[Item]:
    """The training variants (``data/training_variants.yaml``): training views only."""
    from assistant.perception.instances import load_instances

    return [Item(i.name, i.category, i.front_offset_rad, "variant")
            for i in load_instances("training_variants.yaml").values()]


@dataclass(frozen=True)
class RealSensorNoise:
    """What a real depth camera adds to the simulator's Kinect model (:class:`KinectNoise`,
    applied first): ``holes`` — blobs of missing depth (dark or shiny surfaces, IR
    interference) covering about ``hole_share`` of the image, from a coarse random field
    (``hole_cell_px`` cells) — plus single missing readings (``dropout``), and flying pixels:
    a reading next to a depth jump of more than ``edge_jump_m`` becomes, with probability
    ``flying``, a mix of the two sides' depths (the time-of-flight mixed pixel)."""

    hole_share: float = 0.04
    hole_cell_px: int = 12
    dropout: float = 0.02
    edge_jump_m: float = 0.1
    flying: float = 0.5

    def apply(self, depth_m: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        from assistant.sim.renderer import KinectNoise

        out = KinectNoise().apply(depth_m, rng)
        h, w = out.shape
        c = self.hole_cell_px
        field_ = rng.random((h // c + 1, w // c + 1))
        holes = np.kron(field_ < self.hole_share, np.ones((c, c), dtype=bool))[:h, :w]
        out[holes | (rng.random(out.shape) < self.dropout)] = 0.0
        right = out[:, 1:]
        left = out[:, :-1]
        jump = (np.abs(right - left) > self.edge_jump_m) & (right > 0) & (left > 0)
        mix = jump & (rng.random(jump.shape) < self.flying)
        t = rng.random(jump.shape).astype(np.float32)
        right[mix] = (t * left + (1 - t) * right)[mix]
        return out


class ItemRenderer:
    """Renders depth frames of one mesh standing on an open floor, the robot at the origin."""

    def __init__(self, mesh, intrinsics: CameraIntrinsics | None = None,
                 mount: CameraMount | None = None, noise=None):
        import open3d as o3d

        from assistant.sim.renderer import KinectNoise

        self.intrinsics = intrinsics or training_intrinsics()
        self.mount = mount or CameraMount()
        self.noise = noise if noise is not None else KinectNoise()  # or RealSensorNoise
        self._mesh = mesh
        self._rays = pixel_rays(self.intrinsics).reshape(-1, 3).astype(np.float32)
        floor = o3d.geometry.TriangleMesh(
            o3d.utility.Vector3dVector(np.array([[-20.0, -20, 0], [20, -20, 0], [20, 20, 0], [-20, 20, 0]])),
            o3d.utility.Vector3iVector(np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32)))
        self._floor = floor

    def footprint(self, pose: Pose2D, scale=(1.0, 1.0, 1.0)) -> np.ndarray:
        """(4, 2) corners of the (scaled) mesh's bounding rectangle at ``pose`` (robot frame)."""
        v = np.asarray(self._mesh.vertices)[:, :2] * np.asarray(scale[:2])
        (x0, y0), (x1, y1) = v.min(axis=0), v.max(axis=0)
        corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
        return pose.transform_points(corners)

    def _scene(self, scale, extra=None, wall=None):
        import open3d as o3d

        key = (tuple(round(float(v), 6) for v in scale), extra, wall)
        if getattr(self, "_scene_key", None) != key:
            mesh = o3d.geometry.TriangleMesh(self._mesh)
            mesh.vertices = o3d.utility.Vector3dVector(np.asarray(mesh.vertices) * np.asarray(scale))
            parts = [self._floor, mesh]
            if extra is not None:  # a target object standing on the (table) top
                from assistant.sim.meshes import object_mesh

                name, dx, dy, yaw = extra
                obj = object_mesh(name)
                top = float(np.asarray(mesh.vertices)[:, 2].max())
                obj.transform(Pose2D(dx, dy, yaw).matrix4())
                obj.translate((0.0, 0.0, top))
                parts.append(obj)
            if wall is not None:  # a wall behind the item: (outward side angle, gap in metres)
                parts.append(self._wall(mesh, *wall))
            scene = o3d.t.geometry.RaycastingScene()
            for m in parts:
                scene.add_triangles(o3d.core.Tensor(np.asarray(m.vertices, dtype=np.float32)),
                                    o3d.core.Tensor(np.asarray(m.triangles, dtype=np.uint32)))
            self._scene_key, self._scene_cache = key, scene
        return self._scene_cache

    @staticmethod
    def _wall(mesh, side_rad: float, gap_m: float, length_m: float = 5.0, height_m: float = 2.6,
              thickness_m: float = 0.1):
        """A wall box parallel to one side of the mesh's bounding box (the side whose outward
        normal points at ``side_rad``, a multiple of 90° in the model frame), ``gap_m`` off it."""
        import open3d as o3d

        v = np.asarray(mesh.vertices)
        u = np.array([math.cos(side_rad), math.sin(side_rad)])
        reach = float(np.max(v[:, :2] @ u)) + gap_m + thickness_m / 2
        box = o3d.geometry.TriangleMesh.create_box(thickness_m, length_m, height_m)
        box.translate((-thickness_m / 2, -length_m / 2, 0.0))
        box.transform(Pose2D(float(u[0] * reach), float(u[1] * reach), side_rad).matrix4())
        return box

    def render(self, item_pose: Pose2D, scale=(1.0, 1.0, 1.0), seed: int = 0,
               on_top: tuple | None = None, wall: tuple | None = None) -> DepthFrame:
        """A noisy frame with the item at ``item_pose`` (robot frame, the robot at the origin);
        ``on_top`` = (object name, x, y, yaw) puts a target object on the item's top (model
        frame); ``wall`` = (side angle, gap) stands a 2.6 m wall behind one side of it.

        The item stays put in its own frame and the camera moves (the robot's pose in the item
        frame is ``item_pose.inverse()``), so one ray-casting scene serves every unscaled view.
        """
        import open3d as o3d

        scene = self._scene(scale, on_top, wall)
        t = camera_to_world_matrix(self.mount, item_pose.inverse()).astype(np.float32)
        rays = np.empty((len(self._rays), 6), dtype=np.float32)
        rays[:, :3] = t[:3, 3]
        rays[:, 3:] = self._rays @ t[:3, :3].T
        hit = scene.cast_rays(o3d.core.Tensor(rays))
        depth = hit["t_hit"].numpy().reshape(self.intrinsics.height, self.intrinsics.width)
        depth = self.noise.apply(depth, np.random.default_rng(seed))
        return DepthFrame(depth, self.intrinsics, self.mount, Pose2D(0.0, 0.0, 0.0))


@dataclass
class Database:
    """Labelled samples: features ``X`` (n, L), shape descriptors ``S`` (n, 49), orientation
    features ``Q`` (n, L), and per
    sample the category, item name, source, true facing (floor frame, NaN for tables), true
    centre (floor frame), the view's direction (item front vs. the robot, degrees; NaN for
    random views), distance, and the angle ``alpha`` between the item's front and the
    direction to the camera (0 = the robot sees its front)."""

    X: np.ndarray
    S: np.ndarray
    Q: np.ndarray
    category: np.ndarray
    item: np.ndarray
    source: np.ndarray
    facing: np.ndarray
    centre: np.ndarray
    direction_deg: np.ndarray
    distance: np.ndarray
    alpha: np.ndarray
    missed: int = 0
    points: list = field(default_factory=list, repr=False)  # (points, normals) per sample, optional

    def __len__(self) -> int:
        return len(self.category)

    def subset(self, mask: np.ndarray) -> "Database":
        idx = np.nonzero(mask)[0]
        kw = {f.name: getattr(self, f.name)[idx] for f in fields(self)
              if isinstance(getattr(self, f.name), np.ndarray)}
        pts = [self.points[i] for i in idx] if self.points else []
        return Database(**kw, missed=0, points=pts)

    @staticmethod
    def concat(parts: list["Database"]) -> "Database":
        kw = {f.name: np.concatenate([getattr(p, f.name) for p in parts])
              for f in fields(Database) if f.name not in ("missed", "points")}
        pts = [x for p in parts for x in p.points]
        return Database(**kw, missed=sum(p.missed for p in parts), points=pts)

    def to_bytes(self) -> bytes:
        """npz bytes; the samples' points and normals (float32) travel as one ragged array."""
        buf = io.BytesIO()
        arrays = {f.name: getattr(self, f.name) for f in fields(self) if f.name not in ("missed", "points")}
        if self.points:
            arrays["points_xyz"] = np.vstack([p for p, _ in self.points]).astype(np.float32)
            arrays["points_normal"] = np.vstack([n for _, n in self.points]).astype(np.float32)
            arrays["points_offset"] = np.cumsum([0] + [len(p) for p, _ in self.points])
        np.savez_compressed(buf, missed=np.array(self.missed), **arrays)
        return buf.getvalue()

    @classmethod
    def from_bytes(cls, data: bytes) -> "Database":
        with np.load(io.BytesIO(data), allow_pickle=False) as z:
            kw = {k: z[k] for k in z.files if k != "missed" and not k.startswith("points_")}
            points = []
            if "points_offset" in z.files:
                xyz, nrm, off = z["points_xyz"].astype(float), z["points_normal"].astype(float), z["points_offset"]
                points = [(xyz[a:b], nrm[a:b]) for a, b in zip(off[:-1], off[1:])]
            return cls(**kw, missed=int(z["missed"]), points=points)


@dataclass(frozen=True)
class ViewPlan:
    """Which views to render: grid views and/or ``random_per_item`` random ones, with
    ``jitter`` scaling (0 = none), ``objects`` (the chance a random table view has one of the
    six target objects (:data:`TABLE_TOP_OBJECTS`) on top — objects lie on tables in the homes) and a seed."""

    grid: bool = True
    random_per_item: int = 0
    jitter: float = 0.0
    seed: int = 0
    distance_range_m: tuple[float, float] = (1.3, 3.8)
    bearing_max_deg: float = 22.0
    objects: float = 0.0  # chance that a table view has a target object on its top
    height_jitter: float = 1.0  # cap on the height scaling (jitter applies to length and width)
    wall: float = 0.0  # chance that a random view has a wall behind the item (homes have walls)
    wall_gap_m: tuple[float, float] = (0.02, 0.3)
    sensor: str = "kinect"  # "kinect": the simulator's KinectNoise; "real": RealSensorNoise


def _views(item: Item, plan: ViewPlan, rng: np.random.Generator):
    """(pose of the item in the robot frame, scale, direction_deg, distance, facing, on_top,
    wall)."""
    offset = item.front_offset_rad if item.front_offset_rad is not None else 0.0
    if plan.grid:
        for d in GRID_DISTANCES_M:
            for k in GRID_DIRECTIONS_DEG:
                facing = wrap_angle(math.pi + math.radians(k))  # k = 0: its front faces the robot
                yield Pose2D(d, 0.0, facing - offset), (1.0, 1.0, 1.0), float(k), d, facing, None, None
    objects = _object_names() if plan.objects > 0 else []
    for _ in range(plan.random_per_item):
        d = rng.uniform(*plan.distance_range_m)
        b = math.radians(rng.uniform(-plan.bearing_max_deg, plan.bearing_max_deg))
        facing = rng.uniform(-math.pi, math.pi)
        scale = (1.0, 1.0, 1.0)
        if plan.jitter:  # heights vary less than footprints (seats are ~0.45 m on every chair)
            jz = min(plan.jitter, plan.height_jitter)
            scale = (*rng.uniform(1 - plan.jitter, 1 + plan.jitter, 2), rng.uniform(1 - jz, 1 + jz))
        on_top = None
        if objects and item.category.endswith("table") and rng.random() < plan.objects:
            on_top = (objects[int(rng.integers(len(objects)))], float(rng.uniform(-0.15, 0.15)),
                      float(rng.uniform(-0.15, 0.15)), float(rng.uniform(-math.pi, math.pi)))
        pose = Pose2D(d * math.cos(b), d * math.sin(b), facing - offset)
        wall = None
        if plan.wall and rng.random() < plan.wall:
            # against a wall on the far side from the robot, as furniture stands in a room: of
            # the bounding box's four sides, the one facing most directly away from the camera
            cam = pose.inverse().transform_points(np.zeros((1, 2)))[0]
            away = math.atan2(-cam[1], -cam[0])
            side = round(away / (math.pi / 2)) * (math.pi / 2)
            wall = (float(wrap_angle(side)), float(rng.uniform(*plan.wall_gap_m)))
        yield pose, scale, math.nan, d, wrap_angle(facing), on_top, wall


#: the objects a view puts on a table top (``ViewPlan.objects``): the dissertation's six target
#: objects, named here rather than read from the catalogue, whose object list grows with the
#: words people use (issue 16 added ten flat everyday things): drawing from the grown list
#: changed the training views and cost Table 3-6 and Table 3-7 one view each (a bed read as a
#: large table, a low sofa as a bed; docs/perception.md, "Issue 20")
TABLE_TOP_OBJECTS = ("fork", "glasses case", "laptop", "monitor", "mug", "statue")


def _object_names() -> list[str]:
    return sorted(TABLE_TOP_OBJECTS)


def render_database(items: list[Item], plan: ViewPlan, params: FrameParams = FrameParams(),
                    keep_points: bool = True) -> Database:
    """Render every view of every item and label the sample nearest the item."""
    rows = {k: [] for k in ("X", "S", "Q", "category", "item", "source", "facing", "centre",
                            "direction_deg", "distance", "alpha")}
    points = []
    missed = 0
    for n, item in enumerate(items):
        renderer = ItemRenderer(item.mesh(), noise=RealSensorNoise() if plan.sensor == "real" else None)
        seed_base = int.from_bytes(hashlib.sha256(f"{plan.seed}:{item.name}".encode()).digest()[:4], "little")
        rng = np.random.default_rng(seed_base)
        for v, (pose, scale, direction, dist, facing, on_top, wall) in enumerate(_views(item, plan, rng)):
            frame = renderer.render(pose, scale, seed=seed_base + v, on_top=on_top, wall=wall)
            found = analyse_frame(frame, params)
            if not found.samples:
                missed += 1
                continue
            k = _item_sample(found.samples, renderer.footprint(pose, scale))
            if k is None:
                missed += 1
                continue
            sample = found.samples[k]
            has_front = item.front_offset_rad is not None
            to_camera = math.atan2(-pose.y, -pose.x)
            rows["X"].append(found.features[k])
            rows["S"].append(shape_descriptor(sample.points, sample.normals, camera_xy=found.camera_xyz[:2]))
            rows["Q"].append(orientation_features(sample.points, sample.normals, params.features))
            rows["category"].append(item.category)
            rows["item"].append(item.name)
            rows["source"].append(item.source)
            rows["facing"].append(facing if has_front else math.nan)
            rows["centre"].append(pose.xy)
            rows["direction_deg"].append(direction)
            rows["distance"].append(dist)
            rows["alpha"].append(wrap_angle(facing - to_camera) if has_front else math.nan)
            if keep_points:
                points.append((sample.points, sample.normals))
    arrays = {k: np.array(v) for k, v in rows.items()}
    if not rows["X"]:
        arrays["X"] = np.zeros((0, params.features.length))
        arrays["Q"] = np.zeros((0, params.features.length))
        arrays["S"] = np.zeros((0, SHAPE_LENGTH))
        arrays["centre"] = np.zeros((0, 2))
    return Database(**arrays, missed=missed, points=points)


def _item_sample(samples, footprint: np.ndarray, margin_m: float = 0.15) -> int | None:
    """Index of the sample with most points over the item's footprint (inflated by
    ``margin_m``), or None when no sample has a fifth of its points there."""
    from assistant.geometry import point_in_polygon

    centre = footprint.mean(axis=0)
    grown = centre + (footprint - centre) * (1 + margin_m / max(np.linalg.norm(footprint - centre, axis=1).min(), 0.05))
    best, best_count = None, 0
    for i, s in enumerate(samples):
        inside = point_in_polygon(s.points[:, :2], grown)
        count = int(inside.sum())
        if count > best_count and count >= 0.2 * len(s.points):
            best, best_count = i, count
    return best


def code_digest(*objects) -> str:
    """Hash of the *code* of modules, classes or functions: their syntax trees without
    docstrings, comments, line numbers or formatting, so an edit that changes no behaviour (a
    comment, a docstring, a reflowed line) keeps the key, and code outside ``objects`` never
    counts."""
    h = hashlib.sha256()
    for obj in objects:
        tree = ast.parse(textwrap.dedent(inspect.getsource(obj)))
        h.update(_tree_digest(tree).encode())
    return h.hexdigest()


def _tree_digest(tree: ast.AST) -> str:
    """sha256 of a syntax tree with its docstrings removed (line numbers never count)."""
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                and body and isinstance(body[0], ast.Expr)
                and isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value, str)):
            node.body = body[1:] or [ast.Pass()]
    return hashlib.sha256(ast.dump(tree, annotate_fields=False, include_attributes=False).encode()).hexdigest()


@lru_cache(maxsize=1)
def _source_fingerprint() -> str:
    """Hash (once per process) of the data and code a database is made from: the detector's front half, the
    meshes, the Kinect noise model and the camera geometry, this module's rendering code, and
    the catalogue and instance files. Only code that renders or analyses the views counts
    (the rest of the simulator's renderer, for one, does not), compared by syntax tree."""
    from assistant.perception import cloud, features, frame, instances, samples
    from assistant.robot import frames as robot_frames
    from assistant.sim import meshes, renderer

    h = hashlib.sha256(DB_VERSION.encode())
    h.update(code_digest(cloud, features, frame, instances, samples, meshes, renderer.KinectNoise,
                         robot_frames.CameraIntrinsics, robot_frames.CameraMount,
                         robot_frames.pixel_rays, robot_frames.camera_to_world_matrix,
                         robot_frames.camera_to_base_matrix,
                         training_intrinsics, ItemRenderer, RealSensorNoise, _views, _object_names,
                         render_database, _item_sample).encode())
    for pkg, name in (("assistant.world", "catalogue.yaml"), ("assistant.perception", "instances.yaml"),
                      ("assistant.perception", "training_variants.yaml")):
        h.update((resources.files(pkg) / "data" / name).read_bytes())
    return h.hexdigest()


def database_key(name: str, items: list[Item], plan: ViewPlan,
                 params: FrameParams = FrameParams()) -> str:
    """``name-<hash>``: the cache key of a database (content hash of its inputs)."""
    digest = hashlib.sha256((_source_fingerprint() + repr(plan) + repr(params)
                             + repr([(i.name, i.source) for i in items])).encode()).hexdigest()[:16]
    return f"{name}-{digest}"


def cached_database(name: str, items: list[Item], plan: ViewPlan,
                    params: FrameParams = FrameParams()) -> Database:
    """:func:`render_database`, cached under ``cache_dir()/perception`` by a content hash."""
    path = cache_dir() / "perception" / f"db-{database_key(name, items, plan, params)}.npz"

    def render() -> Database:
        from assistant.progress import working

        with working(f"rendering {len(items)} furniture items' training views ({name}; first use, cached after)"):
            return render_database(items, plan, params)

    return cached(path, render, read=_read_database,
                  write=lambda where, db: atomic_write_bytes(where, db.to_bytes()))


def _read_database(path: Path) -> Database | None:
    """The view database cached at ``path``, or None (missing, or damaged: rendered again)."""
    if not path.exists():
        return None
    try:
        return Database.from_bytes(path.read_bytes())
    except (OSError, ValueError, KeyError, TypeError, EOFError, zipfile.BadZipFile) as error:
        logging.getLogger(__name__).warning(  # a damaged cache file is rebuilt
            "ignoring unreadable view database %s (%s); rendering it again", path, error)
        return None

"""SceneView: one meshcat 3D view of a home, shared by the command line and notebooks.

Everything is drawn in the world frame (metres, z up, floor at z = 0) under these meshcat
paths (names are made path-safe: ``living room`` → ``living_room``)::

    /meshcat/world/ground                  the floor around the plan (grey)
    /meshcat/world/origin                  the world's x (red), y (green), z (blue) axes
    /meshcat/world/floors/<room>           a thin coloured slab per room (open areas lighter)
    /meshcat/world/labels/<room>           the room's name written on its floor
    /meshcat/world/walls/<wall id>         wall_0, wall_1, …
    /meshcat/world/furniture/<id>          couch_1, roundtable_1, …
    /meshcat/world/objects/<name>          mug, glasses_case, …
    /meshcat/robots/<name>/{body,heading,mast}   a robot (default name "robot")
    /meshcat/points/<name>                 point clouds
    /meshcat/paths/<name>/{line,ribbon}    paths
    /meshcat/arrows/<name>                 score maps (one mesh of flat arrows)
    /meshcat/highlights/<name>             translucent boxes / footprints
    /meshcat/labels/<name>                 text lying on the floor (draw_label)

A view records every command it draws, so :meth:`SceneView.save_html` writes a page that
needs neither a server nor a network; a server (``meshcat-server``) is only needed to watch
the scene live in a browser (:attr:`SceneView.url`).
"""

from __future__ import annotations

import math
import re
import signal
import threading
import time
from collections.abc import Sequence
from pathlib import Path

import meshcat
import meshcat.geometry as mg
import meshcat.transformations as mtf
import numpy as np

from assistant.errors import AssistantError, UnknownNameError
from assistant.fileio import atomic_write_text
from assistant.geometry import box_polygon, rectangle
from assistant.viz import shapes
from assistant.viz.clouds import cloud_arrays, depth_frame_points
from assistant.viz.colours import room_colour, score_colours, to_hex_int
from assistant.viz.html import scene_html
from assistant.viz.labels import label_object
from assistant.viz.server import MeshcatServer, RecordingWindow

__all__ = ["SceneView", "path_name"]

ROBOT_RADIUS_M = 0.25
ROBOT_BODY_HEIGHT_M = 0.3
FLOOR_TOP_M = 0.01  # room slabs run from 0 to this height, above the ground at z = 0
GROUND_DROP_M = 0.02  # the ground around the plan sits this far below z = 0

_MESH_GROUPS = {"wall": "walls", "furniture": "furniture", "object": "objects"}


def path_name(name: str) -> str:
    """A meshcat path component for a name: runs of characters other than letters, digits,
    ``_``, ``-`` and ``.`` become ``_`` (``glasses case`` → ``glasses_case``)."""
    text = re.sub(r"[^A-Za-z0-9_.-]+", "_", str(name).strip())
    return text or "_"


def _lambert(colour, opacity: float = 1.0, vertex_colours: bool = False) -> mg.MeshLambertMaterial:
    return mg.MeshLambertMaterial(color=0xFFFFFF if vertex_colours else to_hex_int(colour),
                                  opacity=opacity, vertexColors=vertex_colours)


class SceneView:
    """A meshcat 3D view of a world, point clouds, paths, score maps and highlights.

    ``SceneView()`` starts its own ``meshcat-server`` (ended by :meth:`close`, by leaving a
    ``with`` block, and at interpreter exit); ``SceneView(zmq_url="tcp://127.0.0.1:6000")``
    draws into a server someone else runs (left running); ``SceneView(open_server=False)``
    starts nothing and only records, for :meth:`save_html` / :meth:`show`.
    """

    def __init__(self, zmq_url: str | None = None, open_server: bool = True,
                 timeout_s: float = 10.0):
        self._server: MeshcatServer | None = None
        if open_server or zmq_url is not None:
            self._server = MeshcatServer(zmq_url=zmq_url, timeout_s=timeout_s)
        self._window = RecordingWindow(self._server)
        self._vis = meshcat.Visualizer(window=self._window)
        self._drawn: dict[str, set[str]] = {}  # user name → meshcat paths drawn for it
        self._world = None
        self._scene = None
        self._bounds: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # mesh id → (min, max) xyz
        self.title = "Scene"

    # ------------------------------------------------------------------ lifecycle

    @property
    def url(self) -> str | None:
        """The browser URL of the live view, or None for a view without a server (or closed)."""
        return self._window.web_url

    @property
    def zmq_url(self) -> str | None:
        """The server's ZeroMQ address (for ``SceneView(zmq_url=...)``), or None."""
        return None if self._window.server is None else self._window.server.zmq_url

    @property
    def server_process(self):
        """The ``subprocess.Popen`` of the server this view started, or None."""
        return None if self._server is None else self._server.process

    @property
    def visualizer(self) -> meshcat.Visualizer:
        """The underlying ``meshcat.Visualizer`` (its root is ``/meshcat``) for custom drawing;
        what is drawn through it is recorded like the rest."""
        return self._vis

    def close(self) -> None:
        """Close the connection and end the server this view started. Safe to call twice.

        The view then only records: drawing still works and :meth:`save_html` / :meth:`show`
        include everything drawn before and after."""
        if self._server is not None:
            self._server.close()
        self._window.server = None

    def __enter__(self) -> "SceneView":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def wait(self, timeout_s: float | None = None) -> None:
        """Block until Ctrl-C (or SIGTERM / SIGHUP), the server ending, or ``timeout_s``;
        then return normally so the caller can close the view."""
        restore = {}
        if threading.current_thread() is threading.main_thread():
            def stop(signum, frame):
                raise KeyboardInterrupt
            for sig in (signal.SIGTERM, getattr(signal, "SIGHUP", None)):
                if sig is not None:
                    restore[sig] = signal.signal(sig, stop)
        deadline = None if timeout_s is None else time.monotonic() + timeout_s
        try:
            while deadline is None or time.monotonic() < deadline:
                if self._server is not None and not self._server.alive:
                    return
                left = 0.2 if deadline is None else deadline - time.monotonic()
                time.sleep(min(0.2, max(0.0, left)))
        except KeyboardInterrupt:
            return
        finally:
            for sig, handler in restore.items():
                signal.signal(sig, handler)

    # ------------------------------------------------------------------ inspection

    def object_paths(self) -> list[str]:
        """Meshcat paths of every drawn object, e.g. ``/meshcat/world/furniture/couch_1``."""
        return self._window.object_paths()

    def has(self, path: str) -> bool:
        """True if an object is drawn at ``path`` or below it."""
        node = self._window.node(path)
        if node is None:
            return False
        stack = [node]
        while stack:
            current = stack.pop()
            if current.object is not None:
                return True
            stack.extend(current.values())
        return False

    # ------------------------------------------------------------------ the world

    def draw_world(self, world, scene="original", meshes=None, robot_pose=None,
                   frame_camera: bool = True) -> None:
        """Draw a world: ground, room floors, walls, furniture, objects and the robot.

        ``scene`` is a scene name or a :class:`~assistant.world.Scene`; ``meshes`` (a list of
        ``SceneMesh`` with world-frame open3d meshes) defaults to
        ``assistant.sim.meshes.scene_meshes(world, scene)``. The robot is drawn at
        ``robot_pose`` (default: the world's start pose); pass ``robot_pose=False`` for none.
        Drawing a world again replaces the previous one.
        """
        scene_obj = world.scene(scene) if isinstance(scene, str) else scene
        if meshes is None:
            from assistant.sim.meshes import scene_meshes

            meshes = scene_meshes(world, scene_obj.name)
        for item in meshes:
            if item.kind not in _MESH_GROUPS and item.kind != "floor":
                raise AssistantError(f"scene mesh {item.id!r} has kind {item.kind!r}; expected "
                                     "wall, furniture, object or floor")
        self._vis["world"].delete()
        self._world, self._scene = world, scene_obj
        self._bounds = {}
        self.title = f"{world.name} ({scene_obj.name} scene)"
        self._draw_floors(world)
        for item in meshes:
            self._draw_scene_mesh(item)
        if robot_pose is not False:
            self.draw_robot(world.start if robot_pose is None else robot_pose)
        self._vis["world/origin"].set_object(mg.triad(0.5))
        self._vis["/Grid"].set_property("visible", False)
        if frame_camera:
            self.frame_camera(world.floorplan.bounds())

    def _draw_floors(self, world) -> None:
        for index, room in enumerate(world.floorplan.rooms):
            vertices, faces = shapes.slab_mesh(room.polygon_array, 0.0, FLOOR_TOP_M)
            colour = room_colour(index, open_area=room.open)
            self._vis["world/floors"][path_name(room.name)].set_object(
                mg.TriangularMeshGeometry(vertices, faces), _lambert(colour))
            corners = room.polygon_array
            width = float(np.ptp(corners[:, 0]))
            # the room's name on its floor at its centre, at most 0.35 m tall and 60 % as wide
            target = self._vis["world/labels"][path_name(room.name)]
            target.set_object(label_object(room.name, 0.35, 0.6 * width, "#2b2b2b"))
            x, y = room.centre
            target.set_transform(mtf.translation_matrix([x, y, FLOOR_TOP_M + 0.005]))

    def _draw_scene_mesh(self, item) -> None:
        vertices, faces, colours = shapes.mesh_arrays(item.mesh)
        if len(faces) == 0:
            return
        if item.kind == "floor":
            geometry = mg.TriangularMeshGeometry(vertices - [0.0, 0.0, GROUND_DROP_M], faces)
            self._vis["world/ground"].set_object(geometry, _lambert((0.78, 0.78, 0.76)))
            return
        group = _MESH_GROUPS[item.kind]
        geometry = mg.TriangularMeshGeometry(vertices, faces, color=colours)
        material = (_lambert(None, vertex_colours=True) if colours is not None
                    else _lambert({"wall": (0.85, 0.85, 0.82), "furniture": (0.55, 0.38, 0.22),
                                   "object": (0.9, 0.35, 0.2)}[item.kind]))
        self._vis["world"][group][path_name(item.id)].set_object(geometry, material)
        self._bounds[item.id] = (vertices.min(axis=0), vertices.max(axis=0))

    def frame_camera(self, bounds_xy: Sequence[float], elevation_deg: float = 60.0,
                     azimuth_deg: float = -100.0) -> None:
        """Aim the default camera at the centre of ``(xmin, ymin, xmax, ymax)`` (metres), far
        enough back to see all of it, looking down by ``elevation_deg`` (89 for a plan view)
        from the direction ``azimuth_deg`` (counter-clockwise from +x; −90 is from −y).

        The mouse orbits about the centre. Note: the whole drawing (``/meshcat``) is shifted
        by −centre on the page; coordinates you draw in stay world coordinates."""
        xmin, ymin, xmax, ymax = (float(b) for b in bounds_xy)
        cx, cy = (xmin + xmax) / 2.0, (ymin + ymax) / 2.0
        span = max(xmax - xmin, ymax - ymin, 1.0)
        # meshcat's camera sees 75° vertically; stand back far enough for the span (and the
        # near walls' height) to fit in a window wider than high.
        distance = 0.5 * span / math.tan(math.radians(75.0 / 2.0)) * 1.4 + 1.0
        el, az = math.radians(min(max(elevation_deg, 5.0), 89.0)), math.radians(azimuth_deg)
        dx, dy = distance * math.cos(el) * math.cos(az), distance * math.cos(el) * math.sin(az)
        dz = distance * math.sin(el)
        # meshcat's orbit controls always look at the page's origin, so the drawing (all of
        # /meshcat) is shifted to put the centre there; /Axes is hidden as it would sit at
        # the centre — draw_world draws the world's own axes at /meshcat/world/origin.
        self._vis.set_transform(mtf.translation_matrix([-cx, -cy, 0.0]))
        self._vis["/Axes"].set_property("visible", False)
        # The camera's parent frame is y-up: world (x, y, z) is (x, z, -y) there.
        self._vis["/Cameras/default/rotated/<object>"].set_property("position", [dx, dz, -dy])

    # ------------------------------------------------------------------ the robot

    def draw_robot(self, pose, name: str = "robot", colour="#d9482b") -> None:
        """Draw (or move) a robot: a 0.25 m-radius body, a cone along its heading and a mast
        up to the camera height (1.05 m). ``pose`` is a Pose2D or ``(x, y, heading)``."""
        pose = shapes.as_pose(pose)
        group = self._vis["robots"][path_name(name)]
        path = group.path.lower()
        if not self.has(path):
            body = mg.Cylinder(ROBOT_BODY_HEIGHT_M, radius=ROBOT_RADIUS_M)
            group["body"].set_object(body, _lambert(colour))
            group["body"].set_transform(
                mtf.translation_matrix([0.0, 0.0, 0.05 + ROBOT_BODY_HEIGHT_M / 2.0])
                @ mtf.rotation_matrix(math.pi / 2.0, [1.0, 0.0, 0.0]))
            cone = mg.Cylinder(0.35, radiusTop=0.0, radiusBottom=0.09)
            group["heading"].set_object(cone, _lambert("yellow"))
            group["heading"].set_transform(
                mtf.translation_matrix([ROBOT_RADIUS_M + 0.12, 0.0, 0.05 + ROBOT_BODY_HEIGHT_M])
                @ mtf.rotation_matrix(-math.pi / 2.0, [0.0, 0.0, 1.0]))
            group["mast"].set_object(mg.Box([0.05, 0.05, 0.75]), _lambert((0.3, 0.3, 0.3)))
            group["mast"].set_transform(mtf.translation_matrix([0.0, 0.0, 0.35 + 0.375]))
            group["camera"].set_object(mg.Box([0.07, 0.28, 0.06]), _lambert((0.1, 0.1, 0.1)))
            group["camera"].set_transform(mtf.translation_matrix([0.03, 0.0, 1.05]))
        group.set_transform(pose.matrix4())
        self._remember(name, path)

    # ------------------------------------------------------------------ points, paths, arrows

    def draw_points(self, name: str, points_xyz, colors=None, size_m: float = 0.02,
                    max_points: int = 150_000) -> None:
        """Draw a point cloud (world frame, metres).

        ``colors``: None (one default colour), one colour (see :mod:`assistant.viz.colours`),
        or per point (N, 3) floats in 0–1 or uint8 0–255. Points that are not finite are
        dropped; beyond ``max_points`` an evenly spaced subset is drawn.
        """
        pts, cols = cloud_arrays(points_xyz, colors, max_points)
        cloud = mg.PointCloud(pts.T.astype(np.float32), cols.T.astype(np.float32), size=size_m)
        target = self._vis["points"][path_name(name)]
        target.set_object(cloud)
        self._remember(name, target.path.lower())

    def draw_depth_frame(self, name: str, frame, stride: int = 2, max_range_m: float = 6.0,
                         colour_by: str = "height", size_m: float = 0.025) -> np.ndarray:
        """Draw a depth frame's point cloud in the world frame; return the points drawn (N, 3).

        The image is back-projected with its intrinsics (every ``stride``-th pixel, readings
        up to ``max_range_m``) and placed by its camera mount and ``robot_pose`` (a frame with
        no pose is drawn with the floor under the camera at the origin). ``colour_by``:
        ``"height"`` (blue low → yellow high) or ``"hit"`` (simulated frames: the colour of the
        kind of thing each ray hit — evaluation ground truth, for looking only).
        """
        points, colours = depth_frame_points(frame, stride=stride, max_range_m=max_range_m,
                                             colour_by=colour_by)
        self.draw_points(name, points, colors=colours, size_m=size_m)
        return points

    def draw_path(self, name: str, points_xy, color="blue", z_m: float = 0.04,
                  width_m: float = 0.05) -> None:
        """Draw a path through ``points_xy`` ((N, 2) metres, or (N, 3) with heights): line
        segments, plus a flat band ``width_m`` wide (0 for none) that stays visible when
        zoomed out."""
        pts = np.asarray(points_xy, dtype=float)
        if pts.ndim != 2 or pts.shape[1] not in (2, 3) or len(pts) < 2:
            raise AssistantError(f"a path needs (N, 2) points with N ≥ 2; got shape {pts.shape}")
        xyz = pts if pts.shape[1] == 3 else np.column_stack([pts, np.full(len(pts), z_m)])
        group = self._vis["paths"][path_name(name)]
        group.delete()
        group["line"].set_object(mg.Line(mg.PointsGeometry(xyz.T.astype(np.float32)),
                                         mg.LineBasicMaterial(color=to_hex_int(color))))
        if width_m > 0:
            vertices, faces = shapes.ribbon_mesh(xyz[:, :2], width_m, float(np.mean(xyz[:, 2])))
            if len(faces):
                group["ribbon"].set_object(mg.TriangularMeshGeometry(vertices, faces),
                                           _lambert(color))
        self._remember(name, group.path.lower())

    def draw_arrows(self, name: str, poses, scores, min_length_m: float = 0.08,
                    max_length_m: float = 0.45, width_m: float = 0.035, z_m: float = 0.06) -> None:
        """Draw a score map as flat arrows, e.g. the move-to probability map of dissertation
        Figure 5.13. Each arrow starts at its pose and points along its heading; scores are
        divided by their maximum (eq. 5-13), and an arrow runs from red and ``min_length_m``
        (score 0) to green and ``max_length_m`` (the best)."""
        poses_arr = shapes.poses_array(poses)
        values = np.asarray(scores, dtype=float).reshape(-1)
        if len(values) != len(poses_arr):
            raise AssistantError(f"{len(poses_arr)} poses but {len(values)} scores; give one "
                                 "score per pose")
        if len(values) and not np.isfinite(values).all():
            raise AssistantError("scores must be finite numbers")
        top = float(np.max(values)) if len(values) else 0.0
        norm = values / top if top > 0 else np.zeros_like(values)
        target = self._vis["arrows"][path_name(name)]
        if len(values) == 0:
            target.delete()
            self._remember(name, target.path.lower())
            return
        lengths = min_length_m + (max_length_m - min_length_m) * np.clip(norm, 0.0, 1.0)
        vertices, faces, colours = shapes.arrows_mesh(poses_arr, lengths, score_colours(norm),
                                                      width_m=width_m, z=z_m)
        target.set_object(mg.TriangularMeshGeometry(vertices, faces, color=colours),
                          _lambert(None, vertex_colours=True))
        self._remember(name, target.path.lower())

    def draw_label(self, name: str, text: str, xy, height_m: float = 0.3,
                   max_width_m: float | None = None, z_m: float = 0.03, color="#1e1e1e") -> None:
        """Write ``text`` flat on the floor, centred on ``xy`` (metres), letters ``height_m``
        tall (smaller if the text would be wider than ``max_width_m``); it reads upright
        from the default camera (from −y)."""
        target = self._vis["labels"][path_name(name)]
        target.set_object(label_object(text, height_m, max_width_m, color))
        x, y = (float(v) for v in np.asarray(xy, dtype=float).reshape(2))
        target.set_transform(mtf.translation_matrix([x, y, z_m]))
        self._remember(name, target.path.lower())

    # ------------------------------------------------------------------ highlights

    def highlight(self, target, color="yellow", name: str | None = None,
                  opacity: float = 0.35, margin_m: float = 0.06) -> None:
        """Mark something with a translucent box (and its outline).

        ``target`` is a furniture id or object name of the drawn scene, a room name, a
        ``FurnitureItem``, or an :class:`~assistant.world.Entity` (its footprint cells are
        drawn). ``name`` (default: the target's id) names the highlight for :meth:`clear`.
        """
        from assistant.world import Entity, FurnitureItem

        if isinstance(target, Entity):
            key = name or target.id
            cell = target.grid.resolution_m
            vertices, faces = shapes.cells_mesh(target.points_m(), cell, 0.03)
            group = self._vis["highlights"][path_name(key)]
            group.delete()
            if len(faces):
                group["footprint"].set_object(mg.TriangularMeshGeometry(vertices, faces),
                                              _lambert(color, opacity=max(opacity, 0.6)))
            self._remember(key, group.path.lower())
            return
        if isinstance(target, FurnitureItem):
            item, key = target, name or target.id
        else:
            item, key = None, name or str(target)
            if self._scene is not None:
                ids = {f.id: f for f in self._scene.furniture}
                item = ids.get(str(target))
        if item is not None:
            spec = item.spec
            grown = rectangle(item.pose, spec.length_m + 2 * margin_m, spec.width_m + 2 * margin_m)
            self._highlight_prism(key, grown, 0.0, item.height_m + margin_m, color, opacity)
            return
        if str(target) in self._bounds:
            lo, hi = self._bounds[str(target)]
            polygon = box_polygon(lo[0] - margin_m, lo[1] - margin_m, hi[0] + margin_m,
                                  hi[1] + margin_m)
            self._highlight_prism(key, polygon, lo[2] - 0.01, hi[2] + margin_m, color, opacity)
            return
        if self._world is not None and str(target) in self._world.floorplan.room_names:
            room = self._world.floorplan.room(str(target))
            self._highlight_prism(key, room.polygon_array, 0.0, 0.08, color, opacity)
            return
        known = list(self._bounds) + (self._world.floorplan.room_names if self._world else [])
        raise UnknownNameError("thing to highlight", str(target), known)

    def _highlight_prism(self, key: str, polygon, z0: float, z1: float, color, opacity) -> None:
        vertices, faces = shapes.slab_mesh(polygon, z0, z1)
        group = self._vis["highlights"][path_name(key)]
        group.delete()
        group["box"].set_object(mg.TriangularMeshGeometry(vertices, faces),
                                _lambert(color, opacity=opacity))
        group["outline"].set_object(mg.LineSegments(
            mg.PointsGeometry(shapes.prism_outline(polygon, z0, z1).T),
            mg.LineBasicMaterial(color=to_hex_int(color))))
        self._remember(key, group.path.lower())

    # ------------------------------------------------------------------ clearing

    def clear(self, name: str | None = None) -> None:
        """Remove what was drawn under ``name`` (a robot, points, path, arrows, highlight —
        or ``"world"``); with no name, remove everything."""
        if name is None:
            self._vis.delete()
            self._drawn.clear()
            self._world = self._scene = None
            self._bounds = {}
            return
        if name == "world":
            self._vis["world"].delete()
            self._world = self._scene = None
            self._bounds = {}
            return
        paths = self._drawn.pop(name, None)
        if not paths:
            raise UnknownNameError("drawing", name, ["world", *self._drawn])
        for path in paths:
            self._vis[path].delete()

    def _remember(self, name: str, path: str) -> None:
        self._drawn.setdefault(name, set()).add(path)

    # ------------------------------------------------------------------ export

    def static_html(self) -> str:
        """The scene as one self-contained HTML page (no server, no network needed)."""
        return scene_html(self._window.tree, title=self.title)

    def save_html(self, path) -> Path:
        """Write :meth:`static_html` to ``path`` atomically (creating its folder); return the
        path written. AssistantError when it cannot be written."""
        try:
            return atomic_write_text(path, self.static_html())
        except OSError as exc:
            raise AssistantError(f"cannot write the 3D view to {path}: {exc.strerror or exc}; "
                                 "choose a file in a folder you can write to") from None

    def show(self, height: int = 480):
        """Show the scene in a notebook cell as a static, interactive snapshot (works with no
        server and in a saved notebook)."""
        from IPython.display import HTML

        page = self.static_html().replace("&", "&amp;").replace('"', "&quot;")
        return HTML(f'<div style="height:{int(height)}px;width:100%;resize:both;overflow:hidden">'
                    f'<iframe srcdoc="{page}" style="width:100%;height:100%;border:none">'
                    "</iframe></div>")

    def jupyter_cell(self, height: int = 480):
        """Show the live view (needs this view's server) in a notebook cell."""
        if self.url is None:
            raise AssistantError("this SceneView has no server; create it with SceneView() to "
                                 "watch it live, or use show() for a static snapshot")
        return self._vis.jupyter_cell(height=height)

    def __repr__(self) -> str:
        where = self.url or "no server"
        return f"<SceneView {self.title!r} at {where}, {len(self.object_paths())} objects>"



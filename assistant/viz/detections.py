"""What the furniture detector made of one depth frame, drawn in a :class:`SceneView`.

:func:`draw_detection_result` draws, under ``/meshcat/scan/<name>``:

* the frame's point cloud, coloured by height, in the frame the detections are in — the floor
  the detector found (x ahead of the camera, z up, origin on the floor under the camera), placed
  by the robot's pose when the frame has one (then it is the world frame);
* the floor plane: a translucent slab over the floor points found (within ``FLOOR_BAND_M`` of
  the plane), outlined, with the camera's height and tilt written on it;
* each piece of furniture found: a translucent box of its category's colour
  (:data:`~assistant.viz.colours.CATEGORY_COLOURS`) over its footprint, from the floor to its
  height, turned to its heading (an arrow shows the heading when it has one), labelled with
  category and confidence;
* each unknown thing: a grey post where it stands, labelled with the detector's best guess;
* the camera: a small black box where it is.
"""

from __future__ import annotations

import math

import meshcat.geometry as mg
import meshcat.transformations as mtf
import numpy as np

from assistant.geometry import Pose2D, rectangle
from assistant.viz import shapes
from assistant.viz.clouds import depth_frame_points
from assistant.viz.colours import CATEGORY_COLOURS, to_hex_int
from assistant.viz.labels import label_object

__all__ = ["FLOOR_BAND_M", "FLOOR_COLOUR", "detection_box", "draw_detection_result",
           "drawing_matrix", "floor_polygon"]

#: floor-frame points this close to the plane (metres) are drawn as the floor
FLOOR_BAND_M = 0.03
#: the floor plane's colour (a light blue, apart from every category colour)
FLOOR_COLOUR = (0.35, 0.70, 0.95)
UNKNOWN_COLOUR = (0.55, 0.55, 0.55)
_CELL_M = 0.05  # the detector's floor cells


def drawing_matrix(frame, floor) -> np.ndarray:
    """4×4 camera → drawing frame: the detector's floor frame (``floor.camera_to_floor``), then
    the robot's pose when the frame has one — the frame its detections are in."""
    matrix = np.asarray(floor.camera_to_floor, dtype=float)
    if frame.robot_pose is not None:
        matrix = frame.robot_pose.matrix4() @ matrix
    return matrix


def floor_polygon(points_xyz: np.ndarray, band_m: float = FLOOR_BAND_M) -> np.ndarray | None:
    """The convex hull (K, 2) of the points within ``band_m`` of z = 0, or None when fewer than
    three such points span an area."""
    from scipy.spatial import ConvexHull, QhullError

    near = points_xyz[np.abs(points_xyz[:, 2]) < band_m, :2]
    if len(near) < 3:
        return None
    try:
        return near[ConvexHull(near).vertices]
    except (QhullError, ValueError):
        return None


def detection_box(detection) -> np.ndarray:
    """Corners (4, 2) of the rectangle around a detection's floor cells, turned to its heading
    (for an item without one, e.g. a table, to the cells' longer axis)."""
    cells = np.asarray(detection.cells_xy, dtype=float).reshape(-1, 2)
    centre = np.array([detection.x, detection.y])
    if len(cells) == 0:
        return rectangle(Pose2D(*centre, 0.0), 0.3, 0.3)
    if detection.facing is not None:
        angle = float(detection.facing)
    elif len(cells) >= 2:
        spread = np.cov((cells - cells.mean(axis=0)).T)
        major = np.linalg.eigh(spread)[1][:, -1]
        angle = math.atan2(major[1], major[0])
    else:
        angle = 0.0
    axes = np.array([[math.cos(angle), math.sin(angle)], [-math.sin(angle), math.cos(angle)]])
    local = (cells - cells.mean(axis=0)) @ axes.T
    lo, hi = local.min(axis=0) - _CELL_M / 2, local.max(axis=0) + _CELL_M / 2
    middle = cells.mean(axis=0) + ((lo + hi) / 2) @ axes
    return rectangle(Pose2D(float(middle[0]), float(middle[1]), angle), *(hi - lo))


def _prism(group, polygon, z0: float, z1: float, colour, opacity: float) -> None:
    vertices, faces = shapes.slab_mesh(polygon, z0, z1)
    group["box"].set_object(mg.TriangularMeshGeometry(vertices, faces), mg.MeshLambertMaterial(
        color=to_hex_int(colour), opacity=opacity))
    group["outline"].set_object(mg.LineSegments(mg.PointsGeometry(shapes.prism_outline(polygon, z0, z1).T),
                                                mg.LineBasicMaterial(color=to_hex_int(colour))))


def _label(target, text: str, xyz, yaw: float, height_m: float = 0.16, colour="#1e1e1e") -> None:
    """Text lying flat at ``xyz``, turned by ``yaw`` (radians) to read upright from the camera."""
    target.set_object(label_object(text, height_m, None, colour))
    target.set_transform(mtf.translation_matrix([float(v) for v in xyz]) @ mtf.rotation_matrix(yaw, [0.0, 0.0, 1.0]))


def _draw_furniture(group, index: int, d, yaw: float) -> None:
    colour = CATEGORY_COLOURS.get(d.category, UNKNOWN_COLOUR)
    item = group["furniture"][f"{index}"]
    _prism(item, detection_box(d), 0.0, d.height_m, colour, 0.45)
    if d.facing is not None:
        tip = np.array([d.x, d.y]) + 0.6 * np.array([math.cos(d.facing), math.sin(d.facing)])
        z = d.height_m + 0.02
        left = tip - 0.15 * np.array([math.cos(d.facing - 0.5), math.sin(d.facing - 0.5)])
        right = tip - 0.15 * np.array([math.cos(d.facing + 0.5), math.sin(d.facing + 0.5)])
        segments = np.array([[d.x, d.y, z], [*tip, z], [*tip, z], [*left, z], [*tip, z], [*right, z]],
                            dtype=np.float32)
        item["heading"].set_object(mg.LineSegments(mg.PointsGeometry(segments.T),
                                                   mg.LineBasicMaterial(color=to_hex_int(colour), linewidth=3)))
    text = f"{d.category} {d.confidence:.2f}" + (" (unsure)" if d.unsure else "")
    _label(item["label"], text, (d.x, d.y, d.height_m + 0.05), yaw)


def draw_detection_result(view, frame, result, name: str = "scan", stride: int = 2,
                          frame_camera: bool = True) -> dict:
    """Draw ``result`` (:meth:`FurnitureDetector.analyse` of ``frame``) into ``view`` under
    ``/meshcat/scan/<name>``, replacing what was drawn there; see the module's docstring.

    A frame without a floor is drawn as a plain cloud by its camera mount. ``frame_camera`` aims
    the view's camera at the cloud (most of it: the 2nd to 98th percentiles). Returns what was
    drawn: ``{"points" (N, 3), "colours" (N, 3), "floor_polygon" (K, 2) or None, "boxes" [(4, 2)],
    "unknown" (how many)}``, in the drawing frame."""
    from assistant.viz.scene_view import path_name

    group = view.visualizer["scan"][path_name(name)]
    group.delete()
    view.visualizer["/Grid"].set_property("visible", False)  # the floor found is drawn instead
    floor = result.floor
    matrix = None if floor is None else drawing_matrix(frame, floor)
    points, colours = depth_frame_points(frame, stride=stride, camera_to_world=matrix)
    view.draw_points(f"scan-{name}", points, colors=colours, size_m=0.02)
    # looked at from behind the camera, a little to its right; labels read upright from there
    azimuth = 200.0 + (0.0 if frame.robot_pose is None else math.degrees(frame.robot_pose.theta))
    yaw = math.radians(azimuth + 180.0 - 90.0)
    if frame_camera and len(points):
        lo, hi = np.percentile(points[:, :2], [2, 98], axis=0)
        view.frame_camera((*lo, *hi), elevation_deg=50.0, azimuth_deg=azimuth)
    drawn = {"points": points, "colours": colours, "floor_polygon": None, "boxes": [], "unknown": len(result.unknown)}
    if floor is None:
        return drawn
    local = points if frame.robot_pose is None else np.column_stack(
        [frame.robot_pose.to_local(points[:, :2]), points[:, 2]])
    polygon = floor_polygon(local)
    if polygon is not None:
        if frame.robot_pose is not None:
            polygon = frame.robot_pose.transform_points(polygon)
        _prism(group["floor"], polygon, -0.012, -0.002, FLOOR_COLOUR, 0.45)
        centre = polygon.mean(axis=0)
        _label(group["floor"]["label"], f"floor: camera {floor.height_m:.2f} m above, tilted "
               f"{math.degrees(floor.tilt_rad):.0f}°", (*centre, 0.005), yaw, 0.14, "#0b3d66")
        drawn["floor_polygon"] = polygon
    for i, d in enumerate(result.detections):
        _draw_furniture(group, i, d, yaw)
        drawn["boxes"].append(detection_box(d))
    for i, u in enumerate(result.unknown):
        post = group["unknown"][f"{i}"]
        radius = max(0.08, math.sqrt(u.cells * _CELL_M ** 2 / math.pi))
        post["body"].set_object(mg.Cylinder(u.height_m, radius=radius), mg.MeshLambertMaterial(
            color=to_hex_int(UNKNOWN_COLOUR), opacity=0.4))
        post["body"].set_transform(mtf.translation_matrix([u.x, u.y, u.height_m / 2])
                                   @ mtf.rotation_matrix(math.pi / 2, [1.0, 0.0, 0.0]))
        _label(post["label"], f"unknown ({u.why}; {u.best}?)", (u.x, u.y, u.height_m + 0.05), yaw, 0.12)
    camera = matrix[:3, 3]
    group["camera"].set_object(mg.Box([0.07, 0.28, 0.06]), mg.MeshLambertMaterial(color=0x1a1a1a))
    heading = 0.0 if frame.robot_pose is None else frame.robot_pose.theta
    group["camera"].set_transform(mtf.translation_matrix(camera) @ mtf.rotation_matrix(heading, [0.0, 0.0, 1.0]))
    return drawn

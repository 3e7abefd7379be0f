"""Poses, angles, frames and floor grids (metres and radians throughout)."""

from assistant.geometry.angles import angle_difference, angles_close, wrap_angle, wrap_angles
from assistant.geometry.gridmap import GridMap
from assistant.geometry.pose import Pose2D
from assistant.geometry.shapes import (
    box_polygon,
    ellipse,
    point_in_polygon,
    polygon_area,
    polygon_lattice,
    rectangle,
    rectangle_fill,
    regular_polygon,
)

__all__ = [
    "GridMap",
    "Pose2D",
    "angle_difference",
    "angles_close",
    "box_polygon",
    "ellipse",
    "point_in_polygon",
    "polygon_area",
    "polygon_lattice",
    "rectangle",
    "rectangle_fill",
    "regular_polygon",
    "wrap_angle",
    "wrap_angles",
]

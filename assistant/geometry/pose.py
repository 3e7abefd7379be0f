"""Planar poses and rigid transforms in the world frame (metres, radians)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.geometry.angles import wrap_angle


@dataclass(frozen=True)
class Pose2D:
    """A pose on the floor: position ``x``, ``y`` in metres, heading ``theta`` in radians.

    ``theta`` is counter-clockwise from +x of the world frame and kept wrapped to [-π, π).
    A pose doubles as the transform from its local frame (x forward, y left) to the world.
    """

    x: float
    y: float
    theta: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "x", float(self.x))
        object.__setattr__(self, "y", float(self.y))
        object.__setattr__(self, "theta", wrap_angle(float(self.theta)))

    @property
    def xy(self) -> np.ndarray:
        """Position as a length-2 array (metres)."""
        return np.array([self.x, self.y])

    @property
    def heading_vector(self) -> np.ndarray:
        """Unit vector of the heading in the world frame."""
        return np.array([math.cos(self.theta), math.sin(self.theta)])

    def compose(self, other: "Pose2D") -> "Pose2D":
        """``self ∘ other``: ``other`` expressed in this pose's frame, returned in the world."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        return Pose2D(
            self.x + c * other.x - s * other.y,
            self.y + s * other.x + c * other.y,
            self.theta + other.theta,
        )

    def inverse(self) -> "Pose2D":
        c, s = math.cos(self.theta), math.sin(self.theta)
        return Pose2D(-c * self.x - s * self.y, s * self.x - c * self.y, -self.theta)

    def relative_to(self, frame: "Pose2D") -> "Pose2D":
        """This pose expressed in ``frame``'s local frame."""
        return frame.inverse().compose(self)

    def transform_points(self, points_local: np.ndarray) -> np.ndarray:
        """Map (N, 2) points from this pose's local frame to the world frame."""
        pts = np.asarray(points_local, dtype=float).reshape(-1, 2)
        c, s = math.cos(self.theta), math.sin(self.theta)
        rotation = np.array([[c, -s], [s, c]])
        return pts @ rotation.T + self.xy

    def to_local(self, points_world: np.ndarray) -> np.ndarray:
        """Map (N, 2) world points into this pose's local frame."""
        pts = np.asarray(points_world, dtype=float).reshape(-1, 2) - self.xy
        c, s = math.cos(self.theta), math.sin(self.theta)
        rotation = np.array([[c, -s], [s, c]])
        return pts @ rotation

    def distance_to(self, other: "Pose2D") -> float:
        return math.hypot(self.x - other.x, self.y - other.y)

    def as_tuple(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.theta)

    def to_dict(self) -> dict[str, float]:
        return {"x": self.x, "y": self.y, "heading": self.theta}

    def matrix(self) -> np.ndarray:
        """3×3 homogeneous transform local → world."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        return np.array([[c, -s, self.x], [s, c, self.y], [0.0, 0.0, 1.0]])

    def matrix4(self, z: float = 0.0) -> np.ndarray:
        """4×4 homogeneous transform for 3D use (rotation about +z, lifted by ``z`` metres)."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        m = np.eye(4)
        m[:2, :2] = [[c, -s], [s, c]]
        m[:3, 3] = [self.x, self.y, z]
        return m

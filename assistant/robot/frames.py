"""What a robot's sensors deliver: depth frames with their intrinsics and camera pose, odometry.

These types are shared by every robot adapter (simulator, replay, P3-DX + Kinect) and read by
perception; nothing here depends on where a frame came from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from assistant.geometry import Pose2D


@dataclass(frozen=True)
class CameraIntrinsics:
    """Pinhole intrinsics in pixels for an image of ``width`` × ``height``."""

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float

    @classmethod
    def kinect_v1(cls) -> "CameraIntrinsics":
        """The Kinect (v1) depth camera: 640×480, fx = fy = 525, principal point at the centre."""
        return cls(640, 480, 525.0, 525.0, 319.5, 239.5)

    def to_dict(self) -> dict:
        return {"width": self.width, "height": self.height, "fx": self.fx, "fy": self.fy,
                "cx": self.cx, "cy": self.cy}


@dataclass(frozen=True)
class CameraMount:
    """Where the camera sits on the robot: ``height_m`` above the floor, ``forward_m`` ahead of
    the base centre, pitched down by ``tilt_rad`` (positive looks down)."""

    height_m: float = 1.05
    tilt_rad: float = math.radians(15.0)
    forward_m: float = 0.0


@dataclass(frozen=True, eq=False)
class DepthFrame:
    """One depth image.

    ``depth_m`` is an (H, W) float32 array of depth along the optical axis in metres, 0 where
    the sensor has no reading. ``robot_pose`` is the odometry pose at capture (world frame, or
    None for a frame with no robot, e.g. a PNG from disk); ``mount`` places the camera on the
    robot. ``hit_ids`` (simulation only, for evaluation — never read by the executor or
    perception) gives per pixel the index into ``hit_names`` of what the ray hit, -1 for none.
    """

    depth_m: np.ndarray
    intrinsics: CameraIntrinsics
    mount: CameraMount = field(default_factory=CameraMount)
    robot_pose: Pose2D | None = None
    timestamp_s: float = 0.0
    hit_ids: np.ndarray | None = None
    hit_names: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        shape = (self.intrinsics.height, self.intrinsics.width)
        if self.depth_m.shape != shape:
            raise ValueError(f"depth image is {self.depth_m.shape[::-1]} pixels but the intrinsics say "
                             f"{shape[::-1]}")

    @property
    def valid(self) -> np.ndarray:
        """Boolean mask of pixels with a finite, positive reading."""
        d = self.depth_m
        return np.isfinite(d) & (d > 0)

    def to_millimetres(self) -> np.ndarray:
        """uint16 depth in millimetres (0 = missing), as a 16-bit PNG stores it."""
        d = np.where(self.valid, self.depth_m, 0.0)
        return np.clip(np.round(d * 1000.0), 0, 65535).astype(np.uint16)

    def camera_to_world(self) -> np.ndarray:
        """4×4 camera (optical) → world transform; base frame if ``robot_pose`` is None."""
        if self.robot_pose is None:
            return camera_to_base_matrix(self.mount)
        return camera_to_world_matrix(self.mount, self.robot_pose)


@dataclass(frozen=True)
class Odometry:
    """The base's pose estimate (world frame) and velocity at ``timestamp_s``."""

    pose: Pose2D
    linear_m_s: float = 0.0
    angular_rad_s: float = 0.0
    timestamp_s: float = 0.0


# ---------------------------------------------------------------------------- camera geometry
#
# Frames used with a DepthFrame (all metres):
#   * camera (optical) frame: x right in the image, y down in the image, z along the optical
#     axis (depth_m is this z);
#   * base frame: the robot's x forward, y left, z up, origin on the floor under the base centre;
#   * world frame: the world file's x, y, z up; the base frame is ``robot_pose`` lifted to 3D.


def camera_to_base_matrix(mount: CameraMount) -> np.ndarray:
    """4×4 transform from the camera (optical) frame to the robot's base frame.

    The camera sits ``mount.forward_m`` ahead of the base centre, ``mount.height_m`` above the
    floor, its optical axis pitched down by ``mount.tilt_rad`` from the base's +x.
    """
    c, s = math.cos(mount.tilt_rad), math.sin(mount.tilt_rad)
    m = np.eye(4)
    m[:3, 0] = (0.0, -1.0, 0.0)  # image right  → base −y
    m[:3, 1] = (-s, 0.0, -c)  # image down   → down and a little backwards when tilted down
    m[:3, 2] = (c, 0.0, -s)  # optical axis → forward, pitched down by the tilt
    m[:3, 3] = (mount.forward_m, 0.0, mount.height_m)
    return m


def camera_to_world_matrix(mount: CameraMount, robot_pose: Pose2D) -> np.ndarray:
    """4×4 transform from the camera (optical) frame to the world frame for a base pose."""
    return robot_pose.matrix4() @ camera_to_base_matrix(mount)


def pixel_rays(intrinsics: CameraIntrinsics) -> np.ndarray:
    """(H, W, 3) float32 ray directions in the camera frame, scaled so that z = 1.

    A point at depth ``d`` seen at pixel (v, u) is ``d * pixel_rays(K)[v, u]`` in the camera
    frame (so ``depth_m`` times these rays is the organised point cloud).
    """
    u = (np.arange(intrinsics.width, dtype=np.float64) - intrinsics.cx) / intrinsics.fx
    v = (np.arange(intrinsics.height, dtype=np.float64) - intrinsics.cy) / intrinsics.fy
    uu, vv = np.meshgrid(u, v)
    return np.stack([uu, vv, np.ones_like(uu)], axis=-1).astype(np.float32)

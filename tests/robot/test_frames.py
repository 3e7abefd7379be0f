"""Camera geometry helpers added to frames.py: optical → base → world transforms, pixel rays."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.robot import CameraIntrinsics, CameraMount, DepthFrame, camera_to_base_matrix, pixel_rays


def test_level_camera_axes():
    m = camera_to_base_matrix(CameraMount(height_m=1.0, tilt_rad=0.0, forward_m=0.1))
    # optical axis → base forward, image right → base right (−y), image down → base down
    assert m[:3, 2] == pytest.approx([1, 0, 0])
    assert m[:3, 0] == pytest.approx([0, -1, 0])
    assert m[:3, 1] == pytest.approx([0, 0, -1])
    assert m[:3, 3] == pytest.approx([0.1, 0.0, 1.0])
    assert np.allclose(m[:3, :3] @ m[:3, :3].T, np.eye(3)) and np.linalg.det(m[:3, :3]) == pytest.approx(1)


def test_tilted_axis_meets_the_floor_where_expected():
    tilt = math.radians(20)
    m = camera_to_base_matrix(CameraMount(height_m=1.05, tilt_rad=tilt))
    point = m @ np.array([0, 0, 1.05 / math.sin(tilt), 1.0])
    assert point[:3] == pytest.approx([1.05 / math.tan(tilt), 0.0, 0.0], abs=1e-9)


def test_frame_camera_to_world_uses_the_pose():
    k = CameraIntrinsics(4, 2, 2.0, 2.0, 1.5, 0.5)
    frame = DepthFrame(np.ones((2, 4), np.float32), k, CameraMount(1.0, 0.0), robot_pose=Pose2D(1, 2, math.pi / 2))
    origin = frame.camera_to_world() @ np.array([0, 0, 1.0, 1])
    assert origin[:3] == pytest.approx([1.0, 3.0, 1.0])  # 1 m ahead of a robot facing +y


def test_pixel_rays_have_unit_z_and_centre_at_principal_point():
    k = CameraIntrinsics.kinect_v1()
    rays = pixel_rays(k)
    assert rays.shape == (480, 640, 3) and rays.dtype == np.float32
    assert np.all(rays[..., 2] == 1)
    assert rays[0, 0, :2] == pytest.approx([-319.5 / 525, -239.5 / 525])
    assert (rays[239, 319, :2] + rays[240, 320, :2]) == pytest.approx([0, 0], abs=1e-6)

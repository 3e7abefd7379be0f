"""The one robot interface and its adapters (simulator, replay, P3-DX + Kinect)."""

from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame, Odometry

__all__ = ["CameraIntrinsics", "CameraMount", "DepthFrame", "Odometry"]

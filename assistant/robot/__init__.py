"""The one robot interface and its adapters (simulator, replay, P3-DX + Kinect).

The simulator adapter lives in :mod:`assistant.sim` (``from assistant.sim import SimRobot``):
this package does not import the simulator.
"""

from assistant.robot.contract import check_robot, robot_checks
from assistant.robot.errors import (
    DeviceAlreadyConnectedError,
    DeviceNotConnectedError,
    RobotConnectionError,
    RobotError,
)
from assistant.robot.frames import (
    CameraIntrinsics,
    CameraMount,
    DepthFrame,
    Odometry,
    camera_to_base_matrix,
    camera_to_world_matrix,
    pixel_rays,
)
from assistant.robot.interface import Robot

__all__ = [
    "CameraIntrinsics", "CameraMount", "DepthFrame", "DeviceAlreadyConnectedError",
    "DeviceNotConnectedError", "Odometry", "Robot", "RobotConnectionError", "RobotError",
    "camera_to_base_matrix", "camera_to_world_matrix", "check_robot", "pixel_rays", "robot_checks",
]

"""The one robot interface and its adapters (simulator, replay, P3-DX + Kinect).

Build a robot with :func:`make_robot` (``"sim:apartment"``, ``"replay:PATH"``, ``"p3dx:PORT"``).
The simulator adapter lives in :mod:`assistant.sim`; the factory imports an adapter by name only
when asked for it, so this package never imports the layers above it.
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
from assistant.robot.factory import RobotSpec, make_robot, parse_robot_spec, register_adapter, robot_schemes
from assistant.robot.interface import Robot

__all__ = [
    "CameraIntrinsics", "CameraMount", "DepthFrame", "DeviceAlreadyConnectedError",
    "DeviceNotConnectedError", "Odometry", "Robot", "RobotSpec", "make_robot", "parse_robot_spec", "register_adapter", "robot_schemes", "RobotConnectionError", "RobotError",
    "camera_to_base_matrix", "camera_to_world_matrix", "check_robot", "pixel_rays", "robot_checks",
]

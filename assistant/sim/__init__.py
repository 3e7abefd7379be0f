"""The simulator: procedural meshes, ray-cast Kinect depth, differential-drive kinematics.

The simulator is a robot adapter like any other (:class:`SimRobot` implements
:class:`assistant.robot.Robot`); the ground truth it holds (hit ids, the true pose) is for
evaluation only.
"""

from assistant.sim.collision import Obstacles
from assistant.sim.kinematics import DiffDriveBase, DiffDriveLimits, OdometryNoise, StartPoseError
from assistant.sim.meshes import (
    KIND_COLOURS,
    SceneMesh,
    floor_mesh,
    furniture_mesh,
    object_mesh,
    scene_meshes,
    wall_mesh,
)
from assistant.sim.renderer import DepthRenderer, KinectNoise, PoseOutsideMapError, check_pose_in_map
from assistant.sim.robot import SimRobot

__all__ = [
    "DepthRenderer", "DiffDriveBase", "DiffDriveLimits", "KIND_COLOURS", "KinectNoise",
    "Obstacles", "OdometryNoise", "PoseOutsideMapError", "SceneMesh", "SimRobot",
    "StartPoseError", "check_pose_in_map", "floor_mesh", "furniture_mesh", "object_mesh",
    "scene_meshes", "wall_mesh",
]

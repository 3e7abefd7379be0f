"""``SimRobot``: the simulator behind the one :class:`~assistant.robot.Robot` interface.

It drives a :class:`~assistant.sim.kinematics.DiffDriveBase` in simulated time (``advance``)
and renders Kinect frames with a :class:`~assistant.sim.renderer.DepthRenderer` from the true
pose; the frame and the odometry carry the *odometry* pose, as on the real robot. The true pose
(``ground_truth_pose``) and the frames' hit ids are for evaluation only.
"""

from __future__ import annotations

import math

from assistant.geometry import Pose2D
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame, Odometry
from assistant.robot.interface import Robot
from assistant.sim.kinematics import DiffDriveBase, DiffDriveLimits, OdometryNoise
from assistant.sim.renderer import DepthRenderer, KinectNoise
from assistant.world import World, load_world

__all__ = ["SimRobot", "sim_robot_from_spec"]


class SimRobot(Robot):
    """A simulated P3-DX with a Kinect in one scene of a world.

    ``world`` is a :class:`~assistant.world.World` or a world name/path (an unknown name raises
    :class:`~assistant.errors.UnknownNameError` listing the known ones). ``start`` defaults to
    the world's start pose; a start off the map or inside an obstacle raises
    :class:`~assistant.sim.kinematics.StartPoseError`. ``tilt_deg`` pitches the camera down;
    ``odometry_noise`` (None = exact odometry) and ``depth_noise`` set the sensor errors; the
    same ``seed`` and commands give the same run.
    """

    def __init__(self, world: World | str, scene: str = "original", start: Pose2D | None = None,
                 seed: int | None = 0, *, tilt_deg: float = 15.0,
                 odometry_noise: OdometryNoise | None = None, depth_noise: KinectNoise | None = None,
                 intrinsics: CameraIntrinsics | None = None, camera_height_m: float = 1.05,
                 limits: DiffDriveLimits | None = None, adaptive_rendering: bool = True):
        super().__init__()
        self.world = world if isinstance(world, World) else load_world(world)
        self.scene = self.world.scene(scene).name
        self.seed = seed
        self.mount = CameraMount(height_m=camera_height_m, tilt_rad=math.radians(tilt_deg))
        self.intrinsics = intrinsics or CameraIntrinsics.kinect_v1()
        self.depth_noise = depth_noise
        self.adaptive_rendering = adaptive_rendering
        self.name = f"simulated robot in {self.world.name} ({self.scene})"
        self.base = DiffDriveBase(self.world, self.scene, start, limits=limits,
                                  odometry_noise=odometry_noise, seed=seed)
        self._renderer: DepthRenderer | None = None
        self._last_frame: DepthFrame | None = None
        self._last_frame_key: tuple | None = None

    # ---------------------------------------------------------------- ground truth (evaluation only)
    @property
    def ground_truth_pose(self) -> Pose2D:
        """The true pose (world frame). For evaluation only: the executor never reads it."""
        return self.base.pose

    @property
    def renderer(self) -> DepthRenderer:
        if self._renderer is None:
            # a different stream from the odometry's, still fixed by the seed
            seed = None if self.seed is None else self.seed + 7919
            self._renderer = DepthRenderer(self.world, self.scene, self.intrinsics, self.mount,
                                           self.depth_noise, seed, adaptive=self.adaptive_rendering)
        return self._renderer

    # ---------------------------------------------------------------- hooks
    def _connect(self) -> None:
        self.renderer  # build the ray-casting scene now, not on the first frame

    def _close(self) -> None:
        self.base.halt()  # a closed robot does not keep rolling
        self._last_frame = None
        self._last_frame_key = None

    def _odometry(self) -> Odometry:
        linear, angular = self.base.velocity
        return Odometry(self.base.odometry_pose, linear, angular, self.base.time_s)

    def _depth_frame(self) -> DepthFrame:
        key = (self.base.time_s, self.base.pose)
        if self._last_frame is not None and self._last_frame_key == key:
            return self._last_frame
        rendered = self.renderer.render(self.base.pose, timestamp_s=self.base.time_s)
        frame = DepthFrame(depth_m=rendered.depth_m, intrinsics=rendered.intrinsics,
                           mount=rendered.mount, robot_pose=self.base.odometry_pose,
                           timestamp_s=rendered.timestamp_s, hit_ids=rendered.hit_ids,
                           hit_names=rendered.hit_names)
        self._last_frame, self._last_frame_key = frame, key
        return frame

    def _send_velocity(self, linear_m_s: float, angular_rad_s: float) -> None:
        self.base.set_command(linear_m_s, angular_rad_s)

    def _stop(self) -> None:
        self.base.stop()

    def _advance(self, seconds: float) -> None:
        self.base.step(seconds)

    def _time_s(self) -> float:
        return self.base.time_s

    def _bumped(self) -> bool:
        return self.base.bumped

    # ---------------------------------------------------------------- simulator extras
    def step(self, dt_s: float) -> None:
        """Same as :meth:`advance` (simulated seconds)."""
        self.advance(dt_s)

    @property
    def bumped_into(self) -> str | None:
        """What the base bumped into (``wall_<k>``, a furniture id, ``map edge``), or None."""
        return self.base.bumped_into


def sim_robot_from_spec(argument: str = "", *, world: World | str | None = None,
                        scene: str | None = None, noise: bool = False, **options) -> SimRobot:
    """The ``sim`` adapter of :func:`assistant.robot.factory.make_robot`.

    ``argument`` is ``""``, ``WORLD`` or ``WORLD:SCENE``; it wins over the ``world`` and
    ``scene`` options. ``noise=True`` turns on the default odometry noise (the evaluations'
    setting) unless ``odometry_noise`` is given. Other options go to :class:`SimRobot`.
    """
    name, _, scene_arg = argument.partition(":")
    same_home = isinstance(world, World) and world.name == name  # the home already loaded
    chosen_world = world if same_home else name or world or "apartment"
    chosen_scene = scene_arg or scene or "original"
    if noise and "odometry_noise" not in options:
        options["odometry_noise"] = OdometryNoise()
    return SimRobot(chosen_world, chosen_scene, **options)

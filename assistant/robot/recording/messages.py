"""The product's sensor data as ROS 2 messages, and back.

A session is stored with the ROS 2 message types the robotics ecosystem's viewers know
(serialised as CDR by ``rosbags``' type store):

========================  ==============================  ===========================================
topic                     type                            what
========================  ==============================  ===========================================
``/camera/depth/image``   ``sensor_msgs/msg/Image``       depth, ``16UC1``, millimetres, 0 = no reading
``/camera/depth/info``    ``sensor_msgs/msg/CameraInfo``  the depth camera's pinhole intrinsics
``/camera/depth/pose``    ``geometry_msgs/msg/PoseStamped``  the base's odometry pose when the frame was taken
``/tf_static``            ``tf2_msgs/msg/TFMessage``      ``base_link`` → camera optical frame (height, tilt)
``/odom``                 ``nav_msgs/msg/Odometry``       pose estimate and velocity of the base
``/cmd_vel``              ``geometry_msgs/msg/Twist``     velocity commands sent to the base
``/dialogue``             ``std_msgs/msg/String``         one JSON object per turn: speaker, text
========================  ==============================  ===========================================

Every converter here is exact both ways for what the product keeps: depth is stored as whole
millimetres (:func:`depth_from_millimetres` is the one way back to metres), times as integer
nanoseconds (:func:`to_ns`), headings as a quaternion about +z.
"""

from __future__ import annotations

import functools
import json
import math

import numpy as np

from assistant.geometry import Pose2D
from assistant.robot.frames import CameraIntrinsics, CameraMount, Odometry, camera_to_base_matrix

__all__ = [
    "CAMERA_FRAME", "TOPICS", "depth_from_millimetres", "from_ns", "to_ns", "typestore",
]

#: topic → ROS 2 type of every topic a session holds
TOPICS = {
    "/camera/depth/image": "sensor_msgs/msg/Image",
    "/camera/depth/info": "sensor_msgs/msg/CameraInfo",
    "/camera/depth/pose": "geometry_msgs/msg/PoseStamped",
    "/tf_static": "tf2_msgs/msg/TFMessage",
    "/odom": "nav_msgs/msg/Odometry",
    "/cmd_vel": "geometry_msgs/msg/Twist",
    "/dialogue": "std_msgs/msg/String",
}
CAMERA_FRAME = "camera_depth_optical_frame"
BASE_FRAME = "base_link"
ODOM_FRAME = "odom"


@functools.lru_cache(maxsize=1)
def typestore():
    """The ROS 2 (Humble) message type store of ``rosbags`` (built once per process)."""
    from rosbags.typesys import Stores, get_typestore

    return get_typestore(Stores.ROS2_HUMBLE)


def message_definition(typename: str) -> str:
    """The ``ros2msg`` schema text of a type, with its dependencies, as MCAP stores it."""
    text, _ = typestore().generate_msgdef(typename, ros_version=2)
    return text


def serialize(message, typename: str) -> bytes:
    return bytes(typestore().serialize_cdr(message, typename))


def deserialize(data: bytes, typename: str):
    return typestore().deserialize_cdr(data, typename)


def ros2_type_name(typename: str) -> str:
    """``sensor_msgs/Image`` (ROS 1 spelling) → ``sensor_msgs/msg/Image``; ROS 2 names unchanged."""
    package, _, name = typename.rpartition("/")
    return typename if package.endswith("/msg") else f"{package}/msg/{name}"


# ---------------------------------------------------------------------------- time
def to_ns(seconds: float) -> int:
    """Seconds → whole nanoseconds (the one rounding every recorded time goes through)."""
    return int(round(float(seconds) * 1e9))


def from_ns(nanoseconds: int) -> float:
    return nanoseconds / 1e9


def _stamp(t_ns: int):
    Time = typestore().types["builtin_interfaces/msg/Time"]
    return Time(sec=int(t_ns // 1_000_000_000), nanosec=int(t_ns % 1_000_000_000))


def stamp_ns(stamp) -> int:
    return int(stamp.sec) * 1_000_000_000 + int(stamp.nanosec)


def _header(t_ns: int, frame_id: str):
    Header = typestore().types["std_msgs/msg/Header"]
    return Header(stamp=_stamp(t_ns), frame_id=frame_id)


# ---------------------------------------------------------------------------- depth
def depth_from_millimetres(millimetres: np.ndarray) -> np.ndarray:
    """uint16 millimetres (0 = no reading) → float32 metres; the one conversion both the
    recorder and the replay use, so a replayed frame equals the recorded one bit for bit."""
    return millimetres.astype(np.float32) / np.float32(1000.0)


def image_message(millimetres: np.ndarray, t_ns: int):
    """A ``sensor_msgs/Image`` (``16UC1``, little-endian) of a uint16 millimetre depth image."""
    Image = typestore().types["sensor_msgs/msg/Image"]
    height, width = millimetres.shape
    data = np.ascontiguousarray(millimetres, dtype="<u2").view(np.uint8).reshape(-1)
    return Image(header=_header(t_ns, CAMERA_FRAME), height=height, width=width, encoding="16UC1",
                 is_bigendian=0, step=width * 2, data=data)


def image_depth_m(image) -> np.ndarray:
    """Depth in metres (float32, 0 = no reading) from a ``sensor_msgs/Image`` of depth.

    ``16UC1`` is millimetres (the ROS depth convention), ``32FC1`` metres; other encodings raise
    ``ValueError`` naming the encoding.
    """
    height, width, step = int(image.height), int(image.width), int(image.step)
    raw = np.asarray(image.data, dtype=np.uint8)
    encoding = str(image.encoding).lower()
    if encoding in ("16uc1", "mono16"):
        dtype = np.dtype(">u2" if image.is_bigendian else "<u2")
        rows = raw.reshape(height, step)[:, : width * 2].copy().view(dtype)
        return depth_from_millimetres(rows.astype(np.uint16))
    if encoding == "32fc1":
        dtype = np.dtype(">f4" if image.is_bigendian else "<f4")
        depth = raw.reshape(height, step)[:, : width * 4].copy().view(dtype).astype(np.float32)
        return np.where(np.isfinite(depth) & (depth > 0), depth, np.float32(0.0)).astype(np.float32)
    raise ValueError(f"depth images must be 16UC1 (millimetres) or 32FC1 (metres), not {image.encoding!r}")


def image_millimetres(image) -> np.ndarray:
    """The uint16 millimetre array of a ``16UC1`` image (exactly as recorded)."""
    dtype = np.dtype(">u2" if image.is_bigendian else "<u2")
    raw = np.asarray(image.data, dtype=np.uint8).reshape(int(image.height), int(image.step))
    return raw[:, : int(image.width) * 2].copy().view(dtype).astype(np.uint16)


# ---------------------------------------------------------------------------- camera
def camera_info_message(k: CameraIntrinsics, t_ns: int):
    """A ``sensor_msgs/CameraInfo`` for an undistorted pinhole camera."""
    types = typestore().types
    K = np.array([k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0])
    P = np.array([k.fx, 0.0, k.cx, 0.0, 0.0, k.fy, k.cy, 0.0, 0.0, 0.0, 1.0, 0.0])
    roi = types["sensor_msgs/msg/RegionOfInterest"](x_offset=0, y_offset=0, height=0, width=0, do_rectify=False)
    return types["sensor_msgs/msg/CameraInfo"](
        header=_header(t_ns, CAMERA_FRAME), height=k.height, width=k.width, distortion_model="plumb_bob",
        d=np.zeros(5), k=K, r=np.eye(3).reshape(-1), p=P, binning_x=0, binning_y=0, roi=roi)


def intrinsics_from_info(info) -> CameraIntrinsics:
    """Pinhole intrinsics of a ``CameraInfo`` (ROS 2 spells the matrix ``k``, ROS 1 ``K``)."""
    K = np.asarray(info.k if hasattr(info, "k") else info.K, dtype=float)
    return CameraIntrinsics(int(info.width), int(info.height), float(K[0]), float(K[4]), float(K[2]), float(K[5]))


def mount_message(mount: CameraMount, t_ns: int):
    """A ``tf2_msgs/TFMessage`` with the ``base_link`` → optical-frame transform of a mount."""
    from scipy.spatial.transform import Rotation

    types = typestore().types
    m = camera_to_base_matrix(mount)
    qx, qy, qz, qw = Rotation.from_matrix(m[:3, :3]).as_quat()
    transform = types["geometry_msgs/msg/Transform"](
        translation=types["geometry_msgs/msg/Vector3"](x=float(m[0, 3]), y=float(m[1, 3]), z=float(m[2, 3])),
        rotation=types["geometry_msgs/msg/Quaternion"](x=float(qx), y=float(qy), z=float(qz), w=float(qw)))
    stamped = types["geometry_msgs/msg/TransformStamped"](
        header=_header(t_ns, BASE_FRAME), child_frame_id=CAMERA_FRAME, transform=transform)
    return types["tf2_msgs/msg/TFMessage"](transforms=[stamped])


def mount_from_tf(message) -> CameraMount | None:
    """The camera mount in a ``TFMessage`` (None when it has no base → camera transform)."""
    from scipy.spatial.transform import Rotation

    for stamped in message.transforms:
        if stamped.child_frame_id != CAMERA_FRAME:
            continue
        q = stamped.transform.rotation
        r = Rotation.from_quat([q.x, q.y, q.z, q.w]).as_matrix()
        t = stamped.transform.translation
        tilt = math.atan2(-r[2, 2], r[0, 2])  # optical axis = (cos tilt, 0, −sin tilt) in the base
        return CameraMount(height_m=float(t.z), tilt_rad=float(tilt), forward_m=float(t.x))
    return None


# ---------------------------------------------------------------------------- poses and motion
def _quaternion(theta: float):
    return typestore().types["geometry_msgs/msg/Quaternion"](
        x=0.0, y=0.0, z=math.sin(theta / 2.0), w=math.cos(theta / 2.0))


def yaw_of(q) -> float:
    """Heading (radians about +z) of a quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def _pose_message(pose: Pose2D):
    types = typestore().types
    return types["geometry_msgs/msg/Pose"](
        position=types["geometry_msgs/msg/Point"](x=pose.x, y=pose.y, z=0.0), orientation=_quaternion(pose.theta))


def pose_of(pose_message) -> Pose2D:
    return Pose2D(float(pose_message.position.x), float(pose_message.position.y), yaw_of(pose_message.orientation))


def round_trip_pose(pose: Pose2D) -> Pose2D:
    """``pose`` as a recording gives it back (its heading through a quaternion)."""
    return pose_of(_pose_message(pose))


def pose_stamped_message(pose: Pose2D, t_ns: int):
    return typestore().types["geometry_msgs/msg/PoseStamped"](header=_header(t_ns, ODOM_FRAME), pose=_pose_message(pose))


def twist_message(linear_m_s: float, angular_rad_s: float):
    types = typestore().types
    Vector3 = types["geometry_msgs/msg/Vector3"]
    return types["geometry_msgs/msg/Twist"](linear=Vector3(x=float(linear_m_s), y=0.0, z=0.0),
                                            angular=Vector3(x=0.0, y=0.0, z=float(angular_rad_s)))


def odometry_message(odometry: Odometry, t_ns: int):
    types = typestore().types
    covariance = np.zeros(36)
    return types["nav_msgs/msg/Odometry"](
        header=_header(t_ns, ODOM_FRAME), child_frame_id=BASE_FRAME,
        pose=types["geometry_msgs/msg/PoseWithCovariance"](pose=_pose_message(odometry.pose), covariance=covariance),
        twist=types["geometry_msgs/msg/TwistWithCovariance"](
            twist=twist_message(odometry.linear_m_s, odometry.angular_rad_s), covariance=covariance.copy()))


def odometry_of(message) -> Odometry:
    """An :class:`Odometry` from a ``nav_msgs/Odometry`` (time from its header stamp)."""
    twist = message.twist.twist
    return Odometry(pose_of(message.pose.pose), float(twist.linear.x), float(twist.angular.z),
                    from_ns(stamp_ns(message.header.stamp)))


def string_message(payload: dict):
    return typestore().types["std_msgs/msg/String"](data=json.dumps(payload, ensure_ascii=False))

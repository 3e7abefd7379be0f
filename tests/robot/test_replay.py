"""Replaying recordings as a robot: the product's MCAP sessions, ROS 1 / ROS 2 bags, TUM folders."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from assistant.errors import AssistantError
from assistant.robot import make_robot
from assistant.robot.recording import RecordingError
from assistant.robot.replay import RecordingEndedError, ReplayRobot
from tests.robot.conftest import record_sim_session


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    path = tmp_path_factory.mktemp("replay") / "session.mcap"
    return path, record_sim_session(path, steps=6)


def _replay_steps(robot, live, commands=None):
    """Drive a replay as the live session was driven; returns what it gave back."""
    seen = []
    for step, (_, _, command) in enumerate(live):
        seen.append((robot.odometry(), robot.depth_frame()))
        robot.send_velocity(*(commands[step] if commands else command))
        robot.advance(0.5)
    return seen


def test_round_trip_frames_bit_identical_and_poses_equal(session):
    path, live = session
    with ReplayRobot(path) as robot:
        assert robot.metadata["world"] == "apartment"
        seen = _replay_steps(robot, live)
        report = robot.command_report()
        assert robot.transcript == [{"t": 3.0, "speaker": "user", "text": "where is my mug?"}]
    for (odometry, frame, _), (odometry2, frame2) in zip(live, seen):
        assert np.array_equal(frame2.depth_m, frame.depth_m) and frame2.depth_m.dtype == np.float32
        assert frame2.robot_pose == frame.robot_pose and odometry2 == odometry
        assert frame2.mount == frame.mount and frame2.intrinsics == frame.intrinsics
        assert frame2.timestamp_s == frame.timestamp_s
    assert report["issued"] == len(live) and report["matched"] == len(live)
    assert report["first_difference_s"] is None


def test_a_command_that_differs_from_the_recording_is_reported(session):
    path, live = session
    commands = [c for _, _, c in live]
    commands[2] = (0.3, -0.4)
    with ReplayRobot(path) as robot:
        _replay_steps(robot, live, commands)
        report = robot.command_report()
    assert report["matched"] == len(live) - 1
    assert report["first_difference_s"] == pytest.approx(1.0)
    assert report["max_linear_difference"] == pytest.approx(0.3)
    assert report["max_angular_difference"] == pytest.approx(0.8)


def test_the_end_of_the_recording_is_a_typed_error_or_held(session):
    path, live = session
    with ReplayRobot(path) as robot:
        robot.advance(3.0)
        assert robot.ended
        with pytest.raises(RecordingEndedError, match="ends at 3.00 s"):
            robot.advance(0.5)
        assert isinstance(RecordingEndedError("x"), ConnectionError)
    with ReplayRobot(path, on_end="hold") as robot:
        robot.advance(60.0)
        assert robot.time_s == pytest.approx(60.0)
        assert np.array_equal(robot.depth_frame().depth_m, live[-1][1].depth_m)


def test_real_time_replay_waits_for_the_recorded_times(session):
    path, _ = session
    with ReplayRobot(path, speed=4.0) as robot:
        start = time.monotonic()
        robot.advance(1.0)  # one recorded second at four times real speed
        assert 0.2 <= time.monotonic() - start < 1.0


def test_factory_and_bad_paths(session, tmp_path):
    path, _ = session
    robot = make_robot(f"replay:{path}", world="ignored", seed=3)
    assert isinstance(robot, ReplayRobot) and not robot.follows_commands
    with pytest.raises(AssistantError, match="replay:PATH"):
        make_robot("replay")
    with pytest.raises(RecordingError, match="no recording at"):
        make_robot(f"replay:{tmp_path / 'missing.mcap'}")
    (tmp_path / "junk.mcap").write_bytes(b"not a recording")
    with pytest.raises(RecordingError, match="not an MCAP file"):
        ReplayRobot(tmp_path / "junk.mcap")
    with pytest.raises(RecordingError, match="not a recording this product reads"):
        ReplayRobot(tmp_path)


# ---------------------------------------------------------------------------- other robots' bags
def _depth_images(count=3, shape=(60, 80)):
    rng = np.random.default_rng(1)
    return [rng.integers(800, 3000, shape).astype(np.uint16) for _ in range(count)]


def _write_ros2_bag(path, storage):
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    T = store.types
    depths = _depth_images()
    with Writer(path, version=8, storage_plugin=getattr(StoragePlugin, storage)) as writer:
        depth = writer.add_connection("/camera/depth/image_raw", "sensor_msgs/msg/Image", typestore=store)
        colour = writer.add_connection("/camera/rgb/image_raw", "sensor_msgs/msg/Image", typestore=store)
        odom = writer.add_connection("/odom", "nav_msgs/msg/Odometry", typestore=store)
        for i, mm in enumerate(depths):
            t = 1_700_000_000_000_000_000 + i * 100_000_000
            stamp = T["builtin_interfaces/msg/Time"](sec=t // 10**9, nanosec=t % 10**9)
            header = T["std_msgs/msg/Header"](stamp=stamp, frame_id="camera")
            metres = (mm / 1000.0).astype("<f4")
            image = T["sensor_msgs/msg/Image"](header=header, height=60, width=80, encoding="32FC1", is_bigendian=0,
                                               step=320, data=metres.view(np.uint8).reshape(-1))
            rgb = T["sensor_msgs/msg/Image"](header=header, height=2, width=2, encoding="rgb8", is_bigendian=0,
                                             step=6, data=np.zeros(12, np.uint8))
            pose = T["geometry_msgs/msg/Pose"](
                position=T["geometry_msgs/msg/Point"](x=0.1 * i, y=0.0, z=0.0),
                orientation=T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=math.sin(0.05 * i), w=math.cos(0.05 * i)))
            twist = T["geometry_msgs/msg/Twist"](linear=T["geometry_msgs/msg/Vector3"](x=0.2, y=0.0, z=0.0),
                                                 angular=T["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=0.1))
            odometry = T["nav_msgs/msg/Odometry"](
                header=header, child_frame_id="base_link",
                pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=np.zeros(36)),
                twist=T["geometry_msgs/msg/TwistWithCovariance"](twist=twist, covariance=np.zeros(36)))
            writer.write(odom, t, store.serialize_cdr(odometry, "nav_msgs/msg/Odometry"))
            writer.write(colour, t, store.serialize_cdr(rgb, "sensor_msgs/msg/Image"))
            writer.write(depth, t + 1, store.serialize_cdr(image, "sensor_msgs/msg/Image"))
    return depths


@pytest.mark.parametrize("storage", ["SQLITE3", "MCAP"])
def test_a_ros2_bag_of_another_robot_replays(tmp_path, storage):
    path = tmp_path / "bag"
    depths = _write_ros2_bag(path, storage)
    with make_robot(f"replay:{path}", camera_height_m=0.8, tilt_deg=10.0) as robot:
        frame = robot.depth_frame()
        assert frame.depth_m.shape == (60, 80)
        assert np.allclose(frame.depth_m, depths[0] / 1000.0, atol=1e-6)  # 32FC1 metres
        assert frame.intrinsics.width == 80 and frame.intrinsics.fx == pytest.approx(525.0 / 8)
        assert frame.mount.height_m == 0.8 and frame.mount.tilt_rad == pytest.approx(math.radians(10))
        robot.advance(0.2)
        assert robot.odometry().pose.x == pytest.approx(0.2)
        assert robot.odometry().pose.theta == pytest.approx(0.2)
        assert robot.depth_frame().robot_pose.x == pytest.approx(0.2)


def test_a_ros1_bag_replays(tmp_path):
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    T = store.types
    path = tmp_path / "robot.bag"
    mm = _depth_images(1)[0]
    with Writer(path) as writer:
        depth = writer.add_connection("/kinect/depth/image", "sensor_msgs/msg/Image", typestore=store)
        info = writer.add_connection("/kinect/depth/camera_info", "sensor_msgs/msg/CameraInfo", typestore=store)
        header = T["std_msgs/msg/Header"](seq=0, stamp=T["builtin_interfaces/msg/Time"](sec=5, nanosec=0), frame_id="k")
        roi = T["sensor_msgs/msg/RegionOfInterest"](x_offset=0, y_offset=0, height=0, width=0, do_rectify=False)
        camera = T["sensor_msgs/msg/CameraInfo"](
            header=header, height=60, width=80, distortion_model="plumb_bob", D=np.zeros(5),
            K=np.array([70.0, 0, 40, 0, 71.0, 30, 0, 0, 1]), R=np.eye(3).reshape(-1), P=np.zeros(12),
            binning_x=0, binning_y=0, roi=roi)
        image = T["sensor_msgs/msg/Image"](header=header, height=60, width=80, encoding="16UC1", is_bigendian=0,
                                           step=160, data=mm.astype("<u2").view(np.uint8).reshape(-1))
        writer.write(info, 5 * 10**9, store.serialize_ros1(camera, "sensor_msgs/msg/CameraInfo"))
        writer.write(depth, 5 * 10**9, store.serialize_ros1(image, "sensor_msgs/msg/Image"))
    with ReplayRobot(path) as robot:
        frame = robot.depth_frame()
        assert np.array_equal(frame.to_millimetres(), mm)
        assert (frame.intrinsics.fx, frame.intrinsics.fy, frame.intrinsics.cx) == (70.0, 71.0, 40.0)
        assert robot.odometry().pose.x == 0.0  # a bag without odometry stays where it started


def test_a_tum_rgbd_folder_replays(tmp_path):
    from PIL import Image

    depths = _depth_images(2, shape=(48, 64))
    lines, truth = [], []
    for i, mm in enumerate(depths):
        Image.fromarray((mm.astype(np.uint32) * 5).astype(np.uint16)).save(tmp_path / f"{i}.png")
        lines.append(f"{100 + i * 0.5:.4f} {i}.png")
        # camera looking along world +y: its optical axis is the rotation's third column
        truth.append(f"{100 + i * 0.5:.4f} {i:.1f} 2.0 1.2 -0.7071068 0 0 0.7071068")
    (tmp_path / "depth.txt").write_text("# depth maps\n# file\n# timestamp filename\n" + "\n".join(lines) + "\n")
    (tmp_path / "groundtruth.txt").write_text("# ground truth\n" + "\n".join(truth) + "\n")
    with ReplayRobot(tmp_path) as robot:
        assert robot.metadata["format"] == "tum-rgbd"
        frame = robot.depth_frame()
        assert np.allclose(frame.depth_m, depths[0] / 1000.0, atol=1e-6)  # 5000 units per metre
        assert robot.time_s == pytest.approx(100.0)
        robot.advance(0.5)
        pose = robot.depth_frame().robot_pose
        assert (pose.x, pose.y) == pytest.approx((1.0, 2.0)) and pose.theta == pytest.approx(math.pi / 2)
        with pytest.raises(RecordingEndedError):
            robot.advance(1.0)


def test_a_tum_folder_with_a_bad_line_says_where(tmp_path):
    (tmp_path / "depth.txt").write_text("100.0\n")
    with pytest.raises(RecordingError, match=r"depth.txt: line 1"):
        ReplayRobot(tmp_path)


def test_a_real_tum_frame_replays(tmp_path, shared_dir):
    """The TUM RGB-D office frame of ../shared/realdata, as a one-frame TUM folder (in a temporary
    folder: nothing from realdata is copied into the repository)."""
    import shutil

    from PIL import Image

    source = shared_dir / "realdata" / "tum_office_open3d" / "TUM_depth.png"
    if not source.is_file():
        pytest.skip(f"{source} is not on this machine")
    (tmp_path / "depth").mkdir()
    shutil.copyfile(source, tmp_path / "depth" / "1305031102.160407.png")
    (tmp_path / "depth.txt").write_text("# timestamp filename\n1305031102.160407 depth/1305031102.160407.png\n")
    units = np.asarray(Image.open(source))
    with ReplayRobot(tmp_path, camera_height_m=1.2, tilt_deg=5.0) as robot:
        frame = robot.depth_frame()
    assert frame.depth_m.shape == units.shape
    assert np.allclose(frame.depth_m, units / 5000.0, atol=1e-6)
    assert 2.0 < float(np.median(frame.depth_m[frame.valid])) < 3.0  # the README's median, 2.4 m
    k = frame.intrinsics
    assert (k.fx, k.fy, k.cx, k.cy) == (525.0, 525.0, 319.5, 239.5)


def test_headings_come_back_to_the_last_bit_over_many_readings(tmp_path):
    """What the recording robot gave its caller equals what the replay gives, bit for bit, at
    many headings (a heading encoded twice would differ in its last bit now and then)."""
    from assistant.robot.recording import RecordingRobot
    from assistant.sim import SimRobot

    path = tmp_path / "turns.mcap"
    live = []
    with RecordingRobot(SimRobot("apartment", seed=0), path) as robot:
        robot.depth_frame()
        for step in range(80):
            robot.send_velocity(0.0, 0.37 + 0.01 * (step % 7))
            robot.advance(0.3)
            live.append((robot.odometry(), robot.time_s))
    with ReplayRobot(path) as replay:
        for odometry, t in live:
            replay.advance(0.3)
            assert replay.odometry() == odometry and replay.time_s == t

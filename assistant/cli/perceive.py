"""``assistant perceive``: detect furniture in one depth frame (simulated or from a PNG)."""

from __future__ import annotations

import argparse
import math
import re
import sys

from assistant.cli.common import (add_json_flag, emit_json, finite_float, parse_pose, print_table,
                                  run_batch, whole_number)


def _numbers(count: int, what: str):
    """An argument type for ``count`` finite numbers separated by commas or spaces; ``what``
    names them in the message (argparse names the option itself)."""
    def parse(text: str) -> tuple[float, ...]:
        parts = [p for p in re.split(r"[,;\s]+", text.strip()) if p]
        try:
            values = tuple(float(p) for p in parts)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {count} numbers ({what}), got {text!r}") from None
        if len(values) != count or not all(math.isfinite(v) for v in values):
            raise argparse.ArgumentTypeError(f"expected {count} finite numbers ({what}), got {text!r}")
        return values

    return parse


#: camera heights (metres above the floor found) a depth camera in a home is seldom outside:
#: a floor found farther off says more of a wrong --depth-scale than of the camera
LIKELY_CAMERA_HEIGHT_M = (0.35, 2.2)


#: largest --at (seconds): a week of recording
MAX_AT_S = 7 * 24 * 3600.0


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "perceive", help="detect furniture in a depth frame (simulated view or a depth PNG)",
        description="Detect furniture (category, view subclass, position, facing) in one depth "
                    "frame: rendered by the simulator from a pose in a world, or read from a 16-bit "
                    "depth PNG. Positions are in the world frame (simulated) or the camera-floor "
                    "frame (x ahead along the camera's heading, y left, origin under the camera).")
    source = parser.add_argument_group("simulated frame")
    source.add_argument("--world", help="world name or file")
    source.add_argument("--scene", default="original", help="scene: original or modified")
    source.add_argument("--pose", type=parse_pose, help="robot pose X,Y,HEADING (m, m, rad)")
    disk = parser.add_argument_group("frame from disk")
    disk.add_argument("--depth", metavar="FILE.png",
                      help="depth image: 16-bit PNG or TIFF (depth units), 32-bit float TIFF or .npy (metres)")
    disk.add_argument("--intrinsics", type=_numbers(4, "FX,FY,CX,CY in pixels"), metavar="FX,FY,CX,CY",
                      help="pinhole intrinsics in 0-based pixels")
    disk.add_argument("--depth-scale", type=finite_float, metavar="S",
                      help="metres per depth unit (0.001 for millimetres, 1 for metres; "
                           "guessed from the readings when left out)")
    disk.add_argument("--camera-height", type=finite_float, metavar="H",
                      help="camera height above the floor (m); with --tilt predicts the floor")
    disk.add_argument("--tilt", type=finite_float, metavar="DEG", help="camera pitch down (degrees)")
    replay = parser.add_argument_group("frames of a recording")
    replay.add_argument("--replay", metavar="FILE",
                        help="a recording (assistant record's .mcap, a ROS bag, a TUM RGB-D folder): "
                             "detections in every frame, in the world (odometry) frame")
    replay.add_argument("--frame", type=whole_number(0, 10**9), metavar="N",
                        help="with --replay: only frame N (0 = the first)")
    replay.add_argument("--at", type=finite_float, metavar="SECONDS",
                        help="with --replay: only the frame in view SECONDS after the recording starts")
    parser.epilog = ("Output: the floor found (the camera's height above it, its tilt and roll), then each "
                     "piece of furniture: category, view subclass (the side seen: +front, +side, +back), "
                     "position x ahead and y left (m), facing (rad: the direction its front faces, "
                     "0 = along x, counter-clockwise; - for tables), the classifier's confidence, and "
                     "notes (unsure: look again from elsewhere; partial: cut by the image border; "
                     "beyond range: it may go on past the 4 m the detector reads); then the things on "
                     "the floor it would not name.")
    parser.add_argument("--orientation", default="plane", choices=("plane", "linear"),
                        help="orientation estimator (default: plane)")
    parser.add_argument("--classifier", default=None, choices=("gsvm", "lsvm", "autoencoder"),
                        help="classifier (default: the measured best, gsvm)")
    add_json_flag(parser)
    parser.add_argument("--batch", metavar="FILE",
                        help="one JSON request per line: {world, scene, pose:[x,y,h]} or {depth, "
                             "intrinsics:[fx,fy,cx,cy], depth_scale, camera_height, tilt}")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.errors import AssistantError

    import functools

    detector = functools.cache(lambda: _detector(args))  # built when a request first needs it
    if args.replay:
        return _run_replay(detector(), args)
    if args.batch:
        return run_batch(args.batch, lambda req: _handle(detector, _request(req)), json_requests=True)
    if bool(args.world) == bool(args.depth):
        raise AssistantError("give either --world NAME --pose X,Y,HEADING or --depth FILE.png "
                             "[--intrinsics FX,FY,CX,CY --depth-scale S]")
    request = {"world": args.world, "scene": args.scene, "pose": args.pose, "depth": args.depth,
               "intrinsics": args.intrinsics, "depth_scale": args.depth_scale,
               "camera_height": args.camera_height, "tilt": args.tilt}
    result = _handle(detector, request)
    for note in result.get("assumed", []):  # defaults stood in for --intrinsics / --depth-scale
        print(f"note: {note}", file=sys.stderr)
    if args.json:
        emit_json(result)
        return 0
    _print(result)
    return 0


def _run_replay(detector, args) -> int:
    """Detections in the frames of a recording (all, or the one chosen by --frame / --at)."""
    from assistant.errors import AssistantError
    from assistant.robot.replay import ReplayRobot

    if args.world or args.depth or args.batch:
        raise AssistantError("--replay reads its frames from the recording: leave out --world, --depth and --batch")
    if args.frame is not None and args.at is not None:
        raise AssistantError("choose the frame with --frame N or --at SECONDS, not both")
    if (args.frame is not None and args.frame < 0) or (args.at is not None and args.at < 0):
        raise AssistantError("--frame and --at count from the start of the recording: use 0 or more")
    if args.at is not None and args.at > MAX_AT_S:  # (1e300 s overflowed the nanosecond clock)
        raise AssistantError(f"--at {args.at:g}: a recording is at most {MAX_AT_S:g} s long; give seconds from its start")
    rows = []
    with ReplayRobot(args.replay, on_end="hold") as robot:
        start_s = robot.time_s
        if args.at is not None:
            robot.advance(args.at)
        for index, frame in enumerate(robot.frames() if args.at is None else [robot.depth_frame()]):
            if args.frame is not None and index != args.frame:
                continue
            result = detector.analyse(frame).to_dict()
            pose = frame.robot_pose
            rows.append({"index": index if args.at is None else None, "t": round(frame.timestamp_s - start_s, 3),
                         "pose": None if pose is None else [round(pose.x, 3), round(pose.y, 3), round(pose.theta, 4)],
                         **result})
            if args.frame is not None:
                break
    if args.frame is not None and not rows:
        raise AssistantError(f"the recording has no frame {args.frame} (frames count from 0)")
    single = args.frame is not None or args.at is not None
    out = {"replay": args.replay, **rows[0]} if single else {"replay": args.replay, "frames": rows}
    if args.json:
        emit_json(out)
        return 0
    for row in rows:
        print(f"frame {row['index'] if row['index'] is not None else '-'} at {row['t']:.2f} s, pose {row['pose']}:")
        _print(row)
    return 0


def _detector(args):
    from assistant.perception import FurnitureDetector

    models = None
    if args.classifier:
        from assistant.perception.models import trained_models

        models = trained_models(method=args.classifier)
    return FurnitureDetector(models=models, orientation=args.orientation)


def _request(req: dict) -> dict:
    from assistant.errors import AssistantError

    out = dict(req)
    if "pose" in out and out["pose"] is not None:
        pose = out["pose"]
        if isinstance(pose, str):
            pose = parse_pose(pose)
        if not (isinstance(pose, (list, tuple)) and len(pose) == 3):
            raise AssistantError("pose: expected [x, y, heading]")
        out["pose"] = tuple(float(v) for v in pose)
    for key, count, what in (("intrinsics", 4, "[fx, fy, cx, cy] in pixels"),):
        value = out.get(key)
        if value is not None:
            if isinstance(value, str):
                value = _numbers(count, what)(value)
            if not (isinstance(value, (list, tuple)) and len(value) == count
                    and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)):
                raise AssistantError(f"{key}: expected {count} numbers, {what}, got {value!r}")
            out[key] = tuple(float(v) for v in value)
    for key in ("depth_scale", "camera_height", "tilt"):
        value = out.get(key)
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, float))):
            raise AssistantError(f"{key}: expected a number, got {value!r}")
    for key in ("depth", "world"):
        if out.get(key) is not None and not isinstance(out[key], str):
            raise AssistantError(f"{key}: expected a file or world name as a string, got {out[key]!r}")
    out.setdefault("scene", "original")
    return out


def _handle(detector, req: dict) -> dict:
    from assistant.errors import AssistantError

    if req.get("world"):
        if req.get("pose") is None:
            raise AssistantError("--world needs --pose X,Y,HEADING")
        from assistant.geometry import Pose2D
        from assistant.sim.renderer import DepthRenderer
        from assistant.world import load_world

        from assistant.sim import check_pose_in_map

        world = load_world(req["world"])
        check_pose_in_map(world, Pose2D(*req["pose"]))
        renderer = DepthRenderer(world, req.get("scene", "original"))
        frame = renderer.render(Pose2D(*req["pose"]))
        result = detector().analyse(frame)
        out = {"world": world.name, "scene": renderer.scene, "pose": list(req["pose"])}
    elif req.get("depth"):
        from assistant.perception.depthfile import load_depth_png

        notes: list[str] = []
        intrinsics = None if req.get("intrinsics") is None else tuple(req["intrinsics"])
        scale = None if req.get("depth_scale") is None else float(req["depth_scale"])
        frame, has_mount = load_depth_png(req["depth"], intrinsics, scale, camera_height_m=req.get("camera_height"),
                                          tilt_deg=req.get("tilt"), notes=notes)
        result = detector().analyse(frame, use_mount=has_mount)
        out = {"depth": str(req["depth"])}
        if notes:
            out["assumed"] = notes
    else:
        raise AssistantError("a request needs either world and pose, or depth (with intrinsics and depth_scale "
                             "if they are not a Kinect's and millimetres)")
    out.update(result.to_dict())
    out["ms"] = round(result.timings_ms.get("total", 0.0), 1)
    floor = out.get("floor")
    if req.get("depth") and floor and not req.get("camera_height") and not (
            LIKELY_CAMERA_HEIGHT_M[0] <= floor["height"] <= LIKELY_CAMERA_HEIGHT_M[1]):
        out.setdefault("assumed", []).append(
            f"the floor was found {floor['height']:.2f} m below the camera, an unlikely height for a "
            "depth camera: if the depth units are wrong, so is everything here — check --depth-scale")
    return out


def _print(result: dict) -> None:
    floor = result.get("floor")
    if floor:
        print(f"floor: camera {floor['height']:.2f} m above it, tilted {floor['tilt_deg']:.1f}°, "
              f"rolled {floor['roll_deg']:.1f}°")
    else:
        print("floor: not found")
    if not result["detections"]:
        print(f"no furniture: {result.get('reason', 'nothing recognised')}")
    else:
        rows = [(d["category"], d["subclass"] if d["subclass"] != d["category"] else "-", d["x"], d["y"],
                 "-" if d["facing"] is None else f"{d['facing']:.2f}", d["confidence"], _notes(d))
                for d in result["detections"]]
        print_table(rows, ["category", "view", "x (m)", "y (m)", "facing (rad)", "confidence", "notes"])
    for u in result.get("unknown", []):
        why = {"unsure": "the classifier is unsure",
               "disputed": "cut by the range, the second opinion disagrees",
               "no surface": "tall, with no seat, mattress or top"}.get(u["why"], u["why"])
        what = (f"not one of the five kinds ({u['probability']:.2f}): a bench, dresser, shelf …" if u["best"] == "other"
                else f"looks most like a {u['best']} ({u['probability']:.2f}), but {why}")
        print(f"unknown thing at x {u['x']:.2f} m, y {u['y']:.2f} m, {u['height']:.2f} m high: {what}")


def _notes(detection: dict) -> str:
    """The caveats of a detection, as words: unsure, partial, beyond range."""
    notes = [word for key, word in (("unsure", "unsure"), ("partial", "partial"),
                                    ("beyond_range", "beyond range")) if detection.get(key)]
    return ", ".join(notes) or "-"

"""``assistant record --robot SPEC OUT.mcap``: record a robot session as MCAP (ROS 2 messages).

Without ``--fetch`` the robot looks around: it turns once in place and takes a depth frame
every ``--step-deg`` degrees (on a real robot: slowly, where it stands — clear the space around
it first). With ``--fetch TEXT`` it carries out that fetch command and the recording holds
everything the task saw and did; ``assistant fetch TEXT --robot replay:OUT.mcap`` replays it.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import add_json_flag, emit_json, finite_float, out_file, seed_int


#: smallest --step-deg: 360 frames in one turn (0.0001° asked for 3.6 million and never ended)
MIN_STEP_DEG = 1.0


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "record", help="record a robot session (depth, odometry, commands) as an MCAP file",
        description="Record what a robot senses and does — depth frames (sensor_msgs/Image 16UC1, "
                    "millimetres), camera info, odometry, velocity commands and the dialogue — as "
                    "ROS 2 messages in an MCAP file, written as it happens (a cut file replays up to "
                    "the cut). Replay it with --robot replay:OUT.mcap.")
    parser.add_argument("out", metavar="OUT.mcap", type=out_file(".mcap"), help="the recording to write")
    parser.add_argument("--robot", required=True, metavar="SPEC",
                        help="sim:WORLD[:SCENE], p3dx:PORT, or replay:PATH (to re-record a recording)")
    parser.add_argument("--fetch", metavar="TEXT", help="carry out this fetch command while recording")
    parser.add_argument("--world", metavar="NAME",
                        help="the home (default: the one a sim spec names; needed with --fetch on a real robot)")
    parser.add_argument("--scene", default="original", help="scene: original or modified (default: original)")
    parser.add_argument("--perception", choices=("sensed", "oracle"), default="sensed",
                        help="furniture perception for --fetch (default: sensed)")
    parser.add_argument("--seed", type=seed_int, default=0, help="simulator seed (default 0)")
    parser.add_argument("--step-deg", type=finite_float, default=30.0, metavar="DEG",
                        help="looking around: a frame every DEG degrees of the turn (default 30)")
    parser.add_argument("--turn-rate", type=finite_float, default=0.4, metavar="RAD_S",
                        help="looking around: turn rate in rad/s (default 0.4)")
    parser.add_argument("--overwrite", action="store_true", help="replace OUT.mcap if it exists")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.errors import AssistantError
    from assistant.robot import make_robot, parse_robot_spec
    from assistant.robot.recording import RecordingRobot, recording_summary

    if not (MIN_STEP_DEG <= args.step_deg <= 360 and args.turn_rate > 0):
        raise AssistantError(f"--step-deg must be from {MIN_STEP_DEG:g} to 360 degrees (a frame every step of "
                             "one turn) and --turn-rate positive")
    spec = parse_robot_spec(args.robot)
    world = args.world or (spec.argument.partition(":")[0] if spec.scheme == "sim" else None) or None
    scene = (spec.argument.partition(":")[2] if spec.scheme == "sim" else "") or args.scene
    if args.fetch and not world:
        raise AssistantError("say which home the fetch is in: --world NAME")
    # the home options (each robot takes those it needs); noisy odometry as the fetch command drives
    options = {"world": world, "scene": scene, "seed": args.seed, "noise": bool(args.fetch)}
    metadata = {"spec": str(spec), "world": world or "", "scene": scene if world else "",
                "task": f"fetch: {args.fetch}" if args.fetch else f"look around, a frame every {args.step_deg:g}°"}
    if args.fetch:
        metadata["fetch"] = args.fetch
    robot = RecordingRobot(make_robot(spec, **options), args.out, metadata, overwrite=args.overwrite)
    if args.fetch:
        result = _fetch(robot, args, world, scene)
    else:
        with robot:
            look_around(robot, args.step_deg, args.turn_rate)
        result = None
    summary = recording_summary(args.out)
    if result is not None:
        summary["fetch"] = {k: result[k] for k in ("success", "failure", "final_pose", "sim_seconds")}
    if args.json:
        emit_json(summary)
    else:
        print(f"recorded {summary['frames']} depth frames, {summary['odometry']} odometry readings and "
              f"{summary['commands']} velocity commands over {summary['seconds']:.1f} s "
              f"to {args.out} ({summary['bytes'] / 1e6:.1f} MB)")
        if result is not None:
            print("fetch: " + ("SUCCESS" if result["success"] else f"FAILED: {result['failure']}"))
    return 0


def look_around(robot, step_deg: float = 30.0, turn_rate_rad_s: float = 0.4) -> int:
    """Turn once in place, a frame every ``step_deg`` degrees; returns the frames read."""
    import math

    steps = max(1, round(360.0 / step_deg))
    interval_s = math.radians(360.0 / steps) / turn_rate_rad_s
    for _ in range(steps):
        robot.odometry()
        robot.depth_frame()
        robot.send_velocity(0.0, turn_rate_rad_s)
        robot.advance(interval_s)
    robot.stop()
    robot.odometry()
    robot.depth_frame()
    return steps + 1


def _fetch(robot, args, world: str, scene: str) -> dict:
    from assistant.app import Fetcher

    robot.connect()
    robot.record_turn("user", args.fetch)
    outcome = Fetcher().fetch(args.fetch, world, scene, args.perception, robot=robot, seed=args.seed)
    robot.close()
    return outcome.data

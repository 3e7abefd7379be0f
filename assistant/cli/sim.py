"""``assistant sim render``: a simulated Kinect depth frame as a 16-bit PNG (millimetres)."""

from __future__ import annotations

import argparse

from assistant.cli.common import add_json_flag, emit_json, finite_float, out_file, parse_pose, seed_int


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "sim", help="the simulator: render what the robot's Kinect sees",
        description="Simulator tools.",
    )
    sub = parser.add_subparsers(dest="sim_command", metavar="SIM_COMMAND")
    sub.required = True
    render = sub.add_parser(
        "render", help="write a simulated depth frame (16-bit PNG, millimetres) and its intrinsics",
        description="Ray-cast the Kinect's depth frame from a robot pose in a world and write it as "
                    "a 16-bit PNG in millimetres (0 = no reading), with a JSON sidecar FILE.json "
                    "holding the intrinsics, camera height, tilt, depth scale and robot pose.",
    )
    render.add_argument("name", help="world name (apartment, hk-studio, …) or a world file path")
    render.add_argument("--pose", required=True, type=parse_pose, metavar="X,Y,HEADING",
                        help="robot pose: metres, metres, radians counter-clockwise from +x")
    render.add_argument("--scene", default="original", help="scene: original or modified")
    render.add_argument("--tilt", type=finite_float, default=15.0, metavar="DEG",
                        help="downward tilt of the camera in degrees (default 15)")
    render.add_argument("--seed", type=seed_int, default=0, help="seed of the sensor noise (default 0)")
    render.add_argument("--no-noise", action="store_true", help="exact depth: no noise or quantisation")
    render.add_argument("--out", required=True, metavar="FILE.png", type=out_file(".png"), help="PNG file to write")
    add_json_flag(render)
    render.set_defaults(handler=run_render)


def run_render(args: argparse.Namespace) -> int:
    import io
    import math
    from pathlib import Path

    import numpy as np
    from PIL import Image

    from assistant.fileio import atomic_write_bytes, atomic_write_text
    from assistant.geometry import Pose2D
    from assistant.robot import CameraMount
    from assistant.sim import DepthRenderer, KinectNoise, check_pose_in_map
    from assistant.world import load_world

    from assistant.perception.depthfile import check_mount

    check_mount(None, args.tilt)
    world = load_world(args.name)
    scene = world.scene(args.scene).name
    pose = Pose2D(*args.pose)
    check_pose_in_map(world, pose)  # before building the scene: a quick, clear refusal
    mount = CameraMount(height_m=CameraMount().height_m, tilt_rad=math.radians(args.tilt))
    noise = KinectNoise.none() if args.no_noise else KinectNoise()
    renderer = DepthRenderer(world, scene, mount=mount, noise=noise, seed=args.seed)
    frame = renderer.render(pose)

    millimetres = frame.to_millimetres()
    buffer = io.BytesIO()
    image = Image.fromarray(np.ascontiguousarray(millimetres))  # uint16 → mode "I;16"
    assert image.mode == "I;16", image.mode
    image.save(buffer, format="PNG")
    out = Path(args.out)
    atomic_write_bytes(out, buffer.getvalue())

    valid = frame.valid
    seen = sorted({frame.hit_names[i] for i in np.unique(frame.hit_ids[valid]) if i >= 0})
    info = {
        "world": world.name,
        "scene": scene,
        "file": str(out),
        "width": frame.intrinsics.width,
        "height": frame.intrinsics.height,
        "intrinsics": frame.intrinsics.to_dict(),
        "depth_scale": 0.001,
        "depth_units": "millimetres; 0 = no reading",
        "camera_height": mount.height_m,
        "tilt_deg": args.tilt,
        "tilt_rad": mount.tilt_rad,
        "robot_pose": pose.to_dict(),
        "seed": args.seed,
        "noise": not args.no_noise,
        "valid_fraction": round(float(valid.mean()), 4),
        "depth_range_m": ([round(float(frame.depth_m[valid].min()), 3),
                           round(float(frame.depth_m[valid].max()), 3)] if valid.any() else None),
        "seen": seen,  # ground truth from the simulator, for checking
    }
    sidecar = out.with_name(out.name + ".json")
    import json

    atomic_write_text(sidecar, json.dumps(info, indent=2) + "\n")
    info["sidecar"] = str(sidecar)
    if args.json:
        emit_json(info)
    else:
        k = frame.intrinsics
        print(f"wrote {out} ({k.width}×{k.height}, 16-bit millimetres, "
              f"{100 * info['valid_fraction']:.1f}% valid) and {sidecar}")
        print(f"intrinsics fx={k.fx} fy={k.fy} cx={k.cx} cy={k.cy}; camera {mount.height_m} m up, "
              f"tilted {args.tilt}° down; depth scale 0.001")
        print("sees: " + (", ".join(seen) or "nothing in range"))
    return 0

"""Benchmark: simulated Kinect depth frames (640×480) of furnished rooms, frames per second.

Target (issue "The robot's world"): median ≥ 60 frames/s on the 2-core machine (a real Kinect
delivers 30). Renders a loop of poses in the apartment's living room and bedroom with the
default renderer (adaptive casting + Kinect noise) and, in the same run for comparison, with
every pixel cast. Prints medians over repeated rounds.

    .venv/bin/python benchmarks/bench_render.py [--rounds 7] [--frames 60] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import time


def _poses():
    from assistant.geometry import Pose2D

    # furnished views: living room (couch, tables, chairs) and bedroom (bed, tables, chairs)
    out = []
    for i in range(12):
        a = 2 * math.pi * i / 12
        out.append(Pose2D(4.5 + 0.6 * math.cos(a), 5.3 + 0.4 * math.sin(a), -math.pi / 2 + 0.5 * math.sin(a)))
        out.append(Pose2D(3.0 + 0.4 * math.cos(a), 2.3, 0.3 * math.sin(a)))
        out.append(Pose2D(1.0 + 0.3 * math.cos(a), -4.5 + 0.5 * math.sin(a), math.pi + 0.4 * math.sin(a)))
        out.append(Pose2D(3.0, -5.0 + 0.5 * math.sin(a), 0.5 * math.cos(a)))
    return out


def _time_frames(render, poses, frames: int) -> list[float]:
    times = []
    for i in range(frames):
        pose = poses[i % len(poses)]
        t0 = time.perf_counter()
        render(pose)
        times.append(time.perf_counter() - t0)
    return times


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--frames", type=int, default=60, help="frames per round")
    parser.add_argument("--world", default="apartment")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)

    from assistant.sim import DepthRenderer
    from assistant.world import load_world

    world = load_world(args.world)
    t0 = time.perf_counter()
    renderer = DepthRenderer(world, "original", seed=0)
    build_s = time.perf_counter() - t0
    full = DepthRenderer(world, "original", seed=0, adaptive=False)
    poses = _poses()
    for pose in poses[:8]:  # warm up (BVH build on the first cast)
        renderer.render(pose)
        full.render(pose)

    round_fps, round_full_fps, all_times, fractions, cpu_ms = [], [], [], [], []
    for _ in range(args.rounds):
        cpu0 = time.process_time()
        times = _time_frames(renderer.render, poses, args.frames)
        cpu_ms.append(1000 * (time.process_time() - cpu0) / args.frames)
        fractions.append(renderer.last_cast_fraction)
        full_times = _time_frames(full.render, poses, max(10, args.frames // 4))
        all_times.extend(times)
        round_fps.append(1.0 / statistics.median(times))
        round_full_fps.append(1.0 / statistics.median(full_times))
    median_frame_ms = 1000 * statistics.median(all_times)
    result = {
        "world": world.name,
        "frame": "640x480",
        "rounds": args.rounds,
        "frames_per_round": args.frames,
        "scene_build_s": round(build_s, 3),
        "median_frame_ms": round(median_frame_ms, 2),
        "median_fps": round(statistics.median(round_fps), 1),
        "round_fps": [round(f, 1) for f in round_fps],
        "every_pixel_median_fps": round(statistics.median(round_full_fps), 1),
        "speedup_vs_every_pixel": round(statistics.median(round_fps) / statistics.median(round_full_fps), 2),
        "median_cpu_ms_per_frame": round(statistics.median(cpu_ms), 2),
        "load_average_1min": round(os.getloadavg()[0], 2),
        "rays_cast_fraction_last_frame": round(fractions[-1], 3),
        "target_fps": 60,
    }
    if args.json:
        print(json.dumps(result))
    else:
        print(f"{world.name}: scene built in {build_s * 1000:.0f} ms")
        print(f"median frame {median_frame_ms:.1f} ms → median {result['median_fps']} frames/s over "
              f"{args.rounds} rounds of {args.frames} frames (rounds: {result['round_fps']})")
        print(f"CPU time {result['median_cpu_ms_per_frame']} ms per frame (all threads); "
              f"load average during the run {result['load_average_1min']} on {os.cpu_count()} cores")
        print(f"casting every pixel: {result['every_pixel_median_fps']} frames/s "
              f"(adaptive is {result['speedup_vs_every_pixel']}× faster)")
        print(f"target ≥ 60 frames/s: {'met' if result['median_fps'] >= 60 else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

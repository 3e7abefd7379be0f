"""Perception speed: one 640×480 Kinect frame, depth → detections, end to end.

Renders a few views of the apartment with the simulator once, then times
``FurnitureDetector.analyse`` on them over repeated runs and prints the median per frame and
per stage (milliseconds). Target: median ≤ 33 ms on the 2-core machine.

    .venv/bin/python benchmarks/bench_perception.py [--repeats N]
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

POSES = [(4.5, 6.0, -math.pi / 2), (3.0, 3.5, -0.6), (5.5, 2.0, 2.2), (5.0, 0.0, math.pi),
         (-0.5, -3.0, -1.2), (4.0, -5.5, 1.2)]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()

    from assistant.geometry import Pose2D
    from assistant.perception import FurnitureDetector
    from assistant.sim.renderer import DepthRenderer
    from assistant.world import load_world

    world = load_world("apartment")
    renderer = DepthRenderer(world, "original", seed=0)
    frames = [renderer.render(Pose2D(*p)) for p in POSES]
    detector = FurnitureDetector()
    for frame in frames:  # warm-up (imports, caches)
        detector.analyse(frame)
    totals, stages = [], {}
    detections = 0
    for _ in range(args.repeats):
        for frame in frames:
            t = time.perf_counter()
            result = detector.analyse(frame)
            totals.append((time.perf_counter() - t) * 1e3)
            for k, v in result.timings_ms.items():
                stages.setdefault(k, []).append(v)
            detections += len(result.detections)
    print(f"frames: {len(frames)} views × {args.repeats} runs = {len(totals)}; "
          f"{detections / len(totals):.1f} detections per frame")
    print(f"end to end: median {statistics.median(totals):.1f} ms, "
          f"p90 {sorted(totals)[int(0.9 * len(totals))]:.1f} ms (target ≤ 33 ms)")
    for k, v in stages.items():
        if k != "total":
            print(f"  {k:<9} median {statistics.median(v):.1f} ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Benchmark: the 3D scene view — server start/stop, drawing a home, writing its page.

    .venv/bin/python benchmarks/bench_scene_view.py [--world apartment] [--repeats 7]

Prints medians (and min/max) over repeated runs of:
  * starting and closing a meshcat server (SceneView() then close());
  * drawing the world and building its HTML page without a server (the world's meshes are
    built once beforehand, as ``assistant world NAME --html`` builds them once);
  * starting a server, drawing the world into it and closing it;
  * drawing a simulated Kinect frame's point cloud (stride 2) into a server-less view;
and the size of the world's page and of the page with that point cloud.
Timings are noisy on a shared 2-core machine; the medians are what to compare.
"""

from __future__ import annotations

import argparse
import statistics
import time


def _timed(fn, repeats: int) -> tuple[float, float, float]:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), min(times), max(times)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--world", default="apartment")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()

    from assistant.sim import DepthRenderer
    from assistant.sim.meshes import scene_meshes
    from assistant.viz import SceneView
    from assistant.world import load_world

    world = load_world(args.world)
    meshes = scene_meshes(world, "original")
    frame = DepthRenderer(world, "original").render(world.start)

    def start_close():
        SceneView().close()

    def draw_offline():
        view = SceneView(open_server=False)
        view.draw_world(world, meshes=meshes)
        view.static_html()

    def draw_live():
        with SceneView() as view:
            view.draw_world(world, meshes=meshes)

    def draw_cloud():
        SceneView(open_server=False).draw_depth_frame("kinect", frame)

    rows = [("server start + close", start_close),
            ("draw world + build page (no server)", draw_offline),
            ("server start + draw world + close", draw_live),
            ("draw a depth frame's point cloud", draw_cloud)]
    print(f"{args.world}: medians over {args.repeats} runs (min–max), seconds")
    for label, fn in rows:
        med, lo, hi = _timed(fn, args.repeats)
        print(f"  {label:<38} {med:7.3f}  ({lo:.3f}–{hi:.3f})")

    view = SceneView(open_server=False)
    view.draw_world(world, meshes=meshes)
    plain = len(view.static_html().encode("utf-8"))
    points = view.draw_depth_frame("kinect", frame)
    with_cloud = len(view.static_html().encode("utf-8"))
    print(f"  page size: {plain / 1e6:.2f} MB; with the {len(points)}-point cloud seen from "
          f"the start pose: {with_cloud / 1e6:.2f} MB")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

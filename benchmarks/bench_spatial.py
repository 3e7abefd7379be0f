"""Speed of the spatial layer (medians over repeated runs; run on an idle machine for best figures).

    .venv/bin/python benchmarks/bench_spatial.py [--repeats N] [--json]

1. World state feature at one candidate robot pose (couch, coffee table and the robot of the
   apartment's living room on a 0.1 m grid): with the node's builder (fixed pairs cached — how
   a move-to search uses it; target ≤ 1 ms) and one-shot (everything recomputed).
2. F0 + F2 for two 2 m × 1 m objects at 0.05 m cells (target ≤ 5 ms): both from one
   correlation (``force_histograms``) and as two ``histogram_of_forces`` calls.
3. ``relations()`` for every furniture pair of the apartment at 0.05 m.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import numpy as np  # noqa: E402

from assistant.geometry import GridMap, Pose2D, rectangle  # noqa: E402
from assistant.spatial import (  # noqa: E402
    WSFBuilder,
    force_histograms,
    histogram_of_forces,
    relations,
    world_state_feature,
)
from assistant.world import Entity, EntityKind, furniture_entities, load_world, world_grid  # noqa: E402


CPU: dict[str, float] = {}


def median_ms(fn, repeats: int, warmup: int = 3, name: str | None = None) -> float:
    """Median wall-clock milliseconds per call; the median CPU time of this process per call
    goes to ``CPU[name]`` (less sensitive to other processes sharing the cores)."""
    for _ in range(warmup):
        fn()
    times, cpu = [], []
    for _ in range(repeats):
        c0 = time.process_time()
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    if name:
        CPU[name] = 1000.0 * statistics.median(cpu)
    return 1000.0 * statistics.median(times)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=200)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    results: dict[str, float] = {}

    world = load_world("apartment")
    grid = world_grid(world, 0.1)
    items = {e.id: e for e in furniture_entities(world, "original", grid)}
    couch, table = items["couch_1"], items["coffeetable_1"]
    start = Pose2D(2.6, 1.8, np.pi / 2)  # just inside the living-room door
    rng = np.random.default_rng(0)
    poses = [Pose2D(x, y, t) for x, y, t in zip(rng.uniform(2.0, 6.8, 1000), rng.uniform(1.7, 7.4, 1000),
                                                  rng.uniform(-np.pi, np.pi, 1000))]
    builder = WSFBuilder(start, couch, table)
    it = iter(poses * 100)
    results["wsf_cached_ms"] = median_ms(lambda: builder.feature(next(it)), args.repeats,
                                         name="wsf_cached_cpu_ms")
    it2 = iter(poses * 100)
    results["wsf_one_shot_ms"] = median_ms(lambda: world_state_feature(next(it2), start, couch, table),
                                           max(20, args.repeats // 4))
    c0, t0 = time.process_time(), time.perf_counter()
    for p in poses[:500]:
        builder.feature(p)
    results["wsf_500_candidates_s"] = time.perf_counter() - t0
    results["wsf_500_candidates_cpu_s"] = time.process_time() - c0

    g05 = GridMap(0.05, 0.0, 0.0, 160, 160)
    a = Entity.from_polygon("a", "a", EntityKind.SHORT_TERM, rectangle(Pose2D(2.0, 2.0, 0.0), 2.0, 1.0), g05)
    b = Entity.from_polygon("b", "b", EntityKind.SHORT_TERM, rectangle(Pose2D(4.6, 5.1, 0.0), 2.0, 1.0), g05)
    am, bm = a.mask(), b.mask()
    results["f0_f2_pair_ms"] = median_ms(lambda: force_histograms(am, bm), args.repeats,
                                         name="f0_f2_pair_cpu_ms")
    results["f0_then_f2_ms"] = median_ms(
        lambda: (histogram_of_forces(am, bm, force="constant"),
                 histogram_of_forces(am, bm, force="gravitational")), args.repeats)
    results["relations_apartment_s"] = median_ms(lambda: relations(world), 5, warmup=1) / 1000.0

    results.update(CPU)
    results["load_average_1min"] = os.getloadavg()[0]
    if args.json:
        print(json.dumps({k: round(v, 4) for k, v in results.items()}))
        return 0
    print(f"WSF at one candidate pose, cached builder   : {results['wsf_cached_ms']:.3f} ms wall, "
          f"{results['wsf_cached_cpu_ms']:.3f} ms CPU (target ≤ 1 ms)")
    print(f"WSF at one candidate pose, one-shot         : {results['wsf_one_shot_ms']:.3f} ms")
    print(f"500 candidate poses with one builder        : {results['wsf_500_candidates_s']:.3f} s wall, "
          f"{results['wsf_500_candidates_cpu_s']:.3f} s CPU")
    print(f"F0 + F2, 2 m × 1 m objects, 0.05 m cells    : {results['f0_f2_pair_ms']:.3f} ms wall, "
          f"{results['f0_f2_pair_cpu_ms']:.3f} ms CPU (target ≤ 5 ms)")
    print(f"  as two histogram_of_forces calls          : {results['f0_then_f2_ms']:.3f} ms")
    print(f"relations() for the apartment at 0.05 m     : {results['relations_apartment_s']:.3f} s")
    print(f"(1-minute load average during the run: {results['load_average_1min']:.1f} on {os.cpu_count()} cores)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""How long the robot takes to compose its answer once the object is found.

Composition = content selection (candidates from the spatial layer, exact maximisation of
O(W)) + surface realization (chunks, Algorithm 1, guards), i.e. ``Describer.describe`` with
the environment model already built (the robot builds it while it searches) and the
generation model already loaded (it is loaded when the assistant starts). Target: within
100 ms of the object being found. Prints medians over repeated runs of the 48 study
descriptions, plus the one-off costs (model load from the cache, first description).

    .venv/bin/python benchmarks/bench_generation.py [--repeats 5]
"""

from __future__ import annotations

import argparse
import statistics
import time


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5, help="runs over the 48 descriptions")
    ap.add_argument("--style", choices=("static", "dynamic"), default="static")
    args = ap.parse_args()

    from assistant.generation import Describer, load_generation_model, oracle_cases
    from assistant.generation.evaluation import SCENES, STUDY_WORLDS

    t0 = time.perf_counter()
    model = load_generation_model()
    load_s = time.perf_counter() - t0
    describer = Describer(model)
    cases = []
    for case in oracle_cases(STUDY_WORLDS, SCENES):
        cases.append((case.world, case.environment, case.sighting))
    first = None
    per_run_medians, all_ms = [], []
    for rep in range(args.repeats):
        times = []
        for world, env, sighting in cases:
            t = time.perf_counter()
            describer.describe(sighting, env, world.floorplan,
                               listener_pose=world.start if args.style == "dynamic" else None,
                               style=args.style)
            ms = (time.perf_counter() - t) * 1000
            if first is None:
                first = ms
            times.append(ms)
        per_run_medians.append(statistics.median(times))
        all_ms.extend(times)
    all_ms.sort()
    p95 = all_ms[int(0.95 * (len(all_ms) - 1))]
    print(f"generation model load (cache): {load_s * 1000:.0f} ms")
    print(f"first description (cold imports): {first:.1f} ms")
    print(f"{args.style} composition, {len(cases)} descriptions x {args.repeats} runs:")
    print(f"  median {statistics.median(all_ms):.1f} ms (per-run medians "
          f"{', '.join(f'{m:.1f}' for m in per_run_medians)}), 95th percentile {p95:.1f} ms, "
          f"max {all_ms[-1]:.1f} ms; target <= 100 ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""How long the robot takes to compose its answer once the object is found, and how long the
search takes before that.

Composition = content selection (candidates from the spatial layer, exact maximisation of
O(W)) + surface realization (chunks, Algorithm 1, guards), i.e.
``Describer.describe_search`` on a finished search (the environment model is the one the
robot built while searching; the generation model is loaded when the assistant starts).
Target: within 100 ms of the object being found. The search is measured separately: each
case is searched once (sensed perception, simulated robot from the world's start pose), then
the composition is timed ``--repeats`` times on that search's result. Prints medians.

    .venv/bin/python benchmarks/bench_generation.py [--repeats 5] [--cases 48]
    .venv/bin/python benchmarks/bench_generation.py --searches FILE   # saved by the evaluation
    .venv/bin/python benchmarks/bench_generation.py --search oracle   # world-file furniture
"""

from __future__ import annotations

import argparse
import statistics
import time


def _summary(ms: list[float]) -> str:
    ms = sorted(ms)
    p95 = ms[int(0.95 * (len(ms) - 1))]
    return f"median {statistics.median(ms):.1f} ms, 95th percentile {p95:.1f} ms, max {ms[-1]:.1f} ms"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5, help="compositions per case")
    ap.add_argument("--style", choices=("static", "dynamic"), default="static")
    ap.add_argument("--search", choices=("sensed", "oracle"), default="sensed")
    ap.add_argument("--cases", type=int, default=48, help="how many of the 48 study cases")
    ap.add_argument("--searches", metavar="FILE",
                    help="re-use the searches saved by `assistant eval generation --save-searches FILE`")
    args = ap.parse_args()

    from assistant.generation import Describer, load_generation_model, oracle_cases
    from assistant.eval.generation import SCENES, STUDY_WORLDS

    t0 = time.perf_counter()
    model = load_generation_model()
    load_s = time.perf_counter() - t0
    describer = Describer(model)
    cases = list(oracle_cases(STUDY_WORLDS, SCENES))[:args.cases]
    searches = []
    if args.search == "sensed":
        saved = {}
        if args.searches:
            import pickle

            with open(args.searches, "rb") as fh:
                saved = pickle.load(fh)
        finder = None
        for case in cases:
            result = saved.get((case.world_name, case.scene, case.obj.name))
            if result is None:
                from assistant.app import Finder

                finder = finder or Finder()
                result = finder.search(case.obj.name, case.world, case.scene)
            searches.append((case.world, result))
    first = None
    all_ms = []
    per_run_medians = []
    for rep in range(args.repeats):
        times = []
        for i, case in enumerate(cases):
            listener = case.world.start if args.style == "dynamic" else None
            t = time.perf_counter()
            if args.search == "sensed":
                world, result = searches[i]
                describer.describe_search(result, world.floorplan, listener_pose=listener, style=args.style)
            else:
                describer.describe(case.sighting, case.environment, case.world.floorplan,
                                   listener_pose=listener, style=args.style)
            ms = (time.perf_counter() - t) * 1000
            if first is None:
                first = ms
            times.append(ms)
        per_run_medians.append(statistics.median(times))
        all_ms.extend(times)
    print(f"generation model load (cache): {load_s * 1000:.0f} ms")
    print(f"first description (cold imports): {first:.1f} ms")
    if searches:
        found = [r for _, r in searches if r.found]
        print(f"search ({len(searches)} cases, sensed): found {len(found)}/{len(searches)}; time to the "
              f"sighting median {statistics.median(r.found_at_wall_s for r in found):.1f} s computer time; "
              f"whole search median {statistics.median(r.wall_seconds for _, r in searches):.1f} s computer, "
              f"{statistics.median(r.sim_seconds for _, r in searches):.0f} s robot time, "
              f"{statistics.median(r.path_m for _, r in searches):.1f} m driven")
    print(f"{args.style} composition after the object is found ({args.search} environment), "
          f"{len(cases)} descriptions x {args.repeats} runs:")
    print(f"  {_summary(all_ms)} (per-run medians {', '.join(f'{m:.1f}' for m in per_run_medians)}); "
          "target <= 100 ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

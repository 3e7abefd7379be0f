"""Median time of one move-to inference (dissertation 5.5.4) and of training all models.

    .venv/bin/python benchmarks/bench_policy.py [--repeats 5]

Each inference is the full coarse-to-fine search of one RDT from one start pose in the training
home's modified scene (the WSF builder, the free-space map and the search; the free-space map
is built once per layout and shared, as the evaluation does).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()

    import numpy as np

    from assistant.policy.demonstration import environment_from_world
    from assistant.policy.freespace import FreeSpace
    from assistant.policy.library import PolicyLibrary
    from assistant.policy.rdt import TABLE_RDTS
    from assistant.policy.teacher import sample_start
    from assistant.world import load_world

    with tempfile.TemporaryDirectory() as cache:
        import os

        os.environ["ASSISTANT_CACHE"] = cache
        t0 = time.perf_counter()
        library = PolicyLibrary(use_cache=False)
        library.models
        train_s = time.perf_counter() - t0
    env = environment_from_world(load_world("training-home"), "modified")
    t0 = time.perf_counter()
    free = FreeSpace(env)
    free_s = time.perf_counter() - t0
    per_rdt = {}
    evaluated = {}
    for rdt in TABLE_RDTS:
        rng = np.random.default_rng(3)
        start, goal = sample_start(rdt, env, free, rng)
        model = library.model(rdt).model
        times, cpu = [], []
        for _ in range(args.repeats):
            w, c = time.perf_counter(), time.process_time()
            result = model.infer_move_to(env, start, goal.reference_id, goal.target_id, free=free)
            times.append(time.perf_counter() - w)
            cpu.append(time.process_time() - c)
        per_rdt[rdt] = (statistics.median(times), statistics.median(cpu))
        evaluated[rdt] = len(result.scores)
    print(f"training all {len(library.rdts())} models from {sum(m.n_demonstrations_ for m in library.models.values())} "
          f"demonstrations: {train_s:.2f} s (one run)")
    print(f"free-space map of the layout: {free_s * 1000:.0f} ms (once per layout)")
    print(f"{'RDT':20s} {'median wall s':>13s} {'median CPU s':>12s} {'candidates':>10s}")
    for rdt, (w, c) in per_rdt.items():
        print(f"{rdt:20s} {w:13.3f} {c:12.3f} {evaluated[rdt]:10d}")
    walls = [w for w, _ in per_rdt.values()]
    cpus = [c for _, c in per_rdt.values()]
    print(f"median over the 13 RDTs of the per-RDT medians ({args.repeats} runs each): "
          f"{statistics.median(walls):.3f} s wall, {statistics.median(cpus):.3f} s CPU; "
          f"slowest RDT {max(walls):.3f} s wall")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

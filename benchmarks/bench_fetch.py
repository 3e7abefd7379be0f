"""Wall-clock time of one fetch in the simulator, from text to final pose.

Runs a fixed set of dev-set commands (one per home) with sensed and with oracle perception,
``--repeats`` times each, after one warm-up fetch that loads the parser, the policy models and
the furniture detector (a one-time cost per session, reported separately). Prints the median
wall-clock seconds per fetch and the simulated seconds.

    .venv/bin/python benchmarks/bench_fetch.py [--repeats 3] [--perception sensed|oracle|both]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

COMMANDS = (
    ("Please go into the living room, the glasses case is on the table in front of the couch.",
     "apartment", "original", "glasses case"),
    ("Go into the office, the mug is on the table in front of the couch.", "hk-studio", "modified", "mug"),
    ("Go into the bedroom, the statue is on the table to the right of the bed.",
     "one-bedroom-house", "original", "statue"),
    ("Go into the office and turn left, the monitor is on the desk with the chair.",
     "two-bedrooms-house", "modified", "monitor"),
)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--perception", choices=("sensed", "oracle", "both"), default="both")
    args = parser.parse_args()
    from assistant.app import Fetcher

    fetcher = Fetcher()
    t0 = time.perf_counter()
    warm = fetcher.fetch(*COMMANDS[0][:3], "sensed", object_name=COMMANDS[0][3])
    print(f"warm-up (loads parser, policy models, detector): {time.perf_counter() - t0:.1f} s "
          f"(that fetch: {warm.data['wall_seconds']:.1f} s)")
    modes = ("sensed", "oracle") if args.perception == "both" else (args.perception,)
    for mode in modes:
        walls, sims, ok = [], [], 0
        for _ in range(args.repeats):
            for text, world, scene, obj in COMMANDS:
                data = fetcher.fetch(text, world, scene, mode, object_name=obj).data
                walls.append(data["wall_seconds"])
                sims.append(data["sim_seconds"])
                ok += bool(data["success"])
        print(f"{mode:>6}: median wall {statistics.median(walls):.2f} s per fetch "
              f"(min {min(walls):.2f}, max {max(walls):.2f}; {len(walls)} fetches, {ok} successes); "
              f"median simulated {statistics.median(sims):.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Recording and replay speed: writing a depth frame to MCAP, reading one back, and a whole sample.

* write: one 640×480 simulated depth frame (with its pose, odometry and a command) added to a
  session file, including the 16-bit conversion, the CDR serialisation, zstd and the flush;
* replay: the frames of ``sample_scans/apartment_fetch.mcap`` read through a ``ReplayRobot``
  (decoding every frame to metres), as fast as asked;
* bytes per frame of that file.

Medians over ``--repeats`` runs.

    .venv/bin/python benchmarks/bench_replay.py [--repeats 5]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SAMPLE = ROOT / "sample_scans" / "apartment_fetch.mcap"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    from assistant.robot import Odometry
    from assistant.robot.recording import SessionWriter
    from assistant.robot.replay import ReplayRobot
    from assistant.sim import SimRobot

    with SimRobot("apartment", seed=0) as sim:
        frame = sim.depth_frame()
    writes = []
    with tempfile.TemporaryDirectory() as folder:
        with SessionWriter(Path(folder) / "bench.mcap") as writer:
            for i in range(args.repeats * 10):
                t0 = time.perf_counter()
                writer.write_frame(frame.to_millimetres(), frame.intrinsics, frame.mount, frame.robot_pose, i * 0.1)
                writer.write_odometry(Odometry(frame.robot_pose, 0.0, 0.0, i * 0.1))
                writer.write_command(0.0, 0.0, i * 0.1)
                writes.append(time.perf_counter() - t0)
    print(f"write one frame + odometry + command: median {1e3 * statistics.median(writes):.1f} ms")
    if not SAMPLE.exists():
        print(f"{SAMPLE} missing: run tools/make_sample_scans.py for the replay figures")
        return 0
    runs = []
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        with ReplayRobot(SAMPLE) as robot:
            count = sum(1 for _ in robot.frames())
        runs.append(time.perf_counter() - t0)
    median = statistics.median(runs)
    print(f"replay {SAMPLE.name}: {count} frames in median {median:.2f} s ({count / median:.0f} frames/s), "
          f"{SAMPLE.stat().st_size / count / 1e3:.0f} kB per frame on disk")
    return 0


if __name__ == "__main__":
    sys.exit(main())

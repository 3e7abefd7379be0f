"""Record the first training set of demonstrations (``corpus/demonstrations/``).

For each RDT of dissertation Table 5-1 the scripted teacher (``assistant.policy.teacher``)
picks a start pose at random (fixed seed), chooses the reference, the target and the goal
pose by its written rules, plans a way there on the floor plan (``assistant.executor``'s
planner) and drives the simulated robot along it with key presses
(``assistant.policy.keyboard``), as the dissertation's teacher drove the Stage robot. The
environment model stored with each demonstration is the world's ground-truth layout (oracle
perception).

    .venv/bin/python tools/record_demonstrations.py                 # 12 per RDT, training-home
    .venv/bin/python tools/record_demonstrations.py --per-rdt 6 --rdt couch-front-table
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from assistant.executor import build_occupancy, plan_path  # noqa: E402
from assistant.policy.demonstration import environment_from_world  # noqa: E402
from assistant.policy.freespace import FreeSpace  # noqa: E402
from assistant.policy.keyboard import KeyboardSession, drive_by_keys  # noqa: E402
from assistant.policy.rdt import TABLE_RDTS  # noqa: E402
from assistant.policy.teacher import sample_start  # noqa: E402
from assistant.sim import SimRobot  # noqa: E402
from assistant.world import furniture_entities, load_world, world_grid  # noqa: E402


def record(rdt: str, world, scene: str, index: int, count: int, seed: int, env, free, occupancy):
    rng = np.random.default_rng([seed, TABLE_RDTS.index(rdt) if rdt in TABLE_RDTS else 99, index])
    # the teacher spreads the start headings over the circle (demo i of n: 360°·i/n, ± half a
    # sector), so what depends only on where the robot started varies across demonstrations
    sector = 2 * math.pi / count
    for attempt in range(20):
        heading = -math.pi + sector * (index + rng.random())
        start, goal = sample_start(rdt, env, free, rng, instance=index, heading_rad=heading)
        try:
            path = plan_path(occupancy, start, (goal.goal.x, goal.goal.y), snap_goal=False)
        except Exception:
            continue
        robot = SimRobot(world, scene, start=start, seed=seed + index)
        robot.connect()
        session = KeyboardSession(robot)
        ok = drive_by_keys(session, path.waypoints[1:] if len(path.waypoints) > 1 else path.waypoints,
                           goal.goal.theta)
        robot.close()
        if ok:
            demo = session.demonstration(rdt, world.name, scene, env, goal.reference_id, goal.target_id,
                                         goal.goal, "scripted-keyboard")
            return demo, attempt
    raise RuntimeError(f"{rdt}: the teacher could not finish a demonstration in 20 tries")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--world", default="training-home")
    parser.add_argument("--scene", default="original")
    parser.add_argument("--per-rdt", type=int, default=12)
    parser.add_argument("--rdt", action="append", help="only these RDTs (repeatable)")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--out", default=str(ROOT / "corpus" / "demonstrations"))
    args = parser.parse_args(argv)
    world = load_world(args.world)
    env = environment_from_world(world, args.scene)
    free = FreeSpace(env)
    grid = world_grid(world, 0.05)
    occupancy = build_occupancy(world, furniture_entities(world, args.scene, grid), grid=grid)
    out = Path(args.out)
    for rdt in args.rdt or TABLE_RDTS:
        for i in range(args.per_rdt):
            t0 = time.perf_counter()
            demo, retries = record(rdt, world, args.scene, i, args.per_rdt, args.seed, env, free, occupancy)
            path = out / rdt / f"{args.world}-{args.scene}-{i + 1:02d}.json"
            demo.save(path)
            last, goal = demo.last_pose, demo.goal
            print(f"{path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}: "
                  f"{len(demo.frames)} frames, {demo.frames[-1].t:.1f} s, "
                  f"end {math.hypot(last.x - goal.x, last.y - goal.y):.2f} m from the goal, "
                  f"retries {retries}, {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Benchmark: path planning across a home, and following the path in simulated time.

    .venv/bin/python benchmarks/bench_planning.py [--world apartment] [--repeats 15] [--no-follow]

Prints medians (and min/max) over repeated runs of:
  * building the occupancy map from the floor plan plus perceived furniture (here the scene's
    furniture as entities on a 0.1 m grid, standing in for perception's output);
  * planning each of a few long routes across the home (scikit-image MCP + shortcuts);
  * following each route with the pure-pursuit controller on the simulator's SimRobot:
    the simulated seconds it takes, the wall-clock seconds that costs, and their ratio;
  * the same with P3-DX-like odometry noise, steering by odometry alone and with the
    FloorplanLocalizer (depth frames matched to the floor plan's walls): outcomes and how far
    from the goal the robot truly stops (the simulator's ground-truth pose, read here for
    evaluation only).
Timings are noisy on a shared 2-core machine; the medians are what to compare.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

# long routes: (name, start x, y, heading, goal x, y) per world
ROUTES = {
    "apartment": [
        ("start → living room far corner", None, (6.5, 7.0)),
        ("start → bedroom far corner", None, (-1.3, -7.2)),
        ("living room → bedroom", (5.5, 6.0, 0.0), (0.0, -6.8)),
    ],
    "training-home": [
        ("start → living room centre", None, (2.5, 2.5)),
        ("start → bedroom", None, (8.5, 1.5)),
        ("living room → bedroom", (1.0, 3.2, 0.0), (9.5, 1.2)),
    ],
}


def _stats(values: list[float]) -> str:
    return (f"median {statistics.median(values) * 1000:8.2f} ms   "
            f"min {min(values) * 1000:8.2f}   max {max(values) * 1000:8.2f}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--world", default="apartment", choices=sorted(ROUTES))
    parser.add_argument("--scene", default="original")
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--follow-repeats", type=int, default=3)
    parser.add_argument("--noise-seeds", type=int, default=5,
                        help="seeds of the odometry-noise runs per route")
    parser.add_argument("--no-follow", action="store_true", help="time planning only")
    args = parser.parse_args(argv)

    from assistant.executor import PathFollower, build_occupancy, plan_path
    from assistant.geometry import Pose2D
    from assistant.world import furniture_entities, load_world, world_grid

    world = load_world(args.world)
    entities = furniture_entities(world, args.scene, world_grid(world, 0.1))
    print(f"world {world.name} ({args.scene}), {len(entities)} perceived furniture entities, "
          f"{args.repeats} repeats")

    build_times = []
    for _ in range(args.repeats):
        t = time.perf_counter()
        occupancy = build_occupancy(world, entities)
        build_times.append(time.perf_counter() - t)
    print(f"occupancy map {occupancy.grid.shape[1]}x{occupancy.grid.shape[0]} cells at "
          f"{occupancy.grid.resolution_m} m: {_stats(build_times)}")

    plans = []
    all_plan_times = []
    for name, start, goal in ROUTES[args.world]:
        start_pose = world.start if start is None else Pose2D(*start)
        times = []
        for _ in range(args.repeats):
            t = time.perf_counter()
            path = plan_path(occupancy, start_pose, goal)
            times.append(time.perf_counter() - t)
        all_plan_times.extend(times)
        plans.append((name, start_pose, path))
        print(f"plan {name:<32} {path.length_m:5.2f} m, {len(path.waypoints):2d} waypoints, "
              f"clearance {path.min_clearance_m:.2f} m: {_stats(times)}")
    print(f"plan, all routes: {_stats(all_plan_times)}")

    if args.no_follow:
        return 0
    try:
        from assistant.sim import SimRobot
    except ImportError:
        print("follow: skipped (assistant.sim.SimRobot is not available)")
        return 0
    from assistant.sim.kinematics import OdometryNoise

    follower = PathFollower()
    ratios = []
    for name, start_pose, path in plans:
        walls, sims, errors, outcomes = [], [], [], set()
        for _ in range(args.follow_repeats):
            with SimRobot(world, scene=args.scene, start=start_pose) as robot:
                t = time.perf_counter()
                result = follower.follow(robot, path, occupancy=occupancy)
                walls.append(time.perf_counter() - t)
                errors.append(robot.ground_truth_pose.distance_to(Pose2D(*path.goal)))
            sims.append(result.sim_seconds)
            outcomes.add(result.status.value)
        wall, sim = statistics.median(walls), statistics.median(sims)
        ratios.append(sim / wall if wall > 0 else float("inf"))
        print(f"follow {name:<30} {sim:6.1f} s simulated in {wall:6.2f} s wall-clock "
              f"({sim / wall:5.1f}x real time), arrival error {statistics.median(errors):.3f} m, "
              f"outcome {'/'.join(sorted(outcomes))}")
    print(f"follow, median real-time factor over routes: {statistics.median(ratios):.1f}x")

    # the same routes with P3-DX-like odometry drift (the controller only sees odometry), with
    # and without matching walls to the floor plan: how far from the goal the robot truly stops
    from assistant.executor import FloorplanLocalizer

    for label, use_localizer in (("odometry only", False), ("with FloorplanLocalizer", True)):
        errors, outcomes, walls = [], [], []
        for name, start_pose, path in plans:
            for seed in range(args.noise_seeds):
                with SimRobot(world, scene=args.scene, start=start_pose, seed=seed,
                              odometry_noise=OdometryNoise()) as robot:
                    localizer = FloorplanLocalizer(world) if use_localizer else None
                    t = time.perf_counter()
                    result = follower.follow(robot, path, occupancy=occupancy, localizer=localizer)
                    walls.append(time.perf_counter() - t)
                    errors.append(robot.ground_truth_pose.distance_to(Pose2D(*path.goal)))
                    outcomes.append(result.status.value)
        ok = [e for e, o in zip(errors, outcomes) if o == "success"]
        counts = ", ".join(f"{o} {outcomes.count(o)}" for o in sorted(set(outcomes)))
        print(f"odometry noise, {label:<24} ({args.noise_seeds} seeds x {len(plans)} routes): {counts}; "
              f"true arrival error of the successes median "
              f"{statistics.median(ok) if ok else float('nan'):.3f} m, max {max(ok) if ok else float('nan'):.3f} m; "
              f"wall-clock per route median {statistics.median(walls):.2f} s")

    # furniture unknown to the planner (no perception): the floor plan alone, or the floor plan
    # plus obstacles seen in depth frames (DepthObstacles), with Navigator replanning
    from assistant.executor import DepthObstacles, Navigator, build_occupancy as _build

    plain = _build(world, [])
    for label, use_depth in (("floor plan only", False), ("floor plan + DepthObstacles", True)):
        outcomes, errors, walls, attempts = [], [], [], []
        for name, start_pose, path in plans:
            with SimRobot(world, scene=args.scene, start=start_pose) as robot:
                obstacles = DepthObstacles(world)
                localizer = FloorplanLocalizer(world, listeners=[obstacles.add_frame])
                source = obstacles.occupancy if use_depth else (lambda: plain)
                navigator = Navigator(world, source, localizer=localizer, max_replans=10)
                t = time.perf_counter()
                result = navigator.go_to(robot, path.goal)
                walls.append(time.perf_counter() - t)
                outcomes.append(result.status.value)
                errors.append(robot.ground_truth_pose.distance_to(Pose2D(*path.goal)))
                attempts.append(result.details.get("attempts", 0))
        counts = ", ".join(f"{o} {outcomes.count(o)}" for o in sorted(set(outcomes)))
        print(f"furniture unknown, {label:<28} ({len(plans)} routes): {counts}; plans per route "
              f"{'/'.join(map(str, attempts))}; wall-clock per route median {statistics.median(walls):.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())

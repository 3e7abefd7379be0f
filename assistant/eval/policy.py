"""``assistant eval policy``: dissertation Table 5-1 on layouts changed from training.

For every RDT of Table 5-1 and every test layout where the RDT has an instance — the
training home's ``modified`` scene (the layout "changed from training", as Figure 5.14(b)) and
the four study homes (``original`` scenes, never seen in training) — the evaluation draws
``--trials`` random start poses (fixed seed; the same start rules as the teacher's), lets the
trained policy model infer the move-to pose (5.5.4) from the ground-truth environment model,
and compares it with the *expected pose*: the teacher's rule applied to the test layout
(``assistant.policy.teacher``). Per RDT it reports:

* ``d`` (m): distance from the robot's final position to the expected position;
* ``θ`` (rad): with a target, the angle between the robot's heading and the direction from the
  robot to the target's centre (the dissertation's definition); without one, the difference
  between the robot's heading and the expected heading;
* ``T``: how often the target furniture is in the final depth frame — the simulator's renderer
  is cast from the final pose and T counts a success when any pixel's hit id is the target
  (``DepthRenderer(...).render(pose).hit_ids``); "-" for RDTs without a target.

The final pose is the inferred pose, or with ``--drive`` the pose where the simulated robot
stops after the executor (``assistant.executor.Navigator``) drives it there.
"""

from __future__ import annotations

import argparse

STUDY_HOMES = ("apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house")
TRAINING_LAYOUT = ("training-home", "modified")
TARGET_MEAN_D_M = 0.3
DISSERTATION_MEAN_D_M = 0.47


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--demonstrations", metavar="DIR",
                        help="demonstration directory to train from (default: corpus/demonstrations)")
    parser.add_argument("--layout", action="append", metavar="WORLD[:SCENE]",
                        help="test layouts (repeatable; default: training-home:modified and the "
                             "four study homes' original scenes)")
    parser.add_argument("--rdt", action="append", help="only these RDTs (repeatable)")
    parser.add_argument("--trials", type=int, default=3, help="start poses per RDT and layout (3)")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--stop-rule", choices=("min-step", "score-falls"), default=None,
                        help="how the coarse-to-fine search ends (default: the model's, min-step)")
    parser.add_argument("--unrelated-over", choices=("all", "support"), default=None,
                        help="u of equation 5-16 over all values (default) or those seen in training")
    parser.add_argument("--search-starts", type=int, default=None,
                        help="refine from this many of the best coarse poses (default 5)")
    parser.add_argument("--reachable-only", action="store_true", default=None,
                        help="search only floor connected to the robot (0.25 m clearance)")
    parser.add_argument("--drive", action="store_true",
                        help="drive the simulated robot there with the executor and measure where it stops")
    parser.add_argument("--no-cache", action="store_true", help="retrain the models, do not use the cache")


def _layouts(args) -> list[tuple[str, str]]:
    if not args.layout:
        return [TRAINING_LAYOUT] + [(name, "original") for name in STUDY_HOMES]
    out = []
    for text in args.layout:
        world, _, scene = text.partition(":")
        out.append((world, scene or "original"))
    return out


def evaluate_layout(library, world_name: str, scene: str, rdts, trials: int, seed: int,
                    drive: bool = False) -> list[dict]:
    """Rows of Table 5-1 for one layout (RDTs without an instance there are left out)."""
    import math

    import numpy as np

    from assistant.geometry import Pose2D, angle_difference
    from assistant.policy.demonstration import environment_from_world
    from assistant.policy.freespace import FreeSpace
    from assistant.policy.rdt import TABLE_5_1, TABLE_RDTS, RDT
    from assistant.policy.teacher import NoInstanceError, sample_start
    from assistant.sim import DepthRenderer
    from assistant.world import load_world

    world = load_world(world_name)
    env = environment_from_world(world, scene)
    free = FreeSpace(env)
    renderer = None
    numbers = {name: (n, text) for n, text, name in TABLE_5_1}
    rows = []
    for rdt in rdts:
        parsed = RDT.parse(rdt)
        choice = library.model(rdt)
        rng = np.random.default_rng([seed, TABLE_RDTS.index(rdt) if rdt in TABLE_RDTS else 99,
                                     sum(map(ord, world_name + scene))])
        results = []
        for trial in range(trials):
            try:
                start, goal = sample_start(parsed, env, free, rng, instance=trial)
            except NoInstanceError:
                break
            inferred = choice.model.infer_move_to(env, start, goal.reference_id, goal.target_id, free=free)
            final = inferred.pose
            drive_status = None
            if drive:
                final, drive_status = _drive(world, scene, start, inferred.pose)
            d = math.hypot(final.x - goal.goal.x, final.y - goal.goal.y)
            seen = None
            if goal.target_id is not None:
                tar = next(e for e in env if e.id == goal.target_id)
                c = tar.polygon_array().mean(axis=0)
                theta = abs(angle_difference(math.atan2(c[1] - final.y, c[0] - final.x), final.theta))
                if renderer is None:
                    renderer = DepthRenderer(world, scene)
                frame = renderer.render(final)
                names = np.asarray(frame.hit_names, dtype=object)
                ids = frame.hit_ids[frame.hit_ids >= 0]
                seen = bool(goal.target_id in set(names[np.unique(ids)]))
            else:
                theta = abs(angle_difference(goal.goal.theta, final.theta))
            results.append({"start": _pose(start), "expected": _pose(goal.goal), "inferred": _pose(inferred.pose),
                            "final": _pose(final), "reference": goal.reference_id, "target": goal.target_id,
                            "d": round(d, 4), "theta": round(theta, 4), "target_in_view": seen,
                            "score": inferred.score, "evaluated": int(len(inferred.scores)),
                            **({"drive": drive_status} if drive else {})})
        if not results:
            continue
        ds = np.array([r["d"] for r in results])
        ths = np.array([r["theta"] for r in results])
        seen = [r["target_in_view"] for r in results if r["target_in_view"] is not None]
        number, text = numbers.get(rdt, (None, ""))
        rows.append({"world": world_name, "scene": scene, "number": number, "nsld": text, "rdt": rdt,
                     "model": choice.used, "d_mean": float(ds.mean()), "d_std": float(ds.std()),
                     "theta_mean": float(ths.mean()), "theta_std": float(ths.std()),
                     "T_success": sum(seen) if parsed.has_target else None,
                     "T_total": len(seen) if parsed.has_target else None, "trials": results})
    return rows


def _pose(p) -> list[float]:
    return [round(float(p.x), 3), round(float(p.y), 3), round(float(p.theta), 4)]


def _drive(world, scene, start, goal):
    from assistant.executor import Navigator, build_occupancy
    from assistant.sim import SimRobot
    from assistant.world import furniture_entities, world_grid

    grid = world_grid(world, 0.05)
    occupancy = build_occupancy(world, furniture_entities(world, scene, grid), grid=grid)
    robot = SimRobot(world, scene, start=start, seed=0)
    robot.connect()
    try:
        result = Navigator(world, lambda: occupancy).go_to(robot, (goal.x, goal.y), goal.theta)
        return robot.ground_truth_pose, getattr(result.status, "value", str(result.status))
    finally:
        robot.close()


def run(args: argparse.Namespace) -> int:
    import time

    import numpy as np

    from assistant.cli.common import emit_json, print_table
    from assistant.policy.library import PolicyLibrary
    from assistant.policy.rdt import TABLE_RDTS, parse_rdt

    params = {k: v for k, v in (("stop_rule", args.stop_rule), ("unrelated_over", args.unrelated_over),
                                ("search_starts", args.search_starts),
                                ("reachable_only", args.reachable_only)) if v is not None}
    t0 = time.perf_counter()
    library = PolicyLibrary(args.demonstrations, use_cache=not args.no_cache, **params)
    library.models
    train_s = time.perf_counter() - t0
    rdts = [parse_rdt(r).name for r in args.rdt] if args.rdt else list(TABLE_RDTS)
    layouts = _layouts(args)
    all_rows = []
    for world, scene in layouts:
        all_rows.extend(evaluate_layout(library, world, scene, rdts, args.trials, args.seed, args.drive))
    elapsed = time.perf_counter() - t0

    def mean_d(rows):
        return float(np.mean([r["d_mean"] for r in rows])) if rows else None

    primary = [r for r in all_rows if (r["world"], r["scene"]) == layouts[0]]
    others = [r for r in all_rows if (r["world"], r["scene"]) != layouts[0]]
    summary = {"layouts": [f"{w}:{s}" for w, s in layouts], "trials": args.trials, "seed": args.seed,
               "drive": bool(args.drive), "model_params": params,
               "demonstrations": str(library.directory), "trained_from_cache": library.loaded_from_cache,
               "train_seconds": round(train_s, 2), "seconds": round(elapsed, 1),
               "mean_d": mean_d(primary), "mean_d_layout": f"{layouts[0][0]}:{layouts[0][1]}",
               "mean_d_other_layouts": mean_d(others), "target_mean_d": TARGET_MEAN_D_M,
               "dissertation_mean_d": DISSERTATION_MEAN_D_M, "rows": all_rows}
    if args.json:
        emit_json(summary)
        return 0
    for world, scene in layouts:
        rows = [r for r in all_rows if (r["world"], r["scene"]) == (world, scene)]
        print(f"\n{world} ({scene} scene): {len(rows)} RDTs with an instance, {args.trials} trials each")
        if not rows:
            continue
        table = []
        for r in rows:
            t = "-" if r["T_total"] is None else f"{r['T_success']}/{r['T_total']}"
            model = r["rdt"] if r["model"] == r["rdt"] else f"{r['rdt']} (model {r['model']})"
            table.append([r["number"] or "", r["nsld"], model, f"{r['d_mean']:.2f}/{r['d_std']:.2f}",
                          f"{r['theta_mean']:.2f}/{r['theta_std']:.2f}", t])
        print_table(table, ["#", "NSLD", "RDT", "d (m) mean/std", "θ (rad) mean/std", "T"])
        print(f"mean d over {len(rows)} RDTs: {mean_d(rows):.3f} m")
    print(f"\nmean d on {summary['mean_d_layout']}: {summary['mean_d']:.3f} m "
          f"(target ≤ {TARGET_MEAN_D_M} m; dissertation about {DISSERTATION_MEAN_D_M} m)")
    if others:
        print(f"mean d on the other layouts: {summary['mean_d_other_layouts']:.3f} m")
    print(f"trained in {train_s:.1f} s{' (cache)' if library.loaded_from_cache else ''}, total {elapsed:.0f} s")
    return 0

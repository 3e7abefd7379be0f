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

from assistant.eval.progress import Progress, no_progress

STUDY_HOMES = ("apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house")
TRAINING_LAYOUT = ("training-home", "modified")
TARGET_MEAN_D_M = 0.3
DISSERTATION_MEAN_D_M = 0.47
#: the dissertation's Table 5-1: mean distance d (m) from the final to the expected position, per RDT
DISSERTATION_D_M = {
    "move-front-non": 0.55, "move-left-non": 0.03, "move-right-non": 0.03, "robot-left-table": 0.36,
    "robot-right-table": 0.66, "bed-left-table": 0.20, "bed-right-table": 1.01, "couch-front-table": 0.35,
    "couch-left-table": 0.08, "couch-right-table": 0.73, "chair-beside-table": 0.53,
    "room-center-non": 0.91, "wall-front-non": 0.67,
}


def default_layouts() -> list[tuple[str, str]]:
    """The training home's modified scene, then the four study homes' original scenes."""
    return [TRAINING_LAYOUT] + [(name, "original") for name in STUDY_HOMES]


def evaluate_layout(library, world_name: str, scene: str, rdts, trials: int, seed: int,
                    drive: bool = False) -> list[dict]:
    """Rows of Table 5-1 for one layout (RDTs without an instance there are left out)."""
    import math

    import numpy as np

    from assistant.geometry import angle_difference
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


def mean_d(rows) -> float | None:
    """Mean over ``rows`` (Table 5-1 rows) of their mean distance ``d`` (m); ``None`` for none."""
    import numpy as np

    return float(np.mean([r["d_mean"] for r in rows])) if rows else None


def _pose(p) -> list[float]:
    return [round(float(p.x), 3), round(float(p.y), 3), round(float(p.theta), 4)]


def _drive(world, scene, start, goal):
    from assistant.executor import Navigator, build_occupancy
    from assistant.robot import make_robot
    from assistant.world import furniture_entities, world_grid

    grid = world_grid(world, 0.05)
    occupancy = build_occupancy(world, furniture_entities(world, scene, grid), grid=grid)
    robot = make_robot("sim", world=world, scene=scene, start=start, seed=0)
    robot.connect()
    try:
        result = Navigator(world, lambda: occupancy).go_to(robot, (goal.x, goal.y), goal.theta)
        return robot.ground_truth_pose, getattr(result.status, "value", str(result.status))
    finally:
        robot.close()


def evaluate_policy(demonstrations=None, *, layouts=None, rdts=None, trials: int = 3, seed: int = 7,
                    drive: bool = False, use_cache: bool = True, model_params: dict | None = None,
                    progress: Progress = no_progress) -> dict:
    """Table 5-1 on each of ``layouts`` ((world, scene) pairs; default
    :func:`default_layouts`) for ``rdts`` (default every RDT of the table), with the policy models
    trained from ``demonstrations`` (default: the corpus's). ``model_params``: the model's search
    settings (``stop_rule``, ``unrelated_over``, ``search_starts``, ``reachable_only``).
    Returns the JSON report: the rows and the mean ``d`` of the first layout and of the others."""
    import time

    from assistant.policy.library import PolicyLibrary
    from assistant.policy.rdt import TABLE_RDTS, parse_rdt

    params = dict(model_params or {})
    t0 = time.perf_counter()
    progress("training (or loading) the policy models")
    library = PolicyLibrary(demonstrations, use_cache=use_cache, **params)
    library.models
    train_s = time.perf_counter() - t0
    rdts = [parse_rdt(r).name for r in rdts] if rdts else list(TABLE_RDTS)
    layouts = list(layouts) if layouts else default_layouts()
    all_rows = []
    for number, (world, scene) in enumerate(layouts):
        progress(f"layout {world}:{scene}", number, len(layouts))
        all_rows.extend(evaluate_layout(library, world, scene, rdts, trials, seed, drive))
    elapsed = time.perf_counter() - t0
    primary = [r for r in all_rows if (r["world"], r["scene"]) == layouts[0]]
    others = [r for r in all_rows if (r["world"], r["scene"]) != layouts[0]]
    return {"layouts": [f"{w}:{s}" for w, s in layouts], "trials": trials, "seed": seed,
            "drive": bool(drive), "model_params": params,
            "demonstrations": str(library.directory), "trained_from_cache": library.loaded_from_cache,
            "train_seconds": round(train_s, 2), "seconds": round(elapsed, 1),
            "mean_d": mean_d(primary), "mean_d_layout": f"{layouts[0][0]}:{layouts[0][1]}",
            "mean_d_other_layouts": mean_d(others), "target_mean_d": TARGET_MEAN_D_M,
            "dissertation_mean_d": DISSERTATION_MEAN_D_M, "rows": all_rows}

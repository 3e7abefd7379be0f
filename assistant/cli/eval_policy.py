"""``assistant eval policy``: options and printed tables of :mod:`assistant.eval.policy`."""

from __future__ import annotations

import argparse

from assistant.cli.common import print_table, progress_for, seed_int, show_report, whole_number

#: what ``--quick`` stands for (see assistant.cli.eval): one RDT, one layout, one start pose
QUICK = ("--rdt", "couch-front-table", "--layout", "apartment", "--trials", "1")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--demonstrations", metavar="DIR",
                        help="demonstration directory to train from (default: corpus/demonstrations)")
    parser.add_argument("--layout", action="append", metavar="WORLD[:SCENE]",
                        help="test layouts (repeatable; default: training-home:modified and the "
                             "four study homes' original scenes)")
    parser.add_argument("--rdt", action="append", help="only these RDTs (repeatable)")
    parser.add_argument("--trials", type=whole_number(1, 1000), default=3, help="start poses per RDT and layout (3)")
    parser.add_argument("--seed", type=seed_int, default=7)
    parser.add_argument("--stop-rule", choices=("min-step", "score-falls"), default=None,
                        help="how the coarse-to-fine search ends (default: the model's, min-step)")
    parser.add_argument("--unrelated-over", choices=("all", "support"), default=None,
                        help="u of equation 5-16 over all values (default) or those seen in training")
    parser.add_argument("--search-starts", type=whole_number(1, 1000), default=None,
                        help="refine from this many of the best coarse poses (default 5)")
    parser.add_argument("--reachable-only", action="store_true", default=None,
                        help="search only floor connected to the robot (0.25 m clearance)")
    parser.add_argument("--drive", action="store_true",
                        help="drive the simulated robot there with the executor and measure where it stops")
    parser.add_argument("--no-cache", action="store_true", help="retrain the models, do not use the cache")


def parse_layouts(texts) -> list[tuple[str, str]] | None:
    """``WORLD[:SCENE]`` texts → (world, scene) pairs (scene default ``original``); ``None``
    for none given (the evaluation's default layouts)."""
    if not texts:
        return None
    out = []
    for text in texts:
        world, _, scene = text.partition(":")
        out.append((world, scene or "original"))
    return out


def run(args: argparse.Namespace) -> int:
    from assistant.eval.policy import evaluate_policy

    params = {k: v for k, v in (("stop_rule", args.stop_rule), ("unrelated_over", args.unrelated_over),
                                ("search_starts", args.search_starts),
                                ("reachable_only", args.reachable_only)) if v is not None}
    summary = evaluate_policy(args.demonstrations, layouts=parse_layouts(args.layout), rdts=args.rdt,
                              trials=args.trials, seed=args.seed, drive=args.drive,
                              use_cache=not args.no_cache, model_params=params,
                              progress=progress_for(args))
    return show_report(args, summary, print_report)


def print_report(summary: dict) -> None:
    """One Table 5-1 per layout, then the mean distances against the target."""
    from assistant.eval.policy import DISSERTATION_MEAN_D_M, TARGET_MEAN_D_M, mean_d

    for layout in summary["layouts"]:
        world, _, scene = layout.partition(":")
        rows = [r for r in summary["rows"] if (r["world"], r["scene"]) == (world, scene)]
        print(f"\n{world} ({scene} scene): {len(rows)} RDTs with an instance, {summary['trials']} trials each")
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
    if summary["mean_d_other_layouts"] is not None:
        print(f"mean d on the other layouts: {summary['mean_d_other_layouts']:.3f} m")
    cache = " (cache)" if summary["trained_from_cache"] else ""
    print(f"trained in {summary['train_seconds']:.1f} s{cache}, total {summary['seconds']:.0f} s")

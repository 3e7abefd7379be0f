"""``assistant eval fetch``: options and printed table of :mod:`assistant.eval.fetch`."""

from __future__ import annotations

import argparse
import json

from assistant.cli.common import print_table, progress_for, seed_int, show_report, whole_number
from assistant.errors import AssistantError
from assistant.eval.fetch import DEFAULT_DEV_SET, OUTCOMES, REQUIRED

#: what ``--quick`` stands for (see assistant.cli.eval): the first two commands, oracle perception
QUICK = ("--limit", "2", "--perception", "oracle")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--perception", choices=("sensed", "oracle", "both"), default="both",
                        help="perception mode(s) to run (default: both)")
    parser.add_argument("--limit", type=whole_number(1, 10**6), default=None, metavar="N",
                        help="only the first N commands")
    parser.add_argument("--world", metavar="NAME", help="only the commands of this home")
    parser.add_argument("--scene", help="only this scene (original, modified, lived-in)")
    parser.add_argument("--dev-set", metavar="FILE", default=None,
                        help=f"JSON lines {{{', '.join(REQUIRED)}}} (default: {DEFAULT_DEV_SET.name} in corpus/)")
    parser.add_argument("--grounder", choices=("scored", "learned"), default=None)
    parser.add_argument("--seed", type=seed_int, default=0)
    parser.add_argument("--trials", metavar="FILE", help="also write every trial's JSON line to FILE")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.fetch import evaluate_fetch

    try:
        sink = open(args.trials, "w", encoding="utf-8") if args.trials else None
    except OSError as error:
        raise AssistantError(f"cannot write the trials file {args.trials}: {error.strerror}; "
                             "give a path in a folder you can write") from None

    def write_trial(data: dict) -> None:  # as each trial ends, so a long run can be watched
        sink.write(json.dumps(data) + "\n")
        sink.flush()

    try:
        summary = evaluate_fetch(args.dev_set, perception=args.perception, world=args.world,
                                 scene=args.scene, limit=args.limit, grounder=args.grounder,
                                 seed=args.seed, on_trial=write_trial if sink else None,
                                 progress=progress_for(args))
    finally:
        if sink is not None:
            sink.close()
    return show_report(args, summary, print_report)


def print_report(summary: dict) -> None:
    """Table 5-4: outcome counts per home and scene, then the totals per perception mode."""
    header = ["perception", "world", "scene", *OUTCOMES, "all", "rate"]
    rows = [[g["perception"], g["world"], g["scene"], *(g[o] for o in OUTCOMES), g["all"],
             f"{100 * g['success_rate']:.1f}%"] for g in summary["groups"]]
    for mode, row in summary["totals"].items():
        rows.append([mode, "ALL", "all", *(row[o] for o in OUTCOMES), row["all"], f"{100 * row['success_rate']:.1f}%"])
    print_table(rows, header)
    threshold = summary["threshold"]
    print(f"success: target object ≥ {threshold['min_pixels']} pixels of the final depth frame within "
          f"{threshold['max_distance_m']} m; median wall-clock per fetch {summary['median_wall_seconds']} s")

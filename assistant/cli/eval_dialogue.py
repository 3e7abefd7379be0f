"""``assistant eval dialogue``: options and printed summary of :mod:`assistant.eval.dialogue`."""

from __future__ import annotations

import argparse

from assistant.cli.common import finite_float, print_table, progress_for, show_report

#: what ``--quick`` stands for (see assistant.cli.eval): the conversations named nonsense-…
QUICK = ("--only", "nonsense")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from assistant.generation.types import SEARCH_MODES

    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="conversation files or folders (default: the repository's corpus/dialogues)")
    parser.add_argument("--perception", choices=("oracle", "sensed"), default="oracle",
                        help="furniture perception for fetches (default: oracle)")
    parser.add_argument("--search", choices=SEARCH_MODES, default="sensed",
                        help="'where is my X' for an object not in memory: the robot searches (sensed, "
                             "default) or the world file answers (oracle); a conversation's own "
                             "'search:' key wins")
    parser.add_argument("--timeout", type=finite_float, default=180.0, help="seconds a fetch may take before it counts as a hang")
    parser.add_argument("--only", metavar="NAME", help="run only conversations whose name contains NAME")
    parser.add_argument("--verbose", action="store_true", help="print every turn")


def print_turn(name: str, said: str, turn) -> None:
    """``--verbose``: one line per turn (intent, action, outcome, reply)."""
    print(f"  [{name}] {said!r} -> "
          f"{None if turn is None else (turn.intent, turn.action, turn.outcome, turn.reply)}")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.dialogue import evaluate_dialogue

    report = evaluate_dialogue(args.corpus, perception=args.perception, search=args.search,
                               timeout=args.timeout, only=args.only,
                               on_turn=print_turn if args.verbose else None,
                               progress=progress_for(args))
    return show_report(args, report, print_report)


def print_report(summary: dict) -> None:
    """Conversations per topic, the share that ended as expected, and each failure's problems."""
    n, ok = summary["conversations"], summary["as_expected"]
    print_table([[k, v["conversations"], v["as_expected"]] for k, v in summary["by_topic"].items()],
                ["topic", "conversations", "as expected"])
    print(f"\n{ok}/{n} conversations ended as expected ({100 * ok / max(n, 1):.1f}%); "
          f"crashed {summary['crashed']}, hung {summary['hung']}; median reply {summary['median_reply_ms']} ms "
          f"(every 'say' turn, models loaded); {summary['wall_seconds']} s")
    for f in summary["failures"]:
        print(f"  FAILED {f['name']} ({f['file']}):")
        for p in f["problems"]:
            print(f"    {p}")

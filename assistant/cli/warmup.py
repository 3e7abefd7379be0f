"""``assistant warm-up``: train (or load) every model the chat uses, now, with progress.

``make run`` runs it during set-up, so the first reply of the chat does not wait for training:
on a fresh machine the models train here once (minutes, each step shown as it goes), and are
cached for every later command (``~/.cache/assistant``).
"""

from __future__ import annotations

import argparse
import time

from assistant.cli.common import add_json_flag, emit_json


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "warm-up", help="train (or load) every model the chat uses, now",
        description="Train, or load from the cache, the models the chat and the commands use: "
                    "language and grounding, the description model, the policy models (shipped "
                    "and taught demonstrations) and the furniture detector. Run once after "
                    "installing (make run does); later runs only load them.")
    parser.add_argument("--world", default="apartment", help="the home to prepare (default: apartment)")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.dialogue.services import Services
    from assistant.progress import working
    from assistant.world import load_world

    world = load_world(args.world)
    services = Services(perception="sensed")
    steps = (
        ("language and grounding models", lambda: services.parser(world)),
        ("description model", lambda: services.describer),
        ("policy models", lambda: services.fetcher().policies.models),
        ("furniture detector", lambda: services.fetcher().detector),
    )
    done = []
    started = time.monotonic()
    for number, (what, build) in enumerate(steps, start=1):
        t0 = time.monotonic()
        with working(f"warm-up {number}/{len(steps)}: {what}"):  # ticks on a terminal
            build()
        done.append({"what": what, "seconds": round(time.monotonic() - t0, 2)})
    total = round(time.monotonic() - started, 2)
    if args.json:
        emit_json({"world": world.name, "steps": done, "seconds": total})
    else:
        print(f"ready in {total:.1f} s: the models are cached for every command")
    return 0

"""``assistant teach RDT --world NAME``: drive the simulated robot by keys and record a
demonstration of an RDT node (dissertation 5.5.2)."""

from __future__ import annotations

import argparse
import sys

from assistant.cli.common import add_json_flag, emit_json, parse_pose


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "teach", help="drive the simulated robot by keys and record a demonstration of an RDT",
        description="Record a demonstration: in a terminal, drive with the arrow keys or w/a/s/d "
                    "(x or space stops), q finishes and saves, Esc aborts. With a pipe, give one key "
                    "per line (w, a, s, d, x, up, left, 'w 5' for five presses, q, esc); the end of "
                    "input saves like q.")
    parser.add_argument("rdt", help="the RDT node, e.g. couch-front-table, move-left-non")
    parser.add_argument("--world", required=True, help="world name or file (e.g. training-home)")
    parser.add_argument("--scene", default="original", help="scene: original or modified")
    parser.add_argument("--start", type=parse_pose, metavar="X,Y,HEADING",
                        help="start pose (metres, radians; default: the world's start)")
    parser.add_argument("--reference", metavar="ID", help="reference entity id (default: the teacher rule's pick)")
    parser.add_argument("--target", metavar="ID", help="target entity id (default: the teacher rule's pick)")
    parser.add_argument("--out", metavar="FILE",
                        help="demonstration file (default: corpus/demonstrations/RDT/WORLD-SCENE-keyboard-NN.json)")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.policy.teaching import run_teaching

    outcome = run_teaching(args.rdt, args.world, args.scene, args.start, args.reference, args.target,
                           args.out, echo=lambda text: print(text, file=sys.stderr))
    if args.json:
        emit_json(outcome.to_dict())
    elif outcome.saved is None:
        print(f"aborted after {outcome.presses} key presses; nothing saved")
    else:
        d = outcome.to_dict()
        print(f"saved {outcome.saved}: {d['frames']} frames, {outcome.presses} key presses, "
              f"final pose {d['final_pose']}")
    return 0 if outcome.saved is not None else 1

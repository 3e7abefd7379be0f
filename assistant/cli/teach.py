"""``assistant teach RDT --world NAME``: drive the robot (the simulator by default) by keys and
record a demonstration of an RDT node (dissertation 5.5.2); the application layer's
:func:`assistant.app.teach`."""

from __future__ import annotations

import argparse
import sys

from assistant.cli.common import add_json_flag, add_robot_option, emit_json, parse_pose


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
    add_robot_option(parser)
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.app import teach

    result = teach(args.rdt, args.world, args.scene, robot=args.robot, start=args.start, reference=args.reference,
                   target=args.target, out=args.out, echo=lambda text: print(text, file=sys.stderr))
    d = result.to_dict()
    if args.json:
        emit_json(d)
    elif not result.success:
        print(result.message)
    else:
        print(f"{result.message}: {d['frames']} frames, {d['presses']} key presses, final pose {d['final_pose']}")
    return 0 if result.success else 1

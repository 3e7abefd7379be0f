"""``assistant teach RDT --world NAME``: drive the robot (the simulator by default, ``--robot
SPEC``) by keys and record a demonstration of an RDT node (dissertation 5.5.2; the application
layer's :func:`assistant.app.teach`); ``--list``, ``--forget NAME`` and
``--accept NAME`` manage what the user taught (kept in the user's data folder, see
:mod:`assistant.policy.taught`)."""

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
                    "input saves like q. Demonstrations go to DATA/demonstrations (DATA is "
                    "$ASSISTANT_DATA or ~/.local/share/assistant); one that ends far from where the "
                    "others of its RDT end is held back until you --accept it.")
    parser.add_argument("rdt", nargs="?", help="the RDT node, e.g. couch-front-table, move-left-non")
    parser.add_argument("--world", help="world name or file (e.g. training-home)")
    parser.add_argument("--scene", default="original", help="scene: original or modified")
    parser.add_argument("--start", type=parse_pose, metavar="X,Y,HEADING",
                        help="start pose (metres, radians; default: the world's start)")
    parser.add_argument("--reference", metavar="ID", help="reference entity id (default: the teacher rule's pick)")
    parser.add_argument("--target", metavar="ID", help="target entity id (default: the teacher rule's pick)")
    parser.add_argument("--out", metavar="FILE.json",
                        help="demonstration file (default: DATA/demonstrations/RDT/WORLD-SCENE-keyboard-NN.json)")
    parser.add_argument("--accept-outlier", action="store_true",
                        help="use this demonstration even if it ends far from the others of its RDT")
    manage = parser.add_mutually_exclusive_group()
    manage.add_argument("--list", action="store_true", help="list the demonstrations you taught")
    manage.add_argument("--forget", metavar="NAME", help="delete a taught demonstration (RDT/NAME)")
    manage.add_argument("--accept", metavar="NAME", help="use a held-back demonstration (RDT/NAME)")
    add_robot_option(parser)
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.app import teach
    from assistant.errors import AssistantError

    if args.list or args.forget or args.accept:
        return _manage(args)
    if not args.rdt or not args.world:
        raise AssistantError("give the RDT and --world NAME (e.g. `assistant teach couch-front-table "
                             "--world training-home`), or --list / --forget NAME / --accept NAME")
    result = teach(args.rdt, args.world, args.scene, robot=args.robot, start=args.start, reference=args.reference,
                   target=args.target, out=args.out, echo=lambda text: print(text, file=sys.stderr),
                   accept_outlier=args.accept_outlier)
    outcome, d = result.task, result.to_dict()
    if args.json:
        emit_json(d)
    elif outcome.saved is None:
        print(f"aborted after {outcome.presses} key presses; nothing saved")
    elif outcome.held:
        print(f"held back {d['name']} ({outcome.saved}): {d['check']}. It is not used until you "
              f"confirm it: `assistant teach --accept {d['name']}` (or `--forget {d['name']}`)")
    else:
        print(f"saved {outcome.saved}: {d['frames']} frames, {outcome.presses} key presses, "
              f"final pose {d['final_pose']}")
    return 0 if outcome.saved is not None else 1


def _manage(args: argparse.Namespace) -> int:
    from assistant.policy import taught

    if args.list:
        items = taught.list_taught()
        rows = [{"name": t.name, "path": str(t.path), "held": t.held} for t in items]
        if args.json:
            emit_json({"directory": str(taught.taught_directory()), "demonstrations": rows})
        elif not rows:
            print(f"no taught demonstrations (they go to {taught.taught_directory()})")
        else:
            for row in rows:
                print(f"{row['name']}{'  (held back: --accept to use it)' if row['held'] else ''}")
        return 0
    if args.forget:
        item = taught.forget_taught(args.forget)
        result = {"forgot": item.name, "path": str(item.path)}
        message = f"forgot {item.name} ({item.path})"
    else:
        path = taught.accept_held(args.accept)
        result = {"accepted": args.accept, "path": str(path)}
        message = f"accepted {args.accept}: now used, saved as {path}"
    if args.json:
        emit_json(result)
    else:
        print(message)
    return 0

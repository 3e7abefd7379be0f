"""``assistant where OBJECT --world NAME``: search for an object, then say where it is.

By default (``--search sensed``) the simulated robot searches the home room by room from the
world's start pose with its own perception (furniture from depth, small objects from the
object detector) and the description is composed from the environment model it built
(``"search": "sensed"``, ``"environment": "perceived"``). ``--search oracle`` keeps the old
shortcut — the object's position and the furniture read from the world file — and is labelled
``"search": "oracle"``, ``"environment": "oracle"``. The description itself is composed by
content selection and surface realization learned from the corpus. Search, then describe, is
the application layer's :meth:`assistant.app.Finder.where_is`.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import (MAX_SEED, add_json_flag, add_robot_option, emit_json, miss_probability, parse_pose,
                                  request_int, run_batch, seed_int)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "where", help="say where an object is (\"the mug is on the table in front of the couch\")",
        description="Describe where an object is in a home, as a static description (where it is) "
                    "or a how-to-find one from the listener's pose (--style dynamic).",
    )
    parser.add_argument("object", nargs="?", help="object name, e.g. mug or 'glasses case'")
    parser.add_argument("--world", help="world name (apartment, hk-studio, …) or a world file path")
    parser.add_argument("--scene", default="original", help="scene: original, modified or lived-in")
    parser.add_argument("--listener", type=parse_pose, metavar="X,Y,HEADING",
                        help="where the person asking stands (metres, metres, radians; default: "
                             "the world's start pose, where the robot was asked); the room is not "
                             "said when they are in it, walls are named as they walk in")
    parser.add_argument("--style", choices=("static", "dynamic"), default=None,
                        help="static: where it is; dynamic: how to get there from --listener "
                             "(default: from --question, else static)")
    parser.add_argument("--question", help="the person's question; 'how do I get to my X' picks "
                                           "the dynamic style")
    parser.add_argument("--search", choices=("sensed", "oracle"), default="sensed",
                        help="sensed (default): the simulated robot searches with its own "
                             "perception; oracle: read the object and furniture from the world file")
    parser.add_argument("--miss-rate", type=miss_probability, default=0.0, metavar="P",
                        help="sensed search: probability that the object detector misses a visible "
                             "object in a frame (default 0)")
    parser.add_argument("--seed", type=seed_int, default=0, help="sensed search: simulator seed")
    add_robot_option(parser)
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="annotated corpus (XML + chunk-grounding CSV, files or folders) to "
                             "learn from instead of the repository's corpus/")
    parser.add_argument("--batch", metavar="FILE",
                        help="one JSON request per line: {object, world, scene, listener, style, "
                             "question, search, miss_rate, seed, robot}")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.app import Finder, spec_world
    from assistant.errors import AssistantError
    from assistant.generation import Describer, load_generation_model

    finder = Finder(Describer(load_generation_model(args.corpus)))

    def answer(name, world, scene="original", listener=None, style=None, question=None, search="sensed",
               miss_rate=0.0, seed=0, robot="sim"):
        if not name or not world:
            raise AssistantError("a request needs 'object' and 'world'")
        if not isinstance(name, str) or not isinstance(world, str):  # ["mug"] was searched for as "['mug']"
            raise AssistantError("'object' and 'world' are names, as text (\"mug\", \"apartment\")")
        return finder.where_is(name, world, scene, robot=robot, search=search, listener=listener,
                               style=style, question=question, miss_rate=miss_rate, seed=seed).description

    if args.batch:
        def handle(request: dict) -> dict:
            listener = request.get("listener")
            if isinstance(listener, str):
                listener = parse_pose(listener)
            return answer(request.get("object"), request.get("world"), request.get("scene", "original"),
                          listener, request.get("style"), request.get("question"),
                          search=request.get("search", args.search),
                          miss_rate=miss_probability(str(request.get("miss_rate", args.miss_rate))),
                          seed=request_int(request, "seed", args.seed, high=MAX_SEED),
                          robot=str(request.get("robot", args.robot))).to_dict()
        return run_batch(args.batch, handle, json_requests=True)
    args.world = args.world or spec_world(args.robot)
    if not args.object or not args.world:
        raise AssistantError("give an object and --world NAME (or --batch FILE)")
    if args.search == "sensed" and not args.json:
        import sys

        print(f"searching for the {args.object} …", file=sys.stderr, flush=True)
    result = answer(args.object, args.world, args.scene, args.listener, args.style, args.question,
                    search=args.search, miss_rate=args.miss_rate, seed=args.seed, robot=args.robot)
    if args.json:
        emit_json(result.to_dict())
        return 0
    print(result.description)
    report = result.search_report or {}
    if result.search == "sensed":
        print(f"  search: sensed — rooms searched: {', '.join(result.searched_rooms) or 'none'}; "
              f"{report.get('path_m', 0):.1f} m driven, {report.get('sim_seconds', 0):.0f} s robot time, "
              f"{result.search_seconds:.1f} s computer time to the sighting")
    else:
        print("  search: oracle (world file), environment: oracle (world file furniture)")
    if result.found and result.tree is not None:
        said_room = any(n.kind == "room" for n in result.selected)
        print(f"  nodes: {', '.join(result.nodes)}"
              + (f"; room: {result.to_dict()['room']}" if said_room else ""))
        print(f"  tree: {result.tree.bracketed()}")
        print(f"  composed in {result.composition_seconds * 1000:.1f} ms")
        if result.ambiguous:
            print("  note: no selection singles the furniture out; the description may be ambiguous")
    return 0

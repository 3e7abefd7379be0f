"""``assistant where OBJECT --world NAME``: search for an object, then say where it is.

By default (``--search sensed``) the simulated robot searches the home room by room from the
world's start pose with its own perception (furniture from depth, small objects from the
object detector) and the description is composed from the environment model it built
(``"search": "sensed"``, ``"environment": "perceived"``). ``--search oracle`` keeps the old
shortcut — the object's position and the furniture read from the world file — and is labelled
``"search": "oracle"``, ``"environment": "oracle"``. The description itself is composed by
content selection and surface realization learned from the corpus.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import (MAX_SEED, add_json_flag, emit_json, miss_probability, parse_pose, request_int,
                                  run_batch, seed_int)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "where", help="say where an object is (\"the mug is on the table in front of the couch\")",
        description="Describe where an object is in a home, as a static description (where it is) "
                    "or a how-to-find one from the listener's pose (--style dynamic).",
    )
    parser.add_argument("object", nargs="?", help="object name, e.g. mug or 'glasses case'")
    parser.add_argument("--world", help="world name (apartment, hk-studio, …) or a world file path")
    parser.add_argument("--scene", default="original", help="scene: original or modified")
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
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="annotated corpus (XML + chunk-grounding CSV, files or folders) to "
                             "learn from instead of the repository's corpus/")
    parser.add_argument("--batch", metavar="FILE",
                        help="one JSON request per line: {object, world, scene, listener, style, "
                             "question, search}")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.errors import AssistantError
    from assistant.generation import Describer, load_generation_model

    describer = Describer(load_generation_model(args.corpus))
    shared: dict = {}
    if args.batch:
        def handle(request: dict) -> dict:
            listener = request.get("listener")
            if isinstance(listener, str):
                listener = parse_pose(listener)
            return answer(describer, request.get("object"), request.get("world"),
                          request.get("scene", "original"), listener, request.get("style"),
                          request.get("question"), search=request.get("search", args.search),
                          miss_rate=miss_probability(str(request.get("miss_rate", args.miss_rate))),
                          seed=request_int(request, "seed", args.seed, high=MAX_SEED), shared=shared).to_dict()
        return run_batch(args.batch, handle, json_requests=True)
    if not args.object or not args.world:
        raise AssistantError("give an object and --world NAME (or --batch FILE)")
    if args.search == "sensed" and not args.json:
        import sys

        print(f"searching for the {args.object} …", file=sys.stderr, flush=True)
    result = answer(describer, args.object, args.world, args.scene, args.listener, args.style,
                    args.question, search=args.search, miss_rate=args.miss_rate, seed=args.seed,
                    shared=shared)
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


def answer(describer, name, world_name, scene="original", listener=None, style=None, question=None,
           search: str = "sensed", miss_rate: float = 0.0, seed: int = 0, shared: dict | None = None,
           on_event=None):
    """One "where is my X?" request: search (``sensed``: the simulated robot from the world's
    start pose; ``oracle``: the world file), then compose. ``shared`` keeps the loaded furniture
    detector between requests of a batch."""
    import time

    from assistant.errors import AssistantError, UnknownNameError
    from assistant.generation import (not_found_description, oracle_environment, oracle_sighting,
                                      style_for_question)
    from assistant.generation.types import SEARCH_MODES
    from assistant.geometry import Pose2D
    from assistant.world import load_world

    if not name or not world_name:
        raise AssistantError("a request needs 'object' and 'world'")
    if search not in SEARCH_MODES:
        raise UnknownNameError("search", str(search), SEARCH_MODES)
    world = load_world(world_name)
    scene = world.scene(scene).name
    # the person asking stands where the robot was asked (the world's start pose) unless told
    # otherwise: rooms are entered, and walls named ("the back wall"), from there
    pose = Pose2D(*listener) if listener is not None else world.start
    if style is None:
        style = style_for_question(question) if question else "static"
    if search == "sensed":
        from assistant.executor.search import search_for

        shared = {} if shared is None else shared
        if "furniture_detector" not in shared:
            from assistant.perception import FurnitureDetector

            shared["furniture_detector"] = FurnitureDetector()
        found = search_for(" ".join(str(name).lower().split()), world, scene,
                           furniture_detector=shared["furniture_detector"], miss_rate=miss_rate,
                           seed=seed, on_event=on_event)
        return describer.describe_search(found, world.floorplan, listener_pose=pose, style=style)
    start = time.perf_counter()
    sighting = oracle_sighting(world, scene, str(name))
    search_s = time.perf_counter() - start
    if sighting is None:
        result = not_found_description(str(name), world.floorplan.room_names)
        result.search_seconds = search_s
        return result
    env = oracle_environment(world, scene)
    result = describer.describe(sighting, env, world.floorplan, listener_pose=pose, style=style)
    result.search_seconds = search_s
    return result

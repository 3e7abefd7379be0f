"""``assistant where OBJECT --world NAME``: say where an object is, like a person would.

Today the search is the *oracle search* (the object's position is read from the world file) and
the environment model is the world file's furniture (*oracle environment*); both are labelled
in the output (``"search": "oracle"``, ``"environment": "oracle"``). The description itself is
composed by content selection and surface realization learned from the corpus.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import add_json_flag, emit_json, parse_pose, run_batch


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
                        help="where the person asking stands (metres, metres, radians); the room "
                             "is not said when they are in it")
    parser.add_argument("--style", choices=("static", "dynamic"), default=None,
                        help="static: where it is; dynamic: how to get there from --listener "
                             "(default: from --question, else static)")
    parser.add_argument("--question", help="the person's question; 'how do I get to my X' picks "
                                           "the dynamic style")
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="annotated corpus (XML + chunk-grounding CSV, files or folders) to "
                             "learn from instead of the repository's corpus/")
    parser.add_argument("--batch", metavar="FILE",
                        help="one JSON request per line: {object, world, scene, listener, style}")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.errors import AssistantError
    from assistant.generation import Describer, load_generation_model

    describer = Describer(load_generation_model(args.corpus))
    if args.batch:
        def handle(request: dict) -> dict:
            listener = request.get("listener")
            if isinstance(listener, str):
                listener = parse_pose(listener)
            return answer(describer, request.get("object"), request.get("world"),
                          request.get("scene", "original"), listener, request.get("style"),
                          request.get("question")).to_dict() | _labels()
        return run_batch(args.batch, handle, json_requests=True)
    if not args.object or not args.world:
        raise AssistantError("give an object and --world NAME (or --batch FILE)")
    result = answer(describer, args.object, args.world, args.scene, args.listener, args.style,
                    args.question)
    if args.json:
        emit_json(result.to_dict() | _labels())
        return 0
    print(result.description)
    if result.found:
        said_room = any(n.kind == "room" for n in result.selected)
        print(f"  nodes: {', '.join(result.nodes)}"
              + (f"; room: {result.to_dict()['room']}" if said_room else ""))
        print(f"  tree: {result.tree.bracketed()}")
        print(f"  search: oracle (world file), environment: oracle (world file furniture); "
              f"composed in {result.composition_seconds * 1000:.1f} ms")
        if result.ambiguous:
            print("  note: no selection singles the furniture out; the description may be ambiguous")
    return 0


def _labels() -> dict:
    return {"search": "oracle", "environment": "oracle"}


def answer(describer, name, world_name, scene="original", listener=None, style=None, question=None):
    """One "where is my X?" request with the oracle search (see the module docstring)."""
    import time

    from assistant.errors import AssistantError
    from assistant.generation import (not_found_description, oracle_environment, oracle_sighting,
                                      style_for_question)
    from assistant.geometry import Pose2D
    from assistant.world import load_world

    if not name or not world_name:
        raise AssistantError("a request needs 'object' and 'world'")
    world = load_world(world_name)
    start = time.perf_counter()
    sighting = oracle_sighting(world, scene, str(name))
    search_s = time.perf_counter() - start
    if sighting is None:
        result = not_found_description(str(name), world.floorplan.room_names)
        result.search_seconds = search_s
        return result
    pose = Pose2D(*listener) if listener is not None else None
    if style is None:
        style = style_for_question(question) if question else "static"
    if style == "dynamic" and pose is None:
        pose = world.start
    env = oracle_environment(world, scene)
    result = describer.describe(sighting, env, world.floorplan, listener_pose=pose, style=style)
    result.search_seconds = search_s
    return result

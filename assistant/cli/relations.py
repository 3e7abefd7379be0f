"""``assistant relations --world NAME``: what the spatial layer makes of a home's furniture.

For each room and each ordered pair of furniture items, the direction (DIR-SRV) and distance
(DIST-SRV) of the *described* item with respect to the *reference* item — e.g. whether the
table is in front of the couch. Front-less references (tables) are read from the robot's start
pose as the viewer.
"""

from __future__ import annotations

import argparse
import math

from assistant.cli.common import add_json_flag, emit_json, finite_float, print_table, run_batch


#: finest floor grid accepted (metres per cell): a house at 1 cm is already millions of cells
MIN_RESOLUTION_M = 0.01


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "relations", help="spatial relations (direction, distance) between a home's furniture",
        description="Direction and distance of every furniture item relative to every other "
                    "item of its room, from the world file's furniture (ground truth).",
    )
    parser.add_argument("--world", help="world name (apartment, hk-studio, …) or world file path")
    parser.add_argument("--scene", default="original", help="scene: original or modified")
    parser.add_argument("--reference", metavar="WORD_OR_ID",
                        help="only pairs whose reference is this furniture id or word (e.g. couch)")
    parser.add_argument("--resolution", type=finite_float, default=0.05, metavar="METRES",
                        help="floor-grid cell size (default 0.05 m)")
    parser.add_argument("--viewer", type=finite_float, metavar="RADIANS",
                        help="viewer heading for front-less references (default: the start heading)")
    parser.add_argument("--batch", metavar="FILE",
                        help="one JSON request per line: {world, scene, reference}; one JSON answer per line")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def _answer(world_name: str, scene: str, reference: str | None, resolution: float,
            viewer: float | None) -> dict:
    from assistant.errors import AssistantError, UnknownNameError
    from assistant.spatial import relations
    from assistant.world import load_world

    if not MIN_RESOLUTION_M <= resolution <= 1.0:
        raise AssistantError(f"--resolution must be from {MIN_RESOLUTION_M} to 1 metre, got {resolution}")
    if viewer is not None:
        viewer = float(viewer)
        if not math.isfinite(viewer):
            raise AssistantError(f"the viewer heading must be a finite number of radians, got {viewer}")
        viewer = math.remainder(viewer, 2 * math.pi)  # any turn count: the same heading in (-π, π]
    world = load_world(world_name)
    sc = world.scene(scene)
    if reference is not None:
        known = {f.id for f in sc.furniture} | {f.word for f in sc.furniture}
        if reference not in known:
            raise UnknownNameError("furniture", reference, known)
    rel = relations(world, sc.name, resolution_m=resolution, viewer_heading_rad=viewer,
                    reference=reference)
    return {"world": world.name, "scene": sc.name, "resolution": resolution,
            "viewer_heading": world.start.theta if viewer is None else viewer,
            "relations": rel}


def run(args: argparse.Namespace) -> int:
    from assistant.errors import AssistantError

    if args.batch:
        def handle(request: dict) -> dict:
            if "world" not in request:
                raise AssistantError("a request needs a \"world\"")
            return _answer(str(request["world"]), str(request.get("scene", "original")),
                           request.get("reference"), float(request.get("resolution", args.resolution)),
                           request.get("viewer", args.viewer))
        return run_batch(args.batch, handle, json_requests=True)
    if not args.world:
        raise AssistantError("give --world NAME (or --batch FILE)")
    data = _answer(args.world, args.scene, args.reference, args.resolution, args.viewer)
    if args.json:
        emit_json(data)
        return 0
    whose = "the start heading" if args.viewer is None else "the viewer heading"
    print(f"{data['world']} ({data['scene']} scene); tables are seen from {whose} "
          f"{data['viewer_heading']:.2f} rad")
    room = None
    rows: list[list] = []
    for r in data["relations"]:
        if r["room"] != room:
            if rows:
                print_table(rows, header)
            room = r["room"]
            print(f"\n{room}")
            rows = []
            header = ["described", "is", "reference", "frame", "direction", "distance"]
        rows.append([r["described"], f"{_phrase(r['direction'])}", r["reference"], r["frame"],
                     f"{r['direction']} {r['dir'][r['direction']]:.2f}",
                     f"{r['distance']} {r['dist'][r['distance']]:.2f}"])
    if rows:
        print_table(rows, header)
    if not data["relations"]:
        print("no furniture pairs")
    return 0


def _phrase(direction: str) -> str:
    """``front`` → "in front of", ``inner-left`` → "in the left part of"…"""
    if direction.startswith("inner-"):
        return f"in the {direction.removeprefix('inner-')} part of"
    return {"front": "in front of", "back": "behind", "left": "left of", "right": "right of"}[direction]

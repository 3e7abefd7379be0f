"""``assistant world NAME``: show a home — its rooms, doors, furniture and objects."""

from __future__ import annotations

import argparse

from assistant.cli.common import add_json_flag, emit_json


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "world", help="describe a home (rooms, doors, furniture, objects) or show it in 3D",
        description="Describe a world (a packaged home by name, or a world file by path).",
    )
    parser.add_argument("name", help="world name (apartment, hk-studio, …) or a world file path")
    parser.add_argument("--scene", default="original", help="scene: original, modified or lived-in")
    add_json_flag(parser)
    parser.add_argument("--check", action="store_true",
                        help="check objects lie on furniture, furniture in rooms, rooms reachable")
    parser.add_argument("--view", action="store_true",
                        help="serve the 3D view (meshcat), print its URL, wait for Ctrl-C")
    parser.add_argument("--html", metavar="FILE", help="write the 3D view as a self-contained HTML page")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.world import check_world, load_world

    world = load_world(args.name)
    scene = world.scene(args.scene)
    if args.check:
        problems = check_world(world)
        if args.json:
            emit_json({"world": world.name, "problems": [str(p) for p in problems]})
        else:
            for problem in problems:
                print(problem)
            print(f"{world.name}: {'no problems' if not problems else f'{len(problems)} problem(s)'}")
        return 1 if problems else 0
    if args.view or args.html:
        return _show(world, scene.name, args)
    data = world.to_dict(scene.name)
    if args.json:
        emit_json(data)
        return 0
    _print_summary(data, world.title)
    return 0


def _show(world, scene: str, args: argparse.Namespace) -> int:
    from assistant.viz import SceneView

    with SceneView(open_server=bool(args.view)) as view:
        view.draw_world(world, scene)
        if args.html:
            path = view.save_html(args.html)
            print(f"wrote {path}")
        if args.view:
            print(f"3D view of {world.name} ({scene}): {view.url}", flush=True)
            print("press Ctrl-C to stop", flush=True)
            view.wait()
    return 0


def _print_summary(data: dict, title: str) -> None:
    from assistant.generation import is_are

    start = data["start"]
    print(f"{data['world']} ({data['scene']} scene){' — ' + title if title else ''}")
    print(f"robot starts at x={start['x']:.2f} m, y={start['y']:.2f} m, heading {start['heading']:.2f} rad")
    print("rooms: " + ", ".join(r["name"] for r in data["rooms"]))
    for door in data["doors"]:
        print(f"door '{door['name']}' at ({door['x']:.2f}, {door['y']:.2f}) joins {' and '.join(door['connects'])}")
    for f in data["furniture"]:
        facing = "" if f["facing"] is None else f", facing {f['facing']:.2f} rad"
        print(f"  {f['id']:<16} {f['model']:<14} in the {f['room']:<13} at ({f['x']:.2f}, {f['y']:.2f}){facing}")
    for o in data["objects"]:
        print(f"  the {o['name']} {is_are(o['name'])} on {o['on']} in the {o['room']} at ({o['x']:.2f}, {o['y']:.2f})")

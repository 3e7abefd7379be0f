"""``assistant fetch TEXT --world NAME``: follow a fetch command with a robot (the simulator by
default, or a replay), from text to the final pose, and say whether the target object ends up
in view. The fetch itself is the application layer's (:meth:`assistant.app.Fetcher.fetch`)."""

from __future__ import annotations

import argparse

from assistant.cli.common import (MAX_SEED, add_json_flag, add_robot_option, check_command_text, emit_json, request_int,
                                  out_file, require_text_or_batch, run_batch, seed_int)

PERCEPTION_MODES = ("sensed", "oracle")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "fetch", help="follow a fetch command in the simulator",
        description="Parse a fetch command, enter the target room, follow its RDT nodes with the "
                    "policy models and perception, face the target furniture, and report whether "
                    "the target object is in the final camera frame (evaluation from the "
                    "simulator's hit ids; the robot never reads them).",
    )
    parser.add_argument("text", nargs="*", help="the command (omit with --batch)")
    parser.add_argument("--world", metavar="NAME", help="world name or file (required without --batch)")
    parser.add_argument("--scene", default="original",
                        help="furniture placement: original (default), modified or lived-in (the study's "
                             "homes; assistant world NAME --scene S shows one)")
    parser.add_argument("--perception", choices=PERCEPTION_MODES, default="sensed",
                        help="sensed: furniture detector on depth frames (default); oracle: the world "
                             "file's furniture (to separate language from perception errors)")
    parser.add_argument("--grounder", choices=("scored", "learned"), default=None,
                        help="grounding model (default: the one measured best)")
    parser.add_argument("--seed", type=seed_int, default=0, help="simulator seed (odometry and depth noise)")
    add_robot_option(parser, help_="sim (default; sim:WORLD[:SCENE] names the home) or replay:FILE.mcap — a "
                                   "recorded session (assistant record): its home is the recording's unless "
                                   "--world says otherwise")
    parser.add_argument("--record", metavar="OUT.mcap", type=out_file(".mcap"),
                        help="record the run (depth, odometry, commands, the command's words) as MCAP; "
                             "replay it with --robot replay:OUT.mcap")
    parser.add_argument("--object", metavar="NAME", help="the object to check for at the end "
                        "(default: the one the command names)")
    parser.add_argument("--batch", metavar="FILE",
                        help="JSON lines {text, world, scene, perception[, object, seed]} ('-' for stdin); "
                             "one JSON object per line out")
    parser.add_argument("--view", action="store_true",
                        help="show the run in the 3D view (meshcat) and wait until Ctrl-C")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.app import Fetcher
    from assistant.errors import AssistantError

    require_text_or_batch(args.text, args.batch, "fetch")
    fetcher = Fetcher(grounder=args.grounder, taught=True)
    if args.batch:
        def handle(request: dict) -> dict:
            unknown = set(request) - {"text", "world", "scene", "perception", "object", "seed", "kind", "robot"}
            if unknown:
                raise AssistantError(f"unknown key(s) {', '.join(sorted(unknown))}; a request has "
                                     "text, world, scene, perception, object, seed, robot")
            if not request.get("text") or not request.get("world"):
                raise AssistantError("a request needs 'text' and 'world'")
            check_command_text(request["text"])
            if not isinstance(request["world"], str):
                raise AssistantError(f"world: expected a name, got {request['world']!r}")
            perception = request.get("perception", args.perception)
            if perception not in PERCEPTION_MODES:
                raise AssistantError(f"perception must be one of {', '.join(PERCEPTION_MODES)}, got {perception!r}")
            return fetcher.fetch(str(request["text"]), str(request["world"]), request.get("scene", args.scene),
                                 perception, robot=str(request.get("robot", args.robot)),
                                 seed=request_int(request, "seed", args.seed, high=MAX_SEED),
                                 object_name=request.get("object")).data

        return run_batch(args.batch, handle, json_requests=True)
    robot = _robot(args)
    if not args.world:
        from assistant.app import spec_world

        args.world = spec_world(args.robot)
    if not args.world:
        from assistant.world import world_names

        raise AssistantError(f"say which home with --world NAME; homes: {', '.join(world_names())}")
    text = check_command_text(" ".join(args.text))
    if args.record:
        robot = _recording(robot, args, text)
    view = _Viewer() if args.view else None
    outcome = fetcher.fetch(text, args.world, args.scene, args.perception, robot=robot or args.robot,
                            seed=args.seed, object_name=args.object, on_event=view.on_event if view else None)
    if robot is not None and hasattr(robot, "command_report"):
        outcome.data["replay"] = robot.command_report()
    if args.json:
        emit_json(outcome.data)
    else:
        _print(outcome.data)
    if view is not None:
        view.finish(outcome)
    return 0


def _robot(args):
    """None for the simulator or a real robot (the fetcher opens it from the spec); a replay for
    ``replay:FILE``, whose recorded home and scene fill in --world and --scene when not given."""
    from assistant.robot import make_robot, parse_robot_spec

    spec = parse_robot_spec(args.robot)
    if spec.scheme != "replay":
        return None
    robot = make_robot(spec)
    recorded = robot.metadata
    args.world = args.world or recorded.get("world") or None
    if recorded.get("scene") and args.scene == "original":
        args.scene = recorded["scene"]
    return robot


def _recording(robot, args, text: str):
    """The run's robot (a new simulator like the runner's when None) wrapped in a recorder,
    connected, with the command's words as the dialogue's first turn."""
    from assistant.robot import make_robot
    from assistant.robot.recording import RecordingRobot

    if robot is None:
        robot = make_robot("sim", world=args.world, scene=args.scene, seed=args.seed, noise=True)
    metadata = {"spec": args.robot, "world": args.world, "scene": args.scene, "task": f"fetch: {text}", "fetch": text}
    recorder = RecordingRobot(robot, args.record, metadata).connect()
    recorder.record_turn("user", text)
    return recorder


def _print(d: dict) -> None:
    plan = d["plan"]
    print(f"plan: room={plan['room'] or '?'} object={plan['object'] or '?'} kind={plan['kind']} "
          f"nodes={', '.join(plan['nodes']) or '-'}")
    for node in d["nodes"]:
        pose = node["move_to"]
        where = f"({pose[0]:.2f}, {pose[1]:.2f}, {pose[2]:.2f} rad)" if pose else "-"
        score = f"{node['score']:.3g}" if node["score"] is not None else "-"
        print(f"  {node['rdt']:<22} {node['status']:<20} move-to {where} score {score}  "
              f"ref={node['reference'] or '-'} target={node['target'] or '-'}")
    fp = d["final_pose"]
    print(f"final pose: ({fp[0]:.2f}, {fp[1]:.2f}, {fp[2]:.2f} rad)   robot said: {d['executor']['message']}")
    tv = d["target_visible"]
    where = d["target_position"]
    if where is not None:  # (a command that names no object has none to see: "turn around")
        print(f"{d['object'] or 'object'} at {where}: {tv['pixels']} pixels in view"
              + (f" at {tv['distance']:.2f} m" if tv["distance"] is not None else ""))
    replay = d.get("replay") or {}
    if replay.get("first_difference_s") is not None:  # the replayed robot follows the recording, not this run
        print(f"note: the recording's commands differ from this run's from {replay['first_difference_s']:.1f} s on "
              f"({replay.get('matched', 0)} of {replay.get('issued', 0)} matched): a replay shows what was recorded, "
              "so a different command cannot be carried out on it — give the recorded command")
    print(("SUCCESS" if d["success"] else f"FAILED: {d['failure']}")
          + f"   ({d['sim_seconds']:.1f} s simulated, {d['wall_seconds']:.1f} s wall-clock)")


class _Viewer:
    """Draws the run in a :class:`~assistant.viz.SceneView` (robot path, move-to score maps)."""

    def __init__(self):
        from assistant.viz import SceneView

        self.view = SceneView()
        self.drawn_world = False
        self.goals = 0
        self.points: list = []

    def on_event(self, name: str, data: dict) -> None:
        if name == "move_to":
            self.goals += 1
            if data.get("score_map") is not None:
                poses, scores = data["score_map"]
                self.view.draw_arrows(f"scores/{self.goals}", poses, scores)
            g = data["goal"]
            self.points.append((g.x, g.y))
            self.view.draw_robot(g, name=f"goal/{self.goals}", colour="#2b8cd9")

    def finish(self, outcome) -> None:
        from assistant.world import load_world

        d = outcome.data
        world = load_world(d["world"])
        self.view.draw_world(world, d["scene"], robot_pose=d["final_pose"])
        self.view.draw_robot(d["final_pose"])
        route = [tuple(world.start.xy.ravel()[:2])] + self.points + [tuple(d["final_pose"][:2])]
        self.view.draw_path("move-to goals", route)
        target = (d["executor"].get("target_furniture") or {}).get("id")
        if target:
            try:
                self.view.highlight(target)
            except Exception:  # highlighting is a courtesy; the run's data is already printed
                pass
        print(f"3D view: {self.view.url}  (Ctrl-C to quit)")
        try:
            self.view.wait()
        finally:
            self.view.close()

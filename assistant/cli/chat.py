"""``assistant chat --world NAME``: talk to the robot in a terminal.

A read–eval–print loop over :class:`~assistant.dialogue.DialogueManager`: line editing and
history (stdlib ``readline``; history in the data folder), a transcript of every turn saved
atomically after each one, the robot's progress printed as it acts. Ctrl-C stops the robot, a
second Ctrl-C in a row leaves; the end of input (Ctrl-D) leaves cleanly. The models load in a
background thread, so the prompt appears at once.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import add_robot_option

PROMPT = "you> "


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "chat", help="talk to the robot: fetch, where is my X, teach, stop",
        description="A conversation with the robot in a terminal. Ask it to fetch things, where "
                    "something is, how to get to it, or to learn a place; say 'help' inside.")
    parser.add_argument("--world", default=None, help="world name or file (default: the one a sim:WORLD robot "
                                                     "names, else apartment)")
    parser.add_argument("--scene", default="original", help="scene: original or modified")
    add_robot_option(parser)
    parser.add_argument("--perception", choices=("sensed", "oracle"), default="sensed",
                        help="sensed: furniture detector on depth frames (default); oracle: the world "
                             "file's furniture")
    parser.add_argument("--search", choices=("sensed", "oracle"), default="sensed",
                        help="'where is my X' for an object the robot has not seen: sensed (default) "
                             "— the robot searches the home; oracle — answer from the simulator's "
                             "world file (labelled as such)")
    parser.add_argument("--view", action="store_true", help="show the robot acting in the 3D view (meshcat)")
    parser.add_argument("--memory", metavar="FILE",
                        help="object memory file (default: DATA/memory.json; DATA is $ASSISTANT_DATA or "
                             "~/.local/share/assistant)")
    parser.add_argument("--transcripts", metavar="DIR", help="where transcripts go (default: DATA/transcripts)")
    parser.add_argument("--seed", type=int, default=0, help="simulator seed")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.app import spec_world
    from assistant.dialogue.repl import ChatSession

    args.world = args.world or spec_world(args.robot) or "apartment"
    return ChatSession(args).loop()

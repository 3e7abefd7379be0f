"""``assistant chat --world NAME``: talk to the robot in a terminal.

A read–eval–print loop over :class:`~assistant.dialogue.DialogueManager`: line editing and
history (stdlib ``readline``; history in the data folder), a transcript of every turn saved
atomically after each one, the robot's progress printed as it acts. Ctrl-C stops the robot, a
second Ctrl-C in a row leaves; the end of input (Ctrl-D) leaves cleanly. The models load in a
background thread, so the prompt appears at once.
"""

from __future__ import annotations

import argparse

from assistant.cli.common import add_robot_option, finite_float, seed_int

PROMPT = "you> "


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "chat", help="talk to the robot: fetch, where is my X, teach, stop",
        description="A conversation with the robot in a terminal. Ask it to fetch things, where "
                    "something is, how to get to it, or to learn a place; say 'help' inside.")
    parser.add_argument("--world", default=None, help="world name or file (default: the one a sim:WORLD robot "
                                                     "names, else apartment)")
    parser.add_argument("--scene", default="original", help="scene: original, modified or lived-in")
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
    parser.add_argument("--seed", type=seed_int, default=0, help="simulator seed")
    add_speech_arguments(parser)
    parser.set_defaults(handler=run)


def add_speech_arguments(parser) -> None:
    """``--speech`` and its options (docs/speech.md)."""
    group = parser.add_argument_group("speech", "talk and listen instead of typing (docs/speech.md)")
    group.add_argument("--speech", action="store_true",
                       help="speak every reply and listen to the microphone (or --audio-in)")
    group.add_argument("--audio-in", metavar="FILE|DIR",
                       help="take the utterances from a WAV file or a folder of them (name order)")
    group.add_argument("--asr", choices=("pocketsphinx", "vosk"), default="pocketsphinx",
                       help="speech recogniser (default pocketsphinx: needs no download)")
    group.add_argument("--asr-model", metavar="DIR", help="the vosk model folder (with --asr vosk)")
    group.add_argument("--voice", default="en-us", help="espeak-ng voice (default en-us; `espeak-ng --voices=en`)")
    group.add_argument("--rate", type=int, default=170, help="speaking rate, words per minute (default 170)")
    group.add_argument("--say-to", metavar="FILE.wav",
                       help="write everything the robot says to this WAV file instead of playing it")
    group.add_argument("--confirm-below", type=finite_float, default=None, metavar="P",
                       help="ask \"Did you say ...?\" below this recognition confidence (default 0.45)")
    group.add_argument("--mic", default=None, help="microphone: a PortAudio device index or name")
    group.add_argument("--speaker", metavar="NAME", help="decode with NAME's voice model (assistant enrol NAME)")


def run(args: argparse.Namespace) -> int:
    from assistant.progress import working

    if args.audio_in or args.say_to:
        args.speech = True
    if args.asr_model and args.asr != "vosk":
        from assistant.errors import AssistantError

        raise AssistantError("--asr-model is the folder of a vosk model: add --asr vosk")
    # the product's code, the home, the memory and the language models load before the greeting:
    # a ticking line on a terminal meanwhile (12–16 s on a loaded machine: the chat's silent start)
    with working("getting ready to talk: the home, the memory and the language models"):
        from assistant.app import spec_world

        args.world = args.world or spec_world(args.robot) or "apartment"
        if not args.speech:
            from assistant.dialogue.repl import ChatSession

            session = ChatSession(args)
            session.prepare()
    if args.speech:
        from assistant.dialogue.speech.session import run as run_speech

        return run_speech(args)
    return session.loop()

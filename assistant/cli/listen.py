"""``assistant listen FILE.wav``: what the robot hears in a recording, and how it parses it."""

from __future__ import annotations

import argparse

from assistant.cli.common import add_json_flag, emit_json


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "listen", help="recognise the speech in a WAV file and parse it",
        description="Recognise one utterance in a recording (WAV, any rate, mono or stereo; it is "
                    "resampled to 16 kHz) and parse the words into a plan, as the chat would.")
    parser.add_argument("files", nargs="+", metavar="FILE.wav", help="recordings (one utterance each)")
    parser.add_argument("--asr", choices=("pocketsphinx", "vosk"), default="pocketsphinx",
                        help="speech recogniser (default pocketsphinx)")
    parser.add_argument("--asr-model", metavar="DIR", help="the vosk model folder (with --asr vosk)")
    parser.add_argument("--world", metavar="NAME", default=None,
                        help="the home: its words join the recogniser's model and the parse uses it")
    parser.add_argument("--no-open", action="store_true",
                        help="pocketsphinx: only the home model (no general-English fallback)")
    parser.add_argument("--speaker", metavar="NAME", help="pocketsphinx: decode with NAME's voice model (assistant enrol)")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.dialogue.speech.listener import Listener
    from assistant.grounding import CommandParser

    world = None
    if args.world:
        from assistant.world import load_world

        world = load_world(args.world)
    options = {}
    if args.asr == "pocketsphinx":
        options = {"world": world, "open_fallback": not args.no_open}
        if args.asr_model:
            from assistant.errors import AssistantError

            raise AssistantError("--asr-model is the folder of a vosk model: add --asr vosk")
    elif args.asr_model:
        options = {"asr_model": args.asr_model}
    if args.speaker is not None:
        options["speaker"] = args.speaker  # vosk refuses it with what to do
    listener = Listener(args.asr, **options)
    try:
        return _listen(args, listener, CommandParser.load(None, world=world))
    finally:
        listener.recogniser.close()


def _listen(args, listener, parser) -> int:
    from assistant.dialogue.speech.errors import SpeechError

    status = 0
    single = len(args.files) == 1
    for path in args.files:
        try:
            heard = listener.hear_file(path)
        except SpeechError as error:
            if single:
                raise
            status = 2
            _emit(args, {"file": path, "error": str(error)}, str(error))
            continue
        out = heard.to_dict() | {"file": path, "parse": parser.parse(heard.transcript).to_dict()}
        plan = out["parse"]["plan"]
        _emit(args, out, f"{path}: \u201c{heard.transcript}\u201d (confidence {heard.confidence:.2f}, "
                         f"{heard.recognition.decode_s:.2f} s to decode {heard.recognition.audio_s:.1f} s)\n"
                         f"  plan: room {plan['room'] or '?'}, object {plan['object'] or '?'}, "
                         f"nodes {', '.join(plan['nodes']) or '-'}")
    return status


def _emit(args, obj: dict, text: str) -> None:
    if args.json:
        emit_json(obj)
    else:
        print(text)

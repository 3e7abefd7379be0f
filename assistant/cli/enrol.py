"""``assistant enrol NAME``: fit the speech recogniser to one person's voice (docs/speech.md)."""

from __future__ import annotations

import argparse
from pathlib import Path

from assistant.cli.common import add_json_flag, emit_json, progress_for, whole_number


def register(subparsers) -> None:
    from assistant.dialogue.speech.enrol import ENROL_SENTENCES, SCRIPT_MAX

    parser = subparsers.add_parser(
        "enrol", help="fit speech recognition to one person's voice",
        description="Read the enrolment script aloud (or give recordings of it): the recogniser's "
                    "acoustic model is adapted to your voice and kept in your data folder. Then talk "
                    "with `assistant chat --speech --speaker NAME` or `assistant listen --speaker NAME`. "
                    "Needs SphinxTrain (make setup installs it).")
    parser.add_argument("name", help="the speaker's name (letters, digits, '-' and '_')")
    parser.add_argument("--script", action="store_true", help="print the sentences to read, one per line, and stop")
    parser.add_argument("--sentences", type=whole_number(10, SCRIPT_MAX), default=ENROL_SENTENCES, metavar="N",
                        help=f"how many script sentences to read (default {ENROL_SENTENCES})")
    parser.add_argument("--audio-in", metavar="DIR",
                        help="recordings of the script instead of the microphone: DIR's .wav files in name "
                             "order, the first the first sentence (see --script)")
    parser.add_argument("--mic", default=None, help="microphone: a PortAudio device index or name")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.dialogue.speech.enrol import check_name, enrol, enrolment_script, require_tools

    script = enrolment_script(args.sentences)
    if args.script:
        for n, text in enumerate(script, start=1):
            print(f"{n:3d}  {text}")
        return 0
    check_name(args.name)
    require_tools()  # before anyone reads forty sentences for nothing
    recordings = _from_folder(Path(args.audio_in), script) if args.audio_in else _from_microphone(script, args.mic)
    result = enrol(args.name, recordings, progress=progress_for(args))
    if args.json:
        emit_json({"speaker": result.name, "model": str(result.model), "recordings": result.recordings})
    else:
        print(f"Enrolled {result.name} from {result.recordings} recordings ({result.model}). Talk with: "
              f"assistant chat --speech --speaker {result.name}")
    return 0


def _from_folder(folder: Path, script: list[str]):
    """(samples, sentence) of each recording in ``folder`` (name order = script order)."""
    from assistant.dialogue.speech.audio import read_audio
    from assistant.dialogue.speech.enrol import MIN_RECORDINGS
    from assistant.dialogue.speech.errors import AudioFileError
    from assistant.dialogue.speech.vad import has_speech

    if not folder.is_dir():
        raise AudioFileError(f"{folder}: no such folder (give the folder of the script's recordings)")
    files = sorted(folder.glob("*.wav"))
    if not MIN_RECORDINGS <= len(files) <= len(script):
        raise AudioFileError(f"{folder}: {len(files)} .wav files; give {MIN_RECORDINGS} to {len(script)}, one per "
                             "script sentence in order (assistant enrol NAME --script prints them)")
    out = []
    for path, text in zip(files, script):
        samples = read_audio(path).samples
        if not has_speech(samples):
            raise AudioFileError(f"{path}: no speech heard (it should hold: {text!r})")
        out.append((samples, text))
    return out


def _from_microphone(script: list[str], device) -> list:
    """Each sentence shown, then the next utterance heard taken as its reading."""
    from assistant.dialogue.speech.microphone import Microphone

    out = []
    with Microphone(device) as mic:
        print(f"Read each sentence aloud when it appears ({len(script)} in all; Ctrl-C cancels, nothing is kept).")
        heard = mic.utterances()
        for n, text in enumerate(script, start=1):
            print(f"[{n}/{len(script)}] {text}", flush=True)
            utterance = next(heard, None)
            if utterance is None:
                break
            out.append((utterance.samples, text))
    return out

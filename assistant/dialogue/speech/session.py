"""``assistant chat --speech``: the terminal chat with speech in and out.

:class:`SpeechChat` wraps :class:`~assistant.dialogue.repl.ChatSession` through its two hooks:
``read_line`` (where the next utterance comes from) and ``speak`` (who else hears the robot).

* Input: the WAV files given with ``--audio-in FILE|DIR`` (a folder: its ``*.wav`` in name
  order), one utterance each; or the microphone. A file that cannot be used (empty, corrupt,
  too long, only silence) is named with the reason and the session goes on with the next.
  Without a usable microphone the chat says why and goes on by text.
* Each recognition is printed (``you (heard, 0.82): …``); an unsure one is confirmed first
  ("Did you say …?", see :class:`~assistant.dialogue.speech.listener.Confirmer`).
* Output: every sentence the robot says is spoken (:class:`~assistant.dialogue.speech.tts.Speaker`)
  and, with ``--say-to FILE.wav``, written to that file.
* Barge-in (microphone): while the robot is busy or talking, "stop" stops it like Ctrl-C.
"""

from __future__ import annotations

import logging
import time
from pathlib import Path

from assistant.dialogue.speech.errors import MicrophoneError, SpeechError

log = logging.getLogger(__name__)


def audio_files(path) -> list[Path]:
    """The recordings of ``--audio-in``: one file, or a folder's ``*.wav`` files in name order."""
    from assistant.dialogue.speech.errors import AudioFileError

    p = Path(path)
    if p.is_dir():
        files = sorted(f for f in p.iterdir() if f.suffix.lower() in (".wav", ".flac", ".ogg"))
        if not files:
            raise AudioFileError(f"--audio-in {p}: the folder holds no .wav files")
        return files
    if not p.exists():
        raise AudioFileError(f"--audio-in {p}: no such file or folder")
    return [p]


class SpeechChat:
    """Speech in and out around one :class:`ChatSession` (``args``: the chat's options)."""

    def __init__(self, args, stdin=None, stdout=None, listener=None, speaker=None):
        from assistant.dialogue.repl import ChatSession
        from assistant.dialogue.speech.listener import Confirmer, Listener
        from assistant.dialogue.speech.tts import Speaker

        self.session = ChatSession(args, stdin=stdin, stdout=stdout)
        self.args = args
        options = {"asr_model": args.asr_model} if getattr(args, "asr_model", None) else {}
        if getattr(args, "asr", "pocketsphinx") == "pocketsphinx":
            options["world"] = self.session.world
        if getattr(args, "speaker", None) is not None:
            options["speaker"] = args.speaker  # vosk refuses it with what to do
        self.listener = listener or Listener(getattr(args, "asr", "pocketsphinx"), **options)
        tip = None if getattr(args, "speaker", None) else (
            "If I keep mishearing you, fit me to your voice: assistant enrol YOUR-NAME, then talk with "
            "--speaker YOUR-NAME.")
        self.confirmer = Confirmer(getattr(args, "confirm_below", None) or Confirmer().below, tip=tip)
        say_to = getattr(args, "say_to", None)
        self.speaker = speaker or Speaker(args.voice, args.rate, say_to=say_to, play=not say_to)
        self.session.speak = self._speak
        self.files = audio_files(args.audio_in) if getattr(args, "audio_in", None) else None
        self._mic = None
        self._utterances = None
        self._stream = None
        self._stop_heard = 0
        self.latencies_s: list[float] = []  # end of speech → reply handed to the speaker
        self._heard_at: float | None = None

    # ------------------------------------------------------------------ output
    def _speak(self, sentence: str) -> None:
        if self._heard_at is not None:
            self.latencies_s.append(time.perf_counter() - self._heard_at)
            self._heard_at = None
        self.speaker.say(sentence)

    # ------------------------------------------------------------------ input
    def _next_heard(self):
        """The next recognition (files or microphone); EOFError at the end of the files."""
        if self.files is not None:
            while self.files:
                path = self.files.pop(0)
                try:
                    return self.listener.hear_file(path)
                except SpeechError as error:
                    self.session.show(f"(skipped {path.name}: {error})")
            raise EOFError
        from assistant.dialogue.speech.listener import Heard

        utterance = next(self._utterances)  # decoded while it was said (see _on_samples)
        stream, self._stream = self._stream, None
        return Heard(stream.finish(), utterance.start_s, utterance.end_s, "microphone")

    def _on_samples(self, samples, starting: bool) -> None:
        """Endpointer hook (microphone): feed the recogniser while the person talks."""
        if starting or self._stream is None:
            self._stream = self.listener.recogniser.stream()
        self._stream.feed(samples)

    def read_line(self) -> str:
        """The hook ChatSession reads from: the words to act on, after any confirmation."""
        while True:
            heard = self._next_heard()
            self._heard_at = time.perf_counter()
            text, question = self.confirmer.check(heard.transcript, heard.confidence)
            self.session.show(f"you (heard, {heard.confidence:.2f}): {heard.transcript or '(nothing)'}")
            if text is not None:
                return text
            self.session.say(question)

    # ------------------------------------------------------------------ microphone
    def _open_microphone(self) -> bool:
        from assistant.dialogue.speech.keyword import KeywordSpotter
        from assistant.dialogue.speech.microphone import Microphone

        try:
            self._mic = Microphone(getattr(self.args, "mic", None))
            self._mic.open()
        except MicrophoneError as error:
            self._mic = None
            self.session.show(f"(no speech input: {error}) — type instead.")
            return False
        try:
            spotter = KeywordSpotter("stop")
            self._mic.listeners.append(lambda block: self._barge_in(spotter, block))
        except SpeechError as error:
            self.session.show(f"(no barge-in: {error})")
        from assistant.dialogue.speech.vad import UtteranceDetector

        self._utterances = self._mic.utterances(detector=UtteranceDetector(on_samples=self._on_samples))
        self.session.show("(listening: speak after the prompt; say \"stop\" to stop the robot)")
        return True

    def _barge_in(self, spotter, block) -> None:
        """Microphone callback: spot "stop" only while the robot drives or talks."""
        if not (self.session.manager.busy or self.speaker.speaking):
            spotter.reset()
            return
        if spotter.feed(block):
            self._stop_heard += 1
            self.speaker.stop()
            if self.session.manager.stop():
                self.session.say("Stopping.")

    def loop(self) -> int:
        """Run the chat; returns its exit status."""
        if self.files is not None or self._open_microphone():
            self.session.read_line = self.read_line
        # before the greeting, not beside it: synthesis silences stdout while it runs (pyttsx3's
        # chatter), and a thread still inside espeak's C code at exit aborts the program
        self._warm_speaker()
        try:
            return self.session.loop()
        finally:
            if self._mic is not None:
                self._mic.close()
            self.listener.recogniser.close()

    def _warm_speaker(self) -> None:
        try:
            self.speaker.synthesise("ready")
        except SpeechError as error:
            log.info("speech output not ready: %s", error)


def run(args) -> int:
    """Entry point of ``assistant chat --speech``."""
    return SpeechChat(args).loop()

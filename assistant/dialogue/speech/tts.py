"""Speech out: pyttsx3 on espeak-ng, played through PortAudio or written to a WAV file.

pyttsx3's espeak driver has known problems with ``save_to_file`` (pyttsx3 2.9x): it prints
"Audio saved to …" on standard output (which would break ``--json``), the file name sticks to
the engine so a later ``say`` writes that file again instead of speaking, older releases hang
in ``runAndWait`` or leave an empty file, and ``say`` plays by running ``aplay`` through a shell.
:class:`Speaker` therefore always asks pyttsx3 for a WAV of each reply — into a fresh temporary
file, with standard output captured, and with a time limit — checks that the WAV holds audio,
and then plays the samples itself (``sounddevice``) and/or appends them to the ``--say-to``
file, which it rewrites atomically after every reply. When pyttsx3 fails, the same text is
synthesised by the ``espeak-ng`` program (same voice and rate) and the fallback is logged.
"""

from __future__ import annotations

import contextlib
import io
import logging
import os
import shutil
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, audio_from_bytes, write_wav
from assistant.dialogue.speech.errors import SpeechOutputError, require

log = logging.getLogger(__name__)

#: pause written between two replies in a --say-to file (seconds)
GAP_S = 0.4
#: longest a synthesis may take before it counts as hung (seconds)
SYNTH_TIMEOUT_S = 20.0
#: synthesis threads that did not finish in time (maybe still inside espeak's C code)
_HUNG: list[threading.Thread] = []


def synthesis_hung() -> bool:
    """Whether a timed-out synthesis thread is still running."""
    return any(thread.is_alive() for thread in _HUNG)


def leave_if_synthesis_hung(code: int) -> None:
    """End the process now, with ``code``, when a timed-out synthesis thread is still running.

    Python's normal exit would tear the interpreter down under that thread while it is inside
    espeak's C code, which aborts the program ("terminate called without an active exception",
    exit status 134) instead of exiting with ``code``. Output is flushed first; nothing of the
    program's own is left to do when this is called (the command has returned)."""
    if not synthesis_hung():
        return
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(code)


class Speaker:
    """Speaks replies. ``voice``: an espeak-ng voice (``en-us``, ``en-gb``, ``en-us+f3`` …);
    ``rate``: words per minute; ``say_to``: a WAV file collecting everything said;
    ``play``: also play through the sound card (False: only the file)."""

    def __init__(self, voice: str = "en-us", rate: int = 170, say_to=None, play: bool = True):
        if not 80 <= int(rate) <= 450:
            raise SpeechOutputError(f"--rate {rate}: choose a speaking rate between 80 and 450 words per minute")
        self.voice = voice
        self.rate = int(rate)
        self.say_to = Path(say_to) if say_to else None
        self.play = play
        self._said: list[np.ndarray] = []
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._engine = None
        self._pyttsx3_hung = False  # a synthesis timed out: its engine is busy for good
        self.fallbacks = 0
        self.speaking = False  # sound is playing (barge-in listens then)
        self._check_voice()
        if self.say_to is not None:
            self._check_writable(self.say_to)

    # ------------------------------------------------------------------ set-up
    def _check_voice(self) -> None:
        if shutil.which("espeak-ng") is None:
            raise SpeechOutputError("espeak-ng is not installed; install it with: apt-get install espeak-ng")
        listed = subprocess.run(["espeak-ng", "--voices"], capture_output=True, text=True, timeout=10).stdout
        names = {p for line in listed.splitlines()[1:] for p in line.split()[1:2] + line.split()[3:5]}
        base = self.voice.split("+", 1)[0]
        if base not in names and base.split("/")[-1] not in names:
            raise SpeechOutputError(f"--voice {self.voice}: espeak-ng has no such voice; `espeak-ng --voices=en` "
                                    "lists them (e.g. en-us, en-gb, en-us+f3)")

    @staticmethod
    def _check_writable(path: Path) -> None:
        folder = path.parent if str(path.parent) else Path(".")
        if not folder.is_dir() or not os.access(folder, os.W_OK):
            raise SpeechOutputError(f"--say-to {path}: cannot write in {folder}; choose a file in a writable folder")

    def _pyttsx3(self):
        if self._engine is None:
            pyttsx3 = require("pyttsx3", "pip install pyttsx3", SpeechOutputError)
            engine = pyttsx3.init("espeak")
            engine.setProperty("rate", self.rate)
            engine.setProperty("voice", self.voice)
            self._engine = engine
        return self._engine

    # ------------------------------------------------------------------ synthesis
    def synthesise(self, text: str) -> np.ndarray:
        """The spoken ``text`` as 16 kHz mono samples (pyttsx3; espeak-ng if pyttsx3 fails)."""
        text = " ".join(text.split())
        if not text:
            return np.zeros(0, dtype=np.float32)
        with self._lock:
            if self._pyttsx3_hung:
                self.fallbacks += 1
                return self._with_espeak(text)
            try:
                return self._with_pyttsx3(text)
            except Exception as error:  # pyttsx3's driver problems: fall back to the program
                self.fallbacks += 1
                self._engine = None
                log.info("pyttsx3 could not synthesise (%s); using espeak-ng directly", error)
                return self._with_espeak(text)

    def _with_pyttsx3(self, text: str) -> np.ndarray:
        engine = self._pyttsx3()
        with tempfile.TemporaryDirectory(prefix="assistant-tts-") as folder:
            path = os.path.join(folder, "reply.wav")
            errors: list[BaseException] = []

            def run():
                try:
                    with contextlib.redirect_stdout(io.StringIO()):
                        engine.save_to_file(text, path)
                        engine.runAndWait()
                except BaseException as error:  # reported to the caller below
                    errors.append(error)

            worker = threading.Thread(target=run, name="pyttsx3", daemon=True)
            worker.start()
            worker.join(SYNTH_TIMEOUT_S)
            if worker.is_alive():
                # the thread cannot be stopped; pyttsx3 is not used again (its engine, shared by
                # every init, is stuck in that thread) and the program's exit steps round it
                _HUNG.append(worker)
                self._pyttsx3_hung = True
                raise TimeoutError(f"pyttsx3 did not finish within {SYNTH_TIMEOUT_S:.0f} s")
            if errors:
                raise errors[0]
            if not os.path.isfile(path) or os.path.getsize(path) <= 44:
                raise OSError("pyttsx3 wrote no audio")
            samples = audio_from_bytes(Path(path).read_bytes(), "pyttsx3").samples
        if not np.any(samples):
            raise OSError("pyttsx3 wrote only silence")
        return samples

    def _with_espeak(self, text: str) -> np.ndarray:
        try:
            done = subprocess.run(["espeak-ng", "-v", self.voice, "-s", str(self.rate), "--stdout", text],
                                  capture_output=True, timeout=SYNTH_TIMEOUT_S, check=True)
        except (OSError, subprocess.SubprocessError) as error:
            raise SpeechOutputError(f"espeak-ng could not speak ({error}); check `espeak-ng \"hello\"`") from None
        return audio_from_bytes(done.stdout, "espeak-ng").samples

    # ------------------------------------------------------------------ speaking
    def say(self, text: str) -> np.ndarray:
        """Speak ``text``: synthesise, append to the --say-to file, play (unless stopped)."""
        self._stop.clear()
        samples = self.synthesise(text)
        if samples.size == 0:
            return samples
        if self.say_to is not None:
            self._said.append(samples)
            self._write_file()
        if self.play:
            self._play(samples)
        return samples

    def stop(self) -> None:
        """Stop speaking now (barge-in); the --say-to file keeps what was synthesised."""
        self._stop.set()
        if self.play:
            with contextlib.suppress(Exception):
                import sounddevice

                sounddevice.stop()

    def _write_file(self) -> None:
        gap = np.zeros(int(GAP_S * SAMPLE_RATE_HZ), dtype=np.float32)
        parts = []
        for i, s in enumerate(self._said):
            parts.extend([gap, s] if i else [s])
        try:
            write_wav(self.say_to, np.concatenate(parts))
        except OSError as error:
            raise SpeechOutputError(f"--say-to {self.say_to}: cannot write ({error.strerror})") from None

    def _play(self, samples: np.ndarray) -> None:
        sd = require("sounddevice", "pip install sounddevice; apt-get install libportaudio2", SpeechOutputError)
        try:
            self.speaking = True
            sd.play(samples, SAMPLE_RATE_HZ)
            while not self._stop.wait(0.02):
                if not sd.get_stream().active:
                    break
        except Exception as error:  # no output device: the reply is still printed
            self.play = False
            self.speaking = False
            raise SpeechOutputError(f"cannot play sound ({error}); replies are printed (and written with "
                                    "--say-to FILE.wav)") from None
        finally:
            self.speaking = False

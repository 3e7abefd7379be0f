"""The microphone, through PortAudio (``sounddevice``): 16 kHz mono blocks as they arrive.

:class:`Microphone` opens the default input device (or ``device``) and puts every block in a
queue; :meth:`Microphone.utterances` cuts the stream into utterances with the endpointer
(:class:`~assistant.dialogue.speech.vad.UtteranceDetector`) and ``listeners`` see every block
too (barge-in spotting). Every way it can fail — PortAudio not installed, no input device, the
device busy or unplugged — is a :class:`~assistant.dialogue.speech.errors.MicrophoneError`
saying so, and the chat carries on by text.
"""

from __future__ import annotations

import queue
import threading

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ
from assistant.dialogue.speech.errors import MicrophoneError, require

BLOCK_S = 0.03
INSTALL = "apt-get install libportaudio2 && pip install sounddevice"


def input_devices() -> list[dict]:
    """The input devices PortAudio sees (name, channels, default rate)."""
    sd = require("sounddevice", INSTALL, MicrophoneError)
    return [{"index": i, "name": d["name"], "channels": d["max_input_channels"],
             "rate_hz": d["default_samplerate"]}
            for i, d in enumerate(sd.query_devices()) if d["max_input_channels"] > 0]


class Microphone:
    """``device``: a PortAudio device index or name (default: the system's default input)."""

    def __init__(self, device=None):
        self.sd = require("sounddevice", INSTALL, MicrophoneError)
        self.device = device
        self.blocks: queue.Queue = queue.Queue(maxsize=2000)
        self.listeners: list = []
        self._stream = None
        self.overflows = 0

    def __enter__(self) -> "Microphone":
        self.open()
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def open(self) -> None:
        if not input_devices():
            raise MicrophoneError("no microphone found (PortAudio lists no input device); plug one in, or "
                                  "talk by text, or give recordings with --audio-in FILE|DIR")
        try:
            self._stream = self.sd.InputStream(samplerate=SAMPLE_RATE_HZ, channels=1, dtype="float32",
                                               blocksize=int(BLOCK_S * SAMPLE_RATE_HZ), device=self.device,
                                               callback=self._callback)
            self._stream.start()
        except Exception as error:  # PortAudioError: busy, unplugged, rate not supported
            self._stream = None
            raise MicrophoneError(f"cannot open the microphone ({error}); close other programs using it, or "
                                  "talk by text") from None

    def close(self) -> None:
        if self._stream is not None:
            try:
                self._stream.stop()
                self._stream.close()
            finally:
                self._stream = None

    def _callback(self, data, frames, time_info, status) -> None:
        if status:
            self.overflows += 1
        block = np.array(data[:, 0], dtype=np.float32)
        for listener in list(self.listeners):
            listener(block)
        try:
            self.blocks.put_nowait(block)
        except queue.Full:
            self.overflows += 1

    def utterances(self, stop: threading.Event | None = None, detector=None):
        """Yield each utterance (:class:`~assistant.dialogue.speech.vad.Utterance`) as it ends."""
        from assistant.dialogue.speech.vad import UtteranceDetector

        detector = detector or UtteranceDetector()
        stop = stop or threading.Event()
        while not stop.is_set():
            try:
                block = self.blocks.get(timeout=0.1)
            except queue.Empty:
                if self._stream is None:
                    return
                continue
            yield from detector.feed(block)

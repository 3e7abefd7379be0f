"""Barge-in: spotting "stop" in the audio while the robot drives or talks.

:class:`KeywordSpotter` runs pocketsphinx's keyphrase search over audio as it arrives (blocks
of any length) and reports the keyword as soon as the decoder's best path holds it — typically
within a few frames of the word's end, without waiting for the speaker to fall silent.
``threshold`` trades false alarms for misses (pocketsphinx's ``kws_threshold``; lower is more
eager). After a detection the search restarts, so one "stop" is reported once.

The keyphrase search alone fires inside ordinary sentences ("… the desk top …", "… to the
stove …"): on 125 utterances that are not "stop" (our speech test set's commands, questions and
chat turns, and the robot's own sentences) it fired 55 times at the threshold used, against 67
of 72 "stop"s heard (six phrasings, four voices, two rates, clean and 10 dB). A stop request is
said on its own or at the end of a short phrase ("stop", "okay stop now"), so a detection counts
only when the stretch of speech it ends began at most ``max_run_s`` before (pocketsphinx's voice
activity detector, pauses under ``PAUSE_S`` joined): 18 false alarms in the same 125, the same
67 of 72 heard, no added delay (``benchmarks/bench_barge_in.py``).
"""

from __future__ import annotations

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, to_pcm16
from assistant.dialogue.speech.errors import RecogniserError, require

DEFAULT_THRESHOLD = 1e-20
#: a detection counts when the speech it ends began at most this long before (seconds)
MAX_RUN_S = 1.6
#: pauses shorter than this (seconds) do not end a stretch of speech
PAUSE_S = 0.2


class KeywordSpotter:
    """``keyword``: a word (or phrase) of the dictionary; ``threshold``: see the module doc."""

    def __init__(self, keyword: str = "stop", threshold: float = DEFAULT_THRESHOLD, dictionary=None,
                 max_run_s: float | None = MAX_RUN_S):
        ps = require("pocketsphinx", "pip install pocketsphinx", RecogniserError)
        from assistant.dialogue.speech.language_model import default_dictionary

        self.keyword = keyword
        try:
            self._decoder = ps.Decoder(keyphrase=keyword, kws_threshold=threshold, lm=None, dither=True, seed=1,
                                       dict=str(dictionary or default_dictionary()), loglevel="FATAL")
        except (RuntimeError, ValueError) as error:
            raise RecogniserError(f"cannot spot {keyword!r} ({error}); is every word in the dictionary?") from None
        self._started = False
        self.heard_s = 0.0  # audio fed so far (seconds)
        self.max_run_s = max_run_s  # None: every detection counts
        self.ignored = 0  # detections inside longer speech, not reported
        self._vad = ps.Vad(0)
        self._pending = b""  # PCM not yet judged by the voice activity detector (under a frame)
        self._vad_s = 0.0  # audio the voice activity detector has judged (seconds)
        self._run_start_s: float | None = None
        self._speech_end_s = -1.0

    def reset(self) -> None:
        """Forget the audio so far (the robot went idle, or the keyword was just reported)."""
        if self._started:
            self._decoder.end_utt()
            self._started = False
        self._pending = b""
        self._run_start_s = None

    def feed(self, samples: np.ndarray) -> bool:
        """Take more audio (16 kHz mono); True when the keyword was just heard."""
        if not self._started:
            self._decoder.start_utt()
            self._started = True
        self.heard_s += len(samples) / float(SAMPLE_RATE_HZ)
        pcm = to_pcm16(samples)
        if self.max_run_s is not None:
            self._track_speech(pcm)
        self._decoder.process_raw(pcm)
        if self._decoder.hyp() is None:
            return False
        run_s = self.speech_run_s()
        self.reset()
        if self.max_run_s is not None and run_s > self.max_run_s:
            self.ignored += 1
            return False
        return True

    def speech_run_s(self) -> float:
        """Seconds since the latest stretch of speech began (pauses under :data:`PAUSE_S` do not
        end one); 0 before any speech."""
        if self._run_start_s is None:
            return 0.0
        return self._vad_s - self._run_start_s

    def _track_speech(self, pcm: bytes) -> None:
        audio = self._pending + pcm
        size = self._vad.frame_bytes
        whole = len(audio) - len(audio) % size
        step = size / 2.0 / SAMPLE_RATE_HZ
        for start in range(0, whole, size):
            if self._vad.is_speech(audio[start:start + size]):
                if self._run_start_s is None or self._vad_s - self._speech_end_s > PAUSE_S:
                    self._run_start_s = self._vad_s
                self._speech_end_s = self._vad_s + step
            self._vad_s += step
        self._pending = audio[whole:]

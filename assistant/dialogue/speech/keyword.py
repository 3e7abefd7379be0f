"""Barge-in: spotting "stop" in the audio while the robot drives or talks.

:class:`KeywordSpotter` runs pocketsphinx's keyphrase search over audio as it arrives (blocks
of any length) and reports the keyword as soon as the decoder's best path holds it — typically
within a few frames of the word's end, without waiting for the speaker to fall silent.
``threshold`` trades false alarms for misses (pocketsphinx's ``kws_threshold``; lower is more
eager). After a detection the search restarts, so one "stop" is reported once.
"""

from __future__ import annotations

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, to_pcm16
from assistant.dialogue.speech.errors import RecogniserError, require

DEFAULT_THRESHOLD = 1e-20


class KeywordSpotter:
    """``keyword``: a word (or phrase) of the dictionary; ``threshold``: see the module doc."""

    def __init__(self, keyword: str = "stop", threshold: float = DEFAULT_THRESHOLD, dictionary=None):
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

    def reset(self) -> None:
        if self._started:
            self._decoder.end_utt()
            self._started = False

    def feed(self, samples: np.ndarray) -> bool:
        """Take more audio (16 kHz mono); True when the keyword was just heard."""
        if not self._started:
            self._decoder.start_utt()
            self._started = True
        self.heard_s += len(samples) / float(SAMPLE_RATE_HZ)
        self._decoder.process_raw(to_pcm16(samples))
        if self._decoder.hyp() is not None:
            self.reset()
            return True
        return False

"""Voice activity and the end of an utterance (pocketsphinx's WebRTC-style VAD endpointer).

:class:`UtteranceDetector` takes audio as it arrives (a microphone block, a file read in
pieces) and hands back each utterance once its speaker has stopped: speech has ended when
``ratio`` of the last ``window_s`` seconds is non-speech. The utterance is returned with
``pad_s`` of the audio around it, because the acoustic model decodes better with some silence
before and after the words. :func:`speech_spans` does the same over a whole recording.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, from_pcm16, to_pcm16


@dataclass(frozen=True)
class Utterance:
    """One stretch of speech: samples (with padding), and where it lies in the stream (s)."""

    samples: np.ndarray
    start_s: float
    end_s: float

    @property
    def seconds(self) -> float:
        return self.end_s - self.start_s


class UtteranceDetector:
    """Streaming end-of-utterance detection over 16 kHz mono audio.

    ``window_s``/``ratio``: the endpointer's decision window and the share of it that must be
    (non-)speech to switch; ``vad_mode``: 0 (loose) … 3 (strict); ``pad_s``: audio kept before
    and after the speech; ``min_speech_s``: shorter bursts (a click, a cough) are ignored;
    ``on_samples(samples, starting)``: called with the utterance's audio as soon as it is known to
    be speech (``starting`` True for the first piece of a new utterance), so a recogniser can
    decode while the person is still talking.
    """

    def __init__(self, window_s: float = 0.3, ratio: float = 0.9, vad_mode: int = 0, pad_s: float = 0.3,
                 min_speech_s: float = 0.15, on_samples=None):
        from pocketsphinx import Endpointer

        self._ep = Endpointer(window=window_s, ratio=ratio, vad_mode=vad_mode, sample_rate=SAMPLE_RATE_HZ)
        self.window_s = window_s
        self.pad_s = pad_s
        self.min_speech_s = min_speech_s
        self.frame_samples = self._ep.frame_bytes // 2
        self._pending = np.zeros(0, dtype=np.float32)
        # the endpointer hands speech back ``window_s`` late: keep enough input to find the pad
        self._pad_frames = int(round(pad_s / self._ep.frame_length))
        self._history: deque = deque(maxlen=self._pad_frames + int(window_s / self._ep.frame_length) + 4)
        self._index = 0
        self._speech: list[np.ndarray] = []
        self._start_s = 0.0
        self._end_s = 0.0
        self.on_samples = on_samples

    @property
    def in_speech(self) -> bool:
        return bool(self._ep.in_speech)

    def feed(self, samples: np.ndarray) -> list[Utterance]:
        """Take more audio; the utterances that ended in it (usually none or one)."""
        buf = np.concatenate([self._pending, np.asarray(samples, dtype=np.float32)])
        n = self.frame_samples
        done: list[Utterance] = []
        whole = len(buf) // n
        for i in range(whole):
            done.extend(self._frame(buf[i * n:(i + 1) * n]))
        self._pending = buf[whole * n:]
        return done

    def flush(self) -> list[Utterance]:
        """End of the stream: the utterance still open, if any."""
        done: list[Utterance] = []
        if self._ep.in_speech:
            # (pocketsphinx reads past an empty last frame: IndexError on 3 s of loud noise)
            last = self._pending if len(self._pending) else np.zeros(1, dtype=np.float32)
            rest = self._ep.end_stream(to_pcm16(last))
            if rest:
                self._speech.append(from_pcm16(rest))
            self._end_s = self._ep.speech_end
            done.extend(self._close())
        self._pending = np.zeros(0, dtype=np.float32)
        return done

    # ------------------------------------------------------------------ internals
    def _frame(self, frame: np.ndarray) -> list[Utterance]:
        was = self._ep.in_speech
        speech = self._ep.process(to_pcm16(frame))
        self._history.append((self._index, frame))
        self._index += 1
        out: list[Utterance] = []
        if speech is not None:
            if not was:  # speech began: keep the pad of audio before it
                self._start_s = self._ep.speech_start
                first = int(round(self._start_s / self._ep.frame_length))
                self._speech = [f for i, f in self._history if first - self._pad_frames <= i < first]
                self._tell(np.concatenate(self._speech) if self._speech else np.zeros(0, np.float32), True)
            piece = from_pcm16(speech)
            self._speech.append(piece)
            self._tell(piece, False)
        if was and not self._ep.in_speech:  # the last speech frame comes with in_speech off
            self._end_s = self._ep.speech_end
            out.extend(self._close())
        return out

    def _tell(self, samples: np.ndarray, starting: bool) -> None:
        if self.on_samples is not None:
            self.on_samples(samples, starting)

    def _close(self) -> list[Utterance]:
        """The utterance, with the pad after it taken from the audio already heard (the
        endpointer decides ``window_s`` after the speech's end: no further wait)."""
        speech, self._speech = self._speech, []
        if self._end_s - self._start_s < self.min_speech_s:
            return []
        last = int(round(self._end_s / self._ep.frame_length))
        trail = [f for i, f in self._history if last <= i < last + self._pad_frames]
        if trail:
            pad = np.concatenate(trail)
            speech.append(pad)
            self._tell(pad, False)
        samples = np.concatenate(speech) if speech else np.zeros(0, dtype=np.float32)
        return [Utterance(samples, self._start_s, self._end_s)]


def speech_spans(samples: np.ndarray, **options) -> list[Utterance]:
    """Every utterance in a recording (16 kHz mono)."""
    detector = UtteranceDetector(**options)
    return detector.feed(samples) + detector.flush()


def has_speech(samples: np.ndarray, **options) -> bool:
    return bool(speech_spans(samples, **options))

"""Vocal tract length normalisation (VTLN) for pocketsphinx, with the warp estimated from pitch.

pocketsphinx's en-US acoustic model was trained on mostly men's voices. A shorter vocal tract
(most women, children) puts every formant higher, and the model hears other words ("living room"
→ "meeting room"). VTLN scales the frequency axis of the front end's mel filters back
(pocketsphinx's ``warp_type inverse_linear``: a frequency f is read as f / warp).

The classic per-speaker warp is the one whose features the acoustic model scores best; that needs
a decoding or an alignment per candidate warp, and on single utterances the first pass's words bias
it (docs/speech.md). Here the warp is estimated instead from the voice's pitch, which follows
vocal tract length across men, women and children: ``warp = (f0 / REFERENCE_F0_HZ) **
PITCH_EXPONENT``, clipped to [1, :data:`MAX_WARP`] and rounded to :data:`WARP_STEP`. The constants
come from published averages, not from our test set: men ~132 Hz and women ~223 Hz mean pitch,
women's formants ~1.17 times men's (Peterson and Barney, 1952), so ``1.17 = (223 / 132) ** k``
gives k ≈ 0.3. Voices at or below men's average pitch are not warped (warping them below 1 made
every male voice worse in development: the model already fits them).

:func:`pitch_hz` is the median pitch of the voiced frames (normalised autocorrelation, 60–400 Hz);
:class:`SpeakerPitch` keeps it over a conversation (the speaker stays the same), so a stream, which
is decoded while the person talks, uses the pitch of the utterances heard before.
"""

from __future__ import annotations

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ

#: men's average pitch (Hz): voices at or below it are not warped
REFERENCE_F0_HZ = 132.0
#: warp = (f0 / reference) ** exponent: women's average pitch (223 Hz) gives their average
#: formant ratio to men's (1.17)
PITCH_EXPONENT = 0.3
MAX_WARP = 1.3
WARP_STEP = 0.05
#: a pitch needs at least this many voiced 40 ms frames (hop 20 ms)
MIN_VOICED_FRAMES = 10
FRAME_S, HOP_S = 0.04, 0.02
LOW_HZ, HIGH_HZ = 60.0, 400.0
#: a frame is voiced when its normalised autocorrelation peak reaches this
VOICED_PEAK = 0.5
#: a shorter period whose peak reaches this share of the highest is the period (not a multiple)
OCTAVE_NEAR = 0.9
#: frames further than this under the loudest are left out (pauses, the noise between words)
SPEECH_WITHIN_DB = 25.0


def voiced_pitches(samples: np.ndarray, rate_hz: int = SAMPLE_RATE_HZ) -> np.ndarray:
    """The pitch (Hz) of every voiced frame of ``samples``' speech."""
    x = np.asarray(samples, dtype=np.float64)
    n, hop = int(FRAME_S * rate_hz), int(HOP_S * rate_hz)
    if len(x) < n:
        return np.zeros(0)
    frames = np.lib.stride_tricks.sliding_window_view(x, n)[::hop]
    frames = frames - frames.mean(axis=1, keepdims=True)
    energy = (frames ** 2).mean(axis=1)
    if energy.max() <= 0:
        return np.zeros(0)
    window = np.hanning(n)
    frames = frames[energy >= energy.max() * 10 ** (-SPEECH_WITHIN_DB / 10.0)] * window
    corr = np.fft.irfft(np.abs(np.fft.rfft(frames, 2 * n)) ** 2)[:, :n]
    bias = np.fft.irfft(np.abs(np.fft.rfft(window, 2 * n)) ** 2)[:n]  # the window's own decay
    corr = corr / np.maximum(corr[:, :1], 1e-12) / np.maximum(bias / bias[0], 1e-3)
    low, high = int(rate_hz / HIGH_HZ), int(rate_hz / LOW_HZ)
    corr = corr[:, low:high]
    # the shortest period whose peak is near the best one: multiples of the period peak as high
    near = corr >= OCTAVE_NEAR * corr.max(axis=1, keepdims=True)
    first = np.argmax(near, axis=1)
    lag = np.array([f + int(np.argmax(row[f:f + f // 4 + 3])) for f, row in zip(first, corr)], dtype=int)
    peak = corr[np.arange(len(corr)), lag]
    return rate_hz / (low + lag[peak >= VOICED_PEAK])


def pitch_hz(samples: np.ndarray, rate_hz: int = SAMPLE_RATE_HZ) -> float | None:
    """Median pitch of the voiced speech, or None when too little of it is voiced."""
    pitches = voiced_pitches(samples, rate_hz)
    return float(np.median(pitches)) if len(pitches) >= MIN_VOICED_FRAMES else None


def warp_for_pitch(f0_hz: float | None) -> float:
    """The frequency warp for a voice of pitch ``f0_hz`` (None: unknown, no warp)."""
    if f0_hz is None or f0_hz <= REFERENCE_F0_HZ:
        return 1.0
    warp = min(MAX_WARP, (f0_hz / REFERENCE_F0_HZ) ** PITCH_EXPONENT)
    return round(round(warp / WARP_STEP) * WARP_STEP, 2)


class SpeakerPitch:
    """The pitch of one speaker over a conversation: the median of every voiced frame heard.

    :meth:`add` measures an utterance now; :meth:`add_later` keeps it to be measured when the pitch
    is next asked for (after a streamed utterance, off the path from its end to the reply)."""

    def __init__(self, keep_frames: int = 3000):
        self.keep_frames = keep_frames  # about a minute of voiced speech
        self._pitches = np.zeros(0)
        self._later: list[np.ndarray] = []

    def add(self, samples: np.ndarray) -> float | None:
        """Add an utterance; its own median pitch (None when too little of it is voiced)."""
        pitches = voiced_pitches(samples)
        self._pitches = np.concatenate([self._pitches, pitches])[-self.keep_frames:]
        return float(np.median(pitches)) if len(pitches) >= MIN_VOICED_FRAMES else None

    def add_later(self, samples: np.ndarray) -> None:
        self._later.append(np.asarray(samples, dtype=np.float32))

    def reset(self) -> None:
        self._pitches, self._later = np.zeros(0), []

    @property
    def hz(self) -> float | None:
        """The speaker's median pitch so far (None: too little voiced speech heard)."""
        while self._later:
            self.add(self._later.pop(0))
        return float(np.median(self._pitches)) if len(self._pitches) >= MIN_VOICED_FRAMES else None

"""One utterance from a file or a stream to words: the checks, the endpoints, the decoding.

:class:`Listener` owns a recogniser. :meth:`Listener.hear_file` reads a recording (any rate,
mono or stereo), finds where the speech is (no speech at all is an
:class:`~assistant.dialogue.speech.errors.AudioFileError`, not an empty transcript), decodes
it and reports when the speech ended, so a caller can time "end of speech → reply".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, read_audio
from assistant.dialogue.speech.errors import AudioFileError
from assistant.dialogue.speech.recogniser import Recognition, make_recogniser
from assistant.dialogue.speech.vad import speech_spans

#: utterances below this confidence are confirmed ("Did you say …?") instead of acted on
DEFAULT_CONFIRM_BELOW = 0.45
#: silence added before and after a recording before decoding (seconds)
PAD_S = 0.4


@dataclass
class Heard:
    """A recognition with where its speech lay in the recording (seconds) and the file."""

    recognition: Recognition
    speech_start_s: float
    speech_end_s: float
    source: str = ""
    source_rate_hz: int = SAMPLE_RATE_HZ
    source_channels: int = 1

    @property
    def transcript(self) -> str:
        return self.recognition.transcript

    @property
    def confidence(self) -> float:
        return self.recognition.confidence

    def to_dict(self) -> dict:
        return {"transcript": self.transcript, "confidence": round(self.confidence, 3),
                "timing": {"audio_s": round(self.recognition.audio_s, 3),
                           "speech_start_s": round(self.speech_start_s, 3),
                           "speech_end_s": round(self.speech_end_s, 3),
                           "decode_s": round(self.recognition.decode_s, 4),
                           "real_time_factor": round(self.recognition.real_time_factor, 3)},
                "engine": self.recognition.engine, "search": self.recognition.search, "warp": self.recognition.warp,
                "words": self.recognition.to_dict()["words"],
                "audio": {"file": self.source, "rate_hz": self.source_rate_hz, "channels": self.source_channels}}


class Listener:
    """``engine``/``options``: which recogniser (see :func:`make_recogniser`)."""

    def __init__(self, engine: str = "pocketsphinx", recogniser=None, **options):
        self.recogniser = recogniser or make_recogniser(engine, **options)

    def hear(self, samples: np.ndarray, source: str = "<audio>") -> Heard:
        """Decode 16 kHz mono samples holding (at least) one utterance."""
        spans = speech_spans(samples, pad_s=0.0)
        if not spans:
            level = float(np.sqrt(np.mean(np.square(samples)))) if len(samples) else 0.0
            raise AudioFileError(f"{source}: no speech heard ({len(samples) / SAMPLE_RATE_HZ:.1f} s of silence or "
                                 f"noise, level {20 * np.log10(level + 1e-9):.0f} dBFS); speak closer to the "
                                 "microphone or check the recording")
        start, end = spans[0].start_s, spans[-1].end_s
        # the acoustic model needs silence round the words; a file cut tight at the speech
        # (or synthesised) has none, so some is added
        pad = np.zeros(int(PAD_S * SAMPLE_RATE_HZ), dtype=np.float32)
        return Heard(self.recogniser.recognise(np.concatenate([pad, samples, pad])), start, end, source)

    def hear_file(self, path) -> Heard:
        audio = read_audio(path)
        heard = self.hear(audio.samples, str(path))
        heard.source_rate_hz = audio.source_rate_hz
        heard.source_channels = audio.source_channels
        return heard


class Confirmer:
    """"Did you say …?" for unsure recognitions.

    :meth:`check` takes each recognised utterance and returns ``(text_for_the_dialogue,
    question)``: the text to act on (or None) and a question to ask instead (or None). After
    a question, "yes" acts on the remembered words, "no" asks to say it again, and anything
    else is a new utterance. ``tip``: said once, with the second "no" of a conversation (the
    robot keeps mishearing this person: enrolment would help).
    """

    YES = frozenset({"yes", "yeah", "yep", "correct", "right", "sure", "yes please", "that's right", "okay", "ok"})
    NO = frozenset({"no", "nope", "no thanks", "wrong", "no that's wrong"})

    def __init__(self, below: float = DEFAULT_CONFIRM_BELOW, tip: str | None = None):
        self.below = below
        self.pending: str | None = None
        self.tip = tip
        self.misheard = 0  # "no" answers to "Did you say …?" in this conversation

    def check(self, transcript: str, confidence: float) -> tuple[str | None, str | None]:
        words = " ".join(transcript.split())
        if self.pending is not None:
            pending, self.pending = self.pending, None
            if words in self.YES:
                return pending, None
            if words in self.NO:
                self.misheard += 1
                tip = f" {self.tip}" if self.tip and self.misheard == 2 else ""
                return None, "Sorry — please say it again." + tip
        if not words:
            return None, "Sorry, I didn't catch that. Please say it again."
        if confidence < self.below and words not in self.YES | self.NO:
            self.pending = words
            return None, f"Did you say \u201c{words}\u201d?"
        return words, None

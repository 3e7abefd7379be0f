"""The one recogniser interface, its result, and the engines picked by name.

An engine turns one utterance (16 kHz mono samples) into a :class:`Recognition`: the words, a
confidence in [0, 1], and how long decoding took. Engines register themselves by name
(``pocketsphinx``, ``vosk``); :func:`make_recogniser` builds one and lists the known names
when asked for another. Engines load their library lazily, so importing this module is cheap.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import asdict, dataclass, field

import numpy as np

from assistant.dialogue.speech.errors import RecogniserError

#: engine name → "module:Class" (imported when the engine is made)
ENGINES = {
    "pocketsphinx": "assistant.dialogue.speech.sphinx:PocketsphinxRecogniser",
    "vosk": "assistant.dialogue.speech.vosk_engine:VoskRecogniser",
}
DEFAULT_ENGINE = "pocketsphinx"


@dataclass
class Recognition:
    """What was heard in one utterance.

    ``transcript``: lower-case words; ``confidence``: 0 … 1 (the engine's word posteriors);
    ``audio_s``: the utterance's length; ``decode_s``: wall-clock decoding time; ``engine``;
    ``search``: which model produced the words (``home``: the home's language model,
    ``open``: the general fallback); ``words``: [(word, start_s, end_s, confidence)];
    ``warp``: the front end's frequency warp for the voice (vocal tract length normalisation,
    pocketsphinx; 1: none).
    """

    transcript: str
    confidence: float
    audio_s: float
    decode_s: float
    engine: str
    search: str = "home"
    words: list = field(default_factory=list)
    warp: float = 1.0

    @property
    def real_time_factor(self) -> float:
        return self.decode_s / self.audio_s if self.audio_s > 0 else 0.0

    def to_dict(self) -> dict:
        out = asdict(self)
        out["confidence"] = round(self.confidence, 3)
        out["audio_s"] = round(self.audio_s, 3)
        out["decode_s"] = round(self.decode_s, 4)
        out["real_time_factor"] = round(self.real_time_factor, 3)
        out["words"] = [[w, round(s, 2), round(e, 2), round(c, 3)] for w, s, e, c in self.words]
        return out


class Recogniser(ABC):
    """Speech → text for one utterance at a time (engines are not thread-safe: one caller)."""

    name = "recogniser"
    sample_rate_hz = 16000

    @abstractmethod
    def recognise(self, samples: np.ndarray) -> Recognition:
        """Decode one utterance (16 kHz mono float samples, silence around it welcome)."""

    def stream(self) -> "RecognitionStream":
        """Decode while audio arrives: ``feed`` pieces, then ``finish()`` for the
        :class:`Recognition` (engines without streaming decode everything at the end)."""
        return RecognitionStream(self)

    def spot(self, samples: np.ndarray, keyword: str = "stop") -> bool:
        """Whether ``keyword`` is said in ``samples`` (barge-in); engines may do better."""
        return keyword in self.recognise(samples).transcript.split()

    def use_home(self, world) -> None:
        """The home the words come from (engines may prefer its rooms; None: any home)."""

    def describe(self) -> dict:
        """Engine, model and settings, for ``--json`` outputs and the docs."""
        return {"engine": self.name}

    def close(self) -> None:
        """Wait for background loading to end (before the program exits)."""



def make_recogniser(name: str = DEFAULT_ENGINE, **options) -> Recogniser:
    """The engine called ``name`` (``pocketsphinx`` or ``vosk``) built with ``options``."""
    import importlib

    from assistant.errors import UnknownNameError

    if name not in ENGINES:
        raise UnknownNameError("speech recogniser", name, ENGINES)
    module_name, class_name = ENGINES[name].split(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as error:
        raise RecogniserError(f"the {name} recogniser cannot load ({error})") from None
    return getattr(module, class_name)(**options)


class RecognitionStream:
    """One utterance decoded as it arrives; this base collects the audio and decodes at the end."""

    def __init__(self, recogniser: Recogniser):
        self.recogniser = recogniser
        self.pieces: list[np.ndarray] = []

    def feed(self, samples: np.ndarray) -> None:
        self.pieces.append(np.asarray(samples, dtype=np.float32))

    @property
    def samples(self) -> np.ndarray:
        return np.concatenate(self.pieces) if self.pieces else np.zeros(0, dtype=np.float32)

    def finish(self) -> Recognition:
        return self.recogniser.recognise(self.samples)

"""The vosk recogniser (Kaldi), for people who have a vosk model: ``--asr vosk --asr-model DIR``.

No vosk model ships in a package, so this engine never downloads one: it takes a model folder
(one of the models from the vosk project, unpacked) and checks its layout before loading it.
The home's phrase list (:mod:`~assistant.dialogue.speech.language_model`) plus ``[unk]`` is
passed as the recogniser's grammar, which the small vosk models (those with a ``graph/Gr.fst``)
use to prefer the home's words; the big models ignore it and decode with their own model.
The confidence is the mean of the words' ``conf`` values. ``$ASSISTANT_VOSK_MODEL`` is the
default model folder.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.audio import to_pcm16
from assistant.dialogue.speech.errors import RecogniserError, require
from assistant.dialogue.speech.recogniser import Recognition, Recogniser

ENV_MODEL = "ASSISTANT_VOSK_MODEL"


def check_model_dir(path) -> Path:
    """The model folder, or :class:`RecogniserError` saying what is wrong with it."""
    if path is None:
        path = os.environ.get(ENV_MODEL)
    if not path:
        raise RecogniserError(f"--asr vosk needs a model: give --asr-model DIR (or set {ENV_MODEL}); "
                              "see docs/speech.md for where to get one")
    folder = Path(path).expanduser()
    if not folder.is_dir():
        raise RecogniserError(f"--asr-model {folder}: no such folder; unpack a vosk model there")
    has_am = (folder / "am" / "final.mdl").is_file() or (folder / "final.mdl").is_file()
    has_conf = (folder / "conf" / "mfcc.conf").is_file() or (folder / "mfcc.conf").is_file()
    if not (has_am and has_conf):
        missing = [n for n, ok in (("am/final.mdl", has_am), ("conf/mfcc.conf", has_conf)) if not ok]
        raise RecogniserError(f"--asr-model {folder}: not a vosk model (missing {', '.join(missing)}); "
                              "give the folder that holds am/ and conf/")
    return folder


class VoskRecogniser(Recogniser):
    """``asr_model``: the model folder; ``phrases``: the grammar (default: the home's phrase
    list); ``world``: add that world's words to it."""

    name = "vosk"

    def __init__(self, asr_model=None, phrases=None, world=None, open_fallback=None, speaker=None):
        if speaker is not None:
            raise RecogniserError("--speaker is a voice enrolled for pocketsphinx (assistant enrol); "
                                  "vosk has no enrolment: leave --speaker out with --asr vosk")
        folder = check_model_dir(asr_model)
        vosk = require("vosk", "pip install vosk", RecogniserError)
        vosk.SetLogLevel(-1)
        try:
            self._model = vosk.Model(str(folder))
        except Exception as error:  # vosk raises a bare Exception for a model it cannot read
            raise RecogniserError(f"--asr-model {folder}: vosk cannot load this model ({error}); "
                                  "unpack it again") from None
        if phrases is None:
            from assistant.dialogue.speech.language_model import build_home_model

            phrases = json.loads(build_home_model(world=world).phrases.read_text(encoding="utf-8"))
        self.folder = folder
        self.phrases = list(phrases)
        self._vosk = vosk

    def describe(self) -> dict:
        return {"engine": self.name, "model": str(self.folder), "phrases": len(self.phrases)}

    def _recogniser(self):
        grammar = json.dumps([*self.phrases, "[unk]"])
        rec = self._vosk.KaldiRecognizer(self._model, float(self.sample_rate_hz), grammar)
        rec.SetWords(True)
        return rec

    def recognise(self, samples: np.ndarray) -> Recognition:
        samples = np.asarray(samples, dtype=np.float32)
        start = time.perf_counter()
        rec = self._recogniser()
        pcm = to_pcm16(samples)
        step = 8000
        for i in range(0, len(pcm), step):
            rec.AcceptWaveform(pcm[i:i + step])
        result = json.loads(rec.FinalResult())
        words = [(w["word"], float(w["start"]), float(w["end"]), float(w.get("conf", 1.0)))
                 for w in result.get("result", []) if w["word"] != "[unk]"]
        transcript = " ".join(w for w, *_ in words) or result.get("text", "").replace("[unk]", "").strip()
        confidence = float(np.mean([c for *_, c in words])) if words else 0.0
        return Recognition(transcript, confidence, len(samples) / float(self.sample_rate_hz),
                           time.perf_counter() - start, self.name, "grammar", words)

"""The pocketsphinx recogniser (the default engine: its wheel ships an en-US model).

Two searches over the same acoustic model:

* **home** — the home's trigram language model and its small dictionary
  (:mod:`~assistant.dialogue.speech.language_model`), tried first;
* **open** — pocketsphinx's general US English model (72 000 words), loaded in the background
  and tried when the home search is unsure (confidence below ``open_below``): "where is my
  wallet" must come through even when the home model does not hold the words. The open result
  is kept when it is more confident.

Dither is on (synthetic and digitally silent audio otherwise upsets the feature extraction),
with a fixed seed so the same audio always gives the same words. More than dither, the
acoustic model needs a recording's noise floor: audio cleaner than any room (synthesised
speech, a close microphone in a quiet room) is decoded with white noise added ``floor_db``
(30 dB) under the speech's power — on the clean synthetic test set this cut the word error
about fourfold (docs/speech.md); in real rooms the noise is already louder and it changes nothing. The confidence of an
utterance is the mean posterior probability of its words (pocketsphinx's lattice posteriors).

The recogniser knows the home it serves (``world``, or :meth:`use_home`): when the home search's
best words name a room of another home ("meeting room" in a flat without one), the next
hypotheses of its n-best list whose score is within ``home_margin`` are tried, and the first
naming only rooms the home has, and differing from the best words in at most ``ROOM_EDITS`` words,
is taken. Words outside every home (open vocabulary) are never
penalised: only room names known from some home count.

The front end is fitted to the voice (``vtln``, :mod:`~assistant.dialogue.speech.vtln`): a voice
pitched above men's average (most women, children) is decoded with its frequency axis warped
back towards the male-dominated acoustic model's. A whole utterance is warped by its own pitch; a
stream, decoded while the person talks, by the pitch of its first second (:class:`SphinxStream`),
or of the conversation's earlier utterances when that holds too little voice
(:attr:`PocketsphinxRecogniser.speaker`).
"""

from __future__ import annotations

import threading
import time
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.audio import DEFAULT_FLOOR_DB, active_power, frame_energies, to_pcm16, with_noise_floor
from assistant.dialogue.speech.errors import RecogniserError, require
from assistant.dialogue.speech.recogniser import Recognition, RecognitionStream, Recogniser
from assistant.dialogue.speech.vtln import SpeakerPitch, pitch_hz, warp_for_pitch

#: decoder settings: pocketsphinx's language weights, wider beams than its defaults (fewer word
#: errors in development, docs/speech.md), dither with a fixed seed, and each frame scored on the
#: best 8 Gaussians of each codebook of the phonetically tied model rather than pocketsphinx's 4 (a
#: speed default: 8 took word error 4.4 → 3.7 % on the clean commands and questions and the
#: real-time factor 0.07 → 0.09; 12, 16 and 32 were no better)
DECODER_SETTINGS = {"dither": True, "seed": 1, "beam": 1e-60, "wbeam": 1e-40, "pbeam": 1e-60, "topn": 8,
                    "loglevel": "FATAL"}
#: the open search's settings over DECODER_SETTINGS: pocketsphinx's default beams and a cap on the
#: HMMs and words searched per frame — with the home search's wide beams its 72 000-word model
#: decoded slower than real time (4–5 s of CPU for a 3.8 s utterance), so an utterance that fell
#: to it was answered seconds late (``benchmarks/bench_open_search.py``); pocketsphinx's 4 Gaussians
OPEN_SEARCH = {"beam": 1e-48, "wbeam": 7e-29, "pbeam": 1e-48, "maxhmmpf": 3000, "maxwpf": 20, "topn": 4}
FILLERS = frozenset({"<s>", "</s>", "<sil>", "<unk>"})
FRAME_S = 0.01
#: how many n-best hypotheses are looked at, and how far under the first one's score one may
#: score (a share of it: the scores are per-frame probabilities, ~0.3-0.5 here) and still replace
#: the best words for naming the home's room rather than another home's
NBEST = 20
DEFAULT_HOME_MARGIN = 0.05
#: at most this many words may differ from the best words (the room's name: "meeting" → "living"),
#: so that a hypothesis rewriting the rest of the sentence is not taken for its room
ROOM_EDITS = 2
#: a stream holds this much audio (s) before choosing its warp from the voice's pitch
VTLN_HOLD_S = 1.0


class PocketsphinxRecogniser(Recogniser):
    """``model``: a :class:`~assistant.dialogue.speech.language_model.HomeModel` (default: built
    from the corpus and the homes, cached); ``world``: add that world's words and prefer its rooms
    (:meth:`use_home`); ``home_margin``: how far (a share of the first n-best score) under it a
    hypothesis naming the home's room may score and still win; ``open_fallback``:
    use the general model when unsure; ``open_below``: the confidence under which it is tried;
    ``speaker``: an enrolled speaker's name (or adapted model folder): decode with the acoustic
    model adapted to that voice (:mod:`~assistant.dialogue.speech.enrol`);
    ``open_margin``: how much more confident its words must be to be taken; ``floor_db``: the
    noise floor added before decoding (dB under the speech, None: none); ``vtln``: warp the front
    end to the voice's pitch (:mod:`~assistant.dialogue.speech.vtln`).
    """

    name = "pocketsphinx"

    def __init__(self, model=None, world=None, open_fallback: bool = True, open_below: float = 0.3,
                 open_margin: float = 0.3, settings: dict | None = None, asr_model=None,
                 floor_db: float | None = DEFAULT_FLOOR_DB, home_margin: float = DEFAULT_HOME_MARGIN,
                 vtln: bool = True, speaker: str | None = None):
        if asr_model is not None:
            raise RecogniserError("pocketsphinx uses its packaged en-US model; --asr-model is for --asr vosk")
        ps = require("pocketsphinx", "pip install pocketsphinx", RecogniserError)
        from assistant.dialogue.speech.language_model import build_home_model

        self.model = model or build_home_model(world=world)
        self.settings = {**DECODER_SETTINGS, **(settings or {})}
        self.speaker_name = speaker
        if speaker is not None:  # the acoustic model adapted to this person (assistant enrol)
            from assistant.dialogue.speech.enrol import enrolled_model

            folder = Path(speaker) if (Path(speaker) / "means").is_file() else enrolled_model(speaker)
            self.settings["hmm"] = str(folder)
        try:
            self._home = ps.Decoder(lm=str(self.model.lm), dict=str(self.model.dictionary), **self.settings)
        except (RuntimeError, ValueError) as error:
            raise RecogniserError(f"pocketsphinx cannot load the home model {self.model.lm} ({error}); "
                                  "delete it to rebuild it") from None
        self._home_front = WarpedFrontEnd(self._home)
        self.floor_db = floor_db
        self.home_margin = home_margin
        self.vtln = vtln
        self.speaker = SpeakerPitch()  # the voice heard so far in this conversation
        self._known_rooms: frozenset[str] | None = None  # of every home: read when a home is first given
        self._rooms: frozenset[str] = frozenset()  # the home's rooms
        self._foreign: tuple[str, ...] = ()  # rooms of other homes (not of this one)
        self.use_home(world)
        self.open_fallback = open_fallback
        self.open_below = open_below
        self.open_margin = open_margin
        self._open = None
        self._open_front = None
        self._open_lock = threading.Lock()
        self._open_error: str | None = None
        self._loader = None
        if open_fallback:
            self._loader = threading.Thread(target=self._load_open, name="pocketsphinx-open-model", daemon=True)
            self._loader.start()

    def close(self) -> None:
        # a daemon thread still inside the decoder's C++ code when Python exits aborts the program
        if self._loader is not None:
            self._loader.join()

    def use_home(self, world) -> None:
        """Prefer, among near hypotheses, words naming ``world``'s rooms (None: no preference)."""
        if world is None:
            self._rooms, self._foreign = frozenset(), ()
            return
        if self._known_rooms is None:
            from assistant.dialogue.speech.vocabulary import home_words

            self._known_rooms = frozenset(home_words()["rooms"])
        self._rooms = frozenset(world.floorplan.room_names)
        self._foreign = tuple(sorted(self._known_rooms - self._rooms))

    # ------------------------------------------------------------------ models
    def _load_open(self):
        with self._open_lock:
            if self._open is None and self._open_error is None:
                import pocketsphinx as ps

                try:
                    self._open = ps.Decoder(**{**self.settings, **OPEN_SEARCH})
                    self._open_front = WarpedFrontEnd(self._open)
                except (RuntimeError, ValueError) as error:  # the packaged model is damaged
                    self._open_error = str(error)
            return self._open

    def describe(self) -> dict:
        return {"engine": self.name, "home_lm": str(self.model.lm), "home_words": self.model.words,
                "open_fallback": self.open_fallback, "open_below": self.open_below, "floor_db": self.floor_db,
                "home_margin": self.home_margin, "home_rooms": sorted(self._rooms), "vtln": self.vtln,
                "speaker": self.speaker_name,
                "settings": {k: v for k, v in self.settings.items() if k != "loglevel"}}

    # ------------------------------------------------------------------ decoding
    def recognise(self, samples: np.ndarray) -> Recognition:
        samples = np.asarray(samples, dtype=np.float32)
        start = time.perf_counter()
        warp = 1.0
        if self.vtln:  # the utterance's own pitch; the conversation's when it has too little voice
            f0 = self.speaker.add(samples)
            warp = warp_for_pitch(self.speaker.hz if f0 is None else f0)
        if self.floor_db is not None:
            samples = with_noise_floor(samples, self.floor_db)
        pcm = to_pcm16(samples)
        self._home_front.use(warp, fresh=True)
        _decode(self._home, pcm)
        return self._choose(self._home_words(), pcm, start, warp)

    def speaker_warp(self) -> float:
        """The warp for the voice heard so far in this conversation (1: none, or vtln off)."""
        return warp_for_pitch(self.speaker.hz) if self.vtln else 1.0

    def stream(self) -> "SphinxStream":
        return SphinxStream(self)

    def _home_words(self) -> list[tuple[str, float, float, float]]:
        """The home search's best words, or a near n-best hypothesis naming only the home's rooms
        when the best names a room of another home (its words get the best's mean posterior)."""
        words = _words(self._home)
        heard = [w for w, *_ in words]
        if not self._foreign or not _names_any(" ".join(heard), self._foreign):
            return words
        from rapidfuzz.distance import Levenshtein

        best = None
        for n, hyp in enumerate(self._home.nbest()):
            if n >= NBEST:
                break
            best = hyp.score if best is None else best
            if hyp.score < best - self.home_margin * abs(best):
                continue
            text = " ".join(w.split("(", 1)[0] for w in hyp.hypstr.split() if w not in FILLERS and w[:1] not in "+[")
            if (_names_any(text, self._rooms) and not _names_any(text, self._foreign)
                    and Levenshtein.distance(heard, text.split()) <= ROOM_EDITS):
                confidence = _confidence(words)
                return [(w, 0.0, 0.0, confidence) for w in text.split()]
        return words

    def _choose(self, words, pcm: bytes, start: float, warp: float = 1.0) -> Recognition:
        """The home search's words, or the open search's when the home one is unsure."""
        audio_s = len(pcm) / 2.0 / self.sample_rate_hz
        search = "home"
        if self.open_fallback and _confidence(words) < self.open_below:
            open_decoder = self._load_open()
            if open_decoder is not None:
                self._open_front.use(warp, fresh=True)
                other = _decode(open_decoder, pcm)
                if other and (not words or _confidence(other) > _confidence(words) + self.open_margin):
                    words, search = other, "open"
        transcript = " ".join(w for w, *_ in words)
        return Recognition(transcript, _confidence(words), audio_s, time.perf_counter() - start, self.name,
                           search, words, warp)


class SphinxStream(RecognitionStream):
    """The home search fed while the person talks: at the end only its last passes remain.
    (Cepstral mean normalisation is then live rather than over the whole utterance.)

    With VTLN the warp is the conversation's (the pitch of every utterance heard before: steadier
    than a part of one, whose pitch falls from its start to its end). For the first utterance of a
    conversation the first :data:`VTLN_HOLD_S` of audio are held until the warp is chosen from their
    pitch; the decoder then catches up with them in a few tens of milliseconds, while the person is
    still talking (an utterance shorter than that is decoded whole at its end)."""

    def __init__(self, recogniser: PocketsphinxRecogniser):
        super().__init__(recogniser)
        self.warp: float | None = None  # None: held until VTLN_HOLD_S have been heard
        self.decode_s = 0.0
        if not recogniser.vtln or recogniser.speaker.hz is not None:
            self._start(np.zeros(0, dtype=np.float32))
        self._energies: list[float] = []  # of the 30 ms frames so far: the speech's power
        self._rng = np.random.default_rng(0)

    def feed(self, samples: np.ndarray) -> None:
        samples = np.asarray(samples, dtype=np.float32)
        start = time.perf_counter()
        if self.recogniser.floor_db is not None and len(samples):
            samples = self._with_floor(samples)
        super().feed(samples)
        if self.warp is not None:
            self.recogniser._home.process_raw(to_pcm16(samples))
        elif len(self.samples) >= VTLN_HOLD_S * self.recogniser.sample_rate_hz:
            self._start(self.samples)
        self.decode_s += time.perf_counter() - start

    def _start(self, held: np.ndarray) -> None:
        """Choose the warp (the conversation's, else ``held``'s pitch), start, decode ``held``."""
        rec = self.recogniser
        f0 = rec.speaker.hz if rec.vtln else None
        if rec.vtln and f0 is None and len(held):
            f0 = pitch_hz(held)
        self.warp = warp_for_pitch(f0) if rec.vtln else 1.0
        rec._home_front.use(self.warp)
        rec._home.start_utt()
        if len(held):
            rec._home.process_raw(to_pcm16(held))

    def _with_floor(self, samples: np.ndarray) -> np.ndarray:
        """The noise floor, from the power of the speech heard so far (as in whole decoding)."""
        self._energies.extend(frame_energies(samples))
        power = active_power(self._energies)
        if power <= 0:
            return samples
        level = np.sqrt(power / 10 ** (self.recogniser.floor_db / 10.0))
        return samples + self._rng.normal(0.0, level, len(samples)).astype(np.float32)

    def finish(self) -> Recognition:
        start = time.perf_counter()
        if self.warp is None:  # shorter than the hold
            self._start(self.samples)
        self.recogniser._home.end_utt()
        result = self.recogniser._choose(self.recogniser._home_words(), to_pcm16(self.samples), start, self.warp)
        if self.recogniser.vtln:
            self.recogniser.speaker.add_later(self.samples)  # measured when the next utterance starts
        result.decode_s += self.decode_s
        return result


def _names_any(text: str, phrases) -> bool:
    """Whether ``text`` holds one of ``phrases`` as whole words."""
    padded = f" {text} "
    return any(f" {p} " in padded for p in phrases)


class WarpedFrontEnd:
    """A decoder's front end at a frequency warp (inverse linear: f is read as f / warp; 1: none).

    pocketsphinx keeps the warp's parameters in process-wide variables, read when a front end is
    built, and skips parsing a parameter string equal to the last one parsed, even when a decoder
    built since without a warp has switched warping off: going back to an earlier warp would then
    silently build an unwarped front end. Each change therefore passes a parameter string unlike
    the previous one (the same number, spelt with or without a trailing space), and 1 is passed as
    "1", not as no warp. (Decoders built in other threads at the same moment could still race.)

    ``fresh``: rebuild the front end even when the warp is unchanged. Building it seeds the dither's
    random numbers, which are process-wide too: without that, the words heard in an utterance
    depended on what had been decoded before it (and by which decoder). Whole utterances are decoded
    fresh, so the same audio always gives the same words; a stream is not (its live cepstral mean,
    carried from the speaker's earlier utterances, would be reset), and when a stream's warp changes
    that mean is kept: rebuilding would start the utterance from the model's initial mean, and in
    the speech benchmark one such utterance fell to the slow open search (2.9 s)."""

    _spelling = 0  # alternates between the two spellings, across every decoder of the process

    def __init__(self, decoder):
        self.decoder = decoder
        self.warp = 1.0

    def use(self, warp: float, fresh: bool = False) -> None:
        if warp == self.warp and not fresh:
            return
        mean = None if fresh else self.decoder.get_cmn()
        WarpedFrontEnd._spelling ^= 1
        self.decoder.config["warp_type"] = "inverse_linear"
        self.decoder.config["warp_params"] = f"{warp:g}" + " " * WarpedFrontEnd._spelling
        self.decoder.reinit_feat()
        if mean is not None:  # a stream's live cepstral mean is the speaker's: keep it over a new warp
            self.decoder.set_cmn(mean)
        self.warp = warp


def _decode(decoder, pcm: bytes) -> list[tuple[str, float, float, float]]:
    """(word, start s, end s, posterior) of the best hypothesis, fillers left out."""
    decoder.start_utt()
    decoder.process_raw(pcm, full_utt=True)
    decoder.end_utt()
    return _words(decoder)


def _words(decoder) -> list[tuple[str, float, float, float]]:
    if decoder.hyp() is None:
        return []
    out = []
    for seg in decoder.seg():
        word = seg.word.split("(", 1)[0]  # "the(2)": an alternative pronunciation
        if word in FILLERS or word[:1] in "+[":  # fillers: [SPEECH], [NOISE], +BREATH+
            continue
        out.append((word, seg.start_frame * FRAME_S, (seg.end_frame + 1) * FRAME_S,
                    float(min(1.0, max(0.0, seg.prob)))))
    return out


def _confidence(words) -> float:
    return float(np.mean([c for *_, c in words])) if words else 0.0

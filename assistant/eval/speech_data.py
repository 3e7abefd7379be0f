"""The speech test set, made here: our sentences spoken by espeak-ng, with household noise.

Sentences (all from the repository, none in the recogniser's model text):

* ``command`` — the fetch dev set's commands (``corpus/fetch_dev.jsonl``), each (text, home) once: the
  dev set repeats commands in other scenes, seeds and robots (186 lines, 98 commands on 2 Dec);
* ``where`` — "where is my X" questions in five wordings over the homes' objects and a few
  objects the robot does not know ("where is my wallet");
* ``chat`` — the words people say in the dialogue scripts (``corpus/dialogues/*.yaml``), less
  the deliberately garbled ones (words that are not English), as a fixed list
  (``corpus/speech_test_chat.tsv``, 225 sentences taken on 3 Dec 2026): the test set grew with
  every scripted conversation, and the figures of two measurements did not compare.

Each sentence is spoken by one of :data:`VOICES` × :data:`RATES` in rotation (``all_voices``:
by every one), with 0.5 s of room silence before and after, and then mixed with household
noise at each SNR of ``snrs_db``. The noise (:func:`household_noise`) is generated: a
refrigerator-like low rumble (brown noise, low-passed), mains hum (50 Hz and harmonics) and
kitchen clatter (short decaying bursts of band-passed noise), seeded by the utterance, so the
set is the same on every machine. SNR is the ratio of the speech's power over its spoken part
to the noise's power. The audio is cached as WAV under ``<cache>/speech-testset/``.
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, audio_from_bytes, read_audio, speech_power, write_wav
from assistant.dialogue.speech.vocabulary import normalise_transcript

#: espeak-ng voices (US English, as the acoustic model: docs/speech.md for British voices)
VOICES = ("en-us", "en-us+f3", "en-us+m3", "en-us-nyc")
#: speaking rates (words per minute)
RATES = (140, 175)
#: noise levels: None is clean
SNRS_DB = (None, 20.0, 10.0)
SILENCE_S = 0.5
GENERATOR_VERSION = 1

WHERE_WORDINGS = ("where is my {o}", "have you seen my {o}", "where did i leave the {o}",
                  "do you know where my {o} is", "how do i get to my {o}")
UNKNOWN_OBJECTS = ("wallet", "keys", "phone", "remote")


@dataclass(frozen=True)
class Item:
    """One test utterance: its id, text (as typed), kind, world, voice, rate (wpm), SNR (dB)."""

    id: str
    text: str
    kind: str
    world: str
    voice: str
    rate: int
    snr_db: float | None

    @property
    def reference(self) -> str:
        return normalise_transcript(self.text)

    @property
    def noise(self) -> str:
        return "clean" if self.snr_db is None else f"{self.snr_db:g} dB"


def sentences(repo: Path | None = None) -> list[tuple[str, str, str]]:
    """(text, kind, world) of every test sentence, in a fixed order: the fetch dev set's
    commands, where-questions, and the chat sentences of ``corpus/speech_test_chat.tsv`` (a
    fixed list: new scripted conversations do not change the test set)."""
    from assistant.language.corpus import repo_root

    repo = Path(repo or repo_root())
    out = []
    for line in (repo / "corpus" / "fetch_dev.jsonl").read_text(encoding="utf-8").splitlines():
        if line.strip():
            request = json.loads(line)
            sentence = (request["text"], "command", request.get("world", "apartment"))
            if sentence not in out:  # the dev set repeats a command in other scenes and seeds: one is enough
                out.append(sentence)
    objects = ("mug", "fork", "laptop", "monitor", "statue", "glasses case") + UNKNOWN_OBJECTS
    for i, obj in enumerate(objects):
        for j, wording in enumerate(WHERE_WORDINGS):
            if (i + j) % 2 == 0:  # half of the pairs: 5 wordings over 10 objects, 25 questions
                out.append((wording.format(o=obj), "where", "apartment"))
    for line in (repo / "corpus" / "speech_test_chat.tsv").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            world, said = line.split("\t", 1)
            out.append((said, "chat", world))
    return out


def items(per_kind: int | None = None, all_voices: bool = False, snrs_db=SNRS_DB, kinds=None) -> list[Item]:
    """The test utterances (``per_kind``: only the first that many sentences of each kind)."""
    pairs = [(v, r) for v in VOICES for r in RATES]
    chosen = sentences()
    if kinds:
        chosen = [s for s in chosen if s[1] in kinds]
    if per_kind is not None:
        chosen = [s for k in ("command", "where", "chat") for s in [c for c in chosen if c[1] == k][:per_kind]]
    out = []
    for n, (text, kind, world) in enumerate(chosen):
        speakers = pairs if all_voices else [pairs[n % len(pairs)]]
        for voice, rate in speakers:
            for snr in snrs_db:
                out.append(Item(f"{n:03d}-{voice}-{rate}-{'clean' if snr is None else f'{snr:g}dB'}",
                                text, kind, world, voice, rate, snr))
    return out


# ---------------------------------------------------------------------------- audio
def synthesise(text: str, voice: str, rate: int) -> np.ndarray:
    """espeak-ng's rendering of ``text`` at 16 kHz, with :data:`SILENCE_S` of silence around."""
    try:
        done = subprocess.run(["espeak-ng", "-v", voice, "-s", str(rate), "--stdout", text],
                              capture_output=True, timeout=60, check=True)
    except (OSError, subprocess.SubprocessError) as error:
        from assistant.errors import AssistantError

        raise AssistantError(f"espeak-ng could not synthesise the test set ({error}); install espeak-ng") from None
    speech = audio_from_bytes(done.stdout, "espeak-ng").samples
    pad = np.zeros(int(SILENCE_S * SAMPLE_RATE_HZ), dtype=np.float32)
    return np.concatenate([pad, speech, pad])


def household_noise(n: int, seed: int) -> np.ndarray:
    """``n`` samples (16 kHz) of generated household noise with unit power."""
    from scipy.signal import butter, sosfilt

    rng = np.random.default_rng(seed)
    t = np.arange(n) / SAMPLE_RATE_HZ
    rumble = np.cumsum(rng.normal(size=n))
    rumble = sosfilt(butter(4, 300, "lowpass", fs=SAMPLE_RATE_HZ, output="sos"), rumble - rumble.mean())
    hum_hz = 50.0 if rng.random() < 0.5 else 60.0
    hum = sum(np.sin(2 * np.pi * k * hum_hz * t + rng.uniform(0, 2 * np.pi)) / k for k in (1, 2, 3, 5))
    clatter = np.zeros(n)
    band = butter(2, [1500, 6000], "bandpass", fs=SAMPLE_RATE_HZ, output="sos")
    for _ in range(max(1, int(n / SAMPLE_RATE_HZ * 1.5))):  # about 1.5 knocks a second
        at = int(rng.integers(0, n))
        length = int(rng.uniform(0.03, 0.15) * SAMPLE_RATE_HZ)
        burst = sosfilt(band, rng.normal(size=length)) * np.exp(-np.arange(length) / (0.2 * length))
        end = min(n, at + length)
        clatter[at:end] += burst[:end - at] * rng.uniform(0.5, 2.0)
    parts = [p / (np.sqrt(np.mean(p ** 2)) + 1e-12) for p in (rumble, hum, clatter)]
    mix = 1.0 * parts[0] + 0.4 * parts[1] + 0.8 * parts[2]
    return (mix / np.sqrt(np.mean(mix ** 2))).astype(np.float32)


def mix_at_snr(speech: np.ndarray, noise: np.ndarray, snr_db: float) -> np.ndarray:
    """``speech`` + ``noise`` scaled so the speech's active power is ``snr_db`` above it."""
    power = speech_power(speech)
    scale = np.sqrt(power / (10 ** (snr_db / 10.0)))
    out = speech + scale * noise[:len(speech)]
    peak = float(np.max(np.abs(out)))
    return (out / peak * 0.9 if peak > 0.99 else out).astype(np.float32)


def cache_folder() -> Path:
    from assistant.fileio import cache_dir

    return cache_dir() / "speech-testset" / f"v{GENERATOR_VERSION}"


def audio_of(item: Item, folder: Path | None = None) -> np.ndarray:
    """The item's audio, made and cached on first use (16 kHz mono)."""
    folder = folder or cache_folder()
    key = hashlib.sha1(f"{item.text}|{item.voice}|{item.rate}|{item.snr_db}".encode()).hexdigest()[:12]
    path = folder / f"{item.id}-{key}.wav"
    if path.is_file():
        return read_audio(path).samples
    clean_path = folder / f"clean-{hashlib.sha1(f'{item.text}|{item.voice}|{item.rate}'.encode()).hexdigest()[:12]}.wav"
    if clean_path.is_file():
        speech = read_audio(clean_path).samples
    else:
        speech = synthesise(item.text, item.voice, item.rate)
        write_wav(clean_path, speech)
    if item.snr_db is None:
        return speech
    noise = household_noise(len(speech), zlib.crc32(key.encode()))
    noisy = mix_at_snr(speech, noise, item.snr_db)
    write_wav(path, noisy)
    return read_audio(path).samples

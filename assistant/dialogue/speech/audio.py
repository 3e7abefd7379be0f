"""Audio as the recognisers take it: mono, 16 kHz, float samples in [-1, 1].

:func:`read_audio` reads a WAV (or FLAC/OGG: anything libsndfile reads), mixes stereo down and
resamples with a polyphase filter (``scipy.signal.resample_poly``); every way a file can be
unusable — missing, corrupt, empty, longer than an utterance can be — is an
:class:`~assistant.dialogue.speech.errors.AudioFileError` that says what to do.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.errors import AudioFileError

#: the rate the recognisers' acoustic models are trained on (Hz)
SAMPLE_RATE_HZ = 16000
#: the longest file taken as one utterance (seconds)
MAX_UTTERANCE_S = 60.0


@dataclass(frozen=True)
class Audio:
    """Mono samples at ``rate_hz``; where they came from (file rate, channel count)."""

    samples: np.ndarray
    rate_hz: int = SAMPLE_RATE_HZ
    source_rate_hz: int = SAMPLE_RATE_HZ
    source_channels: int = 1
    source: str = ""

    @property
    def seconds(self) -> float:
        return len(self.samples) / float(self.rate_hz)

    def pcm16(self) -> bytes:
        """16-bit signed little-endian PCM, as the recognisers take it."""
        return to_pcm16(self.samples)


def to_pcm16(samples: np.ndarray) -> bytes:
    return (np.clip(np.asarray(samples, dtype=np.float64), -1.0, 1.0) * 32767.0).astype("<i2").tobytes()


def from_pcm16(data: bytes) -> np.ndarray:
    return np.frombuffer(data, dtype="<i2").astype(np.float32) / 32768.0


def frame_energies(samples: np.ndarray) -> np.ndarray:
    """Mean power of each 30 ms frame (a shorter tail is a frame of its own)."""
    frame = int(0.03 * SAMPLE_RATE_HZ)
    samples = np.asarray(samples, dtype=np.float64)
    return np.array([np.mean(samples[i:i + frame] ** 2) for i in range(0, len(samples), frame)])


def active_power(energies) -> float:
    """Mean of the frame energies within 25 dB of the loudest: the power of the speech."""
    energies = np.asarray(energies, dtype=np.float64)
    if not energies.size:
        return 0.0
    active = energies > 0.003 * float(energies.max())
    return float(energies[active].mean()) if active.any() else float(energies.mean())


def speech_power(samples: np.ndarray) -> float:
    """Mean power of the spoken part of ``samples`` (see :func:`active_power`)."""
    return active_power(frame_energies(samples))


#: the noise floor the recogniser adds before decoding, in dB under the speech's power
#: (:mod:`~assistant.dialogue.speech.sphinx`; enrolment computes its features over the same floor)
DEFAULT_FLOOR_DB = 30.0


def with_noise_floor(samples: np.ndarray, below_db: float, seed: int = 0, power: float | None = None) -> np.ndarray:
    """``samples`` with white noise ``below_db`` under the speech's power (``power``: that power,
    when known; default :func:`speech_power`). Fixed seed: the same input gives the same output."""
    samples = np.asarray(samples, dtype=np.float32)
    power = speech_power(samples) if power is None else power
    if power <= 0 or not len(samples):
        return samples
    level = np.sqrt(power / 10 ** (below_db / 10.0))
    return samples + np.random.default_rng(seed).normal(0.0, level, len(samples)).astype(np.float32)


def resample(samples: np.ndarray, rate_hz: int, target_hz: int = SAMPLE_RATE_HZ) -> np.ndarray:
    """Polyphase resampling from ``rate_hz`` to ``target_hz`` (exact for integer rates)."""
    if rate_hz == target_hz:
        return np.asarray(samples, dtype=np.float32)
    from scipy.signal import resample_poly

    g = math.gcd(int(rate_hz), int(target_hz))
    return resample_poly(samples, target_hz // g, rate_hz // g).astype(np.float32)


def read_audio(path, max_seconds: float = MAX_UTTERANCE_S) -> Audio:
    """A file's audio at 16 kHz mono; :class:`AudioFileError` for a file that cannot be used."""
    from assistant.dialogue.speech.errors import require

    sf = require("soundfile", "pip install soundfile", AudioFileError)
    path = Path(path)
    if not path.is_file():
        raise AudioFileError(f"{path}: no such audio file; give a WAV file (16-bit PCM, any rate)")
    if path.stat().st_size == 0:
        raise AudioFileError(f"{path}: the file is empty (0 bytes); record the command again")
    try:
        info = sf.info(str(path))
    except Exception as error:  # libsndfile's error for anything it cannot parse
        raise AudioFileError(f"{path}: not a readable audio file ({_short(error)}); record or convert it "
                             "to WAV, e.g. `sox IN -r 16000 -c 1 OUT.wav`") from None
    if info.frames <= 0:
        raise AudioFileError(f"{path}: the recording is empty (no samples); record the command again")
    seconds = info.frames / float(info.samplerate)
    if seconds > max_seconds:
        raise AudioFileError(f"{path}: {seconds:.0f} s is longer than one utterance may be ({max_seconds:.0f} s); "
                             f"cut out the command, e.g. `sox {path.name} part.wav trim 0 20`")
    try:
        data, rate = sf.read(str(path), dtype="float32", always_2d=True)
    except Exception as error:
        raise AudioFileError(f"{path}: the audio data is damaged ({_short(error)}); record it again") from None
    if data.shape[0] == 0:
        raise AudioFileError(f"{path}: the recording is empty (no samples); record the command again")
    mono = data.mean(axis=1)
    return Audio(resample(mono, int(rate)), SAMPLE_RATE_HZ, int(rate), int(data.shape[1]), str(path))


def audio_from_bytes(data: bytes, source: str = "<bytes>") -> Audio:
    """WAV bytes (e.g. from ``espeak-ng --stdout``) as 16 kHz mono audio."""
    import soundfile as sf

    try:
        samples, rate = sf.read(io.BytesIO(data), dtype="float32", always_2d=True)
    except Exception as error:
        raise AudioFileError(f"{source}: not readable audio ({_short(error)})") from None
    return Audio(resample(samples.mean(axis=1), int(rate)), SAMPLE_RATE_HZ, int(rate), int(samples.shape[1]), source)


def wav_bytes(samples: np.ndarray, rate_hz: int = SAMPLE_RATE_HZ) -> bytes:
    """16-bit PCM WAV bytes of mono samples."""
    import soundfile as sf

    buffer = io.BytesIO()
    sf.write(buffer, np.clip(samples, -1.0, 1.0), rate_hz, subtype="PCM_16", format="WAV")
    return buffer.getvalue()


def write_wav(path, samples: np.ndarray, rate_hz: int = SAMPLE_RATE_HZ) -> Path:
    """Write a mono 16-bit WAV atomically (a reader never sees half a file)."""
    from assistant.fileio import atomic_write_bytes

    return atomic_write_bytes(path, wav_bytes(samples, rate_hz))


def _short(error: Exception) -> str:
    text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
    return text[:120]

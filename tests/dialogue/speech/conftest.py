"""Speech fixtures: utterances spoken by espeak-ng into temporary WAV files (no audio committed)."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

pytest.importorskip("pocketsphinx")
pytest.importorskip("soundfile")

RATE = 16000


def speak(text: str, voice: str = "en-us", rate: int = 150, pad_s: float = 0.5) -> np.ndarray:
    """``text`` spoken by espeak-ng at 16 kHz with ``pad_s`` of silence around it."""
    if shutil.which("espeak-ng") is None:
        pytest.skip("espeak-ng is not installed (apt-get install espeak-ng)")
    from assistant.dialogue.speech.audio import audio_from_bytes

    wav = subprocess.run(["espeak-ng", "-v", voice, "-s", str(rate), "--stdout", text], capture_output=True,
                         check=True).stdout
    pad = np.zeros(int(pad_s * RATE), dtype=np.float32)
    return np.concatenate([pad, audio_from_bytes(wav).samples, pad])


@pytest.fixture
def say_wav(tmp_path):
    """Write an utterance to a WAV (16-bit; ``rate_hz``/``channels`` as asked) and return its path."""
    import soundfile as sf

    from assistant.dialogue.speech.audio import resample

    def make(text: str, name: str = "utterance.wav", rate_hz: int = RATE, channels: int = 1, **options):
        samples = resample(speak(text, **options), RATE, rate_hz)
        data = np.stack([samples] * channels, axis=1) if channels > 1 else samples
        path = tmp_path / name
        sf.write(path, data, rate_hz, subtype="PCM_16")
        return path

    return make


@pytest.fixture(scope="session")
def recogniser():
    """One pocketsphinx recogniser for the module (the home model is built once)."""
    from assistant.dialogue.speech.recogniser import make_recogniser

    return make_recogniser("pocketsphinx")

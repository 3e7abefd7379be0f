"""Reading recordings: resampling, mixing down, and a clear message for every unusable file."""

import numpy as np
import pytest
import soundfile as sf

from assistant.dialogue.speech.audio import SAMPLE_RATE_HZ, read_audio, resample
from assistant.dialogue.speech.errors import AudioFileError
from assistant.dialogue.speech.vad import speech_spans

from .conftest import speak


def test_stereo_44k_is_mixed_down_and_resampled(tmp_path):
    t = np.arange(44100) / 44100.0
    left, right = 0.5 * np.sin(2 * np.pi * 440 * t), 0.1 * np.sin(2 * np.pi * 440 * t)
    sf.write(tmp_path / "s.wav", np.stack([left, right], axis=1), 44100, subtype="PCM_16")
    audio = read_audio(tmp_path / "s.wav")
    assert (audio.source_rate_hz, audio.source_channels, audio.rate_hz) == (44100, 2, SAMPLE_RATE_HZ)
    assert abs(audio.seconds - 1.0) < 1e-3
    spectrum = np.abs(np.fft.rfft(audio.samples))
    assert abs(np.argmax(spectrum) * SAMPLE_RATE_HZ / len(audio.samples) - 440) < 2  # same pitch after resampling
    assert abs(np.sqrt(2 * np.mean(audio.samples[1000:-1000] ** 2)) - 0.3) < 0.01  # the mean of the channels


@pytest.mark.parametrize("make, message", [
    (lambda p: p.write_bytes(b""), r"empty \(0 bytes\)"),
    (lambda p: sf.write(p, np.zeros((0,)), 16000, subtype="PCM_16"), r"empty \(no samples\)"),
    (lambda p: p.write_bytes(b"RIFF\x10\x00\x00\x00WAVEjunk" + bytes(range(200))), "not a readable audio file"),
    (lambda p: sf.write(p, np.zeros(16000 * 600, dtype=np.int16), 16000, subtype="PCM_16"), "longer than one utterance"),
    (lambda p: None, "no such audio file"),
])
def test_unusable_files_say_what_is_wrong(tmp_path, make, message):
    path = tmp_path / "bad.wav"
    make(path)
    with pytest.raises(AudioFileError, match=message):
        read_audio(path)


def test_resample_keeps_length_ratio():
    x = np.random.default_rng(0).normal(size=22050).astype(np.float32)
    assert len(resample(x, 22050, 16000)) == 16000


def test_endpointer_finds_each_utterance_with_padding():
    one, two = speak("where is my mug", pad_s=1.0), speak("stop", pad_s=1.0)
    x = np.concatenate([one, two]) + np.random.default_rng(1).normal(0, 1e-3, len(one) + len(two)).astype(np.float32)
    spans = speech_spans(x, pad_s=0.3)
    assert len(spans) == 2
    assert 0.8 < spans[0].start_s < 1.2 and spans[1].start_s > len(one) / SAMPLE_RATE_HZ
    first = spans[0]
    assert abs(len(first.samples) / SAMPLE_RATE_HZ - (first.seconds + 0.6)) < 0.1  # 0.3 s before and after
    assert speech_spans(np.zeros(3 * SAMPLE_RATE_HZ, dtype=np.float32)) == []


def test_an_utterance_is_handed_back_as_soon_as_the_endpointer_hears_the_pause():
    from assistant.dialogue.speech.vad import UtteranceDetector

    x = speak("where is my mug", pad_s=1.0)
    x = x + np.random.default_rng(1).normal(0, 1e-3, len(x)).astype(np.float32)
    fed: list[np.ndarray] = []
    detector = UtteranceDetector(window_s=0.3, pad_s=0.3, on_samples=lambda s, starting: fed.append(s))
    for i in range(0, len(x), 480):  # 30 ms blocks, as the microphone delivers them
        done = detector.feed(x[i:i + 480])
        if done:
            heard_at_s = (i + 480) / SAMPLE_RATE_HZ
            break
    else:
        raise AssertionError("the utterance never ended")
    # the pad after the words comes from audio already heard: no wait beyond the endpointer's window
    assert heard_at_s - done[0].end_s <= 0.3 + 0.05
    assert len(done[0].samples) / SAMPLE_RATE_HZ > done[0].seconds + 0.45  # both pads kept
    assert sum(len(s) for s in fed) == len(done[0].samples)  # the stream got every sample

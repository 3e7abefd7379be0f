"""Vocal tract length normalisation: the pitch estimate, the warp it gives, and the warped decoder."""

import numpy as np
import pytest

from assistant.dialogue.speech.vtln import (MAX_WARP, REFERENCE_F0_HZ, SpeakerPitch, pitch_hz, voiced_pitches,
                                            warp_for_pitch)

RATE = 16000


def voice(f0_hz: float, seconds: float = 1.0, seed: int = 0) -> np.ndarray:
    """A buzz at ``f0_hz`` (harmonics falling 6 dB an octave) with a little noise, 0.3 s of silence round it."""
    t = np.arange(int(seconds * RATE)) / RATE
    buzz = sum(np.sin(2 * np.pi * k * f0_hz * t) / k for k in range(1, int(4000 / f0_hz)))
    buzz = 0.3 * buzz / np.max(np.abs(buzz)) + np.random.default_rng(seed).normal(0, 0.003, len(t))
    pad = np.zeros(int(0.3 * RATE))
    return np.concatenate([pad, buzz, pad]).astype(np.float32)


@pytest.mark.parametrize("f0", [95.0, 132.0, 210.0, 300.0])
def test_the_pitch_of_a_voiced_sound_is_measured(f0):
    assert pitch_hz(voice(f0)) == pytest.approx(f0, rel=0.03)


def test_noise_and_silence_have_no_pitch():
    rng = np.random.default_rng(1)
    assert pitch_hz(rng.normal(0, 0.1, RATE).astype(np.float32)) is None
    assert pitch_hz(np.zeros(RATE, np.float32)) is None
    assert pitch_hz(np.zeros(100, np.float32)) is None
    assert len(voiced_pitches(voice(200.0, seconds=0.05))) < 10  # too short to count


def test_the_warp_follows_the_pitch_from_mens_average_up():
    assert warp_for_pitch(None) == 1.0
    assert warp_for_pitch(90.0) == warp_for_pitch(REFERENCE_F0_HZ) == 1.0  # men's voices are not warped
    assert warp_for_pitch(223.0) == 1.15  # women's average pitch: their average formant ratio (1.17), rounded
    assert warp_for_pitch(600.0) == MAX_WARP
    warps = [warp_for_pitch(f) for f in range(100, 400, 10)]
    assert warps == sorted(warps) and all(round(w / 0.05) * 0.05 == pytest.approx(w) for w in warps)


def test_the_speaker_pitch_is_kept_over_a_conversation():
    speaker = SpeakerPitch()
    assert speaker.hz is None
    assert speaker.add(voice(200.0)) == pytest.approx(200.0, rel=0.03)
    assert speaker.add(np.zeros(RATE, np.float32)) is None  # a silent utterance adds nothing
    speaker.add_later(voice(210.0, seed=2))
    assert speaker.hz == pytest.approx(205.0, rel=0.03)
    speaker.reset()
    assert speaker.hz is None


def test_a_high_voice_is_decoded_warped_and_heard_right():
    """en-us+f3 (pitch ~200 Hz) at 140 wpm: unwarped, "living room" is heard as "meeting room"."""
    from assistant.dialogue.speech.recogniser import make_recogniser
    from assistant.eval import speech_data

    said = "bring me the mug from the living room"
    audio = speech_data.synthesise(said, "en-us+f3", 140)
    warped = make_recogniser("pocketsphinx", open_fallback=False)
    plain = make_recogniser("pocketsphinx", open_fallback=False, vtln=False)
    heard, unwarped = warped.recognise(audio), plain.recognise(audio)
    assert heard.warp == 1.15 and unwarped.warp == 1.0
    assert "living room" in heard.transcript and "meeting room" in unwarped.transcript, (heard, unwarped)
    # back to the warp after a man's voice and a decoder built without a warp (pocketsphinx keeps the
    # warp's parameters process-wide and would otherwise silently build this front end unwarped)
    man = speech_data.synthesise("go into the office the laptop is on the desk", "en-us", 140)
    assert warped.recognise(man).warp == 1.0
    make_recogniser("pocketsphinx", open_fallback=False, vtln=False)
    assert warped.recognise(audio).transcript == heard.transcript


def test_a_stream_is_warped_by_the_voice_heard_before_or_its_first_second():
    from assistant.dialogue.speech.recogniser import make_recogniser
    from assistant.eval import speech_data

    def streamed(recogniser, audio):
        stream = recogniser.stream()
        for i in range(0, len(audio), 480):  # 30 ms blocks, as the microphone gives them
            stream.feed(audio[i:i + 480])
            if i >= 16000:  # after the hold: the warp is chosen and the decoder has caught up
                assert stream.warp is not None
        return stream.finish()

    recogniser = make_recogniser("pocketsphinx", open_fallback=False)
    audio = speech_data.synthesise("bring me the mug from the living room", "en-us+f3", 175)
    hum = np.random.default_rng(3).normal(0, 0.01, 12000).astype(np.float32)
    assert streamed(recogniser, hum).warp == 1.0  # nothing heard yet and no voice: not warped
    first = streamed(recogniser, audio)  # the first voice of the conversation: its first second decides
    assert first.warp in (1.15, 1.2) and "living room" in first.transcript, first
    assert recogniser.speaker_warp() == 1.15  # the whole utterance's pitch, kept for the next ones
    second = recogniser.stream()
    assert second.warp == 1.15  # chosen at once: no hold
    second.finish()
    plain = make_recogniser("pocketsphinx", open_fallback=False, vtln=False)
    unwarped = plain.stream()
    assert unwarped.warp == 1.0  # chosen at once
    unwarped.finish()
    assert streamed(plain, audio).warp == 1.0

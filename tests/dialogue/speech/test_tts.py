"""Speech out: pyttsx3 on espeak-ng into a --say-to file, nothing on stdout, clear errors."""

import shutil

import numpy as np
import pytest

from assistant.dialogue.speech.audio import read_audio
from assistant.dialogue.speech.errors import SpeechOutputError

pytestmark = pytest.mark.skipif(shutil.which("espeak-ng") is None, reason="espeak-ng is not installed")


def test_replies_accumulate_in_the_say_to_file(tmp_path, capsys):
    pytest.importorskip("pyttsx3")
    from assistant.dialogue.speech.tts import Speaker

    out = tmp_path / "said.wav"
    speaker = Speaker("en-us", 170, say_to=out, play=False)
    first = speaker.say("Going to the bedroom.")
    one = read_audio(out).seconds
    speaker.say("The mug is on the table.")
    two = read_audio(out).seconds
    assert first.size > 8000 and one > 0.5 and two > one + 0.5
    assert capsys.readouterr().out == ""  # pyttsx3's "Audio saved to" does not reach stdout
    assert np.abs(read_audio(out).samples).max() > 0.05


def test_bad_voice_rate_and_folder(tmp_path):
    from assistant.dialogue.speech.tts import Speaker

    with pytest.raises(SpeechOutputError, match="no such voice"):
        Speaker("xx-nowhere")
    with pytest.raises(SpeechOutputError, match="between 80 and 450"):
        Speaker("en-us", 5)
    with pytest.raises(SpeechOutputError, match="cannot write"):
        Speaker("en-us", say_to=tmp_path / "missing" / "x.wav")

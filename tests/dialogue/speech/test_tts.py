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


class _StuckEngine:
    """A pyttsx3 engine whose synthesis never ends until ``release`` is set (a hung espeak)."""

    def __init__(self):
        import threading

        self.release = threading.Event()
        self.runs = 0

    def setProperty(self, name, value):
        pass

    def save_to_file(self, text, path):
        pass

    def runAndWait(self):
        self.runs += 1
        self.release.wait(30)


def test_a_hung_pyttsx3_is_left_alone_and_espeak_speaks(monkeypatch):
    import time
    import types

    from assistant.dialogue.speech import tts

    engine = _StuckEngine()
    monkeypatch.setitem(__import__("sys").modules, "pyttsx3", types.SimpleNamespace(init=lambda driver: engine))
    monkeypatch.setattr(tts, "SYNTH_TIMEOUT_S", 0.3)
    monkeypatch.setattr(tts, "_HUNG", [])
    speaker = tts.Speaker("en-us", 170, play=False)
    try:
        assert speaker.synthesise("Going to the bedroom.").size > 8000  # espeak-ng spoke it
        assert tts.synthesis_hung() and speaker.fallbacks == 1
        start = time.perf_counter()
        assert speaker.synthesise("The mug is on the table.").size > 8000
        assert time.perf_counter() - start < 0.3  # no second wait for the stuck engine
        assert engine.runs == 1 and speaker.fallbacks == 2
    finally:
        engine.release.set()
    tts._HUNG[0].join(5)
    assert not tts.synthesis_hung()


def test_the_program_exits_with_its_status_while_a_synthesis_hangs(tmp_path):
    import subprocess
    import sys
    import textwrap

    script = textwrap.dedent("""
        import sys, threading
        from assistant.dialogue.speech import tts
        tts.leave_if_synthesis_hung(5)  # nothing hung: returns
        print("still here", end="")
        stuck = threading.Thread(target=threading.Event().wait, daemon=True)
        stuck.start()
        tts._HUNG.append(stuck)
        tts.leave_if_synthesis_hung(3)
        print("not reached")
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                          cwd=str(__import__("pathlib").Path(__file__).resolve().parents[3]))
    assert done.returncode == 3, done.stderr
    assert done.stdout == "still here"  # flushed before leaving

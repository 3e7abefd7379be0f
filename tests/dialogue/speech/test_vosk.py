"""vosk: configuration and model errors always; recognition when $ASSISTANT_VOSK_MODEL names a model."""

import os

import pytest

from assistant.dialogue.speech.errors import RecogniserError
from assistant.dialogue.speech.vosk_engine import ENV_MODEL, VoskRecogniser, check_model_dir

from .conftest import speak


def test_no_model_given(monkeypatch):
    monkeypatch.delenv(ENV_MODEL, raising=False)
    with pytest.raises(RecogniserError, match="needs a model"):
        check_model_dir(None)


def test_missing_and_not_a_model(tmp_path):
    with pytest.raises(RecogniserError, match="no such folder"):
        check_model_dir(tmp_path / "nowhere")
    (tmp_path / "conf").mkdir()
    with pytest.raises(RecogniserError, match="missing am/final.mdl, conf/mfcc.conf"):
        check_model_dir(tmp_path)


def test_an_enrolled_speaker_is_refused_with_what_to_do(tmp_path):
    with pytest.raises(RecogniserError, match="leave --speaker out with --asr vosk"):
        VoskRecogniser(tmp_path, speaker="ann")


def test_broken_model_is_reported(tmp_path):
    pytest.importorskip("vosk")
    (tmp_path / "am").mkdir()
    (tmp_path / "conf").mkdir()
    (tmp_path / "am" / "final.mdl").write_bytes(b"not a model")
    (tmp_path / "conf" / "mfcc.conf").write_text("--sample-frequency=16000\n")
    with pytest.raises(RecogniserError, match="vosk cannot load this model"):
        VoskRecogniser(tmp_path, phrases=["stop"])


@pytest.mark.skipif(not os.environ.get(ENV_MODEL), reason=f"no vosk model: set {ENV_MODEL} to a model folder")
def test_vosk_hears_a_question():
    rec = VoskRecogniser(os.environ[ENV_MODEL])
    heard = rec.recognise(speak("where is my mug"))
    assert "mug" in heard.transcript and 0 < heard.confidence <= 1

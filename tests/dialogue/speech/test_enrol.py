"""Speaker enrolment: the packaged model's files expanded, the script, the stored model, and a
real adaptation with SphinxTrain (skipped, saying why, where its tools are not installed)."""

import json
import struct

import numpy as np
import pytest

from assistant.cli import main
from assistant.dialogue.speech import enrol as enrolment
from assistant.dialogue.speech.errors import RecogniserError

from .conftest import speak


def _sendump(weights_bytes: np.ndarray, shift: int = 10) -> bytes:
    """A small sendump: title, header lines, end, densities and senones, then stream × density rows."""
    def string(text: str) -> bytes:
        data = text.encode() + b"\0"
        return struct.pack("<I", len(data)) + data

    streams, densities, senones = weights_bytes.shape
    head = string("BEGIN FILE FORMAT DESCRIPTION") + string(f"feature_count {streams}") + string(f"mixw_shift {shift}")
    head += string("cluster_count 0") + struct.pack("<I", 0)
    return head + struct.pack("<II", densities, senones) + weights_bytes.astype(np.uint8).tobytes()


def test_the_compressed_mixture_weights_are_expanded_and_written_as_sphinxtrain_reads_them(tmp_path):
    raw = np.arange(2 * 3 * 5, dtype=np.uint8).reshape(2, 3, 5)  # streams × densities × senones
    (tmp_path / "sendump").write_bytes(_sendump(raw))
    weights = enrolment.expand_sendump(tmp_path / "sendump")
    assert weights.shape == (5, 2, 3)  # senones × streams × densities
    assert weights[4, 1, 2] == pytest.approx(1.0001 ** -(int(raw[1, 2, 4]) << 10))
    enrolment.write_mixture_weights(tmp_path / "mixw", weights)
    data = (tmp_path / "mixw").read_bytes()
    start = data.index(b"endhdr\n") + len(b"endhdr\n")
    assert start % 4 == 0 and struct.unpack_from("=i", data, start)[0] == 0x11223344
    assert struct.unpack_from("=IIII", data, start + 4) == (5, 2, 3, 30)
    assert np.frombuffer(data, "<f4", 30, start + 20).reshape(5, 2, 3) == pytest.approx(weights, rel=1e-6)
    (tmp_path / "short").write_bytes(_sendump(raw)[:-7])
    with pytest.raises(RecogniserError, match="truncated"):
        enrolment.expand_sendump(tmp_path / "short")


def test_the_script_is_fixed_pronounceable_and_holds_no_test_sentence():
    from assistant.dialogue.speech.vocabulary import normalise_transcript
    from assistant.eval.speech_data import sentences

    script = enrolment.enrolment_script()
    assert script == enrolment.enrolment_script() and len(script) == enrolment.ENROL_SENTENCES
    assert enrolment.enrolment_script(12) == script[:12]  # recordings of a script's start match any script
    assert all(5 <= len(s.split()) <= 14 for s in script)
    test = {normalise_transcript(text) for text, _, _ in sentences()}
    assert not test & set(script)


def test_speaker_names_and_unknown_speakers_get_clear_errors(tmp_path):
    for bad in ("", "../x", "a b", "x" * 41):
        with pytest.raises(RecogniserError, match="speaker name"):
            enrolment.speaker_model(bad, tmp_path)
    with pytest.raises(RecogniserError, match="assistant enrol ann"):
        enrolment.enrolled_model("ann", tmp_path)
    with pytest.raises(RecogniserError, match="at least"):
        enrolment.enrol("ann", [(np.zeros(16000, dtype=np.float32), "go to the bedroom")], tmp_path)


def test_the_cli_prints_the_script_and_refuses_a_folder_of_too_few_recordings(tmp_path, capsys):
    assert main(["enrol", "ann", "--script", "--sentences", "12"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 12 and lines[0].split(None, 1)[1] == enrolment.enrolment_script(12)[0]
    if any(path is None for path in enrolment.tools().values()):
        pytest.skip(f"SphinxTrain is not installed ({enrolment.INSTALL_HINT})")
    (tmp_path / "one.wav").write_bytes(b"")
    assert main(["enrol", "ann", "--audio-in", str(tmp_path)]) == 2
    assert "1 .wav files" in capsys.readouterr().err


def test_an_enrolled_voice_is_decoded_with_its_own_model(tmp_path, monkeypatch, capsys):
    """Recordings of twelve script sentences in a synthetic woman's voice, enrolled from the
    command line (the real tools): the model is kept in the data folder and decodes by name."""
    if any(path is None for path in enrolment.tools().values()):
        pytest.skip(f"SphinxTrain is not installed ({enrolment.INSTALL_HINT})")
    from assistant.dialogue.speech.audio import write_wav
    from assistant.dialogue.speech.recogniser import make_recogniser

    data, recordings = tmp_path / "data", tmp_path / "recordings"
    recordings.mkdir()
    monkeypatch.setenv("ASSISTANT_DATA", str(data))
    for n, text in enumerate(enrolment.enrolment_script(12)):
        write_wav(recordings / f"{n:02d}.wav", speak(text, voice="en-us+f3", rate=150))
    assert main(["enrol", "ann", "--audio-in", str(recordings), "--json"]) == 0
    model = data / "speakers" / "ann" / "model"
    assert json.loads(capsys.readouterr().out) == {"speaker": "ann", "model": str(model), "recordings": 12}
    assert (model / "means").is_file() and not list(model.parent.glob(".enrol-*"))  # no half-built model left
    recogniser = make_recogniser("pocketsphinx", open_fallback=False, speaker="ann")
    assert recogniser.settings["hmm"] == str(model) and recogniser.describe()["speaker"] == "ann"
    from assistant.eval.speech import word_errors

    said = ("go into the bedroom and turn left", "where is my mug", "bring me the laptop from the table in the living room")
    heard = [recogniser.recognise(speak(s, voice="en-us+f3", rate=150)).transcript for s in said]
    # the packaged model makes 5 errors in these 20 words ("go in the living room and then the", "money")
    assert sum(word_errors(s, h) for s, h in zip(said, heard)) <= 3, heard
